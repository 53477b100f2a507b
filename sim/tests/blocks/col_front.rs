//! The column core's front `fcc_col_front` (behind `FccColFrontProbe`:
//! `FccPixThr`, `FccRowRuns`, `FccColWindow` and `FccColDist` as the core
//! wires them) alone under Verilator, against the golden stream: seeded
//! frames in column order, with bubbles and back to back, at K = 7 (the
//! input half's bench, `col_in`, runs the front at K = 3 and 11 through
//! this bench's check), fixed and range-adaptive thresholds, bridge and
//! ring-reach limits.
//! Every pixel must leave `FRONT_LATENCY` cycles after it went in, with its
//! golden run (a label taken from the free list at the run's first pixel,
//! the same for the run's other pixels), hold 3, the ring check and the
//! row's held run (spec §3, §9.2), and every window entry it joins with
//! the entry's run (spec §4 in column order): `column::pixels`, the
//! reference the blocks' own benches share. A mismatch prints K, the case,
//! the pixel, expected, got and the seed.

use crate::column;
use column::{run_params, Pix};
use std::collections::{HashMap, VecDeque};

use fcc_golden::{Frame, Stream};
use fcc_params::FccParams;
use fcc_rtl::{BenchBlock, RunLimits, FRONT_LATENCY};
use fcc_sim::core_form::{offset_binary as ob, thr_inputs};
use fcc_sim::{c_struct, load_plain, PlainDut};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

c_struct! {
    /// Inputs of one cycle, named as the ports of `FccColFrontProbe`.
    pub struct FrIn {
        pub ch_t: u64,
        pub cv_t: u64,
        pub sh: u32,
        pub sv: u32,
        pub x: u16,
        pub y: u16,
        pub z: u16,
        pub col: u16,
        pub last_col: u16,
        pub reach: u16,
        pub ring_f_max: u16,
        pub ring_l_min: u16,
        pub free_label: u16,
        pub open_room: u16,
        pub rst: u8,
        pub valid: u8,
        pub ok: u8,
        pub row: u8,
        pub first: u8,
        pub last: u8,
        pub ring_on: u8,
        pub last_row: u8,
        pub run_k: u8,
        pub free_ok: u8,
    }
}

c_struct! {
    /// Outputs during one cycle.
    pub struct FrOut {
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
        pub o_col: u16,
        pub o_label: u16,
        pub o_ring_a: u16,
        pub o_ring_b: u16,
        pub o_hold_drop: u16,
        pub o_hold_add: u16,
        pub take: u8,
        pub o_valid: u8,
        pub o_ok: u8,
        pub o_lok: u8,
        pub o_row: u8,
        pub o_first: u8,
        pub o_last: u8,
        pub o_start: u8,
        pub o_refused: u8,
        pub o_ring_first: u8,
        pub o_ring: u8,
    }
}

impl FrOut {
    /// Window entry `e`'s label.
    pub fn label(&self, e: usize) -> u16 {
        let w = [
            self.lw0, self.lw1, self.lw2, self.lw3, self.lw4, self.lw5, self.lw6, self.lw7,
            self.lw8, self.lw9, self.lw10, self.lw11, self.lw12, self.lw13,
        ];
        (w[e / 4] >> (16 * (e % 4))) as u16
    }
}

/// The open limit's room when there is none (`FccRowRuns`' widest).
const NO_LIMIT: u16 = 1023;

/// Labels handed out, never reused within a bench: below `0xFFFF`.
const LABELS: u16 = 0xFFFE;

struct Bench {
    dut: PlainDut<FrIn, FrOut>,
    /// The next label of the free list.
    next_label: u16,
    /// Labels taken, in order, until their run's first pixel leaves.
    taken: VecDeque<u16>,
    cycle: u64,
    /// Each pixel's input cycle, by (row, col), while in flight.
    fed: HashMap<(usize, usize), u64>,
    outs: HashMap<(usize, usize), FrOut>,
    seed: u64,
}

impl Bench {
    fn new(build: &FccParams, seed: u64) -> Bench {
        let model =
            load_plain::<FrIn, FrOut>(BenchBlock::ColFront, build).expect("column front model");
        Bench {
            dut: PlainDut::new(model),
            next_label: 1,
            taken: VecDeque::new(),
            cycle: 0,
            fed: HashMap::new(),
            outs: HashMap::new(),
            seed,
        }
    }

    /// One cycle: the pixel at (row, col) of `f` or a bubble in.
    fn cycle(&mut self, p: &FccParams, f: &Frame, slot: Option<(usize, usize)>, rst: bool) {
        let lim = RunLimits::new(p);
        let thr = thr_inputs(p);
        let mut i = FrIn {
            rst: rst as u8,
            ch_t: thr.ch_t,
            cv_t: thr.cv_t,
            sh: thr.sh,
            sv: thr.sv,
            last_col: (p.cols - 1) as u16,
            reach: lim.reach,
            ring_on: lim.ring_on as u8,
            ring_f_max: lim.ring_f_max,
            ring_l_min: lim.ring_l_min,
            last_row: (p.rows - 1) as u8,
            run_k: p.fsize as u8,
            free_ok: 1,
            free_label: self.next_label,
            open_room: NO_LIMIT,
            ..FrIn::default()
        };
        if let Some((r, c)) = slot {
            i.valid = 1;
            i.row = r as u8;
            i.col = c as u16;
            i.first = (r == 0 && c == 0) as u8;
            i.last = (r == p.rows - 1 && c == p.cols - 1) as u8;
            if let Some(q) = f.get(r, c) {
                i.ok = 1;
                i.x = ob(q[0]);
                i.y = ob(q[1]);
                i.z = ob(q[2]);
            }
            self.fed.insert((r, c), self.cycle);
        }
        let o = self.dut.step(&i);
        if o.take != 0 {
            self.taken.push_back(self.next_label);
            self.next_label = self.next_label % LABELS + 1;
        }
        if o.o_valid != 0 && !rst {
            let at = (o.o_row as usize, o.o_col as usize);
            let t = self.fed.remove(&at);
            assert_eq!(
                t.map(|t| self.cycle - t),
                Some(FRONT_LATENCY as u64),
                "pixel {at:?} left at cycle {}, seed {}",
                self.cycle,
                self.seed
            );
            if o.o_start != 0 {
                assert_eq!(
                    self.taken.pop_front(),
                    Some(o.o_label),
                    "pixel {at:?}: a started run's label is not the one taken, seed {}",
                    self.seed
                );
            }
            self.outs.insert(at, o);
        }
        self.cycle += 1;
    }

    fn drain(&mut self, p: &FccParams, f: &Frame) {
        for _ in 0..FRONT_LATENCY + 2 {
            self.cycle(p, f, None, false);
        }
    }
}

/// Feed `f` in column order (bubbles at the rate `bubbles`; `cut`: a reset
/// after that many pixels, then the whole frame), then check every pixel
/// against the golden stream's.
fn run_frame(
    b: &mut Bench,
    p: &FccParams,
    f: &Frame,
    bubbles: f64,
    cut: Option<usize>,
    what: &str,
) -> Seen {
    let mut rng = ChaCha8Rng::seed_from_u64(b.seed ^ 0xb0b);
    if let Some(n) = cut {
        for k in 0..n {
            b.cycle(p, f, Some((k % p.rows, k / p.rows)), false);
        }
        b.cycle(p, f, None, true);
        // Nothing fed before the reset may come out after it.
        b.fed.clear();
        b.taken.clear();
        b.drain(p, f);
    }
    b.outs.clear();
    for c in 0..p.cols {
        for r in 0..p.rows {
            while rng.gen_bool(bubbles) {
                b.cycle(p, f, None, false);
            }
            b.cycle(p, f, Some((r, c)), false);
        }
    }
    b.drain(p, f);
    assert!(
        b.taken.is_empty(),
        "{what}: labels taken but not seen at a start, seed {}",
        b.seed
    );
    check(&b.outs, b.seed, p, &golden_pixels(p, f), what)
}

/// Every pixel of `f` as the front must give it, from the golden stream.
pub fn golden_pixels(p: &FccParams, f: &Frame) -> Vec<Pix> {
    let mut stream = Stream::new(p).expect("the golden stream");
    let mut column = vec![None; p.rows];
    for c in 0..p.cols {
        for (r, v) in column.iter_mut().enumerate() {
            *v = f.get(r, c);
        }
        stream.push_column(&column).expect("a column");
    }
    stream.finish().expect("the frame end");
    let mut runs = Vec::new();
    stream.runs_into(&mut runs).expect("the runs");
    column::pixels(p, f, &runs)
}

/// What a frame's check saw: runs started, ring checks, hold changes,
/// entries joined.
#[derive(Default, Debug)]
pub struct Seen {
    pub starts: usize,
    pub rings: usize,
    pub holds: usize,
    pub hits: usize,
    /// Points left unlabelled (spec §9.1's limits).
    pub unlabelled: usize,
}

impl Seen {
    pub fn add(&mut self, s: Seen) {
        self.starts += s.starts;
        self.rings += s.rings;
        self.holds += s.holds;
        self.hits += s.hits;
        self.unlabelled += s.unlabelled;
    }

    /// The frames reached every check.
    pub fn enough(&self) -> bool {
        self.starts > 100 && self.rings > 5 && self.holds > 100 && self.hits > 1000
    }
}

/// Every pixel's output against its golden one: runs mapped to labels at
/// their first pixels.
pub fn check(
    outs: &HashMap<(usize, usize), FrOut>,
    seed: u64,
    p: &FccParams,
    want: &[Pix],
    what: &str,
) -> Seen {
    let mut seen = Seen::default();
    let mut label_of: HashMap<u32, u16> = HashMap::new();
    let lab = |m: &HashMap<u32, u16>, run: u32| if run == 0 { 0 } else { m[&run] };
    for px in want {
        let at = format!(
            "K = {}, {what}: row {}, col {}, seed {}",
            p.fsize, px.row, px.col, seed
        );
        let o = outs
            .get(&(px.row, px.col))
            .unwrap_or_else(|| panic!("{at}: never left the front"));
        assert_eq!(o.o_ok != 0, px.ok, "{at}: ok");
        let (first, last) = (
            px.row == 0 && px.col == 0,
            px.row + 1 == p.rows && px.col + 1 == p.cols,
        );
        assert_eq!(
            (o.o_first != 0, o.o_last != 0),
            (first, last),
            "{at}: the frame's first and last pixel"
        );
        assert_eq!(o.o_start != 0, px.start, "{at}: starts a run");
        if px.start {
            label_of.insert(px.run, o.o_label);
        }
        if p.open_limit.is_none() || px.run != 0 {
            assert_eq!(o.o_refused, 0, "{at}: refused with labels to spare");
        }
        assert_eq!(o.o_lok != 0, px.run != 0, "{at}: labelled");
        assert_eq!(
            o.o_label,
            lab(&label_of, px.run),
            "{at}: run {}'s label",
            px.run
        );
        assert_eq!(o.o_ring_first != 0, px.ring_first, "{at}: hold 3");
        let ring = px.ring.map(|(a, z)| (lab(&label_of, a), lab(&label_of, z)));
        let got_ring = (o.o_ring != 0).then_some((o.o_ring_a, o.o_ring_b));
        assert_eq!(got_ring, ring, "{at}: the ring check (first, last)");
        let hold = px.hold.map_or((0, 0), |(was, now)| {
            (lab(&label_of, was), lab(&label_of, now))
        });
        assert_eq!(
            (o.o_hold_drop, o.o_hold_add),
            hold,
            "{at}: the row's held run (dropped, added)"
        );
        let hits: Vec<(usize, u16)> = px
            .hits
            .iter()
            .map(|&(e, run)| (e, lab(&label_of, run)))
            .collect();
        let got: Vec<(usize, u16)> = (0..64)
            .filter(|e| o.hits >> e & 1 != 0)
            .map(|e| (e, o.label(e)))
            .collect();
        // An unlabelled pixel's hits are not used (`FccRepMatch` masks them
        // with `lok`); the golden stream gives it none.
        if px.run != 0 {
            assert_eq!(got, hits, "{at}: the entries joined (entry, label)");
        }
        seen.starts += usize::from(px.start);
        seen.rings += usize::from(px.ring.is_some());
        seen.holds += usize::from(px.hold.is_some());
        seen.hits += hits.len();
        seen.unlabelled += usize::from(px.ok && px.run == 0);
    }
    seen
}

/// The cases every K runs: frames back to back on one instance.
fn every_case(k: usize) {
    let build = FccParams {
        fsize: k,
        ..FccParams::default()
    };
    let cases: [(&str, FccParams, f64); 4] = [
        (
            "fixed thresholds, no limits",
            FccParams {
                fsize: k,
                ..run_params(16, 40)
            },
            0.0,
        ),
        (
            "bridge 2, ring reach 6, bubbles",
            FccParams {
                fsize: k,
                bridge: Some(2),
                ring_reach: Some(6),
                ..run_params(20, 36)
            },
            0.3,
        ),
        (
            "range-adaptive",
            FccParams {
                fsize: k,
                th_h: 0.1,
                th_h_slope: 0.05,
                th_v_slope: 0.03,
                ..run_params(24, 30)
            },
            0.1,
        ),
        (
            "all rows of the build",
            FccParams {
                fsize: k,
                ..run_params(build.rows, 20)
            },
            0.0,
        ),
    ];
    let mut seen = Seen::default();
    for (n, (what, p, bubbles)) in cases.iter().enumerate() {
        let seed = 0xf207_0000 + (k * 16 + n) as u64;
        let mut b = Bench::new(&build, seed);
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut frames = vec![];
        for (density, jump) in [(0.8, 0.05), (0.4, 0.1)] {
            let f = column::random_frame(p.rows, p.cols, density, jump, true, &mut rng);
            frames.push(run_frame(&mut b, p, &f, *bubbles, None, what));
        }
        let f = column::random_frame(p.rows, p.cols, 0.7, 0.05, false, &mut rng);
        let cut = rng.gen_range(1..p.rows * p.cols);
        let what = format!("{what}, reset mid-frame");
        frames.push(run_frame(&mut b, p, &f, *bubbles, Some(cut), &what));
        frames.into_iter().for_each(|s| seen.add(s));
    }
    eprintln!("K = {k}: {seen:?}");
    assert!(seen.enough(), "K = {k}: too little seen: {seen:?}");
}

#[test]
fn every_pixel_leaves_with_its_golden_run_and_joins_k7() {
    every_case(7);
}
