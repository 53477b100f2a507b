// C ABI around the Verilator model of fcc_regs (the register file alone),
// loaded at run time by the fcc-sim crate. One call advances one clock cycle.
#include "Vfcc_regs.h"
#include "fcc_ffi.h"
#include "vl_model.h"

extern "C" {

void* fcc_regs_new() { return vl_model_new<Vfcc_regs>("fcc_regs"); }

void fcc_regs_free(void* p) { vl_model_free<Vfcc_regs>(p); }

void fcc_regs_step(void* p, const RegsIn* in, RegsOut* out) {
    vl_model_step<Vfcc_regs>(
        p,
        [in](Vfcc_regs* t) {
            FCC_DRIVE_RegsIn(t, in);
            t->s_axil_wstrb = 0xf;  // every byte lane written
        },
        [out](Vfcc_regs* t) { FCC_SAMPLE_RegsOut(t, out); });
}

}  // extern "C"
