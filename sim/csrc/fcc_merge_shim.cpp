// C ABI around the Verilator model of fcc_merge_table (the merge table alone),
// loaded at run time by the fcc-sim crate. One call advances one clock cycle.
#include "Vfcc_merge_table.h"
#include "fcc_ffi.h"
#include "vl_model.h"

extern "C" {

void* fcc_merge_new() { return vl_model_new<Vfcc_merge_table>("fcc_merge_table"); }

void fcc_merge_free(void* p) { vl_model_free<Vfcc_merge_table>(p); }

void fcc_merge_step(void* p, const MergeIn* in, MergeOut* out) {
    vl_model_step<Vfcc_merge_table>(
        p,
        [in](Vfcc_merge_table* t) { FCC_DRIVE_MergeIn(t, in); },
        [out](Vfcc_merge_table* t) { FCC_SAMPLE_MergeOut(t, out); });
}

}  // extern "C"
