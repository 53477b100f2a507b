// C ABI around the Verilator model of fcc_point_thr (the per-point threshold
// unit alone), loaded at run time by the fcc-sim crate. One call advances one
// clock cycle.
#include "Vfcc_point_thr.h"
#include "fcc_ffi.h"
#include "vl_model.h"

extern "C" {

void* fcc_point_thr_new() { return vl_model_new<Vfcc_point_thr>("fcc_point_thr"); }

void fcc_point_thr_free(void* p) { vl_model_free<Vfcc_point_thr>(p); }

void fcc_point_thr_step(void* p, const PtIn* in, PtOut* out) {
    vl_model_step<Vfcc_point_thr>(
        p,
        [in](Vfcc_point_thr* t) { FCC_DRIVE_PtIn(t, in); },
        [out](Vfcc_point_thr* t) { FCC_SAMPLE_PtOut(t, out); });
}

}  // extern "C"
