//! The virtual board: a model of the AXI DMA's direct-register (simple)
//! mode (PG021) and of memory, wired to the Verilator model of `fcc_top`
//! (AXI4-Lite, both AXI4-Stream ports and `irq`), behind the driver's
//! [`Hal`], so `fcc_driver::Driver` runs here exactly as on a board:
//! cycle-accurate on the core's side.
//!
//! One clock drives everything. Each cycle the DMA model offers the next
//! pixel beat (MM2S) and takes label or record beats (S2MM) from the core; register
//! accesses to the core go through its AXI4-Lite slave (a few cycles each),
//! accesses to the DMA take [`DMA_ACCESS_CYCLES`]. The CPU's cache is
//! modelled by buffers that hold the CPU's view apart from memory: a driver
//! that forgets a cache clean sends stale pixels, one that forgets an
//! invalidate reads stale labels.
//!
//! [`Fault`]s make the DMA fail the way hardware does: a decode or slave
//! error on a memory access, a frame shorter than its length, an S2MM
//! channel that never takes a beat; [`VirtualBoard::leave_core_mid_frame`]
//! leaves the core in the middle of a frame as an aborted earlier run would.

use std::sync::Arc;

use fcc_driver::{dma, Channel, DmaBuffer, Hal, Window, DMA_ALIGN};
use fcc_golden::Frame;

use crate::axil::{AxilM, AxilMaster, AxilPort, AxilS};
use crate::model::{Dut, FccIn, FccOut, Model};
use crate::SimError;

/// Cycles one access to the DMA's registers takes (interconnect and slave).
pub const DMA_ACCESS_CYCLES: u64 = 4;
/// Cycles the DMA's soft reset takes before DMACR.Reset reads 0 again.
pub const DMA_RESET_CYCLES: u32 = 16;
/// Bus address of the modelled memory.
pub const MEM_BASE: u64 = 0x1000_0000;
/// What unwritten memory holds (so labels never written show).
const MEM_FILL: u8 = 0xa5;

/// A failure the DMA model injects.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Fault {
    /// The memory access of beat `beat` of the channel's next transfer
    /// answers DECERR (DMASR.DMADecErr).
    DecodeError { channel: Channel, beat: usize },
    /// As `DecodeError`, answering SLVERR (DMASR.DMASlvErr).
    SlaveError { channel: Channel, beat: usize },
    /// The next MM2S transfer ends its packet (`tlast`) after `beats` beats,
    /// as a transfer given a shorter length would: a frame shorter than the
    /// core's rows x cols.
    ShortFrame { beats: usize },
    /// S2MM never takes a beat (a stuck downstream) until the DMA is reset.
    StuckS2mm,
}

#[derive(Debug, Clone, Default)]
struct Chan {
    cr: u32,
    sr: u32,
    addr_lo: u32,
    addr_hi: u32,
    length: u32,
    active: bool,
    /// Beats moved in the current transfer (S2MM: bytes received in `bytes`).
    beats: usize,
    bytes: u32,
    /// MM2S: beats of the current transfer.
    total: usize,
    /// A memory error armed for this transfer: (beat, DMASR bit).
    error_at: Option<(usize, u32)>,
}

impl Chan {
    fn reset() -> Chan {
        Chan {
            cr: dma::CR_RESET_VALUE,
            sr: dma::SR_RESET_VALUE,
            ..Chan::default()
        }
    }

    fn addr(&self) -> u64 {
        (u64::from(self.addr_hi) << 32) | u64::from(self.addr_lo)
    }

    /// Stop with an error: PG021, errors are fatal and halt the channel.
    fn fail(&mut self, bit: u32) {
        self.sr |= bit | dma::SR_ERR_IRQ | dma::SR_HALTED;
        self.sr &= !dma::SR_IDLE;
        self.cr &= !dma::CR_RS;
        self.active = false;
    }

    fn complete(&mut self) {
        self.active = false;
        self.sr |= dma::SR_IDLE | dma::SR_IOC_IRQ;
    }

    fn irq(&self) -> bool {
        (self.sr & dma::SR_IOC_IRQ != 0 && self.cr & dma::CR_IOC_IRQ_EN != 0)
            || (self.sr & dma::SR_ERR_IRQ != 0 && self.cr & dma::CR_ERR_IRQ_EN != 0)
    }
}

/// The AXI DMA in simple mode: MM2S and S2MM register sets and engines.
#[derive(Debug, Clone)]
pub struct AxiDmaModel {
    mm2s: Chan,
    s2mm: Chan,
    /// Cycles left of a soft reset in progress.
    resetting: u32,
    /// Width of the length registers (`c_sg_length_width`).
    pub length_bits: u32,
    faults: Vec<Fault>,
    stuck_s2mm: bool,
}

impl AxiDmaModel {
    pub fn new(length_bits: u32) -> Self {
        AxiDmaModel {
            mm2s: Chan::reset(),
            s2mm: Chan::reset(),
            resetting: 0,
            length_bits,
            faults: Vec::new(),
            stuck_s2mm: false,
        }
    }

    /// The interrupt outputs (`mm2s_introut`, `s2mm_introut`).
    pub fn irqs(&self) -> (bool, bool) {
        (self.mm2s.irq(), self.s2mm.irq())
    }

    fn do_reset(&mut self) {
        self.mm2s = Chan::reset();
        self.s2mm = Chan::reset();
        self.stuck_s2mm = false;
        self.resetting = DMA_RESET_CYCLES;
    }

    /// A register read.
    pub fn read(&self, off: u32) -> u32 {
        let resetting = if self.resetting > 0 { dma::CR_RESET } else { 0 };
        match off {
            dma::MM2S_DMACR => self.mm2s.cr | resetting,
            dma::MM2S_DMASR => self.mm2s.sr,
            dma::MM2S_SA => self.mm2s.addr_lo,
            dma::MM2S_SA_MSB => self.mm2s.addr_hi,
            dma::MM2S_LENGTH => self.mm2s.length,
            dma::S2MM_DMACR => self.s2mm.cr | resetting,
            dma::S2MM_DMASR => self.s2mm.sr,
            dma::S2MM_DA => self.s2mm.addr_lo,
            dma::S2MM_DA_MSB => self.s2mm.addr_hi,
            dma::S2MM_LENGTH => self.s2mm.length,
            _ => 0,
        }
    }

    /// A register write.
    pub fn write(&mut self, off: u32, v: u32) {
        if self.resetting > 0 {
            return;
        }
        let mask = ((1u64 << self.length_bits) - 1) as u32;
        let is_mm2s = off < dma::S2MM_DMACR;
        let faults = &mut self.faults;
        let stuck = &mut self.stuck_s2mm;
        let ch = if is_mm2s {
            &mut self.mm2s
        } else {
            &mut self.s2mm
        };
        match off {
            dma::MM2S_DMACR | dma::S2MM_DMACR => {
                if v & dma::CR_RESET != 0 {
                    self.do_reset();
                    return;
                }
                let was = ch.cr & dma::CR_RS != 0;
                ch.cr = v;
                if v & dma::CR_RS != 0 && !was {
                    ch.sr &= !dma::SR_HALTED;
                } else if v & dma::CR_RS == 0 && was {
                    ch.active = false;
                    ch.sr |= dma::SR_HALTED;
                }
            }
            dma::MM2S_DMASR | dma::S2MM_DMASR => ch.sr &= !(v & dma::SR_IRQS),
            dma::MM2S_SA | dma::S2MM_DA => ch.addr_lo = v,
            dma::MM2S_SA_MSB | dma::S2MM_DA_MSB => ch.addr_hi = v,
            dma::MM2S_LENGTH | dma::S2MM_LENGTH => {
                let len = v & mask;
                if ch.cr & dma::CR_RS == 0 || ch.sr & dma::SR_HALTED != 0 || len == 0 {
                    return;
                }
                ch.length = len;
                ch.active = true;
                ch.sr &= !dma::SR_IDLE;
                ch.beats = 0;
                ch.bytes = 0;
                ch.total = (len as usize).div_ceil(8);
                ch.error_at = None;
                let here = if is_mm2s {
                    Channel::Mm2s
                } else {
                    Channel::S2mm
                };
                faults.retain(|f| match *f {
                    Fault::DecodeError { channel, beat } if channel == here => {
                        ch.error_at = Some((beat, dma::SR_DMA_DEC_ERR));
                        false
                    }
                    Fault::SlaveError { channel, beat } if channel == here => {
                        ch.error_at = Some((beat, dma::SR_DMA_SLV_ERR));
                        false
                    }
                    Fault::ShortFrame { beats } if is_mm2s => {
                        ch.total = ch.total.min(beats.max(1));
                        false
                    }
                    Fault::StuckS2mm if !is_mm2s => {
                        *stuck = true;
                        false
                    }
                    _ => true,
                });
            }
            _ => {}
        }
    }
}

/// Memory at [`MEM_BASE`]; addresses outside it decode to nothing.
#[derive(Debug, Clone)]
struct Memory {
    data: Vec<u8>,
    next: u64,
}

impl Memory {
    fn range(&self, addr: u64, len: usize) -> Option<std::ops::Range<usize>> {
        let start = usize::try_from(addr.checked_sub(MEM_BASE)?).ok()?;
        let end = start.checked_add(len)?;
        (end <= self.data.len()).then_some(start..end)
    }
}

/// The core, the DMA and memory on one clock.
struct System {
    dut: Dut,
    dma: AxiDmaModel,
    mem: Memory,
}

impl System {
    /// One clock cycle with `axil` on the core's register port.
    fn cycle(&mut self, axil: &AxilM) -> FccOut {
        let busy = self.dma.resetting > 0;
        // MM2S: the next pixel beat from memory, or an error.
        let mut beat = None;
        let ch = &mut self.dma.mm2s;
        if ch.active && !busy {
            let addr = ch.addr() + 8 * ch.beats as u64;
            match ch.error_at {
                Some((b, bit)) if b == ch.beats => ch.fail(bit),
                _ => match self.mem.range(addr, 8) {
                    None => ch.fail(dma::SR_DMA_DEC_ERR),
                    Some(r) => {
                        let mut w = [0u8; 8];
                        w.copy_from_slice(&self.mem.data[r]);
                        beat = Some((u64::from_le_bytes(w), ch.beats + 1 == ch.total));
                    }
                },
            }
        }
        let s2mm_ready = self.dma.s2mm.active && !busy && !self.dma.stuck_s2mm;
        let (tdata, tlast) = beat.unwrap_or((0, false));
        let streams = FccIn {
            s_axis_tdata: tdata,
            s_axis_tvalid: u8::from(beat.is_some()),
            s_axis_tlast: u8::from(tlast),
            m_axis_tready: u8::from(s2mm_ready),
            ..Default::default()
        };
        let out = self
            .dut
            .step(&crate::axil::axil_inputs!(FccIn, axil, streams));
        if beat.is_some() && out.s_axis_tready != 0 {
            let ch = &mut self.dma.mm2s;
            ch.beats += 1;
            if ch.beats == ch.total {
                ch.complete();
            }
        }
        if s2mm_ready && out.m_axis_tvalid != 0 {
            self.s2mm_take(&out);
        }
        if self.dma.resetting > 0 {
            self.dma.resetting -= 1;
        }
        out
    }

    /// S2MM takes one label beat: its kept bytes go to memory.
    fn s2mm_take(&mut self, out: &FccOut) {
        let ch = &mut self.dma.s2mm;
        if matches!(ch.error_at, Some((b, _)) if b == ch.beats) {
            let bit = ch.error_at.map_or(dma::SR_DMA_DEC_ERR, |e| e.1);
            ch.fail(bit);
            return;
        }
        let bytes = out.m_axis_tdata.to_le_bytes();
        let kept: Vec<u8> = (0..8)
            .filter(|b| out.m_axis_tkeep >> b & 1 != 0)
            .map(|b| bytes[b])
            .collect();
        if ch.bytes as usize + kept.len() > ch.length as usize {
            // PG021, simple mode: a packet longer than the buffer.
            ch.fail(dma::SR_DMA_INT_ERR);
            return;
        }
        let addr = ch.addr() + u64::from(ch.bytes);
        match self.mem.range(addr, kept.len()) {
            None => ch.fail(dma::SR_DMA_DEC_ERR),
            Some(r) => {
                self.mem.data[r].copy_from_slice(&kept);
                ch.bytes += kept.len() as u32;
                ch.beats += 1;
                if out.m_axis_tlast != 0 {
                    ch.length = ch.bytes;
                    ch.complete();
                }
            }
        }
    }
}

impl AxilPort for System {
    fn axil_cycle(&mut self, m: &AxilM) -> AxilS {
        let o = self.cycle(m);
        crate::axil::axil_outputs!(o)
    }
}

/// A DMA buffer of the virtual board: the CPU's (cached) view and its
/// address in the modelled memory.
#[derive(Debug, Clone)]
pub struct VBuffer {
    phys: u64,
    cpu: Vec<u8>,
}

impl DmaBuffer for VBuffer {
    fn phys(&self) -> u64 {
        self.phys
    }
    fn bytes(&self) -> &[u8] {
        &self.cpu
    }
    fn bytes_mut(&mut self) -> &mut [u8] {
        &mut self.cpu
    }
}

/// The core's Verilator model with a modelled AXI DMA and memory.
pub struct VirtualBoard {
    sys: System,
    axil: AxilMaster,
    clock_mhz: f64,
}

impl VirtualBoard {
    /// A board around a fresh instance of `model` (held in reset for a few
    /// cycles), with `mem_bytes` of memory and a DMA whose length registers
    /// have `length_bits` bits.
    pub fn new(model: Arc<Model>, length_bits: u32, mem_bytes: usize) -> Self {
        let clock_mhz = model.params.clock_mhz;
        let mut dut = Dut::new(model);
        dut.reset(4);
        VirtualBoard {
            sys: System {
                dut,
                dma: AxiDmaModel::new(length_bits),
                mem: Memory {
                    data: vec![MEM_FILL; mem_bytes],
                    next: MEM_BASE,
                },
            },
            axil: AxilMaster::new(0),
            clock_mhz,
        }
    }

    /// Memory for the driver's two buffers of the largest frame (pixels in;
    /// labels, or a frame of records for the column core, out) and some
    /// slack.
    pub fn mem_for(p: &fcc_params::FccParams) -> usize {
        let px = p.pixels();
        let out = match p.scan {
            fcc_params::Scan::Row => fcc_driver::label_buffer_bytes(px),
            fcc_params::Scan::Column => fcc_driver::record_buffer_bytes(px),
        };
        px * fcc_pixel::PIXEL_BYTES + out + 4 * DMA_ALIGN
    }

    /// Inject a fault (taken by the next transfer of its channel).
    pub fn inject(&mut self, f: Fault) {
        self.sys.dma.faults.push(f);
    }

    /// Clock cycles simulated so far.
    pub fn cycles(&self) -> u64 {
        self.sys.dut.cycle
    }

    pub fn clock_mhz(&self) -> f64 {
        self.clock_mhz
    }

    /// The DMA model (registers and interrupt lines).
    pub fn dma(&self) -> &AxiDmaModel {
        &self.sys.dma
    }

    /// Feed the first `beats` pixels of `frame` straight into the core and
    /// stop, without `tlast`: the state an earlier run leaves when its DMA
    /// is stopped in the middle of a frame.
    pub fn leave_core_mid_frame(&mut self, frame: &Frame, beats: usize) -> Result<(), SimError> {
        self.sys
            .dut
            .feed_partial(frame, beats, 10 * beats as u64 + 100_000)
    }

    fn cycles_for_us(&self, us: u64) -> u64 {
        (us as f64 * self.clock_mhz).ceil() as u64
    }
}

impl Hal for VirtualBoard {
    type Buffer = VBuffer;
    type Error = SimError;

    fn read32(&mut self, w: Window, offset: u32) -> Result<u32, SimError> {
        match w {
            Window::Core => self.axil.read(&mut self.sys, offset),
            Window::Dma => {
                for _ in 0..DMA_ACCESS_CYCLES {
                    self.sys.cycle(&AxilM::default());
                }
                Ok(self.sys.dma.read(offset))
            }
        }
    }

    fn write32(&mut self, w: Window, offset: u32, value: u32) -> Result<(), SimError> {
        match w {
            Window::Core => self.axil.write_ok(&mut self.sys, offset, value),
            Window::Dma => {
                for _ in 0..DMA_ACCESS_CYCLES {
                    self.sys.cycle(&AxilM::default());
                }
                self.sys.dma.write(offset, value);
                Ok(())
            }
        }
    }

    fn alloc_dma(&mut self, len: usize) -> Result<VBuffer, SimError> {
        let mem = &mut self.sys.mem;
        let phys = mem.next.div_ceil(DMA_ALIGN as u64) * DMA_ALIGN as u64;
        if mem.range(phys, len).is_none() {
            return Err(SimError::Board(format!(
                "out of DMA memory: {len} bytes asked, {} of {} in use",
                mem.next - MEM_BASE,
                mem.data.len()
            )));
        }
        mem.next = phys + len as u64;
        Ok(VBuffer {
            phys,
            cpu: vec![0; len],
        })
    }

    fn cache_clean(
        &mut self,
        buf: &mut VBuffer,
        offset: usize,
        len: usize,
    ) -> Result<(), SimError> {
        let r = self.buffer_range(buf, offset, len)?;
        self.sys.mem.data[r].copy_from_slice(&buf.cpu[offset..offset + len]);
        Ok(())
    }

    fn cache_invalidate(
        &mut self,
        buf: &mut VBuffer,
        offset: usize,
        len: usize,
    ) -> Result<(), SimError> {
        let r = self.buffer_range(buf, offset, len)?;
        buf.cpu[offset..offset + len].copy_from_slice(&self.sys.mem.data[r]);
        Ok(())
    }

    fn wait_irq(&mut self, timeout_us: u64) -> Result<bool, SimError> {
        for _ in 0..self.cycles_for_us(timeout_us) {
            if self.sys.cycle(&AxilM::default()).irq != 0 {
                return Ok(true);
            }
        }
        Ok(false)
    }

    fn now_ns(&mut self) -> u64 {
        (self.sys.dut.cycle as f64 * 1000.0 / self.clock_mhz) as u64
    }
}

impl VirtualBoard {
    fn buffer_range(
        &self,
        buf: &VBuffer,
        offset: usize,
        len: usize,
    ) -> Result<std::ops::Range<usize>, SimError> {
        if offset + len > buf.cpu.len() {
            return Err(SimError::Board(format!(
                "cache operation on bytes {offset}..{} of a {}-byte buffer",
                offset + len,
                buf.cpu.len()
            )));
        }
        self.sys
            .mem
            .range(buf.phys + offset as u64, len)
            .ok_or_else(|| SimError::Board("a buffer outside memory".into()))
    }
}

/// What a driver expects of the build `p` on the virtual board: the hash,
/// the DMA's length width as `fcc gen` sets it
/// (`fcc_rtl::vivado::dma_length_width`) and the address width of the
/// ZC706's DMA, which the virtual board models (memory below 4 GiB).
pub fn build_expect(p: &fcc_params::FccParams) -> Result<fcc_driver::BuildExpect, SimError> {
    build_expect_for(p, fcc_rtl::vivado::Board::Zc706)
}

/// [`build_expect`] for the block design of `board`: its DMA's address
/// width comes from the board table (40 bits on the ZCU104).
pub fn build_expect_for(
    p: &fcc_params::FccParams,
    board: fcc_rtl::vivado::Board,
) -> Result<fcc_driver::BuildExpect, SimError> {
    let gen = fcc_rtl::generate(p)?;
    let ports = fcc_rtl::vivado::top_ports(&gen.verilog, &fcc_rtl::top_module(p));
    Ok(fcc_driver::BuildExpect {
        hash: fcc_rtl::regmap::hash_value(p),
        dma_length_bits: fcc_rtl::vivado::dma_length_width(p, &ports)?,
        dma_addr_bits: board.info().ps.info().dma_addr_width,
        column: p.scan == fcc_params::Scan::Column,
    })
}

/// A virtual board for the build `p` (its Verilator model built on first
/// use and cached, see [`crate::load`]) and the driver's expectations of it.
pub fn virtual_board(
    p: &fcc_params::FccParams,
) -> Result<(VirtualBoard, fcc_driver::BuildExpect), SimError> {
    virtual_board_with(p, crate::load(p)?)
}

/// A virtual board around `model`, the Verilator model of the build `p`
/// (from [`crate::load`] or [`crate::load_dir`]), and the driver's
/// expectations of it.
pub fn virtual_board_with(
    p: &fcc_params::FccParams,
    model: std::sync::Arc<crate::Model>,
) -> Result<(VirtualBoard, fcc_driver::BuildExpect), SimError> {
    let expect = build_expect(p)?;
    let board = VirtualBoard::new(model, expect.dma_length_bits, VirtualBoard::mem_for(p));
    Ok((board, expect))
}

/// The run parameters of `p` (for a core built from `p`: its power-on
/// run values).
pub fn build_run(p: &fcc_params::FccParams) -> fcc_driver::RunConfig {
    let q = |v: i64| u32::try_from(v).unwrap_or(u32::MAX);
    fcc_driver::RunConfig {
        rows: p.rows as u32,
        cols: p.cols as u32,
        k: p.fsize as u32,
        th_h_q: q(p.th_h_q()),
        th_v_q: q(p.th_v_q()),
        th_h_slope_q: q(p.th_h_slope_q()),
        th_v_slope_q: q(p.th_v_slope_q()),
        limits: (p.scan == fcc_params::Scan::Column).then(|| {
            let [bridge, ring_reach, open_limit] =
                fcc_rtl::regmap::stream_limit_values(p).map(|(_, _, v)| v);
            fcc_driver::StreamLimits {
                bridge,
                ring_reach,
                open_limit,
            }
        }),
    }
}
