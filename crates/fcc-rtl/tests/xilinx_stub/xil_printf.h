/* Test stand-in for the Xilinx standalone BSP's xil_printf.h. */
#ifndef XIL_PRINTF_H
#define XIL_PRINTF_H
void xil_printf(const char *ctrl1, ...) __attribute__((format(printf, 1, 2)));
#endif
