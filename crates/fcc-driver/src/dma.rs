//! The AXI DMA's direct-register (simple) mode interface, PG021 (v7.1),
//! "Register Space": offsets and bits, written once for the driver and the
//! virtual board's model of the DMA.

/// MM2S (memory to stream: the pixel frame) control register.
pub const MM2S_DMACR: u32 = 0x00;
/// MM2S status register.
pub const MM2S_DMASR: u32 = 0x04;
/// MM2S source address, bits 31:0 and 63:32.
pub const MM2S_SA: u32 = 0x18;
pub const MM2S_SA_MSB: u32 = 0x1C;
/// MM2S transfer length in bytes; writing it starts the transfer.
pub const MM2S_LENGTH: u32 = 0x28;
/// S2MM (stream to memory: the labels) control register.
pub const S2MM_DMACR: u32 = 0x30;
pub const S2MM_DMASR: u32 = 0x34;
/// S2MM destination address, bits 31:0 and 63:32.
pub const S2MM_DA: u32 = 0x48;
pub const S2MM_DA_MSB: u32 = 0x4C;
/// S2MM buffer length in bytes; writing it arms the channel. When the
/// packet ends (`tlast`) it reads back the bytes actually received.
pub const S2MM_LENGTH: u32 = 0x58;

/// DMACR.RS: run (1) / stop (0).
pub const CR_RS: u32 = 1 << 0;
/// DMACR.Reset: soft reset of the whole DMA (both channels); self-clearing.
pub const CR_RESET: u32 = 1 << 2;
/// DMACR.IOC_IrqEn: interrupt on complete.
pub const CR_IOC_IRQ_EN: u32 = 1 << 12;
/// DMACR.Dly_IrqEn (scatter-gather only).
pub const CR_DLY_IRQ_EN: u32 = 1 << 13;
/// DMACR.Err_IrqEn: interrupt on error.
pub const CR_ERR_IRQ_EN: u32 = 1 << 14;
/// DMACR reset value: IRQThreshold = 1 (bits 23:16).
pub const CR_RESET_VALUE: u32 = 0x0001_0000;

/// DMASR.Halted: the channel is stopped (RS = 0 and its transfers done).
pub const SR_HALTED: u32 = 1 << 0;
/// DMASR.Idle: the programmed transfer is done (cleared by a LENGTH write).
pub const SR_IDLE: u32 = 1 << 1;
/// DMASR.SGIncld: scatter-gather included (0 in simple mode).
pub const SR_SG_INCLD: u32 = 1 << 3;
/// DMASR.DMAIntErr: internal error (length 0, or in simple mode S2MM a
/// packet longer than LENGTH).
pub const SR_DMA_INT_ERR: u32 = 1 << 4;
/// DMASR.DMASlvErr: the memory answered SLVERR.
pub const SR_DMA_SLV_ERR: u32 = 1 << 5;
/// DMASR.DMADecErr: the address decodes to nothing (DECERR).
pub const SR_DMA_DEC_ERR: u32 = 1 << 6;
/// DMASR.IOC_Irq: transfer complete (write 1 to clear).
pub const SR_IOC_IRQ: u32 = 1 << 12;
/// DMASR.Dly_Irq (scatter-gather only; write 1 to clear).
pub const SR_DLY_IRQ: u32 = 1 << 13;
/// DMASR.Err_Irq: an error occurred (write 1 to clear).
pub const SR_ERR_IRQ: u32 = 1 << 14;
/// DMASR reset value: halted.
pub const SR_RESET_VALUE: u32 = SR_HALTED;
/// Every error bit of DMASR in simple mode.
pub const SR_ERRORS: u32 = SR_DMA_INT_ERR | SR_DMA_SLV_ERR | SR_DMA_DEC_ERR;
/// The write-one-to-clear interrupt bits of DMASR.
pub const SR_IRQS: u32 = SR_IOC_IRQ | SR_DLY_IRQ | SR_ERR_IRQ;
