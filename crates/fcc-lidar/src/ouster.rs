//! Ouster sensors: JSON metadata, lidar packets, destaggered range images.
//!
//! Supported lidar UDP profiles: `LEGACY` (firmware before 2.2, and any
//! metadata that does not name a profile), `RNG19_RFL8_SIG16_NIR16`,
//! `RNG15_RFL8_NIR8` and `RNG19_RFL8_SIG16_NIR16_DUAL` (first return).
//!
//! Geometry follows the sensor documentation: for a pixel of beam `u` in
//! measurement column `v` of a `w`-column frame, with range `r` mm,
//! encoder angle `θe = 2π (1 - v / w)`, beam azimuth `θa = -azimuth[u]`,
//! altitude `φ = altitude[u]` and beam-origin offset `n` mm,
//!
//! ```text
//! x = (r - n) cos(θe + θa) cos φ + n cos θe
//! y = (r - n) sin(θe + θa) cos φ + n sin θe
//! z = (r - n) sin φ
//! ```
//!
//! then `lidar_to_sensor_transform` (when absent, the product line's
//! default, [`default_lidar_to_sensor`]) maps the lidar
//! frame to the sensor frame, and millimetres become metres. Columns are
//! destaggered: the pixel of beam `u` from column `v` lands in image column
//! `(v + shift[u] - o) mod w`, with `pixel_shift_by_row` when the metadata
//! has it, else `shift[u] = round(azimuth[u] w / 360) - min over beams`. The
//! image origin `o` is 0 for the sensor's own image ([`ImageOrigin::Sensor`],
//! the Ouster SDK's destaggered image) and the largest shift for
//! [`ImageOrigin::Sweep`], whose column `j` is complete as soon as
//! measurement column `j + o` has arrived, so a frame can be clustered while
//! the sensor sweeps it.

use crate::error::{LidarError, Result};
use crate::image::RangeImage;
use crate::pcap::{PcapReader, PcapStats};
use serde_json::Value;
use std::collections::BTreeMap;
use std::fs::File;
use std::io::{BufReader, Read};
use std::path::{Path, PathBuf};

/// Beam-origin offset when neither the metadata nor its product line gives
/// one: the first-generation OS-1 value Ouster's own SDK falls back to.
pub const DEFAULT_BEAM_ORIGIN_MM: f64 = 12.163;
/// Largest frame accepted (beams x columns); real sensors stay under a
/// quarter of it.
pub const MAX_PIXELS: usize = 1 << 21;
/// Size of a legacy IMU packet, recognised and skipped.
const LEGACY_IMU_PACKET: usize = 48;

/// The layout of the lidar packets.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
pub enum Profile {
    /// Firmware before 2.2: 16-byte column header, 12-byte pixels, 20-bit
    /// range in mm, 4-byte status word after each column.
    Legacy,
    /// `RNG19_RFL8_SIG16_NIR16`: 12-byte pixels, 19-bit range in mm.
    Rng19Rfl8Sig16Nir16,
    /// `RNG15_RFL8_NIR8`: 4-byte pixels, 15-bit range in units of 8 mm.
    Rng15Rfl8Nir8,
    /// `RNG19_RFL8_SIG16_NIR16_DUAL`: 16-byte pixels; the first return is used.
    Rng19Rfl8Sig16Nir16Dual,
}

impl Profile {
    /// Parse the metadata's `udp_profile_lidar`.
    pub fn from_name(name: &str) -> Option<Profile> {
        match name {
            "LEGACY" => Some(Profile::Legacy),
            "RNG19_RFL8_SIG16_NIR16" => Some(Profile::Rng19Rfl8Sig16Nir16),
            "RNG15_RFL8_NIR8" => Some(Profile::Rng15Rfl8Nir8),
            "RNG19_RFL8_SIG16_NIR16_DUAL" => Some(Profile::Rng19Rfl8Sig16Nir16Dual),
            _ => None,
        }
    }

    /// The name the metadata uses.
    pub fn name(self) -> &'static str {
        match self {
            Profile::Legacy => "LEGACY",
            Profile::Rng19Rfl8Sig16Nir16 => "RNG19_RFL8_SIG16_NIR16",
            Profile::Rng15Rfl8Nir8 => "RNG15_RFL8_NIR8",
            Profile::Rng19Rfl8Sig16Nir16Dual => "RNG19_RFL8_SIG16_NIR16_DUAL",
        }
    }

    /// Bytes per pixel.
    pub fn pixel_bytes(self) -> usize {
        match self {
            Profile::Legacy | Profile::Rng19Rfl8Sig16Nir16 => 12,
            Profile::Rng15Rfl8Nir8 => 4,
            Profile::Rng19Rfl8Sig16Nir16Dual => 16,
        }
    }

    fn packet_header(self) -> usize {
        if self == Profile::Legacy {
            0
        } else {
            32
        }
    }

    fn packet_footer(self) -> usize {
        self.packet_header()
    }

    fn column_header(self) -> usize {
        if self == Profile::Legacy {
            16
        } else {
            12
        }
    }

    fn column_footer(self) -> usize {
        if self == Profile::Legacy {
            4
        } else {
            0
        }
    }

    /// Reflectivity of the pixel starting at `px` (16 bits in LEGACY, 8
    /// otherwise; the first return's in DUAL).
    fn reflectivity(self, px: &[u8]) -> u16 {
        match self {
            Profile::Legacy => u16::from_le_bytes([px[4], px[5]]),
            Profile::Rng19Rfl8Sig16Nir16 => u16::from(px[4]),
            Profile::Rng15Rfl8Nir8 => u16::from(px[2]),
            Profile::Rng19Rfl8Sig16Nir16Dual => u16::from(px[3]),
        }
    }

    /// Range in millimetres of the pixel starting at `px`; 0 = no return.
    fn range_mm(self, px: &[u8]) -> u32 {
        match self {
            Profile::Legacy => u32::from_le_bytes([px[0], px[1], px[2], px[3]]) & 0x000f_ffff,
            Profile::Rng19Rfl8Sig16Nir16 | Profile::Rng19Rfl8Sig16Nir16Dual => {
                u32::from_le_bytes([px[0], px[1], px[2], px[3]]) & 0x0007_ffff
            }
            Profile::Rng15Rfl8Nir8 => u32::from(u16::from_le_bytes([px[0], px[1]]) & 0x7fff) << 3,
        }
    }
}

/// Which coordinate frame the points are given in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum CoordFrame {
    /// Apply `lidar_to_sensor_transform` (the sensor frame Ouster's tools use).
    #[default]
    Sensor,
    /// The lidar frame, before that transform.
    Lidar,
}

/// The Ouster sample captures shipped in this crate's `tests/data`
/// (BSD-3-Clause, licence beside them), as (capture, metadata) file names:
/// 128 beams (OS-0, OS-2), 64 and 32 beams, 1024 columns each.
pub const SAMPLE_CAPTURES: [(&str, &str); 4] = [
    (
        "OS-0-128-U1_v2.3.0_1024x10.pcap",
        "OS-0-128-U1_v2.3.0_1024x10.json",
    ),
    (
        "OS-1-32-G_v2.1.1_1024x10.pcap",
        "OS-1-32-G_v2.1.1_1024x10.json",
    ),
    (
        "OS-1-64_1024x10_fw20.pcap",
        "OS-1-64_sensor_config_reduced.json",
    ),
    (
        "OS-2-128-U1_v2.3.0_1024x10.pcap",
        "OS-2-128-U1_v2.3.0_1024x10.json",
    ),
];

/// Where [`SAMPLE_CAPTURES`] are: this crate's `tests/data` in the source
/// tree the program was built from (so tools find them from any directory).
pub fn sample_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests")
        .join("data")
}

/// Everything the decoder needs from the sensor's JSON metadata.
#[derive(Debug, Clone, PartialEq)]
pub struct OusterMetadata {
    /// Where the metadata came from (for messages).
    pub source: PathBuf,
    pub prod_line: Option<String>,
    /// Serial number, used to reject packets of another sensor.
    pub prod_sn: Option<u64>,
    pub profile: Profile,
    /// Beams: image rows.
    pub pixels_per_column: usize,
    /// Columns per rotation: image columns.
    pub columns_per_frame: usize,
    pub columns_per_packet: usize,
    /// First and last measurement column the sensor sends (may wrap).
    pub column_window: (usize, usize),
    /// Destaggering shift per beam.
    pub pixel_shift_by_row: Vec<i64>,
    /// True if the shifts came from the metadata, false if derived.
    pub shift_from_metadata: bool,
    pub beam_altitude_deg: Vec<f64>,
    pub beam_azimuth_deg: Vec<f64>,
    /// Distance from the lidar origin to the beam origin, mm.
    pub beam_origin_mm: f64,
    /// True if `beam_origin_mm` is a default, not read from the metadata.
    pub beam_origin_default: bool,
    /// Row-major 4 x 4, translation in mm.
    pub lidar_to_sensor: [f64; 16],
    /// True if `lidar_to_sensor` is the product line's default, not read
    /// from the metadata.
    pub transform_default: bool,
    pub udp_port_lidar: Option<u16>,
    pub udp_port_imu: Option<u16>,
}

/// Containers in which newer metadata files nest the fields.
const NESTS: [&str; 7] = [
    "data_format",
    "lidar_data_format",
    "beam_intrinsics",
    "lidar_intrinsics",
    "config_params",
    "sensor_info",
    "imu_intrinsics",
];

fn find<'a>(root: &'a Value, key: &str) -> Option<&'a Value> {
    if let Some(v) = root.get(key) {
        return Some(v);
    }
    NESTS
        .iter()
        .find_map(|n| root.get(n).and_then(|o| o.get(key)))
}

impl OusterMetadata {
    /// Read a metadata JSON file.
    pub fn from_file(path: &Path) -> Result<OusterMetadata> {
        let bytes = std::fs::read(path).map_err(|e| LidarError::io(path, e))?;
        let text = std::str::from_utf8(&bytes).map_err(|e| {
            LidarError::metadata(path, format!("not valid JSON: not UTF-8 text ({e})"))
        })?;
        OusterMetadata::from_json_str(text, path)
    }

    /// Parse metadata JSON; `source` names it in messages.
    pub fn from_json_str(text: &str, source: &Path) -> Result<OusterMetadata> {
        let bad = |why: String| LidarError::metadata(source, why);
        let root: Value =
            serde_json::from_str(text).map_err(|e| bad(format!("not valid JSON: {e}")))?;
        if !root.is_object() {
            return Err(bad("the top level is not a JSON object".into()));
        }
        let floats = |key: &str| -> Result<Option<Vec<f64>>> {
            match find(&root, key) {
                None => Ok(None),
                Some(Value::Array(a)) => a
                    .iter()
                    .map(|v| v.as_f64().filter(|x| x.is_finite()))
                    .collect::<Option<Vec<f64>>>()
                    .map(Some)
                    .ok_or_else(|| bad(format!("`{key}` must be a list of numbers"))),
                Some(_) => Err(bad(format!("`{key}` must be a list of numbers"))),
            }
        };
        let uint = |key: &str| -> Result<Option<usize>> {
            match find(&root, key) {
                None => Ok(None),
                Some(v) => v.as_u64().map(|x| Some(x as usize)).ok_or_else(|| {
                    bad(format!("`{key}` must be a non-negative integer, found {v}"))
                }),
            }
        };
        let text_of = |key: &str| find(&root, key).and_then(Value::as_str).map(str::to_owned);

        let altitude = floats("beam_altitude_angles")?
            .ok_or_else(|| bad("`beam_altitude_angles` is missing".into()))?;
        let azimuth = floats("beam_azimuth_angles")?
            .ok_or_else(|| bad("`beam_azimuth_angles` is missing".into()))?;
        let lidar_mode = text_of("lidar_mode");
        let mode_cols = lidar_mode
            .as_deref()
            .and_then(|m| m.split('x').next())
            .and_then(|c| c.parse::<usize>().ok());
        let columns_per_frame = match (uint("columns_per_frame")?, mode_cols) {
            (Some(c), _) => c,
            (None, Some(c)) => c,
            (None, None) => {
                return Err(bad(
                    "neither `columns_per_frame` nor a `lidar_mode` like \"1024x10\" says how many columns a frame has"
                        .into(),
                ))
            }
        };
        if !(1..=65_536).contains(&columns_per_frame) {
            return Err(bad(format!(
                "columns_per_frame = {columns_per_frame} is out of range 1..=65536"
            )));
        }
        let pixels_per_column = uint("pixels_per_column")?.unwrap_or(altitude.len());
        if !(1..=1024).contains(&pixels_per_column) {
            return Err(bad(format!(
                "pixels_per_column = {pixels_per_column} is out of range 1..=1024"
            )));
        }
        if pixels_per_column * columns_per_frame > MAX_PIXELS {
            return Err(bad(format!(
                "{pixels_per_column} beams x {columns_per_frame} columns is more than the {MAX_PIXELS} pixels any sensor has"
            )));
        }
        for (name, list) in [
            ("beam_altitude_angles", &altitude),
            ("beam_azimuth_angles", &azimuth),
        ] {
            if list.len() != pixels_per_column {
                return Err(bad(format!(
                    "`{name}` has {} entries but there are {pixels_per_column} beams",
                    list.len()
                )));
            }
        }
        let columns_per_packet = uint("columns_per_packet")?.unwrap_or(16);
        if !(1..=256).contains(&columns_per_packet) {
            return Err(bad(format!(
                "columns_per_packet = {columns_per_packet} is out of range 1..=256"
            )));
        }
        let profile = match text_of("udp_profile_lidar") {
            None => Profile::Legacy,
            Some(name) => Profile::from_name(&name).ok_or_else(|| {
                bad(format!(
                    "lidar UDP profile `{name}` is not supported (supported: LEGACY, RNG19_RFL8_SIG16_NIR16, RNG15_RFL8_NIR8, RNG19_RFL8_SIG16_NIR16_DUAL)"
                ))
            })?,
        };
        let column_window = match find(&root, "column_window") {
            None => (0, columns_per_frame - 1),
            Some(v) => {
                let w: Option<Vec<usize>> = v.as_array().map(|a| {
                    a.iter()
                        .filter_map(|x| x.as_u64().map(|x| x as usize))
                        .collect()
                });
                match w.as_deref() {
                    Some(&[a, b]) if a < columns_per_frame && b < columns_per_frame => (a, b),
                    _ => {
                        return Err(bad(format!(
                            "`column_window` must be two column indices below {columns_per_frame}, found {v}"
                        )))
                    }
                }
            }
        };
        let (pixel_shift_by_row, shift_from_metadata) = match find(&root, "pixel_shift_by_row") {
            Some(Value::Array(a)) => {
                let s: Option<Vec<i64>> = a.iter().map(Value::as_i64).collect();
                let s =
                    s.ok_or_else(|| bad("`pixel_shift_by_row` must be a list of integers".into()))?;
                if s.len() != pixels_per_column {
                    return Err(bad(format!(
                        "`pixel_shift_by_row` has {} entries but there are {pixels_per_column} beams",
                        s.len()
                    )));
                }
                (s, true)
            }
            Some(_) => return Err(bad("`pixel_shift_by_row` must be a list of integers".into())),
            None => (shifts_from_azimuth(&azimuth, columns_per_frame), false),
        };
        let prod_line = text_of("prod_line");
        let (beam_origin_mm, beam_origin_default) =
            match find(&root, "lidar_origin_to_beam_origin_mm") {
                Some(v) => (
                    v.as_f64().filter(|x| x.is_finite()).ok_or_else(|| {
                        bad("`lidar_origin_to_beam_origin_mm` must be a number".into())
                    })?,
                    false,
                ),
                None => match floats("beam_to_lidar_transform")? {
                    Some(t) if t.len() == 16 => (t[3], false),
                    _ => (default_beam_origin(prod_line.as_deref()), true),
                },
            };
        let (lidar_to_sensor, transform_default) = match floats("lidar_to_sensor_transform")? {
            None => (default_lidar_to_sensor(prod_line.as_deref()), true),
            Some(t) => (
                t.as_slice().try_into().map_err(|_| {
                    bad(format!(
                        "`lidar_to_sensor_transform` has {} numbers, not 16",
                        t.len()
                    ))
                })?,
                false,
            ),
        };
        let prod_sn = match find(&root, "prod_sn") {
            Some(Value::String(s)) => s.trim().parse::<u64>().ok().filter(|&n| n != 0),
            Some(Value::Number(n)) => n.as_u64().filter(|&n| n != 0),
            _ => None,
        };
        let port = |key: &str| -> Option<u16> {
            find(&root, key)
                .and_then(Value::as_u64)
                .and_then(|p| u16::try_from(p).ok())
                .filter(|&p| p != 0)
        };
        Ok(OusterMetadata {
            source: source.to_path_buf(),
            prod_line: prod_line.filter(|s| !s.is_empty()),
            prod_sn,
            profile,
            pixels_per_column,
            columns_per_frame,
            columns_per_packet,
            column_window,
            pixel_shift_by_row,
            shift_from_metadata,
            beam_altitude_deg: altitude,
            beam_azimuth_deg: azimuth,
            beam_origin_mm,
            beam_origin_default,
            lidar_to_sensor,
            transform_default,
            udp_port_lidar: port("udp_port_lidar"),
            udp_port_imu: port("udp_port_imu"),
        })
    }

    /// Bytes of one lidar packet.
    pub fn packet_size(&self) -> usize {
        let p = self.profile;
        let col = p.column_header() + self.pixels_per_column * p.pixel_bytes() + p.column_footer();
        p.packet_header() + self.columns_per_packet * col + p.packet_footer()
    }

    /// Measurement columns inside the column window.
    pub fn window_columns(&self) -> usize {
        let (a, b) = self.column_window;
        if a <= b {
            b - a + 1
        } else {
            self.columns_per_frame - a + b + 1
        }
    }

    /// Image columns the origin moves the sensor's image by (0 for
    /// [`ImageOrigin::Sensor`], the largest shift for [`ImageOrigin::Sweep`]).
    pub fn origin_columns(&self, origin: ImageOrigin) -> usize {
        let w = self.columns_per_frame as i64;
        match origin {
            ImageOrigin::Sensor => 0,
            ImageOrigin::Sweep => self
                .pixel_shift_by_row
                .iter()
                .map(|s| s.rem_euclid(w))
                .max()
                .unwrap_or(0) as usize,
        }
    }

    /// Per beam, the image column of measurement column 0 with `origin`:
    /// beam `u` of measurement column `v` lands in image column
    /// `(v + offsets[u]) mod w`.
    pub fn column_offsets(&self, origin: ImageOrigin) -> Vec<usize> {
        let w = self.columns_per_frame;
        let o = self.origin_columns(origin);
        self.pixel_shift_by_row
            .iter()
            .map(|s| (s.rem_euclid(w as i64) as usize + w - o) % w)
            .collect()
    }

    fn in_window(&self, v: usize) -> bool {
        let (a, b) = self.column_window;
        if a <= b {
            (a..=b).contains(&v)
        } else {
            v >= a || v <= b
        }
    }
}

const IDENTITY: [f64; 16] = [
    1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
];

/// Beam-origin offset by product line, as Ouster's SDK defaults it.
pub fn default_beam_origin(prod_line: Option<&str>) -> f64 {
    match prod_line {
        Some(p) if p.starts_with("OS-0-") => 27.67,
        Some(p) if p.starts_with("OS-1-") => 15.806,
        Some(p) if p.starts_with("OS-2-") => 13.762,
        _ => DEFAULT_BEAM_ORIGIN_MM,
    }
}

/// The lidar-to-sensor transform of metadata that lacks one: the lidar
/// frame turned half round about z (x and y negated) and lifted to the
/// sensor's base, 78.296 mm on the OS-2 and 36.18 mm on the other lines (the
/// values the OS-0, OS-1 and OS-2 metadata carry, and 36.18 mm is the
/// default of Ouster's SDK).
pub fn default_lidar_to_sensor(prod_line: Option<&str>) -> [f64; 16] {
    let line: String = prod_line
        .unwrap_or("")
        .chars()
        .filter(|c| c.is_ascii_alphanumeric())
        .collect::<String>()
        .to_ascii_uppercase();
    let lift = if line.starts_with("OS2") {
        78.296
    } else {
        36.18
    };
    [
        -1.0, 0.0, 0.0, 0.0, //
        0.0, -1.0, 0.0, 0.0, //
        0.0, 0.0, 1.0, lift, //
        0.0, 0.0, 0.0, 1.0,
    ]
}

/// Destaggering shifts derived from the beam azimuth offsets:
/// `round(azimuth * w / 360)`, moved so the smallest is 0.
pub fn shifts_from_azimuth(azimuth_deg: &[f64], columns: usize) -> Vec<i64> {
    let raw: Vec<i64> = azimuth_deg
        .iter()
        .map(|a| (a * columns as f64 / 360.0).round() as i64)
        .collect();
    let min = raw.iter().copied().min().unwrap_or(0);
    raw.iter().map(|s| s - min).collect()
}

/// Add `add` to the frame id of a lidar packet of `meta`'s layout (in the
/// packet header, or in every column header of LEGACY packets), as a
/// replay does to send a capture's rotation again as a new frame. False,
/// and the packet untouched, when it is not a lidar packet of that size.
pub fn bump_frame_id(meta: &OusterMetadata, packet: &mut [u8], add: u16) -> bool {
    if packet.len() != meta.packet_size() {
        return false;
    }
    let bump = |b: &mut [u8]| {
        let id = u16::from_le_bytes([b[0], b[1]]).wrapping_add(add);
        b.copy_from_slice(&id.to_le_bytes());
    };
    let p = meta.profile;
    if p == Profile::Legacy {
        let col = p.column_header() + meta.pixels_per_column * p.pixel_bytes() + p.column_footer();
        for c in 0..meta.columns_per_packet {
            bump(&mut packet[c * col + 10..c * col + 12]);
        }
    } else {
        bump(&mut packet[2..4]);
    }
    true
}

/// Which destaggered column an Ouster image starts at.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, serde::Serialize)]
pub enum ImageOrigin {
    /// The sensor's image (Ouster's SDK): beam `u` of measurement column `v`
    /// in image column `(v + shift[u]) mod w`. Image columns `0 .. max
    /// shift - 1` hold beams of the frame's last measurement columns, so
    /// column 0 is complete only when the frame has ended.
    #[default]
    Sensor,
    /// The same image rotated by the largest shift `o`: image column `j`
    /// holds beams of measurement columns `j .. j + o` only, and is complete
    /// once those have arrived (the sweep order).
    Sweep,
}

impl ImageOrigin {
    /// Every origin, in the order the options list them.
    pub const ALL: [ImageOrigin; 2] = [ImageOrigin::Sensor, ImageOrigin::Sweep];

    /// The option's name (`sensor`, `sweep`).
    pub fn name(self) -> &'static str {
        match self {
            ImageOrigin::Sensor => "sensor",
            ImageOrigin::Sweep => "sweep",
        }
    }
}

impl std::str::FromStr for ImageOrigin {
    type Err = String;

    fn from_str(s: &str) -> std::result::Result<Self, String> {
        ImageOrigin::ALL
            .into_iter()
            .find(|o| o.name() == s)
            .ok_or_else(|| {
                let names: Vec<&str> = ImageOrigin::ALL.iter().map(|o| o.name()).collect();
                format!(
                    "unknown image origin `{s}`: expected {}",
                    names.join(" or ")
                )
            })
    }
}

/// Options of the decoder.
#[derive(Debug, Clone, Default)]
pub struct DecodeOptions {
    pub frame: CoordFrame,
    /// Where the destaggered image starts.
    pub origin: ImageOrigin,
    /// Also deliver frames that miss columns (missing columns are empty).
    pub keep_incomplete: bool,
    /// Returns closer than this many metres are dropped (0 keeps all).
    pub min_range_m: f64,
}

/// One rotation of the sensor.
#[derive(Debug, Clone)]
pub struct OusterFrame {
    pub frame_id: u16,
    /// The timestamp of the frame's first column received, nanoseconds, as
    /// the sensor stamps its columns (its own clock: PTP or GPS time when
    /// synchronised, else time since power-on).
    pub timestamp_ns: u64,
    /// Per measurement column, the decoded packet that brought it (its
    /// number in `CaptureStats::lidar_packets`, from 1; 0 for none).
    pub column_packet: Vec<u64>,
    /// Destaggered: rows = beams (row 0 the top beam), cols = columns per frame.
    pub image: RangeImage,
    /// Reflectivity per pixel of `image` (NaN where it has no return).
    pub reflectivity: Vec<f32>,
    pub stats: FrameStats,
}

/// What went into one frame.
#[derive(Debug, Clone, Default, PartialEq, Eq, serde::Serialize)]
pub struct FrameStats {
    pub packets: usize,
    /// Measurement columns received.
    pub columns: usize,
    /// Of those, columns whose status said valid.
    pub valid_columns: usize,
    /// Pixels with a return.
    pub returns: usize,
    /// Every column of the column window arrived.
    pub complete: bool,
}

/// What the decoder met in a whole capture.
#[derive(Debug, Clone, Default, PartialEq, Eq, serde::Serialize)]
pub struct CaptureStats {
    pub pcap: PcapStats,
    /// Lidar packets decoded.
    pub lidar_packets: u64,
    /// IMU packets recognised and skipped.
    pub imu_packets: u64,
    /// Lidar packets of the wrong size, packet type or column index.
    pub malformed_packets: u64,
    /// Packets from a sensor whose serial number is not the metadata's.
    pub foreign_packets: u64,
    /// Other datagrams, by payload size (for telling the user what was there).
    pub other_datagrams: BTreeMap<usize, u64>,
    /// Frames delivered.
    pub frames: u64,
    /// Frames dropped because columns were missing.
    pub incomplete_frames: u64,
    /// Columns that arrived twice in one frame (the later one wins).
    pub duplicate_columns: u64,
}

/// Per-pixel geometry, precomputed once per metadata.
struct Lut {
    /// Direction and offset of each (beam, measurement column), staggered, in
    /// the output frame: 6 values per pixel (dx dy dz ox oy oz), offsets in mm.
    table: Vec<[f64; 6]>,
    cols: usize,
}

impl Lut {
    fn new(meta: &OusterMetadata, frame: CoordFrame) -> Lut {
        let (h, w) = (meta.pixels_per_column, meta.columns_per_frame);
        let t = if frame == CoordFrame::Sensor {
            meta.lidar_to_sensor
        } else {
            IDENTITY
        };
        let n = meta.beam_origin_mm;
        let mut table = Vec::with_capacity(h * w);
        for u in 0..h {
            let alt = meta.beam_altitude_deg[u].to_radians();
            let az = -meta.beam_azimuth_deg[u].to_radians();
            for v in 0..w {
                let enc = 2.0 * std::f64::consts::PI * (1.0 - v as f64 / w as f64);
                let d = [
                    (enc + az).cos() * alt.cos(),
                    (enc + az).sin() * alt.cos(),
                    alt.sin(),
                ];
                let o = [n * (enc.cos() - d[0]), n * (enc.sin() - d[1]), -n * d[2]];
                let rot = |p: [f64; 3]| {
                    [
                        t[0] * p[0] + t[1] * p[1] + t[2] * p[2],
                        t[4] * p[0] + t[5] * p[1] + t[6] * p[2],
                        t[8] * p[0] + t[9] * p[1] + t[10] * p[2],
                    ]
                };
                let d = rot(d);
                let o = rot(o);
                table.push([d[0], d[1], d[2], o[0] + t[3], o[1] + t[7], o[2] + t[11]]);
            }
        }
        Lut { table, cols: w }
    }

    fn xyz_m(&self, u: usize, v: usize, range_mm: u32) -> [f32; 3] {
        let e = &self.table[u * self.cols + v];
        let r = f64::from(range_mm);
        [
            ((r * e[0] + e[3]) / 1000.0) as f32,
            ((r * e[1] + e[4]) / 1000.0) as f32,
            ((r * e[2] + e[5]) / 1000.0) as f32,
        ]
    }
}

/// Collects the columns of the frame being received.
struct Assembly {
    frame_id: u16,
    /// The sensor's timestamp of the first column received.
    timestamp_ns: u64,
    range_mm: Vec<u32>,
    reflectivity: Vec<u16>,
    received: Vec<bool>,
    /// The decoded packet (the count of `lidar_packets` after it) that
    /// brought each measurement column, 0 for none.
    column_packet: Vec<u64>,
    /// Image columns `0 .. ready` are complete: every measurement column
    /// that lands in them (inside the column window) has arrived.
    ready: usize,
    stats: FrameStats,
}

/// The packet-level decoder: lidar packets in, whatever their transport (a
/// capture file or a socket), frames out. It holds one frame being received
/// and nothing else, so its memory stays bounded however long it runs.
pub struct OusterDecoder {
    meta: OusterMetadata,
    opts: DecodeOptions,
    lut: Lut,
    /// Per beam, the image column of measurement column 0 (see
    /// [`OusterMetadata::column_offsets`]).
    offsets: Vec<usize>,
    /// The distinct values of `offsets`.
    distinct_offsets: Vec<usize>,
    current: Option<Assembly>,
    stats: CaptureStats,
    /// See [`set_columns_read`](Self::set_columns_read).
    columns_read: bool,
}

impl OusterDecoder {
    /// A decoder for the packets of the sensor `meta` describes.
    pub fn new(meta: &OusterMetadata, opts: DecodeOptions) -> Result<Self> {
        if !(opts.min_range_m.is_finite() && opts.min_range_m >= 0.0) {
            return Err(LidarError::Config(format!(
                "minimum range {} m must be a non-negative number",
                opts.min_range_m
            )));
        }
        let offsets = meta.column_offsets(opts.origin);
        let mut distinct_offsets = offsets.clone();
        distinct_offsets.sort_unstable();
        distinct_offsets.dedup();
        Ok(OusterDecoder {
            lut: Lut::new(meta, opts.frame),
            offsets,
            distinct_offsets,
            meta: meta.clone(),
            opts,
            current: None,
            stats: CaptureStats::default(),
            columns_read: false,
        })
    }

    /// For a consumer that reads each image column through
    /// [`column_into`](Self::column_into) as soon as
    /// [`ready_columns`](Self::ready_columns) counts it complete: a frame's
    /// image then leaves out (empty) the columns counted complete when it
    /// closed, which that consumer has already read, instead of working
    /// their points out a second time. Off by default.
    pub fn set_columns_read(&mut self, on: bool) {
        self.columns_read = on;
    }

    /// The metadata in use.
    pub fn metadata(&self) -> &OusterMetadata {
        &self.meta
    }

    /// What was met so far (`pcap` is left to the transport).
    pub fn stats(&self) -> &CaptureStats {
        &self.stats
    }

    /// The columns received so far of the frame being assembled.
    pub fn pending_columns(&self) -> usize {
        self.current.as_ref().map_or(0, |a| a.stats.columns)
    }

    /// Per beam, the image column of measurement column 0 (the shift and
    /// the image origin, see [`OusterMetadata::column_offsets`]).
    pub fn column_offsets(&self) -> &[usize] {
        &self.offsets
    }

    /// The frame being assembled: its frame id and how many of its leading
    /// image columns are complete (every measurement column that lands in
    /// them has arrived). With [`ImageOrigin::Sweep`] they follow the sweep
    /// a few columns behind; with [`ImageOrigin::Sensor`] column 0 waits for
    /// the frame's last measurement columns, so none is complete before the
    /// frame ends. A frame whose first columns never came (one that started
    /// before the input did, or lost a packet) has none complete until it
    /// ends.
    pub fn ready_columns(&self) -> Option<(u16, usize)> {
        self.current.as_ref().map(|a| (a.frame_id, a.ready))
    }

    /// Image column `col` of the frame being assembled, row 0 first, as the
    /// frame will hold it (`out` has one entry per beam). Meaningful for the
    /// columns [`ready_columns`](Self::ready_columns) counts: the pixels of
    /// measurement columns still to come are empty.
    pub fn column_into(&self, col: usize, out: &mut [Option<[f32; 3]>]) {
        let w = self.meta.columns_per_frame;
        let Some(a) = &self.current else {
            out.fill(None);
            return;
        };
        for (u, p) in out.iter_mut().enumerate().take(self.meta.pixels_per_column) {
            // (col - offset) mod w, offset < w, without a division per pixel.
            let v = col + w - self.offsets[u];
            let v = if v >= w { v - w } else { v };
            *p = self.pixel(u, v, a.range_mm[u * w + v]);
        }
    }

    /// The point of beam `u`, measurement column `v` at range `r` mm, or
    /// `None` for no return or one nearer than the minimum range.
    fn pixel(&self, u: usize, v: usize, r: u32) -> Option<[f32; 3]> {
        self.is_return(r).then(|| self.lut.xyz_m(u, v, r))
    }

    /// A range of `r` mm is a return: not 0, not nearer than the minimum.
    fn is_return(&self, r: u32) -> bool {
        r != 0 && f64::from(r) >= self.opts.min_range_m * 1000.0
    }

    /// Move the frame's count of complete image columns on.
    fn advance(&mut self) {
        let m = &self.meta;
        let w = m.columns_per_frame;
        let Some(a) = &mut self.current else { return };
        while a.ready < w
            && self.distinct_offsets.iter().all(|&o| {
                let v = (a.ready + w - o) % w;
                a.received[v] || !m.in_window(v)
            })
        {
            a.ready += 1;
        }
    }

    /// One UDP payload sent to `dst_port`: returns a frame it completed, if
    /// any. Datagrams that are not lidar packets (IMU packets, other sizes)
    /// are counted and skipped; a bad lidar packet is counted and skipped
    /// whole.
    pub fn push(&mut self, dst_port: u16, payload: &[u8]) -> Option<OusterFrame> {
        let size = self.meta.packet_size();
        let on_lidar_port = self.meta.udp_port_lidar == Some(dst_port);
        let on_imu_port = self.meta.udp_port_imu == Some(dst_port);
        if payload.len() != size {
            if on_lidar_port {
                self.stats.malformed_packets += 1;
            } else if on_imu_port || payload.len() == LEGACY_IMU_PACKET {
                self.stats.imu_packets += 1;
            } else {
                *self.stats.other_datagrams.entry(payload.len()).or_insert(0) += 1;
            }
            return None;
        }
        if on_imu_port {
            self.stats.imu_packets += 1;
            return None;
        }
        self.packet(payload)
    }

    /// The end of the input: the frame being received, if it makes one.
    pub fn flush(&mut self) -> Option<OusterFrame> {
        let a = self.current.take()?;
        self.close(a)
    }

    /// Decode one lidar packet; returns a frame it completed, if any.
    fn packet(&mut self, p: &[u8]) -> Option<OusterFrame> {
        let m = &self.meta;
        let prof = m.profile;
        let h = m.pixels_per_column;
        let w = m.columns_per_frame;
        let mut packet_frame = None;
        if prof != Profile::Legacy {
            let ptype = u16::from_le_bytes([p[0], p[1]]);
            if ptype != 1 {
                self.stats.malformed_packets += 1;
                return None;
            }
            let sn = u64::from_le_bytes([p[7], p[8], p[9], p[10], p[11], 0, 0, 0]);
            if let Some(want) = m.prod_sn {
                if sn != want {
                    self.stats.foreign_packets += 1;
                    return None;
                }
            }
            packet_frame = Some(u16::from_le_bytes([p[2], p[3]]));
        }
        let col_bytes = prof.column_header() + h * prof.pixel_bytes() + prof.column_footer();
        // Check every column before using any, so a bad packet is all or nothing.
        let mut cols = Vec::with_capacity(m.columns_per_packet);
        for i in 0..m.columns_per_packet {
            let c = &p[prof.packet_header() + i * col_bytes..][..col_bytes];
            let mid = usize::from(u16::from_le_bytes([c[8], c[9]]));
            let (fid, valid) = if prof == Profile::Legacy {
                let status = u32::from_le_bytes([
                    c[col_bytes - 4],
                    c[col_bytes - 3],
                    c[col_bytes - 2],
                    c[col_bytes - 1],
                ]);
                (u16::from_le_bytes([c[10], c[11]]), status == 0xffff_ffff)
            } else {
                let status = u16::from_le_bytes([c[10], c[11]]);
                (packet_frame.unwrap_or(0), status & 1 == 1)
            };
            if mid >= w {
                self.stats.malformed_packets += 1;
                return None;
            }
            cols.push((c, mid, fid, valid));
        }
        self.stats.lidar_packets += 1;
        let mut done = None;
        let mut counted = false;
        for (c, mid, fid, valid) in cols {
            if self.current.as_ref().is_some_and(|a| a.frame_id != fid) {
                if let Some(a) = self.current.take() {
                    // At most one frame ends per packet in practice; keep the first.
                    let f = self.close(a);
                    if done.is_none() {
                        done = f;
                    }
                }
                counted = false;
            }
            let a = self.current.get_or_insert_with(|| Assembly {
                frame_id: fid,
                timestamp_ns: u64::from_le_bytes([c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]]),
                range_mm: vec![0; h * w],
                reflectivity: vec![0; h * w],
                received: vec![false; w],
                column_packet: vec![0; w],
                ready: 0,
                stats: FrameStats::default(),
            });
            if !counted {
                a.stats.packets += 1;
                counted = true;
            }
            a.column_packet[mid] = self.stats.lidar_packets;
            if a.received[mid] {
                self.stats.duplicate_columns += 1;
            } else {
                a.received[mid] = true;
                a.stats.columns += 1;
            }
            if valid {
                a.stats.valid_columns += 1;
            }
            let px0 = prof.column_header();
            for u in 0..h {
                let px = &c[px0 + u * prof.pixel_bytes()..];
                let r = if valid { prof.range_mm(px) } else { 0 };
                a.range_mm[u * w + mid] = r;
                a.reflectivity[u * w + mid] = prof.reflectivity(px);
            }
        }
        self.advance();
        done
    }

    /// Turn a finished assembly into a frame, or count it as incomplete.
    fn close(&mut self, a: Assembly) -> Option<OusterFrame> {
        let m = &self.meta;
        let (h, w) = (m.pixels_per_column, m.columns_per_frame);
        let complete = (0..w).filter(|&v| m.in_window(v)).all(|v| a.received[v]);
        if !complete && !self.opts.keep_incomplete {
            self.stats.incomplete_frames += 1;
            return None;
        }
        let mut image = RangeImage::empty(h, w);
        let mut reflectivity = vec![f32::NAN; h * w];
        let mut returns = 0;
        // The columns the consumer has read already (`set_columns_read`).
        let read = if self.columns_read { a.ready } else { 0 };
        for u in 0..h {
            let off = self.offsets[u];
            for v in 0..w {
                let r = a.range_mm[u * w + v];
                if !self.is_return(r) {
                    continue;
                }
                returns += 1;
                // (v + offset) mod w, both below w, without a division.
                let col = if v + off >= w { v + off - w } else { v + off };
                if col < read {
                    continue;
                }
                image.set(u * w + col, Some(self.lut.xyz_m(u, v, r)));
                reflectivity[u * w + col] = f32::from(a.reflectivity[u * w + v]);
            }
        }
        self.stats.frames += 1;
        let mut stats = a.stats;
        stats.returns = returns;
        stats.complete = complete;
        Some(OusterFrame {
            frame_id: a.frame_id,
            timestamp_ns: a.timestamp_ns,
            column_packet: a.column_packet,
            image,
            reflectivity,
            stats,
        })
    }
}

/// Decodes the lidar packets of a capture into frames, one at a time: the
/// capture's datagrams through an [`OusterDecoder`].
pub struct OusterReader<R: Read> {
    decoder: OusterDecoder,
    pcap: PcapReader<R>,
    finished: bool,
}

impl OusterReader<BufReader<File>> {
    /// Open a capture with its metadata.
    pub fn open(pcap: &Path, meta: &OusterMetadata, opts: DecodeOptions) -> Result<Self> {
        OusterReader::new(PcapReader::open(pcap)?, meta, opts)
    }
}

impl<R: Read> OusterReader<R> {
    /// Decode the datagrams of an open capture.
    pub fn new(pcap: PcapReader<R>, meta: &OusterMetadata, opts: DecodeOptions) -> Result<Self> {
        Ok(OusterReader {
            decoder: OusterDecoder::new(meta, opts)?,
            pcap,
            finished: false,
        })
    }

    /// What was met so far.
    pub fn stats(&self) -> CaptureStats {
        let mut s = self.decoder.stats().clone();
        s.pcap = self.pcap.stats().clone();
        s
    }

    /// The metadata in use.
    pub fn metadata(&self) -> &OusterMetadata {
        self.decoder.metadata()
    }

    /// The next frame, `Ok(None)` at the end of the capture.
    pub fn next_frame(&mut self) -> Result<Option<OusterFrame>> {
        while !self.finished {
            let Some(d) = self.pcap.next_datagram()? else {
                self.finished = true;
                return Ok(self.decoder.flush());
            };
            if let Some(f) = self.decoder.push(d.dst_port, &d.payload) {
                return Ok(Some(f));
            }
        }
        Ok(None)
    }
}

impl<R: Read> Iterator for OusterReader<R> {
    type Item = Result<OusterFrame>;
    fn next(&mut self) -> Option<Self::Item> {
        self.next_frame().transpose()
    }
}

/// Every frame of a capture, and what the decoder met.
#[derive(Debug, Clone)]
pub struct OusterCapture {
    pub frames: Vec<OusterFrame>,
    pub stats: CaptureStats,
}

/// Decode a whole capture. Finding no frame at all is an error that says
/// what the capture held instead, since it usually means the metadata
/// belongs to another capture.
pub fn read_capture(
    pcap: &Path,
    meta: &OusterMetadata,
    opts: DecodeOptions,
) -> Result<OusterCapture> {
    let mut reader = OusterReader::open(pcap, meta, opts)?;
    let mut frames = Vec::new();
    while let Some(f) = reader.next_frame()? {
        frames.push(f);
    }
    let stats = reader.stats();
    if frames.is_empty() {
        return Err(LidarError::malformed(pcap, explain_no_frames(meta, &stats)));
    }
    Ok(OusterCapture { frames, stats })
}

/// Why a capture gave no frame, from what the decoder met: for messages.
pub fn explain_no_frames(meta: &OusterMetadata, s: &CaptureStats) -> String {
    let mut why = format!(
        "no complete frame: the metadata ({}) expects {}-byte lidar packets ({}, {} beams, {} columns per packet)",
        meta.source.display(),
        meta.packet_size(),
        meta.profile.name(),
        meta.pixels_per_column,
        meta.columns_per_packet
    );
    why.push_str(&format!("; decoded {} lidar packets", s.lidar_packets));
    if s.incomplete_frames > 0 {
        why.push_str(&format!(", {} frames missed columns", s.incomplete_frames));
    }
    if s.malformed_packets > 0 {
        why.push_str(&format!(", {} malformed", s.malformed_packets));
    }
    if s.foreign_packets > 0 {
        why.push_str(&format!(
            ", {} came from a sensor other than serial {} (is this the metadata of this capture?)",
            s.foreign_packets,
            meta.prod_sn.unwrap_or(0)
        ));
    }
    if !s.other_datagrams.is_empty() {
        let sizes: Vec<String> = s
            .other_datagrams
            .iter()
            .map(|(k, v)| format!("{v} of {k} bytes"))
            .collect();
        why.push_str(&format!(
            "; other UDP datagrams: {} (is this the metadata of this capture?)",
            sizes.join(", ")
        ));
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
    fn shifts_from_azimuth_match_published_tables() {
        // OS-1-32 beams: -4.22, -1.43, 1.44, 4.27 deg at 1024 columns.
        assert_eq!(
            shifts_from_azimuth(&[-4.22, -1.43, 1.44, 4.27], 1024),
            vec![0, 8, 16, 24]
        );
        // First-generation OS-1-64 pattern 18, 12, 6, 0.
        assert_eq!(
            shifts_from_azimuth(&[3.12, 0.97, -1.18, -3.3], 1024),
            vec![18, 12, 6, 0]
        );
    }

    #[test]
    fn packet_sizes_of_the_profiles() {
        let mut m = OusterMetadata::from_json_str(
            r#"{"beam_altitude_angles": [1, 0, -1, -2], "beam_azimuth_angles": [0, 0, 0, 0], "lidar_mode": "512x20"}"#,
            Path::new("m.json"),
        )
        .unwrap();
        assert_eq!(m.profile, Profile::Legacy);
        assert_eq!(m.columns_per_frame, 512);
        assert!(m.beam_origin_default);
        assert_eq!(m.packet_size(), 16 * (16 + 4 * 12 + 4));
        m.profile = Profile::Rng15Rfl8Nir8;
        assert_eq!(m.packet_size(), 32 + 16 * (12 + 4 * 4) + 32);
        m.profile = Profile::Rng19Rfl8Sig16Nir16Dual;
        assert_eq!(m.packet_size(), 32 + 16 * (12 + 4 * 16) + 32);
    }

    #[test]
    fn metadata_errors_name_file_and_field() {
        let cases = [
            ("{", "not valid JSON"),
            ("[1]", "not a JSON object"),
            (
                r#"{"beam_azimuth_angles": [0], "lidar_mode": "1024x10"}"#,
                "`beam_altitude_angles` is missing",
            ),
            (
                r#"{"beam_altitude_angles": [0], "beam_azimuth_angles": [0]}"#,
                "how many columns",
            ),
            (
                r#"{"beam_altitude_angles": [0, 1], "beam_azimuth_angles": [0], "lidar_mode": "1024x10"}"#,
                "`beam_azimuth_angles` has 1 entries but there are 2 beams",
            ),
            (
                r#"{"beam_altitude_angles": [0], "beam_azimuth_angles": [0], "lidar_mode": "1024x10", "data_format": {"udp_profile_lidar": "FUSA_RNG15_RFL8_NIR8_DUAL"}}"#,
                "`FUSA_RNG15_RFL8_NIR8_DUAL` is not supported",
            ),
            (
                r#"{"beam_altitude_angles": ["a"], "beam_azimuth_angles": [0], "lidar_mode": "1024x10"}"#,
                "must be a list of numbers",
            ),
            (
                r#"{"beam_altitude_angles": [0], "beam_azimuth_angles": [0], "lidar_mode": "1024x10", "pixel_shift_by_row": [1, 2]}"#,
                "`pixel_shift_by_row` has 2 entries",
            ),
            (
                r#"{"beam_altitude_angles": [0], "beam_azimuth_angles": [0], "lidar_mode": "1024x10", "pixels_per_column": 1000, "columns_per_frame": 65536}"#,
                "more than the 2097152 pixels",
            ),
        ];
        for (json, want) in cases {
            let err = OusterMetadata::from_json_str(json, Path::new("meta.json"))
                .unwrap_err()
                .to_string();
            assert!(
                err.contains("meta.json") && err.contains(want),
                "{json}: {err}"
            );
        }
    }

    #[test]
    fn nested_metadata_of_newer_firmware() {
        let json = r#"{
            "beam_intrinsics": {"beam_altitude_angles": [2, -2], "beam_azimuth_angles": [1.5, -1.5],
                                "beam_to_lidar_transform": [1,0,0,15.8, 0,1,0,0, 0,0,1,0, 0,0,0,1]},
            "lidar_data_format": {"columns_per_frame": 2048, "columns_per_packet": 16, "pixels_per_column": 2,
                                  "pixel_shift_by_row": [9, 0], "column_window": [0, 2047],
                                  "udp_profile_lidar": "RNG19_RFL8_SIG16_NIR16"},
            "config_params": {"lidar_mode": "2048x10", "udp_port_lidar": 7502},
            "sensor_info": {"prod_line": "OS-1-16", "prod_sn": "992000000001"}
        }"#;
        let m = OusterMetadata::from_json_str(json, Path::new("n.json")).unwrap();
        assert_eq!(m.columns_per_frame, 2048);
        assert_eq!(m.profile, Profile::Rng19Rfl8Sig16Nir16);
        assert_eq!(m.pixel_shift_by_row, vec![9, 0]);
        assert!(m.shift_from_metadata);
        assert_eq!(m.beam_origin_mm, 15.8);
        assert!(!m.beam_origin_default);
        assert_eq!(m.prod_sn, Some(992_000_000_001));
        assert_eq!(m.udp_port_lidar, Some(7502));
    }

    #[test]
    fn lut_matches_the_documented_formula() {
        let json = r#"{"beam_altitude_angles": [10, -10], "beam_azimuth_angles": [2, -2],
                       "lidar_mode": "1024x10", "lidar_origin_to_beam_origin_mm": 20.0}"#;
        let m = OusterMetadata::from_json_str(json, Path::new("m.json")).unwrap();
        let lut = Lut::new(&m, CoordFrame::Lidar);
        let (u, v, r) = (1usize, 100usize, 12_345u32);
        let enc = 2.0 * std::f64::consts::PI * (1.0 - v as f64 / 1024.0);
        let az = (2.0f64).to_radians();
        let alt = (-10.0f64).to_radians();
        let rr = f64::from(r) - 20.0;
        let want = [
            (rr * (enc + az).cos() * alt.cos() + 20.0 * enc.cos()) / 1000.0,
            (rr * (enc + az).sin() * alt.cos() + 20.0 * enc.sin()) / 1000.0,
            rr * alt.sin() / 1000.0,
        ];
        let got = lut.xyz_m(u, v, r);
        for k in 0..3 {
            assert!(
                (f64::from(got[k]) - want[k]).abs() < 1e-5,
                "{got:?} vs {want:?}"
            );
        }
    }
}
