//! Property tests: the golden model equals the pixel-level union-find
//! reference on random frames, for every K, random thresholds and densities,
//! and on shapes made to produce long merge chains and label overflow.

use fcc_golden::{cluster, reference::reference_labels, split_components, Frame, MergeMode};
use fcc_params::FccParams;
use proptest::prelude::*;

/// Shapes that stress the merge: all are masks over a grid of points.
#[derive(Debug, Clone, Copy)]
enum Family {
    /// Independent pixels with the given density.
    Random,
    /// A rectangular spiral path: one component that winds back on itself.
    Spiral,
    /// Vertical teeth joined only by the bottom row: many runs merge last.
    Comb,
    /// Diagonal steps: every row's run links to the one above at its end.
    Staircase,
    /// Nested U-shapes: arms meet late, from the outside in.
    NestedU,
}

fn mask(family: Family, rows: usize, cols: usize, density: u32, rng: &mut u64) -> Vec<bool> {
    let mut next = || {
        *rng ^= *rng << 13;
        *rng ^= *rng >> 7;
        *rng ^= *rng << 17;
        *rng
    };
    let mut m = vec![false; rows * cols];
    match family {
        Family::Random => {
            for v in m.iter_mut() {
                *v = (next() % 100) < u64::from(density);
            }
        }
        Family::Spiral => {
            let (mut top, mut left, mut bottom, mut right) =
                (0i64, 0i64, rows as i64 - 1, cols as i64 - 1);
            while top <= bottom && left <= right {
                for c in left..=right {
                    m[top as usize * cols + c as usize] = true;
                }
                for r in top..=bottom {
                    m[r as usize * cols + right as usize] = true;
                }
                for c in left..=right {
                    m[bottom as usize * cols + c as usize] = true;
                }
                for r in (top + 2)..=bottom {
                    m[r as usize * cols + left as usize] = true;
                }
                top += 2;
                left += 2;
                bottom -= 2;
                right -= 2;
                if top <= bottom && left > 0 {
                    m[top as usize * cols + (left - 1) as usize] = true;
                }
            }
        }
        Family::Comb => {
            for r in 0..rows {
                for c in 0..cols {
                    m[r * cols + c] = c % 2 == 0 || r == rows - 1;
                }
            }
        }
        Family::Staircase => {
            let w = 1 + (next() % 4) as usize;
            for r in 0..rows {
                for c in 0..cols {
                    let start = (rows - 1 - r) * w;
                    m[r * cols + c] = c >= start % cols && c < (start % cols) + w + 1;
                }
            }
        }
        Family::NestedU => {
            // U number u: arms in columns 2u and cols-1-2u from row 0 down to
            // row rows-1-2u, joined by a bar on that row.
            for u in 0.. {
                let (l, r) = (2 * u, (cols - 1).checked_sub(2 * u));
                let (Some(r), Some(bottom)) = (r, (rows - 1).checked_sub(2 * u)) else {
                    break;
                };
                if l > r {
                    break;
                }
                for row in 0..=bottom {
                    m[row * cols + l] = true;
                    m[row * cols + r] = true;
                }
                for c in l..=r {
                    m[bottom * cols + c] = true;
                }
            }
        }
    }
    // Sprinkle dropouts into the shapes too.
    if !matches!(family, Family::Random) && density < 100 {
        for v in m.iter_mut() {
            if next() % 100 >= u64::from(density.max(70)) {
                *v = false;
            }
        }
    }
    m
}

/// Points on a grid `spacing` apart at 10 m range, with Q7.8 jitter.
fn frame(rows: usize, cols: usize, m: &[bool], spacing: f64, jitter: f64, rng: &mut u64) -> Frame {
    let mut next = || {
        *rng ^= *rng << 13;
        *rng ^= *rng >> 7;
        *rng ^= *rng << 17;
        (*rng % 2001) as f64 / 1000.0 - 1.0
    };
    let mut xyz = Vec::with_capacity(rows * cols * 3);
    for r in 0..rows {
        for c in 0..cols {
            if m[r * cols + c] {
                xyz.extend([
                    10.0 + jitter * next(),
                    c as f64 * spacing + jitter * next() - 60.0,
                    -(r as f64) * spacing + jitter * next() + 20.0,
                ]);
            } else {
                xyz.extend([f64::NAN; 3]);
            }
        }
    }
    Frame::from_xyz_f64(rows, cols, &xyz)
}

fn family() -> impl Strategy<Value = Family> {
    prop_oneof![
        3 => Just(Family::Random),
        1 => Just(Family::Spiral),
        1 => Just(Family::Comb),
        1 => Just(Family::Staircase),
        1 => Just(Family::NestedU),
    ]
}

/// One generated test case.
#[derive(Debug, Clone, Copy)]
struct Case {
    fsize: usize,
    fam: Family,
    rows: usize,
    cols: usize,
    density: u32,
    th_h: f64,
    th_v: f64,
    label_bits: u32,
    seed: u64,
}

fn check(case: Case) -> Result<(), TestCaseError> {
    let Case {
        fsize,
        fam,
        rows,
        cols,
        density,
        th_h,
        th_v,
        label_bits,
        seed,
    } = case;
    let mut rng = seed | 1;
    let m = mask(fam, rows, cols, density, &mut rng);
    let f = frame(rows, cols, &m, 0.25, 0.08, &mut rng);
    let p = FccParams {
        rows,
        cols,
        fsize,
        th_h,
        th_v,
        label_bits,
        ..FccParams::default()
    };
    let got = cluster(&p, &f, MergeMode::Exact).map_err(|e| TestCaseError::fail(e.to_string()))?;
    let want = reference_labels(&p, &f);
    if let Some(i) = (0..want.len()).find(|&i| got.labels[i] != want[i]) {
        return Err(TestCaseError::fail(format!(
            "seed {seed}: first mismatch at row {}, col {}: expected {} != got {}",
            i / cols,
            i % cols,
            want[i],
            got.labels[i]
        )));
    }
    // The published merge never joins what is not connected: it may only split.
    let paper =
        cluster(&p, &f, MergeMode::Paper).map_err(|e| TestCaseError::fail(e.to_string()))?;
    prop_assert_eq!(
        split_components(&paper.labels, &got.labels),
        0,
        "paper merged two components"
    );
    prop_assert!(paper.clusters >= got.clusters);
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 160, ..ProptestConfig::default() })]

    #[test]
    fn model_equals_reference(
        k in prop::sample::select(vec![3usize, 5, 7, 9, 11, 13, 15]),
        fam in family(),
        rows in 1usize..24,
        cols in 1usize..48,
        density in 5u32..=100,
        th_h in 0.05f64..0.6,
        th_v in 0.05f64..0.9,
        seed in any::<u64>(),
    ) {
        check(Case { fsize: k, fam, rows, cols, density, th_h, th_v, label_bits: 15, seed })?;
    }

    #[test]
    fn model_equals_reference_under_label_overflow(
        k in prop::sample::select(vec![3usize, 5, 7, 9, 11, 13, 15]),
        fam in family(),
        rows in 8usize..40,
        cols in 40usize..120,
        density in 30u32..=100,
        th_h in 0.05f64..0.3,
        th_v in 0.05f64..0.9,
        seed in any::<u64>(),
    ) {
        // 8-bit labels run out after 255 runs on most of these frames.
        check(Case { fsize: k, fam, rows, cols, density, th_h, th_v, label_bits: 8, seed })?;
    }
}

#[test]
fn every_fsize_on_every_family() {
    let fams = [
        Family::Random,
        Family::Spiral,
        Family::Comb,
        Family::Staircase,
        Family::NestedU,
    ];
    for k in [3usize, 5, 7, 9, 11, 13, 15] {
        for (n, &fam) in fams.iter().enumerate() {
            check(Case {
                fsize: k,
                fam,
                rows: 31,
                cols: 57,
                density: 85,
                th_h: 0.3,
                th_v: 0.6,
                label_bits: 15,
                seed: 1000 + n as u64,
            })
            .unwrap();
        }
    }
}

#[test]
fn overflow_is_reached_by_the_overflow_strategy() {
    // Guard the test above against silently never overflowing.
    let mut rng = 7u64;
    let m = mask(Family::Random, 30, 100, 60, &mut rng);
    let f = frame(30, 100, &m, 0.25, 0.08, &mut rng);
    let p = FccParams {
        rows: 30,
        cols: 100,
        fsize: 5,
        th_h: 0.1,
        th_v: 0.5,
        label_bits: 8,
        ..FccParams::default()
    };
    let got = cluster(&p, &f, MergeMode::Exact).unwrap();
    assert!(got.overflow && got.unlabelled > 0);
    assert_eq!(got.labels, reference_labels(&p, &f));
}

#[test]
fn long_chains_stay_one_component() {
    for fam in [Family::Spiral, Family::Comb, Family::NestedU] {
        let mut rng = 99u64;
        let m = mask(fam, 25, 41, 100, &mut rng);
        let f = frame(25, 41, &m, 0.25, 0.0, &mut rng);
        let p = FccParams {
            rows: 25,
            cols: 41,
            fsize: 3,
            th_h: 0.3,
            th_v: 0.3,
            ..FccParams::default()
        };
        let got = cluster(&p, &f, MergeMode::Exact).unwrap();
        assert_eq!(got.labels, reference_labels(&p, &f));
        // The spiral and the comb are one component each; the nested Us are
        // one per U: u = 0..=10 fit in 41 columns (2u <= 40 - 2u).
        let expect = if matches!(fam, Family::NestedU) {
            11
        } else {
            1
        };
        assert_eq!(got.clusters, expect, "{fam:?}");
        assert!(got.provisional > 10, "{fam:?} is not a chain of runs");
    }
}
