//! The core's AXI4-Stream input stage `fcc_input_stage` (behind
//! `FccInputStageProbe`, its slot field by field) alone under Verilator,
//! against a software stage written from its module documentation: slot k
//! of a frame is pixel (k / C, k % C) with its first / last / column flags
//! (in column order, `fcc_col_input_stage`: pixel (k % R, k / R)),
//! a beat's x, y, z offset binary and its valid bit as `ok`; a frame that
//! ends early is padded with empty slots, one that ends late has its beats
//! dropped up to its `tlast`, either sets `err` until the next frame starts;
//! `s_axis_tready` and the padding are registered from the frame phase and
//! the credits' `room`; `rst_next` drops the ready a cycle ahead of `rst`.
//! In column order a column's first slot (`col_first`) waits while
//! `col_hold` is high: no beat, no padding slot, the ready low; the
//! raster order ignores `col_hold`.
//!
//! A software frame phase (INIT, RUN until `in_done`, DRAIN, OUT, RUN again
//! with `restart`) and a source of frames (exact, short and long, random
//! gaps, data held until taken) drive it, for several frame sizes, with and
//! without resets. Every output is compared in every cycle after the first
//! reset (a slot's fields while it is valid). A mismatch prints the size,
//! the cycle, the output, expected, got and the seed.

use fcc_params::FccParams;
use fcc_rtl::BenchBlock;
use fcc_sim::{c_struct, load_plain, PlainDut};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

c_struct! {
    /// Inputs of one cycle, named as the ports.
    pub struct IsIn {
        pub s_axis_tdata: u64,
        pub run_cols: u16,
        pub run_rows: u8,
        pub rst: u8,
        pub rst_next: u8,
        pub s_axis_tvalid: u8,
        pub s_axis_tlast: u8,
        pub run: u8,
        pub restart: u8,
        pub run_next: u8,
        pub room: u8,
        pub col_hold: u8,
    }
}

c_struct! {
    /// Outputs during one cycle.
    #[derive(PartialEq, Eq)]
    pub struct IsOut {
        pub slot_x: u16,
        pub slot_y: u16,
        pub slot_z: u16,
        pub slot_col: u16,
        pub last_col: u16,
        pub slot_row: u8,
        pub s_axis_tready: u8,
        pub slot_now: u8,
        pub slot_valid: u8,
        pub slot_ok: u8,
        pub slot_first: u8,
        pub slot_last: u8,
        pub slot_col0: u8,
        pub slot_coln: u8,
        pub in_done: u8,
        pub err: u8,
        pub idle: u8,
        pub idle_next: u8,
        pub col_first: u8,
    }
}

/// The stage as its documentation states it.
#[derive(Default)]
struct Model {
    rows: usize,
    cols: usize,
    /// The frame comes in column order.
    col_major: bool,
    ready: bool,
    pad_go: bool,
    /// The registered slot: its fields (valid or not).
    slot: IsOut,
    /// Slots of the current frame so far.
    k: usize,
    pad: bool,
    discard: bool,
    done: bool,
    err: bool,
    last_col: u16,
}

impl Model {
    fn new(rows: usize, cols: usize, col_major: bool) -> Self {
        Model {
            rows,
            cols,
            col_major,
            ..Model::default()
        }
    }

    /// The outputs before the clock edge, then the edge.
    fn step(&mut self, i: &IsIn) -> IsOut {
        let b = |x: bool| x as u8;
        let col_first = self.col_major && self.k.is_multiple_of(self.rows) && !self.discard;
        let held = col_first && i.col_hold != 0;
        let accept = i.s_axis_tvalid != 0 && self.ready && !held;
        let beat = accept && !self.discard;
        let slot_now = beat || (self.pad_go && !held);
        let is_last = self.k + 1 == self.rows * self.cols;
        let run = i.run != 0;
        // The next state.
        let mut k = self.k;
        let mut pad = self.pad;
        let mut discard = self.discard;
        let mut done = self.done;
        let mut err = self.err;
        let mut slot = IsOut {
            slot_valid: b(slot_now),
            ..self.slot
        };
        if slot_now {
            let (row, col) = if self.col_major {
                (self.k % self.rows, self.k / self.rows)
            } else {
                (self.k / self.cols, self.k % self.cols)
            };
            let d = i.s_axis_tdata;
            slot.slot_ok = b(beat && (d >> 48) & 1 != 0);
            slot.slot_x = (d as u16) ^ 0x8000;
            slot.slot_y = ((d >> 16) as u16) ^ 0x8000;
            slot.slot_z = ((d >> 32) as u16) ^ 0x8000;
            slot.slot_row = row as u8;
            slot.slot_col = col as u16;
            slot.slot_first = b(self.k == 0);
            slot.slot_last = b(is_last);
            slot.slot_col0 = b(col == 0);
            slot.slot_coln = b(col + 1 == self.cols);
            k += 1;
            if is_last {
                k = 0;
                done = true;
                pad = false;
            }
        }
        if beat && i.s_axis_tlast != 0 && !is_last {
            err = true;
            pad = true;
        }
        if beat && is_last && i.s_axis_tlast == 0 {
            err = true;
            discard = true;
        }
        if self.discard && accept && i.s_axis_tlast != 0 {
            discard = false;
        }
        let mut run_after = run;
        if i.restart != 0 {
            run_after = true;
            done = false;
            err = false;
        }
        let room = i.room != 0;
        let mut ready = discard || (run_after && !done && !pad && room);
        let mut pad_go = pad && run_after && !done && room;
        if i.rst_next != 0 {
            ready = false;
            pad_go = false;
        }
        if i.rst != 0 {
            ready = false;
            pad_go = false;
            slot.slot_valid = 0;
            k = 0;
            pad = false;
            discard = false;
            done = false;
            err = false;
        }
        let out = IsOut {
            s_axis_tready: b(self.ready && !held),
            col_first: b(col_first),
            slot_now: b(slot_now),
            in_done: b(self.done),
            err: b(self.err),
            last_col: self.last_col,
            idle: b(run && !self.done && self.k == 0),
            idle_next: b(i.run_next != 0 && !done && k == 0),
            ..self.slot
        };
        self.ready = ready;
        self.pad_go = pad_go;
        self.slot = slot;
        self.k = k;
        self.pad = pad;
        self.discard = discard;
        self.done = done;
        self.err = err;
        self.last_col = i.run_cols.wrapping_sub(1) & 0xfff;
        out
    }
}

/// The frame phase around the stage, as `fcc_frame_phase` runs it.
#[derive(Clone, Copy, PartialEq, Debug)]
enum Phase {
    Init,
    Run,
    Drain,
    Out,
}

/// A source of frames: each frame's beats, held until taken.
struct Source {
    beats: Vec<(u64, bool)>,
    next: usize,
}

impl Source {
    fn frame(rng: &mut ChaCha8Rng, pixels: usize) -> Vec<(u64, bool)> {
        let n = match rng.gen_range(0..10) {
            0..=5 => pixels,
            6 | 7 => rng.gen_range(1..pixels),
            _ => pixels + rng.gen_range(1..6),
        };
        (0..n)
            .map(|j| (rng.gen::<u64>() & ((1 << 49) - 1), j + 1 == n))
            .collect()
    }
}

/// What differs between two outputs: the first field, expected and got.
fn first_difference(want: &IsOut, got: &IsOut) -> Option<String> {
    let fields: [(&str, u64, u64); 19] = [
        (
            "s_axis_tready",
            want.s_axis_tready.into(),
            got.s_axis_tready.into(),
        ),
        ("col_first", want.col_first.into(), got.col_first.into()),
        ("slot_now", want.slot_now.into(), got.slot_now.into()),
        ("slot_valid", want.slot_valid.into(), got.slot_valid.into()),
        ("in_done", want.in_done.into(), got.in_done.into()),
        ("err", want.err.into(), got.err.into()),
        ("last_col", want.last_col.into(), got.last_col.into()),
        ("idle", want.idle.into(), got.idle.into()),
        ("idle_next", want.idle_next.into(), got.idle_next.into()),
        ("slot_ok", want.slot_ok.into(), got.slot_ok.into()),
        ("slot_x", want.slot_x.into(), got.slot_x.into()),
        ("slot_y", want.slot_y.into(), got.slot_y.into()),
        ("slot_z", want.slot_z.into(), got.slot_z.into()),
        ("slot_row", want.slot_row.into(), got.slot_row.into()),
        ("slot_col", want.slot_col.into(), got.slot_col.into()),
        ("slot_first", want.slot_first.into(), got.slot_first.into()),
        ("slot_last", want.slot_last.into(), got.slot_last.into()),
        ("slot_col0", want.slot_col0.into(), got.slot_col0.into()),
        ("slot_coln", want.slot_coln.into(), got.slot_coln.into()),
    ];
    // A slot's fields count while it is valid.
    let n = if want.slot_valid != 0 { 19 } else { 9 };
    fields[..n]
        .iter()
        .find(|(_, w, g)| w != g)
        .map(|(name, w, g)| format!("{name}: expected {w:#x}, got {g:#x}"))
}

/// The order a stage takes its frame in.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Order {
    Raster,
    Column,
}

/// Run `cycles` cycles of frames of `rows` x `cols` in `order` with resets
/// at the rate `resets`, a column's first slot held now and then; returns
/// the frames that completed, the slots compared and the cycles a slot
/// waited for `col_hold` alone.
fn run(
    order: Order,
    (rows, cols): (usize, usize),
    cycles: usize,
    resets: f64,
    seed: u64,
) -> (usize, usize, usize) {
    let p = FccParams::default();
    let block = match order {
        Order::Raster => BenchBlock::InputStage,
        Order::Column => BenchBlock::ColInputStage,
    };
    let model = load_plain::<IsIn, IsOut>(block, &p).expect("input stage model");
    let mut dut = PlainDut::new(model);
    let mut m = Model::new(rows, cols, order == Order::Column);
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut src = Source {
        beats: Source::frame(&mut rng, rows * cols),
        next: 0,
    };
    let mut phase = Phase::Init;
    let mut wait = 0usize;
    let mut rst_next = true;
    let mut rst = false;
    let mut in_done = false;
    let (mut frames, mut slots, mut held) = (0, 0, 0);
    let mut room = true;
    let mut hold = false;
    for t in 0..cycles {
        // The phase after this edge, from the stage's in_done of this cycle.
        let mut restart = false;
        let mut next = phase;
        match phase {
            Phase::Init | Phase::Drain | Phase::Out if wait > 0 => wait -= 1,
            Phase::Init => next = Phase::Run,
            Phase::Run if in_done => {
                next = Phase::Drain;
                wait = rng.gen_range(0..8);
                frames += 1;
            }
            Phase::Run => {}
            Phase::Drain => {
                next = Phase::Out;
                wait = rng.gen_range(0..8);
            }
            Phase::Out => {
                next = Phase::Run;
                restart = true;
            }
        }
        if rst {
            next = Phase::Init;
            wait = rng.gen_range(0..4);
            restart = false;
        }
        if rng.gen_bool(0.05) {
            room = !room;
        }
        if rng.gen_bool(0.1) {
            hold = !hold;
        }
        let (data, last) = src.beats[src.next];
        let valid = rng.gen_bool(0.7);
        let i = IsIn {
            s_axis_tdata: if valid {
                data
            } else {
                rng.gen::<u64>() & ((1 << 49) - 1)
            },
            run_cols: cols as u16,
            run_rows: rows as u8,
            rst: rst as u8,
            rst_next: rst_next as u8,
            s_axis_tvalid: valid as u8,
            s_axis_tlast: (valid && last) as u8,
            run: (phase == Phase::Run) as u8,
            restart: restart as u8,
            run_next: (next == Phase::Run) as u8,
            room: room as u8,
            col_hold: hold as u8,
        };
        let waits = hold && (m.pad_go || (valid && m.ready));
        let want = m.step(&i);
        held += usize::from(waits && want.col_first != 0);
        let got = dut.step(&i);
        if t >= 2 {
            if let Some(d) = first_difference(&want, &got) {
                panic!(
                    "{rows} x {cols} in {order:?} order: outputs differ at cycle {t} (input {i:?}): {d}; expected {want:?}, got {got:?}, seed {seed}"
                );
            }
            slots += want.slot_valid as usize;
        }
        // The source moves on when its beat is taken.
        if valid && want.s_axis_tready != 0 {
            src.next += 1;
            if src.next == src.beats.len() {
                src = Source {
                    beats: Source::frame(&mut rng, rows * cols),
                    next: 0,
                };
            }
        }
        in_done = m.done;
        phase = next;
        rst = rst_next;
        rst_next = rng.gen_bool(resets);
    }
    (frames, slots, held)
}

#[test]
fn frames_exact_short_and_long_with_gaps_and_back_pressure() {
    for order in [Order::Raster, Order::Column] {
        for (seed, (rows, cols)) in [(1, 3), (2, 3), (3, 5), (4, 8), (1, 17), (17, 3)]
            .into_iter()
            .enumerate()
        {
            let (frames, slots, held) = run(order, (rows, cols), 30_000, 0.0, seed as u64);
            assert!(
                frames > 100,
                "{rows} x {cols} in {order:?} order: only {frames} frames completed"
            );
            assert!(
                slots > frames * rows * cols / 2,
                "{rows} x {cols} in {order:?} order: only {slots} slots"
            );
            assert_eq!(
                held > 100,
                order == Order::Column,
                "{rows} x {cols} in {order:?} order: a column's first slot held {held} cycles"
            );
        }
    }
}

#[test]
fn seeded_random_resets_in_every_phase() {
    for order in [Order::Raster, Order::Column] {
        for (seed, (rows, cols)) in [(2, 4), (3, 3), (4, 6)].into_iter().enumerate() {
            let (frames, _, _) = run(order, (rows, cols), 30_000, 0.003, 10 + seed as u64);
            assert!(
                frames > 50,
                "{rows} x {cols} in {order:?} order: only {frames} frames completed"
            );
        }
    }
}
