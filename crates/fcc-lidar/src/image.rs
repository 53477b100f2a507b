//! The range image every reader produces and every stage after it consumes.

use crate::error::{LidarError, Result};
use fcc_golden::Frame;

/// A range image of `rows` x `cols` pixels, row-major, row 0 the top beam.
/// Each pixel holds x, y, z in metres; a pixel with no return holds NaN in
/// all three. Two images are equal when their coordinates are equal bit for
/// bit (so empty pixels compare equal).
#[derive(Debug, Clone)]
pub struct RangeImage {
    pub rows: usize,
    pub cols: usize,
    /// `rows * cols * 3` coordinates, x y z per pixel.
    pub xyz: Vec<f32>,
}

impl PartialEq for RangeImage {
    fn eq(&self, other: &Self) -> bool {
        self.rows == other.rows
            && self.cols == other.cols
            && self.xyz.len() == other.xyz.len()
            && self
                .xyz
                .iter()
                .zip(&other.xyz)
                .all(|(a, b)| a.to_bits() == b.to_bits())
    }
}

impl RangeImage {
    /// An image with every pixel empty.
    pub fn empty(rows: usize, cols: usize) -> RangeImage {
        RangeImage {
            rows,
            cols,
            xyz: vec![f32::NAN; rows * cols * 3],
        }
    }

    /// Every pixel empty again, at `rows` x `cols`, in the memory already
    /// held where it is enough (a frame after frame without fresh pages).
    pub fn reset(&mut self, rows: usize, cols: usize) {
        self.rows = rows;
        self.cols = cols;
        self.xyz.clear();
        self.xyz.resize(rows * cols * 3, f32::NAN);
    }

    /// Wrap coordinates, checking the length.
    pub fn from_xyz(rows: usize, cols: usize, xyz: Vec<f32>) -> Result<RangeImage> {
        let expected = rows * cols * 3;
        if xyz.len() != expected {
            return Err(LidarError::Mismatch {
                what: format!("coordinates of a {rows} x {cols} range image"),
                expected,
                got: xyz.len(),
            });
        }
        Ok(RangeImage { rows, cols, xyz })
    }

    /// Pixels in the image.
    pub fn pixels(&self) -> usize {
        self.rows * self.cols
    }

    /// The point at pixel index `i` (row-major), or `None` if empty.
    pub fn point(&self, i: usize) -> Option<[f32; 3]> {
        let p = [self.xyz[3 * i], self.xyz[3 * i + 1], self.xyz[3 * i + 2]];
        if p.iter().all(|v| v.is_finite()) {
            Some(p)
        } else {
            None
        }
    }

    /// The point at (row, col), or `None` if empty.
    pub fn at(&self, r: usize, c: usize) -> Option<[f32; 3]> {
        self.point(r * self.cols + c)
    }

    /// Store a point (or clear the pixel with `None`).
    pub fn set(&mut self, i: usize, p: Option<[f32; 3]>) {
        let v = p.unwrap_or([f32::NAN; 3]);
        self.xyz[3 * i..3 * i + 3].copy_from_slice(&v);
    }

    /// Distance of pixel `i` from the origin, or `None` if empty.
    pub fn range(&self, i: usize) -> Option<f32> {
        self.point(i).map(norm)
    }

    /// Pixels that hold a point.
    pub fn valid_count(&self) -> usize {
        (0..self.pixels())
            .filter(|&i| self.point(i).is_some())
            .count()
    }

    /// A copy with the pixels where `mask` is true emptied (for example the
    /// ground before clustering).
    pub fn without(&self, mask: &[bool]) -> RangeImage {
        let mut out = self.clone();
        for (i, &m) in mask.iter().enumerate().take(self.pixels()) {
            if m {
                out.set(i, None);
            }
        }
        out
    }

    /// The golden model's quantised frame of this image.
    pub fn to_frame(&self) -> Frame {
        Frame::from_xyz_f32(self.rows, self.cols, &self.xyz)
    }
}

/// Euclidean norm of a point.
pub fn norm(p: [f32; 3]) -> f32 {
    (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn from_xyz_checks_length() {
        let err = RangeImage::from_xyz(2, 3, vec![0.0; 17]).unwrap_err();
        assert!(err.to_string().contains("expected 18, got 17"), "{err}");
    }

    #[test]
    fn nan_pixels_are_empty_and_frame_matches() {
        let mut img = RangeImage::empty(1, 3);
        img.set(1, Some([1.0, 2.0, 2.0]));
        assert_eq!(img.valid_count(), 1);
        assert_eq!(img.range(1), Some(3.0));
        assert_eq!(img.range(0), None);
        let f = img.to_frame();
        assert_eq!(f.get(0, 1), Some([256, 512, 512]));
        assert_eq!(f.get(0, 0), None);
        let cleared = img.without(&[false, true, false]);
        assert_eq!(cleared.valid_count(), 0);
    }

    #[test]
    fn reset_empties_every_pixel_at_the_new_size() {
        let mut img = RangeImage::empty(2, 3);
        img.set(5, Some([1.0, 2.0, 2.0]));
        img.reset(2, 3);
        assert_eq!(img, RangeImage::empty(2, 3));
        img.set(0, Some([1.0, 2.0, 2.0]));
        img.reset(4, 2);
        assert_eq!(img, RangeImage::empty(4, 2));
    }
}
