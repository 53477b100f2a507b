//! The record beats (spec §9.4): a cluster's record as the column-streaming
//! core sends it, [`RECORD_WORDS`] 64-bit beats per record, each field in one
//! beat at the place [`RECORD_LAYOUT`] gives it, bits outside the fields
//! zero. The widths hold every value of the largest hardware frame (128 rows,
//! 4096 columns, 2^19 points of 16-bit coordinates; the golden model's test
//! `record_beats` packs such a record). After a frame's last record comes
//! its end beat ([`FrameEnd`], `tlast` high); [`RecordReader`] reads such a
//! stream back and refuses one that is not.

use core::fmt;

/// Beats (64-bit words) of one record.
pub const RECORD_WORDS: usize = 11;

/// The most beats one frame's record stream can take: a record per pixel
/// (every pixel a cluster) and the end beat. What a buffer for a frame's
/// records must hold (the block design's S2MM length, the driver's buffer).
pub const fn frame_beats_max(pixels: usize) -> usize {
    pixels * RECORD_WORDS + 1
}

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

/// One field of the end beat.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EndField {
    Id,
    Records,
    Overflow,
    FrameError,
}

/// Where an end-beat field lies: bits `lsb .. lsb + bits`, unsigned.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct EndFieldLayout {
    pub field: EndField,
    /// The field's name (spec §9.4).
    pub name: &'static str,
    pub lsb: u32,
    pub bits: u32,
}

const fn e(field: EndField, name: &'static str, lsb: u32, bits: u32) -> EndFieldLayout {
    EndFieldLayout {
        field,
        name,
        lsb,
        bits,
    }
}

/// The end beat's fields, from bit 0 up (spec §9.4). Its `id` is 0, which
/// no record has.
pub const END_LAYOUT: [EndFieldLayout; 4] = [
    e(EndField::Id, "id", 0, 20),
    e(EndField::Records, "records", 20, 20),
    e(EndField::Overflow, "overflow", 40, 1),
    e(EndField::FrameError, "frame_error", 41, 1),
];

/// The end beat of a frame (spec §9.4): what follows its last record, with
/// `tlast`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct FrameEnd {
    /// Records of the frame (their ids are `1 ..= records`).
    pub records: u32,
    /// A run of the frame was refused a label (labels or the open limit).
    pub overflow: bool,
    /// The frame's input `tlast` came early or late.
    pub frame_error: bool,
}

impl FrameEnd {
    fn value(&self, field: EndField) -> u64 {
        match field {
            EndField::Id => 0,
            EndField::Records => self.records.into(),
            EndField::Overflow => self.overflow.into(),
            EndField::FrameError => self.frame_error.into(),
        }
    }

    /// The end beat, or `DoesNotFit` for a count of records beyond its bits.
    pub fn pack(&self) -> Result<u64, RecordError> {
        let mut w = 0;
        for l in &END_LAYOUT {
            let v = self.value(l.field);
            if v > mask(l.bits) {
                return Err(RecordError::DoesNotFit {
                    field: l.name,
                    value: v.into(),
                });
            }
            w |= v << l.lsb;
        }
        Ok(w)
    }

    /// Whether beat `w`, the first of a record or an end beat, is an end
    /// beat (its `id` field is 0).
    pub fn is_end(w: u64) -> bool {
        w & mask(END_LAYOUT[0].bits) == 0
    }

    /// The end beat `w`: `None` when its `id` is not 0 (a record's beat),
    /// `SpareBits` (beat 0) when bits outside its fields are set.
    pub fn unpack(w: u64) -> Result<Option<FrameEnd>, RecordError> {
        if !Self::is_end(w) {
            return Ok(None);
        }
        let mut used = 0;
        let mut end = FrameEnd::default();
        for l in &END_LAYOUT {
            let v = (w >> l.lsb) & mask(l.bits);
            used |= mask(l.bits) << l.lsb;
            match l.field {
                EndField::Id => {}
                EndField::Records => end.records = v as u32,
                EndField::Overflow => end.overflow = v != 0,
                EndField::FrameError => end.frame_error = v != 0,
            }
        }
        if w & !used != 0 {
            return Err(RecordError::SpareBits {
                word: 0,
                bits: w & !used,
            });
        }
        Ok(Some(end))
    }
}

/// What a [`RecordReader`] gives back: a record, or a frame's end.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Item {
    Record(HwRecord),
    End(FrameEnd),
}

/// Why a beat stream is no record stream (spec §9.4).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ReadError {
    /// A record or end beat with bad bits.
    Beat(RecordError),
    /// `tlast` on beat `word` of a record.
    LastInRecord { word: usize },
    /// An end beat without `tlast`.
    EndWithoutLast,
    /// A record whose id is not the next of its frame.
    IdOutOfOrder { expected: u32, got: u32 },
    /// An end beat whose count of records is not the number read.
    CountDiffers { said: u32, read: u32 },
    /// The stream ended after `words` beats of a record.
    EndsInRecord { words: usize },
    /// The stream ended after `records` records of a frame without its end
    /// beat.
    EndsInFrame { records: u32 },
}

impl fmt::Display for ReadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ReadError::Beat(e) => e.fmt(f),
            ReadError::LastInRecord { word } => {
                write!(
                    f,
                    "tlast on beat {word} of a record (only an end beat has it)"
                )
            }
            ReadError::EndWithoutLast => write!(f, "an end beat without tlast"),
            ReadError::IdOutOfOrder { expected, got } => {
                write!(f, "record id {got} where {expected} comes next")
            }
            ReadError::CountDiffers { said, read } => {
                write!(
                    f,
                    "the end beat counts {said} records, the frame had {read}"
                )
            }
            ReadError::EndsInRecord { words } => {
                write!(f, "the stream ends after {words} beats of a record")
            }
            ReadError::EndsInFrame { records } => write!(
                f,
                "the stream ends after {records} records of a frame, without its end beat"
            ),
        }
    }
}

/// Reads a stream of record beats (spec §9.4) one beat at a time: push
/// each beat with its `tlast`, take each record and each frame end as it
/// completes, and [`finish`](Self::finish) at the stream's end. After an
/// error the reader is of no further use.
#[derive(Clone, Debug, Default)]
pub struct RecordReader {
    words: [u64; RECORD_WORDS],
    /// Beats of the record being read.
    n: usize,
    /// Records of the frame being read.
    records: u32,
    frames: u64,
    beats: u64,
}

impl RecordReader {
    pub fn new() -> RecordReader {
        RecordReader::default()
    }

    /// Frames ended so far.
    pub fn frames(&self) -> u64 {
        self.frames
    }

    /// Beats pushed so far (the failing beat is `beats() - 1`).
    pub fn beats(&self) -> u64 {
        self.beats
    }

    /// Take one beat.
    pub fn push(&mut self, beat: u64, last: bool) -> Result<Option<Item>, ReadError> {
        self.beats += 1;
        if self.n == 0 {
            if let Some(end) = FrameEnd::unpack(beat).map_err(ReadError::Beat)? {
                if !last {
                    return Err(ReadError::EndWithoutLast);
                }
                if end.records != self.records {
                    return Err(ReadError::CountDiffers {
                        said: end.records,
                        read: self.records,
                    });
                }
                self.records = 0;
                self.frames += 1;
                return Ok(Some(Item::End(end)));
            }
        }
        if last {
            return Err(ReadError::LastInRecord { word: self.n });
        }
        self.words[self.n] = beat;
        self.n += 1;
        if self.n < RECORD_WORDS {
            return Ok(None);
        }
        self.n = 0;
        let r = HwRecord::unpack(&self.words).map_err(ReadError::Beat)?;
        let expected = self.records + 1;
        if r.id != expected {
            return Err(ReadError::IdOutOfOrder {
                expected,
                got: r.id,
            });
        }
        self.records = expected;
        Ok(Some(Item::Record(r)))
    }

    /// The stream ended: an error if it ends inside a record or a frame.
    pub fn finish(&self) -> Result<(), ReadError> {
        if self.n > 0 {
            Err(ReadError::EndsInRecord { words: self.n })
        } else if self.records > 0 {
            Err(ReadError::EndsInFrame {
                records: self.records,
            })
        } else {
            Ok(())
        }
    }
}

/// Append one frame's beats, `(beat, tlast)`: each record's, then the end
/// beat (spec §9.4). The records' ids must count `1, 2, ...`, which the
/// caller's reader checks.
pub fn frame_beats<'a>(
    records: impl IntoIterator<Item = &'a HwRecord>,
    end: FrameEnd,
    out: &mut impl Extend<(u64, bool)>,
) -> Result<(), RecordError> {
    for r in records {
        out.extend(r.pack()?.into_iter().map(|w| (w, false)));
    }
    out.extend(core::iter::once((end.pack()?, true)));
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn end_fields_lie_apart_inside_their_beat() {
        let mut used = 0u64;
        for l in &END_LAYOUT {
            assert!(
                l.bits >= 1 && l.lsb + l.bits <= 64,
                "{} leaves its beat",
                l.name
            );
            let m = mask(l.bits) << l.lsb;
            assert_eq!(used & m, 0, "{} overlaps another field", l.name);
            used |= m;
        }
        // The end beat's id is where a record's is.
        assert_eq!(
            (END_LAYOUT[0].lsb, END_LAYOUT[0].bits),
            (RECORD_LAYOUT[0].lsb, RECORD_LAYOUT[0].bits)
        );
        assert_eq!((END_LAYOUT[0].name, RECORD_LAYOUT[0].name), ("id", "id"));
    }

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

    struct Beats([(u64, bool); 64], usize);
    impl Extend<(u64, bool)> for Beats {
        fn extend<I: IntoIterator<Item = (u64, bool)>>(&mut self, it: I) {
            for b in it {
                self.0[self.1] = b;
                self.1 += 1;
            }
        }
    }

    fn rec(id: u32) -> HwRecord {
        HwRecord {
            id,
            points: id + 2,
            min: [-3, 4, -5],
            ..HwRecord::default()
        }
    }

    /// Two frames: records 1 and 2 then an end beat; an end beat alone.
    fn two_frames() -> Beats {
        let mut b = Beats([(0, false); 64], 0);
        let end = FrameEnd {
            records: 2,
            overflow: true,
            frame_error: false,
        };
        frame_beats(&[rec(1), rec(2)], end, &mut b).unwrap();
        frame_beats(&[], FrameEnd::default(), &mut b).unwrap();
        b
    }

    fn read(beats: &[(u64, bool)]) -> Result<(u32, u64), (u64, ReadError)> {
        let mut r = RecordReader::new();
        let mut records = 0;
        for &(w, last) in beats {
            match r.push(w, last) {
                Ok(Some(Item::Record(_))) => records += 1,
                Ok(_) => {}
                Err(e) => return Err((r.beats() - 1, e)),
            }
        }
        r.finish().map_err(|e| (r.beats(), e))?;
        Ok((records, r.frames()))
    }

    #[test]
    fn a_reader_takes_records_and_end_beats_back() {
        let b = two_frames();
        let beats = &b.0[..b.1];
        assert_eq!(beats.len(), 2 * RECORD_WORDS + 2);
        assert_eq!(beats[2 * RECORD_WORDS], (1 << 40 | 2 << 20, true));
        assert_eq!(beats[2 * RECORD_WORDS + 1], (0, true));
        let mut r = RecordReader::new();
        let mut items = [None; 4];
        let mut n = 0;
        for &(w, last) in beats {
            if let Some(i) = r.push(w, last).unwrap() {
                items[n] = Some(i);
                n += 1;
            }
        }
        assert_eq!(
            items,
            [
                Some(Item::Record(rec(1))),
                Some(Item::Record(rec(2))),
                Some(Item::End(FrameEnd {
                    records: 2,
                    overflow: true,
                    frame_error: false
                })),
                Some(Item::End(FrameEnd::default())),
            ]
        );
        assert_eq!(r.finish(), Ok(()));
        assert_eq!(read(beats), Ok((2, 2)));
    }

    #[test]
    fn a_reader_refuses_what_is_no_record_stream() {
        let b = two_frames();
        let good = &b.0[..b.1];
        let with = |k: usize, beat: (u64, bool)| {
            let mut v = Beats([(0, false); 64], 0);
            v.extend(good.iter().copied());
            v.0[k] = beat;
            read(&v.0[..v.1])
        };
        let end1 = 2 * RECORD_WORDS;
        // tlast on a record's beat 3.
        assert_eq!(
            with(3, (good[3].0, true)),
            Err((3, ReadError::LastInRecord { word: 3 }))
        );
        // The end beat without tlast.
        assert_eq!(
            with(end1, (good[end1].0, false)),
            Err((end1 as u64, ReadError::EndWithoutLast))
        );
        // The end beat counts 3 records.
        assert_eq!(
            with(end1, (3 << 20, true)),
            Err((end1 as u64, ReadError::CountDiffers { said: 3, read: 2 }))
        );
        // Spare bits in the end beat.
        assert_eq!(
            with(end1, (good[end1].0 | 1 << 50, true)),
            Err((
                end1 as u64,
                ReadError::Beat(RecordError::SpareBits {
                    word: 0,
                    bits: 1 << 50
                })
            ))
        );
        // The second record numbered 3.
        let w0 = good[RECORD_WORDS].0;
        let w3 = (w0 & !0xF_FFFF) | 3;
        assert_eq!(
            with(RECORD_WORDS, (w3, false)),
            Err((
                2 * RECORD_WORDS as u64 - 1,
                ReadError::IdOutOfOrder {
                    expected: 2,
                    got: 3
                }
            ))
        );
        // Ends inside a record, inside a frame.
        assert_eq!(
            read(&good[..RECORD_WORDS + 4]),
            Err((
                (RECORD_WORDS + 4) as u64,
                ReadError::EndsInRecord { words: 4 }
            ))
        );
        assert_eq!(
            read(&good[..RECORD_WORDS]),
            Err((RECORD_WORDS as u64, ReadError::EndsInFrame { records: 1 }))
        );
        // A count of records beyond 20 bits has no end beat.
        let big = FrameEnd {
            records: 1 << 20,
            ..FrameEnd::default()
        };
        assert!(matches!(
            big.pack(),
            Err(RecordError::DoesNotFit {
                field: "records",
                ..
            })
        ));
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
