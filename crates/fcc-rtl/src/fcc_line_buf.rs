//! `FccLineBuf`: one line buffer of `fcc_window` (one row above the centre):
//! `cols` words of point + "has a provisional label" in block RAM, with the
//! fields as separate ports so the window can index a `Vec` of them. Reads
//! take two cycles (`FccRam`).

use rust_hdl::prelude::*;

use crate::fcc_ram::FccRam;
use crate::types::LbEntry;

#[derive(LogicBlock)]
pub struct FccLineBuf {
    pub clk: Signal<In, Clock>,
    // Read port (data two cycles after `read_en`).
    pub read_en: Signal<In, Bit>,
    pub read_addr: Signal<In, Bits<12>>,
    pub rd_lok: Signal<Out, Bit>,
    pub rd_x: Signal<Out, Bits<16>>,
    pub rd_y: Signal<Out, Bits<16>>,
    pub rd_z: Signal<Out, Bits<16>>,
    // Write port.
    pub write_en: Signal<In, Bit>,
    pub write_addr: Signal<In, Bits<12>>,
    pub wr_lok: Signal<In, Bit>,
    pub wr_x: Signal<In, Bits<16>>,
    pub wr_y: Signal<In, Bits<16>>,
    pub wr_z: Signal<In, Bits<16>>,
    ram: FccRam<LbEntry, 12>,
}

impl FccLineBuf {
    pub fn new(cols: usize) -> Self {
        Self {
            clk: Default::default(),
            read_en: Default::default(),
            read_addr: Default::default(),
            rd_lok: Default::default(),
            rd_x: Default::default(),
            rd_y: Default::default(),
            rd_z: Default::default(),
            write_en: Default::default(),
            write_addr: Default::default(),
            wr_lok: Default::default(),
            wr_x: Default::default(),
            wr_y: Default::default(),
            wr_z: Default::default(),
            ram: FccRam::new(cols),
        }
    }
}

impl Logic for FccLineBuf {
    #[hdl_gen]
    fn update(&mut self) {
        self.ram.clk.next = self.clk.val();
        self.ram.read_en.next = self.read_en.val();
        self.ram.read_addr.next = self.read_addr.val();
        self.ram.write_en.next = self.write_en.val();
        self.ram.write_addr.next = self.write_addr.val();
        self.ram.write_data.next.lok = self.wr_lok.val();
        self.ram.write_data.next.x = self.wr_x.val();
        self.ram.write_data.next.y = self.wr_y.val();
        self.ram.write_data.next.z = self.wr_z.val();
        self.rd_lok.next = self.ram.read_data.val().lok;
        self.rd_x.next = self.ram.read_data.val().x;
        self.rd_y.next = self.ram.read_data.val().y;
        self.rd_z.next = self.ram.read_data.val().z;
    }
}
