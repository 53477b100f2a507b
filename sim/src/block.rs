//! One block alone under Verilator, for its own bench: the cache, build and
//! load shared by the block benches (the hand-written shims of `regs_bench`,
//! `axil_adapter_bench`, `window_bench`, `sort_net_bench`, and the generated
//! ones of `plain`).
//!
//! A block's shim exports three C functions, `<symbol>_new`, `<symbol>_free`
//! and `<symbol>_step`; `S` is the type of the step function, which differs
//! per block (its in/out structs).

use std::collections::HashMap;
use std::ffi::c_void;
use std::path::Path;
use std::sync::{Arc, Mutex, OnceLock};

use crate::model::{build, cache_root, fnv, shim_text, Shim};
use crate::SimError;

type NewFn = unsafe extern "C" fn() -> *mut c_void;
type FreeFn = unsafe extern "C" fn(*mut c_void);

/// A loaded Verilator model of one block.
pub struct BlockModel<S> {
    new_fn: NewFn,
    free_fn: FreeFn,
    step_fn: S,
    _lib: libloading::Library,
}

/// The models of one block already loaded in this process, by cache key.
pub(crate) type BlockCache<S> = OnceLock<Mutex<HashMap<String, Arc<BlockModel<S>>>>>;

/// How to build one block's model.
pub(crate) struct BlockBuild<'a> {
    /// Start of the cache directory's name (`regs`, `merge`, ...).
    pub key: &'a str,
    /// The files written beside the shim (Verilog, waivers).
    pub files: &'a [(&'a str, &'a str)],
    pub shim: Shim<'a>,
    /// Prefix of the shim's three C functions.
    pub symbol: &'a str,
}

/// A block bench's C++ shim: its file name, its text and the prefix of its
/// three C functions.
pub(crate) struct BenchShim<'a> {
    pub file: &'a str,
    pub text: &'a str,
    pub symbol: &'a str,
}

/// Load the model of the bench block `block` (its Verilog and waivers from
/// `fcc_rtl`'s table) for the build `p` behind `shim`, with `extra` files
/// the shim includes; built once and cached on disk.
pub(crate) fn load_bench<S: Copy>(
    cache: &'static BlockCache<S>,
    block: fcc_rtl::BenchBlock,
    p: &fcc_params::FccParams,
    shim: &BenchShim<'_>,
    extra: &[(&str, &str)],
) -> Result<Arc<BlockModel<S>>, SimError> {
    let name = block.name();
    let (v, vlt) = (format!("{name}.v"), format!("{name}.vlt"));
    let (verilog, waivers) = (block.generate(p)?, block.waivers(p));
    let mut files = vec![
        (v.as_str(), verilog.as_str()),
        (vlt.as_str(), waivers.as_str()),
    ];
    files.extend_from_slice(extra);
    let lib = format!("lib{}_sim.so", shim.symbol);
    load_block(
        cache,
        &BlockBuild {
            key: name,
            files: &files,
            shim: Shim {
                name: shim.file,
                text: shim.text,
                top: &block.module(p),
                prefix: &format!("V{name}"),
                sources: &[vlt.as_str(), v.as_str()],
                lib: &lib,
                coverage: false,
            },
            symbol: shim.symbol,
        },
    )
}

/// Load the model `b` describes, building it (once, cached on disk) if
/// needed.
pub(crate) fn load_block<S: Copy>(
    cache: &'static BlockCache<S>,
    b: &BlockBuild,
) -> Result<Arc<BlockModel<S>>, SimError> {
    let models = cache.get_or_init(|| Mutex::new(HashMap::new()));
    let mut map = models.lock().unwrap_or_else(|e| e.into_inner());
    let files: String = b.files.iter().map(|(_, text)| *text).collect();
    let key = format!(
        "{}-{:016x}",
        b.key,
        fnv(&format!("{files}{}", shim_text(b.shim.text)))
    );
    if let Some(m) = map.get(&key) {
        return Ok(m.clone());
    }
    let dir = cache_root().join(&key);
    if !dir.join(b.shim.lib).exists() {
        build(b.files, &dir, &b.shim)?;
    }
    let model = Arc::new(open(&dir.join(b.shim.lib), b.symbol)?);
    map.insert(key, model.clone());
    Ok(model)
}

pub(crate) fn open<S: Copy>(path: &Path, symbol: &str) -> Result<BlockModel<S>, SimError> {
    let err = |source| SimError::Load {
        path: path.to_path_buf(),
        source,
    };
    let name = |f: &str| format!("{symbol}_{f}\0").into_bytes();
    // SAFETY: the library is built from our own shim; loading it runs no
    // initialisers beyond the C++ runtime's.
    let lib = unsafe { libloading::Library::new(path) }.map_err(err)?;
    // SAFETY: the symbol types match the `extern "C"` declarations in the
    // shim (`S` is the block's step signature, chosen with its shim).
    let (new_fn, free_fn, step_fn) = unsafe {
        let n: NewFn = *lib.get::<NewFn>(&name("new")).map_err(err)?;
        let f: FreeFn = *lib.get::<FreeFn>(&name("free")).map_err(err)?;
        let s: S = *lib.get::<S>(&name("step")).map_err(err)?;
        (n, f, s)
    };
    Ok(BlockModel {
        new_fn,
        free_fn,
        step_fn,
        _lib: lib,
    })
}

/// One simulated instance of a block, freed on drop.
pub(crate) struct BlockInstance<S> {
    model: Arc<BlockModel<S>>,
    handle: *mut c_void,
}

impl<S: Copy> BlockInstance<S> {
    pub fn new(model: Arc<BlockModel<S>>) -> Self {
        // SAFETY: a fresh model from the same library, freed in `drop`.
        let handle = unsafe { (model.new_fn)() };
        BlockInstance { model, handle }
    }

    /// The step function and the live handle to pass it.
    pub fn step_fn(&self) -> (S, *mut c_void) {
        (self.model.step_fn, self.handle)
    }
}

impl<S> Drop for BlockInstance<S> {
    fn drop(&mut self) {
        // SAFETY: freed exactly once, with the library still loaded.
        unsafe { (self.model.free_fn)(self.handle) };
    }
}
