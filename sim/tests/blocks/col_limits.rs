//! The column top's run parameters in the datapath's form
//! (`fcc_col_limits`, behind its probe's registered inputs) against
//! `RunLimits` (spec §3's bridge and ring rules, checked on their own in
//! fcc-rtl) and the frame's size: seeded random register values over their
//! whole ranges, and the corners (no bridge, bridge 0, ring reach 0, a
//! reach of the whole frame or more, 128 rows, 4095 columns). A mismatch
//! prints the values, expected, got and the seed.

use fcc_params::{FccParams, Scan};
use fcc_rtl::{BenchBlock, RunLimits};
use fcc_sim::{c_struct, load_plain, PlainDut};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

c_struct! {
    /// Inputs of one cycle, named as the ports.
    pub struct LimIn {
        pub run_rows: u8,
        pub run_cols: u16,
        pub half_k: u8,
        pub bridge: u16,
        pub ring_reach: u16,
        pub open_limit: u16,
    }
}

c_struct! {
    /// Outputs during one cycle.
    pub struct LimOut {
        pub cols: u16,
        pub last_row: u8,
        pub last_col: u16,
        pub col_half: u16,
        pub h: u8,
        pub reach: u16,
        pub ring_on: u8,
        pub ring_f_max: u16,
        pub ring_l_min: u16,
        pub n_o: u16,
    }
}

/// What the block must give for rows `r`, columns `c`, K `k` and the
/// three register values.
fn expected(r: usize, c: usize, k: usize, bridge: u32, reach: u32, open: u32) -> LimOut {
    let p = FccParams {
        rows: r,
        cols: c,
        fsize: k,
        bridge: Some(bridge),
        ring_reach: Some(reach),
        scan: Scan::Column,
        ..Default::default()
    };
    let l = RunLimits::new(&p);
    LimOut {
        cols: c as u16,
        last_row: (r - 1) as u8,
        last_col: (c - 1) as u16,
        col_half: (c / 2) as u16,
        h: (k / 2) as u8,
        reach: l.reach,
        ring_on: u8::from(l.ring_on),
        ring_f_max: l.ring_f_max,
        ring_l_min: l.ring_l_min,
        n_o: open as u16,
    }
}

#[test]
fn the_limits_are_run_limits_and_the_frame_size() {
    let model = load_plain::<LimIn, LimOut>(BenchBlock::ColLimits, &FccParams::default())
        .expect("the limits' model");
    let mut d = PlainDut::new(model);
    let seed = 0x11a1_u64;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut cases: Vec<(usize, usize, usize, u32, u32, u32)> = vec![
        (16, 32, 3, 4095, 4095, 511),
        (128, 4095, 11, 0, 0, 1),
        (128, 4095, 11, 4094, 4095, 511),
        (19, 256, 11, 4093, 256, 12),
        (64, 2048, 7, 16, 2047, 100),
        (64, 2048, 7, 2, 2049, 100),
    ];
    for _ in 0..5000 {
        cases.push((
            rng.gen_range(16..=128),
            rng.gen_range(32..=4095),
            [3, 5, 7, 9, 11][rng.gen_range(0..5)],
            if rng.gen_bool(0.5) {
                rng.gen_range(0..=20)
            } else {
                rng.gen_range(0..=4095)
            },
            if rng.gen_bool(0.5) {
                rng.gen_range(0..=40)
            } else {
                rng.gen_range(0..=4095)
            },
            rng.gen_range(1..=511),
        ));
    }
    // Each case is given for two cycles. The probe's inputs are registered,
    // so the combinational outputs show a case one step after it is given
    // and the ring check's (registered) one step later: after a case's
    // first step the ring check's are still the case before's.
    let mut last: Option<(String, LimOut)> = None;
    for &(r, c, k, bridge, reach, open) in &cases {
        let input = LimIn {
            run_rows: r as u8,
            run_cols: c as u16,
            half_k: (k >> 1) as u8,
            bridge: bridge as u16,
            ring_reach: reach as u16,
            open_limit: open as u16,
        };
        let what = format!(
            "rows {r}, cols {c}, K {k}, RUN_BRIDGE {bridge}, RUN_RING_REACH {reach}, RUN_OPEN_LIMIT {open}"
        );
        let want = expected(r, c, k, bridge, reach, open);
        // First step: the case before, whole.
        let o = d.step(&input);
        if let Some((what, want)) = &last {
            assert_eq!(
                format!("{o:?}"),
                format!("{want:?}"),
                "{what}, seed {seed:#x}"
            );
        }
        // Second step: this case, the ring check's still the one before's.
        let o = d.step(&input);
        let mut mixed = want;
        if let Some((_, before)) = &last {
            (mixed.ring_on, mixed.ring_f_max, mixed.ring_l_min) =
                (before.ring_on, before.ring_f_max, before.ring_l_min);
            assert_eq!(
                format!("{o:?}"),
                format!("{mixed:?}"),
                "{what} (the ring check's a cycle late, the case before's), seed {seed:#x}"
            );
        }
        last = Some((what, want));
    }
    let (what, want) = last.expect("a case");
    let o = d.step(&LimIn::default());
    assert_eq!(
        format!("{o:?}"),
        format!("{want:?}"),
        "{what}, seed {seed:#x}"
    );
}
