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
        [in](Vfcc_window_probe* t) {
            t->rst = in->rst;
            t->in_valid = in->valid;
            t->in_lok = in->lok;
            t->in_x = in->x;
            t->in_y = in->y;
            t->in_z = in->z;
            t->in_row = in->row;
            t->in_col = in->col;
            t->in_rdcol = in->rdcol;
            t->last_col = in->last_col;
            t->run_k = in->run_k;
        },
        [out, entries, n](Vfcc_window_probe* t) {
            out->centre_valid = t->centre_valid;
            out->centre_x = t->centre_x;
            out->centre_col = t->centre_col;
            for (uint32_t e = 0; e < n; e++) {
                t->ent_sel = e;
                t->eval();
                entries[e] = (uint64_t(t->ent_ok) << 48) | (uint64_t(t->ent_z) << 32) |
                             (uint64_t(t->ent_y) << 16) | uint64_t(t->ent_x);
            }
        });
}

}  // extern "C"
