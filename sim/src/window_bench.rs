//! The window `fcc_window` and its line buffers alone under Verilator: built
//! (once, cached) from `fcc_rtl::generate_window`, driven one pixel per cycle
//! through the scalar ports of `fcc_window_probe`, every window entry read
//! back in every cycle.

use std::collections::HashMap;
use std::ffi::c_void;
use std::path::Path;
use std::sync::{Arc, Mutex, OnceLock};

use fcc_params::FccParams;

use crate::ffi::c_struct;
use crate::model::{build, cache_root, fnv, shim_text, Shim};
use crate::SimError;

const SHIM: &str = include_str!("../csrc/fcc_window_shim.cpp");
const LIB_NAME: &str = "libfcc_window_sim.so";

c_struct! {
    /// Inputs of one cycle: the W0 pixel and the run size.
    pub struct WinIn {
        pub x: u16,
        pub y: u16,
        pub z: u16,
        pub col: u16,
        pub rdcol: u16,
        pub last_col: u16,
        pub row: u8,
        pub valid: u8,
        pub lok: u8,
        pub run_k: u8,
        pub rst: u8,
    }
}

c_struct! {
    /// The W3 centre during one cycle (its entries come apart, see [`WindowDut::step`]).
    pub struct WinOut {
        pub centre_x: u16,
        pub centre_col: u16,
        pub centre_valid: u8,
    }
}

type NewFn = unsafe extern "C" fn() -> *mut c_void;
type FreeFn = unsafe extern "C" fn(*mut c_void);
type StepFn = unsafe extern "C" fn(*mut c_void, *const WinIn, *mut WinOut, *mut u64, u32);

/// A loaded Verilator model of `fcc_window_probe`.
pub struct WindowModel {
    new_fn: NewFn,
    free_fn: FreeFn,
    step_fn: StepFn,
    entries: usize,
    _lib: libloading::Library,
}

/// Load the window model of the build `p`, building it if needed.
pub fn load_window(p: &FccParams) -> Result<Arc<WindowModel>, SimError> {
    static MODELS: OnceLock<Mutex<HashMap<String, Arc<WindowModel>>>> = OnceLock::new();
    let models = MODELS.get_or_init(|| Mutex::new(HashMap::new()));
    let mut map = models.lock().unwrap_or_else(|e| e.into_inner());
    let verilog = fcc_rtl::generate_window(p)?;
    let key = format!(
        "window-{:016x}",
        fnv(&format!("{verilog}{}", shim_text(SHIM)))
    );
    if let Some(m) = map.get(&key) {
        return Ok(m.clone());
    }
    let dir = cache_root().join(&key);
    if !dir.join(LIB_NAME).exists() {
        build(
            &[("fcc_window_probe.v", &verilog)],
            &dir,
            &Shim {
                name: "fcc_window_shim.cpp",
                text: SHIM,
                top: &fcc_rtl::window_module(p),
                prefix: "Vfcc_window_probe",
                sources: &["fcc_window_probe.v"],
                lib: LIB_NAME,
                coverage: false,
            },
        )?;
    }
    let model = Arc::new(open(&dir, p.window_positions())?);
    map.insert(key, model.clone());
    Ok(model)
}

fn open(dir: &Path, entries: usize) -> Result<WindowModel, SimError> {
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
        let n: NewFn = *lib.get::<NewFn>(b"fcc_window_new\0").map_err(err)?;
        let f: FreeFn = *lib.get::<FreeFn>(b"fcc_window_free\0").map_err(err)?;
        let s: StepFn = *lib.get::<StepFn>(b"fcc_window_step\0").map_err(err)?;
        (n, f, s)
    };
    Ok(WindowModel {
        new_fn,
        free_fn,
        step_fn,
        entries,
        _lib: lib,
    })
}

/// One window entry as the probe reads it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct WinEntry {
    pub ok: bool,
    pub x: u16,
    pub y: u16,
    pub z: u16,
}

/// One simulated window.
pub struct WindowDut {
    model: Arc<WindowModel>,
    handle: *mut c_void,
    entries: Vec<u64>,
}

impl WindowDut {
    pub fn new(model: Arc<WindowModel>) -> Self {
        // SAFETY: a fresh model from the same library, freed in `drop`.
        let handle = unsafe { (model.new_fn)() };
        let entries = vec![0; model.entries];
        WindowDut {
            model,
            handle,
            entries,
        }
    }

    /// One cycle with `inp`: the centre and its `K*h` entries (row-major
    /// from the top row) seen before the clock edge.
    pub fn step(&mut self, inp: &WinIn) -> (WinOut, Vec<WinEntry>) {
        let mut out = WinOut::default();
        // SAFETY: `handle` is live; `entries` holds the model's entry count.
        unsafe {
            (self.model.step_fn)(
                self.handle,
                inp,
                &mut out,
                self.entries.as_mut_ptr(),
                self.entries.len() as u32,
            )
        };
        let ents = self
            .entries
            .iter()
            .map(|&w| WinEntry {
                ok: (w >> 48) & 1 == 1,
                x: w as u16,
                y: (w >> 16) as u16,
                z: (w >> 32) as u16,
            })
            .collect();
        (out, ents)
    }
}

impl Drop for WindowDut {
    fn drop(&mut self) {
        // SAFETY: freed exactly once, with the library still loaded.
        unsafe { (self.model.free_fn)(self.handle) };
    }
}
