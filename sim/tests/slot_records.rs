//! The column core's record store `FccSlotRecords` under Verilator (behind
//! the scalar ports of `FccSlotRecordsProbe`), against a model of its
//! contract (docs/column-core.md, item 3) over the golden record
//! accumulator (`fcc_golden::Acc`, spec §9.3): runs' accumulators added to
//! slots, slots merged into others, closed slots read out, in any order
//! over few slots (an op on the slot of the op before it, often) and many;
//! ops offered in bursts and sparse; a reset mid-run. Every closed record
//! is checked, field by field, in the cycle it must come out, and the
//! cycles an op takes are counted exactly. A mismatch prints the close,
//! expected, got and the seed.

use std::collections::VecDeque;

use fcc_golden::{Acc, Point};
use fcc_params::FccParams;
use fcc_rtl::{BenchBlock, SLOT_RECORDS_LATENCY};
use fcc_sim::core_form::CoreAcc;
use fcc_sim::{c_struct, load_plain, PlainDut, PlainModel};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

c_struct! {
    /// Inputs of one cycle, named as the ports.
    pub struct SrIn {
        pub rst: u8,
        pub op_valid: u8,
        pub merge: u8,
        pub close: u8,
        pub slot: u16,
        pub other: u16,
        pub a_points: u32,
        pub a_min_col: u16,
        pub a_max_col: u16,
        pub a_lo_has: u8,
        pub a_lo_max: u16,
        pub a_hi_has: u8,
        pub a_hi_min: u16,
        pub a_first_row: u8,
        pub a_last_row: u8,
        pub a_min_x: u16,
        pub a_min_y: u16,
        pub a_min_z: u16,
        pub a_max_x: u16,
        pub a_max_y: u16,
        pub a_max_z: u16,
        pub a_r2_min: u32,
        pub a_r2_max: u32,
        pub a_sa: u64,
        pub a_sb: u64,
        pub a_sc: u64,
        pub a_sxx: u64,
        pub a_syy: u64,
        pub a_sab: u64,
        pub a_seam: u8,
    }
}

c_struct! {
    /// Outputs during one cycle.
    pub struct SrOut {
        pub op_take: u8,
        pub out_valid: u8,
        pub out_slot: u16,
        pub idle: u8,
        pub o_points: u32,
        pub o_min_col: u16,
        pub o_max_col: u16,
        pub o_lo_has: u8,
        pub o_lo_max: u16,
        pub o_hi_has: u8,
        pub o_hi_min: u16,
        pub o_first_row: u8,
        pub o_last_row: u8,
        pub o_min_x: u16,
        pub o_min_y: u16,
        pub o_min_z: u16,
        pub o_max_x: u16,
        pub o_max_y: u16,
        pub o_max_z: u16,
        pub o_r2_min: u32,
        pub o_r2_max: u32,
        pub o_sa: u64,
        pub o_sb: u64,
        pub o_sc: u64,
        pub o_sxx: u64,
        pub o_syy: u64,
        pub o_sab: u64,
        pub o_seam: u8,
    }
}

/// Record slots.
const SLOTS: usize = 512;

#[derive(Debug, Clone, Copy)]
enum Op {
    Add(u16, Acc),
    /// Keep, gone.
    Merge(u16, u16),
    Close(u16),
}

impl Op {
    fn input(&self) -> SrIn {
        let mut i = SrIn {
            op_valid: 1,
            ..SrIn::default()
        };
        match *self {
            Op::Add(s, ref a) => {
                i.slot = s;
                let c = CoreAcc::of(a);
                i.a_points = c.points as u32;
                i.a_min_col = c.min_col as u16;
                i.a_max_col = c.max_col as u16;
                i.a_lo_has = c.lo_has as u8;
                i.a_lo_max = c.lo_max as u16;
                i.a_hi_has = c.hi_has as u8;
                i.a_hi_min = c.hi_min as u16;
                i.a_first_row = c.first_row as u8;
                i.a_last_row = c.last_row as u8;
                i.a_min_x = c.min[0] as u16;
                i.a_min_y = c.min[1] as u16;
                i.a_min_z = c.min[2] as u16;
                i.a_max_x = c.max[0] as u16;
                i.a_max_y = c.max[1] as u16;
                i.a_max_z = c.max[2] as u16;
                i.a_r2_min = c.r2_min as u32;
                i.a_r2_max = c.r2_max as u32;
                i.a_sa = c.sa;
                i.a_sb = c.sb;
                i.a_sc = c.sc;
                i.a_sxx = c.sxx;
                i.a_syy = c.syy;
                i.a_sab = c.sab;
                i.a_seam = c.seam as u8;
            }
            Op::Merge(k, g) => (i.merge, i.slot, i.other) = (1, k, g),
            Op::Close(s) => (i.close, i.slot) = (1, s),
        }
        i
    }
}

/// A record as it came out (a seam span's half it does not have reads 0).
fn got(o: &SrOut) -> CoreAcc {
    let mut a = CoreAcc {
        points: o.o_points.into(),
        min_col: o.o_min_col.into(),
        max_col: o.o_max_col.into(),
        lo_has: o.o_lo_has.into(),
        lo_max: o.o_lo_max.into(),
        hi_has: o.o_hi_has.into(),
        hi_min: o.o_hi_min.into(),
        first_row: o.o_first_row.into(),
        last_row: o.o_last_row.into(),
        min: [o.o_min_x.into(), o.o_min_y.into(), o.o_min_z.into()],
        max: [o.o_max_x.into(), o.o_max_y.into(), o.o_max_z.into()],
        r2_min: o.o_r2_min.into(),
        r2_max: o.o_r2_max.into(),
        sa: o.o_sa,
        sb: o.o_sb,
        sc: o.o_sc,
        sxx: o.o_sxx,
        syy: o.o_syy,
        sab: o.o_sab,
        seam: o.o_seam.into(),
    };
    if a.lo_has == 0 {
        a.lo_max = 0;
    }
    if a.hi_has == 0 {
        a.hi_min = 0;
    }
    a
}

/// The block, the ops waiting for it, the model (each op applied as the
/// block takes it, ops taking effect in order) and the closed records
/// due, each with the cycle it must come out in.
struct Bench {
    d: PlainDut<SrIn, SrOut>,
    queue: VecDeque<Op>,
    slots: Vec<Acc>,
    due: VecDeque<(u64, u16, CoreAcc)>,
    cycle: u64,
    taken: u64,
    closes: u64,
    idle: bool,
    /// No op may be taken before this cycle (a reset empties the slots).
    clear_until: u64,
    what: String,
}

impl Bench {
    fn new(model: &PlainModel<SrIn, SrOut>, what: String) -> Bench {
        let mut b = Bench {
            d: PlainDut::new(model.clone()),
            queue: VecDeque::new(),
            slots: vec![Acc::default(); SLOTS],
            due: VecDeque::new(),
            cycle: 0,
            taken: 0,
            closes: 0,
            idle: false,
            clear_until: 0,
            what,
        };
        b.reset();
        b
    }

    /// A reset, then the cycles the block empties its slots in: as many
    /// as slots, in which no op is taken.
    fn reset(&mut self) {
        self.step(false, true);
        let start = self.cycle;
        while !self.idle {
            self.step(false, false);
        }
        let cycles = self.cycle - start;
        assert_eq!(
            cycles,
            SLOTS as u64 + 1,
            "{}: cycles until idle after a reset",
            self.what
        );
    }

    /// One cycle: the queue's head offered if `offer`; a reset if `rst`.
    fn step(&mut self, offer: bool, rst: bool) {
        let head = self.queue.front().copied().filter(|_| offer && !rst);
        let mut inp = head.map_or_else(SrIn::default, |op| op.input());
        inp.rst = rst as u8;
        let o = self.d.step(&inp);
        let now = self.cycle;
        self.cycle += 1;
        self.idle = o.idle != 0;
        if rst {
            self.idle = false;
            self.clear_until = now + 1 + SLOTS as u64;
            self.queue.clear();
            self.due.clear();
            self.slots = vec![Acc::default(); SLOTS];
            return;
        }
        if o.out_valid != 0 {
            let (when, slot, want) = self.due.pop_front().unwrap_or_else(|| {
                panic!(
                    "{}, cycle {now}: a record out (slot {}) with no close due",
                    self.what, o.out_slot
                )
            });
            assert_eq!(
                (when, slot),
                (now, o.out_slot),
                "{}, close {}: (cycle, slot) expected (left), got (right)",
                self.what,
                self.closes
            );
            assert_eq!(
                got(&o),
                want,
                "{}, cycle {now}, close {} (slot {slot}): expected (left), got (right)",
                self.what,
                self.closes
            );
            self.closes += 1;
        } else if let Some(&(when, slot, _)) = self.due.front() {
            assert!(
                when > now,
                "{}: the record of slot {slot}, due at cycle {when}, did not come out",
                self.what
            );
        }
        if o.idle != 0 {
            assert!(
                self.due.is_empty(),
                "{}, cycle {now}: idle with {} records due",
                self.what,
                self.due.len()
            );
        }
        if o.op_take != 0 {
            let op =
                head.unwrap_or_else(|| panic!("{}, cycle {now}: op_take with no op", self.what));
            self.queue.pop_front();
            self.apply(op, now);
        }
    }

    fn apply(&mut self, op: Op, now: u64) {
        self.taken += 1;
        match op {
            Op::Add(s, a) => self.slots[s as usize].merge(&a),
            Op::Merge(k, g) => {
                assert_ne!(k, g, "{}: the bench merges a slot into itself", self.what);
                let gone = std::mem::take(&mut self.slots[g as usize]);
                self.slots[k as usize].merge(&gone);
            }
            Op::Close(s) => {
                let r = std::mem::take(&mut self.slots[s as usize]);
                let when = now + SLOT_RECORDS_LATENCY as u64;
                self.due.push_back((when, s, CoreAcc::of(&r)));
            }
        }
    }

    /// Offer every op queued, then close `slots` and step until every
    /// record due is out and the block says idle (at most `limit` cycles).
    fn drain(&mut self, slots: impl IntoIterator<Item = u16>, limit: u64) {
        self.queue.extend(slots.into_iter().map(Op::Close));
        let start = self.cycle;
        while !self.queue.is_empty() || !self.due.is_empty() {
            self.step(true, false);
            assert!(
                self.cycle - start < limit,
                "{}: {} ops and {} records left after {limit} cycles",
                self.what,
                self.queue.len(),
                self.due.len()
            );
        }
        self.step(false, false);
        let o = self.d.step(&SrIn::default());
        self.cycle += 1;
        assert!(o.idle != 0, "{}: not idle once every op is done", self.what);
    }
}

fn coord(rng: &mut ChaCha8Rng) -> i16 {
    match rng.gen_range(0..8) {
        0 => i16::MIN,
        1 => i16::MAX,
        2 => 0,
        3 => rng.gen_range(-3..=3),
        _ => rng.gen(),
    }
}

/// A run's accumulator: 1 to 20 pixels of one row, columns on either side
/// of `C/2`, coordinates at the ends of the Q7.8 range among them.
fn run_acc(rng: &mut ChaCha8Rng, cols: u32) -> Acc {
    let mut a = Acc::default();
    let row = rng.gen_range(0..128);
    let first = rng.gen_range(0..cols);
    for k in 0..rng.gen_range(1..=20u32) {
        let p: Point = [coord(rng), coord(rng), coord(rng)];
        a.add(row, (first + k) % cols, p, cols / 2);
    }
    a.seam = rng.gen_range(0..10) == 0;
    a
}

/// Seeded traffic over `pool` slots (of the 512, from a random base): adds,
/// merges and closes offered at rates changed every 300 cycles, a reset
/// at `reset_at`; every slot closed at the end. Returns (ops, closes).
fn random_run(
    model: &PlainModel<SrIn, SrOut>,
    seed: u64,
    pool: usize,
    cycles: u64,
    reset_at: Option<u64>,
) -> (u64, u64) {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let cols = [512, 1024, 2048, 4096][(seed % 4) as usize];
    let base = rng.gen_range(0..SLOTS);
    let slot_of = |k: usize| ((base + k) % SLOTS) as u16;
    let what = format!("seed {seed:#x}, {pool} slots");
    let mut b = Bench::new(model, what);
    // The points a slot may reach: the accumulator's widths hold 2^19.
    const FULL: u32 = 300_000;
    let mut rate = 1.0;
    for cycle in 0..cycles {
        if cycle % 300 == 0 {
            rate = [1.0, 0.7, 0.3, 0.05][rng.gen_range(0..4)];
        }
        if b.queue.len() < 4 && rng.gen_bool(rate) {
            let s = slot_of(rng.gen_range(0..pool));
            let g = slot_of(rng.gen_range(0..pool));
            let points = |x: u16| b.slots[x as usize].points;
            let op = match rng.gen_range(0..100) {
                _ if points(s) > FULL => Op::Close(s),
                0..=59 => Op::Add(s, run_acc(&mut rng, cols)),
                60..=84 if g != s && points(s) + points(g) <= FULL => Op::Merge(s, g),
                _ => Op::Close(s),
            };
            b.queue.push_back(op);
        }
        let offer = rng.gen_range(0..10) != 0;
        b.step(offer, reset_at == Some(cycle));
    }
    b.drain((0..pool).map(slot_of), 20 * pool as u64 + 1_000);
    (b.taken, b.closes)
}

fn model() -> PlainModel<SrIn, SrOut> {
    load_plain::<SrIn, SrOut>(BenchBlock::SlotRecords, &FccParams::default())
        .expect("record store model")
}

#[test]
fn records_follow_adds_merges_and_closes_in_order() {
    let model = model();
    let (mut ops, mut closes) = (0, 0);
    for (seed, pool, reset_at) in [
        (0x51, 2, None),
        (0x52, 5, Some(4_000)),
        (0x53, 24, None),
        (0x54, 512, Some(9_000)),
        (0x55, 3, None),
        (0x56, 64, Some(100)),
    ] {
        let (o, c) = random_run(&model, seed, pool, 30_000, reset_at);
        println!("seed {seed:#x}, {pool} slots: {o} ops, {c} records out");
        ops += o;
        closes += c;
    }
    println!("in all: {ops} ops, {closes} records out");
    assert!(
        ops > 50_000 && closes > 10_000,
        "too little traffic: {ops} ops, {closes} closes"
    );
}

/// The cycles from offering `ops` at once to the last one taken, and the
/// records of `touched` slots then checked.
fn cycles_for(model: &PlainModel<SrIn, SrOut>, what: &str, ops: Vec<Op>, touched: &[u16]) -> u64 {
    let mut b = Bench::new(model, what.to_string());
    b.queue.extend(ops);
    let start = b.cycle;
    while !b.queue.is_empty() {
        b.step(true, false);
        assert!(b.cycle - start < 10_000, "{what}: ops left");
    }
    let cycles = b.cycle - start;
    b.drain(touched.iter().copied(), 10_000);
    cycles
}

#[test]
fn an_op_a_cycle_and_four_on_the_slot_just_written() {
    let model = model();
    let mut rng = ChaCha8Rng::seed_from_u64(0x57);
    let n = 400;
    let mut acc = || run_acc(&mut rng, 2048);
    let all: Vec<u16> = (0..SLOTS as u16).collect();
    let cases: Vec<(&str, Vec<Op>, u64)> = vec![
        // Every op on a slot of its own: one a cycle.
        (
            "adds, each to another slot than the last 3",
            (0..n).map(|k| Op::Add((k % SLOTS) as u16, acc())).collect(),
            n as u64,
        ),
        // Each op waits for the write of the one before: four cycles.
        (
            "adds to one slot",
            (0..n).map(|_| Op::Add(7, acc())).collect(),
            4 * (n as u64 - 1) + 1,
        ),
        // Two slots in turn: two ops every four cycles.
        (
            "adds to two slots in turn",
            (0..n).map(|k| Op::Add((k % 2) as u16, acc())).collect(),
            2 * (n as u64 - 2) + 2,
        ),
        // A merge reads two records: two cycles.
        (
            "merges of different pairs",
            (0..n / 2)
                .map(|k| Op::Merge((2 * k) as u16, (2 * k + 1) as u16))
                .collect(),
            n as u64 - 1,
        ),
    ];
    for (what, ops, want) in cases {
        let count = ops.len() as u64;
        let got = cycles_for(&model, what, ops, &all);
        println!(
            "{what}: {count} ops in {got} cycles ({:.2} an op)",
            got as f64 / count as f64
        );
        assert_eq!(got, want, "{what}: cycles expected (left), got (right)");
    }
}
