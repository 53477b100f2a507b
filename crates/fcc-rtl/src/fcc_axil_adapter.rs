//! `FccAxilAdapter`: the register file's AXI4-Lite bus adapter. It turns the
//! bus traffic into one write-enable per writable register (`we`), the held
//! write data (`wdata`) and the read's word address (`raddr`), and gives the
//! responses; the registers themselves are field blocks of their access type
//! (`FccRegs` wires them).
//!
//! Write channel: the address (AW) and the data (W) are each taken into a
//! holding register whenever it is empty (`awready = !aw_v`, `wready =
//! !w_v`), in either order. The held address is decoded as AW is taken, one
//! flag per writable register (`aw_sel`, from the list given to `new`), so no
//! address comparator lies in the write's cycle. The write is performed in
//! the cycle after both are held, no response is pending and `hold` is low:
//! `wr` is high for one cycle and `we[i]` for the addressed register. Its
//! response (always OKAY) is held on B until `bready`; a write that raises
//! `defer` in its cycle is answered when `done` rises instead. `w_take` is
//! the W handshake: blocks that register a check of the bus data
//! (`s_axil_wdata`) do it then, so that nothing follows the held data.
//!
//! Read channel (one read outstanding): `arready` is high while no read is
//! held (`ar_pend_q` clear, `rvalid` low) and `read_block` is low; the word
//! address is registered at the AR handshake (`ar_word_q` and its copy
//! `ar_word_hi_q`, so that the `araddr` port drives two flip-flops per bit
//! rather than the read multiplexer), the addressed word (`read_data`) is
//! registered into `rdata` with `rvalid` in the next cycle (two cycles from
//! the handshake to `rvalid`) and held until `rready`. Every output comes
//! from a flip-flop or one gate after flip-flops.

use rust_hdl::prelude::*;

use crate::fcc_fanout_reg::{FccFanoutReg, MAX_FANOUT};
use crate::fcc_keep_reg::FccKeepReg;
use crate::fcc_reg_mux::WORD_BITS;
use crate::regmap::ADDR_BITS;
use crate::types::kb;

#[derive(LogicBlock)]
pub struct FccAxilAdapter {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    // AXI4-Lite slave (write strobes are ignored: the register file's port).
    pub s_axil_awaddr: Signal<In, Bits<ADDR_BITS>>,
    pub s_axil_awvalid: Signal<In, Bit>,
    pub s_axil_awready: Signal<Out, Bit>,
    pub s_axil_wdata: Signal<In, Bits<32>>,
    pub s_axil_wvalid: Signal<In, Bit>,
    pub s_axil_wready: Signal<Out, Bit>,
    pub s_axil_bresp: Signal<Out, Bits<2>>,
    pub s_axil_bvalid: Signal<Out, Bit>,
    pub s_axil_bready: Signal<In, Bit>,
    pub s_axil_araddr: Signal<In, Bits<ADDR_BITS>>,
    pub s_axil_arvalid: Signal<In, Bit>,
    pub s_axil_arready: Signal<Out, Bit>,
    pub s_axil_rdata: Signal<Out, Bits<32>>,
    pub s_axil_rresp: Signal<Out, Bits<2>>,
    pub s_axil_rvalid: Signal<Out, Bit>,
    pub s_axil_rready: Signal<In, Bit>,
    // Writes, to the field blocks.
    /// No write is performed while high.
    pub hold: Signal<In, Bit>,
    /// The write performed in this cycle is answered on `done`.
    pub defer: Signal<In, Bit>,
    /// The deferred write's response is due.
    pub done: Signal<In, Bit>,
    /// W is taken in this cycle (`s_axil_wdata` becomes `wdata`).
    pub w_take: Signal<Out, Bit>,
    /// A write is performed in this cycle.
    pub wr: Signal<Out, Bit>,
    /// The write is performed to writable register `i`.
    pub we: Vec<Signal<Out, Bit>>,
    /// The held write data.
    pub wdata: Signal<Out, Bits<32>>,
    // Reads, from the read multiplexer.
    /// No read is taken while high.
    pub read_block: Signal<In, Bit>,
    /// The word `raddr` selects (bits 15:0) and `raddr_hi` (bits 31:16).
    pub read_data: Signal<In, Bits<32>>,
    pub raddr: Signal<Out, Bits<WORD_BITS>>,
    pub raddr_hi: Signal<Out, Bits<WORD_BITS>>,
    aw_v: DFF<Bit>,
    aw_sel: Vec<DFF<Bit>>,
    w_v: DFF<Bit>,
    w_d: DFF<Bits<32>>,
    b_v: DFF<Bit>,
    /// The word address of the read taken at the AR handshake, and the
    /// read waiting for its data (set in the cycle after the handshake).
    /// `ar_word_q` selects the read word's bits 15:0, its copy
    /// `ar_word_hi_q` bits 31:16 (under 64 loads a bit each; both kept, or
    /// synthesis would merge them).
    ar_word_q: FccKeepReg<Bits<WORD_BITS>>,
    ar_word_hi_q: FccKeepReg<Bits<WORD_BITS>>,
    ar_pend_q: FccFanoutReg<Bit>,
    r_v: DFF<Bit>,
    r_d: DFF<Bits<32>>,
    aw_word: Signal<Local, Bits<WORD_BITS>>,
    w_taken: Signal<Local, Bit>,
    perform: Signal<Local, Bit>,
    ar_take: Signal<Local, Bit>,
    words: Vec<Constant<Bits<WORD_BITS>>>,
    okay: Constant<Bits<2>>,
    _n: usize,
}

impl FccAxilAdapter {
    /// `offsets`: the byte offsets of the writable registers, in the order
    /// of `we`.
    pub fn new(offsets: &[u32]) -> Self {
        assert!(!offsets.is_empty(), "no writable register");
        for (i, a) in offsets.iter().enumerate() {
            assert!(a % 4 == 0 && *a < 1 << ADDR_BITS, "offset {a:#x}");
            assert!(!offsets[..i].contains(a), "offset {a:#x} twice");
        }
        let n = offsets.len();
        Self {
            clk: Default::default(),
            rst: Default::default(),
            s_axil_awaddr: Default::default(),
            s_axil_awvalid: Default::default(),
            s_axil_awready: Default::default(),
            s_axil_wdata: Default::default(),
            s_axil_wvalid: Default::default(),
            s_axil_wready: Default::default(),
            s_axil_bresp: Default::default(),
            s_axil_bvalid: Default::default(),
            s_axil_bready: Default::default(),
            s_axil_araddr: Default::default(),
            s_axil_arvalid: Default::default(),
            s_axil_arready: Default::default(),
            s_axil_rdata: Default::default(),
            s_axil_rresp: Default::default(),
            s_axil_rvalid: Default::default(),
            s_axil_rready: Default::default(),
            hold: Default::default(),
            defer: Default::default(),
            done: Default::default(),
            w_take: Default::default(),
            wr: Default::default(),
            we: (0..n).map(|_| Default::default()).collect(),
            wdata: Default::default(),
            read_block: Default::default(),
            read_data: Default::default(),
            raddr: Default::default(),
            raddr_hi: Default::default(),
            aw_v: Default::default(),
            aw_sel: (0..n).map(|_| Default::default()).collect(),
            w_v: Default::default(),
            w_d: Default::default(),
            b_v: Default::default(),
            ar_word_q: FccKeepReg::with_max_fanout(MAX_FANOUT),
            ar_word_hi_q: FccKeepReg::with_max_fanout(MAX_FANOUT),
            ar_pend_q: Default::default(),
            r_v: Default::default(),
            r_d: Default::default(),
            aw_word: Default::default(),
            w_taken: Default::default(),
            perform: Default::default(),
            ar_take: Default::default(),
            words: offsets.iter().map(|a| kb((a / 4) as u64)).collect(),
            okay: kb(0),
            _n: n,
        }
    }
}

impl Logic for FccAxilAdapter {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, aw_v, w_v, w_d, b_v, r_v, r_d);
        for i in 0..self._n {
            self.aw_sel[i].clock.next = self.clk.val();
            self.aw_sel[i].d.next = self.aw_sel[i].q.val();
        }
        self.ar_word_q.clock.next = self.clk.val();
        self.ar_word_hi_q.clock.next = self.clk.val();
        self.ar_pend_q.clock.next = self.clk.val();
        // ---- Write channel: AW and W held in either order, then one write.
        self.perform.next =
            self.aw_v.q.val() & self.w_v.q.val() & !self.b_v.q.val() & !self.hold.val();
        self.aw_word.next = self.s_axil_awaddr.val().get_bits::<WORD_BITS>(2);
        if self.s_axil_awvalid.val() & !self.aw_v.q.val() {
            self.aw_v.d.next = true;
            for i in 0..self._n {
                self.aw_sel[i].d.next = self.aw_word.val() == self.words[i].val();
            }
        }
        self.w_taken.next = self.s_axil_wvalid.val() & !self.w_v.q.val();
        if self.w_taken.val() {
            self.w_v.d.next = true;
            self.w_d.d.next = self.s_axil_wdata.val();
        }
        if self.b_v.q.val() & self.s_axil_bready.val() {
            self.b_v.d.next = false;
        }
        // The write-enables (and `w_take`, `wr` below) are written from the
        // registers and `hold` alone, with no local signal shared with the
        // response's logic: Verilator orders the statements of a block
        // apart only if they share none, and `we` reaches `defer`.
        for i in 0..self._n {
            self.we[i].next = self.aw_v.q.val()
                & self.w_v.q.val()
                & !self.b_v.q.val()
                & !self.hold.val()
                & self.aw_sel[i].q.val();
        }
        if self.perform.val() {
            self.aw_v.d.next = false;
            self.w_v.d.next = false;
            self.b_v.d.next = !self.defer.val();
        }
        if self.done.val() {
            self.b_v.d.next = true;
        }
        // ---- Read channel.
        self.ar_take.next = self.s_axil_arvalid.val()
            & !self.ar_pend_q.q.val()
            & !self.r_v.q.val()
            & !self.read_block.val();
        self.ar_pend_q.d.next = self.ar_take.val();
        self.ar_word_q.d.next = self.ar_word_q.q.val();
        self.ar_word_hi_q.d.next = self.ar_word_hi_q.q.val();
        if self.ar_take.val() {
            self.ar_word_q.d.next = self.s_axil_araddr.val().get_bits::<WORD_BITS>(2);
            self.ar_word_hi_q.d.next = self.s_axil_araddr.val().get_bits::<WORD_BITS>(2);
        }
        if self.ar_pend_q.q.val() {
            self.r_v.d.next = true;
            self.r_d.d.next = self.read_data.val();
        }
        if self.r_v.q.val() & self.s_axil_rready.val() {
            self.r_v.d.next = false;
        }
        if self.rst.val() {
            self.aw_v.d.next = false;
            self.w_v.d.next = false;
            self.b_v.d.next = false;
            self.ar_pend_q.d.next = false;
            self.r_v.d.next = false;
        }
        // ---- Outputs.
        self.w_take.next = self.s_axil_wvalid.val() & !self.w_v.q.val();
        self.wr.next = self.aw_v.q.val() & self.w_v.q.val() & !self.b_v.q.val() & !self.hold.val();
        self.wdata.next = self.w_d.q.val();
        self.raddr.next = self.ar_word_q.q.val();
        self.raddr_hi.next = self.ar_word_hi_q.q.val();
        self.s_axil_awready.next = !self.aw_v.q.val();
        self.s_axil_wready.next = !self.w_v.q.val();
        self.s_axil_bvalid.next = self.b_v.q.val();
        self.s_axil_bresp.next = self.okay.val();
        self.s_axil_arready.next =
            !self.ar_pend_q.q.val() & !self.r_v.q.val() & !self.read_block.val();
        self.s_axil_rvalid.next = self.r_v.q.val();
        self.s_axil_rdata.next = self.r_d.q.val();
        self.s_axil_rresp.next = self.okay.val();
    }
}
