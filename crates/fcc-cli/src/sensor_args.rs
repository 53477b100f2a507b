//! Which sensor a packet capture comes from, and the Velodyne options.

use anyhow::bail;
use clap::{Args, ValueEnum};
use fcc_lidar::velodyne::{
    explain_no_frames, DualReturn, VelodyneFrame, VelodyneModel, VelodyneOptions, VelodyneReader,
    VelodyneStats,
};
use std::path::{Path, PathBuf};

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
    /// Whether a capture is to be read as Velodyne.
    pub fn is_velodyne(&self, capture: &Path, meta: Option<&Path>) -> bool {
        match self.sensor {
            Sensor::Velodyne => true,
            Sensor::Ouster => false,
            Sensor::Auto => {
                self.velodyne_model.is_some()
                    || self.velodyne_calibration.is_some()
                    || (meta.is_none() && !capture.with_extension("json").exists())
            }
        }
    }

    fn options(&self, keep_incomplete: bool) -> VelodyneOptions {
        VelodyneOptions {
            model: self.velodyne_model,
            calibration: self.velodyne_calibration.clone(),
            columns: self.velodyne_cols,
            dual: self.velodyne_return,
            keep_incomplete,
        }
    }
}

/// Decode a Velodyne capture, skip and cap rotations as asked, and hand
/// each to `f`. Returns the rotations used and the decoder's statistics; a
/// capture without a single rotation is an error that says what it held.
pub fn for_each_velodyne_frame(
    input: &Path,
    v: &VelodyneArgs,
    keep_incomplete: bool,
    skip: usize,
    max: Option<usize>,
    mut f: impl FnMut(VelodyneFrame) -> anyhow::Result<()>,
) -> anyhow::Result<(usize, VelodyneStats, Option<VelodyneModel>)> {
    let mut reader = VelodyneReader::open(input, v.options(keep_incomplete))?;
    let (mut n, mut used) = (0, 0);
    while let Some(frame) = reader.next_frame()? {
        n += 1;
        if n <= skip {
            continue;
        }
        if max.is_some_and(|m| used >= m) {
            break;
        }
        used += 1;
        f(frame)?;
    }
    let stats = reader.stats();
    if stats.frames == 0 {
        bail!("{}: {}", input.display(), explain_no_frames(&stats));
    }
    Ok((used, stats, reader.model()))
}

/// The summary line of a decoded capture, for stderr.
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
