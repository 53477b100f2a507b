//! The frame-phase machine `fcc_frame_phase` alone under Verilator, against
//! a software machine written from its module documentation: INIT until the
//! merge table is initialised, RUN until the frame's last slot is in, DRAIN
//! until the last joins are sent and the union engine and join queue are
//! idle, OUT until the read-back is done; `out_start` and `restart` pulse at
//! those two edges, `run_next` / `out_next` show the phase after the edge,
//! and `rst` returns to INIT. Directed frames back to back, then seeded random
//! inputs with resets. A mismatch prints the cycle, the phase, expected, got
//! and the seed.

use fcc_params::FccParams;
use fcc_rtl::BenchBlock;
use fcc_sim::{c_struct, load_plain, PlainDut};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

c_struct! {
    /// Inputs of one cycle, named as the ports.
    pub struct FpIn {
        pub rst: u8,
        pub in_done: u8,
        pub init_busy: u8,
        pub last_done: u8,
        pub union_idle: u8,
        pub jq_empty: u8,
        pub rb_done: u8,
    }
}

c_struct! {
    /// Outputs during one cycle.
    #[derive(PartialEq, Eq)]
    pub struct FpOut {
        pub run: u8,
        pub restart: u8,
        pub out_start: u8,
        pub run_next: u8,
        pub out_next: u8,
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
enum Phase {
    #[default]
    Init,
    Run,
    Drain,
    Out,
}

#[derive(Default)]
struct Model {
    phase: Phase,
    last_seen: bool,
}

impl Model {
    /// The outputs before the clock edge, then the edge.
    fn step(&mut self, i: &FpIn) -> FpOut {
        let on = |v: u8| v != 0;
        let drained = self.last_seen && on(i.union_idle) && on(i.jq_empty);
        let mut next = self.phase;
        let mut last_seen = self.last_seen || on(i.last_done);
        let mut o = FpOut {
            run: (self.phase == Phase::Run) as u8,
            ..FpOut::default()
        };
        match self.phase {
            Phase::Init if !on(i.init_busy) => next = Phase::Run,
            Phase::Run if on(i.in_done) => next = Phase::Drain,
            Phase::Drain if drained => {
                next = Phase::Out;
                o.out_start = 1;
            }
            Phase::Out if on(i.rb_done) => {
                next = Phase::Run;
                o.restart = 1;
                last_seen = false;
            }
            _ => {}
        }
        if on(i.rst) {
            next = Phase::Init;
            last_seen = false;
        }
        o.run_next = (next == Phase::Run) as u8;
        o.out_next = (next == Phase::Out) as u8;
        self.phase = next;
        self.last_seen = last_seen;
        o
    }
}

fn run(cycles: &[FpIn], what: &str, seed: u64) {
    let p = FccParams::default();
    let model = load_plain::<FpIn, FpOut>(BenchBlock::FramePhase, &p).expect("frame phase model");
    let mut dut = PlainDut::new(model);
    let mut m = Model::default();
    for (t, i) in cycles.iter().enumerate() {
        let phase = m.phase;
        let want = m.step(i);
        let got = dut.step(i);
        assert_eq!(
            got, want,
            "{what}: outputs differ at cycle {t} in {phase:?} (input {i:?}): expected {want:?}, got {got:?}, seed {seed}"
        );
    }
}

/// Idle inputs: nothing happens, the engines are idle.
fn idle() -> FpIn {
    FpIn {
        union_idle: 1,
        jq_empty: 1,
        ..FpIn::default()
    }
}

#[test]
fn frames_back_to_back_and_a_reset_in_each_phase() {
    let mut c = vec![FpIn { rst: 1, ..idle() }];
    c.extend((0..4).map(|_| FpIn {
        init_busy: 1,
        ..idle()
    }));
    for frame in 0..3 {
        c.extend((0..3).map(|_| idle()));
        c.push(FpIn {
            in_done: 1,
            ..idle()
        });
        // The last joins: busy engines hold DRAIN after `last_done`.
        c.push(FpIn {
            union_idle: 0,
            ..idle()
        });
        c.push(FpIn {
            last_done: 1,
            jq_empty: 0,
            ..idle()
        });
        c.push(FpIn {
            union_idle: 0,
            ..idle()
        });
        c.extend((0..3).map(|_| idle()));
        c.push(FpIn {
            rb_done: 1,
            ..idle()
        });
        // A reset in RUN, in DRAIN and in OUT of the later frames.
        if frame > 0 {
            c.push(FpIn {
                in_done: (frame == 2) as u8,
                ..idle()
            });
            c.push(FpIn { rst: 1, ..idle() });
            c.push(FpIn {
                init_busy: 1,
                ..idle()
            });
        }
    }
    run(&c, "directed", 0);
}

#[test]
fn seeded_random_inputs_with_resets() {
    for seed in 0..8u64 {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut c = vec![FpIn { rst: 1, ..idle() }];
        for _ in 0..5_000 {
            let mut b = |p: f64| rng.gen_bool(p) as u8;
            c.push(FpIn {
                rst: b(0.005),
                in_done: b(0.1),
                init_busy: b(0.3),
                last_done: b(0.1),
                union_idle: b(0.7),
                jq_empty: b(0.7),
                rb_done: b(0.1),
            });
        }
        run(&c, "random", seed);
    }
}
