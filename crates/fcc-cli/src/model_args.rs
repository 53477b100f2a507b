//! The clustering parameters shared by subcommands, defaulting to `FccParams::default()`.

use anyhow::Context;
use clap::Args;
use fcc_golden::MergeMode;
use fcc_params::{FccParams, Preset, Scan};

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
    #[arg(long, value_name = "B", help = with_default("Provisional label width B (8..=20)", defaults().label_bits))]
    pub label_bits: Option<u32>,
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
    /// A preset or a non-zero slope is on the command line.
    pub fn given(&self) -> bool {
        self.preset.is_some() || self.th_h_slope != 0.0 || self.th_v_slope != 0.0
    }

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
    /// The stream's open limit: a run starts unlabelled while N clusters
    /// count as open (spec §9.1; the stream only; default: unlimited).
    #[arg(long, value_name = "N")]
    pub open_limit: Option<u32>,
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
            label_bits: self.label_bits.unwrap_or(defaults().label_bits),
            bridge: self.limits.bridge,
            ring_reach: self.limits.ring_reach,
            open_limit: self.limits.open_limit,
            ..defaults()
        });
        p.validate()?;
        Ok(p)
    }
}

/// `text` and its default, for the help of an option whose absence is
/// resolved later (the default is the configuration's, said once).
fn with_default(text: &str, v: impl std::fmt::Display) -> String {
    format!("{text} [default: {v}]")
}

/// Every parameter of a hardware configuration (`gen`, `sim`, `synth`), as
/// given: `None` is an option not on the command line. [`HwArgs::over`]
/// resolves them once against a base configuration (the defaults, or a
/// build's parameters for `sim --rtl`), so no command asks clap which
/// options were given.
#[derive(Args, Debug, Clone, Default)]
pub struct HwArgs {
    #[arg(long, value_name = "K", help = with_default("Connection-filter size K (odd, 3..=11 in hardware)", defaults().fsize))]
    pub fsize: Option<usize>,
    #[arg(long, value_name = "R", help = with_default("Laser channels (image rows), 16..=128", defaults().rows))]
    pub rows: Option<usize>,
    #[arg(long, value_name = "C", help = with_default("Azimuth columns, 256..=4096", defaults().cols))]
    pub cols: Option<usize>,
    #[arg(long, value_name = "M", allow_negative_numbers = true, help = with_default("Intra-channel threshold th_H, metres", defaults().th_h))]
    pub th_h: Option<f64>,
    #[arg(long, value_name = "M", allow_negative_numbers = true, help = with_default("Inter-channel threshold th_V, metres", defaults().th_v))]
    pub th_v: Option<f64>,
    #[arg(long, value_name = "B", help = with_default("Provisional label width B (8..=16 in hardware)", format!("{}; {} with --scan column", Scan::Row.default_label_bits(), Scan::Column.default_label_bits())))]
    pub label_bits: Option<u32>,
    #[arg(long, value_name = "MHZ", allow_negative_numbers = true, help = with_default("Clock the constraints ask for, MHz", defaults().clock_mhz))]
    pub clock_mhz: Option<f64>,
    #[arg(long, value_name = "N", help = with_default("Labels per output beat: 1, 2 or 4", defaults().labels_per_beat))]
    pub labels_per_beat: Option<u32>,
    /// Refused by the row-major core (it keeps the unlimited contract).
    #[command(flatten)]
    pub limits: LimitArgs,
    /// The build's slopes (power-on values of RUN_SLOPE_H and RUN_SLOPE_V).
    #[command(flatten)]
    pub slopes: SlopeArgs,
    /// The core: `row` (raster order in, the frame's labels out) or
    /// `column` (column order in, one record per cluster as it closes;
    /// docs/column-core.md) [default: row]
    #[arg(long, value_name = "ORDER")]
    pub scan: Option<fcc_params::Scan>,
}

impl HwArgs {
    /// `base` with every option given on the command line in its place.
    pub fn over(&self, base: &FccParams) -> FccParams {
        let b = base.clone();
        let p = FccParams {
            rows: self.rows.unwrap_or(b.rows),
            cols: self.cols.unwrap_or(b.cols),
            fsize: self.fsize.unwrap_or(b.fsize),
            th_h: self.th_h.unwrap_or(b.th_h),
            th_v: self.th_v.unwrap_or(b.th_v),
            label_bits: self.label_bits.unwrap_or(b.label_bits),
            clock_mhz: self.clock_mhz.unwrap_or(b.clock_mhz),
            labels_per_beat: self.labels_per_beat.unwrap_or(b.labels_per_beat),
            bridge: self.limits.bridge.or(b.bridge),
            ring_reach: self.limits.ring_reach.or(b.ring_reach),
            open_limit: self.limits.open_limit.or(b.open_limit),
            scan: self.scan.unwrap_or(b.scan),
            ..b
        };
        if self.slopes.given() {
            self.slopes.apply(p)
        } else {
            p
        }
    }

    /// The defaults of the core asked for (`--scan`).
    fn scan_defaults(&self) -> FccParams {
        FccParams::defaults_for(self.scan.unwrap_or_default())
    }

    /// The parameters as given over the defaults of the core asked for,
    /// not yet validated.
    pub fn unchecked(&self) -> FccParams {
        self.over(&self.scan_defaults())
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
        // By name: a field the defaults leave out (the stream limits, the
        // slopes, the scan) is a change too. Against the defaults of the
        // core asked for, whose label width is its own; the scan is only
        // in the fields when it is not the default.
        let (d, p) = (self.scan_defaults().fields(), self.unchecked().fields());
        p.iter()
            .filter(|(name, v)| {
                *name != "fsize" && (*name == "scan" || !d.iter().any(|(n, x)| n == name && x == v))
            })
            .map(|(name, v)| format!(" --{} {v}", name.replace('_', "-")))
            .collect()
    }
}
