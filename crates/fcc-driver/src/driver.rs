//! The driver proper: open, program, run a frame, recover.

use fcc_pixel::{label_of_beat, pixel_beat, quantize_point, Point, LABEL_BEAT_BYTES, PIXEL_BYTES};
use fcc_regmap::{bits, offset, ID_MAGIC};

use crate::dma;
use crate::error::{Channel, DmaCause, Error, RefusedBits};
use crate::hal::{DmaBuffer, Hal, Window, DMA_ALIGN};

/// Labels per output beat the driver takes: the AXI DMA's S2MM channel needs
/// every beat of a packet whole except the last, so every slot of a beat
/// must hold a label.
pub const LABELS_PER_BEAT: u32 = 4;
/// Every bit of the ERROR register (one per run register).
const ERROR_ALL: u32 = bits::ERROR_K
    | bits::ERROR_TH_H
    | bits::ERROR_TH_V
    | bits::ERROR_ROWS
    | bits::ERROR_COLS
    | bits::ERROR_SLOPE_H
    | bits::ERROR_SLOPE_V;
/// Bytes of one label in the S2MM buffer.
const LABEL_BYTES: usize = 2;

/// The parameters one frame runs with (the run registers of the core).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RunConfig {
    pub rows: u32,
    pub cols: u32,
    /// Filter size K (odd).
    pub k: u32,
    /// Thresholds in Q7.8 (`fcc_params::quantize_threshold`).
    pub th_h_q: u32,
    pub th_v_q: u32,
    /// Threshold slopes in UQ0.16 (`fcc_params::quantize_slope`; 0: the
    /// threshold is fixed).
    pub th_h_slope_q: u32,
    pub th_v_slope_q: u32,
}

impl RunConfig {
    pub fn pixels(&self) -> usize {
        self.rows as usize * self.cols as usize
    }
}

/// What the software knows of the build it expects (from the build's
/// `fcc_params.json` / `fcc_regs.h` and its block design).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct BuildExpect {
    /// The parameter hash (`FCC_PARAMS_HASH`).
    pub hash: u64,
    /// Bits of the AXI DMA's length registers (`c_sg_length_width`).
    pub dma_length_bits: u32,
    /// Bits of the AXI DMA's addresses (`c_addr_width`), from the board
    /// table (`fcc_rtl::vivado::PsInfo::dma_addr_width`): 32 on the Zynq-7000
    /// boards, 40 on the ZCU104. Above 32 the driver writes the MSB halves
    /// of the address registers (PG021 MM2S_SA_MSB, S2MM_DA_MSB), which a
    /// 32-bit DMA does not have.
    pub dma_addr_bits: u32,
}

/// The build as the core reports it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct BuildInfo {
    /// Generator version, major << 16 | minor << 8 | patch.
    pub version: u32,
    pub hash: u64,
    pub k_max: u32,
    pub rows_max: u32,
    pub cols_max: u32,
    pub label_bits: u32,
    pub labels_per_beat: u32,
    pub clock_khz: u32,
}

/// How long the driver waits, microseconds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Timeouts {
    /// From the start of the DMA to the core's frame-done interrupt.
    pub frame_us: u64,
    /// From the interrupt to S2MM idle (its last writes landing).
    pub dma_done_us: u64,
    /// For the DMA's reset and the core's table initialisation after a
    /// soft reset.
    pub reset_us: u64,
    /// The DMA's status is checked for errors this often while waiting.
    pub poll_us: u64,
}

impl Timeouts {
    /// Generous limits for a build: four times the cycles of the largest
    /// frame (the core needs about 1.3 x R x C) plus the table
    /// initialisation, and fixed margins.
    pub fn for_build(b: &BuildInfo) -> Timeouts {
        let mhz = u64::from(b.clock_khz.max(1000)) / 1000;
        let pixels = u64::from(b.rows_max) * u64::from(b.cols_max);
        let init_us = (1u64 << b.label_bits) / mhz + 1;
        Timeouts {
            frame_us: 4 * pixels / mhz + init_us + 200,
            dma_done_us: 100,
            reset_us: init_us + 100,
            poll_us: 100,
        }
    }
}

/// The status the core latched at the frame's end.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct FrameStatus {
    pub frame_count: u32,
    pub clusters: u32,
    pub provisional: u32,
    pub unlabelled: u32,
    pub overflow: bool,
    pub joins: u32,
    pub gear_stalls: u32,
}

/// One frame's result (the labels are in the caller's buffer).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FrameReport {
    pub status: FrameStatus,
    /// From the start of MM2S to S2MM idle, on the platform's clock.
    pub time_ns: u64,
}

/// A frame's pixels, row-major, before quantisation (metres; a pixel is
/// empty when a coordinate is not finite or out of the Q7.8 range) or
/// already quantised.
#[derive(Debug, Clone, Copy)]
pub enum Pixels<'a> {
    XyzF32(&'a [f32]),
    XyzF64(&'a [f64]),
    Points(&'a [Option<Point>]),
}

impl Pixels<'_> {
    fn len(&self) -> usize {
        match self {
            Pixels::XyzF32(v) => v.len() / 3,
            Pixels::XyzF64(v) => v.len() / 3,
            Pixels::Points(v) => v.len(),
        }
    }

    fn exact(&self) -> bool {
        match self {
            Pixels::XyzF32(v) => v.len() % 3 == 0,
            Pixels::XyzF64(v) => v.len() % 3 == 0,
            Pixels::Points(_) => true,
        }
    }

    /// Quantise (the golden model's rule, `fcc_pixel::quantize_point`) and
    /// pack into `out`, 8 bytes per pixel, little-endian.
    fn pack(&self, out: &mut [u8]) {
        let put = |i: usize, out: &mut [u8], p: Option<Point>| {
            out[i * PIXEL_BYTES..(i + 1) * PIXEL_BYTES]
                .copy_from_slice(&pixel_beat(p).to_le_bytes());
        };
        match self {
            Pixels::XyzF32(v) => {
                for (i, c) in v.chunks_exact(3).enumerate() {
                    let p = quantize_point(f64::from(c[0]), f64::from(c[1]), f64::from(c[2]));
                    put(i, out, p);
                }
            }
            Pixels::XyzF64(v) => {
                for (i, c) in v.chunks_exact(3).enumerate() {
                    put(i, out, quantize_point(c[0], c[1], c[2]));
                }
            }
            Pixels::Points(v) => {
                for (i, p) in v.iter().enumerate() {
                    put(i, out, *p);
                }
            }
        }
    }
}

fn round_up(n: usize) -> usize {
    n.div_ceil(DMA_ALIGN) * DMA_ALIGN
}

/// Bytes of the S2MM buffer for `pixels` labels (whole beats).
fn label_buffer_bytes(pixels: usize) -> usize {
    pixels.div_ceil(LABELS_PER_BEAT as usize) * LABEL_BEAT_BYTES
}

/// The FCC core and its AXI DMA, through a [`Hal`].
pub struct Driver<H: Hal> {
    hal: H,
    build: BuildInfo,
    defaults: RunConfig,
    length_bits: u32,
    addr_bits: u32,
    pub timeouts: Timeouts,
    tx: H::Buffer,
    rx: H::Buffer,
}

type Res<T, H> = Result<T, Error<<H as Hal>::Error>>;

impl<H: Hal> Driver<H> {
    /// Find the core (ID word), check its parameter hash, reset the DMA,
    /// enable the interrupt and allocate the frame buffers for the build's
    /// largest frame. A core left in the middle of a frame is not reset
    /// here: [`Driver::core_busy`] tells, [`Driver::recover`] resets it (and
    /// [`Driver::run_frame`] refuses to start on it).
    pub fn open(mut hal: H, expect: &BuildExpect) -> Res<Self, H> {
        let id = hal.read32(Window::Core, offset::ID)?;
        if id != ID_MAGIC {
            return Err(Error::NotFcc { id });
        }
        let lo = hal.read32(Window::Core, offset::HASH_LO)?;
        let hi = hal.read32(Window::Core, offset::HASH_HI)?;
        let hash = (u64::from(hi) << 32) | u64::from(lo);
        if hash != expect.hash {
            return Err(Error::HashMismatch {
                expected: expect.hash,
                found: hash,
            });
        }
        let mut rd = |o| hal.read32(Window::Core, o);
        let build = BuildInfo {
            version: rd(offset::VERSION)?,
            hash,
            k_max: rd(offset::K_MAX)?,
            rows_max: rd(offset::ROWS_MAX)?,
            cols_max: rd(offset::COLS_MAX)?,
            label_bits: rd(offset::LABEL_BITS)?,
            labels_per_beat: rd(offset::LABELS_PER_BEAT)?,
            clock_khz: rd(offset::CLOCK_KHZ)?,
        };
        if build.labels_per_beat != LABELS_PER_BEAT {
            return Err(Error::Unsupported(
                "the AXI DMA's S2MM channel needs whole beats (all but the last), so the core must put 4 labels in each; generate it with --labels-per-beat 4",
            ));
        }
        if !(8..=26).contains(&expect.dma_length_bits) {
            return Err(Error::Unsupported(
                "the DMA's length register width (c_sg_length_width) must be 8 ..= 26 bits",
            ));
        }
        let pixels = build.rows_max as usize * build.cols_max as usize;
        // The build's largest frame must fit the DMA's length registers;
        // refused here rather than at the first large frame.
        let max = (1usize << expect.dma_length_bits) - 1;
        for (channel, bytes) in [
            (Channel::Mm2s, pixels * PIXEL_BYTES),
            (Channel::S2mm, label_buffer_bytes(pixels)),
        ] {
            if bytes > max {
                return Err(Error::TooLong {
                    channel,
                    bytes,
                    length_bits: expect.dma_length_bits,
                });
            }
        }
        if !(32..=64).contains(&expect.dma_addr_bits) {
            return Err(Error::Unsupported(
                "the DMA's address width (c_addr_width) must be 32 ..= 64 bits",
            ));
        }
        let tx = hal.alloc_dma(round_up(pixels * PIXEL_BYTES))?;
        let rx = hal.alloc_dma(round_up(label_buffer_bytes(pixels)))?;
        for b in [&tx, &rx] {
            let end = b.phys().checked_add(b.bytes().len() as u64);
            let limit = 1u128 << expect.dma_addr_bits;
            if end.is_none_or(|e| u128::from(e) > limit) {
                return Err(Error::BufferAddress {
                    phys: b.phys(),
                    len: b.bytes().len(),
                    addr_bits: expect.dma_addr_bits,
                });
            }
        }
        // The power-on run values (the build's), or what the last program
        // left in the run registers.
        let mut rd = |o| hal.read32(Window::Core, o);
        let defaults = RunConfig {
            rows: rd(offset::RUN_ROWS)?,
            cols: rd(offset::RUN_COLS)?,
            k: rd(offset::RUN_K)?,
            th_h_q: rd(offset::RUN_TH_H)?,
            th_v_q: rd(offset::RUN_TH_V)?,
            th_h_slope_q: rd(offset::RUN_SLOPE_H)?,
            th_v_slope_q: rd(offset::RUN_SLOPE_V)?,
        };
        let mut d = Driver {
            defaults,
            timeouts: Timeouts::for_build(&build),
            length_bits: expect.dma_length_bits,
            addr_bits: expect.dma_addr_bits,
            build,
            hal,
            tx,
            rx,
        };
        d.reset_dma()?;
        // A core just out of reset initialises its merge table (2^B cycles)
        // before it waits for a frame; one left mid-frame never does.
        let t0 = d.hal.now_ns();
        while d.core_r(offset::STATUS)? & bits::STATUS_IDLE == 0
            && d.elapsed_us(t0) <= d.timeouts.reset_us
        {}
        d.core_w(offset::CONTROL, bits::CONTROL_IRQ_ENABLE)?;
        d.core_w(offset::STATUS, bits::STATUS_FRAME_DONE)?;
        Ok(d)
    }

    /// The build as the core reported it.
    pub fn build(&self) -> &BuildInfo {
        &self.build
    }

    /// The run parameters of a core that is never programmed.
    pub fn defaults(&self) -> RunConfig {
        self.defaults
    }

    /// The platform (for inspection by tests and tools).
    pub fn hal(&mut self) -> &mut H {
        &mut self.hal
    }

    fn core_r(&mut self, o: u32) -> Res<u32, H> {
        Ok(self.hal.read32(Window::Core, o)?)
    }
    fn core_w(&mut self, o: u32, v: u32) -> Res<(), H> {
        Ok(self.hal.write32(Window::Core, o, v)?)
    }
    fn dma_r(&mut self, o: u32) -> Res<u32, H> {
        Ok(self.hal.read32(Window::Dma, o)?)
    }
    fn dma_w(&mut self, o: u32, v: u32) -> Res<(), H> {
        Ok(self.hal.write32(Window::Dma, o, v)?)
    }

    fn elapsed_us(&mut self, t0: u64) -> u64 {
        self.hal.now_ns().saturating_sub(t0) / 1000
    }

    /// Whether the core or a DMA channel is in the middle of something: the
    /// core not waiting for a frame's first pixel, or a channel neither
    /// halted nor idle. Returns (STATUS, MM2S DMASR, S2MM DMASR) when busy.
    pub fn core_busy(&mut self) -> Res<Option<(u32, u32, u32)>, H> {
        let st = self.core_r(offset::STATUS)?;
        let mm = self.dma_r(dma::MM2S_DMASR)?;
        let s2 = self.dma_r(dma::S2MM_DMASR)?;
        let stopped = |sr: u32| sr & (dma::SR_HALTED | dma::SR_IDLE) != 0;
        let busy = st & bits::STATUS_IDLE == 0 || !stopped(mm) || !stopped(s2);
        Ok(busy.then_some((st, mm, s2)))
    }

    /// Reset the DMA (both channels) and wait for the reset to end.
    fn reset_dma(&mut self) -> Res<(), H> {
        self.dma_w(dma::MM2S_DMACR, dma::CR_RESET)?;
        let t0 = self.hal.now_ns();
        while self.dma_r(dma::MM2S_DMACR)? & dma::CR_RESET != 0 {
            let us = self.elapsed_us(t0);
            if us > self.timeouts.reset_us {
                return Err(Error::ResetStuck {
                    what: "the AXI DMA's reset (DMACR.Reset)",
                    waited_us: us,
                });
            }
        }
        Ok(())
    }

    /// Abandon whatever is in flight: reset the DMA, soft-reset the core
    /// (CONTROL.SOFT_RESET), wait until it waits for a frame again, clear
    /// FRAME_DONE and re-enable the interrupt.
    pub fn recover(&mut self) -> Res<(), H> {
        self.reset_dma()?;
        self.core_w(
            offset::CONTROL,
            bits::CONTROL_SOFT_RESET | bits::CONTROL_IRQ_ENABLE,
        )?;
        let t0 = self.hal.now_ns();
        while self.core_r(offset::STATUS)? & bits::STATUS_IDLE == 0 {
            let us = self.elapsed_us(t0);
            if us > self.timeouts.reset_us {
                return Err(Error::ResetStuck {
                    what: "the core's soft reset (STATUS.IDLE never came back)",
                    waited_us: us,
                });
            }
        }
        self.core_w(offset::STATUS, bits::STATUS_FRAME_DONE)?;
        Ok(())
    }

    /// Set `run` for the next frame (the core takes run parameters at a
    /// frame's start). The core checks each value against its build's
    /// limits; a refusal is [`Error::RunRefused`].
    pub fn program_run(&mut self, run: &RunConfig) -> Res<(), H> {
        self.write_run_registers(run)
    }

    /// The one place the run registers are written: clear ERROR, write
    /// each value, read ERROR. A set bit means the core refused that value
    /// (it keeps the old one); the bits are cleared and reported.
    fn write_run_registers(&mut self, run: &RunConfig) -> Res<(), H> {
        self.core_w(offset::ERROR, ERROR_ALL)?;
        self.core_w(offset::RUN_K, run.k)?;
        self.core_w(offset::RUN_TH_H, run.th_h_q)?;
        self.core_w(offset::RUN_TH_V, run.th_v_q)?;
        self.core_w(offset::RUN_ROWS, run.rows)?;
        self.core_w(offset::RUN_COLS, run.cols)?;
        self.core_w(offset::RUN_SLOPE_H, run.th_h_slope_q)?;
        self.core_w(offset::RUN_SLOPE_V, run.th_v_slope_q)?;
        let refused = self.core_r(offset::ERROR)? & ERROR_ALL;
        if refused != 0 {
            self.core_w(offset::ERROR, refused)?;
            let b = &self.build;
            return Err(Error::RunRefused {
                bits: RefusedBits(refused),
                run: *run,
                limits: (b.k_max, b.rows_max, b.cols_max),
            });
        }
        Ok(())
    }

    /// Send one frame through the core and read its labels into `labels`
    /// (raster order, `rows * cols` of them) and its status.
    ///
    /// On a DMA error, a timeout or a wrong label count the DMA and the core
    /// are reset before the error is returned, so the next frame can run.
    pub fn run_frame(
        &mut self,
        run: &RunConfig,
        pixels: Pixels<'_>,
        labels: &mut [u32],
    ) -> Res<FrameReport, H> {
        self.program_run(run)?;
        let n = run.pixels();
        if !pixels.exact() || pixels.len() != n {
            return Err(Error::FrameSize {
                expected: n,
                got: pixels.len(),
            });
        }
        if labels.len() < n {
            return Err(Error::LabelsBuffer {
                expected: n,
                got: labels.len(),
            });
        }
        let tx_bytes = n * PIXEL_BYTES;
        let rx_bytes = label_buffer_bytes(n);
        let max = (1usize << self.length_bits) - 1;
        for (channel, bytes) in [(Channel::Mm2s, tx_bytes), (Channel::S2mm, rx_bytes)] {
            if bytes > max {
                return Err(Error::TooLong {
                    channel,
                    bytes,
                    length_bits: self.length_bits,
                });
            }
        }
        if let Some((status, mm2s_sr, s2mm_sr)) = self.core_busy()? {
            self.recover()?;
            return Err(Error::CoreWasBusy {
                status,
                mm2s_sr,
                s2mm_sr,
            });
        }

        pixels.pack(&mut self.tx.bytes_mut()[..tx_bytes]);
        self.hal.cache_clean(&mut self.tx, 0, tx_bytes)?;
        // No dirty line of the label buffer may be written back over the
        // DMA's data.
        self.hal
            .cache_invalidate(&mut self.rx, 0, round_up(rx_bytes))?;
        self.core_w(offset::STATUS, bits::STATUS_FRAME_DONE)?;
        self.core_w(offset::CONTROL, bits::CONTROL_IRQ_ENABLE)?;

        // S2MM first, so no label beat waits for a channel that is not armed.
        let cr = dma::CR_RS | dma::CR_IOC_IRQ_EN | dma::CR_ERR_IRQ_EN;
        let (rx_phys, tx_phys) = (self.rx.phys(), self.tx.phys());
        self.dma_w(dma::S2MM_DMASR, dma::SR_IRQS)?;
        self.dma_w(dma::S2MM_DMACR, cr)?;
        self.dma_w(dma::S2MM_DA, rx_phys as u32)?;
        if self.addr_bits > 32 {
            self.dma_w(dma::S2MM_DA_MSB, (rx_phys >> 32) as u32)?;
        }
        self.dma_w(dma::S2MM_LENGTH, rx_bytes as u32)?;
        self.dma_w(dma::MM2S_DMASR, dma::SR_IRQS)?;
        self.dma_w(dma::MM2S_DMACR, cr)?;
        self.dma_w(dma::MM2S_SA, tx_phys as u32)?;
        if self.addr_bits > 32 {
            self.dma_w(dma::MM2S_SA_MSB, (tx_phys >> 32) as u32)?;
        }
        let t0 = self.hal.now_ns();
        self.dma_w(dma::MM2S_LENGTH, tx_bytes as u32)?;

        // The core's interrupt, checking the DMA for errors meanwhile.
        loop {
            let waited = self.elapsed_us(t0);
            if waited >= self.timeouts.frame_us {
                return Err(self.timeout(waited, "the core's frame-done interrupt"));
            }
            let slice = self.timeouts.poll_us.min(self.timeouts.frame_us - waited);
            let irq = self.hal.wait_irq(slice.max(1))?;
            self.check_dma_errors()?;
            if irq {
                break;
            }
        }
        // The last label beat left the core; wait for S2MM to write it.
        let t1 = self.hal.now_ns();
        for (channel, sr) in [
            (Channel::S2mm, dma::S2MM_DMASR),
            (Channel::Mm2s, dma::MM2S_DMASR),
        ] {
            loop {
                let v = self.dma_r(sr)?;
                if v & dma::SR_ERRORS != 0 {
                    return Err(self.dma_error(channel, v));
                }
                if v & dma::SR_IDLE != 0 {
                    break;
                }
                let waited = self.elapsed_us(t1);
                if waited > self.timeouts.dma_done_us {
                    let stage = match channel {
                        Channel::S2mm => "S2MM to finish writing the labels",
                        Channel::Mm2s => {
                            "MM2S to finish (the core ended the frame before taking every pixel)"
                        }
                    };
                    return Err(self.timeout(waited, stage));
                }
            }
        }
        let time_ns = self.hal.now_ns() - t0;
        let got = self.dma_r(dma::S2MM_LENGTH)?;
        let expected = (n * LABEL_BYTES) as u32;

        let status = self.read_status()?;
        self.core_w(offset::STATUS, bits::STATUS_FRAME_DONE)?;
        self.dma_w(dma::S2MM_DMASR, dma::SR_IRQS)?;
        self.dma_w(dma::MM2S_DMASR, dma::SR_IRQS)?;
        if status.1 & bits::FLAGS_FRAME_ERROR != 0 {
            return Err(Error::StreamLength { pixels: n });
        }
        if got != expected {
            self.recover()?;
            return Err(Error::LabelBytes { expected, got });
        }
        self.hal
            .cache_invalidate(&mut self.rx, 0, round_up(rx_bytes))?;
        let rx = self.rx.bytes();
        for (i, l) in labels[..n].iter_mut().enumerate() {
            let b = (i / LABELS_PER_BEAT as usize) * LABEL_BEAT_BYTES;
            let mut w = [0u8; 8];
            w.copy_from_slice(&rx[b..b + 8]);
            *l = label_of_beat(u64::from_le_bytes(w), i % LABELS_PER_BEAT as usize);
        }
        Ok(FrameReport {
            status: status.0,
            time_ns,
        })
    }

    /// The latched frame status and the raw FRAME_FLAGS.
    fn read_status(&mut self) -> Res<(FrameStatus, u32), H> {
        let flags = self.core_r(offset::FRAME_FLAGS)?;
        Ok((
            FrameStatus {
                frame_count: self.core_r(offset::FRAME_COUNT)?,
                clusters: self.core_r(offset::CLUSTERS)?,
                provisional: self.core_r(offset::PROVISIONAL)?,
                unlabelled: self.core_r(offset::UNLABELLED)?,
                overflow: flags & bits::FLAGS_OVERFLOW != 0,
                joins: self.core_r(offset::JOINS)?,
                gear_stalls: self.core_r(offset::GEAR_STALLS)?,
            },
            flags,
        ))
    }

    fn check_dma_errors(&mut self) -> Res<(), H> {
        for (channel, sr) in [
            (Channel::Mm2s, dma::MM2S_DMASR),
            (Channel::S2mm, dma::S2MM_DMASR),
        ] {
            let v = self.dma_r(sr)?;
            if v & dma::SR_ERRORS != 0 {
                return Err(self.dma_error(channel, v));
            }
        }
        Ok(())
    }

    /// The error for a channel stopped with error bits, after recovery.
    fn dma_error(&mut self, channel: Channel, dmasr: u32) -> Error<H::Error> {
        if let Err(e) = self.recover() {
            return e;
        }
        Error::Dma {
            channel,
            dmasr,
            cause: DmaCause(dmasr & dma::SR_ERRORS),
        }
    }

    /// The error for a timeout (with the state seen), after recovery.
    fn timeout(&mut self, waited_us: u64, stage: &'static str) -> Error<H::Error> {
        let snap = (
            self.core_r(offset::STATUS),
            self.dma_r(dma::MM2S_DMASR),
            self.dma_r(dma::S2MM_DMASR),
        );
        let (core_status, mm2s_sr, s2mm_sr) = match snap {
            (Ok(a), Ok(b), Ok(c)) => (a, b, c),
            (Err(e), _, _) | (_, Err(e), _) | (_, _, Err(e)) => return e,
        };
        if let Err(e) = self.recover() {
            return e;
        }
        Error::Timeout {
            waited_us,
            stage,
            core_status,
            mm2s_sr,
            s2mm_sr,
        }
    }
}
