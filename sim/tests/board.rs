//! The driver (`fcc-driver`) on the virtual board: the AXI DMA model and
//! memory around the Verilator model of the core. Frames through the whole
//! path are compared label by label with the golden model; each fault ends
//! with a clear error and the next frame is right.

use fcc_driver::{Channel, Driver, Error, Pixels, RunConfig};
use fcc_golden::Frame;
use fcc_params::FccParams;
use fcc_sim::{build_run, expected, frames, virtual_board, Fault, VirtualBoard};

/// The regression's small K = 3 core (its Verilator model is shared).
fn small() -> FccParams {
    FccParams {
        rows: 16,
        cols: 256,
        fsize: 3,
        label_bits: 11,
        ..Default::default()
    }
}

fn open(p: &FccParams) -> Driver<VirtualBoard> {
    let (board, expect) = virtual_board(p).unwrap_or_else(|e| panic!("{e}"));
    Driver::open(board, &expect).unwrap_or_else(|e| panic!("{e}"))
}

/// Run `frame` and compare every label and the status with the golden model.
fn run_ok(d: &mut Driver<VirtualBoard>, p: &FccParams, frame: &Frame, what: &str) {
    let mut labels = vec![0u32; p.pixels()];
    let r = d
        .run_frame(&build_run(p), Pixels::Points(&frame.points), &mut labels)
        .unwrap_or_else(|e| panic!("{what}: {e}"));
    let gold = expected(p, frame).unwrap();
    if let Some(i) = (0..labels.len()).find(|&i| labels[i] != gold.labels[i]) {
        panic!(
            "{what}: first mismatch at row {} col {}: expected {} != got {}",
            i / p.cols,
            i % p.cols,
            gold.labels[i],
            labels[i]
        );
    }
    assert_eq!(r.status.clusters, gold.clusters, "{what}: clusters");
    assert_eq!(
        r.status.provisional, gold.provisional,
        "{what}: provisional"
    );
    assert_eq!(r.status.overflow, gold.overflow, "{what}: overflow");
    assert_eq!(
        r.status.unlabelled as usize, gold.unlabelled,
        "{what}: unlabelled"
    );
    assert!(r.time_ns > 0);
}

fn run_err(d: &mut Driver<VirtualBoard>, p: &FccParams, frame: &Frame) -> Error<fcc_sim::SimError> {
    let mut labels = vec![0u32; p.pixels()];
    match d.run_frame(&build_run(p), Pixels::Points(&frame.points), &mut labels) {
        Ok(_) => panic!("the frame should have failed"),
        Err(e) => e,
    }
}

#[test]
fn frames_through_the_dma_match_the_golden_model_back_to_back() {
    let p = small();
    let mut d = open(&p);
    for seed in 1..=2 {
        run_ok(
            &mut d,
            &p,
            &frames::random(&p, seed),
            &format!("random seed {seed}"),
        );
    }
    run_ok(&mut d, &p, &frames::label_overflow(&p), "label overflow");
    run_ok(&mut d, &p, &frames::empty(&p), "empty");
}

#[test]
fn float_input_is_quantised_as_the_golden_model_does() {
    let p = small();
    let mut d = open(&p);
    // Coordinates on and around the rounding and range edges, NaN and
    // infinities: the driver's packing and the golden model's frame agree.
    let specials = [
        0.5 / 256.0,
        -0.5 / 256.0,
        127.998,
        -128.0,
        -128.002,
        f64::NAN,
    ];
    let mut xyz = Vec::with_capacity(p.pixels() * 3);
    let base = frames::random(&p, 5);
    for (i, pt) in base.points.iter().enumerate() {
        let s = specials[i % specials.len()];
        match pt {
            Some(q) if i % 7 == 0 => {
                xyz.extend([f64::from(q[0]) / 256.0, s, f64::from(q[2]) / 256.0])
            }
            Some(q) => xyz.extend(q.map(|v| f64::from(v) / 256.0)),
            None => xyz.extend([f64::INFINITY, 0.0, 0.0]),
        }
    }
    let frame = Frame::from_xyz_f64(p.rows, p.cols, &xyz);
    let mut labels = vec![0u32; p.pixels()];
    d.run_frame(&build_run(&p), Pixels::XyzF64(&xyz), &mut labels)
        .unwrap_or_else(|e| panic!("{e}"));
    let gold = expected(&p, &frame).unwrap();
    assert_eq!(labels, gold.labels);
}

#[test]
fn dma_decode_error_on_the_label_write_is_reported_and_the_next_frame_is_right() {
    let p = small();
    let mut d = open(&p);
    let f = frames::random(&p, 3);
    d.hal().inject(Fault::DecodeError {
        channel: Channel::S2mm,
        beat: 100,
    });
    match run_err(&mut d, &p, &f) {
        Error::Dma {
            channel: Channel::S2mm,
            dmasr,
            ..
        } => {
            assert_ne!(
                dmasr & fcc_driver::dma::SR_DMA_DEC_ERR,
                0,
                "DMASR {dmasr:#x}"
            );
            assert_ne!(dmasr & fcc_driver::dma::SR_HALTED, 0, "DMASR {dmasr:#x}");
        }
        e => panic!("expected a DMA decode error, got: {e}"),
    }
    run_ok(&mut d, &p, &f, "after the decode error");
}

#[test]
fn dma_slave_error_on_the_pixel_read_is_reported_and_the_next_frame_is_right() {
    let p = small();
    let mut d = open(&p);
    let f = frames::random(&p, 4);
    d.hal().inject(Fault::SlaveError {
        channel: Channel::Mm2s,
        beat: 1000,
    });
    let e = run_err(&mut d, &p, &f);
    let msg = e.to_string();
    assert!(
        matches!(
            e,
            Error::Dma {
                channel: Channel::Mm2s,
                ..
            }
        ) && msg.contains("DMASlvErr"),
        "{msg}"
    );
    run_ok(&mut d, &p, &f, "after the slave error");
}

#[test]
fn frame_shorter_than_announced_is_flagged_and_the_next_frame_is_right() {
    let p = small();
    let mut d = open(&p);
    let f = frames::random(&p, 6);
    d.hal().inject(Fault::ShortFrame { beats: 1000 });
    let e = run_err(&mut d, &p, &f);
    assert!(matches!(e, Error::StreamLength { pixels: 4096 }), "{e}");
    assert!(e.to_string().contains("tlast early or late"), "{e}");
    run_ok(&mut d, &p, &f, "after the short frame");
}

#[test]
fn stuck_label_stream_times_out_and_the_next_frame_is_right() {
    let p = small();
    let mut d = open(&p);
    let f = frames::random(&p, 7);
    d.hal().inject(Fault::StuckS2mm);
    let e = run_err(&mut d, &p, &f);
    match &e {
        Error::Timeout { stage, .. } => assert!(stage.contains("frame-done"), "{e}"),
        _ => panic!("expected a timeout, got: {e}"),
    }
    run_ok(&mut d, &p, &f, "after the timeout");
}

#[test]
fn core_left_mid_frame_by_a_previous_run_is_reset_and_the_next_frame_is_right() {
    let p = small();
    let (mut board, expect) = virtual_board(&p).unwrap_or_else(|e| panic!("{e}"));
    let f = frames::random(&p, 8);
    board.leave_core_mid_frame(&f, 1500).unwrap();
    let mut d = Driver::open(board, &expect).unwrap_or_else(|e| panic!("{e}"));
    assert!(
        d.core_busy().unwrap().is_some(),
        "the core should be mid-frame"
    );
    let e = run_err(&mut d, &p, &f);
    assert!(matches!(e, Error::CoreWasBusy { .. }), "{e}");
    assert!(e.to_string().contains("previous run"), "{e}");
    run_ok(&mut d, &p, &f, "after the reset");
    // Open on a busy core, recover first (what `fcc board run` does).
    let (mut board, expect) = virtual_board(&p).unwrap();
    board.leave_core_mid_frame(&f, 10).unwrap();
    let mut d = Driver::open(board, &expect).unwrap();
    d.recover().unwrap();
    run_ok(&mut d, &p, &f, "after recover at open");
}

#[test]
fn wrong_build_and_wrong_run_parameters_are_refused() {
    let p = small();
    let (board, mut expect) = virtual_board(&p).unwrap();
    expect.hash ^= 1;
    match Driver::open(board, &expect) {
        Err(Error::HashMismatch { .. }) => {}
        Err(e) => panic!("expected a hash mismatch, got: {e}"),
        Ok(_) => panic!("a wrong hash was accepted"),
    }
    let mut d = open(&p);
    let f = frames::random(&p, 9);
    let mut labels = vec![0u32; p.pixels()];
    let base = build_run(&p);
    let bad = [
        (RunConfig { k: 4, ..base }, "RUN_K = 4"),
        (RunConfig { k: 9, ..base }, "RUN_K = 9"),
        (RunConfig { rows: 17, ..base }, "RUN_ROWS = 17"),
        (RunConfig { cols: 31, ..base }, "RUN_COLS = 31"),
        (RunConfig { th_h_q: 0, ..base }, "RUN_TH_H = 0"),
        (
            RunConfig {
                th_v_q: 0x8001,
                ..base
            },
            "RUN_TH_V = 32769",
        ),
        (
            RunConfig {
                th_h_slope_q: 0x1_0000,
                ..base
            },
            "RUN_SLOPE_H = 65536",
        ),
    ];
    for (run, name) in bad {
        let e = d
            .run_frame(&run, Pixels::Points(&f.points), &mut labels)
            .expect_err("refused");
        assert!(matches!(e, Error::RunRefused { .. }), "{run:?}: {e}");
        assert!(e.to_string().contains(name), "{run:?}: {e}");
    }
    let short = &f.points[..100];
    let e = d
        .run_frame(&base, Pixels::Points(short), &mut labels)
        .expect_err("refused");
    assert!(
        matches!(
            e,
            Error::FrameSize {
                expected: 4096,
                got: 100
            }
        ),
        "{e}"
    );
    run_ok(&mut d, &p, &f, "after the refusals");
}

// ---- The column-streaming core on the virtual board.

/// The column regression's K = 3 build (24 x 256, 9-bit labels; its
/// Verilator model is shared).
fn column_build() -> FccParams {
    FccParams {
        rows: 24,
        cols: 256,
        fsize: 3,
        label_bits: 9,
        scan: fcc_params::Scan::Column,
        ..Default::default()
    }
}

/// Run `frame` (row-major pixels; the driver sends them in column order)
/// under `p`'s run values and compare every record and the end beat with
/// the golden stream's, and the status with the end beat.
fn records_ok(
    d: &mut Driver<VirtualBoard>,
    p: &FccParams,
    frame: &Frame,
    pixels: Pixels<'_>,
    what: &str,
) -> u32 {
    use fcc_pixel::record::Item;
    let mut got = Vec::new();
    let r = d
        .run_records(&build_run(p), pixels, &mut got)
        .unwrap_or_else(|e| panic!("{what}: {e}"));
    let want = fcc_sim::column::golden_items(p, frame, false).unwrap();
    let got: Vec<Item> = got
        .into_iter()
        .map(Item::Record)
        .chain([Item::End(r.end)])
        .collect();
    if let Some(d) = fcc_sim::column::first_difference(&want, &got) {
        panic!("{what}: {d}");
    }
    assert_eq!(r.status.clusters, r.end.records.min(0xffff), "{what}");
    assert_eq!(r.status.overflow, r.end.overflow, "{what}");
    assert!(r.time_ns > 0);
    r.end.records
}

fn records_of(d: &mut Driver<VirtualBoard>, p: &FccParams, f: &Frame, what: &str) -> u32 {
    records_ok(d, p, f, Pixels::Points(&f.points), what)
}

#[test]
fn column_core_records_through_the_dma_equal_the_golden_streams_back_to_back() {
    let p = column_build();
    let mut d = open(&p);
    assert_eq!(d.defaults(), build_run(&p), "the build's run values");
    let mut total = 0;
    for seed in 1..=2 {
        let f = frames::random(&p, seed);
        total += records_of(&mut d, &p, &f, &format!("random seed {seed}"));
    }
    assert!(total > 20, "{total} records");
    // The first directed frame that runs out of the 511 labels.
    let (name, f) = frames::directed(&p)
        .into_iter()
        .find(|(_, f)| {
            let items = fcc_sim::column::golden_items(&p, f, false).unwrap();
            matches!(items.last(), Some(fcc_pixel::record::Item::End(e)) if e.overflow)
        })
        .expect("a directed frame runs out of labels");
    records_of(&mut d, &p, &f, name);
    records_of(&mut d, &p, &frames::empty(&p), "empty");
    // Other run values, the stream limits among them, then the build's.
    let q = FccParams {
        rows: 21,
        cols: 200,
        bridge: Some(2),
        ring_reach: Some(6),
        open_limit: Some(12),
        th_h_slope: 0.02,
        ..p.clone()
    };
    records_of(
        &mut d,
        &q,
        &frames::random(&q, 3),
        "21 x 200, limits 2 / 6 / 12",
    );
    records_of(
        &mut d,
        &p,
        &frames::random(&p, 3),
        "the build's values again",
    );
}

#[test]
fn column_core_float_input_is_quantised_and_sent_in_column_order() {
    let p = column_build();
    let mut d = open(&p);
    let base = frames::random(&p, 5);
    // Row-major metres, with NaN and out-of-range coordinates mixed in.
    let mut xyz = Vec::with_capacity(p.pixels() * 3);
    for (i, pt) in base.points.iter().enumerate() {
        match pt {
            Some(_) if i % 11 == 0 => xyz.extend([f64::NAN, 1.0, 1.0]),
            Some(_) if i % 13 == 0 => xyz.extend([-128.002, 1.0, 1.0]),
            Some(q) => xyz.extend(q.map(|v| f64::from(v) / 256.0)),
            None => xyz.extend([f64::INFINITY, 0.0, 0.0]),
        }
    }
    let frame = Frame::from_xyz_f64(p.rows, p.cols, &xyz);
    records_ok(&mut d, &p, &frame, Pixels::XyzF64(&xyz), "float input");
}

#[test]
fn column_core_refusals_and_faults_end_clearly_and_the_next_frame_is_right() {
    let p = column_build();
    let mut d = open(&p);
    let f = frames::random(&p, 9);
    let base = build_run(&p);
    let limits = base.limits.expect("a column build has stream limits");
    for (l, name) in [
        (
            fcc_driver::StreamLimits {
                open_limit: 0,
                ..limits
            },
            "RUN_OPEN_LIMIT = 0",
        ),
        (
            fcc_driver::StreamLimits {
                open_limit: 512,
                ..limits
            },
            "RUN_OPEN_LIMIT = 512",
        ),
        (
            fcc_driver::StreamLimits {
                bridge: 0x1000,
                ..limits
            },
            "RUN_BRIDGE = 4096",
        ),
    ] {
        let run = RunConfig {
            limits: Some(l),
            ..base
        };
        let e = d
            .run_records(&run, Pixels::Points(&f.points), &mut Vec::new())
            .expect_err("refused");
        assert!(matches!(e, Error::RunRefused { .. }), "{run:?}: {e}");
        assert!(e.to_string().contains(name), "{run:?}: {e}");
    }
    records_of(&mut d, &p, &f, "after the refusals");
    // Labels are refused on the column core.
    let e = d
        .run_frame(&base, Pixels::Points(&f.points), &mut vec![0; p.pixels()])
        .unwrap_err();
    assert!(e.to_string().contains("run_records"), "{e}");

    d.hal().inject(Fault::ShortFrame { beats: 1000 });
    let e = d
        .run_records(&base, Pixels::Points(&f.points), &mut Vec::new())
        .unwrap_err();
    assert!(matches!(e, Error::StreamLength { pixels: 6144 }), "{e}");
    records_of(&mut d, &p, &f, "after the short frame");

    d.hal().inject(Fault::DecodeError {
        channel: Channel::S2mm,
        beat: 5,
    });
    let e = d
        .run_records(&base, Pixels::Points(&f.points), &mut Vec::new())
        .unwrap_err();
    assert!(
        matches!(
            e,
            Error::Dma {
                channel: Channel::S2mm,
                ..
            }
        ),
        "{e}"
    );
    records_of(&mut d, &p, &f, "after the decode error");

    d.hal().inject(Fault::StuckS2mm);
    let e = d
        .run_records(&base, Pixels::Points(&f.points), &mut Vec::new())
        .unwrap_err();
    assert!(matches!(e, Error::Timeout { .. }), "{e}");
    records_of(&mut d, &p, &f, "after the timeout");
}
