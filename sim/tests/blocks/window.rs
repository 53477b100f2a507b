//! The window `fcc_window` and its line buffers alone under Verilator,
//! against a software model of the K x h window: for every build K, at the
//! image edges (first and last rows and columns, no wrap-around), with a
//! K = 11 build running every smaller K, random idle cycles between pixels,
//! and run-time rows and columns below the build's limits. A mismatch prints
//! the frame, the centre pixel, the window entry, expected, got and the seed.

use fcc_params::FccParams;
use fcc_rtl::regmap::RUN_COLS_MIN;
use fcc_sim::{load_window, WinEntry, WinIn, WindowDut};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// One point of a frame: whether it has a provisional label, and its x, y, z.
#[derive(Clone, Copy)]
struct Point {
    lok: bool,
    xyz: [u16; 3],
}

/// A frame run: its size, its K and its points in raster order.
struct Frame {
    rows: usize,
    cols: usize,
    run_k: usize,
    points: Vec<Point>,
}

fn build(fsize: usize) -> FccParams {
    FccParams {
        rows: 16,
        cols: 256,
        fsize,
        ..Default::default()
    }
}

fn random_frame(rng: &mut ChaCha8Rng, rows: usize, cols: usize, run_k: usize) -> Frame {
    let points = (0..rows * cols)
        .map(|_| Point {
            lok: rng.gen_bool(0.7),
            xyz: [rng.gen(), rng.gen(), rng.gen()],
        })
        .collect();
    Frame {
        rows,
        cols,
        run_k,
        points,
    }
}

/// The software model: entry e = r*K + n of centre (i, j) is the point at
/// (i - h + r, j - h + n) when that lies inside the image and within the
/// run's window, else masked (`None`).
fn expected(p: &FccParams, f: &Frame, i: usize, j: usize, e: usize) -> Option<Point> {
    let (k, h) = (p.fsize, p.half());
    let run_h = (f.run_k - 1) / 2;
    let (r, n) = (e / k, e % k);
    if h - r > run_h || n.abs_diff(h) > run_h || i + r < h || j + n < h {
        return None;
    }
    let (row, col) = (i + r - h, j + n - h);
    if col >= f.cols {
        return None;
    }
    let pt = f.points[row * f.cols + col];
    pt.lok.then_some(pt)
}

/// Run `frames` back to back through a fresh window of build `p` (random
/// idle cycles between pixels with probability `gap`) and compare every
/// centre's window with the model.
fn run(p: &FccParams, frames: &[Frame], gap: f64, seed: u64) {
    let model = match load_window(p) {
        Ok(m) => m,
        Err(e) => panic!("{e}"),
    };
    let mut dut = WindowDut::new(model, p);
    let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0x9e37);
    let h = p.half();
    let idle = |f: &Frame| WinIn {
        last_col: (f.cols - 1) as u16,
        run_k: f.run_k as u8,
        ..Default::default()
    };
    for _ in 0..2 {
        dut.step(&WinIn {
            rst: 1,
            ..Default::default()
        });
    }
    // Pixels sent, in order: (frame, row, column); centres come out in the same order.
    let mut sent = std::collections::VecDeque::new();
    let mut checked = 0usize;
    let mut check =
        |dut_out: (fcc_sim::WinOut, Vec<WinEntry>),
         sent: &mut std::collections::VecDeque<(usize, usize, usize)>| {
            let (out, ents) = dut_out;
            if out.centre_valid == 0 {
                return;
            }
            let (fi, i, j) = sent
                .pop_front()
                .unwrap_or_else(|| panic!("seed {seed}: a centre came out that was never sent"));
            let f = &frames[fi];
            let c = f.points[i * f.cols + j];
            assert_eq!(
                (out.centre_x, usize::from(out.centre_col)),
                (c.xyz[0], j),
                "seed {seed}: frame {fi} K={}: centre ({i}, {j}): expected x, col != got",
                f.run_k
            );
            for (e, got) in ents.iter().enumerate() {
                let want = expected(p, f, i, j, e);
                let ok = match want {
                    None => !got.ok,
                    Some(pt) => got.ok && [got.x, got.y, got.z] == pt.xyz,
                };
                assert!(
                    ok,
                    "seed {seed}: frame {fi} ({} x {}, run K={}), centre ({i}, {j}), entry {e} \
                 (row {}, column offset {}): expected {:?} != got {:?}",
                    f.rows,
                    f.cols,
                    f.run_k,
                    e / p.fsize,
                    (e % p.fsize) as i64 - h as i64,
                    want.map(|pt| (true, pt.xyz)),
                    (got.ok, [got.x, got.y, got.z]),
                );
            }
            checked += 1;
        };
    for (fi, f) in frames.iter().enumerate() {
        // The run size settles before the frame's first pixel.
        for _ in 0..2 {
            check(dut.step(&idle(f)), &mut sent);
        }
        for i in 0..f.rows {
            for j in 0..f.cols {
                while rng.gen_bool(gap) {
                    check(dut.step(&idle(f)), &mut sent);
                }
                let pt = f.points[i * f.cols + j];
                let inp = WinIn {
                    in_valid: 1,
                    in_lok: u8::from(pt.lok),
                    in_x: pt.xyz[0],
                    in_y: pt.xyz[1],
                    in_z: pt.xyz[2],
                    in_row: i as u8,
                    in_col: j as u16,
                    in_rdcol: ((j + h) % f.cols) as u16,
                    ..idle(f)
                };
                sent.push_back((fi, i, j));
                check(dut.step(&inp), &mut sent);
            }
        }
        for _ in 0..4 {
            check(dut.step(&idle(f)), &mut sent);
        }
    }
    let total: usize = frames.iter().map(|f| f.rows * f.cols).sum();
    assert!(
        sent.is_empty(),
        "seed {seed}: {} centres never came out",
        sent.len()
    );
    assert_eq!(checked, total, "seed {seed}: centres checked");
}

#[test]
fn every_build_k_matches_the_window_model_at_the_image_edges() {
    for k in [3, 5, 7, 9, 11] {
        let p = build(k);
        let seed = 90 + k as u64;
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let min = RUN_COLS_MIN as usize;
        let mut frames = vec![
            // One row: every window row lies above the image.
            random_frame(&mut rng, 1, min, k),
            // The narrowest frame, then the build's full width.
            random_frame(&mut rng, k, min, k),
            random_frame(&mut rng, 2, p.cols, k),
        ];
        for _ in 0..3 {
            let rows = rng.gen_range(2..=8);
            let cols = rng.gen_range(min..=64);
            frames.push(random_frame(&mut rng, rows, cols, k));
        }
        run(&p, &frames, 0.0, seed);
        run(&p, &frames, 0.25, seed);
    }
}

#[test]
fn k11_build_masks_the_outer_positions_of_every_smaller_run_k() {
    let p = build(11);
    let seed = 911;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut frames = vec![];
    for run_k in [3, 5, 7, 9, 11, 3] {
        let rows = rng.gen_range(1..=7);
        let cols = rng.gen_range(RUN_COLS_MIN as usize..=48);
        frames.push(random_frame(&mut rng, rows, cols, run_k));
    }
    run(&p, &frames, 0.1, seed);
}
