//! The scene configuration and the crate's error type.

use serde::{Deserialize, Serialize};
use thiserror::Error;

/// Everything that shapes a synthetic scene. Build one, change fields, then
/// [`validate`](SceneConfig::validate) it (or let [`crate::generate`] do so).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct SceneConfig {
    /// Beams (rows of the range image), 16..=128. Default 64.
    pub rows: usize,
    /// Azimuth columns per revolution, 1..=65536. Default 2048.
    pub cols: usize,
    /// Seed of every random choice; the street layout depends on nothing else.
    pub seed: u64,
    /// Keep ground returns as points (flagged in [`crate::Scene::ground`]). Default
    /// false: ground pixels are empty, as after a perfect ground removal.
    pub keep_ground: bool,
    /// Probability, per beam and azimuth segment (1/64 of a revolution), that the beam
    /// drops out for a short stretch of columns, 0..=1. Default 0.02.
    pub dropout: f64,
    /// Probability that a single return is missing, 0..=1. Default 0.01.
    pub missing: f64,
    /// Standard deviation of the gaussian range noise along the ray, metres, 0..=1.
    /// Default 0.01.
    pub range_noise_m: f64,
}

impl Default for SceneConfig {
    fn default() -> Self {
        SceneConfig {
            rows: 64,
            cols: 2048,
            seed: 0,
            keep_ground: false,
            dropout: 0.02,
            missing: 0.01,
            range_noise_m: 0.01,
        }
    }
}

/// Allowed beam counts.
pub const ROWS_RANGE: std::ops::RangeInclusive<usize> = 16..=128;

/// Allowed column counts.
pub const COLS_RANGE: std::ops::RangeInclusive<usize> = 1..=65536;

/// Largest allowed range noise standard deviation, metres.
pub const MAX_RANGE_NOISE_M: f64 = 1.0;

/// Why a scene could not be built.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum SceneError {
    /// A [`SceneConfig`] field is outside its allowed range.
    #[error(
        "invalid scene config: `{field}` = {value} is out of range; set it to a value in {allowed}"
    )]
    OutOfRange {
        /// The field's name, as spelled in [`SceneConfig`].
        field: &'static str,
        /// The rejected value.
        value: String,
        /// The allowed range.
        allowed: &'static str,
    },
    /// An object handed to [`crate::render`] cannot be rendered.
    #[error("invalid object at index {index} (id {id}): {reason}")]
    InvalidObject {
        /// Position of the object in the slice.
        index: usize,
        /// The object's id.
        id: u32,
        /// What is wrong with it.
        reason: String,
    },
}

fn out_of_range(field: &'static str, value: impl ToString, allowed: &'static str) -> SceneError {
    SceneError::OutOfRange {
        field,
        value: value.to_string(),
        allowed,
    }
}

fn check_probability(field: &'static str, p: f64) -> Result<(), SceneError> {
    if (0.0..=1.0).contains(&p) {
        Ok(())
    } else {
        Err(out_of_range(field, p, "0.0..=1.0"))
    }
}

impl SceneConfig {
    /// Checks every field against its allowed range; the error names the first bad field.
    pub fn validate(&self) -> Result<(), SceneError> {
        if !ROWS_RANGE.contains(&self.rows) {
            return Err(out_of_range("rows", self.rows, "16..=128"));
        }
        if !COLS_RANGE.contains(&self.cols) {
            return Err(out_of_range("cols", self.cols, "1..=65536"));
        }
        check_probability("dropout", self.dropout)?;
        check_probability("missing", self.missing)?;
        if !(0.0..=MAX_RANGE_NOISE_M).contains(&self.range_noise_m) {
            return Err(out_of_range(
                "range_noise_m",
                self.range_noise_m,
                "0.0..=1.0 (metres)",
            ));
        }
        Ok(())
    }

    /// Number of pixels (`rows * cols`).
    pub fn pixels(&self) -> usize {
        self.rows * self.cols
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn field_of(cfg: &SceneConfig) -> &'static str {
        match cfg.validate() {
            Err(SceneError::OutOfRange { field, .. }) => field,
            other => panic!("expected OutOfRange, got {other:?}"),
        }
    }

    #[test]
    fn default_is_valid() {
        assert_eq!(SceneConfig::default().validate(), Ok(()));
    }

    #[test]
    fn range_edges_are_accepted() {
        for (rows, cols) in [(16, 1), (128, 65536), (64, 2048)] {
            let cfg = SceneConfig {
                rows,
                cols,
                dropout: 1.0,
                missing: 0.0,
                range_noise_m: 1.0,
                ..SceneConfig::default()
            };
            assert_eq!(cfg.validate(), Ok(()), "rows={rows} cols={cols}");
        }
    }

    #[test]
    fn each_bad_field_is_named() {
        let d = SceneConfig::default;
        let cases = [
            (SceneConfig { rows: 15, ..d() }, "rows"),
            (SceneConfig { rows: 129, ..d() }, "rows"),
            (SceneConfig { cols: 0, ..d() }, "cols"),
            (SceneConfig { cols: 65537, ..d() }, "cols"),
            (
                SceneConfig {
                    dropout: -0.1,
                    ..d()
                },
                "dropout",
            ),
            (
                SceneConfig {
                    dropout: f64::NAN,
                    ..d()
                },
                "dropout",
            ),
            (
                SceneConfig {
                    missing: 1.5,
                    ..d()
                },
                "missing",
            ),
            (
                SceneConfig {
                    range_noise_m: -1e-3,
                    ..d()
                },
                "range_noise_m",
            ),
            (
                SceneConfig {
                    range_noise_m: f64::INFINITY,
                    ..d()
                },
                "range_noise_m",
            ),
        ];
        for (cfg, field) in cases {
            assert_eq!(field_of(&cfg), field, "{cfg:?}");
        }
    }

    #[test]
    fn error_message_names_field_value_and_range() {
        let cfg = SceneConfig {
            rows: 8,
            ..SceneConfig::default()
        };
        let msg = cfg.validate().unwrap_err().to_string();
        assert_eq!(
            msg,
            "invalid scene config: `rows` = 8 is out of range; set it to a value in 16..=128"
        );
        let cfg = SceneConfig {
            missing: 2.0,
            ..SceneConfig::default()
        };
        let msg = cfg.validate().unwrap_err().to_string();
        assert!(
            msg.contains("`missing` = 2") && msg.contains("0.0..=1.0"),
            "{msg}"
        );
    }
}
