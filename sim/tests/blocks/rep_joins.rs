//! The column core's representative rows `fcc_rep_joins` alone under
//! Verilator: pixels in column order with their runs' labels, ring checks
//! and pass-2 hits (worked out from the golden stream's runs and spec §3,
//! §4 and §9.2, as the other column benches do), against a model of the
//! joins it must send. The bench gives labels out as runs start and takes
//! them back when the golden stream closes their cluster (reused last
//! freed first). Checked:
//!
//! * every pixel in input order, and the joins after it (its first in its
//!   cycle, the others while `j_more` says they come, all before the next
//!   pixel), one for one,
//!   against the model of docs/column-core.md, item 3: a run's
//!   representative is a label of its cluster; a pixel's smallest named
//!   representative `m` (a run it starts counting only when it names no
//!   other) becomes every named run's, every other distinct value is a
//!   join `(x, m)`, and the next pixel sees the rewrite; at the
//!   last column a ring check's pair is one more join;
//! * the clusters: a union-find over the labels, fed only by the joins,
//!   makes each cluster the golden stream closes one set, holding no label
//!   of another cluster;
//! * no label named is ever missing from its row (`miss`);
//! * a pixel whose row stops holding a run names, for its flush, a label
//!   of that run's cluster (by the same union-find), nine times in ten
//!   at least the model's representative of the run.
//!
//! Seeded random frames (fixed and range-adaptive thresholds, bridge and
//! ring-reach limits, the smallest frame the block takes at the build's K),
//! bubbles, columns back to back, frames back to back, a reset mid-frame.
//! A mismatch prints the frame, pixel, expected, got and the seed.

use std::collections::{HashMap, VecDeque};

use crate::column;

use column::rep_io::{rep_in, RjIn, RjOut};
use column::{build, pixels, random_frame, run_params, Pix};
use fcc_golden::Frame;
use fcc_params::FccParams;
use fcc_rtl::BenchBlock;
use fcc_sim::{load_plain, PlainDut};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// A union-find over labels, fed by the block's joins.
#[derive(Default)]
struct Uf(HashMap<u16, u16>);

impl Uf {
    fn find(&mut self, x: u16) -> u16 {
        let p = *self.0.entry(x).or_insert(x);
        if p == x {
            return x;
        }
        let r = self.find(p);
        self.0.insert(x, r);
        r
    }
    fn union(&mut self, a: u16, b: u16) {
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
    /// Wait for every pixel of a column, check the clusters the golden
    /// stream closes at it and free their labels before the next column;
    /// otherwise columns go back to back and clusters close at the end.
    drain: bool,
}

/// A pixel fed, with the joins the model expects before it.
#[derive(Clone)]
struct Fed {
    px: Pix,
    label: u16,
    /// Each join: its labels, `under`, and whether it is the ring check's.
    joins: Vec<(u16, u16, bool, bool)>,
    /// The run its row stops holding (its label, 0 for none) and its
    /// representative in the model before the pixel.
    drop: u16,
    drop_rep: u16,
}

struct Bench {
    dut: PlainDut<RjIn, RjOut>,
    k: usize,
    /// Labels: free (reused last freed first) and per open run.
    free_labels: Vec<u16>,
    label_of: HashMap<u32, u16>,
    /// The model: each open run's representative.
    rep: HashMap<u32, u16>,
    /// Pixels fed, waiting to come out; the pixel out last, whose joins
    /// `got` are, and whether `j_more` said more would come.
    pending: VecDeque<Fed>,
    last: Option<Fed>,
    got: Vec<(u16, u16, bool, bool)>,
    more: bool,
    uf: Uf,
    joins: u64,
    stalls: u64,
    /// Flushes out; of them, named by the model's representative, and by
    /// a representative other than the run's label.
    flushes: u64,
    flush_exact: u64,
    flush_rep: u64,
    /// Cycles the input has been held in a row.
    held: u32,
    seed: u64,
    what: String,
}

impl Bench {
    /// The block built for `build`, reset for frames of `p`'s rows.
    fn new(build: &FccParams, p: &FccParams, seed: u64, what: &str) -> Bench {
        let model =
            load_plain::<RjIn, RjOut>(BenchBlock::RepJoins, build).expect("rep joins model");
        // The block starts from a reset, with the frame's last row (its
        // table's counters count rows from there).
        let mut b = Bench {
            dut: PlainDut::new(model),
            k: build.fsize,
            free_labels: (1..=8191u16).rev().collect(),
            label_of: HashMap::new(),
            rep: HashMap::new(),
            pending: VecDeque::new(),
            last: None,
            got: Vec::new(),
            more: false,
            uf: Uf::default(),
            joins: 0,
            stalls: 0,
            flushes: 0,
            flush_exact: 0,
            flush_rep: 0,
            held: 0,
            seed,
            what: what.to_string(),
        };
        b.reset(p);
        b
    }

    /// The input of a pixel (its run's label given out at its start), and
    /// the model's joins for it.
    fn input(&mut self, p: &FccParams, px: &Pix) -> (RjIn, Fed) {
        if px.start {
            let l = self.free_labels.pop().expect("labels left");
            self.label_of.insert(px.run, l);
            self.rep.insert(px.run, l);
        }
        let label_of = &self.label_of;
        let i = rep_in(p, px, |run| if run == 0 { 0 } else { label_of[&run] });
        let (drop, drop_rep) = match px.hold {
            Some((was, _)) if was != 0 => (self.label_of[&was], self.rep[&was]),
            _ => (0, 0),
        };
        let mut joins = Vec::new();
        if px.run != 0 {
            let mut named = vec![px.run];
            for &(_, r) in &px.hits {
                if !named.contains(&r) {
                    named.push(r);
                }
            }
            // A run the pixel starts takes the others' minimum when it
            // names others (it does not rename their cluster).
            let m = named
                .iter()
                .filter(|&&r| !(px.start && r == px.run && named.len() > 1))
                .map(|r| self.rep[r])
                .min()
                .expect("own run");
            for r in &named {
                let x = self.rep[r];
                // The run started, filed under its neighbours' cluster.
                let under = px.start && *r == px.run;
                if x != m && !joins.contains(&(x, m, under, false)) {
                    joins.push((x, m, under, false));
                }
                self.rep.insert(*r, m);
            }
        }
        if px.ring.is_some() {
            joins.push((i.ring_a, i.ring_b, false, true));
        }
        joins.sort_unstable();
        let fed = Fed {
            px: px.clone(),
            label: i.label,
            joins,
            drop,
            drop_rep,
        };
        (i, fed)
    }

    /// One cycle; returns whether the input was taken.
    fn cycle(&mut self, p: &FccParams, mut i: RjIn, fed: Option<&Fed>) -> bool {
        i.last_row = (p.rows - 1) as u8;
        let o = self.dut.step(&i);
        assert_eq!(
            o.miss, 0,
            "{}: a label named is not in its row (seed {})",
            self.what, self.seed
        );
        self.event(&o);
        if o.j_valid != 0 {
            assert!(
                o.o_valid != 0 || self.more,
                "{}: a join after its pixel's last (seed {})",
                self.what,
                self.seed
            );
            self.got.push((o.j_a, o.j_b, o.j_under != 0, o.j_seam != 0));
            self.uf.union(o.j_a, o.j_b);
            self.joins += 1;
        }
        self.more = o.j_more != 0;
        if !self.more {
            self.settle();
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
            let f = fed.expect("a pixel");
            self.pending.push_back(f.clone());
        }
        taken
    }

    /// The pixel out last: its joins are all out, and must be the model's.
    fn settle(&mut self) {
        let mut got = std::mem::take(&mut self.got);
        let Some(f) = self.last.take() else {
            assert!(
                got.is_empty(),
                "{}: joins {got:?} with no pixel out (seed {})",
                self.what,
                self.seed
            );
            return;
        };
        got.sort_unstable();
        assert_eq!(
            got, f.joins,
            "{}: row {}, col {}, seed {}: the joins after the pixel",
            self.what, f.px.row, f.px.col, self.seed
        );
    }

    fn event(&mut self, o: &RjOut) {
        if o.o_valid == 0 {
            return;
        }
        assert!(
            !self.more,
            "{}: a pixel out while the one before has joins to come (seed {})",
            self.what, self.seed
        );
        self.settle();
        let f = self
            .pending
            .pop_front()
            .expect("a pixel out with no pixel fed");
        let at = format!(
            "{}: row {}, col {}, seed {}",
            self.what, f.px.row, f.px.col, self.seed
        );
        assert_eq!(
            (o.o_row as usize, o.o_col as usize, o.o_lok != 0, o.o_label),
            (f.px.row, f.px.col, f.px.run != 0, f.label),
            "{at}: (row, col, labelled, label) of the next pixel out"
        );
        self.last = Some(f.clone());
        // The flush names a label of the dropped run's cluster: its
        // representative as the window had it at A2 (the model's, or one
        // the pixels after A2 have rewritten since).
        assert_eq!(o.o_hold_drop, f.drop, "{at}: the run its row stops holding");
        if f.drop != 0 {
            assert!(
                o.o_hold_rep != 0 && self.uf.find(o.o_hold_rep) == self.uf.find(f.drop),
                "{at}: the flush of label {} names {}, not of its cluster (the model's representative {})",
                f.drop,
                o.o_hold_rep,
                f.drop_rep
            );
            self.flushes += 1;
            self.flush_exact += u64::from(o.o_hold_rep == f.drop_rep);
            self.flush_rep += u64::from(o.o_hold_rep != f.drop);
        } else {
            assert_eq!(o.o_hold_rep, 0, "{at}: a flush with no run dropped");
        }
    }

    /// A reset: the block and the bench forget everything in flight, every
    /// label is free again.
    fn reset(&mut self, p: &FccParams) {
        let i = RjIn {
            rst: 1,
            ..RjIn::default()
        };
        self.cycle(p, i, None);
        self.pending.clear();
        self.last = None;
        self.more = false;
        self.got.clear();
        self.label_of.clear();
        self.rep.clear();
        self.uf = Uf::default();
        self.free_labels = (1..=8191u16).rev().collect();
    }

    /// Bubbles until every pixel fed is out.
    fn drain(&mut self, p: &FccParams) {
        let mut n = 0;
        while !self.pending.is_empty() || self.more || n < 3 {
            n = if self.pending.is_empty() && !self.more {
                n + 1
            } else {
                0
            };
            self.cycle(p, RjIn::default(), None);
        }
        assert!(
            self.got.is_empty() && self.last.is_none() && !self.more,
            "{}: the last pixel's joins not settled",
            self.what
        );
    }

    /// Close the clusters of these runs: each one set of the joins'
    /// union-find holding no other open run's label; their labels freed.
    fn close(&mut self, closing: &[Vec<u32>], at: &str) {
        for rs in closing {
            let root = self.uf.find(self.label_of[&rs[0]]);
            for r in rs {
                let l = self.label_of[r];
                assert_eq!(
                    self.uf.find(l),
                    root,
                    "{at}: runs {} and {r} are one cluster, but no joins link labels {} and {l}",
                    rs[0],
                    self.label_of[&rs[0]]
                );
            }
            let members: Vec<u32> = self
                .label_of
                .iter()
                .filter(|(r, _)| !rs.contains(r))
                .map(|(r, _)| *r)
                .collect();
            for r in members {
                let l = self.label_of[&r];
                assert_ne!(
                    self.uf.find(l),
                    root,
                    "{at}: run {r} (label {l}) is joined to a cluster it is not in"
                );
            }
        }
        for rs in closing {
            for r in rs {
                let l = self.label_of.remove(r).expect("a label");
                self.rep.remove(r);
                self.uf.0.remove(&l);
                self.free_labels.push(l);
            }
        }
    }
}

/// Stream `f` through the bench and check it (see the file's comment).
fn run_frame(b: &mut Bench, p: &FccParams, f: &Frame, feed: Feed, rng: &mut ChaCha8Rng) {
    assert_eq!(p.fsize, b.k, "the run's K is the build's");
    let (rows, cols) = (p.rows, p.cols);
    let column::Closing {
        runs,
        at: mut closed,
    } = column::closing(p, f);
    let at_end = closed.pop().expect("the frame end's closes");
    let pix = pixels(p, f, &runs);
    let mut deferred: Vec<Vec<u32>> = Vec::new();
    for c in 0..cols {
        for px in &pix[c * rows..(c + 1) * rows] {
            while rng.gen_bool(feed.bubbles) {
                b.cycle(p, RjIn::default(), None);
            }
            let (i, fed) = b.input(p, px);
            while !b.cycle(p, i, Some(&fed)) {}
        }
        if feed.drain {
            b.drain(p);
            let at = format!("{}: after column {c}, seed {}", b.what, b.seed);
            b.close(&closed[c], &at);
        } else {
            deferred.extend(closed[c].iter().cloned());
        }
    }
    b.drain(p);
    let at = format!("{}: at the frame end, seed {}", b.what, b.seed);
    deferred.extend(at_end);
    b.close(&deferred, &at);
    assert!(
        b.label_of.is_empty(),
        "{at}: runs left open after the frame"
    );
}

/// The smallest frame height the block takes at K: `K + 4 + 4` rows (the
/// window, the four rows above it, the table's read-ahead).
fn min_rows(k: usize) -> usize {
    k + 8
}

#[test]
fn joins_follow_the_model_and_the_golden_clusters() {
    let build = build();
    let k = build.fsize;
    let cases: [(&str, FccParams); 5] = [
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
        ("fewest rows", run_params(min_rows(k), 30)),
        ("all rows of the build", run_params(build.rows, 24)),
    ];
    for (n, (what, p)) in cases.into_iter().enumerate() {
        let seed = 0x5eed_3000 + n as u64;
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut b = Bench::new(&build, &p, seed, what);
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
            "{what}: {} joins, {} stalls; {} flushes, {} named by the model's representative, {} by a representative not the run's label",
            b.joins, b.stalls, b.flushes, b.flush_exact, b.flush_rep
        );
        assert!(b.joins > 0, "{what}: no join at all");
        // Nearly every flush names the model's representative (the others
        // one the pixels after A2 rewrote, or the run's label when the
        // run is not among its row's two newest).
        assert!(
            b.flushes > 0 && b.flush_exact * 10 >= b.flushes * 9,
            "{what}: {} of {} flushes named by the model's representative",
            b.flush_exact,
            b.flushes
        );
    }
}

#[test]
fn columns_and_frames_back_to_back_with_bubbles() {
    let build = build();
    let p = FccParams {
        bridge: Some(4),
        ..run_params(32, 32)
    };
    let seed = 0x5eed_3100;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut b = Bench::new(&build, &p, seed, "back to back");
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
    eprintln!("back to back: {} joins, {} stalls", b.joins, b.stalls);
    assert!(
        b.stalls > 0,
        "no pixel sent two joins: the test is too easy"
    );
}

/// A frame cut short by a reset, then whole frames: rows from before the
/// reset never answer for the new frame's labels.
#[test]
fn a_reset_mid_frame_starts_afresh() {
    let build = build();
    let p = run_params(16, 40);
    let seed = 0x5eed_3200;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut b = Bench::new(&build, &p, seed, "reset mid-frame");
    for cut in [5, 16 * 17 + 3, 16 * 39 + 15] {
        let f = random_frame(p.rows, p.cols, 0.8, 0.05, true, &mut rng);
        let runs = column::closing(&p, &f).runs;
        for px in pixels(&p, &f, &runs).iter().take(cut) {
            let (i, fed) = b.input(&p, px);
            while !b.cycle(&p, i, Some(&fed)) {}
        }
        b.reset(&p);
        let f = random_frame(p.rows, p.cols, 0.8, 0.05, true, &mut rng);
        let feed = Feed {
            bubbles: 0.1,
            drain: false,
        };
        run_frame(&mut b, &p, &f, feed, &mut rng);
    }
}
