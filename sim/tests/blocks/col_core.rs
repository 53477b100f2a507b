//! The column core's datapath, `fcc_col_core` (`FccColCore`: the input,
//! slot table and record store halves wired) under Verilator: frames sent
//! as AXI4-Stream beats in column order with random gaps, back to back,
//! the record stream taken under random back-pressure and read by
//! `fcc_pixel::record::RecordReader`. Every record and every end beat must
//! be the golden stream's (`fcc_golden::Stream`, spec §9.3 and §9.4),
//! record for record and in order: ids, counts, columns, rows, boxes,
//! ranges, sums, seams, the end beat's count and flags. Cases: the fewest
//! rows, bridge and ring limits (seam clusters), range-adaptive
//! thresholds, an open limit that binds (the end beat's overflow); in
//! each, frames whose `tlast` comes early (the rest of the frame empty)
//! and late (the beats after it dropped), both with the end beat's input
//! error, and a reset in the middle of a frame (then that frame again).
//! At K = 3 and 11. A
//! mismatch prints K, the case, the frame, the item and the seed, the
//! frame's items read and expected from there to its end, and the first
//! difference in full.

use std::collections::VecDeque;

use crate::column::{random_frame, run_params};

use fcc_golden::Frame;
use fcc_params::FccParams;
use fcc_pixel::record::{Item, RecordReader};
use fcc_rtl::{BenchBlock, RunLimits};
use fcc_sim::column::{column_beats, golden_items, short};
use fcc_sim::core_form::thr_inputs;
use fcc_sim::{c_struct, load_plain, PlainDut};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

c_struct! {
    /// Inputs of one cycle, named as the ports of `FccColCore`.
    pub struct TbIn {
        pub s_axis_tdata: u64,
        pub ch_t: u64,
        pub cv_t: u64,
        pub sh: u32,
        pub sv: u32,
        pub run_cols: u16,
        pub last_col: u16,
        pub col_half: u16,
        pub reach: u16,
        pub ring_f_max: u16,
        pub ring_l_min: u16,
        pub n_o: u16,
        pub rst: u8,
        pub rst_next: u8,
        pub s_axis_tvalid: u8,
        pub s_axis_tlast: u8,
        pub run: u8,
        pub restart: u8,
        pub run_next: u8,
        pub start_hold: u8,
        pub run_rows: u8,
        pub last_row: u8,
        pub run_k: u8,
        pub h: u8,
        pub ring_on: u8,
        pub m_axis_tready: u8,
    }
}

c_struct! {
    /// Outputs during one cycle.
    pub struct TbOut {
        pub m_axis_tdata: u64,
        pub s_axis_tready: u8,
        pub in_done: u8,
        pub idle: u8,
        pub idle_next: u8,
        pub m_axis_tvalid: u8,
        pub m_axis_tlast: u8,
        pub col_held: u8,
        pub miss: u8,
        pub bad: u8,
    }
}

/// The build's label bits: the column core's (13 hold the corpus).
const LABEL_BITS: u32 = 13;

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
        col_half: (p.cols / 2) as u16,
        run_k: p.fsize as u8,
        h: (p.fsize / 2) as u8,
        ch_t: thr.ch_t,
        cv_t: thr.cv_t,
        sh: thr.sh,
        sv: thr.sv,
        reach: lim.reach,
        ring_on: lim.ring_on as u8,
        ring_f_max: lim.ring_f_max,
        ring_l_min: lim.ring_l_min,
        n_o: p.open_limit.map_or(511, |n| n.min(511)) as u16,
        ..TbIn::default()
    }
}

/// A frame's beats in and the golden stream's items out.
struct Golden {
    beats: Vec<u64>,
    items: Vec<Item>,
}

impl Golden {
    fn of(p: &FccParams, f: &Frame) -> Golden {
        Golden {
            beats: column_beats(p, f),
            items: items(p, f, false),
        }
    }

    /// The frame's `tlast` after its first `n` beats: the frame with the
    /// rest of its pixels empty, and an input error (spec §9.4).
    fn early(p: &FccParams, f: &Frame, n: usize) -> Golden {
        let mut short = f.clone();
        for k in n..p.pixels() {
            short.set(k % p.rows, k / p.rows, None);
        }
        Golden {
            beats: column_beats(p, f)[..n].to_vec(),
            items: items(p, &short, true),
        }
    }

    /// The frame's `tlast` `extra` beats after its last pixel: those beats
    /// dropped, and an input error.
    fn late(p: &FccParams, f: &Frame, extra: usize, rng: &mut ChaCha8Rng) -> Golden {
        let mut b = column_beats(p, f);
        b.extend((0..extra).map(|_| rng.gen::<u64>() & ((1 << 49) - 1)));
        Golden {
            beats: b,
            items: items(p, f, true),
        }
    }
}

/// The golden stream's records of a frame, then its end beat.
fn items(p: &FccParams, f: &Frame, frame_error: bool) -> Vec<Item> {
    golden_items(p, f, frame_error).expect("the golden stream")
}

/// The frame's items from the first difference to its end beat, read and
/// expected, then the first difference in full.
fn mismatch(at: &str, got: &[Item], want: &[Item]) -> ! {
    for (g, w) in got.iter().zip(want) {
        eprintln!(
            "got      {}
expected {}",
            short(g),
            short(w)
        );
    }
    panic!(
        "{at}: the item (left) against the golden one (right)\n  left: {:?}\n right: {:?}",
        got[0], want[0]
    );
}

/// What the runs saw.
#[derive(Default, Debug)]
struct Seen {
    records: usize,
    seams: usize,
    overflows: usize,
    frames: usize,
    errors: usize,
    pixels: usize,
    cycles: usize,
}

/// The frames back to back (the next frame's beats offered as soon as the
/// input stage has the last one's); `cut`: a reset after that many beats
/// of the last frame, then that frame again. Every item out is checked
/// against the next one expected.
#[allow(clippy::too_many_arguments)]
fn run_frames(
    dut: &mut PlainDut<TbIn, TbOut>,
    p: &FccParams,
    frames: &[Golden],
    ready: f64,
    cut: Option<usize>,
    rng: &mut ChaCha8Rng,
    what: &str,
    seed: u64,
) -> Seen {
    let total: usize = frames.iter().map(|g| g.beats.len()).sum();
    let last = frames.len() - 1;
    let mut cut = cut;
    let mut seen = Seen::default();
    // Items expected, each with its frame; the reader of the beats.
    let mut want: VecDeque<(usize, Item)> = frames
        .iter()
        .enumerate()
        .flat_map(|(n, g)| g.items.iter().map(move |i| (n, *i)))
        .collect();
    let mut reader = RecordReader::new();
    // The frame being sent, its beats sent, the beats sent in all; a
    // restart owed.
    let (mut frame, mut pos, mut sent) = (0usize, 0usize, 0usize);
    let mut restart = Some(0usize);
    let mut owed = false;
    let mut cycles = 0usize;
    let mut item = 0usize;
    // The first mismatch: where, the items read and expected since.
    let mut bad: Option<(String, Vec<Item>, Vec<Item>)> = None;
    while !want.is_empty() {
        if frame == last && cut == Some(pos) {
            // A reset mid-frame, then that frame again.
            for (rst_next, rst) in [(1, 0), (0, 1)] {
                dut.step(&TbIn {
                    rst_next,
                    rst,
                    ..params_in(p)
                });
            }
            (cut, frame, pos, restart, owed) = (None, last, 0, Some(last), false);
            want = frames[last].items.iter().map(|i| (last, *i)).collect();
            reader = RecordReader::new();
        }
        let beats = &frames[frame.min(last)].beats;
        let valid = frame <= last && restart.is_none() && rng.gen_bool(0.8);
        let take = rng.gen_bool(ready);
        let i = TbIn {
            s_axis_tdata: if valid { beats[pos] } else { 0 },
            s_axis_tvalid: valid as u8,
            s_axis_tlast: (valid && pos + 1 == beats.len()) as u8,
            restart: restart.is_some() as u8,
            m_axis_tready: take as u8,
            ..params_in(p)
        };
        restart = None;
        let o = dut.step(&i);
        let (n, _) = want.front().copied().expect("an item expected");
        let at = format!(
            "K = {}, {what}: frame {n}, item {item}, seed {seed:#x}",
            p.fsize
        );
        assert_eq!(o.bad, 0, "{at}: bad");
        assert_eq!(o.miss, 0, "{at}: a label not in its row");
        if valid && o.s_axis_tready != 0 {
            (pos, sent) = (pos + 1, sent + 1);
            if pos == beats.len() {
                (frame, pos) = (frame + 1, 0);
                // The next frame waits for the input stage to be done.
                owed = frame <= last;
            }
        }
        if owed && o.in_done != 0 {
            (owed, restart) = (false, Some(frame));
        }
        if o.m_axis_tvalid != 0 && take {
            let k = reader.beats();
            match reader.push(o.m_axis_tdata, o.m_axis_tlast != 0) {
                Ok(Some(got)) => {
                    let (_, exp) = want.pop_front().expect("an item expected");
                    if got != exp || bad.is_some() {
                        // Keep reading to the frame's end beat, then show
                        // the frame's items from the first difference.
                        bad.get_or_insert_with(|| (at.clone(), Vec::new(), Vec::new()));
                        let (first, gots, exps) = bad.as_mut().expect("set");
                        gots.push(got);
                        exps.push(exp);
                        if matches!(got, Item::End(_)) {
                            mismatch(first, gots, exps);
                        }
                    }
                    item += 1;
                    match got {
                        Item::Record(r) => {
                            seen.records += 1;
                            seen.seams += usize::from(r.seam);
                        }
                        Item::End(e) => {
                            seen.frames += 1;
                            seen.overflows += usize::from(e.overflow);
                            seen.errors += usize::from(e.frame_error);
                            item = 0;
                        }
                    }
                }
                Ok(None) => {}
                Err(e) => panic!("{at}: output beat {k}: {e} (beat {:#x})", o.m_axis_tdata),
            }
        }
        cycles += 1;
        assert!(
            cycles < 30 * total + 20_000,
            "{at}: {} items still expected after {cycles} cycles ({sent} beats in)",
            want.len()
        );
    }
    // Nothing more comes out.
    for _ in 0..200 {
        let o = dut.step(&TbIn {
            m_axis_tready: 1,
            ..params_in(p)
        });
        assert_eq!(
            o.m_axis_tvalid, 0,
            "K = {}, {what}: a beat after the last frame end, seed {seed:#x}",
            p.fsize
        );
    }
    seen.pixels = total;
    seen.cycles = cycles;
    seen
}

fn every_case(k: usize) {
    let build = FccParams {
        fsize: k,
        label_bits: LABEL_BITS,
        ..FccParams::default()
    };
    let base = |rows, cols| FccParams {
        fsize: k,
        label_bits: LABEL_BITS,
        ..run_params(rows, cols)
    };
    let cases: [(&str, FccParams, f64); 4] = [
        (
            "the fewest rows, records taken often",
            // `FccRepJoins` takes frames of `max(16, K + 8)` rows.
            base((k + 8).max(16), 48),
            0.9,
        ),
        (
            "bridge 2, ring reach 6, records taken rarely",
            FccParams {
                bridge: Some(2),
                ring_reach: Some(6),
                ..base(20, 40)
            },
            0.3,
        ),
        (
            "range-adaptive, records taken every cycle",
            FccParams {
                th_h: 0.1,
                th_h_slope: 0.05,
                th_v_slope: 0.03,
                ..base(24, 36)
            },
            1.0,
        ),
        (
            "an open limit of 12",
            FccParams {
                open_limit: Some(12),
                ..base((k + 8).max(16), 40)
            },
            0.7,
        ),
    ];
    let model = load_plain::<TbIn, TbOut>(BenchBlock::ColCore, &build).expect("the column core");
    let mut all = Seen::default();
    for (n, (what, p, ready)) in cases.iter().enumerate() {
        let seed = 0xc0c0_0000 + (k * 16 + n) as u64;
        let mut dut = PlainDut::new(model.clone());
        for (rst_next, rst) in [(1, 0), (1, 1), (0, 1), (0, 0)] {
            dut.step(&TbIn {
                rst_next,
                rst,
                ..params_in(p)
            });
        }
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let frame = |density, jump, rng: &mut ChaCha8Rng| {
            random_frame(p.rows, p.cols, density, jump, true, rng)
        };
        let px = p.pixels();
        let f = [
            frame(0.8, 0.05, &mut rng),
            frame(0.5, 0.1, &mut rng),
            frame(0.7, 0.05, &mut rng),
            frame(0.7, 0.05, &mut rng),
        ];
        let early = rng.gen_range(px / 2..px);
        let extra = rng.gen_range(1..20);
        let frames = [
            Golden::of(p, &f[0]),
            Golden::of(p, &f[1]),
            Golden::early(p, &f[2], early),
            Golden::late(p, &f[3], extra, &mut rng),
        ];
        // Four frames back to back (the third's `tlast` early, the
        // fourth's late); then the last two again with a reset in the
        // middle of the late one.
        let mid = rng.gen_range(1..px);
        for (from, cut) in [(0, None), (2, Some(mid))] {
            let s = run_frames(
                &mut dut,
                p,
                &frames[from..],
                *ready,
                cut,
                &mut rng,
                what,
                seed,
            );
            all.records += s.records;
            all.seams += s.seams;
            all.overflows += s.overflows;
            all.frames += s.frames;
            all.errors += s.errors;
            all.pixels += s.pixels;
            all.cycles += s.cycles;
        }
    }
    eprintln!("K = {k}: {all:?}");
    assert!(
        all.records > 200 && all.seams > 0 && all.overflows > 0 && all.errors > 0,
        "K = {k}: too little seen: {all:?}"
    );
}

#[test]
fn the_core_streams_the_golden_records_k3() {
    every_case(3);
}

#[test]
fn the_core_streams_the_golden_records_k11() {
    every_case(11);
}

/// The core on the first frame of the OS-2-128 sample capture (128 x
/// 1024, ground removed, K = 7, bridge 16, ring reach 16), pixels offered
/// every cycle and records taken every cycle: its records must be the
/// golden stream's; it reports the cycles a pixel (the input held back)
/// and each record's latency, from the cycle its closing column's last
/// pixel is taken (the frame's last, for the frame end's) to the cycle its
/// first beat leaves. A measurement with Verilator's exact cycle counts;
/// on demand (a 128-row build and 131,072 pixels): `cargo test --release
/// -p fcc-sim --test blocks -- --ignored col_core:: --nocapture`.
#[test]
#[ignore = "a measurement: a 128-row build; run with --ignored"]
fn the_core_on_a_captured_frame_k7() {
    let (mut p, f) = crate::set_queue::capture("OS-2-128-U1_v2.3.0_1024x10");
    p.label_bits = LABEL_BITS;
    let build = FccParams {
        rows: p.rows,
        fsize: p.fsize,
        label_bits: LABEL_BITS,
        ..FccParams::default()
    };
    let g = Golden::of(&p, &f);
    let model = load_plain::<TbIn, TbOut>(BenchBlock::ColCore, &build).expect("the column core");
    let mut dut = PlainDut::new(model);
    for (rst_next, rst) in [(1, 0), (1, 1), (0, 1), (0, 0)] {
        dut.step(&TbIn {
            rst_next,
            rst,
            ..params_in(&p)
        });
    }
    let px = p.pixels();
    // The cycle each column's last pixel was taken.
    let mut col_done = vec![0usize; p.cols + 1];
    let (mut sent, mut cycle, mut first) = (0usize, 0usize, None);
    let mut reader = RecordReader::new();
    let mut want: VecDeque<Item> = g.items.iter().copied().collect();
    let mut beat0 = true;
    let mut lat: Vec<(u32, usize)> = Vec::new();
    let mut restart = true;
    let mut held = 0usize;
    while !want.is_empty() {
        let valid = sent < px && !restart;
        let i = TbIn {
            s_axis_tdata: if valid { g.beats[sent] } else { 0 },
            s_axis_tvalid: valid as u8,
            s_axis_tlast: (valid && sent + 1 == px) as u8,
            restart: restart as u8,
            m_axis_tready: 1,
            ..params_in(&p)
        };
        restart = false;
        let o = dut.step(&i);
        assert_eq!(o.bad, 0, "captured frame: bad at cycle {cycle}");
        held += usize::from(o.col_held);
        assert_eq!(
            o.miss, 0,
            "captured frame: a label not in its row at cycle {cycle}"
        );
        if valid && o.s_axis_tready != 0 {
            first.get_or_insert(cycle);
            sent += 1;
            if sent % p.rows == 0 {
                col_done[sent / p.rows - 1] = cycle;
            }
            if sent == px {
                col_done[p.cols] = cycle;
            }
        }
        if o.m_axis_tvalid != 0 {
            // A record's first beat: its latency.
            if beat0 {
                if let Some(Item::Record(r)) = want.front() {
                    let c = r.closed_col as usize;
                    lat.push((r.closed_col, cycle - col_done[c]));
                }
            }
            match reader.push(o.m_axis_tdata, o.m_axis_tlast != 0) {
                Ok(Some(got)) => {
                    let exp = want.pop_front().expect("an item expected");
                    assert_eq!(
                        got, exp,
                        "captured frame: the item (left) against the golden one (right)"
                    );
                    beat0 = true;
                }
                Ok(None) => beat0 = false,
                Err(e) => panic!("captured frame: {e}"),
            }
        }
        cycle += 1;
        assert!(
            cycle < 4 * px + 100_000,
            "captured frame: {} items left after {cycle} cycles",
            want.len()
        );
    }
    let span = col_done[p.cols] - first.expect("a pixel taken") + 1;
    let (end, cols): (Vec<_>, Vec<_>) = lat.iter().partition(|(c, _)| *c as usize == p.cols);
    let mut l: Vec<usize> = cols.iter().map(|&(_, d)| d).collect();
    l.sort_unstable();
    let q = |f: f64| l[((l.len() - 1) as f64 * f) as usize];
    eprintln!(
        "captured frame, K = {}: {} pixels in {span} cycles ({:.4} a pixel); {} records closed in the frame, latency from the column's last pixel: median {}, 90 % {}, 99 % {}, largest {} cycles (R = {}), over R: {}; {} at the frame end, largest {} cycles; a column's first pixel held {held} cycles",
        p.fsize,
        px,
        span as f64 / px as f64,
        l.len(),
        q(0.5),
        q(0.9),
        q(0.99),
        l[l.len() - 1],
        p.rows,
        l.iter().filter(|&&d| d > p.rows).count(),
        end.len(),
        end.iter().map(|&(_, d)| d).max().unwrap_or(0),
    );
}
