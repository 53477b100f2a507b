//! The bare-metal C example written beside a block design: one frame
//! through the AXI DMA in simple mode (the Xilinx standalone `XAxiDma`
//! driver) and the core's register sequence, with the golden model's
//! quantisation rule. Every number in it comes from `fcc_regs.h` (written
//! from the same register map) or from [`FccParams`] through the generator.

use fcc_params::FccParams;
use fcc_pixel::{LABEL_SLOT_BITS, PIXEL_BYTES, PIXEL_VALID_BIT, Q_ONE};

use crate::file_header;
use crate::vivado::{Board, Ps};

/// Writes of the run-time registers, before the frame is sent: the frame's
/// size, K, thresholds and slopes, then a check of ERROR (the register
/// map's rules: a refused value keeps the old one and sets its bit).
const RUN_WRITES: &str = r#"    /*    The frame's rows and columns, K, thresholds (Q7.8,
     *    floor(th * 256 + 0.5)) and threshold slopes (UQ0.16,
     *    floor(a * 65536 + 0.5), 0 for fixed thresholds); here the build's
     *    power-on values. A core built for larger frames or a larger K takes
     *    each frame's own values. The core takes them at the start of the next
     *    frame; a refused value keeps the old one and sets its ERROR bit. */
    fcc_wr(FCC_REG_ERROR, FCC_ERROR_K_MASK | FCC_ERROR_TH_H_MASK | FCC_ERROR_TH_V_MASK |
                              FCC_ERROR_ROWS_MASK | FCC_ERROR_COLS_MASK |
                              FCC_ERROR_SLOPE_H_MASK | FCC_ERROR_SLOPE_V_MASK);
    fcc_wr(FCC_REG_RUN_ROWS, FCC_ROWS);
    fcc_wr(FCC_REG_RUN_COLS, FCC_COLS);
    fcc_wr(FCC_REG_RUN_K, FCC_REG_RUN_K_RESET);
    fcc_wr(FCC_REG_RUN_TH_H, FCC_REG_RUN_TH_H_RESET);
    fcc_wr(FCC_REG_RUN_TH_V, FCC_REG_RUN_TH_V_RESET);
    fcc_wr(FCC_REG_RUN_SLOPE_H, FCC_REG_RUN_SLOPE_H_RESET);
    fcc_wr(FCC_REG_RUN_SLOPE_V, FCC_REG_RUN_SLOPE_V_RESET);
    if (fcc_rd(FCC_REG_ERROR) != 0u) {
        xil_printf("fcc: run parameters refused (ERROR 0x%02x)\r\n", (unsigned)fcc_rd(FCC_REG_ERROR));
        return 1;
    }
"#;

/// `fcc_<board>_example.c` for `p` on `board`.
pub fn c_example(p: &FccParams, board: Board) -> String {
    let b = board.info();
    let (cache_line, addr_note) = match b.ps {
        Ps::Ps7 => (32, "32-bit DMA addresses"),
        Ps::ZynqUltra => (
            64,
            "DMA addresses wider than 32 bits (XAxiDma_SimpleTransfer writes both halves)",
        ),
    };
    let mut s = file_header(p, "//");
    s.push_str(&format!("// Board: {} ({})\n", b.name, b.part));
    let column = p.scan == fcc_params::Scan::Column;
    let out_words = fcc_pixel::record::frame_beats_max(p.pixels());
    s.push_str(&crate::vivado::fill_public(
        if column { COLUMN_EXAMPLE } else { EXAMPLE },
        &[
            ("BUILD", BUILD.to_string()),
            ("SIZES", SIZES.to_string()),
            ("BUFFERS", BUFFERS.to_string()),
            ("HEAD", HEAD.to_string()),
            ("QUANTIZE", QUANTIZE.to_string()),
            ("OPEN", OPEN.to_string()),
            ("WAIT", WAIT.to_string()),
            ("OUT_WORDS", out_words.to_string()),
            ("TITLE", b.title.to_string()),
            ("BD", b.bd_script.to_string()),
            ("ADDR_NOTE", addr_note.to_string()),
            ("CACHE_LINE", cache_line.to_string()),
            ("Q_ONE", format!("{Q_ONE:.1}")),
            ("VALID_BIT", PIXEL_VALID_BIT.to_string()),
            ("PIXEL_BYTES", PIXEL_BYTES.to_string()),
            ("SLOT_BITS", LABEL_SLOT_BITS.to_string()),
            (
                "SLOT_MASK",
                format!("0x{:X}u", (1u64 << LABEL_SLOT_BITS) - 1),
            ),
            ("RUN_WRITES", RUN_WRITES.to_string()),
            ("STREAM_WRITES", STREAM_WRITES.to_string()),
        ],
    ));
    s
}

/// How to build the example (both cores).
const BUILD: &str = r#"// Build: add this file and fcc_regs.h (beside it, written by fcc gen from the
// same parameters) to a standalone application on the exported platform.
// The core's base address comes from xparameters.h (the cell is named
// "fcc"); if the BSP names it differently, compile with -DFCC_BASEADDR=0x...
// (the fcc segment in the block design's _map.txt). The DMA is found by
// device ID (XPAR_AXIDMA_0_DEVICE_ID, or -DFCC_DMA_ID=...).
"#;

/// The buffers' sizes in bytes, the Q7.8 scale and the valid bit.
const SIZES: &str = r#"#define FCC_IN_BYTES (FCC_PIXELS * @PIXEL_BYTES@u)
#define FCC_OUT_BYTES (FCC_OUT_WORDS * @PIXEL_BYTES@u)
/* Q7.8: 1 m = 256; bit @VALID_BIT@ of an input word marks a pixel with a point
 * (fcc-pixel, the format the golden model and the drivers share). */
#define FCC_Q_ONE @Q_ONE@
#define FCC_VALID_BIT @VALID_BIT@u
"#;

/// The poll limit, the buffers and the register access.
const BUFFERS: &str = r#"/* Polls before a frame is given up (each poll is one register read). */
#define FCC_POLL_LIMIT 100000000u

static uint64_t fcc_in[FCC_PIXELS] __attribute__((aligned(@CACHE_LINE@)));
static uint64_t fcc_out[FCC_OUT_WORDS] __attribute__((aligned(@CACHE_LINE@)));

static uint32_t fcc_rd(uint32_t offset) { return Xil_In32((UINTPTR)FCC_BASEADDR + offset); }
static void fcc_wr(uint32_t offset, uint32_t value) { Xil_Out32((UINTPTR)FCC_BASEADDR + offset, value); }
"#;

/// The includes and the addresses of the core and the DMA.
const HEAD: &str = r#"#include <math.h>
#include <stddef.h>
#include <stdint.h>

#include "xaxidma.h"
#include "xil_cache.h"
#include "xil_io.h"
#include "xil_printf.h"
#include "xparameters.h"
#include "xstatus.h"

#include "fcc_regs.h"

#ifndef FCC_BASEADDR
#define FCC_BASEADDR XPAR_FCC_BASEADDR
#endif
#ifndef FCC_DMA_ID
#define FCC_DMA_ID XPAR_AXIDMA_0_DEVICE_ID
#endif

"#;

/// The golden model's quantisation and the input word.
const QUANTIZE: &str = r#"/* One coordinate in metres to Q7.8, the golden model's rule:
 * sign(x) * floor(|x| * 256 + 0.5); 0 (no value) when x is not finite or the
 * result is outside [-32768, 32767]. */
int fcc_quantize(double x, int16_t *q)
{
    double mag;
    uint32_t m;
    if (!isfinite(x)) {
        return 0;
    }
    mag = (x < 0.0 ? -x : x) * FCC_Q_ONE + 0.5;
    if (mag >= 65536.0) {
        return 0;
    }
    m = (uint32_t)mag; /* non-negative: truncation is the floor */
    if (x < 0.0) {
        if (m > 32768u) {
            return 0;
        }
        *q = (int16_t)(-(int32_t)m);
    } else {
        if (m > 32767u) {
            return 0;
        }
        *q = (int16_t)m;
    }
    return 1;
}

/* One input word: x, y, z in Q7.8 and the valid bit; an empty pixel (any
 * coordinate without a value) is 0. */
uint64_t fcc_pack_pixel(double x, double y, double z)
{
    int16_t q[3];
    if (!fcc_quantize(x, &q[0]) || !fcc_quantize(y, &q[1]) || !fcc_quantize(z, &q[2])) {
        return 0;
    }
    return (uint64_t)(uint16_t)q[0] | ((uint64_t)(uint16_t)q[1] << FCC_SLOT_BITS) |
           ((uint64_t)(uint16_t)q[2] << (2u * FCC_SLOT_BITS)) | ((uint64_t)1 << FCC_VALID_BIT);
}

"#;

/// Steps 1 to 3: the right core, the DMA, the interrupt.
const OPEN: &str = r#"    /* 1. The right core: ID and the parameter hash of this build. */
    if (fcc_rd(FCC_REG_ID) != FCC_ID_MAGIC) {
        xil_printf("fcc: no FCC core at 0x%08x (ID 0x%08x)\r\n", (unsigned)FCC_BASEADDR,
                   (unsigned)fcc_rd(FCC_REG_ID));
        return 1;
    }
    hash = ((uint64_t)fcc_rd(FCC_REG_HASH_HI) << 32) | fcc_rd(FCC_REG_HASH_LO);
    if (hash != FCC_PARAMS_HASH) {
        xil_printf("fcc: the bitstream was built with other parameters (hash %08x%08x); "
                   "this program is for " FCC_TOP_MODULE "\r\n",
                   (unsigned)(hash >> 32), (unsigned)hash);
        return 1;
    }

    /* 2. The DMA in simple mode, its interrupts off (this example polls). */
    cfg = XAxiDma_LookupConfig(FCC_DMA_ID);
    if (cfg == NULL || XAxiDma_CfgInitialize(&dma, cfg) != XST_SUCCESS || XAxiDma_HasSg(&dma)) {
        xil_printf("fcc: AXI DMA %d not found or not in simple mode\r\n", (int)FCC_DMA_ID);
        return 1;
    }
    XAxiDma_IntrDisable(&dma, XAXIDMA_IRQ_ALL_MASK, XAXIDMA_DEVICE_TO_DMA);
    XAxiDma_IntrDisable(&dma, XAXIDMA_IRQ_ALL_MASK, XAXIDMA_DMA_TO_DEVICE);

    /* 3. Clear the frame counter and status, then enable the interrupt
     * (irq follows STATUS.FRAME_DONE). */
    fcc_wr(FCC_REG_CONTROL, FCC_CONTROL_CLEAR_MASK);
    fcc_wr(FCC_REG_CONTROL, FCC_CONTROL_IRQ_ENABLE_MASK);

"#;

/// Step 7: the frame done and both channels idle, or a reset.
const WAIT: &str = r#"    /* 7. Wait for the frame: FRAME_DONE (irq) and both channels idle. */
    for (polls = 0; polls < FCC_POLL_LIMIT; polls++) {
        status = fcc_rd(FCC_REG_STATUS);
        if ((status & FCC_STATUS_FRAME_DONE_MASK) && !XAxiDma_Busy(&dma, XAXIDMA_DEVICE_TO_DMA) &&
            !XAxiDma_Busy(&dma, XAXIDMA_DMA_TO_DEVICE)) {
            break;
        }
    }
    if (polls == FCC_POLL_LIMIT) {
        xil_printf("fcc: no frame done after %u polls; reset the DMA and write CONTROL.SOFT_RESET\r\n",
                   (unsigned)FCC_POLL_LIMIT);
        XAxiDma_Reset(&dma);
        fcc_wr(FCC_REG_CONTROL, FCC_CONTROL_SOFT_RESET_MASK);
        return 1;
    }
"#;

const EXAMPLE: &str = r#"//
// Bare-metal example for the @TITLE@ block design (scripts/@BD@, exported
// as an .xsa): sends one frame through the AXI DMA in simple mode, waits for
// the core, and reads back the labels and the frame's status. C99, for a
// Vitis standalone application; @ADDR_NOTE@.
//
@BUILD@//
// The sequence: check ID and parameter hash; clear; enable the interrupt;
// arm S2MM (labels) before MM2S (pixels); wait for STATUS.FRAME_DONE (the
// level of the core's irq) and for both DMA channels; read the latched
// status; clear FRAME_DONE.

@HEAD@/* The frame this build takes (build constants of fcc_regs.h). */
#define FCC_ROWS FCC_REG_ROWS_MAX_RESET
#define FCC_COLS FCC_REG_COLS_MAX_RESET
#define FCC_PIXELS (FCC_ROWS * FCC_COLS)
#define FCC_LPB FCC_REG_LABELS_PER_BEAT_RESET
#define FCC_OUT_WORDS ((FCC_PIXELS + FCC_LPB - 1u) / FCC_LPB)
@SIZES@/* 16-bit fields: coordinates in an input word, labels in an output word. */
#define FCC_SLOT_BITS @SLOT_BITS@u
@BUFFERS@
@QUANTIZE@/* The label of pixel i (raster order) in the output buffer. */
static uint32_t fcc_label(uint32_t i)
{
    return (uint32_t)(fcc_out[i / FCC_LPB] >> (FCC_SLOT_BITS * (i % FCC_LPB))) & @SLOT_MASK@;
}

/* A demonstration frame: two short walls of points 10 m ahead, on the
 * first two rows, far enough apart to be two clusters. Replace it with a
 * sensor's range image (x, y, z per pixel, NaN for no return). */
static void fcc_demo_frame(void)
{
    uint32_t i;
    for (i = 0; i < FCC_PIXELS; i++) {
        uint32_t r = i / FCC_COLS, c = i % FCC_COLS;
        int wall = r < 2u && (c < 4u || (c >= 16u && c < 20u));
        fcc_in[i] = wall ? fcc_pack_pixel(10.0, 0.05 * (double)c, 0.1 * (double)r) : 0;
    }
}

int main(void)
{
    XAxiDma dma;
    XAxiDma_Config *cfg;
    uint32_t polls, status, i, labelled = 0;
    uint64_t hash;

@OPEN@    /* 4. Run parameters. */
@RUN_WRITES@
    /* 5. The frame, out of the data cache; the label buffer invalidated. */
    fcc_demo_frame();
    Xil_DCacheFlushRange((UINTPTR)fcc_in, FCC_IN_BYTES);
    Xil_DCacheInvalidateRange((UINTPTR)fcc_out, FCC_OUT_BYTES);

    /* 6. Arm S2MM (labels) first, then start MM2S (pixels). */
    if (XAxiDma_SimpleTransfer(&dma, (UINTPTR)fcc_out, FCC_OUT_BYTES, XAXIDMA_DEVICE_TO_DMA) != XST_SUCCESS ||
        XAxiDma_SimpleTransfer(&dma, (UINTPTR)fcc_in, FCC_IN_BYTES, XAXIDMA_DMA_TO_DEVICE) != XST_SUCCESS) {
        xil_printf("fcc: the DMA refused the transfer\r\n");
        return 1;
    }

@WAIT@    Xil_DCacheInvalidateRange((UINTPTR)fcc_out, FCC_OUT_BYTES);

    /* 8. The frame's latched status, then clear FRAME_DONE (and irq). */
    xil_printf("fcc: frame %u: %u clusters, %u provisional labels, %u unlabelled, flags 0x%x, %u joins, %u stalls\r\n",
               (unsigned)fcc_rd(FCC_REG_FRAME_COUNT), (unsigned)fcc_rd(FCC_REG_CLUSTERS),
               (unsigned)fcc_rd(FCC_REG_PROVISIONAL), (unsigned)fcc_rd(FCC_REG_UNLABELLED),
               (unsigned)fcc_rd(FCC_REG_FRAME_FLAGS), (unsigned)fcc_rd(FCC_REG_JOINS),
               (unsigned)fcc_rd(FCC_REG_GEAR_STALLS));
    fcc_wr(FCC_REG_STATUS, FCC_STATUS_FRAME_DONE_MASK);

    for (i = 0; i < FCC_PIXELS; i++) {
        labelled += fcc_label(i) != 0u;
    }
    xil_printf("fcc: %u labelled pixels\r\n", (unsigned)labelled);
    return 0;
}
"#;

/// The stream limits of a column build, written after the run parameters
/// (its power-on values here; each frame may take its own).
const STREAM_WRITES: &str = r#"    /*    The stream's limits (docs/spec.md, section 9.1): bridge, ring reach
     *    and open limit; here the build's power-on values. A refused value
     *    keeps the old one and sets its ERROR bit. */
    fcc_wr(FCC_REG_ERROR, FCC_ERROR_BRIDGE_MASK | FCC_ERROR_RING_REACH_MASK | FCC_ERROR_OPEN_LIMIT_MASK);
    fcc_wr(FCC_REG_RUN_BRIDGE, FCC_REG_RUN_BRIDGE_RESET);
    fcc_wr(FCC_REG_RUN_RING_REACH, FCC_REG_RUN_RING_REACH_RESET);
    fcc_wr(FCC_REG_RUN_OPEN_LIMIT, FCC_REG_RUN_OPEN_LIMIT_RESET);
    if (fcc_rd(FCC_REG_ERROR) != 0u) {
        xil_printf("fcc: stream limits refused (ERROR 0x%03x)\r\n", (unsigned)fcc_rd(FCC_REG_ERROR));
        return 1;
    }
"#;

/// The column-streaming core's example: the frame in column order, one
/// record per cluster and the frame's end beat back.
const COLUMN_EXAMPLE: &str = r#"//
// Bare-metal example for the @TITLE@ block design (scripts/@BD@, exported
// as an .xsa) with the column-streaming core (fcc gen --scan column): sends
// one frame in column order through the AXI DMA in simple mode, waits for
// the core, and reads back one record per cluster and the frame's end beat
// (docs/spec.md, section 9.4). C99, for a Vitis standalone application;
// @ADDR_NOTE@.
//
@BUILD@//
// The sequence: check ID and parameter hash; clear; enable the interrupt;
// write the run parameters and the stream's limits; arm S2MM (records)
// before MM2S (pixels); wait for STATUS.FRAME_DONE (the level of the core's
// irq) and for both DMA channels; read the records (S2MM's length register
// says how many bytes came: the records, then the end beat); read the
// latched status; clear FRAME_DONE. The S2MM transfer is the whole frame's:
// the simple-mode DMA ends each transfer at tlast, which the core raises on
// the end beat only.

@HEAD@/* The frame this build takes (build constants of fcc_regs.h). */
#define FCC_ROWS FCC_REG_ROWS_MAX_RESET
#define FCC_COLS FCC_REG_COLS_MAX_RESET
#define FCC_PIXELS (FCC_ROWS * FCC_COLS)
/* The most beats a frame's records take: a record (FCC_RECORD_WORDS beats)
 * per pixel at most, then the end beat. */
#define FCC_OUT_WORDS @OUT_WORDS@u
@SIZES@/* 16-bit fields: coordinates in an input word. */
#define FCC_SLOT_BITS @SLOT_BITS@u
@BUFFERS@
@QUANTIZE@/* Bits shift .. shift + bits - 1 of w, two's complement when sign. */
static int64_t fcc_bits(uint64_t w, unsigned shift, unsigned bits, unsigned sign)
{
    uint64_t m = bits >= 64u ? ~(uint64_t)0 : (((uint64_t)1 << bits) - 1u);
    uint64_t v = (w >> shift) & m;
    if (sign != 0u && bits < 64u && ((v >> (bits - 1u)) & 1u) != 0u) {
        v |= ~m;
    }
    return (int64_t)v;
}

/* Field F of the record at r, by its layout in fcc_regs.h. */
#define FCC_REC(r, F)                                                                          \
    fcc_bits((r)[FCC_REC_##F##_WORD], FCC_REC_##F##_SHIFT, FCC_REC_##F##_BITS,                 \
             FCC_REC_##F##_SIGNED)
#define FCC_END(w, F) fcc_bits((w), FCC_END_##F##_SHIFT, FCC_END_##F##_BITS, 0u)

/* The frame's output as the core sent it, `beats` 64-bit words: a record
 * of FCC_RECORD_WORDS beats per cluster in closing order, then the end
 * beat. Prints each record (its box in Q7.8, 1/256 m) and the end beat;
 * returns the number of records, or -1 when the words are not one frame's. */
int fcc_read_records(const uint64_t *w, uint32_t beats)
{
    uint32_t n, i;
    int64_t counted;
    if (beats == 0u || (beats - 1u) % FCC_RECORD_WORDS != 0u) {
        xil_printf("fcc: %u beats: not records of %u beats and an end beat\r\n", (unsigned)beats,
                   (unsigned)FCC_RECORD_WORDS);
        return -1;
    }
    n = (beats - 1u) / FCC_RECORD_WORDS;
    for (i = 0; i < n; i++) {
        const uint64_t *r = w + (size_t)i * FCC_RECORD_WORDS;
        xil_printf("fcc: cluster %u: %u points, columns %u..%u, closed at %u, rows %u..%u, "
                   "x %d..%d, y %d..%d, z %d..%d\r\n",
                   (unsigned)FCC_REC(r, ID), (unsigned)FCC_REC(r, POINTS),
                   (unsigned)FCC_REC(r, FIRST_COL), (unsigned)FCC_REC(r, LAST_COL),
                   (unsigned)FCC_REC(r, CLOSED_COL), (unsigned)FCC_REC(r, FIRST_ROW),
                   (unsigned)FCC_REC(r, LAST_ROW), (int)FCC_REC(r, MIN_X), (int)FCC_REC(r, MAX_X),
                   (int)FCC_REC(r, MIN_Y), (int)FCC_REC(r, MAX_Y), (int)FCC_REC(r, MIN_Z),
                   (int)FCC_REC(r, MAX_Z));
    }
    counted = FCC_END(w[beats - 1u], RECORDS);
    xil_printf("fcc: end of frame: %u records, overflow %u, frame error %u\r\n", (unsigned)counted,
               (unsigned)FCC_END(w[beats - 1u], OVERFLOW),
               (unsigned)FCC_END(w[beats - 1u], FRAME_ERROR));
    if (counted != (int64_t)n) {
        xil_printf("fcc: the end beat counts %u records, %u came\r\n", (unsigned)counted, (unsigned)n);
        return -1;
    }
    return (int)n;
}

/* A demonstration frame: two short walls of points 10 m ahead, on the
 * first two rows, far enough apart to be two clusters, in column order
 * (pixel (r, c) at index c * FCC_ROWS + r). Replace it with a sensor's
 * columns (x, y, z per pixel, NaN for no return). */
static void fcc_demo_frame(void)
{
    uint32_t i;
    for (i = 0; i < FCC_PIXELS; i++) {
        uint32_t c = i / FCC_ROWS, r = i % FCC_ROWS;
        int wall = r < 2u && (c < 4u || (c >= 16u && c < 20u));
        fcc_in[i] = wall ? fcc_pack_pixel(10.0, 0.05 * (double)c, 0.1 * (double)r) : 0;
    }
}

int main(void)
{
    XAxiDma dma;
    XAxiDma_Config *cfg;
    uint32_t polls, status, received;
    uint64_t hash;

@OPEN@    /* 4. Run parameters and the stream's limits. */
@RUN_WRITES@@STREAM_WRITES@
    /* 5. The frame, out of the data cache; the record buffer invalidated. */
    fcc_demo_frame();
    Xil_DCacheFlushRange((UINTPTR)fcc_in, FCC_IN_BYTES);
    Xil_DCacheInvalidateRange((UINTPTR)fcc_out, FCC_OUT_BYTES);

    /* 6. Arm S2MM (records) first, then start MM2S (pixels). */
    if (XAxiDma_SimpleTransfer(&dma, (UINTPTR)fcc_out, FCC_OUT_BYTES, XAXIDMA_DEVICE_TO_DMA) != XST_SUCCESS ||
        XAxiDma_SimpleTransfer(&dma, (UINTPTR)fcc_in, FCC_IN_BYTES, XAXIDMA_DMA_TO_DEVICE) != XST_SUCCESS) {
        xil_printf("fcc: the DMA refused the transfer\r\n");
        return 1;
    }

@WAIT@    /* 8. The records: S2MM's length register holds the bytes received. */
    received = XAxiDma_ReadReg(dma.RegBase, XAXIDMA_RX_OFFSET + XAXIDMA_BUFFLEN_OFFSET);
    Xil_DCacheInvalidateRange((UINTPTR)fcc_out, FCC_OUT_BYTES);
    if (received % @PIXEL_BYTES@u != 0u || fcc_read_records(fcc_out, received / @PIXEL_BYTES@u) < 0) {
        xil_printf("fcc: %u bytes received are not one frame's records\r\n", (unsigned)received);
        return 1;
    }

    /* 9. The frame's latched status, then clear FRAME_DONE (and irq). */
    xil_printf("fcc: frame %u: %u clusters, %u labels in use at most, flags 0x%x, %u joins, %u cycles held\r\n",
               (unsigned)fcc_rd(FCC_REG_FRAME_COUNT), (unsigned)fcc_rd(FCC_REG_CLUSTERS),
               (unsigned)fcc_rd(FCC_REG_PROVISIONAL), (unsigned)fcc_rd(FCC_REG_FRAME_FLAGS),
               (unsigned)fcc_rd(FCC_REG_JOINS), (unsigned)fcc_rd(FCC_REG_GEAR_STALLS));
    fcc_wr(FCC_REG_STATUS, FCC_STATUS_FRAME_DONE_MASK);
    return 0;
}
"#;
