//! Readers never panic: every reader is fed a few hundred mutated copies of
//! a valid file (bytes flipped, cut short, runs overwritten) and must return
//! `Ok` or `Err`, nothing else. The seed of a failing case is printed.

use fcc_lidar::cloud::{
    read_kitti_bin, read_pcd, read_ply, write_kitti_bin, write_ply, PlyFormat, PointCloud,
};
use fcc_lidar::ouster::{read_capture, DecodeOptions, OusterMetadata};
use std::path::Path;

/// A small deterministic generator (splitmix64).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
}

fn mutate(rng: &mut Rng, base: &[u8], header_bias: usize) -> Vec<u8> {
    let mut b = base.to_vec();
    match rng.below(4) {
        0 => b.truncate(rng.below(b.len())),
        1 => {
            for _ in 0..1 + rng.below(8) {
                // Half of the flips land in the first bytes, where headers are.
                let i = if rng.below(2) == 0 {
                    rng.below(header_bias.min(b.len()))
                } else {
                    rng.below(b.len())
                };
                b[i] ^= 1 << rng.below(8);
            }
        }
        2 => {
            let i = rng.below(b.len());
            let v = rng.next() as u8;
            for x in b.iter_mut().skip(i).take(1 + rng.below(64)) {
                *x = v;
            }
        }
        _ => {
            let i = rng.below(header_bias.min(b.len()));
            let digit = b"0123456789-.e9"[rng.below(14)];
            b[i] = digit;
        }
    }
    b
}

fn run(name: &str, base: &[u8], header_bias: usize, cases: u64, read: impl Fn(&Path) -> bool) {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join(name);
    for seed in 0..cases {
        let mut rng = Rng(seed * 7919 + 1);
        std::fs::write(&path, mutate(&mut rng, base, header_bias)).unwrap();
        let ok = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| read(&path)));
        assert!(
            ok.is_ok(),
            "{name}: reader panicked on mutation seed {seed}"
        );
    }
}

fn cloud() -> PointCloud {
    PointCloud {
        points: (0..40).map(|i| [i as f32, 1.0, -2.0]).collect(),
        intensity: Some(vec![0.5; 40]),
    }
}

#[test]
fn mutated_point_clouds_never_panic() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("a.ply");
    for f in [PlyFormat::Ascii, PlyFormat::BinaryLittleEndian] {
        write_ply(&p, &cloud().points, None, Some(&[3; 40]), f).unwrap();
        run("m.ply", &std::fs::read(&p).unwrap(), 200, 400, |q| {
            read_ply(q).is_ok()
        });
    }
    let b = dir.path().join("a.bin");
    write_kitti_bin(&b, &cloud()).unwrap();
    run("m.bin", &std::fs::read(&b).unwrap(), 64, 100, |q| {
        read_kitti_bin(q).is_ok()
    });
    let mut ascii = String::from("VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 40\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 40\nDATA ascii\n");
    for p in cloud().points {
        ascii.push_str(&format!("{} {} {}\n", p[0], p[1], p[2]));
    }
    run("m.pcd", ascii.as_bytes(), 150, 400, |q| read_pcd(q).is_ok());
    let mut bin = ascii[..ascii.find("DATA").unwrap()]
        .to_string()
        .into_bytes();
    bin.extend_from_slice(b"DATA binary\n");
    for p in cloud().points {
        for v in p {
            bin.extend_from_slice(&v.to_le_bytes());
        }
    }
    run("mb.pcd", &bin, 150, 400, |q| read_pcd(q).is_ok());
}

#[test]
fn mutated_captures_never_panic() {
    let data = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data");
    let m = OusterMetadata::from_file(&data.join("OS-1-32-G_v2.1.1_1024x10.json")).unwrap();
    let bytes = std::fs::read(data.join("OS-1-32-G_v2.1.1_1024x10.pcap")).unwrap();
    // Mutations anywhere in the first records, where the headers are.
    run("m.pcap", &bytes[..30_000], 30_000, 300, |q| {
        read_capture(q, &m, DecodeOptions::default()).is_ok()
    });
    let json = std::fs::read(data.join("OS-1-32-G_v2.1.1_1024x10.json")).unwrap();
    run("m.json", &json, json.len(), 300, |q| {
        OusterMetadata::from_file(q).is_ok()
    });
}
