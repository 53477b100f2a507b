//! The ports of `FccSetPack` (the union-find queue's packer), for the
//! benches that drive it.

use fcc_sim::c_struct;

use super::rep_io::RjOut;

c_struct! {
    /// Inputs of one cycle, named as the ports of `FccSetPack`.
    pub struct PkIn {
        pub rst: u8,
        pub p_valid: u8,
        pub p_row: u8,
        pub p_col: u16,
        pub p_start: u8,
        pub p_label: u16,
        pub p_ring_first: u8,
        pub p_hold_drop: u16,
        pub p_hold_rep: u16,
        pub j_valid: u8,
        pub j_a: u16,
        pub j_b: u16,
        pub j_under: u8,
        pub j_more: u8,
        pub last_row: u8,
    }
}

c_struct! {
    /// Outputs during one cycle.
    pub struct PkOut {
        pub q_valid: u8,
        pub q_find: u8,
        pub q_make: u8,
        pub q_join: u8,
        pub q_mark: u8,
        pub q_ring: u8,
        pub q_under: u8,
        pub q_f: u16,
        pub q_m: u16,
        pub q_ja: u16,
        pub q_jb: u16,
        pub q_col: u16,
        pub q_row: u8,
    }
}

/// The packer's input from the representative rows' outputs.
pub fn pack_in(o: &RjOut, last_row: u8) -> PkIn {
    PkIn {
        rst: 0,
        p_valid: o.o_valid,
        p_row: o.o_row,
        p_col: o.o_col,
        p_start: o.o_start,
        p_label: o.o_label,
        p_ring_first: o.o_ring_first,
        p_hold_drop: o.o_hold_drop,
        p_hold_rep: o.o_hold_rep,
        j_valid: o.j_valid,
        j_a: o.j_a,
        j_b: o.j_b,
        j_under: o.j_under,
        j_more: o.j_more,
        last_row,
    }
}
