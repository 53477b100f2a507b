//! The column core's record store `FccSlotRecords` under Verilator (behind
//! the scalar ports of `FccSlotRecordsProbe`), against a model of its
//! contract (docs/column-core.md, items 3 and 4) over the golden record
//! accumulator (`fcc_golden::Acc`, spec §9.3) and the holds of spec §9.2:
//! runs started and flushed into slots, slots merged into others, closes
//! at a column (a record leaves only if nothing holds its cluster; at the
//! frame's last column hold 1 no longer counts) and at the frame end, each naming the cluster's first pixel or, now and then,
//! another (a stale report: the record stays), peeks (a slot with a
//! record reported, whatever holds it), in any order over few slots (an op on the slot of the op
//! before it, often) and many; ops offered in bursts and sparse; resets
//! mid-run. Every record out and every quiet report is checked, field by
//! field, in the cycle it is due, none comes that is not, and the cycles
//! an op takes are counted exactly. A mismatch prints what, expected, got
//! and the seed.

use std::collections::VecDeque;

use fcc_golden::{Acc, Point};
use fcc_params::FccParams;
use fcc_rtl::{BenchBlock, CLOSE_KEY_BITS, SLOT_RECORDS_LATENCY};
use fcc_sim::core_form::CoreAcc;
use fcc_sim::{c_struct, core_acc_out, load_plain, PlainDut, PlainModel};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

c_struct! {
    /// Inputs of one cycle, named as the ports.
    pub struct SrIn {
        pub rst: u8,
        pub half: u8,
        pub last_col: u16,
        pub op_valid: u8,
        pub merge: u8,
        pub close: u8,
        pub frame_end: u8,
        pub peek: u8,
        pub slot: u16,
        pub other: u16,
        pub col: u16,
        pub h_open: u8,
        pub h_ring: u8,
        pub h_first: u32,
        pub h_head: u16,
        pub h_tail: u16,
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
    pub struct SrOut with acc_out {
        pub op_take: u8,
        pub out_valid: u8,
        pub out_slot: u16,
        pub q_valid: u8,
        pub q_slot: u16,
        pub q_first: u32,
        pub q_last: u16,
        pub q_col: u16,
        pub out_head: u16,
        pub out_tail: u16,
        pub link_valid: u8,
        pub link_from: u16,
        pub link_to: u16,
        pub idle: u8,
    }
}

/// Record slots.
const SLOTS: usize = 512;
/// No first pixel: the empty holds'.
const NO_FIRST: u32 = (1 << CLOSE_KEY_BITS) - 1;

/// A run's start or flush: its accumulator (none for a start), the open
/// runs it adds (+1 or -1), its ring flag and first pixel.
#[derive(Debug, Clone, Copy)]
struct Word {
    acc: Acc,
    open: i8,
    ring: bool,
    first: u32,
    /// A start's list of one label; none for a flush.
    ends: Option<(u16, u16)>,
}

#[derive(Debug, Clone, Copy)]
enum Op {
    Add(u16, Word, u16),
    /// Keep, gone, column.
    Merge(u16, u16, u16),
    /// Slot, column and the first pixel it names (`None`: the slot's when
    /// the op is offered, all ops before it taken).
    Close(u16, u16, Option<u32>),
    End(u16, Option<u32>),
    /// Slot, column: reported if it has a record, left as it is.
    Peek(u16, u16),
}

impl Op {
    /// The first pixel a close or end names, with `slots` as the op is taken.
    fn key(key: Option<u32>, s: u16, slots: &[Slot]) -> u32 {
        key.unwrap_or(slots[s as usize].first)
    }

    fn input(&self, slots: &[Slot]) -> SrIn {
        let mut i = SrIn {
            op_valid: 1,
            ..SrIn::default()
        };
        match *self {
            Op::Add(s, ref w, col) => {
                (i.slot, i.col) = (s, col);
                (i.h_open, i.h_ring, i.h_first) = (w.open as u8, w.ring as u8, w.first);
                (i.h_head, i.h_tail) = w.ends.unwrap_or((0, 0));
                let c = CoreAcc::of(&w.acc);
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
            Op::Merge(k, g, col) => (i.merge, i.slot, i.other, i.col) = (1, k, g, col),
            Op::Close(s, col, k) => {
                (i.close, i.slot, i.col) = (1, s, col);
                i.h_first = Op::key(k, s, slots);
            }
            Op::End(s, k) => (i.frame_end, i.slot, i.h_first) = (1, s, Op::key(k, s, slots)),
            Op::Peek(s, col) => (i.peek, i.slot, i.col) = (1, s, col),
        }
        i
    }
}

/// A quiet report: first pixel, last column, quiet column.
type Quiet = (u32, u16, u16);
/// Two lists' link: the first one's tail, the second one's head.
type Link = (u16, u16);

/// A slot in the model: the record and the holds.
#[derive(Debug, Clone, Copy)]
struct Slot {
    acc: Acc,
    open: u8,
    ring: bool,
    first: u32,
    quiet: u16,
    /// Its labels' list's first and last.
    ends: Option<(u16, u16)>,
}

impl Default for Slot {
    fn default() -> Self {
        Slot {
            acc: Acc::default(),
            open: 0,
            ring: false,
            first: NO_FIRST,
            quiet: 0,
            ends: None,
        }
    }
}

impl Slot {
    /// Take in `o`'s runs at column `col`; the quiet report if the slot
    /// is left quiet: (first pixel, last column, quiet column); the link
    /// of the two lists, `o`'s after this one's.
    fn merge(&mut self, o: &Slot, col: u16) -> (Option<Quiet>, Option<Link>) {
        let link = match (self.ends, o.ends) {
            (Some((h, t)), Some((oh, ot))) => {
                self.ends = Some((h, ot));
                Some((t, oh))
            }
            (None, e) => {
                self.ends = e;
                None
            }
            (Some(_), None) => None,
        };
        self.acc.merge(&o.acc);
        self.open = self.open.wrapping_add(o.open);
        self.ring |= o.ring;
        self.first = self.first.min(o.first);
        if self.open == 0 {
            self.quiet = col;
        }
        let last = CoreAcc::of(&self.acc).max_col as u16;
        let quiet = (self.open == 0 && !self.ring).then_some((self.first, last, self.quiet));
        (quiet, link)
    }

    /// Whether a close at `col` (`None`: at the frame end) naming first
    /// pixel `key` takes the record, or would but for the key (`.1`). At
    /// the frame's last column `last_col` hold 1 no longer counts.
    fn leaves(&self, col: Option<u16>, half: u16, last_col: u16, key: u32) -> (bool, bool) {
        let due = self.due(col, half, last_col);
        (due && self.first == key, due && self.first != key)
    }

    fn due(&self, col: Option<u16>, half: u16, last_col: u16) -> bool {
        let last = CoreAcc::of(&self.acc).max_col as u16;
        self.acc.points > 0
            && col.is_none_or(|c| {
                self.open == 0
                    && !self.ring
                    && self.quiet <= c
                    && (last + half <= c || c == last_col)
            })
    }

    /// Whether hold 1 alone would keep the record after `col` but for the
    /// last column.
    fn window_held(&self, col: u16, half: u16) -> bool {
        CoreAcc::of(&self.acc).max_col as u16 + half > col
    }
}

/// What the runs saw, to show each rule was exercised.
#[derive(Debug, Default, Clone, Copy)]
struct Seen {
    ops: u64,
    out_close: u64,
    out_end: u64,
    /// Records out at the last column that hold 1 would have kept.
    out_last: u64,
    closes_held: u64,
    /// Closes and ends that named another first pixel than the slot's and
    /// would have taken the record otherwise.
    key_held: u64,
    quiet: u64,
    /// Peeks that reported a slot.
    peeks: u64,
    /// Lists linked.
    links: u64,
}

/// The block, the ops waiting for it, the model (each op applied as the
/// block takes it, ops taking effect in order), the records and quiet
/// reports due, each with the cycle it must come out in.
struct Bench {
    d: PlainDut<SrIn, SrOut>,
    half: u16,
    last_col: u16,
    queue: VecDeque<Op>,
    slots: Vec<Slot>,
    due: VecDeque<(u64, u16, CoreAcc, (u16, u16))>,
    links: VecDeque<(u64, (u16, u16))>,
    quiet: VecDeque<(u64, u16, (u32, u16, u16))>,
    cycle: u64,
    seen: Seen,
    idle: bool,
    /// No op may be taken before this cycle (a reset empties the slots).
    clear_until: u64,
    what: String,
}

impl Bench {
    fn new(model: &PlainModel<SrIn, SrOut>, half: u16, last_col: u16, what: String) -> Bench {
        let mut b = Bench {
            d: PlainDut::new(model.clone()),
            half,
            last_col,
            queue: VecDeque::new(),
            slots: vec![Slot::default(); SLOTS],
            due: VecDeque::new(),
            links: VecDeque::new(),
            quiet: VecDeque::new(),
            cycle: 0,
            seen: Seen::default(),
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
        let mut inp = head.map_or_else(SrIn::default, |op| op.input(&self.slots));
        inp.rst = rst as u8;
        inp.half = self.half as u8;
        inp.last_col = self.last_col;
        let o = self.d.step(&inp);
        let now = self.cycle;
        self.cycle += 1;
        self.idle = o.idle != 0;
        if rst {
            self.idle = false;
            self.clear_until = now + 1 + SLOTS as u64;
            self.queue.clear();
            self.due.clear();
            self.quiet.clear();
            self.links.clear();
            self.slots = vec![Slot::default(); SLOTS];
            return;
        }
        self.check_out(&o, now);
        self.check_quiet(&o, now);
        self.check_link(&o, now);
        if o.idle != 0 {
            assert!(
                self.due.is_empty() && self.quiet.is_empty(),
                "{}, cycle {now}: idle with {} records and {} quiet reports due",
                self.what,
                self.due.len(),
                self.quiet.len()
            );
        }
        if o.op_take != 0 {
            let op =
                head.unwrap_or_else(|| panic!("{}, cycle {now}: op_take with no op", self.what));
            assert!(
                now >= self.clear_until,
                "{}, cycle {now}: an op taken while the slots are emptied (until cycle {})",
                self.what,
                self.clear_until
            );
            self.queue.pop_front();
            self.apply(op, now);
        }
    }

    fn check_out(&mut self, o: &SrOut, now: u64) {
        if o.out_valid != 0 {
            let (when, slot, want, ends) = self.due.pop_front().unwrap_or_else(|| {
                panic!(
                    "{}, cycle {now}: a record out (slot {}) with none due",
                    self.what, o.out_slot
                )
            });
            assert_eq!(
                (when, slot),
                (now, o.out_slot),
                "{}: record out: (cycle, slot) expected (left), got (right)",
                self.what
            );
            assert_eq!(
                core_acc_out!(o),
                want,
                "{}, cycle {now}, the record of slot {slot}: expected (left), got (right)",
                self.what
            );
            assert_eq!(
                ends,
                (o.out_head, o.out_tail),
                "{}, cycle {now}, the labels' list of slot {slot}: expected (left), got (right)",
                self.what
            );
        } else if let Some(&(when, slot, _, _)) = self.due.front() {
            assert!(
                when > now,
                "{}: the record of slot {slot}, due at cycle {when}, did not come out",
                self.what
            );
        }
    }

    fn check_link(&mut self, o: &SrOut, now: u64) {
        let due = self.links.front().filter(|l| l.0 == now).map(|l| l.1);
        let got = (o.link_valid != 0).then_some((o.link_from, o.link_to));
        assert_eq!(
            due, got,
            "{}, cycle {now}: the lists' link (from, to): expected (left), got (right)",
            self.what
        );
        if due.is_some() {
            self.links.pop_front();
            self.seen.links += 1;
        }
    }

    fn check_quiet(&mut self, o: &SrOut, now: u64) {
        if o.q_valid != 0 {
            let (when, slot, want) = self.quiet.pop_front().unwrap_or_else(|| {
                panic!(
                    "{}, cycle {now}: slot {} reported quiet, none due",
                    self.what, o.q_slot
                )
            });
            assert_eq!(
                (when, slot, want),
                (now, o.q_slot, (o.q_first, o.q_last, o.q_col)),
                "{}: quiet report (cycle, slot, (first pixel, last column, quiet column)): \
                 expected (left), got (right)",
                self.what
            );
            self.seen.quiet += 1;
        } else if let Some(&(when, slot, _)) = self.quiet.front() {
            assert!(
                when > now,
                "{}: slot {slot}'s quiet report, due at cycle {when}, did not come",
                self.what
            );
        }
    }

    fn apply(&mut self, op: Op, now: u64) {
        self.seen.ops += 1;
        let when = now + SLOT_RECORDS_LATENCY as u64;
        let report = match op {
            Op::Add(s, w, col) => {
                let run = Slot {
                    acc: w.acc,
                    open: w.open as u8,
                    ring: w.ring,
                    first: w.first,
                    quiet: 0,
                    ends: w.ends,
                };
                let (quiet, link) = self.slots[s as usize].merge(&run, col);
                if let Some(l) = link {
                    self.links.push_back((when, l));
                }
                quiet.map(|q| (s, q))
            }
            Op::Merge(k, g, col) => {
                assert_ne!(k, g, "{}: the bench merges a slot into itself", self.what);
                let gone = std::mem::take(&mut self.slots[g as usize]);
                // The kept half is read, and written, a cycle after the gone.
                let (kept, link) = self.slots[k as usize].merge(&gone, col);
                if let Some(l) = link {
                    self.links.push_back((when + 1, l));
                }
                if let Some(q) = kept {
                    self.quiet.push_back((when + 1, k, q));
                }
                None
            }
            Op::Close(s, col, k) => self.close(s, Some(col), Op::key(k, s, &self.slots), when),
            Op::End(s, k) => self.close(s, None, Op::key(k, s, &self.slots), when),
            Op::Peek(s, col) => {
                // Its holds merged with none: the op's column is the quiet
                // one if no run is open.
                let x = &self.slots[s as usize];
                let last = CoreAcc::of(&x.acc).max_col as u16;
                let quiet = if x.open == 0 { col } else { x.quiet };
                self.seen.peeks += u64::from(x.acc.points > 0);
                (x.acc.points > 0).then_some((s, (x.first, last, quiet)))
            }
        };
        if let Some((s, q)) = report {
            self.quiet.push_back((when, s, q));
        }
    }

    fn close(
        &mut self,
        s: u16,
        col: Option<u16>,
        key: u32,
        when: u64,
    ) -> Option<(u16, (u32, u16, u16))> {
        let slot = &self.slots[s as usize];
        let (leaves, key_held) = slot.leaves(col, self.half, self.last_col, key);
        self.seen.key_held += u64::from(key_held);
        if leaves && col.is_some_and(|c| slot.window_held(c, self.half)) {
            self.seen.out_last += 1;
        }
        if leaves {
            let r = std::mem::take(&mut self.slots[s as usize]);
            self.due
                .push_back((when, s, CoreAcc::of(&r.acc), r.ends.unwrap_or((0, 0))));
            match col {
                Some(_) => self.seen.out_close += 1,
                None => self.seen.out_end += 1,
            }
        } else if col.is_some() {
            self.seen.closes_held += 1;
        }
        None
    }

    /// Offer every op queued, then close `slots` at the frame end and step
    /// until every record and report due is out and the block says idle
    /// (at most `limit` cycles).
    fn drain(&mut self, slots: impl IntoIterator<Item = u16>, limit: u64) {
        self.queue
            .extend(slots.into_iter().map(|s| Op::End(s, None)));
        let start = self.cycle;
        while !self.queue.is_empty()
            || !self.due.is_empty()
            || !self.quiet.is_empty()
            || !self.links.is_empty()
            || !self.idle
        {
            self.step(true, false);
            assert!(
                self.cycle - start < limit,
                "{}: {} ops, {} records and {} reports left after {limit} cycles",
                self.what,
                self.queue.len(),
                self.due.len(),
                self.quiet.len()
            );
        }
        self.step(false, false);
        assert!(self.idle, "{}: not idle once every op is done", self.what);
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

/// A run's accumulator: 1 to 12 pixels of one row, ending at most 12
/// columns before `col` (a frame of `cols` columns), coordinates at the
/// ends of the Q7.8 range among them.
fn run_acc(rng: &mut ChaCha8Rng, col: u32, cols: u32) -> Acc {
    let mut a = Acc::default();
    let row = rng.gen_range(0..128);
    let n = rng.gen_range(1..=12u32);
    let last = col.saturating_sub(rng.gen_range(0..=12));
    for c in last.saturating_sub(n - 1)..=last {
        let p: Point = [coord(rng), coord(rng), coord(rng)];
        a.add(row, c, p, cols / 2);
    }
    a.seam = rng.gen_range(0..10) == 0;
    a
}

/// The first pixel a close names: the slot's as it is taken, or now and
/// then another (a stale report: `first` with one bit changed).
fn stale(rng: &mut ChaCha8Rng, first: u32) -> Option<u32> {
    (rng.gen_range(0..8) == 0).then(|| first ^ (1 << rng.gen_range(0..CLOSE_KEY_BITS)))
}

/// A run's start at column `col`: one run open, a first pixel of this
/// column, the ring flag now and then.
fn start(rng: &mut ChaCha8Rng, col: u32) -> Word {
    let label = rng.gen_range(1..=u16::MAX);
    Word {
        acc: Acc::default(),
        open: 1,
        ring: rng.gen_range(0..40) == 0,
        first: (col << 7) | rng.gen_range(0..128),
        ends: Some((label, label)),
    }
}

/// A run's flush: its accumulator, one run open less.
fn flush(rng: &mut ChaCha8Rng, col: u32, cols: u32) -> Word {
    Word {
        acc: run_acc(rng, col, cols),
        open: -1,
        ring: false,
        first: NO_FIRST,
        ends: None,
    }
}

/// Seeded traffic over `pool` slots (of the 512, from a random base) in
/// frames whose columns advance every few cycles: runs started and
/// flushed (a flush where the slot has runs open, mostly), merges, closes
/// at the column or a few later, frame-end closes now and then, offered
/// at rates changed every 300 cycles; a reset at `reset_at`; every slot
/// closed at the end.
fn random_run(
    model: &PlainModel<SrIn, SrOut>,
    seed: u64,
    pool: usize,
    cycles: u64,
    reset_at: Option<u64>,
) -> Seen {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let cols = [512, 1024, 2048, 4096][(seed % 4) as usize];
    let half = rng.gen_range(1..=5);
    let base = rng.gen_range(0..SLOTS);
    let slot_of = |k: usize| ((base + k) % SLOTS) as u16;
    let what = format!("seed {seed:#x}, {pool} slots, h = {half}");
    // The last column: the frame's (`cols - 1`), where hold 1 drops.
    let mut b = Bench::new(model, half, (cols - 1) as u16, what);
    // The points a slot may reach: the accumulator's widths hold 2^19.
    const FULL: u32 = 300_000;
    let (mut rate, mut col) = (1.0, 0u32);
    for cycle in 0..cycles {
        if cycle % 300 == 0 {
            rate = [1.0, 0.7, 0.3, 0.05][rng.gen_range(0..4)];
        }
        // The last column lasts longer: closes there drop hold 1.
        if rng.gen_range(0..if col == cols - 1 { 60 } else { 6 }) == 0 {
            col = (col + 1) % cols;
        }
        if b.queue.len() < 4 && rng.gen_bool(rate) {
            let s = slot_of(rng.gen_range(0..pool));
            let g = slot_of(rng.gen_range(0..pool));
            let slot = |x: u16| b.slots[x as usize];
            let c16 = col as u16;
            let op = match rng.gen_range(0..100) {
                _ if slot(s).acc.points > FULL => Op::End(s, None),
                0..=24 => Op::Add(s, start(&mut rng, col), c16),
                25..=49 if slot(s).open > 0 || rng.gen_range(0..8) == 0 => {
                    Op::Add(s, flush(&mut rng, col, cols), c16)
                }
                25..=64 if g != s && slot(s).acc.points + slot(g).acc.points <= FULL => {
                    Op::Merge(s, g, c16)
                }
                98..=99 => Op::End(s, stale(&mut rng, slot(s).first)),
                95..=97 => Op::Peek(s, c16),
                65..=89 => {
                    // A quiet slot, closed at about its due column: just
                    // before, at or just after `last + h`.
                    let k0 = rng.gen_range(0..pool);
                    let quiet = (0..pool).map(|k| slot_of((k0 + k) % pool)).find(|&x| {
                        let q = slot(x);
                        q.open == 0 && !q.ring && q.acc.points > 0
                    });
                    match quiet {
                        Some(x) => {
                            let due = (slot(x).acc.max_col + u32::from(half))
                                .max(u32::from(slot(x).quiet));
                            let mut at = (due + rng.gen_range(0..=2)).saturating_sub(1);
                            if col == cols - 1 && rng.gen_bool(0.5) {
                                at = col;
                            }
                            Op::Close(x, at.min(cols - 1) as u16, stale(&mut rng, slot(x).first))
                        }
                        None => Op::Close(s, c16, None),
                    }
                }
                _ => Op::Close(
                    s,
                    (col + rng.gen_range(0..=6)).min(cols - 1) as u16,
                    stale(&mut rng, slot(s).first),
                ),
            };
            b.queue.push_back(op);
        }
        let offer = rng.gen_range(0..10) != 0;
        b.step(offer, reset_at == Some(cycle));
    }
    b.drain((0..pool).map(slot_of), 20 * pool as u64 + 1_000);
    b.seen
}

fn model() -> PlainModel<SrIn, SrOut> {
    load_plain::<SrIn, SrOut>(BenchBlock::SlotRecords, &FccParams::default())
        .expect("record store model")
}

#[test]
fn records_and_holds_follow_the_ops_in_order() {
    let model = model();
    let mut all = Seen::default();
    for (seed, pool, reset_at) in [
        (0x51, 2, None),
        (0x52, 5, Some(4_000)),
        (0x53, 24, None),
        (0x54, 512, Some(9_000)),
        (0x55, 3, None),
        (0x56, 64, Some(100)),
    ] {
        let s = random_run(&model, seed, pool, 30_000, reset_at);
        println!("seed {seed:#x}, {pool} slots: {s:?}");
        all.ops += s.ops;
        all.out_close += s.out_close;
        all.out_end += s.out_end;
        all.out_last += s.out_last;
        all.closes_held += s.closes_held;
        all.key_held += s.key_held;
        all.peeks += s.peeks;
        all.links += s.links;
        all.quiet += s.quiet;
    }
    println!("in all: {all:?}");
    assert!(
        all.ops > 50_000
            && all.out_close > 2_000
            && all.out_end > 500
            && all.out_last > 0
            && all.closes_held > 10_000
            && all.key_held > 100
            && all.peeks > 500
            && all.links > 2_000
            && all.quiet > 4_000,
        "too little of some traffic: {all:?}"
    );
}

/// Spec §9.2 at the frame's last column: a quiet cluster whose last
/// column is within `h` of it leaves there (hold 1 ends with the frame's
/// columns), while one column earlier hold 1 still keeps such a cluster.
#[test]
fn at_the_last_column_hold_1_no_longer_keeps_a_cluster() {
    const LAST: u16 = 99;
    let model = model();
    let mut rng = ChaCha8Rng::seed_from_u64(0x58);
    let mut b = Bench::new(&model, 3, LAST, "the last column".to_string());
    // A run started and flushed in column `c`: its last column `c`, quiet
    // at `c`.
    let run = |rng: &mut ChaCha8Rng, s: u16, c: u16| {
        let mut acc = Acc::default();
        acc.add(5, u32::from(c), [100, -200, 300], 64);
        let flush = Word {
            acc,
            open: -1,
            ring: false,
            first: NO_FIRST,
            ends: None,
        };
        [
            Op::Add(s, start(rng, u32::from(c)), c),
            Op::Add(s, flush, c),
        ]
    };
    // Slot 7: last column 98, closed at 99 (the last): it leaves. Slot 8:
    // last column 97, closed at 98: held (97 + 3 > 98); it leaves at 99.
    let ops: Vec<Op> = [run(&mut rng, 7, LAST - 1), run(&mut rng, 8, LAST - 2)]
        .into_iter()
        .flatten()
        .chain([
            Op::Close(8, LAST - 1, None),
            Op::Close(7, LAST, None),
            Op::Close(8, LAST, None),
        ])
        .collect();
    b.queue.extend(ops);
    b.drain([], 1_000);
    assert_eq!(
        (b.seen.out_close, b.seen.out_last, b.seen.closes_held),
        (2, 2, 1),
        "(records out at a column, of them at the last column held by hold 1 \
         but for it, closes held): expected (left), got (right)"
    );
}

/// The cycles from offering `ops` at once to the last one taken, and the
/// records of `touched` slots then checked.
fn cycles_for(model: &PlainModel<SrIn, SrOut>, what: &str, ops: Vec<Op>, touched: &[u16]) -> u64 {
    let mut b = Bench::new(model, 3, 4095, what.to_string());
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
fn an_op_a_cycle_on_any_slot() {
    let model = model();
    let mut rng = ChaCha8Rng::seed_from_u64(0x57);
    let n = 400;
    let mut word = |k: usize| match k % 2 {
        0 => start(&mut rng, 100),
        _ => flush(&mut rng, 100, 2048),
    };
    let all: Vec<u16> = (0..SLOTS as u16).collect();
    let cases: Vec<(&str, Vec<Op>, u64)> = vec![
        // Every op on a slot of its own: one a cycle.
        (
            "adds, each to another slot than the last 3",
            (0..n)
                .map(|k| Op::Add((k % SLOTS) as u16, word(k / SLOTS), 100))
                .collect(),
            n as u64,
        ),
        // The writes an op's read misses are forwarded: one a cycle.
        (
            "adds to one slot",
            (0..n).map(|k| Op::Add(7, word(k), 100)).collect(),
            n as u64,
        ),
        (
            "adds to two slots in turn",
            (0..n)
                .map(|k| Op::Add((k % 2) as u16, word(k / 2), 100))
                .collect(),
            n as u64,
        ),
        // Merges into one kept slot, each gone slot written just before.
        (
            "merges into one slot, their gone slots just added to",
            (0..n / 2)
                .flat_map(|k| {
                    let g = (8 + k % 400) as u16;
                    [Op::Add(g, start(&mut rng, 100), 100), Op::Merge(7, g, 100)]
                })
                .collect(),
            3 * (n as u64 / 2) - 1,
        ),
        // A merge reads two records: two cycles.
        (
            "merges of different pairs",
            (0..n / 2)
                .map(|k| Op::Merge((2 * k) as u16, (2 * k + 1) as u16, 100))
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
