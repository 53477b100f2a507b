//! `fcc live`: a sensor's UDP packets in, the records of `fcc cluster
//! --stream` out as JSON lines: on the column path (`--ground none`) each
//! record as the stream closes it, on the frame path (a ground removal that
//! fits the whole frame) the frame's records after its ground removal;
//! `fcc replay`: a capture's packets sent to a socket at their
//! recorded timing, to feed `fcc live` without a sensor.

use crate::cmd_lidar::{per_point, stream_rows, valid_pixels, write_json_lines, GroundArgs};
use crate::model_args::ModelArgs;
use crate::sensor_args::VelodyneArgs;
use anyhow::{bail, Context};
use clap::Args;
use fcc_golden::MergeMode;
use fcc_lidar::clusters::ClusterRow;
use fcc_lidar::ground::GroundMethod;
use fcc_lidar::live::LiveFrame;
use fcc_lidar::live::{Decoder, End, Event, LiveOptions, LiveSource, Receive};
use fcc_lidar::ouster::{bump_frame_id, ImageOrigin, OusterMetadata};
use fcc_lidar::pcap::PcapReader;
use fcc_lidar::pipeline::{params_for, ColumnStream, PipelineConfig};
use fcc_lidar::sinks::mcap::{McapFrame, McapSink};
use fcc_lidar::source::{Frame as Item, SourceOptions};
use fcc_lidar::RangeImage;
use std::net::{SocketAddr, ToSocketAddrs, UdpSocket};
use std::path::PathBuf;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

#[derive(Args, Debug)]
pub struct LiveArgs {
    /// Where to listen: ADDR:PORT, or ADDR for the sensor's default port
    /// (Ouster: the metadata's udp_port_lidar, else 7502; Velodyne: 2368).
    #[arg(long, default_value = "0.0.0.0")]
    pub udp: String,
    /// Ouster metadata JSON of the sensor (makes the input Ouster).
    #[arg(long)]
    pub meta: Option<PathBuf>,
    /// Also cluster frames that miss columns or packets (missing columns
    /// are empty; each such frame is reported on stderr).
    #[arg(long)]
    pub keep_incomplete: bool,
    /// Ouster: points in the lidar frame instead of the sensor frame.
    #[arg(long)]
    pub lidar_frame: bool,
    /// Ouster: where the image starts, as `fcc cluster --image-origin`:
    /// sensor (the sensor's image: its column 0 holds beams of the frame's
    /// last packets, so no column is complete before the frame ends) or
    /// sweep (each column complete a few columns after the sweep passes it:
    /// on the column path, records are written as the sweep passes them).
    #[arg(long, default_value = "sensor")]
    pub image_origin: ImageOrigin,
    #[command(flatten)]
    pub velodyne: VelodyneArgs,
    #[command(flatten)]
    pub model: ModelArgs,
    #[command(flatten)]
    pub ground: GroundArgs,
    /// Drop clusters of N points or fewer (the authors' pipeline used 40).
    #[arg(long, default_value_t = 0)]
    pub min_points: usize,
    /// Stop after N frames.
    #[arg(long)]
    pub frames: Option<u64>,
    /// Seconds without a packet after which the stream has ended (before
    /// the first packet: an error).
    #[arg(long, allow_negative_numbers = true, default_value_t = 5.0)]
    pub idle_timeout: f64,
    /// Name of the frames in the records (`<NAME>_f<frame>`, as `fcc
    /// cluster` names a capture's frames after its file).
    #[arg(long, default_value = "live")]
    pub name: String,
    /// Print, at the end, on stderr: the time from receiving the packet that
    /// completed each frame to writing its records, and from receiving the
    /// packet of each cluster's last column (Ouster; the frame's completing
    /// packet for Velodyne) to writing its record (p50, p99, max, ms;
    /// frames delivered by the idle timeout left out).
    #[arg(long)]
    pub latency: bool,
    /// Also write a ROS 2 recording (MCAP): per frame a
    /// sensor_msgs/msg/PointCloud2 with the cluster `label` and a
    /// visualization_msgs/msg/MarkerArray of the clusters' boxes, stamped
    /// with the sensor's timestamp (Ouster) or the time the frame's last
    /// packet was received (Velodyne).
    #[arg(long)]
    pub mcap: Option<PathBuf>,
    /// Serve the frames live to Foxglove over WebSocket (the Foxglove SDK)
    /// on ADDR (default 127.0.0.1:8765): the points coloured by cluster on
    /// /fcc/points and the boxes with their ids on /fcc/clusters.
    #[cfg(feature = "foxglove")]
    #[arg(long, value_name = "ADDR", num_args = 0..=1, default_missing_value = fcc_viz::DEFAULT_ADDR)]
    pub foxglove: Option<String>,
    /// Cluster on the column-streaming core of the virtual board (its
    /// Verilator model, built on first use, then cached, behind a model of
    /// the AXI DMA and memory, as `fcc board run --virtual --scan column`)
    /// instead of the golden stream: each frame's records are the core's,
    /// every one checked against the golden stream's (a difference ends the
    /// command). A frame goes to the core once its last packet has arrived:
    /// the simple-mode AXI DMA ends each transfer with `tlast`, which the
    /// core takes as the frame's end. The open limit is at most 511 (the
    /// core's record slots; 511 when none is given); --min-points is refused.
    #[arg(long = "virtual")]
    pub virtual_board: bool,
}

/// The address to listen on: `spec` with the decoder's default port when
/// it names none.
fn listen_addr(spec: &str, default_port: u16) -> anyhow::Result<SocketAddr> {
    let with_port = if spec.parse::<SocketAddr>().is_ok()
        || spec
            .rsplit_once(':')
            .is_some_and(|(h, p)| !h.contains(':') && p.parse::<u16>().is_ok())
    {
        spec.to_string()
    } else {
        format!("{spec}:{default_port}")
    };
    with_port
        .to_socket_addrs()
        .with_context(|| format!("--udp {spec}: not an address (give ADDR:PORT or ADDR)"))?
        .next()
        .with_context(|| format!("--udp {spec}: names no address"))
}

pub fn run_live(args: &LiveArgs) -> anyhow::Result<()> {
    if args.model.merge != MergeMode::Exact {
        bail!("fcc live clusters with the stream, exactly (spec §9): drop --merge paper");
    }
    if !(args.idle_timeout.is_finite() && args.idle_timeout > 0.0) {
        bail!(
            "--idle-timeout {}: give a positive number of seconds",
            args.idle_timeout
        );
    }
    // The virtual board's column core, and the golden stream's options beside it.
    let (core, model) = if args.virtual_board {
        eprintln!("virtual board: the column-streaming core (K_max 11, up to 128 x 2048, 16-bit labels); each frame goes in once its last packet has arrived");
        let (core, model) = crate::cmd_board::virtual_column_core(&args.model, args.min_points)?;
        (Some(core), model)
    } else {
        (None, args.model.clone())
    };
    let hw = core.as_ref().map(|c| c.hardware());
    // The ground removals that fit a plane to the whole frame need the frame
    // before any column can be cleared of its ground; the core on the
    // virtual board gets whole frames.
    let column_path = args.ground.params(false)?.method == GroundMethod::None && hw.is_none();
    // Streamed as the sweep passes, a frame has records out before it is
    // known complete, so it cannot be dropped for missing columns.
    let streamed = column_path && args.image_origin == ImageOrigin::Sweep;
    let opts = SourceOptions {
        meta: args.meta.clone(),
        keep_incomplete: args.keep_incomplete || streamed,
        lidar_frame: args.lidar_frame,
        origin: args.image_origin,
        sensor: args.velodyne.sensor(),
        velodyne: args.velodyne.options(),
        ..SourceOptions::default()
    };
    let cfg = PipelineConfig {
        params: model.params(1, 1)?,
        mode: model.merge,
        ground: args.ground.params(false)?,
        min_points: args.min_points,
    };
    let decoder = Decoder::for_source(&opts)?;
    let addr = listen_addr(&args.udp, decoder.default_port())?;
    let stop = Arc::new(AtomicBool::new(false));
    {
        let stop = stop.clone();
        ctrlc::set_handler(move || stop.store(true, Ordering::Relaxed))
            .context("cannot catch Ctrl-C")?;
    }
    #[cfg(feature = "foxglove")]
    let want_points = args.mcap.is_some() || args.foxglove.is_some();
    #[cfg(not(feature = "foxglove"))]
    let want_points = args.mcap.is_some();
    // Streamed as the sweep passes and written as JSON lines only, the work
    // keeps up with the packets (no frame's worth at its end): the socket is
    // read on this thread, without a hand-off per packet.
    let inline = streamed && !want_points && matches!(decoder, Decoder::Ouster(_));
    let live = LiveOptions {
        idle_timeout: Duration::from_secs_f64(args.idle_timeout),
        receive: if inline {
            Receive::Inline
        } else {
            Receive::Thread
        },
        // Streamed, each column is read as it becomes complete.
        columns_read: streamed,
    };
    let mut mcap = args.mcap.as_deref().map(McapSink::create).transpose()?;
    let mut src = LiveSource::bind(addr, decoder, live)?;
    // The port bound (the system's choice for port 0).
    let addr = SocketAddr::new(addr.ip(), src.local_port());
    let sensor = match src.decoder() {
        Decoder::Ouster(_) => "Ouster",
        Decoder::Velodyne(_) => "Velodyne",
    };
    eprintln!("listening on udp {addr} ({sensor} packets)");
    #[cfg(feature = "foxglove")]
    let mut viz = match &args.foxglove {
        Some(a) => {
            let v = fcc_viz::FoxgloveServer::start(a)?;
            eprintln!(
                "foxglove: ws://{}:{}",
                a.rsplit_once(':').map_or("127.0.0.1", |(h, _)| h),
                v.port()
            );
            Some(v)
        }
        None => None,
    };
    if column_path {
        let wait = match src.decoder() {
            Decoder::Ouster(_) if streamed => {
                "columns streamed as their packets arrive (--image-origin sweep; frames that miss columns are kept, the missing columns empty, as --keep-incomplete)"
            }
            Decoder::Ouster(_) => {
                "columns streamed once the frame's last packet has arrived (image column 0 holds the frame's last measurement columns; --image-origin sweep streams them as they arrive)"
            }
            Decoder::Velodyne(_) => "columns streamed once the rotation has ended",
        };
        eprintln!(
            "column path: each record written as the stream closes it (--ground none), {wait}"
        );
    } else if hw.is_some() {
        eprintln!(
            "frame path: each frame through the column core when its last packet has arrived (ground removal `{}`), its records written when the core has sent them all",
            cfg.ground.method
        );
    } else {
        eprintln!(
            "frame path: ground removal `{}` fits a plane to the whole frame, so each frame's records are written after its last packet and its ground removal (--ground none takes the column path)",
            cfg.ground.method
        );
    }
    let mut columns = ColumnPath::default();
    let (mut frames, mut clusters) = (0u64, 0usize);
    let mut latency_ms: Vec<f64> = Vec::new();
    // Per record: from the packet of its last column (Ouster) or of the
    // frame's end (Velodyne) to its line written.
    let mut record_ms: Vec<f64> = Vec::new();
    let stdout = std::io::stdout();
    let result = (|| -> anyhow::Result<()> {
        loop {
            if args.frames.is_some_and(|n| frames >= n) {
                return Ok(());
            }
            let event = match src.next_event(&stop)? {
                Ok(e) => e,
                Err(End::Stopped) => return Ok(()),
                Err(End::Idle) => {
                    eprintln!(
                        "udp {addr}: no packet for {} s: the stream ended",
                        args.idle_timeout
                    );
                    return Ok(());
                }
            };
            let mut f = match event {
                Event::Frame(f) => *f,
                Event::Columns { frame, ready, at } => {
                    // Only the sweep origin keeps a frame that misses columns:
                    // the sensor origin waits for the frame, which the decoder
                    // drops when incomplete (as offline), before any record.
                    if streamed {
                        let name = format!("{}_f{:05}", args.name, frame);
                        columns.columns(
                            &src,
                            frame,
                            (ready, at),
                            &cfg,
                            &name,
                            &mut stdout.lock(),
                            (&mut record_ms, &mut latency_ms),
                        )?;
                    }
                    continue;
                }
            };
            let name = format!("{}_f{:05}", args.name, f.frame);
            if !f.complete {
                eprintln!(
                    "warning: {name}: incomplete, {} columns lost (empty)",
                    f.lost_columns
                );
            }
            let stamp_ns = f.sensor_ns.unwrap_or(f.received_unix_ns);
            let (rows, points, labels) = if column_path {
                let (rows, labels, image) = columns.frame(
                    &f,
                    want_points,
                    &cfg,
                    &name,
                    &mut stdout.lock(),
                    (&mut record_ms, &mut latency_ms),
                )?;
                if !want_points {
                    (rows, Vec::new(), Vec::new())
                } else {
                    let idx = valid_pixels(image);
                    let points = idx.iter().filter_map(|&i| image.point(i)).collect();
                    (rows, points, idx.iter().map(|&i| labels[i]).collect())
                }
            } else {
                // The image moves into the item; the column times stay with `f`.
                let image = std::mem::replace(&mut f.image, fcc_lidar::RangeImage::empty(0, 0));
                let item = Item::image(name, image, Some(std::mem::take(&mut f.intensity)));
                let (out, rows) = stream_rows(&item, &cfg, hw)?;
                write_json_lines(&mut stdout.lock(), &rows)?;
                if !f.at_end {
                    let now = Instant::now();
                    latency_ms.push((now - f.received_at).as_secs_f64() * 1e3);
                    for r in &rows {
                        let t = f
                            .column_time(r.span_last_col as usize)
                            .unwrap_or(f.received_at);
                        record_ms.push(now.saturating_duration_since(t).as_secs_f64() * 1e3);
                    }
                }
                if !want_points {
                    (rows, Vec::new(), Vec::new())
                } else {
                    let (points, labels, _, _) = per_point(&item, &out)?;
                    (rows, points, labels)
                }
            };
            if let Some(sink) = &mut mcap {
                sink.write(&McapFrame {
                    stamp_ns,
                    frame_id: "lidar",
                    points: &points,
                    labels: &labels,
                    clusters: &rows,
                })?;
            }
            #[cfg(feature = "foxglove")]
            if let Some(v) = &mut viz {
                v.publish(&fcc_viz::VizFrame {
                    stamp_ns,
                    frame_id: "lidar",
                    points: &points,
                    labels: &labels,
                    clusters: &rows,
                });
            }
            frames += 1;
            clusters += rows.len();
        }
    })();
    let s = src.stats();
    eprintln!(
        "live: {frames} frames, {} packets, {} lost ({} columns, {} packets dropped, {} incomplete frames dropped), {} malformed, {} duplicate columns, {} from another sensor, {clusters} clusters",
        s.packets,
        s.lost_columns + s.dropped,
        s.lost_columns,
        s.dropped,
        s.incomplete_frames,
        s.malformed,
        s.duplicate_columns,
        s.foreign
    );
    if args.latency {
        let summary = |v: &mut Vec<f64>| -> Option<String> {
            if v.is_empty() {
                return None;
            }
            v.sort_by(f64::total_cmp);
            let q = |p: usize| v[((p * v.len()).div_ceil(100)).max(1) - 1];
            Some(format!(
                "p50 {:.2} ms, p99 {:.2} ms, max {:.2} ms",
                q(50),
                q(99),
                v[v.len() - 1]
            ))
        };
        if let Some(l) = summary(&mut latency_ms) {
            eprintln!(
                "latency from the packet that completed a frame to its records written: {l} over {} frames",
                latency_ms.len()
            );
        }
        if let Some(l) = summary(&mut record_ms) {
            eprintln!(
                "latency from the packet of a cluster's last column to its record written: {l} over {} records",
                record_ms.len()
            );
        }
    }
    if let (Some(sink), Some(p)) = (mcap, &args.mcap) {
        sink.finish()?;
        eprintln!("wrote {} ({frames} frames)", p.display());
    }
    if let (Some(core), Ok(())) = (&core, &result) {
        eprintln!("{}", core.summary());
    }
    result
}

/// The column path: the frame's columns through the stream, each record's
/// JSON line written and flushed as it closes (the records of one packet's
/// columns in one write). With the sweep origin an
/// Ouster frame's columns go in as they become complete ([`Event::Columns`]),
/// the rest when the frame ends; with the sensor origin (whose frames that
/// miss packets are dropped whole, as offline) and for a Velodyne rotation,
/// all of them when the frame ends. Latencies: per record from
/// the packet that completed its last column, per frame from the packet
/// that completed the frame to its last record (frames delivered by the
/// idle timeout left out).
struct ColumnPath {
    stream: Option<ColumnStream>,
    /// The frame being streamed (until it is delivered), and whether the
    /// stream has finished it.
    frame: Option<u64>,
    finished: bool,
    /// Columns of the frame pushed so far.
    pushed: usize,
    /// The frame as streamed (its pushed columns).
    image: RangeImage,
    /// Per pushed column, when the packet that completed it was received.
    ready_at: Vec<Instant>,
    rows: Vec<ClusterRow>,
    /// Rows written so far.
    written: usize,
    column: Vec<Option<fcc_golden::Point>>,
    pixels: Vec<Option<[f32; 3]>>,
}

impl Default for ColumnPath {
    fn default() -> Self {
        ColumnPath {
            stream: None,
            frame: None,
            finished: false,
            pushed: 0,
            image: RangeImage::empty(0, 0),
            ready_at: Vec::new(),
            rows: Vec::new(),
            written: 0,
            column: Vec::new(),
            pixels: Vec::new(),
        }
    }
}

impl ColumnPath {
    /// Start streaming frame `frame` of `rows` x `cols`: a frame left
    /// unfinished (the decoder dropped it as incomplete after some of its
    /// columns were streamed) is warned about, and the stream remade.
    fn begin(
        &mut self,
        frame: u64,
        (rows, cols): (usize, usize),
        cfg: &PipelineConfig,
        name: &str,
    ) -> anyhow::Result<()> {
        if self.frame.is_some() && !self.finished {
            eprintln!(
                "warning: frame {}: dropped as incomplete after the records of its first {} columns were written (--keep-incomplete keeps such frames)",
                self.frame.unwrap_or(0),
                self.pushed
            );
            self.stream = None;
        }
        self.image.reset(rows, cols);
        let params = params_for(&self.image, &cfg.params);
        if !self
            .stream
            .as_ref()
            .is_some_and(|s| *s.params() == params && s.min_points() == cfg.min_points)
        {
            self.stream =
                Some(ColumnStream::new(&params, cfg.min_points).with_context(|| name.to_string())?);
        }
        self.frame = Some(frame);
        self.finished = false;
        self.pushed = 0;
        self.ready_at.clear();
        self.rows.clear();
        self.written = 0;
        Ok(())
    }

    /// Push column `self.pushed`, whose pixels are `self.pixels`, completed
    /// at `at`, and make the rows of the records it closed (written by
    /// [`write`](Self::write)).
    fn push(&mut self, at: Instant, name: &str) -> anyhow::Result<()> {
        let (cols, c) = (self.image.cols, self.pushed);
        self.column.clear();
        for (r, p) in self.pixels.iter().enumerate() {
            // The image keeps the points for the records' rows.
            self.image.set(r * cols + c, *p);
            self.column.push(p.and_then(|p| {
                fcc_golden::quantize_point(f64::from(p[0]), f64::from(p[1]), f64::from(p[2]))
            }));
        }
        let s = self.stream.as_mut().expect("made by begin");
        let n = s.push_column(&self.column)?.len();
        self.pushed += 1;
        self.ready_at.push(at);
        self.rows_of(n, name);
        if self.pushed == cols {
            let n = self.stream.as_mut().expect("made by begin").finish()?.len();
            self.finished = true;
            self.rows_of(n, name);
        }
        Ok(())
    }

    /// The rows of the `n` records of the stream's last call.
    fn rows_of(&mut self, n: usize, name: &str) {
        let s = self.stream.as_mut().expect("made by begin");
        for k in 0..n {
            self.rows.push(s.row(k, name, &self.image));
        }
    }

    /// Write the rows not yet written, in one write.
    fn write(
        &mut self,
        out: &mut impl std::io::Write,
        record_ms: &mut Vec<f64>,
    ) -> anyhow::Result<()> {
        let new = &self.rows[self.written..];
        if new.is_empty() {
            return Ok(());
        }
        write_json_lines(out, new)?;
        let now = Instant::now();
        for r in new {
            let t = self.ready_at[r.span_last_col as usize];
            record_ms.push(now.saturating_duration_since(t).as_secs_f64() * 1e3);
        }
        self.written = self.rows.len();
        Ok(())
    }

    /// Columns `0 .. ready` of the Ouster frame `frame` being received are
    /// complete, the last of them at `at`: stream those not yet streamed.
    #[allow(clippy::too_many_arguments)]
    fn columns(
        &mut self,
        src: &LiveSource,
        frame: u64,
        (ready, at): (usize, Instant),
        cfg: &PipelineConfig,
        name: &str,
        out: &mut impl std::io::Write,
        (record_ms, frame_ms): (&mut Vec<f64>, &mut Vec<f64>),
    ) -> anyhow::Result<()> {
        if self.frame != Some(frame) {
            let Decoder::Ouster(d) = src.decoder() else {
                return Ok(());
            };
            let m = d.metadata();
            self.begin(frame, (m.pixels_per_column, m.columns_per_frame), cfg, name)?;
        }
        let was_finished = self.finished;
        while self.pushed < ready.min(self.image.cols) {
            self.pixels.resize(self.image.rows, None);
            src.column_into(self.pushed, &mut self.pixels);
            self.push(at, name)?;
        }
        self.write(out, record_ms)?;
        if self.finished && !was_finished {
            frame_ms.push(at.elapsed().as_secs_f64() * 1e3);
        }
        Ok(())
    }

    /// Frame `f` has ended: stream the columns not yet streamed (from its
    /// image), finish the frame if that is not done, and return its rows,
    /// its label image (empty unless `labels`) and the image as streamed.
    #[allow(clippy::too_many_arguments)]
    fn frame(
        &mut self,
        f: &LiveFrame,
        labels: bool,
        cfg: &PipelineConfig,
        name: &str,
        out: &mut impl std::io::Write,
        (record_ms, frame_ms): (&mut Vec<f64>, &mut Vec<f64>),
    ) -> anyhow::Result<(Vec<ClusterRow>, Vec<u32>, &RangeImage)> {
        if self.frame != Some(f.frame)
            || f.image.rows != self.image.rows
            || f.image.cols != self.image.cols
        {
            self.begin(f.frame, (f.image.rows, f.image.cols), cfg, name)?;
        }
        let was_finished = self.finished;
        let cols = f.image.cols;
        while self.pushed < cols {
            let c = self.pushed;
            self.pixels.clear();
            self.pixels
                .extend((0..f.image.rows).map(|r| f.image.at(r, c)));
            let at = f.column_time(c).unwrap_or(f.received_at);
            self.push(at, name)?;
            // A whole frame's columns at once: each column's records out
            // as soon as they are made.
            self.write(out, record_ms)?;
        }
        if !was_finished && !f.at_end {
            frame_ms.push(f.received_at.elapsed().as_secs_f64() * 1e3);
        }
        let mut image_labels = Vec::new();
        if labels {
            self.stream
                .as_mut()
                .expect("made by begin")
                .labels_into(&mut image_labels)?;
        }
        // Delivered: the next frame starts afresh, even with the same id.
        self.frame = None;
        Ok((std::mem::take(&mut self.rows), image_labels, &self.image))
    }
}

#[derive(Args, Debug)]
pub struct ReplayArgs {
    /// The capture (.pcap, .pcapng) whose UDP datagrams are sent.
    pub capture: PathBuf,
    /// Where to send them: ADDR:PORT.
    #[arg(long)]
    pub udp: String,
    /// Speed relative to the recorded timing (2 = twice as fast; 0 = as
    /// fast as possible).
    #[arg(long, allow_negative_numbers = true, default_value_t = 1.0)]
    pub rate: f64,
    /// Send only the datagrams sent to this port in the capture (e.g. the
    /// lidar port, leaving out IMU or position packets).
    #[arg(long)]
    pub only_port: Option<u16>,
    /// Send the capture this many times, back to back at its own period
    /// (for long runs and measurements).
    #[arg(long, default_value_t = 1)]
    pub repeat: u32,
    /// Ouster metadata of the capture: each repeat then renumbers the frame
    /// ids so that it arrives as new frames (Velodyne rotations need nothing).
    #[arg(long)]
    pub meta: Option<PathBuf>,
}

pub fn run_replay(args: &ReplayArgs) -> anyhow::Result<()> {
    if !(args.rate.is_finite() && args.rate >= 0.0) {
        bail!(
            "--rate {}: give a non-negative number (0: as fast as possible)",
            args.rate
        );
    }
    let to: SocketAddr = args
        .udp
        .to_socket_addrs()
        .with_context(|| format!("--udp {}: not an address (give ADDR:PORT)", args.udp))?
        .next()
        .with_context(|| format!("--udp {}: names no address", args.udp))?;
    let bind = if to.is_ipv4() { "0.0.0.0:0" } else { "[::]:0" };
    let socket = UdpSocket::bind(bind).context("cannot open a UDP socket")?;
    let meta = args
        .meta
        .as_deref()
        .map(OusterMetadata::from_file)
        .transpose()?;
    let start = Instant::now();
    let mut sent = 0u64;
    // Capture times of the first pass: first, last, datagrams.
    let (mut first, mut last, mut count) = (None::<u64>, 0u64, 0u64);
    let mut offset_us = 0.0f64;
    for pass in 0..args.repeat {
        if pass > 0 {
            // One period of the capture: its span and one mean gap more.
            let span = last.saturating_sub(first.unwrap_or(last)) as f64;
            offset_us += span * count as f64 / (count.max(2) - 1) as f64;
        }
        let mut pcap = PcapReader::open(&args.capture)?;
        while let Some(mut d) = pcap.next_datagram()? {
            if args.only_port.is_some_and(|p| p != d.dst_port) {
                continue;
            }
            if pass == 0 {
                first.get_or_insert(d.time_us);
                last = d.time_us;
                count += 1;
            }
            if let Some(m) = &meta {
                // Frame ids wrap at 2^16, as the sensor's do.
                bump_frame_id(m, &mut d.payload, (pass % 65_536) as u16);
            }
            if args.rate > 0.0 {
                let t = d.time_us.saturating_sub(first.unwrap_or(d.time_us)) as f64 + offset_us;
                let due = Duration::from_secs_f64(t / 1e6 / args.rate);
                if let Some(wait) = due.checked_sub(start.elapsed()) {
                    std::thread::sleep(wait);
                }
            }
            socket
                .send_to(&d.payload, to)
                .with_context(|| format!("udp {to}: cannot send"))?;
            sent += 1;
        }
    }
    eprintln!(
        "{}: sent {sent} datagrams to udp {to} in {:.2} s",
        args.capture.display(),
        start.elapsed().as_secs_f64()
    );
    Ok(())
}
