//! The column core's row roots `fcc_row_roots` alone under Verilator: pixels
//! in column order with their runs' labels, hold changes, ring checks and
//! pass-2 hits (worked out here from the golden stream's runs and spec §3,
//! §4 and §9.2), against a model of the slots the block hands out. The
//! bench is the slot pool (a FIFO: a merged-away slot goes to its back, so
//! the head holds until taken) and closes clusters as the golden stream
//! does (their slots and labels freed after the column, labels reused at
//! once). Checked:
//!
//! * every pixel event in input order, its run's slot (a new run's: the
//!   slot taken), the slots of the runs its row stops and starts holding;
//! * every merge: between a slot in use and one in use or the pool's head;
//! * after every column (drained feeds) and at the frame end, the clusters
//!   the slots make equal a union-find over the golden runs with spec §4's
//!   pairs in column order and the ring checks: runs in one cluster have
//!   one slot, runs of two clusters two; a cluster the golden stream closes
//!   has one slot, which no other run holds;
//! * no label named is ever missing from its row's roots (`miss`).
//!
//! Seeded random frames (fixed and range-adaptive thresholds, bridge and
//! ring-reach limits), bubbles, frames back to back on one instance, and a
//! small slot pool that makes slots reused. A mismatch prints the frame,
//! pixel, expected, got and the seed.

use std::collections::{HashMap, VecDeque};

mod column;

use column::{build, pixels, random_frame, run_params, Pix};
use fcc_golden::{Frame, Stream, Thresholds};
use fcc_params::FccParams;
use fcc_rtl::BenchBlock;
use fcc_sim::{c_struct, load_plain, PlainDut};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

c_struct! {
    /// Inputs of one cycle, named as the ports.
    pub struct RtIn {
        pub rst: u8,
        pub valid: u8,
        pub ok: u8,
        pub lok: u8,
        pub row: u8,
        pub col: u16,
        pub label: u16,
        pub start: u8,
        pub ring_first: u8,
        pub ring: u8,
        pub ring_a: u16,
        pub ring_b: u16,
        pub hold_drop: u16,
        pub hold_add: u16,
        pub hits: u64,
        pub lw0: u64,
        pub lw1: u64,
        pub lw2: u64,
        pub lw3: u64,
        pub lw4: u64,
        pub lw5: u64,
        pub lw6: u64,
        pub lw7: u64,
        pub lw8: u64,
        pub lw9: u64,
        pub lw10: u64,
        pub lw11: u64,
        pub lw12: u64,
        pub lw13: u64,
        pub last_row: u8,
        pub new_slot: u16,
    }
}

c_struct! {
    /// Outputs during one cycle.
    pub struct RtOut {
        pub ready: u8,
        pub take: u8,
        pub o_valid: u8,
        pub o_lok: u8,
        pub o_row: u8,
        pub o_col: u16,
        pub o_label: u16,
        pub o_start: u8,
        pub o_own: u16,
        pub o_drop_ok: u8,
        pub o_drop: u16,
        pub o_add_ok: u8,
        pub o_add: u16,
        pub m_valid: u8,
        pub m_from: u16,
        pub m_into: u16,
        pub miss: u8,
    }
}

/// A union-find over run numbers.
struct Uf(HashMap<u32, u32>);

impl Uf {
    fn find(&mut self, x: u32) -> u32 {
        let p = *self.0.entry(x).or_insert(x);
        if p == x {
            return x;
        }
        let r = self.find(p);
        self.0.insert(x, r);
        r
    }
    fn union(&mut self, a: u32, b: u32) {
        let (a, b) = (self.find(a), self.find(b));
        if a != b {
            self.0.insert(a, b);
        }
    }
}

/// How a frame is fed.
#[derive(Debug, Clone, Copy)]
struct Feed {
    /// Probability of a bubble before each pixel.
    bubbles: f64,
    /// Wait for every event of a column, check the clusters and close
    /// those the golden stream closes at it before the next column;
    /// otherwise columns go back to back and clusters close at the end.
    drain: bool,
}

struct Bench {
    dut: PlainDut<RtIn, RtOut>,
    k: usize,
    /// The slot pool, head first.
    pool: VecDeque<u16>,
    /// Slots taken, not yet seen at their pixel's event.
    taken: VecDeque<u16>,
    /// Open runs' slots as the events and merges left them.
    slot_of: HashMap<u32, u16>,
    /// Labels: free (reused last freed first) and per open run.
    free_labels: Vec<u16>,
    label_of: HashMap<u32, u16>,
    /// Pixels fed, waiting for their events.
    pending: VecDeque<Pix>,
    merges: u64,
    stalls: u64,
    /// Cycles the input has been held in a row.
    held: u32,
    rings: u64,
    seed: u64,
    what: String,
}

impl Bench {
    fn new(build: &FccParams, slots: usize, seed: u64, what: &str) -> Bench {
        let model =
            load_plain::<RtIn, RtOut>(BenchBlock::RowRoots, build).expect("row roots model");
        Bench {
            dut: PlainDut::new(model),
            k: build.fsize,
            pool: (0..slots as u16).collect(),
            taken: VecDeque::new(),
            slot_of: HashMap::new(),
            free_labels: (1..=u16::MAX).rev().collect(),
            label_of: HashMap::new(),
            pending: VecDeque::new(),
            merges: 0,
            stalls: 0,
            held: 0,
            rings: 0,
            seed,
            what: what.to_string(),
        }
    }

    fn at(&self, px: &Pix) -> String {
        format!(
            "{}: row {}, col {}, seed {}",
            self.what, px.row, px.col, self.seed
        )
    }

    /// The input of a pixel (labels of its runs given out at its start).
    fn input(&mut self, p: &FccParams, px: &Pix) -> RtIn {
        if px.start {
            let l = self.free_labels.pop().expect("labels left");
            self.label_of.insert(px.run, l);
        }
        let lab = |b: &Bench, run: u32| if run == 0 { 0 } else { b.label_of[&run] };
        let mut i = RtIn {
            valid: 1,
            ok: px.ok as u8,
            lok: (px.run != 0) as u8,
            row: px.row as u8,
            col: px.col as u16,
            label: lab(self, px.run),
            start: px.start as u8,
            ring_first: px.ring_first as u8,
            last_row: (p.rows - 1) as u8,
            ..RtIn::default()
        };
        if let Some((a, b)) = px.ring {
            (i.ring, i.ring_a, i.ring_b) = (1, lab(self, a), lab(self, b));
        }
        if let Some((d, a)) = px.hold {
            (i.hold_drop, i.hold_add) = (lab(self, d), lab(self, a));
        }
        let mut words = [0u64; 14];
        for &(e, run) in &px.hits {
            i.hits |= 1 << e;
            words[e / 4] |= (lab(self, run) as u64) << (16 * (e % 4));
        }
        [
            i.lw0, i.lw1, i.lw2, i.lw3, i.lw4, i.lw5, i.lw6, i.lw7, i.lw8, i.lw9, i.lw10, i.lw11,
            i.lw12, i.lw13,
        ] = words;
        i
    }

    /// One cycle; returns whether the input was taken.
    fn cycle(&mut self, p: &FccParams, mut i: RtIn, px: Option<&Pix>) -> bool {
        i.new_slot = self.pool.front().copied().unwrap_or(0);
        i.last_row = (p.rows - 1) as u8;
        let o = self.dut.step(&i);
        assert_eq!(
            o.miss, 0,
            "{}: a label named is not in its row's roots (seed {})",
            self.what, self.seed
        );
        self.event(&o);
        self.merge(&o);
        if o.take != 0 {
            let s = self.pool.pop_front();
            let s = s.unwrap_or_else(|| panic!("{}: a slot taken from an empty pool", self.what));
            self.taken.push_back(s);
        }
        let taken = i.valid != 0 && o.ready != 0;
        if o.ready == 0 {
            self.stalls += 1;
            self.held += 1;
            assert!(
                self.held < 64,
                "{}: the input held for 64 cycles (seed {})",
                self.what,
                self.seed
            );
        } else {
            self.held = 0;
        }
        if taken {
            self.pending.push_back(px.expect("a pixel").clone());
        }
        taken
    }

    fn slot(&self, run: u32) -> u16 {
        self.slot_of[&run]
    }

    fn event(&mut self, o: &RtOut) {
        if o.o_valid == 0 {
            return;
        }
        let px = self
            .pending
            .pop_front()
            .expect("an event with no pixel fed");
        let at = self.at(&px);
        assert_eq!(
            (
                o.o_row as usize,
                o.o_col as usize,
                o.o_lok != 0,
                o.o_start != 0
            ),
            (px.row, px.col, px.run != 0, px.start),
            "{at}: (row, col, labelled, start) of the next event"
        );
        if px.start {
            let s = self
                .taken
                .pop_front()
                .expect("a start without a slot taken");
            self.slot_of.insert(px.run, s);
        }
        if px.run != 0 {
            assert_eq!(o.o_own, self.slot(px.run), "{at}: the run's slot");
        }
        let (d, a) = px.hold.unwrap_or((0, 0));
        assert_eq!(
            (o.o_drop_ok != 0, o.o_add_ok != 0),
            (d != 0, a != 0),
            "{at}: hold changes"
        );
        if d != 0 {
            assert_eq!(
                o.o_drop,
                self.slot(d),
                "{at}: the slot the row stops holding"
            );
        }
        if a != 0 {
            assert_eq!(
                o.o_add,
                self.slot(a),
                "{at}: the slot the row starts holding"
            );
        }
    }

    fn merge(&mut self, o: &RtOut) {
        if o.m_valid == 0 {
            return;
        }
        let (from, into) = (o.m_from, o.m_into);
        let ctx = format!(
            "{}: merge {from} into {into}, seed {}",
            self.what, self.seed
        );
        assert_ne!(from, into, "{ctx}: a slot into itself");
        let live = |s: u16| {
            self.slot_of
                .values()
                .chain(self.taken.iter())
                .any(|&v| v == s)
        };
        assert!(live(from), "{ctx}: from a slot no open run holds");
        assert!(live(into), "{ctx}: into a slot not in use");
        for v in self.slot_of.values_mut().chain(self.taken.iter_mut()) {
            if *v == from {
                *v = into;
            }
        }
        self.pool.push_back(from);
        self.merges += 1;
    }

    /// A reset: the block and the bench forget everything in flight, every
    /// slot and label is free again.
    fn reset(&mut self, p: &FccParams, slots: usize) {
        let i = RtIn {
            rst: 1,
            ..RtIn::default()
        };
        self.cycle(p, i, None);
        self.pending.clear();
        self.taken.clear();
        self.slot_of.clear();
        self.label_of.clear();
        self.free_labels = (1..=u16::MAX).rev().collect();
        self.pool = (0..slots as u16).collect();
    }

    /// Bubbles until every pixel fed has its event (and its merges).
    fn drain(&mut self, p: &FccParams) {
        let mut n = 0;
        while !self.pending.is_empty() || n < 3 {
            n = if self.pending.is_empty() { n + 1 } else { 0 };
            self.cycle(p, RtIn::default(), None);
        }
    }

    /// The clusters the slots make against the union-find's, over the open
    /// runs.
    fn check_clusters(&self, uf: &mut Uf, at: &str) {
        let mut root_slot: HashMap<u32, (u16, u32)> = HashMap::new();
        let mut slot_root: HashMap<u16, (u32, u32)> = HashMap::new();
        for (&run, &s) in &self.slot_of {
            let root = uf.find(run);
            let (s0, r0) = *root_slot.entry(root).or_insert((s, run));
            assert_eq!(
                s, s0,
                "{at}: runs {run} and {r0} are one cluster but have slots {s} and {s0}"
            );
            let (root0, r1) = *slot_root.entry(s).or_insert((root, run));
            assert_eq!(
                root, root0,
                "{at}: runs {run} and {r1} are two clusters but share slot {s}"
            );
        }
    }

    /// Close the clusters with these pixels: one slot each, freed with
    /// their labels.
    fn close(&mut self, p: &FccParams, runs: &[u32], clusters: &[Vec<u32>], at: &str) {
        for px in clusters {
            let mut rs: Vec<u32> = px.iter().map(|&k| runs[k as usize]).collect();
            rs.sort_unstable();
            rs.dedup();
            let s = self.slot(rs[0]);
            for &r in &rs {
                assert_eq!(
                    self.slot(r),
                    s,
                    "{at}: a closing cluster's runs have two slots"
                );
                self.slot_of.remove(&r);
                let l = self.label_of.remove(&r).expect("a label");
                self.free_labels.push(l);
            }
            assert!(
                !self.slot_of.values().any(|&v| v == s),
                "{at}: a closing cluster's slot {s} is held by another run"
            );
            self.pool.push_back(s);
        }
        let _ = p;
    }
}

/// Stream `f` through the bench and check it (see the file's comment).
fn run_frame(b: &mut Bench, p: &FccParams, f: &Frame, feed: Feed, rng: &mut ChaCha8Rng) {
    assert_eq!(p.fsize, b.k, "the run's K is the build's");
    let (rows, cols, h) = (p.rows, p.cols, p.half());
    let th = Thresholds::new(p);
    let mut golden = Stream::new(p).unwrap();
    let mut column = vec![None; rows];
    let mut closed: Vec<Vec<Vec<u32>>> = Vec::new();
    for c in 0..cols {
        for (r, v) in column.iter_mut().enumerate() {
            *v = f.get(r, c);
        }
        let recs = golden.push_column(&column).unwrap();
        closed.push(
            (0..recs.len())
                .map(|k| golden.pixels_of(k).to_vec())
                .collect(),
        );
    }
    let recs = golden.finish().unwrap();
    let at_end: Vec<Vec<u32>> = (0..recs.len())
        .map(|k| golden.pixels_of(k).to_vec())
        .collect();
    let mut runs = Vec::new();
    golden.runs_into(&mut runs).unwrap();
    let pix = pixels(p, f, &runs);
    let mut uf = Uf(HashMap::new());
    let mut deferred: Vec<Vec<u32>> = Vec::new();
    for c in 0..cols {
        for px in &pix[c * rows..(c + 1) * rows] {
            while rng.gen_bool(feed.bubbles) {
                b.cycle(p, RtIn::default(), None);
            }
            let i = b.input(p, px);
            while !b.cycle(p, i, Some(px)) {}
            // The reference clusters: spec §4's pairs as the pixel arrives.
            if px.run != 0 {
                uf.find(px.run);
                for (ii, cc) in fcc_golden::column_window(rows, h, px.row, c) {
                    let other = runs[ii * cols + cc];
                    let (q, o) = (f.get(px.row, c).unwrap(), f.get(ii, cc));
                    if other != 0 && o.is_some_and(|o| th.joins(q, o)) {
                        uf.union(px.run, other);
                    }
                }
            }
            if let Some((a, z)) = px.ring {
                uf.union(a, z);
                b.rings += 1;
            }
        }
        if feed.drain {
            b.drain(p);
            let at = format!("{}: after column {c}, seed {}", b.what, b.seed);
            b.check_clusters(&mut uf, &at);
            b.close(p, &runs, &closed[c], &at);
        } else {
            deferred.extend(closed[c].iter().cloned());
        }
    }
    b.drain(p);
    let at = format!("{}: at the frame end, seed {}", b.what, b.seed);
    b.check_clusters(&mut uf, &at);
    deferred.extend(at_end);
    b.close(p, &runs, &deferred, &at);
    assert!(b.slot_of.is_empty(), "{at}: runs left open after the frame");
    assert!(
        b.taken.is_empty(),
        "{at}: slots taken but not seen at a start"
    );
}

/// A random frame of objects: a range profile along the columns shared by
/// every row (jumps between objects), each row a little off it and now and
/// then off on its own, points missing at random. Runs of one object start
/// apart in rows and columns and meet later, so clusters merge often, and
/// pixels join two clusters at once.
/// With `seam`, the y coordinate runs back to its start at the last column,
/// so rows' first and last points meet in ring checks (spec §3).
#[test]
fn slots_follow_the_golden_clusters_column_by_column() {
    let build = build();
    let cases: [(&str, FccParams); 4] = [
        ("unlimited", run_params(16, 40)),
        (
            "bridge 2, ring reach 6",
            FccParams {
                bridge: Some(2),
                ring_reach: Some(6),
                ..run_params(20, 40)
            },
        ),
        (
            "adaptive",
            FccParams {
                th_h: 0.1,
                th_h_slope: 0.05,
                th_v_slope: 0.03,
                ..run_params(24, 36)
            },
        ),
        ("all rows of the build", run_params(build.rows, 24)),
    ];
    for (n, (what, p)) in cases.into_iter().enumerate() {
        let seed = 0x5eed_2000 + n as u64;
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        // A pool a little larger than the clusters open at once: slots are
        // reused within the frame.
        let mut b = Bench::new(&build, 160, seed, what);
        for (density, jump, bubbles, seam) in [
            (0.8, 0.05, 0.0, false),
            (0.4, 0.1, 0.2, true),
            (0.9, 0.02, 0.0, true),
        ] {
            let f = random_frame(p.rows, p.cols, density, jump, seam, &mut rng);
            let feed = Feed {
                bubbles,
                drain: true,
            };
            run_frame(&mut b, &p, &f, feed, &mut rng);
        }
        eprintln!(
            "{what}: {} merges, {} stalls, {} ring checks",
            b.merges, b.stalls, b.rings
        );
        assert!(b.merges > 0, "{what}: no merge at all");
    }
}

#[test]
fn columns_back_to_back_with_bubbles() {
    let build = build();
    let p = FccParams {
        bridge: Some(4),
        ..run_params(32, 32)
    };
    let seed = 0x5eed_2100;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut b = Bench::new(&build, 512, seed, "back to back");
    for (density, jump, bubbles, seam) in [
        (0.85, 0.03, 0.0, true),
        (0.6, 0.08, 0.3, false),
        (0.95, 0.01, 0.05, true),
    ] {
        let f = random_frame(p.rows, p.cols, density, jump, seam, &mut rng);
        let feed = Feed {
            bubbles,
            drain: false,
        };
        run_frame(&mut b, &p, &f, feed, &mut rng);
    }
    eprintln!(
        "back to back: {} merges, {} stalls, {} ring checks",
        b.merges, b.stalls, b.rings
    );
    assert!(
        b.stalls > 0,
        "no pixel joined two clusters: the test is too easy"
    );
}

/// A frame cut short by a reset, then whole frames: rows' roots from before
/// the reset never answer for the new frame's labels.
#[test]
fn a_reset_mid_frame_starts_afresh() {
    let build = build();
    let p = run_params(16, 40);
    let seed = 0x5eed_2300;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut b = Bench::new(&build, 160, seed, "reset mid-frame");
    for cut in [5, 16 * 17 + 3, 16 * 39 + 15] {
        let f = random_frame(p.rows, p.cols, 0.8, 0.05, true, &mut rng);
        let mut runs = Vec::new();
        let mut golden = Stream::new(&p).unwrap();
        let mut column = vec![None; p.rows];
        for c in 0..p.cols {
            for (r, v) in column.iter_mut().enumerate() {
                *v = f.get(r, c);
            }
            golden.push_column(&column).unwrap();
        }
        golden.finish().unwrap();
        golden.runs_into(&mut runs).unwrap();
        for px in pixels(&p, &f, &runs).iter().take(cut) {
            let i = b.input(&p, px);
            while !b.cycle(&p, i, Some(px)) {}
        }
        b.reset(&p, 160);
        let f = random_frame(p.rows, p.cols, 0.8, 0.05, true, &mut rng);
        let feed = Feed {
            bubbles: 0.1,
            drain: false,
        };
        run_frame(&mut b, &p, &f, feed, &mut rng);
    }
}

/// At the last column one pixel both joins another cluster and closes a
/// ring: row 5 has a run at columns 0 ..= 3 (A) and one at 36 ..= 39 (B),
/// whose first and last points meet across the seam; a lone point at row
/// 6, column 38 (C) is near (5, 39) only. Pixel (5, 39) merges C into B, is
/// still in two clusters after it, and holds the input three cycles (ask
/// for A into B, check, find none left): one cluster.
#[test]
fn a_ring_check_and_a_join_at_one_pixel() {
    let build = build();
    let p = FccParams {
        th_h: 0.5,
        bridge: Some(2),
        ..run_params(16, 40)
    };
    let mut f = Frame::empty(p.rows, p.cols);
    let at = |c: usize| (80 * c.min(p.cols - 1 - c)) as i16;
    for c in (0..4).chain(36..40) {
        f.set(5, c, Some([1000, at(c), 0]));
    }
    f.set(6, 38, Some([1000, at(39), 25]));
    let seed = 0x5eed_2200;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut b = Bench::new(&build, 64, seed, "ring and join");
    let feed = Feed {
        bubbles: 0.0,
        drain: true,
    };
    run_frame(&mut b, &p, &f, feed, &mut rng);
    assert_eq!(
        (b.merges, b.rings, b.stalls),
        (2, 1, 3),
        "(merges, ring checks, stalls)"
    );
}

/// One pixel joins three clusters: three lone points around (5, 10), each
/// 70 units (Q7.8) from it and over 120 from one another. Stage C merges
/// the first in window order; R asks for the other two, each followed by a
/// check, then finds none left: the input waits five cycles.
#[test]
fn a_pixel_joining_three_clusters() {
    let build = build();
    let p = run_params(16, 20);
    let mut f = Frame::empty(p.rows, p.cols);
    f.set(5, 10, Some([1000, 0, 0]));
    f.set(2, 10, Some([1070, 0, 0]));
    f.set(8, 9, Some([965, 60, 0]));
    f.set(4, 8, Some([965, -60, 0]));
    let seed = 0x5eed_2400;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut b = Bench::new(&build, 64, seed, "three clusters");
    let feed = Feed {
        bubbles: 0.0,
        drain: true,
    };
    run_frame(&mut b, &p, &f, feed, &mut rng);
    assert_eq!((b.merges, b.stalls), (3, 5), "(merges, stalls)");
}
