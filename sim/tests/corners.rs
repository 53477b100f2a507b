//! Directed corners for what the regression alone never reached (see
//! docs/coverage.md): the read-back waiting on a sink that stalls for long
//! stretches (every queue of the label updater full), dense frames fed without
//! gaps (input credits running low), a sink that is never ready until the
//! whole frame is in, and a join queue that fills. All on 16 x 256, 11-bit
//! configurations of the regression (K = 3 and 9), so no model beyond the
//! regression's is built.

use fcc_params::FccParams;
use fcc_sim::model::FccIn;
use fcc_sim::{frames, load, run_and_check, Drive, Dut, FrameRun};

fn small() -> FccParams {
    FccParams {
        rows: 16,
        cols: 256,
        fsize: 3,
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

fn check(d: &mut Dut, f: &fcc_golden::Frame, drive: &Drive, what: &str) -> FrameRun {
    match run_and_check(d, f, drive, what) {
        Ok(r) => r,
        Err(e) => panic!("{e}"),
    }
}

/// The sink is ready one cycle in twenty: the output register, the decoded
/// beat queue and the gearbox fill and the flatten pass waits on them.
#[test]
fn readback_waits_on_a_sink_ready_one_cycle_in_twenty() {
    let p = small();
    let mut d = dut(&p);
    for (seed, f) in [
        (1u64, frames::random(&p, 4001)),
        (2, frames::checkerboard(&p)),
        (3, frames::label_overflow(&p)),
    ] {
        let drive = Drive {
            backpressure: 0.95,
            seed,
            max_cycles: 2_000_000,
            ..Default::default()
        };
        let run = check(&mut d, &f, &drive, "sink ready 1 in 20");
        assert!(run.labels.len() == p.pixels());
    }
}

/// The sink is held not ready until every pixel has been accepted and the
/// drain is over, then runs free: the read-back starts against a full
/// output path.
#[test]
fn readback_starts_against_a_sink_stalled_for_the_whole_frame() {
    let p = small();
    let mut d = dut(&p);
    let f = frames::u_shapes(&p);
    // Stall the sink while the whole frame goes in, then a while longer.
    let beats = fcc_sim::drive::frame_beats(&f, fcc_sim::Tlast::Normal);
    let mut i = 0;
    let mut guard = 0u64;
    while i < beats.len() {
        let out = d.step(&FccIn {
            s_axis_tdata: beats[i].0,
            s_axis_tvalid: 1,
            s_axis_tlast: u8::from(beats[i].1),
            m_axis_tready: 0,
            ..Default::default()
        });
        assert_eq!(out.status_frame_done, 0, "frame_done with the sink stalled");
        if out.s_axis_tready != 0 {
            i += 1;
        }
        guard += 1;
        assert!(guard < 1_000_000, "input not taken with the sink stalled");
    }
    for _ in 0..3000 {
        let out = d.step(&FccIn::default());
        assert_eq!(out.status_frame_done, 0, "frame_done with the sink stalled");
    }
    // The whole frame was accepted: the labels come out once the sink runs.
    let run = match d.run_frame_from(&f, &Drive::default(), beats.len()) {
        Ok(r) => r,
        Err(e) => panic!("{e}"),
    };
    let gold = fcc_sim::expected(&p, &f).unwrap();
    if let Err(e) = fcc_sim::compare(&p, &gold, &run, "u_shapes after a stalled sink") {
        panic!("{e}");
    }
}

/// Frames with the most joins per pixel, fed with no gaps and the sink
/// always ready, then with the sink mostly stalled: the centre buffer and
/// the join queue run as full as this size allows.
#[test]
fn dense_frames_without_input_gaps_under_full_and_no_backpressure() {
    let p = small();
    let mut d = dut(&p);
    for (name, f) in [
        ("checkerboard", frames::checkerboard(&p)),
        ("comb", frames::comb(&p)),
        ("staircase", frames::staircase(&p)),
    ] {
        let run = check(&mut d, &f, &Drive::default(), name);
        eprintln!(
            "{name}: joins {}, input stalls {}, read-back waits {}",
            run.joins, run.input_stalls, run.gear_stalls
        );
        let drive = Drive {
            backpressure: 0.9,
            seed: 7,
            max_cycles: 2_000_000,
            ..Default::default()
        };
        check(&mut d, &f, &drive, name);
    }
}

/// More joins than the union engine can take: 120 columns of stripes (1,920
/// runs, within the 11-bit labels) give about 17,000 joins at K = 9, more than
/// one per cycle, while the union engine takes at most one per two cycles.
/// The join queue (4,096 joins) fills, the serializer waits for its room and
/// the input is held; the labels must still be exact. (The sort-network
/// bench checks that the queue reaches its high level for this frame even
/// with a union engine ready every other cycle; docs/coverage.md shows the
/// serializer's wait reached here.)
#[test]
fn join_queue_fills_and_holds_the_input() {
    let p = FccParams {
        fsize: 9,
        ..small()
    };
    let mut d = dut(&p);
    let f = frames::stripes(&p, 120);
    let run = check(&mut d, &f, &Drive::default(), "stripes, 120 columns");
    eprintln!(
        "stripes: joins {}, input stalls {}, cycles {}",
        run.joins, run.input_stalls, run.cycles
    );
    assert!(
        run.joins as usize > fcc_rtl::JQ_HIGH_LEVEL,
        "only {} joins: too few to fill the join queue",
        run.joins
    );
    assert!(run.input_stalls > 0, "the input was never held");
}
