//! `fcc_label_update`: the frame buffer and the label read-back.
//!
//! Provisional labels are non-decreasing in raster order and a new label is
//! taken exactly where a labelled run starts, so the frame buffer does not
//! store labels: it stores a 2-bit code per pixel (0 empty, 1 continues the
//! run, 2 starts a labelled run, 3 starts an unlabelled run), four pixels per
//! word. At read-back the k-th code 2 *is* provisional label k. The merge
//! table's flatten pass emits the compact label of 1, 2, 3, ... in that same
//! order into an eight-entry queue (the gearbox), so the read-back never
//! looks a label up; it starts as soon as flatten starts.
//!
//! Sub-blocks, in pipeline order:
//! - `fcc_fb_writer` packs the codes into frame-buffer words (`fcc_ram`);
//! - `fcc_rb_pipeline` reads a beat's word and decodes it (stages 0 .. 3);
//! - `fcc_beat_queue` holds up to five decoded beats (a head register and a
//!   ring of four);
//! - `fcc_gearbox` holds the compact labels flatten emits;
//! - `fcc_beat_assembly` gives the head beat its labels (`fcc_slot_mux` per
//!   slot) and holds the output register.
//!
//! Output: `L` labels per beat in 16-bit slots from bit 0, `tkeep` marking
//! the bytes of the slots that hold labels, `tlast` on the frame's last beat.
//!
//! Reset: `rst` is the reset one cycle ahead. The sub-blocks take registered
//! copies of it (`FccKeepReg`), one per group of at most 64 reset loads (see
//! `RESET_COPIES`), and are in reset in the cycle after `rst`.

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use crate::fcc_beat_assembly::FccBeatAssembly;
use crate::fcc_beat_queue::FccBeatQueue;
use crate::fcc_fb_writer::FccFbWriter;
use crate::fcc_gearbox::FccGearbox;
use crate::fcc_keep_reg::FccKeepReg;
use crate::fcc_pop_decision::FccPopDecision;
use crate::fcc_ram::FccRam;
use crate::fcc_rb_pipeline::FccRbPipeline;
use crate::types::FbWord;

/// Registered copies of the reset: the writer; the read-back pipeline and
/// the beat queue; the gearbox's control and front labels; its slots 0 .. 3;
/// its slots 4 .. 7; the beat assembly's control and carried run; its
/// collected labels.
const RESET_COPIES: usize = 7;

#[derive(LogicBlock)]
pub struct FccLabelUpdate {
    pub clk: Signal<In, Clock>,
    /// Reset, one cycle ahead of the sub-blocks' (see the module doc).
    pub rst: Signal<In, Bit>,
    // Frame-buffer writes from the labelled pixel stream.
    pub wr_valid: Signal<In, Bit>,
    pub wr_state: Signal<In, Bits<2>>,
    pub wr_last: Signal<In, Bit>,
    // Read-back.
    pub rb_start: Signal<In, Bit>,
    pub fv: Signal<In, Bit>,
    pub fval: Signal<In, Bits<16>>,
    /// Compact labels waiting in the gearbox (registered).
    pub gear_used: Signal<Out, Bits<4>>,
    pub m_axis_tdata: Signal<Out, Bits<64>>,
    pub m_axis_tkeep: Signal<Out, Bits<8>>,
    pub m_axis_tvalid: Signal<Out, Bit>,
    pub m_axis_tlast: Signal<Out, Bit>,
    pub m_axis_tready: Signal<In, Bit>,
    pub rb_done: Signal<Out, Bit>,
    /// Cycles in which the head beat waited for compact labels.
    pub gear_stalls: Signal<Out, Bits<24>>,
    rst_copy: Vec<FccKeepReg<Bit>>,
    writer: FccFbWriter,
    fb: FccRam<FbWord, 17>,
    pipeline: FccRbPipeline,
    queue: FccBeatQueue,
    gearbox: FccGearbox,
    /// The gearbox's copy of the pop decision, from kept copies of the head
    /// beat's state and of `taken` (the assembly has its own copy).
    gear_decision: FccPopDecision,
    assembly: FccBeatAssembly,
}

impl FccLabelUpdate {
    pub fn new(p: &FccParams) -> Self {
        let l = p.labels_per_beat as usize;
        let words = p.pixels().div_ceil(4);
        Self {
            clk: Default::default(),
            rst: Default::default(),
            wr_valid: Default::default(),
            wr_state: Default::default(),
            wr_last: Default::default(),
            rb_start: Default::default(),
            fv: Default::default(),
            fval: Default::default(),
            gear_used: Default::default(),
            m_axis_tdata: Default::default(),
            m_axis_tkeep: Default::default(),
            m_axis_tvalid: Default::default(),
            m_axis_tlast: Default::default(),
            m_axis_tready: Default::default(),
            rb_done: Default::default(),
            gear_stalls: Default::default(),
            rst_copy: (0..RESET_COPIES).map(|_| FccKeepReg::default()).collect(),
            writer: FccFbWriter::new(l),
            fb: FccRam::new(words.max(2)),
            pipeline: FccRbPipeline::new(l),
            queue: FccBeatQueue::new(),
            gearbox: FccGearbox::new(),
            gear_decision: Default::default(),
            assembly: FccBeatAssembly::new(),
        }
    }
}

impl Logic for FccLabelUpdate {
    #[hdl_gen]
    fn update(&mut self) {
        self.writer.clk.next = self.clk.val();
        self.fb.clk.next = self.clk.val();
        self.pipeline.clk.next = self.clk.val();
        self.queue.clk.next = self.clk.val();
        self.gearbox.clk.next = self.clk.val();
        self.assembly.clk.next = self.clk.val();
        for i in 0..7 {
            self.rst_copy[i].clock.next = self.clk.val();
            self.rst_copy[i].d.next = self.rst.val();
        }
        self.writer.rst.next = self.rst_copy[0].q.val();
        self.pipeline.rst.next = self.rst_copy[1].q.val();
        self.queue.rst.next = self.rst_copy[1].q.val();
        self.gearbox.rst.next = self.rst_copy[2].q.val();
        self.gearbox.rst_low_slots.next = self.rst_copy[3].q.val();
        self.gearbox.rst_high_slots.next = self.rst_copy[4].q.val();
        self.assembly.rst.next = self.rst_copy[5].q.val();
        self.assembly.rst_collected.next = self.rst_copy[6].q.val();
        // ---- Frame-buffer writes.
        self.writer.pixel_valid.next = self.wr_valid.val();
        self.writer.pixel_code.next = self.wr_state.val();
        self.writer.pixel_last.next = self.wr_last.val();
        self.fb.write_en.next = self.writer.write_en.val();
        self.fb.write_addr.next = self.writer.write_addr.val();
        self.fb.write_data.next = self.writer.write_data.val();
        // ---- Read-back pipeline: frame-buffer reads to decoded beats.
        self.pipeline.start.next = self.rb_start.val();
        self.pipeline.beats_m1.next = self.writer.beats_m1.val();
        self.pipeline.last_beat_labels.next = self.writer.last_beat_labels.val();
        self.pipeline.beat_done.next = self.assembly.head_done.val();
        self.fb.read_en.next = self.pipeline.read_en.val();
        self.fb.read_addr.next = self.pipeline.read_addr.val();
        self.pipeline.read_data.next = self.fb.read_data.val();
        // ---- Decoded-beat queue.
        self.queue.clear.next = self.rb_start.val();
        self.queue.in_valid.next = self.pipeline.beat_valid.val();
        self.queue.in_beat.next = self.pipeline.beat.val();
        self.queue.pop.next = self.assembly.head_done.val();
        // ---- Gearbox: compact labels from flatten.
        self.gearbox.clear.next = self.rb_start.val();
        self.gearbox.push_valid.next = self.fv.val();
        self.gearbox.push_label.next = self.fval.val();
        self.gear_decision.head_valid.next = self.queue.head_valid_copy.val();
        self.gear_decision.need.next = self.queue.head_need_copy.val();
        self.gear_decision.taken.next = self.assembly.taken_copy.val();
        self.gear_decision.has_one.next = self.gearbox.has_one.val();
        self.gear_decision.has_two.next = self.gearbox.has_two.val();
        self.gearbox.pop.next = self.gear_decision.pop.val();
        self.gearbox.pop_two.next = self.gear_decision.pop_two.val();
        self.gear_used.next = self.gearbox.used.val();
        // ---- The head beat's labels and the output register.
        self.assembly.clear.next = self.rb_start.val();
        self.assembly.head_valid.next = self.queue.head_valid.val();
        self.assembly.head.next = self.queue.head.val();
        self.assembly.gear_front.next = self.gearbox.front.val();
        self.assembly.gear_second.next = self.gearbox.second.val();
        self.assembly.gear_has_one.next = self.gearbox.has_one_copy.val();
        self.assembly.gear_has_two.next = self.gearbox.has_two_copy.val();
        self.assembly.m_axis_tready.next = self.m_axis_tready.val();
        self.m_axis_tdata.next = self.assembly.m_axis_tdata.val();
        self.m_axis_tkeep.next = self.assembly.m_axis_tkeep.val();
        self.m_axis_tvalid.next = self.assembly.m_axis_tvalid.val();
        self.m_axis_tlast.next = self.assembly.m_axis_tlast.val();
        self.rb_done.next = self.assembly.frame_sent.val();
        self.gear_stalls.next = self.assembly.gear_stalls.val();
    }
}
