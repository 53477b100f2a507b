//! `FccFlushWaitProbe`: `FccFlushWait`, built for the run accumulators'
//! flush latency, behind scalar ports for its own bench. A pushed
//! accumulator is a 51-bit tag in every field (its low bits in the
//! narrower ones); out come the head's tag (`o_tag`, its `sab`) and
//! whether every other field holds the tag's low bits (`o_agree`), so a
//! field stored or read wrongly shows. `take` takes the head if one shows
//! (as the record store's side will: `took` says it did); `take_none`
//! takes regardless, for the bench's misuse case.

use rust_hdl::prelude::*;

use super::fcc_flush_wait::FccFlushWait;
use super::fcc_run_acc::RUN_ACC_LATENCY;
use super::AccWord;

#[derive(LogicBlock)]
pub struct FccFlushWaitProbe {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub push: Signal<In, Bit>,
    pub tag: Signal<In, Bits<51>>,
    pub take: Signal<In, Bit>,
    pub take_none: Signal<In, Bit>,
    pub took: Signal<Out, Bit>,
    pub valid: Signal<Out, Bit>,
    pub o_tag: Signal<Out, Bits<51>>,
    pub o_agree: Signal<Out, Bit>,
    pub room: Signal<Out, Bit>,
    pub idle: Signal<Out, Bit>,
    pub bad: Signal<Out, Bit>,
    flushes: FccFlushWait,
    word: Signal<Local, AccWord>,
    /// The head, and its tag (a field of a field is not sliced again).
    head: Signal<Local, AccWord>,
    head_tag: Signal<Local, Bits<51>>,
}

impl Default for FccFlushWaitProbe {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            push: Default::default(),
            tag: Default::default(),
            take: Default::default(),
            take_none: Default::default(),
            took: Default::default(),
            valid: Default::default(),
            o_tag: Default::default(),
            o_agree: Default::default(),
            room: Default::default(),
            idle: Default::default(),
            bad: Default::default(),
            flushes: FccFlushWait::new(RUN_ACC_LATENCY),
            word: Default::default(),
            head: Default::default(),
            head_tag: Default::default(),
        }
    }
}

impl Logic for FccFlushWaitProbe {
    #[hdl_gen]
    fn update(&mut self) {
        self.word.next.points = self.tag.val().get_bits::<20>(0);
        self.word.next.min_col = self.tag.val().get_bits::<12>(0);
        self.word.next.max_col = self.tag.val().get_bits::<12>(0);
        self.word.next.lo_has = self.tag.val().get_bit(0);
        self.word.next.lo_max = self.tag.val().get_bits::<12>(0);
        self.word.next.hi_has = self.tag.val().get_bit(0);
        self.word.next.hi_min = self.tag.val().get_bits::<12>(0);
        self.word.next.first_row = self.tag.val().get_bits::<7>(0);
        self.word.next.last_row = self.tag.val().get_bits::<7>(0);
        self.word.next.min_x = self.tag.val().get_bits::<16>(0);
        self.word.next.min_y = self.tag.val().get_bits::<16>(0);
        self.word.next.min_z = self.tag.val().get_bits::<16>(0);
        self.word.next.max_x = self.tag.val().get_bits::<16>(0);
        self.word.next.max_y = self.tag.val().get_bits::<16>(0);
        self.word.next.max_z = self.tag.val().get_bits::<16>(0);
        self.word.next.r2_min = self.tag.val().get_bits::<32>(0);
        self.word.next.r2_max = self.tag.val().get_bits::<32>(0);
        self.word.next.sa = self.tag.val().get_bits::<35>(0);
        self.word.next.sb = self.tag.val().get_bits::<35>(0);
        self.word.next.sc = self.tag.val().get_bits::<35>(0);
        self.word.next.sxx = self.tag.val().get_bits::<50>(0);
        self.word.next.syy = self.tag.val().get_bits::<50>(0);
        self.word.next.sab = self.tag.val();
        self.word.next.seam = self.tag.val().get_bit(0);
        self.flushes.clk.next = self.clk.val();
        self.flushes.rst.next = self.rst.val();
        self.flushes.push.next = self.push.val();
        self.flushes.din.next = self.word.val();
        self.flushes.take.next =
            (self.take.val() & self.flushes.valid.val()) | self.take_none.val();
        self.took.next = self.take.val() & self.flushes.valid.val();
        self.valid.next = self.flushes.valid.val();
        self.head.next = self.flushes.dout.val();
        self.head_tag.next = self.head.val().sab;
        self.o_tag.next = self.head_tag.val();
        self.o_agree.next = (self.head.val().points == self.head_tag.val().get_bits::<20>(0))
            & (self.head.val().min_col == self.head_tag.val().get_bits::<12>(0))
            & (self.head.val().max_col == self.head_tag.val().get_bits::<12>(0))
            & (self.head.val().lo_has == self.head_tag.val().get_bit(0))
            & (self.head.val().lo_max == self.head_tag.val().get_bits::<12>(0))
            & (self.head.val().hi_has == self.head_tag.val().get_bit(0))
            & (self.head.val().hi_min == self.head_tag.val().get_bits::<12>(0))
            & (self.head.val().first_row == self.head_tag.val().get_bits::<7>(0))
            & (self.head.val().last_row == self.head_tag.val().get_bits::<7>(0))
            & (self.head.val().min_x == self.head_tag.val().get_bits::<16>(0))
            & (self.head.val().min_y == self.head_tag.val().get_bits::<16>(0))
            & (self.head.val().min_z == self.head_tag.val().get_bits::<16>(0))
            & (self.head.val().max_x == self.head_tag.val().get_bits::<16>(0))
            & (self.head.val().max_y == self.head_tag.val().get_bits::<16>(0))
            & (self.head.val().max_z == self.head_tag.val().get_bits::<16>(0))
            & (self.head.val().r2_min == self.head_tag.val().get_bits::<32>(0))
            & (self.head.val().r2_max == self.head_tag.val().get_bits::<32>(0))
            & (self.head.val().sa == self.head_tag.val().get_bits::<35>(0))
            & (self.head.val().sb == self.head_tag.val().get_bits::<35>(0))
            & (self.head.val().sc == self.head_tag.val().get_bits::<35>(0))
            & (self.head.val().sxx == self.head_tag.val().get_bits::<50>(0))
            & (self.head.val().syy == self.head_tag.val().get_bits::<50>(0))
            & (self.head.val().seam == self.head_tag.val().get_bit(0));
        self.room.next = self.flushes.room.val();
        self.idle.next = self.flushes.idle.val();
        self.bad.next = self.flushes.bad.val();
    }
}
