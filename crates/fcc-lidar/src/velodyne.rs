//! Velodyne packet captures: VLP-16, VLP-32C, HDL-32E and HDL-64E (S2, S3)
//! data packets in pcap / pcapng, one range image per rotation.
//!
//! A data packet is a 1206-byte UDP payload: 12 blocks of 100 bytes (a
//! 2-byte flag, `0xEEFF` or for the HDL-64E's lower lasers `0xDDFF`, a
//! 2-byte azimuth in hundredths of a degree, then 32 returns of a 2-byte
//! distance and a 1-byte intensity, all little endian), a 4-byte timestamp
//! and two factory bytes (return mode and product id; on the HDL-64E a
//! status type and value). `docs/lidar.md` gives the layout of each model,
//! the geometry and the sources.
//!
//! Rows are the lasers ordered by elevation (row 0 the top beam); each
//! firing sequence owns a column, placed from its position in the rotation
//! with the projection's convention (column 0 looks backwards, `cols / 2`
//! forwards, clockwise seen from above), so a Velodyne range image lines
//! up with a projected point cloud and no two firing sequences of a
//! rotation share a column however the block azimuths were rounded.

use crate::error::{LidarError, Result};
use crate::pcap::{PcapReader, PcapStats};
use crate::RangeImage;
use std::collections::BTreeMap;
use std::fs::File;
use std::io::{BufReader, Read};
use std::path::{Path, PathBuf};

/// UDP payload of a data packet.
pub const DATA_PACKET: usize = 1206;
/// UDP payload of a position (GPS) packet.
pub const POSITION_PACKET: usize = 512;
/// Blocks in a data packet.
const BLOCKS: usize = 12;
const BLOCK_BYTES: usize = 100;
/// Flag of a block of the upper lasers (all lasers of the 16- and 32-laser models).
const FLAG_UPPER: u16 = 0xEEFF;
/// Flag of a block of the HDL-64E's lower 32 lasers.
const FLAG_LOWER: u16 = 0xDDFF;
/// Widest azimuth step between consecutive firings, in hundredths of a
/// degree, before a rotation counts as missing packets.
const MAX_GAP_CENTIDEG: f64 = 200.0;
/// Most columns a Velodyne range image may have.
const MAX_COLUMNS: usize = 1 << 14;

/// The sensor models this reader decodes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum VelodyneModel {
    Vlp16,
    Vlp32c,
    Hdl32e,
    Hdl64e,
}

/// Names accepted for the models, lower case, as in `--velodyne-model`.
pub const MODEL_NAMES: [&str; 4] = ["vlp16", "vlp32c", "hdl32e", "hdl64e"];

impl VelodyneModel {
    /// All models, in [`MODEL_NAMES`] order.
    pub const ALL: [VelodyneModel; 4] = [
        VelodyneModel::Vlp16,
        VelodyneModel::Vlp32c,
        VelodyneModel::Hdl32e,
        VelodyneModel::Hdl64e,
    ];

    /// The model of a name (`vlp16`, `VLP-16`, ...), case and dashes ignored.
    pub fn from_name(name: &str) -> Option<VelodyneModel> {
        let n: String = name
            .chars()
            .filter(|c| c.is_ascii_alphanumeric())
            .collect::<String>()
            .to_ascii_lowercase();
        MODEL_NAMES
            .iter()
            .position(|&m| m == n)
            .map(|i| VelodyneModel::ALL[i])
    }

    /// The name Velodyne uses.
    pub fn name(self) -> &'static str {
        match self {
            VelodyneModel::Vlp16 => "VLP-16",
            VelodyneModel::Vlp32c => "VLP-32C",
            VelodyneModel::Hdl32e => "HDL-32E",
            VelodyneModel::Hdl64e => "HDL-64E",
        }
    }

    /// Lasers of the model.
    pub fn lasers(self) -> usize {
        match self {
            VelodyneModel::Vlp16 => 16,
            VelodyneModel::Vlp32c | VelodyneModel::Hdl32e => 32,
            VelodyneModel::Hdl64e => 64,
        }
    }

    /// The product id byte (the last byte of a data packet), if the model has one.
    pub fn product_id(self) -> Option<u8> {
        match self {
            VelodyneModel::Hdl32e => Some(0x21),
            VelodyneModel::Vlp16 => Some(0x22),
            VelodyneModel::Vlp32c => Some(0x28),
            VelodyneModel::Hdl64e => None,
        }
    }

    /// The model of a product id byte.
    pub fn from_product_id(id: u8) -> Option<VelodyneModel> {
        VelodyneModel::ALL
            .into_iter()
            .find(|m| m.product_id() == Some(id))
    }

    /// Firing sequences per data block: two on the VLP-16 (16 lasers fired
    /// twice), one otherwise.
    fn sequences_per_block(self) -> usize {
        if self == VelodyneModel::Vlp16 {
            2
        } else {
            1
        }
    }

    /// Time of the firing of slot `k` of a sequence after its start, and the
    /// length of a sequence, in microseconds (the user manuals' timing
    /// tables).
    fn firing_time_us(self, k: usize) -> (f64, f64) {
        match self {
            VelodyneModel::Vlp16 => (2.304 * k as f64, 55.296),
            // Lasers fire in pairs.
            VelodyneModel::Vlp32c => (2.304 * (k / 2) as f64, 55.296),
            VelodyneModel::Hdl32e => (1.152 * k as f64, 46.08),
            // Four lasers of each bank fire every 6 µs, 1.26, 2.46 and 3.66 µs
            // apart, in a 48 µs period shared by an upper and a lower block
            // (S2; the S3's 7.2 and 57.6 µs give the same fractions of a
            // period within 0.4 %).
            VelodyneModel::Hdl64e => (6.0 * (k / 4) as f64 + [0.0, 1.26, 2.46, 3.66][k % 4], 48.0),
        }
    }

    /// Elevation and `rot_correction` in degrees and vertical offset in
    /// metres of each laser of the models
    /// whose geometry is the same for every unit (the user manuals); `None`
    /// for the HDL-64E, whose every unit has its own calibration.
    fn nominal(self) -> Option<Vec<(f64, f64, f64)>> {
        match self {
            VelodyneModel::Vlp16 => Some(
                (0..16)
                    .map(|i| {
                        let e = if i % 2 == 0 { -15 + i } else { i };
                        (f64::from(e), 0.0, VLP16_VERTICAL_MM[i as usize] / 1000.0)
                    })
                    .collect(),
            ),
            VelodyneModel::Hdl32e => Some(
                (0..32)
                    .map(|i: i32| {
                        // Even lasers from -30.67 deg, odd lasers from -9.33 deg, 4/3 deg
                        // apart; the manual gives them to 0.01 deg.
                        let thirds = if i % 2 == 0 { -92 } else { -28 } + 4 * (i / 2);
                        ((f64::from(thirds) / 3.0 * 100.0).round() / 100.0, 0.0, 0.0)
                    })
                    .collect(),
            ),
            VelodyneModel::Vlp32c => Some(VLP32C.iter().map(|&(e, off)| (e, -off, 0.0)).collect()),
            VelodyneModel::Hdl64e => None,
        }
    }
}

impl std::str::FromStr for VelodyneModel {
    type Err = String;
    fn from_str(s: &str) -> std::result::Result<Self, String> {
        VelodyneModel::from_name(s).ok_or_else(|| {
            format!(
                "unknown Velodyne model `{s}` (expected one of {})",
                MODEL_NAMES.join(", ")
            )
        })
    }
}

/// Beam elevations in degrees, top beam first, of a model by name
/// (`vlp16`, `vlp32c`, `hdl32e`, `hdl64e`; case and dashes ignored): the
/// `--beams` tables for projecting that sensor's point clouds. The HDL-64E
/// table is the manual's nominal layout (upper block +2 to -8.33 degrees in
/// steps of 1/3, lower block -8.83 to -24.33 degrees in steps of 1/2); each
/// unit's calibration differs from it by a fraction of a step.
pub fn beam_table(name: &str) -> Option<Vec<f64>> {
    let model = VelodyneModel::from_name(name)?;
    let mut e: Vec<f64> = match model.nominal() {
        Some(t) => t.into_iter().map(|(e, _, _)| e).collect(),
        None => (0..32)
            .map(|i| 2.0 - f64::from(i) * (10.33 / 31.0))
            .chain((0..32).map(|i| -8.83 - f64::from(i) * 0.5))
            .collect(),
    };
    e.sort_by(|a, b| b.total_cmp(a));
    Some(e)
}

/// VLP-16 vertical offsets of the laser origins, mm, laser 0 first (the
/// manual's laser table).
const VLP16_VERTICAL_MM: [f64; 16] = [
    11.2, -0.7, 9.7, -2.2, 8.1, -3.7, 6.6, -5.1, 5.1, -6.6, 3.7, -8.1, 2.2, -9.7, 0.7, -11.2,
];

/// VLP-32C laser elevation and azimuth offset, degrees, laser 0 first (the
/// manual's table: a laser points at the block azimuth plus its offset, so
/// its `rot_correction` is minus the offset).
const VLP32C: [(f64, f64); 32] = [
    (-25.0, 1.4),
    (-1.0, -4.2),
    (-1.667, 1.4),
    (-15.639, -1.4),
    (-11.31, 1.4),
    (0.0, -1.4),
    (-0.667, 4.2),
    (-8.843, -1.4),
    (-7.254, 1.4),
    (0.333, -4.2),
    (-0.333, 1.4),
    (-6.148, -1.4),
    (-5.333, 4.2),
    (1.333, -1.4),
    (0.667, 4.2),
    (-4.0, -1.4),
    (-4.667, 1.4),
    (1.667, -4.2),
    (1.0, 1.4),
    (-3.667, -4.2),
    (-3.333, 4.2),
    (3.333, -1.4),
    (2.333, 1.4),
    (-2.667, -1.4),
    (-3.0, 1.4),
    (7.0, -1.4),
    (4.667, 1.4),
    (-2.333, -4.2),
    (-2.0, 4.2),
    (15.0, -1.4),
    (10.333, 1.4),
    (-1.333, -1.4),
];

/// One laser's corrections, in the units of the ROS calibration files
/// (radians and metres): a return of corrected distance `r` fired at block
/// azimuth `a` points at azimuth `a - rot_correction`, elevation
/// `vert_correction`, from an origin shifted by the two offsets.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct LaserCorrection {
    pub rot_correction: f64,
    pub vert_correction: f64,
    pub dist_correction: f64,
    pub dist_correction_x: f64,
    pub dist_correction_y: f64,
    pub vert_offset_correction: f64,
    pub horiz_offset_correction: f64,
    /// Apply the two-point distance correction (HDL-64E).
    pub two_point: bool,
}

/// The geometry of one sensor.
#[derive(Debug, Clone, PartialEq)]
pub struct VelodyneCalibration {
    pub model: VelodyneModel,
    /// One per laser, laser 0 first.
    pub lasers: Vec<LaserCorrection>,
    /// Metres per distance count.
    pub distance_resolution_m: f64,
    /// Where it came from, for messages.
    pub source: String,
}

impl VelodyneCalibration {
    /// The published geometry of a model; the HDL-64E has none and needs
    /// its unit's calibration file.
    pub fn nominal(model: VelodyneModel) -> Result<VelodyneCalibration> {
        let Some(table) = model.nominal() else {
            return Err(LidarError::Config(format!(
                "an {} capture needs the unit's calibration file (the ROS driver's .yaml or Velodyne's db.xml): pass --velodyne-calibration FILE",
                model.name()
            )));
        };
        Ok(VelodyneCalibration {
            model,
            lasers: table
                .iter()
                .map(|&(elev, rot, vert_offset)| LaserCorrection {
                    rot_correction: rot.to_radians(),
                    vert_correction: elev.to_radians(),
                    vert_offset_correction: vert_offset,
                    ..LaserCorrection::default()
                })
                .collect(),
            distance_resolution_m: if model == VelodyneModel::Vlp32c {
                0.004
            } else {
                0.002
            },
            source: format!("the published {} geometry", model.name()),
        })
    }

    /// Beam elevations in degrees, top beam first: the rows of this
    /// sensor's range images, and a `--beams` table for projecting its
    /// point clouds.
    pub fn elevations_top_down(&self) -> Vec<f64> {
        let mut e: Vec<f64> = self
            .lasers
            .iter()
            .map(|l| l.vert_correction.to_degrees())
            .collect();
        e.sort_by(|a, b| b.total_cmp(a));
        e
    }

    /// Read a calibration file: the ROS driver's YAML (`lasers:` with
    /// `laser_id`, `rot_correction`, `vert_correction`, ... in radians and
    /// metres, block or flow style) or Velodyne's `db.xml` (`<px>` items
    /// with `rotCorrection_`, `vertCorrection_` in degrees and distances in
    /// centimetres). Lasers beyond the model's count are ignored; missing
    /// ones are an error.
    pub fn from_file(path: &Path, model: VelodyneModel) -> Result<VelodyneCalibration> {
        let text = std::fs::read_to_string(path).map_err(|e| LidarError::io(path, e))?;
        let (lasers, resolution) = if text.trim_start().starts_with('<') {
            parse_db_xml(path, &text)?
        } else {
            parse_ros_yaml(path, &text)?
        };
        let n = model.lasers();
        let mut out = vec![None; n];
        for (id, l) in lasers {
            if id < n {
                if out[id].is_some() {
                    return Err(LidarError::malformed(
                        path,
                        format!("laser {id} is given twice"),
                    ));
                }
                out[id] = Some(l);
            }
        }
        let missing: Vec<String> = (0..n)
            .filter(|&i| out[i].is_none())
            .map(|i| i.to_string())
            .collect();
        if !missing.is_empty() {
            return Err(LidarError::malformed(
                path,
                format!(
                    "no calibration for laser(s) {} of the {} lasers of an {}",
                    missing.join(", "),
                    n,
                    model.name()
                ),
            ));
        }
        let resolution = resolution.unwrap_or(if model == VelodyneModel::Vlp32c {
            0.004
        } else {
            0.002
        });
        if !(resolution.is_finite() && resolution > 0.0 && resolution < 1.0) {
            return Err(LidarError::malformed(
                path,
                format!("distance resolution {resolution} m is not a small positive number"),
            ));
        }
        Ok(VelodyneCalibration {
            model,
            lasers: out.into_iter().flatten().collect(),
            distance_resolution_m: resolution,
            source: path.display().to_string(),
        })
    }
}

/// Set a correction field by its ROS name; false for unknown names.
fn set_ros_field(l: &mut LaserCorrection, key: &str, v: f64) -> bool {
    match key {
        "rot_correction" => l.rot_correction = v,
        "vert_correction" => l.vert_correction = v,
        "dist_correction" => l.dist_correction = v,
        "dist_correction_x" => l.dist_correction_x = v,
        "dist_correction_y" => l.dist_correction_y = v,
        "vert_offset_correction" => l.vert_offset_correction = v,
        "horiz_offset_correction" => l.horiz_offset_correction = v,
        _ => return false,
    }
    true
}

type ParsedLasers = (Vec<(usize, LaserCorrection)>, Option<f64>);

/// The ROS driver's calibration YAML. Only the subset these files use is
/// read: top-level `key: value` lines, and a `lasers:` list whose items are
/// `key: value` maps in block or flow (`{k: v, ...}`) style.
fn parse_ros_yaml(path: &Path, text: &str) -> Result<ParsedLasers> {
    let mut items: Vec<(usize, String)> = Vec::new();
    let mut resolution = None;
    let mut in_item = false;
    for (n, raw) in text.lines().enumerate() {
        let line = raw.split('#').next().unwrap_or("");
        if line.trim().is_empty() {
            continue;
        }
        let indent = line.len() - line.trim_start().len();
        let t = line.trim();
        if let Some(rest) = t.strip_prefix('-') {
            items.push((n + 1, rest.to_string()));
            in_item = true;
        } else if indent > 0 && in_item {
            if let Some(last) = items.last_mut() {
                last.1.push(',');
                last.1.push_str(t);
            }
        } else {
            in_item = false;
            let Some((k, v)) = t.split_once(':') else {
                return Err(LidarError::not_format(
                    path,
                    "Velodyne calibration",
                    format!("line {}: `{t}` is not `key: value`", n + 1),
                ));
            };
            if k.trim() == "distance_resolution" {
                resolution = Some(v.trim().parse::<f64>().map_err(|_| {
                    LidarError::malformed(
                        path,
                        format!(
                            "line {}: distance_resolution `{}` is not a number",
                            n + 1,
                            v.trim()
                        ),
                    )
                })?);
            }
        }
    }
    if items.is_empty() {
        return Err(LidarError::not_format(
            path,
            "Velodyne calibration",
            "no `lasers:` list items (expected the ROS driver's YAML or Velodyne's db.xml)",
        ));
    }
    let mut lasers = Vec::with_capacity(items.len());
    for (line, body) in items {
        let mut l = LaserCorrection::default();
        let mut id = None;
        let mut two_point = None;
        for pair in body.split([',', '{', '}']) {
            let pair = pair.trim();
            if pair.is_empty() {
                continue;
            }
            let Some((k, v)) = pair.split_once(':') else {
                return Err(LidarError::malformed(
                    path,
                    format!("laser item at line {line}: `{pair}` is not `key: value`"),
                ));
            };
            let (k, v) = (k.trim(), v.trim());
            match k {
                "laser_id" => {
                    id = Some(v.parse::<usize>().map_err(|_| {
                        LidarError::malformed(
                            path,
                            format!(
                                "laser item at line {line}: laser_id `{v}` is not a laser number"
                            ),
                        )
                    })?)
                }
                "two_pt_correction_available" => two_point = Some(v == "true"),
                _ => {
                    let Ok(x) = v.parse::<f64>() else {
                        continue;
                    };
                    if !x.is_finite() {
                        return Err(LidarError::malformed(
                            path,
                            format!("laser item at line {line}: {k} is {v}"),
                        ));
                    }
                    set_ros_field(&mut l, k, x);
                }
            }
        }
        let Some(id) = id else {
            return Err(LidarError::malformed(
                path,
                format!("laser item at line {line} has no laser_id"),
            ));
        };
        l.two_point = two_point.unwrap_or(l.dist_correction_x != 0.0 || l.dist_correction_y != 0.0);
        lasers.push((id, l));
    }
    Ok((lasers, resolution))
}

/// The text between `<tag>` and `</tag>` at or after `from`, and the end of it.
fn xml_tag<'a>(text: &'a str, tag: &str, from: usize) -> Option<(&'a str, usize)> {
    let open = format!("<{tag}>");
    let close = format!("</{tag}>");
    let s = text[from..].find(&open)? + from + open.len();
    let e = text[s..].find(&close)? + s;
    Some((&text[s..e], e + close.len()))
}

/// Velodyne's `db.xml`: `<px>` items with `id_` and corrections in degrees
/// and centimetres, `distLSB_` in centimetres.
fn parse_db_xml(path: &Path, text: &str) -> Result<ParsedLasers> {
    let mut lasers = Vec::new();
    let mut at = 0;
    let num = |body: &str, tag: &str, id: &str| -> Result<Option<f64>> {
        match xml_tag(body, tag, 0) {
            None => Ok(None),
            Some((v, _)) => v
                .trim()
                .parse::<f64>()
                .ok()
                .filter(|x| x.is_finite())
                .map(Some)
                .ok_or_else(|| {
                    LidarError::malformed(
                        path,
                        format!("laser {id}: {tag} `{}` is not a number", v.trim()),
                    )
                }),
        }
    };
    while let Some((body, end)) = xml_tag(text, "px", at) {
        at = end;
        let id_text = xml_tag(body, "id_", 0).map(|(v, _)| v.trim()).unwrap_or("");
        let id: usize = id_text.parse().map_err(|_| {
            LidarError::malformed(
                path,
                format!("a <px> item has no laser number in <id_> (`{id_text}`)"),
            )
        })?;
        let deg = |tag| -> Result<f64> { Ok(num(body, tag, id_text)?.unwrap_or(0.0).to_radians()) };
        let cm = |tag| -> Result<f64> { Ok(num(body, tag, id_text)?.unwrap_or(0.0) / 100.0) };
        let l = LaserCorrection {
            rot_correction: deg("rotCorrection_")?,
            vert_correction: deg("vertCorrection_")?,
            dist_correction: cm("distCorrection_")?,
            dist_correction_x: cm("distCorrectionX_")?,
            dist_correction_y: cm("distCorrectionY_")?,
            vert_offset_correction: cm("vertOffsetCorrection_")?,
            horiz_offset_correction: cm("horizOffsetCorrection_")?,
            two_point: num(body, "distCorrectionX_", id_text)?.is_some(),
        };
        lasers.push((id, l));
    }
    if lasers.is_empty() {
        return Err(LidarError::not_format(
            path,
            "Velodyne calibration",
            "an XML file without <px> laser items (expected Velodyne's db.xml)",
        ));
    }
    let lsb = num(text, "distLSB_", "-")?.map(|cm| cm / 100.0);
    Ok((lasers, lsb))
}

/// Which return of a dual-return capture to use.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum DualReturn {
    /// The first block of each pair with the same azimuth (the last return
    /// on the VLP-16, VLP-32C and HDL-32E).
    #[default]
    First,
    /// The second (the strongest, or the second strongest when the
    /// strongest is also the last).
    Second,
}

impl std::str::FromStr for DualReturn {
    type Err = String;
    fn from_str(s: &str) -> std::result::Result<Self, String> {
        match s.to_ascii_lowercase().as_str() {
            "first" => Ok(DualReturn::First),
            "second" => Ok(DualReturn::Second),
            _ => Err(format!("unknown return `{s}` (expected first or second)")),
        }
    }
}

/// How to decode a capture.
#[derive(Debug, Clone, Default)]
pub struct VelodyneOptions {
    /// The sensor; `None` tells it from the packets (product id byte; the
    /// HDL-64E by its lower-block flags).
    pub model: Option<VelodyneModel>,
    /// Calibration file (required for the HDL-64E).
    pub calibration: Option<PathBuf>,
    /// Columns of the range image; `None` takes the firings per rotation
    /// of the first rotation.
    pub columns: Option<usize>,
    pub dual: DualReturn,
    /// Also give the partial rotations at the start and end of the capture
    /// and rotations that miss packets.
    pub keep_incomplete: bool,
}

/// Return modes as the factory byte names them.
pub fn return_mode_name(byte: u8) -> &'static str {
    match byte {
        0x37 => "strongest",
        0x38 => "last",
        0x39 => "dual",
        _ => "unknown",
    }
}

/// One rotation.
#[derive(Debug, Clone)]
pub struct VelodyneFrame {
    /// Rotations counted from 0 at the start of the capture, partial ones included.
    pub index: usize,
    pub image: RangeImage,
    /// Intensity (0..255) per pixel, NaN for no return.
    pub intensity: Vec<f32>,
    /// Bounded by two azimuth wraps and without a gap.
    pub complete: bool,
    /// Returns in the image.
    pub returns: usize,
}

/// What the decoder met in a capture.
#[derive(Debug, Clone, Default, serde::Serialize)]
pub struct VelodyneStats {
    pub pcap: PcapStats,
    pub data_packets: u64,
    pub position_packets: u64,
    /// Data packets with a bad block flag or azimuth: skipped whole.
    pub malformed_packets: u64,
    /// Data packets whose product id names another model.
    pub foreign_packets: u64,
    /// Blocks skipped as the other return of a dual-return pair.
    pub other_return_blocks: u64,
    /// Return modes seen (factory byte, VLP-16 / VLP-32C / HDL-32E), packets each.
    pub return_modes: BTreeMap<String, u64>,
    /// Datagrams of other sizes, by size.
    pub other_datagrams: BTreeMap<usize, u64>,
    pub frames: u64,
    pub incomplete_frames: u64,
    /// Returns that lost their pixel to a nearer return of the same laser.
    pub pixel_collisions: u64,
}

/// One laser return, before it is put in a pixel.
#[derive(Debug, Clone, Copy)]
struct Firing {
    /// Block azimuth at the time of the firing, hundredths of a degree.
    azimuth: f64,
    /// Position of its firing sequence in the rotation (0 for the first):
    /// the sequence's column comes from it, never from the azimuth of a
    /// single firing.
    sequence: u64,
    laser: u16,
    distance: u16,
    intensity: u8,
}

#[derive(Debug, Default)]
struct Rotation {
    firings: Vec<Firing>,
    /// Started at an azimuth wrap.
    started_at_wrap: bool,
    gap: bool,
    /// Firing sequences and the azimuth they span (unwrapped), for the column count.
    sequences: usize,
    first_azimuth: Option<f64>,
    last_azimuth: Option<f64>,
    /// Azimuth of the first block used.
    first_block: Option<u16>,
    /// Azimuth and position of the latest block used.
    last_block: Option<(u16, u64)>,
    /// Position of the latest block of each bank (upper, lower).
    bank_last: [Option<u64>; 2],
}

impl Rotation {
    /// The position of a block in the rotation, counted in block steps
    /// from its first block: the steps of `step` hundredths of a degree
    /// since the latest block (rounded to the nearest, so a skipped packet
    /// leaves its positions empty), and at least one past the latest block
    /// of the same bank, so two blocks of one bank never share a position
    /// however their azimuths were rounded. The HDL-64E's lower block
    /// takes the position of the upper block it fired with.
    fn place_block(&mut self, lower: bool, azimuth: u16, step: f64) -> u64 {
        let mut pos = match self.last_block {
            None => 0,
            Some((prev, p)) => {
                let steps = if step > 0.0 {
                    ((f64::from(azimuth) - f64::from(prev)) / step + 0.5).floor()
                } else {
                    0.0
                };
                // Saturating: corrupt azimuths give nonsense, never a panic.
                (p as f64 + steps).max(0.0) as u64
            }
        };
        let bank = usize::from(lower);
        if let Some(b) = self.bank_last[bank] {
            pos = pos.max(b.saturating_add(1));
        }
        self.bank_last[bank] = Some(pos);
        self.first_block.get_or_insert(azimuth);
        self.last_block = Some((azimuth, pos));
        pos
    }
}

/// The packet-level decoder: data packets in, whatever their transport (a
/// capture file or a socket), rotations out. It holds one rotation being
/// received and nothing else, so its memory stays bounded however long it
/// runs.
pub struct VelodyneDecoder {
    /// Names the input in messages.
    path: PathBuf,
    opts: VelodyneOptions,
    calibration: Option<VelodyneCalibration>,
    /// Row of each laser.
    rows: Vec<usize>,
    /// Trig of each laser, computed once.
    trig: Vec<[f64; 2]>,
    columns: Option<usize>,
    current: Rotation,
    last_block_azimuth: Option<u16>,
    index: usize,
    stats: VelodyneStats,
}

impl VelodyneDecoder {
    /// A decoder; `path` names the input in messages.
    pub fn new(path: &Path, opts: VelodyneOptions) -> Result<Self> {
        if let Some(c) = opts.columns {
            if !(2..=MAX_COLUMNS).contains(&c) {
                return Err(LidarError::Config(format!(
                    "{c} columns for a Velodyne range image: expected 2 to {MAX_COLUMNS}"
                )));
            }
        }
        let mut me = VelodyneDecoder {
            path: path.to_path_buf(),
            columns: opts.columns,
            opts,
            calibration: None,
            rows: Vec::new(),
            trig: Vec::new(),
            current: Rotation::default(),
            last_block_azimuth: None,
            index: 0,
            stats: VelodyneStats::default(),
        };
        if let Some(m) = me.opts.model {
            me.set_model(m)?;
        }
        Ok(me)
    }

    fn set_model(&mut self, model: VelodyneModel) -> Result<()> {
        let cal = match &self.opts.calibration {
            Some(p) => VelodyneCalibration::from_file(p, model)?,
            None => VelodyneCalibration::nominal(model)
                .map_err(|e| LidarError::malformed(&self.path, e.to_string()))?,
        };
        let mut order: Vec<usize> = (0..cal.lasers.len()).collect();
        order.sort_by(|&a, &b| {
            cal.lasers[b]
                .vert_correction
                .total_cmp(&cal.lasers[a].vert_correction)
        });
        self.rows = vec![0; cal.lasers.len()];
        for (row, &laser) in order.iter().enumerate() {
            self.rows[laser] = row;
        }
        self.trig = cal
            .lasers
            .iter()
            .map(|l| [l.vert_correction.sin(), l.vert_correction.cos()])
            .collect();
        self.opts.model = Some(model);
        self.calibration = Some(cal);
        Ok(())
    }

    /// The model in use (known after the first data packet when not given).
    pub fn model(&self) -> Option<VelodyneModel> {
        self.opts.model
    }

    /// The calibration in use.
    pub fn calibration(&self) -> Option<&VelodyneCalibration> {
        self.calibration.as_ref()
    }

    /// What was met so far (`pcap` is left to the transport).
    pub fn stats(&self) -> &VelodyneStats {
        &self.stats
    }

    /// Firing sequences received so far of the rotation being assembled.
    pub fn pending_sequences(&self) -> usize {
        self.current.sequences
    }

    /// One UDP payload: returns a rotation it completed, if any. Position
    /// packets and datagrams of other sizes are counted and skipped; a bad
    /// data packet is counted and skipped whole. An error only when the
    /// model is to be told from the packets and a packet names none.
    pub fn push(&mut self, payload: &[u8]) -> Result<Option<VelodyneFrame>> {
        match payload.len() {
            DATA_PACKET => return self.packet(payload),
            POSITION_PACKET => self.stats.position_packets += 1,
            n => *self.stats.other_datagrams.entry(n).or_insert(0) += 1,
        }
        Ok(None)
    }

    /// The end of the input: the rotation being received, if it makes one.
    pub fn flush(&mut self) -> Option<VelodyneFrame> {
        let last = std::mem::take(&mut self.current);
        self.finish(last, false)
    }

    /// Decode one data packet; returns a rotation it completed, if any.
    fn packet(&mut self, p: &[u8]) -> Result<Option<VelodyneFrame>> {
        // Check every block before using any, so a bad packet is all or nothing.
        let mut blocks = Vec::with_capacity(BLOCKS);
        for b in 0..BLOCKS {
            let blk = &p[b * BLOCK_BYTES..(b + 1) * BLOCK_BYTES];
            let flag = u16::from_le_bytes([blk[0], blk[1]]);
            let azimuth = u16::from_le_bytes([blk[2], blk[3]]);
            if !(flag == FLAG_UPPER || flag == FLAG_LOWER) || azimuth >= 36000 {
                self.stats.malformed_packets += 1;
                return Ok(None);
            }
            blocks.push((flag == FLAG_LOWER, azimuth, blk));
        }
        let has_lower = blocks.iter().any(|b| b.0);
        let (mode_byte, product) = (p[1204], p[1205]);
        let model = match self.opts.model {
            Some(m) => m,
            None => {
                let m = if has_lower {
                    Some(VelodyneModel::Hdl64e)
                } else {
                    VelodyneModel::from_product_id(product)
                };
                let Some(m) = m else {
                    return Err(LidarError::malformed(
                        &self.path,
                        format!(
                            "data packet {}: product id {product:#04x} names no supported Velodyne model: pass --velodyne-model ({})",
                            self.stats.data_packets + 1,
                            MODEL_NAMES.join(", ")
                        ),
                    ));
                };
                self.set_model(m)?;
                m
            }
        };
        if model != VelodyneModel::Hdl64e {
            let foreign =
                has_lower || VelodyneModel::from_product_id(product).is_some_and(|m| m != model);
            if foreign {
                self.stats.foreign_packets += 1;
                return Ok(None);
            }
            *self
                .stats
                .return_modes
                .entry(return_mode_name(mode_byte).to_string())
                .or_insert(0) += 1;
        }
        self.stats.data_packets += 1;
        // Azimuth step between firing sequences: from the distinct block
        // azimuths of this packet.
        let mut distinct: Vec<u16> = Vec::with_capacity(BLOCKS);
        for &(_, a, _) in &blocks {
            if distinct.last() != Some(&a) && !distinct.contains(&a) {
                distinct.push(a);
            }
        }
        let block_step = if distinct.len() >= 2 {
            let span = (i64::from(distinct[distinct.len() - 1]) - i64::from(distinct[0]))
                .rem_euclid(36000);
            span as f64 / (distinct.len() - 1) as f64
        } else {
            0.0
        };
        let seqs = model.sequences_per_block();
        let seq_step = block_step / seqs as f64;
        let mut seen: Vec<(bool, u16)> = Vec::with_capacity(BLOCKS);
        let want = match self.opts.dual {
            DualReturn::First => 0,
            DualReturn::Second => 1,
        };
        let mut done = None;
        for &(lower, azimuth, blk) in &blocks {
            // A block with the bank and azimuth of an earlier block of this
            // packet is another return of the same firing.
            let nth = seen.iter().filter(|&&s| s == (lower, azimuth)).count();
            seen.push((lower, azimuth));
            let second_exists = blocks
                .iter()
                .filter(|b| (b.0, b.1) == (lower, azimuth))
                .count()
                > 1;
            let use_it = if second_exists { nth == want } else { nth == 0 };
            if !use_it {
                self.stats.other_return_blocks += 1;
                continue;
            }
            // Rotation boundary: the azimuth went backwards past half a turn.
            if let Some(prev) = self.last_block_azimuth {
                if azimuth < prev && prev - azimuth > 18000 {
                    let ended = std::mem::take(&mut self.current);
                    self.current.started_at_wrap = true;
                    let f = self.finish(ended, true);
                    if done.is_none() {
                        done = f;
                    }
                } else if f64::from(azimuth) - f64::from(prev)
                    > MAX_GAP_CENTIDEG.max(3.0 * block_step)
                {
                    self.current.gap = true;
                }
            }
            self.last_block_azimuth = Some(azimuth);
            let pos = self.current.place_block(lower, azimuth, block_step);
            let per_seq = 32 / seqs;
            for s in 0..seqs {
                let seq_az = f64::from(azimuth) + seq_step * s as f64;
                let sequence = pos.saturating_mul(seqs as u64).saturating_add(s as u64);
                let r = &mut self.current;
                if !lower {
                    r.sequences += 1;
                    if r.first_azimuth.is_none() {
                        r.first_azimuth = Some(seq_az);
                    }
                    r.last_azimuth = Some(seq_az);
                }
                for k in 0..per_seq {
                    let slot = s * per_seq + k;
                    let o = 4 + 3 * slot;
                    let distance = u16::from_le_bytes([blk[o], blk[o + 1]]);
                    if distance == 0 {
                        continue;
                    }
                    let (t, period) = model.firing_time_us(k);
                    r.firings.push(Firing {
                        azimuth: seq_az + seq_step * t / period,
                        sequence,
                        laser: (k + if lower { 32 } else { 0 }) as u16,
                        distance,
                        intensity: blk[o + 2],
                    });
                }
            }
        }
        Ok(done)
    }

    /// Turn a finished rotation into a frame, or count it as incomplete.
    fn finish(&mut self, r: Rotation, ended_at_wrap: bool) -> Option<VelodyneFrame> {
        let index = self.index;
        if r.sequences == 0 {
            return None;
        }
        self.index += 1;
        let cal = self.calibration.as_ref()?;
        let complete = r.started_at_wrap && ended_at_wrap && !r.gap;
        if self.columns.is_none() {
            // Sequences over the azimuth they span, scaled to a turn.
            let (a, b) = (
                r.first_azimuth.unwrap_or(0.0),
                r.last_azimuth.unwrap_or(0.0),
            );
            let span = if complete {
                36000.0
            } else {
                (b - a).rem_euclid(36000.0)
            };
            let n = if complete {
                r.sequences as f64
            } else {
                (r.sequences.saturating_sub(1)) as f64 * 36000.0 / span.max(1.0)
            };
            let c = (n.round() as usize).clamp(2, MAX_COLUMNS);
            if complete || self.opts.keep_incomplete {
                self.columns = Some(c);
            }
        }
        if !complete && !self.opts.keep_incomplete {
            self.stats.incomplete_frames += 1;
            return None;
        }
        let cols = self.columns?;
        let rows = cal.lasers.len();
        let columns = SequenceColumns::new(&r, cal, cols, complete);
        let mut image = RangeImage::empty(rows, cols);
        let mut intensity = vec![f32::NAN; rows * cols];
        let mut best = vec![f32::INFINITY; rows * cols];
        for f in &r.firings {
            let laser = usize::from(f.laser);
            let Some(l) = cal.lasers.get(laser) else {
                continue;
            };
            let p = point(l, self.trig[laser], cal.distance_resolution_m, f);
            let i = self.rows[laser] * cols + columns.column(f.sequence, laser);
            let range = (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt() as f32;
            if range.is_nan() {
                continue;
            }
            if best[i].is_finite() {
                self.stats.pixel_collisions += 1;
                if range >= best[i] {
                    continue;
                }
            }
            best[i] = range;
            image.set(i, Some([p[0] as f32, p[1] as f32, p[2] as f32]));
            intensity[i] = f32::from(f.intensity);
        }
        self.stats.frames += 1;
        let returns = image.valid_count();
        Some(VelodyneFrame {
            index,
            image,
            intensity,
            complete,
            returns,
        })
    }
}

/// Decodes the data packets of a capture into rotations, one at a time:
/// the capture's datagrams through a [`VelodyneDecoder`].
pub struct VelodyneReader<R: Read> {
    decoder: VelodyneDecoder,
    pcap: PcapReader<R>,
    finished: bool,
}

impl VelodyneReader<BufReader<File>> {
    /// Open a capture.
    pub fn open(path: &Path, opts: VelodyneOptions) -> Result<Self> {
        VelodyneReader::new(path, PcapReader::open(path)?, opts)
    }
}

impl<R: Read> VelodyneReader<R> {
    /// Decode the datagrams of an open capture; `path` is used in messages.
    pub fn new(path: &Path, pcap: PcapReader<R>, opts: VelodyneOptions) -> Result<Self> {
        Ok(VelodyneReader {
            decoder: VelodyneDecoder::new(path, opts)?,
            pcap,
            finished: false,
        })
    }

    /// The model in use (known after the first data packet when not given).
    pub fn model(&self) -> Option<VelodyneModel> {
        self.decoder.model()
    }

    /// The calibration in use.
    pub fn calibration(&self) -> Option<&VelodyneCalibration> {
        self.decoder.calibration()
    }

    /// What was met so far.
    pub fn stats(&self) -> VelodyneStats {
        let mut s = self.decoder.stats().clone();
        s.pcap = self.pcap.stats().clone();
        s
    }

    /// The next rotation, `Ok(None)` at the end of the capture.
    pub fn next_frame(&mut self) -> Result<Option<VelodyneFrame>> {
        while !self.finished {
            let Some(d) = self.pcap.next_datagram()? else {
                self.finished = true;
                return Ok(self.decoder.flush());
            };
            if let Some(f) = self.decoder.push(&d.payload)? {
                return Ok(Some(f));
            }
        }
        Ok(None)
    }
}

/// Columns of one rotation's firing sequences. A firing sequence owns one
/// column, taken from its position in the rotation, never from the rounded
/// azimuth of a single firing: the first sequence's column is the bin of
/// its azimuth, and sequence `j` lies `round(j · ratio)` columns after it,
/// `ratio` being the columns per sequence: `cols` over the sequences of
/// the turn in a complete rotation (exactly one column per sequence when
/// the image has as many columns as the turn has sequences), otherwise
/// from the azimuth its blocks span. Each laser's return goes to its
/// sequence's column shifted by the laser's `rot_correction` in whole
/// columns, so that a column looks in one direction. Positions and
/// columns are integers: no floating-point rounding of an azimuth near a
/// column edge decides a column.
struct SequenceColumns {
    cols: u64,
    /// Column of the first sequence.
    first: u64,
    /// Columns per sequence position, as a fraction `num / den`.
    num: u128,
    den: u128,
    /// Whole columns each laser's `rot_correction` turns it by, in 0..cols.
    shift: Vec<u64>,
}

impl SequenceColumns {
    fn new(
        r: &Rotation,
        cal: &VelodyneCalibration,
        cols: usize,
        complete: bool,
    ) -> SequenceColumns {
        let seqs = cal.model.sequences_per_block() as u128;
        let first_az = r.first_block.unwrap_or(0);
        let (last_az, last_pos) = r.last_block.unwrap_or((first_az, 0));
        let cols_u = cols as u128;
        let (num, den) = if complete {
            // The turn's firing sequences: every position its blocks take.
            (cols_u, seqs * (u128::from(last_pos) + 1))
        } else if last_pos > 0 && last_az > first_az {
            // The step its blocks' azimuths give.
            (
                cols_u * u128::from(last_az - first_az),
                36000 * seqs * u128::from(last_pos),
            )
        } else {
            (1, 1)
        };
        let cols = cols as u64;
        let first = (u64::from(first_az) + 18000) * cols / 36000;
        let shift = cal
            .lasers
            .iter()
            .map(|l| {
                let s = (-l.rot_correction.to_degrees() * cols as f64 / 360.0 + 0.5).floor();
                (s as i64).rem_euclid(cols as i64) as u64
            })
            .collect();
        SequenceColumns {
            cols,
            first,
            num,
            den,
            shift,
        }
    }

    /// The column of laser `laser`'s return in the firing sequence at
    /// position `sequence`: `first + floor(sequence · num / den + 1/2)`
    /// plus the laser's shift, modulo `cols`.
    fn column(&self, sequence: u64, laser: usize) -> usize {
        let steps = (2 * u128::from(sequence) * self.num + self.den) / (2 * self.den);
        let steps = (steps % u128::from(self.cols)) as u64;
        let shift = self.shift.get(laser).copied().unwrap_or(0);
        ((self.first + steps + shift) % self.cols) as usize
    }
}

/// A return in metres (x forward, y left, z up).
fn point(l: &LaserCorrection, [sin_v, cos_v]: [f64; 2], res: f64, f: &Firing) -> [f64; 3] {
    let az = f.azimuth / 100.0 - l.rot_correction.to_degrees();
    let (sin_a, cos_a) = az.to_radians().sin_cos();
    let r = f64::from(f.distance) * res + l.dist_correction;
    let (vo, ho) = (l.vert_offset_correction, l.horiz_offset_correction);
    // Velodyne's own frame: xv to the right, yv forward.
    let horizontal = |d: f64| d * cos_v - vo * sin_v;
    let (mut rx, mut ry) = (r, r);
    if l.two_point {
        // Two-point calibration: the distance offset varies linearly with
        // the distance along each axis, between the 2.4 m (x) or 1.93 m (y)
        // and 25.04 m calibration points.
        let h = horizontal(r);
        let xx = (h * sin_a - ho * cos_a).abs();
        let yy = (h * cos_a + ho * sin_a).abs();
        let dc = l.dist_correction;
        rx += (dc - l.dist_correction_x) * (xx - 2.4) / (25.04 - 2.4) + l.dist_correction_x - dc;
        ry += (dc - l.dist_correction_y) * (yy - 1.93) / (25.04 - 1.93) + l.dist_correction_y - dc;
    }
    let xv = horizontal(rx) * sin_a - ho * cos_a;
    let yv = horizontal(ry) * cos_a + ho * sin_a;
    let z = ry * sin_v + vo * cos_v;
    [yv, -xv, z]
}

impl<R: Read> Iterator for VelodyneReader<R> {
    type Item = Result<VelodyneFrame>;
    fn next(&mut self) -> Option<Self::Item> {
        self.next_frame().transpose()
    }
}

/// Why a capture gave no rotation: for messages.
pub fn explain_no_frames(s: &VelodyneStats) -> String {
    let mut why = format!(
        "no complete Velodyne rotation: {} data packets of {DATA_PACKET} bytes decoded",
        s.data_packets
    );
    if s.incomplete_frames > 0 {
        why.push_str(&format!(
            ", {} partial rotations dropped (--keep-incomplete keeps them)",
            s.incomplete_frames
        ));
    }
    if s.malformed_packets > 0 {
        why.push_str(&format!(", {} malformed", s.malformed_packets));
    }
    if s.foreign_packets > 0 {
        why.push_str(&format!(
            ", {} from another model (is --velodyne-model right?)",
            s.foreign_packets
        ));
    }
    if !s.other_datagrams.is_empty() {
        let sizes: Vec<String> = s
            .other_datagrams
            .iter()
            .map(|(k, v)| format!("{v} of {k} bytes"))
            .collect();
        why.push_str(&format!("; other UDP datagrams: {}", sizes.join(", ")));
    }
    if s.pcap.udp_datagrams == 0 {
        why.push_str("; the capture holds no UDP datagram");
    }
    if s.pcap.truncated_file {
        why.push_str("; the file ends in the middle of a record");
    }
    why
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nominal_tables_have_one_row_per_laser_top_down() {
        for m in [
            VelodyneModel::Vlp16,
            VelodyneModel::Vlp32c,
            VelodyneModel::Hdl32e,
        ] {
            let c = VelodyneCalibration::nominal(m).unwrap();
            assert_eq!(c.lasers.len(), m.lasers(), "{}", m.name());
            let e = c.elevations_top_down();
            assert!(e.windows(2).all(|w| w[0] > w[1]), "{}: {e:?}", m.name());
        }
        let e = VelodyneCalibration::nominal(VelodyneModel::Vlp16)
            .unwrap()
            .elevations_top_down();
        assert!(
            (e[0] - 15.0).abs() < 1e-12 && (e[15] + 15.0).abs() < 1e-12,
            "{e:?}"
        );
        let e = VelodyneCalibration::nominal(VelodyneModel::Hdl32e)
            .unwrap()
            .elevations_top_down();
        assert!(
            (e[0] - 10.67).abs() < 1e-12 && (e[31] + 30.67).abs() < 1e-12,
            "{e:?}"
        );
        assert!(VelodyneCalibration::nominal(VelodyneModel::Hdl64e)
            .unwrap_err()
            .to_string()
            .contains("--velodyne-calibration"));
    }

    #[test]
    fn beam_tables_of_every_model_fall_strictly() {
        for name in MODEL_NAMES {
            let t = beam_table(name).unwrap();
            assert_eq!(t.len(), VelodyneModel::from_name(name).unwrap().lasers());
            assert!(t.windows(2).all(|w| w[0] > w[1]), "{name}: {t:?}");
        }
        let t = beam_table("HDL-64E").unwrap();
        assert!((t[0] - 2.0).abs() < 1e-12 && (t[63] + 24.33).abs() < 1e-12);
        assert!(beam_table("os1").is_none());
    }

    #[test]
    fn model_names_and_product_ids() {
        assert_eq!(
            VelodyneModel::from_name("VLP-16"),
            Some(VelodyneModel::Vlp16)
        );
        assert_eq!(
            VelodyneModel::from_name("hdl64e"),
            Some(VelodyneModel::Hdl64e)
        );
        assert_eq!(VelodyneModel::from_name("vls128"), None);
        assert_eq!(
            VelodyneModel::from_product_id(0x28),
            Some(VelodyneModel::Vlp32c)
        );
        assert_eq!(VelodyneModel::from_product_id(0x00), None);
    }

    #[test]
    fn point_geometry_forward_left_up() {
        let l = LaserCorrection::default();
        let f = |az: f64| Firing {
            azimuth: az,
            sequence: 0,
            laser: 0,
            distance: 5000,
            intensity: 0,
        };
        // Azimuth 0 looks forward (+x), 90 degrees to the right (-y).
        let p = point(&l, [0.0, 1.0], 0.002, &f(0.0));
        assert!((p[0] - 10.0).abs() < 1e-9 && p[1].abs() < 1e-9, "{p:?}");
        let p = point(&l, [0.0, 1.0], 0.002, &f(9000.0));
        assert!(p[0].abs() < 1e-9 && (p[1] + 10.0).abs() < 1e-9, "{p:?}");
        let up = 10f64.to_radians();
        let p = point(&l, [up.sin(), up.cos()], 0.002, &f(0.0));
        assert!((p[2] - 10.0 * up.sin()).abs() < 1e-9, "{p:?}");
    }

    #[test]
    fn block_positions_count_steps_and_never_repeat_in_a_bank() {
        let mut r = Rotation::default();
        // Jittered azimuths around a 40-step, then a lost packet of 12 blocks.
        let pos: Vec<u64> = [0u16, 41, 79, 122, 158, 160 + 13 * 40]
            .iter()
            .map(|&a| r.place_block(false, a, 40.0))
            .collect();
        assert_eq!(pos, [0, 1, 2, 3, 4, 17]);
        // A repeated or backward azimuth still advances by one.
        assert_eq!(r.place_block(false, 680, 40.0), 18);
        assert_eq!(r.place_block(false, 670, 40.0), 19);
        // HDL-64E: the lower block shares its upper block's position.
        let mut r = Rotation::default();
        let pos: Vec<u64> = [
            (false, 0u16),
            (true, 0),
            (false, 18),
            (true, 18),
            (false, 35),
        ]
        .iter()
        .map(|&(lower, a)| r.place_block(lower, a, 18.0))
        .collect();
        assert_eq!(pos, [0, 0, 1, 1, 2]);
    }

    #[test]
    fn sequence_columns_are_one_apart_in_a_complete_turn_and_shift_per_laser() {
        let mut cal = VelodyneCalibration::nominal(VelodyneModel::Vlp32c).unwrap();
        cal.lasers.truncate(2);
        let mut r = Rotation::default();
        for b in 0..1800u16 {
            r.place_block(false, b * 20, 20.0);
        }
        let c = SequenceColumns::new(&r, &cal, 1800, true);
        // Block azimuth 0 (forward) is column 900; laser 0 turns 1.4 degrees
        // clockwise (7 columns), laser 1 4.2 degrees back (21 columns).
        let cols: Vec<usize> = (0..1800).map(|j| c.column(j, 0)).collect();
        assert_eq!(cols[0], 907);
        assert!(cols.windows(2).all(|w| w[1] == (w[0] + 1) % 1800));
        assert_eq!(c.column(0, 1), 879);
        // Twice the columns: every other column.
        let c = SequenceColumns::new(&r, &cal, 3600, true);
        assert_eq!(
            (0..4).map(|j| c.column(j, 0)).collect::<Vec<_>>(),
            [1814, 1816, 1818, 1820]
        );
    }

    #[test]
    fn yaml_block_and_flow_styles_agree() {
        let dir = tempfile::tempdir().unwrap();
        let flow = dir.path().join("flow.yaml");
        let block = dir.path().join("block.yaml");
        let mut f = String::from("lasers:\n");
        let mut b = String::from("distance_resolution: 0.002\nlasers:\n");
        for i in 0..16 {
            f.push_str(&format!(
                "- {{dist_correction: 0.0, laser_id: {i},\n  rot_correction: 0.0, vert_correction: {}}}\n",
                (f64::from(i) - 7.5).to_radians()
            ));
            b.push_str(&format!(
                "  - laser_id: {i}\n    rot_correction: 0.0\n    vert_correction: {}\n",
                (f64::from(i) - 7.5).to_radians()
            ));
        }
        f.push_str("num_lasers: 16\n");
        std::fs::write(&flow, f).unwrap();
        std::fs::write(&block, b).unwrap();
        let a = VelodyneCalibration::from_file(&flow, VelodyneModel::Vlp16).unwrap();
        let c = VelodyneCalibration::from_file(&block, VelodyneModel::Vlp16).unwrap();
        assert_eq!(a.lasers, c.lasers);
        let err = VelodyneCalibration::from_file(&flow, VelodyneModel::Hdl32e)
            .unwrap_err()
            .to_string();
        assert!(err.contains("no calibration for laser(s) 16, 17"), "{err}");
    }
}
