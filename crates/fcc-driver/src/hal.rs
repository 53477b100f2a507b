//! What the driver needs from a platform.

/// Alignment of DMA buffers: the cache line of the Cortex-A9 (and A53 is 64,
/// a multiple: backends may align more).
pub const DMA_ALIGN: usize = 32;

/// A register window.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Window {
    /// The core's AXI4-Lite register file (offsets in `fcc_regmap::offset`).
    Core,
    /// The AXI DMA's registers (offsets in [`crate::dma`]).
    Dma,
}

/// Memory the DMA can reach: the CPU's view of it and its bus address.
pub trait DmaBuffer {
    /// Bus (physical) address of byte 0; a multiple of [`DMA_ALIGN`].
    fn phys(&self) -> u64;
    /// The CPU's view.
    fn bytes(&self) -> &[u8];
    fn bytes_mut(&mut self) -> &mut [u8];
}

/// The platform under the driver. Register accesses are 32 bits wide at a
/// 4-byte aligned byte offset.
pub trait Hal {
    type Buffer: DmaBuffer;
    type Error: core::fmt::Debug + core::fmt::Display;

    fn read32(&mut self, w: Window, offset: u32) -> Result<u32, Self::Error>;
    fn write32(&mut self, w: Window, offset: u32, value: u32) -> Result<(), Self::Error>;
    /// A DMA buffer of at least `len` bytes, aligned to [`DMA_ALIGN`].
    fn alloc_dma(&mut self, len: usize) -> Result<Self::Buffer, Self::Error>;
    /// Make the CPU's writes to `buf[offset..offset + len]` visible to the DMA.
    fn cache_clean(
        &mut self,
        buf: &mut Self::Buffer,
        offset: usize,
        len: usize,
    ) -> Result<(), Self::Error>;
    /// Drop the CPU's copy of `buf[offset..offset + len]`, so the next reads
    /// see what the DMA wrote.
    fn cache_invalidate(
        &mut self,
        buf: &mut Self::Buffer,
        offset: usize,
        len: usize,
    ) -> Result<(), Self::Error>;
    /// Wait until the core's interrupt (`irq`) is raised, at most
    /// `timeout_us` microseconds; `Ok(true)` when it was raised.
    fn wait_irq(&mut self, timeout_us: u64) -> Result<bool, Self::Error>;
    /// A monotonic clock in nanoseconds (the hardware's time on a model).
    fn now_ns(&mut self) -> u64;
}
