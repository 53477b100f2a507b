// C ABI around the Verilator model of fcc_window_probe (the window and its
// line buffers alone), loaded at run time by the fcc-sim crate. One call
// advances one clock cycle and reads every window entry before the edge.
#include <cstdint>

#include "Vfcc_window_probe.h"
#include "fcc_ffi.h"
#include "vl_model.h"

extern "C" {

void* fcc_window_new() { return vl_model_new<Vfcc_window_probe>("fcc_window_probe"); }

void fcc_window_free(void* p) { vl_model_free<Vfcc_window_probe>(p); }

// `entries[e]` (e < n) gets entry e as ok << 48 | z << 32 | y << 16 | x.
void fcc_window_step(void* p, const WinIn* in, WinOut* out, uint64_t* entries, uint32_t n) {
    vl_model_step<Vfcc_window_probe>(
        p,
        [in](Vfcc_window_probe* t) { FCC_DRIVE_WinIn(t, in); },
        [out, entries, n](Vfcc_window_probe* t) {
            FCC_SAMPLE_WinOut(t, out);
            for (uint32_t e = 0; e < n; e++) {
                t->ent_sel = e;
                t->eval();
                entries[e] = (uint64_t(t->ent_ok) << 48) | (uint64_t(t->ent_z) << 32) |
                             (uint64_t(t->ent_y) << 16) | uint64_t(t->ent_x);
            }
        });
}

}  // extern "C"
