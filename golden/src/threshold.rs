//! The join tests of pass 1 and pass 2 with range-adaptive thresholds
//! (spec §2): a pair joins within `max(t^2, min(T(p), T(q)))`, each point's
//! `T(p) = (S * rc2(p)) >> 8` from its coarse squared range `rc2` and the
//! squared slope `S = A^2 >> 8`.

use crate::frame::{dist2, Point};
use fcc_params::FccParams;

/// A coordinate's coarse magnitude in whole metres (spec §2):
/// `min((|c| + 128) >> 8, 127)`, rounded half up, at most 127.
#[inline]
pub fn coarse_metres(c: i16) -> u32 {
    ((u32::from(c.unsigned_abs()) + 128) >> 8).min(COARSE_MAX)
}

/// The largest coarse magnitude (metres).
pub const COARSE_MAX: u32 = 127;

/// A point's coarse squared range in square metres (spec §2): the sum of its
/// coordinates' squared coarse magnitudes, at most `3 * 127^2 = 48,387`.
#[inline]
pub fn coarse_range2(p: Point) -> u32 {
    p.iter().map(|&c| coarse_metres(c).pow(2)).sum()
}

/// A point's own squared threshold for a squared slope `S = A^2 >> 8`
/// (UQ0.24): `(S * rc2(p)) >> 8`, rounded down, in units of 1/65536 m^2
/// (`S < 2^24`, `rc2 < 2^16`: below 2^32).
#[inline]
pub fn point_threshold(slope_sq: u64, p: Point) -> i64 {
    ((slope_sq * u64::from(coarse_range2(p))) >> 8) as i64
}

/// Both join tests of one parameter set.
#[derive(Debug, Clone, Copy)]
pub struct Thresholds {
    h_sq: i64,
    v_sq: i64,
    h_slope_sq: u64,
    v_slope_sq: u64,
}

impl Thresholds {
    pub fn new(p: &FccParams) -> Thresholds {
        Thresholds {
            h_sq: p.th_h_sq(),
            v_sq: p.th_v_sq(),
            h_slope_sq: p.th_h_slope_sq(),
            v_slope_sq: p.th_v_slope_sq(),
        }
    }

    /// The inter-channel threshold of one point, `max(tV^2, its own)`: the
    /// squared threshold of a pair is the smaller of its two points'.
    #[inline]
    pub fn v_of(&self, p: Point) -> i64 {
        self.v_sq.max(point_threshold(self.v_slope_sq, p))
    }

    /// Whether the inter-channel threshold grows with range.
    #[inline]
    pub fn v_adaptive(&self) -> bool {
        self.v_slope_sq != 0
    }

    /// The fixed inter-channel squared threshold `tV^2`.
    #[inline]
    pub fn v_sq(&self) -> i64 {
        self.v_sq
    }

    /// Pass 1 and the ring check: `d2 <= max(tH^2, min(T_H(p), T_H(q)))`.
    #[inline]
    pub fn continues(&self, p: Point, q: Point) -> bool {
        let d = dist2(p, q);
        if self.h_slope_sq == 0 {
            return d <= self.h_sq;
        }
        let t = point_threshold(self.h_slope_sq, p).min(point_threshold(self.h_slope_sq, q));
        d <= self.h_sq.max(t)
    }

    /// Pass 2: `d2 < max(tV^2, min(T_V(p), T_V(q)))`.
    #[inline]
    pub fn joins(&self, p: Point, q: Point) -> bool {
        self.joins_with(p).joins(q)
    }
}

/// Pass 2's test for the pairs of one point `p` (the later pixel of a
/// stream's window pairs), its own threshold worked out once.
#[derive(Debug, Clone, Copy)]
pub struct JoinsWith {
    p: Point,
    th: Thresholds,
    /// `T_V(p)` floored at `tV^2` (`tV^2` alone for fixed thresholds).
    p_v: i64,
}

impl JoinsWith {
    /// Whether `p` and `q` join: [`Thresholds::joins`].
    #[inline]
    pub fn joins(&self, q: Point) -> bool {
        let d = dist2(self.p, q);
        if self.th.v_slope_sq == 0 {
            return d < self.p_v;
        }
        d < self.p_v.min(self.th.v_of(q))
    }
}

impl Thresholds {
    /// Pass 2's test for the pairs of `p`.
    #[inline]
    pub fn joins_with(&self, p: Point) -> JoinsWith {
        let p_v = if self.v_slope_sq == 0 {
            self.v_sq
        } else {
            self.v_of(p)
        };
        JoinsWith { p, th: *self, p_v }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    #[test]
    fn joins_with_is_spec_pass_2_for_fixed_and_adaptive_thresholds() {
        let seed = 0x853c_49e6_748f_ea9b;
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        for (slope, th_v) in [(0.0, 0.5), (0.02, 0.3), (0.2, 0.1), (0.9, 0.0)] {
            let params = FccParams {
                th_v_slope: slope,
                th_v,
                ..FccParams::default()
            };
            let th = Thresholds::new(&params);
            for case in 0..20_000 {
                // Near pairs (within a few thresholds) and far ones, anywhere
                // in the Q7.8 range.
                let p: Point = [0; 3].map(|_: i16| rng.gen());
                let spread = [64, 512, 65_536][case % 3];
                let q = p.map(|v| {
                    (i64::from(v) + rng.gen_range(-spread..spread)).clamp(-32_768, 32_767) as i16
                });
                // Spec §2 and §4: d2 < max(tV^2, min(T_V(p), T_V(q))).
                let t = |x: Point| point_threshold(params.th_v_slope_sq(), x);
                let spec = dist2(p, q) < params.th_v_sq().max(t(p).min(t(q)));
                assert_eq!(
                    th.joins_with(p).joins(q),
                    spec,
                    "slope {slope}, tV {th_v}: {p:?} {q:?}, seed {seed:#x}"
                );
            }
        }
    }
}
