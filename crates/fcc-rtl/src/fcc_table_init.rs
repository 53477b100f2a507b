//! `fcc_table_init`: after every reset, makes every word of the merge table
//! a root, one word per cycle, while `active` (the table's Init mode).

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use crate::types::kb;

#[derive(LogicBlock)]
pub struct FccTableInit {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// The table is in Init mode.
    pub active: Signal<In, Bit>,
    /// The word written this cycle (written whenever `active`).
    pub write_addr: Signal<Out, Bits<16>>,
    /// The last word is written this cycle.
    pub done: Signal<Out, Bit>,
    word: DFF<Bits<17>>,
    zero: Constant<Bits<17>>,
    one: Constant<Bits<17>>,
    last_word: Constant<Bits<17>>,
}

impl FccTableInit {
    pub fn new(p: &FccParams) -> Self {
        let words = 1u64 << p.label_bits;
        Self {
            clk: Default::default(),
            rst: Default::default(),
            active: Default::default(),
            write_addr: Default::default(),
            done: Default::default(),
            word: Default::default(),
            zero: kb(0),
            one: kb(1),
            last_word: kb(words - 1),
        }
    }
}

impl Logic for FccTableInit {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, word);
        self.write_addr.next = self.word.q.val().get_bits::<16>(0);
        self.done.next = false;
        if self.active.val() {
            self.word.d.next = self.word.q.val() + self.one.val();
            self.done.next = self.word.q.val() == self.last_word.val();
        }
        if self.rst.val() {
            self.word.d.next = self.zero.val();
        }
    }
}
