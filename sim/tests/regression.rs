//! Verilator regression of the generated core against the golden model.
//!
//! Per K in {3, 5, 7, 9, 11}: every directed frame, seeded random frames with
//! random input gaps and output back-pressure, early and late `tlast` with
//! recovery, a reset in the middle of a frame (16 x 256), and two synthetic
//! 64 x 2048 scenes whose cycle counts are printed. Range-adaptive
//! thresholds at K = 3, 7 and 11 through the run registers of those cores.
//! Models are built once per
//! configuration and cached (see `fcc_sim::model`).

use fcc_golden::Frame;
use fcc_params::FccParams;
use fcc_rtl::regmap::{bits, offset};
use fcc_sim::model::FccIn;
use fcc_sim::{
    compare, expected, frames, load, run_and_check, run_and_check_with, AxilMaster, Drive, Dut,
    FrameRun, Tlast,
};

/// 16 x 256 with 11-bit labels, so the `label_overflow` and `checkerboard`
/// frames (thousands of runs) exhaust the labels for every K.
fn small(fsize: usize) -> FccParams {
    FccParams {
        rows: 16,
        cols: 256,
        fsize,
        label_bits: 11,
        ..Default::default()
    }
}

fn dut(p: &FccParams) -> Dut {
    let model = match load(p) {
        Ok(m) => m,
        Err(e) => panic!("{e}"),
    };
    let mut d = Dut::new(model);
    d.reset(4);
    d
}

fn check(d: &mut Dut, f: &Frame, drive: &Drive, what: &str) -> FrameRun {
    match run_and_check(d, f, drive, what) {
        Ok(r) => r,
        Err(e) => panic!("{e}"),
    }
}

fn directed_random_protocol(fsize: usize) {
    let p = small(fsize);
    let mut d = dut(&p);
    // Directed corners, plain and under stress.
    for (name, f) in frames::directed(&p) {
        let run = check(&mut d, &f, &Drive::default(), name);
        if name == "label_overflow" {
            assert!(
                run.overflow,
                "label_overflow must exhaust {} labels",
                p.max_label()
            );
        }
        let stress = Drive {
            gap: 0.25,
            backpressure: 0.5,
            seed: fsize as u64,
            ..Default::default()
        };
        check(&mut d, &f, &stress, name);
    }
    // Seeded random frames with random gaps and back-pressure.
    for seed in 0..6u64 {
        let f = frames::random(&p, seed * 1000 + fsize as u64);
        let drive = Drive {
            gap: [0.0, 0.1, 0.5][seed as usize % 3],
            backpressure: [0.0, 0.3, 0.7][(seed as usize / 2) % 3],
            seed,
            ..Default::default()
        };
        check(
            &mut d,
            &f,
            &drive,
            &format!("random {}", seed * 1000 + fsize as u64),
        );
    }
    // Early tlast: the rest of the frame is empty; the error bit is set.
    let f = frames::random(&p, 77);
    let at = p.pixels() / 3;
    let mut cut = f.clone();
    for px in cut.points.iter_mut().skip(at + 1) {
        *px = None;
    }
    let gold = expected(&p, &cut).unwrap();
    let drive = Drive {
        tlast: Tlast::Early { at },
        gap: 0.2,
        seed: 5,
        ..Default::default()
    };
    let run = d.run_frame(&f, &drive).unwrap();
    compare(&p, &gold, &run, "early tlast").unwrap();
    assert!(run.frame_error, "early tlast must set frame_error");
    let run = check(&mut d, &f, &Drive::default(), "after early tlast");
    assert!(!run.frame_error);
    // Late tlast: extra beats are dropped up to the next tlast.
    let drive = Drive {
        tlast: Tlast::Late { extra: 7 },
        ..Default::default()
    };
    let run = check(&mut d, &f, &drive, "late tlast");
    assert!(run.frame_error, "missing tlast must set frame_error");
    let run = check(
        &mut d,
        &frames::ring(&p),
        &Drive::default(),
        "after late tlast",
    );
    assert!(!run.frame_error);
    // Reset in the middle of a frame, then a clean frame: its status, joins
    // included, is that frame's alone (reset clears the joins counter).
    let clean = check(&mut d, &frames::comb(&p), &Drive::default(), "before reset");
    d.feed_partial(&f, p.pixels() / 2, 1_000_000).unwrap();
    d.reset(3);
    let after = check(&mut d, &frames::comb(&p), &Drive::default(), "after reset");
    assert_eq!(
        after.joins, clean.joins,
        "fsize {fsize}: status_joins after a reset in the middle of a frame counts the abandoned frame"
    );
    // The same with CONTROL.SOFT_RESET through the registers: the frame is
    // abandoned, the registers keep their values, the next frame is clean.
    d.feed_partial(&f, p.pixels() / 3, 1_000_000).unwrap();
    let mut m = AxilMaster::new(fsize as u64);
    m.write_ok(
        &mut d,
        offset::CONTROL,
        bits::CONTROL_SOFT_RESET | bits::CONTROL_IRQ_ENABLE,
    )
    .unwrap();
    assert_eq!(
        m.read(&mut d, offset::CONTROL).unwrap(),
        bits::CONTROL_IRQ_ENABLE
    );
    let run = check(
        &mut d,
        &frames::comb(&p),
        &Drive::default(),
        "after soft reset",
    );
    assert!(!run.frame_error);
    m.write_ok(&mut d, offset::CONTROL, 0).unwrap();
}

/// The registers of the core itself: build constants, the interrupt line
/// over a frame, and the status read back through the registers.
#[test]
fn registers_of_the_core_read_back_and_irq_follows_frame_done() {
    let p = small(5);
    let mut d = dut(&p);
    let mut m = AxilMaster::new(21);
    m.stall = 0.5;
    for r in fcc_rtl::regmap::registers(&p) {
        let got = m.read(&mut d, r.offset).unwrap();
        let want = if r.offset == offset::STATUS {
            // IDLE is live: set once the merge table is initialised.
            got & bits::STATUS_IDLE
        } else {
            r.reset
        };
        assert_eq!(got, want, "{}: expected {want:#x} != got {got:#x}", r.name);
    }
    m.write_ok(&mut d, offset::CONTROL, bits::CONTROL_IRQ_ENABLE)
        .unwrap();
    let f = frames::random(&p, 5);
    let gold = expected(&p, &f).unwrap();
    let run = d.run_frame(&f, &Drive::default()).unwrap();
    compare(&p, &gold, &run, "irq frame").unwrap();
    let o = d.step(&fcc_sim::model::FccIn {
        m_axis_tready: 1,
        ..Default::default()
    });
    assert_eq!(o.irq, 1, "irq high after the frame while enabled");
    fcc_sim::check_status_registers(&mut d, &run, "irq frame").unwrap();
    let o = d.step(&fcc_sim::model::FccIn {
        m_axis_tready: 1,
        ..Default::default()
    });
    assert_eq!(o.irq, 0, "irq low once FRAME_DONE is cleared");
    assert_eq!(m.read(&mut d, offset::FRAME_COUNT).unwrap(), 1);
    // Offsets that name no register read 0.
    for unmapped in [0x028, 0x04C, 0x06C, 0x094, 0xFFC] {
        let got = m.read(&mut d, unmapped).unwrap();
        assert_eq!(
            got, 0,
            "unmapped offset {unmapped:#x}: expected 0 != got {got:#x}"
        );
    }
    // CONTROL.CLEAR: the frame counter, the frame status registers and
    // STATUS.FRAME_DONE go to 0; IRQ_ENABLE stays; CLEAR reads 0.
    let frame_regs = [
        ("FRAME_COUNT", offset::FRAME_COUNT),
        ("CLUSTERS", offset::CLUSTERS),
        ("PROVISIONAL", offset::PROVISIONAL),
        ("JOINS", offset::JOINS),
    ];
    for (name, off) in frame_regs {
        let got = m.read(&mut d, off).unwrap();
        assert_ne!(
            got, 0,
            "{name} is 0 before CONTROL.CLEAR: the clear would prove nothing"
        );
    }
    m.write_ok(
        &mut d,
        offset::CONTROL,
        bits::CONTROL_IRQ_ENABLE | bits::CONTROL_CLEAR,
    )
    .unwrap();
    for (name, off) in frame_regs.into_iter().chain([
        ("UNLABELLED", offset::UNLABELLED),
        ("FRAME_FLAGS", offset::FRAME_FLAGS),
        ("GEAR_STALLS", offset::GEAR_STALLS),
    ]) {
        let got = m.read(&mut d, off).unwrap();
        assert_eq!(
            got, 0,
            "{name} after CONTROL.CLEAR: expected 0 != got {got:#x}"
        );
    }
    let status = m.read(&mut d, offset::STATUS).unwrap();
    assert_eq!(
        status & bits::STATUS_FRAME_DONE,
        0,
        "FRAME_DONE after CONTROL.CLEAR"
    );
    let control = m.read(&mut d, offset::CONTROL).unwrap();
    assert_eq!(
        control,
        bits::CONTROL_IRQ_ENABLE,
        "CONTROL after CLEAR: expected IRQ_ENABLE only != got {control:#x}"
    );
    // The frame counter starts again from 0: the next frame is frame 1.
    let run = d.run_frame(&f, &Drive::default()).unwrap();
    compare(&p, &gold, &run, "frame after CONTROL.CLEAR").unwrap();
    d.step(&fcc_sim::model::FccIn {
        m_axis_tready: 1,
        ..Default::default()
    });
    assert_eq!(m.read(&mut d, offset::FRAME_COUNT).unwrap(), 1);
}

fn scenes(fsize: usize) {
    let p = FccParams {
        fsize,
        ..Default::default()
    };
    let mut d = dut(&p);
    for seed in [1u64, 2] {
        let cfg = fcc_scene::SceneConfig {
            rows: p.rows,
            cols: p.cols,
            seed,
            ..Default::default()
        };
        let scene = fcc_scene::generate(&cfg).unwrap();
        let f = Frame::from_xyz_f32(p.rows, p.cols, &scene.xyz);
        let run = check(&mut d, &f, &Drive::default(), &format!("scene {seed}"));
        let rc = p.pixels() as f64;
        eprintln!(
            "CYCLES fsize {fsize} scene {seed}: {} cycles = {:.3} x R x C, latency {} after last pixel, \
             input stalls {} ({:.2}%), joins {}, provisional {}, clusters {}, read-back waits {}",
            run.cycles,
            run.cycles as f64 / rc,
            run.latency,
            run.input_stalls,
            100.0 * run.input_stalls as f64 / rc,
            run.joins,
            run.provisional,
            run.clusters,
            run.gear_stalls,
        );
        if fsize == 7 {
            assert!(
                run.cycles as f64 <= 1.3 * rc,
                "fsize 7 scene {seed}: {} cycles exceed 1.3 x R x C",
                run.cycles
            );
        }
    }
    // The same scene again under back-pressure and gaps.
    let cfg = fcc_scene::SceneConfig {
        rows: p.rows,
        cols: p.cols,
        seed: 3,
        ..Default::default()
    };
    let scene = fcc_scene::generate(&cfg).unwrap();
    let f = Frame::from_xyz_f32(p.rows, p.cols, &scene.xyz);
    let drive = Drive {
        gap: 0.1,
        backpressure: 0.3,
        seed: 3,
        ..Default::default()
    };
    check(&mut d, &f, &drive, "scene 3 stressed");
}

macro_rules! per_fsize {
    ($($k:literal => $small:ident, $full:ident;)*) => {$(
        #[test]
        fn $small() {
            directed_random_protocol($k);
        }
        #[test]
        fn $full() {
            scenes($k);
        }
    )*};
}

per_fsize! {
    3 => fsize3_directed_random_protocol, fsize3_scenes_64x2048;
    5 => fsize5_directed_random_protocol, fsize5_scenes_64x2048;
    7 => fsize7_directed_random_protocol, fsize7_scenes_64x2048;
    9 => fsize9_directed_random_protocol, fsize9_scenes_64x2048;
    11 => fsize11_directed_random_protocol, fsize11_scenes_64x2048;
}

/// Range-adaptive thresholds (spec §2) at the `adaptive` preset's slopes and
/// at steeper ones, programmed through the run registers (RUN_TH_*,
/// RUN_SLOPE_*) of cores the other tests build, so no model is built for
/// them alone (a build's own power-on slopes are the register bench's and
/// the cocotb bench's K = 9): the synthetic scenes (objects out to 80 m) on
/// the 64 x 2048 K = 7 core of `scenes`, seeded random frames (ranges to
/// 80 m) with gaps and back-pressure on it and on the 16 x 256 cores of K =
/// 3 and 11.
fn adaptive(build: FccParams, slopes: (f64, f64)) {
    let (th_h, th_v, _, _) = fcc_params::ADAPTIVE;
    let run = FccParams {
        th_h,
        th_v,
        th_h_slope: slopes.0,
        th_v_slope: slopes.1,
        ..build.clone()
    };
    let mut d = dut(&build);
    let check = |d: &mut Dut, f: &Frame, drive: &Drive, what: &str| {
        if let Err(e) = run_and_check_with(d, &run, f, drive, what) {
            panic!("{e}");
        }
    };
    if run.rows == 64 {
        for seed in [1u64, 4] {
            let cfg = fcc_scene::SceneConfig {
                rows: run.rows,
                cols: run.cols,
                seed,
                ..Default::default()
            };
            let scene = fcc_scene::generate(&cfg).unwrap();
            let f = Frame::from_xyz_f32(run.rows, run.cols, &scene.xyz);
            check(
                &mut d,
                &f,
                &Drive::default(),
                &format!("adaptive scene {seed}"),
            );
        }
    }
    for seed in 1..=8u64 {
        let f = frames::random(&run, seed);
        let drive = Drive {
            gap: 0.1,
            backpressure: 0.2,
            seed,
            ..Default::default()
        };
        check(&mut d, &f, &drive, &format!("adaptive random {seed}"));
    }
    check(
        &mut d,
        &frames::thresholds(&run),
        &Drive::default(),
        "adaptive thresholds",
    );
}

#[test]
fn adaptive_thresholds_fsize7_scenes_64x2048() {
    let (_, _, a_h, a_v) = fcc_params::ADAPTIVE;
    let build = FccParams {
        fsize: 7,
        ..Default::default()
    };
    adaptive(build, (a_h, a_v));
}

#[test]
fn adaptive_thresholds_fsize3_and_fsize11_random() {
    adaptive(small(3), (0.08, 0.2));
    adaptive(small(11), (0.05, 0.5));
}

/// A reset in every state of the top-level state machine and of the merge
/// table: table initialisation, idle before the first pixel, the first
/// pixels, the middle of the input, draining after the last pixel, the
/// read-back with the sink stalled and with it running. After each, a clean
/// frame must give the golden labels and the `status_joins` of a clean run.
#[test]
fn reset_in_every_state_of_the_top_state_machine() {
    let p = small(3);
    let mut d = dut(&p);
    let f = frames::random(&p, 91);
    let clean = check(&mut d, &frames::comb(&p), &Drive::default(), "clean comb");
    let n = p.pixels();
    let init = 1u64 << p.label_bits;
    // (state, beats fed, then cycles with the sink stalled, then with it ready)
    let points: [(&str, usize, u64, u64); 7] = [
        ("table initialisation", 0, 10, 0),
        ("idle before the first pixel", 0, init + 50, 0),
        ("the first pixels", 5, 0, 0),
        ("the middle of the input", n / 2, 0, 0),
        ("drain after the last pixel", n, 1, 0),
        ("read-back with the sink stalled", n, 400, 0),
        ("read-back with the sink ready", n, 0, 300),
    ];
    for (state, beats, stalled, ready) in points {
        d.reset(3);
        d.feed_partial(&f, beats, 1_000_000).unwrap();
        for _ in 0..stalled {
            d.step(&FccIn::default());
        }
        for _ in 0..ready {
            d.step(&FccIn {
                m_axis_tready: 1,
                ..Default::default()
            });
        }
        d.reset(3);
        let what = format!("comb after a reset during {state}");
        let run = check(&mut d, &frames::comb(&p), &Drive::default(), &what);
        assert_eq!(
            run.joins, clean.joins,
            "{what}: status_joins {} != {} of a clean run",
            run.joins, clean.joins
        );
        assert!(!run.frame_error, "{what}: frame_error set");
    }
}

#[test]
fn label_overflow_with_8_bit_labels() {
    let p = FccParams {
        label_bits: 8,
        ..small(5)
    };
    let mut d = dut(&p);
    let run = check(
        &mut d,
        &frames::label_overflow(&p),
        &Drive::default(),
        "label_overflow",
    );
    assert!(run.overflow && run.unlabelled > 0 && run.provisional == 255);
    // The core recovers: the next frame fits in 255 labels.
    let run = check(
        &mut d,
        &frames::u_shapes(&p),
        &Drive::default(),
        "after overflow",
    );
    assert!(!run.overflow);
    for seed in 0..3 {
        check(
            &mut d,
            &frames::random(&p, seed),
            &Drive::default(),
            "random",
        );
    }
}

/// Every output width, and frame sizes whose last beat holds each possible
/// number of labels: 16 x 256 leaves a full beat, 19 x 259, 18 x 257 and
/// 17 x 259 leave 1, 2 and 3 of 4 labels (17 x 257 leaves 1 of 2). Labels
/// run out in every build (11 bits), so unlabelled pixels reach every slot.
/// Three tests, so that their builds run beside each other.
#[test]
fn one_and_two_labels_per_beat_and_odd_sizes() {
    labels_per_beat_and_sizes(&[(1, 16, 256, 3), (2, 17, 257, 7)]);
}

#[test]
fn four_labels_per_beat_odd_sizes_k9() {
    labels_per_beat_and_sizes(&[(4, 19, 259, 9)]);
}

#[test]
fn four_labels_per_beat_odd_sizes_k3_k5() {
    labels_per_beat_and_sizes(&[(4, 18, 257, 3), (4, 17, 259, 5)]);
}

/// Each (labels per beat, rows, cols, K): the directed frames under gaps
/// and back-pressure, then a random frame.
fn labels_per_beat_and_sizes(configs: &[(u32, usize, usize, usize)]) {
    for &(lpb, rows, cols, fsize) in configs {
        let p = FccParams {
            rows,
            cols,
            fsize,
            labels_per_beat: lpb,
            label_bits: 11,
            ..Default::default()
        };
        let mut d = dut(&p);
        let directed = frames::directed(&p);
        let kept = directed
            .into_iter()
            .enumerate()
            .filter(|(i, (name, _))| *i < 6 || *name == "label_overflow")
            .map(|(_, nf)| nf);
        for (name, f) in kept {
            let drive = Drive {
                backpressure: 0.3,
                gap: 0.1,
                seed: 9,
                ..Default::default()
            };
            let run = check(&mut d, &f, &drive, name);
            assert_eq!(run.beats as usize, p.pixels().div_ceil(lpb as usize));
            if name == "label_overflow" {
                assert!(
                    run.overflow && run.unlabelled > 0,
                    "K {fsize}, {rows} x {cols}: labels never ran out"
                );
            }
        }
        check(
            &mut d,
            &frames::random(&p, 11),
            &Drive::default(),
            "random 11",
        );
    }
}

#[test]
fn mismatch_names_pixel_expected_got_and_seed() {
    let p = small(3);
    let f = frames::one_row(&p, 2);
    let gold = expected(&p, &f).unwrap();
    let mut run = FrameRun {
        labels: gold.labels.clone(),
        clusters: gold.clusters,
        provisional: gold.provisional,
        overflow: gold.overflow,
        unlabelled: gold.unlabelled as u32,
        ..Default::default()
    };
    compare(&p, &gold, &run, "seed 42").unwrap();
    let i = 2 * p.cols + 7;
    run.labels[i] += 1;
    let e = compare(&p, &gold, &run, "seed 42").unwrap_err().to_string();
    assert!(
        e.contains("row 2 col 7") && e.contains("seed 42") && e.contains("!="),
        "{e}"
    );
}

#[test]
fn bad_parameters_are_reported_not_panicked() {
    let p = FccParams {
        fsize: 4,
        ..small(3)
    };
    let e = load(&p).unwrap_err().to_string();
    assert!(e.contains("fsize"), "{e}");
}

/// The real Ouster captures in the repository, every frame at its own size
/// (32, 64 and 128 beams x 1024 columns) as run registers, ground left in:
/// the hardest join load the core sees. K = 7, default thresholds, on the
/// K_max = 11, 128 x 2048, B = 16 core of `run_size` and the virtual board
/// (one Verilator model shared through the cache, not a core built to each
/// size: `run_size` runs the first frame of each at every K; this test
/// every frame, with its cycles).
#[test]
fn real_ouster_frames_at_their_own_size() {
    use fcc_lidar::ouster::{read_capture, DecodeOptions, OusterMetadata, SAMPLE_CAPTURES};
    let data =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../crates/fcc-lidar/tests/data");
    let build = FccParams {
        rows: 128,
        cols: 2048,
        fsize: 11,
        label_bits: 16,
        ..Default::default()
    };
    let mut d = dut(&build);
    for (pcap, json) in SAMPLE_CAPTURES {
        let meta = OusterMetadata::from_file(&data.join(json)).unwrap();
        let capture = read_capture(&data.join(pcap), &meta, DecodeOptions::default()).unwrap();
        assert!(!capture.frames.is_empty(), "{pcap}: no frame");
        for frame in &capture.frames {
            let img = &frame.image;
            let run = FccParams {
                rows: img.rows,
                cols: img.cols,
                fsize: 7,
                ..build.clone()
            };
            let f = img.to_frame();
            let r = run_and_check_with(&mut d, &run, &f, &Drive::default(), pcap)
                .unwrap_or_else(|e| panic!("{e}"));
            let rc = run.pixels() as f64;
            eprintln!(
                "CYCLES ouster {pcap} {} x {}: {} cycles = {:.3} x R x C, latency {}, input stalls {} ({:.2}%), joins {}",
                img.rows,
                img.cols,
                r.cycles,
                r.cycles as f64 / rc,
                r.latency,
                r.input_stalls,
                100.0 * r.input_stalls as f64 / rc,
                r.joins,
            );
        }
    }
}

/// `fcc sim` says "building" or "loading the cached model" from this.
#[test]
fn cache_knows_built_models_from_unbuilt_ones() {
    let p = small(3);
    let _ = dut(&p);
    assert!(fcc_sim::is_cached(&p).unwrap());
    let never = FccParams {
        th_h: 0.371,
        ..small(3)
    };
    assert!(!fcc_sim::is_cached(&never).unwrap());
}

/// How a short reset reaches the core.
#[derive(Clone, Copy, Debug)]
enum ShortReset {
    /// `rst` high for this many cycles.
    Pin(u64),
    /// CONTROL.SOFT_RESET written this many times back to back.
    Soft(u32),
}

fn short_reset(d: &mut Dut, how: ShortReset, m: &mut AxilMaster) {
    match how {
        ShortReset::Pin(n) => d.reset(n),
        ShortReset::Soft(n) => {
            for _ in 0..n {
                m.write_ok(d, offset::CONTROL, bits::CONTROL_SOFT_RESET)
                    .unwrap();
            }
        }
    }
}

/// A reset of one or two cycles (the `rst` pin, or CONTROL.SOFT_RESET) right
/// after a finished frame, and in the middle of a frame, then seeded random
/// frames: each must give the golden labels.
fn short_reset_then_random_frames(fsize: usize) {
    let p = small(fsize);
    let mut d = dut(&p);
    let mut m = AxilMaster::new(fsize as u64);
    let hows = [
        ShortReset::Pin(1),
        ShortReset::Pin(2),
        ShortReset::Soft(1),
        ShortReset::Soft(2),
    ];
    for (i, how) in hows.into_iter().enumerate() {
        for mid_frame in [false, true] {
            let seed = 21 + 10 * i as u64 + u64::from(mid_frame);
            let f = frames::random(&p, seed);
            let what = format!("fsize {fsize}, seed {seed}, before {how:?}");
            check(&mut d, &f, &Drive::default(), &what);
            if mid_frame {
                d.feed_partial(&f, p.pixels() / 2, 1_000_000).unwrap();
            }
            short_reset(&mut d, how, &mut m);
            let at = if mid_frame {
                "in the middle of a frame"
            } else {
                "after a frame"
            };
            let what = format!("fsize {fsize}, seed {seed}, same frame after {how:?} {at}");
            check(&mut d, &f, &Drive::default(), &what);
            let g = frames::random(&p, seed + 5);
            let what = format!(
                "fsize {fsize}, seed {}, next frame after {how:?} {at}",
                seed + 5
            );
            check(&mut d, &g, &Drive::default(), &what);
        }
    }
}

#[test]
fn fsize3_one_and_two_cycle_reset_after_and_within_a_frame() {
    short_reset_then_random_frames(3);
}

#[test]
fn fsize11_one_and_two_cycle_reset_after_and_within_a_frame() {
    short_reset_then_random_frames(11);
}
