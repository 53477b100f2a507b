//! Offsets and bit fields of the FCC core's AXI4-Lite register file.
//!
//! This crate is the one place the addresses are written down. It has no
//! dependencies and builds without `std`, so a bare-metal or embedded driver
//! can use it as well as the RTL generator (`fcc-rtl`, which decodes these
//! offsets in hardware and derives the C header, the JSON and the register
//! table of docs/rtl.md from them).
#![no_std]

/// Address bits of the slave (a 4 KiB window, the smallest a Vivado address
/// map assigns).
pub const ADDR_BITS: usize = 12;

/// Value of the ID register: "FCC1" in ASCII.
pub const ID_MAGIC: u32 = 0x4643_4331;

/// Byte offsets.
pub mod offset {
    pub const ID: u32 = 0x000;
    pub const VERSION: u32 = 0x004;
    pub const HASH_LO: u32 = 0x008;
    pub const HASH_HI: u32 = 0x00C;
    pub const K_MAX: u32 = 0x010;
    pub const ROWS_MAX: u32 = 0x014;
    pub const COLS_MAX: u32 = 0x018;
    pub const LABEL_BITS: u32 = 0x01C;
    pub const LABELS_PER_BEAT: u32 = 0x020;
    pub const CLOCK_KHZ: u32 = 0x024;
    pub const CONTROL: u32 = 0x040;
    pub const STATUS: u32 = 0x044;
    pub const ERROR: u32 = 0x048;
    pub const FRAME_COUNT: u32 = 0x050;
    pub const CLUSTERS: u32 = 0x054;
    pub const PROVISIONAL: u32 = 0x058;
    pub const UNLABELLED: u32 = 0x05C;
    pub const FRAME_FLAGS: u32 = 0x060;
    pub const JOINS: u32 = 0x064;
    pub const GEAR_STALLS: u32 = 0x068;
    pub const RUN_K: u32 = 0x080;
    pub const RUN_TH_H: u32 = 0x084;
    pub const RUN_TH_V: u32 = 0x088;
    pub const RUN_ROWS: u32 = 0x08C;
    pub const RUN_COLS: u32 = 0x090;
    pub const RUN_SLOPE_H: u32 = 0x094;
    pub const RUN_SLOPE_V: u32 = 0x098;
    /// The column-streaming core only (`--scan column`).
    pub const RUN_BRIDGE: u32 = 0x09C;
    pub const RUN_RING_REACH: u32 = 0x0A0;
    pub const RUN_OPEN_LIMIT: u32 = 0x0A4;
}

/// Bit masks of the fields.
pub mod bits {
    /// CONTROL: write 1 to reset the pixel pipeline (self-clearing, reads 0).
    pub const CONTROL_SOFT_RESET: u32 = 1 << 0;
    /// CONTROL: raise `irq` while STATUS.FRAME_DONE is set.
    pub const CONTROL_IRQ_ENABLE: u32 = 1 << 1;
    /// CONTROL: write 1 to clear FRAME_COUNT, the latched frame status and
    /// STATUS.FRAME_DONE (self-clearing, reads 0).
    pub const CONTROL_CLEAR: u32 = 1 << 2;
    /// STATUS: a frame ended since the bit was last cleared (write 1 to clear).
    pub const STATUS_FRAME_DONE: u32 = 1 << 0;
    /// STATUS: the core waits for the first pixel of a frame (read-only, live).
    pub const STATUS_IDLE: u32 = 1 << 1;
    /// FRAME_FLAGS: the last frame ran out of provisional labels.
    pub const FLAGS_OVERFLOW: u32 = 1 << 0;
    /// FRAME_FLAGS: the last frame's `tlast` came early or late.
    pub const FLAGS_FRAME_ERROR: u32 = 1 << 1;
    /// ERROR: a write to RUN_K was refused (sticky, write 1 to clear).
    pub const ERROR_K: u32 = 1 << 0;
    /// ERROR: a write to RUN_TH_H was refused.
    pub const ERROR_TH_H: u32 = 1 << 1;
    /// ERROR: a write to RUN_TH_V was refused.
    pub const ERROR_TH_V: u32 = 1 << 2;
    /// ERROR: a write to RUN_ROWS was refused.
    pub const ERROR_ROWS: u32 = 1 << 3;
    /// ERROR: a write to RUN_COLS was refused.
    pub const ERROR_COLS: u32 = 1 << 4;
    /// ERROR: a write to RUN_SLOPE_H was refused.
    pub const ERROR_SLOPE_H: u32 = 1 << 5;
    /// ERROR: a write to RUN_SLOPE_V was refused.
    pub const ERROR_SLOPE_V: u32 = 1 << 6;
    /// ERROR: a write to RUN_BRIDGE was refused (the column core).
    pub const ERROR_BRIDGE: u32 = 1 << 7;
    /// ERROR: a write to RUN_RING_REACH was refused (the column core).
    pub const ERROR_RING_REACH: u32 = 1 << 8;
    /// ERROR: a write to RUN_OPEN_LIMIT was refused (the column core).
    pub const ERROR_OPEN_LIMIT: u32 = 1 << 9;
}

/// Largest threshold register value: `floor(th * 256 + 0.5)` of a threshold
/// below 128 m (the Q7.8 rule of the golden model).
pub const TH_Q_MAX: u32 = 0x8000;

/// Largest threshold slope register value: a slope below 1 metre per metre
/// in UQ0.16, `floor(a * 65536 + 0.5)` (spec §2; 0: a fixed threshold).
pub const SLOPE_Q_MAX: u32 = 0xFFFF;

/// RUN_BRIDGE and RUN_RING_REACH: the largest value, and the one that
/// means no limit (no frame of the column core, at most 4095 columns, has
/// a gap or a reach that long).
pub const LIMIT_MAX: u32 = 0xFFF;

/// RUN_OPEN_LIMIT: the largest value, the column core's record slots (511
/// clusters open at once; the value that a build without an open limit
/// starts with).
pub const OPEN_LIMIT_MAX: u32 = 511;

/// Fewest columns a frame may have (RUN_COLS), in every build. The
/// representative of a row's first columns is written back a few tens of
/// cycles after the pixel, and the last pixels of the same row read it for
/// the next row (the window reads column (j + h) mod C), so a row must be
/// longer than that pipeline; 32 leaves a margin for K_MAX = 11.
pub const RUN_COLS_MIN: u32 = 32;
