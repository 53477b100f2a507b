// C ABI around the Verilator model of fcc_label_update (the label updater
// alone), loaded at run time by the fcc-sim crate. One call advances one
// clock cycle.
#include "Vfcc_label_update.h"
#include "fcc_ffi.h"
#include "vl_model.h"

extern "C" {

void* fcc_label_update_new() { return vl_model_new<Vfcc_label_update>("fcc_label_update"); }

void fcc_label_update_free(void* p) { vl_model_free<Vfcc_label_update>(p); }

void fcc_label_update_step(void* p, const LuIn* in, LuOut* out) {
    vl_model_step<Vfcc_label_update>(
        p,
        [in](Vfcc_label_update* t) { FCC_DRIVE_LuIn(t, in); },
        [out](Vfcc_label_update* t) { FCC_SAMPLE_LuOut(t, out); });
}

}  // extern "C"
