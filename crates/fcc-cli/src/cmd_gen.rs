//! `fcc gen`: generate the RTL of the FCC core, its constraints and Vivado script.

use std::path::PathBuf;

use anyhow::Context;
use clap::Args;
use fcc_rtl::Layout;

use crate::model_args::HwArgs;

/// Hardware parameters and output places.
#[derive(Args, Debug, Clone)]
pub struct GenArgs {
    #[command(flatten)]
    pub hw: HwArgs,
    /// Directory for the Verilog, parameter headers and lint waivers.
    #[arg(long, default_value = "rtl_out")]
    pub out: PathBuf,
    /// Directory for the XDC constraints.
    #[arg(long, default_value = "constraints")]
    pub constraints: PathBuf,
    /// Directory for the Vivado scripts.
    #[arg(long, default_value = "scripts")]
    pub scripts: PathBuf,
    /// Do not run `verilator --lint-only -Wall` on the result.
    #[arg(long)]
    pub no_lint: bool,
}

pub fn run(args: &GenArgs) -> anyhow::Result<()> {
    let p = args.hw.params()?;
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
