//! The driver's errors: each says what was found and, where it helps, what
//! to do.

use core::fmt;

use crate::dma;
use crate::driver::{RunConfig, StreamLimits};
use fcc_pixel::record::ReadError;

/// The bits of the core's ERROR register: which run registers refused the
/// value written.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RefusedBits(pub u32);

impl RefusedBits {
    /// The refused registers: name, the value the run asked for, the range
    /// the core takes (docs/rtl.md).
    pub fn registers(
        self,
        run: &RunConfig,
    ) -> impl Iterator<Item = (&'static str, u32, &'static str)> + '_ {
        use fcc_regmap::bits;
        let limits = run.limits.unwrap_or(StreamLimits {
            bridge: 0,
            ring_reach: 0,
            open_limit: 0,
        });
        [
            (bits::ERROR_K, "RUN_K", run.k, "odd, 3 ..= K_MAX"),
            (
                bits::ERROR_TH_H,
                "RUN_TH_H",
                run.th_h_q,
                "1 ..= 0x8000 (Q7.8)",
            ),
            (
                bits::ERROR_TH_V,
                "RUN_TH_V",
                run.th_v_q,
                "1 ..= 0x8000 (Q7.8)",
            ),
            (bits::ERROR_ROWS, "RUN_ROWS", run.rows, "1 ..= ROWS_MAX"),
            (
                bits::ERROR_COLS,
                "RUN_COLS",
                run.cols,
                "RUN_COLS_MIN (32) ..= COLS_MAX",
            ),
            (
                bits::ERROR_SLOPE_H,
                "RUN_SLOPE_H",
                run.th_h_slope_q,
                "0 ..= 0xFFFF (UQ0.16)",
            ),
            (
                bits::ERROR_SLOPE_V,
                "RUN_SLOPE_V",
                run.th_v_slope_q,
                "0 ..= 0xFFFF (UQ0.16)",
            ),
            (
                bits::ERROR_BRIDGE,
                "RUN_BRIDGE",
                limits.bridge,
                "0 ..= 0xFFF columns (0xFFF: no limit)",
            ),
            (
                bits::ERROR_RING_REACH,
                "RUN_RING_REACH",
                limits.ring_reach,
                "0 ..= 0xFFF columns (0xFFF: no limit)",
            ),
            (
                bits::ERROR_OPEN_LIMIT,
                "RUN_OPEN_LIMIT",
                limits.open_limit,
                "1 ..= 511 clusters",
            ),
        ]
        .into_iter()
        .filter(move |(b, ..)| self.0 & b != 0)
        .map(|(_, name, v, range)| (name, v, range))
    }
}

/// A DMA channel.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Channel {
    /// Memory to stream: the pixel frame into the core.
    Mm2s,
    /// Stream to memory: the labels (or records) out of the core.
    S2mm,
}

impl fmt::Display for Channel {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Channel::Mm2s => "MM2S (pixels in)",
            Channel::S2mm => "S2MM (labels or records out)",
        })
    }
}

/// The error bits of a DMASR value, named.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct DmaCause(pub u32);

impl fmt::Display for DmaCause {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let names = [
            (dma::SR_DMA_DEC_ERR, "DMADecErr: an address decodes to no memory (DECERR); check the buffer's physical address and the DMA's address map"),
            (dma::SR_DMA_SLV_ERR, "DMASlvErr: the memory answered SLVERR"),
            (dma::SR_DMA_INT_ERR, "DMAIntErr: internal error (length 0, or more data than the programmed length)"),
        ];
        let mut first = true;
        for (bit, name) in names {
            if self.0 & bit != 0 {
                if !first {
                    f.write_str("; ")?;
                }
                f.write_str(name)?;
                first = false;
            }
        }
        if first {
            f.write_str("no error bit")?;
        }
        Ok(())
    }
}

/// Everything that can go wrong; `E` is the platform's error.
#[derive(Debug)]
pub enum Error<E> {
    /// The platform failed (a register access, memory, the interrupt).
    Hal(E),
    /// No FCC core at the register window: the ID word is wrong.
    NotFcc { id: u32 },
    /// The core was built from other parameters than the software expects.
    HashMismatch { expected: u64, found: u64 },
    /// The core's build cannot be driven by this driver.
    Unsupported(&'static str),
    /// The core refused run values (its ERROR register): it keeps the
    /// previous ones; ERROR was cleared.
    RunRefused {
        bits: RefusedBits,
        run: RunConfig,
        /// The build's limits (K_MAX, ROWS_MAX, COLS_MAX).
        limits: (u32, u32, u32),
    },
    /// The frame's data does not hold `rows * cols` pixels.
    FrameSize { expected: usize, got: usize },
    /// A DMA transfer would exceed the DMA's length register.
    TooLong {
        channel: Channel,
        bytes: usize,
        length_bits: u32,
    },
    /// A DMA buffer lies (partly) beyond the DMA's address width.
    BufferAddress {
        phys: u64,
        len: usize,
        addr_bits: u32,
    },
    /// The labels buffer is too small.
    LabelsBuffer { expected: usize, got: usize },
    /// A DMA channel stopped with error bits set (the driver reset the DMA
    /// and the core; the next frame can run).
    Dma {
        channel: Channel,
        dmasr: u32,
        cause: DmaCause,
    },
    /// The frame did not finish in time (the driver reset the DMA and the
    /// core; the next frame can run).
    Timeout {
        waited_us: u64,
        stage: &'static str,
        core_status: u32,
        mm2s_sr: u32,
        s2mm_sr: u32,
    },
    /// The core saw the frame's `tlast` early or late (FRAME_FLAGS.FRAME_ERROR):
    /// the stream did not carry `rows * cols` pixels. Its labels are not valid.
    StreamLength { pixels: usize },
    /// S2MM received another number of label bytes than the frame has.
    LabelBytes { expected: u32, got: u32 },
    /// What S2MM received from the column core is not one frame's record
    /// stream (spec §9.4): `error` at beat `beat` of the `bytes` written
    /// (the driver reset the DMA and the core).
    Records {
        bytes: u32,
        beat: u64,
        error: ReadError,
    },
    /// The core was not waiting for a frame (left in the middle of one by a
    /// previous run): it was reset; run the frame again.
    CoreWasBusy {
        status: u32,
        mm2s_sr: u32,
        s2mm_sr: u32,
    },
    /// A reset did not complete.
    ResetStuck { what: &'static str, waited_us: u64 },
}

impl<E> From<E> for Error<E> {
    fn from(e: E) -> Self {
        Error::Hal(e)
    }
}

impl<E: fmt::Display> fmt::Display for Error<E> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Hal(e) => write!(f, "platform: {e}"),
            Error::NotFcc { id } => write!(
                f,
                "no FCC core at the register window: ID reads {id:#010x}, expected {:#010x} (\"FCC1\"); check the device (UIO name, address)",
                fcc_regmap::ID_MAGIC
            ),
            Error::HashMismatch { expected, found } => write!(
                f,
                "the core was built from other parameters: its hash is {found:016x}, the software expects {expected:016x}; load the bitstream of these parameters or give the core's fcc_params.json"
            ),
            Error::Unsupported(why) => write!(f, "this core cannot be driven: {why}"),
            Error::RunRefused { bits, run, limits } => {
                f.write_str("the core refused")?;
                for (i, (name, v, range)) in bits.registers(run).enumerate() {
                    let sep = if i == 0 { " " } else { "; " };
                    write!(f, "{sep}{name} = {v} (takes {range})")?;
                }
                write!(
                    f,
                    "; this build has K_MAX {}, ROWS_MAX {}, COLS_MAX {} (ERROR {:#04x}, cleared; the frame was not sent)",
                    limits.0, limits.1, limits.2, bits.0
                )
            }
            Error::FrameSize { expected, got } => write!(
                f,
                "the frame holds {got} pixels, the run parameters say {expected}"
            ),
            Error::TooLong {
                channel,
                bytes,
                length_bits,
            } => write!(
                f,
                "{channel}: {bytes} bytes exceed the DMA's {length_bits}-bit length register (at most {} bytes); rebuild the block design with a wider c_sg_length_width",
                (1u64 << length_bits) - 1
            ),
            Error::BufferAddress {
                phys,
                len,
                addr_bits,
            } => write!(
                f,
                "a DMA buffer of {len} bytes at 0x{phys:x} reaches beyond the DMA's {addr_bits}-bit addresses; allocate DMA memory lower, or build the block design for a board whose DMA has wider addresses (c_addr_width)"
            ),
            Error::LabelsBuffer { expected, got } => write!(
                f,
                "the labels buffer holds {got} labels, the frame has {expected}"
            ),
            Error::Dma {
                channel,
                dmasr,
                cause,
            } => write!(
                f,
                "DMA {channel} stopped with an error (DMASR {dmasr:#010x}: {cause}); the DMA and the core were reset"
            ),
            Error::Timeout {
                waited_us,
                stage,
                core_status,
                mm2s_sr,
                s2mm_sr,
            } => write!(
                f,
                "timeout after {waited_us} us waiting for {stage} (core STATUS {core_status:#x}, MM2S DMASR {mm2s_sr:#010x}, S2MM DMASR {s2mm_sr:#010x}); the DMA and the core were reset"
            ),
            Error::StreamLength { pixels } => write!(
                f,
                "the core saw the frame's tlast early or late (FRAME_FLAGS.FRAME_ERROR): the stream did not carry the {pixels} pixels of the frame; its labels are not valid"
            ),
            Error::LabelBytes { expected, got } => write!(
                f,
                "S2MM received {got} label bytes, the frame has {expected}; the DMA and the core were reset"
            ),
            Error::Records { bytes, beat, error } => write!(
                f,
                "S2MM received {bytes} bytes that are not one frame's records and end beat: at beat {beat}, {error}; the DMA and the core were reset"
            ),
            Error::CoreWasBusy {
                status,
                mm2s_sr,
                s2mm_sr,
            } => write!(
                f,
                "the core was not waiting for a frame (STATUS {status:#x}, MM2S DMASR {mm2s_sr:#010x}, S2MM DMASR {s2mm_sr:#010x}): a previous run left it in the middle of a frame; the DMA and the core were reset, run the frame again"
            ),
            Error::ResetStuck { what, waited_us } => {
                write!(f, "{what} did not complete in {waited_us} us")
            }
        }
    }
}

#[cfg(feature = "std")]
impl<E: fmt::Debug + fmt::Display> std::error::Error for Error<E> {}
