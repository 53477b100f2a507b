//! Unordered point clouds: KITTI / SemanticKITTI velodyne `.bin`, PCD
//! (ASCII, binary and binary_compressed) and PLY (ASCII and binary, either
//! byte order).

use crate::error::{LidarError, Result};
use std::fs::File;
use std::io::{BufRead, BufReader, Read, Write};
use std::path::Path;

/// Points in metres, with an intensity per point when the file has one.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct PointCloud {
    pub points: Vec<[f32; 3]>,
    pub intensity: Option<Vec<f32>>,
}

impl PointCloud {
    pub fn len(&self) -> usize {
        self.points.len()
    }

    pub fn is_empty(&self) -> bool {
        self.points.is_empty()
    }
}

/// The point-cloud formats this crate reads.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CloudFormat {
    /// KITTI velodyne scans: float32 x, y, z, intensity, little endian.
    KittiBin,
    Pcd,
    Ply,
}

impl CloudFormat {
    /// The format a file name's extension says (`.bin`, `.pcd`, `.ply`).
    pub fn from_path(path: &Path) -> Option<CloudFormat> {
        let ext = path.extension()?.to_str()?.to_ascii_lowercase();
        match ext.as_str() {
            "bin" => Some(CloudFormat::KittiBin),
            "pcd" => Some(CloudFormat::Pcd),
            "ply" => Some(CloudFormat::Ply),
            _ => None,
        }
    }
}

/// Read a point cloud in the format its extension names.
pub fn read_point_cloud(path: &Path) -> Result<PointCloud> {
    match CloudFormat::from_path(path) {
        Some(CloudFormat::KittiBin) => read_kitti_bin(path),
        Some(CloudFormat::Pcd) => read_pcd(path),
        Some(CloudFormat::Ply) => read_ply(path),
        None => Err(LidarError::Config(format!(
            "{}: unknown point-cloud extension (expected .bin, .pcd or .ply)",
            path.display()
        ))),
    }
}

/// Read a KITTI velodyne scan.
pub fn read_kitti_bin(path: &Path) -> Result<PointCloud> {
    let bytes = std::fs::read(path).map_err(|e| LidarError::io(path, e))?;
    if bytes.len() % 16 != 0 {
        return Err(LidarError::not_format(
            path,
            "KITTI velodyne .bin",
            format!(
                "{} bytes is not a whole number of 16-byte points (float32 x, y, z, intensity)",
                bytes.len()
            ),
        ));
    }
    let mut points = Vec::with_capacity(bytes.len() / 16);
    let mut intensity = Vec::with_capacity(bytes.len() / 16);
    for rec in bytes.chunks_exact(16) {
        let f = |k: usize| {
            f32::from_le_bytes([rec[4 * k], rec[4 * k + 1], rec[4 * k + 2], rec[4 * k + 3]])
        };
        points.push([f(0), f(1), f(2)]);
        intensity.push(f(3));
    }
    Ok(PointCloud {
        points,
        intensity: Some(intensity),
    })
}

/// Write a KITTI velodyne scan (intensity 0 where the cloud has none).
pub fn write_kitti_bin(path: &Path, cloud: &PointCloud) -> Result<()> {
    let mut out = Vec::with_capacity(cloud.len() * 16);
    for (i, p) in cloud.points.iter().enumerate() {
        let inten = cloud
            .intensity
            .as_ref()
            .and_then(|v| v.get(i))
            .copied()
            .unwrap_or(0.0);
        for v in [p[0], p[1], p[2], inten] {
            out.extend_from_slice(&v.to_le_bytes());
        }
    }
    fcc_io::write_atomic(path, &out).map_err(|e| LidarError::io(path, e))
}

fn field_f64(f: &pcd_rs::Field) -> Option<f64> {
    use pcd_rs::Field as F;
    Some(match f {
        F::I8(v) => f64::from(*v.first()?),
        F::I16(v) => f64::from(*v.first()?),
        F::I32(v) => f64::from(*v.first()?),
        F::I64(v) => *v.first()? as f64,
        F::U8(v) => f64::from(*v.first()?),
        F::U16(v) => f64::from(*v.first()?),
        F::U32(v) => f64::from(*v.first()?),
        F::U64(v) => *v.first()? as f64,
        F::F32(v) => f64::from(*v.first()?),
        F::F64(v) => *v.first()?,
    })
}

/// Length of a PCD header in bytes (up to and including the DATA line).
fn pcd_header_len(path: &Path, bytes: &[u8]) -> Result<usize> {
    let mut off = 0;
    while off < bytes.len() {
        let end = bytes[off..]
            .iter()
            .position(|&b| b == b'\n')
            .map_or(bytes.len(), |p| off + p + 1);
        let line = &bytes[off..end];
        off = end;
        if line.starts_with(b"DATA") {
            return Ok(off);
        }
        if off > 1 << 16 {
            break;
        }
    }
    Err(LidarError::not_format(
        path,
        "PCD",
        "no DATA line in the header",
    ))
}

/// Read a PCD file (fields `x`, `y`, `z` of any numeric type required,
/// `intensity` used if present).
pub fn read_pcd(path: &Path) -> Result<PointCloud> {
    let bytes = std::fs::read(path).map_err(|e| LidarError::io(path, e))?;
    let bad = |why: String| LidarError::malformed(path, format!("PCD: {why}"));
    let meta = pcd_rs::PcdMeta::from_reader(BufReader::new(&bytes[..]))
        .map_err(|e| LidarError::not_format(path, "PCD", e.to_string()))?;
    let names: Vec<&str> = meta.field_defs.iter().map(|f| f.name.as_str()).collect();
    let index = |n: &str| names.iter().position(|&m| m == n);
    let (Some(ix), Some(iy), Some(iz)) = (index("x"), index("y"), index("z")) else {
        return Err(bad(format!(
            "fields x, y and z are required, the file has {}",
            names.join(" ")
        )));
    };
    let ii = index("intensity").or_else(|| index("i"));
    // Guard the reader against counts the file cannot hold.
    let header = pcd_header_len(path, &bytes)?;
    let body = bytes.len() - header;
    let rec: usize = meta
        .field_defs
        .iter()
        .map(|f| f.kind.byte_size() * f.count as usize)
        .sum();
    let n = meta.num_points;
    if meta.width.checked_mul(meta.height) != Some(n) {
        return Err(bad(format!(
            "WIDTH {} x HEIGHT {} is not POINTS {n}",
            meta.width, meta.height
        )));
    }
    match meta.data {
        pcd_rs::DataKind::Binary => {
            if (n as u128) * (rec as u128) > body as u128 {
                return Err(bad(format!(
                    "{n} points of {rec} bytes need more than the {body} bytes of data"
                )));
            }
        }
        pcd_rs::DataKind::BinaryCompressed => {
            if body < 8 {
                return Err(bad("compressed data is cut short".into()));
            }
            let b = &bytes[header..];
            let csize = u32::from_le_bytes([b[0], b[1], b[2], b[3]]) as usize;
            let usize_ = u32::from_le_bytes([b[4], b[5], b[6], b[7]]) as usize;
            if csize > body - 8 || (usize_ as u128) != (n as u128) * (rec as u128) {
                return Err(bad(format!(
                    "compressed block claims {csize} -> {usize_} bytes; the file holds {} and {n} points need {}",
                    body - 8,
                    n as u128 * rec as u128
                )));
            }
        }
        pcd_rs::DataKind::Ascii => {
            if n as u128 > body as u128 {
                return Err(bad(format!(
                    "{n} points cannot fit in {body} bytes of text"
                )));
            }
        }
    }
    let reader = pcd_rs::DynReader::from_bytes(&bytes).map_err(|e| bad(e.to_string()))?;
    let mut points = Vec::with_capacity(n as usize);
    let mut intensity = ii.map(|_| Vec::with_capacity(n as usize));
    for (k, rec) in reader.enumerate() {
        let rec = rec.map_err(|e| bad(format!("point {k}: {e}")))?;
        let get = |i: usize| rec.0.get(i).and_then(field_f64);
        let (Some(x), Some(y), Some(z)) = (get(ix), get(iy), get(iz)) else {
            return Err(bad(format!("point {k} lacks a coordinate")));
        };
        points.push([x as f32, y as f32, z as f32]);
        if let (Some(v), Some(i)) = (intensity.as_mut(), ii) {
            v.push(get(i).unwrap_or(0.0) as f32);
        }
    }
    if points.len() as u64 != n {
        return Err(bad(format!(
            "header says {n} points, data holds {}",
            points.len()
        )));
    }
    Ok(PointCloud { points, intensity })
}

/// PLY encodings.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PlyFormat {
    Ascii,
    BinaryLittleEndian,
    BinaryBigEndian,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum PlyType {
    I8,
    U8,
    I16,
    U16,
    I32,
    U32,
    F32,
    F64,
}

impl PlyType {
    fn parse(s: &str) -> Option<PlyType> {
        Some(match s {
            "char" | "int8" => PlyType::I8,
            "uchar" | "uint8" => PlyType::U8,
            "short" | "int16" => PlyType::I16,
            "ushort" | "uint16" => PlyType::U16,
            "int" | "int32" => PlyType::I32,
            "uint" | "uint32" => PlyType::U32,
            "float" | "float32" => PlyType::F32,
            "double" | "float64" => PlyType::F64,
            _ => return None,
        })
    }

    fn size(self) -> usize {
        match self {
            PlyType::I8 | PlyType::U8 => 1,
            PlyType::I16 | PlyType::U16 => 2,
            PlyType::I32 | PlyType::U32 | PlyType::F32 => 4,
            PlyType::F64 => 8,
        }
    }

    fn read(self, b: &[u8], big: bool) -> f64 {
        macro_rules! num {
            ($t:ty, $n:expr) => {{
                let mut a = [0u8; $n];
                a.copy_from_slice(&b[..$n]);
                if big {
                    <$t>::from_be_bytes(a) as f64
                } else {
                    <$t>::from_le_bytes(a) as f64
                }
            }};
        }
        match self {
            PlyType::I8 => f64::from(b[0] as i8),
            PlyType::U8 => f64::from(b[0]),
            PlyType::I16 => num!(i16, 2),
            PlyType::U16 => num!(u16, 2),
            PlyType::I32 => num!(i32, 4),
            PlyType::U32 => num!(u32, 4),
            PlyType::F32 => num!(f32, 4),
            PlyType::F64 => num!(f64, 8),
        }
    }
}

#[derive(Debug, Clone)]
struct PlyProperty {
    name: String,
    ty: PlyType,
    /// For list properties: the type of the count.
    list_count: Option<PlyType>,
}

#[derive(Debug, Clone)]
struct PlyElement {
    name: String,
    count: usize,
    props: Vec<PlyProperty>,
}

/// Read a PLY file's `vertex` element: `x`, `y`, `z` required, `intensity`
/// (or `scalar_intensity`, `reflectance`) used if present. Other elements
/// (faces, ...) are read past.
pub fn read_ply(path: &Path) -> Result<PointCloud> {
    let file = File::open(path).map_err(|e| LidarError::io(path, e))?;
    let mut r = BufReader::new(file);
    let not = |why: String| LidarError::not_format(path, "PLY", why);
    let bad = |why: String| LidarError::malformed(path, format!("PLY: {why}"));
    let mut line = Vec::new();
    let mut next_line = |r: &mut BufReader<File>| -> Result<Option<String>> {
        line.clear();
        let n = r
            .by_ref()
            .take(4096)
            .read_until(b'\n', &mut line)
            .map_err(|e| LidarError::io(path, e))?;
        if n == 0 {
            return Ok(None);
        }
        Ok(Some(String::from_utf8_lossy(&line).trim().to_string()))
    };
    if next_line(&mut r)?.as_deref() != Some("ply") {
        return Err(not("the first line is not `ply`".into()));
    }
    let mut format = None;
    let mut elements: Vec<PlyElement> = Vec::new();
    loop {
        let Some(l) = next_line(&mut r)? else {
            return Err(bad("the header has no end_header line".into()));
        };
        let words: Vec<&str> = l.split_whitespace().collect();
        match words.as_slice() {
            ["end_header"] => break,
            [] | ["comment", ..] | ["obj_info", ..] => {}
            ["format", f, _version] => {
                format = Some(match *f {
                    "ascii" => PlyFormat::Ascii,
                    "binary_little_endian" => PlyFormat::BinaryLittleEndian,
                    "binary_big_endian" => PlyFormat::BinaryBigEndian,
                    other => return Err(bad(format!("unknown format `{other}`"))),
                })
            }
            ["element", name, count] => {
                let count = count.parse::<usize>().map_err(|_| {
                    bad(format!(
                        "element `{name}` has count `{count}`, not a number"
                    ))
                })?;
                elements.push(PlyElement {
                    name: (*name).to_string(),
                    count,
                    props: Vec::new(),
                });
            }
            ["property", "list", ct, it, name] => {
                let (Some(c), Some(i)) = (PlyType::parse(ct), PlyType::parse(it)) else {
                    return Err(bad(format!("unknown type in `{l}`")));
                };
                let el = elements
                    .last_mut()
                    .ok_or_else(|| bad(format!("`{l}` before any element")))?;
                el.props.push(PlyProperty {
                    name: (*name).to_string(),
                    ty: i,
                    list_count: Some(c),
                });
            }
            ["property", ty, name] => {
                let ty = PlyType::parse(ty).ok_or_else(|| bad(format!("unknown type in `{l}`")))?;
                let el = elements
                    .last_mut()
                    .ok_or_else(|| bad(format!("`{l}` before any element")))?;
                el.props.push(PlyProperty {
                    name: (*name).to_string(),
                    ty,
                    list_count: None,
                });
            }
            _ => return Err(bad(format!("cannot read header line `{l}`"))),
        }
    }
    let format = format.ok_or_else(|| bad("the header has no format line".into()))?;
    let vi = elements
        .iter()
        .position(|e| e.name == "vertex")
        .ok_or_else(|| bad("no `vertex` element".into()))?;
    let find = |names: &[&str]| {
        elements[vi]
            .props
            .iter()
            .position(|p| p.list_count.is_none() && names.contains(&p.name.as_str()))
    };
    let (Some(px), Some(py), Some(pz)) = (find(&["x"]), find(&["y"]), find(&["z"])) else {
        return Err(bad("the vertex element needs properties x, y and z".into()));
    };
    let pi = find(&["intensity", "scalar_intensity", "reflectance"]);
    let mut body = Vec::new();
    r.read_to_end(&mut body)
        .map_err(|e| LidarError::io(path, e))?;
    // Every vertex needs at least one byte (binary) or two characters (ASCII).
    let min_rec: usize = match format {
        PlyFormat::Ascii => 2 * elements[vi].props.len(),
        _ => elements[vi]
            .props
            .iter()
            .map(|p| p.list_count.unwrap_or(p.ty).size())
            .sum(),
    };
    if (elements[vi].count as u128) * (min_rec.max(1) as u128) > body.len() as u128 {
        return Err(bad(format!(
            "{} vertices cannot fit in the {} bytes after the header",
            elements[vi].count,
            body.len()
        )));
    }
    let mut src = PlySource::new(&body, format);
    let mut points = Vec::new();
    let mut intensity = pi.map(|_| Vec::new());
    let mut values = Vec::new();
    for (ei, el) in elements.iter().enumerate() {
        if ei > vi {
            break;
        }
        for k in 0..el.count {
            values.clear();
            for p in &el.props {
                let at = |what: &str| {
                    format!("element `{}` {k}, property `{}`: {what}", el.name, p.name)
                };
                if let Some(ct) = p.list_count {
                    let n = src
                        .value(ct)
                        .ok_or_else(|| bad(at("data ends or is not a number")))?;
                    if !(0.0..=1e6).contains(&n) || n.fract() != 0.0 {
                        return Err(bad(at(&format!("list length {n} is impossible"))));
                    }
                    for _ in 0..n as usize {
                        src.value(p.ty)
                            .ok_or_else(|| bad(at("data ends or is not a number")))?;
                    }
                    values.push(f64::NAN);
                } else {
                    values.push(
                        src.value(p.ty)
                            .ok_or_else(|| bad(at("data ends or is not a number")))?,
                    );
                }
            }
            if ei == vi {
                points.push([values[px] as f32, values[py] as f32, values[pz] as f32]);
                if let (Some(v), Some(i)) = (intensity.as_mut(), pi) {
                    v.push(values[i] as f32);
                }
            }
        }
    }
    Ok(PointCloud { points, intensity })
}

/// Reads PLY values one at a time from ASCII tokens or binary bytes.
struct PlySource<'a> {
    body: &'a [u8],
    pos: usize,
    format: PlyFormat,
}

impl<'a> PlySource<'a> {
    fn new(body: &'a [u8], format: PlyFormat) -> Self {
        PlySource {
            body,
            pos: 0,
            format,
        }
    }

    fn value(&mut self, ty: PlyType) -> Option<f64> {
        match self.format {
            PlyFormat::Ascii => {
                let b = self.body;
                while self.pos < b.len() && b[self.pos].is_ascii_whitespace() {
                    self.pos += 1;
                }
                let start = self.pos;
                while self.pos < b.len() && !b[self.pos].is_ascii_whitespace() {
                    self.pos += 1;
                }
                std::str::from_utf8(&b[start..self.pos])
                    .ok()?
                    .parse::<f64>()
                    .ok()
            }
            f => {
                let n = ty.size();
                let b = self.body.get(self.pos..self.pos + n)?;
                self.pos += n;
                Some(ty.read(b, f == PlyFormat::BinaryBigEndian))
            }
        }
    }
}

/// Write points as PLY, with a colour and a label per point when given.
pub fn write_ply(
    path: &Path,
    points: &[[f32; 3]],
    colours: Option<&[[u8; 3]]>,
    labels: Option<&[u32]>,
    format: PlyFormat,
) -> Result<()> {
    write_ply_with_intensity(path, points, colours, labels, None, format)
}

/// Write points as PLY, with a colour, a label (a signed 32-bit `int`
/// property, which Open3D and most readers keep) and an `intensity`
/// (`float`) per point when given.
pub fn write_ply_with_intensity(
    path: &Path,
    points: &[[f32; 3]],
    colours: Option<&[[u8; 3]]>,
    labels: Option<&[u32]>,
    intensity: Option<&[f32]>,
    format: PlyFormat,
) -> Result<()> {
    if let Some(l) = labels.and_then(|l| l.iter().find(|&&v| i32::try_from(v).is_err())) {
        return Err(LidarError::Config(format!(
            "{}: label {l} does not fit the signed 32-bit PLY label",
            path.display()
        )));
    }
    for (what, n) in [
        ("colours", colours.map(<[_]>::len)),
        ("labels", labels.map(<[_]>::len)),
        ("intensities", intensity.map(<[_]>::len)),
    ] {
        if let Some(n) = n {
            if n != points.len() {
                return Err(LidarError::Mismatch {
                    what: format!("{what} for the points of {}", path.display()),
                    expected: points.len(),
                    got: n,
                });
            }
        }
    }
    let mut w = fcc_io::AtomicFile::create(path).map_err(|e| LidarError::io(path, e))?;
    let io = |e| LidarError::io(path, e);
    let fmt = match format {
        PlyFormat::Ascii => "ascii",
        PlyFormat::BinaryLittleEndian => "binary_little_endian",
        PlyFormat::BinaryBigEndian => "binary_big_endian",
    };
    let mut header = format!(
        "ply\nformat {fmt} 1.0\ncomment written by fcc-lidar\nelement vertex {}\nproperty float x\nproperty float y\nproperty float z\n",
        points.len()
    );
    if colours.is_some() {
        header.push_str("property uchar red\nproperty uchar green\nproperty uchar blue\n");
    }
    if intensity.is_some() {
        header.push_str("property float intensity\n");
    }
    if labels.is_some() {
        header.push_str("property int label\n");
    }
    header.push_str("end_header\n");
    w.write_all(header.as_bytes()).map_err(io)?;
    let big = format == PlyFormat::BinaryBigEndian;
    for (i, p) in points.iter().enumerate() {
        if format == PlyFormat::Ascii {
            let mut l = format!("{} {} {}", p[0], p[1], p[2]);
            if let Some(c) = colours {
                l.push_str(&format!(" {} {} {}", c[i][0], c[i][1], c[i][2]));
            }
            if let Some(v) = intensity {
                l.push_str(&format!(" {}", v[i]));
            }
            if let Some(lab) = labels {
                l.push_str(&format!(" {}", lab[i]));
            }
            l.push('\n');
            w.write_all(l.as_bytes()).map_err(io)?;
        } else {
            for v in p {
                w.write_all(&if big {
                    v.to_be_bytes()
                } else {
                    v.to_le_bytes()
                })
                .map_err(io)?;
            }
            if let Some(c) = colours {
                w.write_all(&c[i]).map_err(io)?;
            }
            if let Some(v) = intensity {
                let v = v[i];
                w.write_all(&if big {
                    v.to_be_bytes()
                } else {
                    v.to_le_bytes()
                })
                .map_err(io)?;
            }
            if let Some(lab) = labels {
                let v = lab[i] as i32;
                w.write_all(&if big {
                    v.to_be_bytes()
                } else {
                    v.to_le_bytes()
                })
                .map_err(io)?;
            }
        }
    }
    w.commit().map_err(io)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn format_from_extension() {
        assert_eq!(
            CloudFormat::from_path(Path::new("a/000001.BIN")),
            Some(CloudFormat::KittiBin)
        );
        assert_eq!(
            CloudFormat::from_path(Path::new("x.pcd")),
            Some(CloudFormat::Pcd)
        );
        assert_eq!(
            CloudFormat::from_path(Path::new("x.ply")),
            Some(CloudFormat::Ply)
        );
        assert_eq!(CloudFormat::from_path(Path::new("x.las")), None);
        let err = read_point_cloud(Path::new("x.las"))
            .unwrap_err()
            .to_string();
        assert!(
            err.contains("x.las") && err.contains("unknown point-cloud extension"),
            "{err}"
        );
    }
}
