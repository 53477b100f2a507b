//! Ouster captures: the real sample frames of every supported profile, and
//! captures made broken on purpose.

use fcc_lidar::ouster::{
    read_capture, shifts_from_azimuth, CoordFrame, DecodeOptions, ImageOrigin, OusterMetadata,
    OusterReader, Profile, SAMPLE_CAPTURES,
};
use fcc_lidar::pcap::{PcapReader, PcapWriter};
use std::path::{Path, PathBuf};

fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data")
        .join(name)
}

/// (capture, metadata, profile, beams)
const CAPTURES: [(&str, &str, Profile, usize); 4] = [
    (
        "OS-0-128-U1_v2.3.0_1024x10.pcap",
        "OS-0-128-U1_v2.3.0_1024x10.json",
        Profile::Rng15Rfl8Nir8,
        128,
    ),
    (
        "OS-1-32-G_v2.1.1_1024x10.pcap",
        "OS-1-32-G_v2.1.1_1024x10.json",
        Profile::Legacy,
        32,
    ),
    (
        "OS-1-64_1024x10_fw20.pcap",
        "OS-1-64_sensor_config_reduced.json",
        Profile::Legacy,
        64,
    ),
    (
        "OS-2-128-U1_v2.3.0_1024x10.pcap",
        "OS-2-128-U1_v2.3.0_1024x10.json",
        Profile::Rng19Rfl8Sig16Nir16,
        128,
    ),
];

fn meta(name: &str) -> OusterMetadata {
    OusterMetadata::from_file(&data(name)).unwrap()
}

/// Every UDP payload of a capture with its destination port.
fn datagrams(pcap: &Path) -> Vec<(u16, Vec<u8>)> {
    let mut r = PcapReader::open(pcap).unwrap();
    let mut out = Vec::new();
    while let Some(d) = r.next_datagram().unwrap() {
        out.push((d.dst_port, d.payload));
    }
    out
}

fn write_capture(path: &Path, packets: &[(u16, Vec<u8>)], mtu: Option<usize>) {
    let mut w = PcapWriter::create(path).unwrap();
    for (port, p) in packets {
        w.write_udp(7502, *port, p, mtu).unwrap();
    }
    w.finish().unwrap();
}

#[test]
fn every_sample_capture_gives_one_sensible_frame() {
    let listed: Vec<(&str, &str)> = CAPTURES.iter().map(|c| (c.0, c.1)).collect();
    assert_eq!(
        listed, SAMPLE_CAPTURES,
        "the public sample list and this test differ"
    );
    for (pcap, json, profile, beams) in CAPTURES {
        let m = meta(json);
        assert_eq!(m.profile, profile, "{pcap}");
        assert_eq!(m.pixels_per_column, beams, "{pcap}");
        let cap = read_capture(&data(pcap), &m, DecodeOptions::default()).unwrap();
        assert_eq!(cap.frames.len(), 1, "{pcap}");
        assert_eq!(cap.stats.lidar_packets, 64, "{pcap}");
        assert_eq!(cap.stats.malformed_packets, 0, "{pcap}");
        let f = &cap.frames[0];
        assert!(
            f.stats.complete && f.stats.columns == 1024,
            "{pcap}: {:?}",
            f.stats
        );
        assert_eq!((f.image.rows, f.image.cols), (beams, 1024), "{pcap}");
        let ranges: Vec<f32> = (0..f.image.pixels())
            .filter_map(|i| f.image.range(i))
            .collect();
        assert_eq!(ranges.len(), f.stats.returns, "{pcap}");
        let fill = ranges.len() as f64 / f.image.pixels() as f64;
        assert!(
            fill > 0.2,
            "{pcap}: only {fill:.2} of the pixels have a return"
        );
        let sensible = ranges
            .iter()
            .filter(|&&r| (0.5..120.0).contains(&r))
            .count();
        let share = sensible as f64 / ranges.len() as f64;
        assert!(
            share > 0.95,
            "{pcap}: {share:.3} of returns within 0.5..120 m"
        );
        eprintln!(
            "{pcap}: {} returns ({:.0} %), {:.1} % within 0.5..120 m",
            ranges.len(),
            fill * 100.0,
            share * 100.0
        );
    }
}

/// Destaggering puts the beams of one image column at one azimuth: the
/// spread of azimuths down a column is small, and much smaller than with
/// the shifts left out.
#[test]
fn destaggered_columns_share_one_azimuth() {
    for (pcap, json, _, _) in CAPTURES {
        let m = meta(json);
        let img = &read_capture(&data(pcap), &m, DecodeOptions::default())
            .unwrap()
            .frames[0]
            .image;
        let mut flat = m.clone();
        flat.pixel_shift_by_row = vec![0; m.pixels_per_column];
        let stag = &read_capture(&data(pcap), &flat, DecodeOptions::default())
            .unwrap()
            .frames[0]
            .image;
        let step = 360.0 / img.cols as f64;
        let spread = |im: &fcc_lidar::RangeImage| {
            // Share of pixels within 1.5 columns of their column's median azimuth,
            // counting only returns beyond 3 m (the beam-origin offset bends
            // azimuths of very close returns).
            let (mut good, mut all) = (0usize, 0usize);
            for c in 0..im.cols {
                let mut az: Vec<f64> = (0..im.rows)
                    .filter_map(|r| im.at(r, c))
                    .filter(|p| (p[0] * p[0] + p[1] * p[1]).sqrt() > 3.0)
                    .map(|p| f64::from(p[1]).atan2(f64::from(p[0])).to_degrees())
                    .collect();
                if az.len() < 3 {
                    continue;
                }
                az.sort_by(f64::total_cmp);
                let med = az[az.len() / 2];
                for a in &az {
                    let d = (a - med + 540.0).rem_euclid(360.0) - 180.0;
                    good += usize::from(d.abs() <= 1.5 * step);
                    all += 1;
                }
            }
            good as f64 / all as f64
        };
        let (d, s) = (spread(img), spread(stag));
        eprintln!("{pcap}: aligned {d:.3} destaggered, {s:.3} staggered");
        assert!(
            d > 0.95,
            "{pcap}: only {d:.3} of pixels line up after destaggering"
        );
        assert!(
            s < d - 0.2,
            "{pcap}: staggered {s:.3} vs destaggered {d:.3}"
        );
    }
}

/// Where the metadata has `pixel_shift_by_row`, the shifts derived from the
/// beam azimuths agree with it up to one common offset (and one column of
/// rounding).
#[test]
fn derived_shifts_agree_with_the_metadata() {
    for json in [
        "OS-0-128-U1_v2.3.0_1024x10.json",
        "OS-1-32-G_v2.1.1_1024x10.json",
        "OS-2-128-U1_v2.3.0_1024x10.json",
    ] {
        let m = meta(json);
        assert!(m.shift_from_metadata);
        let derived = shifts_from_azimuth(&m.beam_azimuth_deg, m.columns_per_frame);
        let offset = m.pixel_shift_by_row[0] - derived[0];
        for (u, (a, b)) in m.pixel_shift_by_row.iter().zip(&derived).enumerate() {
            assert!(
                (a - b - offset).abs() <= 1,
                "{json} beam {u}: {a} vs derived {b} + {offset}"
            );
        }
    }
    let reduced = meta("OS-1-64_sensor_config_reduced.json");
    assert!(!reduced.shift_from_metadata && reduced.beam_origin_default);
    assert_eq!(&reduced.pixel_shift_by_row[..4], &[18, 12, 6, 0]);
}

#[test]
fn sensor_frame_is_the_lidar_frame_turned_half_round_and_lifted() {
    let (pcap, json) = (
        "OS-2-128-U1_v2.3.0_1024x10.pcap",
        "OS-2-128-U1_v2.3.0_1024x10.json",
    );
    let m = meta(json);
    let s = &read_capture(&data(pcap), &m, DecodeOptions::default())
        .unwrap()
        .frames[0]
        .image;
    let opts = DecodeOptions {
        frame: CoordFrame::Lidar,
        ..DecodeOptions::default()
    };
    let l = &read_capture(&data(pcap), &m, opts).unwrap().frames[0].image;
    let lift = (m.lidar_to_sensor[11] / 1000.0) as f32;
    for i in (0..s.pixels()).step_by(97) {
        if let (Some(a), Some(b)) = (s.point(i), l.point(i)) {
            assert!(
                (a[0] + b[0]).abs() < 1e-4
                    && (a[1] + b[1]).abs() < 1e-4
                    && (a[2] - b[2] - lift).abs() < 1e-4
            );
        }
    }
}

#[test]
fn several_frames_fragments_and_noise_in_one_capture() {
    let (pcap, json) = (
        "OS-1-32-G_v2.1.1_1024x10.pcap",
        "OS-1-32-G_v2.1.1_1024x10.json",
    );
    let m = meta(json);
    let packets = datagrams(&data(pcap));
    let mut all = Vec::new();
    for frame in 0..3u16 {
        for (i, (port, p)) in packets.iter().enumerate() {
            let mut p = p.clone();
            // Legacy packets carry the frame id in every column header.
            let col = p.len() / 16;
            for c in 0..16 {
                let fid =
                    u16::from_le_bytes([p[c * col + 10], p[c * col + 11]]).wrapping_add(frame);
                p[c * col + 10..c * col + 12].copy_from_slice(&fid.to_le_bytes());
            }
            all.push((*port, p));
            if i == 10 {
                all.push((7503, vec![0u8; 48]));
                all.push((9999, vec![1u8; 333]));
            }
        }
    }
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("three.pcap");
    write_capture(&path, &all, Some(1500));
    let cap = read_capture(&path, &m, DecodeOptions::default()).unwrap();
    assert_eq!(cap.frames.len(), 3);
    assert_eq!(cap.stats.imu_packets, 3);
    assert_eq!(cap.stats.other_datagrams.get(&333), Some(&3));
    assert!(cap.stats.pcap.reassembled >= 192, "{:?}", cap.stats.pcap);
    let ids: Vec<u16> = cap.frames.iter().map(|f| f.frame_id).collect();
    assert_eq!(ids, vec![638, 639, 640]);
    assert_eq!(cap.frames[0].image, cap.frames[2].image);
}

#[test]
fn truncated_capture_drops_the_cut_frame_or_keeps_it_on_request() {
    let (pcap, json) = (
        "OS-0-128-U1_v2.3.0_1024x10.pcap",
        "OS-0-128-U1_v2.3.0_1024x10.json",
    );
    let m = meta(json);
    let bytes = std::fs::read(data(pcap)).unwrap();
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("cut.pcap");
    std::fs::write(&path, &bytes[..bytes.len() / 2]).unwrap();
    let err = read_capture(&path, &m, DecodeOptions::default())
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("cut.pcap")
            && err.contains("missed columns")
            && err.contains("ends in the middle"),
        "{err}"
    );
    let opts = DecodeOptions {
        keep_incomplete: true,
        ..DecodeOptions::default()
    };
    let cap = read_capture(&path, &m, opts).unwrap();
    let f = &cap.frames[0];
    assert!(
        !f.stats.complete && f.stats.columns < 1024 && f.stats.columns >= 400,
        "{:?}",
        f.stats
    );
}

#[test]
fn malformed_packets_are_counted_and_skipped() {
    let (pcap, json) = (
        "OS-2-128-U1_v2.3.0_1024x10.pcap",
        "OS-2-128-U1_v2.3.0_1024x10.json",
    );
    let m = meta(json);
    let mut packets = datagrams(&data(pcap));
    let lidar: Vec<usize> = (0..packets.len())
        .filter(|&i| packets[i].0 == 7502)
        .collect();
    // A column index beyond the frame, a wrong packet type, a short packet.
    packets[lidar[3]].1[32 + 8..32 + 10].copy_from_slice(&5000u16.to_le_bytes());
    packets[lidar[4]].1[0] = 7;
    packets[lidar[5]].1.truncate(1000);
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("bad.pcap");
    write_capture(&path, &packets, None);
    let opts = DecodeOptions {
        keep_incomplete: true,
        ..DecodeOptions::default()
    };
    let cap = read_capture(&path, &m, opts).unwrap();
    assert_eq!(cap.stats.malformed_packets, 3);
    assert_eq!(cap.stats.lidar_packets, 61);
    assert_eq!(cap.frames[0].stats.columns, 1024 - 48);
    let err = read_capture(&path, &m, DecodeOptions::default())
        .unwrap_err()
        .to_string();
    assert!(err.contains("3 malformed"), "{err}");
}

#[test]
fn metadata_of_another_sensor_is_a_clear_error() {
    // Legacy OS-1-32 capture with the OS-1-64 metadata: packet sizes differ.
    let m = meta("OS-1-64_sensor_config_reduced.json");
    let err = read_capture(
        &data("OS-1-32-G_v2.1.1_1024x10.pcap"),
        &m,
        DecodeOptions::default(),
    )
    .unwrap_err()
    .to_string();
    assert!(
        err.contains("12608-byte")
            && err.contains("64 of 6464 bytes")
            && err.contains("metadata of this capture"),
        "{err}"
    );
    // Same layout, another serial number.
    let text = std::fs::read_to_string(data("OS-2-128-U1_v2.3.0_1024x10.json")).unwrap();
    let other = OusterMetadata::from_json_str(
        &text.replace("992210000957", "992210000958"),
        Path::new("other.json"),
    )
    .unwrap();
    let err = read_capture(
        &data("OS-2-128-U1_v2.3.0_1024x10.pcap"),
        &other,
        DecodeOptions::default(),
    )
    .unwrap_err()
    .to_string();
    assert!(
        err.contains("64 came from a sensor other than serial 992210000958"),
        "{err}"
    );
}

#[test]
fn garbage_and_missing_files_are_clear_errors() {
    let m = meta("OS-1-32-G_v2.1.1_1024x10.json");
    let err = read_capture(
        &data("OS-1-32-G_v2.1.1_1024x10.json"),
        &m,
        DecodeOptions::default(),
    )
    .unwrap_err()
    .to_string();
    assert!(
        err.contains("OS-1-32-G_v2.1.1_1024x10.json") && err.contains("not a pcap or pcapng file"),
        "{err}"
    );
    let err = read_capture(Path::new("no/such/file.pcap"), &m, DecodeOptions::default())
        .unwrap_err()
        .to_string();
    assert!(err.contains("no/such/file.pcap"), "{err}");
    let err = OusterMetadata::from_file(&data("OS-1-32-G_v2.1.1_1024x10.pcap"))
        .unwrap_err()
        .to_string();
    assert!(err.contains("not valid JSON"), "{err}");
}

#[test]
fn streaming_reader_matches_read_capture() {
    let (pcap, json) = (
        "OS-1-64_1024x10_fw20.pcap",
        "OS-1-64_sensor_config_reduced.json",
    );
    let m = meta(json);
    let frames: Vec<_> = OusterReader::open(&data(pcap), &m, DecodeOptions::default())
        .unwrap()
        .collect::<Result<_, _>>()
        .unwrap();
    let whole = read_capture(&data(pcap), &m, DecodeOptions::default()).unwrap();
    assert_eq!(frames.len(), 1);
    assert_eq!(frames[0].image, whole.frames[0].image);
    assert_eq!(whole.stats.imu_packets, 11);
}

/// Build the lidar packets of one frame of `profile` from known ranges
/// (mm, per beam and measurement column), as the sensor would send them.
/// The reflectivity `encode_frame` writes (plus 300 in LEGACY's 16 bits).
fn reflectivity(u: usize, v: usize) -> u16 {
    ((u * 31 + v) % 200 + 1) as u16
}

fn encode_frame(
    m: &OusterMetadata,
    frame_id: u16,
    range: impl Fn(usize, usize) -> u32,
) -> Vec<Vec<u8>> {
    let (h, w, cpp) = (
        m.pixels_per_column,
        m.columns_per_frame,
        m.columns_per_packet,
    );
    let legacy = m.profile == Profile::Legacy;
    let ps = m.profile.pixel_bytes();
    let mut packets = Vec::new();
    for first in (0..w).step_by(cpp) {
        let mut p = Vec::new();
        if !legacy {
            p.extend_from_slice(&1u16.to_le_bytes());
            p.extend_from_slice(&frame_id.to_le_bytes());
            p.resize(32, 0);
        }
        for v in first..first + cpp {
            p.extend_from_slice(&(v as u64 * 1000).to_le_bytes());
            p.extend_from_slice(&(v as u16).to_le_bytes());
            if legacy {
                p.extend_from_slice(&frame_id.to_le_bytes());
                p.extend_from_slice(&0u32.to_le_bytes());
            } else {
                p.extend_from_slice(&1u16.to_le_bytes());
            }
            for u in 0..h {
                let r = range(u, v);
                let mut px = vec![0u8; ps];
                match m.profile {
                    Profile::Rng15Rfl8Nir8 => {
                        px[0..2].copy_from_slice(&((r / 8) as u16).to_le_bytes())
                    }
                    _ => px[0..4].copy_from_slice(&r.to_le_bytes()),
                }
                // Reflectivity / signal bytes set, to check they are masked off.
                px[ps - 1] = 0xff;
                if m.profile == Profile::Rng19Rfl8Sig16Nir16Dual {
                    px[4..8].copy_from_slice(&(r + 5000).to_le_bytes());
                }
                let refl = reflectivity(u, v);
                match m.profile {
                    Profile::Legacy => px[4..6].copy_from_slice(&(refl + 300).to_le_bytes()),
                    Profile::Rng19Rfl8Sig16Nir16 => px[4] = refl as u8,
                    Profile::Rng15Rfl8Nir8 => px[2] = refl as u8,
                    Profile::Rng19Rfl8Sig16Nir16Dual => px[3] = refl as u8,
                }
                p.extend_from_slice(&px);
            }
            if legacy {
                p.extend_from_slice(&0xffff_ffffu32.to_le_bytes());
            }
        }
        if !legacy {
            p.resize(p.len() + 32, 0);
        }
        assert_eq!(p.len(), m.packet_size());
        packets.push(p);
    }
    packets
}

#[test]
fn every_profile_decodes_known_ranges_exactly() {
    let json = r#"{"beam_altitude_angles": [15, 5, -5, -15], "beam_azimuth_angles": [3, 1, -1, -3],
                   "lidar_mode": "512x10", "lidar_origin_to_beam_origin_mm": 0.0}"#;
    let base = OusterMetadata::from_json_str(json, Path::new("synthetic.json")).unwrap();
    let range = |u: usize, v: usize| 1000 + 8 * ((u as u32 * 7919 + v as u32 * 104_729) % 30_000);
    for profile in [
        Profile::Legacy,
        Profile::Rng19Rfl8Sig16Nir16,
        Profile::Rng15Rfl8Nir8,
        Profile::Rng19Rfl8Sig16Nir16Dual,
    ] {
        let mut m = base.clone();
        m.profile = profile;
        let packets: Vec<(u16, Vec<u8>)> = encode_frame(&m, 9, range)
            .into_iter()
            .map(|p| (7502, p))
            .collect();
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("synthetic.pcap");
        write_capture(&path, &packets, None);
        let opts = DecodeOptions {
            frame: CoordFrame::Lidar,
            ..DecodeOptions::default()
        };
        let cap = read_capture(&path, &m, opts).unwrap();
        assert_eq!(cap.frames.len(), 1, "{profile:?}");
        let img = &cap.frames[0].image;
        assert_eq!(cap.frames[0].frame_id, 9);
        for u in 0..4 {
            let shift = m.pixel_shift_by_row[u] as usize;
            for v in 0..512 {
                let px = u * 512 + (v + shift) % 512;
                let r = img.range(px).unwrap();
                let want = range(u, v) as f32 / 1000.0;
                assert!(
                    (r - want).abs() < 1e-3,
                    "{profile:?} beam {u} column {v}: {r} vs {want}"
                );
                let refl = reflectivity(u, v) + if profile == Profile::Legacy { 300 } else { 0 };
                assert_eq!(
                    cap.frames[0].reflectivity[px],
                    f32::from(refl),
                    "{profile:?} beam {u} column {v}: reflectivity"
                );
            }
        }
    }
}

#[test]
fn pcapng_capture_decodes_like_classic() {
    let (pcap, json) = (
        "OS-2-128-U1_v2.3.0_1024x10.pcap",
        "OS-2-128-U1_v2.3.0_1024x10.json",
    );
    let bytes = std::fs::read(data(pcap)).unwrap();
    // Re-wrap every classic record as an enhanced packet block.
    let mut ng = Vec::new();
    let block = |ng: &mut Vec<u8>, kind: u32, body: &[u8]| {
        let len = 12 + body.len().div_ceil(4) * 4;
        ng.extend_from_slice(&kind.to_le_bytes());
        ng.extend_from_slice(&(len as u32).to_le_bytes());
        ng.extend_from_slice(body);
        ng.resize(ng.len() + body.len().div_ceil(4) * 4 - body.len(), 0);
        ng.extend_from_slice(&(len as u32).to_le_bytes());
    };
    let mut shb = 0x1a2b_3c4du32.to_le_bytes().to_vec();
    shb.extend_from_slice(&[1, 0, 0, 0]);
    shb.extend_from_slice(&[0xff; 8]);
    block(&mut ng, 0x0a0d_0d0a, &shb);
    let mut idb = 1u16.to_le_bytes().to_vec();
    idb.extend_from_slice(&[0, 0]);
    idb.extend_from_slice(&65535u32.to_le_bytes());
    block(&mut ng, 1, &idb);
    let mut off = 24;
    while off < bytes.len() {
        let incl = u32::from_le_bytes(bytes[off + 8..off + 12].try_into().unwrap()) as usize;
        let mut epb = vec![0u8; 12];
        epb.extend_from_slice(&(incl as u32).to_le_bytes());
        epb.extend_from_slice(&(incl as u32).to_le_bytes());
        epb.extend_from_slice(&bytes[off + 16..off + 16 + incl]);
        block(&mut ng, 6, &epb);
        off += 16 + incl;
    }
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("capture.pcapng");
    std::fs::write(&path, ng).unwrap();
    let m = meta(json);
    let a = read_capture(&path, &m, DecodeOptions::default()).unwrap();
    let b = read_capture(&data(pcap), &m, DecodeOptions::default()).unwrap();
    assert_eq!(a.frames.len(), 1);
    assert!(a.frames[0].image == b.frames[0].image);
}

#[test]
fn metadata_without_transform_takes_the_product_line_default() {
    let reduced = meta("OS-1-64_sensor_config_reduced.json");
    assert!(reduced.transform_default);
    assert_eq!(
        reduced.lidar_to_sensor,
        fcc_lidar::ouster::default_lidar_to_sensor(None)
    );
    assert_eq!(reduced.lidar_to_sensor[11], 36.18);
    // The default is what the metadata of each line carries.
    for &(_, json, _, _) in CAPTURES
        .iter()
        .filter(|c| c.1 != "OS-1-64_sensor_config_reduced.json")
    {
        let m = meta(json);
        assert!(!m.transform_default);
        assert_eq!(
            m.lidar_to_sensor,
            fcc_lidar::ouster::default_lidar_to_sensor(m.prod_line.as_deref()),
            "{json}"
        );
    }
    // The OS-1-64 capture's sensor frame: the lidar frame turned half round, lifted 36.18 mm.
    let pcap = data("OS-1-64_1024x10_fw20.pcap");
    let s = &read_capture(&pcap, &reduced, DecodeOptions::default())
        .unwrap()
        .frames[0]
        .image;
    let opts = DecodeOptions {
        frame: CoordFrame::Lidar,
        ..DecodeOptions::default()
    };
    let l = &read_capture(&pcap, &reduced, opts).unwrap().frames[0].image;
    let mut n = 0;
    for i in 0..s.pixels() {
        if let (Some(a), Some(b)) = (s.point(i), l.point(i)) {
            assert!(
                (a[0] + b[0]).abs() < 1e-4
                    && (a[1] + b[1]).abs() < 1e-4
                    && (a[2] - b[2] - 0.03618).abs() < 1e-4,
                "pixel {i}: {a:?} vs {b:?}"
            );
            n += 1;
        }
    }
    assert!(n > 10_000, "{n}");
}

/// The first pixel that differs between two images, as "row r col c:
/// expected .., got ..".
fn first_difference(exp: &fcc_lidar::RangeImage, got: &fcc_lidar::RangeImage) -> Option<String> {
    let bits = |p: Option<[f32; 3]>| p.map(|p| p.map(f32::to_bits));
    (0..exp.pixels())
        .find(|&i| bits(exp.point(i)) != bits(got.point(i)))
        .map(|i| {
            format!(
                "row {} col {}: expected {:?}, got {:?}",
                i / exp.cols,
                i % exp.cols,
                exp.point(i),
                got.point(i)
            )
        })
}

#[test]
fn sweep_origin_is_the_sensor_image_rotated_by_the_largest_shift() {
    for (pcap, json, _, _) in CAPTURES {
        let m = meta(json);
        let w = m.columns_per_frame;
        let o = m.origin_columns(ImageOrigin::Sweep);
        let max = m
            .pixel_shift_by_row
            .iter()
            .map(|s| s.rem_euclid(w as i64))
            .max();
        assert_eq!(Some(o as i64), max, "{pcap}");
        assert!(o > 0, "{pcap}: the sample sensors have staggered beams");
        assert_eq!(m.origin_columns(ImageOrigin::Sensor), 0);
        let read = |origin| {
            let opts = DecodeOptions {
                origin,
                ..DecodeOptions::default()
            };
            read_capture(&data(pcap), &m, opts).unwrap().frames
        };
        let (sensor, sweep) = (read(ImageOrigin::Sensor), read(ImageOrigin::Sweep));
        assert_eq!(sensor.len(), sweep.len(), "{pcap}");
        for (a, b) in sensor.iter().zip(&sweep) {
            let mut rotated = fcc_lidar::RangeImage::empty(a.image.rows, w);
            let mut refl = vec![f32::NAN; a.image.rows * w];
            for r in 0..a.image.rows {
                for j in 0..w {
                    rotated.set(r * w + j, a.image.at(r, (j + o) % w));
                    refl[r * w + j] = a.reflectivity[r * w + (j + o) % w];
                }
            }
            if let Some(d) = first_difference(&rotated, &b.image) {
                panic!(
                    "{pcap} frame {}: sweep image against the sensor image rotated by {o}: {d}",
                    a.frame_id
                );
            }
            let same = refl
                .iter()
                .zip(&b.reflectivity)
                .all(|(x, y)| x.to_bits() == y.to_bits());
            assert!(same, "{pcap}: reflectivity not rotated with the points");
            assert_eq!(a.stats, b.stats, "{pcap}");
        }
    }
}

/// The frame being received: its id, its image columns as read when they
/// became complete, and per column the measurement columns received then.
type Seen = (u16, Vec<Vec<Option<[f32; 3]>>>, Vec<Option<usize>>);

/// Decode `packets` one by one; after each, every image column the decoder
/// counts as complete must already be the delivered frame's column, bit for
/// bit. Returns, per delivered frame, the measurement columns received when
/// each image column became complete (`None`: only at the frame's end).
fn ready_columns_hold_the_final_pixels(
    m: &OusterMetadata,
    origin: ImageOrigin,
    packets: &[(u16, Vec<u8>)],
    what: &str,
) -> Vec<Vec<Option<usize>>> {
    let opts = DecodeOptions {
        origin,
        ..DecodeOptions::default()
    };
    let mut d = fcc_lidar::ouster::OusterDecoder::new(m, opts).unwrap();
    let (h, w) = (m.pixels_per_column, m.columns_per_frame);
    // The frame being received: its id, its columns as read when they
    // became complete, and the columns received at that moment.
    let mut seen: Option<Seen> = None;
    let mut out = Vec::new();
    let mut check = |f: fcc_lidar::ouster::OusterFrame, seen: &mut Option<Seen>| {
        let Some((id, cols, when)) = seen.take() else {
            return;
        };
        assert_eq!(id, f.frame_id, "{what}: frame delivered out of turn");
        for (j, col) in cols.iter().enumerate() {
            for (r, p) in col.iter().enumerate() {
                let bits = |p: Option<[f32; 3]>| p.map(|p| p.map(f32::to_bits));
                assert_eq!(
                    bits(*p),
                    bits(f.image.at(r, j)),
                    "{what} frame {id}: image column {j} row {r} read when complete differs from the frame's"
                );
            }
        }
        out.push(when);
    };
    for (port, p) in packets {
        if let Some(f) = d.push(*port, p) {
            check(f, &mut seen);
        }
        let Some((id, ready)) = d.ready_columns() else {
            continue;
        };
        if seen.as_ref().map_or(true, |s| s.0 != id) {
            seen = Some((id, Vec::new(), vec![None; w]));
        }
        let pending = d.pending_columns();
        let (_, cols, when) = seen.as_mut().expect("set above");
        while cols.len() < ready {
            let mut col = vec![None; h];
            d.column_into(cols.len(), &mut col);
            when[cols.len()] = Some(pending);
            cols.push(col);
        }
    }
    if let Some(f) = d.flush() {
        check(f, &mut seen);
    }
    out
}

#[test]
fn sweep_columns_are_complete_as_the_sweep_passes_them_and_hold_their_final_pixels() {
    for (pcap, json, _, _) in CAPTURES {
        let m = meta(json);
        let w = m.columns_per_frame;
        let o = m.origin_columns(ImageOrigin::Sweep);
        let packets = datagrams(&data(pcap));
        let sweep = ready_columns_hold_the_final_pixels(&m, ImageOrigin::Sweep, &packets, pcap);
        let sensor = ready_columns_hold_the_final_pixels(&m, ImageOrigin::Sensor, &packets, pcap);
        assert!(!sweep.is_empty(), "{pcap}: no frame");
        for when in &sweep {
            // Column j needs measurement columns up to j + o: with the
            // packets in order, j is complete once j + o + 1 columns have
            // come (a packet's worth later at most).
            for (j, got) in when.iter().enumerate().take(w - o) {
                let got = got.unwrap_or_else(|| {
                    panic!("{pcap}: sweep column {j} complete only at the frame's end")
                });
                let need = j + o + 1;
                assert!(
                    got >= need && got < need + m.columns_per_packet,
                    "{pcap}: sweep column {j} complete with {got} columns received, expected {need} .. {}",
                    need + m.columns_per_packet - 1
                );
            }
        }
        // The sensor's image: column 0 waits for the frame's last columns.
        for when in &sensor {
            assert!(
                when.iter()
                    .all(|c| c.is_none_or(|n| n >= w - m.columns_per_packet)),
                "{pcap}: a sensor-origin column was complete before the frame's last packet"
            );
        }
    }
}
