//! The label updater `fcc_label_update` alone under Verilator: built (once,
//! cached) from `fcc_rtl::generate_label_update`, fed frame-buffer codes and
//! compact labels, its output stream read with back-pressure.

use std::collections::HashMap;
use std::ffi::c_void;
use std::path::Path;
use std::sync::{Arc, Mutex, OnceLock};

use fcc_params::FccParams;

use crate::ffi::c_struct;
use crate::model::{build, cache_root, fnv, shim_text, Shim};
use crate::SimError;

const SHIM: &str = include_str!("../csrc/fcc_label_update_shim.cpp");
const LIB_NAME: &str = "libfcc_label_update_sim.so";

c_struct! {
    /// Inputs of one cycle (declared to the shim by the generated `fcc_ffi.h`).
    pub struct LuIn {
        /// Compact label pushed into the gearbox (with `fv`).
        pub fval: u16,
        pub rst: u8,
        /// A labelled pixel's frame-buffer code (`wr_state`), the frame's last pixel.
        pub wr_valid: u8,
        pub wr_state: u8,
        pub wr_last: u8,
        /// Start of the read-back of the frame written.
        pub rb_start: u8,
        pub fv: u8,
        pub tready: u8,
    }
}

c_struct! {
    /// Outputs during one cycle.
    pub struct LuOut {
        pub tdata: u64,
        pub gear_stalls: u32,
        pub tkeep: u8,
        pub tvalid: u8,
        pub tlast: u8,
        pub rb_done: u8,
        /// Compact labels waiting in the gearbox.
        pub gear_used: u8,
    }
}

type NewFn = unsafe extern "C" fn() -> *mut c_void;
type FreeFn = unsafe extern "C" fn(*mut c_void);
type StepFn = unsafe extern "C" fn(*mut c_void, *const LuIn, *mut LuOut);

/// A loaded Verilator model of `fcc_label_update`.
pub struct LuModel {
    new_fn: NewFn,
    free_fn: FreeFn,
    step_fn: StepFn,
    _lib: libloading::Library,
}

/// Load the label-updater model of the build `p`, building it if needed.
pub fn load_label_update(p: &FccParams) -> Result<Arc<LuModel>, SimError> {
    static MODELS: OnceLock<Mutex<HashMap<String, Arc<LuModel>>>> = OnceLock::new();
    let models = MODELS.get_or_init(|| Mutex::new(HashMap::new()));
    let mut map = models.lock().unwrap_or_else(|e| e.into_inner());
    let verilog = fcc_rtl::generate_label_update(p)?;
    let vlt = fcc_rtl::lint::label_update_waivers(p);
    let key = format!(
        "label-update-{:016x}",
        fnv(&format!("{verilog}{vlt}{}", shim_text(SHIM)))
    );
    if let Some(m) = map.get(&key) {
        return Ok(m.clone());
    }
    let dir = cache_root().join(&key);
    if !dir.join(LIB_NAME).exists() {
        build(
            &[
                ("fcc_label_update.v", &verilog),
                ("fcc_label_update.vlt", &vlt),
            ],
            &dir,
            &Shim {
                name: "fcc_label_update_shim.cpp",
                text: SHIM,
                top: &fcc_rtl::label_update_module(p),
                prefix: "Vfcc_label_update",
                sources: &["fcc_label_update.vlt", "fcc_label_update.v"],
                lib: LIB_NAME,
                coverage: false,
            },
        )?;
    }
    let model = Arc::new(open(&dir)?);
    map.insert(key, model.clone());
    Ok(model)
}

fn open(dir: &Path) -> Result<LuModel, SimError> {
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
        let n: NewFn = *lib.get::<NewFn>(b"fcc_label_update_new\0").map_err(err)?;
        let f: FreeFn = *lib.get::<FreeFn>(b"fcc_label_update_free\0").map_err(err)?;
        let s: StepFn = *lib.get::<StepFn>(b"fcc_label_update_step\0").map_err(err)?;
        (n, f, s)
    };
    Ok(LuModel {
        new_fn,
        free_fn,
        step_fn,
        _lib: lib,
    })
}

/// One simulated label updater.
pub struct LuDut {
    model: Arc<LuModel>,
    handle: *mut c_void,
}

impl LuDut {
    pub fn new(model: Arc<LuModel>) -> Self {
        // SAFETY: a fresh model from the same library, freed in `drop`.
        let handle = unsafe { (model.new_fn)() };
        LuDut { model, handle }
    }

    /// One cycle with `inp`; the outputs seen before the clock edge.
    pub fn step(&mut self, inp: &LuIn) -> LuOut {
        let mut out = LuOut::default();
        // SAFETY: `handle` is live; both pointers refer to `repr(C)` values.
        unsafe { (self.model.step_fn)(self.handle, inp, &mut out) };
        out
    }
}

impl Drop for LuDut {
    fn drop(&mut self) {
        // SAFETY: freed exactly once, with the library still loaded.
        unsafe { (self.model.free_fn)(self.handle) };
    }
}
