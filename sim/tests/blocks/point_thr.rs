//! The per-point threshold unit `fcc_point_thr` alone under Verilator
//! against the golden model's definitions (spec §2): for every point, its
//! key `rc2` (`fcc_golden::coarse_range2`) and the `FccSqDist` addends
//! `-(max(tH^2, T_H) + 1)` and `-max(tV^2, T_V)`, with
//! `T = fcc_golden::point_threshold`. Directed corners (coordinate codes at
//! the metre rounding edges and the ends of the range, slopes 0 and the
//! largest, thresholds 1 and 128 m), then seeded random points under random
//! parameters, back to back (the unit has no state across points). A mismatch prints the point, the parameters, expected, got and
//! the seed.

use fcc_golden::{coarse_range2, point_threshold};
use fcc_params::FccParams;
use fcc_pixel::Point;
use fcc_sim::{load_point_thr, PointThrDut, PtIn, PtOut};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

const LATENCY: usize = 8;
const MASK36: u64 = (1 << 36) - 1;

/// One input: a point (signed Q7.8), squared slopes, fixed thresholds (Q7.8).
#[derive(Debug, Clone, Copy)]
struct Case {
    p: Point,
    sh: u64,
    sv: u64,
    th: i64,
    tv: i64,
}

fn neg36(v: i64) -> u64 {
    (-v) as u64 & MASK36
}

fn input(c: &Case) -> PtIn {
    let ob = |v: i16| (v as u16) ^ 0x8000;
    PtIn {
        ch_t: neg36(c.th * c.th + 1),
        cv_t: neg36(c.tv * c.tv),
        sh: c.sh as u32,
        sv: c.sv as u32,
        x: ob(c.p[0]),
        y: ob(c.p[1]),
        z: ob(c.p[2]),
        rst: 0,
    }
}

fn expected(c: &Case) -> (u16, u64, u64) {
    let key = coarse_range2(c.p);
    let th = (c.th * c.th).max(point_threshold(c.sh, c.p));
    let tv = (c.tv * c.tv).max(point_threshold(c.sv, c.p));
    (key as u16, neg36(th + 1), neg36(tv))
}

/// Feed `cases` back to back and compare each output `LATENCY` cycles
/// later. The parameters are run parameters (constant while a frame runs),
/// sampled by the unit's later stages: they change only between runs of
/// cases that share them, after the pipeline has drained.
fn run(d: &mut PointThrDut, cases: &[Case], seed: u64) {
    let same = |a: &Case, b: &Case| (a.sh, a.sv, a.th, a.tv) == (b.sh, b.sv, b.th, b.tv);
    let mut start = 0;
    while start < cases.len() {
        let mut end = start + 1;
        while end < cases.len() && same(&cases[start], &cases[end]) {
            end += 1;
        }
        let group = &cases[start..end];
        // Idle cycles carry the group's parameters.
        let idle = PtIn {
            x: 0x8000,
            y: 0x8000,
            z: 0x8000,
            ..input(&group[0])
        };
        for i in 0..group.len() + LATENCY {
            let out: PtOut = d.step(&group.get(i).map_or(idle, input));
            if i < LATENCY {
                continue;
            }
            let c = &group[i - LATENCY];
            let want = expected(c);
            let got = (out.key, out.ch, out.cv);
            assert_eq!(
                got,
                want,
                "point {} of {}: {c:?} (seed {seed}): expected (key, ch, cv) {want:x?}, got {got:x?}",
                start + i - LATENCY,
                cases.len()
            );
        }
        start = end;
    }
}

fn dut() -> PointThrDut {
    match load_point_thr(&FccParams::default()) {
        Ok(m) => PointThrDut::new(m),
        Err(e) => panic!("{e}"),
    }
}

/// The largest squared slope, `65535^2 >> 8`.
const S_MAX: u64 = (65535 * 65535) >> 8;

#[test]
fn corners_match_the_contract() {
    // Codes around every rounding edge of whole metres, and the range ends.
    let mut coords: Vec<i16> = vec![i16::MIN, i16::MIN + 1, i16::MAX, -1, 0, 1];
    for m in [0i32, 1, 2, 63, 126, 127] {
        for off in [127, 128, 129] {
            let v = m * 256 + off;
            coords.push(v as i16);
            coords.push((-v) as i16);
        }
    }
    let mut cases = Vec::new();
    for &(sh, sv) in &[
        (0, 0),
        (S_MAX, S_MAX),
        (1, S_MAX),
        (S_MAX, 0),
        (167_792, 6713),
    ] {
        for &(th, tv) in &[(1, 1), (0x8000, 0x8000), (128, 256)] {
            for &a in &coords {
                for &b in &[i16::MIN, 0, 5120, a] {
                    cases.push(Case {
                        p: [a, b, a],
                        sh,
                        sv,
                        th,
                        tv,
                    });
                }
            }
        }
    }
    run(&mut dut(), &cases, 0);
}

#[test]
fn seeded_random_points_match_the_contract() {
    let mut d = dut();
    for seed in 1..=4u64 {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut cases = Vec::new();
        for _ in 0..40 {
            let slope = |rng: &mut ChaCha8Rng| match rng.gen_range(0..4) {
                0 => 0,
                1 => S_MAX,
                _ => (rng.gen_range(0..=65535u64).pow(2)) >> 8,
            };
            let (sh, sv) = (slope(&mut rng), slope(&mut rng));
            let (th, tv) = (rng.gen_range(1..=0x8000), rng.gen_range(1..=0x8000));
            for _ in 0..500 {
                let p = [rng.gen(), rng.gen(), rng.gen()];
                cases.push(Case { p, sh, sv, th, tv });
            }
        }
        run(&mut d, &cases, seed);
    }
}
