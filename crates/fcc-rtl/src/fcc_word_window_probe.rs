//! `FccWordWindowProbe`: a 16-bit `FccWordWindow` of the build's K over its
//! columns behind scalar ports, for the word window's own bench. Buffer 0's
//! write has its own enable and address; the cascade's buffers (1 .. h-1)
//! share one, and every entry shifts with `shift`. The entry chosen by
//! `ent_sel` comes out combinationally (zero past the last entry).

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use crate::fcc_word_window::FccWordWindow;
use crate::types::kb;

#[derive(LogicBlock)]
pub struct FccWordWindowProbe {
    pub clk: Signal<In, Clock>,
    pub read_en: Signal<In, Bit>,
    pub read_addr: Signal<In, Bits<12>>,
    pub in_data: Signal<In, Bits<16>>,
    pub wr0_en: Signal<In, Bit>,
    pub wr0_addr: Signal<In, Bits<12>>,
    pub cas_en: Signal<In, Bit>,
    pub cas_addr: Signal<In, Bits<12>>,
    pub shift: Signal<In, Bit>,
    pub ent_sel: Signal<In, Bits<8>>,
    pub ent: Signal<Out, Bits<16>>,
    window: FccWordWindow<Bits<16>, 12>,
    entry_index: Vec<Constant<Bits<8>>>,
    zero16: Constant<Bits<16>>,
    _h: usize,
}

impl FccWordWindowProbe {
    pub fn new(p: &FccParams) -> Self {
        let n = p.window_positions();
        assert!(n <= 256, "{n} window entries do not fit ent_sel");
        Self {
            clk: Default::default(),
            read_en: Default::default(),
            read_addr: Default::default(),
            in_data: Default::default(),
            wr0_en: Default::default(),
            wr0_addr: Default::default(),
            cas_en: Default::default(),
            cas_addr: Default::default(),
            shift: Default::default(),
            ent_sel: Default::default(),
            ent: Default::default(),
            window: FccWordWindow::new(p.fsize, p.half(), p.cols, 16),
            entry_index: (0..n).map(|e| kb(e as u64)).collect(),
            zero16: kb(0),
            _h: p.half(),
        }
    }
}

impl Logic for FccWordWindowProbe {
    #[hdl_gen]
    fn update(&mut self) {
        self.window.clk.next = self.clk.val();
        self.window.read_en.next = self.read_en.val();
        self.window.read_addr.next = self.read_addr.val();
        self.window.in_data.next = self.in_data.val();
        self.window.cas_en[0].next = self.wr0_en.val();
        self.window.cas_addr[0].next = self.wr0_addr.val();
        for j in 1..self._h {
            self.window.cas_en[j].next = self.cas_en.val();
            self.window.cas_addr[j].next = self.cas_addr.val();
        }
        self.ent.next = self.zero16.val();
        for e in 0..self.entry_index.len() {
            self.window.shift_en[e].next = self.shift.val();
            if self.ent_sel.val() == self.entry_index[e].val() {
                self.ent.next = self.window.ent[e].val();
            }
        }
    }
}
