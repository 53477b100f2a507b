// C ABI around the Verilator model of fcc_top, loaded at run time by the
// fcc-sim crate. One call advances one clock cycle.
#include "Vfcc_top.h"
#include "fcc_ffi.h"
#include "vl_model.h"

extern "C" {

void* fcc_new() { return vl_model_new<Vfcc_top>("fcc_top"); }

void fcc_free(void* p) { vl_model_free<Vfcc_top>(p); }

void fcc_step(void* p, const FccIn* in, FccOut* out) {
    vl_model_step<Vfcc_top>(
        p,
        [in](Vfcc_top* t) {
            FCC_DRIVE_FccIn(t, in);
            t->s_axis_tkeep = 0xff;  // every byte of a pixel beat
            t->s_axil_wstrb = 0xf;   // every byte lane written
        },
        [out](Vfcc_top* t) { FCC_SAMPLE_FccOut(t, out); });
}

}  // extern "C"
