//! The column core's union-find over labels `fcc_label_sets` alone under
//! Verilator, against a model of its contract (docs/column-core.md, item
//! 3): makes, finds and joins over labels that are made, merged, closed
//! (their cluster's labels freed at once) and made again with new slots,
//! many times over; ops offered in bursts and sparse, with makes beside
//! them; deep trees; a reset mid-run. Every event is checked, in op order:
//! a find's root and slot, a join's roots and slots kept and gone (the
//! second label's root keeps its slot when the join files a run just
//! started under the second's cluster, else the smaller root) and whether
//! it merged two sets. A mismatch
//! prints the op, expected, got and the seed.

use std::collections::VecDeque;

use crate::column;
use column::forest::Forest;

use fcc_params::FccParams;
use fcc_rtl::BenchBlock;
use fcc_sim::{c_struct, load_plain, PlainDut, PlainModel};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

c_struct! {
    /// Inputs of one cycle, named as the ports.
    pub struct SetsIn {
        pub rst: u8,
        pub mk_valid: u8,
        pub mk_label: u16,
        pub mk_slot: u16,
        pub op_valid: u8,
        pub op_join: u8,
        pub op_under: u8,
        pub op_a: u16,
        pub op_b: u16,
    }
}

c_struct! {
    /// Outputs during one cycle.
    pub struct SetsOut {
        pub op_take: u8,
        pub mk_ready: u8,
        pub ev_valid: u8,
        pub ev_join: u8,
        pub ev_merged: u8,
        pub ev_keep: u16,
        pub ev_keep_slot: u16,
        pub ev_gone: u16,
        pub ev_gone_slot: u16,
        pub idle: u8,
    }
}

/// An op and the event it must give.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Ev {
    join: bool,
    merged: bool,
    keep: u16,
    keep_slot: u16,
    gone: u16,
    gone_slot: u16,
}

#[derive(Debug, Clone, Copy)]
struct Op {
    join: bool,
    under: bool,
    a: u16,
    b: u16,
}

/// The contract: the forest over labels and the free slots.
struct Model {
    f: Forest,
    free_slots: Vec<u16>,
}

impl Model {
    fn new(labels: usize) -> Model {
        Model {
            f: Forest::new(labels),
            free_slots: (0..512).rev().collect(),
        }
    }

    fn make(&mut self, l: u16) -> u16 {
        let s = self.free_slots.pop().expect("a free slot");
        self.f.make(l, s);
        s
    }

    fn apply(&mut self, op: Op) -> Ev {
        if !op.join {
            let ra = self.f.root(op.a);
            return Ev {
                join: false,
                merged: false,
                keep: ra,
                keep_slot: self.f.slot[ra as usize],
                gone: 0,
                gone_slot: 0,
            };
        }
        let (keep, gone, merged) = self.f.join(op.a, op.b, op.under);
        if merged {
            self.free_slots.push(self.f.slot[gone as usize]);
        }
        Ev {
            join: true,
            merged,
            keep,
            keep_slot: self.f.slot[keep as usize],
            gone,
            gone_slot: self.f.slot[gone as usize],
        }
    }

    /// Close cluster `c`: its labels are free again.
    fn close(&mut self, c: usize) -> Vec<u16> {
        let (labels, s) = self.f.close(c);
        self.free_slots.push(s);
        labels
    }
}

/// The event as the block gave it.
fn got(o: &SetsOut) -> Ev {
    Ev {
        join: o.ev_join != 0,
        merged: o.ev_merged != 0,
        keep: o.ev_keep,
        keep_slot: o.ev_keep_slot,
        gone: if o.ev_join != 0 { o.ev_gone } else { 0 },
        gone_slot: if o.ev_join != 0 { o.ev_gone_slot } else { 0 },
    }
}

/// Drives the block: a bench-side queue of ops (with the events they must
/// give) and makes on the cycle they are decided.
struct Bench {
    d: PlainDut<SetsIn, SetsOut>,
    queue: VecDeque<Op>,
    expect: VecDeque<(Op, Ev)>,
    cycle: u64,
    ops: u64,
    events: u64,
    merged: u64,
    what: String,
}

impl Bench {
    fn new(model: &PlainModel<SetsIn, SetsOut>, what: String) -> Bench {
        let mut b = Bench {
            d: PlainDut::new(model.clone()),
            queue: VecDeque::new(),
            expect: VecDeque::new(),
            cycle: 0,
            ops: 0,
            events: 0,
            merged: 0,
            what,
        };
        b.step(None, true);
        b
    }

    /// One cycle: a make (label, slot) if any; the queue's head offered.
    /// Whether the make was taken.
    fn step(&mut self, mk: Option<(u16, u16)>, rst: bool) -> bool {
        let head = self.queue.front().copied().filter(|_| !rst);
        let inp = SetsIn {
            rst: rst as u8,
            mk_valid: mk.is_some() as u8,
            mk_label: mk.map_or(0, |m| m.0),
            mk_slot: mk.map_or(0, |m| m.1),
            op_valid: head.is_some() as u8,
            op_join: head.is_some_and(|o| o.join) as u8,
            op_under: head.is_some_and(|o| o.under) as u8,
            op_a: head.map_or(0, |o| o.a),
            op_b: head.map_or(0, |o| o.b),
        };
        let o = self.d.step(&inp);
        self.cycle += 1;
        if rst {
            self.queue.clear();
            self.expect.clear();
            return false;
        }
        if o.ev_valid != 0 {
            let (op, want) = self.expect.pop_front().unwrap_or_else(|| {
                panic!(
                    "{}, cycle {}: an event with no op left: {:?}",
                    self.what,
                    self.cycle,
                    got(&o)
                )
            });
            assert_eq!(
                got(&o),
                want,
                "{}, cycle {}, op {} {op:?}: expected (left), got (right)",
                self.what,
                self.cycle,
                self.events
            );
            self.events += 1;
            self.merged += u64::from(want.merged);
        }
        if o.idle != 0 {
            assert!(
                self.expect.len() == self.queue.len(),
                "{}, cycle {}: idle with {} events to come",
                self.what,
                self.cycle,
                self.expect.len() - self.queue.len()
            );
        }
        if o.op_take != 0 {
            assert!(head.is_some(), "{}: op_take with no op", self.what);
            self.queue.pop_front();
            self.ops += 1;
        }
        mk.is_some() && o.mk_ready != 0
    }

    /// Offer a make until it is taken (a few cycles at most: while a join
    /// may retire).
    fn make(&mut self, mk: (u16, u16)) {
        for _ in 0..4 {
            if self.step(Some(mk), false) {
                return;
            }
        }
        panic!("{}, cycle {}: make {mk:?} not taken", self.what, self.cycle);
    }

    fn push(&mut self, op: Op, ev: Ev) {
        self.queue.push_back(op);
        self.expect.push_back((op, ev));
    }

    /// Step until every op has given its event (at most `limit` cycles).
    fn drain(&mut self, limit: u64) {
        let start = self.cycle;
        while !self.expect.is_empty() {
            self.step(None, false);
            assert!(
                self.cycle - start < limit,
                "{}: {} events still missing after {limit} cycles",
                self.what,
                self.expect.len()
            );
        }
        // The block says idle once the last event is out.
        self.step(None, false);
    }
}

fn params(label_bits: u32) -> FccParams {
    FccParams {
        label_bits,
        ..FccParams::default()
    }
}

/// Seeded traffic over `2^bits - 1` labels: makes, finds and joins at
/// rates changed every few hundred cycles, clusters closed (after the ops
/// naming them have given their events) and their labels made again.
fn random_run(bits: u32, seed: u64, cycles: u64, reset_at: u64) -> (u64, u64, u64, u32) {
    let p = params(bits);
    let model = load_plain::<SetsIn, SetsOut>(BenchBlock::LabelSets, &p).expect("label sets model");
    let labels = p.max_label() as usize;
    let mut b = Bench::new(&model, format!("{bits}-bit labels, seed {seed:#x}"));
    let mut m = Model::new(labels);
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let (mut p_make, mut p_op, mut p_join) = (0.3, 0.5, 0.5);
    // Labels made in the cycle before (named from this cycle on), and a
    // make offered and not yet taken.
    let mut live: Vec<u16> = Vec::new();
    let mut fresh: Vec<u16> = Vec::new();
    let mut pending: Option<(u16, u16)> = None;
    for t in 0..cycles {
        if t % 400 == 0 {
            (p_make, p_op, p_join) = match rng.gen_range(0..4) {
                0 => (0.5, 0.9, 0.8),
                1 => (0.2, 0.3, 0.5),
                2 => (0.05, 1.0, 0.9),
                _ => (0.3, 0.6, 0.3),
            };
        }
        if t == reset_at {
            b.step(None, true);
            m = Model::new(labels);
            live.clear();
            fresh.clear();
            pending = None;
            continue;
        }
        live.append(&mut fresh);
        // Close a cluster now and then, once its ops are done.
        if m.f.clusters.len() > labels / 2 || (rng.gen_bool(0.01) && !m.f.clusters.is_empty()) {
            if let Some(mk) = pending.take() {
                b.make(mk);
                live.push(mk.0);
            }
            b.drain(10_000);
            let c = rng.gen_range(0..m.f.clusters.len());
            for l in m.close(c) {
                live.retain(|&x| x != l);
            }
        }
        if pending.is_none() && rng.gen_bool(p_make) && !m.free_slots.is_empty() {
            let free: Vec<u16> = (1..=labels as u16)
                .filter(|&l| !m.f.made[l as usize])
                .collect();
            if !free.is_empty() {
                let l = free[rng.gen_range(0..free.len())];
                pending = Some((l, m.make(l)));
            }
        }
        if !live.is_empty() && rng.gen_bool(p_op) && b.queue.len() < 8 {
            let a = live[rng.gen_range(0..live.len())];
            let op = if rng.gen_bool(p_join) {
                let bb = live[rng.gen_range(0..live.len())];
                Op {
                    join: true,
                    under: rng.gen_bool(0.5),
                    a,
                    b: bb,
                }
            } else {
                Op {
                    join: false,
                    under: false,
                    a,
                    b: 0,
                }
            };
            let ev = m.apply(op);
            b.push(op, ev);
        }
        if b.step(pending, false) {
            fresh.push(pending.take().expect("a make").0);
        }
    }
    if let Some(mk) = pending {
        b.make(mk);
    }
    b.drain(10_000);
    (b.ops, b.merged, b.cycle, m.f.walk_max)
}

#[test]
fn every_event_follows_the_model_with_labels_made_again() {
    let mut total = (0, 0);
    for (bits, seed, cycles, reset_at) in [
        (8, 0x5e75_0001, 40_000, 17_000),
        (9, 0x5e75_0002, 60_000, 41_000),
        (13, 0x5e75_0003, 30_000, 29_000),
    ] {
        let (ops, merged, cyc, walk) = random_run(bits, seed, cycles, reset_at);
        eprintln!(
            "{bits}-bit labels: {ops} ops, {merged} merges, {cyc} cycles, longest walk {walk}"
        );
        assert!(
            merged > 500 && walk >= 4,
            "{bits}-bit labels: too easy a trace"
        );
        total.0 += ops;
        total.1 += merged;
    }
    eprintln!("total: {} ops, {} merges", total.0, total.1);
}

/// A chain 64 deep: each new label `l` joined as `(top, l)`, so the old
/// root goes under it; then finds from
/// the deepest label and the shallowest in turn (the younger one done
/// first, waiting for the older), and joins from both ends.
#[test]
fn deep_chains_and_finds_done_out_of_order_give_events_in_order() {
    let p = params(8);
    let model = load_plain::<SetsIn, SetsOut>(BenchBlock::LabelSets, &p).expect("label sets model");
    let mut b = Bench::new(&model, "deep chain".into());
    let mut m = Model::new(p.max_label() as usize);
    let top = 64u16;
    let s = m.make(top);
    b.make((top, s));
    for l in (1..top).rev() {
        let s = m.make(l);
        b.make((l, s));
        let op = Op {
            join: true,
            under: false,
            a: top,
            b: l,
        };
        let ev = m.apply(op);
        assert!(ev.merged && ev.keep == l);
        b.push(op, ev);
        b.drain(1_000);
    }
    assert_eq!(m.f.walk_max as u16, top - 1, "the walks down the chain");
    let start = b.cycle;
    let reads = m.f.reads;
    for k in 0..20u16 {
        for a in [top, 1 + k % 5] {
            let op = Op {
                join: false,
                under: false,
                a,
                b: 0,
            };
            let ev = m.apply(op);
            b.push(op, ev);
        }
        let op = Op {
            join: true,
            under: false,
            a: top - k,
            b: 1 + k,
        };
        let ev = m.apply(op);
        assert!(!ev.merged);
        b.push(op, ev);
    }
    b.drain(100_000);
    assert_eq!(m.f.walk_max as u16, top, "the chain is {top} deep");
    let walked = b.cycle - start;
    eprintln!("60 ops on a chain of {top}: {walked} cycles");
    // One read a cycle: the walks read at least as many words as a
    // model walking them reads (the block's chase never reads more).
    let reads = m.f.reads - reads;
    eprintln!("{reads} words read");
    assert!(
        walked >= reads && reads > 40 * 50,
        "{walked} cycles for {reads} words"
    );
}

/// Throughput on sets as the representative rows keep them shallow: 40
/// clusters of 10 labels (each joined to its first, the smallest) and
/// 400 labels made alone, then 400 ops offered all at once: finds of
/// the clusters' labels (one or two words), joins of a label made alone
/// to a cluster's root (one word each), or both mixed. Cycles an op,
/// exact: four ops overlap, so a find takes about two cycles, a word a
/// cycle through the read port (2.60 with two ops in flight); a join, one
/// word a side, retires two cycles after the join before it (its link,
/// then the cycle in which nothing retires).
#[test]
fn shallow_sets_take_a_find_or_a_join_in_two_cycles() {
    let p = params(13);
    let model = load_plain::<SetsIn, SetsOut>(BenchBlock::LabelSets, &p).expect("label sets model");
    let mut rng = ChaCha8Rng::seed_from_u64(0x5e75_0004);
    for (join_share, per) in [(0.0, 1.98), (1.0, 2.02), (0.5, 2.0)] {
        let mut b = Bench::new(&model, format!("join share {join_share}"));
        let mut m = Model::new(p.max_label() as usize);
        let mut made = Vec::new();
        for l in 1..=400u16 {
            let s = m.make(l);
            b.make((l, s));
            made.push(l);
        }
        for c in 0..40u16 {
            for k in 1..10u16 {
                let op = Op {
                    join: true,
                    under: false,
                    a: 1 + c * 10 + k,
                    b: 1 + c * 10,
                };
                let ev = m.apply(op);
                b.push(op, ev);
            }
        }
        b.drain(100_000);
        for l in 401..=800u16 {
            let s = m.make(l);
            b.make((l, s));
        }
        let start = b.cycle;
        let n = 400u16;
        let mut next = 401u16;
        for _ in 0..n {
            let op = if rng.gen_bool(join_share) {
                next += 1;
                Op {
                    join: true,
                    under: true,
                    a: next - 1,
                    b: 1 + 10 * rng.gen_range(0..40u16),
                }
            } else {
                Op {
                    join: false,
                    under: false,
                    a: made[rng.gen_range(0..made.len())],
                    b: 0,
                }
            };
            let ev = m.apply(op);
            b.push(op, ev);
        }
        b.drain(100_000);
        let cycles = b.cycle - start;
        eprintln!(
            "join share {join_share}: {cycles} cycles for {n} ops, {:.2} an op (walks up to {})",
            cycles as f64 / f64::from(n),
            m.f.walk_max
        );
        // The last event's latency and the drain's closing cycle on top.
        let bound = (per * f64::from(n)) as u64 + 8;
        assert!(
            cycles <= bound,
            "join share {join_share}: {cycles} cycles, at most {bound}"
        );
    }
}
