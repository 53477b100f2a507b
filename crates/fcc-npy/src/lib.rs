//! NumPy `.npy` files as FCC exchanges them.
//!
//! * point frames: shape `(R, C, 3)`, `float32` or `float64`, either byte
//!   order, C order; NaN marks an empty pixel;
//! * label images: shape `(R, C)`, written as little-endian `uint32`, read
//!   from any 8/16/32/64-bit integer type whose values fit in `u32`.
//!
//! The format is small enough that a reader written against the published
//! format description (versions 1.0, 2.0 and 3.0) gives better errors than a
//! general array library: every error names the file and the problem.

use std::fs;
use std::path::{Path, PathBuf};
use thiserror::Error;

const MAGIC: &[u8] = b"\x93NUMPY";

/// A problem with one `.npy` file.
#[derive(Debug, Error)]
#[error("{}: {problem}", path.display())]
pub struct NpyError {
    pub path: PathBuf,
    pub problem: String,
}

fn err(path: &Path, problem: impl Into<String>) -> NpyError {
    NpyError {
        path: path.to_path_buf(),
        problem: problem.into(),
    }
}

/// Element type and byte order of an array.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Dtype {
    Float {
        bytes: usize,
        big: bool,
    },
    Int {
        bytes: usize,
        signed: bool,
        big: bool,
    },
}

impl Dtype {
    fn parse(descr: &str) -> Option<Dtype> {
        let (order, rest) = descr.split_at(1.min(descr.len()));
        let big = match order {
            "<" | "|" | "=" => false,
            ">" => true,
            _ => return None,
        };
        let (kind, size) = rest.split_at(1.min(rest.len()));
        let bytes: usize = size.parse().ok()?;
        match (kind, bytes) {
            ("f", 4 | 8) => Some(Dtype::Float { bytes, big }),
            ("i", 1 | 2 | 4 | 8) => Some(Dtype::Int {
                bytes,
                signed: true,
                big,
            }),
            ("u", 1 | 2 | 4 | 8) => Some(Dtype::Int {
                bytes,
                signed: false,
                big,
            }),
            _ => None,
        }
    }

    fn size(self) -> usize {
        match self {
            Dtype::Float { bytes, .. } | Dtype::Int { bytes, .. } => bytes,
        }
    }
}

/// A parsed `.npy` file: its header and raw data bytes.
#[derive(Debug)]
pub struct Npy {
    pub descr: String,
    pub dtype: Dtype,
    pub shape: Vec<usize>,
    data: Vec<u8>,
}

/// The value of `'key': value` in the header dictionary, as text.
fn dict_value<'a>(header: &'a str, key: &str) -> Option<&'a str> {
    let pat_sq = format!("'{key}'");
    let pat_dq = format!("\"{key}\"");
    let start = header.find(&pat_sq).or_else(|| header.find(&pat_dq))? + key.len() + 2;
    let rest = header[start..].trim_start().strip_prefix(':')?.trim_start();
    if rest.starts_with('(') {
        rest.find(')').map(|e| &rest[..=e])
    } else {
        let end = rest.find([',', '}']).unwrap_or(rest.len());
        Some(rest[..end].trim())
    }
}

/// Parse `.npy` bytes; `path` is used only for messages.
pub fn parse(path: &Path, bytes: Vec<u8>) -> Result<Npy, NpyError> {
    if bytes.len() < 10 || &bytes[..6] != MAGIC {
        return Err(err(path, "not a .npy file (missing the \\x93NUMPY magic)"));
    }
    let major = bytes[6];
    let (header_len, header_start) = match major {
        1 => (usize::from(u16::from_le_bytes([bytes[8], bytes[9]])), 10),
        2 | 3 => {
            if bytes.len() < 12 {
                return Err(err(path, "truncated header"));
            }
            let n = u32::from_le_bytes([bytes[8], bytes[9], bytes[10], bytes[11]]);
            (n as usize, 12)
        }
        v => return Err(err(path, format!("unsupported .npy format version {v}"))),
    };
    let data_start = header_start + header_len;
    if bytes.len() < data_start {
        return Err(err(path, "truncated header"));
    }
    let header = std::str::from_utf8(&bytes[header_start..data_start])
        .map_err(|_| err(path, "header is not text"))?;
    let descr_raw =
        dict_value(header, "descr").ok_or_else(|| err(path, "header has no 'descr'"))?;
    let descr = descr_raw
        .trim_matches(|c| c == '\'' || c == '"')
        .to_string();
    let dtype =
        Dtype::parse(&descr).ok_or_else(|| err(path, format!("unsupported dtype '{descr}'")))?;
    let fortran = dict_value(header, "fortran_order")
        .ok_or_else(|| err(path, "header has no 'fortran_order'"))?;
    if fortran != "False" {
        return Err(err(
            path,
            "Fortran-order arrays are not supported: save with C order (np.ascontiguousarray)",
        ));
    }
    let shape_txt =
        dict_value(header, "shape").ok_or_else(|| err(path, "header has no 'shape'"))?;
    let shape = shape_txt
        .trim_start_matches('(')
        .trim_end_matches(')')
        .split(',')
        .map(str::trim)
        .filter(|s| !s.is_empty())
        .map(|s| s.trim_end_matches('L').parse::<usize>())
        .collect::<Result<Vec<_>, _>>()
        .map_err(|_| err(path, format!("bad shape {shape_txt}")))?;
    let count = shape
        .iter()
        .try_fold(1usize, |a, &d| a.checked_mul(d))
        .ok_or_else(|| err(path, "shape too large"))?;
    let need = count
        .checked_mul(dtype.size())
        .ok_or_else(|| err(path, "shape too large"))?;
    let have = bytes.len() - data_start;
    if have < need {
        return Err(err(
            path,
            format!(
                "truncated: shape {shape:?} of {descr} needs {need} data bytes, file has {have}"
            ),
        ));
    }
    if have > need {
        return Err(err(
            path,
            format!("{} bytes after the array data", have - need),
        ));
    }
    let data = bytes[data_start..].to_vec();
    Ok(Npy {
        descr,
        dtype,
        shape,
        data,
    })
}

/// Read and parse a `.npy` file.
pub fn read(path: &Path) -> Result<Npy, NpyError> {
    let bytes = fs::read(path).map_err(|e| err(path, format!("cannot read: {e}")))?;
    parse(path, bytes)
}

fn word<const N: usize>(chunk: &[u8], big: bool) -> [u8; N] {
    let mut b = [0u8; N];
    b.copy_from_slice(chunk);
    if big {
        b.reverse();
    }
    b
}

/// A point frame: `rows * cols * 3` coordinates in metres, NaN = empty.
#[derive(Debug, Clone, PartialEq)]
pub struct XyzImage {
    pub rows: usize,
    pub cols: usize,
    pub xyz: Vec<f64>,
}

/// Read a `(R, C, 3)` float32/float64 point frame.
pub fn read_xyz(path: &Path) -> Result<XyzImage, NpyError> {
    let npy = read(path)?;
    let &[rows, cols, 3] = npy.shape.as_slice() else {
        return Err(err(
            path,
            format!("shape {:?} is not (rows, cols, 3)", npy.shape),
        ));
    };
    if rows == 0 || cols == 0 {
        return Err(err(path, format!("shape {:?} has no pixels", npy.shape)));
    }
    let xyz = match npy.dtype {
        Dtype::Float { bytes: 4, big } => npy
            .data
            .chunks_exact(4)
            .map(|c| f64::from(f32::from_le_bytes(word(c, big))))
            .collect(),
        Dtype::Float { bytes: 8, big } => npy
            .data
            .chunks_exact(8)
            .map(|c| f64::from_le_bytes(word(c, big)))
            .collect(),
        _ => {
            return Err(err(
                path,
                format!("dtype '{}' is not float32 or float64", npy.descr),
            ))
        }
    };
    Ok(XyzImage { rows, cols, xyz })
}

/// A label image: `rows * cols` labels.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct LabelImage {
    pub rows: usize,
    pub cols: usize,
    pub labels: Vec<u32>,
}

/// Read a `(R, C)` integer label image; every value must fit in `u32`.
pub fn read_labels(path: &Path) -> Result<LabelImage, NpyError> {
    let npy = read(path)?;
    let &[rows, cols] = npy.shape.as_slice() else {
        return Err(err(
            path,
            format!("shape {:?} is not (rows, cols)", npy.shape),
        ));
    };
    let Dtype::Int { bytes, signed, big } = npy.dtype else {
        return Err(err(
            path,
            format!("dtype '{}' is not an integer type", npy.descr),
        ));
    };
    let mut labels = Vec::with_capacity(rows * cols);
    for (i, c) in npy.data.chunks_exact(bytes).enumerate() {
        let v: i128 = match (bytes, signed) {
            (1, false) => i128::from(c[0]),
            (1, true) => i128::from(c[0] as i8),
            (2, false) => i128::from(u16::from_le_bytes(word(c, big))),
            (2, true) => i128::from(i16::from_le_bytes(word(c, big))),
            (4, false) => i128::from(u32::from_le_bytes(word(c, big))),
            (4, true) => i128::from(i32::from_le_bytes(word(c, big))),
            (8, false) => i128::from(u64::from_le_bytes(word(c, big))),
            _ => i128::from(i64::from_le_bytes(word(c, big))),
        };
        let v = u32::try_from(v).map_err(|_| {
            err(
                path,
                format!(
                    "label {v} at row {}, col {} does not fit in uint32",
                    i / cols,
                    i % cols
                ),
            )
        })?;
        labels.push(v);
    }
    Ok(LabelImage { rows, cols, labels })
}

fn header(descr: &str, shape: &[usize]) -> Vec<u8> {
    let dims: Vec<String> = shape.iter().map(usize::to_string).collect();
    let shape_txt = if dims.len() == 1 {
        format!("({},)", dims[0])
    } else {
        format!("({})", dims.join(", "))
    };
    let mut dict =
        format!("{{'descr': '{descr}', 'fortran_order': False, 'shape': {shape_txt}, }}");
    // Pad with spaces so the data starts on a 64-byte boundary; end with '\n'.
    let total = MAGIC.len() + 4 + dict.len() + 1;
    dict.push_str(&" ".repeat((64 - total % 64) % 64));
    dict.push('\n');
    let mut out = MAGIC.to_vec();
    out.extend([1u8, 0]);
    out.extend((dict.len() as u16).to_le_bytes());
    out.extend(dict.as_bytes());
    out
}

fn write_file(path: &Path, bytes: &[u8]) -> Result<(), NpyError> {
    fcc_io::write_atomic(path, bytes).map_err(|e| err(path, format!("cannot write: {e}")))
}

/// Write a `(R, C)` little-endian uint32 label image.
pub fn write_labels(path: &Path, rows: usize, cols: usize, labels: &[u32]) -> Result<(), NpyError> {
    assert_eq!(labels.len(), rows * cols, "label image size");
    let mut out = header("<u4", &[rows, cols]);
    out.reserve(labels.len() * 4);
    for l in labels {
        out.extend(l.to_le_bytes());
    }
    write_file(path, &out)
}

/// Write a `(R, C, 3)` little-endian float32 point frame.
pub fn write_xyz_f32(path: &Path, rows: usize, cols: usize, xyz: &[f32]) -> Result<(), NpyError> {
    assert_eq!(xyz.len(), rows * cols * 3, "point frame size");
    let mut out = header("<f4", &[rows, cols, 3]);
    out.reserve(xyz.len() * 4);
    for v in xyz {
        out.extend(v.to_le_bytes());
    }
    write_file(path, &out)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A file `name` in a scratch directory of its own, removed with it.
    fn tmp(name: &str) -> (fcc_testkit::Scratch, PathBuf) {
        let dir = fcc_testkit::tmpdir(name);
        let path = dir.join(name);
        (dir, path)
    }

    #[test]
    fn xyz_round_trip_f32() {
        let (_dir, p) = tmp("a.npy");
        let xyz = [1.5f32, -2.0, f32::NAN, 0.0, 0.25, 3.0];
        write_xyz_f32(&p, 1, 2, &xyz).unwrap();
        let img = read_xyz(&p).unwrap();
        assert_eq!((img.rows, img.cols), (1, 2));
        assert_eq!(img.xyz[0], 1.5);
        assert!(img.xyz[2].is_nan());
        let raw = fs::read(&p).unwrap();
        assert_eq!((raw.len() - 6 * 4) % 64, 0, "data is 64-byte aligned");
    }

    #[test]
    fn labels_round_trip() {
        let (_dir, p) = tmp("l.npy");
        write_labels(&p, 2, 2, &[0, 1, 70000, 3]).unwrap();
        let l = read_labels(&p).unwrap();
        assert_eq!(l.labels, vec![0, 1, 70000, 3]);
    }

    fn with_header(descr: &str, shape: &str, data: &[u8]) -> Vec<u8> {
        let dict = format!("{{'descr': '{descr}', 'fortran_order': False, 'shape': {shape}, }}\n");
        let mut out = MAGIC.to_vec();
        out.extend([1u8, 0]);
        out.extend((dict.len() as u16).to_le_bytes());
        out.extend(dict.as_bytes());
        out.extend(data);
        out
    }

    #[test]
    fn big_endian_f64_is_read() {
        let data: Vec<u8> = [1.0f64, 2.0, 3.0]
            .iter()
            .flat_map(|v| v.to_be_bytes())
            .collect();
        let (_dir, p) = tmp("be.npy");
        fs::write(&p, with_header(">f8", "(1, 1, 3)", &data)).unwrap();
        assert_eq!(read_xyz(&p).unwrap().xyz, vec![1.0, 2.0, 3.0]);
    }

    #[test]
    fn errors_name_the_file_and_the_problem() {
        let (_dir, p) = tmp("bad.npy");
        fs::write(&p, b"hello world, not numpy").unwrap();
        let e = read_xyz(&p).unwrap_err().to_string();
        assert!(e.starts_with(&p.display().to_string()), "{e}");
        assert!(
            e.ends_with("not a .npy file (missing the \\x93NUMPY magic)"),
            "{e}"
        );

        fs::write(&p, with_header("<f4", "(2, 3)", &[0u8; 24])).unwrap();
        assert!(read_xyz(&p)
            .unwrap_err()
            .to_string()
            .ends_with("shape [2, 3] is not (rows, cols, 3)"));

        fs::write(&p, with_header("<i4", "(1, 1, 3)", &[0u8; 12])).unwrap();
        assert!(read_xyz(&p)
            .unwrap_err()
            .to_string()
            .ends_with("dtype '<i4' is not float32 or float64"));

        fs::write(&p, with_header("<f4", "(2, 2, 3)", &[0u8; 40])).unwrap();
        let e = read_xyz(&p).unwrap_err().to_string();
        assert!(
            e.ends_with("truncated: shape [2, 2, 3] of <f4 needs 48 data bytes, file has 40"),
            "{e}"
        );

        fs::write(&p, with_header("<c8", "(1, 1, 3)", &[0u8; 24])).unwrap();
        assert!(read_xyz(&p)
            .unwrap_err()
            .to_string()
            .ends_with("unsupported dtype '<c8'"));

        let mut h = with_header("<f4", "(1, 1, 3)", &[0u8; 12]);
        h.truncate(20);
        fs::write(&p, h).unwrap();
        assert!(read_xyz(&p)
            .unwrap_err()
            .to_string()
            .ends_with("truncated header"));

        let (_dir, missing) = tmp("does-not-exist.npy");
        assert!(read_xyz(&missing)
            .unwrap_err()
            .to_string()
            .contains("cannot read"));
    }

    #[test]
    fn negative_labels_are_rejected() {
        let (_dir, p) = tmp("neg.npy");
        let data: Vec<u8> = [1i32, -1].iter().flat_map(|v| v.to_le_bytes()).collect();
        fs::write(&p, with_header("<i4", "(1, 2)", &data)).unwrap();
        let e = read_labels(&p).unwrap_err().to_string();
        assert!(
            e.ends_with("label -1 at row 0, col 1 does not fit in uint32"),
            "{e}"
        );
    }

    #[test]
    fn fortran_order_is_rejected() {
        let (_dir, p) = tmp("f.npy");
        let dict = "{'descr': '<f4', 'fortran_order': True, 'shape': (1, 1, 3), }\n";
        let mut out = MAGIC.to_vec();
        out.extend([1u8, 0]);
        out.extend((dict.len() as u16).to_le_bytes());
        out.extend(dict.as_bytes());
        out.extend([0u8; 12]);
        fs::write(&p, out).unwrap();
        assert!(read_xyz(&p)
            .unwrap_err()
            .to_string()
            .contains("Fortran-order"));
    }
}
