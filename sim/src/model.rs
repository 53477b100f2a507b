//! Building and loading a Verilator model of `fcc_top` for one parameter set.
//!
//! The model is built on demand, not by a build script, so any configuration
//! works without recompiling this crate: the RTL is generated into a cache
//! directory keyed by the parameters and the generated text, verilated, the
//! C shim (`csrc/fcc_shim.cpp`, with `csrc/vl_model.h` and the `fcc_ffi.h`
//! that [`crate::ffi`] generates) is linked against it into a shared library,
//! and the library is loaded with `libloading`. Builds go to a private
//! directory that is renamed into place, so concurrent builders never see a
//! half-built model. The cache root is `$FCC_SIM_CACHE`, else
//! `$CARGO_TARGET_DIR/fcc-sim-cache`, else `target/fcc-sim-cache` in the workspace.
//!
//! With `FCC_SIM_COVERAGE=<dir>` the models are built with Verilator's line
//! and toggle coverage (cached apart from the plain ones) and every simulated
//! instance writes its counts to `<dir>/fcc-<pid>-<n>.dat` when dropped
//! (`sim/coverage.sh` runs the regression so and summarises per block).

use std::collections::HashMap;
use std::ffi::c_void;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::{Arc, Mutex, OnceLock};

use fcc_params::FccParams;

use crate::block::{open as open_block, BlockInstance, BlockModel};
use crate::ffi::{self, c_struct};
use crate::SimError;

const SHIM: &str = include_str!("../csrc/fcc_shim.cpp");
const LIB_NAME: &str = "libfcc_sim.so";

c_struct! {
    /// Inputs of one cycle (declared to the shim by the generated `fcc_ffi.h`).
    pub struct FccIn {
        pub s_axis_tdata: u64,
        pub s_axis_tvalid: u8,
        pub s_axis_tlast: u8,
        pub m_axis_tready: u8,
        pub rst: u8,
        pub s_axil_awaddr: u32,
        pub s_axil_wdata: u32,
        pub s_axil_araddr: u32,
        pub s_axil_awvalid: u8,
        pub s_axil_wvalid: u8,
        pub s_axil_bready: u8,
        pub s_axil_arvalid: u8,
        pub s_axil_rready: u8,
    }
}

c_struct! {
    /// Outputs during one cycle, before its rising edge.
    pub struct FccOut {
        pub m_axis_tdata: u64,
        pub status_clusters: u32,
        pub status_provisional: u32,
        pub status_unlabelled: u32,
        pub status_joins: u32,
        pub status_gear_stalls: u32,
        pub s_axis_tready: u8,
        pub m_axis_tvalid: u8,
        pub m_axis_tlast: u8,
        pub m_axis_tkeep: u8,
        pub status_frame_done: u8,
        pub status_frame_error: u8,
        pub status_overflow: u8,
        pub status_idle: u8,
        pub s_axil_rdata: u32,
        pub s_axil_awready: u8,
        pub s_axil_wready: u8,
        pub s_axil_bvalid: u8,
        pub s_axil_bresp: u8,
        pub s_axil_arready: u8,
        pub s_axil_rvalid: u8,
        pub s_axil_rresp: u8,
        pub irq: u8,
    }
}

type StepFn = unsafe extern "C" fn(*mut c_void, *const FccIn, *mut FccOut);

/// A loaded Verilator model (shared library) for one parameter set: the
/// whole core, loaded as every block bench's model is (its shim's
/// functions are `fcc_new`, `fcc_free` and `fcc_step`).
pub struct Model {
    pub params: FccParams,
    /// Directory holding the generated RTL and the library.
    pub dir: PathBuf,
    block: Arc<BlockModel<StepFn>>,
}

impl std::fmt::Debug for Model {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Model").field("dir", &self.dir).finish()
    }
}

/// One simulated instance of the core.
pub struct Dut {
    model: Arc<Model>,
    instance: BlockInstance<StepFn>,
    /// Rising edges simulated so far.
    pub cycle: u64,
    /// FRAME_COUNT as last read by the bench (0 after a reset).
    pub frames_seen: u32,
}

impl Dut {
    pub fn new(model: Arc<Model>) -> Self {
        let instance = BlockInstance::new(model.block.clone());
        Dut {
            model,
            instance,
            cycle: 0,
            frames_seen: 0,
        }
    }

    pub fn params(&self) -> &FccParams {
        &self.model.params
    }

    /// Advance one clock cycle with `inp`; returns the outputs seen before the edge.
    pub fn step(&mut self, inp: &FccIn) -> FccOut {
        let mut out = FccOut::default();
        let (step, handle) = self.instance.step_fn();
        // SAFETY: `handle` came from `fcc_new` of the same library and is
        // freed only when `instance` drops; both pointers refer to live
        // `repr(C)` values.
        unsafe { step(handle, inp, &mut out) };
        self.cycle += 1;
        out
    }
}

/// The directory for coverage counts (`FCC_SIM_COVERAGE`), created if needed.
pub fn coverage_dir() -> Option<PathBuf> {
    let dir = PathBuf::from(std::env::var_os("FCC_SIM_COVERAGE")?);
    let _ = std::fs::create_dir_all(&dir);
    Some(dir)
}

/// Where built models are kept.
pub fn cache_root() -> PathBuf {
    if let Some(dir) = std::env::var_os("FCC_SIM_CACHE") {
        return PathBuf::from(dir);
    }
    if let Some(dir) = std::env::var_os("CARGO_TARGET_DIR") {
        return PathBuf::from(dir).join("fcc-sim-cache");
    }
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("..")
        .join("target")
        .join("fcc-sim-cache")
}

pub(crate) fn fnv(text: &str) -> u64 {
    fcc_params::fnv1a64(text.as_bytes())
}

/// The text of the shim `shim` and of the files it includes, for cache keys.
pub(crate) fn shim_text(shim: &str) -> String {
    let mut s = shim.to_string();
    for (_, text) in ffi::support_files() {
        s.push_str(&text);
    }
    s
}

/// The cache directory's name: the parameters, the Verilog and the shim, and
/// whether the model counts coverage.
fn cache_key(p: &FccParams, verilog: &str) -> String {
    format!(
        "{}-{:016x}{}",
        p.hash(),
        fnv(&format!("{verilog}{}", shim_text(SHIM))),
        if coverage_dir().is_some() { "-cov" } else { "" }
    )
}

/// Whether the model for `p` is built and cached ([`load`] is then quick;
/// otherwise it runs Verilator and the C++ compiler, minutes).
pub fn is_cached(p: &FccParams) -> Result<bool, SimError> {
    let gen = fcc_rtl::generate(p)?;
    Ok(cache_root()
        .join(cache_key(p, &gen.verilog))
        .join(LIB_NAME)
        .exists())
}

/// The Verilog and lint waivers of a configuration that `fcc gen --out dir`
/// wrote, with its build parameters.
pub struct GeneratedDir {
    pub params: FccParams,
    pub verilog: String,
    pub waivers: String,
}

/// Read the configuration generated into `dir` (`fcc_params.json`,
/// `fcc_top.v`, `fcc_lint.vlt`; found by `fcc_rtl::generated_rtl_dir`).
pub fn read_generated(dir: &Path) -> Result<GeneratedDir, SimError> {
    let rtl = fcc_rtl::generated_rtl_dir(dir)?;
    let params = fcc_rtl::read_generated_params(dir)?;
    let read = |name: &str| {
        let path = rtl.join(name);
        std::fs::read_to_string(&path).map_err(io(&path))
    };
    let verilog = read("fcc_top.v")?;
    fcc_rtl::check_top_module(&params, &verilog, &rtl.join("fcc_top.v"))?;
    Ok(GeneratedDir {
        params,
        verilog,
        waivers: read("fcc_lint.vlt")?,
    })
}

/// Whether the model of the configuration generated into `dir` is cached.
pub fn is_cached_dir(dir: &Path) -> Result<bool, SimError> {
    let g = read_generated(dir)?;
    Ok(cache_root()
        .join(cache_key(&g.params, &g.verilog))
        .join(LIB_NAME)
        .exists())
}

/// Load the model for `p`, building it first if the cache lacks it. Models
/// are shared within the process.
pub fn load(p: &FccParams) -> Result<Arc<Model>, SimError> {
    let gen = fcc_rtl::generate(p)?;
    load_verilog(p, &gen.verilog, &gen.lint_waivers)
}

/// Load the model of the configuration generated into `dir` by `fcc gen`:
/// its own Verilog, as written there (nothing is regenerated).
pub fn load_dir(dir: &Path) -> Result<Arc<Model>, SimError> {
    let g = read_generated(dir)?;
    load_verilog(&g.params, &g.verilog, &g.waivers)
}

fn load_verilog(p: &FccParams, verilog: &str, waivers: &str) -> Result<Arc<Model>, SimError> {
    static MODELS: OnceLock<Mutex<HashMap<String, Arc<Model>>>> = OnceLock::new();
    let models = MODELS.get_or_init(|| Mutex::new(HashMap::new()));
    // One build at a time in this process: builds are heavy.
    let mut map = models.lock().unwrap_or_else(|e| e.into_inner());
    let key = cache_key(p, verilog);
    if let Some(m) = map.get(&key) {
        return Ok(m.clone());
    }
    let dir = cache_root().join(&key);
    if !dir.join(LIB_NAME).exists() {
        let top = fcc_rtl::top_module(p);
        let files: Vec<(&str, &str)> = vec![("fcc_top.v", verilog), ("fcc_lint.vlt", waivers)];
        build(
            &files,
            &dir,
            &Shim {
                name: "fcc_shim.cpp",
                text: SHIM,
                top: &top,
                prefix: "Vfcc_top",
                sources: &["fcc_lint.vlt", "fcc_top.v"],
                lib: LIB_NAME,
                coverage: coverage_dir().is_some(),
            },
        )?;
    }
    let model = Arc::new(open(p, &dir)?);
    map.insert(key, model.clone());
    Ok(model)
}

fn open(p: &FccParams, dir: &Path) -> Result<Model, SimError> {
    Ok(Model {
        params: p.clone(),
        dir: dir.to_path_buf(),
        block: Arc::new(open_block(&dir.join(LIB_NAME), "fcc")?),
    })
}

fn run(cmd: &mut Command, what: &str) -> Result<(), SimError> {
    let out = cmd.output().map_err(|e| SimError::Tool {
        tool: what.to_string(),
        message: e.to_string(),
    })?;
    if out.status.success() {
        Ok(())
    } else {
        Err(SimError::Build {
            step: what.to_string(),
            log: format!(
                "{}{}",
                String::from_utf8_lossy(&out.stdout),
                String::from_utf8_lossy(&out.stderr)
            ),
        })
    }
}

fn io(path: &Path) -> impl FnOnce(std::io::Error) -> SimError + '_ {
    move |source| SimError::Io {
        path: path.to_path_buf(),
        source,
    }
}

/// Verilator's run-time library (`verilated.cpp`, `verilated_threads.cpp`)
/// compiled once under the cache `root`, for the compiler `cxx` and the
/// sources in `inc` (their text is in the directory's name), and shared by
/// every model linked after: it is the same for every model without
/// coverage. Written to a private name and renamed, so that builds running
/// at once never link a half-written object.
fn runtime_objects(root: &Path, cxx: &str, inc: &Path) -> Result<Vec<PathBuf>, SimError> {
    let sources = ["verilated.cpp", "verilated_threads.cpp"];
    let mut key = format!("{cxx}\0{}\0", inc.display());
    for src in sources {
        let path = inc.join(src);
        key.push_str(&std::fs::read_to_string(&path).map_err(io(&path))?);
    }
    let dir = root.join(format!("verilated-{:016x}", fnv(&key)));
    std::fs::create_dir_all(&dir).map_err(io(&dir))?;
    let mut objects = vec![];
    for src in sources {
        let obj = dir.join(src.replace(".cpp", ".o"));
        if !obj.exists() {
            let tmp = dir.join(format!("{src}.tmp-{}.o", std::process::id()));
            run(
                Command::new(cxx)
                    .args(["-c", "-fPIC", "-O1", "-std=c++17"])
                    .arg(format!("-I{}", inc.display()))
                    .arg(format!("-I{}", inc.join("vltstd").display()))
                    .arg(inc.join(src))
                    .arg("-o")
                    .arg(&tmp),
                "c++ (Verilator's run-time library)",
            )?;
            std::fs::rename(&tmp, &obj).map_err(io(&obj))?;
        }
        objects.push(obj);
    }
    Ok(objects)
}

/// What to verilate and link: the C shim, the top module, the files handed
/// to Verilator and the library's name.
pub(crate) struct Shim<'a> {
    pub name: &'a str,
    pub text: &'a str,
    /// The top module: its name carries the configuration's suffix.
    pub top: &'a str,
    /// Verilator's `--prefix`: the C++ class the shim includes and uses,
    /// the same for every configuration.
    pub prefix: &'a str,
    pub sources: &'a [&'a str],
    pub lib: &'a str,
    /// Verilator line and toggle coverage (`FCC_SIM_COVERAGE`).
    pub coverage: bool,
}

/// Write `files` and the shim into a private directory, verilate and link
/// them, and rename the directory to `dir`.
pub(crate) fn build(files: &[(&str, &str)], dir: &Path, shim: &Shim) -> Result<(), SimError> {
    let root = dir.parent().unwrap_or(dir);
    std::fs::create_dir_all(root).map_err(io(root))?;
    let tmp = root.join(format!(
        "{}.tmp-{}",
        dir.file_name().and_then(|n| n.to_str()).unwrap_or("model"),
        std::process::id()
    ));
    let _ = std::fs::remove_dir_all(&tmp);
    std::fs::create_dir_all(&tmp).map_err(io(&tmp))?;
    for (name, text) in files {
        let path = tmp.join(name);
        std::fs::write(&path, text).map_err(io(&path))?;
    }
    for (name, text) in ffi::support_files() {
        let path = tmp.join(name);
        std::fs::write(&path, text).map_err(io(&path))?;
    }
    let shim_path = tmp.join(shim.name);
    std::fs::write(&shim_path, shim.text).map_err(io(&shim_path))?;
    let jobs = std::env::var("FCC_SIM_JOBS").unwrap_or_else(|_| "2".to_string());
    run(
        Command::new("verilator")
            .current_dir(&tmp)
            .args(["--cc", "--build", "-j", &jobs, "-Wno-fatal", "-O3"])
            .args(["--x-assign", "fast", "--x-initial", "fast", "--noassert"])
            .args(if shim.coverage {
                &["--coverage-line", "--coverage-toggle"][..]
            } else {
                &[][..]
            })
            // A coverage model is compiled without optimisation: with its
            // counters the generated C++ takes the compiler several times as
            // long at -O1, and the small coverage runs do not need the speed.
            .args([
                "-CFLAGS",
                if shim.coverage {
                    "-fPIC -O0"
                } else {
                    "-fPIC -O1"
                },
                "--top-module",
                shim.top,
            ])
            .args(["--prefix", shim.prefix])
            .args(["-Mdir", "obj"])
            // Coverage points name their file: an absolute path lets the
            // summary find the source (after the rename, without `.tmp-<pid>`).
            .args(shim.sources.iter().map(|s| {
                if shim.coverage && s.ends_with(".v") {
                    tmp.join(s)
                } else {
                    PathBuf::from(s)
                }
            })),
        "verilator",
    )?;
    let vroot = Command::new("verilator")
        .arg("--getenv")
        .arg("VERILATOR_ROOT")
        .output()
        .map_err(|e| SimError::Tool {
            tool: "verilator".into(),
            message: e.to_string(),
        })?;
    let vroot = PathBuf::from(String::from_utf8_lossy(&vroot.stdout).trim());
    let inc = vroot.join("include");
    let cxx = std::env::var("CXX").unwrap_or_else(|_| "c++".to_string());
    let mut link = Command::new(&cxx);
    if shim.coverage {
        // Verilator's run-time library, compiled here with coverage.
        link.arg("-DVM_COVERAGE=1")
            .arg(inc.join("verilated_cov.cpp"))
            .arg(inc.join("verilated.cpp"))
            .arg(inc.join("verilated_threads.cpp"));
    } else {
        // Verilator's run-time library, compiled once for every model.
        link.args(runtime_objects(root, &cxx, &inc)?);
    }
    run(
        link.current_dir(&tmp)
            .args(["-shared", "-fPIC", "-O1", "-std=c++17", "-Iobj"])
            .arg(format!("-I{}", inc.display()))
            .arg(format!("-I{}", inc.join("vltstd").display()))
            .arg(shim.name)
            .arg(format!("obj/{}__ALL.a", shim.prefix))
            .args(["-pthread", "-latomic", "-o", shim.lib]),
        "c++ (link the Verilator model)",
    )?;
    // Keep only what is needed to load and inspect the model.
    let _ = std::fs::remove_dir_all(tmp.join("obj"));
    match std::fs::rename(&tmp, dir) {
        Ok(()) => Ok(()),
        // Another process finished the same model first: use theirs.
        Err(_) if dir.join(shim.lib).exists() => {
            let _ = std::fs::remove_dir_all(&tmp);
            Ok(())
        }
        Err(e) => Err(SimError::Io {
            path: dir.to_path_buf(),
            source: e,
        }),
    }
}
