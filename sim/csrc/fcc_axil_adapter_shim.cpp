// C ABI around the Verilator model of fcc_axil_adapter (the register file's
// bus adapter alone), loaded at run time by the fcc-sim crate. One call
// advances one clock cycle.
#include <cstdint>

#include "Vfcc_axil_adapter.h"
#include "fcc_axil_adapter_ports.h"
#include "fcc_ffi.h"
#include "vl_model.h"

extern "C" {

void* fcc_axil_adapter_new() { return vl_model_new<Vfcc_axil_adapter>("fcc_axil_adapter"); }

void fcc_axil_adapter_free(void* p) { vl_model_free<Vfcc_axil_adapter>(p); }

// `we` holds FCC_AXIL_ADAPTER_N write-enables.
void fcc_axil_adapter_step(void* p, const AdIn* in, AdOut* out, uint8_t* we) {
    vl_model_step<Vfcc_axil_adapter>(
        p,
        [in](Vfcc_axil_adapter* t) { FCC_DRIVE_AdIn(t, in); },
        [out, we](Vfcc_axil_adapter* t) {
            FCC_SAMPLE_AdOut(t, out);
            FCC_AXIL_ADAPTER_WE(t, we);
        });
}

}  // extern "C"
