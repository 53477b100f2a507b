//! The one parameter set of Fast Channel Clustering.
//!
//! [`FccParams`] is built once (by the CLI, a test or a bench), validated, and
//! then read by everything else: the golden model, the RTL generator, the
//! Verilator benches and the Vivado scripts. Derived quantities (integer
//! thresholds, window half-size, label range) are methods, computed in one
//! place, so no other crate retypes a formula.

use serde::{Deserialize, Serialize};
use thiserror::Error;

/// Fractional bits of the Q7.8 coordinate format, and one metre in Q7.8
/// units (defined with the quantisation rule in `fcc-pixel`).
pub use fcc_pixel::{FRAC_BITS, Q_ONE};

/// Allowed ranges, named once so errors, docs and the CLI agree.
pub mod limits {
    use std::ops::RangeInclusive;
    /// Connection-filter size K (odd).
    pub const FSIZE: RangeInclusive<usize> = 3..=15;
    /// Provisional label width in bits.
    pub const LABEL_BITS: RangeInclusive<u32> = 8..=20;
    /// The stream's open limit `N_o`, when set (spec §9.1).
    pub const OPEN_LIMIT: RangeInclusive<u32> = 1..=u32::MAX;
    /// Thresholds in metres, exclusive on both ends.
    pub const TH_MIN_EXCL: f64 = 0.0;
    pub const TH_MAX_EXCL: f64 = 128.0;
    /// Image sizes the golden model accepts.
    pub const ROWS: RangeInclusive<usize> = 1..=4096;
    pub const COLS: RangeInclusive<usize> = 1..=65536;
    /// Image sizes the RTL generator accepts.
    pub const HW_ROWS: RangeInclusive<usize> = 16..=128;
    pub const HW_COLS: RangeInclusive<usize> = 256..=4096;
    /// Filter sizes the RTL generator accepts.
    pub const HW_FSIZE: RangeInclusive<usize> = 3..=11;
    /// Label widths the RTL generator accepts (output slots are 16 bits).
    pub const HW_LABEL_BITS: RangeInclusive<u32> = 8..=fcc_pixel::LABEL_SLOT_BITS;
    /// Columns the column-streaming core accepts at most (its column
    /// numbers are 12 bits wide, and a frame's end is marked at column C).
    pub const HW_COLUMN_COLS_MAX: usize = 4095;
    /// Rows the column-streaming core needs at least at filter size K: a
    /// row's run state is read again `R` slots after it was written, and the
    /// window spans `K + 8` rows of that pipeline.
    pub const fn hw_column_rows_min(fsize: usize) -> usize {
        if fsize + 8 > 16 {
            fsize + 8
        } else {
            16
        }
    }
    /// Labels packed into one output beat.
    pub const LABELS_PER_BEAT: [u32; 3] = [1, 2, 4];
    /// Clock requested from the XDC, MHz.
    pub const CLOCK_MHZ_MIN_EXCL: f64 = 0.0;
    pub const CLOCK_MHZ_MAX: f64 = 500.0;
}

/// A parameter that is out of range. The message names the field, the value
/// and what is allowed.
#[derive(Debug, Error, Clone, PartialEq)]
#[error("{field} = {value} is out of range: {allowed}")]
pub struct ParamError {
    pub field: &'static str,
    pub value: String,
    pub allowed: String,
}

fn range_err(field: &'static str, value: impl ToString, allowed: impl ToString) -> ParamError {
    ParamError {
        field,
        value: value.to_string(),
        allowed: allowed.to_string(),
    }
}

/// Every setting of one FCC configuration.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FccParams {
    /// Laser channels (image rows); row 0 is the top beam.
    pub rows: usize,
    /// Azimuth columns.
    pub cols: usize,
    /// Connection-filter size K (odd).
    pub fsize: usize,
    /// Intra-channel (horizontal) threshold, metres.
    pub th_h: f64,
    /// Inter-channel (vertical) threshold, metres.
    pub th_v: f64,
    /// Provisional label width B; labels are 1 ..= 2^B - 1.
    pub label_bits: u32,
    /// Clock the constraints ask for, MHz (hardware only).
    pub clock_mhz: f64,
    /// Output labels packed per AXI4-Stream beat (hardware only).
    pub labels_per_beat: u32,
    /// Pass 1 bridge limit (spec §3): two consecutive valid pixels of a row
    /// with more than this many empty pixels between them are not compared
    /// (the later one starts a new run). `None`: unlimited.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub bridge: Option<u32>,
    /// Ring-check reach (spec §3): the ring check applies only when the
    /// row's first valid pixel lies in columns `0 .. N-1` and its last in
    /// `C-N .. C-1`. `None`: unlimited.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ring_reach: Option<u32>,
    /// Range-adaptive slopes of the thresholds (spec §2), metres per metre:
    /// a pair's squared threshold grows to `slope^2 * min(r^2)` when that is
    /// larger. Quantised to UQ0.16 ([`quantize_slope`]); 0: fixed thresholds.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub th_h_slope: f64,
    #[serde(default, skip_serializing_if = "is_zero")]
    pub th_v_slope: f64,
    /// The stream's open limit `N_o` (spec §9.1): a run starting at column `c`
    /// receives a label only while fewer than `N_o` clusters count as open
    /// (those open after column `c - 1` closed, plus the runs already
    /// labelled in column `c`). `None`: unlimited. The stream only: frame
    /// mode refuses it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub open_limit: Option<u32>,
    /// The core the RTL generator builds (hardware only): the row-major
    /// core (labels of a finished frame) or the column-streaming core (one
    /// record per cluster as it closes, spec §9).
    #[serde(default, skip_serializing_if = "Scan::is_row")]
    pub scan: Scan,
}

/// The pixel order of the generated core (`--scan`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Scan {
    /// Raster order in, labels of the finished frame out (the default).
    #[default]
    Row,
    /// Column order in, one record per cluster out as it closes.
    Column,
}

impl Scan {
    fn is_row(&self) -> bool {
        *self == Scan::Row
    }

    /// The label width B a core of this scan is built with unless told.
    /// The row-major core labels a whole frame before any label comes
    /// back: a 128 x 2048 frame needs 15 bits. The column core reuses the
    /// labels of closed clusters: 13 bits hold every source of the corpus
    /// at every K (at most 6,899 labels at once; docs/column-core.md,
    /// "Width"): the column core takes 24 block RAMs (36k equivalents)
    /// at 13 bits, 65 at 15.
    pub fn default_label_bits(self) -> u32 {
        match self {
            Scan::Row => 15,
            Scan::Column => 13,
        }
    }

    /// `row` or `column`, as `--scan` takes it.
    pub fn as_str(self) -> &'static str {
        match self {
            Scan::Row => "row",
            Scan::Column => "column",
        }
    }
}

impl std::str::FromStr for Scan {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "row" => Ok(Scan::Row),
            "column" => Ok(Scan::Column),
            _ => Err(format!("unknown scan `{s}`: expected `row` or `column`")),
        }
    }
}

fn is_zero(v: &f64) -> bool {
    *v == 0.0
}

/// The recommended streaming limits (docs/streaming.md): `--bridge 16
/// --ring-reach 16` keeps every record within 17 columns of its last one
/// at almost no change of the partition.
pub const RECOMMENDED_BRIDGE: u32 = 16;
pub const RECOMMENDED_RING_REACH: u32 = 16;

/// Fractional bits of a threshold slope (UQ0.16, metres per metre).
pub const SLOPE_FRAC_BITS: u32 = 16;

/// The squared slope of spec §2, `A^2 >> 8` (UQ0.24), from a slope in
/// metres per metre.
pub fn slope_sq(a: f64) -> u64 {
    (quantize_slope(a) as u64).pow(2) >> 8
}

/// Quantise a slope in metres per metre: `floor(a * 2^16 + 0.5)`.
pub fn quantize_slope(a: f64) -> i64 {
    (a * f64::from(1u32 << SLOPE_FRAC_BITS) + 0.5).floor() as i64
}

/// Named parameter sets (`--preset`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Preset {
    /// The published thresholds, fixed: 0.5 m / 1.0 m.
    #[default]
    Paper,
    /// Range-adaptive thresholds (spec §2), tuned on the synthetic scenes.
    Adaptive,
}

impl Preset {
    /// (th_h, th_v, th_h_slope, th_v_slope) of the preset.
    pub fn thresholds(self) -> (f64, f64, f64, f64) {
        match self {
            Preset::Paper => (0.5, 1.0, 0.0, 0.0),
            Preset::Adaptive => ADAPTIVE,
        }
    }
}

/// The `adaptive` preset: (th_h, th_v, th_h_slope, th_v_slope). Tuned at
/// K = 7 on synthetic scenes 1-12 (mean PQ 0.540 with `paper`, 0.885), checked
/// on scenes 13-24 and K = 3, 11 and by eye and cluster counts on the Ouster
/// captures (docs/results.md).
pub const ADAPTIVE: (f64, f64, f64, f64) = (0.5, 1.0, 0.02, 0.05);

impl std::str::FromStr for Preset {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "paper" => Ok(Preset::Paper),
            "adaptive" => Ok(Preset::Adaptive),
            _ => Err(format!(
                "unknown preset `{s}`: expected `paper` or `adaptive`"
            )),
        }
    }
}

impl Default for FccParams {
    /// The HDL-64E-like default: K = 7 on 64 x 2048, 0.5 m / 1.0 m, 15-bit labels.
    fn default() -> Self {
        FccParams {
            rows: 64,
            cols: 2048,
            fsize: 7,
            th_h: 0.5,
            th_v: 1.0,
            label_bits: Scan::Row.default_label_bits(),
            clock_mhz: 200.0,
            labels_per_beat: 4,
            bridge: None,
            ring_reach: None,
            th_h_slope: 0.0,
            th_v_slope: 0.0,
            open_limit: None,
            scan: Scan::Row,
        }
    }
}

/// Quantise a threshold in metres: `floor(th * 256 + 0.5)`.
pub fn quantize_threshold(th: f64) -> i64 {
    (th * Q_ONE + 0.5).floor() as i64
}

impl FccParams {
    /// The defaults of the core `scan`: [`Default`] with that scan and its
    /// label width ([`Scan::default_label_bits`]).
    pub fn defaults_for(scan: Scan) -> Self {
        FccParams {
            scan,
            label_bits: scan.default_label_bits(),
            ..FccParams::default()
        }
    }

    /// Check every field against the ranges the golden model supports.
    pub fn validate(&self) -> Result<(), ParamError> {
        check_range("rows", self.rows, &limits::ROWS)?;
        check_range("cols", self.cols, &limits::COLS)?;
        check_fsize("fsize", self.fsize, &limits::FSIZE)?;
        check_threshold("th_h", self.th_h)?;
        check_threshold("th_v", self.th_v)?;
        check_slope("th_h_slope", self.th_h_slope)?;
        check_slope("th_v_slope", self.th_v_slope)?;
        check_range("label_bits", self.label_bits, &limits::LABEL_BITS)?;
        if let Some(s) = self.open_limit {
            check_range("open_limit", s, &limits::OPEN_LIMIT)?;
        }
        if !(self.clock_mhz > limits::CLOCK_MHZ_MIN_EXCL && self.clock_mhz <= limits::CLOCK_MHZ_MAX)
        {
            return Err(range_err(
                "clock_mhz",
                self.clock_mhz,
                format!("0 < clock_mhz <= {}", limits::CLOCK_MHZ_MAX),
            ));
        }
        if !limits::LABELS_PER_BEAT.contains(&self.labels_per_beat) {
            return Err(range_err(
                "labels_per_beat",
                self.labels_per_beat,
                "1, 2 or 4",
            ));
        }
        Ok(())
    }

    /// [`validate`](Self::validate), plus the tighter ranges of the RTL generator.
    pub fn validate_for_hardware(&self) -> Result<(), ParamError> {
        self.validate()?;
        self.validate_rtl_contract()?;
        check_range("rows", self.rows, &limits::HW_ROWS)?;
        check_range("cols", self.cols, &limits::HW_COLS)?;
        check_fsize("fsize", self.fsize, &limits::HW_FSIZE)?;
        check_range("label_bits", self.label_bits, &limits::HW_LABEL_BITS)?;
        if self.scan == Scan::Column {
            let rows = limits::hw_column_rows_min(self.fsize)..=*limits::HW_ROWS.end();
            check_range("rows", self.rows, &rows).map_err(|e| ParamError {
                allowed: format!("{} (the column core at K = {})", e.allowed, self.fsize),
                ..e
            })?;
            let cols = *limits::HW_COLS.start()..=limits::HW_COLUMN_COLS_MAX;
            check_range("cols", self.cols, &cols).map_err(|e| ParamError {
                allowed: format!("{} (the column core)", e.allowed),
                ..e
            })?;
        }
        Ok(())
    }

    /// The part of the contract the row-major RTL follows, whatever the
    /// sizes: unlimited reach. Run
    /// parameters of a build (smaller than what can be generated) are
    /// checked with this and the build's own ranges.
    pub fn validate_rtl_contract(&self) -> Result<(), ParamError> {
        // The row-major core follows the unlimited contract, and labels a
        // whole frame (no open limit). The column core has all three as run
        // registers.
        if self.scan == Scan::Column {
            return Ok(());
        }
        for (field, v) in [
            ("bridge", self.bridge),
            ("ring_reach", self.ring_reach),
            ("open_limit", self.open_limit),
        ] {
            if let Some(v) = v {
                return Err(range_err(
                    field,
                    v,
                    "unlimited only: the row-major core has no limit (the stream, the golden model and the column core, --scan column, do)",
                ));
            }
        }
        Ok(())
    }

    /// Whether a run may start when `counted` clusters count as open
    /// (spec §9.1, the stream's open limit).
    #[inline]
    pub fn opens(&self, counted: u32) -> bool {
        self.open_limit.is_none_or(|s| counted < s)
    }

    /// Whether pass 1 compares two consecutive valid pixels of a row with
    /// `gap` empty pixels between them (spec §3, the bridge limit).
    #[inline]
    pub fn bridges(&self, gap: usize) -> bool {
        self.bridge.is_none_or(|n| gap <= n as usize)
    }

    /// Whether the ring check applies to a row whose first and last valid
    /// pixels lie in columns `first` and `last` (spec §3, the ring reach).
    #[inline]
    pub fn ring_reaches(&self, first: usize, last: usize) -> bool {
        self.ring_reach
            .is_none_or(|n| first < n as usize && last + n as usize >= self.cols)
    }

    /// Window half-size h = (K - 1) / 2: rows above the centre, columns either side.
    pub fn half(&self) -> usize {
        (self.fsize - 1) / 2
    }

    /// Window positions compared with each centre: K * (K - 1) / 2.
    pub fn window_positions(&self) -> usize {
        self.fsize * self.half()
    }

    /// Intra-channel threshold in Q7.8 units.
    pub fn th_h_q(&self) -> i64 {
        quantize_threshold(self.th_h)
    }

    /// Inter-channel threshold in Q7.8 units.
    pub fn th_v_q(&self) -> i64 {
        quantize_threshold(self.th_v)
    }

    /// Squared intra-channel threshold: a pair continues a run when d2 <= this.
    pub fn th_h_sq(&self) -> i64 {
        self.th_h_q() * self.th_h_q()
    }

    /// Squared inter-channel threshold: a pair joins when d2 < this.
    pub fn th_v_sq(&self) -> i64 {
        self.th_v_q() * self.th_v_q()
    }

    /// Quantised intra-channel slope `A` (UQ0.16, [`quantize_slope`]): the
    /// RUN_SLOPE_H register's value.
    pub fn th_h_slope_q(&self) -> i64 {
        quantize_slope(self.th_h_slope)
    }

    /// As [`th_h_slope_q`](Self::th_h_slope_q), inter-channel (RUN_SLOPE_V).
    pub fn th_v_slope_q(&self) -> i64 {
        quantize_slope(self.th_v_slope)
    }

    /// Squared quantised slope `S = A^2 >> 8` (UQ0.24, below 2^24): a
    /// point's squared threshold is `(S * rc2) >> 8` (spec §2).
    pub fn th_h_slope_sq(&self) -> u64 {
        slope_sq(self.th_h_slope)
    }

    /// As [`th_h_slope_sq`](Self::th_h_slope_sq), inter-channel.
    pub fn th_v_slope_sq(&self) -> u64 {
        slope_sq(self.th_v_slope)
    }

    /// Largest provisional label, 2^B - 1.
    pub fn max_label(&self) -> u32 {
        (1u32 << self.label_bits) - 1
    }

    /// The smallest label width B whose labels `1 ..= 2^B - 1` hold `labels`
    /// provisional labels (at least 1).
    pub fn label_bits_for(labels: u64) -> u32 {
        (64 - labels.leading_zeros()).max(1)
    }

    /// Pixels in one frame.
    pub fn pixels(&self) -> usize {
        self.rows * self.cols
    }

    /// Every field as `(name, value)`, in declaration order: the one list that
    /// summaries and command lines are made from. The limits appear only
    /// when set, as in the JSON.
    pub fn fields(&self) -> Vec<(&'static str, String)> {
        // No `..`: a new field must be added here to compile.
        let FccParams {
            rows,
            cols,
            fsize,
            th_h,
            th_v,
            label_bits,
            clock_mhz,
            labels_per_beat,
            bridge,
            ring_reach,
            th_h_slope,
            th_v_slope,
            open_limit,
            scan,
        } = self;
        let limits = [("bridge", bridge), ("ring_reach", ring_reach)];
        let slopes = [("th_h_slope", th_h_slope), ("th_v_slope", th_v_slope)];
        let mut fields = vec![
            ("rows", rows.to_string()),
            ("cols", cols.to_string()),
            ("fsize", fsize.to_string()),
            ("th_h", th_h.to_string()),
            ("th_v", th_v.to_string()),
            ("label_bits", label_bits.to_string()),
            ("clock_mhz", clock_mhz.to_string()),
            ("labels_per_beat", labels_per_beat.to_string()),
        ];
        fields.extend(
            limits
                .into_iter()
                .filter_map(|(name, v)| Some((name, v.as_ref()?.to_string()))),
        );
        fields.extend(
            slopes
                .into_iter()
                .filter(|(_, v)| **v != 0.0)
                .map(|(name, v)| (name, v.to_string())),
        );
        fields.extend(open_limit.map(|s| ("open_limit", s.to_string())));
        if !scan.is_row() {
            fields.push(("scan", scan.as_str().to_string()));
        }
        fields
    }

    /// The parameters as canonical JSON (stable field order), as written beside generated files.
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).expect("FccParams always serialises")
    }

    /// A short, stable hash of the canonical JSON (FNV-1a 64), for generated-file headers.
    pub fn hash(&self) -> String {
        format!("{:016x}", fnv1a64(self.to_json().as_bytes()))
    }

    /// A short name of the configuration, `k<K>_<first 8 hex digits of the
    /// hash>` (e.g. `k7_1b2c3d4e`): readable K for people, the hash so that
    /// any two parameter sets differ. It names the generated Verilog modules
    /// ([`module_suffix`](Self::module_suffix)) and the packaged IP.
    pub fn config_tag(&self) -> String {
        format!("k{}_{}", self.fsize, &self.hash()[..8])
    }

    /// The suffix every generated Verilog module name carries, `_` and
    /// [`config_tag`](Self::config_tag): `fcc_top_k7_1b2c3d4e`. Two
    /// configurations' modules can then be compiled together.
    pub fn module_suffix(&self) -> String {
        format!("_{}", self.config_tag())
    }
}

fn check_range<T>(
    field: &'static str,
    v: T,
    r: &std::ops::RangeInclusive<T>,
) -> Result<(), ParamError>
where
    T: PartialOrd + std::fmt::Display + Copy,
{
    if r.contains(&v) {
        Ok(())
    } else {
        Err(range_err(
            field,
            v,
            format!("{} ..= {}", r.start(), r.end()),
        ))
    }
}

fn check_fsize(
    field: &'static str,
    k: usize,
    r: &std::ops::RangeInclusive<usize>,
) -> Result<(), ParamError> {
    if r.contains(&k) && k % 2 == 1 {
        Ok(())
    } else {
        Err(range_err(
            field,
            k,
            format!("an odd number in {} ..= {}", r.start(), r.end()),
        ))
    }
}

fn check_slope(field: &'static str, a: f64) -> Result<(), ParamError> {
    let max = (1i64 << SLOPE_FRAC_BITS) - 1;
    if a.is_finite() && a >= 0.0 && quantize_slope(a) <= max {
        Ok(())
    } else {
        Err(range_err(
            field,
            a,
            format!("0 <= {field} < 1 metre per metre"),
        ))
    }
}

fn check_threshold(field: &'static str, th: f64) -> Result<(), ParamError> {
    if th.is_finite() && th > limits::TH_MIN_EXCL && th < limits::TH_MAX_EXCL {
        Ok(())
    } else {
        Err(range_err(
            field,
            th,
            format!(
                "{} < {field} < {} metres",
                limits::TH_MIN_EXCL,
                limits::TH_MAX_EXCL
            ),
        ))
    }
}

/// FNV-1a, 64 bits: the project's one short stable hash (parameter hashes in
/// generated-file headers, the simulator's model cache keys).
pub fn fnv1a64(bytes: &[u8]) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for &b in bytes {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x0000_0100_0000_01b3);
    }
    h
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fields_name_every_json_key_in_order() {
        let json = FccParams::default().to_json();
        let keys: Vec<&str> = json
            .lines()
            .filter_map(|l| l.trim().strip_prefix('"')?.split('"').next())
            .collect();
        let names: Vec<&str> = FccParams::default().fields().iter().map(|f| f.0).collect();
        assert_eq!(names, keys);
    }

    #[test]
    fn limits_are_in_the_json_and_fields_only_when_set() {
        let p = FccParams {
            bridge: Some(16),
            ring_reach: Some(0),
            ..Default::default()
        };
        let json = p.to_json();
        let keys: Vec<&str> = json
            .lines()
            .filter_map(|l| l.trim().strip_prefix('"')?.split('"').next())
            .collect();
        let names: Vec<&str> = p.fields().iter().map(|f| f.0).collect();
        assert_eq!(names, keys);
        assert!(keys.ends_with(&["bridge", "ring_reach"]));
        let q: FccParams = serde_json::from_str(&json).unwrap();
        assert_eq!(p, q);
        let s = FccParams {
            th_h_slope: 0.01,
            open_limit: Some(512),
            ..p.clone()
        };
        let keys: Vec<String> = s.fields().iter().map(|f| f.0.to_string()).collect();
        assert!(keys.ends_with(&["th_h_slope".into(), "open_limit".into()]));
        assert!(s.to_json().contains("\"open_limit\": 512"));
        assert_eq!(serde_json::from_str::<FccParams>(&s.to_json()).unwrap(), s);
        assert_ne!(p.hash(), FccParams::default().hash());
        assert!(!FccParams::default().to_json().contains("bridge"));
    }

    #[test]
    fn slopes_are_checked_quantised_and_absent_when_zero() {
        let mut p = FccParams {
            th_v_slope: 0.02,
            ..Default::default()
        };
        p.validate().unwrap();
        assert_eq!(quantize_slope(0.02), 1311);
        assert_eq!(p.th_v_slope_sq(), (1311 * 1311) >> 8);
        assert!(p.to_json().contains("th_v_slope") && !p.to_json().contains("th_h_slope"));
        assert_eq!(p.fields().last().unwrap().0, "th_v_slope");
        // The RTL takes slopes as build parameters (spec §2).
        p.validate_for_hardware().unwrap();
        for bad in [1.0, -0.1, f64::NAN] {
            p.th_h_slope = bad;
            let e = p.validate().unwrap_err();
            assert_eq!(e.field, "th_h_slope");
            assert!(e.to_string().contains("metre per metre"), "{e}");
        }
        p.th_h_slope = 0.99998;
        p.validate().unwrap();
        assert_eq!(FccParams::default().th_h_slope_sq(), 0);
        assert_eq!("adaptive".parse::<Preset>(), Ok(Preset::Adaptive));
        assert!("fast".parse::<Preset>().is_err());
    }

    #[test]
    fn bridge_and_ring_reach_rules() {
        let mut p = FccParams {
            cols: 100,
            ..Default::default()
        };
        assert!(p.bridges(5000) && p.ring_reaches(99, 0));
        p.bridge = Some(2);
        assert!(p.bridges(0) && p.bridges(2) && !p.bridges(3));
        p.ring_reach = Some(3);
        assert!(p.ring_reaches(2, 97) && !p.ring_reaches(3, 97) && !p.ring_reaches(2, 96));
        p.ring_reach = Some(0);
        assert!(!p.ring_reaches(0, 99));
        assert!(p.opens(u32::MAX - 1));
        p.open_limit = Some(2);
        assert!(p.opens(1) && !p.opens(2));
        p.validate().unwrap();
        p.open_limit = Some(0);
        assert_eq!(p.validate().unwrap_err().field, "open_limit");
    }

    #[test]
    fn limits_are_refused_by_the_row_major_core() {
        let p = FccParams {
            bridge: Some(16),
            ..Default::default()
        };
        p.validate().unwrap();
        let e = p.validate_for_hardware().unwrap_err();
        assert_eq!(e.field, "bridge");
        assert!(e.to_string().contains("row-major core"), "{e}");
    }

    #[test]
    fn label_bits_for_is_the_narrowest_width_that_holds_the_labels() {
        assert_eq!(FccParams::label_bits_for(0), 1);
        assert_eq!(FccParams::label_bits_for(255), 8);
        assert_eq!(FccParams::label_bits_for(256), 9);
        assert_eq!(FccParams::label_bits_for(32_767), 15);
        assert_eq!(FccParams::label_bits_for(32_768), 16);
    }

    #[test]
    fn default_is_valid_for_hardware() {
        FccParams::default().validate_for_hardware().unwrap();
    }

    #[test]
    fn even_fsize_names_the_field() {
        let p = FccParams {
            fsize: 6,
            ..Default::default()
        };
        let e = p.validate().unwrap_err();
        assert_eq!(e.field, "fsize");
        assert_eq!(
            e.to_string(),
            "fsize = 6 is out of range: an odd number in 3 ..= 15"
        );
    }

    #[test]
    fn fsize_one_is_rejected() {
        let p = FccParams {
            fsize: 1,
            ..Default::default()
        };
        assert_eq!(p.validate().unwrap_err().field, "fsize");
    }

    #[test]
    fn thresholds_must_be_positive_and_below_128() {
        for (th, ok) in [
            (0.0, false),
            (-1.0, false),
            (128.0, false),
            (f64::NAN, false),
            (127.99, true),
        ] {
            let p = FccParams {
                th_v: th,
                ..Default::default()
            };
            assert_eq!(p.validate().is_ok(), ok, "th_v = {th}");
            if !ok {
                assert_eq!(p.validate().unwrap_err().field, "th_v");
            }
        }
    }

    #[test]
    fn zero_rows_or_cols_rejected() {
        let p = FccParams {
            rows: 0,
            ..Default::default()
        };
        assert_eq!(p.validate().unwrap_err().field, "rows");
        let p = FccParams {
            cols: 0,
            ..Default::default()
        };
        assert_eq!(p.validate().unwrap_err().field, "cols");
    }

    #[test]
    fn hardware_ranges_are_tighter() {
        let p = FccParams {
            fsize: 13,
            ..Default::default()
        };
        p.validate().unwrap();
        assert_eq!(p.validate_for_hardware().unwrap_err().field, "fsize");
        let p = FccParams {
            rows: 8,
            ..Default::default()
        };
        assert_eq!(p.validate_for_hardware().unwrap_err().field, "rows");
    }

    #[test]
    fn threshold_quantisation_rounds_half_up() {
        assert_eq!(quantize_threshold(0.5), 128);
        assert_eq!(quantize_threshold(1.0), 256);
        // 0.001953125 m is exactly half a Q7.8 step: rounds up.
        assert_eq!(quantize_threshold(0.001_953_125), 1);
        assert_eq!(quantize_threshold(0.0019), 0);
    }

    #[test]
    fn derived_sizes() {
        let p = FccParams::default();
        assert_eq!(p.half(), 3);
        assert_eq!(p.window_positions(), 21);
        assert_eq!(p.max_label(), 32767);
        assert_eq!(p.th_v_sq(), 65536);
    }

    #[test]
    fn json_round_trip_and_stable_hash() {
        let p = FccParams::default();
        let q: FccParams = serde_json::from_str(&p.to_json()).unwrap();
        assert_eq!(p, q);
        assert_eq!(p.hash(), q.hash());
        let r = FccParams {
            fsize: 5,
            ..Default::default()
        };
        assert_ne!(p.hash(), r.hash());
    }

    #[test]
    fn module_suffix_names_k_and_differs_for_a_threshold_change() {
        let p = FccParams::default();
        assert_eq!(p.module_suffix(), format!("_k7_{}", &p.hash()[..8]));
        let q = FccParams {
            th_h: 0.75,
            ..Default::default()
        };
        assert_eq!(q.config_tag().len(), p.config_tag().len());
        assert_ne!(p.module_suffix(), q.module_suffix());
    }
}
