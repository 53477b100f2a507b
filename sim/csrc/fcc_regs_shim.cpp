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
            t->rst = in->rst;
            vl_drive_axil(t, in);
            t->frame_sent = in->frame_sent;
            t->out_next = in->out_next;
            t->idle_next = in->idle_next;
            t->clusters = in->clusters;
            t->provisional = in->provisional;
            t->overflow = in->overflow;
            t->unlabelled = in->unlabelled;
            t->frame_error = in->frame_error;
            t->joins = in->joins;
            t->gear_stalls = in->gear_stalls;
        },
        [out](Vfcc_regs* t) {
            vl_sample_axil(t, out);
            out->st_unlabelled = t->st_unlabelled;
            out->st_joins = t->st_joins;
            out->st_gear_stalls = t->st_gear_stalls;
            out->st_clusters = t->st_clusters;
            out->st_provisional = t->st_provisional;
            out->core_rst = t->core_rst;
            out->frame_done = t->frame_done;
            out->st_overflow = t->st_overflow;
            out->st_frame_error = t->st_frame_error;
            out->run_k = t->run_k;
            out->run_rows = t->run_rows;
            out->run_cols = t->run_cols;
            out->run_th_h_c = t->run_th_h_c;
            out->run_th_v_c = t->run_th_v_c;
        });
}

}  // extern "C"
