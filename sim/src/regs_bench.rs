//! The register file `fcc_regs` alone under Verilator: built (once, cached)
//! from `fcc_rtl::generate_regs`, driven through its AXI4-Lite port and its
//! frame-status inputs.

use std::ffi::c_void;
use std::sync::{Arc, OnceLock};

use fcc_params::FccParams;

use crate::axil::{AxilM, AxilPort, AxilS};
use crate::block::{load_bench, BenchShim, BlockCache, BlockInstance, BlockModel};
use crate::ffi::c_struct;
use crate::SimError;

const SHIM: BenchShim = BenchShim {
    file: "fcc_regs_shim.cpp",
    text: include_str!("../csrc/fcc_regs_shim.cpp"),
    symbol: "fcc_regs",
};

c_struct! {
    /// Inputs of one cycle (declared to the shim by the generated `fcc_ffi.h`).
    pub struct RegsIn {
        pub s_axil_awaddr: u32,
        pub s_axil_wdata: u32,
        pub s_axil_araddr: u32,
        pub unlabelled: u32,
        pub joins: u32,
        pub gear_stalls: u32,
        pub clusters: u16,
        pub provisional: u16,
        pub s_axil_awvalid: u8,
        pub s_axil_wvalid: u8,
        pub s_axil_bready: u8,
        pub s_axil_arvalid: u8,
        pub s_axil_rready: u8,
        pub rst: u8,
        /// The frame's last label beat is accepted.
        pub frame_sent: u8,
        /// The core is in phase Out in the next cycle.
        pub out_next: u8,
        /// The core waits for a frame's first pixel in the next cycle.
        pub idle_next: u8,
        pub overflow: u8,
        pub frame_error: u8,
    }
}

c_struct! {
    /// Outputs during one cycle.
    pub struct RegsOut {
        /// Active -(tH^2 + 1), 36-bit two's complement.
        pub run_th_h_c: u64,
        /// Active -tV^2, 36-bit two's complement.
        pub run_th_v_c: u64,
        pub s_axil_rdata: u32,
        /// Active squared slopes `A^2 >> 8` (UQ0.24).
        pub run_sl_h: u32,
        pub run_sl_v: u32,
        pub st_unlabelled: u32,
        pub st_joins: u32,
        pub st_gear_stalls: u32,
        pub st_clusters: u16,
        pub st_provisional: u16,
        pub s_axil_awready: u8,
        pub s_axil_wready: u8,
        pub s_axil_bvalid: u8,
        pub s_axil_bresp: u8,
        pub s_axil_arready: u8,
        pub s_axil_rvalid: u8,
        pub s_axil_rresp: u8,
        pub irq: u8,
        pub core_rst: u8,
        pub frame_done: u8,
        pub st_overflow: u8,
        pub st_frame_error: u8,
        /// Active run parameters.
        pub run_k: u8,
        pub run_rows: u8,
        pub run_cols: u16,
    }
}

type StepFn = unsafe extern "C" fn(*mut c_void, *const RegsIn, *mut RegsOut);

/// A loaded Verilator model of `fcc_regs`.
pub type RegsModel = BlockModel<StepFn>;

/// Load the register-file model of the build `p`, building it if needed.
pub fn load_regs(p: &FccParams) -> Result<Arc<RegsModel>, SimError> {
    static MODELS: BlockCache<StepFn> = OnceLock::new();
    load_bench(&MODELS, fcc_rtl::BenchBlock::Regs, p, &SHIM, &[])
}

/// One simulated register file.
pub struct RegsDut {
    dut: BlockInstance<StepFn>,
    /// The non-AXI inputs applied in every cycle (frame status, reset).
    pub live: RegsIn,
    /// The outputs of the last cycle.
    pub last: RegsOut,
}

impl RegsDut {
    pub fn new(model: Arc<RegsModel>) -> Self {
        let dut = BlockInstance::new(model);
        RegsDut {
            dut,
            live: RegsIn::default(),
            last: RegsOut::default(),
        }
    }

    /// One cycle with `inp`.
    pub fn step(&mut self, inp: &RegsIn) -> RegsOut {
        let mut out = RegsOut::default();
        let (step, handle) = self.dut.step_fn();
        // SAFETY: `handle` is live; both pointers refer to `repr(C)` values.
        unsafe { step(handle, inp, &mut out) };
        self.last = out;
        out
    }

    /// One cycle with the live inputs and the AXI4-Lite master idle.
    pub fn idle(&mut self) -> RegsOut {
        let inp = RegsIn {
            s_axil_bready: 1,
            s_axil_rready: 1,
            ..self.live
        };
        self.step(&inp)
    }

    /// Hold `rst` for `cycles` cycles.
    pub fn reset(&mut self, cycles: u64) {
        for _ in 0..cycles {
            let inp = RegsIn {
                rst: 1,
                ..self.live
            };
            self.step(&inp);
        }
    }
}

impl AxilPort for RegsDut {
    fn axil_cycle(&mut self, m: &AxilM) -> AxilS {
        let o = self.step(&crate::axil::axil_inputs!(RegsIn, m, self.live));
        crate::axil::axil_outputs!(o)
    }
}
