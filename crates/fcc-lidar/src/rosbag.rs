//! ROS 2 recordings: `sensor_msgs/msg/PointCloud2` messages (CDR) in MCAP
//! files, read with the `mcap` crate (chunks compressed with zstd or lz4
//! included), streamed from the file.
//!
//! An organised cloud (height > 1) is a range image as it stands: rows are
//! its rows, flipped when its first row is its lowest beam, so that row 0 is
//! the top beam; columns are its columns. An unorganised cloud (height 1) is
//! a point list, projected like a `.bin` scan. Fields used: `x`, `y`, `z`
//! (float32 or float64, required) and `intensity` (any numeric type) when
//! present. The CDR decoding of PointCloud2 is this module's own: no crate
//! does it.

use crate::error::{LidarError, Result};
use crate::RangeImage;
use std::collections::BTreeMap;
use std::path::Path;

/// The schema name of the messages this module reads.
pub const POINTCLOUD2: &str = "sensor_msgs/msg/PointCloud2";

/// One PointCloud2 message.
#[derive(Debug, Clone, PartialEq)]
pub struct Cloud2 {
    pub frame_id: String,
    pub stamp_sec: i32,
    pub stamp_nanosec: u32,
    pub height: usize,
    pub width: usize,
    /// `height * width` points in row-major order; NaN where the cloud has
    /// no return (or a non-finite coordinate).
    pub points: Vec<[f32; 3]>,
    pub intensity: Option<Vec<f32>>,
}

impl Cloud2 {
    /// The cloud as a range image (organised clouds only), row 0 the top
    /// beam, with its intensity per pixel.
    pub fn range_image(&self) -> Result<Option<(RangeImage, Option<Vec<f32>>)>> {
        if self.height <= 1 {
            return Ok(None);
        }
        let (h, w) = (self.height, self.width);
        // Mean elevation of a row's returns.
        let elevation = |r: usize| {
            let (mut s, mut n) = (0.0f64, 0usize);
            for p in &self.points[r * w..(r + 1) * w] {
                if p.iter().all(|v| v.is_finite()) {
                    let hz = f64::from(p[0]).hypot(f64::from(p[1]));
                    s += f64::from(p[2]).atan2(hz);
                    n += 1;
                }
            }
            (n > 0).then(|| s / n as f64)
        };
        let first = (0..h).find_map(elevation);
        let last = (0..h).rev().find_map(elevation);
        let flip = matches!((first, last), (Some(a), Some(b)) if a < b);
        let row_of = |r: usize| if flip { h - 1 - r } else { r };
        let mut image = RangeImage::empty(h, w);
        let mut intensity = self.intensity.as_ref().map(|_| vec![f32::NAN; h * w]);
        for r in 0..h {
            for c in 0..w {
                let p = self.points[r * w + c];
                let i = row_of(r) * w + c;
                if p.iter().all(|v| v.is_finite()) {
                    image.set(i, Some(p));
                    if let (Some(out), Some(src)) = (intensity.as_mut(), self.intensity.as_ref()) {
                        out[i] = src[r * w + c];
                    }
                }
            }
        }
        Ok(Some((image, intensity)))
    }

    /// The returns of the cloud (finite points) with their intensity.
    pub fn finite_points(&self) -> (Vec<[f32; 3]>, Option<Vec<f32>>) {
        let keep: Vec<usize> = (0..self.points.len())
            .filter(|&i| self.points[i].iter().all(|v| v.is_finite()))
            .collect();
        (
            keep.iter().map(|&i| self.points[i]).collect(),
            self.intensity
                .as_ref()
                .map(|v| keep.iter().map(|&i| v[i]).collect()),
        )
    }
}

/// A little CDR reader: alignment is counted from the end of the 4-byte
/// encapsulation header.
struct Cdr<'a> {
    buf: &'a [u8],
    pos: usize,
    big: bool,
}

impl<'a> Cdr<'a> {
    fn new(data: &'a [u8]) -> std::result::Result<Self, String> {
        if data.len() < 4 {
            return Err(format!("{} bytes hold no CDR header", data.len()));
        }
        let big = match (data[0], data[1]) {
            (0, 0) => true,
            (0, 1) => false,
            (a, b) => {
                return Err(format!(
                    "CDR representation {a:#04x} {b:#04x} is not plain CDR (00 00 or 00 01)"
                ))
            }
        };
        Ok(Cdr {
            buf: &data[4..],
            pos: 0,
            big,
        })
    }

    fn take(
        &mut self,
        n: usize,
        align: usize,
        what: &str,
    ) -> std::result::Result<&'a [u8], String> {
        let start = self.pos.div_ceil(align) * align;
        let end = start
            .checked_add(n)
            .filter(|&e| e <= self.buf.len())
            .ok_or_else(|| {
                format!(
                    "message ends in {what} (needs {n} bytes at offset {start} of {})",
                    self.buf.len()
                )
            })?;
        self.pos = end;
        Ok(&self.buf[start..end])
    }

    fn u8(&mut self, what: &str) -> std::result::Result<u8, String> {
        Ok(self.take(1, 1, what)?[0])
    }

    fn u32(&mut self, what: &str) -> std::result::Result<u32, String> {
        let b: [u8; 4] = self
            .take(4, 4, what)?
            .try_into()
            .map_err(|_| what.to_string())?;
        Ok(if self.big {
            u32::from_be_bytes(b)
        } else {
            u32::from_le_bytes(b)
        })
    }

    fn string(&mut self, what: &str) -> std::result::Result<String, String> {
        let n = self.u32(what)? as usize;
        let b = self.take(n, 1, what)?;
        let b = b.strip_suffix(&[0]).unwrap_or(b);
        String::from_utf8(b.to_vec()).map_err(|_| format!("{what} is not UTF-8"))
    }
}

/// A field of a PointCloud2.
#[derive(Debug, Clone, PartialEq)]
struct Field {
    name: String,
    offset: usize,
    datatype: u8,
}

/// Bytes of a PointField datatype (INT8 = 1 ... FLOAT64 = 8).
fn datatype_size(t: u8) -> Option<usize> {
    match t {
        1 | 2 => Some(1),
        3 | 4 => Some(2),
        5..=7 => Some(4),
        8 => Some(8),
        _ => None,
    }
}

fn read_value(b: &[u8], t: u8, big: bool) -> f64 {
    macro_rules! num {
        ($ty:ty, $n:expr) => {{
            let a: [u8; $n] = b[..$n].try_into().unwrap_or([0; $n]);
            f64::from(if big {
                <$ty>::from_be_bytes(a)
            } else {
                <$ty>::from_le_bytes(a)
            })
        }};
    }
    match t {
        1 => f64::from(b[0] as i8),
        2 => f64::from(b[0]),
        3 => num!(i16, 2),
        4 => num!(u16, 2),
        5 => num!(i32, 4),
        6 => num!(u32, 4),
        7 => num!(f32, 4),
        _ => num!(f64, 8),
    }
}

/// Most points a cloud may claim (guards against absurd headers).
const MAX_POINTS: usize = 1 << 24;

/// Decode one CDR-serialised PointCloud2; the error says what is wrong.
pub fn decode_pointcloud2(data: &[u8]) -> std::result::Result<Cloud2, String> {
    let mut r = Cdr::new(data)?;
    let sec = r.u32("header.stamp.sec")? as i32;
    let nanosec = r.u32("header.stamp.nanosec")?;
    let frame_id = r.string("header.frame_id")?;
    let height = r.u32("height")? as usize;
    let width = r.u32("width")? as usize;
    let nfields = r.u32("fields")? as usize;
    if nfields > 1024 {
        return Err(format!("{nfields} fields is not a point cloud"));
    }
    let mut fields = Vec::with_capacity(nfields);
    for i in 0..nfields {
        let name = r.string(&format!("fields[{i}].name"))?;
        let offset = r.u32(&format!("fields[{i}].offset"))? as usize;
        let datatype = r.u8(&format!("fields[{i}].datatype"))?;
        let _count = r.u32(&format!("fields[{i}].count"))?;
        fields.push(Field {
            name,
            offset,
            datatype,
        });
    }
    let big = r.u8("is_bigendian")? != 0;
    let step = r.u32("point_step")? as usize;
    let row_step = r.u32("row_step")? as usize;
    let n = r.u32("data")? as usize;
    let bytes = r.take(n, 1, "data")?;
    let points = height
        .checked_mul(width)
        .filter(|&p| p <= MAX_POINTS)
        .ok_or_else(|| format!("{height} x {width} points is beyond {MAX_POINTS}"))?;
    if height > 0
        && (row_step < width * step || bytes.len() < (height - 1) * row_step + width * step)
    {
        return Err(format!(
            "{height} x {width} points of {step} bytes (rows of {row_step}) need more than the {} bytes of data",
            bytes.len()
        ));
    }
    let find = |names: &[&str]| fields.iter().find(|f| names.contains(&f.name.as_str()));
    let mut coord = Vec::with_capacity(3);
    for axis in ["x", "y", "z"] {
        let f = find(&[axis]).ok_or_else(|| {
            let names: Vec<&str> = fields.iter().map(|f| f.name.as_str()).collect();
            format!("no field `{axis}` (fields: {})", names.join(", "))
        })?;
        if f.datatype != 7 && f.datatype != 8 {
            return Err(format!(
                "field `{axis}` has datatype {}; x, y, z must be float32 (7) or float64 (8)",
                f.datatype
            ));
        }
        coord.push(f.clone());
    }
    let inten = find(&["intensity", "reflectivity", "i"]).cloned();
    for f in coord.iter().chain(inten.iter()) {
        let size = datatype_size(f.datatype)
            .ok_or_else(|| format!("field `{}` has unknown datatype {}", f.name, f.datatype))?;
        if f.offset + size > step {
            return Err(format!(
                "field `{}` at offset {} does not fit a point of {step} bytes",
                f.name, f.offset
            ));
        }
    }
    let mut pts = Vec::with_capacity(points);
    let mut intensity = inten.as_ref().map(|_| Vec::with_capacity(points));
    for row in 0..height {
        for col in 0..width {
            let p = &bytes[row * row_step + col * step..][..step];
            let v = |f: &Field| read_value(&p[f.offset..], f.datatype, big);
            let xyz = [
                v(&coord[0]) as f32,
                v(&coord[1]) as f32,
                v(&coord[2]) as f32,
            ];
            pts.push(if xyz.iter().all(|c| c.is_finite()) {
                xyz
            } else {
                [f32::NAN; 3]
            });
            if let (Some(out), Some(f)) = (intensity.as_mut(), inten.as_ref()) {
                out.push(v(f) as f32);
            }
        }
    }
    Ok(Cloud2 {
        frame_id,
        stamp_sec: sec,
        stamp_nanosec: nanosec,
        height,
        width,
        points: pts,
        intensity,
    })
}

/// What was met in a recording.
#[derive(Debug, Clone, Default, serde::Serialize)]
pub struct McapStats {
    /// Messages per topic, with the topic's schema name.
    pub topics: BTreeMap<String, (String, u64)>,
    /// PointCloud2 messages of the chosen topic decoded.
    pub clouds: u64,
    /// PointCloud2 messages of the chosen topic that did not decode, and
    /// the first reason.
    pub malformed: u64,
    pub first_problem: Option<String>,
    /// The file ended or broke after some messages (read up to there).
    pub cut_short: Option<String>,
}

/// Longest record (message, chunk) read: a length beyond this in a file is
/// taken as corruption rather than allocated.
const MAX_RECORD: usize = 256 << 20;

/// A channel of a recording: topic, schema name, message encoding.
#[derive(Debug, Clone)]
struct ChannelInfo {
    topic: String,
    schema: String,
    encoding: String,
}

/// Stream the messages of a recording through `f(channel, sequence, data)`
/// (which returns false to stop). Returns why the file broke off, if it did
/// after its first record; a file that is not MCAP at all is an error.
fn for_each_message(
    path: &Path,
    mut f: impl FnMut(&ChannelInfo, u32, &[u8]) -> Result<bool>,
) -> Result<Option<String>> {
    use mcap::records::Record;
    use mcap::sans_io::{LinearReadEvent, LinearReader, LinearReaderOptions};
    use std::io::Read;
    let mut file = std::fs::File::open(path).map_err(|e| LidarError::io(path, e))?;
    let mut reader = LinearReader::new_with_options(
        LinearReaderOptions::default()
            .with_record_length_limit(MAX_RECORD)
            .with_validate_chunk_crcs(true),
    );
    let mut schemas: BTreeMap<u16, String> = BTreeMap::new();
    let mut channels: BTreeMap<u16, ChannelInfo> = BTreeMap::new();
    let mut records = 0u64;
    while let Some(event) = reader.next_event() {
        let event = match event {
            Ok(e) => e,
            Err(e) => {
                if records == 0 {
                    return Err(LidarError::not_format(path, "MCAP", e.to_string()));
                }
                return Ok(Some(e.to_string()));
            }
        };
        match event {
            LinearReadEvent::ReadRequest(n) => {
                let buf = reader.insert(n.min(MAX_RECORD));
                let got = file.read(buf).map_err(|e| LidarError::io(path, e))?;
                reader.notify_read(got);
            }
            LinearReadEvent::Record { data, opcode } => {
                records += 1;
                let rec = match mcap::parse_record(opcode, data) {
                    Ok(r) => r,
                    Err(e) => return Ok(Some(e.to_string())),
                };
                match rec {
                    Record::Schema { header, .. } => {
                        schemas.insert(header.id, header.name);
                    }
                    Record::Channel(c) => {
                        let schema = schemas.get(&c.schema_id).cloned().unwrap_or_default();
                        channels.insert(
                            c.id,
                            ChannelInfo {
                                topic: c.topic,
                                schema,
                                encoding: c.message_encoding,
                            },
                        );
                    }
                    Record::Message { header, data } => {
                        let Some(ch) = channels.get(&header.channel_id) else {
                            return Ok(Some(format!(
                                "message of channel {} before the channel",
                                header.channel_id
                            )));
                        };
                        if !f(ch, header.sequence, &data)? {
                            return Ok(None);
                        }
                    }
                    _ => {}
                }
            }
        }
    }
    Ok(None)
}

/// Read the PointCloud2 messages of `topic` (or of the only PointCloud2
/// topic, when `topic` is `None`: the recording is then read twice) and
/// hand each, with its index among the topic's messages, to `f`. A
/// recording cut short gives the clouds before the cut.
pub fn read_pointclouds(
    path: &Path,
    topic: Option<&str>,
    mut f: impl FnMut(usize, Cloud2) -> Result<()>,
) -> Result<McapStats> {
    let mut stats = McapStats::default();
    let chosen = match topic {
        Some(t) => t.to_string(),
        None => {
            let mut clouds: BTreeMap<String, u64> = BTreeMap::new();
            let mut all: BTreeMap<String, String> = BTreeMap::new();
            for_each_message(path, |ch, _, _| {
                if ch.schema == POINTCLOUD2 {
                    *clouds.entry(ch.topic.clone()).or_insert(0) += 1;
                }
                all.insert(ch.topic.clone(), ch.schema.clone());
                Ok(true)
            })?;
            match clouds.len() {
                1 => clouds.into_keys().next().unwrap_or_default(),
                0 => {
                    let list: Vec<String> = all.iter().map(|(t, s)| format!("{t} ({s})")).collect();
                    return Err(LidarError::malformed(
                        path,
                        format!(
                            "no {POINTCLOUD2} messages (topics: {})",
                            if list.is_empty() {
                                "none".into()
                            } else {
                                list.join(", ")
                            }
                        ),
                    ));
                }
                _ => {
                    let list: Vec<String> = clouds
                        .iter()
                        .map(|(t, n)| format!("{t} ({n} messages)"))
                        .collect();
                    return Err(LidarError::Config(format!(
                        "{}: several PointCloud2 topics: choose one with --topic ({})",
                        path.display(),
                        list.join(", ")
                    )));
                }
            }
        }
    };
    let mut index = 0;
    let cut = for_each_message(path, |ch, sequence, data| {
        let e = stats
            .topics
            .entry(ch.topic.clone())
            .or_insert((ch.schema.clone(), 0));
        e.1 += 1;
        if ch.topic != chosen {
            return Ok(true);
        }
        if ch.schema != POINTCLOUD2 || ch.encoding != "cdr" {
            return Err(LidarError::malformed(
                path,
                format!(
                    "topic {chosen} carries {} messages in {} encoding, not {POINTCLOUD2} in cdr",
                    if ch.schema.is_empty() {
                        "schemaless"
                    } else {
                        &ch.schema
                    },
                    ch.encoding
                ),
            ));
        }
        match decode_pointcloud2(data) {
            Ok(c) => {
                stats.clouds += 1;
                f(index, c)?;
            }
            Err(why) => {
                stats.malformed += 1;
                if stats.first_problem.is_none() {
                    stats.first_problem =
                        Some(format!("message {index} (sequence {sequence}): {why}"));
                }
            }
        }
        index += 1;
        Ok(true)
    })?;
    stats.cut_short = cut;
    if stats.clouds == 0 {
        let mut why = if stats.topics.contains_key(&chosen) {
            format!("no message of topic {chosen} decoded")
        } else {
            let list: Vec<String> = stats
                .topics
                .iter()
                .map(|(t, (s, _))| format!("{t} ({s})"))
                .collect();
            format!("no topic {chosen} (topics: {})", list.join(", "))
        };
        if let Some(p) = &stats.first_problem {
            why.push_str(&format!(": {} malformed, first {p}", stats.malformed));
        }
        if let Some(c) = &stats.cut_short {
            why.push_str(&format!("; the file breaks off: {c}"));
        }
        return Err(LidarError::malformed(path, why));
    }
    Ok(stats)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A little-endian CDR PointCloud2 with float32 x, y, z and a uint16 intensity.
    fn message(h: u32, w: u32, pts: &[[f32; 3]]) -> Vec<u8> {
        let mut b = vec![0, 1, 0, 0];
        let mut body: Vec<u8> = Vec::new();
        let align = |body: &mut Vec<u8>, a: usize| {
            while body.len() % a != 0 {
                body.push(0);
            }
        };
        let u32_ = |body: &mut Vec<u8>, v: u32| {
            while body.len() % 4 != 0 {
                body.push(0);
            }
            body.extend_from_slice(&v.to_le_bytes());
        };
        let string = |body: &mut Vec<u8>, s: &str| {
            while body.len() % 4 != 0 {
                body.push(0);
            }
            body.extend_from_slice(&(s.len() as u32 + 1).to_le_bytes());
            body.extend_from_slice(s.as_bytes());
            body.push(0);
        };
        u32_(&mut body, 7);
        u32_(&mut body, 9);
        string(&mut body, "lidar");
        u32_(&mut body, h);
        u32_(&mut body, w);
        u32_(&mut body, 4);
        for (name, off, ty) in [
            ("x", 0, 7u8),
            ("y", 4, 7),
            ("z", 8, 7),
            ("intensity", 12, 4),
        ] {
            string(&mut body, name);
            u32_(&mut body, off);
            body.push(ty);
            u32_(&mut body, 1);
        }
        body.push(0);
        u32_(&mut body, 14);
        u32_(&mut body, 14 * w);
        u32_(&mut body, 14 * pts.len() as u32);
        for (k, p) in pts.iter().enumerate() {
            for v in p {
                body.extend_from_slice(&v.to_le_bytes());
            }
            body.extend_from_slice(&(k as u16).to_le_bytes());
        }
        body.push(1);
        align(&mut body, 1);
        b.extend_from_slice(&body);
        b
    }

    #[test]
    fn decodes_fields_and_flips_bottom_first_rows() {
        // 2 x 2, row 0 the lower beam.
        let pts = [
            [10.0, 0.0, -1.0],
            [10.0, 1.0, -1.0],
            [10.0, 0.0, 1.0],
            [f32::NAN, 0.0, 0.0],
        ];
        let c = decode_pointcloud2(&message(2, 2, &pts)).unwrap();
        assert_eq!(
            (c.frame_id.as_str(), c.stamp_sec, c.stamp_nanosec),
            ("lidar", 7, 9)
        );
        assert_eq!(c.intensity, Some(vec![0.0, 1.0, 2.0, 3.0]));
        let (img, inten) = c.range_image().unwrap().unwrap();
        assert_eq!(img.at(0, 0), Some([10.0, 0.0, 1.0]));
        assert_eq!(img.at(0, 1), None);
        assert_eq!(img.at(1, 1), Some([10.0, 1.0, -1.0]));
        assert_eq!(inten.unwrap()[0], 2.0);
        let one_row = decode_pointcloud2(&message(1, 4, &pts)).unwrap();
        assert!(one_row.range_image().unwrap().is_none());
        assert_eq!(one_row.finite_points().0.len(), 3);
    }

    #[test]
    fn broken_messages_say_what_is_wrong() {
        let pts = [[1.0, 2.0, 3.0]; 4];
        let m = message(2, 2, &pts);
        let err = decode_pointcloud2(&m[..m.len() - 20]).unwrap_err();
        assert!(
            err.contains("need more than") || err.contains("message ends in data"),
            "{err}"
        );
        let err = decode_pointcloud2(&m[..30]).unwrap_err();
        assert!(err.contains("message ends in"), "{err}");
        let mut bad = m.clone();
        bad[1] = 7;
        assert!(decode_pointcloud2(&bad)
            .unwrap_err()
            .contains("not plain CDR"));
        assert!(decode_pointcloud2(&[0, 1])
            .unwrap_err()
            .contains("no CDR header"));
    }
}
