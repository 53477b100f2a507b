//! The ports of `FccRepJoinsProbe` (the representative rows behind scalar
//! ports) and a pixel's input to it, for the benches that drive it.

use fcc_params::FccParams;
use fcc_sim::c_struct;

use super::Pix;

c_struct! {
    /// Inputs of one cycle, named as the ports of `FccRepJoinsProbe`.
    pub struct RjIn {
        pub rst: u8,
        pub valid: u8,
        pub ok: u8,
        pub lok: u8,
        pub row: u8,
        pub col: u16,
        pub label: u16,
        pub start: u8,
        pub ring_first: u8,
        pub ring: u8,
        pub ring_a: u16,
        pub ring_b: u16,
        pub hold_drop: u16,
        pub hits: u64,
        pub lw0: u64,
        pub lw1: u64,
        pub lw2: u64,
        pub lw3: u64,
        pub lw4: u64,
        pub lw5: u64,
        pub lw6: u64,
        pub lw7: u64,
        pub lw8: u64,
        pub lw9: u64,
        pub lw10: u64,
        pub lw11: u64,
        pub lw12: u64,
        pub lw13: u64,
        pub last_row: u8,
    }
}

c_struct! {
    /// Outputs during one cycle.
    pub struct RjOut {
        pub ready: u8,
        pub o_valid: u8,
        pub o_lok: u8,
        pub o_row: u8,
        pub o_col: u16,
        pub o_label: u16,
        pub o_start: u8,
        pub o_ring_first: u8,
        pub o_hold_drop: u16,
        pub o_hold_rep: u16,
        pub j_valid: u8,
        pub j_more: u8,
        pub j_a: u16,
        pub j_b: u16,
        pub j_under: u8,
        pub j_seam: u8,
        pub miss: u8,
    }
}

/// Pixel `px`'s input, its runs named by `lab` (a run's label; 0 for none)
/// and its flush by its run's label (the block names the representative).
pub fn rep_in(p: &FccParams, px: &Pix, lab: impl Fn(u32) -> u16) -> RjIn {
    let mut i = RjIn {
        valid: 1,
        ok: px.ok as u8,
        lok: (px.run != 0) as u8,
        row: px.row as u8,
        col: px.col as u16,
        label: lab(px.run),
        start: px.start as u8,
        ring_first: px.ring_first as u8,
        last_row: (p.rows - 1) as u8,
        ..RjIn::default()
    };
    let mut words = [0u64; 14];
    for &(e, run) in &px.hits {
        i.hits |= 1 << e;
        words[e / 4] |= (lab(run) as u64) << (16 * (e % 4));
    }
    [
        i.lw0, i.lw1, i.lw2, i.lw3, i.lw4, i.lw5, i.lw6, i.lw7, i.lw8, i.lw9, i.lw10, i.lw11,
        i.lw12, i.lw13,
    ] = words;
    if let Some((was, _)) = px.hold {
        i.hold_drop = lab(was);
    }
    if let Some((a, b)) = px.ring {
        (i.ring, i.ring_a, i.ring_b) = (1, lab(a), lab(b));
    }
    i
}
