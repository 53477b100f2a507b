//! From a range image to final cluster labels: ground removal, the golden
//! model, the `--min-points` filter.

use crate::cloud::{write_ply, PlyFormat};
use crate::clusters::{ClusterRow, RowAcc};
use crate::error::Result;
use crate::ground::{detect_ground, Ground, GroundParams};
use crate::image::RangeImage;
use crate::labels::filter_min_points;
use crate::picture::cluster_colour;
use fcc_golden::{
    cluster_with, runs_needed, Clustering, MergeMode, OrientedBox, Point, Record, Stream,
    StreamStats, Workspace,
};
use fcc_params::FccParams;
use std::path::Path;

/// Everything that shapes one clustering run.
#[derive(Debug, Clone, PartialEq)]
pub struct PipelineConfig {
    /// FCC parameters; rows and cols are taken from each image.
    pub params: FccParams,
    pub mode: MergeMode,
    pub ground: GroundParams,
    /// Clusters of this many points or fewer are dropped (0 keeps all).
    pub min_points: usize,
}

impl Default for PipelineConfig {
    fn default() -> Self {
        PipelineConfig {
            params: FccParams::default(),
            mode: MergeMode::Exact,
            ground: GroundParams::default(),
            min_points: 0,
        }
    }
}

/// The outcome of one run.
#[derive(Debug, Clone)]
pub struct PipelineResult {
    /// Final label per pixel: 0 for empty, ground and dropped pixels,
    /// clusters 1..=clusters in raster order of their first pixel.
    pub labels: Vec<u32>,
    /// Clusters after the min-points filter.
    pub clusters: u32,
    pub ground: Ground,
    /// The golden model's own result on the image without its ground.
    pub clustering: Clustering,
    /// The parameters used (with this image's rows and cols).
    pub params: FccParams,
    /// Points (not ground) whose coordinates do not fit the Q7.8 format
    /// (beyond about ±128 m): the model never sees them, they stay unlabelled.
    pub out_of_range: usize,
    /// Provisional labels the frame needs: the runs of pass 1 (only counted on
    /// label overflow; otherwise equal to `clustering.provisional`).
    pub labels_needed: u64,
    /// Runs the stream left unlabelled by its open limit (spec §9.1); 0 in
    /// frame mode, which has none.
    pub open_refused: u32,
}

/// The parameters of `cfg` sized for `image`.
pub fn params_for(image: &RangeImage, params: &FccParams) -> FccParams {
    FccParams {
        rows: image.rows,
        cols: image.cols,
        ..params.clone()
    }
}

thread_local! {
    /// The golden model's buffers, kept by each thread from one image to
    /// the next (only the returned labels are allocated per image).
    static WORKSPACE: std::cell::RefCell<Workspace> = Default::default();
}

/// Remove the ground, cluster with the golden model, drop small clusters.
pub fn cluster_image(image: &RangeImage, cfg: &PipelineConfig) -> Result<PipelineResult> {
    let params = params_for(image, &cfg.params);
    params.validate()?;
    let ground = detect_ground(image, &cfg.ground)?;
    let kept = image.without(&ground.mask);
    let frame = kept.to_frame();
    let out_of_range = kept.valid_count() - frame.valid_count();
    let clustering =
        WORKSPACE.with(|ws| cluster_with(&mut ws.borrow_mut(), &params, &frame, cfg.mode))?;
    let labels_needed = if clustering.overflow {
        runs_needed(&params, &frame)
    } else {
        u64::from(clustering.provisional)
    };
    let (labels, clusters) = if cfg.min_points > 0 {
        filter_min_points(&clustering.labels, cfg.min_points)
    } else {
        (clustering.labels.clone(), clustering.clusters)
    };
    Ok(PipelineResult {
        labels,
        clusters,
        ground,
        clustering,
        params,
        out_of_range,
        labels_needed,
        open_refused: 0,
    })
}

/// A record of the stream as it closed, with the oriented box of its points.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ClosedRecord {
    pub record: Record,
    pub oriented_box: Option<OrientedBox>,
}

/// The outcome of one frame through the stream.
#[derive(Debug, Clone)]
pub struct StreamResult {
    /// As in frame mode; `labels` numbered by record id, `clustering` with
    /// the stream's counts (no joins or merges: the stream does not count
    /// them).
    pub result: PipelineResult,
    /// The records in closing order, after the min-points filter (ids
    /// renumbered 1.. in closing order, as the label image).
    pub records: Vec<ClosedRecord>,
    pub stats: StreamStats,
}

/// The golden stream with the `--min-points` filter: columns in, records out
/// as they close, with their oriented boxes and, on request, the row of the
/// cluster table. The one loop behind `fcc cluster --stream` and the column
/// path of `fcc live`; its buffers are kept from one frame to the next.
#[derive(Debug, Clone)]
pub struct ColumnStream {
    stream: Stream,
    min_points: usize,
    /// Per stream record id of the frame: the id kept, 0 for one dropped.
    new_id: Vec<u32>,
    /// Records kept so far in the frame.
    kept: u32,
    /// The records of the last call, and the stream's index of each.
    closed: Vec<ClosedRecord>,
    closed_at: Vec<usize>,
    pixels: Vec<u32>,
    /// [`raster_order`]'s per-row counts and ends.
    row_ends: Vec<u32>,
}

/// `pixels` (raster indices `row * cols + col`, distinct) in raster order
/// into `out`. A cluster's pixel list holds each row's pixels mostly in
/// column order (its runs), so they are put in row order by counting, and
/// only a row whose pixels are out of order is sorted.
fn raster_order(pixels: &[u32], cols: u32, out: &mut Vec<u32>, ends: &mut Vec<u32>) {
    out.clear();
    if pixels.len() < 32 {
        out.extend_from_slice(pixels);
        out.sort_unstable();
        return;
    }
    // A pixel's row grows with its index.
    let (lo, hi) = pixels
        .iter()
        .fold((u32::MAX, 0), |(lo, hi), &p| (lo.min(p), hi.max(p)));
    let (lo, hi) = (lo / cols, hi / cols);
    ends.clear();
    ends.resize((hi - lo + 2) as usize, 0);
    for &p in pixels {
        ends[(p / cols - lo + 1) as usize] += 1;
    }
    for r in 1..ends.len() {
        ends[r] += ends[r - 1];
    }
    // ends[r] is now where row lo + r starts; filling moves it to the end.
    out.resize(pixels.len(), 0);
    for &p in pixels {
        let e = &mut ends[(p / cols - lo) as usize];
        out[*e as usize] = p;
        *e += 1;
    }
    let mut start = 0;
    for &end in &ends[..ends.len() - 1] {
        let row = &mut out[start..end as usize];
        if !row.windows(2).all(|w| w[0] < w[1]) {
            row.sort_unstable();
        }
        start = end as usize;
    }
}

impl ColumnStream {
    /// A stream for frames of `params.rows` x `params.cols` that drops
    /// clusters of `min_points` points or fewer.
    pub fn new(params: &FccParams, min_points: usize) -> Result<ColumnStream> {
        Ok(ColumnStream {
            stream: Stream::new(params)?,
            min_points,
            new_id: vec![0],
            kept: 0,
            closed: Vec::new(),
            closed_at: Vec::new(),
            pixels: Vec::new(),
            row_ends: Vec::new(),
        })
    }

    /// The parameters of the stream.
    pub fn params(&self) -> &FccParams {
        self.stream.params()
    }

    /// The `--min-points` of the stream.
    pub fn min_points(&self) -> usize {
        self.min_points
    }

    /// Take the next column (`R` pixels, row 0 first); the records that
    /// closed at it, ids renumbered `1..` in closing order over the frame.
    pub fn push_column(&mut self, column: &[Option<Point>]) -> Result<&[ClosedRecord]> {
        if self.stream.columns_taken() == 0 {
            self.new_id.truncate(1);
            self.kept = 0;
        }
        self.stream.push_column(column)?;
        self.keep();
        Ok(&self.closed)
    }

    /// End the frame after its `C` columns: the records still open.
    pub fn finish(&mut self) -> Result<&[ClosedRecord]> {
        self.stream.finish()?;
        self.keep();
        Ok(&self.closed)
    }

    /// The records the stream just closed, through the min-points filter.
    fn keep(&mut self) {
        self.closed.clear();
        self.closed_at.clear();
        for (k, r) in self.stream.closed().iter().enumerate() {
            if (r.points as usize) <= self.min_points {
                self.new_id.push(0);
                continue;
            }
            self.kept += 1;
            self.new_id.push(self.kept);
            self.closed.push(ClosedRecord {
                record: Record {
                    id: self.kept,
                    ..*r
                },
                oriented_box: fcc_golden::oriented_box(self.stream.points_of(k)),
            });
            self.closed_at.push(k);
        }
    }

    /// The records of the last [`push_column`](Self::push_column) or
    /// [`finish`](Self::finish).
    pub fn closed(&self) -> &[ClosedRecord] {
        &self.closed
    }

    /// The row of the cluster table (and of `--stream`'s JSON lines) of the
    /// `k`-th record of the last call, from its pixels of `image` (the
    /// image the columns came from), frame name `frame`.
    pub fn row(&mut self, k: usize, frame: &str, image: &RangeImage) -> ClusterRow {
        // Raster order, as the table of a whole frame sums them.
        raster_order(
            self.stream.pixels_of(self.closed_at[k]),
            image.cols as u32,
            &mut self.pixels,
            &mut self.row_ends,
        );
        let first = self.pixels.first().map_or(0, |&p| p as usize);
        let c = &self.closed[k];
        let mut acc = RowAcc::new(frame, c.record.id, first, image.cols);
        for &px in &self.pixels {
            if let Some(p) = image.point(px as usize) {
                acc.add(p);
            }
        }
        let mut row = acc.finish();
        row.set_record(&c.record, c.oriented_box.as_ref());
        row
    }

    /// What the finished frame (or the frame so far) reported.
    pub fn stats(&self) -> StreamStats {
        self.stream.stats()
    }

    /// The label image of the finished frame, raster order, numbered by the
    /// ids kept (0 for empty, unlabelled and dropped pixels).
    pub fn labels_into(&mut self, out: &mut Vec<u32>) -> Result<()> {
        self.stream.labels_into(out)?;
        for l in out.iter_mut() {
            *l = self.new_id[*l as usize];
        }
        Ok(())
    }
}

thread_local! {
    /// The stream of each thread, kept from one image to the next while the
    /// image size and parameters stay.
    static STREAM: std::cell::RefCell<Option<ColumnStream>> = const { std::cell::RefCell::new(None) };
}

/// Remove the ground and cluster column by column with the golden stream
/// (spec §9): the frame's columns in scan order, records as they close.
/// `on_record` sees each record (after the min-points filter) as it closes.
pub fn stream_image(
    image: &RangeImage,
    cfg: &PipelineConfig,
    mut on_record: impl FnMut(&ClosedRecord),
) -> Result<StreamResult> {
    let params = params_for(image, &cfg.params);
    params.validate()?;
    let ground = detect_ground(image, &cfg.ground)?;
    let kept = image.without(&ground.mask);
    let frame = kept.to_frame();
    let out_of_range = kept.valid_count() - frame.valid_count();
    STREAM.with(|cell| {
        let mut cell = cell.borrow_mut();
        if !cell
            .as_ref()
            .is_some_and(|s| *s.params() == params && s.min_points() == cfg.min_points)
        {
            *cell = Some(ColumnStream::new(&params, cfg.min_points)?);
        }
        let stream = cell.as_mut().expect("made above");
        let mut records = Vec::new();
        let mut column: Vec<Option<Point>> = vec![None; frame.rows];
        for c in 0..=frame.cols {
            let closed = if c < frame.cols {
                for (i, v) in column.iter_mut().enumerate() {
                    *v = frame.get(i, c);
                }
                stream.push_column(&column)?
            } else {
                stream.finish()?
            };
            for rec in closed {
                on_record(rec);
                records.push(*rec);
            }
        }
        let stats = stream.stats();
        let mut labels = Vec::new();
        stream.labels_into(&mut labels)?;
        let clusters = records.len() as u32;
        let clustering = Clustering {
            rows: frame.rows,
            cols: frame.cols,
            labels: labels.clone(),
            points: stats.points,
            clusters: stats.clusters,
            provisional: stats.runs,
            joins: 0,
            merges: 0,
            overflow: stats.overflow,
            unlabelled: stats.unlabelled,
        };
        let labels_needed = if stats.overflow {
            runs_needed(&params, &frame)
        } else {
            u64::from(stats.runs)
        };
        Ok(StreamResult {
            result: PipelineResult {
                labels,
                clusters,
                ground,
                clustering,
                params,
                out_of_range,
                labels_needed,
                open_refused: stats.open_refused,
            },
            records,
            stats,
        })
    })
}

/// Write the points of an image as a binary PLY coloured by cluster (ground
/// dark brown, unclustered grey), with the label as a property.
pub fn write_cluster_ply(
    path: &Path,
    image: &RangeImage,
    labels: &[u32],
    ground: Option<&[bool]>,
) -> Result<()> {
    let mut points = Vec::new();
    let mut colours = Vec::new();
    let mut out_labels = Vec::new();
    for i in 0..image.pixels() {
        let Some(p) = image.point(i) else {
            continue;
        };
        let l = labels.get(i).copied().unwrap_or(0);
        let c = if l == 0 && ground.is_some_and(|g| g.get(i).copied().unwrap_or(false)) {
            [110, 80, 50]
        } else {
            cluster_colour(l)
        };
        points.push(p);
        colours.push(c);
        out_labels.push(l);
    }
    write_ply(
        path,
        &points,
        Some(&colours),
        Some(&out_labels),
        PlyFormat::BinaryLittleEndian,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cloud::read_ply;
    use crate::ground::GroundMethod;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    #[test]
    fn raster_order_is_the_sorted_order() {
        // Lists of runs (a row's pixels in column order) concatenated in
        // any row order, some rows' runs out of column order, short and long.
        let seed = 0x2545_f491_4f6c_dd1d;
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut next = |m: u32| rng.gen_range(0..m);
        let (mut out, mut ends) = (Vec::new(), Vec::new());
        for case in 0..300 {
            let cols = [7, 1024, 2048][case % 3];
            let mut used = std::collections::HashSet::new();
            let mut pixels = Vec::new();
            for _ in 0..1 + next(40) {
                let (row, start) = (next(128), next(cols));
                for c in start..(start + 1 + next(60)).min(cols) {
                    if used.insert(row * cols + c) {
                        pixels.push(row * cols + c);
                    }
                }
            }
            raster_order(&pixels, cols, &mut out, &mut ends);
            let mut want = pixels.clone();
            want.sort_unstable();
            assert_eq!(
                out,
                want,
                "case {case}: {} pixels, {cols} columns, seed {seed:#x}",
                pixels.len()
            );
        }
    }

    /// Two little objects on a flat ground plane.
    fn image() -> RangeImage {
        let (rows, cols) = (16, 256);
        let mut img = RangeImage::empty(rows, cols);
        for r in 0..rows {
            let e = (2.0 - 1.5 * r as f32).to_radians();
            for c in 0..cols {
                let a =
                    std::f32::consts::PI - std::f32::consts::TAU * (c as f32 + 0.5) / cols as f32;
                let dir = [e.cos() * a.cos(), e.cos() * a.sin(), e.sin()];
                // Objects: 6 m away between columns 100..110 and 150..153.
                let obj = (100..110).contains(&c) || (150..153).contains(&c);
                let t = if obj && r > 3 {
                    6.0
                } else if dir[2] < -0.01 {
                    -1.7 / dir[2]
                } else {
                    continue;
                };
                img.set(r * cols + c, Some([t * dir[0], t * dir[1], t * dir[2]]));
            }
        }
        img
    }

    #[test]
    fn column_stream_rows_are_the_rows_of_the_whole_frame() {
        // Ground left in (one big cluster) and small ones dropped: the rows
        // built per record as it closes equal those of the whole frame's
        // points and labels, in closing order.
        let img = image();
        let cfg = PipelineConfig {
            ground: GroundParams {
                method: GroundMethod::None,
                ..GroundParams::default()
            },
            min_points: 2,
            ..PipelineConfig::default()
        };
        let whole = stream_image(&img, &cfg, |_| {}).unwrap();
        let idx: Vec<usize> = (0..img.pixels())
            .filter(|&i| img.point(i).is_some())
            .collect();
        let points: Vec<[f32; 3]> = idx.iter().filter_map(|&i| img.point(i)).collect();
        let labels: Vec<u32> = idx.iter().map(|&i| whole.result.labels[i]).collect();
        let mut want =
            crate::clusters::cluster_rows("f", &points, &labels, &whole.result.labels, img.cols)
                .unwrap();
        for row in &mut want {
            let c = &whole.records[row.cluster as usize - 1];
            row.set_record(&c.record, c.oriented_box.as_ref());
        }
        assert!(want.len() >= 2, "{} clusters", want.len());
        let params = params_for(&img, &cfg.params);
        let mut cs = ColumnStream::new(&params, cfg.min_points).unwrap();
        let frame = img.to_frame();
        let mut got = Vec::new();
        let mut column = vec![None; frame.rows];
        for c in 0..=frame.cols {
            let n = if c < frame.cols {
                for (i, v) in column.iter_mut().enumerate() {
                    *v = frame.get(i, c);
                }
                cs.push_column(&column).unwrap().len()
            } else {
                cs.finish().unwrap().len()
            };
            for k in 0..n {
                got.push(cs.row(k, "f", &img));
            }
        }
        got.sort_by_key(|r| r.cluster);
        assert_eq!(got, want);
    }

    #[test]
    fn points_beyond_the_q7_8_range_are_counted_as_out_of_range() {
        let mut img = RangeImage::empty(16, 256);
        img.set(0, Some([10.0, 0.0, 0.0]));
        img.set(1, Some([130.0, 0.0, 0.0]));
        img.set(2, Some([0.0, -129.0, 0.0]));
        let cfg = PipelineConfig {
            ground: GroundParams {
                method: GroundMethod::None,
                ..GroundParams::default()
            },
            ..PipelineConfig::default()
        };
        let out = cluster_image(&img, &cfg).unwrap();
        assert_eq!(out.out_of_range, 2);
        assert_eq!(out.clustering.points, 1);
        assert_eq!(&out.labels[..3], &[1, 0, 0]);
    }

    #[test]
    fn label_overflow_counts_the_labels_the_frame_needs() {
        // 300 isolated points in one row, 8-bit labels.
        let mut img = RangeImage::empty(16, 600);
        for c in (0..600).step_by(2) {
            let a = std::f32::consts::TAU * c as f32 / 600.0;
            img.set(c, Some([10.0 * a.cos(), 10.0 * a.sin(), 0.0]));
        }
        let cfg = PipelineConfig {
            params: FccParams {
                label_bits: 8,
                th_h: 0.05,
                ..FccParams::default()
            },
            ground: GroundParams {
                method: GroundMethod::None,
                ..GroundParams::default()
            },
            ..PipelineConfig::default()
        };
        let out = cluster_image(&img, &cfg).unwrap();
        assert!(out.clustering.overflow);
        assert_eq!(out.labels_needed, 300);
        assert_eq!(out.clustering.unlabelled, 45);
    }

    #[test]
    fn ground_goes_and_objects_become_clusters() {
        let img = image();
        let cfg = PipelineConfig {
            params: FccParams {
                fsize: 5,
                ..FccParams::default()
            },
            ..PipelineConfig::default()
        };
        let out = cluster_image(&img, &cfg).unwrap();
        assert_eq!(out.params.rows, 16);
        assert!(out.ground.count() > 1000, "{}", out.ground.count());
        assert_eq!(out.clusters, 2, "{:?}", out.clustering);
        // The small object has 3 columns x 12 rows (minus feet given to ground or not).
        let (small, _) = filter_min_points(&out.labels, 40);
        assert_eq!(
            small.iter().filter(|&&l| l != 0).count(),
            out.labels.iter().filter(|&&l| l == 1).count()
        );
        let filtered = cluster_image(
            &img,
            &PipelineConfig {
                min_points: 40,
                ..cfg.clone()
            },
        )
        .unwrap();
        assert_eq!(filtered.clusters, 1);
        // Without ground removal the ground glues everything together.
        let none = PipelineConfig {
            ground: GroundParams {
                method: GroundMethod::None,
                ..GroundParams::default()
            },
            ..cfg
        };
        let glued = cluster_image(&img, &none).unwrap();
        let (object, ground) = (15 * 256 + 100, 15 * 256 + 99);
        assert!(glued.labels[object] != 0 && glued.labels[object] == glued.labels[ground]);
        assert!(out.labels[object] != 0 && out.labels[ground] == 0);
    }

    #[test]
    fn cluster_ply_holds_every_point_with_its_label() {
        let img = image();
        let out = cluster_image(&img, &PipelineConfig::default()).unwrap();
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("clusters.ply");
        write_cluster_ply(&p, &img, &out.labels, Some(&out.ground.mask)).unwrap();
        let back = read_ply(&p).unwrap();
        assert_eq!(back.len(), img.valid_count());
        let text = std::fs::read(&p).unwrap();
        let header = String::from_utf8_lossy(&text[..300]);
        assert!(header.contains("property uchar red") && header.contains("property int label"));
    }
}
