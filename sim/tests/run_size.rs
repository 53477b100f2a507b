//! One core, many sensors: a core built once for K_max = 11, 128 rows, 2048
//! columns and 16-bit labels runs frames of other sizes, filter sizes and
//! thresholds back to back, programmed through its run registers between
//! frames (never regenerated), each frame bit-exact with the golden model
//! called with that frame's parameters.

use fcc_golden::Frame;
use fcc_params::FccParams;
use fcc_sim::{frames, load, run_and_check_with, Drive, Dut, FrameRun, Tlast};

/// The "one bitstream for every sensor" build.
fn build() -> FccParams {
    FccParams {
        rows: 128,
        cols: 2048,
        fsize: 11,
        label_bits: 16,
        ..Default::default()
    }
}

fn dut(p: &FccParams) -> Dut {
    let model = load(p).unwrap_or_else(|e| panic!("{e}"));
    let mut d = Dut::new(model);
    d.reset(4);
    d
}

/// The run parameters of `frame` with K and the thresholds (th_H, th_V).
fn run_of(frame: &Frame, fsize: usize, th: (f64, f64)) -> FccParams {
    FccParams {
        rows: frame.rows,
        cols: frame.cols,
        fsize,
        th_h: th.0,
        th_v: th.1,
        ..build()
    }
}

fn check(d: &mut Dut, run: &FccParams, f: &Frame, drive: &Drive, what: &str) -> FrameRun {
    run_and_check_with(d, run, f, drive, what).unwrap_or_else(|e| panic!("{e}"))
}

/// The first frame of every Ouster capture in the repository, at its own
/// size (32, 64 and 128 beams x 1024 columns), and a 64 x 2048 synthetic
/// street scene.
fn sensor_frames() -> Vec<(String, Frame)> {
    use fcc_lidar::ouster::{read_capture, DecodeOptions, OusterMetadata, SAMPLE_CAPTURES};
    let data =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../crates/fcc-lidar/tests/data");
    let mut out = vec![];
    for (pcap, json) in SAMPLE_CAPTURES {
        let meta = OusterMetadata::from_file(&data.join(json)).unwrap();
        let capture = read_capture(&data.join(pcap), &meta, DecodeOptions::default()).unwrap();
        let img = &capture
            .frames
            .first()
            .unwrap_or_else(|| panic!("{pcap}: no frame"))
            .image;
        out.push((pcap.to_string(), img.to_frame()));
    }
    let cfg = fcc_scene::SceneConfig {
        rows: 64,
        cols: 2048,
        seed: 1,
        ..Default::default()
    };
    let scene = fcc_scene::generate(&cfg).unwrap();
    out.push((
        "scene 64x2048 seed 1".to_string(),
        Frame::from_xyz_f32(64, 2048, &scene.xyz),
    ));
    out
}

/// Threshold pairs (th_H, th_V) in metres.
const THRESHOLDS: [(f64, f64); 2] = [(0.4, 0.8), (0.25, 1.5)];
const KS: [usize; 5] = [3, 5, 7, 9, 11];

/// Every frame at every K and both threshold pairs, the size changing from
/// one frame to the next.
#[test]
fn one_core_runs_every_sensor_size_k_and_threshold_back_to_back() {
    let b = build();
    let mut d = dut(&b);
    let sensors = sensor_frames();
    let mut n = 0u64;
    for th in THRESHOLDS {
        for k in KS {
            for (name, f) in &sensors {
                let run = run_of(f, k, th);
                let drive = Drive {
                    seed: n,
                    ..Default::default()
                };
                let what = format!(
                    "{name} {}x{} K {k} th_h {} th_v {}",
                    f.rows, f.cols, th.0, th.1
                );
                let r = check(&mut d, &run, f, &drive, &what);
                let rc = (f.rows * f.cols) as f64;
                eprintln!(
                    "CYCLES {what}: {} = {:.3} x R x C, joins {}",
                    r.cycles,
                    r.cycles as f64 / rc,
                    r.joins
                );
                // The real captures keep the ground (a heavier join load than
                // the scenes, up to 1.32 x R x C); the scene has the budget.
                if name.starts_with("scene") {
                    assert!(
                        r.cycles as f64 <= 1.3 * rc,
                        "{what}: {} cycles exceed 1.3 x R x C",
                        r.cycles
                    );
                }
                n += 1;
            }
        }
    }
}

/// Run sizes at the edges: one row, the fewest columns, sizes that are not a
/// multiple of the labels per beat, the build's full size, frames cut short
/// and too long at a run size, under input gaps and output back-pressure.
#[test]
fn run_sizes_at_the_edges_on_one_core() {
    let b = build();
    let mut d = dut(&b);
    // Power-on: the build's own size and parameters, no register written.
    let f = frames::random(&b, 3);
    let gold = fcc_sim::expected(&b, &f).unwrap();
    let r = d.run_frame(&f, &Drive::default()).unwrap();
    fcc_sim::compare(&b, &gold, &r, "power-on defaults").unwrap();
    let cols_min = fcc_rtl::regmap::run_cols_min(&b) as usize;
    let sizes = [
        (1, cols_min),
        (1, 2048),
        (2, cols_min + 1),
        (16, cols_min),
        (5, 37),
        (17, 257),
        (128, 33),
        (3, 2047),
    ];
    let stress = Drive {
        gap: 0.2,
        backpressure: 0.4,
        seed: 17,
        ..Default::default()
    };
    for (i, (rows, cols)) in sizes.into_iter().enumerate() {
        let shape = FccParams {
            rows,
            cols,
            ..b.clone()
        };
        let k = KS[i % KS.len()];
        let th = THRESHOLDS[i % 2];
        for (name, f) in frames::directed(&shape).into_iter().take(8) {
            let run = run_of(&f, k, th);
            check(
                &mut d,
                &run,
                &f,
                &Drive::default(),
                &format!("{name} {rows}x{cols} K {k}"),
            );
        }
        let f = frames::random(&shape, 100 + i as u64);
        let run = run_of(&f, k, th);
        check(
            &mut d,
            &run,
            &f,
            &stress,
            &format!("random {} {rows}x{cols} K {k}", 100 + i),
        );
        // tlast early, then late, at this run size: the frame error follows
        // the run's R x C, and the next frame is clean.
        let at = rows * cols / 2;
        let mut cut = f.clone();
        for px in cut.points.iter_mut().skip(at + 1) {
            *px = None;
        }
        d.program_run(&run).unwrap();
        let gold = fcc_sim::expected(&run, &cut).unwrap();
        let early = Drive {
            tlast: Tlast::Early { at },
            ..Default::default()
        };
        let r = d.run_frame(&f, &early).unwrap();
        fcc_sim::compare(&run, &gold, &r, &format!("early tlast {rows}x{cols}")).unwrap();
        assert!(
            r.frame_error,
            "{rows}x{cols}: early tlast must set frame_error"
        );
        let late = Drive {
            tlast: Tlast::Late { extra: 5 },
            ..Default::default()
        };
        let r = check(
            &mut d,
            &run,
            &f,
            &late,
            &format!("late tlast {rows}x{cols}"),
        );
        assert!(
            r.frame_error,
            "{rows}x{cols}: late tlast must set frame_error"
        );
        let r = check(
            &mut d,
            &run,
            &f,
            &Drive::default(),
            &format!("after tlast errors {rows}x{cols}"),
        );
        assert!(
            !r.frame_error,
            "{rows}x{cols}: frame_error after a clean frame"
        );
    }
}
