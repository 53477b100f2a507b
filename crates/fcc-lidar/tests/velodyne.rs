//! Velodyne captures: the fixtures of `tests/data/velodyne` (written by
//! `make_fixtures.py` with dpkt, from the packet format), decoded against
//! the scene they were ray-cast from, and captures broken on purpose.

use fcc_lidar::pcap::{PcapReader, PcapWriter};
use fcc_lidar::velodyne::{
    explain_no_frames, DualReturn, VelodyneFrame, VelodyneModel, VelodyneOptions, VelodyneReader,
};
use std::path::{Path, PathBuf};

fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/velodyne")
        .join(name)
}

/// (capture stem, model, columns, calibration file)
const FIXTURES: [(&str, VelodyneModel, usize, Option<&str>); 4] = [
    ("vlp16", VelodyneModel::Vlp16, 360, None),
    ("vlp32c", VelodyneModel::Vlp32c, 180, None),
    ("hdl32e", VelodyneModel::Hdl32e, 180, None),
    ("hdl64e", VelodyneModel::Hdl64e, 180, Some("hdl64e.yaml")),
];

fn options(cal: Option<&str>) -> VelodyneOptions {
    VelodyneOptions {
        calibration: cal.map(data),
        ..VelodyneOptions::default()
    }
}

fn frames(
    path: &Path,
    opts: VelodyneOptions,
) -> (Vec<VelodyneFrame>, VelodyneReader<impl std::io::Read>) {
    let mut r = VelodyneReader::open(path, opts).unwrap();
    let mut out = Vec::new();
    while let Some(f) = r.next_frame().unwrap() {
        out.push(f);
    }
    (out, r)
}

/// Which surface of the fixtures' scene a point lies on, if any (the
/// scene of `make_fixtures.py`: ground 1.5 m below, walls at x = +-15 and
/// y = +-12 m, a box at x 6..8, y -1..1 up to z 0.5 m).
fn surface(p: [f32; 3], tol: f32) -> Vec<u8> {
    let [x, y, z] = p;
    let mut s = Vec::new();
    if (z + 1.5).abs() < tol {
        s.push(10);
    }
    if (x.abs() - 15.0).abs() < tol || (y.abs() - 12.0).abs() < tol {
        s.push(50);
    }
    let inside = (6.0 - tol..=8.0 + tol).contains(&x)
        && (-1.0 - tol..=1.0 + tol).contains(&y)
        && (-1.5 - tol..=0.5 + tol).contains(&z);
    let on_face = (x - 6.0).abs() < tol
        || (x - 8.0).abs() < tol
        || (y.abs() - 1.0).abs() < tol
        || (z - 0.5).abs() < tol;
    if inside && on_face {
        s.push(200);
    }
    s
}

#[test]
fn every_model_decodes_one_rotation_onto_the_scene() {
    for (stem, model, cols, cal) in FIXTURES {
        let (fr, r) = frames(&data(&format!("{stem}.pcap")), options(cal));
        let s = r.stats();
        assert_eq!(
            r.model(),
            Some(model),
            "{stem}: model told from the packets"
        );
        assert_eq!(fr.len(), 1, "{stem}: one complete rotation, stats {s:?}");
        assert_eq!(
            s.incomplete_frames, 2,
            "{stem}: the partial turns at both ends"
        );
        assert_eq!(s.malformed_packets, 0, "{stem}");
        let f = &fr[0];
        assert!(f.complete);
        assert_eq!(
            (f.image.rows, f.image.cols),
            (model.lasers(), cols),
            "{stem}"
        );
        // Every return lies on the surface its intensity names.
        let mut on = 0;
        for i in 0..f.image.pixels() {
            let Some(p) = f.image.point(i) else {
                assert!(
                    f.intensity[i].is_nan(),
                    "{stem}: pixel {i} has intensity but no point"
                );
                continue;
            };
            let surf = surface(p, 0.01);
            assert!(
                surf.contains(&(f.intensity[i] as u8)),
                "{stem}: pixel {i} (row {}, col {}) at {p:?} with intensity {} is on {surf:?}",
                i / cols,
                i % cols,
                f.intensity[i]
            );
            on += 1;
        }
        assert!(on > cols * model.lasers() * 9 / 10, "{stem}: {on} returns");
        // Rows run top down: the mean elevation falls row by row.
        let elev: Vec<f64> = (0..f.image.rows)
            .map(|row| {
                let e: Vec<f64> = (0..cols)
                    .filter_map(|c| f.image.at(row, c))
                    .map(|p| f64::from(p[2]).atan2(f64::from(p[0]).hypot(f64::from(p[1]))))
                    .collect();
                e.iter().sum::<f64>() / e.len() as f64
            })
            .collect();
        assert!(elev.windows(2).all(|w| w[0] > w[1]), "{stem}: {elev:?}");
        // The box stands forward: in the columns around cols / 2.
        let box_cols: Vec<usize> = (0..f.image.pixels())
            .filter(|&i| f.intensity[i] == 200.0)
            .map(|i| i % cols)
            .collect();
        assert!(!box_cols.is_empty(), "{stem}");
        assert!(
            box_cols
                .iter()
                .all(|&c| c.abs_diff(cols / 2) <= cols / 36 + 3),
            "{stem}: box columns {box_cols:?}"
        );
    }
}

#[test]
fn sampled_firings_land_where_the_writer_put_them() {
    for (stem, _, cols, cal) in FIXTURES {
        let (fr, r) = frames(&data(&format!("{stem}.pcap")), options(cal));
        let calib = r.calibration().unwrap();
        let mut order: Vec<usize> = (0..calib.lasers.len()).collect();
        order.sort_by(|&a, &b| {
            calib.lasers[b]
                .vert_correction
                .total_cmp(&calib.lasers[a].vert_correction)
        });
        let json: serde_json::Value = serde_json::from_str(
            &std::fs::read_to_string(data(&format!("{stem}_points.json"))).unwrap(),
        )
        .unwrap();
        let expected = json["expected"].as_array().unwrap();
        assert!(expected.len() > 20, "{stem}");
        for e in expected {
            let laser = e["laser"].as_u64().unwrap() as usize;
            let want = ["x", "y", "z"].map(|k| e[k].as_f64().unwrap());
            let row = order.iter().position(|&l| l == laser).unwrap();
            let best = (0..cols)
                .filter_map(|c| fr[0].image.at(row, c).map(|p| (c, p)))
                .map(|(c, p)| {
                    let d = (0..3)
                        .map(|k| (f64::from(p[k]) - want[k]).powi(2))
                        .sum::<f64>()
                        .sqrt();
                    (d, c)
                })
                .min_by(|a, b| a.0.total_cmp(&b.0))
                .unwrap();
            assert!(
                best.0 < 0.005,
                "{stem}: laser {laser} (row {row}): expected {want:?}, nearest pixel (col {}) is {} m away",
                best.1,
                best.0
            );
        }
    }
}

#[test]
fn keep_incomplete_gives_the_partial_turns_too() {
    let (fr, _) = frames(
        &data("vlp16.pcap"),
        VelodyneOptions {
            keep_incomplete: true,
            ..VelodyneOptions::default()
        },
    );
    assert_eq!(
        fr.iter().map(|f| (f.index, f.complete)).collect::<Vec<_>>(),
        vec![(0, false), (1, true), (2, false)]
    );
    // The first partial turn covers 300..360 degrees: columns 0..cols/2 of the
    // backward-looking half stay empty on its forward side.
    assert!(fr.iter().all(|f| f.image.cols == 360));
    assert!(
        fr[0].returns < fr[1].returns / 4,
        "{} vs {}",
        fr[0].returns,
        fr[1].returns
    );
}

#[test]
fn dual_return_first_block_matches_single_return_and_second_is_a_metre_farther() {
    let (single, _) = frames(&data("vlp16.pcap"), VelodyneOptions::default());
    let (first, r) = frames(&data("vlp16_dual.pcap"), VelodyneOptions::default());
    assert_eq!(r.stats().return_modes.get("dual"), Some(&45));
    assert!(r.stats().other_return_blocks > 0);
    assert_eq!(first[0].image, single[0].image);
    let (second, _) = frames(
        &data("vlp16_dual.pcap"),
        VelodyneOptions {
            dual: DualReturn::Second,
            ..VelodyneOptions::default()
        },
    );
    let (a, b) = (&single[0].image, &second[0].image);
    let mut compared = 0;
    for i in 0..a.pixels() {
        if let (Some(ra), Some(rb)) = (a.range(i), b.range(i)) {
            assert!((rb - ra - 1.0).abs() < 0.004, "pixel {i}: {ra} then {rb}");
            compared += 1;
        }
    }
    assert!(compared > a.pixels() * 9 / 10, "{compared}");
}

#[test]
fn columns_can_be_set() {
    let (fr, _) = frames(
        &data("hdl32e.pcap"),
        VelodyneOptions {
            columns: Some(1024),
            ..VelodyneOptions::default()
        },
    );
    assert_eq!((fr[0].image.rows, fr[0].image.cols), (32, 1024));
    let err = VelodyneReader::open(
        &data("hdl32e.pcap"),
        VelodyneOptions {
            columns: Some(1),
            ..VelodyneOptions::default()
        },
    )
    .err()
    .unwrap()
    .to_string();
    assert!(
        err.contains("1 columns for a Velodyne range image"),
        "{err}"
    );
}

#[test]
fn hdl64e_without_calibration_is_a_one_line_error() {
    let mut r = VelodyneReader::open(&data("hdl64e.pcap"), VelodyneOptions::default()).unwrap();
    let err = r.next_frame().unwrap_err().to_string();
    assert!(
        err.contains("HDL-64E capture needs the unit's calibration file") && !err.contains('\n'),
        "{err}"
    );
}

#[test]
fn packets_of_another_model_are_counted_not_decoded() {
    let mut r = VelodyneReader::open(
        &data("vlp32c.pcap"),
        VelodyneOptions {
            model: Some(VelodyneModel::Vlp16),
            ..VelodyneOptions::default()
        },
    )
    .unwrap();
    assert!(r.next_frame().unwrap().is_none());
    let s = r.stats();
    assert_eq!((s.foreign_packets, s.data_packets), (22, 0));
    let why = explain_no_frames(&s);
    assert!(why.contains("22 from another model"), "{why}");
}

/// Every UDP payload of a capture.
fn payloads(pcap: &Path) -> Vec<Vec<u8>> {
    let mut r = PcapReader::open(pcap).unwrap();
    let mut out = Vec::new();
    while let Some(d) = r.next_datagram().unwrap() {
        out.push(d.payload);
    }
    out
}

fn write_capture(path: &Path, packets: &[Vec<u8>]) {
    let mut w = PcapWriter::create(path).unwrap();
    for p in packets {
        w.write_udp(2368, 2368, p, None).unwrap();
    }
    w.finish().unwrap();
}

#[test]
fn malformed_packet_is_skipped_and_its_rotation_dropped() {
    let dir = tempfile::tempdir().unwrap();
    let mut packets = payloads(&data("vlp16.pcap"));
    assert_eq!(packets.len(), 22);
    // Packet 10 lies inside the complete rotation: a bad flag in block 5.
    packets[10][500] = 0x12;
    // A bad azimuth (36000 or more) in another packet.
    packets[12][2..4].copy_from_slice(&36001u16.to_le_bytes());
    // A datagram cut short and a position packet.
    packets.push(packets[3][..700].to_vec());
    packets.push(vec![0; 512]);
    let p = dir.path().join("broken.pcap");
    write_capture(&p, &packets);
    let (fr, r) = frames(&p, VelodyneOptions::default());
    let s = r.stats();
    assert_eq!(s.malformed_packets, 2);
    assert_eq!(s.position_packets, 1);
    assert_eq!(s.other_datagrams.get(&700), Some(&1));
    assert!(fr.is_empty(), "the rotation with a gap is not complete");
    let why = explain_no_frames(&s);
    assert!(
        why.contains("2 malformed") && why.contains("1 of 700 bytes"),
        "{why}"
    );
    // Kept when asked, the missing blocks leave empty columns.
    let (fr, _) = frames(
        &p,
        VelodyneOptions {
            keep_incomplete: true,
            ..VelodyneOptions::default()
        },
    );
    assert_eq!(fr.len(), 3);
    assert!(!fr[1].complete);
    let (whole, _) = frames(&data("vlp16.pcap"), VelodyneOptions::default());
    // Two packets of 12 x 32 returns lost (a few shared a pixel with a neighbour).
    let lost = whole[0].returns - fr[1].returns;
    assert!((700..=2 * 12 * 32).contains(&lost), "{lost} returns lost");
}

#[test]
fn not_a_capture_and_cut_captures_are_one_line_errors() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("junk.pcap");
    std::fs::write(&p, b"velodyne? no").unwrap();
    let err = VelodyneReader::open(&p, VelodyneOptions::default())
        .err()
        .unwrap()
        .to_string();
    assert!(
        err.contains("junk.pcap") && err.contains("not a pcap or pcapng file"),
        "{err}"
    );
    assert!(!err.contains('\n'));
    // A capture cut in the middle of a record: the frames before the cut survive.
    let bytes = std::fs::read(data("vlp16.pcap")).unwrap();
    let cut = dir.path().join("cut.pcap");
    std::fs::write(&cut, &bytes[..bytes.len() - 600]).unwrap();
    let (fr, r) = frames(&cut, VelodyneOptions::default());
    assert_eq!(fr.len(), 1);
    assert!(r.stats().pcap.truncated_file);
    // An unknown product id without a model named.
    let mut packets = payloads(&data("vlp16.pcap"));
    for p in &mut packets {
        p[1205] = 0x99;
    }
    let odd = dir.path().join("odd.pcap");
    write_capture(&odd, &packets);
    let mut r = VelodyneReader::open(&odd, VelodyneOptions::default()).unwrap();
    let err = r.next_frame().unwrap_err().to_string();
    assert!(
        err.contains("odd.pcap")
            && err.contains("product id 0x99")
            && err.contains("--velodyne-model"),
        "{err}"
    );
}

#[test]
fn calibration_file_errors_name_file_and_laser() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("cal.yaml");
    std::fs::write(&p, "lasers:\n- {laser_id: 0, vert_correction: nan}\n").unwrap();
    let err = fcc_lidar::velodyne::VelodyneCalibration::from_file(&p, VelodyneModel::Vlp16)
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("cal.yaml") && err.contains("vert_correction is nan"),
        "{err}"
    );
    std::fs::write(&p, "hello world\n").unwrap();
    let err = fcc_lidar::velodyne::VelodyneCalibration::from_file(&p, VelodyneModel::Vlp16)
        .unwrap_err()
        .to_string();
    assert!(err.contains("not a Velodyne calibration file"), "{err}");
    // Velodyne's db.xml: degrees and centimetres.
    let mut xml = String::from("<boost_serialization><DB><distLSB_>0.2</distLSB_><points_>");
    for i in 0..16 {
        xml.push_str(&format!(
            "<item><px><id_>{i}</id_><rotCorrection_>1.5</rotCorrection_><vertCorrection_>{}</vertCorrection_><distCorrection_>120</distCorrection_></px></item>",
            i - 8
        ));
    }
    xml.push_str("</points_></DB></boost_serialization>");
    std::fs::write(&p, xml).unwrap();
    let c = fcc_lidar::velodyne::VelodyneCalibration::from_file(&p, VelodyneModel::Vlp16).unwrap();
    assert_eq!(c.distance_resolution_m, 0.002);
    assert!((c.lasers[3].vert_correction.to_degrees() + 5.0).abs() < 1e-12);
    assert!((c.lasers[3].dist_correction - 1.2).abs() < 1e-12);
    assert!((c.lasers[3].rot_correction.to_degrees() - 1.5).abs() < 1e-12);
}

#[test]
fn flipped_bytes_and_cuts_never_panic() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("m.pcap");
    let packets = payloads(&data("hdl64e.pcap"));
    let mut seed = 0x2545_f491_4f6c_dd1du64;
    let mut next = || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        seed
    };
    for round in 0..40 {
        let mut ps = packets.clone();
        for _ in 0..20 {
            let k = (next() % ps.len() as u64) as usize;
            let i = (next() % ps[k].len() as u64) as usize;
            ps[k][i] = next() as u8;
        }
        write_capture(&p, &ps);
        let opts = VelodyneOptions {
            calibration: Some(data("hdl64e.yaml")),
            keep_incomplete: round % 2 == 0,
            ..VelodyneOptions::default()
        };
        let mut r = VelodyneReader::open(&p, opts).unwrap();
        while let Ok(Some(f)) = r.next_frame() {
            assert_eq!(f.image.rows, 64, "round {round}");
        }
    }
    let bytes = std::fs::read(data("vlp16.pcap")).unwrap();
    for len in (0..bytes.len()).step_by(1013) {
        std::fs::write(&p, &bytes[..len]).unwrap();
        if let Ok(mut r) = VelodyneReader::open(&p, VelodyneOptions::default()) {
            while let Ok(Some(_)) = r.next_frame() {}
        }
    }
}

/// Points of the fixtures as the `velodyne-decoder` package decodes them
/// (`cross_check.py`): every one has an fcc return next to it. The VLP-32C
/// and HDL-32E references use VeloView's calibrations against fcc's own
/// tables. It rounds firing azimuths to hundredths of a degree (up to 1.5
/// mm at 17 m), and the VLP-16 keeps a model difference of up to 3.4 mm
/// (vertical offsets added to z there, turned with the beam here).
#[test]
fn points_agree_with_an_independent_decoder() {
    for (stem, cal, tol) in [
        ("vlp16", None, 0.004),
        ("vlp32c", None, 0.002),
        ("hdl32e", None, 0.002),
        ("hdl64e", Some("hdl64e_no_offsets.yaml"), 0.002),
    ] {
        let (fr, _) = frames(
            &data(&format!("{stem}.pcap")),
            VelodyneOptions {
                calibration: cal.map(data),
                keep_incomplete: true,
                // Fine columns: every firing keeps a pixel of its own.
                columns: Some(8192),
                ..VelodyneOptions::default()
            },
        );
        let ours: Vec<[f32; 3]> = fr
            .iter()
            .flat_map(|f| (0..f.image.pixels()).filter_map(|i| f.image.point(i)))
            .collect();
        let text = std::fs::read_to_string(data(&format!("{stem}_velodyne_decoder.json"))).unwrap();
        let json: serde_json::Value = serde_json::from_str(&text).unwrap();
        let theirs = json["points"].as_array().unwrap();
        assert!(theirs.len() > 100, "{stem}");
        let mut worst = 0.0f64;
        for (k, p) in theirs.iter().enumerate() {
            let p: Vec<f64> = p
                .as_array()
                .unwrap()
                .iter()
                .map(|v| v.as_f64().unwrap())
                .collect();
            let d = ours
                .iter()
                .map(|q| {
                    (0..3)
                        .map(|a| (f64::from(q[a]) - p[a]).powi(2))
                        .sum::<f64>()
                        .sqrt()
                })
                .fold(f64::INFINITY, f64::min);
            assert!(
                d < tol,
                "{stem}: reference point {k} {p:?} is {d} m from the nearest fcc point"
            );
            worst = worst.max(d);
        }
        eprintln!(
            "{stem}: {} reference points, farthest {:.2} mm",
            theirs.len(),
            worst * 1e3
        );
    }
}
