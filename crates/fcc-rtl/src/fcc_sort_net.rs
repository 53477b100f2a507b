//! `fcc_sort_net`: reduces the window positions that matched a centre to a
//! few joins, buffers them, and hands them to the union engine one at a time.
//!
//! Every upper pixel carries a *representative* (`rep`): a provisional label
//! already known to be in its component (its own label at worst; see
//! `fcc_window`). Two pixels with equal representatives are known to be
//! connected. Four sub-blocks, in flow order:
//!
//! * `FccSortFilter` (one centre per cycle, no stalls): drops the matches
//!   that add nothing, keeps the others, writes the centre's representative
//!   back to the window, and asks for a centre-buffer record when the centre
//!   has kept matches, a ring join or the frame's end.
//! * `FccCentreBuf`: 512 records in block RAM.
//! * `FccSerializer`: the head record's joins, one every other cycle, then the
//!   ring join; takes the record with its last join.
//! * `FccJoinQueue`: 4096 joins (block RAM) in front of the union engine,
//!   which absorb the bursts of joins of dense regions without holding the
//!   input; counts the frame's joins.
//!
//! Exactness: a dropped match (c, n) always has a justification made of joins
//! already queued (or themselves justified) at earlier positions or earlier
//! centres, so the connected components are unchanged. A kept match is sent
//! as the join (rc, rep(n)) with rc = the run's representative before this
//! centre (c for a new run): both ends are in the components of c and n,
//! which is what a join of c and n needs.
//!
//! Reset: `rst` is the reset one cycle ahead. The centre buffer, the
//! serializer and the join queue each have their own registered copy of it
//! (`FccKeepReg`); the filter, whose reset has the most loads, takes `rst`
//! itself and registers one copy per group of at most `MAX_FANOUT` loads.
//! Every sub-block is in reset in the cycle after `rst`.
//!
//! A record taken and a centre that needed no record return their input
//! credit (`take`, `drop`), which `fcc_top` counts to drive `s_axis_tready`.

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use crate::fcc_centre_buf::FccCentreBuf;
use crate::fcc_fanout_reg::MAX_FANOUT;
use crate::fcc_join_queue::FccJoinQueue;
use crate::fcc_keep_reg::FccKeepReg;
use crate::fcc_serializer::FccSerializer;
use crate::fcc_sort_filter::FccSortFilter;
use crate::types::{vec_of, Ctr};

pub use crate::fcc_centre_buf::CB_BITS;

#[derive(LogicBlock)]
pub struct FccSortNet {
    pub clk: Signal<In, Clock>,
    /// Reset, one cycle ahead of the sub-blocks' (see the module doc).
    pub rst: Signal<In, Bit>,
    /// Clear the join counter (start of a frame).
    pub clear: Signal<In, Bit>,
    // From the distance tree and the window (stage S0).
    pub centre: Signal<In, Ctr>,
    pub hit: Vec<Signal<In, Bit>>,
    pub rep: Vec<Signal<In, Bits<16>>>,
    // The centre pixel's representative, back to the window.
    pub rep_we: Signal<Out, Bit>,
    pub rep_waddr: Signal<Out, Bits<12>>,
    pub rep_wdata: Signal<Out, Bits<16>>,
    // Joins to the union engine.
    pub jv: Signal<Out, Bit>,
    pub ja: Signal<Out, Bits<16>>,
    pub jb: Signal<Out, Bits<16>>,
    /// `ja` equals the previous join's `ja` of this frame.
    pub jsame: Signal<Out, Bit>,
    pub jtake: Signal<In, Bit>,
    /// The join queue holds nothing (registered; one cycle late).
    pub jq_empty: Signal<Out, Bit>,
    /// The frame's last centre has left the serializer (its joins are out).
    pub last_done: Signal<Out, Bit>,
    /// Input credits returned: a slot that needed no record, a record taken.
    pub drop: Signal<Out, Bit>,
    pub take: Signal<Out, Bit>,
    /// Joins emitted in this frame.
    pub joins: Signal<Out, Bits<24>>,
    filter: FccSortFilter,
    centre_buf: FccCentreBuf,
    serializer: FccSerializer,
    join_queue: FccJoinQueue,
    centre_buf_rst: FccKeepReg<Bit>,
    serializer_rst: FccKeepReg<Bit>,
    join_queue_rst: FccKeepReg<Bit>,
    _n: usize,
}

impl FccSortNet {
    pub fn new(p: &FccParams) -> Self {
        let n = p.window_positions();
        Self {
            clk: Default::default(),
            rst: Default::default(),
            clear: Default::default(),
            centre: Default::default(),
            hit: vec_of(n),
            rep: vec_of(n),
            rep_we: Default::default(),
            rep_waddr: Default::default(),
            rep_wdata: Default::default(),
            jv: Default::default(),
            ja: Default::default(),
            jb: Default::default(),
            jsame: Default::default(),
            jtake: Default::default(),
            jq_empty: Default::default(),
            last_done: Default::default(),
            drop: Default::default(),
            take: Default::default(),
            joins: Default::default(),
            filter: FccSortFilter::new(p),
            centre_buf: FccCentreBuf::new(p),
            serializer: FccSerializer::new(p),
            join_queue: FccJoinQueue::default(),
            centre_buf_rst: FccKeepReg::with_max_fanout(MAX_FANOUT),
            serializer_rst: FccKeepReg::with_max_fanout(MAX_FANOUT),
            join_queue_rst: FccKeepReg::with_max_fanout(MAX_FANOUT),
            _n: n,
        }
    }
}

impl Logic for FccSortNet {
    #[hdl_gen]
    fn update(&mut self) {
        // Reset: one registered copy per sub-block (the filter makes its own).
        self.centre_buf_rst.clock.next = self.clk.val();
        self.serializer_rst.clock.next = self.clk.val();
        self.join_queue_rst.clock.next = self.clk.val();
        self.centre_buf_rst.d.next = self.rst.val();
        self.serializer_rst.d.next = self.rst.val();
        self.join_queue_rst.d.next = self.rst.val();
        self.filter.clk.next = self.clk.val();
        self.filter.rst.next = self.rst.val();
        self.centre_buf.clk.next = self.clk.val();
        self.centre_buf.rst.next = self.centre_buf_rst.q.val();
        self.serializer.clk.next = self.clk.val();
        self.serializer.rst.next = self.serializer_rst.q.val();
        self.join_queue.clk.next = self.clk.val();
        self.join_queue.rst.next = self.join_queue_rst.q.val();
        // Filter: the centre and its window in; the representative back out.
        self.filter.centre.next = self.centre.val();
        for e in 0..self._n {
            self.filter.hit[e].next = self.hit[e].val();
            self.filter.rep[e].next = self.rep[e].val();
        }
        self.rep_we.next = self.filter.rep_we.val();
        self.rep_waddr.next = self.filter.rep_waddr.val();
        self.rep_wdata.next = self.filter.rep_wdata.val();
        self.drop.next = self.filter.credit_drop.val();
        // Filter -> centre buffer -> serializer.
        self.centre_buf.push.next = self.filter.rec_push.val();
        self.centre_buf.rec.next = self.filter.rec.val();
        self.serializer.head_valid.next = self.centre_buf.head_valid.val();
        self.serializer.head.next = self.centre_buf.head.val();
        for e in 0..self._n {
            self.centre_buf.rep[e].next = self.filter.rec_rep[e].val();
            self.centre_buf.keep[e].next = self.filter.rec_keep[e].val();
            self.centre_buf.first[e].next = self.filter.rec_first[e].val();
            self.serializer.head_rep[e].next = self.centre_buf.head_rep[e].val();
            self.serializer.head_keep[e].next = self.centre_buf.head_keep[e].val();
            self.serializer.head_first[e].next = self.centre_buf.head_first[e].val();
        }
        self.centre_buf.take.next = self.serializer.take.val();
        self.take.next = self.serializer.take.val();
        self.last_done.next = self.serializer.last_done.val();
        // Serializer -> join queue -> union engine.
        self.join_queue.clear.next = self.clear.val();
        self.join_queue.push.next = self.serializer.join_push.val();
        self.join_queue.din.next = self.serializer.join_rec.val();
        self.serializer.join_room.next = self.join_queue.room.val();
        self.join_queue.jtake.next = self.jtake.val();
        self.jv.next = self.join_queue.jv.val();
        self.ja.next = self.join_queue.ja.val();
        self.jb.next = self.join_queue.jb.val();
        self.jsame.next = self.join_queue.jsame.val();
        self.jq_empty.next = self.join_queue.empty.val();
        self.joins.next = self.join_queue.joins.val();
    }
}
