//! Golden values in the form the core holds them, shared by the benches of
//! the column core's blocks: coordinates in offset binary, a point's key and
//! `FccSqDist` addends (spec §2), and a record accumulator as `AccWord`
//! keeps it (unsigned: offset-binary sums and `sum(a b)`).

use fcc_golden::{coarse_range2, point_threshold, Acc, Point};
use fcc_params::FccParams;

/// A Q7.8 coordinate in offset binary (its sign bit flipped).
pub fn offset_binary(v: i16) -> u16 {
    (v as u16) ^ 0x8000
}

/// The bits of a 36-bit `FccSqDist` addend.
const MASK36: u64 = (1 << 36) - 1;

/// A point's key `rc2` and addends `-(max(tH^2, T_H) + 1)` (pass 1, `<=`)
/// and `-max(tV^2, T_V)` (pass 2, `<`), 36-bit two's complement, as
/// `FccPointThr` gives them.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PointAddends {
    pub key: u16,
    pub ch: u64,
    pub cv: u64,
}

/// The run parameters `FccPointThr` (and `FccPixThr`) take: the squared
/// slopes `S = A^2 >> 8` and the fixed thresholds' addends `-(tH^2 + 1)`
/// and `-tV^2`, 36-bit two's complement.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ThrInputs {
    pub sh: u32,
    pub sv: u32,
    pub ch_t: u64,
    pub cv_t: u64,
}

/// The threshold inputs of `p`, as the register file gives them.
pub fn thr_inputs(p: &FccParams) -> ThrInputs {
    ThrInputs {
        sh: p.th_h_slope_sq() as u32,
        sv: p.th_v_slope_sq() as u32,
        ch_t: (-(p.th_h_sq() + 1)) as u64 & MASK36,
        cv_t: (-p.th_v_sq()) as u64 & MASK36,
    }
}

/// The key and addends of `q` under the thresholds of `p` (spec §2).
pub fn point_addends(p: &FccParams, q: Point) -> PointAddends {
    let th = p.th_h_sq().max(point_threshold(p.th_h_slope_sq(), q));
    let tv = p.th_v_sq().max(point_threshold(p.th_v_slope_sq(), q));
    PointAddends {
        key: coarse_range2(q) as u16,
        ch: (-(th + 1)) as u64 & MASK36,
        cv: (-tv) as u64 & MASK36,
    }
}

/// A golden accumulator as the core's `AccWord` holds it, field by field
/// (named as its fields). No pixel: `AccWord::empty`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CoreAcc {
    pub points: u64,
    pub min_col: u64,
    pub max_col: u64,
    pub lo_has: u64,
    pub lo_max: u64,
    pub hi_has: u64,
    pub hi_min: u64,
    pub first_row: u64,
    pub last_row: u64,
    pub min: [u64; 3],
    pub max: [u64; 3],
    pub r2_min: u64,
    pub r2_max: u64,
    pub sa: u64,
    pub sb: u64,
    pub sc: u64,
    pub sxx: u64,
    pub syy: u64,
    pub sab: u64,
    pub seam: u64,
}

impl CoreAcc {
    /// `a` in the core's form: `sa = sum_x + n 2^15` (likewise `sb`, `sc`),
    /// `sab = sum_xy + 2^15 (sum_x + sum_y) + n 2^30`, the box in offset
    /// binary; a seam span's missing half reads 0.
    pub fn of(a: &Acc) -> CoreAcc {
        if a.points == 0 {
            return CoreAcc {
                points: 0,
                min_col: 0xfff,
                max_col: 0,
                lo_has: 0,
                lo_max: 0,
                hi_has: 0,
                hi_min: 0,
                first_row: 0x7f,
                last_row: 0,
                min: [0xffff; 3],
                max: [0; 3],
                r2_min: 0xffff_ffff,
                r2_max: 0,
                sa: 0,
                sb: 0,
                sc: 0,
                sxx: 0,
                syy: 0,
                sab: 0,
                seam: 0,
            };
        }
        const K: i128 = 1 << 15;
        let n = i128::from(a.points);
        let off = |s: i64| (i128::from(s) + n * K) as u64;
        let sab =
            i128::from(a.sum_xy) + K * i128::from(a.sum[0]) + K * i128::from(a.sum[1]) + n * K * K;
        CoreAcc {
            points: u64::from(a.points),
            min_col: u64::from(a.min_col),
            max_col: u64::from(a.max_col),
            lo_has: a.lo_max.is_some() as u64,
            lo_max: a.lo_max.map_or(0, u64::from),
            hi_has: a.hi_min.is_some() as u64,
            hi_min: a.hi_min.map_or(0, u64::from),
            first_row: u64::from(a.first_row),
            last_row: u64::from(a.last_row),
            min: a.min.map(|v| u64::from(offset_binary(v))),
            max: a.max.map(|v| u64::from(offset_binary(v))),
            r2_min: a.range2_min,
            r2_max: a.range2_max,
            sa: off(a.sum[0]),
            sb: off(a.sum[1]),
            sc: off(a.sum[2]),
            sxx: a.sum_xx as u64,
            syy: a.sum_yy as u64,
            sab: sab as u64,
            seam: a.seam as u64,
        }
    }
}

/// The accumulator a bench block puts out as the scalar ports `o_points`,
/// `o_min_col`, ... `o_seam` (an `AccWord` field by field, as the column
/// core's probes name them), read from the outputs struct `$o`; a seam
/// span's half it does not have reads 0, as [`CoreAcc::of`] gives it.
#[macro_export]
macro_rules! core_acc_out {
    ($o:expr) => {{
        let o = &$o;
        let mut a = $crate::core_form::CoreAcc {
            points: o.o_points.into(),
            min_col: o.o_min_col.into(),
            max_col: o.o_max_col.into(),
            lo_has: o.o_lo_has.into(),
            lo_max: o.o_lo_max.into(),
            hi_has: o.o_hi_has.into(),
            hi_min: o.o_hi_min.into(),
            first_row: o.o_first_row.into(),
            last_row: o.o_last_row.into(),
            min: [o.o_min_x.into(), o.o_min_y.into(), o.o_min_z.into()],
            max: [o.o_max_x.into(), o.o_max_y.into(), o.o_max_z.into()],
            r2_min: o.o_r2_min.into(),
            r2_max: o.o_r2_max.into(),
            sa: o.o_sa,
            sb: o.o_sb,
            sc: o.o_sc,
            sxx: o.o_sxx,
            syy: o.o_syy,
            sab: o.o_sab,
            seam: o.o_seam.into(),
        };
        if a.lo_has == 0 {
            a.lo_max = 0;
        }
        if a.hi_has == 0 {
            a.hi_min = 0;
        }
        a
    }};
}
