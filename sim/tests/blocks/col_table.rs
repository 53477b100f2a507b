//! The column core's two halves before the record store, `fcc_col_table`
//! (behind `FccColTableProbe`: the input half `FccColIn` and the slot
//! table half `FccColTable` as the core wires them) under Verilator:
//! frames sent as AXI4-Stream beats in column order with random gaps,
//! three back to back, the union-find queue's events taken at random (a
//! find with its run's accumulator), a reset in the middle of a frame and
//! one in a frame's end (then that frame again), at K = 3 and 11.
//!
//! The bench is the record store: a record per slot, made by a make, two
//! merged by a join that merged (the slot gone back to the slot pool), a
//! run's accumulator added by its find. At each column's marker, every
//! cluster the golden stream closes at that column must be one record
//! holding exactly the labels of its runs and exactly their golden
//! accumulators (`fcc_golden::Acc`, in the core's form), one a run; it is
//! closed, its slot and labels back to the pools. After the frame end's
//! marker (column `C`) no record is left. So the halves' runs, joins,
//! flushes and frame end make the golden clusters. A mismatch prints K,
//! the case, the column, expected, got and the seed.

use std::collections::{HashMap, VecDeque};

use crate::column;
use column::{random_frame, run_params};
use fcc_sim::column::column_beats;

use fcc_golden::{Acc, Frame};
use fcc_params::FccParams;
use fcc_rtl::{BenchBlock, RunLimits};
use fcc_sim::core_form::{thr_inputs, CoreAcc};
use fcc_sim::{c_struct, core_acc_out, load_plain, PlainDut};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

c_struct! {
    /// Inputs of one cycle, named as the ports of `FccColTableProbe`.
    pub struct TbIn {
        pub s_axis_tdata: u64,
        pub ch_t: u64,
        pub cv_t: u64,
        pub sh: u32,
        pub sv: u32,
        pub run_cols: u16,
        pub reach: u16,
        pub ring_f_max: u16,
        pub ring_l_min: u16,
        pub n_o: u16,
        pub slots_used: u16,
        pub in_flight: u16,
        pub labels_free: u16,
        pub free_label: u16,
        pub last_col: u16,
        pub half: u16,
        pub slot: u16,
        pub rst: u8,
        pub rst_next: u8,
        pub s_axis_tvalid: u8,
        pub s_axis_tlast: u8,
        pub run: u8,
        pub restart: u8,
        pub run_next: u8,
        pub run_rows: u8,
        pub last_row: u8,
        pub run_k: u8,
        pub ring_on: u8,
        pub settled: u8,
        pub free_ok: u8,
        pub slot_ok: u8,
        pub ev_ready: u8,
    }
}

c_struct! {
    /// Outputs during one cycle.
    pub struct TbOut with acc_out {
        pub ev_label: u16,
        pub ev_slot: u16,
        pub ev_other: u16,
        pub ev_col: u16,
        pub s_axis_tready: u8,
        pub in_done: u8,
        pub err: u8,
        pub label_take: u8,
        pub idle: u8,
        pub idle_next: u8,
        pub slot_take: u8,
        pub ev_valid: u8,
        pub ev_make: u8,
        pub ev_join: u8,
        pub ev_mark: u8,
        pub ev_ring: u8,
        pub ev_merged: u8,
        pub ev_row: u8,
        pub acc_valid: u8,
        pub miss: u8,
        pub bad: u8,
    }
}

/// Labels the bench's pool gives out (reused once their clusters close).
const LABELS: u16 = 2047;
/// Slots of the record store (`FccLabelPool` at 9 bits: 1 to 511).
const SLOTS: u16 = 511;

/// A record: the labels of its runs, the accumulators of its runs' flushes.
#[derive(Default)]
struct Rec {
    labels: Vec<u16>,
    flushes: Vec<CoreAcc>,
}

/// What the frames saw.
#[derive(Default, Debug)]
struct Seen {
    makes: usize,
    finds: usize,
    merges: usize,
    closed: usize,
    /// Pixel slots sent, and the cycles they took.
    slots: usize,
    cycles: usize,
}

struct Bench {
    dut: PlainDut<TbIn, TbOut>,
    recs: HashMap<u16, Rec>,
    labels: VecDeque<u16>,
    slots: VecDeque<u16>,
    taken: usize,
    makes: usize,
    marks: usize,
    run_label: HashMap<u32, u16>,
    seed: u64,
}

impl Bench {
    /// The pools full, no record: as after a reset.
    fn clear(&mut self) {
        self.recs.clear();
        self.labels = (1..=LABELS).collect();
        self.slots = (1..=SLOTS).collect();
        (self.taken, self.makes, self.marks) = (0, 0, 0);
        self.run_label.clear();
    }

    /// A reset (`rst_next` a cycle ahead of `rst`) with the frame's run
    /// parameters: the representative rows' feed takes its rows then.
    fn reset(&mut self, p: &FccParams, steps: &[(u8, u8)]) {
        for &(rst_next, rst) in steps {
            self.dut.step(&TbIn {
                rst_next,
                rst,
                ..params_in(p)
            });
        }
        self.clear();
    }
}

/// A cycle's inputs with nothing offered: the frame's run parameters.
fn params_in(p: &FccParams) -> TbIn {
    let lim = RunLimits::new(p);
    let thr = thr_inputs(p);
    TbIn {
        run: 1,
        run_next: 1,
        run_rows: p.rows as u8,
        run_cols: p.cols as u16,
        last_row: (p.rows - 1) as u8,
        last_col: (p.cols - 1) as u16,
        half: (p.cols / 2) as u16,
        run_k: p.fsize as u8,
        ch_t: thr.ch_t,
        cv_t: thr.cv_t,
        sh: thr.sh,
        sv: thr.sv,
        reach: lim.reach,
        ring_on: lim.ring_on as u8,
        ring_f_max: lim.ring_f_max,
        ring_l_min: lim.ring_l_min,
        n_o: 511,
        ..TbIn::default()
    }
}

/// Each golden run's accumulator, in the core's form.
fn run_accs(p: &FccParams, f: &Frame, runs: &[u32]) -> HashMap<u32, CoreAcc> {
    let half = (p.cols / 2) as u32;
    let mut acc: HashMap<u32, Acc> = HashMap::new();
    for c in 0..p.cols {
        for r in 0..p.rows {
            let run = runs[r * p.cols + c];
            if run != 0 {
                let q = f.get(r, c).expect("a labelled pixel has a point");
                acc.entry(run)
                    .or_default()
                    .add_in_scan(r as u32, c as u32, q, half);
            }
        }
    }
    acc.iter().map(|(&r, a)| (r, CoreAcc::of(a))).collect()
}

/// Sorted by their text, to compare as multisets.
fn sorted(mut v: Vec<CoreAcc>) -> Vec<CoreAcc> {
    v.sort_by_cached_key(|a| format!("{a:?}"));
    v
}

/// A frame with its golden clusters: the runs, the clusters closed at each
/// column (the frame end's at `C`), each run's accumulator.
struct Golden {
    beats: Vec<u64>,
    runs: Vec<u32>,
    at: Vec<Vec<Vec<u32>>>,
    accs: HashMap<u32, CoreAcc>,
}

impl Golden {
    fn of(p: &FccParams, f: &Frame) -> Golden {
        let column::Closing { runs, at } = column::closing(p, f);
        let accs = run_accs(p, f, &runs);
        Golden {
            beats: column_beats(p, f),
            runs,
            at,
            accs,
        }
    }
}

/// Frames back to back through the halves (the next frame's beats offered
/// as soon as the input stage has the last one's), each cluster checked at
/// its marker; `cut`: a reset after that many beats of the last frame (all
/// of them: in its frame end, between the last column's marker and the
/// frame end's), then that frame again.
fn run_frames(
    b: &mut Bench,
    p: &FccParams,
    frames: &[Golden],
    ready: f64,
    cut: Option<usize>,
    rng: &mut ChaCha8Rng,
    what: &str,
) -> Seen {
    let px = p.pixels();
    let per = p.cols + 1;
    let total = frames.len() * px;
    let cut = cut.map(|n| (frames.len() - 1) * px + n);
    let mut seen = Seen {
        slots: total,
        ..Seen::default()
    };
    // Beats sent (all frames), markers out (all frames); the frame a
    // restart is owed to; this frame's makes and finds (a run flushes once).
    let (mut next, mut cut, mut restart) = (0usize, cut, Some(0usize));
    let (mut made, mut found) = (0usize, 0usize);
    let mut given: VecDeque<u16> = VecDeque::new();
    let mut cycles = 0usize;
    let seed = b.seed;
    let at_ = |n: usize, c: usize| {
        format!(
            "K = {}, {what}: frame {n}, column {c}, seed {seed}",
            p.fsize
        )
    };
    while b.marks < frames.len() * per {
        // A cut after all the beats lands in the frame end: the last
        // column's marker out, the frame end's not yet.
        let due = match cut {
            Some(n) if n < total => next == n,
            Some(_) => b.marks + 1 == frames.len() * per,
            None => false,
        };
        if due {
            // A reset (mid-frame, or in the last frame's end), then that
            // frame again; the frames before it done or abandoned.
            b.reset(p, &[(1, 0), (0, 1)]);
            let last = frames.len() - 1;
            (cut, next, restart) = (None, last * px, Some(last));
            b.marks = last * per;
            (made, found) = (0, 0);
            given.clear();
        }
        let frame = next / px;
        let valid = next < total && restart.is_none() && rng.gen_bool(0.8);
        let in_flight = b.taken - b.makes;
        // The next beat's column, counted as markers are.
        let col = (next.min(total - 1) / px) * per + (next.min(total - 1) % px) / p.rows;
        let i = TbIn {
            s_axis_tdata: if valid {
                frames[frame].beats[next % px]
            } else {
                0
            },
            s_axis_tvalid: valid as u8,
            s_axis_tlast: (valid && (next + 1) % px == 0) as u8,
            restart: restart.is_some() as u8,
            slots_used: b.recs.len() as u16,
            in_flight: in_flight as u16,
            labels_free: b.labels.len() as u16,
            settled: (in_flight == 0 && b.marks >= col) as u8,
            free_ok: !b.labels.is_empty() as u8,
            free_label: b.labels.front().copied().unwrap_or(0),
            slot_ok: !b.slots.is_empty() as u8,
            slot: b.slots.front().copied().unwrap_or(0),
            ev_ready: rng.gen_bool(ready) as u8,
            ..params_in(p)
        };
        restart = None;
        let o = b.dut.step(&i);
        let (n, c) = (b.marks / per, b.marks % per);
        assert_eq!(o.err, 0, "{}: a frame error", at_(n, c));
        assert_eq!(o.bad, 0, "{}: bad", at_(n, c));
        assert_eq!(o.miss, 0, "{}: a label not in its row", at_(n, c));
        if o.label_take != 0 {
            b.labels.pop_front().expect("a label given");
            b.taken += 1;
        }
        if o.slot_take != 0 {
            given.push_back(b.slots.pop_front().expect("a slot given"));
        }
        if valid && o.s_axis_tready != 0 {
            next += 1;
        }
        if o.in_done != 0 && next % px == 0 && next < total && next > 0 {
            // The input stage has the frame: the next one starts.
            restart = Some(next / px);
        }
        let find = o.ev_make == 0 && o.ev_join == 0 && o.ev_mark == 0;
        if o.ev_valid != 0 && i.ev_ready != 0 && (!find || o.acc_valid != 0) {
            let g = &frames[n];
            let ec = usize::from(o.ev_col);
            if o.ev_make != 0 {
                let r = usize::from(o.ev_row);
                let run = g.runs[r * p.cols + ec];
                assert_ne!(run, 0, "{}, row {r}: a make where no run is", at_(n, ec));
                assert_eq!(
                    given.pop_front(),
                    Some(o.ev_slot),
                    "{}, row {r}: a make's slot (right) not the one the pool gave (left)",
                    at_(n, ec)
                );
                assert!(
                    !b.recs.contains_key(&o.ev_slot),
                    "{}: a make into slot {} in use",
                    at_(n, ec),
                    o.ev_slot
                );
                b.recs.insert(
                    o.ev_slot,
                    Rec {
                        labels: vec![o.ev_label],
                        flushes: Vec::new(),
                    },
                );
                assert!(
                    b.run_label.insert(run, o.ev_label).is_none(),
                    "{}, row {r}: run {run} made twice",
                    at_(n, ec)
                );
                b.makes += 1;
                made += 1;
                seen.makes += 1;
            } else if o.ev_join != 0 {
                if o.ev_merged != 0 {
                    let gone = b.recs.remove(&o.ev_other).unwrap_or_else(|| {
                        panic!("{}: slot {} merged away, not open", at_(n, ec), o.ev_other)
                    });
                    let keep = b.recs.get_mut(&o.ev_slot).unwrap_or_else(|| {
                        panic!("{}: slot {} kept, not open", at_(n, ec), o.ev_slot)
                    });
                    keep.labels.extend(gone.labels);
                    keep.flushes.extend(gone.flushes);
                    b.slots.push_back(o.ev_other);
                    seen.merges += 1;
                }
            } else if o.ev_mark != 0 {
                assert_eq!(ec, c, "{}: a marker out of order", at_(n, c));
                for rs in &g.at[c] {
                    close(b, g, rs, &at_(n, c));
                    seen.closed += 1;
                }
                b.marks += 1;
                if c == p.cols {
                    // The frame's end: every record closed, a find a run.
                    assert!(
                        b.recs.is_empty(),
                        "{}: {} records open after the frame end",
                        at_(n, c),
                        b.recs.len()
                    );
                    assert_eq!(
                        found,
                        made,
                        "{}: finds (left) against runs made (right)",
                        at_(n, c)
                    );
                    (made, found) = (0, 0);
                    b.run_label.clear();
                }
            } else {
                let acc = core_acc_out!(o);
                b.recs
                    .get_mut(&o.ev_slot)
                    .unwrap_or_else(|| {
                        panic!("{}: a find of slot {}, not open", at_(n, ec), o.ev_slot)
                    })
                    .flushes
                    .push(acc);
                found += 1;
                seen.finds += 1;
            }
        }
        cycles += 1;
        assert!(
            cycles < 20 * total + 2000,
            "{}: {} of {} markers out after {cycles} cycles ({next} beats in)",
            at_(n, c),
            b.marks,
            frames.len() * per
        );
    }
    // Nothing more comes out.
    for _ in 0..40 {
        let o = b.dut.step(&TbIn {
            ev_ready: 1,
            ..params_in(p)
        });
        assert_eq!(
            o.ev_valid, 0,
            "K = {}, {what}: an event after the last frame end",
            p.fsize
        );
    }
    b.marks = 0;
    seen.cycles = cycles;
    seen
}

/// Cluster `rs` (golden runs) closed at this marker: one record holding
/// exactly its runs' labels and accumulators; its slot and labels back.
fn close(b: &mut Bench, g: &Golden, rs: &[u32], at: &str) {
    let mut want: Vec<u16> = rs
        .iter()
        .map(|r| {
            *b.run_label
                .get(r)
                .unwrap_or_else(|| panic!("{at}: run {r} never made"))
        })
        .collect();
    want.sort_unstable();
    let slot = *b
        .recs
        .iter()
        .find(|(_, rec)| rec.labels.contains(&want[0]))
        .unwrap_or_else(|| panic!("{at}: label {} in no open record", want[0]))
        .0;
    let rec = b.recs.remove(&slot).expect("found");
    let mut got = rec.labels.clone();
    got.sort_unstable();
    assert_eq!(
        got, want,
        "{at}: the record's labels (left) against the golden cluster's runs' (right, runs {rs:?})"
    );
    let want_acc = sorted(rs.iter().map(|r| g.accs[r]).collect());
    let got_acc = sorted(rec.flushes);
    if let Some(n) =
        (0..got_acc.len().max(want_acc.len())).find(|&n| got_acc.get(n) != want_acc.get(n))
    {
        panic!(
            "{at}: the record of runs {rs:?}: {} flushes, {} runs; the first differing (in sorted order), expected {:?}, got {:?}",
            got_acc.len(),
            want_acc.len(),
            want_acc.get(n),
            got_acc.get(n)
        );
    }
    b.slots.push_back(slot);
    b.labels.extend(got);
    for r in rs {
        b.run_label.remove(r);
    }
}

fn every_case(k: usize) {
    let build = FccParams {
        fsize: k,
        ..FccParams::default()
    };
    let cases: [(&str, FccParams, f64); 3] = [
        (
            "the fewest rows, events taken often",
            FccParams {
                fsize: k,
                // `FccRepJoins` takes frames of `max(16, K + 8)` rows.
                ..run_params((k + 8).max(16), 48)
            },
            0.9,
        ),
        (
            "bridge 2, ring reach 6, events taken rarely",
            FccParams {
                fsize: k,
                bridge: Some(2),
                ring_reach: Some(6),
                ..run_params(20, 40)
            },
            0.3,
        ),
        (
            "range-adaptive, events taken every cycle",
            FccParams {
                fsize: k,
                th_h: 0.1,
                th_h_slope: 0.05,
                th_v_slope: 0.03,
                ..run_params(24, 36)
            },
            1.0,
        ),
    ];
    let model = load_plain::<TbIn, TbOut>(BenchBlock::ColTable, &build).expect("the two halves");
    let mut all = Seen::default();
    for (n, (what, p, ready)) in cases.iter().enumerate() {
        let seed = 0xc07a_0000 + (k * 16 + n) as u64;
        let mut b = Bench {
            dut: PlainDut::new(model.clone()),
            recs: HashMap::new(),
            labels: VecDeque::new(),
            slots: VecDeque::new(),
            taken: 0,
            makes: 0,
            marks: 0,
            run_label: HashMap::new(),
            seed,
        };
        b.reset(p, &[(1, 0), (1, 1), (0, 1), (0, 0)]);
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let frames: Vec<Golden> = [(0.8, 0.05), (0.5, 0.1), (0.7, 0.05)]
            .iter()
            .map(|&(density, jump)| {
                Golden::of(
                    p,
                    &random_frame(p.rows, p.cols, density, jump, true, &mut rng),
                )
            })
            .collect();
        // Three frames back to back; two with a reset mid-frame in the
        // second; one with a reset in its frame end.
        let mid = rng.gen_range(1..p.pixels());
        for (from, cut) in [(0, None), (1, Some(mid)), (2, Some(p.pixels()))] {
            let s = run_frames(&mut b, p, &frames[from..], *ready, cut, &mut rng, what);
            all.makes += s.makes;
            all.finds += s.finds;
            all.merges += s.merges;
            all.closed += s.closed;
            all.slots += s.slots;
            all.cycles += s.cycles;
        }
    }
    eprintln!("K = {k}: {all:?}");
    assert!(
        all.makes > 300 && all.merges > 30 && all.closed > 100,
        "K = {k}: too little seen: {all:?}"
    );
}

// CI runs the datapath's bench (`col_core`), the same halves to the
// records; these check the clusters at each marker, to find where a
// difference starts.
#[test]
#[ignore = "CI time: col_core covers the halves to the records; run with --ignored"]
fn the_halves_make_the_golden_clusters_k3() {
    every_case(3);
}

#[test]
#[ignore = "CI time: col_core covers the halves to the records; run with --ignored"]
fn the_halves_make_the_golden_clusters_k11() {
    every_case(11);
}
