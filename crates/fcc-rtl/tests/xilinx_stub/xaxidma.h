/* Test stand-in for the standalone XAxiDma driver's xaxidma.h: the types,
 * constants and calls of simple (register) mode only. */
#ifndef XAXIDMA_H
#define XAXIDMA_H
#include "xil_io.h"
#include "xil_types.h"
#define XAXIDMA_DMA_TO_DEVICE 0x00
#define XAXIDMA_DEVICE_TO_DMA 0x01
#define XAXIDMA_IRQ_ALL_MASK 0x00007000
/* xaxidma_hw.h (which xaxidma.h includes): the S2MM channel's registers
 * and the register read. */
#define XAXIDMA_RX_OFFSET 0x00000030
#define XAXIDMA_BUFFLEN_OFFSET 0x00000028
#define XAxiDma_ReadReg(BaseAddress, RegOffset) Xil_In32((BaseAddress) + (u32)(RegOffset))
typedef struct {
    u32 DeviceId;
    UINTPTR BaseAddr;
    int HasSg;
} XAxiDma_Config;
typedef struct {
    UINTPTR RegBase;
    int HasSg;
} XAxiDma;
XAxiDma_Config *XAxiDma_LookupConfig(u32 DeviceId);
int XAxiDma_CfgInitialize(XAxiDma *InstancePtr, XAxiDma_Config *Config);
int XAxiDma_HasSg(XAxiDma *InstancePtr);
void XAxiDma_IntrDisable(XAxiDma *InstancePtr, u32 Mask, int Direction);
u32 XAxiDma_SimpleTransfer(XAxiDma *InstancePtr, UINTPTR BuffAddr, u32 Length, int Direction);
u32 XAxiDma_Busy(XAxiDma *InstancePtr, int Direction);
void XAxiDma_Reset(XAxiDma *InstancePtr);
#endif
