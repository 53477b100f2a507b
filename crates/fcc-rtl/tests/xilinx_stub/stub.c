/* Definitions of the stand-in BSP calls, so that a host program can link
 * the example; none of them is meant to run but xil_printf, which prints
 * to stdout (the record test reads it). */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include "xaxidma.h"
#include "xil_cache.h"
#include "xil_io.h"
#include "xil_printf.h"

u32 Xil_In32(UINTPTR Addr) { (void)Addr; abort(); }
void Xil_Out32(UINTPTR Addr, u32 Value) { (void)Addr; (void)Value; abort(); }
void Xil_DCacheFlushRange(INTPTR adr, u32 len) { (void)adr; (void)len; abort(); }
void Xil_DCacheInvalidateRange(INTPTR adr, u32 len) { (void)adr; (void)len; abort(); }
void xil_printf(const char *ctrl1, ...)
{
    va_list ap;
    va_start(ap, ctrl1);
    vprintf(ctrl1, ap);
    va_end(ap);
}
XAxiDma_Config *XAxiDma_LookupConfig(u32 DeviceId) { (void)DeviceId; abort(); }
int XAxiDma_CfgInitialize(XAxiDma *InstancePtr, XAxiDma_Config *Config) { (void)InstancePtr; (void)Config; abort(); }
int XAxiDma_HasSg(XAxiDma *InstancePtr) { (void)InstancePtr; abort(); }
void XAxiDma_IntrDisable(XAxiDma *InstancePtr, u32 Mask, int Direction) { (void)InstancePtr; (void)Mask; (void)Direction; abort(); }
u32 XAxiDma_SimpleTransfer(XAxiDma *InstancePtr, UINTPTR BuffAddr, u32 Length, int Direction) { (void)InstancePtr; (void)BuffAddr; (void)Length; (void)Direction; abort(); }
u32 XAxiDma_Busy(XAxiDma *InstancePtr, int Direction) { (void)InstancePtr; (void)Direction; abort(); }
void XAxiDma_Reset(XAxiDma *InstancePtr) { (void)InstancePtr; abort(); }
