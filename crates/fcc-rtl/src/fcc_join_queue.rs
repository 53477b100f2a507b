//! `FccJoinQueue`: the 2^JQ_BITS-entry join queue (block RAM) between the
//! serializer and the union engine. It absorbs the bursts of joins of dense
//! regions without holding the input, tells the serializer when it is
//! nearly full (`room`, registered, with a margin for its lateness) and
//! counts the joins of the frame.

use rust_hdl::prelude::*;

use crate::fcc_fanout_net::FccFanoutNet;
use crate::fcc_fifo::FccFifo;
use crate::types::{kb, JoinRec};

/// Join queue between the serializer and the union engine: 2^JQ_BITS joins.
pub const JQ_BITS: usize = 12;

/// Queue level from which the serializer is told there is no room: eight
/// places short of full, the margin for `room`'s lateness.
pub const JQ_HIGH_LEVEL: usize = (1 << JQ_BITS) - 8;

#[derive(LogicBlock)]
pub struct FccJoinQueue {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// Clear the join counter (start of a frame).
    pub clear: Signal<In, Bit>,
    // From the serializer.
    pub push: Signal<In, Bit>,
    pub din: Signal<In, JoinRec>,
    /// The queue can take a join this cycle.
    pub room: Signal<Out, Bit>,
    // To the union engine.
    pub jv: Signal<Out, Bit>,
    pub ja: Signal<Out, Bits<16>>,
    pub jb: Signal<Out, Bits<16>>,
    pub jsame: Signal<Out, Bit>,
    pub jtake: Signal<In, Bit>,
    /// The queue holds nothing (registered; one cycle late).
    pub empty: Signal<Out, Bit>,
    /// Joins pushed in this frame.
    pub joins: Signal<Out, Bits<24>>,
    /// `push` and `jtake` reach every block RAM's write enable and the
    /// counters' enables: their drivers are replicated by Vivado.
    push_net: FccFanoutNet<Bit>,
    take_net: FccFanoutNet<Bit>,
    queue: FccFifo<JoinRec, JQ_BITS, { JQ_BITS + 1 }>,
    nearly_full: DFF<Bit>,
    join_count: DFF<Bits<24>>,
    high_level: Constant<Bits<{ JQ_BITS + 1 }>>,
    zero_level: Constant<Bits<{ JQ_BITS + 1 }>>,
    one24: Constant<Bits<24>>,
    zero24: Constant<Bits<24>>,
}

impl Default for FccJoinQueue {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            clear: Default::default(),
            push: Default::default(),
            din: Default::default(),
            room: Default::default(),
            jv: Default::default(),
            ja: Default::default(),
            jb: Default::default(),
            jsame: Default::default(),
            jtake: Default::default(),
            empty: Default::default(),
            joins: Default::default(),
            push_net: Default::default(),
            take_net: Default::default(),
            queue: FccFifo::default(),
            nearly_full: Default::default(),
            join_count: Default::default(),
            high_level: kb(JQ_HIGH_LEVEL as u64),
            zero_level: kb(0),
            one24: kb(1),
            zero24: kb(0),
        }
    }
}

impl Logic for FccJoinQueue {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, nearly_full, join_count);
        self.queue.clk.next = self.clk.val();
        self.queue.rst.next = self.rst.val();
        self.push_net.x.next = self.push.val();
        self.take_net.x.next = self.jtake.val();
        self.queue.push.next = self.push_net.y.val();
        self.queue.din.next = self.din.val();
        self.queue.take.next = self.take_net.y.val();
        self.nearly_full.d.next = self.queue.level.val() >= self.high_level.val();
        self.room.next = !self.nearly_full.q.val();
        if self.push_net.y.val() {
            self.join_count.d.next = self.join_count.q.val() + self.one24.val();
        }
        // Cleared at the end of a read-back and by reset, so that a frame
        // abandoned by a reset does not count in the next frame's joins.
        if self.clear.val() | self.rst.val() {
            self.join_count.d.next = self.zero24.val();
        }
        self.jv.next = self.queue.valid.val();
        self.ja.next = self.queue.dout.val().a;
        self.jb.next = self.queue.dout.val().b;
        self.jsame.next = self.queue.dout.val().same;
        self.empty.next = self.queue.level.val() == self.zero_level.val();
        self.joins.next = self.join_count.q.val();
        if self.rst.val() {
            self.nearly_full.d.next = false;
        }
    }
}
