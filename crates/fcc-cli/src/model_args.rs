//! The clustering parameters shared by subcommands, defaulting to `FccParams::default()`.

use clap::Args;
use fcc_golden::MergeMode;
use fcc_params::FccParams;

fn defaults() -> FccParams {
    FccParams::default()
}

/// K, thresholds and label width; rows and columns come from the data.
#[derive(Args, Debug, Clone)]
pub struct ModelArgs {
    /// Connection-filter size K (odd, 3..=15).
    #[arg(long, default_value_t = defaults().fsize)]
    pub fsize: usize,
    /// Intra-channel threshold th_H, metres.
    #[arg(long, default_value_t = defaults().th_h)]
    pub th_h: f64,
    /// Inter-channel threshold th_V, metres.
    #[arg(long, default_value_t = defaults().th_v)]
    pub th_v: f64,
    /// Provisional label width B (8..=20).
    #[arg(long, default_value_t = defaults().label_bits)]
    pub label_bits: u32,
    /// Merge: `exact` connected components, or the published `paper` table.
    #[arg(long, default_value = "exact")]
    pub merge: MergeMode,
}

impl ModelArgs {
    /// Validated parameters for a `rows` x `cols` image.
    pub fn params(&self, rows: usize, cols: usize) -> anyhow::Result<FccParams> {
        let p = FccParams {
            rows,
            cols,
            fsize: self.fsize,
            th_h: self.th_h,
            th_v: self.th_v,
            label_bits: self.label_bits,
            ..defaults()
        };
        p.validate()?;
        Ok(p)
    }
}
