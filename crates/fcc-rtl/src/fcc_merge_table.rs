//! `fcc_merge_table`: the exact equivalence table.
//!
//! The parent table `T` (block RAM, `2^B` words) is a union-find forest in
//! which every parent is smaller than its child, so a tree's root is the
//! smallest provisional label of its component. A second one-bit table `R`
//! beside it says whether a label is a root, so a read tells at once whether
//! the walk is over. Reads take two cycles (`FccRam`). The table has three
//! users, one per mode ([`MergeMode`]), each a block of its own behind the
//! RAM-port multiplexer `fcc_table_ports`, which owns `T` and `R` and
//! forwards a link write to a read of the same word issued in its cycle:
//!
//! * Init (after every reset, `fcc_table_init`): every label becomes a root,
//!   one per cycle.
//! * Union (while pixels stream, `fcc_union_engine`): each join (a, b) walks
//!   from a and from b to their roots, two interleaved walks sharing the read
//!   port, and links the larger root under the smaller.
//! * Flatten (frame end, `fcc_flatten`, which owns the compact table `C`):
//!   labels 1 .. P in ascending order get their compact numbers, in the raster
//!   order of their components' first pixels, exactly as the golden model;
//!   they leave on the `fv`/`fval` stream, and every label becomes a root
//!   again for the next frame.
//!
//! This block holds only the mode and the wiring.

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use crate::fcc_flatten::FccFlatten;
use crate::fcc_table_init::FccTableInit;
use crate::fcc_table_ports::FccTablePorts;
use crate::fcc_union_engine::FccUnionEngine;

/// Who owns the table.
#[derive(Copy, Clone, Debug, PartialEq, LogicState)]
pub enum MergeMode {
    /// After reset, until every word is a root.
    Init,
    /// Joins are merged.
    Union,
    /// From `flat_start` until every compact label has left.
    Flatten,
}

#[derive(LogicBlock)]
pub struct FccMergeTable {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    // Joins from the sort network.
    pub jv: Signal<In, Bit>,
    pub ja: Signal<In, Bits<16>>,
    pub jb: Signal<In, Bits<16>>,
    pub jsame: Signal<In, Bit>,
    pub jtake: Signal<Out, Bit>,
    // Control.
    pub init_busy: Signal<Out, Bit>,
    /// No join held or in progress.
    pub union_idle: Signal<Out, Bit>,
    pub flat_start: Signal<In, Bit>,
    pub provisional: Signal<In, Bits<17>>,
    // Compact labels in ascending provisional order.
    pub fv: Signal<Out, Bit>,
    pub fval: Signal<Out, Bits<16>>,
    /// Compact labels waiting in the label updater's gearbox (registered).
    pub gear_used: Signal<In, Bits<4>>,
    pub clusters: Signal<Out, Bits<16>>,
    mode: DFF<MergeMode>,
    table_init: FccTableInit,
    union_engine: FccUnionEngine,
    flatten: FccFlatten,
    ports: FccTablePorts,
    init_active: Signal<Local, Bit>,
    union_active: Signal<Local, Bit>,
    flatten_active: Signal<Local, Bit>,
}

impl FccMergeTable {
    pub fn new(p: &FccParams) -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            jv: Default::default(),
            ja: Default::default(),
            jb: Default::default(),
            jsame: Default::default(),
            jtake: Default::default(),
            init_busy: Default::default(),
            union_idle: Default::default(),
            flat_start: Default::default(),
            provisional: Default::default(),
            fv: Default::default(),
            fval: Default::default(),
            gear_used: Default::default(),
            clusters: Default::default(),
            mode: Default::default(),
            table_init: FccTableInit::new(p),
            union_engine: Default::default(),
            flatten: FccFlatten::new(p),
            ports: FccTablePorts::new(p),
            init_active: Default::default(),
            union_active: Default::default(),
            flatten_active: Default::default(),
        }
    }
}

impl Logic for FccMergeTable {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, mode);
        self.table_init.clk.next = self.clk.val();
        self.union_engine.clk.next = self.clk.val();
        self.flatten.clk.next = self.clk.val();
        self.ports.clk.next = self.clk.val();
        self.table_init.rst.next = self.rst.val();
        self.union_engine.rst.next = self.rst.val();
        self.flatten.rst.next = self.rst.val();
        self.ports.rst.next = self.rst.val();
        // ---- Mode.
        self.init_active.next = false;
        self.union_active.next = false;
        self.flatten_active.next = false;
        match self.mode.q.val() {
            MergeMode::Init => {
                self.init_active.next = true;
            }
            MergeMode::Union => {
                self.union_active.next = true;
            }
            MergeMode::Flatten => {
                self.flatten_active.next = true;
            }
        }
        if self.table_init.done.val() | self.flatten.done.val() {
            self.mode.d.next = MergeMode::Union;
        }
        if self.flat_start.val() {
            self.mode.d.next = MergeMode::Flatten;
        }
        if self.rst.val() {
            self.mode.d.next = MergeMode::Init;
        }
        self.table_init.active.next = self.init_active.val();
        self.union_engine.active.next = self.union_active.val();
        self.flatten.active.next = self.flatten_active.val();
        self.ports.init_active.next = self.init_active.val();
        self.ports.flatten_active.next = self.flatten_active.val();
        self.init_busy.next = self.init_active.val();
        // ---- Joins in, the union engine.
        self.union_engine.join_valid.next = self.jv.val();
        self.union_engine.join_a.next = self.ja.val();
        self.union_engine.join_b.next = self.jb.val();
        self.union_engine.join_same.next = self.jsame.val();
        self.jtake.next = self.union_engine.join_take.val();
        self.union_idle.next = self.union_engine.idle.val();
        self.union_engine.word_root.next = self.ports.word_root.val();
        self.union_engine.word_parent.next = self.ports.word_parent.val();
        // ---- The flatten pass, compact labels out.
        self.flatten.start.next = self.flat_start.val();
        self.flatten.provisional.next = self.provisional.val();
        self.flatten.gear_used.next = self.gear_used.val();
        self.flatten.word_root.next = self.ports.word_root.val();
        self.flatten.word_parent.next = self.ports.word_parent.val();
        self.fv.next = self.flatten.out_valid.val();
        self.fval.next = self.flatten.out_label.val();
        self.clusters.next = self.flatten.clusters.val();
        // ---- The table's ports.
        self.ports.init_write_addr.next = self.table_init.write_addr.val();
        self.ports.union_read_en.next = self.union_engine.read_en.val();
        self.ports.union_read_addr.next = self.union_engine.read_addr.val();
        self.ports.link_en.next = self.union_engine.link_en.val();
        self.ports.link_addr.next = self.union_engine.link_addr.val();
        self.ports.link_data.next = self.union_engine.link_data.val();
        self.ports.flatten_read_en.next = self.flatten.read_en.val();
        self.ports.flatten_read_addr.next = self.flatten.read_addr.val();
        self.ports.flatten_write_en.next = self.flatten.write_en.val();
        self.ports.flatten_write_addr.next = self.flatten.write_addr.val();
    }
}
