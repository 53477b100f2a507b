//! Range images in the golden model's integer form.

/// The Q7.8 point and the quantisation rule (with the empty-pixel rule) are
/// defined once, in `fcc-pixel`, shared with drivers that pack frames for
/// the hardware.
pub use fcc_pixel::{quantize, quantize_point, Point};

/// A range image of `rows` x `cols` pixels in raster order (row 0 is the top
/// beam); `None` is an empty pixel.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Frame {
    pub rows: usize,
    pub cols: usize,
    pub points: Vec<Option<Point>>,
}

impl Frame {
    /// A frame with every pixel empty.
    pub fn empty(rows: usize, cols: usize) -> Frame {
        Frame {
            rows,
            cols,
            points: vec![None; rows * cols],
        }
    }

    /// Quantise `rows * cols * 3` coordinates (row-major, x y z per pixel).
    ///
    /// # Panics
    /// If `xyz.len() != rows * cols * 3`; readers check the shape first.
    pub fn from_xyz_f32(rows: usize, cols: usize, xyz: &[f32]) -> Frame {
        assert_eq!(
            xyz.len(),
            rows * cols * 3,
            "xyz length must be rows * cols * 3"
        );
        let points = xyz
            .chunks_exact(3)
            .map(|p| quantize_point(f64::from(p[0]), f64::from(p[1]), f64::from(p[2])))
            .collect();
        Frame { rows, cols, points }
    }

    /// As [`from_xyz_f32`](Self::from_xyz_f32), for 64-bit input.
    pub fn from_xyz_f64(rows: usize, cols: usize, xyz: &[f64]) -> Frame {
        assert_eq!(
            xyz.len(),
            rows * cols * 3,
            "xyz length must be rows * cols * 3"
        );
        let points = xyz
            .chunks_exact(3)
            .map(|p| quantize_point(p[0], p[1], p[2]))
            .collect();
        Frame { rows, cols, points }
    }

    /// The pixel at (row, col).
    pub fn get(&self, r: usize, c: usize) -> Option<Point> {
        self.points[r * self.cols + c]
    }

    /// Set the pixel at (row, col).
    pub fn set(&mut self, r: usize, c: usize, p: Option<Point>) {
        self.points[r * self.cols + c] = p;
    }

    /// Number of valid (non-empty) pixels.
    pub fn valid_count(&self) -> usize {
        self.points.iter().filter(|p| p.is_some()).count()
    }
}

/// Exact squared distance between two Q7.8 points, in Q7.8² units.
#[inline]
pub fn dist2(a: Point, b: Point) -> i64 {
    let dx = i64::from(a[0]) - i64::from(b[0]);
    let dy = i64::from(a[1]) - i64::from(b[1]);
    let dz = i64::from(a[2]) - i64::from(b[2]);
    dx * dx + dy * dy + dz * dz
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quantize_rounds_half_away_from_zero() {
        assert_eq!(quantize(0.0), Some(0));
        assert_eq!(quantize(1.0), Some(256));
        assert_eq!(quantize(-1.0), Some(-256));
        // 1/512 m is half a step: away from zero on both sides.
        assert_eq!(quantize(1.0 / 512.0), Some(1));
        assert_eq!(quantize(-1.0 / 512.0), Some(-1));
        assert_eq!(quantize(0.0019), Some(0));
    }

    #[test]
    fn quantize_range_limits() {
        assert_eq!(quantize(127.996), Some(32767));
        assert_eq!(quantize(127.999), None); // rounds to 32768
        assert_eq!(quantize(-128.0), Some(-32768));
        assert_eq!(quantize(-128.002), None);
        assert_eq!(quantize(f64::NAN), None);
        assert_eq!(quantize(f64::INFINITY), None);
    }

    #[test]
    fn one_bad_coordinate_empties_the_pixel() {
        let f = Frame::from_xyz_f32(1, 2, &[1.0, 2.0, 3.0, 1.0, f32::NAN, 3.0]);
        assert_eq!(f.get(0, 0), Some([256, 512, 768]));
        assert_eq!(f.get(0, 1), None);
        assert_eq!(f.valid_count(), 1);
    }

    #[test]
    fn dist2_does_not_overflow_at_extremes() {
        let a = [i16::MIN; 3];
        let b = [i16::MAX; 3];
        assert_eq!(dist2(a, b), 3 * 65535i64 * 65535);
    }
}
