//! The blocks generated alone for their own Verilator benches, in one
//! table: each block's module name, Verilog and lint waivers. The benches
//! (`fcc-sim`) and the lint test read it, so a new block bench is a row
//! here, its test and (for a block with a non-plain port) its shim.

use fcc_params::FccParams;
use rust_hdl::prelude::Bits;

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
    /// The core's AXI4-Stream input stage `FccInputStage`, its slot field by
    /// field behind `FccInputStageProbe`.
    InputStage,
    /// The same stage in column order (`FccInputStage::column_order`, the
    /// column-streaming core's).
    ColInputStage,
    /// The front end's credit counter `FccCredits`.
    Credits,
    /// The stream FIFO `FccStreamFifo` (its control `FccStreamCtl` and one
    /// lane `FccStreamLane`) of 16-bit words, 16 deep.
    StreamFifo,
    /// The frame-phase machine `FccFramePhase`.
    FramePhase,
    /// The sort filter's centre pipeline `FccFiltCentre`.
    FiltCentre,
    /// A 16-bit lane of `FccWordWindow` (the representative and threshold
    /// windows' shape) behind the scalar ports of `FccWordWindowProbe`.
    WordWindow,
    /// The column core's per-row run state `FccRowRuns` behind the scalar
    /// ports of `FccRowRunsProbe`.
    RowRuns,
    /// The column core's pass-2 window `FccColWindow` behind the scalar
    /// ports of `FccColWindowProbe`.
    ColWindow,
    /// The column core's pass-2 distance tests `FccColDist` behind the
    /// scalar ports of `FccColDistProbe`.
    ColDist,
    /// The column core's front `FccColFront` (thresholds, row runs, window,
    /// distance tests) behind the scalar ports of `FccColFrontProbe`.
    ColFront,
    /// The column core's slot buffer with its credits `FccColSlotBuf`
    /// behind the scalar ports of `FccColSlotBufProbe`.
    ColSlotBuf,
    /// The column core's input half `FccColIn` (input stage, column-start
    /// check, front, slot buffer) behind the scalar ports of
    /// `FccColInProbe`.
    ColIn,
    /// The column core's input half and slot table half (`FccColIn`,
    /// `FccColTable`) wired, behind the scalar ports of `FccColTableProbe`.
    ColTable,
    /// The column core's datapath `FccColCore`: the input, slot table and
    /// record store halves wired, pixels in and records out.
    ColCore,
    /// The column top's run parameters in the datapath's form
    /// (`FccColLimits`) behind the registered inputs of
    /// `FccColLimitsProbe`.
    ColLimits,
    /// The column top's frame sequence (`FccColFlow`).
    ColFlow,
    /// The column core's record accumulator (`FccAccPixel`, `FccAccMerge`)
    /// over the four registers of `FccAccProbe`.
    Acc,
    /// The column core's record output `FccRecordOut` (with `FccRecBeats`)
    /// behind the scalar ports of `FccRecordOutProbe`.
    RecordOut,
    /// The column core's free labels `FccLabelPool`.
    LabelPool,
    /// The column core's union-find over labels `FccLabelSets`.
    LabelSets,
    /// The column core's run accumulators `FccRunAcc` behind the scalar
    /// ports of `FccRunAccProbe`.
    RunAcc,
    /// The column core's record store `FccSlotRecords` behind the scalar
    /// ports of `FccSlotRecordsProbe`.
    SlotRecords,
    /// The column core's closer's sorted entries `FccCloseOrder`.
    CloseOrder,
    /// The column core's closer `FccCloser` (wait list, passes, sorted
    /// entries).
    Closer,
    /// The column core's clusters' label lists `FccLabelLists`.
    LabelLists,
    /// The column core's column-start check `FccColStart`.
    ColStart,
    /// The column core's union-find queue `FccSetQueue` (with
    /// `FccLabelSets` and `FccSetOrder`).
    SetQueue,
    /// The column core's packer of a pixel slot's ops into the union-find
    /// queue's entries `FccSetPack`.
    SetPack,
    /// The column core's representative rows and join filter `FccRepJoins`
    /// behind the scalar ports of `FccRepJoinsProbe`.
    RepJoins,
    /// The column core's flushes' accumulators waiting for their finds
    /// `FccFlushWait` behind the scalar ports of `FccFlushWaitProbe`.
    FlushWait,
}

/// One row of the table: the module's name before the configuration
/// suffix (the stem of its files), its generator and its waivers.
struct Row {
    name: &'static str,
    generate: fn(&FccParams) -> Result<String, RtlError>,
    waivers: fn(&FccParams, &str) -> String,
}

impl Row {
    /// A block whose Verilog is the same for every build (the suffix names
    /// it) and needs no waiver beyond its file's name.
    const fn plain(
        name: &'static str,
        generate: fn(&FccParams) -> Result<String, RtlError>,
    ) -> Row {
        Row {
            name,
            generate,
            waivers: lint::block_waivers,
        }
    }
}

impl BenchBlock {
    /// Every block with a bench.
    pub const ALL: [BenchBlock; 38] = [
        BenchBlock::Regs,
        BenchBlock::AxilAdapter,
        BenchBlock::MergeTable,
        BenchBlock::LabelUpdate,
        BenchBlock::Window,
        BenchBlock::SortNet,
        BenchBlock::PointThr,
        BenchBlock::InputStage,
        BenchBlock::ColInputStage,
        BenchBlock::Credits,
        BenchBlock::StreamFifo,
        BenchBlock::FramePhase,
        BenchBlock::FiltCentre,
        BenchBlock::WordWindow,
        BenchBlock::RowRuns,
        BenchBlock::ColWindow,
        BenchBlock::ColDist,
        BenchBlock::ColFront,
        BenchBlock::ColSlotBuf,
        BenchBlock::ColIn,
        BenchBlock::ColTable,
        BenchBlock::ColCore,
        BenchBlock::ColLimits,
        BenchBlock::ColFlow,
        BenchBlock::Acc,
        BenchBlock::RecordOut,
        BenchBlock::LabelPool,
        BenchBlock::LabelSets,
        BenchBlock::RunAcc,
        BenchBlock::SlotRecords,
        BenchBlock::CloseOrder,
        BenchBlock::Closer,
        BenchBlock::LabelLists,
        BenchBlock::SetQueue,
        BenchBlock::SetPack,
        BenchBlock::ColStart,
        BenchBlock::RepJoins,
        BenchBlock::FlushWait,
    ];

    fn row(self) -> Row {
        use crate::generate_block as gen;
        match self {
            BenchBlock::Regs => Row {
                name: crate::REGS_NAME,
                generate: crate::generate_regs,
                waivers: |p, _| lint::regs_waivers(p),
            },
            BenchBlock::AxilAdapter => Row {
                name: crate::AXIL_ADAPTER_NAME,
                generate: crate::generate_axil_adapter,
                waivers: |p, _| lint::axil_adapter_waivers(p),
            },
            BenchBlock::MergeTable => Row {
                name: crate::MERGE_TABLE_NAME,
                generate: crate::generate_merge_table,
                waivers: |p, _| lint::merge_table_waivers(p),
            },
            BenchBlock::LabelUpdate => Row {
                name: crate::LABEL_UPDATE_NAME,
                generate: crate::generate_label_update,
                waivers: |p, _| lint::label_update_waivers(p),
            },
            BenchBlock::Window => Row {
                name: crate::WINDOW_NAME,
                generate: crate::generate_window,
                waivers: |p, _| lint::window_waivers(p),
            },
            BenchBlock::SortNet => Row {
                name: crate::SORT_NET_NAME,
                generate: crate::generate_sort_net,
                waivers: |p, _| lint::sort_net_waivers(p),
            },
            BenchBlock::PointThr => Row::plain(crate::POINT_THR_NAME, crate::generate_point_thr),
            BenchBlock::InputStage => Row::plain("fcc_input_stage", |p| {
                gen(
                    p,
                    crate::fcc_input_stage_probe::FccInputStageProbe::default(),
                    "fcc_input_stage",
                )
            }),
            BenchBlock::ColInputStage => Row::plain("fcc_col_input_stage", |p| {
                gen(
                    p,
                    crate::fcc_input_stage_probe::FccInputStageProbe::column_order(),
                    "fcc_col_input_stage",
                )
            }),
            BenchBlock::Credits => Row::plain("fcc_credits", |p| {
                gen(p, crate::fcc_credits::FccCredits::default(), "fcc_credits")
            }),
            BenchBlock::StreamFifo => Row::plain("fcc_stream_fifo", |p| {
                gen(
                    p,
                    crate::fcc_stream_fifo::FccStreamFifo::<Bits<16>, 4, 5>::default(),
                    "fcc_stream_fifo",
                )
            }),
            BenchBlock::FramePhase => Row {
                name: "fcc_frame_phase",
                generate: |p| {
                    gen(
                        p,
                        crate::fcc_frame_phase::FccFramePhase::default(),
                        "fcc_frame_phase",
                    )
                },
                waivers: lint::enum_block_waivers,
            },
            BenchBlock::FiltCentre => Row::plain("fcc_filt_centre", |p| {
                let levels = crate::types::clog2(p.window_positions());
                gen(
                    p,
                    crate::fcc_filt_centre::FccFiltCentre::new(levels),
                    "fcc_filt_centre",
                )
            }),
            BenchBlock::WordWindow => Row {
                name: "fcc_word_window",
                generate: |p| {
                    gen(
                        p,
                        crate::fcc_word_window_probe::FccWordWindowProbe::new(p),
                        "fcc_word_window",
                    )
                },
                waivers: lint::word_window_waivers,
            },
            BenchBlock::RowRuns => Row::plain("fcc_row_runs", |p| {
                gen(
                    p,
                    crate::column::fcc_row_runs_probe::FccRowRunsProbe::new(p),
                    "fcc_row_runs",
                )
            }),
            BenchBlock::ColWindow => Row {
                name: "fcc_col_window",
                generate: |p| {
                    gen(
                        p,
                        crate::column::fcc_col_window_probe::FccColWindowProbe::new(p),
                        "fcc_col_window",
                    )
                },
                waivers: lint::col_window_waivers,
            },
            BenchBlock::ColDist => Row {
                name: "fcc_col_dist",
                generate: |p| {
                    gen(
                        p,
                        crate::column::fcc_col_dist_probe::FccColDistProbe::new(p),
                        "fcc_col_dist",
                    )
                },
                waivers: lint::col_dist_waivers,
            },
            BenchBlock::ColFront => Row {
                name: "fcc_col_front",
                generate: |p| {
                    gen(
                        p,
                        crate::column::fcc_col_front_probe::FccColFrontProbe::new(p),
                        "fcc_col_front",
                    )
                },
                waivers: lint::col_front_waivers,
            },
            BenchBlock::ColSlotBuf => Row {
                name: "fcc_col_slot_buf",
                generate: |p| {
                    gen(
                        p,
                        crate::column::fcc_col_slot_buf_probe::FccColSlotBufProbe::new(p),
                        "fcc_col_slot_buf",
                    )
                },
                waivers: lint::col_slot_buf_waivers,
            },
            BenchBlock::ColIn => Row {
                name: "fcc_col_in",
                generate: |p| {
                    gen(
                        p,
                        crate::column::fcc_col_in_probe::FccColInProbe::new(p),
                        "fcc_col_in",
                    )
                },
                waivers: lint::col_in_waivers,
            },
            BenchBlock::ColTable => Row {
                name: "fcc_col_table",
                generate: |p| {
                    gen(
                        p,
                        crate::column::fcc_col_table_probe::FccColTableProbe::new(p),
                        "fcc_col_table",
                    )
                },
                waivers: lint::col_table_waivers,
            },
            BenchBlock::ColCore => Row {
                name: "fcc_col_core",
                generate: |p| {
                    gen(
                        p,
                        crate::column::fcc_col_core::FccColCore::new(p),
                        "fcc_col_core",
                    )
                },
                waivers: lint::col_core_waivers,
            },
            BenchBlock::ColLimits => Row {
                name: "fcc_col_limits",
                generate: |p| {
                    gen(
                        p,
                        crate::column::fcc_col_limits_probe::FccColLimitsProbe::default(),
                        "fcc_col_limits",
                    )
                },
                waivers: lint::col_limits_waivers,
            },
            BenchBlock::ColFlow => Row {
                name: "fcc_col_flow",
                generate: |p| {
                    gen(
                        p,
                        crate::column::fcc_col_flow::FccColFlow::default(),
                        "fcc_col_flow",
                    )
                },
                waivers: lint::block_waivers,
            },
            BenchBlock::Acc => Row {
                name: "fcc_acc",
                generate: |p| {
                    gen(
                        p,
                        crate::column::fcc_acc_probe::FccAccProbe::default(),
                        "fcc_acc",
                    )
                },
                waivers: lint::acc_waivers,
            },
            BenchBlock::RecordOut => Row {
                name: "fcc_record_out",
                generate: |p| {
                    gen(
                        p,
                        crate::column::fcc_record_out_probe::FccRecordOutProbe::default(),
                        "fcc_record_out",
                    )
                },
                waivers: lint::enum_block_waivers,
            },
            BenchBlock::LabelPool => Row::plain("fcc_label_pool", |p| {
                gen(
                    p,
                    crate::column::fcc_label_pool::FccLabelPool::new(p),
                    "fcc_label_pool",
                )
            }),
            BenchBlock::LabelSets => Row::plain("fcc_label_sets", |p| {
                gen(
                    p,
                    crate::column::fcc_label_sets::FccLabelSets::new(p),
                    "fcc_label_sets",
                )
            }),
            BenchBlock::RunAcc => Row {
                name: "fcc_run_acc_probe",
                generate: |p| {
                    gen(
                        p,
                        crate::column::fcc_run_acc_probe::FccRunAccProbe::new(p),
                        "fcc_run_acc_probe",
                    )
                },
                waivers: lint::run_acc_waivers,
            },
            BenchBlock::SlotRecords => Row {
                name: "fcc_slot_records_probe",
                generate: |p| {
                    gen(
                        p,
                        crate::column::fcc_slot_records_probe::FccSlotRecordsProbe::default(),
                        "fcc_slot_records_probe",
                    )
                },
                waivers: lint::slot_records_waivers,
            },
            BenchBlock::CloseOrder => Row::plain("fcc_close_order", |p| {
                gen(
                    p,
                    crate::column::fcc_close_order::FccCloseOrder::default(),
                    "fcc_close_order",
                )
            }),
            BenchBlock::Closer => Row {
                name: "fcc_closer",
                generate: |p| {
                    gen(
                        p,
                        crate::column::fcc_closer::FccCloser::default(),
                        "fcc_closer",
                    )
                },
                waivers: lint::closer_waivers,
            },
            BenchBlock::LabelLists => Row {
                name: "fcc_label_lists",
                generate: |p| {
                    gen(
                        p,
                        crate::column::fcc_label_lists::FccLabelLists::new(p),
                        "fcc_label_lists",
                    )
                },
                waivers: lint::label_lists_waivers,
            },
            BenchBlock::ColStart => Row {
                name: "fcc_col_start",
                generate: |p| {
                    gen(
                        p,
                        crate::column::fcc_col_start::FccColStart::default(),
                        "fcc_col_start",
                    )
                },
                // Its counts are widened with bit_cast.
                waivers: lint::acc_waivers,
            },
            BenchBlock::SetQueue => Row {
                name: "fcc_set_queue",
                generate: |p| {
                    gen(
                        p,
                        crate::column::fcc_set_queue::FccSetQueue::new(p),
                        "fcc_set_queue",
                    )
                },
                waivers: lint::set_queue_waivers,
            },
            BenchBlock::FlushWait => Row {
                name: "fcc_flush_wait_probe",
                generate: |p| {
                    gen(
                        p,
                        crate::column::fcc_flush_wait_probe::FccFlushWaitProbe::default(),
                        "fcc_flush_wait_probe",
                    )
                },
                waivers: lint::flush_wait_waivers,
            },
            BenchBlock::SetPack => Row::plain("fcc_set_pack", |p| {
                gen(
                    p,
                    crate::column::fcc_set_pack::FccSetPack::default(),
                    "fcc_set_pack",
                )
            }),
            BenchBlock::RepJoins => Row {
                name: "fcc_rep_joins_probe",
                generate: |p| {
                    gen(
                        p,
                        crate::column::fcc_rep_joins_probe::FccRepJoinsProbe::new(p),
                        "fcc_rep_joins_probe",
                    )
                },
                waivers: lint::rep_joins_waivers,
            },
        }
    }

    /// The module's name before the configuration suffix, and the stem of
    /// its files (`<name>.v`, `<name>.vlt`).
    pub fn name(self) -> &'static str {
        self.row().name
    }

    /// The module when generated alone for `p`: `fcc_regs_k7_1b2c3d4e`.
    pub fn module(self, p: &FccParams) -> String {
        format!("{}{}", self.name(), p.module_suffix())
    }

    /// The block's Verilog for the build `p`, as the module [`Self::module`].
    pub fn generate(self, p: &FccParams) -> Result<String, RtlError> {
        p.validate_for_hardware()?;
        (self.row().generate)(p)
    }

    /// The Verilator waivers of the block's file (`verilator --lint-only
    /// -Wall` passes with them).
    pub fn waivers(self, p: &FccParams) -> String {
        let row = self.row();
        (row.waivers)(p, row.name)
    }
}
