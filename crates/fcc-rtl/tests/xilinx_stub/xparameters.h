/* Test stand-in for a BSP's generated xparameters.h. */
#ifndef XPARAMETERS_H
#define XPARAMETERS_H
#define XPAR_FCC_BASEADDR 0x43C00000u
#define XPAR_AXIDMA_0_DEVICE_ID 0u
#endif
