//! The merge table alone (union engine, flatten, RAM-port multiplexer)
//! against the golden model's `ExactMerge`: the compact numbering of every
//! label and the component count must match, with the joins offered with
//! random gaps and the flatten throttled by random gearbox back-pressure.

use fcc_params::FccParams;
use fcc_sim::merge_bench::{first_mismatch, MergeFrame, Pressure};
use fcc_sim::{load_merge_table, MergeDut};
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};

/// Run `frames` one after another through one table (the flatten of each
/// frame makes the table ready for the next), and fail with the case, the
/// seed and the first differing label.
fn check(case: &str, seed: u64, pressure: Pressure, frames: &[MergeFrame]) {
    let p = FccParams::default();
    let model = load_merge_table(&p).unwrap_or_else(|e| panic!("{case}: {e}"));
    let mut dut = MergeDut::new(model, &p);
    let mut rng = StdRng::seed_from_u64(seed);
    if let Err(e) = dut.reset_and_init() {
        panic!("{case} (seed {seed}): {e}");
    }
    for (i, f) in frames.iter().enumerate() {
        let got = dut
            .run(f, pressure, &mut rng)
            .unwrap_or_else(|e| panic!("{case} frame {i} (seed {seed}): {e}"));
        if let Some(m) = first_mismatch(f, &got) {
            panic!(
                "{case} frame {i} (seed {seed}, P = {}, {} joins): {m}",
                f.provisional,
                f.joins.len()
            );
        }
    }
}

fn last_label() -> u32 {
    (1u32 << FccParams::default().label_bits) - 1
}

/// Random joins as the sort network sends them: runs of joins that share
/// the centre label `a`, the other label anywhere below or above it.
fn random_frame(rng: &mut StdRng, provisional: u32, joins: usize) -> MergeFrame {
    let mut out = Vec::with_capacity(joins);
    while out.len() < joins {
        let a = rng.gen_range(1..=provisional);
        for _ in 0..rng.gen_range(1..=4) {
            let near = a.saturating_sub(rng.gen_range(0..64)).max(1);
            let b = if rng.gen_bool(0.8) {
                near
            } else {
                rng.gen_range(1..=provisional)
            };
            out.push((a, b));
        }
    }
    out.truncate(joins);
    MergeFrame {
        provisional,
        joins: out,
    }
}

#[test]
fn random_joins_with_back_pressure_on_both_sides() {
    for seed in 0..4u64 {
        let mut rng = StdRng::seed_from_u64(seed);
        let frames: Vec<MergeFrame> = (0..3)
            .map(|_| {
                let p = rng.gen_range(1..=3000);
                let j = rng.gen_range(0..=2 * p as usize);
                random_frame(&mut rng, p, j)
            })
            .collect();
        check("random joins", seed, Pressure::RANDOM, &frames);
    }
}

#[test]
fn random_joins_without_gaps() {
    let mut rng = StdRng::seed_from_u64(7);
    let frames: Vec<MergeFrame> = (0..3).map(|_| random_frame(&mut rng, 2000, 3000)).collect();
    check("random joins, no gaps", 7, Pressure::NONE, &frames);
}

#[test]
fn long_chain_in_reverse_label_order_then_a_walk_from_its_end() {
    // (P-1, P), (P-2, P-1), ...: every link lengthens one chain, so the
    // last join walks from P down through every label.
    let p = 1500;
    let mut joins: Vec<(u32, u32)> = (1..p).rev().map(|a| (a, a + 1)).collect();
    joins.push((p, 1));
    joins.push((p - 1, p));
    let frame = MergeFrame {
        provisional: p,
        joins,
    };
    check("long chain", 11, Pressure::RANDOM, &[frame.clone(), frame]);
}

#[test]
fn chain_in_ascending_label_order() {
    let p = 1500;
    let frame = MergeFrame {
        provisional: p,
        joins: (1..p).map(|a| (a + 1, a)).collect(),
    };
    check("ascending chain", 12, Pressure::RANDOM, &[frame]);
}

#[test]
fn everything_into_one_component() {
    let mut rng = StdRng::seed_from_u64(13);
    let p = 2500u32;
    // A random spanning tree: each label joins one label before it.
    let mut joins: Vec<(u32, u32)> = (2..=p).map(|l| (l, rng.gen_range(1..l))).collect();
    // Then random repeats, which must change nothing.
    for _ in 0..500 {
        joins.push((rng.gen_range(1..=p), rng.gen_range(1..=p)));
    }
    let frame = MergeFrame {
        provisional: p,
        joins,
    };
    assert_eq!(frame.expected().1, 1);
    check("one component", 13, Pressure::RANDOM, &[frame]);
}

#[test]
fn joins_in_reverse_label_order() {
    let mut rng = StdRng::seed_from_u64(14);
    let mut f = random_frame(&mut rng, 2000, 2500);
    f.joins.sort_by(|x, y| y.cmp(x));
    let mut g = random_frame(&mut rng, 2000, 2500);
    g.joins.iter_mut().for_each(|j| *j = (j.1, j.0));
    check("reverse label order", 14, Pressure::RANDOM, &[f, g]);
}

#[test]
fn last_label_every_label_used_label_overflow() {
    // The provisional counter stops at the last label when labels overflow:
    // the whole table is in use and the last label takes part in joins.
    let p = last_label();
    let mut rng = StdRng::seed_from_u64(15);
    let mut f = random_frame(&mut rng, p, 4000);
    f.joins.push((p, 1));
    f.joins.push((p, p - 1));
    f.joins.push((p - 2, p));
    check("last label", 15, Pressure::RANDOM, &[f]);
}

#[test]
fn empty_frames_single_label_and_no_joins() {
    let frames = [
        MergeFrame::default(),
        MergeFrame {
            provisional: 1,
            joins: vec![],
        },
        MergeFrame {
            provisional: 1,
            joins: vec![(1, 1)],
        },
        MergeFrame {
            provisional: 300,
            joins: vec![],
        },
        MergeFrame::default(),
    ];
    check("empty and single", 16, Pressure::RANDOM, &frames);
}

#[test]
fn a_bench_mismatch_names_the_label() {
    let f = MergeFrame {
        provisional: 3,
        joins: vec![(3, 1)],
    };
    let got = fcc_sim::merge_bench::MergeResult {
        labels: vec![1, 2, 2],
        clusters: 2,
        union_cycles: 0,
        flatten_cycles: 0,
    };
    let m = first_mismatch(&f, &got).expect("a mismatch");
    assert!(
        m.contains("label 3: expected compact label 1, got 2"),
        "{m}"
    );
}
