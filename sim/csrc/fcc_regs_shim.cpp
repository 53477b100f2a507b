// C ABI around the Verilator model of fcc_regs (the register file alone),
// loaded at run time by the fcc-sim crate. One call advances one clock cycle.
#include <cstdint>

#include "Vfcc_regs.h"
#include "verilated.h"

extern "C" {

// Inputs for one cycle (must match `RegsIn` in sim/src/regs_bench.rs).
struct RegsIn {
    uint32_t awaddr;
    uint32_t wdata;
    uint32_t araddr;
    uint32_t unlabelled;
    uint32_t joins;
    uint32_t gear_stalls;
    uint16_t clusters;
    uint16_t provisional;
    uint8_t awvalid;
    uint8_t wvalid;
    uint8_t bready;
    uint8_t arvalid;
    uint8_t rready;
    uint8_t rst;
    uint8_t frame_end;
    uint8_t idle;
    uint8_t overflow;
    uint8_t frame_error;
};

// Outputs seen during that cycle, before its rising edge (must match `RegsOut`).
struct RegsOut {
    uint64_t run_th_h_c;
    uint64_t run_th_v_c;
    uint32_t rdata;
    uint32_t st_unlabelled;
    uint32_t st_joins;
    uint32_t st_gear_stalls;
    uint16_t st_clusters;
    uint16_t st_provisional;
    uint8_t awready;
    uint8_t wready;
    uint8_t bvalid;
    uint8_t bresp;
    uint8_t arready;
    uint8_t rvalid;
    uint8_t rresp;
    uint8_t irq;
    uint8_t core_rst;
    uint8_t frame_done;
    uint8_t st_overflow;
    uint8_t st_frame_error;
    uint8_t run_k;
    uint8_t run_rows;
    uint16_t run_cols;
};

struct RegsModel {
    VerilatedContext ctx;
    Vfcc_regs* top;
};

void* fcc_regs_new() {
    RegsModel* m = new RegsModel;
    m->top = new Vfcc_regs(&m->ctx, "fcc_regs");
    m->top->clk = 0;
    m->top->rst = 1;
    m->top->eval();
    return m;
}

void fcc_regs_free(void* p) {
    RegsModel* m = static_cast<RegsModel*>(p);
    if (m == nullptr) return;
    m->top->final();
    delete m->top;
    delete m;
}

void fcc_regs_step(void* p, const RegsIn* in, RegsOut* out) {
    RegsModel* m = static_cast<RegsModel*>(p);
    Vfcc_regs* t = m->top;
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
    t->clk = 0;
    t->eval();
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
    out->run_k = t->run_k;
    out->run_rows = t->run_rows;
    out->run_cols = t->run_cols;
    out->run_th_h_c = t->run_th_h_c;
    out->run_th_v_c = t->run_th_v_c;
    t->clk = 1;
    t->eval();
    m->ctx.timeInc(1);
}

}  // extern "C"
