// Life-cycle of one Verilator model behind the C ABI of the fcc-sim shims:
// create with reset high, free (writing coverage counts in a coverage
// build), and one clock cycle per step.
#pragma once
#include <atomic>
#include <cstdlib>
#include <string>
#include <unistd.h>

#include "verilated.h"
#if VM_COVERAGE
#include "verilated_cov.h"
#endif

template <class Top>
struct VlModel {
    VerilatedContext ctx;
    Top* top;
};

// Hold a model's reset, if it has one (a pipeline without state to reset,
// such as fcc_point_thr, has none).
template <class Top>
auto vl_hold_reset(Top* t, int) -> decltype(t->rst = 1, void()) {
    t->rst = 1;
}
template <class Top>
void vl_hold_reset(Top*, long) {}

// A fresh model named `name`, clock low and reset held.
template <class Top>
void* vl_model_new(const char* name) {
    auto* m = new VlModel<Top>;
    m->top = new Top(&m->ctx, name);
    m->top->clk = 0;
    vl_hold_reset(m->top, 0);
    m->top->eval();
    return m;
}

template <class Top>
void vl_model_free(void* p) {
    auto* m = static_cast<VlModel<Top>*>(p);
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

// One clock cycle: `drive` sets the inputs, the model settles with the clock
// low, `sample` reads the outputs seen before the rising edge, then the edge.
template <class Top, class Drive, class Sample>
void vl_model_step(void* p, Drive drive, Sample sample) {
    auto* m = static_cast<VlModel<Top>*>(p);
    Top* t = m->top;
    drive(t);
    t->clk = 0;
    t->eval();
    sample(t);
    t->clk = 1;
    t->eval();
    m->ctx.timeInc(1);
}
