//! The column top's frame sequence `fcc_col_flow` alone under Verilator,
//! against its rules (docs/column-core.md, "The top"), cycle by cycle with
//! a model of its state, and against the properties the top relies on:
//! no restart while a write is owed and a frame is in the datapath; a
//! reload only while idle and quiet, after a write; the first pixel held
//! while a write is owed; `quiet` exactly when every frame done has sent
//! its end beat. Inputs: a random stream of frames (their input done,
//! held until the restart; their end beats, at most one frame behind),
//! idle as the input stage gives it, register writes at random. A
//! mismatch prints the cycle, the outputs expected and got, and the seed.

use fcc_params::FccParams;
use fcc_rtl::BenchBlock;
use fcc_sim::{c_struct, load_plain, PlainDut};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

c_struct! {
    /// Inputs of one cycle, named as the ports.
    pub struct FlIn {
        pub rst: u8,
        pub in_done: u8,
        pub idle: u8,
        pub idle_next: u8,
        pub end_sent: u8,
        pub written: u8,
    }
}

c_struct! {
    /// Outputs during one cycle.
    pub struct FlOut {
        pub restart: u8,
        pub quiet: u8,
        pub load_next: u8,
        pub start_hold: u8,
        pub reload_next: u8,
        pub reload: u8,
    }
}

/// The block's state as its rules say.
#[derive(Default)]
struct Model {
    open: u8,
    done_q: bool,
    restarted: bool,
    dirty: bool,
    reload_q: bool,
}

impl Model {
    /// The outputs for `i`, and the state after the clock edge.
    fn step(&mut self, i: &FlIn) -> FlOut {
        let (in_done, idle, end) = (i.in_done != 0, i.idle != 0, i.end_sent != 0);
        let rise = in_done && !self.done_q;
        let quiet = self.open == 0;
        let open_next = (self.open + u8::from(rise)) - u8::from(end);
        let restart = in_done && !self.restarted && (!self.dirty || quiet);
        let reload_next = idle && quiet && self.dirty;
        let out = FlOut {
            restart: u8::from(restart),
            quiet: u8::from(quiet),
            load_next: u8::from(i.idle_next != 0 && open_next == 0),
            start_hold: u8::from(idle && (self.dirty || i.written != 0)),
            reload_next: u8::from(reload_next),
            reload: u8::from(self.reload_q),
        };
        if i.rst != 0 {
            *self = Model::default();
        } else {
            self.open = open_next;
            self.done_q = in_done;
            self.restarted = restart;
            self.dirty = i.written != 0 || (self.dirty && !(idle && quiet));
            self.reload_q = reload_next;
        }
        out
    }
}

#[test]
fn the_frame_sequence_follows_its_rules() {
    let model = load_plain::<FlIn, FlOut>(BenchBlock::ColFlow, &FccParams::default())
        .expect("the frame sequence's model");
    let mut d = PlainDut::new(model);
    let seed = 0xf10e_u64;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut m = Model::default();
    // The environment: the input stage (idle, taking a frame's pixels,
    // done until restarted) and the frames whose end beats are owed.
    let (mut idle, mut running, mut in_done, mut owed) = (true, false, false, 0u32);
    let (mut restarts, mut reloads, mut held, mut most) = (0u32, 0u32, 0u32, 0u32);
    for cycle in 0..200_000u32 {
        let rst = cycle < 2 || rng.gen_bool(0.0005);
        let written = rng.gen_bool(0.003);
        // The stage sees the hold in the same cycle; a restart makes it
        // idle in the next.
        let hold = idle && (m.dirty || written);
        let restart = in_done && !m.restarted && (!m.dirty || m.open == 0);
        let start = idle && !hold && rng.gen_bool(0.1);
        let i = FlIn {
            rst: u8::from(rst),
            in_done: u8::from(in_done),
            idle: u8::from(idle),
            idle_next: u8::from((idle && !start) || restart),
            // Frames queue up behind a slow frame end now and then.
            end_sent: u8::from(
                owed > 0 && rng.gen_bool(if cycle % 40_000 < 10_000 { 0.001 } else { 0.02 }),
            ),
            written: u8::from(written),
        };
        let want = m.step(&i);
        let got = d.step(&i);
        assert_eq!(
            format!("{got:?}"),
            format!("{want:?}"),
            "cycle {cycle}, inputs {i:?}, seed {seed:#x}"
        );
        restarts += u32::from(got.restart);
        reloads += u32::from(got.reload);
        held += u32::from(got.start_hold);
        if rst {
            (idle, running, in_done, owed) = (true, false, false, 0);
            continue;
        }
        owed -= u32::from(i.end_sent);
        if restart {
            (idle, in_done) = (true, false);
        } else if start {
            (idle, running) = (false, true);
        } else if running && rng.gen_bool(0.01) {
            // The frame's last pixel: its end beat is owed from now.
            (running, in_done, owed) = (false, true, owed + 1);
            most = most.max(owed);
        }
    }
    // More than three frames in the datapath at once (a 2-bit count wrapped).
    assert!(
        restarts > 500 && reloads > 50 && held > 500 && most > 4,
        "restarts {restarts}, reloads {reloads}, held {held}, frames in the datapath at most {most}"
    );
    eprintln!("restarts {restarts}, reloads {reloads}, held {held}, frames in the datapath at most {most}");
}
