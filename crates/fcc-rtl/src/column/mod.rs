//! The column-streaming core's blocks (docs/column-core.md): the frame's
//! pixels in column order in, one record per cluster out as it closes.
//! Built so far, each with its own bench: the per-row run state of pass 1
//! (`FccRowRuns`, with the open limit in `FccOpenRoom`), the label pool
//! (`FccLabelPool`), the pass-2 window (`FccColWindow`) and its distance
//! tests (`FccColDist`), the record accumulator (`FccAccPixel`,
//! `FccAccMerge`), the record output (`FccRecordOut`), each row's current
//! run's accumulator (`FccRunAcc`, flushed to its cluster once the run is
//! over), and the front of the slot table, the representative rows
//! (`FccRepJoins`: a label of each run's cluster, the joins between labels
//! a union-find must make; see docs/column-core.md), and the union-find
//! over labels behind it (`FccLabelSets`: each root's record slot) with
//! its queue (`FccSetQueue`: the slot table's ops in pixel order through
//! it, out in order with their slots), and the record store
//! (`FccSlotRecords`: a record and the holds per slot, added to, merged,
//! and read out as clusters close), and the closer's
//! sorted entries (`FccCloseOrder`: a column's closes in the golden
//! order) and the closer around them (`FccCloser`: the quiet clusters'
//! wait list, passed over once a column is done), and the labels' lists
//! (`FccLabelLists`: a closed cluster's labels back to the pool); the
//! record slots are handed out by a 9-bit `FccLabelPool`, the
//! column-start check (`FccColStart`: when a column may start), and the
//! flushes' accumulators waiting for their finds (`FccFlushWait`); and the
//! front (`FccColFront`: thresholds, row runs, window and distance tests
//! wired, the part of the core a slot passes without a hold), its slot
//! buffer with credits (`FccColSlotBuf`), and the input half they make
//! with the input stage and the column-start check (`FccColIn`); the
//! datapath of all three halves (`FccColCore`) and the top around it with
//! the register file (`FccColTop`, `fcc gen --scan column`).

pub mod fcc_acc_merge;
pub mod fcc_acc_pixel;
pub mod fcc_acc_probe;
pub mod fcc_close_order;
pub mod fcc_closer;
pub mod fcc_closer_in;
pub mod fcc_closer_list;
pub mod fcc_closer_pass;
pub mod fcc_col_core;
pub mod fcc_col_dist;
pub mod fcc_col_dist_probe;
pub mod fcc_col_edge;
pub mod fcc_col_end;
pub mod fcc_col_flow;
pub mod fcc_col_front;
pub mod fcc_col_front_probe;
pub mod fcc_col_in;
pub mod fcc_col_in_probe;
pub mod fcc_col_limits;
pub mod fcc_col_limits_probe;
pub mod fcc_col_settle;
pub mod fcc_col_slot_buf;
pub mod fcc_col_slot_buf_probe;
pub mod fcc_col_start;
pub mod fcc_col_stats;
pub mod fcc_col_store;
pub mod fcc_col_table;
pub mod fcc_col_table_probe;
pub mod fcc_col_top;
pub mod fcc_col_window;
pub mod fcc_col_window_probe;
pub mod fcc_col_word_split;
pub mod fcc_flush_wait;
pub mod fcc_flush_wait_probe;
pub mod fcc_hits_pack;
pub mod fcc_hits_unpack;
pub mod fcc_holds_merge;
pub mod fcc_label_lists;
pub mod fcc_label_pool;
pub mod fcc_label_sets;
pub mod fcc_open_room;
pub mod fcc_quad_lane;
pub mod fcc_rec_beats;
pub mod fcc_record_out;
pub mod fcc_record_out_probe;
pub mod fcc_rep_ahead;
pub mod fcc_rep_eq;
pub mod fcc_rep_extract;
pub mod fcc_rep_first;
pub mod fcc_rep_front;
pub mod fcc_rep_gaps;
pub mod fcc_rep_joins;
pub mod fcc_rep_joins_probe;
pub mod fcc_rep_match;
pub mod fcc_rep_min;
pub mod fcc_rep_overlap;
pub mod fcc_rep_replay;
pub mod fcc_rep_row_feed;
pub mod fcc_rep_seen_ahead;
pub mod fcc_rep_shift;
pub mod fcc_rep_sieve;
pub mod fcc_rep_stage;
pub mod fcc_rep_take;
pub mod fcc_row_entry;
pub mod fcc_row_reps;
pub mod fcc_row_runs;
pub mod fcc_row_runs_probe;
pub mod fcc_run_acc;
pub mod fcc_run_acc_probe;
pub mod fcc_run_decide;
pub mod fcc_set_gate;
pub mod fcc_set_op;
pub mod fcc_set_order;
pub mod fcc_set_pack;
pub mod fcc_set_pick;
pub mod fcc_set_queue;
pub mod fcc_set_reads;
pub mod fcc_set_retire;
pub mod fcc_set_took;
pub mod fcc_set_walks;
pub mod fcc_slot_check;
pub mod fcc_slot_issue;
pub mod fcc_slot_pipe;
pub mod fcc_slot_records;
pub mod fcc_slot_records_probe;
pub mod fcc_slot_returns;
pub mod fcc_store_end;
pub mod fcc_store_ops;

use rust_hdl::prelude::*;

/// Bits of a label in the label tables (`FccLabelPool`, `FccLabelSets`,
/// `FccLabelLists`): `FccParams::label_bits`; labels travel in 16-bit
/// fields.
pub fn label_bits(p: &fcc_params::FccParams) -> usize {
    let b = p.label_bits as usize;
    assert!(b <= 16, "labels are 16 bits wide here");
    b
}

/// Bits of a run slot's age (or number) in a representative row (`h + 1`
/// slots, at most 6 at K = 11).
pub const REP_AGE_BITS: usize = 3;

/// One pixel slot of the frame in column order.
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct ColPix {
    /// A pixel position is present in this slot (not a bubble).
    pub valid: Bit,
    /// The pixel holds a point.
    pub ok: Bit,
    pub x: Bits<16>,
    pub y: Bits<16>,
    pub z: Bits<16>,
    pub row: Bits<7>,
    pub col: Bits<12>,
    /// The frame's first and last pixel.
    pub first: Bit,
    pub last: Bit,
}

/// One row's entry in the per-row table: its latest valid pixel (`l_*`)
/// and its first (`f_*`) of the frame so far, each with its column, point
/// (offset binary) and pass-1 thresholds (`key` and the `FccSqDist` addend
/// `ch`, from `FccPointThr`).
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct RowPts {
    pub l_has: Bit,
    pub l_col: Bits<12>,
    /// The last column the bridge reaches from the latest valid pixel,
    /// `l_col + reach` (at most 4095).
    pub l_dead: Bits<12>,
    pub l_x: Bits<16>,
    pub l_y: Bits<16>,
    pub l_z: Bits<16>,
    pub l_key: Bits<16>,
    pub l_ch: Bits<36>,
    pub f_has: Bit,
    pub f_col: Bits<12>,
    pub f_x: Bits<16>,
    pub f_y: Bits<16>,
    pub f_z: Bits<16>,
    pub f_key: Bits<16>,
    pub f_ch: Bits<36>,
}

/// One row's labels in the per-row table: its latest and first valid
/// pixels' (0: unlabelled), and the label the row holds open (spec §9.2,
/// holds 2 and 4; 0: none).
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct RowLabs {
    pub l_lab: Bits<16>,
    pub f_lab: Bits<16>,
    pub h_lab: Bits<16>,
}

/// A pixel on its way from the table read to the label decision, with
/// what the decision needs of its row (worked out when the entry is read).
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct RunCtl {
    pub valid: Bit,
    pub ok: Bit,
    pub x: Bits<16>,
    pub y: Bits<16>,
    pub z: Bits<16>,
    pub row: Bits<7>,
    pub col: Bits<12>,
    /// The column's first slot (row 0): the open limit's count restarts.
    pub col_first: Bit,
    pub first: Bit,
    pub last: Bit,
    /// The point's key and pass-2 addend `-T'_V` (`FccPointThr`).
    pub key: Bits<16>,
    pub cv: Bits<36>,
    /// The row's first valid pixel is this one.
    pub first_here: Bit,
    /// The row's labels before this pixel, 0 where it had none.
    pub l_lab: Bits<16>,
    pub f_lab: Bits<16>,
    pub h_lab: Bits<16>,
    /// Their comparisons, made here so that the decision compares nothing:
    /// `l_lab`, `f_lab`, `h_lab` not 0; `l_lab != h_lab`; `f_lab != l_lab`.
    pub l_nz: Bit,
    pub f_nz: Bit,
    pub h_nz: Bit,
    pub l_ne_h: Bit,
    pub f_ne_l: Bit,
    /// Hold 2 after this column: the row's latest valid pixel may be
    /// continued at the next column (not after the last column).
    pub bridge_h: Bit,
    /// The row's first and latest valid pixels after this one are both
    /// within the ring reach (hold 4; at the last column, the ring check).
    pub ring_geom: Bit,
    /// This column is within the ring reach of the last (hold 3 for the
    /// row's first pixel).
    pub first_reach: Bit,
    /// The frame's last column.
    pub last_col: Bit,
}

/// A pixel out of `FccRowRuns`: its point, its run's label and what its
/// row's state changed.
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct RunPix {
    pub valid: Bit,
    pub ok: Bit,
    /// A point with a label (it can join).
    pub lok: Bit,
    pub x: Bits<16>,
    pub y: Bits<16>,
    pub z: Bits<16>,
    pub row: Bits<7>,
    pub col: Bits<12>,
    pub first: Bit,
    pub last: Bit,
    pub last_col: Bit,
    /// The point's key and pass-2 addend `-T'_V` (`FccPointThr`).
    pub key: Bits<16>,
    pub cv: Bits<36>,
    /// The run's label, 0 for an empty or unlabelled pixel.
    pub label: Bits<16>,
    /// The pixel starts a run and took `label` from the free list.
    pub start: Bit,
    /// The pixel starts a run but no label was free (spec §7).
    pub refused: Bit,
    /// Hold 3: the row's first valid pixel, labelled, within the ring
    /// reach of the last column.
    pub ring_first: Bit,
    /// The ring check joins `ring_a` (the row's first run) and `ring_b`
    /// (its last), at the last column.
    pub ring: Bit,
    pub ring_a: Bits<16>,
    pub ring_b: Bits<16>,
    /// The row stops holding `hold_drop` and holds `hold_add` (0: none).
    /// At column 0 no row holds a label of the frame before (every cluster
    /// closes at the frame end).
    pub hold_drop: Bits<16>,
    pub hold_add: Bits<16>,
    /// At the last column: the row still holds its latest run by hold 4
    /// (its ring check pends), so that run's cluster is held to the frame
    /// end, not only to the last column (spec §9.2).
    pub ring_hold: Bit,
    /// A label of `hold_drop`'s cluster, for its flush's find: `hold_drop`
    /// out of `FccRowRuns`, its run's representative out of `FccRepJoins`
    /// (a shallower walk).
    pub hold_rep: Bits<16>,
}

/// A pixel's word in the column window: its point, its pass-2 key and
/// addend, and its run's label (whether it can join travels in a lane of
/// its own).
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct ColWord {
    pub x: Bits<16>,
    pub y: Bits<16>,
    pub z: Bits<16>,
    pub key: Bits<16>,
    pub cv: Bits<36>,
    pub label: Bits<16>,
}

/// A cluster's record being accumulated (spec §9.3), all unsigned: the
/// core's coordinates are offset binary (`a = x + 2^15`), so the sums are
/// of `a`, `|x|^2`, `|y|^2` and `a * b` (x, y offset binary), and the
/// record's signed sums follow when it is written (`sum_x = sa - n 2^15`,
/// `sum_xy = sab - 2^15 (sa + sb) + n 2^30`). Widths hold the largest
/// hardware frame (2^19 points). No pixel: [`AccWord::empty`]'s values
/// (every `min` at its largest, every `max` at 0).
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct AccWord {
    pub points: Bits<20>,
    pub min_col: Bits<12>,
    pub max_col: Bits<12>,
    /// The largest column below `C/2` and the smallest at or above it (a
    /// seam cluster's wrapped span), when it has one.
    pub lo_has: Bit,
    pub lo_max: Bits<12>,
    pub hi_has: Bit,
    pub hi_min: Bits<12>,
    pub first_row: Bits<7>,
    pub last_row: Bits<7>,
    pub min_x: Bits<16>,
    pub min_y: Bits<16>,
    pub min_z: Bits<16>,
    pub max_x: Bits<16>,
    pub max_y: Bits<16>,
    pub max_z: Bits<16>,
    pub r2_min: Bits<32>,
    pub r2_max: Bits<32>,
    pub sa: Bits<35>,
    pub sb: Bits<35>,
    pub sc: Bits<35>,
    pub sxx: Bits<50>,
    pub syy: Bits<50>,
    pub sab: Bits<51>,
    pub seam: Bit,
}

impl AccWord {
    /// The accumulator of no pixel: the identity of `FccAccMerge`.
    pub fn empty() -> AccWord {
        AccWord {
            min_col: 0xfff_u64.to_bits(),
            first_row: 0x7f_u64.to_bits(),
            min_x: 0xffff_u64.to_bits(),
            min_y: 0xffff_u64.to_bits(),
            min_z: 0xffff_u64.to_bits(),
            r2_min: 0xffff_ffff_u64.to_bits(),
            ..AccWord::default()
        }
    }
}

/// Bits of a first pixel in column order: its column (12 bits) above
/// its row (7), so that pixels compare in column order.
pub const FIRST_BITS: usize = 19;

/// A cluster's holds (spec §9.2) beside its record in the record store
/// (docs/column-core.md, item 4), merged as records are:
/// * `open`: its runs not yet flushed, added as a two's complement
///   number (+1 a run's start, -1 its flush; the sum on a merge);
/// * `ring`: a row's first run is in it (hold 3), ORed;
/// * `first`: its first pixel in column order, column in the high 12
///   bits and row in the low 7 (the record order of a column), the
///   smaller kept;
/// * `quiet`: the column of the last add or merge that left `open` at 0;
/// * `head`, `tail`: the first and last of its labels' list
///   (`FccLabelLists`; 0: none), the gone list after the kept one on a
///   merge.
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct SlotHolds {
    pub open: Bits<8>,
    pub ring: Bit,
    pub first: Bits<FIRST_BITS>,
    pub quiet: Bits<12>,
    pub head: Bits<16>,
    pub tail: Bits<16>,
}

impl SlotHolds {
    /// The holds of no run: the identity of their merge.
    pub fn empty() -> SlotHolds {
        SlotHolds {
            first: ((1_u64 << FIRST_BITS) - 1).to_bits(),
            ..SlotHolds::default()
        }
    }
}

/// A record slot's word: the record and the cluster's holds.
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct SlotWord {
    pub acc: AccWord,
    pub holds: SlotHolds,
}

impl SlotWord {
    /// An empty slot's word.
    pub fn empty() -> SlotWord {
        SlotWord {
            acc: AccWord::empty(),
            holds: SlotHolds::empty(),
        }
    }
}

/// The run parameters of `FccRowRuns` that encode the bridge limit and the
/// ring reach (spec §3) for a frame of `p.cols` columns, so that the
/// block's tests are plain comparisons:
/// * `reach`: `min(N_b + 1, 4095)`, 4095 when unlimited: a row's latest
///   valid pixel at column `l` continues to a pixel at `c` (at most `N_b`
///   empty pixels between) when `c <= min(l + reach, 4095)`;
/// * `ring_on`: `N_r >= 1` (or unlimited); with `m = min(N_r, C)`, a first
///   pixel reaches in columns `0 ..= ring_f_max = m - 1` and a last one in
///   `ring_l_min = C - m ..= C - 1` (unlimited: `C - 1` and 0).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RunLimits {
    pub reach: u16,
    pub ring_on: bool,
    pub ring_f_max: u16,
    pub ring_l_min: u16,
}

impl RunLimits {
    /// The limits of `p` (its columns at most 4096, as the hardware's).
    pub fn new(p: &fcc_params::FccParams) -> RunLimits {
        const MAX12: u32 = (1 << 12) - 1;
        let cols = p.cols as u32;
        let reach = p.bridge.map_or(MAX12, |n| n.saturating_add(1).min(MAX12)) as u16;
        match p.ring_reach.map_or(cols, |n| n.min(cols)) {
            0 => RunLimits {
                reach,
                ring_on: false,
                ring_f_max: 0,
                ring_l_min: 0,
            },
            m => RunLimits {
                reach,
                ring_on: true,
                ring_f_max: (m - 1) as u16,
                ring_l_min: (cols - m) as u16,
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::RunLimits;
    use fcc_params::FccParams;

    /// The encoded limits give spec §3's rules (`FccParams::bridges`,
    /// `ring_reaches`) at every gap and column pair of small frames.
    #[test]
    fn run_limits_are_the_spec_rules() {
        for cols in [1usize, 2, 5, 9] {
            for bridge in [None, Some(0), Some(1), Some(3), Some(5000)] {
                for ring_reach in [None, Some(0), Some(1), Some(2), Some(4), Some(9), Some(70)] {
                    let p = FccParams {
                        cols,
                        bridge,
                        ring_reach,
                        ..FccParams::default()
                    };
                    let l = RunLimits::new(&p);
                    for last in 0..cols {
                        for c in last + 1..cols {
                            let dead = (last + l.reach as usize).min(4095);
                            assert_eq!(c <= dead, p.bridges(c - last - 1), "{p:?} {last} {c}");
                        }
                    }
                    for f in 0..cols {
                        for last in f..cols {
                            let got = l.ring_on
                                && f <= l.ring_f_max as usize
                                && last >= l.ring_l_min as usize;
                            assert_eq!(got, p.ring_reaches(f, last), "{p:?} {f} {last}");
                        }
                    }
                }
            }
        }
        // The widest frame: reaches that saturate at the last column.
        for bridge in [
            None,
            Some(0),
            Some(4093),
            Some(4094),
            Some(4095),
            Some(9000),
        ] {
            let p = FccParams {
                cols: 4096,
                bridge,
                ..FccParams::default()
            };
            let l = RunLimits::new(&p);
            for (last, c) in [
                (0, 4095),
                (0, 4094),
                (1, 4095),
                (4094, 4095),
                (2000, 4095),
                (0, 1),
            ] {
                let dead = (last + l.reach as usize).min(4095);
                assert_eq!(c <= dead, p.bridges(c - last - 1), "{bridge:?} {last} {c}");
            }
        }
    }
}
