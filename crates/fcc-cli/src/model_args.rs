//! The clustering parameters shared by subcommands, defaulting to `FccParams::default()`.

use anyhow::Context;
use clap::Args;
use fcc_golden::MergeMode;
use fcc_params::{FccParams, Preset};

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
    #[arg(long, allow_negative_numbers = true, default_value_t = defaults().th_h)]
    pub th_h: f64,
    /// Inter-channel threshold th_V, metres.
    #[arg(long, allow_negative_numbers = true, default_value_t = defaults().th_v)]
    pub th_v: f64,
    /// Provisional label width B (8..=20).
    #[arg(long, default_value_t = defaults().label_bits)]
    pub label_bits: u32,
    /// Merge: `exact` connected components, or the published `paper` table.
    #[arg(long, default_value = "exact")]
    pub merge: MergeMode,
    #[command(flatten)]
    pub slopes: SlopeArgs,
    #[command(flatten)]
    pub limits: LimitArgs,
}

/// Range-adaptive thresholds (spec §2) and the named presets.
#[derive(Args, Debug, Clone, Default)]
pub struct SlopeArgs {
    /// Slope of th_H with range, metres per metre (0 <= a < 1; 0: fixed).
    #[arg(long, allow_negative_numbers = true, default_value_t = defaults().th_h_slope)]
    pub th_h_slope: f64,
    /// Slope of th_V with range, metres per metre (0 <= a < 1; 0: fixed).
    #[arg(long, allow_negative_numbers = true, default_value_t = defaults().th_v_slope)]
    pub th_v_slope: f64,
    /// Thresholds and slopes by name: `paper` (0.5 m / 1.0 m, fixed, the
    /// default) or `adaptive` (range-adaptive, tuned on the synthetic scenes).
    #[arg(long, conflicts_with_all = ["th_h", "th_v", "th_h_slope", "th_v_slope"])]
    pub preset: Option<Preset>,
}

impl SlopeArgs {
    /// `p` with the preset's thresholds and slopes, or the slopes given.
    pub fn apply(&self, p: FccParams) -> FccParams {
        match self.preset {
            Some(preset) => {
                let (th_h, th_v, th_h_slope, th_v_slope) = preset.thresholds();
                FccParams {
                    th_h,
                    th_v,
                    th_h_slope,
                    th_v_slope,
                    ..p
                }
            }
            None => FccParams {
                th_h_slope: self.th_h_slope,
                th_v_slope: self.th_v_slope,
                ..p
            },
        }
    }
}

/// The reach limits of pass 1 (spec §3), unlimited unless given.
#[derive(Args, Debug, Clone, Default)]
pub struct LimitArgs {
    /// Pass 1 bridge limit: consecutive valid pixels of a row with more than
    /// N empty pixels between them start a new run (default: unlimited).
    #[arg(long, value_name = "N")]
    pub bridge: Option<u32>,
    /// Ring reach: the ring check applies only when the row's first valid
    /// pixel is in columns 0..N-1 and its last in C-N..C-1 (default: unlimited).
    #[arg(long, value_name = "N")]
    pub ring_reach: Option<u32>,
}

impl ModelArgs {
    /// Validated parameters for a `rows` x `cols` image.
    pub fn params(&self, rows: usize, cols: usize) -> anyhow::Result<FccParams> {
        let p = self.slopes.apply(FccParams {
            rows,
            cols,
            fsize: self.fsize,
            th_h: self.th_h,
            th_v: self.th_v,
            label_bits: self.label_bits,
            bridge: self.limits.bridge,
            ring_reach: self.limits.ring_reach,
            ..defaults()
        });
        p.validate()?;
        Ok(p)
    }
}

/// Every parameter of a hardware configuration (`gen`, `sim`, `synth`).
#[derive(Args, Debug, Clone)]
pub struct HwArgs {
    /// Connection-filter size K (odd, 3..=11 in hardware).
    #[arg(long, default_value_t = defaults().fsize)]
    pub fsize: usize,
    /// Laser channels (image rows), 16..=128.
    #[arg(long, default_value_t = defaults().rows)]
    pub rows: usize,
    /// Azimuth columns, 256..=4096.
    #[arg(long, default_value_t = defaults().cols)]
    pub cols: usize,
    /// Intra-channel threshold th_H, metres.
    #[arg(long, allow_negative_numbers = true, default_value_t = defaults().th_h)]
    pub th_h: f64,
    /// Inter-channel threshold th_V, metres.
    #[arg(long, allow_negative_numbers = true, default_value_t = defaults().th_v)]
    pub th_v: f64,
    /// Provisional label width B (8..=16 in hardware).
    #[arg(long, default_value_t = defaults().label_bits)]
    pub label_bits: u32,
    /// Clock the constraints ask for, MHz.
    #[arg(long, allow_negative_numbers = true, default_value_t = defaults().clock_mhz)]
    pub clock_mhz: f64,
    /// Labels per output beat: 1, 2 or 4.
    #[arg(long, default_value_t = defaults().labels_per_beat)]
    pub labels_per_beat: u32,
    /// Refused by the row-major core (it keeps the unlimited contract).
    #[command(flatten)]
    pub limits: LimitArgs,
    /// Refused by the RTL while it has fixed thresholds.
    #[command(flatten)]
    pub slopes: SlopeArgs,
}

impl Default for HwArgs {
    /// The flags' defaults: the default configuration.
    fn default() -> HwArgs {
        let d = defaults();
        HwArgs {
            fsize: d.fsize,
            rows: d.rows,
            cols: d.cols,
            th_h: d.th_h,
            th_v: d.th_v,
            label_bits: d.label_bits,
            clock_mhz: d.clock_mhz,
            labels_per_beat: d.labels_per_beat,
            limits: LimitArgs::default(),
            slopes: SlopeArgs::default(),
        }
    }
}

impl HwArgs {
    /// The parameters as given, not yet validated.
    pub fn unchecked(&self) -> FccParams {
        self.slopes.apply(FccParams {
            rows: self.rows,
            cols: self.cols,
            fsize: self.fsize,
            th_h: self.th_h,
            th_v: self.th_v,
            label_bits: self.label_bits,
            clock_mhz: self.clock_mhz,
            labels_per_beat: self.labels_per_beat,
            bridge: self.limits.bridge,
            ring_reach: self.limits.ring_reach,
            ..defaults()
        })
    }

    /// The parameters, validated for the RTL generator.
    pub fn params(&self) -> anyhow::Result<FccParams> {
        let p = self.unchecked();
        p.validate_for_hardware()
            .context("these parameters cannot be generated in hardware")?;
        Ok(p)
    }

    /// The flags that differ from the defaults, as ` --name value` pairs
    /// (K excluded), to name a command in generated reports.
    pub fn changed_flags(&self) -> String {
        let (d, p) = (defaults().fields(), self.unchecked().fields());
        p.iter()
            .zip(&d)
            .filter(|((name, v), (_, d))| *name != "fsize" && v != d)
            .map(|((name, v), _)| format!(" --{} {v}", name.replace('_', "-")))
            .collect()
    }
}
