//! The live socket: a sensor's UDP packets into the same packet decoders the
//! capture readers use ([`OusterDecoder`], [`VelodyneDecoder`]), frames out
//! as they complete, delimited exactly as in a capture.
//!
//! The socket is read in one of two ways ([`Receive`]): by a receiving
//! thread that drains it into a bounded queue, so that a long frame end (a
//! whole frame's ground removal, its recording) never makes the kernel drop
//! packets, or by the caller's own thread as it waits for the next packet,
//! which saves a hand-off between threads per packet when the work keeps up
//! with the packets. Either way packets lost for want of room are counted,
//! never lost unseen (in the queue, or on Linux in the kernel's buffer). The
//! decoder holds one frame being received, so memory stays bounded however
//! long it runs.
//!
//! Faults are counted, never fatal, except where going on would give wrong
//! output: a long run of packets that no decoder accepts (packets of
//! another profile or model, or the wrong metadata) is one clear error, and
//! no packet at all within the idle timeout is another.

use crate::error::{LidarError, Result};
use crate::image::RangeImage;
use crate::ouster::{ImageOrigin, OusterDecoder, OusterFrame, OusterMetadata};
use crate::source::{decode_options, Sensor, SourceOptions};
use crate::velodyne::{VelodyneDecoder, VelodyneFrame, VelodyneOptions};
use std::net::{SocketAddr, UdpSocket};
use std::path::Path;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::mpsc::{sync_channel, Receiver, RecvTimeoutError, TrySendError};
use std::sync::Arc;
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

/// Default UDP port of Ouster lidar packets.
pub const OUSTER_PORT: u16 = 7502;
/// Default UDP port of Velodyne data packets.
pub const VELODYNE_PORT: u16 = 2368;
/// Packets the queue between the socket and the decoder holds (about 25 MB
/// of the largest Ouster packets, many rotations of any sensor).
pub const QUEUE_PACKETS: usize = 1024;
/// Consecutive packets no decoder accepts before the run stops with an
/// error (a few frames' worth: packets of another profile or model).
pub const UNDECODABLE_RUN: u64 = 256;
/// Largest UDP payload.
const MAX_DATAGRAM: usize = 65_536;
/// How often the waiting loops look at the stop flag.
const POLL: Duration = Duration::from_millis(50);

/// The packet decoder behind the socket.
pub enum Decoder {
    Ouster(Box<OusterDecoder>),
    Velodyne(Box<VelodyneDecoder>),
}

impl Decoder {
    /// The decoder the options ask for: Ouster with the metadata of
    /// `opts.meta` (`Sensor::Auto` when it is given), else Velodyne; the
    /// capture readers' options (`keep_incomplete`, `lidar_frame`, the
    /// Velodyne model and calibration) mean the same here.
    pub fn for_source(opts: &SourceOptions) -> Result<Decoder> {
        let ouster = match opts.sensor {
            Sensor::Ouster => true,
            Sensor::Velodyne => false,
            Sensor::Auto => opts.meta.is_some(),
        };
        if ouster {
            let Some(meta) = &opts.meta else {
                return Err(LidarError::Config(
                    "a live Ouster sensor needs its metadata JSON: pass --meta FILE".into(),
                ));
            };
            let meta = OusterMetadata::from_file(meta)?;
            Ok(Decoder::Ouster(Box::new(OusterDecoder::new(
                &meta,
                decode_options(opts),
            )?)))
        } else {
            if opts.origin != ImageOrigin::Sensor {
                return Err(LidarError::Config(format!(
                    "image origin `{}` is for Ouster sensors only: a Velodyne rotation's column grid is fixed when the rotation ends",
                    opts.origin.name()
                )));
            }
            let v = VelodyneOptions {
                keep_incomplete: opts.keep_incomplete,
                ..opts.velodyne.clone()
            };
            Ok(Decoder::Velodyne(Box::new(VelodyneDecoder::new(
                Path::new("udp"),
                v,
            )?)))
        }
    }

    /// The default port of the sensor's packets.
    pub fn default_port(&self) -> u16 {
        match self {
            Decoder::Ouster(d) => d.metadata().udp_port_lidar.unwrap_or(OUSTER_PORT),
            Decoder::Velodyne(_) => VELODYNE_PORT,
        }
    }
}

/// How the live source runs.
#[derive(Debug, Clone)]
pub struct LiveOptions {
    /// With no packet for this long, the stream has ended (or, before the
    /// first packet, never started: an error).
    pub idle_timeout: Duration,
    /// Which thread reads the socket.
    pub receive: Receive,
    /// The caller reads each Ouster column through
    /// [`LiveSource::column_into`] as [`Event::Columns`] reports it: the
    /// frame's image then holds only the columns not reported by the time
    /// the frame ended, the others empty
    /// ([`OusterDecoder::set_columns_read`]).
    pub columns_read: bool,
}

impl Default for LiveOptions {
    fn default() -> Self {
        LiveOptions {
            idle_timeout: Duration::from_secs(5),
            receive: Receive::Thread,
            columns_read: false,
        }
    }
}

/// Which thread reads the socket.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Receive {
    /// A receiving thread drains the socket into a queue of
    /// [`QUEUE_PACKETS`], so that work that falls behind the packets for a
    /// while (a whole frame processed at its end) leaves them in the
    /// process, not in the kernel's buffer; a packet the queue has no room
    /// for is counted in [`LiveStats::dropped`].
    #[default]
    Thread,
    /// The caller's thread reads the socket while it waits for the next
    /// packet: no hand-off between threads per packet, the kernel's buffer
    /// ([`RECEIVE_BUFFER`] asked for) the only queue. For work that keeps up
    /// with the packets, as the column path streamed as the sweep passes
    /// does. On Linux the packets the kernel dropped for want of room are
    /// counted in [`LiveStats::dropped`] (`SO_RXQ_OVFL`); elsewhere they
    /// show only as lost columns.
    Inline,
}

/// One frame received live.
#[derive(Debug, Clone)]
pub struct LiveFrame {
    /// The frame's number in its capture: the Ouster frame id, or the
    /// Velodyne rotation counted from the first packet (as the capture
    /// readers name frames).
    pub frame: u64,
    /// The frame (with [`LiveOptions::columns_read`], only its columns not
    /// reported by [`Event::Columns`]).
    pub image: RangeImage,
    /// Reflectivity (Ouster) or intensity (Velodyne) per pixel.
    pub intensity: Vec<f32>,
    /// Every column arrived (Ouster: the column window; Velodyne: a full
    /// rotation without a gap).
    pub complete: bool,
    /// Ouster: measurement columns of the window that did not arrive
    /// (their pixels are empty); 0 for Velodyne, whose gaps are in `complete`.
    pub lost_columns: usize,
    /// When the packet that completed the frame was received.
    pub received_at: Instant,
    /// The same, nanoseconds since the Unix epoch (the system clock).
    pub received_unix_ns: u64,
    /// Delivered at the end of the stream (the idle timeout), not by a packet.
    pub at_end: bool,
    /// The sensor's own timestamp of the frame, nanoseconds (Ouster: its
    /// first column's; `None` for Velodyne, whose packets count from the hour).
    pub sensor_ns: Option<u64>,
    /// Ouster: when each measurement column's packet was received (`None`
    /// for a column that did not arrive, or for Velodyne).
    pub column_received: Vec<Option<Instant>>,
    /// Ouster: the distinct destaggering offsets (image column = measurement
    /// column + offset, modulo the columns: the beam's shift less the image
    /// origin).
    pub shifts: Vec<usize>,
}

impl LiveFrame {
    /// When the last pixel of image column `col` arrived: the latest packet
    /// among the measurement columns that land in it (Ouster), else `None`.
    pub fn column_time(&self, col: usize) -> Option<Instant> {
        let w = self.column_received.len();
        if w == 0 {
            return None;
        }
        self.shifts
            .iter()
            .filter_map(|&s| self.column_received[(col % w + w - s % w) % w])
            .max()
    }
}

/// What the live source met so far.
#[derive(Debug, Clone, Default, PartialEq, Eq, serde::Serialize)]
pub struct LiveStats {
    /// Datagrams received.
    pub packets: u64,
    /// Lidar (Ouster) or data (Velodyne) packets decoded.
    pub decoded: u64,
    /// Datagrams the decoder could not use: the wrong size, type or column
    /// index, bad block flags or azimuths.
    pub malformed: u64,
    /// Packets from another sensor (serial number or model).
    pub foreign: u64,
    /// Ouster columns that arrived twice in a frame (the later one wins).
    pub duplicate_columns: u64,
    /// Packets dropped because the decoder fell behind the socket (no room
    /// in the queue of [`Receive::Thread`], or in the kernel's buffer).
    pub dropped: u64,
    /// Frames delivered.
    pub frames: u64,
    /// Frames dropped because they missed columns (see `keep_incomplete`
    /// of the decoders).
    pub incomplete_frames: u64,
    /// Ouster columns missing in the frames delivered.
    pub lost_columns: u64,
}

/// What the datagrams brought, in order.
#[derive(Debug, Clone)]
pub enum Event {
    /// Image columns `0 .. ready` of the Ouster frame `frame` being received
    /// are complete ([`OusterDecoder::ready_columns`]); `at` is when the
    /// packet that completed the last of them was received. Read them with
    /// [`LiveSource::column_into`] before the next event.
    Columns {
        frame: u64,
        ready: usize,
        at: Instant,
    },
    /// A frame has ended (the first packet of the next one, or the end of
    /// the stream, closed it).
    Frame(Box<LiveFrame>),
}

/// Why [`LiveSource::next_frame`] returned no frame.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum End {
    /// The stop flag was raised.
    Stopped,
    /// No packet for the idle timeout after packets had come: the stream ended.
    Idle,
}

/// A datagram and when it came.
struct Datagram {
    payload: Vec<u8>,
    at: Instant,
    unix_ns: u64,
}

/// Bytes of socket receive buffer asked for (the kernel caps it, on Linux
/// at `net.core.rmem_max`): a few frames of the largest sensors, so that a
/// busy moment of the receiving thread loses nothing.
pub const RECEIVE_BUFFER: i32 = 8 << 20;

/// Set the socket option `name` (level `SOL_SOCKET`) to `value`; where the
/// system refuses, the option stays as it was.
#[cfg(unix)]
fn set_socket_int(socket: &UdpSocket, name: libc::c_int, value: libc::c_int) {
    use std::os::unix::io::AsRawFd;
    // SAFETY: a valid socket descriptor and a pointer to a c_int of the
    // length given, as setsockopt(2) requires.
    unsafe {
        libc::setsockopt(
            socket.as_raw_fd(),
            libc::SOL_SOCKET,
            name,
            (&value as *const libc::c_int).cast(),
            std::mem::size_of::<libc::c_int>() as libc::socklen_t,
        );
    }
}

/// Ask for a receive buffer of [`RECEIVE_BUFFER`] bytes; the default stays
/// where the system refuses.
#[cfg(unix)]
fn grow_receive_buffer(socket: &UdpSocket) {
    set_socket_int(socket, libc::SO_RCVBUF, RECEIVE_BUFFER);
}

#[cfg(not(unix))]
fn grow_receive_buffer(_: &UdpSocket) {}

/// Ask the kernel to attach its count of the datagrams it dropped for want
/// of buffer room to each datagram received ([`recv_counting`]).
#[cfg(target_os = "linux")]
fn count_kernel_drops(socket: &UdpSocket) {
    set_socket_int(socket, libc::SO_RXQ_OVFL, 1);
}

#[cfg(not(target_os = "linux"))]
fn count_kernel_drops(_: &UdpSocket) {}

/// One datagram into `buf`: its length, and the kernel's count of the
/// datagrams it has dropped on this socket so far, where it gives one.
#[cfg(target_os = "linux")]
fn recv_counting(socket: &UdpSocket, buf: &mut [u8]) -> std::io::Result<(usize, Option<u32>)> {
    use std::os::unix::io::AsRawFd;
    // Room for one control message of a u32, aligned as cmsghdr wants.
    let mut control = [0u64; 8];
    let mut iov = libc::iovec {
        iov_base: buf.as_mut_ptr().cast(),
        iov_len: buf.len(),
    };
    // SAFETY: msghdr is plain data; zeroed is its empty value.
    let mut msg: libc::msghdr = unsafe { std::mem::zeroed() };
    msg.msg_iov = &mut iov;
    msg.msg_iovlen = 1;
    msg.msg_control = control.as_mut_ptr().cast();
    msg.msg_controllen = std::mem::size_of_val(&control) as _;
    // SAFETY: `msg` points at `iov` (into `buf`) and `control`, which
    // outlive the call, with their lengths.
    let n = unsafe { libc::recvmsg(socket.as_raw_fd(), &mut msg, 0) };
    if n < 0 {
        return Err(std::io::Error::last_os_error());
    }
    let mut drops = None;
    // SAFETY: the CMSG macros walk the control buffer the kernel filled,
    // within `msg_controllen`.
    unsafe {
        let mut c = libc::CMSG_FIRSTHDR(&msg);
        while !c.is_null() {
            if (*c).cmsg_level == libc::SOL_SOCKET && (*c).cmsg_type == libc::SO_RXQ_OVFL {
                drops = Some(std::ptr::read_unaligned(libc::CMSG_DATA(c).cast::<u32>()));
            }
            c = libc::CMSG_NXTHDR(&msg, c);
        }
    }
    Ok((n as usize, drops))
}

#[cfg(not(target_os = "linux"))]
fn recv_counting(socket: &UdpSocket, buf: &mut [u8]) -> std::io::Result<(usize, Option<u32>)> {
    socket.recv(buf).map(|n| (n, None))
}

impl Reading {
    /// Start the receiving thread of [`Receive::Thread`] on `socket`.
    fn thread(socket: UdpSocket) -> Result<Reading> {
        let (tx, queue) = sync_channel::<Datagram>(QUEUE_PACKETS);
        let dropped = Arc::new(AtomicU64::new(0));
        let kernel = Arc::new(AtomicU64::new(0));
        let quit = Arc::new(AtomicBool::new(false));
        let (d, kd, q) = (dropped.clone(), kernel.clone(), quit.clone());
        let thread = std::thread::Builder::new()
            .name("fcc-udp".into())
            .spawn(move || {
                let mut buf = vec![0u8; MAX_DATAGRAM];
                while !q.load(Ordering::Relaxed) {
                    let n = match recv_counting(&socket, &mut buf) {
                        Ok((n, drops)) => {
                            if let Some(k) = drops {
                                kd.store(u64::from(k), Ordering::Relaxed);
                            }
                            n
                        }
                        // Timeouts (to look at the flag) and transient errors.
                        Err(_) => continue,
                    };
                    let dg = Datagram {
                        payload: buf[..n].to_vec(),
                        at: Instant::now(),
                        unix_ns: unix_ns(),
                    };
                    match tx.try_send(dg) {
                        Ok(()) => {}
                        Err(TrySendError::Full(_)) => {
                            d.fetch_add(1, Ordering::Relaxed);
                        }
                        Err(TrySendError::Disconnected(_)) => break,
                    }
                }
            })
            .map_err(|e| LidarError::Config(format!("cannot start the UDP thread: {e}")))?;
        Ok(Reading::Thread {
            queue,
            dropped,
            kernel,
            quit,
            thread: Some(thread),
        })
    }

    /// The next datagram within `wait`, `None` when none came; an error
    /// when the receiving thread has stopped.
    fn next(&mut self, wait: Duration) -> std::result::Result<Option<Datagram>, ()> {
        match self {
            Reading::Thread { queue, .. } => match queue.recv_timeout(wait) {
                Ok(dg) => Ok(Some(dg)),
                Err(RecvTimeoutError::Timeout) => Ok(None),
                Err(RecvTimeoutError::Disconnected) => Err(()),
            },
            Reading::Inline {
                socket,
                buf,
                timeout,
                dropped,
            } => {
                // The socket's timeout moves only for a wait shorter than
                // the poll (the idle timeout's last moments).
                let want = wait.clamp(Duration::from_millis(1), POLL);
                if want != *timeout && socket.set_read_timeout(Some(want)).is_ok() {
                    *timeout = want;
                }
                // Timeouts, signals and transient errors: nothing came.
                let Ok((n, drops)) = recv_counting(socket, buf) else {
                    return Ok(None);
                };
                if let Some(k) = drops {
                    *dropped = u64::from(k);
                }
                Ok(Some(Datagram {
                    payload: buf[..n].to_vec(),
                    at: Instant::now(),
                    unix_ns: unix_ns(),
                }))
            }
        }
    }

    /// Packets dropped for want of room so far.
    fn dropped(&self) -> u64 {
        match self {
            Reading::Thread {
                dropped, kernel, ..
            } => dropped.load(Ordering::Relaxed) + kernel.load(Ordering::Relaxed),
            Reading::Inline { dropped, .. } => *dropped,
        }
    }
}

/// How the socket is read ([`Receive`]).
enum Reading {
    Thread {
        queue: Receiver<Datagram>,
        /// Datagrams the queue had no room for.
        dropped: Arc<AtomicU64>,
        /// The kernel's count of datagrams dropped, as last given.
        kernel: Arc<AtomicU64>,
        quit: Arc<AtomicBool>,
        thread: Option<JoinHandle<()>>,
    },
    Inline {
        socket: UdpSocket,
        buf: Vec<u8>,
        /// The read timeout set on the socket.
        timeout: Duration,
        /// The kernel's count of datagrams dropped, as last given.
        dropped: u64,
    },
}

/// The system clock, nanoseconds since the Unix epoch (0 before it).
fn unix_ns() -> u64 {
    std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_nanos() as u64)
}

/// A bound socket and its decoder.
pub struct LiveSource {
    decoder: Decoder,
    addr: SocketAddr,
    port: u16,
    opts: LiveOptions,
    reading: Reading,
    stats: LiveStats,
    last_packet: Option<(Instant, u64)>,
    started: Instant,
    undecodable_run: u64,
    /// Receive times of the latest decoded packets, by their number.
    recent: std::collections::VecDeque<(u64, Instant)>,
    /// Sizes of the datagrams of the current undecodable run.
    run_sizes: std::collections::BTreeMap<usize, u64>,
    /// Events of the last datagram not yet handed out.
    pending: std::collections::VecDeque<Event>,
    /// The frame id and complete columns last reported as [`Event::Columns`].
    reported: Option<(u16, usize)>,
    ended: bool,
}

impl LiveSource {
    /// Bind `addr` (UDP) and start receiving.
    pub fn bind(addr: SocketAddr, mut decoder: Decoder, opts: LiveOptions) -> Result<LiveSource> {
        if let Decoder::Ouster(d) = &mut decoder {
            d.set_columns_read(opts.columns_read);
        }
        let io = |e: std::io::Error| LidarError::Config(format!("udp {addr}: cannot bind: {e}"));
        let socket = UdpSocket::bind(addr).map_err(io)?;
        socket.set_read_timeout(Some(POLL)).map_err(io)?;
        grow_receive_buffer(&socket);
        count_kernel_drops(&socket);
        let local = socket.local_addr().map_err(io)?;
        let reading = match opts.receive {
            Receive::Thread => Reading::thread(socket)?,
            Receive::Inline => Reading::Inline {
                socket,
                buf: vec![0u8; MAX_DATAGRAM],
                timeout: POLL,
                dropped: 0,
            },
        };
        Ok(LiveSource {
            decoder,
            addr: SocketAddr::new(addr.ip(), local.port()),
            port: local.port(),
            opts,
            reading,
            stats: LiveStats::default(),
            last_packet: None,
            started: Instant::now(),
            undecodable_run: 0,
            recent: Default::default(),
            run_sizes: Default::default(),
            pending: Default::default(),
            reported: None,
            ended: false,
        })
    }

    /// The address bound (with the port the system chose for port 0).
    pub fn local_port(&self) -> u16 {
        self.port
    }

    /// What was met so far.
    pub fn stats(&self) -> LiveStats {
        let mut s = self.stats.clone();
        s.dropped = self.reading.dropped();
        s
    }

    /// The decoder in use.
    pub fn decoder(&self) -> &Decoder {
        &self.decoder
    }

    /// The next frame as its last packet arrives, or why there is none:
    /// `stop` raised, or the idle timeout after the stream ended (the frame
    /// being received is then delivered first, as at the end of a capture).
    /// No packet at all within the idle timeout is an error, as is a long
    /// run of packets that the decoder cannot use.
    pub fn next_frame(&mut self, stop: &AtomicBool) -> Result<std::result::Result<LiveFrame, End>> {
        loop {
            match self.next_event(stop)? {
                Ok(Event::Frame(f)) => return Ok(Ok(*f)),
                Ok(Event::Columns { .. }) => {}
                Err(e) => return Ok(Err(e)),
            }
        }
    }

    /// Image column `col` of the Ouster frame being received (see
    /// [`Event::Columns`]), one entry per beam; empty for Velodyne.
    pub fn column_into(&self, col: usize, out: &mut [Option<[f32; 3]>]) {
        match &self.decoder {
            Decoder::Ouster(d) => d.column_into(col, out),
            Decoder::Velodyne(_) => out.fill(None),
        }
    }

    /// As [`next_frame`](Self::next_frame), with the columns of the Ouster
    /// frame being received as they become complete: an [`Event::Columns`]
    /// after each packet that completes some, an [`Event::Frame`] when the
    /// frame ends (after its last columns' event).
    pub fn next_event(&mut self, stop: &AtomicBool) -> Result<std::result::Result<Event, End>> {
        if let Some(e) = self.pending.pop_front() {
            return Ok(Ok(e));
        }
        if self.ended {
            return Ok(Err(End::Idle));
        }
        loop {
            if stop.load(Ordering::Relaxed) {
                return Ok(Err(End::Stopped));
            }
            let since = self.last_packet.map_or(self.started, |p| p.0).elapsed();
            if since >= self.opts.idle_timeout {
                if self.last_packet.is_none() {
                    return Err(LidarError::Config(format!(
                        "udp {}: no packet in {:.1} s (--idle-timeout): is the sensor sending to this host and port?",
                        self.addr,
                        self.opts.idle_timeout.as_secs_f64()
                    )));
                }
                self.ended = true;
                let at = self.last_packet.unwrap_or((self.started, unix_ns()));
                return Ok(match self.flush(at) {
                    Some(f) => Ok(Event::Frame(Box::new(f))),
                    None => Err(End::Idle),
                });
            }
            let wait = (self.opts.idle_timeout - since).min(POLL);
            let dg = match self.reading.next(wait) {
                Ok(Some(dg)) => dg,
                Ok(None) => continue,
                Err(()) => {
                    return Err(LidarError::Config(format!(
                        "udp {}: the receiving thread stopped",
                        self.addr
                    )))
                }
            };
            self.last_packet = Some((dg.at, dg.unix_ns));
            self.stats.packets += 1;
            if let Some(f) = self.push(&dg.payload, (dg.at, dg.unix_ns))? {
                self.pending.push_back(Event::Frame(Box::new(f)));
            }
            if let Decoder::Ouster(d) = &self.decoder {
                let now = d.ready_columns();
                if let Some((frame, ready)) = now.filter(|&(_, r)| r > 0) {
                    if self.reported != now {
                        self.reported = now;
                        self.pending.push_back(Event::Columns {
                            frame: u64::from(frame),
                            ready,
                            at: dg.at,
                        });
                    }
                }
            }
            if let Some(e) = self.pending.pop_front() {
                return Ok(Ok(e));
            }
        }
    }

    /// One datagram through the decoder.
    fn push(&mut self, payload: &[u8], at: (Instant, u64)) -> Result<Option<LiveFrame>> {
        let port = self.port;
        let (before, frame) = match &mut self.decoder {
            Decoder::Ouster(d) => {
                let before = d.stats().lidar_packets;
                let f = d.push(port, payload);
                (before, f.map(|f| ouster_frame(d, f, at, &self.recent)))
            }
            Decoder::Velodyne(d) => {
                let before = d.stats().data_packets;
                let f = d.push(payload)?;
                (before, f.map(|f| velodyne_frame(f, at)))
            }
        };
        self.count();
        let decoded = self.stats.decoded > before;
        if decoded {
            if self.recent.len() >= QUEUE_PACKETS {
                self.recent.pop_front();
            }
            self.recent.push_back((self.stats.decoded, at.0));
            self.undecodable_run = 0;
            self.run_sizes.clear();
        } else {
            self.undecodable_run += 1;
            *self.run_sizes.entry(payload.len()).or_insert(0) += 1;
            if self.undecodable_run >= UNDECODABLE_RUN {
                return Err(self.undecodable_error());
            }
        }
        if let Some(f) = &frame {
            self.stats.frames += 1;
            self.stats.lost_columns += f.lost_columns as u64;
        }
        Ok(frame)
    }

    /// The end of the stream: the frame being received, if it makes one.
    fn flush(&mut self, at: (Instant, u64)) -> Option<LiveFrame> {
        let frame = match &mut self.decoder {
            Decoder::Ouster(d) => {
                let f = d.flush();
                f.map(|f| ouster_frame(d, f, at, &self.recent))
            }
            Decoder::Velodyne(d) => d.flush().map(|f| velodyne_frame(f, at)),
        };
        self.count();
        if let Some(f) = &frame {
            self.stats.frames += 1;
            self.stats.lost_columns += f.lost_columns as u64;
        }
        frame.map(|f| LiveFrame { at_end: true, ..f })
    }

    /// Copy the decoder's counts into the stats.
    fn count(&mut self) {
        let s = &mut self.stats;
        match &self.decoder {
            Decoder::Ouster(d) => {
                let c = d.stats();
                s.decoded = c.lidar_packets;
                s.malformed = c.malformed_packets + c.other_datagrams.values().sum::<u64>();
                s.foreign = c.foreign_packets;
                s.duplicate_columns = c.duplicate_columns;
                s.incomplete_frames = c.incomplete_frames;
            }
            Decoder::Velodyne(d) => {
                let c = d.stats();
                s.decoded = c.data_packets;
                s.malformed = c.malformed_packets + c.other_datagrams.values().sum::<u64>();
                s.foreign = c.foreign_packets;
                s.incomplete_frames = c.incomplete_frames;
            }
        }
    }

    fn undecodable_error(&self) -> LidarError {
        let sizes: Vec<String> = self
            .run_sizes
            .iter()
            .map(|(k, v)| format!("{v} of {k} bytes"))
            .collect();
        let expect = match &self.decoder {
            Decoder::Ouster(d) => {
                let m = d.metadata();
                format!(
                    "the metadata ({}) expects {}-byte lidar packets ({}, {} beams, {} columns per packet{})",
                    m.source.display(),
                    m.packet_size(),
                    m.profile.name(),
                    m.pixels_per_column,
                    m.columns_per_packet,
                    m.prod_sn.map(|s| format!(", serial {s}")).unwrap_or_default()
                )
            }
            Decoder::Velodyne(d) => format!(
                "the decoder expects {}-byte data packets of a {}",
                crate::velodyne::DATA_PACKET,
                d.model().map_or("Velodyne sensor", |m| m.name())
            ),
        };
        LidarError::Config(format!(
            "udp {}: {} packets in a row could not be decoded ({}; {} from another sensor): {expect}; is this the sensor's metadata, model and profile?",
            self.addr,
            self.undecodable_run,
            sizes.join(", "),
            self.stats.foreign
        ))
    }
}

impl Drop for Reading {
    fn drop(&mut self) {
        if let Reading::Thread { quit, thread, .. } = self {
            quit.store(true, Ordering::Relaxed);
            if let Some(t) = thread.take() {
                let _ = t.join();
            }
        }
    }
}

fn ouster_frame(
    d: &OusterDecoder,
    f: OusterFrame,
    at: (Instant, u64),
    recent: &std::collections::VecDeque<(u64, Instant)>,
) -> LiveFrame {
    let time_of = |seq: u64| {
        let k = recent.partition_point(|&(s, _)| s < seq);
        recent.get(k).filter(|&&(s, _)| s == seq).map(|&(_, t)| t)
    };
    let column_received = f
        .column_packet
        .iter()
        .map(|&seq| if seq == 0 { None } else { time_of(seq) })
        .collect();
    let mut shifts = d.column_offsets().to_vec();
    shifts.sort_unstable();
    shifts.dedup();
    let lost = d
        .metadata()
        .window_columns()
        .saturating_sub(f.stats.columns);
    LiveFrame {
        frame: u64::from(f.frame_id),
        complete: f.stats.complete,
        lost_columns: lost,
        image: f.image,
        intensity: f.reflectivity,
        received_at: at.0,
        received_unix_ns: at.1,
        at_end: false,
        sensor_ns: Some(f.timestamp_ns).filter(|&t| t != 0),
        column_received,
        shifts,
    }
}

fn velodyne_frame(f: VelodyneFrame, at: (Instant, u64)) -> LiveFrame {
    LiveFrame {
        frame: f.index as u64,
        complete: f.complete,
        lost_columns: 0,
        image: f.image,
        intensity: f.intensity,
        received_at: at.0,
        received_unix_ns: at.1,
        at_end: false,
        sensor_ns: None,
        column_received: Vec::new(),
        shifts: Vec::new(),
    }
}
