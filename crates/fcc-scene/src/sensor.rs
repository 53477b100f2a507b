//! The spinning sensor: beam elevations, column azimuths and range limits.

use std::f64::consts::{PI, TAU};

/// Height of the sensor's optical centre above the ground, in metres (KITTI's HDL-64E mount).
pub const SENSOR_HEIGHT_M: f64 = 1.73;

/// `z` of the flat ground plane in the sensor frame, in metres.
pub const GROUND_Z_M: f64 = -SENSOR_HEIGHT_M;

/// Returns farther than this (in metres, along the ray) are not reported: the pixel is empty.
pub const MAX_RANGE_M: f64 = 120.0;

/// Returns nearer than this (in metres, along the ray) are not reported: the pixel is empty.
pub const MIN_RANGE_M: f64 = 1.0;

/// Number of beams in the reference profile (HDL-64E).
const PROFILE_BEAMS: usize = 64;

/// Beams in the upper block of the reference profile.
const UPPER_BEAMS: usize = 32;

/// Elevation of beam `i` of the 64-beam reference profile, in degrees.
///
/// Upper block: 32 beams from +2 down to -8.33 at 1/3 degree spacing.
/// Lower block: 32 beams from -8.83 down to -24.33 at 1/2 degree spacing.
fn profile_deg(i: usize) -> f64 {
    if i < UPPER_BEAMS {
        2.0 - i as f64 / 3.0
    } else {
        -8.83 - (i - UPPER_BEAMS) as f64 * 0.5
    }
}

/// Beam elevations in degrees, row 0 first (the top beam), strictly decreasing.
///
/// For 64 rows this is the HDL-64E-like profile: an upper block from +2 down to -8.33
/// degrees at 1/3 degree spacing and a lower block from -8.83 down to -24.33 degrees at
/// 1/2 degree spacing, so beams are denser near the horizon. Any other row count
/// resamples the same profile linearly over the same span, keeping the dense upper
/// block. `rows == 1` gives the top beam only; `rows == 0` gives an empty vector.
pub fn beam_elevations_deg(rows: usize) -> Vec<f64> {
    match rows {
        0 => Vec::new(),
        1 => vec![profile_deg(0)],
        _ => {
            let last = (PROFILE_BEAMS - 1) as f64;
            (0..rows)
                .map(|i| {
                    // Exact for rows == 64: i * 63 / 63 == i in floating point.
                    let pos = i as f64 * last / (rows - 1) as f64;
                    let lo = (pos.floor() as usize).min(PROFILE_BEAMS - 2);
                    let frac = pos - lo as f64;
                    if frac == 0.0 {
                        profile_deg(lo)
                    } else {
                        profile_deg(lo) + (profile_deg(lo + 1) - profile_deg(lo)) * frac
                    }
                })
                .collect()
        }
    }
}

/// Azimuth of the centre of column `col` out of `cols`, in radians, measured from +x
/// toward +y (counter-clockwise seen from above), in `(-pi, pi)`.
///
/// Column 0 looks backward (azimuth just below +pi) and the azimuth decreases with the
/// column index, i.e. the columns sweep clockwise seen from above like a KITTI/Velodyne
/// scan: column `cols/4` looks left (+y), `cols/2` forward (+x), `3*cols/4` right (-y).
pub fn column_azimuth_rad(col: usize, cols: usize) -> f64 {
    PI - TAU * (col as f64 + 0.5) / cols as f64
}

/// The column whose azimuth interval contains `azimuth_rad` (any real angle; it is
/// wrapped), the inverse of [`column_azimuth_rad`]. `cols` must be at least 1.
pub fn column_of_azimuth(azimuth_rad: f64, cols: usize) -> usize {
    let cols_i = cols.max(1) as i64;
    let c = ((PI - azimuth_rad) * cols as f64 / TAU).floor() as i64;
    c.rem_euclid(cols_i) as usize
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn elevations_64_match_the_hdl64e_blocks() {
        let e = beam_elevations_deg(64);
        assert_eq!(e.len(), 64);
        assert_eq!(e[0], 2.0);
        assert!((e[31] - (-8.3333)).abs() < 1e-3, "{}", e[31]);
        assert!((e[32] - (-8.83)).abs() < 1e-12, "{}", e[32]);
        assert!((e[63] - (-24.33)).abs() < 1e-12, "{}", e[63]);
        assert!((e[0] - e[1] - 1.0 / 3.0).abs() < 1e-12);
        assert!((e[62] - e[63] - 0.5).abs() < 1e-12);
    }

    #[test]
    fn elevations_resampled_keep_span_order_and_density() {
        for rows in [16, 32, 48, 64, 100, 128] {
            let e = beam_elevations_deg(rows);
            assert_eq!(e.len(), rows);
            assert_eq!(e[0], 2.0, "rows={rows}");
            assert!((e[rows - 1] - (-24.33)).abs() < 1e-9, "rows={rows}");
            assert!(e.windows(2).all(|w| w[0] > w[1]), "rows={rows}");
            let top = e[0] - e[1];
            let bottom = e[rows - 2] - e[rows - 1];
            assert!(
                top < bottom,
                "rows={rows}: top spacing {top} >= bottom {bottom}"
            );
        }
    }

    #[test]
    fn elevations_degenerate_row_counts() {
        assert!(beam_elevations_deg(0).is_empty());
        assert_eq!(beam_elevations_deg(1), vec![2.0]);
    }

    #[test]
    fn column_azimuth_convention() {
        let cols = 2048;
        let q = |c: usize| column_azimuth_rad(c, cols);
        assert!(q(0) > PI - 0.01 && q(0) < PI, "column 0 looks backward");
        assert!((q(cols / 4) - (PI / 2.0 - TAU * 0.5 / cols as f64)).abs() < 1e-12);
        assert!(
            q(cols / 2 - 1) > 0.0 && q(cols / 2) < 0.0,
            "forward between 1023 and 1024"
        );
        assert!(q(cols - 1) < -PI + 0.01);
        for c in [0, 1, 511, 512, 1023, 1024, 2047] {
            assert_eq!(column_of_azimuth(q(c), cols), c);
            assert_eq!(column_of_azimuth(q(c) + TAU, cols), c);
        }
        assert_eq!(column_of_azimuth(PI / 2.0 - 1e-4, cols), 512);
        assert_eq!(column_of_azimuth(-PI / 2.0 - 1e-4, cols), 1536);
        assert_eq!(column_of_azimuth(0.3, 1), 0);
    }
}
