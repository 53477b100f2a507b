//! The run-against-run exact path of `cluster` equals the plain pixel-window
//! path (pass 1, ring joins, `pass2` with an `ExactMerge`, `renumber`) on
//! random frames for every K: labels, clusters, joins and merges. A reused
//! workspace gives the same results as a fresh one.

use fcc_golden::{
    cluster, cluster_with, pass1, pass2, reference::reference_labels, renumber, Clustering,
    ExactMerge, Frame, MergeMode, Workspace,
};
use fcc_params::FccParams;
use proptest::prelude::*;

/// Random points on a jittered grid at 10 m, `density` percent valid.
fn random_frame(rows: usize, cols: usize, density: u64, spacing: f64, seed: u64) -> Frame {
    let mut s = seed | 1;
    let mut next = move || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        s
    };
    let mut xyz = Vec::with_capacity(rows * cols * 3);
    for r in 0..rows {
        for c in 0..cols {
            if next() % 100 < density {
                let j = |v: u64| (v % 2001) as f64 / 1000.0 - 1.0;
                xyz.extend([
                    10.0 + 0.3 * j(next()),
                    c as f64 * spacing + 0.1 * j(next()),
                    -(r as f64) * spacing + 0.1 * j(next()),
                ]);
            } else {
                xyz.extend([f64::NAN; 3]);
            }
        }
    }
    Frame::from_xyz_f64(rows, cols, &xyz)
}

/// The plain path: every window pixel of every centre compared.
fn plain(p: &FccParams, f: &Frame) -> (Vec<u32>, u32, u64, u64) {
    let p1 = pass1(p, f);
    let mut m = ExactMerge::new(p1.provisional);
    for &(a, b) in &p1.ring_joins {
        m.union(a, b);
    }
    let joins = pass2(p, f, &p1, &mut m);
    let merges = m.merges;
    let (labels, clusters) = renumber(&p1.labels, &m.representatives());
    (labels, clusters, joins, merges)
}

fn compare(p: &FccParams, f: &Frame, got: &Clustering, seed: u64) -> Result<(), String> {
    let (labels, clusters, joins, merges) = plain(p, f);
    if let Some(i) = (0..labels.len()).find(|&i| labels[i] != got.labels[i]) {
        return Err(format!(
            "K = {}, seed {seed}: first mismatch at row {}, col {}: expected {} != got {}",
            p.fsize,
            i / f.cols,
            i % f.cols,
            labels[i],
            got.labels[i]
        ));
    }
    let stats = [
        ("clusters", u64::from(clusters), u64::from(got.clusters)),
        ("joins", joins, got.joins),
        ("merges", merges, got.merges),
    ];
    for (name, want, have) in stats {
        if want != have {
            return Err(format!(
                "K = {}, seed {seed}: {name}: expected {want} != got {have}",
                p.fsize
            ));
        }
    }
    Ok(())
}

fn params(rows: usize, cols: usize, fsize: usize, th_h: f64, th_v: f64, bits: u32) -> FccParams {
    FccParams {
        rows,
        cols,
        fsize,
        th_h,
        th_v,
        label_bits: bits,
        ..FccParams::default()
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]

    #[test]
    fn run_path_equals_plain_path(
        k in prop::sample::select(vec![3usize, 5, 7, 9, 11, 13, 15]),
        rows in 1usize..20,
        cols in 1usize..60,
        density in 5u64..=100,
        th_h in 0.05f64..0.6,
        th_v in 0.05f64..0.9,
        bits in prop::sample::select(vec![8u32, 15]),
        seed in any::<u64>(),
    ) {
        let f = random_frame(rows, cols, density, 0.25, seed);
        let p = params(rows, cols, k, th_h, th_v, bits);
        let got = cluster(&p, &f, MergeMode::Exact).unwrap();
        compare(&p, &f, &got, seed).map_err(TestCaseError::fail)?;
    }
}

#[test]
fn run_path_equals_plain_path_on_wide_frames_for_every_fsize() {
    for (n, k) in [3usize, 5, 7, 9, 11, 13, 15].into_iter().enumerate() {
        for density in [30, 70, 100] {
            let seed = 40 + n as u64 * 7 + density;
            let f = random_frame(24, 400, density, 0.2, seed);
            let p = params(24, 400, k, 0.3, 0.5, 15);
            let got = cluster(&p, &f, MergeMode::Exact).unwrap();
            compare(&p, &f, &got, seed).unwrap();
            assert_eq!(got.labels, reference_labels(&p, &f), "K = {k}, seed {seed}");
        }
    }
}

#[test]
fn run_path_under_label_overflow_equals_plain_path() {
    // 8-bit labels: runs after the 255th are unlabelled and join nothing.
    let f = random_frame(30, 200, 60, 0.3, 5);
    for k in [3usize, 7, 15] {
        let p = params(30, 200, k, 0.1, 0.5, 8);
        let got = cluster(&p, &f, MergeMode::Exact).unwrap();
        assert!(got.overflow && got.unlabelled > 0);
        compare(&p, &f, &got, 5).unwrap();
    }
}

#[test]
fn run_path_on_columns_past_the_i16_range_equals_plain_path() {
    // The run path keeps columns in 16 bits: objects beyond column 32767,
    // and one spanning it, with gaps, on three rows.
    let (rows, cols) = (3, 40_000);
    let mut f = Frame::empty(rows, cols);
    for (n, c) in (32_700..32_840).chain(39_900..40_000).enumerate() {
        for r in 0..rows {
            if (n + r) % 5 != 0 {
                let y = (c % 100) as i16 * 20;
                f.set(r, c, Some([2560, y, -(r as i16) * 40]));
            }
        }
    }
    for k in [3usize, 5] {
        let p = params(rows, cols, k, 0.1, 0.3, 15);
        let got = cluster(&p, &f, MergeMode::Exact).unwrap();
        assert!(
            got.joins > 0 && got.clusters >= 2,
            "K = {k}: joins {}, clusters {}",
            got.joins,
            got.clusters
        );
        compare(&p, &f, &got, 0).unwrap();
        assert_eq!(got.labels, reference_labels(&p, &f), "K = {k}");
    }
}

#[test]
fn reused_workspace_gives_the_results_of_a_fresh_one() {
    // Shapes change from frame to frame, so stale buffer contents would show.
    let mut ws = Workspace::default();
    let shapes = [(20, 100), (5, 7), (32, 64), (1, 1), (20, 100), (3, 300)];
    for (n, &(rows, cols)) in shapes.iter().enumerate() {
        for mode in [MergeMode::Exact, MergeMode::Paper] {
            let f = random_frame(rows, cols, 60, 0.25, 100 + n as u64);
            let p = params(rows, cols, 5, 0.3, 0.5, 8);
            let fresh = cluster(&p, &f, mode).unwrap();
            let reused = cluster_with(&mut ws, &p, &f, mode).unwrap();
            assert_eq!(reused, fresh, "frame {n} ({rows} x {cols}), {mode:?}");
            ws.recycle(reused);
        }
    }
}
