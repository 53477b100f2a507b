// C ABI around the Verilator model of fcc_top, loaded at run time by the
// fcc-sim crate. One call advances one clock cycle.
#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <unistd.h>

#include "Vfcc_top.h"
#include "verilated.h"
#if VM_COVERAGE
#include "verilated_cov.h"
#endif

extern "C" {

// Inputs for one cycle (must match `FccIn` in sim/src/ffi.rs).
struct FccIn {
    uint64_t s_tdata;
    uint8_t s_tvalid;
    uint8_t s_tlast;
    uint8_t m_tready;
    uint8_t rst;
    // AXI4-Lite master side.
    uint32_t awaddr;
    uint32_t wdata;
    uint32_t araddr;
    uint8_t awvalid;
    uint8_t wvalid;
    uint8_t bready;
    uint8_t arvalid;
    uint8_t rready;
};

// Outputs seen during that cycle, before its rising edge (must match `FccOut`).
struct FccOut {
    uint64_t m_tdata;
    uint32_t clusters;
    uint32_t provisional;
    uint32_t unlabelled;
    uint32_t joins;
    uint32_t gear_stalls;
    uint8_t s_tready;
    uint8_t m_tvalid;
    uint8_t m_tlast;
    uint8_t m_tkeep;
    uint8_t frame_done;
    uint8_t frame_error;
    uint8_t overflow;
    uint8_t idle;
    // AXI4-Lite slave side and the interrupt.
    uint32_t rdata;
    uint8_t awready;
    uint8_t wready;
    uint8_t bvalid;
    uint8_t bresp;
    uint8_t arready;
    uint8_t rvalid;
    uint8_t rresp;
    uint8_t irq;
};

struct FccModel {
    VerilatedContext ctx;
    Vfcc_top* top;
};

void* fcc_new() {
    FccModel* m = new FccModel;
    m->top = new Vfcc_top(&m->ctx, "fcc_top");
    m->top->clk = 0;
    m->top->rst = 1;
    m->top->eval();
    return m;
}

void fcc_free(void* p) {
    FccModel* m = static_cast<FccModel*>(p);
    if (m == nullptr) return;
    m->top->final();
#if VM_COVERAGE
    // Coverage build (FCC_SIM_COVERAGE set when the model was built): one
    // file of line and toggle counts per simulated instance.
    if (const char* dir = std::getenv("FCC_SIM_COVERAGE")) {
        static std::atomic<unsigned> serial{0};
        std::string path = std::string(dir) + "/fcc-" + std::to_string(getpid()) + "-" +
                           std::to_string(serial++) + ".dat";
        m->ctx.coveragep()->write(path.c_str());
    }
#endif
    delete m->top;
    delete m;
}

void fcc_step(void* p, const FccIn* in, FccOut* out) {
    FccModel* m = static_cast<FccModel*>(p);
    Vfcc_top* t = m->top;
    t->s_axis_tdata = in->s_tdata;
    t->s_axis_tvalid = in->s_tvalid;
    t->s_axis_tlast = in->s_tlast;
    t->m_axis_tready = in->m_tready;
    t->rst = in->rst;
    t->s_axis_tkeep = 0xff;
    t->s_axil_awaddr = in->awaddr;
    t->s_axil_awvalid = in->awvalid;
    t->s_axil_wdata = in->wdata;
    t->s_axil_wstrb = 0xf;
    t->s_axil_wvalid = in->wvalid;
    t->s_axil_bready = in->bready;
    t->s_axil_araddr = in->araddr;
    t->s_axil_arvalid = in->arvalid;
    t->s_axil_rready = in->rready;
    t->clk = 0;
    t->eval();
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
    out->rdata = t->s_axil_rdata;
    out->awready = t->s_axil_awready;
    out->wready = t->s_axil_wready;
    out->bvalid = t->s_axil_bvalid;
    out->bresp = t->s_axil_bresp;
    out->arready = t->s_axil_arready;
    out->rvalid = t->s_axil_rvalid;
    out->rresp = t->s_axil_rresp;
    out->irq = t->irq;
    t->clk = 1;
    t->eval();
    m->ctx.timeInc(1);
}

}  // extern "C"
