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
            t->s_axil_awaddr = in->awaddr;
            t->s_axil_awvalid = in->awvalid;
            t->s_axil_wdata = in->wdata;
            t->s_axil_wstrb = 0xf;
            t->s_axil_wvalid = in->wvalid;
            t->s_axil_bready = in->bready;
            t->s_axil_araddr = in->araddr;
            t->s_axil_arvalid = in->arvalid;
            t->s_axil_rready = in->rready;
            t->frame_end = in->frame_end;
            t->idle = in->idle;
            t->clusters = in->clusters;
            t->provisional = in->provisional;
            t->overflow = in->overflow;
            t->unlabelled = in->unlabelled;
            t->frame_error = in->frame_error;
            t->joins = in->joins;
            t->gear_stalls = in->gear_stalls;
        },
        [out](Vfcc_regs* t) {
            out->rdata = t->s_axil_rdata;
            out->st_unlabelled = t->st_unlabelled;
            out->st_joins = t->st_joins;
            out->st_gear_stalls = t->st_gear_stalls;
            out->st_clusters = t->st_clusters;
            out->st_provisional = t->st_provisional;
            out->awready = t->s_axil_awready;
            out->wready = t->s_axil_wready;
            out->bvalid = t->s_axil_bvalid;
            out->bresp = t->s_axil_bresp;
            out->arready = t->s_axil_arready;
            out->rvalid = t->s_axil_rvalid;
            out->rresp = t->s_axil_rresp;
            out->irq = t->irq;
            out->core_rst = t->core_rst;
            out->frame_done = t->frame_done;
            out->st_overflow = t->st_overflow;
            out->st_frame_error = t->st_frame_error;
        });
}

}  // extern "C"
