//! The FCC golden model: Fast Channel Clustering of LiDAR range images in
//! integer fixed point.
//!
//! This crate is the executable form of the contract in `docs/spec.md`; the
//! section numbers below refer to it. The RTL must reproduce
//! [`cluster`]`(.., MergeMode::Exact)` bit for bit.
//!
//! ```
//! use fcc_golden::{cluster, Frame, MergeMode};
//! use fcc_params::FccParams;
//!
//! let params = FccParams { rows: 2, cols: 3, fsize: 3, ..FccParams::default() };
//! // Two points 0.25 m apart on row 0, one point under the first on row 1.
//! let xyz = [
//!     10.0, 0.0, 0.0,  10.0, 0.25, 0.0,  f64::NAN, 0.0, 0.0,
//!     10.0, 0.0, -0.5, f64::NAN, 0.0, 0.0, f64::NAN, 0.0, 0.0,
//! ];
//! let frame = Frame::from_xyz_f64(2, 3, &xyz);
//! let out = cluster(&params, &frame, MergeMode::Exact).unwrap();
//! assert_eq!(out.labels, vec![1, 1, 0, 1, 0, 0]);
//! assert_eq!(out.clusters, 1);
//! ```

mod exact;
mod frame;
mod merge;
mod pass1;
mod pass2;
mod records;
/// The pixel-level reference used by tests; not for production use.
pub mod reference;
mod stream;
mod threshold;

pub use frame::{dist2, quantize, quantize_point, Frame, Point};
pub use merge::{renumber, ExactMerge, PaperMerge};
pub use pass1::{pass1, pass1_released, runs_needed, Pass1, Run};
pub use pass2::{pass2, JoinSink};
use pass2::{pass2_with, Pass2Buffers};
pub use records::{frame_records, oriented_box, Acc, OrientedBox, Record};
pub use stream::{column_window, Stream, StreamStats};
pub use threshold::{coarse_metres, coarse_range2, point_threshold, Thresholds, COARSE_MAX};

use fcc_params::{FccParams, ParamError};
use serde::{Deserialize, Serialize};
use thiserror::Error;

/// How joins become final labels.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum MergeMode {
    /// Exact connected components (the contract; what the hardware matches).
    #[default]
    Exact,
    /// The published Algorithm 2 merge table, which can split components.
    Paper,
}

impl std::str::FromStr for MergeMode {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "exact" => Ok(MergeMode::Exact),
            "paper" => Ok(MergeMode::Paper),
            _ => Err(format!(
                "unknown merge mode `{s}`: expected `exact` or `paper`"
            )),
        }
    }
}

/// Why the golden model refused a frame.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum GoldenError {
    #[error(transparent)]
    Params(#[from] ParamError),
    #[error("frame is {got_rows} x {got_cols} but the parameters say {rows} x {cols}")]
    Shape {
        rows: usize,
        cols: usize,
        got_rows: usize,
        got_cols: usize,
    },
    #[error("open_limit = {0} applies to the stream only: frame mode holds every cluster open until the frame ends (spec §9.1)")]
    StreamOnly(u32),
    #[error("a column holds {got} pixels, the frame has {rows} rows")]
    ColumnLength { rows: usize, got: usize },
    #[error("the frame already has its {cols} columns: finish it before the next")]
    TooManyColumns { cols: usize },
    #[error("the frame has {got} of its {cols} columns")]
    Unfinished { cols: usize, got: usize },
    #[error("frame holds {got} pixels, {rows} x {cols} needs {expected}")]
    Length {
        rows: usize,
        cols: usize,
        expected: usize,
        got: usize,
    },
}

/// The result of clustering one frame.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Clustering {
    pub rows: usize,
    pub cols: usize,
    /// Final label per pixel in raster order: 0 empty or unlabelled,
    /// otherwise 1..=clusters in raster order of each cluster's first pixel.
    #[serde(skip)]
    pub labels: Vec<u32>,
    /// Valid pixels in the frame.
    pub points: usize,
    /// Clusters in the output.
    pub clusters: u32,
    /// Provisional labels allocated by pass 1.
    pub provisional: u32,
    /// Pass-2 pairs that passed the threshold.
    pub joins: u64,
    /// Joins (ring checks included) that united two different components;
    /// for `paper` merging, 0.
    pub merges: u64,
    /// Provisional labels ran out.
    pub overflow: bool,
    /// Valid pixels left with label 0 by overflow.
    pub unlabelled: usize,
}

/// Cluster one frame: pass 1, pass 2, then the chosen merge and renumbering.
pub fn cluster(
    params: &FccParams,
    frame: &Frame,
    mode: MergeMode,
) -> Result<Clustering, GoldenError> {
    cluster_with(&mut Workspace::default(), params, frame, mode)
}

/// The buffers of [`cluster_with`], kept from one frame to the next. With
/// one workspace per thread, and each result handed back by
/// [`recycle`](Self::recycle), clustering (`exact` or `paper`) allocates
/// nothing per frame once the buffers have grown to the frame size.
#[derive(Debug, Clone, Default)]
pub struct Workspace {
    exact: exact::Exact,
    p1: Pass1,
    paper: PaperMerge,
    pass2: Pass2Buffers,
    rep: Vec<u32>,
    id: Vec<u32>,
    labels: Vec<u32>,
}

impl Workspace {
    /// Give a finished result's label buffer back for the next frame.
    pub fn recycle(&mut self, done: Clustering) {
        self.labels = done.labels;
    }
}

/// As [`cluster`], reusing the buffers of `ws`.
pub fn cluster_with(
    ws: &mut Workspace,
    params: &FccParams,
    frame: &Frame,
    mode: MergeMode,
) -> Result<Clustering, GoldenError> {
    params.validate()?;
    if let Some(s) = params.open_limit {
        return Err(GoldenError::StreamOnly(s));
    }
    if frame.rows != params.rows || frame.cols != params.cols {
        return Err(GoldenError::Shape {
            rows: params.rows,
            cols: params.cols,
            got_rows: frame.rows,
            got_cols: frame.cols,
        });
    }
    if frame.points.len() != params.pixels() {
        return Err(GoldenError::Length {
            rows: params.rows,
            cols: params.cols,
            expected: params.pixels(),
            got: frame.points.len(),
        });
    }
    match mode {
        MergeMode::Exact => {
            let mut labels = std::mem::take(&mut ws.labels);
            let s = ws.exact.run(params, frame, &mut labels);
            Ok(Clustering {
                rows: frame.rows,
                cols: frame.cols,
                labels,
                points: s.points,
                clusters: s.clusters,
                provisional: s.provisional,
                joins: s.joins,
                merges: s.merges,
                overflow: s.overflow,
                unlabelled: s.unlabelled,
            })
        }
        MergeMode::Paper => {
            let p1 = &mut ws.p1;
            p1.labels = std::mem::take(&mut ws.labels);
            pass1::label_runs(params, frame, pass1::RingHandling::Relabel, p1);
            let m = &mut ws.paper;
            m.reset(p1.provisional);
            let joins = pass2_with(&mut ws.pass2, params, frame, p1, m);
            m.representatives_into(&mut ws.rep);
            let clusters = merge::renumber_runs(p1, frame.cols, &ws.rep, &mut ws.id);
            Ok(Clustering {
                rows: frame.rows,
                cols: frame.cols,
                labels: std::mem::take(&mut p1.labels),
                points: p1.points,
                clusters,
                provisional: p1.provisional,
                joins,
                merges: 0,
                overflow: p1.overflow,
                unlabelled: p1.unlabelled,
            })
        }
    }
}

/// Whether two label images are the same partition: a bijection between
/// their non-zero labels, zeros in the same places.
pub fn same_partition(a: &[u32], b: &[u32]) -> bool {
    use std::collections::HashMap;
    let (mut ab, mut ba) = (HashMap::new(), HashMap::new());
    a.len() == b.len()
        && a.iter().zip(b).all(|(&x, &y)| {
            (x == 0) == (y == 0) && *ab.entry(x).or_insert(y) == y && *ba.entry(y).or_insert(x) == x
        })
}

/// Components of `reference` that `got` splits into more than one label:
/// the measure of what the published merge table loses. Both are label
/// images of the same frame; 0 is ignored.
pub fn split_components(reference: &[u32], got: &[u32]) -> usize {
    use std::collections::HashMap;
    let mut first: HashMap<u32, u32> = HashMap::new();
    let mut split: std::collections::HashSet<u32> = Default::default();
    for (&r, &g) in reference.iter().zip(got) {
        if r == 0 {
            continue;
        }
        let f = *first.entry(r).or_insert(g);
        if f != g {
            split.insert(r);
        }
    }
    split.len()
}
