//! `FccCentreBuf`: the centre buffer between the sort filter and the
//! serializer, 2^CB_BITS records in block RAM. A record is the centre's
//! `CtrRec` (in the FIFO's own RAM) and its window rows: per position the
//! representative, the kept flag and the first-kept flag (set at the first
//! kept position only), one RAM word per window row
//! (`FccRowPack`), in side RAMs addressed with the FIFO's RAM ports. The head
//! record's fields all show together, first-word-fall-through.

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use crate::fcc_fifo::FccFifo;
use crate::fcc_ram::FccRam;
use crate::fcc_row_word::{row_bits, FccRowPack, FccRowUnpack, ROW_BITS};
use crate::types::{vec_of, CtrRec};

/// Centre buffer: 2^CB_BITS records.
pub const CB_BITS: usize = 9;

#[derive(LogicBlock)]
pub struct FccCentreBuf {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    // Write side (the caller makes sure there is room: input credits).
    pub push: Signal<In, Bit>,
    pub rec: Signal<In, CtrRec>,
    pub rep: Vec<Signal<In, Bits<16>>>,
    pub keep: Vec<Signal<In, Bit>>,
    pub first: Vec<Signal<In, Bit>>,
    // Read side: the head record.
    pub head_valid: Signal<Out, Bit>,
    pub head: Signal<Out, CtrRec>,
    pub head_rep: Vec<Signal<Out, Bits<16>>>,
    pub head_keep: Vec<Signal<Out, Bit>>,
    pub head_first: Vec<Signal<Out, Bit>>,
    pub take: Signal<In, Bit>,
    records: FccFifo<CtrRec, CB_BITS, { CB_BITS + 1 }>,
    rows: Vec<FccRam<Bits<ROW_BITS>, CB_BITS>>,
    pack: FccRowPack,
    unpack: FccRowUnpack,
    _h: usize,
    _n: usize,
}

impl FccCentreBuf {
    pub fn new(p: &FccParams) -> Self {
        let k = p.fsize;
        let h = p.half();
        let n = p.window_positions();
        Self {
            clk: Default::default(),
            rst: Default::default(),
            push: Default::default(),
            rec: Default::default(),
            rep: vec_of(n),
            keep: vec_of(n),
            first: vec_of(n),
            head_valid: Default::default(),
            head: Default::default(),
            head_rep: vec_of(n),
            head_keep: vec_of(n),
            head_first: vec_of(n),
            take: Default::default(),
            records: FccFifo::default(),
            rows: (0..h)
                .map(|_| FccRam::with_stored_bits(1 << CB_BITS, row_bits(k)))
                .collect(),
            pack: FccRowPack::new(k, h),
            unpack: FccRowUnpack::new(k, h),
            _h: h,
            _n: n,
        }
    }
}

impl Logic for FccCentreBuf {
    #[hdl_gen]
    fn update(&mut self) {
        self.records.clk.next = self.clk.val();
        self.records.rst.next = self.rst.val();
        self.records.push.next = self.push.val();
        self.records.din.next = self.rec.val();
        self.records.take.next = self.take.val();
        self.head_valid.next = self.records.valid.val();
        self.head.next = self.records.dout.val();
        for e in 0..self._n {
            self.pack.v[e].next = self.rep[e].val();
            self.pack.f[e].next = self.keep[e].val();
            self.pack.g[e].next = self.first[e].val();
            self.head_rep[e].next = self.unpack.v[e].val();
            self.head_keep[e].next = self.unpack.f[e].val();
            self.head_first[e].next = self.unpack.g[e].val();
        }
        for r in 0..self._h {
            self.rows[r].clk.next = self.clk.val();
            self.rows[r].write_en.next = self.records.ram_we.val();
            self.rows[r].write_addr.next = self.records.ram_waddr.val();
            self.rows[r].write_data.next = self.pack.word[r].val();
            self.rows[r].read_en.next = self.records.ram_re.val();
            self.rows[r].read_addr.next = self.records.ram_raddr.val();
            self.unpack.word[r].next = self.rows[r].read_data.val();
        }
    }
}
