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
            t->s_axis_tdata = in->s_tdata;
            t->s_axis_tvalid = in->s_tvalid;
            t->s_axis_tlast = in->s_tlast;
            t->m_axis_tready = in->m_tready;
            t->rst = in->rst;
            t->s_axis_tkeep = 0xff;
            vl_drive_axil(t, in);
        },
        [out](Vfcc_top* t) {
            out->m_tdata = t->m_axis_tdata;
            out->clusters = t->status_clusters;
            out->provisional = t->status_provisional;
            out->unlabelled = t->status_unlabelled;
            out->joins = t->status_joins;
            out->gear_stalls = t->status_gear_stalls;
            out->s_tready = t->s_axis_tready;
            out->m_tvalid = t->m_axis_tvalid;
            out->m_tlast = t->m_axis_tlast;
            out->m_tkeep = t->m_axis_tkeep;
            out->frame_done = t->status_frame_done;
            out->frame_error = t->status_frame_error;
            out->overflow = t->status_overflow;
            out->idle = t->status_idle;
            vl_sample_axil(t, out);
        });
}

}  // extern "C"
