//! Frames from files through `fcc_lidar::source` (the one place that tells
//! the file type), and point clouds projected into range images.
//!
//! The source runs on its own thread and hands frames over a channel of
//! [`QUEUE`] frames, so a long capture never sits in memory: the thread
//! waits while the Python side does not ask for the next frame, and stops
//! when the iterator is dropped.

use crate::arrays::{array, floats, labels};
use crate::model::parse;
use crate::{file_err, lidar_err, value_err};
use fcc_lidar::projection::{
    project as project_points, BackProjection, ProjectionConfig, VerticalLayout,
};
use fcc_lidar::source::{Sensor, Source, SourceOptions, Summary};
use fcc_lidar::velodyne::VelodyneOptions;
use fcc_lidar::LidarError;
use pyo3::exceptions::PyStopIteration;
use pyo3::prelude::*;
use std::path::PathBuf;
use std::sync::mpsc::{sync_channel, Receiver};
use std::sync::Mutex;

/// Frames decoded ahead of the Python side.
const QUEUE: usize = 2;

/// What the reading thread sends.
enum Msg {
    Note(String),
    Frame(Box<fcc_lidar::source::Frame>),
    Done(Summary),
    Failed(LidarError),
}

/// Why the reading thread stopped early.
enum Stop {
    Lidar(LidarError),
    /// The iterator was dropped.
    Dropped,
}

impl From<LidarError> for Stop {
    fn from(e: LidarError) -> Self {
        Stop::Lidar(e)
    }
}

/// Projection settings as `--rows --cols --fov-up --fov-down --beams` make
/// them: `beams` a list of elevations (degrees, row 0 the top beam) or the
/// name of a Velodyne beam table.
fn projection_config(
    rows: usize,
    cols: usize,
    fov_up: f64,
    fov_down: f64,
    beams: Option<&Bound<'_, PyAny>>,
) -> PyResult<ProjectionConfig> {
    let layout = match beams {
        None => VerticalLayout::Fov {
            up_deg: fov_up,
            down_deg: fov_down,
        },
        Some(b) => {
            let elev: Vec<f64> = if let Ok(name) = b.extract::<String>() {
                fcc_lidar::velodyne::beam_table(&name).ok_or_else(|| {
                    value_err(format!(
                        "beams: `{name}` is not a beam table name; give the elevations in degrees"
                    ))
                })?
            } else {
                b.extract::<Vec<f64>>().map_err(|_| {
                    value_err(
                        "beams: expected a sequence of elevations in degrees or a beam table name",
                    )
                })?
            };
            VerticalLayout::Beams(elev)
        }
    };
    let rows = match &layout {
        VerticalLayout::Beams(b) => b.len(),
        VerticalLayout::Fov { .. } => rows,
    };
    let cfg = ProjectionConfig { rows, cols, layout };
    cfg.validate().map_err(lidar_err)?;
    Ok(cfg)
}

/// The frames of one input, in order (`fcc.open`).
#[pyclass(module = "fcc._fcc")]
pub struct Frames {
    rx: Mutex<Receiver<Msg>>,
    path: PathBuf,
    first: Option<Msg>,
    done: bool,
    /// Notes on how the input is read, as they arose.
    #[pyo3(get)]
    notes: Vec<String>,
    /// Warnings (each a sentence starting with the path), once read to the end.
    #[pyo3(get)]
    warnings: Vec<String>,
    /// The capture's or recording's summary line, once read to the end.
    #[pyo3(get)]
    summary: Option<String>,
    /// Frames handed on so far.
    #[pyo3(get)]
    frames_used: usize,
}

#[pyfunction]
#[pyo3(signature = (path, *, truth=None, meta=None, sensor="auto", keep_incomplete=false,
    lidar_frame=false, skip_frames=0, max_frames=None, topic=None, rows=64, cols=2048,
    fov_up=3.0, fov_down=-25.0, beams=None, velodyne_model=None, velodyne_calibration=None,
    velodyne_return="first", velodyne_cols=None, image_origin="sensor", strict=false))]
#[allow(clippy::too_many_arguments)]
pub fn open(
    py: Python<'_>,
    path: PathBuf,
    truth: Option<PathBuf>,
    meta: Option<PathBuf>,
    sensor: &str,
    keep_incomplete: bool,
    lidar_frame: bool,
    skip_frames: usize,
    max_frames: Option<usize>,
    topic: Option<String>,
    rows: usize,
    cols: usize,
    fov_up: f64,
    fov_down: f64,
    beams: Option<&Bound<'_, PyAny>>,
    velodyne_model: Option<&str>,
    velodyne_calibration: Option<PathBuf>,
    velodyne_return: &str,
    velodyne_cols: Option<usize>,
    image_origin: &str,
    strict: bool,
) -> PyResult<Frames> {
    let sensor = match sensor {
        "auto" => Sensor::Auto,
        "ouster" => Sensor::Ouster,
        "velodyne" => Sensor::Velodyne,
        s => {
            return Err(value_err(format!(
                "unknown sensor `{s}`: expected auto, ouster or velodyne"
            )))
        }
    };
    let opts = SourceOptions {
        meta,
        keep_incomplete,
        lidar_frame,
        origin: image_origin.parse().map_err(value_err)?,
        skip_frames,
        max_frames,
        sensor,
        velodyne: VelodyneOptions {
            model: velodyne_model.map(parse).transpose()?,
            calibration: velodyne_calibration,
            columns: velodyne_cols,
            dual: parse(velodyne_return)?,
            keep_incomplete: false,
        },
        topic,
        projection: projection_config(rows, cols, fov_up, fov_down, beams)?,
        range_images: true,
        strict,
    };
    // An input of no known type is refused here, before any reading.
    Source::open(&path, truth.as_deref(), &opts).map_err(lidar_err)?;
    let (tx, rx) = sync_channel::<Msg>(QUEUE);
    let thread_path = path.clone();
    std::thread::spawn(move || {
        let run = || -> Result<Summary, Stop> {
            let src = Source::open(&thread_path, truth.as_deref(), &opts)?;
            src.for_each(
                |n| {
                    let _ = tx.send(Msg::Note(n.to_string()));
                },
                |f| tx.send(Msg::Frame(Box::new(f))).map_err(|_| Stop::Dropped),
            )
        };
        let last = match run() {
            Ok(s) => Msg::Done(s),
            Err(Stop::Lidar(e)) => Msg::Failed(e),
            Err(Stop::Dropped) => return,
        };
        let _ = tx.send(last);
    });
    let mut frames = Frames {
        rx: Mutex::new(rx),
        path,
        first: None,
        done: false,
        notes: Vec::new(),
        warnings: Vec::new(),
        summary: None,
        frames_used: 0,
    };
    // A file that cannot be read fails here rather than at the first frame.
    loop {
        match frames.recv(py) {
            Some(Msg::Note(n)) => frames.notes.push(n),
            Some(Msg::Failed(e)) => return Err(file_err(e, &frames.path)),
            other => {
                frames.first = other;
                break;
            }
        }
    }
    Ok(frames)
}

impl Frames {
    fn recv(&self, py: Python<'_>) -> Option<Msg> {
        py.allow_threads(|| match self.rx.lock() {
            Ok(rx) => rx.recv().ok(),
            Err(_) => None,
        })
    }
}

#[pymethods]
impl Frames {
    fn __iter__(slf: PyRef<'_, Self>) -> PyRef<'_, Self> {
        slf
    }

    /// Stop reading: the reading thread ends at its next frame and the
    /// iterator is exhausted.
    fn close(&mut self) {
        let (_, rx) = sync_channel::<Msg>(0);
        if let Ok(mut r) = self.rx.lock() {
            *r = rx;
        }
        self.first = None;
        self.done = true;
    }

    fn __enter__(slf: PyRef<'_, Self>) -> PyRef<'_, Self> {
        slf
    }

    #[pyo3(signature = (*_args))]
    fn __exit__(&mut self, _args: &Bound<'_, pyo3::types::PyTuple>) -> bool {
        self.close();
        false
    }

    fn __next__(&mut self, py: Python<'_>) -> PyResult<Frame> {
        loop {
            if self.done {
                return Err(PyStopIteration::new_err(()));
            }
            let msg = match self.first.take() {
                Some(m) => Some(m),
                None => self.recv(py),
            };
            match msg {
                Some(Msg::Note(n)) => self.notes.push(n),
                Some(Msg::Frame(f)) => {
                    self.frames_used += 1;
                    return Frame::new(py, *f);
                }
                Some(Msg::Done(s)) => {
                    self.done = true;
                    self.warnings = s.warnings;
                    self.summary = s.line;
                }
                Some(Msg::Failed(e)) => {
                    self.done = true;
                    return Err(file_err(e, &self.path));
                }
                None => self.done = true,
            }
        }
    }
}

/// One range image of an input, with what came with it.
#[pyclass(module = "fcc._fcc", frozen)]
pub struct Frame {
    /// Input file stem, plus `_f00012` (frame of a capture) or `_m00003`
    /// (message of a recording).
    #[pyo3(get)]
    name: String,
    /// The range image (R, C, 3) float32, NaN for no return.
    #[pyo3(get)]
    xyz: PyObject,
    /// Read from a `.npy` range image (taken as prepared: no ground removal
    /// by default).
    #[pyo3(get)]
    range_image: bool,
    /// Intensity (reflectivity) per pixel (R, C) for sensor images, per
    /// input point (N,) for projected clouds; None when the input has none.
    #[pyo3(get)]
    intensity: Option<PyObject>,
    /// Ground truth per pixel (R, C) uint32, when given.
    #[pyo3(get)]
    truth: Option<PyObject>,
    /// Ground truth per input point (N,) uint32 (point clouds).
    #[pyo3(get)]
    truth_points: Option<PyObject>,
    /// Projected clouds: the input points (N, 3) float32.
    #[pyo3(get)]
    points: Option<PyObject>,
    /// Projected clouds: the pixel of each input point (N,) uint32
    /// (0xFFFFFFFF for none).
    #[pyo3(get)]
    point_pixel: Option<PyObject>,
    /// When the frame was taken, nanoseconds: an Ouster capture's first
    /// column as the sensor stamped it, a PointCloud2 message's header
    /// stamp; None for Velodyne captures and files.
    #[pyo3(get)]
    timestamp_ns: Option<u64>,
    /// Points in the input.
    #[pyo3(get)]
    input_points: usize,
    /// Point clouds: points above or below the vertical field of view.
    #[pyo3(get)]
    outside_fov: usize,
    /// Point clouds: points that lost their pixel to a nearer point.
    #[pyo3(get)]
    pixel_shared: usize,
    /// Point clouds: points with no pixel.
    #[pyo3(get)]
    unprojected: usize,
    projection: Option<fcc_lidar::projection::Projection>,
}

impl Frame {
    fn new(py: Python<'_>, f: fcc_lidar::source::Frame) -> PyResult<Frame> {
        let (r, c) = (f.image.rows, f.image.cols);
        let obj = |a: PyResult<Bound<'_, PyAny>>| a.map(Bound::unbind);
        let (projection, points, point_pixel) = match f.projection {
            Some((p, pts)) => {
                let n = pts.len();
                let flat: Vec<f32> = pts.into_iter().flatten().collect();
                let pp = obj(array(py, p.point_pixel.clone(), &[n]).map(Bound::into_any))?;
                (
                    Some(p),
                    Some(obj(array(py, flat, &[n, 3]).map(Bound::into_any))?),
                    Some(pp),
                )
            }
            None => (None, None, None),
        };
        let intensity = match f.intensity {
            Some(v) => {
                let shape = if projection.is_some() {
                    vec![v.len()]
                } else {
                    vec![r, c]
                };
                if shape.iter().product::<usize>() != v.len() {
                    return Err(value_err(format!(
                        "{}: {} intensities for {} pixels",
                        f.name,
                        v.len(),
                        r * c
                    )));
                }
                Some(obj(array(py, v, &shape).map(Bound::into_any))?)
            }
            None => None,
        };
        let truth = match f.truth {
            Some(t) => Some(obj(array(py, t, &[r, c]).map(Bound::into_any))?),
            None => None,
        };
        let truth_points = match f.truth_points {
            Some(t) => {
                let n = t.len();
                Some(obj(array(py, t, &[n]).map(Bound::into_any))?)
            }
            None => None,
        };
        Ok(Frame {
            name: f.name,
            xyz: obj(array(py, f.image.xyz, &[r, c, 3]).map(Bound::into_any))?,
            range_image: f.range_image,
            intensity,
            truth,
            truth_points,
            points,
            point_pixel,
            timestamp_ns: f.timestamp_ns,
            input_points: f.losses.input_points,
            outside_fov: f.losses.outside_fov,
            pixel_shared: f.losses.pixel_shared,
            unprojected: f.losses.unprojected,
            projection,
        })
    }
}

/// Labels of a (R, C) label image per point of a projection.
fn to_points<'py>(
    py: Python<'py>,
    p: &fcc_lidar::projection::Projection,
    labels_: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyAny>> {
    let (r, c) = (p.image.rows, p.image.cols);
    let shape = format!("({r}, {c})");
    let (l, _) = labels(labels_, "labels", &[Some(r), Some(c)], &shape)?;
    let per = p
        .labels_to_points(&l, BackProjection::default())
        .map_err(lidar_err)?;
    let n = per.len();
    Ok(array(py, per, &[n])?.into_any())
}

#[pymethods]
impl Frame {
    /// Whether the frame is a projected point cloud.
    #[getter]
    fn projected(&self) -> bool {
        self.projection.is_some()
    }

    /// The ground removal `fcc cluster` applies by default: "none" for a
    /// `.npy` range image, "slope" otherwise.
    #[getter]
    fn default_ground(&self) -> &'static str {
        if self.range_image {
            "none"
        } else {
            "slope"
        }
    }

    /// Labels (N,) per input point of a projected cloud from the frame's
    /// (R, C) label image (points that lost their pixel take a near
    /// neighbour's label, as `fcc cluster --label` writes them).
    fn labels_to_points<'py>(
        &self,
        py: Python<'py>,
        labels: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        match &self.projection {
            Some(p) => to_points(py, p, labels),
            None => Err(value_err(format!(
                "{}: not a projected point cloud: its labels are per pixel already",
                self.name
            ))),
        }
    }

    fn __repr__(&self) -> String {
        format!("<fcc.Frame {}>", self.name)
    }
}

/// A point cloud projected into a range image (`fcc.project`).
#[pyclass(module = "fcc._fcc", frozen)]
pub struct Projection {
    /// The range image (R, C, 3) float32: the nearest point of each pixel.
    #[pyo3(get)]
    xyz: PyObject,
    /// Per point: its pixel (row-major), 0xFFFFFFFF for none.
    #[pyo3(get)]
    point_pixel: PyObject,
    /// Per pixel (R, C): the point that won it, 0xFFFFFFFF for none.
    #[pyo3(get)]
    pixel_point: PyObject,
    /// Points above or below the vertical field of view.
    #[pyo3(get)]
    outside_fov: usize,
    inner: fcc_lidar::projection::Projection,
}

#[pymethods]
impl Projection {
    /// Labels (N,) per input point from an (R, C) label image.
    fn labels_to_points<'py>(
        &self,
        py: Python<'py>,
        labels: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        to_points(py, &self.inner, labels)
    }
}

#[pyfunction]
#[pyo3(signature = (points, rows=64, cols=2048, fov_up=3.0, fov_down=-25.0, beams=None))]
pub fn project(
    py: Python<'_>,
    points: &Bound<'_, PyAny>,
    rows: usize,
    cols: usize,
    fov_up: f64,
    fov_down: f64,
    beams: Option<&Bound<'_, PyAny>>,
) -> PyResult<Projection> {
    let cfg = projection_config(rows, cols, fov_up, fov_down, beams)?;
    let (v, _) = floats(points, "points", &[None, Some(3)], "(N, 3)")?;
    let pts: Vec<[f32; 3]> = v.chunks_exact(3).map(|p| [p[0], p[1], p[2]]).collect();
    let p = py
        .allow_threads(|| project_points(&pts, &cfg))
        .map_err(lidar_err)?;
    let (r, c, n) = (p.image.rows, p.image.cols, pts.len());
    let obj = |a: PyResult<Bound<'_, PyAny>>| a.map(Bound::unbind);
    Ok(Projection {
        xyz: obj(array(py, p.image.xyz.clone(), &[r, c, 3]).map(Bound::into_any))?,
        point_pixel: obj(array(py, p.point_pixel.clone(), &[n]).map(Bound::into_any))?,
        pixel_point: obj(array(py, p.pixel_point.clone(), &[r, c]).map(Bound::into_any))?,
        outside_fov: p.outside_fov,
        inner: p,
    })
}
