//! The driver proper: open, program, run a frame, recover.

use fcc_pixel::record::{frame_beats_max, FrameEnd, HwRecord, Item, ReadError, RecordReader};
use fcc_pixel::{label_of_beat, pixel_beat, quantize_point, Point, LABEL_BEAT_BYTES, PIXEL_BYTES};
use fcc_regmap::{bits, offset, ID_MAGIC};

use crate::dma;
use crate::error::{Channel, DmaCause, Error, RefusedBits};
use crate::hal::{DmaBuffer, Hal, Window, DMA_ALIGN};

/// Labels per output beat the driver takes: the AXI DMA's S2MM channel needs
/// every beat of a packet whole except the last, so every slot of a beat
/// must hold a label.
pub const LABELS_PER_BEAT: u32 = 4;
/// The ERROR bits of the run registers both cores have.
const ERROR_RUN: u32 = bits::ERROR_K
    | bits::ERROR_TH_H
    | bits::ERROR_TH_V
    | bits::ERROR_ROWS
    | bits::ERROR_COLS
    | bits::ERROR_SLOPE_H
    | bits::ERROR_SLOPE_V;
/// The ERROR bits of the column core's stream-limit registers.
const ERROR_STREAM: u32 = bits::ERROR_BRIDGE | bits::ERROR_RING_REACH | bits::ERROR_OPEN_LIMIT;
/// Bytes of one label in the S2MM buffer.
const LABEL_BYTES: usize = 2;
/// Bytes of one record or end beat in the S2MM buffer.
const BEAT_BYTES: usize = 8;

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
    /// The column core's stream limits; `None` leaves its registers as they
    /// are (and is the only value a row-major core takes).
    pub limits: Option<StreamLimits>,
}

/// The column core's stream limits (spec §9.1), as its run registers hold
/// them: RUN_BRIDGE and RUN_RING_REACH in columns (0xFFF: no limit),
/// RUN_OPEN_LIMIT in clusters (1 ..= 511).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct StreamLimits {
    pub bridge: u32,
    pub ring_reach: u32,
    pub open_limit: u32,
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
    /// The build is the column-streaming core (`fcc_params.json`'s `scan`
    /// is `column`): it takes a frame in column order and sends a record
    /// per cluster ([`Driver::run_records`]) instead of labels.
    pub column: bool,
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
    /// Generous limits for a build: for the row-major core four times the
    /// cycles of the largest frame (it needs about 1.3 x R x C); for the
    /// column core (`column`) 64 cycles a pixel (it needs 1.0 to 1.1 on the
    /// corpus, but up to about 12 on a small frame of many small clusters
    /// at 9-bit labels, and 8 on a 32-row capture whose closes lag:
    /// docs/column-core.md); plus the table
    /// initialisation, and fixed margins.
    pub fn for_build(b: &BuildInfo, column: bool) -> Timeouts {
        let mhz = u64::from(b.clock_khz.max(1000)) / 1000;
        let pixels = u64::from(b.rows_max) * u64::from(b.cols_max);
        let init_us = (1u64 << b.label_bits) / mhz + 1;
        let cycles_per_pixel = if column { 64 } else { 4 };
        Timeouts {
            frame_us: cycles_per_pixel * pixels / mhz + init_us + 200,
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

/// One frame's result (the labels or records are the caller's).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FrameReport {
    pub status: FrameStatus,
    /// From the start of MM2S to S2MM idle, on the platform's clock.
    pub time_ns: u64,
}

/// One frame's result on the column core: the status and the frame's end
/// beat (spec §9.4; the records went to the caller).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RecordReport {
    pub status: FrameStatus,
    pub end: FrameEnd,
    /// From the start of MM2S to S2MM idle, on the platform's clock.
    pub time_ns: u64,
}

/// The order the core takes a frame's pixels in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Order {
    /// Row by row (the row-major core).
    Rows,
    /// Column by column, rows 0 .. R-1 of each (the column core).
    Columns { rows: usize, cols: usize },
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
    /// pack into `out` in `order`, 8 bytes per pixel, little-endian. The
    /// pixels are row-major.
    fn pack(&self, out: &mut [u8], order: Order) {
        let put = |i: usize, out: &mut [u8], p: Option<Point>| {
            let at = match order {
                Order::Rows => i,
                Order::Columns { rows, cols } => (i % cols) * rows + i / cols,
            };
            out[at * PIXEL_BYTES..(at + 1) * PIXEL_BYTES]
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
pub fn label_buffer_bytes(pixels: usize) -> usize {
    pixels.div_ceil(LABELS_PER_BEAT as usize) * LABEL_BEAT_BYTES
}

/// Bytes of the S2MM buffer for the records of a frame of `pixels` (every
/// pixel a cluster at most) and its end beat: what `fcc gen` sizes the
/// block design's S2MM length for.
pub fn record_buffer_bytes(pixels: usize) -> usize {
    frame_beats_max(pixels) * BEAT_BYTES
}

/// The FCC core and its AXI DMA, through a [`Hal`].
pub struct Driver<H: Hal> {
    hal: H,
    build: BuildInfo,
    defaults: RunConfig,
    length_bits: u32,
    addr_bits: u32,
    column: bool,
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
        if !expect.column && build.labels_per_beat != LABELS_PER_BEAT {
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
        let out_bytes = if expect.column {
            record_buffer_bytes(pixels)
        } else {
            label_buffer_bytes(pixels)
        };
        // The build's largest frame must fit the DMA's length registers;
        // refused here rather than at the first large frame.
        let max = (1usize << expect.dma_length_bits) - 1;
        for (channel, bytes) in [
            (Channel::Mm2s, pixels * PIXEL_BYTES),
            (Channel::S2mm, out_bytes),
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
        let rx = hal.alloc_dma(round_up(out_bytes))?;
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
        let mut defaults = RunConfig {
            rows: rd(offset::RUN_ROWS)?,
            cols: rd(offset::RUN_COLS)?,
            k: rd(offset::RUN_K)?,
            th_h_q: rd(offset::RUN_TH_H)?,
            th_v_q: rd(offset::RUN_TH_V)?,
            th_h_slope_q: rd(offset::RUN_SLOPE_H)?,
            th_v_slope_q: rd(offset::RUN_SLOPE_V)?,
            limits: None,
        };
        if expect.column {
            defaults.limits = Some(StreamLimits {
                bridge: rd(offset::RUN_BRIDGE)?,
                ring_reach: rd(offset::RUN_RING_REACH)?,
                open_limit: rd(offset::RUN_OPEN_LIMIT)?,
            });
        }
        let mut d = Driver {
            defaults,
            timeouts: Timeouts::for_build(&build, expect.column),
            length_bits: expect.dma_length_bits,
            addr_bits: expect.dma_addr_bits,
            column: expect.column,
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
        if run.limits.is_some() && !self.column {
            return Err(Error::Unsupported(
                "stream limits (bridge, ring reach, open limit) are run registers of the column core only; this is the row-major core",
            ));
        }
        let error_all = if self.column {
            ERROR_RUN | ERROR_STREAM
        } else {
            ERROR_RUN
        };
        self.core_w(offset::ERROR, error_all)?;
        self.core_w(offset::RUN_K, run.k)?;
        self.core_w(offset::RUN_TH_H, run.th_h_q)?;
        self.core_w(offset::RUN_TH_V, run.th_v_q)?;
        self.core_w(offset::RUN_ROWS, run.rows)?;
        self.core_w(offset::RUN_COLS, run.cols)?;
        self.core_w(offset::RUN_SLOPE_H, run.th_h_slope_q)?;
        self.core_w(offset::RUN_SLOPE_V, run.th_v_slope_q)?;
        if let Some(l) = run.limits {
            self.core_w(offset::RUN_BRIDGE, l.bridge)?;
            self.core_w(offset::RUN_RING_REACH, l.ring_reach)?;
            self.core_w(offset::RUN_OPEN_LIMIT, l.open_limit)?;
        }
        let refused = self.core_r(offset::ERROR)? & error_all;
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
        if self.column {
            return Err(Error::Unsupported(
                "the column core sends records, not labels: use run_records",
            ));
        }
        self.program_frame(run, &pixels)?;
        let n = run.pixels();
        if labels.len() < n {
            return Err(Error::LabelsBuffer {
                expected: n,
                got: labels.len(),
            });
        }
        let rx_bytes = label_buffer_bytes(n);
        let (status, time_ns, got) = self.transfer(run, pixels, Order::Rows, rx_bytes)?;
        let expected = (n * LABEL_BYTES) as u32;
        if got != expected {
            self.recover()?;
            return Err(Error::LabelBytes { expected, got });
        }
        let rx = self.rx.bytes();
        for (i, l) in labels[..n].iter_mut().enumerate() {
            let b = (i / LABELS_PER_BEAT as usize) * LABEL_BEAT_BYTES;
            let mut w = [0u8; 8];
            w.copy_from_slice(&rx[b..b + 8]);
            *l = label_of_beat(u64::from_le_bytes(w), i % LABELS_PER_BEAT as usize);
        }
        Ok(FrameReport { status, time_ns })
    }

    /// Send one frame (its pixels row-major, as for [`Driver::run_frame`];
    /// the driver sends them in column order) through the column core and
    /// hand each of its records to `records`, in the order the core sent
    /// them (spec §9.4: the golden stream's order). Returns the status and
    /// the frame's end beat.
    ///
    /// The S2MM bytes are read as a record stream: whole records with ids
    /// `1, 2, ...`, then the end beat (the transfer's last beat, counting
    /// the records). Anything else is [`Error::Records`], after which the
    /// DMA and the core are reset.
    pub fn run_records(
        &mut self,
        run: &RunConfig,
        pixels: Pixels<'_>,
        records: &mut impl Extend<HwRecord>,
    ) -> Res<RecordReport, H> {
        if !self.column {
            return Err(Error::Unsupported(
                "the row-major core sends labels, not records: use run_frame",
            ));
        }
        self.program_frame(run, &pixels)?;
        let order = Order::Columns {
            rows: run.rows as usize,
            cols: run.cols as usize,
        };
        let rx_bytes = record_buffer_bytes(run.pixels());
        let (status, time_ns, got) = self.transfer(run, pixels, order, rx_bytes)?;
        match read_records(&self.rx.bytes()[..(got as usize).min(rx_bytes)], records) {
            Ok(end) => Ok(RecordReport {
                status,
                end,
                time_ns,
            }),
            Err((beat, error)) => {
                self.recover()?;
                Err(Error::Records {
                    bytes: got,
                    beat,
                    error,
                })
            }
        }
    }

    /// Program `run` and check that `pixels` is a frame of its size.
    fn program_frame(&mut self, run: &RunConfig, pixels: &Pixels<'_>) -> Res<(), H> {
        self.program_run(run)?;
        let n = run.pixels();
        if !pixels.exact() || pixels.len() != n {
            return Err(Error::FrameSize {
                expected: n,
                got: pixels.len(),
            });
        }
        Ok(())
    }

    /// One frame through both DMA channels (`run` programmed and `pixels`
    /// checked by [`Self::program_frame`]): pack `pixels` in `order`, arm
    /// S2MM for `rx_bytes`, send, wait for the core's interrupt and both
    /// channels' end. Returns the status, the time and the bytes S2MM
    /// wrote (already visible to the CPU).
    fn transfer(
        &mut self,
        run: &RunConfig,
        pixels: Pixels<'_>,
        order: Order,
        rx_bytes: usize,
    ) -> Res<(FrameStatus, u64, u32), H> {
        let n = run.pixels();
        let tx_bytes = n * PIXEL_BYTES;
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

        pixels.pack(&mut self.tx.bytes_mut()[..tx_bytes], order);
        self.hal.cache_clean(&mut self.tx, 0, tx_bytes)?;
        // No dirty line of the output buffer may be written back over the
        // DMA's data.
        self.hal
            .cache_invalidate(&mut self.rx, 0, round_up(rx_bytes))?;
        self.core_w(offset::STATUS, bits::STATUS_FRAME_DONE)?;
        self.core_w(offset::CONTROL, bits::CONTROL_IRQ_ENABLE)?;

        // S2MM first, so no output beat waits for a channel that is not armed.
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
        // The last output beat left the core; wait for S2MM to write it.
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
                        Channel::S2mm => "S2MM to finish writing the core's output",
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

        let status = self.read_status()?;
        self.core_w(offset::STATUS, bits::STATUS_FRAME_DONE)?;
        self.dma_w(dma::S2MM_DMASR, dma::SR_IRQS)?;
        self.dma_w(dma::MM2S_DMASR, dma::SR_IRQS)?;
        if status.1 & bits::FLAGS_FRAME_ERROR != 0 {
            return Err(Error::StreamLength { pixels: n });
        }
        self.hal
            .cache_invalidate(&mut self.rx, 0, round_up(rx_bytes))?;
        Ok((status.0, time_ns, got))
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

/// Read S2MM's bytes as one frame's record stream (spec §9.4): each record
/// to `records`, and the end beat, which must be the last beat. On an error
/// the beat it was found at (from 0) and why.
fn read_records(
    bytes: &[u8],
    records: &mut impl Extend<HwRecord>,
) -> Result<FrameEnd, (u64, ReadError)> {
    let beats = bytes.len() / BEAT_BYTES;
    // A part of a beat at the end is no end beat.
    let whole = bytes.len().is_multiple_of(BEAT_BYTES);
    let mut reader = RecordReader::new();
    for (i, b) in bytes.chunks_exact(BEAT_BYTES).enumerate() {
        let mut w = [0u8; BEAT_BYTES];
        w.copy_from_slice(b);
        let last = whole && i + 1 == beats;
        match reader.push(u64::from_le_bytes(w), last) {
            Ok(Some(Item::Record(r))) => records.extend(core::iter::once(r)),
            Ok(Some(Item::End(end))) => return Ok(end),
            Ok(None) => {}
            Err(e) => return Err((i as u64, e)),
        }
    }
    // No end beat: the stream stopped inside a record or a frame (or S2MM
    // wrote a part of a beat).
    let e = reader
        .finish()
        .err()
        .unwrap_or(ReadError::EndsInFrame { records: 0 });
    Err((beats as u64, e))
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use fcc_pixel::record::{frame_beats, RECORD_WORDS};
    use std::vec::Vec;

    /// A frame of `n` records (ids 1 ..= n) and its end beat, as bytes.
    fn stream(n: u32) -> (Vec<HwRecord>, Vec<u8>) {
        let recs: Vec<HwRecord> = (1..=n)
            .map(|id| HwRecord {
                id,
                points: id,
                ..HwRecord::default()
            })
            .collect();
        let mut beats: Vec<(u64, bool)> = Vec::new();
        let end = FrameEnd {
            records: n,
            ..FrameEnd::default()
        };
        frame_beats(&recs, end, &mut beats).expect("packs");
        let bytes = beats.iter().flat_map(|(w, _)| w.to_le_bytes()).collect();
        (recs, bytes)
    }

    #[derive(Default)]
    struct Sink(usize, Option<HwRecord>);
    impl Extend<HwRecord> for Sink {
        fn extend<T: IntoIterator<Item = HwRecord>>(&mut self, it: T) {
            for r in it {
                self.0 += 1;
                self.1 = Some(r);
            }
        }
    }

    #[test]
    fn a_frame_of_records_reads_back_with_its_end_beat() {
        let (recs, bytes) = stream(3);
        let mut sink = Sink::default();
        let end = read_records(&bytes, &mut sink).expect("a record stream");
        assert_eq!((end.records, sink.0, sink.1), (3, 3, recs.last().copied()));
        let (_, empty) = stream(0);
        assert_eq!(
            read_records(&empty, &mut Sink::default()).map(|e| e.records),
            Ok(0)
        );
    }

    #[test]
    fn a_stream_that_is_not_one_frame_says_where_and_why() {
        let (_, bytes) = stream(2);
        let w = BEAT_BYTES;
        // The transfer (which ends at `tlast`) ends inside the second
        // record, or after it: `tlast` on a record's beat.
        let e = read_records(&bytes[..(RECORD_WORDS + 3) * w], &mut Sink::default());
        assert_eq!(e, Err((13, ReadError::LastInRecord { word: 2 })));
        let e = read_records(&bytes[..2 * RECORD_WORDS * w], &mut Sink::default());
        assert_eq!(e, Err((21, ReadError::LastInRecord { word: 10 })));
        // Ending in a part of a beat: no end beat.
        let e = read_records(&bytes[..2 * RECORD_WORDS * w + 3], &mut Sink::default());
        assert_eq!(e, Err((22, ReadError::EndsInFrame { records: 2 })));
        // A part of a beat after the end beat: the end beat is not the last.
        let mut longer = bytes.clone();
        longer.extend([0; 4]);
        let e = read_records(&longer, &mut Sink::default());
        assert_eq!(e, Err((22, ReadError::EndWithoutLast)));
        // Nothing at all.
        let e = read_records(&[], &mut Sink::default());
        assert_eq!(e, Err((0, ReadError::EndsInFrame { records: 0 })));
        // A wrong id.
        let (_, mut bad) = stream(1);
        bad[0] = 5;
        let e = read_records(&bad, &mut Sink::default());
        assert!(
            matches!(
                e,
                Err((
                    10,
                    ReadError::IdOutOfOrder {
                        expected: 1,
                        got: 5
                    }
                ))
            ),
            "{e:?}"
        );
    }
}
