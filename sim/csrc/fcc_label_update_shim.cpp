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
        [in](Vfcc_label_update* t) {
            t->rst = in->rst;
            t->wr_valid = in->wr_valid;
            t->wr_state = in->wr_state;
            t->wr_last = in->wr_last;
            t->rb_start = in->rb_start;
            t->fv = in->fv;
            t->fval = in->fval;
            t->m_axis_tready = in->tready;
        },
        [out](Vfcc_label_update* t) {
            out->tdata = t->m_axis_tdata;
            out->gear_stalls = t->gear_stalls;
            out->tkeep = t->m_axis_tkeep;
            out->tvalid = t->m_axis_tvalid;
            out->tlast = t->m_axis_tlast;
            out->rb_done = t->rb_done;
            out->gear_used = t->gear_used;
        });
}

}  // extern "C"
