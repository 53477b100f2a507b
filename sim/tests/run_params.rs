//! Run-time K, thresholds and slopes: one core built for K_max = 11
//! (16 x 256, slopes 0) runs frames at K = 3, 5, 7, 9, 11 and several
//! threshold pairs, fixed and range-adaptive, back to back,
//! programmed through the registers between frames; every frame is compared
//! with the golden model called with that frame's parameters. Refused writes
//! leave the frame's parameters alone; a write during a frame applies from
//! the next frame on.

use fcc_golden::Frame;
use fcc_params::{quantize_slope, quantize_threshold, FccParams};
use fcc_rtl::regmap::{bits, offset};
use fcc_sim::{
    check_status_registers, compare, expected, frames, load, AxilMaster, Drive, Dut, FrameRun,
    WriteOrder,
};

/// The build: K_max = 11 on a small frame, 11-bit labels.
fn build() -> FccParams {
    FccParams {
        rows: 16,
        cols: 256,
        fsize: 11,
        label_bits: 11,
        ..Default::default()
    }
}

/// The parameters of one frame: the build's size and label bits, the run's
/// K and thresholds (slopes 0).
fn run_params(b: &FccParams, k: usize, th_h: f64, th_v: f64) -> FccParams {
    run_adaptive(b, k, (th_h, th_v, 0.0, 0.0))
}

/// As [`run_params`] with slopes: (th_h, th_v, th_h_slope, th_v_slope).
fn run_adaptive(b: &FccParams, k: usize, t: (f64, f64, f64, f64)) -> FccParams {
    FccParams {
        fsize: k,
        th_h: t.0,
        th_v: t.1,
        th_h_slope: t.2,
        th_v_slope: t.3,
        ..b.clone()
    }
}

fn dut(p: &FccParams) -> Dut {
    let model = load(p).unwrap_or_else(|e| panic!("{e}"));
    let mut d = Dut::new(model);
    d.reset(4);
    d
}

/// Write K and the thresholds of `r`, with the channel order and ready
/// stalls of `seed`; read them back and check that nothing was refused.
fn program(d: &mut Dut, r: &FccParams, seed: u64) {
    let mut m = AxilMaster::new(seed);
    m.stall = [0.0, 0.4][seed as usize % 2];
    m.order = [
        WriteOrder::Together,
        WriteOrder::AwFirst(3),
        WriteOrder::WFirst(2),
    ][seed as usize % 3];
    let writes = [
        (offset::RUN_K, r.fsize as u32),
        (offset::RUN_TH_H, quantize_threshold(r.th_h) as u32),
        (offset::RUN_TH_V, quantize_threshold(r.th_v) as u32),
        (offset::RUN_SLOPE_H, quantize_slope(r.th_h_slope) as u32),
        (offset::RUN_SLOPE_V, quantize_slope(r.th_v_slope) as u32),
    ];
    for (off, v) in writes {
        m.write_ok(d, off, v).unwrap();
    }
    for (off, v) in writes {
        let got = m.read(d, off).unwrap();
        assert_eq!(got, v, "read back {off:#05x}: expected {v} != got {got}");
    }
    let err = m.read(d, offset::ERROR).unwrap();
    assert_eq!(err, 0, "ERROR {err:#x} after valid writes (seed {seed})");
}

/// Run `f` and compare it with the golden model at the run parameters `r`.
fn check(d: &mut Dut, r: &FccParams, f: &Frame, drive: &Drive, what: &str) -> FrameRun {
    let gold = expected(r, f).unwrap();
    let run = d
        .run_frame(f, drive)
        .unwrap_or_else(|e| panic!("{what}: {e}"));
    let what = format!(
        "{what} (run K {} th_h {} th_v {} slopes {} {}) seed {}",
        r.fsize, r.th_h, r.th_v, r.th_h_slope, r.th_v_slope, drive.seed
    );
    compare(r, &gold, &run, &what).unwrap_or_else(|e| panic!("{e}"));
    check_status_registers(d, &run, &what).unwrap_or_else(|e| panic!("{e}"));
    run
}

/// Thresholds and slopes (th_h, th_v, th_h_slope, th_v_slope): the build's,
/// the `adaptive` preset, tighter and range-adaptive, wider with th_V < th_H
/// and a steep V slope, and the ends of the register ranges (tH = 0x8000,
/// tV = 1, slopes 0xFFFF and 1).
const THRESHOLDS: [(f64, f64, f64, f64); 5] = [
    (0.5, 1.0, 0.0, 0.0),
    fcc_params::ADAPTIVE,
    (0.3, 0.6, 0.01, 0.035),
    (0.9, 0.4, 0.0, 0.25),
    (127.999, 1.0 / 256.0, 0.99998, 1.0 / 65536.0),
];

fn frames_for(b: &FccParams) -> Vec<(String, Frame)> {
    let mut v: Vec<(String, Frame)> = [11u64, 12, 13]
        .iter()
        .map(|s| (format!("random {s}"), frames::random(b, *s)))
        .collect();
    v.push(("staircase".into(), frames::staircase(b)));
    v.push(("u_shapes".into(), frames::u_shapes(b)));
    v.push(("thresholds".into(), frames::thresholds(b)));
    v
}

#[test]
fn one_core_runs_every_k_and_threshold_pair_back_to_back() {
    let b = build();
    let mut d = dut(&b);
    let frames = frames_for(&b);
    let mut configs = vec![];
    for t in THRESHOLDS {
        for k in [3, 5, 7, 9, 11] {
            configs.push(run_adaptive(&b, k, t));
        }
    }
    // Every frame under every configuration, the configuration changing
    // before every frame; some frames under input gaps and back-pressure.
    let mut n = 0u64;
    for (fi, (name, f)) in frames.iter().enumerate() {
        let mut results: Vec<Vec<u32>> = vec![];
        for i in 0..configs.len() {
            let r = &configs[(i + 7 * fi) % configs.len()];
            program(&mut d, r, n);
            let drive = Drive {
                gap: [0.0, 0.2][n as usize % 2],
                backpressure: [0.0, 0.0, 0.5][n as usize % 3],
                seed: n,
                ..Default::default()
            };
            let run = check(&mut d, r, f, &drive, name);
            results.push(run.labels);
            n += 1;
        }
        results.sort();
        results.dedup();
        assert!(
            results.len() > 1 || !name.starts_with("random"),
            "{name}: every configuration gave the same labels: the frame tests nothing"
        );
    }
    // K alone changes the result of a random frame (the test can see K).
    let f = &frames[0].1;
    let g3 = expected(&run_params(&b, 3, 0.5, 1.0), f).unwrap();
    let g11 = expected(&run_params(&b, 11, 0.5, 1.0), f).unwrap();
    assert_ne!(g3.labels, g11.labels, "K = 3 and 11 agree on random 11");
}

#[test]
fn power_on_run_parameters_are_the_build() {
    let b = build();
    let mut d = dut(&b);
    let mut m = AxilMaster::new(1);
    assert_eq!(m.read(&mut d, offset::RUN_K).unwrap(), 11);
    assert_eq!(m.read(&mut d, offset::RUN_TH_H).unwrap(), b.th_h_q() as u32);
    assert_eq!(m.read(&mut d, offset::RUN_TH_V).unwrap(), b.th_v_q() as u32);
    let f = frames::random(&b, 21);
    check(&mut d, &b, &f, &Drive::default(), "power-on");
    // A soft reset keeps the programmed values; a power-on reset restores
    // the build's.
    let r = run_params(&b, 5, 0.3, 0.6);
    program(&mut d, &r, 2);
    check(&mut d, &r, &f, &Drive::default(), "programmed");
    m.write_ok(&mut d, offset::CONTROL, bits::CONTROL_SOFT_RESET)
        .unwrap();
    assert_eq!(m.read(&mut d, offset::RUN_K).unwrap(), 5);
    d.reset(3);
    assert_eq!(m.read(&mut d, offset::RUN_K).unwrap(), 11);
}

#[test]
fn refused_writes_leave_the_next_frame_on_the_old_parameters() {
    let b = build();
    let mut d = dut(&b);
    let r = run_params(&b, 7, 0.3, 0.6);
    program(&mut d, &r, 3);
    let mut m = AxilMaster::new(3);
    for (off, v, bit) in [
        (offset::RUN_K, 4, bits::ERROR_K),
        (offset::RUN_K, 13, bits::ERROR_K),
        (offset::RUN_K, 1, bits::ERROR_K),
        (offset::RUN_TH_H, 0, bits::ERROR_TH_H),
        (offset::RUN_TH_V, 0x8001, bits::ERROR_TH_V),
        (offset::RUN_ROWS, 0, bits::ERROR_ROWS),
        (offset::RUN_COLS, 4097, bits::ERROR_COLS),
    ] {
        m.write_ok(&mut d, off, v).unwrap();
        let err = m.read(&mut d, offset::ERROR).unwrap();
        assert_eq!(err & bit, bit, "{off:#05x} <- {v}: ERROR {err:#x}");
    }
    let f = frames::random(&b, 31);
    check(&mut d, &r, &f, &Drive::default(), "after refused writes");
    m.write_ok(&mut d, offset::ERROR, u32::MAX).unwrap();
    assert_eq!(m.read(&mut d, offset::ERROR).unwrap(), 0);
}

#[test]
fn write_during_a_frame_applies_from_the_next_frame() {
    let b = build();
    let mut d = dut(&b);
    let old = run_params(&b, 3, 0.3, 0.6);
    let new = run_params(&b, 11, 0.9, 1.5);
    program(&mut d, &old, 4);
    for seed in [41u64, 42] {
        let f = frames::random(&b, seed);
        let half = b.pixels() / 2;
        d.feed_partial(&f, half, 1_000_000).unwrap();
        program(&mut d, &new, seed);
        let drive = Drive {
            seed,
            ..Default::default()
        };
        let gold = expected(&old, &f).unwrap();
        let run = d.run_frame_from(&f, &drive, half).unwrap();
        let what = format!("frame written to in its middle, seed {seed}");
        compare(&old, &gold, &run, &what).unwrap_or_else(|e| panic!("{e}"));
        check_status_registers(&mut d, &run, &what).unwrap_or_else(|e| panic!("{e}"));
        check(&mut d, &new, &f, &drive, "the next frame");
        program(&mut d, &old, seed + 1);
    }
}
