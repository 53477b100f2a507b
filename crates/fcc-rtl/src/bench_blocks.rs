//! The blocks generated alone for their own Verilator benches, in one
//! table: each block's module name, Verilog and lint waivers. The benches
//! (`fcc-sim`) and the lint test read it, so a new block bench is a row
//! here, its shim and its test.

use fcc_params::FccParams;

use crate::{lint, RtlError};

/// A block with a bench of its own.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BenchBlock {
    /// The register file `FccRegs`.
    Regs,
    /// The register file's AXI4-Lite adapter `FccAxilAdapter`; its
    /// write-enables keep rust-hdl's names `we$i`.
    AxilAdapter,
    /// The merge table `FccMergeTable` and its sub-blocks.
    MergeTable,
    /// The label updater `FccLabelUpdate`.
    LabelUpdate,
    /// `FccWindow` and its line buffers behind the scalar ports of `FccWindowProbe`.
    Window,
    /// The sort network `FccSortNet` (sort filter, centre buffer, serializer,
    /// join queue); its per-position ports keep rust-hdl's names `hit$e` and `rep$e`.
    SortNet,
    /// The per-point threshold unit `FccPointThr` (range-adaptive thresholds).
    PointThr,
}

impl BenchBlock {
    /// Every block with a bench.
    pub const ALL: [BenchBlock; 7] = [
        BenchBlock::Regs,
        BenchBlock::AxilAdapter,
        BenchBlock::MergeTable,
        BenchBlock::LabelUpdate,
        BenchBlock::Window,
        BenchBlock::SortNet,
        BenchBlock::PointThr,
    ];

    /// The module's name before the configuration suffix, and the stem of
    /// its files (`<name>.v`, `<name>.vlt`).
    pub fn name(self) -> &'static str {
        match self {
            BenchBlock::Regs => crate::REGS_NAME,
            BenchBlock::AxilAdapter => crate::AXIL_ADAPTER_NAME,
            BenchBlock::MergeTable => crate::MERGE_TABLE_NAME,
            BenchBlock::LabelUpdate => crate::LABEL_UPDATE_NAME,
            BenchBlock::Window => crate::WINDOW_NAME,
            BenchBlock::SortNet => crate::SORT_NET_NAME,
            BenchBlock::PointThr => crate::POINT_THR_NAME,
        }
    }

    /// The module when generated alone for `p`: `fcc_regs_k7_1b2c3d4e`.
    pub fn module(self, p: &FccParams) -> String {
        format!("{}{}", self.name(), p.module_suffix())
    }

    /// The block's Verilog for the build `p`, as the module [`Self::module`].
    pub fn generate(self, p: &FccParams) -> Result<String, RtlError> {
        match self {
            BenchBlock::Regs => crate::generate_regs(p),
            BenchBlock::AxilAdapter => crate::generate_axil_adapter(p),
            BenchBlock::MergeTable => crate::generate_merge_table(p),
            BenchBlock::LabelUpdate => crate::generate_label_update(p),
            BenchBlock::Window => crate::generate_window(p),
            BenchBlock::SortNet => crate::generate_sort_net(p),
            BenchBlock::PointThr => crate::generate_point_thr(p),
        }
    }

    /// The Verilator waivers of the block's file (`verilator --lint-only
    /// -Wall` passes with them).
    pub fn waivers(self, p: &FccParams) -> String {
        match self {
            BenchBlock::Regs => lint::regs_waivers(p),
            BenchBlock::AxilAdapter => lint::axil_adapter_waivers(p),
            BenchBlock::MergeTable => lint::merge_table_waivers(p),
            BenchBlock::LabelUpdate => lint::label_update_waivers(p),
            BenchBlock::Window => lint::window_waivers(p),
            BenchBlock::SortNet => lint::sort_net_waivers(p),
            BenchBlock::PointThr => lint::point_thr_waivers(p),
        }
    }
}
