//! Driver of the FCC core (`fcc_top`) behind a Xilinx AXI DMA in
//! direct-register (simple) mode.
//!
//! The core of the crate is `no_std` and hardware-agnostic: a [`Hal`] gives
//! 32-bit register access in two windows (the core's registers, the DMA's
//! registers), DMA-able buffers with physical addresses, cache maintenance,
//! a wait for the core's interrupt and a clock. [`Driver`] does the rest:
//! it checks the ID word and the parameter hash, quantises and packs a frame
//! exactly as the golden model does (`fcc-pixel`, the one definition of the
//! rule), runs both DMA channels as PG021 describes (S2MM armed before MM2S,
//! error bits, timeouts), unpacks the labels (row-major core) or reads the
//! records (column core, [`Driver::run_records`]) and the frame status, and
//! recovers from an aborted frame with a DMA reset and the core's soft reset.
//!
//! Backends: [`linux`] (feature `linux`: UIO and u-dma-buf) and the virtual
//! board in `fcc-sim` (a model of the AXI DMA and of memory around the
//! Verilator model of the core). Register offsets come from `fcc-regmap`.
#![cfg_attr(not(feature = "std"), no_std)]

pub mod dma;
mod driver;
mod error;
mod hal;
#[cfg(feature = "linux")]
pub mod linux;

pub use driver::{
    label_buffer_bytes, record_buffer_bytes, BuildExpect, BuildInfo, Driver, FrameReport,
    FrameStatus, Pixels, RecordReport, RunConfig, StreamLimits, Timeouts, LABELS_PER_BEAT,
};
pub use error::{Channel, DmaCause, Error, RefusedBits};
pub use hal::{DmaBuffer, Hal, Window, DMA_ALIGN};
