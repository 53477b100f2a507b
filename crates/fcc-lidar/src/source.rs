//! One way from a path to frames: every input the tools read (Ouster and
//! Velodyne packet captures, ROS 2 recordings, point clouds, `.npy` range
//! images) becomes a sequence of [`Frame`]s, in order, with the capture's
//! summary line. The file type is told here and nowhere else.
//!
//! ```no_run
//! use fcc_lidar::source::{Source, SourceOptions};
//! use std::path::Path;
//!
//! let opts = SourceOptions::default();
//! let source = Source::open(Path::new("drive.pcap"), None, &opts)?;
//! let summary = source.for_each(
//!     |note| eprintln!("{note}"),
//!     |frame| {
//!         println!("{}: {} points", frame.name, frame.image.valid_count());
//!         Ok::<(), fcc_lidar::LidarError>(())
//!     },
//! )?;
//! for w in &summary.warnings {
//!     eprintln!("warning: {w}");
//! }
//! if let Some(line) = &summary.line {
//!     eprintln!("{line}");
//! }
//! # Ok::<(), fcc_lidar::LidarError>(())
//! ```

use crate::cloud::{read_point_cloud, CloudFormat};
use crate::labels::{read_label_file, semantickitti_instances};
use crate::ouster::OusterReader;
use crate::ouster::{
    CaptureStats, CoordFrame, DecodeOptions, ImageOrigin, OusterFrame, OusterMetadata,
};
use crate::projection::{project, Projection, ProjectionConfig};
use crate::rosbag::{read_pointclouds, Cloud2};
use crate::velodyne::{
    VelodyneFrame, VelodyneModel, VelodyneOptions, VelodyneReader, VelodyneStats,
};
use crate::{LidarError, RangeImage, Result};
use std::path::{Path, PathBuf};

/// The sensor family of a packet capture.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Sensor {
    /// Ouster when metadata is given or a .json of the same name lies
    /// beside the capture (and no Velodyne model or calibration is given),
    /// Velodyne otherwise.
    #[default]
    Auto,
    Ouster,
    Velodyne,
}

/// How to read inputs.
#[derive(Debug, Clone, Default)]
pub struct SourceOptions {
    /// Ouster metadata JSON (default: the .json beside each capture).
    pub meta: Option<PathBuf>,
    /// Captures: also use frames that miss columns (Ouster) or packets
    /// (Velodyne).
    pub keep_incomplete: bool,
    /// Ouster: points in the lidar frame instead of the sensor frame.
    pub lidar_frame: bool,
    /// Ouster: where the destaggered image starts (other inputs take only
    /// the default).
    pub origin: ImageOrigin,
    /// Captures: skip this many frames.
    pub skip_frames: usize,
    /// Captures: use at most this many frames.
    pub max_frames: Option<usize>,
    /// Sensor family of packet captures.
    pub sensor: Sensor,
    /// Velodyne decoding (its `keep_incomplete` is taken from above).
    pub velodyne: VelodyneOptions,
    /// Topic of MCAP recordings (default: the only PointCloud2 topic).
    pub topic: Option<String>,
    /// How point clouds become range images.
    pub projection: ProjectionConfig,
    /// Accept `.npy` range images (tools that make them refuse them).
    pub range_images: bool,
    /// A capture with no frame used is an error instead of a warning.
    pub strict: bool,
}

/// What an input file is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum InputKind {
    /// Ouster packet capture (.pcap, .pcapng).
    Ouster,
    /// Velodyne packet capture (.pcap, .pcapng).
    Velodyne,
    /// ROS 2 recording of PointCloud2 messages (.mcap).
    Mcap,
    /// Range image (.npy of shape (R, C, 3)).
    RangeImage,
    /// Point cloud (.bin, .pcd, .ply).
    Cloud,
}

fn has_ext(path: &Path, exts: &[&str]) -> bool {
    path.extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| exts.iter().any(|x| e.eq_ignore_ascii_case(x)))
}

impl InputKind {
    /// The kind of `path`, `None` when it is none the tools read.
    pub fn of(path: &Path, opts: &SourceOptions) -> Option<InputKind> {
        if has_ext(path, &["pcap", "pcapng"]) {
            Some(if is_velodyne(path, opts) {
                InputKind::Velodyne
            } else {
                InputKind::Ouster
            })
        } else if has_ext(path, &["mcap"]) {
            Some(InputKind::Mcap)
        } else if has_ext(path, &["npy"]) {
            Some(InputKind::RangeImage)
        } else if CloudFormat::from_path(path).is_some() {
            Some(InputKind::Cloud)
        } else {
            None
        }
    }

    /// Whether one file of this kind can hold several frames.
    pub fn is_sequence(self) -> bool {
        matches!(
            self,
            InputKind::Ouster | InputKind::Velodyne | InputKind::Mcap
        )
    }
}

/// Whether a capture is to be read as Velodyne.
fn is_velodyne(capture: &Path, opts: &SourceOptions) -> bool {
    match opts.sensor {
        Sensor::Velodyne => true,
        Sensor::Ouster => false,
        Sensor::Auto => {
            opts.velodyne.model.is_some()
                || opts.velodyne.calibration.is_some()
                || (opts.meta.is_none() && !capture.with_extension("json").exists())
        }
    }
}

/// Points a frame lost on its way into the range image.
#[derive(Debug, Clone, Copy, Default)]
pub struct Losses {
    /// Point clouds: points above or below the vertical field of view.
    pub outside_fov: usize,
    /// Point clouds: points that lost their pixel to a nearer point (they
    /// take a neighbour's label in per-point outputs).
    pub pixel_shared: usize,
    /// Point clouds: points with no pixel (zero or non-finite coordinates).
    pub unprojected: usize,
    /// Points in the input.
    pub input_points: usize,
}

/// One range image of an input, with what came with it.
#[derive(Debug, Clone)]
pub struct Frame {
    /// Input file stem, plus the frame (`_f00012`) of a capture or the
    /// message (`_m00003`) of a recording.
    pub name: String,
    pub image: RangeImage,
    /// Read from a `.npy` range image (taken as prepared).
    pub range_image: bool,
    /// Projected point clouds: the projection and the input points, to map
    /// labels back to every point.
    pub projection: Option<(Projection, Vec<[f32; 3]>)>,
    /// Ground truth per pixel.
    pub truth: Option<Vec<u32>>,
    /// Ground truth per input point (point clouds).
    pub truth_points: Option<Vec<u32>>,
    /// Intensity per input point (projected clouds) or per pixel (sensor
    /// images), where the input has it.
    pub intensity: Option<Vec<f32>>,
    /// Points lost before the image was made.
    pub losses: Losses,
    /// When the frame was taken, nanoseconds, where the input says: an
    /// Ouster capture's first column as the sensor stamped it (its own
    /// clock), a PointCloud2 message's header stamp. `None` for Velodyne
    /// captures (their packets are not stamped per frame here) and files.
    pub timestamp_ns: Option<u64>,
}

impl Frame {
    /// A range image as it stands (a sensor's): every point is a pixel.
    pub fn image(name: String, image: RangeImage, intensity: Option<Vec<f32>>) -> Frame {
        Frame {
            name,
            range_image: false,
            losses: Losses {
                input_points: image.valid_count(),
                ..Losses::default()
            },
            image,
            projection: None,
            truth: None,
            truth_points: None,
            intensity,
            timestamp_ns: None,
        }
    }

    /// Points projected into a range image.
    fn projected(
        name: String,
        points: Vec<[f32; 3]>,
        intensity: Option<Vec<f32>>,
        proj: &ProjectionConfig,
    ) -> Result<Frame> {
        let projection = project(&points, proj)?;
        let unprojected = projection.unprojected_points();
        let losses = Losses {
            outside_fov: projection.outside_fov,
            pixel_shared: points.len() - projection.kept_points() - unprojected,
            unprojected,
            input_points: points.len(),
        };
        Ok(Frame {
            name,
            range_image: false,
            losses,
            image: projection.image.clone(),
            projection: Some((projection, points)),
            truth: None,
            truth_points: None,
            intensity,
            timestamp_ns: None,
        })
    }
}

/// What an input held besides its frames.
#[derive(Debug, Clone, Default)]
pub struct Summary {
    /// Frames handed on.
    pub frames_used: usize,
    /// The capture's or recording's summary line (none for single files).
    pub line: Option<String>,
    /// Warnings, each a sentence starting with the path, to show before
    /// the summary line.
    pub warnings: Vec<String>,
}

/// An input file, known to be of a kind the tools read.
#[derive(Debug, Clone)]
pub struct Source<'a> {
    path: &'a Path,
    truth: Option<&'a Path>,
    opts: &'a SourceOptions,
    kind: InputKind,
}

impl<'a> Source<'a> {
    /// The input at `path`, with its ground truth (a SemanticKITTI .label
    /// for a point cloud, a .npy label image for a range image). An input
    /// of no known type, or ground truth for a capture or recording, is an
    /// error.
    pub fn open(
        path: &'a Path,
        truth: Option<&'a Path>,
        opts: &'a SourceOptions,
    ) -> Result<Source<'a>> {
        let kind = InputKind::of(path, opts)
            .filter(|&k| k != InputKind::RangeImage || opts.range_images)
            .ok_or_else(|| {
                LidarError::Config(format!(
                    "{}: unknown input type (expected .pcap, .pcapng, .mcap, .bin, .pcd{})",
                    path.display(),
                    if opts.range_images {
                        ", .ply or .npy"
                    } else {
                        " or .ply"
                    }
                ))
            })?;
        if truth.is_some() {
            let what = match kind {
                InputKind::Velodyne => Some("Velodyne captures"),
                InputKind::Ouster => Some("Ouster captures"),
                InputKind::Mcap => Some("MCAP recordings"),
                InputKind::RangeImage | InputKind::Cloud => None,
            };
            if let Some(what) = what {
                return Err(LidarError::Config(format!(
                    "{}: ground truth for {what} is not supported",
                    path.display()
                )));
            }
        }
        if opts.origin != ImageOrigin::Sensor && kind != InputKind::Ouster {
            return Err(LidarError::Config(format!(
                "{}: image origin `{}` is for Ouster captures only (this input's image has one origin)",
                path.display(),
                opts.origin.name()
            )));
        }
        Ok(Source {
            path,
            truth,
            opts,
            kind,
        })
    }

    pub fn kind(&self) -> InputKind {
        self.kind
    }

    pub fn path(&self) -> &Path {
        self.path
    }

    /// Hand every frame to `f`, in order, and notes on how the input is
    /// read (a default transform, say) to `note` as they arise. A capture
    /// without a single frame is an error that says what it held instead;
    /// one whose frames were all skipped a warning in the summary (an
    /// error with `strict`). An error of `f` stops the reading.
    pub fn for_each<E: From<LidarError>>(
        &self,
        note: impl FnMut(&str),
        mut f: impl FnMut(Frame) -> std::result::Result<(), E>,
    ) -> std::result::Result<Summary, E> {
        let (path, opts) = (self.path, self.opts);
        match self.kind {
            InputKind::Ouster => {
                let (used, s) = for_each_ouster_frame(path, opts, note, |frame| {
                    f(Frame {
                        timestamp_ns: Some(frame.timestamp_ns),
                        ..Frame::image(
                            frame_name(path, frame.frame_id.into()),
                            frame.image,
                            Some(frame.reflectivity),
                        )
                    })
                })?;
                let mut warnings = Vec::new();
                if used == 0 {
                    let why = format!(
                        "{}: no frame used of {} (--skip-frames {}{})",
                        path.display(),
                        s.frames,
                        opts.skip_frames,
                        opts.max_frames
                            .map(|m| format!(", --max-frames {m}"))
                            .unwrap_or_default()
                    );
                    if opts.strict {
                        return Err(LidarError::Config(format!("{why} (--strict)")).into());
                    }
                    warnings.push(why);
                }
                Ok(Summary {
                    frames_used: used,
                    line: Some(format!(
                        "{}: {} frames used of {} ({} lidar packets, {} malformed, {} incomplete frames dropped, {} unreassembled fragments)",
                        path.display(),
                        used,
                        s.frames,
                        s.lidar_packets,
                        s.malformed_packets,
                        s.incomplete_frames,
                        s.pcap.unreassembled_fragments
                    )),
                    warnings,
                })
            }
            InputKind::Velodyne => {
                let (used, s, model) = for_each_velodyne_frame(path, opts, |frame| {
                    f(Frame::image(
                        frame_name(path, frame.index as u64),
                        frame.image,
                        Some(frame.intensity),
                    ))
                })?;
                Ok(Summary {
                    frames_used: used,
                    line: Some(velodyne_summary(path, used, &s, model)),
                    warnings: Vec::new(),
                })
            }
            InputKind::Mcap => self.for_each_mcap(f),
            InputKind::RangeImage => {
                f(read_range_image(path, self.truth)?)?;
                Ok(Summary {
                    frames_used: 1,
                    ..Summary::default()
                })
            }
            InputKind::Cloud => {
                f(read_cloud(path, self.truth, &opts.projection)?)?;
                Ok(Summary {
                    frames_used: 1,
                    ..Summary::default()
                })
            }
        }
    }

    fn for_each_mcap<E: From<LidarError>>(
        &self,
        mut f: impl FnMut(Frame) -> std::result::Result<(), E>,
    ) -> std::result::Result<Summary, E> {
        let path = self.path;
        let mut err = None;
        let mut used = 0;
        let s = read_pointclouds(path, self.opts.topic.as_deref(), |k, c| {
            let name = format!("{}_m{k:05}", stem(path));
            let r = match cloud2_frame(name, c, &self.opts.projection) {
                Ok(frame) => f(frame),
                Err(e) => Err(e.into()),
            };
            used += 1;
            r.map_err(|e| {
                err = Some(e);
                LidarError::Config("stopped".into())
            })
        });
        if let Some(e) = err {
            return Err(e);
        }
        let s = s?;
        Ok(Summary {
            frames_used: used,
            line: Some(format!(
                "{}: {} PointCloud2 messages used, {} malformed{}{}",
                path.display(),
                s.clouds,
                s.malformed,
                s.first_problem
                    .as_ref()
                    .map(|p| format!(" (first: {p})"))
                    .unwrap_or_default(),
                s.cut_short
                    .as_ref()
                    .map(|c| format!("; the file breaks off: {c}"))
                    .unwrap_or_default()
            )),
            warnings: Vec::new(),
        })
    }

    /// Whether the input gives exactly one frame: a single file, a capture
    /// capped at one frame or holding one (decoded to find out; cheap next
    /// to clustering). Recordings count as several.
    pub fn single_frame(&self) -> bool {
        match self.kind {
            InputKind::Mcap => false,
            InputKind::RangeImage | InputKind::Cloud => true,
            InputKind::Ouster | InputKind::Velodyne if self.opts.max_frames == Some(1) => true,
            InputKind::Velodyne => {
                let mut n = 0;
                let two = SourceOptions {
                    max_frames: Some(2),
                    ..self.opts.clone()
                };
                let _ = for_each_velodyne_frame(self.path, &two, |_| {
                    n += 1;
                    Ok::<(), LidarError>(())
                });
                n == 1
            }
            InputKind::Ouster => {
                let skip = self.opts.skip_frames;
                let Ok(meta) = metadata_for(self.path, self.opts.meta.as_deref()) else {
                    return false;
                };
                let Ok(mut r) = OusterReader::open(self.path, &meta, decode_options(self.opts))
                else {
                    return false;
                };
                let mut n = 0;
                while let Ok(Some(_)) = r.next_frame() {
                    n += 1;
                    if n > skip + 1 {
                        return false;
                    }
                }
                n == skip + 1
            }
        }
    }
}

/// Whether `path` gives exactly one frame (see [`Source::single_frame`]);
/// an input of no known type counts as one.
pub fn single_frame(path: &Path, opts: &SourceOptions) -> bool {
    match Source::open(path, None, opts) {
        Ok(s) => s.single_frame(),
        Err(_) => true,
    }
}

fn stem(path: &Path) -> String {
    path.file_stem()
        .unwrap_or_default()
        .to_string_lossy()
        .into_owned()
}

fn frame_name(path: &Path, frame: u64) -> String {
    format!("{}_f{frame:05}", stem(path))
}

/// The Ouster metadata of a capture: `meta`, or the .json beside it.
pub fn metadata_for(capture: &Path, meta: Option<&Path>) -> Result<OusterMetadata> {
    let path = match meta {
        Some(m) => m.to_path_buf(),
        None if !capture.exists() => {
            return Err(LidarError::Config(format!(
                "{}: no such capture file",
                capture.display()
            )))
        }
        None => {
            let guess = capture.with_extension("json");
            if !guess.exists() {
                return Err(LidarError::Config(format!(
                    "{}: an Ouster capture needs its metadata JSON: pass --meta FILE (looked for {})",
                    capture.display(),
                    guess.display()
                )));
            }
            guess
        }
    };
    OusterMetadata::from_file(&path)
}

pub(crate) fn decode_options(o: &SourceOptions) -> DecodeOptions {
    DecodeOptions {
        frame: if o.lidar_frame {
            CoordFrame::Lidar
        } else {
            CoordFrame::Sensor
        },
        keep_incomplete: o.keep_incomplete,
        origin: o.origin,
        min_range_m: 0.0,
    }
}

/// Decode an Ouster capture (metadata from the options or beside it), skip
/// and cap frames as asked, and hand each frame to `f`. Returns the frames
/// used and the decoder's statistics; a capture without a single frame is
/// an error that says what it held instead.
pub fn for_each_ouster_frame<E: From<LidarError>>(
    input: &Path,
    o: &SourceOptions,
    mut note: impl FnMut(&str),
    mut f: impl FnMut(OusterFrame) -> std::result::Result<(), E>,
) -> std::result::Result<(usize, CaptureStats), E> {
    let meta = metadata_for(input, o.meta.as_deref())?;
    if meta.transform_default && !o.lidar_frame {
        note(&format!(
            "{}: the metadata has no lidar_to_sensor_transform: using the {} default (x, y negated, z + {} mm)",
            input.display(),
            meta.prod_line.as_deref().unwrap_or("Ouster SDK"),
            meta.lidar_to_sensor[11]
        ));
    }
    let mut reader = OusterReader::open(input, &meta, decode_options(o))?;
    let (mut n, mut used) = (0, 0);
    while let Some(frame) = reader.next_frame()? {
        n += 1;
        if n <= o.skip_frames {
            continue;
        }
        if o.max_frames.is_some_and(|m| used >= m) {
            break;
        }
        used += 1;
        f(frame)?;
    }
    let stats = reader.stats();
    if stats.frames == 0 {
        return Err(LidarError::Config(format!(
            "{}: {}",
            input.display(),
            crate::ouster::explain_no_frames(&meta, &stats)
        ))
        .into());
    }
    Ok((used, stats))
}

/// Decode a Velodyne capture, skip and cap rotations as asked, and hand
/// each to `f`. Returns the rotations used, the decoder's statistics and
/// the model; a capture without a single rotation is an error that says
/// what it held.
pub fn for_each_velodyne_frame<E: From<LidarError>>(
    input: &Path,
    o: &SourceOptions,
    mut f: impl FnMut(VelodyneFrame) -> std::result::Result<(), E>,
) -> std::result::Result<(usize, VelodyneStats, Option<VelodyneModel>), E> {
    let mut reader = VelodyneReader::open(
        input,
        VelodyneOptions {
            keep_incomplete: o.keep_incomplete,
            ..o.velodyne.clone()
        },
    )?;
    let (mut n, mut used) = (0, 0);
    while let Some(frame) = reader.next_frame()? {
        n += 1;
        if n <= o.skip_frames {
            continue;
        }
        if o.max_frames.is_some_and(|m| used >= m) {
            break;
        }
        used += 1;
        f(frame)?;
    }
    let stats = reader.stats();
    if stats.frames == 0 {
        return Err(LidarError::Config(format!(
            "{}: {}",
            input.display(),
            crate::velodyne::explain_no_frames(&stats)
        ))
        .into());
    }
    Ok((used, stats, reader.model()))
}

/// The summary line of a decoded Velodyne capture.
pub fn velodyne_summary(
    input: &Path,
    used: usize,
    s: &VelodyneStats,
    model: Option<VelodyneModel>,
) -> String {
    let mut modes: Vec<String> = s
        .return_modes
        .iter()
        .map(|(k, v)| format!("{k} {v}"))
        .collect();
    if modes.is_empty() {
        modes.push("not in the packets".into());
    }
    format!(
        "{}: Velodyne {}, {} rotations used of {} ({} data packets, return modes [{}], {} malformed, {} of another model, {} partial rotations dropped)",
        input.display(),
        model.map(VelodyneModel::name).unwrap_or("?"),
        used,
        s.frames,
        s.data_packets,
        modes.join(", "),
        s.malformed_packets,
        s.foreign_packets,
        s.incomplete_frames
    )
}

/// The range image of one PointCloud2 message: organised clouds as they
/// stand, unorganised ones projected (with the projection kept to map
/// labels back to the points).
fn cloud2_frame(name: String, c: Cloud2, proj: &ProjectionConfig) -> Result<Frame> {
    // A stamp before 1970 (negative seconds) is no time to pass on.
    let timestamp_ns = u64::try_from(c.stamp_sec)
        .ok()
        .map(|s| s * 1_000_000_000 + u64::from(c.stamp_nanosec));
    let frame = match c.range_image()? {
        Some((image, intensity)) => Frame::image(name, image, intensity),
        None => {
            let (points, intensity) = c.finite_points();
            Frame::projected(name, points, intensity, proj)?
        }
    };
    Ok(Frame {
        timestamp_ns,
        ..frame
    })
}

fn npy_error(e: fcc_npy::NpyError) -> LidarError {
    LidarError::Config(e.to_string())
}

/// A `.npy` range image (R, C, 3), with its `.npy` label image (R, C) as
/// ground truth.
pub fn read_range_image(path: &Path, truth: Option<&Path>) -> Result<Frame> {
    let img = fcc_npy::read_xyz(path).map_err(npy_error)?;
    let xyz = img.xyz.iter().map(|&v| v as f32).collect();
    let image = RangeImage::from_xyz(img.rows, img.cols, xyz)?;
    let truth = match truth {
        Some(t) => {
            let l = fcc_npy::read_labels(t).map_err(npy_error)?;
            if (l.rows, l.cols) != (image.rows, image.cols) {
                return Err(LidarError::Config(format!(
                    "{}: ground truth is {} x {} but {} is {} x {}",
                    t.display(),
                    l.rows,
                    l.cols,
                    path.display(),
                    image.rows,
                    image.cols
                )));
            }
            Some(l.labels)
        }
        None => None,
    };
    let mut frame = Frame::image(stem(path), image, None);
    frame.range_image = true;
    frame.truth = truth;
    Ok(frame)
}

/// A point cloud projected into a range image, with its SemanticKITTI
/// .label ground truth (instances) per point and per pixel.
pub fn read_cloud(path: &Path, truth: Option<&Path>, proj: &ProjectionConfig) -> Result<Frame> {
    let cloud = read_point_cloud(path)?;
    let n = cloud.len();
    let mut frame = Frame::projected(stem(path), cloud.points, cloud.intensity, proj)?;
    if let Some(t) = truth {
        let raw = read_label_file(t, Some(n))?;
        let inst = semantickitti_instances(&raw);
        if let Some((projection, _)) = &frame.projection {
            frame.truth = Some(projection.to_pixels(&inst, 0)?);
        }
        frame.truth_points = Some(inst);
    }
    Ok(frame)
}
