//! `fcc gen`: generate the RTL of the FCC core, its constraints and Vivado script.

use std::path::PathBuf;

use anyhow::Context;
use clap::Args;
use fcc_params::FccParams;
use fcc_rtl::Layout;

fn defaults() -> FccParams {
    FccParams::default()
}

/// Hardware parameters and output places.
#[derive(Args, Debug, Clone)]
pub struct GenArgs {
    /// Connection-filter size K (odd, 3..=11).
    #[arg(long, default_value_t = defaults().fsize)]
    pub fsize: usize,
    /// Laser channels (image rows), 16..=128.
    #[arg(long, default_value_t = defaults().rows)]
    pub rows: usize,
    /// Azimuth columns, 256..=4096.
    #[arg(long, default_value_t = defaults().cols)]
    pub cols: usize,
    /// Intra-channel threshold th_H, metres.
    #[arg(long, default_value_t = defaults().th_h)]
    pub th_h: f64,
    /// Inter-channel threshold th_V, metres.
    #[arg(long, default_value_t = defaults().th_v)]
    pub th_v: f64,
    /// Provisional label width B (8..=16).
    #[arg(long, default_value_t = defaults().label_bits)]
    pub label_bits: u32,
    /// Clock the constraints ask for, MHz.
    #[arg(long, default_value_t = defaults().clock_mhz)]
    pub clock_mhz: f64,
    /// Labels per output beat: 1, 2 or 4.
    #[arg(long, default_value_t = defaults().labels_per_beat)]
    pub labels_per_beat: u32,
    /// Directory for the Verilog, parameter headers and lint waivers.
    #[arg(long, default_value = "rtl_out")]
    pub out: PathBuf,
    /// Directory for the XDC constraints.
    #[arg(long, default_value = "constraints")]
    pub constraints: PathBuf,
    /// Directory for the Vivado build script.
    #[arg(long, default_value = "scripts")]
    pub scripts: PathBuf,
    /// Do not run `verilator --lint-only -Wall` on the result.
    #[arg(long)]
    pub no_lint: bool,
}

impl GenArgs {
    /// The validated hardware parameters.
    pub fn params(&self) -> anyhow::Result<FccParams> {
        let p = FccParams {
            rows: self.rows,
            cols: self.cols,
            fsize: self.fsize,
            th_h: self.th_h,
            th_v: self.th_v,
            label_bits: self.label_bits,
            clock_mhz: self.clock_mhz,
            labels_per_beat: self.labels_per_beat,
        };
        p.validate_for_hardware()
            .context("these parameters cannot be generated in hardware")?;
        Ok(p)
    }
}

pub fn run(args: &GenArgs) -> anyhow::Result<()> {
    let p = args.params()?;
    let layout = Layout {
        rtl: args.out.clone(),
        constraints: args.constraints.clone(),
        scripts: args.scripts.clone(),
    };
    let files = fcc_rtl::write_all(&p, &layout).context("generating the RTL")?;
    for f in &files {
        println!("wrote {}", f.display());
    }
    if args.no_lint {
        println!("lint skipped (--no-lint)");
    } else {
        fcc_rtl::lint::lint_files(&args.out.join("fcc_top.v"), &args.out.join("fcc_lint.vlt"))
            .context("linting the generated Verilog (use --no-lint to skip)")?;
        println!("verilator --lint-only -Wall: clean");
    }
    println!(
        "fcc_top: {} (hash {})",
        fcc_rtl::param_summary(&p),
        p.hash()
    );
    Ok(())
}
