//! Which sensor a packet capture comes from, and the Velodyne options, as
//! the input source takes them.

use clap::{Args, ValueEnum};
use fcc_lidar::velodyne::{DualReturn, VelodyneModel, VelodyneOptions};
use std::path::PathBuf;

/// The sensor family of a packet capture.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Sensor {
    /// Ouster when --meta is given or a .json of the same name lies beside
    /// the capture, Velodyne otherwise.
    Auto,
    Ouster,
    Velodyne,
}

/// Velodyne capture options.
#[derive(Args, Debug, Clone)]
pub struct VelodyneArgs {
    /// Sensor family of .pcap/.pcapng inputs.
    #[arg(long, value_enum, default_value_t = Sensor::Auto)]
    pub sensor: Sensor,
    /// Velodyne model: vlp16, vlp32c, hdl32e, hdl64e (default: told from
    /// the packets).
    #[arg(long)]
    pub velodyne_model: Option<VelodyneModel>,
    /// Velodyne calibration: the ROS driver's .yaml or Velodyne's db.xml
    /// (required for the HDL-64E, optional for the others).
    #[arg(long)]
    pub velodyne_calibration: Option<PathBuf>,
    /// Return of dual-return captures: first (the first block of each pair)
    /// or second.
    #[arg(long, default_value = "first")]
    pub velodyne_return: DualReturn,
    /// Columns of Velodyne range images (default: the firings of the first
    /// rotation).
    #[arg(long)]
    pub velodyne_cols: Option<usize>,
}

impl VelodyneArgs {
    /// The sensor family, for the input source.
    pub fn sensor(&self) -> fcc_lidar::source::Sensor {
        match self.sensor {
            Sensor::Auto => fcc_lidar::source::Sensor::Auto,
            Sensor::Ouster => fcc_lidar::source::Sensor::Ouster,
            Sensor::Velodyne => fcc_lidar::source::Sensor::Velodyne,
        }
    }

    /// The decoder options (`keep_incomplete` comes from the source's options).
    pub fn options(&self) -> VelodyneOptions {
        VelodyneOptions {
            model: self.velodyne_model,
            calibration: self.velodyne_calibration.clone(),
            columns: self.velodyne_cols,
            dual: self.velodyne_return,
            keep_incomplete: false,
        }
    }
}
