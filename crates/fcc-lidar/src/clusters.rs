//! The per-cluster table (`--clusters FILE.csv|.json`): one row per cluster
//! per frame, what a tracker takes as its detections.

use crate::error::{LidarError, Result};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::path::Path;

/// One cluster of one frame. Coordinates in metres, in the frame of the
/// input (x forward, y left, z up for sensors).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
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
    let mut rows: BTreeMap<u32, (ClusterRow, [f64; 3])> = BTreeMap::new();
    for (p, &l) in points.iter().zip(labels) {
        if l == 0 || !p.iter().all(|v| v.is_finite()) {
            continue;
        }
        let r = (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt();
        let (row, sum) = rows.entry(l).or_insert_with(|| {
            let px = first.get(&l).copied().unwrap_or(0);
            (
                ClusterRow {
                    frame: frame.to_string(),
                    cluster: l,
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
                    first_row: px / cols.max(1),
                    first_col: px % cols.max(1),
                },
                [0.0; 3],
            )
        });
        row.points += 1;
        for k in 0..3 {
            sum[k] += f64::from(p[k]);
        }
        row.min_x = row.min_x.min(p[0]);
        row.min_y = row.min_y.min(p[1]);
        row.min_z = row.min_z.min(p[2]);
        row.max_x = row.max_x.max(p[0]);
        row.max_y = row.max_y.max(p[1]);
        row.max_z = row.max_z.max(p[2]);
        row.range_min = row.range_min.min(r);
        row.range_max = row.range_max.max(r);
    }
    Ok(rows
        .into_values()
        .map(|(mut row, sum)| {
            let n = row.points as f64;
            row.centroid_x = sum[0] / n;
            row.centroid_y = sum[1] / n;
            row.centroid_z = sum[2] / n;
            row
        })
        .collect())
}

/// The CSV header, in [`ClusterRow`] field order.
pub const CSV_HEADER: &str = "frame,cluster,points,centroid_x,centroid_y,centroid_z,min_x,min_y,min_z,max_x,max_y,max_z,range_min,range_max,first_row,first_col";

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
                    "{frame},{},{},{:.4},{:.4},{:.4},{:.4},{:.4},{:.4},{:.4},{:.4},{:.4},{:.4},{:.4},{},{}\n",
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
                    r.first_col
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
