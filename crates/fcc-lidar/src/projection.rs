//! Spherical projection of unordered point clouds to range images, and the
//! way back from pixel labels to every input point.
//!
//! Column: `floor(0.5 (1 - atan2(y, x) / π) cols)`, so column 0 looks
//! backwards (-x), the middle column forwards (+x) and columns run
//! clockwise seen from above (the SemanticKITTI / RangeNet convention).
//! Row: with a field of view, `floor((1 - (pitch - down) / (up - down)) rows)`
//! with `pitch = asin(z / r)`, clamped to the image (points beyond the field
//! of view land on the top or bottom row); with a per-beam elevation table,
//! the row of the nearest beam. The nearest point wins a pixel.

use crate::error::{LidarError, Result};
use crate::image::{norm, RangeImage};

/// No pixel (a point with no finite, non-zero position).
pub const NO_PIXEL: u32 = u32::MAX;
/// No point (a pixel nothing landed on).
pub const NO_POINT: u32 = u32::MAX;

/// How rows map to elevation.
#[derive(Debug, Clone, PartialEq)]
pub enum VerticalLayout {
    /// Rows evenly spaced from `up_deg` (top edge of row 0) to `down_deg`
    /// (bottom edge of the last row).
    Fov { up_deg: f64, down_deg: f64 },
    /// One elevation per row in degrees, row 0 the top beam, decreasing.
    Beams(Vec<f64>),
}

/// Image size and vertical layout of a projection.
#[derive(Debug, Clone, PartialEq)]
pub struct ProjectionConfig {
    pub rows: usize,
    pub cols: usize,
    pub layout: VerticalLayout,
}

impl Default for ProjectionConfig {
    /// The HDL-64E / SemanticKITTI convention: 64 x 2048, +3 to -25 degrees.
    fn default() -> Self {
        ProjectionConfig {
            rows: 64,
            cols: 2048,
            layout: VerticalLayout::Fov {
                up_deg: 3.0,
                down_deg: -25.0,
            },
        }
    }
}

impl ProjectionConfig {
    /// Check sizes and angles.
    pub fn validate(&self) -> Result<()> {
        let err = |m: String| Err(LidarError::Config(m));
        if !(1..=4096).contains(&self.rows) || !(1..=65_536).contains(&self.cols) {
            return err(format!(
                "projection of {} x {} pixels: rows must be 1..=4096, cols 1..=65536",
                self.rows, self.cols
            ));
        }
        match &self.layout {
            VerticalLayout::Fov { up_deg, down_deg } => {
                if !(up_deg.is_finite() && down_deg.is_finite() && *up_deg > *down_deg)
                    || *up_deg > 90.0
                    || *down_deg < -90.0
                {
                    return err(format!(
                        "vertical field of view +{up_deg} / {down_deg} degrees: need -90 <= down < up <= 90"
                    ));
                }
            }
            VerticalLayout::Beams(e) => {
                if e.len() != self.rows {
                    return err(format!(
                        "the elevation table has {} beams but the image {} rows",
                        e.len(),
                        self.rows
                    ));
                }
                if e.iter().any(|v| !v.is_finite()) || e.windows(2).any(|w| w[1] >= w[0]) {
                    return err("the elevation table must be finite and strictly decreasing (row 0 the top beam)".into());
                }
            }
        }
        Ok(())
    }

    /// The (row, col) of a point, or `None` if it has no direction.
    pub fn pixel_of(&self, p: [f32; 3]) -> Option<(usize, usize)> {
        let r = f64::from(norm(p));
        if !(r.is_finite() && r > 0.0) {
            return None;
        }
        let (x, y, z) = (f64::from(p[0]), f64::from(p[1]), f64::from(p[2]));
        let yaw = y.atan2(x);
        let u = 0.5 * (1.0 - yaw / std::f64::consts::PI) * self.cols as f64;
        let col = (u.floor() as i64).clamp(0, self.cols as i64 - 1) as usize;
        let pitch = (z / r).clamp(-1.0, 1.0).asin().to_degrees();
        let row = match &self.layout {
            VerticalLayout::Fov { up_deg, down_deg } => {
                let v = (1.0 - (pitch - down_deg) / (up_deg - down_deg)) * self.rows as f64;
                (v.floor() as i64).clamp(0, self.rows as i64 - 1) as usize
            }
            VerticalLayout::Beams(e) => {
                // Decreasing table: first beam at or below the pitch, then
                // the nearer of it and the one above.
                let k = e.partition_point(|&b| b > pitch);
                if k == 0 {
                    0
                } else if k == e.len() {
                    e.len() - 1
                } else if (e[k - 1] - pitch) <= (pitch - e[k]) {
                    k - 1
                } else {
                    k
                }
            }
        };
        Some((row, col))
    }

    /// Whether a point lies above or below the vertical field of view (it is
    /// then put in the top or bottom row, where it crowds out other points):
    /// outside `fov_down ..= fov_up`, or more than half a beam spacing beyond
    /// the first or last beam of a beam table.
    pub fn outside_fov(&self, p: [f32; 3]) -> bool {
        let r = f64::from(norm(p));
        if !(r.is_finite() && r > 0.0) {
            return false;
        }
        let pitch = (f64::from(p[2]) / r).clamp(-1.0, 1.0).asin().to_degrees();
        let (top, bottom) = match &self.layout {
            VerticalLayout::Fov { up_deg, down_deg } => (*up_deg, *down_deg),
            VerticalLayout::Beams(e) if e.len() >= 2 => {
                let n = e.len();
                (
                    e[0] + (e[0] - e[1]) / 2.0,
                    e[n - 1] - (e[n - 2] - e[n - 1]) / 2.0,
                )
            }
            VerticalLayout::Beams(_) => return false,
        };
        pitch > top || pitch < bottom
    }
}

/// A projected cloud: the range image, and which pixel each point fell in.
#[derive(Debug, Clone)]
pub struct Projection {
    pub image: RangeImage,
    /// Per point: its pixel (row-major), or [`NO_PIXEL`].
    pub point_pixel: Vec<u32>,
    /// Per pixel: the point that won it (the nearest), or [`NO_POINT`].
    pub pixel_point: Vec<u32>,
    /// Per point: its range in metres (NaN for points with no pixel).
    pub point_range: Vec<f32>,
    /// Points above or below the vertical field of view (squeezed into the
    /// top or bottom row).
    pub outside_fov: usize,
}

/// Project points to a range image; the nearest point wins each pixel.
pub fn project(points: &[[f32; 3]], cfg: &ProjectionConfig) -> Result<Projection> {
    cfg.validate()?;
    if points.len() >= NO_POINT as usize {
        return Err(LidarError::Config(format!(
            "{} points are too many to project",
            points.len()
        )));
    }
    let mut image = RangeImage::empty(cfg.rows, cfg.cols);
    let mut point_pixel = vec![NO_PIXEL; points.len()];
    let mut point_range = vec![f32::NAN; points.len()];
    let mut pixel_point = vec![NO_POINT; cfg.rows * cfg.cols];
    let mut best = vec![f32::INFINITY; cfg.rows * cfg.cols];
    let mut outside_fov = 0;
    for (i, &p) in points.iter().enumerate() {
        let Some((r, c)) = cfg.pixel_of(p) else {
            continue;
        };
        outside_fov += usize::from(cfg.outside_fov(p));
        let px = r * cfg.cols + c;
        let range = norm(p);
        point_pixel[i] = px as u32;
        point_range[i] = range;
        if range < best[px] {
            best[px] = range;
            pixel_point[px] = i as u32;
        }
    }
    for (px, &i) in pixel_point.iter().enumerate() {
        if i != NO_POINT {
            image.set(px, Some(points[i as usize]));
        }
    }
    Ok(Projection {
        image,
        point_pixel,
        pixel_point,
        point_range,
        outside_fov,
    })
}

/// How points that lost their pixel find a label.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BackProjection {
    /// Rows searched above and below the point's pixel.
    pub half_rows: usize,
    /// Columns searched left and right (wrapping round).
    pub half_cols: usize,
    /// A neighbour further than this in range gives no label (0).
    pub max_range_gap_m: f32,
}

impl Default for BackProjection {
    fn default() -> Self {
        BackProjection {
            half_rows: 1,
            half_cols: 2,
            max_range_gap_m: 1.0,
        }
    }
}

impl Projection {
    /// Points that won their pixel.
    pub fn kept_points(&self) -> usize {
        self.pixel_point.iter().filter(|&&i| i != NO_POINT).count()
    }

    /// Points with no pixel at all (zero or non-finite coordinates).
    pub fn unprojected_points(&self) -> usize {
        self.point_pixel.iter().filter(|&&p| p == NO_PIXEL).count()
    }

    /// A per-point value moved to the pixels (the winner's value; `empty`
    /// where no point landed), e.g. ground-truth labels.
    pub fn to_pixels(&self, per_point: &[u32], empty: u32) -> Result<Vec<u32>> {
        if per_point.len() != self.point_pixel.len() {
            return Err(LidarError::Mismatch {
                what: "per-point values for the projected points".into(),
                expected: self.point_pixel.len(),
                got: per_point.len(),
            });
        }
        Ok(self
            .pixel_point
            .iter()
            .map(|&i| {
                if i == NO_POINT {
                    empty
                } else {
                    per_point[i as usize]
                }
            })
            .collect())
    }

    /// Pixel labels back to every input point. A point that won its pixel
    /// takes that pixel's label; a point that lost it takes the label of the
    /// pixel in the window around it whose point is nearest in range (which
    /// may be 0), or 0 if none is within `max_range_gap_m`; a point with no
    /// pixel gets 0.
    pub fn labels_to_points(&self, pixel_labels: &[u32], opts: BackProjection) -> Result<Vec<u32>> {
        let (rows, cols) = (self.image.rows, self.image.cols);
        if pixel_labels.len() != rows * cols {
            return Err(LidarError::Mismatch {
                what: format!("pixel labels of a {rows} x {cols} projection"),
                expected: rows * cols,
                got: pixel_labels.len(),
            });
        }
        let mut out = vec![0u32; self.point_pixel.len()];
        for (i, &px) in self.point_pixel.iter().enumerate() {
            if px == NO_PIXEL {
                continue;
            }
            let px = px as usize;
            if self.pixel_point[px] == i as u32 {
                out[i] = pixel_labels[px];
                continue;
            }
            let (r0, c0) = (px / cols, px % cols);
            let range = self.point_range[i];
            let mut best = (f32::INFINITY, 0u32);
            let half_c = opts.half_cols.min(cols / 2);
            for r in r0.saturating_sub(opts.half_rows)..=(r0 + opts.half_rows).min(rows - 1) {
                for dc in 0..=2 * half_c {
                    let c = (c0 + cols + dc - half_c) % cols;
                    let q = r * cols + c;
                    let j = self.pixel_point[q];
                    if j == NO_POINT {
                        continue;
                    }
                    let gap = (self.point_range[j as usize] - range).abs();
                    if gap < best.0 {
                        best = (gap, pixel_labels[q]);
                    }
                }
            }
            if best.0 <= opts.max_range_gap_m {
                out[i] = best.1;
            }
        }
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at(yaw_deg: f64, pitch_deg: f64, r: f64) -> [f32; 3] {
        let (y, p) = (yaw_deg.to_radians(), pitch_deg.to_radians());
        [
            (r * p.cos() * y.cos()) as f32,
            (r * p.cos() * y.sin()) as f32,
            (r * p.sin()) as f32,
        ]
    }

    #[test]
    fn forward_is_the_middle_column_and_left_is_before_it() {
        let cfg = ProjectionConfig::default();
        assert_eq!(cfg.pixel_of(at(0.0, 2.9, 10.0)), Some((0, 1024)));
        assert_eq!(cfg.pixel_of(at(0.0, -24.9, 10.0)), Some((63, 1024)));
        // +y (left of a car looking along +x) is a quarter turn before the middle.
        assert_eq!(cfg.pixel_of(at(90.0, -11.0, 10.0)).map(|p| p.1), Some(512));
        assert_eq!(
            cfg.pixel_of(at(-90.0, -11.0, 10.0)).map(|p| p.1),
            Some(1536)
        );
        // Beyond the field of view: clamped.
        assert_eq!(cfg.pixel_of(at(0.0, 30.0, 10.0)).map(|p| p.0), Some(0));
        assert_eq!(cfg.pixel_of(at(0.0, -60.0, 10.0)).map(|p| p.0), Some(63));
        assert_eq!(cfg.pixel_of([0.0, 0.0, 0.0]), None);
        assert_eq!(cfg.pixel_of([f32::NAN, 0.0, 1.0]), None);
    }

    #[test]
    fn elevation_table_picks_the_nearest_beam() {
        let cfg = ProjectionConfig {
            rows: 3,
            cols: 8,
            layout: VerticalLayout::Beams(vec![2.0, 0.0, -4.0]),
        };
        cfg.validate().unwrap();
        let row = |pitch| cfg.pixel_of(at(0.0, pitch, 5.0)).unwrap().0;
        assert_eq!(
            [
                row(10.0),
                row(1.2),
                row(0.8),
                row(-1.9),
                row(-2.1),
                row(-30.0)
            ],
            [0, 0, 1, 1, 2, 2]
        );
        let bad = ProjectionConfig {
            layout: VerticalLayout::Beams(vec![0.0, 1.0, -1.0]),
            ..cfg.clone()
        };
        assert!(bad
            .validate()
            .unwrap_err()
            .to_string()
            .contains("strictly decreasing"));
    }

    #[test]
    fn points_above_or_below_the_field_of_view_are_counted() {
        let fov = ProjectionConfig {
            rows: 4,
            cols: 16,
            layout: VerticalLayout::Fov {
                up_deg: 10.0,
                down_deg: -10.0,
            },
        };
        let pts = [
            at(0.0, 5.0, 10.0),
            at(0.0, 15.0, 10.0),
            at(0.0, -30.0, 10.0),
            at(0.0, -9.9, 10.0),
            [f32::NAN; 3],
        ];
        let p = project(&pts, &fov).unwrap();
        assert_eq!(p.outside_fov, 2);
        assert_eq!(p.unprojected_points(), 1);
        let beams = ProjectionConfig {
            rows: 3,
            cols: 16,
            layout: VerticalLayout::Beams(vec![2.0, 0.0, -2.0]),
        };
        // Half a spacing (1 degree) beyond the first and last beams is still in.
        let pts = [at(0.0, 2.9, 10.0), at(0.0, 3.1, 10.0), at(0.0, -3.2, 10.0)];
        assert_eq!(project(&pts, &beams).unwrap().outside_fov, 2);
    }

    #[test]
    fn nearest_point_wins_and_losers_take_their_neighbours_label() {
        let cfg = ProjectionConfig {
            rows: 4,
            cols: 16,
            layout: VerticalLayout::Fov {
                up_deg: 10.0,
                down_deg: -10.0,
            },
        };
        // Two points in one pixel (10 m and 10.2 m), one far behind (30 m)
        // in the same pixel, one lone point elsewhere, one invalid.
        let pts = [
            at(1.0, 1.0, 10.2),
            at(1.0, 1.0, 10.0),
            at(1.0, 1.0, 30.0),
            at(100.0, -8.0, 5.0),
            [f32::NAN; 3],
        ];
        let p = project(&pts, &cfg).unwrap();
        assert_eq!(p.kept_points(), 2);
        let px = p.point_pixel[1] as usize;
        assert_eq!(p.pixel_point[px], 1);
        assert_eq!(p.point_pixel[4], NO_PIXEL);
        let mut labels = vec![0u32; 64];
        labels[px] = 7;
        labels[p.point_pixel[3] as usize] = 9;
        let back = p
            .labels_to_points(&labels, BackProjection::default())
            .unwrap();
        assert_eq!(back, vec![7, 7, 0, 9, 0]);
        let gt = p.to_pixels(&[1, 2, 3, 4, 5], 0).unwrap();
        assert_eq!(gt[px], 2);
        assert!(p
            .labels_to_points(&labels[..10], BackProjection::default())
            .is_err());
    }
}
