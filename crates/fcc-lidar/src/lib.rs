//! Real LiDAR in, labels, pictures and quality numbers out.
//!
//! Readers turn sensor data into [`RangeImage`]s, the row-major x, y, z
//! images (NaN for no return) that the golden model quantises:
//! - [`ouster`]: Ouster packet captures ([`pcap`]: classic pcap and pcapng)
//!   with the sensor's JSON metadata, legacy and the 2.x single-return
//!   profiles;
//! - [`velodyne`]: Velodyne packet captures (VLP-16, VLP-32C, HDL-32E,
//!   HDL-64E with its calibration), one image per rotation;
//! - [`rosbag`]: ROS 2 recordings (MCAP) of `sensor_msgs/msg/PointCloud2`;
//! - [`cloud`]: KITTI / SemanticKITTI `.bin`, PCD and PLY point clouds, which
//!   [`projection`] turns into range images and whose labels it maps back to
//!   every input point.
//!
//! [`source`] is the one way from a path to frames: it tells the file type
//! and hands every input's range images on in order. [`live`] is the way
//! from a socket: a sensor's UDP packets through the same packet decoders
//! ([`ouster::OusterDecoder`], [`velodyne::VelodyneDecoder`]) that the
//! capture readers use.
//!
//! [`ground`] removes the ground before clustering, [`pipeline`] runs ground
//! removal, the golden model and the `--min-points` filter, [`labels`] and
//! [`picture`] write `.label` files and PNG pictures, [`clusters`] the
//! per-cluster table, and [`eval`] (fcc's rules) and [`semantickitti`]
//! (SemanticKITTI's own) measure clusterings against ground truth.
//! [`sinks`] write clustered frames in the formats viewers open (MCAP
//! with ROS 2 messages).
//! `docs/lidar.md` describes the formats, conventions and metric
//! definitions.
//!
//! ```
//! use fcc_lidar::pipeline::{cluster_image, PipelineConfig};
//! use fcc_lidar::RangeImage;
//!
//! // A 2 x 4 image: two points 0.2 m apart on the top row, the rest empty.
//! let mut image = RangeImage::empty(2, 4);
//! image.set(0, Some([10.0, 0.0, 0.5]));
//! image.set(1, Some([10.0, 0.2, 0.5]));
//! let cfg = PipelineConfig {
//!     ground: fcc_lidar::ground::GroundParams {
//!         method: fcc_lidar::ground::GroundMethod::None,
//!         ..Default::default()
//!     },
//!     ..PipelineConfig::default()
//! };
//! let out = cluster_image(&image, &cfg)?;
//! assert_eq!(out.labels, vec![1, 1, 0, 0, 0, 0, 0, 0]);
//! # Ok::<(), fcc_lidar::LidarError>(())
//! ```

pub mod cloud;
pub mod clusters;
pub mod error;
pub mod eval;
pub mod ground;
pub mod image;
pub mod labels;
pub mod live;
pub mod ouster;
pub mod pcap;
pub mod picture;
pub mod pipeline;
pub mod projection;
pub mod rosbag;
pub mod semantickitti;
pub mod sinks;
pub mod source;
pub mod velodyne;

pub use error::{LidarError, Result};
pub use image::RangeImage;
