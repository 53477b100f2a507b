//! `FccWordWindow`: one word per pixel in a K x h window over the h rows
//! above the centre, with its cascade of h line buffers: the shape of
//! `fcc_window`'s point window, for one word. The representative window
//! (`FccRepWindow`) and the threshold window (`FccThrWindow`, one lane for
//! the keys and one for the addends) are lanes of it; the point window keeps
//! its own, since its four fields share one line-buffer word.
//!
//! Timing, from the user's stage T0: `read_en` / `read_addr` read that
//! column of every buffer; the words arrive in T2, where the window shifts
//! by one column (entry e takes entry e+1 of its row, the last column of row
//! r takes buffer h-1-r's word) wherever `shift_en[e]` is set, and the
//! cascade is written: buffer j (j >= 1) takes the word of the window's
//! centre column in row h-j (the one that buffer j-1 held at that column),
//! buffer 0 takes `in_data`, each where its `cas_en[j]` / `cas_addr[j]`
//! say. The entries `ent[e]` (e = r*K + n, r = 0 the top row, n = 0 the
//! left column) show the window from T3 on. The user keeps the enables
//! (registered copies, shared by its lanes) so that lanes of one window
//! load their fan-out once.

use rust_hdl::prelude::*;

use crate::fcc_ram::FccRam;
use crate::types::vec_of;

#[derive(LogicBlock)]
pub struct FccWordWindow<T: Synth, const A: usize> {
    pub clk: Signal<In, Clock>,
    /// T0: read this column of every buffer.
    pub read_en: Signal<In, Bit>,
    pub read_addr: Signal<In, Bits<A>>,
    /// T2: buffer 0's word, and each buffer's write (buffer 0: `in_data`;
    /// buffer j: the cascade).
    pub in_data: Signal<In, T>,
    pub cas_en: Vec<Signal<In, Bit>>,
    pub cas_addr: Vec<Signal<In, Bits<A>>>,
    /// T2: entry e shifts.
    pub shift_en: Vec<Signal<In, Bit>>,
    /// T3: the window, row-major from the top row.
    pub ent: Vec<Signal<Out, T>>,
    lb: Vec<FccRam<T, A>>,
    win: Vec<DFF<T>>,
    view: Vec<Signal<Local, T>>,
    _k: usize,
    _h: usize,
}

impl<T: Synth, const A: usize> FccWordWindow<T, A> {
    /// The window of a K x h block of words over rows of `cols` pixels, its
    /// buffers storing the low `stored_bits` bits of each word
    /// (`FccRam::with_stored_bits`; the upper bits read back as zero).
    pub fn new(k: usize, h: usize, cols: usize, stored_bits: usize) -> Self {
        let n = k * h;
        Self {
            clk: Default::default(),
            read_en: Default::default(),
            read_addr: Default::default(),
            in_data: Default::default(),
            cas_en: vec_of(h),
            cas_addr: vec_of(h),
            shift_en: vec_of(n),
            ent: vec_of(n),
            lb: (0..h)
                .map(|_| FccRam::with_stored_bits(cols, stored_bits))
                .collect(),
            win: vec_of(n),
            view: vec_of(n),
            _k: k,
            _h: h,
        }
    }
}

impl<T: Synth, const A: usize> Logic for FccWordWindow<T, A> {
    #[hdl_gen]
    fn update(&mut self) {
        for j in 0..self._h {
            self.lb[j].clk.next = self.clk.val();
            self.lb[j].read_en.next = self.read_en.val();
            self.lb[j].read_addr.next = self.read_addr.val();
            self.lb[j].write_en.next = self.cas_en[j].val();
            self.lb[j].write_addr.next = self.cas_addr[j].val();
        }
        self.lb[0].write_data.next = self.in_data.val();
        for kk in self._k..(self._k + 1) {
            for hh in self._h..(self._h + 1) {
                for r in 0..self._h {
                    for n in 0..(self._k - 1) {
                        self.view[r * kk + n].next = self.win[r * kk + n + 1].q.val();
                    }
                    self.view[r * kk + kk - 1].next = self.lb[hh - 1 - r].read_data.val();
                }
                for j in 1..self._h {
                    self.lb[j].write_data.next = self.view[(hh - j) * kk + hh].val();
                }
            }
        }
        for e in 0..(self._k * self._h) {
            self.win[e].clock.next = self.clk.val();
            self.win[e].d.next = self.win[e].q.val();
            if self.shift_en[e].val() {
                self.win[e].d.next = self.view[e].val();
            }
            self.ent[e].next = self.win[e].q.val();
        }
    }
}
