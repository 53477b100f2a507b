//! A ROS 2 recording (MCAP, CDR) of clustered frames, which `ros2 bag`,
//! RViz and Foxglove open: per frame, on `/fcc/points`, a
//! `sensor_msgs/msg/PointCloud2` of the frame's points (x, y, z float32 and
//! the cluster `label` uint32, 0 for none) and, on `/fcc/clusters`, a
//! `visualization_msgs/msg/MarkerArray`: a DELETEALL marker, then one CUBE
//! per cluster (id = the record's cluster id, the record's oriented box and
//! z extent, coloured as in the pictures). Both stamped with the frame's time.

use super::cdr::Cdr;
use crate::clusters::ClusterRow;
use crate::error::{LidarError, Result};
use crate::picture::cluster_colour;
use mcap::records::MessageHeader;
use std::collections::BTreeMap;
use std::fs::File;
use std::io::BufWriter;
use std::path::{Path, PathBuf};

/// Topic of the point clouds.
pub const POINTS_TOPIC: &str = "/fcc/points";
/// Topic of the boxes.
pub const CLUSTERS_TOPIC: &str = "/fcc/clusters";

const POINTCLOUD2: &str = "std_msgs/Header header
uint32 height
uint32 width
sensor_msgs/PointField[] fields
bool is_bigendian
uint32 point_step
uint32 row_step
uint8[] data
bool is_dense
================================================================================
MSG: std_msgs/Header
builtin_interfaces/Time stamp
string frame_id
================================================================================
MSG: builtin_interfaces/Time
int32 sec
uint32 nanosec
================================================================================
MSG: sensor_msgs/PointField
uint8 INT8=1
uint8 UINT8=2
uint8 INT16=3
uint8 UINT16=4
uint8 INT32=5
uint8 UINT32=6
uint8 FLOAT32=7
uint8 FLOAT64=8
string name
uint32 offset
uint8 datatype
uint32 count
";

/// `visualization_msgs/msg/MarkerArray` as ROS 2 Humble and later define it.
const MARKER_ARRAY: &str = "visualization_msgs/Marker[] markers
================================================================================
MSG: visualization_msgs/Marker
int32 ARROW=0
int32 CUBE=1
int32 ADD=0
int32 DELETE=2
int32 DELETEALL=3
std_msgs/Header header
string ns
int32 id
int32 type
int32 action
geometry_msgs/Pose pose
geometry_msgs/Vector3 scale
std_msgs/ColorRGBA color
builtin_interfaces/Duration lifetime
bool frame_locked
geometry_msgs/Point[] points
std_msgs/ColorRGBA[] colors
string texture_resource
sensor_msgs/CompressedImage texture
visualization_msgs/UVCoordinate[] uv_coordinates
string text
string mesh_resource
visualization_msgs/MeshFile mesh_file
bool mesh_use_embedded_materials
================================================================================
MSG: std_msgs/Header
builtin_interfaces/Time stamp
string frame_id
================================================================================
MSG: builtin_interfaces/Time
int32 sec
uint32 nanosec
================================================================================
MSG: geometry_msgs/Pose
geometry_msgs/Point position
geometry_msgs/Quaternion orientation
================================================================================
MSG: geometry_msgs/Point
float64 x
float64 y
float64 z
================================================================================
MSG: geometry_msgs/Quaternion
float64 x
float64 y
float64 z
float64 w
================================================================================
MSG: geometry_msgs/Vector3
float64 x
float64 y
float64 z
================================================================================
MSG: std_msgs/ColorRGBA
float32 r
float32 g
float32 b
float32 a
================================================================================
MSG: builtin_interfaces/Duration
int32 sec
uint32 nanosec
================================================================================
MSG: sensor_msgs/CompressedImage
std_msgs/Header header
string format
uint8[] data
================================================================================
MSG: visualization_msgs/UVCoordinate
float32 u
float32 v
================================================================================
MSG: visualization_msgs/MeshFile
string filename
uint8[] data
";

/// One clustered frame, as the sink takes it.
#[derive(Debug, Clone, Copy)]
pub struct McapFrame<'a> {
    /// The frame's time, nanoseconds since the epoch.
    pub stamp_ns: u64,
    /// The coordinate frame of the points (`header.frame_id`).
    pub frame_id: &'a str,
    /// The points of the frame, with their cluster (0 for none).
    pub points: &'a [[f32; 3]],
    pub labels: &'a [u32],
    /// The frame's clusters (their records' boxes).
    pub clusters: &'a [ClusterRow],
}

/// Writes clustered frames into an MCAP file.
pub struct McapSink {
    path: PathBuf,
    writer: mcap::Writer<BufWriter<File>>,
    points: u16,
    boxes: u16,
    sequence: u32,
}

impl McapSink {
    /// Create `path` (replacing it) with the two channels.
    pub fn create(path: &Path) -> Result<McapSink> {
        let file = File::create(path).map_err(|e| LidarError::io(path, e))?;
        let bad =
            |e: mcap::McapError| LidarError::malformed(path, format!("cannot write MCAP: {e}"));
        let mut writer = mcap::WriteOptions::new()
            .profile("ros2")
            .library("fcc")
            .create(BufWriter::new(file))
            .map_err(bad)?;
        let s1 = writer
            .add_schema(
                "sensor_msgs/msg/PointCloud2",
                "ros2msg",
                POINTCLOUD2.as_bytes(),
            )
            .map_err(bad)?;
        let s2 = writer
            .add_schema(
                "visualization_msgs/msg/MarkerArray",
                "ros2msg",
                MARKER_ARRAY.as_bytes(),
            )
            .map_err(bad)?;
        let none = BTreeMap::new();
        let points = writer
            .add_channel(s1, POINTS_TOPIC, "cdr", &none)
            .map_err(bad)?;
        let boxes = writer
            .add_channel(s2, CLUSTERS_TOPIC, "cdr", &none)
            .map_err(bad)?;
        Ok(McapSink {
            path: path.to_path_buf(),
            writer,
            points,
            boxes,
            sequence: 0,
        })
    }

    /// Write one frame: its point cloud and its boxes.
    pub fn write(&mut self, f: &McapFrame) -> Result<()> {
        if f.points.len() != f.labels.len() {
            return Err(LidarError::Mismatch {
                what: format!("labels for the points of {}", self.path.display()),
                expected: f.points.len(),
                got: f.labels.len(),
            });
        }
        let cloud = point_cloud(f);
        let markers = marker_array(f);
        for (channel, data) in [(self.points, cloud), (self.boxes, markers)] {
            self.sequence = self.sequence.wrapping_add(1);
            let header = MessageHeader {
                channel_id: channel,
                sequence: self.sequence,
                log_time: f.stamp_ns,
                publish_time: f.stamp_ns,
            };
            self.writer
                .write_to_known_channel(&header, &data)
                .map_err(|e| {
                    LidarError::malformed(&self.path, format!("cannot write MCAP: {e}"))
                })?;
        }
        Ok(())
    }

    /// Write the summary and close the file.
    pub fn finish(mut self) -> Result<()> {
        self.writer
            .finish()
            .map_err(|e| LidarError::malformed(&self.path, format!("cannot write MCAP: {e}")))?;
        Ok(())
    }
}

/// The `PointCloud2` of a frame: unorganised (height 1), x y z float32,
/// label uint32, 16 bytes a point.
fn point_cloud(f: &McapFrame) -> Vec<u8> {
    let mut c = Cdr::new();
    c.header(f.stamp_ns, f.frame_id);
    c.u32(1);
    c.u32(f.points.len() as u32);
    let fields = [("x", 0, 7), ("y", 4, 7), ("z", 8, 7), ("label", 12, 6)];
    c.u32(fields.len() as u32);
    for (name, offset, datatype) in fields {
        c.string(name);
        c.u32(offset);
        c.u8(datatype);
        c.u32(1);
    }
    c.bool(false);
    c.u32(16);
    c.u32(16 * f.points.len() as u32);
    let mut data = Vec::with_capacity(16 * f.points.len());
    for (p, l) in f.points.iter().zip(f.labels) {
        for v in p {
            data.extend_from_slice(&v.to_le_bytes());
        }
        data.extend_from_slice(&l.to_le_bytes());
    }
    c.bytes(&data);
    c.bool(true);
    c.into_bytes()
}

/// One `visualization_msgs/Marker`.
fn marker(c: &mut Cdr, f: &McapFrame, id: i32, action: i32, row: Option<&ClusterRow>) {
    c.header(f.stamp_ns, f.frame_id);
    c.string("fcc");
    c.i32(id);
    c.i32(1); // CUBE
    c.i32(action);
    let (pos, yaw, scale, rgb) = match row {
        Some(r) => {
            let dz = f64::from(r.max_z - r.min_z);
            (
                [r.box_cx, r.box_cy, f64::from(r.min_z + r.max_z) / 2.0],
                r.box_yaw,
                [r.box_length.max(0.01), r.box_width.max(0.01), dz.max(0.01)],
                cluster_colour(r.cluster),
            )
        }
        None => ([0.0; 3], 0.0, [1.0; 3], [255; 3]),
    };
    for v in pos {
        c.f64(v);
    }
    for v in [0.0, 0.0, (yaw / 2.0).sin(), (yaw / 2.0).cos()] {
        c.f64(v);
    }
    for v in scale {
        c.f64(v);
    }
    for v in rgb {
        c.f32(f32::from(v) / 255.0);
    }
    c.f32(0.5);
    c.time(0); // lifetime: until replaced
    c.bool(false); // frame_locked
    c.u32(0); // points
    c.u32(0); // colors
    c.string(""); // texture_resource
    c.header(f.stamp_ns, f.frame_id); // texture: an empty CompressedImage
    c.string("");
    c.bytes(&[]);
    c.u32(0); // uv_coordinates
    c.string(&row.map(|r| r.cluster.to_string()).unwrap_or_default());
    c.string(""); // mesh_resource
    c.string(""); // mesh_file
    c.bytes(&[]);
    c.bool(false);
}

/// The `MarkerArray` of a frame: DELETEALL, then a box per cluster.
fn marker_array(f: &McapFrame) -> Vec<u8> {
    let mut c = Cdr::new();
    c.u32(f.clusters.len() as u32 + 1);
    marker(&mut c, f, 0, 3, None);
    for r in f.clusters {
        marker(&mut c, f, r.cluster as i32, 0, Some(r));
    }
    c.into_bytes()
}
