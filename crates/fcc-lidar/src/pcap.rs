//! Packet captures: classic pcap (either byte order, micro- or nanosecond
//! timestamps) and pcapng, down to the UDP payloads inside them.
//!
//! Link layers: Ethernet (with 802.1Q tags), raw IP, BSD loopback, Linux
//! cooked (SLL and SLL2). Network layers: IPv4, with fragments reassembled,
//! and IPv6 without extension headers. Anything else is counted and
//! skipped; a record cut short by the capture's snap length or by the end of
//! the file is counted, never decoded. A file that is not a capture at all,
//! or whose record lengths are impossible, is an error naming the file and
//! the byte offset.

use crate::error::{LidarError, Result};
use std::collections::{HashMap, VecDeque};
use std::fs::File;
use std::io::{BufReader, BufWriter, ErrorKind, Read, Write};
use std::path::{Path, PathBuf};

/// A record longer than this is taken as a sign of a corrupt file.
const MAX_RECORD: usize = 1 << 20;
/// IPv4 datagrams waiting for fragments; the oldest is dropped beyond this.
const MAX_PENDING_DATAGRAMS: usize = 256;

/// One UDP datagram found in a capture.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct UdpDatagram {
    pub src_port: u16,
    pub dst_port: u16,
    pub payload: Vec<u8>,
    /// Capture time of the record that completed it, microseconds since the
    /// epoch (pcapng: taken in the default microsecond resolution).
    pub time_us: u64,
}

/// What the reader met on its way through a capture.
#[derive(Debug, Clone, Default, PartialEq, Eq, serde::Serialize)]
pub struct PcapStats {
    /// Records (packet blocks) read.
    pub records: u64,
    /// Records whose captured length is shorter than the packet on the wire.
    pub truncated_records: u64,
    /// The file ended in the middle of a record.
    pub truncated_file: bool,
    /// Records with a link or network layer this reader does not decode
    /// (ARP, unknown link types, ...).
    pub not_ip: u64,
    /// IP packets carrying something other than UDP.
    pub not_udp: u64,
    /// IP or UDP headers that contradict their own lengths.
    pub bad_headers: u64,
    /// IPv4 fragments seen.
    pub fragments: u64,
    /// Datagrams put back together from fragments.
    pub reassembled: u64,
    /// Fragments that never made a whole datagram.
    pub unreassembled_fragments: u64,
    /// UDP datagrams delivered.
    pub udp_datagrams: u64,
}

#[derive(Debug, Clone, Copy)]
enum Format {
    /// `nanos`: record times in nanoseconds (magic a1b23c4d).
    Classic {
        swapped: bool,
        linktype: u32,
        nanos: bool,
    },
    Ng {
        swapped: bool,
    },
}

/// Reads UDP datagrams out of a classic pcap or pcapng stream.
pub struct PcapReader<R: Read> {
    path: PathBuf,
    reader: R,
    offset: u64,
    format: Format,
    /// pcapng: link type per interface of the current section.
    interfaces: Vec<u32>,
    frags: Reassembler,
    ready: VecDeque<UdpDatagram>,
    stats: PcapStats,
    done: bool,
    /// Capture time of the latest record, microseconds.
    record_time_us: u64,
}

impl PcapReader<BufReader<File>> {
    /// Open a capture file.
    pub fn open(path: &Path) -> Result<Self> {
        let file = File::open(path).map_err(|e| LidarError::io(path, e))?;
        PcapReader::new(path, BufReader::with_capacity(1 << 16, file))
    }
}

fn u16_at(b: &[u8], swapped: bool) -> u16 {
    let v = [b[0], b[1]];
    if swapped {
        u16::from_be_bytes(v)
    } else {
        u16::from_le_bytes(v)
    }
}

fn u32_at(b: &[u8], swapped: bool) -> u32 {
    let v = [b[0], b[1], b[2], b[3]];
    if swapped {
        u32::from_be_bytes(v)
    } else {
        u32::from_le_bytes(v)
    }
}

/// Read exactly `buf.len()` bytes; `Ok(false)` on a clean end of file
/// before the first byte, an error naming `what` on a partial read.
fn read_full<R: Read>(r: &mut R, buf: &mut [u8]) -> std::io::Result<usize> {
    let mut got = 0;
    while got < buf.len() {
        match r.read(&mut buf[got..]) {
            Ok(0) => break,
            Ok(n) => got += n,
            Err(e) if e.kind() == ErrorKind::Interrupted => {}
            Err(e) => return Err(e),
        }
    }
    Ok(got)
}

impl<R: Read> PcapReader<R> {
    /// Wrap a stream; `path` is only used in messages.
    pub fn new(path: &Path, mut reader: R) -> Result<Self> {
        let mut head = [0u8; 24];
        let got = read_full(&mut reader, &mut head).map_err(|e| LidarError::io(path, e))?;
        let not = |why: String| LidarError::not_format(path, "pcap or pcapng", why);
        if got < 4 {
            return Err(not(format!("the file holds only {got} bytes")));
        }
        let magic = u32::from_le_bytes([head[0], head[1], head[2], head[3]]);
        let format = match magic {
            0xa1b2_c3d4 | 0xa1b2_3c4d => Format::Classic {
                swapped: false,
                linktype: 0,
                nanos: magic == 0xa1b2_3c4d,
            },
            0xd4c3_b2a1 | 0x4d3c_b2a1 => Format::Classic {
                swapped: true,
                linktype: 0,
                nanos: magic == 0x4d3c_b2a1,
            },
            0x0a0d_0d0a => Format::Ng { swapped: false },
            _ => {
                return Err(not(format!(
                    "unknown magic number {magic:#010x} (classic pcap starts with a1b2c3d4, pcapng with 0a0d0d0a)"
                )))
            }
        };
        let mut me = PcapReader {
            path: path.to_path_buf(),
            reader,
            offset: 0,
            format,
            interfaces: Vec::new(),
            frags: Reassembler::default(),
            ready: VecDeque::new(),
            stats: PcapStats::default(),
            done: false,
            record_time_us: 0,
        };
        match format {
            Format::Classic { swapped, nanos, .. } => {
                if got < 24 {
                    return Err(not(format!(
                        "the 24-byte file header is cut at {got} bytes"
                    )));
                }
                let major = u16_at(&head[4..6], swapped);
                if major != 2 {
                    return Err(not(format!("pcap version {major} (only version 2 exists)")));
                }
                me.format = Format::Classic {
                    swapped,
                    nanos,
                    linktype: u32_at(&head[20..24], swapped) & 0x0fff_ffff,
                };
                me.offset = 24;
            }
            Format::Ng { .. } => {
                if got < 12 {
                    return Err(not("the section header block is cut short".into()));
                }
                // Section header: type, length, byte-order magic.
                let bom = u32::from_le_bytes([head[8], head[9], head[10], head[11]]);
                let swapped = match bom {
                    0x1a2b_3c4d => false,
                    0x4d3c_2b1a => true,
                    _ => return Err(not(format!("bad pcapng byte-order magic {bom:#010x}"))),
                };
                me.format = Format::Ng { swapped };
                let len = u32_at(&head[4..8], swapped) as usize;
                if !(28..=MAX_RECORD).contains(&len) || len % 4 != 0 {
                    return Err(not(format!(
                        "section header block length {len} is impossible"
                    )));
                }
                if got < 24 {
                    return Err(not("the section header block is cut short".into()));
                }
                me.offset = 24;
                let mut rest = vec![0u8; len - 24];
                let n =
                    read_full(&mut me.reader, &mut rest).map_err(|e| LidarError::io(path, e))?;
                if n < rest.len() {
                    me.stats.truncated_file = true;
                    me.done = true;
                }
                me.offset += n as u64;
            }
        }
        Ok(me)
    }

    /// What was met so far.
    pub fn stats(&self) -> &PcapStats {
        &self.stats
    }

    /// The next UDP datagram, `Ok(None)` at the end of the capture.
    pub fn next_datagram(&mut self) -> Result<Option<UdpDatagram>> {
        loop {
            if let Some(d) = self.ready.pop_front() {
                self.stats.udp_datagrams += 1;
                return Ok(Some(d));
            }
            if self.done {
                self.stats.unreassembled_fragments += self.frags.drain();
                return Ok(None);
            }
            match self.next_record()? {
                Some((linktype, data, orig_len)) => {
                    self.stats.records += 1;
                    if data.len() < orig_len {
                        self.stats.truncated_records += 1;
                        continue;
                    }
                    self.decode_link(linktype, &data);
                }
                None => self.done = true,
            }
        }
    }

    fn corrupt(&self, why: String) -> LidarError {
        LidarError::malformed(
            &self.path,
            format!("corrupt capture at byte {}: {why}", self.offset),
        )
    }

    /// Read `n` bytes of a record body; `None` if the file ends first.
    fn read_body(&mut self, n: usize) -> Result<Option<Vec<u8>>> {
        self.read_part(n, false)
    }

    /// Read a record header: ending before its first byte is a clean end.
    fn read_head(&mut self, n: usize) -> Result<Option<Vec<u8>>> {
        self.read_part(n, true)
    }

    fn read_part(&mut self, n: usize, clean_end_ok: bool) -> Result<Option<Vec<u8>>> {
        let mut buf = vec![0u8; n];
        let got =
            read_full(&mut self.reader, &mut buf).map_err(|e| LidarError::io(&self.path, e))?;
        self.offset += got as u64;
        if got < n {
            if !(clean_end_ok && got == 0) {
                self.stats.truncated_file = true;
            }
            return Ok(None);
        }
        Ok(Some(buf))
    }

    /// The next packet record: (link type, captured bytes, length on the wire).
    fn next_record(&mut self) -> Result<Option<(u32, Vec<u8>, usize)>> {
        match self.format {
            Format::Classic {
                swapped,
                linktype,
                nanos,
            } => {
                let Some(h) = self.read_head(16)? else {
                    // A clean end of file reads zero bytes of the header.
                    return Ok(None);
                };
                let (sec, frac) = (
                    u64::from(u32_at(&h[0..4], swapped)),
                    u64::from(u32_at(&h[4..8], swapped)),
                );
                self.record_time_us = sec * 1_000_000 + if nanos { frac / 1000 } else { frac };
                let incl = u32_at(&h[8..12], swapped) as usize;
                let orig = u32_at(&h[12..16], swapped) as usize;
                if incl > MAX_RECORD {
                    self.offset -= 16;
                    return Err(self.corrupt(format!("a record claims {incl} captured bytes")));
                }
                let Some(data) = self.read_body(incl)? else {
                    return Ok(None);
                };
                Ok(Some((linktype, data, orig.max(incl))))
            }
            Format::Ng { swapped } => loop {
                let Some(h) = self.read_head(8)? else {
                    return Ok(None);
                };
                let btype = u32_at(&h[0..4], swapped);
                let blen = u32_at(&h[4..8], swapped) as usize;
                if btype == 0x0a0d_0d0a {
                    // A new section may change byte order; re-read it.
                    return self.new_section([h[4], h[5], h[6], h[7]]);
                }
                if !(12..=MAX_RECORD).contains(&blen) || blen % 4 != 0 {
                    self.offset -= 8;
                    return Err(
                        self.corrupt(format!("block of type {btype:#x} claims length {blen}"))
                    );
                }
                let Some(body) = self.read_body(blen - 8)? else {
                    return Ok(None);
                };
                let body = &body[..blen - 12];
                match btype {
                    1 if body.len() >= 8 => {
                        self.interfaces
                            .push(u32::from(u16_at(&body[0..2], swapped)));
                    }
                    6 | 2 if body.len() >= 20 => {
                        let iface = if btype == 6 {
                            u32_at(&body[0..4], swapped) as usize
                        } else {
                            usize::from(u16_at(&body[0..2], swapped))
                        };
                        let cap = u32_at(&body[12..16], swapped) as usize;
                        let orig = u32_at(&body[16..20], swapped) as usize;
                        if btype == 6 {
                            let (hi, lo) = (
                                u64::from(u32_at(&body[4..8], swapped)),
                                u64::from(u32_at(&body[8..12], swapped)),
                            );
                            self.record_time_us = (hi << 32) | lo;
                        }
                        let Some(&linktype) = self.interfaces.get(iface) else {
                            return Err(self.corrupt(format!(
                                "packet names interface {iface}, which was never described"
                            )));
                        };
                        if 20 + cap > body.len() {
                            return Err(self.corrupt(format!(
                                "packet block holds {} bytes, claims {cap}",
                                body.len() - 20
                            )));
                        }
                        return Ok(Some((linktype, body[20..20 + cap].to_vec(), orig.max(cap))));
                    }
                    3 if body.len() >= 4 => {
                        let Some(&linktype) = self.interfaces.first() else {
                            return Err(
                                self.corrupt("simple packet block before any interface".into())
                            );
                        };
                        let orig = u32_at(&body[0..4], swapped) as usize;
                        let cap = orig.min(body.len() - 4);
                        return Ok(Some((linktype, body[4..4 + cap].to_vec(), orig)));
                    }
                    _ => {}
                }
            },
        }
    }

    fn new_section(&mut self, raw_len: [u8; 4]) -> Result<Option<(u32, Vec<u8>, usize)>> {
        let Some(b) = self.read_body(4)? else {
            return Ok(None);
        };
        let swapped = match u32::from_le_bytes([b[0], b[1], b[2], b[3]]) {
            0x1a2b_3c4d => false,
            0x4d3c_2b1a => true,
            bom => return Err(self.corrupt(format!("bad pcapng byte-order magic {bom:#010x}"))),
        };
        // The length was read before the byte order was known: read it again.
        let len = u32_at(&raw_len, swapped) as usize;
        if !(28..=MAX_RECORD).contains(&len) || len % 4 != 0 {
            return Err(self.corrupt(format!("section header block length {len} is impossible")));
        }
        if self.read_body(len - 12)?.is_none() {
            return Ok(None);
        }
        self.format = Format::Ng { swapped };
        self.interfaces.clear();
        self.next_record()
    }

    fn decode_link(&mut self, linktype: u32, data: &[u8]) {
        let ip = match linktype {
            // Ethernet, with any number of 802.1Q / 802.1ad tags.
            1 => {
                let mut off = 12;
                loop {
                    if data.len() < off + 2 {
                        self.stats.not_ip += 1;
                        return;
                    }
                    let et = u16::from_be_bytes([data[off], data[off + 1]]);
                    if et == 0x8100 || et == 0x88a8 {
                        off += 4;
                        continue;
                    }
                    if et != 0x0800 && et != 0x86dd {
                        self.stats.not_ip += 1;
                        return;
                    }
                    break &data[off + 2..];
                }
            }
            // Raw IP (101, and 12 / 14 on some systems).
            101 | 12 | 14 => data,
            // BSD loopback: a 4-byte address family in host order.
            0 | 108 => data.get(4..).unwrap_or(&[]),
            // Linux cooked capture v1: protocol at bytes 14..16.
            113 => data.get(16..).unwrap_or(&[]),
            // Linux cooked capture v2: protocol at bytes 0..2.
            276 => data.get(20..).unwrap_or(&[]),
            _ => {
                self.stats.not_ip += 1;
                return;
            }
        };
        match ip.first().map(|b| b >> 4) {
            Some(4) => self.decode_ipv4(ip),
            Some(6) => self.decode_ipv6(ip),
            _ => self.stats.not_ip += 1,
        }
    }

    fn decode_ipv4(&mut self, ip: &[u8]) {
        if ip.len() < 20 {
            self.stats.bad_headers += 1;
            return;
        }
        let ihl = usize::from(ip[0] & 0x0f) * 4;
        let total = usize::from(u16::from_be_bytes([ip[2], ip[3]]));
        if ihl < 20 || total < ihl || total > ip.len() {
            self.stats.bad_headers += 1;
            return;
        }
        let proto = ip[9];
        let flags = u16::from_be_bytes([ip[6], ip[7]]);
        let more = flags & 0x2000 != 0;
        let frag_off = usize::from(flags & 0x1fff) * 8;
        let body = &ip[ihl..total];
        if more || frag_off != 0 {
            self.stats.fragments += 1;
            if proto != 17 {
                self.stats.not_udp += u64::from(frag_off == 0);
                return;
            }
            let key = FragKey {
                src: [ip[12], ip[13], ip[14], ip[15]],
                dst: [ip[16], ip[17], ip[18], ip[19]],
                id: u16::from_be_bytes([ip[4], ip[5]]),
            };
            match self.frags.add(key, frag_off, more, body) {
                FragResult::Pending => {}
                FragResult::Done(whole) => {
                    self.stats.reassembled += 1;
                    self.decode_udp(&whole);
                }
                FragResult::Dropped(n) => self.stats.unreassembled_fragments += n,
            }
            return;
        }
        if proto != 17 {
            self.stats.not_udp += 1;
            return;
        }
        self.decode_udp(body);
    }

    fn decode_ipv6(&mut self, ip: &[u8]) {
        if ip.len() < 40 {
            self.stats.bad_headers += 1;
            return;
        }
        let plen = usize::from(u16::from_be_bytes([ip[4], ip[5]]));
        if 40 + plen > ip.len() {
            self.stats.bad_headers += 1;
            return;
        }
        if ip[6] != 17 {
            self.stats.not_udp += 1;
            return;
        }
        self.decode_udp(&ip[40..40 + plen]);
    }

    fn decode_udp(&mut self, udp: &[u8]) {
        if udp.len() < 8 {
            self.stats.bad_headers += 1;
            return;
        }
        let len = usize::from(u16::from_be_bytes([udp[4], udp[5]]));
        // Length 0 is legal for jumbograms; otherwise it must fit.
        let end = if len == 0 { udp.len() } else { len };
        if end < 8 || end > udp.len() {
            self.stats.bad_headers += 1;
            return;
        }
        self.ready.push_back(UdpDatagram {
            src_port: u16::from_be_bytes([udp[0], udp[1]]),
            dst_port: u16::from_be_bytes([udp[2], udp[3]]),
            payload: udp[8..end].to_vec(),
            time_us: self.record_time_us,
        });
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
struct FragKey {
    src: [u8; 4],
    dst: [u8; 4],
    id: u16,
}

#[derive(Debug, Default)]
struct Pending {
    parts: Vec<(usize, Vec<u8>)>,
    total: Option<usize>,
    order: u64,
}

#[derive(Debug, Default)]
struct Reassembler {
    pending: HashMap<FragKey, Pending>,
    counter: u64,
}

enum FragResult {
    Pending,
    Done(Vec<u8>),
    Dropped(u64),
}

impl Reassembler {
    fn add(&mut self, key: FragKey, off: usize, more: bool, data: &[u8]) -> FragResult {
        let mut dropped = 0;
        if !self.pending.contains_key(&key) && self.pending.len() >= MAX_PENDING_DATAGRAMS {
            if let Some(oldest) = self
                .pending
                .iter()
                .min_by_key(|(_, p)| p.order)
                .map(|(k, _)| *k)
            {
                dropped = self
                    .pending
                    .remove(&oldest)
                    .map_or(0, |p| p.parts.len() as u64);
            }
        }
        self.counter += 1;
        let order = self.counter;
        let p = self.pending.entry(key).or_insert_with(|| Pending {
            order,
            ..Pending::default()
        });
        if !more {
            p.total = Some(off + data.len());
        }
        p.parts.push((off, data.to_vec()));
        let Some(total) = p.total else {
            return if dropped > 0 {
                FragResult::Dropped(dropped)
            } else {
                FragResult::Pending
            };
        };
        p.parts.sort_by_key(|(o, _)| *o);
        let mut covered = 0;
        for (o, d) in &p.parts {
            if *o > covered {
                return if dropped > 0 {
                    FragResult::Dropped(dropped)
                } else {
                    FragResult::Pending
                };
            }
            covered = covered.max(o + d.len());
        }
        if covered < total {
            return if dropped > 0 {
                FragResult::Dropped(dropped)
            } else {
                FragResult::Pending
            };
        }
        let p = self.pending.remove(&key).unwrap_or_default();
        let mut whole = vec![0u8; total];
        for (o, d) in p.parts {
            let end = (o + d.len()).min(total);
            if o < end {
                whole[o..end].copy_from_slice(&d[..end - o]);
            }
        }
        FragResult::Done(whole)
    }

    /// Forget everything pending; returns the fragments forgotten.
    fn drain(&mut self) -> u64 {
        self.pending
            .drain()
            .map(|(_, p)| p.parts.len() as u64)
            .sum()
    }
}

/// Writes a classic pcap (Ethernet, microsecond timestamps) of UDP/IPv4
/// datagrams: for trimming captures and for building test inputs.
pub struct PcapWriter<W: Write> {
    out: W,
    path: PathBuf,
    ip_id: u16,
    time_us: u64,
}

impl PcapWriter<BufWriter<File>> {
    /// Create a capture file.
    pub fn create(path: &Path) -> Result<Self> {
        let file = File::create(path).map_err(|e| LidarError::io(path, e))?;
        PcapWriter::new(path, BufWriter::new(file))
    }
}

impl<W: Write> PcapWriter<W> {
    /// Start a capture on a stream; `path` is only used in messages.
    pub fn new(path: &Path, mut out: W) -> Result<Self> {
        let mut h = Vec::with_capacity(24);
        h.extend_from_slice(&0xa1b2_c3d4u32.to_le_bytes());
        h.extend_from_slice(&2u16.to_le_bytes());
        h.extend_from_slice(&4u16.to_le_bytes());
        h.extend_from_slice(&0i32.to_le_bytes());
        h.extend_from_slice(&0u32.to_le_bytes());
        h.extend_from_slice(&65535u32.to_le_bytes());
        h.extend_from_slice(&1u32.to_le_bytes());
        out.write_all(&h).map_err(|e| LidarError::io(path, e))?;
        Ok(PcapWriter {
            out,
            path: path.to_path_buf(),
            ip_id: 1,
            time_us: 0,
        })
    }

    /// Write one record as it is: `data` captured of `orig_len` on the wire.
    pub fn write_record(&mut self, data: &[u8], orig_len: usize) -> Result<()> {
        let mut h = Vec::with_capacity(16);
        h.extend_from_slice(&((self.time_us / 1_000_000) as u32).to_le_bytes());
        h.extend_from_slice(&((self.time_us % 1_000_000) as u32).to_le_bytes());
        h.extend_from_slice(&(data.len() as u32).to_le_bytes());
        h.extend_from_slice(&(orig_len as u32).to_le_bytes());
        self.time_us += 100;
        let path = self.path.clone();
        self.out
            .write_all(&h)
            .map_err(|e| LidarError::io(&path, e))?;
        self.out
            .write_all(data)
            .map_err(|e| LidarError::io(&path, e))
    }

    /// Write one UDP datagram in Ethernet + IPv4, split into IPv4 fragments
    /// of at most `mtu` bytes of IP packet when `mtu` is given.
    pub fn write_udp(
        &mut self,
        src_port: u16,
        dst_port: u16,
        payload: &[u8],
        mtu: Option<usize>,
    ) -> Result<()> {
        if payload.len() + 8 > 65_507 {
            return Err(LidarError::Config(format!(
                "a UDP payload of {} bytes does not fit IPv4",
                payload.len()
            )));
        }
        let mut udp = Vec::with_capacity(payload.len() + 8);
        udp.extend_from_slice(&src_port.to_be_bytes());
        udp.extend_from_slice(&dst_port.to_be_bytes());
        udp.extend_from_slice(&((payload.len() + 8) as u16).to_be_bytes());
        udp.extend_from_slice(&0u16.to_be_bytes());
        udp.extend_from_slice(payload);
        let id = self.ip_id;
        self.ip_id = self.ip_id.wrapping_add(1);
        // Fragment payloads must be multiples of 8 bytes, except the last.
        let chunk = match mtu {
            Some(m) => ((m.saturating_sub(20)) / 8 * 8).max(8),
            None => udp.len().max(1),
        };
        let mut off = 0;
        while off < udp.len() || off == 0 {
            let end = (off + chunk).min(udp.len());
            let more = end < udp.len();
            let body = &udp[off..end];
            let mut pkt = Vec::with_capacity(34 + body.len());
            pkt.extend_from_slice(&[0xff; 6]);
            pkt.extend_from_slice(&[0x02, 0, 0, 0, 0, 1]);
            pkt.extend_from_slice(&0x0800u16.to_be_bytes());
            let flags = (if more { 0x2000u16 } else { 0 }) | ((off / 8) as u16);
            let mut ip = [0u8; 20];
            ip[0] = 0x45;
            ip[2..4].copy_from_slice(&((20 + body.len()) as u16).to_be_bytes());
            ip[4..6].copy_from_slice(&id.to_be_bytes());
            ip[6..8].copy_from_slice(&flags.to_be_bytes());
            ip[8] = 64;
            ip[9] = 17;
            ip[12..16].copy_from_slice(&[192, 168, 1, 10]);
            ip[16..20].copy_from_slice(&[192, 168, 1, 1]);
            let mut sum: u32 = ip
                .chunks(2)
                .map(|w| u32::from(u16::from_be_bytes([w[0], w[1]])))
                .sum();
            while sum > 0xffff {
                sum = (sum & 0xffff) + (sum >> 16);
            }
            ip[10..12].copy_from_slice(&(!(sum as u16)).to_be_bytes());
            pkt.extend_from_slice(&ip);
            pkt.extend_from_slice(body);
            let n = pkt.len();
            self.write_record(&pkt, n)?;
            off = end;
            if end == udp.len() {
                break;
            }
        }
        Ok(())
    }

    /// Flush and hand back the stream.
    pub fn finish(mut self) -> Result<W> {
        self.out
            .flush()
            .map_err(|e| LidarError::io(&self.path, e))?;
        Ok(self.out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn read_all(bytes: &[u8]) -> Result<(Vec<UdpDatagram>, PcapStats)> {
        let mut r = PcapReader::new(Path::new("mem.pcap"), bytes)?;
        let mut out = Vec::new();
        while let Some(d) = r.next_datagram()? {
            out.push(d);
        }
        Ok((out, r.stats().clone()))
    }

    fn capture(f: impl FnOnce(&mut PcapWriter<Vec<u8>>)) -> Vec<u8> {
        let mut w = PcapWriter::new(Path::new("mem.pcap"), Vec::new()).unwrap();
        f(&mut w);
        w.finish().unwrap()
    }

    #[test]
    fn udp_round_trip() {
        let bytes = capture(|w| {
            w.write_udp(7502, 7502, b"hello", None).unwrap();
            w.write_udp(1, 7503, &[7u8; 1000], None).unwrap();
        });
        let (d, s) = read_all(&bytes).unwrap();
        assert_eq!(d.len(), 2);
        assert_eq!(d[0].payload, b"hello");
        assert_eq!(d[1].dst_port, 7503);
        assert_eq!(d[1].payload.len(), 1000);
        assert_eq!(s.records, 2);
        assert!(!s.truncated_file);
    }

    #[test]
    fn fragments_are_reassembled() {
        let payload: Vec<u8> = (0..20_000u32).map(|i| (i % 251) as u8).collect();
        let bytes = capture(|w| w.write_udp(7502, 7502, &payload, Some(1500)).unwrap());
        let (d, s) = read_all(&bytes).unwrap();
        assert_eq!(d.len(), 1);
        assert_eq!(d[0].payload, payload);
        assert_eq!(s.fragments, 14);
        assert_eq!(s.reassembled, 1);
    }

    #[test]
    fn missing_fragment_is_counted_not_delivered() {
        let payload = vec![1u8; 5000];
        let full = capture(|w| w.write_udp(7502, 7502, &payload, Some(1500)).unwrap());
        // Keep the file header and every record but the second.
        let mut recs = Vec::new();
        let mut off = 24;
        while off < full.len() {
            let incl = u32::from_le_bytes(full[off + 8..off + 12].try_into().unwrap()) as usize;
            recs.push(full[off..off + 16 + incl].to_vec());
            off += 16 + incl;
        }
        let mut cut = full[..24].to_vec();
        for (i, r) in recs.iter().enumerate() {
            if i != 1 {
                cut.extend_from_slice(r);
            }
        }
        let (d, s) = read_all(&cut).unwrap();
        assert!(d.is_empty());
        assert_eq!(s.fragments, 3);
        assert_eq!(s.unreassembled_fragments, 3);
    }

    #[test]
    fn truncated_file_and_snapped_records_are_counted() {
        let bytes = capture(|w| {
            w.write_udp(7502, 7502, &[1u8; 100], None).unwrap();
            w.write_record(&[0u8; 40], 400).unwrap();
            w.write_udp(7502, 7502, &[2u8; 100], None).unwrap();
        });
        let cut = &bytes[..bytes.len() - 10];
        let (d, s) = read_all(cut).unwrap();
        assert_eq!(d.len(), 1);
        assert_eq!(s.truncated_records, 1);
        assert!(s.truncated_file);
    }

    #[test]
    fn non_udp_and_non_ip_are_counted() {
        let bytes = capture(|w| {
            let mut arp = vec![0u8; 42];
            arp[12] = 0x08;
            arp[13] = 0x06;
            w.write_record(&arp, 42).unwrap();
            let mut tcp = vec![0u8; 54];
            tcp[12] = 0x08;
            tcp[14] = 0x45;
            tcp[16..18].copy_from_slice(&40u16.to_be_bytes());
            tcp[23] = 6;
            w.write_record(&tcp, 54).unwrap();
            let mut bad = vec![0u8; 34];
            bad[12] = 0x08;
            bad[14] = 0x45;
            bad[16..18].copy_from_slice(&900u16.to_be_bytes());
            w.write_record(&bad, 34).unwrap();
        });
        let (d, s) = read_all(&bytes).unwrap();
        assert!(d.is_empty());
        assert_eq!((s.not_ip, s.not_udp, s.bad_headers), (1, 1, 1));
    }

    #[test]
    fn garbage_is_a_clear_error() {
        let err = read_all(b"this is not a capture at all").unwrap_err();
        let msg = err.to_string();
        assert!(
            msg.contains("mem.pcap") && msg.contains("unknown magic"),
            "{msg}"
        );
        let err = read_all(&[0xd4, 0xc3]).unwrap_err();
        assert!(err.to_string().contains("only 2 bytes"), "{err}");
    }

    #[test]
    fn impossible_record_length_is_an_error_with_offset() {
        let mut bytes = capture(|w| w.write_udp(1, 2, b"x", None).unwrap());
        bytes[24 + 8..24 + 12].copy_from_slice(&0x7fff_ffffu32.to_le_bytes());
        let err = read_all(&bytes).unwrap_err().to_string();
        assert!(
            err.contains("byte 24") && err.contains("captured bytes"),
            "{err}"
        );
    }

    /// A pcapng file of one section, one Ethernet interface and the
    /// packets given, in the byte order chosen.
    pub(crate) fn pcapng(packets: &[Vec<u8>], big: bool) -> Vec<u8> {
        let w32 = |v: u32| {
            if big {
                v.to_be_bytes()
            } else {
                v.to_le_bytes()
            }
        };
        let w16 = |v: u16| {
            if big {
                v.to_be_bytes()
            } else {
                v.to_le_bytes()
            }
        };
        let mut out = Vec::new();
        out.extend_from_slice(&0x0a0d_0d0au32.to_le_bytes());
        out.extend_from_slice(&w32(28));
        out.extend_from_slice(&w32(0x1a2b_3c4d));
        out.extend_from_slice(&w16(1));
        out.extend_from_slice(&w16(0));
        out.extend_from_slice(&[0xff; 8]);
        out.extend_from_slice(&w32(28));
        out.extend_from_slice(&w32(1));
        out.extend_from_slice(&w32(20));
        out.extend_from_slice(&w16(1));
        out.extend_from_slice(&w16(0));
        out.extend_from_slice(&w32(65535));
        out.extend_from_slice(&w32(20));
        for p in packets {
            let padded = p.len().div_ceil(4) * 4;
            let len = 32 + padded as u32;
            out.extend_from_slice(&w32(6));
            out.extend_from_slice(&w32(len));
            out.extend_from_slice(&w32(0));
            out.extend_from_slice(&w32(0));
            out.extend_from_slice(&w32(0));
            out.extend_from_slice(&w32(p.len() as u32));
            out.extend_from_slice(&w32(p.len() as u32));
            out.extend_from_slice(p);
            out.resize(out.len() + padded - p.len(), 0);
            out.extend_from_slice(&w32(len));
        }
        out
    }

    #[test]
    fn pcapng_both_byte_orders() {
        let classic = capture(|w| {
            w.write_udp(7502, 7502, b"abcde", None).unwrap();
            w.write_udp(7502, 7503, b"fg", None).unwrap();
        });
        let mut pkts = Vec::new();
        let mut off = 24;
        while off < classic.len() {
            let incl = u32::from_le_bytes(classic[off + 8..off + 12].try_into().unwrap()) as usize;
            pkts.push(classic[off + 16..off + 16 + incl].to_vec());
            off += 16 + incl;
        }
        for big in [false, true] {
            let (d, s) = read_all(&pcapng(&pkts, big)).unwrap();
            assert_eq!(d.len(), 2, "big endian {big}");
            assert_eq!(d[0].payload, b"abcde");
            assert_eq!(d[1].payload, b"fg");
            assert_eq!(s.records, 2);
        }
    }
}
