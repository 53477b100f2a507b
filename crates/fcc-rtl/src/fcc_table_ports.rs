//! `fcc_table_ports`: the merge table's RAM-port multiplexer.
//!
//! Owns the parent table `T` and the root table `R` (one read port, one
//! write port each, two-cycle reads, `FccRam`) and gives their ports to the
//! table's three users by mode: Init writes, Union reads and writes links,
//! Flatten reads and writes. `T` is written by links only: a root's word in
//! `T` is never used (a walk ends at a root, and Flatten numbers a root
//! without its parent), so making a word a root (Init, Flatten) writes `R`
//! alone, and each table's write enable drives its own RAMs' pins only.
//! A read issued in the cycle of a write to the same
//! word gets the written word forwarded (`forward_hit`): only a link write can
//! meet a read that way (Init reads nothing; Flatten writes a word two cycles
//! after reading it and reads in ascending order), so a forwarded word is
//! always a link (a parent, never a root), and only link writes are
//! registered for the comparison.

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use crate::fcc_ram::FccRam;

#[derive(LogicBlock)]
pub struct FccTablePorts {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    // The table's mode (at most one is set; neither: Union).
    pub init_active: Signal<In, Bit>,
    pub flatten_active: Signal<In, Bit>,
    // Init: every word a root.
    pub init_write_addr: Signal<In, Bits<16>>,
    // Union: reads and link writes.
    pub union_read_en: Signal<In, Bit>,
    pub union_read_addr: Signal<In, Bits<16>>,
    pub link_en: Signal<In, Bit>,
    pub link_addr: Signal<In, Bits<16>>,
    pub link_data: Signal<In, Bits<16>>,
    // Flatten: reads, and writes that make a word a root again.
    pub flatten_read_en: Signal<In, Bit>,
    pub flatten_read_addr: Signal<In, Bits<16>>,
    pub flatten_write_en: Signal<In, Bit>,
    pub flatten_write_addr: Signal<In, Bits<16>>,
    // The word read two cycles ago, with a same-cycle link write forwarded.
    pub word_root: Signal<Out, Bit>,
    pub word_parent: Signal<Out, Bits<16>>,
    parent_ram: FccRam<Bits<16>, 16>,
    root_ram: FccRam<Bit, 16>,
    // The write and the read of one cycle ago, and the write of two.
    fwd_write_en: DFF<Bit>,
    fwd_write_addr: DFF<Bits<16>>,
    fwd_write_data: DFF<Bits<16>>,
    fwd_write_data_s2: DFF<Bits<16>>,
    fwd_read_en: DFF<Bit>,
    fwd_read_addr: DFF<Bits<16>>,
    /// The word read two cycles ago was written in the cycle of its read.
    forward_hit: DFF<Bit>,
    // Combinational.
    read_en: Signal<Local, Bit>,
    read_addr: Signal<Local, Bits<16>>,
    write_en: Signal<Local, Bit>,
    write_addr: Signal<Local, Bits<16>>,
    write_root: Signal<Local, Bit>,
}

impl FccTablePorts {
    pub fn new(p: &FccParams) -> Self {
        let words = 1usize << p.label_bits;
        Self {
            clk: Default::default(),
            rst: Default::default(),
            init_active: Default::default(),
            flatten_active: Default::default(),
            init_write_addr: Default::default(),
            union_read_en: Default::default(),
            union_read_addr: Default::default(),
            link_en: Default::default(),
            link_addr: Default::default(),
            link_data: Default::default(),
            flatten_read_en: Default::default(),
            flatten_read_addr: Default::default(),
            flatten_write_en: Default::default(),
            flatten_write_addr: Default::default(),
            word_root: Default::default(),
            word_parent: Default::default(),
            parent_ram: FccRam::with_stored_bits(words, p.label_bits as usize),
            root_ram: FccRam::new(words),
            fwd_write_en: Default::default(),
            fwd_write_addr: Default::default(),
            fwd_write_data: Default::default(),
            fwd_write_data_s2: Default::default(),
            fwd_read_en: Default::default(),
            fwd_read_addr: Default::default(),
            forward_hit: Default::default(),
            read_en: Default::default(),
            read_addr: Default::default(),
            write_en: Default::default(),
            write_addr: Default::default(),
            write_root: Default::default(),
        }
    }
}

impl Logic for FccTablePorts {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clk,
            fwd_write_en,
            fwd_write_addr,
            fwd_write_data,
            fwd_write_data_s2,
            fwd_read_en,
            fwd_read_addr,
            forward_hit
        );
        self.parent_ram.clk.next = self.clk.val();
        self.root_ram.clk.next = self.clk.val();
        // Read port.
        self.read_en.next = self.union_read_en.val() | self.flatten_read_en.val();
        self.read_addr.next = self.union_read_addr.val();
        if self.flatten_active.val() {
            self.read_addr.next = self.flatten_read_addr.val();
        }
        // Write ports: `R` takes a link (no longer a root) or a word made a
        // root; `T` takes links only.
        self.write_en.next =
            self.link_en.val() | self.init_active.val() | self.flatten_write_en.val();
        self.write_root.next = self.init_active.val() | self.flatten_write_en.val();
        self.write_addr.next = self.link_addr.val();
        if self.init_active.val() {
            self.write_addr.next = self.init_write_addr.val();
        }
        if self.flatten_write_en.val() {
            self.write_addr.next = self.flatten_write_addr.val();
        }
        self.parent_ram.read_en.next = self.read_en.val();
        self.parent_ram.read_addr.next = self.read_addr.val();
        self.parent_ram.write_en.next = self.link_en.val();
        self.parent_ram.write_addr.next = self.link_addr.val();
        self.parent_ram.write_data.next = self.link_data.val();
        self.root_ram.read_en.next = self.read_en.val();
        self.root_ram.read_addr.next = self.read_addr.val();
        self.root_ram.write_en.next = self.write_en.val();
        self.root_ram.write_addr.next = self.write_addr.val();
        self.root_ram.write_data.next = self.write_root.val();
        // Forwarding: link writes only (see above).
        self.fwd_write_en.d.next = self.link_en.val();
        self.fwd_write_addr.d.next = self.link_addr.val();
        self.fwd_write_data.d.next = self.link_data.val();
        self.fwd_write_data_s2.d.next = self.fwd_write_data.q.val();
        self.fwd_read_en.d.next = self.read_en.val();
        self.fwd_read_addr.d.next = self.read_addr.val();
        self.forward_hit.d.next = self.fwd_write_en.q.val()
            & self.fwd_read_en.q.val()
            & (self.fwd_write_addr.q.val() == self.fwd_read_addr.q.val());
        self.word_root.next = self.root_ram.read_data.val();
        self.word_parent.next = self.parent_ram.read_data.val();
        if self.forward_hit.q.val() {
            self.word_root.next = false;
            self.word_parent.next = self.fwd_write_data_s2.q.val();
        }
        if self.rst.val() {
            self.fwd_write_en.d.next = false;
            self.fwd_read_en.d.next = false;
            self.forward_hit.d.next = false;
        }
    }
}
