//! Verilator regression of the column-streaming core (`fcc gen --scan
//! column`) against the golden stream: per K in {3, 5, 7, 9, 11}, the
//! directed frames and seeded random ones back to back under random input
//! gaps and output back-pressure, early and late `tlast`, a reset and a
//! soft reset in the middle of a frame, and run registers (smaller K and
//! frame, adaptive thresholds, the stream limits) programmed between
//! frames. Every record and end beat must be the golden one; the status
//! ports must give each end beat's counts.

use fcc_params::{FccParams, Scan};
use fcc_rtl::regmap::{bits, offset};
use fcc_sim::column::{ColDrive, ColFrame};
use fcc_sim::{frames, load, AxilMaster, Dut, Tlast};

/// The build: 24 rows (at least K + 8 at every K) by 256 columns, 9-bit
/// labels so that the dense frames run out of them.
fn build(fsize: usize) -> FccParams {
    FccParams {
        rows: 24,
        cols: 256,
        fsize,
        label_bits: 9,
        scan: Scan::Column,
        ..Default::default()
    }
}

fn dut(p: &FccParams) -> Dut {
    let model = load(p).unwrap_or_else(|e| panic!("{e}"));
    let mut d = Dut::new(model);
    d.reset(4);
    d
}

fn frame(p: &FccParams, f: &fcc_golden::Frame, tlast: Tlast, name: &str) -> ColFrame {
    ColFrame::new(p, f, tlast, name).unwrap_or_else(|e| panic!("{name}: {e}"))
}

fn run(d: &mut Dut, frames: &[ColFrame], drive: &ColDrive, what: &str) -> fcc_sim::column::ColRun {
    match d.run_columns(frames, drive) {
        Ok(r) => r,
        Err(e) => panic!("K = {}, {what}: {e}", d.params().fsize),
    }
}

fn column_core(fsize: usize) {
    let p = build(fsize);
    let mut d = dut(&p);
    // Directed frames and seeded random ones, back to back.
    let mut set: Vec<ColFrame> = frames::directed(&p)
        .into_iter()
        .map(|(name, f)| frame(&p, &f, Tlast::Normal, name))
        .collect();
    for seed in 0..4u64 {
        let f = frames::random(&p, seed * 1000 + fsize as u64);
        set.push(frame(&p, &f, Tlast::Normal, &format!("random {seed}")));
    }
    assert!(
        set.iter()
            .any(|f| matches!(f.items.last(), Some(fcc_pixel::record::Item::End(e)) if e.overflow)),
        "a frame must run out of the {} labels",
        p.max_label()
    );
    for (n, (gap, backpressure)) in [(0.0, 0.0), (0.3, 0.5), (0.05, 0.8)]
        .into_iter()
        .enumerate()
    {
        let drive = ColDrive {
            gap,
            backpressure,
            seed: (fsize * 100 + n) as u64,
            ..Default::default()
        };
        let r = run(
            &mut d,
            &set,
            &drive,
            &format!("directed and random, drive {n}"),
        );
        assert_eq!(r.status.len(), set.len());
        for (f, (clusters, _, _)) in set.iter().zip(&r.status) {
            assert_eq!(*clusters, f.records().min(0xFFFF), "{}: CLUSTERS", f.name);
        }
    }
    // Early and late tlast, each followed by a clean frame.
    let f = frames::random(&p, 77);
    let ends = [
        frame(&p, &f, Tlast::Early { at: p.pixels() / 3 }, "early tlast"),
        frame(&p, &frames::ring(&p), Tlast::Normal, "after early tlast"),
        frame(&p, &f, Tlast::Late { extra: 9 }, "late tlast"),
        frame(&p, &frames::comb(&p), Tlast::Normal, "after late tlast"),
    ];
    let drive = ColDrive {
        gap: 0.2,
        backpressure: 0.3,
        seed: 5,
        ..Default::default()
    };
    run(&mut d, &ends, &drive, "early and late tlast");
    // A reset in the middle of a frame, then frames from scratch.
    let clean = [frame(
        &p,
        &frames::u_shapes(&p),
        Tlast::Normal,
        "after reset",
    )];
    d.feed_columns(&ends[0], p.pixels() / 2).unwrap();
    d.reset(3);
    run(&mut d, &clean, &ColDrive::default(), "after a reset");
    // The same with CONTROL.SOFT_RESET: the registers keep their values.
    d.feed_columns(&ends[2], p.pixels() / 3).unwrap();
    let mut m = AxilMaster::new(fsize as u64);
    m.write_ok(&mut d, offset::CONTROL, bits::CONTROL_SOFT_RESET)
        .unwrap();
    run(&mut d, &clean, &ColDrive::default(), "after a soft reset");
    // Run registers: a smaller K and frame, adaptive thresholds and the
    // stream's limits, then the build's values again.
    let small = FccParams {
        rows: fcc_params::limits::hw_column_rows_min(3).max(p.rows - 3),
        cols: 200,
        fsize: 3,
        th_h_slope: 0.02,
        th_v_slope: 0.05,
        bridge: Some(2),
        ring_reach: Some(6),
        open_limit: Some(12),
        ..p.clone()
    };
    for runp in [small.clone(), p.clone()] {
        d.program_run(&runp)
            .unwrap_or_else(|e| panic!("programming: {e}"));
        let set: Vec<ColFrame> = (0..3u64)
            .map(|s| {
                let f = frames::random(&runp, 500 + s);
                frame(
                    &runp,
                    &f,
                    Tlast::Normal,
                    &format!("run registers, random {s}"),
                )
            })
            .collect();
        run(&mut d, &set, &drive, "run registers");
    }
}

#[test]
fn column_core_k3() {
    column_core(3);
}

#[test]
fn column_core_k5() {
    column_core(5);
}

#[test]
fn column_core_k7() {
    column_core(7);
}

#[test]
fn column_core_k9() {
    column_core(9);
}

#[test]
fn column_core_k11() {
    column_core(11);
}
