//! The per-cluster table (`--clusters FILE.csv|.json`): one row per cluster
//! per frame, what a tracker takes as its detections.

use crate::error::{LidarError, Result};
use fcc_golden::{frame_records, oriented_box, Frame, OrientedBox, Point, Record};
use fcc_params::FccParams;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::path::Path;

/// One cluster of one frame. Coordinates in metres, in the frame of the
/// input (x forward, y left, z up for sensors).
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct ClusterRow {
    /// Input stem, with `_f<frame>` for capture frames.
    pub frame: String,
    /// Cluster id, as in the label outputs (1..=n).
    pub cluster: u32,
    pub points: usize,
    pub centroid_x: f64,
    pub centroid_y: f64,
    pub centroid_z: f64,
    pub min_x: f32,
    pub min_y: f32,
    pub min_z: f32,
    pub max_x: f32,
    pub max_y: f32,
    pub max_z: f32,
    /// Distance from the sensor of the closest and farthest point.
    pub range_min: f32,
    pub range_max: f32,
    /// The cluster's first pixel in raster order (row 0 the top beam).
    pub first_row: usize,
    pub first_col: usize,
    /// The record of spec §9.3, from the Q7.8 pixels of the cluster:
    /// column span (wrapped for a seam cluster), the column at which it
    /// closed (`C` at the frame end), whether a ring check joined it, its
    /// last row, the principal-axis heading of its bird's-eye covariance
    /// and the minimum-area oriented box of its bird's-eye points (centre,
    /// length >= width, yaw of the length, radians).
    pub span_first_col: u32,
    pub span_last_col: u32,
    pub closed_col: u32,
    pub seam: bool,
    pub last_row: u32,
    pub heading: f64,
    pub box_cx: f64,
    pub box_cy: f64,
    pub box_length: f64,
    pub box_width: f64,
    pub box_yaw: f64,
}

impl ClusterRow {
    /// Fill the record fields from the cluster's record and oriented box.
    pub fn set_record(&mut self, r: &Record, obb: Option<&OrientedBox>) {
        self.span_first_col = r.first_col;
        self.span_last_col = r.last_col;
        self.closed_col = r.closed_col;
        self.seam = r.seam;
        self.last_row = r.last_row;
        self.heading = r.heading();
        let b = obb.copied().unwrap_or(OrientedBox {
            center: [0.0; 2],
            size: [0.0; 2],
            yaw: 0.0,
            z: [0.0; 2],
        });
        (self.box_cx, self.box_cy) = (b.center[0], b.center[1]);
        (self.box_length, self.box_width, self.box_yaw) = (b.size[0], b.size[1], b.yaw);
    }

    /// The row of a record alone (the stream's: no input points, only the
    /// Q7.8 pixels the record sums). `first_row`, `first_col` are the first
    /// pixel of its first row.
    pub fn from_record(
        frame: &str,
        r: &Record,
        obb: Option<&OrientedBox>,
        first_col: usize,
    ) -> ClusterRow {
        let c = r.centroid();
        let [lo, hi] = r.bounds();
        let range = r.range();
        let mut row = ClusterRow {
            frame: frame.to_string(),
            cluster: r.id,
            points: r.points as usize,
            centroid_x: c[0],
            centroid_y: c[1],
            centroid_z: c[2],
            min_x: lo[0] as f32,
            min_y: lo[1] as f32,
            min_z: lo[2] as f32,
            max_x: hi[0] as f32,
            max_y: hi[1] as f32,
            max_z: hi[2] as f32,
            range_min: range[0] as f32,
            range_max: range[1] as f32,
            first_row: r.first_row as usize,
            first_col,
            ..ClusterRow::default()
        };
        row.set_record(r, obb);
        row
    }
}

/// The record and oriented box of every cluster of a frame (frame mode):
/// `labels` numbers the clusters `1 ..= clusters` over `frame`'s pixels.
pub fn frame_cluster_records(
    params: &FccParams,
    frame: &Frame,
    labels: &[u32],
    clusters: u32,
) -> Vec<(Record, Option<OrientedBox>)> {
    let records = frame_records(params, frame, labels, clusters, 0);
    let mut points: Vec<Vec<Point>> = vec![Vec::new(); clusters as usize + 1];
    for (p, &l) in frame.points.iter().zip(labels) {
        if let (Some(p), true) = (p, l != 0) {
            points[l as usize].push(*p);
        }
    }
    records
        .into_iter()
        .map(|r| {
            let b = oriented_box(&points[r.id as usize]);
            (r, b)
        })
        .collect()
}

/// The clusters of one frame: `points` with their `labels` (0 = none; the
/// points of the PLY and `.label` outputs), and the label image
/// (`pixel_labels`, `cols` wide) for the first pixels.
pub fn cluster_rows(
    frame: &str,
    points: &[[f32; 3]],
    labels: &[u32],
    pixel_labels: &[u32],
    cols: usize,
) -> Result<Vec<ClusterRow>> {
    if points.len() != labels.len() {
        return Err(LidarError::Mismatch {
            what: format!("labels for the points of {frame}"),
            expected: points.len(),
            got: labels.len(),
        });
    }
    let mut first: BTreeMap<u32, usize> = BTreeMap::new();
    for (i, &l) in pixel_labels.iter().enumerate() {
        if l != 0 {
            first.entry(l).or_insert(i);
        }
    }
    let mut rows: BTreeMap<u32, RowAcc> = BTreeMap::new();
    for (p, &l) in points.iter().zip(labels) {
        if l == 0 || !p.iter().all(|v| v.is_finite()) {
            continue;
        }
        rows.entry(l)
            .or_insert_with(|| {
                let px = first.get(&l).copied().unwrap_or(0);
                RowAcc::new(frame, l, px, cols)
            })
            .add(*p);
    }
    Ok(rows.into_values().map(RowAcc::finish).collect())
}

/// One cluster's row being summed from its points (in raster order: the
/// order fixes the bits of the centroid), before its record is set.
#[derive(Debug, Clone)]
pub struct RowAcc {
    row: ClusterRow,
    sum: [f64; 3],
    /// Lowest and highest squared distance from the sensor (the square
    /// root is monotonic and correctly rounded, so the root of the extreme
    /// is the extreme of the roots).
    range_sq: [f32; 2],
}

impl RowAcc {
    /// Cluster `cluster` of `frame`, whose first pixel in raster order is
    /// `first_px` of an image `cols` wide.
    pub fn new(frame: &str, cluster: u32, first_px: usize, cols: usize) -> RowAcc {
        RowAcc {
            row: ClusterRow {
                frame: frame.to_string(),
                cluster,
                points: 0,
                centroid_x: 0.0,
                centroid_y: 0.0,
                centroid_z: 0.0,
                min_x: f32::INFINITY,
                min_y: f32::INFINITY,
                min_z: f32::INFINITY,
                max_x: f32::NEG_INFINITY,
                max_y: f32::NEG_INFINITY,
                max_z: f32::NEG_INFINITY,
                range_min: f32::INFINITY,
                range_max: 0.0,
                first_row: first_px / cols.max(1),
                first_col: first_px % cols.max(1),
                ..ClusterRow::default()
            },
            sum: [0.0; 3],
            range_sq: [f32::INFINITY, 0.0],
        }
    }

    /// Take in one (finite) point of the cluster.
    #[inline]
    pub fn add(&mut self, p: [f32; 3]) {
        // Plain comparisons: the points are finite, so no NaN rule is needed.
        fn lower(m: &mut f32, v: f32) {
            if v < *m {
                *m = v;
            }
        }
        fn raise(m: &mut f32, v: f32) {
            if v > *m {
                *m = v;
            }
        }
        let (row, sum) = (&mut self.row, &mut self.sum);
        let r2 = p[0] * p[0] + p[1] * p[1] + p[2] * p[2];
        row.points += 1;
        for k in 0..3 {
            sum[k] += f64::from(p[k]);
        }
        lower(&mut row.min_x, p[0]);
        lower(&mut row.min_y, p[1]);
        lower(&mut row.min_z, p[2]);
        raise(&mut row.max_x, p[0]);
        raise(&mut row.max_y, p[1]);
        raise(&mut row.max_z, p[2]);
        lower(&mut self.range_sq[0], r2);
        raise(&mut self.range_sq[1], r2);
    }

    /// The row, with its centroid.
    pub fn finish(self) -> ClusterRow {
        let (mut row, sum) = (self.row, self.sum);
        let n = row.points as f64;
        row.centroid_x = sum[0] / n;
        row.centroid_y = sum[1] / n;
        row.centroid_z = sum[2] / n;
        if row.points > 0 {
            row.range_min = self.range_sq[0].sqrt();
            row.range_max = self.range_sq[1].sqrt();
        }
        row
    }
}

/// The CSV header, in [`ClusterRow`] field order.
pub const CSV_HEADER: &str = "frame,cluster,points,centroid_x,centroid_y,centroid_z,min_x,min_y,min_z,max_x,max_y,max_z,range_min,range_max,first_row,first_col,span_first_col,span_last_col,closed_col,seam,last_row,heading,box_cx,box_cy,box_length,box_width,box_yaw";

/// Write the table: CSV for a `.csv` name, JSON (an array of objects) for
/// `.json`; anything else is an error.
pub fn write_cluster_table(path: &Path, rows: &[ClusterRow]) -> Result<()> {
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    let text = match ext.as_deref() {
        Some("csv") => {
            let mut s = String::from(CSV_HEADER);
            s.push('\n');
            for r in rows {
                // Frame names come from file stems: quote them when needed.
                let frame = if r.frame.contains([',', '"', '\n']) {
                    format!("\"{}\"", r.frame.replace('"', "\"\""))
                } else {
                    r.frame.clone()
                };
                s.push_str(&format!(
                    "{frame},{},{},{:.4},{:.4},{:.4},{:.4},{:.4},{:.4},{:.4},{:.4},{:.4},{:.4},{:.4},{},{},{},{},{},{},{},{:.4},{:.4},{:.4},{:.4},{:.4},{:.4}\n",
                    r.cluster,
                    r.points,
                    r.centroid_x,
                    r.centroid_y,
                    r.centroid_z,
                    r.min_x,
                    r.min_y,
                    r.min_z,
                    r.max_x,
                    r.max_y,
                    r.max_z,
                    r.range_min,
                    r.range_max,
                    r.first_row,
                    r.first_col,
                    r.span_first_col,
                    r.span_last_col,
                    r.closed_col,
                    r.seam,
                    r.last_row,
                    r.heading,
                    r.box_cx,
                    r.box_cy,
                    r.box_length,
                    r.box_width,
                    r.box_yaw
                ));
            }
            s
        }
        Some("json") => serde_json::to_string_pretty(rows)
            .map_err(|e| LidarError::Config(format!("{}: {e}", path.display())))?,
        _ => {
            return Err(LidarError::Config(format!(
                "{}: the cluster table is written as .csv or .json: name the file so",
                path.display()
            )))
        }
    };
    fcc_io::write_atomic(path, text.as_bytes()).map_err(|e| LidarError::io(path, e))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_clusters_hand_worked() {
        let points = [
            [1.0, 0.0, 0.0],
            [3.0, 0.0, 0.0],
            [0.0, 4.0, 3.0],
            [9.0, 9.0, 9.0],
        ];
        let labels = [2, 2, 1, 0];
        // 2 x 2 label image: cluster 1 first at pixel 1, cluster 2 at pixel 2.
        let pixels = [0, 1, 2, 2];
        let rows = cluster_rows("f", &points, &labels, &pixels, 2).unwrap();
        assert_eq!(rows.len(), 2);
        let (a, b) = (&rows[0], &rows[1]);
        assert_eq!(
            (a.cluster, a.points, a.first_row, a.first_col),
            (1, 1, 0, 1)
        );
        assert_eq!((a.range_min, a.range_max), (5.0, 5.0));
        assert_eq!(
            (b.cluster, b.points, b.first_row, b.first_col),
            (2, 2, 1, 0)
        );
        assert_eq!((b.centroid_x, b.min_x, b.max_x), (2.0, 1.0, 3.0));
        assert_eq!((b.range_min, b.range_max), (1.0, 3.0));
        assert!(cluster_rows("f", &points, &labels[..2], &pixels, 2).is_err());
    }

    #[test]
    fn table_needs_csv_or_json_name() {
        let dir = tempfile::tempdir().unwrap();
        let err = write_cluster_table(&dir.path().join("t.txt"), &[])
            .unwrap_err()
            .to_string();
        assert!(
            err.contains("t.txt") && err.contains(".csv or .json"),
            "{err}"
        );
    }
}
