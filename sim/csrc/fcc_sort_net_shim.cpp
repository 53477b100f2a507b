// C ABI around the Verilator model of fcc_sort_net (the sort network alone),
// loaded at run time by the fcc-sim crate. One call advances one clock cycle.
#include <cstdint>

#include "Vfcc_sort_net.h"
#include "fcc_ffi.h"
#include "fcc_sort_net_ports.h"
#include "vl_model.h"

extern "C" {

void* fcc_sort_net_new() { return vl_model_new<Vfcc_sort_net>("fcc_sort_net"); }

void fcc_sort_net_free(void* p) { vl_model_free<Vfcc_sort_net>(p); }

// `hit` and `rep` hold FCC_SORT_NET_N positions each.
void fcc_sort_net_step(void* p, const SnIn* in, const uint8_t* hit, const uint16_t* rep,
                       SnOut* out) {
    vl_model_step<Vfcc_sort_net>(
        p,
        [in, hit, rep](Vfcc_sort_net* t) {
            t->rst = in->rst;
            t->clear = in->clear;
            t->centre = in->centre;
            FCC_SORT_NET_POSITIONS(t, hit, rep);
            // The union engine's take follows the queue's registered valid.
            t->jtake = 0;
            t->eval();
            t->jtake = t->jv & in->jready;
        },
        [out](Vfcc_sort_net* t) { FCC_SAMPLE_SnOut(t, out); });
}

}  // extern "C"
