//! The register file `fcc_regs` alone under Verilator: built (once, cached)
//! from `fcc_rtl::generate_regs`, driven through its AXI4-Lite port and its
//! frame-status inputs.

use std::collections::HashMap;
use std::ffi::c_void;
use std::path::Path;
use std::sync::{Arc, Mutex, OnceLock};

use fcc_params::FccParams;

use crate::axil::{AxilM, AxilPort, AxilS};
use crate::ffi::c_struct;
use crate::model::{build, cache_root, fnv, shim_text, Shim};
use crate::SimError;

const SHIM: &str = include_str!("../csrc/fcc_regs_shim.cpp");
const LIB_NAME: &str = "libfcc_regs_sim.so";

c_struct! {
    /// Inputs of one cycle (declared to the shim by the generated `fcc_ffi.h`).
    pub struct RegsIn {
        pub awaddr: u32,
        pub wdata: u32,
        pub araddr: u32,
        pub unlabelled: u32,
        pub joins: u32,
        pub gear_stalls: u32,
        pub clusters: u16,
        pub provisional: u16,
        pub awvalid: u8,
        pub wvalid: u8,
        pub bready: u8,
        pub arvalid: u8,
        pub rready: u8,
        pub rst: u8,
        pub frame_end: u8,
        pub idle: u8,
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
        pub rdata: u32,
        pub st_unlabelled: u32,
        pub st_joins: u32,
        pub st_gear_stalls: u32,
        pub st_clusters: u16,
        pub st_provisional: u16,
        pub awready: u8,
        pub wready: u8,
        pub bvalid: u8,
        pub bresp: u8,
        pub arready: u8,
        pub rvalid: u8,
        pub rresp: u8,
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

type NewFn = unsafe extern "C" fn() -> *mut c_void;
type FreeFn = unsafe extern "C" fn(*mut c_void);
type StepFn = unsafe extern "C" fn(*mut c_void, *const RegsIn, *mut RegsOut);

/// A loaded Verilator model of `fcc_regs`.
pub struct RegsModel {
    new_fn: NewFn,
    free_fn: FreeFn,
    step_fn: StepFn,
    _lib: libloading::Library,
}

/// Load the register-file model of the build `p`, building it if needed.
pub fn load_regs(p: &FccParams) -> Result<Arc<RegsModel>, SimError> {
    static MODELS: OnceLock<Mutex<HashMap<String, Arc<RegsModel>>>> = OnceLock::new();
    let models = MODELS.get_or_init(|| Mutex::new(HashMap::new()));
    let mut map = models.lock().unwrap_or_else(|e| e.into_inner());
    let verilog = fcc_rtl::generate_regs(p)?;
    let vlt = fcc_rtl::lint::regs_waivers(p);
    let key = format!(
        "regs-{:016x}",
        fnv(&format!("{verilog}{vlt}{}", shim_text(SHIM)))
    );
    if let Some(m) = map.get(&key) {
        return Ok(m.clone());
    }
    let dir = cache_root().join(&key);
    if !dir.join(LIB_NAME).exists() {
        build(
            &[("fcc_regs.v", &verilog), ("fcc_regs.vlt", &vlt)],
            &dir,
            &Shim {
                name: "fcc_regs_shim.cpp",
                text: SHIM,
                top: &fcc_rtl::regs_module(p),
                prefix: "Vfcc_regs",
                sources: &["fcc_regs.vlt", "fcc_regs.v"],
                lib: LIB_NAME,
                coverage: false,
            },
        )?;
    }
    let model = Arc::new(open(&dir)?);
    map.insert(key, model.clone());
    Ok(model)
}

fn open(dir: &Path) -> Result<RegsModel, SimError> {
    let path = dir.join(LIB_NAME);
    let err = |source| SimError::Load {
        path: path.clone(),
        source,
    };
    // SAFETY: the library is built from our own shim; loading it runs no
    // initialisers beyond the C++ runtime's.
    let lib = unsafe { libloading::Library::new(&path) }.map_err(err)?;
    // SAFETY: the symbol types match the `extern "C"` declarations in the shim.
    let (new_fn, free_fn, step_fn) = unsafe {
        let n: NewFn = *lib.get::<NewFn>(b"fcc_regs_new\0").map_err(err)?;
        let f: FreeFn = *lib.get::<FreeFn>(b"fcc_regs_free\0").map_err(err)?;
        let s: StepFn = *lib.get::<StepFn>(b"fcc_regs_step\0").map_err(err)?;
        (n, f, s)
    };
    Ok(RegsModel {
        new_fn,
        free_fn,
        step_fn,
        _lib: lib,
    })
}

/// One simulated register file.
pub struct RegsDut {
    model: Arc<RegsModel>,
    handle: *mut c_void,
    /// The non-AXI inputs applied in every cycle (frame status, reset).
    pub live: RegsIn,
    /// The outputs of the last cycle.
    pub last: RegsOut,
}

impl RegsDut {
    pub fn new(model: Arc<RegsModel>) -> Self {
        // SAFETY: a fresh model from the same library, freed in `drop`.
        let handle = unsafe { (model.new_fn)() };
        RegsDut {
            model,
            handle,
            live: RegsIn::default(),
            last: RegsOut::default(),
        }
    }

    /// One cycle with `inp`.
    pub fn step(&mut self, inp: &RegsIn) -> RegsOut {
        let mut out = RegsOut::default();
        // SAFETY: `handle` is live; both pointers refer to `repr(C)` values.
        unsafe { (self.model.step_fn)(self.handle, inp, &mut out) };
        self.last = out;
        out
    }

    /// One cycle with the live inputs and the AXI4-Lite master idle.
    pub fn idle(&mut self) -> RegsOut {
        let inp = RegsIn {
            bready: 1,
            rready: 1,
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

impl Drop for RegsDut {
    fn drop(&mut self) {
        // SAFETY: freed exactly once, with the library still loaded.
        unsafe { (self.model.free_fn)(self.handle) };
    }
}

impl AxilPort for RegsDut {
    fn axil_cycle(&mut self, m: &AxilM) -> AxilS {
        let inp = RegsIn {
            awaddr: m.awaddr,
            awvalid: u8::from(m.awvalid),
            wdata: m.wdata,
            wvalid: u8::from(m.wvalid),
            bready: u8::from(m.bready),
            araddr: m.araddr,
            arvalid: u8::from(m.arvalid),
            rready: u8::from(m.rready),
            ..self.live
        };
        let o = self.step(&inp);
        AxilS {
            awready: o.awready != 0,
            wready: o.wready != 0,
            bvalid: o.bvalid != 0,
            bresp: o.bresp,
            arready: o.arready != 0,
            rvalid: o.rvalid != 0,
            rdata: o.rdata,
            rresp: o.rresp,
        }
    }
}
