//! The pixel and label formats of the FCC core, written once.
//!
//! The golden model (`fcc-golden`) quantises its input with [`quantize`] and
//! [`quantize_point`]; drivers (`fcc-driver`, bare metal or Linux) quantise
//! and pack frames with the same functions, so a frame sent to the hardware
//! is exactly the frame the golden model clusters. No dependencies and no
//! `std`, so an embedded driver can use it.
//!
//! Input beat (64 bits, one pixel): bits 15:0 x, 31:16 y, 47:32 z (Q7.8 two's
//! complement), bit 48 = 1 when the pixel holds a point; bits 63:49 zero.
//! Output beat (64 bits): label of slot `s` in bits `16*s+15 : 16*s`.
//! Record beats of the column-streaming core: [`record`].
#![no_std]

pub mod record;

/// Fractional bits of the Q7.8 coordinate format.
pub const FRAC_BITS: u32 = 8;
/// One metre in Q7.8 units.
pub const Q_ONE: f64 = (1u32 << FRAC_BITS) as f64;

/// A point in Q7.8 fixed point: x, y, z in units of 1/256 m.
pub type Point = [i16; 3];

/// Bit of the input beat that marks a pixel holding a point.
pub const PIXEL_VALID_BIT: u32 = 48;
/// Bytes of one input beat (one pixel).
pub const PIXEL_BYTES: usize = 8;
/// Bytes of one output beat.
pub const LABEL_BEAT_BYTES: usize = 8;
/// Bits of one label slot in an output beat.
pub const LABEL_SLOT_BITS: u32 = 16;
/// Bytes of one label slot (`TKEEP` bits per label).
pub const LABEL_SLOT_BYTES: usize = LABEL_SLOT_BITS as usize / 8;

/// Quantise one coordinate in metres to Q7.8:
/// `sign(x) * floor(|x| * 256 + 0.5)`, or `None` when `x` is not finite or
/// the result falls outside `[-32768, 32767]`.
pub fn quantize(x: f64) -> Option<i16> {
    let abs = if x < 0.0 { -x } else { x };
    // |x| * 256 + 0.5 is non-negative, so truncation is the floor. Below
    // 32769 it fits an i32 exactly; at or above it (and for an infinite or
    // NaN x, which fail the comparison) the point is out of range.
    let t = abs * Q_ONE + 0.5;
    if t.is_nan() || t >= 32769.0 {
        return None;
    }
    let mag = t as i32;
    if x < 0.0 {
        (mag <= 32768).then(|| (-mag) as i16)
    } else {
        (mag <= 32767).then_some(mag as i16)
    }
}

/// Quantise a whole point. The empty-pixel rule: the pixel is empty when any
/// coordinate is (not finite, or outside the Q7.8 range).
pub fn quantize_point(x: f64, y: f64, z: f64) -> Option<Point> {
    Some([quantize(x)?, quantize(y)?, quantize(z)?])
}

/// The input beat of one pixel (0 for an empty pixel).
pub fn pixel_beat(p: Option<Point>) -> u64 {
    match p {
        None => 0,
        Some([x, y, z]) => {
            u64::from(x as u16)
                | (u64::from(y as u16) << 16)
                | (u64::from(z as u16) << 32)
                | (1 << PIXEL_VALID_BIT)
        }
    }
}

/// Label of slot `s` of an output beat.
pub fn label_of_beat(beat: u64, s: usize) -> u32 {
    ((beat >> (LABEL_SLOT_BITS as usize * s)) & ((1 << LABEL_SLOT_BITS) - 1)) as u32
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pixel_beat_layout_and_empty_pixel() {
        assert_eq!(pixel_beat(None), 0);
        assert_eq!(pixel_beat(Some([1, -1, -32768])), 0x0001_8000_ffff_0001);
    }

    #[test]
    fn quantize_is_the_formula_at_every_edge() {
        // sign(x) * floor(|x| * 256 + 0.5), in range or None, in f64 alone.
        fn formula(x: f64) -> Option<i16> {
            let abs = if x < 0.0 { -x } else { x };
            let m = libm_floor(abs * Q_ONE + 0.5);
            let v = if x < 0.0 { -m } else { m };
            (x.is_finite() && (-32768.0..=32767.0).contains(&v)).then_some(v as i16)
        }
        // floor without std: values here are below 2^53 or not finite.
        fn libm_floor(t: f64) -> f64 {
            if t.is_finite() && t < 9.0e15 {
                (t as u64) as f64
            } else {
                t
            }
        }
        let xs = [
            0.0,
            -0.0,
            1e-300,
            -1e-300,
            127.996,
            127.998,
            127.999,
            128.0,
            -128.0,
            -128.001,
            -128.002,
            -128.0019,
            1e19,
            -1e19,
            1e300,
            -1e300,
            f64::MAX,
            f64::MIN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
        ];
        for x in xs {
            assert_eq!(quantize(x), formula(x), "x = {x:e}");
        }
        // Every half step near the ends and zero, and the values next to them.
        for k in [
            -65538i64, -65537, -65536, -65535, -3, -1, 1, 3, 65533, 65535, 65537,
        ] {
            let x = k as f64 / 512.0;
            for (d, v) in [
                x,
                f64::from_bits(x.to_bits() + 1),
                f64::from_bits(x.to_bits() - 1),
            ]
            .into_iter()
            .enumerate()
            {
                assert_eq!(quantize(v), formula(v), "x = {v:e} (half step {k}, {d})");
            }
        }
    }

    #[test]
    fn label_slots_little_end_first() {
        let beat = 0x0004_0003_0002_0001u64;
        for s in 0..4 {
            assert_eq!(label_of_beat(beat, s), s as u32 + 1);
        }
    }
}
