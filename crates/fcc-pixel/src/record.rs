//! The record beats (spec §9.4): a cluster's record as the column-streaming
//! core sends it, [`RECORD_WORDS`] 64-bit beats per record, each field in one
//! beat at the place [`RECORD_LAYOUT`] gives it, bits outside the fields
//! zero. The widths hold every value of the largest hardware frame (128 rows,
//! 4096 columns, 2^19 points of 16-bit coordinates; the golden model's test
//! `record_beats` packs such a record).

use core::fmt;

/// Beats (64-bit words) of one record.
pub const RECORD_WORDS: usize = 11;

/// One field of a record.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RecordField {
    Id,
    Points,
    FirstRow,
    LastRow,
    Seam,
    FirstCol,
    LastCol,
    ClosedCol,
    Min(usize),
    Max(usize),
    Range2Min,
    Range2Max,
    Sum(usize),
    SumXx,
    SumXy,
    SumYy,
}

/// Where a field lies: beat `word`, bits `lsb .. lsb + bits`, two's
/// complement when `signed`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FieldLayout {
    pub field: RecordField,
    /// The field's name (spec §9.4).
    pub name: &'static str,
    pub word: usize,
    pub lsb: u32,
    pub bits: u32,
    pub signed: bool,
}

const fn f(
    field: RecordField,
    name: &'static str,
    word: usize,
    lsb: u32,
    bits: u32,
    signed: bool,
) -> FieldLayout {
    FieldLayout {
        field,
        name,
        word,
        lsb,
        bits,
        signed,
    }
}

/// Every field of a record, beat by beat, from bit 0 up.
pub const RECORD_LAYOUT: [FieldLayout; 22] = [
    f(RecordField::Id, "id", 0, 0, 20, false),
    f(RecordField::Points, "points", 0, 20, 20, false),
    f(RecordField::FirstRow, "first_row", 0, 40, 7, false),
    f(RecordField::LastRow, "last_row", 0, 47, 7, false),
    f(RecordField::Seam, "seam", 0, 54, 1, false),
    f(RecordField::FirstCol, "first_col", 1, 0, 13, false),
    f(RecordField::LastCol, "last_col", 1, 13, 13, false),
    f(RecordField::ClosedCol, "closed_col", 1, 26, 13, false),
    f(RecordField::Min(0), "min_x", 2, 0, 16, true),
    f(RecordField::Min(1), "min_y", 2, 16, 16, true),
    f(RecordField::Min(2), "min_z", 2, 32, 16, true),
    f(RecordField::Max(0), "max_x", 3, 0, 16, true),
    f(RecordField::Max(1), "max_y", 3, 16, 16, true),
    f(RecordField::Max(2), "max_z", 3, 32, 16, true),
    f(RecordField::Range2Min, "range2_min", 4, 0, 32, false),
    f(RecordField::Range2Max, "range2_max", 4, 32, 32, false),
    f(RecordField::Sum(0), "sum_x", 5, 0, 35, true),
    f(RecordField::Sum(1), "sum_y", 6, 0, 35, true),
    f(RecordField::Sum(2), "sum_z", 7, 0, 35, true),
    f(RecordField::SumXx, "sum_xx", 8, 0, 50, false),
    f(RecordField::SumXy, "sum_xy", 9, 0, 51, true),
    f(RecordField::SumYy, "sum_yy", 10, 0, 50, false),
];

/// The hardware part of a record (spec §9.3 without the frame number), in
/// the golden record's types.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct HwRecord {
    pub id: u32,
    pub points: u32,
    pub first_col: u32,
    pub last_col: u32,
    pub closed_col: u32,
    pub seam: bool,
    pub first_row: u32,
    pub last_row: u32,
    pub min: [i16; 3],
    pub max: [i16; 3],
    pub range2_min: u64,
    pub range2_max: u64,
    pub sum: [i64; 3],
    pub sum_xx: i64,
    pub sum_xy: i64,
    pub sum_yy: i64,
}

/// A record that has no beats, or beats that are no record.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RecordError {
    /// A value outside its field's range.
    DoesNotFit { field: &'static str, value: i128 },
    /// Bits set outside every field of beat `word`.
    SpareBits { word: usize, bits: u64 },
}

impl fmt::Display for RecordError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            RecordError::DoesNotFit { field, value } => {
                write!(f, "record field {field} = {value} does not fit its bits")
            }
            RecordError::SpareBits { word, bits } => {
                write!(
                    f,
                    "record beat {word} has bits {bits:#x} outside its fields"
                )
            }
        }
    }
}

/// The bits `0 .. bits` set.
const fn mask(bits: u32) -> u64 {
    if bits == 64 {
        u64::MAX
    } else {
        (1 << bits) - 1
    }
}

impl HwRecord {
    fn value(&self, field: RecordField) -> i128 {
        match field {
            RecordField::Id => self.id.into(),
            RecordField::Points => self.points.into(),
            RecordField::FirstRow => self.first_row.into(),
            RecordField::LastRow => self.last_row.into(),
            RecordField::Seam => i128::from(self.seam),
            RecordField::FirstCol => self.first_col.into(),
            RecordField::LastCol => self.last_col.into(),
            RecordField::ClosedCol => self.closed_col.into(),
            RecordField::Min(a) => self.min[a].into(),
            RecordField::Max(a) => self.max[a].into(),
            RecordField::Range2Min => self.range2_min.into(),
            RecordField::Range2Max => self.range2_max.into(),
            RecordField::Sum(a) => self.sum[a].into(),
            RecordField::SumXx => self.sum_xx.into(),
            RecordField::SumXy => self.sum_xy.into(),
            RecordField::SumYy => self.sum_yy.into(),
        }
    }

    /// Set `field` to `v`, which its width bounds (so every cast is exact).
    fn set(&mut self, field: RecordField, v: i128) {
        match field {
            RecordField::Id => self.id = v as u32,
            RecordField::Points => self.points = v as u32,
            RecordField::FirstRow => self.first_row = v as u32,
            RecordField::LastRow => self.last_row = v as u32,
            RecordField::Seam => self.seam = v != 0,
            RecordField::FirstCol => self.first_col = v as u32,
            RecordField::LastCol => self.last_col = v as u32,
            RecordField::ClosedCol => self.closed_col = v as u32,
            RecordField::Min(a) => self.min[a] = v as i16,
            RecordField::Max(a) => self.max[a] = v as i16,
            RecordField::Range2Min => self.range2_min = v as u64,
            RecordField::Range2Max => self.range2_max = v as u64,
            RecordField::Sum(a) => self.sum[a] = v as i64,
            RecordField::SumXx => self.sum_xx = v as i64,
            RecordField::SumXy => self.sum_xy = v as i64,
            RecordField::SumYy => self.sum_yy = v as i64,
        }
    }

    /// The record's beats, or the first field whose value does not fit.
    pub fn pack(&self) -> Result<[u64; RECORD_WORDS], RecordError> {
        let mut words = [0u64; RECORD_WORDS];
        for l in &RECORD_LAYOUT {
            let v = self.value(l.field);
            let (lo, hi) = if l.signed {
                (-(1i128 << (l.bits - 1)), 1i128 << (l.bits - 1))
            } else {
                (0, 1i128 << l.bits)
            };
            if v < lo || v >= hi {
                return Err(RecordError::DoesNotFit {
                    field: l.name,
                    value: v,
                });
            }
            // Two's complement: the low bits of v.
            words[l.word] |= ((v as u64) & mask(l.bits)) << l.lsb;
        }
        Ok(words)
    }

    /// The record of `words`, or the first beat with bits outside its fields.
    pub fn unpack(words: &[u64; RECORD_WORDS]) -> Result<HwRecord, RecordError> {
        let mut used = [0u64; RECORD_WORDS];
        let mut r = HwRecord::default();
        for l in &RECORD_LAYOUT {
            let raw = (words[l.word] >> l.lsb) & mask(l.bits);
            used[l.word] |= mask(l.bits) << l.lsb;
            let v = if l.signed && raw >> (l.bits - 1) != 0 {
                i128::from(raw) - (1i128 << l.bits)
            } else {
                i128::from(raw)
            };
            r.set(l.field, v);
        }
        for (word, (w, u)) in words.iter().zip(used).enumerate() {
            if w & !u != 0 {
                return Err(RecordError::SpareBits { word, bits: w & !u });
            }
        }
        Ok(r)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fields_lie_apart_inside_their_beats() {
        let mut used = [0u64; RECORD_WORDS];
        for l in &RECORD_LAYOUT {
            assert!(
                l.bits >= 1 && l.lsb + l.bits <= 64,
                "{} leaves its beat",
                l.name
            );
            let m = mask(l.bits) << l.lsb;
            assert_eq!(used[l.word] & m, 0, "{} overlaps another field", l.name);
            used[l.word] |= m;
        }
        assert!(used.iter().all(|&u| u != 0), "a beat without a field");
    }

    #[test]
    fn out_of_range_values_and_spare_bits_are_errors() {
        let r = HwRecord {
            first_row: 128,
            ..HwRecord::default()
        };
        assert_eq!(
            r.pack(),
            Err(RecordError::DoesNotFit {
                field: "first_row",
                value: 128
            })
        );
        let neg = HwRecord {
            sum_xx: -1,
            ..HwRecord::default()
        };
        assert!(matches!(
            neg.pack(),
            Err(RecordError::DoesNotFit {
                field: "sum_xx",
                ..
            })
        ));
        let mut words = HwRecord::default().pack().unwrap();
        words[1] |= 1 << 40;
        assert_eq!(
            HwRecord::unpack(&words),
            Err(RecordError::SpareBits {
                word: 1,
                bits: 1 << 40
            })
        );
    }

    #[test]
    fn signed_fields_round_trip_at_both_ends() {
        let r = HwRecord {
            min: [-1, i16::MIN, 0],
            max: [1, i16::MAX, -2],
            sum: [-(1 << 34), (1 << 34) - 1, -1],
            sum_xy: -(1 << 50),
            ..HwRecord::default()
        };
        let words = r.pack().unwrap();
        assert_eq!(words[2], 0x0000_0000_8000_ffff);
        assert_eq!(HwRecord::unpack(&words), Ok(r));
    }
}
