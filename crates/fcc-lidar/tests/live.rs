//! One decoder, two transports: the packet decoders fed packet by packet
//! (as the live socket feeds them) give the capture readers' frames, and
//! the faults of a live stream, each crafted from a sample capture's
//! packets: loss, reordering, duplicates, a frame id jump, malformed
//! packets, packets of another profile, no packets at all. The socket tests
//! use 127.0.0.1 and stop by themselves (idle timeouts of a few seconds at
//! most), and run with both ways of reading the socket ([`Receive`]).

use fcc_lidar::live::{Decoder, End, LiveOptions, LiveSource, Receive, RECEIVE_BUFFER};
use fcc_lidar::ouster::{
    sample_dir, DecodeOptions, ImageOrigin, OusterDecoder, OusterFrame, OusterMetadata,
    OusterReader, Profile, SAMPLE_CAPTURES,
};
use fcc_lidar::pcap::{PcapReader, UdpDatagram};
use fcc_lidar::velodyne::{VelodyneDecoder, VelodyneOptions, VelodyneReader};
use fcc_lidar::RangeImage;
use std::net::{SocketAddr, UdpSocket};
use std::path::Path;
use std::sync::atomic::AtomicBool;
use std::time::{Duration, Instant};

fn datagrams(path: &Path) -> Vec<UdpDatagram> {
    let mut r = PcapReader::open(path).unwrap();
    let mut v = Vec::new();
    while let Some(d) = r.next_datagram().unwrap() {
        v.push(d);
    }
    v
}

fn meta(k: usize) -> OusterMetadata {
    OusterMetadata::from_file(&sample_dir().join(SAMPLE_CAPTURES[k].1)).unwrap()
}

/// The sample capture of a single-return 2.x profile (frame id in the
/// packet header): its metadata and lidar packets.
fn profile_capture() -> (OusterMetadata, Vec<Vec<u8>>) {
    for (k, (pcap, _)) in SAMPLE_CAPTURES.iter().enumerate() {
        let m = meta(k);
        if m.profile == Profile::Rng19Rfl8Sig16Nir16 {
            let size = m.packet_size();
            let p = datagrams(&sample_dir().join(pcap))
                .into_iter()
                .filter(|d| d.payload.len() == size)
                .map(|d| d.payload)
                .collect();
            return (m, p);
        }
    }
    panic!("no RNG19_RFL8_SIG16_NIR16 sample capture");
}

fn decode(
    m: &OusterMetadata,
    keep: bool,
    packets: &[Vec<u8>],
) -> (Vec<OusterFrame>, OusterDecoder) {
    let opts = DecodeOptions {
        keep_incomplete: keep,
        ..DecodeOptions::default()
    };
    let mut d = OusterDecoder::new(m, opts).unwrap();
    let port = m.udp_port_lidar.unwrap_or(7502);
    let mut frames: Vec<OusterFrame> = packets.iter().filter_map(|p| d.push(port, p)).collect();
    frames.extend(d.flush());
    (frames, d)
}

fn same_image(a: &RangeImage, b: &RangeImage) -> bool {
    a.rows == b.rows
        && a.cols == b.cols
        && (0..a.pixels()).all(|i| {
            a.point(i).map(|p| p.map(f32::to_bits)) == b.point(i).map(|p| p.map(f32::to_bits))
        })
}

fn set_frame_id(p: &mut [u8], id: u16) {
    p[2..4].copy_from_slice(&id.to_le_bytes());
}

#[test]
fn packets_pushed_one_by_one_give_the_readers_frames() {
    for (k, (pcap, _)) in SAMPLE_CAPTURES.iter().enumerate() {
        let m = meta(k);
        let path = sample_dir().join(pcap);
        let mut reader = OusterReader::open(&path, &m, DecodeOptions::default()).unwrap();
        let mut want = Vec::new();
        while let Some(f) = reader.next_frame().unwrap() {
            want.push(f);
        }
        let mut d = OusterDecoder::new(&m, DecodeOptions::default()).unwrap();
        let mut got = Vec::new();
        for dg in datagrams(&path) {
            got.extend(d.push(dg.dst_port, &dg.payload));
        }
        got.extend(d.flush());
        assert_eq!(got.len(), want.len(), "{pcap}");
        for (a, b) in got.iter().zip(&want) {
            assert_eq!(a.frame_id, b.frame_id);
            assert_eq!(a.stats, b.stats);
            assert!(same_image(&a.image, &b.image), "{pcap}");
        }
        let (mut s, r) = (d.stats().clone(), reader.stats());
        s.pcap = r.pcap.clone();
        assert_eq!(s, r, "{pcap}");
    }
    let path = sample_dir().join("velodyne/vlp16.pcap");
    let want: Vec<_> = VelodyneReader::open(&path, VelodyneOptions::default())
        .unwrap()
        .map(Result::unwrap)
        .collect();
    let mut d = VelodyneDecoder::new(&path, VelodyneOptions::default()).unwrap();
    let mut got = Vec::new();
    for dg in datagrams(&path) {
        got.extend(d.push(&dg.payload).unwrap());
    }
    got.extend(d.flush());
    assert_eq!(got.len(), want.len());
    for (a, b) in got.iter().zip(&want) {
        assert_eq!((a.index, a.complete), (b.index, b.complete));
        assert!(same_image(&a.image, &b.image));
    }
}

/// Columns read as they complete (`column_into` as `ready_columns` grows),
/// and the columns a frame's image holds when it ends with
/// `set_columns_read`, make the image of the capture reader, at both image
/// origins, with every packet and with one lost in each frame; the image
/// leaves the columns read empty.
#[test]
fn columns_read_as_they_complete_and_the_frame_end_make_the_readers_image() {
    let (m, packets) = profile_capture();
    let port = m.udp_port_lidar.unwrap_or(7502);
    let mut lossy = packets.clone();
    lossy.remove(10);
    for origin in [ImageOrigin::Sweep, ImageOrigin::Sensor] {
        for input in [&packets, &lossy] {
            let opts = DecodeOptions {
                origin,
                keep_incomplete: true,
                ..DecodeOptions::default()
            };
            let mut reference = OusterDecoder::new(&m, opts.clone()).unwrap();
            let mut want: Vec<OusterFrame> = input
                .iter()
                .filter_map(|p| reference.push(port, p))
                .collect();
            want.extend(reference.flush());
            let mut d = OusterDecoder::new(&m, opts).unwrap();
            d.set_columns_read(true);
            let (h, w) = (m.pixels_per_column, m.columns_per_frame);
            let mut col = vec![None; h];
            let (mut image, mut read) = (RangeImage::empty(h, w), 0);
            let (mut got, mut read_before_end) = (Vec::new(), 0);
            let mut end = |f: OusterFrame, image: &mut RangeImage, read: &mut usize| {
                for c in 0..w {
                    for r in 0..h {
                        let p = f.image.at(r, c);
                        if c < *read {
                            assert!(p.is_none(), "{origin:?}: column {c} read, yet in the image");
                        } else {
                            image.set(r * w + c, p);
                        }
                    }
                }
                read_before_end += *read;
                got.push(std::mem::replace(image, RangeImage::empty(h, w)));
                *read = 0;
            };
            for p in input {
                if let Some(f) = d.push(port, p) {
                    end(f, &mut image, &mut read);
                }
                let (_, ready) = d.ready_columns().unwrap();
                for c in read..ready {
                    d.column_into(c, &mut col);
                    for (r, p) in col.iter().enumerate() {
                        image.set(r * w + c, *p);
                    }
                }
                read = read.max(ready);
            }
            if let Some(f) = d.flush() {
                end(f, &mut image, &mut read);
            }
            assert_eq!(got.len(), want.len(), "{origin:?}");
            for (a, b) in got.iter().zip(&want) {
                assert!(
                    same_image(a, &b.image),
                    "{origin:?}, {} packets",
                    input.len()
                );
            }
            // The sweep origin reads columns before the end.
            assert!(origin == ImageOrigin::Sensor || read_before_end > 0);
        }
    }
}

#[test]
fn lost_packets_leave_their_columns_empty_and_are_counted() {
    let (m, packets) = profile_capture();
    let (whole, _) = decode(&m, false, &packets);
    assert_eq!(whole.len(), 1);
    let mut lossy = packets.clone();
    lossy.remove(10);
    // Dropped whole by default, and counted.
    let (frames, d) = decode(&m, false, &lossy);
    assert!(frames.is_empty());
    assert_eq!(d.stats().incomplete_frames, 1);
    // Kept with --keep-incomplete: the packet's columns are empty, the rest as before.
    let (frames, _) = decode(&m, true, &lossy);
    let f = &frames[0];
    assert!(!f.stats.complete);
    assert_eq!(f.stats.columns, m.window_columns() - m.columns_per_packet);
    let (a, b) = (&f.image, &whole[0].image);
    let mut emptied = 0;
    for i in 0..a.pixels() {
        match (a.point(i), b.point(i)) {
            (None, Some(_)) => emptied += 1,
            (x, y) => assert_eq!(x, y, "pixel {i}"),
        }
    }
    assert!(emptied > 0);
}

#[test]
fn reordered_packets_within_a_frame_give_the_same_frame() {
    let (m, packets) = profile_capture();
    let (want, _) = decode(&m, false, &packets);
    let mut shuffled = packets.clone();
    // A fixed permutation: reverse, then swap neighbours.
    shuffled.reverse();
    for k in (0..shuffled.len() - 1).step_by(2) {
        shuffled.swap(k, k + 1);
    }
    let (got, _) = decode(&m, false, &shuffled);
    assert_eq!(got.len(), 1);
    assert!(same_image(&got[0].image, &want[0].image));
}

#[test]
fn duplicate_packets_are_counted_and_change_nothing() {
    let (m, packets) = profile_capture();
    let (want, _) = decode(&m, false, &packets);
    let mut dup = Vec::new();
    for (k, p) in packets.iter().enumerate() {
        dup.push(p.clone());
        if k % 5 == 0 {
            dup.push(p.clone());
        }
    }
    let (got, d) = decode(&m, false, &dup);
    assert_eq!(got.len(), 1);
    assert!(same_image(&got[0].image, &want[0].image));
    let copies = packets.len().div_ceil(5) as u64;
    assert_eq!(
        d.stats().duplicate_columns,
        copies * m.columns_per_packet as u64
    );
}

#[test]
fn a_frame_id_jump_starts_a_new_frame() {
    // A sensor restart: the same rotation again under a far frame id.
    let (m, packets) = profile_capture();
    let (want, _) = decode(&m, false, &packets);
    let mut seq = packets.clone();
    for p in &packets {
        let mut p = p.clone();
        set_frame_id(&mut p, want[0].frame_id.wrapping_add(30_000));
        seq.push(p);
    }
    let (got, d) = decode(&m, false, &seq);
    assert_eq!(got.len(), 2);
    assert_eq!(got[1].frame_id, want[0].frame_id.wrapping_add(30_000));
    for f in &got {
        assert!(same_image(&f.image, &want[0].image));
    }
    assert_eq!(d.stats().duplicate_columns, 0);
}

#[test]
fn malformed_packets_are_counted_and_skipped() {
    let (m, packets) = profile_capture();
    let (want, _) = decode(&m, false, &packets);
    let mut seq = packets.clone();
    let mut short = packets[3].clone();
    short.truncate(100);
    let mut bad_type = packets[3].clone();
    bad_type[0] = 7;
    let mut bad_column = packets[3].clone();
    // Measurement id of the first column (column header at byte 32).
    bad_column[32 + 8..32 + 10].copy_from_slice(&u16::MAX.to_le_bytes());
    let garbage: Vec<u8> = (0..m.packet_size()).map(|i| (i * 7 + 3) as u8).collect();
    for (k, p) in [short, bad_type, bad_column, garbage, Vec::new()]
        .into_iter()
        .enumerate()
    {
        seq.insert(5 + 7 * k, p);
    }
    let (got, d) = decode(&m, false, &seq);
    assert_eq!(got.len(), 1);
    assert!(same_image(&got[0].image, &want[0].image));
    let s = d.stats();
    assert_eq!(
        s.malformed_packets + s.other_datagrams.values().sum::<u64>(),
        5
    );
    assert_eq!(s.lidar_packets, packets.len() as u64);
}

const BOTH: [Receive; 2] = [Receive::Thread, Receive::Inline];

fn bind(decoder: Decoder, idle: f64) -> (LiveSource, SocketAddr, UdpSocket) {
    bind_reading(decoder, idle, Receive::Thread)
}

fn bind_reading(
    decoder: Decoder,
    idle: f64,
    receive: Receive,
) -> (LiveSource, SocketAddr, UdpSocket) {
    let src = LiveSource::bind(
        "127.0.0.1:0".parse().unwrap(),
        decoder,
        LiveOptions {
            idle_timeout: Duration::from_secs_f64(idle),
            receive,
            columns_read: false,
        },
    )
    .unwrap();
    let to: SocketAddr = format!("127.0.0.1:{}", src.local_port()).parse().unwrap();
    (src, to, UdpSocket::bind("127.0.0.1:0").unwrap())
}

fn ouster(m: &OusterMetadata) -> Decoder {
    Decoder::Ouster(Box::new(
        OusterDecoder::new(m, DecodeOptions::default()).unwrap(),
    ))
}

/// Send with a short pause now and then, so the loopback never drops.
fn send_all(tx: &UdpSocket, to: SocketAddr, packets: &[Vec<u8>]) {
    for (k, p) in packets.iter().enumerate() {
        tx.send_to(p, to).unwrap();
        if k % 8 == 7 {
            std::thread::sleep(Duration::from_millis(2));
        }
    }
}

#[test]
fn the_socket_gives_the_frames_of_the_capture_and_ends_when_idle() {
    for receive in BOTH {
        socket_gives_the_frames(receive);
    }
}

fn socket_gives_the_frames(receive: Receive) {
    let (m, packets) = profile_capture();
    let (want, _) = decode(&m, false, &packets);
    let (mut src, to, tx) = bind_reading(ouster(&m), 0.5, receive);
    send_all(&tx, to, &packets);
    let stop = AtomicBool::new(false);
    let t = Instant::now();
    let f = src.next_frame(&stop).unwrap().expect("the frame");
    assert_eq!(u64::from(want[0].frame_id), f.frame);
    assert!(same_image(&f.image, &want[0].image));
    assert!(f.complete && f.lost_columns == 0);
    assert!(want[0].timestamp_ns > 0);
    assert_eq!(f.sensor_ns, Some(want[0].timestamp_ns));
    // Every column's packet time is known, none later than the frame's end.
    assert!(f
        .column_received
        .iter()
        .all(|t| t.is_some_and(|t| t <= f.received_at)));
    assert!((0..f.image.cols).all(|c| f.column_time(c).is_some()));
    assert_eq!(src.next_frame(&stop).unwrap().err(), Some(End::Idle));
    assert!(t.elapsed() < Duration::from_secs(10));
    let s = src.stats();
    assert_eq!(
        (s.packets, s.decoded, s.frames),
        (packets.len() as u64, packets.len() as u64, 1)
    );
}

#[test]
fn the_stop_flag_ends_the_wait() {
    let (m, _) = profile_capture();
    for receive in BOTH {
        let (mut src, _, _) = bind_reading(ouster(&m), 30.0, receive);
        let stop = AtomicBool::new(true);
        let t = Instant::now();
        assert_eq!(src.next_frame(&stop).unwrap().err(), Some(End::Stopped));
        assert!(t.elapsed() < Duration::from_secs(5));
    }
}

#[test]
fn no_packet_at_all_is_an_error_after_the_idle_timeout() {
    let (m, _) = profile_capture();
    for receive in BOTH {
        let t = Instant::now();
        let (mut src, _, _) = bind_reading(ouster(&m), 0.3, receive);
        let err = src
            .next_frame(&AtomicBool::new(false))
            .unwrap_err()
            .to_string();
        assert!(err.contains("no packet in 0.3 s"), "{receive:?}: {err}");
        let took = t.elapsed();
        assert!(
            took >= Duration::from_millis(300) && took < Duration::from_secs(10),
            "{receive:?}: {took:?}"
        );
    }
}

/// A burst far larger than any buffer on the way, sent before anything is
/// read, then one packet once the buffers have drained: every packet is
/// either received or counted as dropped, whichever way the socket is read.
/// (The kernel reports its drops with the next datagram it queues, hence the
/// last packet.)
#[test]
fn packets_without_room_are_counted_as_dropped() {
    let (m, packets) = profile_capture();
    let size = packets[0].len();
    // Four times the most the kernel can give (twice the buffer asked for),
    // and more than the receiving thread's queue.
    let burst = (4 * 2 * RECEIVE_BUFFER as usize / size).max(2 * fcc_lidar::live::QUEUE_PACKETS);
    for receive in BOTH {
        let (mut src, to, tx) = bind_reading(ouster(&m), 2.0, receive);
        for k in 0..burst {
            tx.send_to(&packets[k % packets.len()], to).unwrap();
            // Never faster than the loopback's own queue drains.
            if k % 64 == 63 {
                std::thread::sleep(Duration::from_millis(1));
            }
        }
        let mut last = packets[0].clone();
        set_frame_id(&mut last, 999);
        let late = std::thread::spawn(move || {
            std::thread::sleep(Duration::from_millis(700));
            tx.send_to(&last, to).unwrap();
        });
        let stop = AtomicBool::new(false);
        while src.next_event(&stop).unwrap().is_ok() {}
        late.join().unwrap();
        let s = src.stats();
        assert!(s.dropped > 0, "{receive:?}: none dropped of {burst}: {s:?}");
        assert_eq!(
            s.packets + s.dropped,
            burst as u64 + 1,
            "{receive:?}: received and dropped against sent: {s:?}"
        );
    }
}

#[test]
fn packets_of_another_profile_are_one_clear_error() {
    // The packets of one sample capture against the metadata of another.
    let (m, _) = profile_capture();
    let other = (0..SAMPLE_CAPTURES.len())
        .find(|&k| meta(k).packet_size() != m.packet_size())
        .unwrap();
    let om = meta(other);
    let packets: Vec<Vec<u8>> = datagrams(&sample_dir().join(SAMPLE_CAPTURES[other].0))
        .into_iter()
        .filter(|d| d.payload.len() == om.packet_size())
        .map(|d| d.payload)
        .collect();
    let (mut src, to, tx) = bind(ouster(&m), 5.0);
    let mut sent = 0;
    while sent < 300 {
        send_all(&tx, to, &packets);
        sent += packets.len();
    }
    let t = Instant::now();
    let err = src
        .next_frame(&AtomicBool::new(false))
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("packets in a row could not be decoded")
            && err.contains(&format!("{} bytes", om.packet_size()))
            && err.contains(&format!("expects {}-byte lidar packets", m.packet_size())),
        "{err}"
    );
    assert!(t.elapsed() < Duration::from_secs(10));
}

#[test]
fn velodyne_packets_of_another_model_are_one_clear_error() {
    let path = sample_dir().join("velodyne/vlp16.pcap");
    let packets: Vec<Vec<u8>> = datagrams(&path).into_iter().map(|d| d.payload).collect();
    let opts = VelodyneOptions {
        model: Some(fcc_lidar::velodyne::VelodyneModel::Hdl32e),
        ..VelodyneOptions::default()
    };
    let d = Decoder::Velodyne(Box::new(
        VelodyneDecoder::new(Path::new("udp"), opts).unwrap(),
    ));
    let (mut src, to, tx) = bind(d, 5.0);
    let mut sent = 0;
    while sent < 300 {
        send_all(&tx, to, &packets);
        sent += packets.len();
    }
    let err = src
        .next_frame(&AtomicBool::new(false))
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("could not be decoded")
            && (err.contains("HDL-32E") || err.contains("hdl32e"))
            && err.contains("from another sensor"),
        "{err}"
    );
}
