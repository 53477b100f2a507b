//! The column core's per-row run state `fcc_row_runs` alone under
//! Verilator against the golden stream (`fcc_golden::Stream`, spec §3 and
//! §9): frames go in column by column with the bench's free list of labels
//! (labels of the clusters the golden stream closes at a column return to
//! it after that column); every pixel's run, label, start and refusal must
//! be the golden stream's runs (`Stream::runs_into`), each row's held label
//! after every column its latest run's when holds 2 or 4 of spec §9.2 keep
//! it, hold 3 on the row's first pixel, and the ring check at the last
//! column spec §3's. Seeded random frames with fixed and range-adaptive
//! thresholds, bridge and ring-reach limits, random bubbles, frames back to
//! back on one instance, a reset mid-frame, and labels that run out and are
//! reused. A mismatch prints the frame, pixel, expected, got and the seed.

use crate::column;

use column::{build, run_params};
use std::collections::{HashMap, VecDeque};

use fcc_golden::{Frame, Point, Stream, Thresholds};
use fcc_params::FccParams;
use fcc_rtl::{BenchBlock, RunLimits, THR_LAG};
use fcc_sim::core_form::{offset_binary as ob, point_addends};
use fcc_sim::{c_struct, load_plain, PlainDut};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

c_struct! {
    /// Inputs of one cycle, named as the ports.
    pub struct RrIn {
        pub rst: u8,
        pub valid: u8,
        pub ok: u8,
        pub x: u16,
        pub y: u16,
        pub z: u16,
        pub row: u8,
        pub col: u16,
        pub first: u8,
        pub last: u8,
        pub key: u16,
        pub ch: u64,
        pub cv: u64,
        pub last_col: u16,
        pub reach: u16,
        pub ring_on: u8,
        pub ring_f_max: u16,
        pub ring_l_min: u16,
        pub free_ok: u8,
        pub free_label: u16,
        pub open_room: u16,
        pub use_pool: u8,
        pub clear: u8,
        pub ret: u8,
        pub ret_label: u16,
    }
}

c_struct! {
    /// Outputs during one cycle.
    pub struct RrOut {
        pub take: u8,
        pub o_valid: u8,
        pub o_ok: u8,
        pub o_lok: u8,
        pub o_x: u16,
        pub o_y: u16,
        pub o_z: u16,
        pub o_row: u8,
        pub o_col: u16,
        pub o_first: u8,
        pub o_last: u8,
        pub o_last_col: u8,
        pub o_key: u16,
        pub o_cv: u64,
        pub o_label: u16,
        pub o_start: u8,
        pub o_refused: u8,
        pub o_ring_first: u8,
        pub o_ring: u8,
        pub o_ring_hold: u8,
        pub o_ring_a: u16,
        pub o_ring_b: u16,
        pub o_hold_drop: u16,
        pub o_hold_add: u16,
        pub o_hold_rep: u16,
        pub pool_ok: u8,
        pub pool_label: u16,
        pub free_count: u16,
    }
}

/// `open_room` with no open limit: more runs than a column has rows.
const NO_LIMIT: u16 = 1023;

/// How a frame is fed.
#[derive(Debug, Clone, Copy)]
struct Feed {
    /// Probability of a bubble before each slot.
    bubbles: f64,
    /// Wait for every output of a column, and return the labels of the
    /// clusters closed at it, before the next column (what spec §9.1's
    /// label reuse needs); otherwise columns go back to back and labels
    /// return at the frame end.
    drain: bool,
    /// Assert reset after this many slots, then start the frame again.
    reset_after: Option<usize>,
}

/// The bench: the block, its inputs' lag, the free list (the bench's, or
/// the build's `FccLabelPool` fed with the returned labels), each row's
/// held label as the block's hold outputs left it.
struct Bench {
    dut: PlainDut<RrIn, RrOut>,
    lag: VecDeque<(u16, u64, u64)>,
    /// Labels `1 ..= labels` in all.
    labels: u16,
    free: VecDeque<u16>,
    /// Labels come from the pool: returned ones wait here to be fed to it,
    /// one a cycle; `clear` starts a frame.
    pooled: bool,
    returns: VecDeque<u16>,
    clear: bool,
    taken: VecDeque<u16>,
    held: Vec<u16>,
    /// The runs the open limit allows in the column being fed (spec §9.1).
    open_room: u16,
    outs: HashMap<(usize, usize), RrOut>,
    seed: u64,
    what: String,
}

impl Bench {
    fn new(build: &FccParams, labels: u32, seed: u64, what: &str) -> Bench {
        let model = load_plain::<RrIn, RrOut>(BenchBlock::RowRuns, build).expect("row runs model");
        Bench {
            dut: PlainDut::new(model),
            lag: VecDeque::from(vec![(0, 0, 0); THR_LAG]),
            labels: labels as u16,
            free: (1..=labels as u16).collect(),
            pooled: false,
            returns: VecDeque::new(),
            clear: false,
            taken: VecDeque::new(),
            held: vec![0; build.rows],
            open_room: NO_LIMIT,
            outs: HashMap::new(),
            seed,
            what: what.to_string(),
        }
    }

    /// One cycle: `slot` (or a bubble) in; the output collected.
    fn cycle(&mut self, p: &FccParams, slot: Option<(usize, usize, Option<Point>)>, rst: bool) {
        let lim = RunLimits::new(p);
        let mut i = RrIn {
            rst: rst as u8,
            last_col: (p.cols - 1) as u16,
            reach: lim.reach,
            ring_on: lim.ring_on as u8,
            ring_f_max: lim.ring_f_max,
            ring_l_min: lim.ring_l_min,
            free_ok: !self.free.is_empty() as u8,
            free_label: self.free.front().copied().unwrap_or(0),
            open_room: self.open_room,
            use_pool: self.pooled as u8,
            clear: std::mem::take(&mut self.clear) as u8,
            ..RrIn::default()
        };
        if let Some(l) = self.returns.pop_front().filter(|_| self.pooled) {
            (i.ret, i.ret_label) = (1, l);
        }
        let (key, ch, cv) = self.lag.pop_front().unwrap();
        i.key = key;
        i.ch = ch;
        i.cv = cv;
        let mut thr = (0, 0, 0);
        if let Some((row, col, pt)) = slot {
            i.valid = 1;
            i.row = row as u8;
            i.col = col as u16;
            i.first = (row == 0 && col == 0) as u8;
            i.last = (row == p.rows - 1 && col == p.cols - 1) as u8;
            if let Some(q) = pt {
                i.ok = 1;
                i.x = ob(q[0]);
                i.y = ob(q[1]);
                i.z = ob(q[2]);
                let a = point_addends(p, q);
                thr = (a.key, a.ch, a.cv);
            }
        }
        self.lag.push_back(thr);
        let o = self.dut.step(&i);
        if o.take != 0 {
            let l = if self.pooled {
                assert!(o.pool_ok != 0, "{}: take with an empty pool", self.what);
                o.pool_label
            } else {
                self.free.pop_front().expect("take with an empty free list")
            };
            self.taken.push_back(l);
        }
        if o.o_valid != 0 && !rst {
            self.collect(o);
        }
    }

    /// One output: its hold events applied to the row's held label.
    fn collect(&mut self, o: RrOut) {
        let (row, col) = (o.o_row as usize, o.o_col as usize);
        let at = format!("{}: row {row}, col {col}, seed {}", self.what, self.seed);
        if o.o_hold_drop != 0 || o.o_hold_add != 0 {
            assert_ne!(
                o.o_hold_drop, o.o_hold_add,
                "{at}: hold event with no change"
            );
            assert_eq!(
                o.o_hold_drop, self.held[row],
                "{at}: drops hold {} but the row holds {}",
                o.o_hold_drop, self.held[row]
            );
            self.held[row] = o.o_hold_add;
        }
        // The flush's name, until the representative rows give theirs: the
        // run's label.
        assert_eq!(
            o.o_hold_rep, o.o_hold_drop,
            "{at}: the flush's name out of the row runs"
        );
        if o.o_start != 0 {
            let l = self.taken.pop_front();
            assert_eq!(
                Some(o.o_label),
                l,
                "{at}: a started run's label is not the one taken"
            );
        }
        self.outs.insert((row, col), o);
    }

    /// Bubbles until nothing is in flight.
    fn drain(&mut self, p: &FccParams) {
        for _ in 0..12 {
            self.cycle(p, None, false);
        }
    }

    /// Labels back to the free list; with the pool, fed to it one a cycle
    /// (bubbles) until all are in.
    fn give_back(&mut self, p: &FccParams, labels: Vec<u16>) {
        if self.pooled {
            self.returns.extend(labels);
            while !self.returns.is_empty() {
                self.cycle(p, None, false);
            }
        } else {
            self.free.extend(labels);
        }
    }

    /// A frame starts: with the pool, `clear` (every label free again).
    fn frame_start(&mut self, p: &FccParams) {
        if self.pooled {
            self.returns.clear();
            self.clear = true;
            self.cycle(p, None, false);
        }
    }
}

/// Stream `f` through the bench and the golden stream and check every
/// output.
fn run_frame(b: &mut Bench, p: &FccParams, f: &Frame, feed: Feed, rng: &mut ChaCha8Rng) {
    let (rows, cols) = (p.rows, p.cols);
    // Every cluster closed at the last frame's end: no row holds a label.
    b.held.fill(0);
    b.frame_start(p);
    if let Some(n) = feed.reset_after {
        // A frame cut short by a reset: its labels come back (the core
        // frees them on reset), the held labels are forgotten.
        let mut sent = 0;
        'cut: for c in 0..cols {
            for r in 0..rows {
                if sent == n {
                    break 'cut;
                }
                b.cycle(p, Some((r, c, f.get(r, c))), false);
                sent += 1;
            }
        }
        b.cycle(p, None, true);
        b.drain(p);
        b.outs.clear();
        b.taken.clear();
        b.free = (1..=b.labels).collect();
        b.returns.clear();
        b.held.fill(0);
    }
    b.outs.clear();
    let mut golden = Stream::new(p).unwrap();
    // The open limit's room at each column (spec §9.1): the limit less the
    // clusters open after the previous column, which the bench knows only
    // between columns (drained feeds).
    assert!(
        p.open_limit.is_none() || feed.drain,
        "an open limit needs a drained feed"
    );
    let room = |g: &Stream| {
        p.open_limit
            .map_or(NO_LIMIT, |s| (s - g.open_clusters()) as u16)
    };
    b.open_room = room(&golden);
    let mut column = vec![None; rows];
    // Drained: each row's held label as the outputs left it after each
    // column (undrained, the check replays the outputs' hold events).
    let mut held_after: Vec<Vec<u16>> = Vec::with_capacity(cols);
    // Labels to return per closing column (by golden pixel lists, mapped
    // to the block's labels once the outputs are in).
    let mut closed: Vec<Vec<u32>> = Vec::new();
    for c in 0..cols {
        for (r, v) in column.iter_mut().enumerate() {
            *v = f.get(r, c);
            while rng.gen_bool(feed.bubbles) {
                b.cycle(p, None, false);
            }
            b.cycle(p, Some((r, c, *v)), false);
        }
        let recs = golden.push_column(&column).unwrap();
        let pixels: Vec<Vec<u32>> = (0..recs.len())
            .map(|k| golden.pixels_of(k).to_vec())
            .collect();
        if feed.drain {
            b.drain(p);
            held_after.push(b.held.clone());
            return_labels(b, p, &pixels);
            b.open_room = room(&golden);
        } else {
            closed.extend(pixels);
        }
    }
    b.drain(p);
    let recs = golden.finish().unwrap();
    let pixels: Vec<Vec<u32>> = (0..recs.len())
        .map(|k| golden.pixels_of(k).to_vec())
        .collect();
    closed.extend(pixels);
    let mut runs = Vec::new();
    golden.runs_into(&mut runs).unwrap();
    check_frame(b, p, f, &runs, &held_after, feed.drain);
    return_labels(b, p, &closed);
    assert!(
        b.taken.is_empty(),
        "{}: labels taken but not seen at a start",
        b.what
    );
}

/// Return to the free list the labels of the clusters with these pixels.
fn return_labels(b: &mut Bench, p: &FccParams, clusters: &[Vec<u32>]) {
    let cols = p.cols;
    let mut back = Vec::new();
    for px in clusters {
        let mut labels: Vec<u16> = px
            .iter()
            .map(|&k| b.outs[&(k as usize / cols, k as usize % cols)].o_label)
            .collect();
        labels.sort_unstable();
        labels.dedup();
        assert!(
            !labels.contains(&0),
            "{}: a cluster with an unlabelled pixel",
            b.what
        );
        back.extend(labels);
    }
    b.give_back(p, back);
}

/// Every output of the frame against the golden runs and spec §3 / §9.2.
fn check_frame(
    b: &Bench,
    p: &FccParams,
    f: &Frame,
    runs: &[u32],
    held_after: &[Vec<u16>],
    drained: bool,
) {
    let (rows, cols) = (p.rows, p.cols);
    let th = Thresholds::new(p);
    let mut label_of: HashMap<u32, u16> = HashMap::new();
    // Per row: latest and first valid pixel so far (col, point, run).
    let mut latest: Vec<Option<(usize, Point, u32)>> = vec![None; rows];
    let mut first: Vec<Option<(usize, Point, u32)>> = vec![None; rows];
    // Held labels replayed from the outputs, for undrained feeds.
    let mut held = vec![0u16; rows];
    for c in 0..cols {
        for r in 0..rows {
            let at = format!("{}: row {r}, col {c}, seed {}", b.what, b.seed);
            let o = b
                .outs
                .get(&(r, c))
                .unwrap_or_else(|| panic!("{at}: no output"));
            let pt = f.get(r, c);
            let run = runs[r * cols + c];
            assert_eq!(
                (
                    o.o_ok != 0,
                    o.o_first != 0,
                    o.o_last != 0,
                    o.o_last_col != 0
                ),
                (
                    pt.is_some(),
                    r == 0 && c == 0,
                    r == rows - 1 && c == cols - 1,
                    c == cols - 1
                ),
                "{at}: slot flags"
            );
            if let Some(q) = pt {
                assert_eq!(
                    (o.o_x, o.o_y, o.o_z),
                    (ob(q[0]), ob(q[1]), ob(q[2])),
                    "{at}: point"
                );
                let a = point_addends(p, q);
                assert_eq!(
                    (o.o_key, o.o_cv),
                    (a.key, a.cv),
                    "{at}: key and pass-2 addend"
                );
                // Spec §3: does this point start a run?
                let starts = match latest[r] {
                    Some((lc, lp, _)) => !(p.bridges(c - lc - 1) && th.continues(q, lp)),
                    None => true,
                };
                let want_label = if run == 0 {
                    0
                } else if starts {
                    assert!(
                        !label_of.contains_key(&run),
                        "{at}: golden run {run} starts twice"
                    );
                    label_of.insert(run, o.o_label);
                    o.o_label
                } else {
                    label_of[&run]
                };
                assert_eq!(
                    (o.o_label, o.o_lok != 0, o.o_start != 0, o.o_refused != 0),
                    (want_label, run != 0, starts && run != 0, starts && run == 0),
                    "{at}: (label, labelled, start, refused), golden run {run} (starts: {starts})"
                );
                assert!(
                    run == 0 || o.o_label != 0,
                    "{at}: a labelled run with label 0"
                );
                let ring_first = first[r].is_none() && run != 0 && p.ring_reaches(c, cols - 1);
                assert_eq!(o.o_ring_first != 0, ring_first, "{at}: hold 3");
                latest[r] = Some((c, q, run));
                if first[r].is_none() {
                    first[r] = Some((c, q, run));
                }
            } else {
                assert_eq!(
                    (o.o_label, o.o_lok, o.o_start, o.o_refused, o.o_ring_first),
                    (0, 0, 0, 0, 0),
                    "{at}: an empty pixel"
                );
            }
            // The ring check (spec §3) at the last column.
            let ring = c == cols - 1
                && match (first[r], latest[r]) {
                    (Some((fc, fp, fr)), Some((lc, lp, lr))) => {
                        fr != 0
                            && lr != 0
                            && fr != lr
                            && p.ring_reaches(fc, lc)
                            && th.continues(fp, lp)
                    }
                    _ => false,
                };
            assert_eq!(o.o_ring != 0, ring, "{at}: ring check");
            if ring {
                let (fr, lr) = (first[r].unwrap().2, latest[r].unwrap().2);
                assert_eq!(
                    (o.o_ring_a, o.o_ring_b),
                    (label_of[&fr], label_of[&lr]),
                    "{at}: ring labels"
                );
            }
            // Holds 2 and 4 after this column (spec §9.2).
            if o.o_hold_drop != 0 || o.o_hold_add != 0 {
                held[r] = o.o_hold_add;
            }
            let want_held = match latest[r] {
                Some((lc, _, lr)) if lr != 0 => {
                    let bridge = c != cols - 1 && p.bridges(c - lc);
                    let ring =
                        first[r].is_some_and(|(fc, _, fr)| fr != 0 && p.ring_reaches(fc, lc));
                    if bridge || ring {
                        label_of[&lr]
                    } else {
                        0
                    }
                }
                _ => 0,
            };
            assert_eq!(
                held[r], want_held,
                "{at}: the row's held label after the column"
            );
            // After the last column only hold 4 holds, and it says so.
            assert_eq!(
                o.o_ring_hold != 0,
                c == cols - 1 && want_held != 0,
                "{at}: hold 4 after the last column"
            );
            if drained {
                assert_eq!(
                    held_after[c][r], want_held,
                    "{at}: held label seen after the column"
                );
            }
        }
    }
}

/// A random frame of surfaces: each row a run of points that drift along
/// the column, broken by jumps and empty pixels, rows close enough apart
/// that neighbouring rows' points are near.
fn random_frame(
    rows: usize,
    cols: usize,
    density: f64,
    jump: f64,
    far: bool,
    rng: &mut ChaCha8Rng,
) -> Frame {
    let mut f = Frame::empty(rows, cols);
    for r in 0..rows {
        // Range in Q7.8: near (a few metres) or far (tens of metres).
        let mut range: i32 = if far {
            rng.gen_range(2_000..30_000)
        } else {
            rng.gen_range(300..3_000)
        };
        for c in 0..cols {
            if rng.gen_bool(jump) {
                range = (range + rng.gen_range(-2_000..2_000)).clamp(100, 32_000);
            }
            range = (range + rng.gen_range(-40..40)).clamp(100, 32_000);
            if rng.gen_bool(density) {
                let x = range;
                let y = (c as i32 * 20 - 2_000).clamp(-32_000, 32_000);
                let z = (r as i32 * 25 - 400).clamp(-32_000, 32_000);
                f.set(r, c, Some([x as i16, y as i16, z as i16]));
            }
        }
    }
    f
}

#[test]
fn runs_holds_and_ring_checks_equal_the_golden_stream() {
    let build = build();
    let cases: [(&str, FccParams, bool); 6] = [
        ("unlimited", run_params(16, 48), false),
        (
            "bridge 2, ring reach 6",
            FccParams {
                bridge: Some(2),
                ring_reach: Some(6),
                ..run_params(20, 40)
            },
            false,
        ),
        (
            "bridge 0, ring reach 0",
            FccParams {
                bridge: Some(0),
                ring_reach: Some(0),
                ..run_params(16, 40)
            },
            false,
        ),
        (
            "ring reach 1, bridge 5000",
            FccParams {
                bridge: Some(5000),
                ring_reach: Some(1),
                ..run_params(16, 30)
            },
            false,
        ),
        (
            "adaptive, far points",
            FccParams {
                th_h: 0.1,
                th_h_slope: 0.05,
                th_v_slope: 0.03,
                ..run_params(24, 40)
            },
            true,
        ),
        ("all rows of the build", run_params(build.rows, 24), false),
    ];
    for (k, (what, p, far)) in cases.into_iter().enumerate() {
        let seed = 0x5eed_0000 + k as u64;
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut b = Bench::new(&build, p.max_label(), seed, what);
        // Frames back to back on one instance: dense, sparse, with bubbles.
        for (density, jump, bubbles) in [(0.8, 0.05, 0.0), (0.3, 0.1, 0.0), (0.7, 0.02, 0.3)] {
            let f = random_frame(p.rows, p.cols, density, jump, far, &mut rng);
            let feed = Feed {
                bubbles,
                drain: false,
                reset_after: None,
            };
            run_frame(&mut b, &p, &f, feed, &mut rng);
        }
    }
}

#[test]
fn a_reset_mid_frame_starts_the_frame_again() {
    let build = build();
    let p = FccParams {
        bridge: Some(3),
        ring_reach: Some(8),
        ..run_params(16, 40)
    };
    let seed = 0x5eed_1000;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut b = Bench::new(&build, p.max_label(), seed, "reset mid-frame");
    for cut in [5, 16 * 17 + 3, 16 * 39 + 15] {
        let f = random_frame(p.rows, p.cols, 0.7, 0.05, false, &mut rng);
        let feed = Feed {
            bubbles: 0.1,
            drain: false,
            reset_after: Some(cut),
        };
        run_frame(&mut b, &p, &f, feed, &mut rng);
    }
}

#[test]
fn labels_run_out_and_are_reused_as_the_golden_stream_frees_them() {
    labels_run_out(false);
}

/// The same with the build's label pool (`FccLabelPool`, 8-bit labels) in
/// place of the bench's free list: the labels freed at a column are fed to
/// it one a cycle between columns, and the decision pops its head.
#[test]
fn labels_run_out_and_are_reused_through_the_label_pool() {
    labels_run_out(true);
}

/// B = 8 (255 labels) on frames with far more runs: labels freed at a
/// column serve runs of the next (spec §9.1), and runs that start while
/// every label is in use stay unlabelled, as in the golden stream.
fn labels_run_out(pooled: bool) {
    let build = if pooled {
        FccParams {
            label_bits: 8,
            ..build()
        }
    } else {
        build()
    };
    let seed = 0x5eed_2000;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut first_refused = false;
    for (what, p) in [
        (
            "B = 8, K = 11, bridge 8",
            FccParams {
                label_bits: 8,
                fsize: 11,
                th_v: 0.05,
                bridge: Some(8),
                ..run_params(64, 120)
            },
        ),
        (
            "B = 8, K = 7, bridge 4",
            FccParams {
                label_bits: 8,
                th_v: 0.05,
                bridge: Some(4),
                ..run_params(64, 100)
            },
        ),
    ] {
        let mut b = Bench::new(&build, p.max_label(), seed, what);
        b.pooled = pooled;
        let (mut reused, mut refused) = (false, false);
        for _ in 0..2 {
            let mut f = random_frame(p.rows, p.cols, 0.9, 0.9, false, &mut rng);
            // The last rows start late, while every label is in use, with a
            // point every 12 columns: their first pixels are refused, later
            // runs labelled, and between points the bridge expires, so only
            // hold 4 (which needs the first labelled) could keep them.
            for r in p.rows - 16..p.rows {
                for c in 0..p.cols {
                    if c < p.cols / 3 || c % 12 != 0 {
                        f.set(r, c, None);
                    }
                }
            }
            let feed = Feed {
                bubbles: 0.05,
                drain: true,
                reset_after: None,
            };
            run_frame(&mut b, &p, &f, feed, &mut rng);
            let starts = b.outs.values().filter(|o| o.o_start != 0).count();
            reused |= starts > p.max_label() as usize;
            refused |= b.outs.values().any(|o| o.o_refused != 0);
            first_refused |= (p.rows - 16..p.rows).any(|r| {
                let first = (0..p.cols).find_map(|c| b.outs.get(&(r, c)).filter(|o| o.o_ok != 0));
                first.is_some_and(|o| o.o_refused != 0)
                    && (0..p.cols).any(|c| b.outs[&(r, c)].o_lok != 0)
            });
        }
        assert!(reused, "{what}: no label was reused (seed {seed})");
        assert!(refused, "{what}: labels never ran out (seed {seed})");
    }
    assert!(
        first_refused,
        "no row with its first pixel refused and a later run labelled (seed {seed})"
    );
}

#[test]
fn the_open_limit_refuses_runs_as_the_golden_stream() {
    // Spec §9.1's open limit with labels plentiful: a run starting at a
    // column is refused once the clusters open after the previous column
    // and the runs labelled in this one reach N_o. The bench gives the block
    // N_o less the golden stream's open clusters between columns.
    let build = build();
    let seed = 0x5eed_3000;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    for (what, limit, bridge) in [
        ("N_o = 1", 1, Some(2)),
        ("N_o = 3, bridge 4", 3, Some(4)),
        ("N_o = 12, no bridge limit", 12, None),
        ("N_o = 40", 40, Some(1)),
    ] {
        let p = FccParams {
            th_v: 0.05,
            bridge,
            ring_reach: Some(4),
            open_limit: Some(limit),
            ..run_params(32, 60)
        };
        let mut b = Bench::new(&build, p.max_label(), seed, what);
        let (mut refused, mut labelled) = (0, 0);
        for density in [0.9, 0.4] {
            let f = random_frame(p.rows, p.cols, density, 0.5, false, &mut rng);
            let feed = Feed {
                bubbles: 0.05,
                drain: true,
                reset_after: None,
            };
            run_frame(&mut b, &p, &f, feed, &mut rng);
            refused += b.outs.values().filter(|o| o.o_refused != 0).count();
            labelled += b.outs.values().filter(|o| o.o_start != 0).count();
        }
        assert!(
            refused > 0 && labelled > limit as usize,
            "{what}: {refused} runs refused, {labelled} labelled (seed {seed})"
        );
    }
}
