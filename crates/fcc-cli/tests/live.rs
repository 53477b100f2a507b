//! `fcc live` and `fcc replay` on the loopback: live = offline, record for
//! record (each Ouster capture and a Velodyne fixture replayed to `fcc live`
//! gives the JSON lines `fcc cluster --stream` prints for the file); no
//! packet at all is an error after the idle timeout; `--frames` stops; a
//! frame that misses a packet writes nothing on the column path, as
//! offline; memory stays flat over hundreds of frames. Every child is
//! bounded in time and killed on failure.

use fcc_testkit::live::{Guard, LIMIT};
use fcc_testkit::{lidar_data, s};
use std::io::Read;
use std::path::Path;
use std::process::{Child, Command, Output};
use std::time::{Duration, Instant};

const FCC: &str = env!("CARGO_BIN_EXE_fcc");

fn fcc(args: &[&str]) -> Output {
    fcc_testkit::run_in(FCC, None, args)
}

fn start_live(args: &[&str]) -> (Guard, u16, Vec<u8>) {
    fcc_testkit::live::start_live(FCC, args)
}

/// Replay `capture` to `fcc live ARGS` and return live's output.
fn live_on_replay(capture: &Path, args: &[&str]) -> (Output, String) {
    fcc_testkit::live::live_on_replay(FCC, capture, args, &[])
}

/// Live's stdout holds offline's JSON lines, line for line (the first
/// difference names its record); the number of records.
fn assert_same_records(what: &str, off: &Output, live: &Output, err: &str) -> usize {
    let (a, b) = (
        String::from_utf8_lossy(&off.stdout),
        String::from_utf8_lossy(&live.stdout),
    );
    let (a, b): (Vec<&str>, Vec<&str>) = (a.lines().collect(), b.lines().collect());
    assert_eq!(a.len(), b.len(), "{what}: records offline vs live\n{err}");
    for (k, (x, y)) in a.iter().zip(&b).enumerate() {
        assert_eq!(x, y, "{what}: record {k}");
    }
    a.len()
}

fn stem(p: &str) -> &str {
    p.rsplit_once('.').map_or(p, |(a, _)| a)
}

/// Each Ouster sample capture and the VLP-16 fixture replayed to `fcc live
/// GROUND` give the JSON lines of `fcc cluster --stream GROUND` on the file,
/// and live's stderr names the path it ran (`path`).
fn live_equals_offline(ground: &[&str], path: &str) {
    live_equals_offline_with(ground, &[], &[], true, path);
}

/// As [`live_equals_offline`], with `live_more` on `fcc live` only and
/// `off_more` on `fcc cluster` only (the Velodyne fixture too when
/// `velodyne`); the counts of a clean run are checked when neither adds
/// options.
fn live_equals_offline_with(
    ground: &[&str],
    live_more: &[&str],
    off_more: &[&str],
    velodyne: bool,
    path: &str,
) {
    let d = lidar_data();
    let mut cases: Vec<(String, Vec<String>)> = fcc_lidar::ouster::SAMPLE_CAPTURES
        .iter()
        .map(|(pcap, meta)| {
            (
                s(&d.join(pcap)).to_string(),
                vec!["--meta".into(), s(&d.join(meta)).to_string()],
            )
        })
        .collect();
    if velodyne {
        cases.push((
            s(&d.join("velodyne/vlp16.pcap")).to_string(),
            vec!["--sensor".into(), "velodyne".into()],
        ));
    }
    for (capture, opts) in &cases {
        let name = stem(
            Path::new(capture)
                .file_name()
                .and_then(|n| n.to_str())
                .unwrap_or(""),
        );
        let extra = [
            "--fsize",
            "7",
            "--preset",
            "adaptive",
            "--bridge",
            "4",
            "--min-points",
            "3",
        ];
        let mut off_args = vec!["cluster", "-i", capture.as_str(), "--stream"];
        off_args.extend(opts.iter().map(String::as_str));
        off_args.extend(extra);
        off_args.extend(ground);
        off_args.extend(off_more);
        let off = fcc(&off_args);
        assert!(
            off.status.success(),
            "{}",
            String::from_utf8_lossy(&off.stderr)
        );
        assert!(!off.stdout.is_empty(), "{capture}: no record offline");
        let mut live_args: Vec<&str> = opts.iter().map(String::as_str).collect();
        live_args.extend(["--name", name, "--idle-timeout", "1.5"]);
        live_args.extend(extra);
        live_args.extend(ground);
        live_args.extend(live_more);
        let (live, err) = live_on_replay(Path::new(capture), &live_args);
        assert!(live.status.success(), "{capture}: {err}");
        assert_same_records(capture, &off, &live, &err);
        if live_more.is_empty() && off_more.is_empty() {
            assert!(
                err.contains("live: 1 frames")
                    && err.contains(" 0 lost")
                    && err.contains("0 malformed"),
                "{capture}: {err}"
            );
        }
        assert!(err.contains(path), "{capture}: no `{path}` in {err}");
    }
}

#[test]
fn live_on_a_replay_gives_the_records_of_cluster_stream() {
    // The default ground removal (slope) fits the whole frame.
    live_equals_offline(&[], "frame path: ground removal `slope`");
}

#[test]
fn column_path_gives_the_records_of_cluster_stream_record_for_record() {
    // Records written as they close, from the columns of each frame.
    live_equals_offline(&["--ground", "none"], "column path:");
}

#[test]
fn sweep_origin_streams_records_as_the_sweep_passes_and_equals_cluster_stream() {
    // Streamed before a frame is known complete, so frames that miss
    // columns are kept (the captures' first, cut frame among them): as
    // `fcc cluster --keep-incomplete` on the file.
    live_equals_offline_with(
        &["--ground", "none", "--image-origin", "sweep"],
        &[],
        &["--keep-incomplete"],
        false,
        "columns streamed as their packets arrive",
    );
}

#[test]
fn no_packet_is_an_error_after_the_idle_timeout() {
    let d = lidar_data();
    let meta = d.join(fcc_lidar::ouster::SAMPLE_CAPTURES[1].1);
    let (live, _, _) = start_live(&["--meta", s(&meta), "--idle-timeout", "0.5"]);
    let t = Instant::now();
    let out = live.wait();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("no packet in 0.5 s (--idle-timeout)") && err.contains("live: 0 frames"),
        "{err}"
    );
    assert!(t.elapsed() < Duration::from_secs(20));
}

#[test]
fn frames_stops_after_n_frames() {
    // Two rotations of the 600 rpm VLP-16 fixture; --frames 1 stops at the first.
    let d = lidar_data();
    let capture = d.join("velodyne/vlp16_600rpm.pcap");
    let (live, err) = live_on_replay(
        &capture,
        &[
            "--sensor",
            "velodyne",
            "--frames",
            "1",
            "--idle-timeout",
            "5",
        ],
    );
    assert!(live.status.success(), "{err}");
    // It stopped at the frame, not at the end of the stream.
    assert!(
        err.contains("live: 1 frames") && !err.contains("the stream ended"),
        "{err}"
    );
}

#[test]
fn bad_options_are_refused_with_a_reason() {
    let d = lidar_data();
    let meta = d.join(fcc_lidar::ouster::SAMPLE_CAPTURES[1].1);
    let vlp = d.join("velodyne/vlp16.pcap");
    let cases: [(&[&str], &str); 7] = [
        (
            &["live", "--meta", s(&meta), "--merge", "paper"],
            "drop --merge paper",
        ),
        (
            &["live", "--meta", s(&meta), "--image-origin", "north"],
            "unknown image origin `north`: expected sensor or sweep",
        ),
        (
            &["live", "--sensor", "velodyne", "--image-origin", "sweep"],
            "image origin `sweep` is for Ouster sensors only",
        ),
        (
            &[
                "cluster",
                "-i",
                s(&vlp),
                "--sensor",
                "velodyne",
                "--image-origin",
                "sweep",
            ],
            "image origin `sweep` is for Ouster captures only",
        ),
        (
            &["live", "--meta", s(&meta), "--idle-timeout", "0"],
            "--idle-timeout 0",
        ),
        (&["live", "--sensor", "ouster"], "needs its metadata JSON"),
        (
            &["replay", s(&meta), "--udp", "127.0.0.1:9", "--rate", "-1"],
            "--rate -1",
        ),
    ];
    for (args, want) in cases {
        let o = fcc(args);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(want), "{args:?}: {err}");
    }
}

#[test]
fn ctrl_c_ends_cleanly_with_a_summary() {
    let d = lidar_data();
    let meta = d.join(fcc_lidar::ouster::SAMPLE_CAPTURES[1].1);
    let (live, _, _) = start_live(&["--meta", s(&meta), "--idle-timeout", "60"]);
    let pid = live.0.as_ref().map(Child::id).expect("a child");
    std::thread::sleep(Duration::from_millis(300));
    let k = Command::new("kill")
        .args(["-INT", &pid.to_string()])
        .status()
        .expect("run kill");
    assert!(k.success());
    let t = Instant::now();
    let out = live.wait();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{err}");
    assert!(t.elapsed() < Duration::from_secs(30), "{err}");
    let summary: Vec<&str> = err.lines().filter(|l| l.starts_with("live: ")).collect();
    assert_eq!(summary.len(), 1, "{err}");
    for word in ["frames", "packets", "lost", "malformed", "clusters"] {
        assert!(summary[0].contains(word), "{err}");
    }
}

/// The third-party MCAP decoder's Python, or why it cannot run.
fn mcap_python() -> Result<std::path::PathBuf, String> {
    let py = std::env::var_os("FCC_MCAP_PYTHON")
        .map(std::path::PathBuf::from)
        .unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join("../../.venv/bin/python"));
    let ok = Command::new(&py)
        .args(["-c", "import mcap_ros2.decoder"])
        .output()
        .is_ok_and(|o| o.status.success());
    if ok {
        Ok(py)
    } else {
        Err(format!(
            "{} cannot import mcap_ros2: run ./setup.sh (or pip install -r crates/fcc-lidar/tests/requirements.txt), or set FCC_MCAP_PYTHON",
            py.display()
        ))
    }
}

/// The messages of an MCAP file as the third-party decoder reads them.
fn read_mcap(py: &Path, file: &Path) -> Vec<serde_json::Value> {
    let script = lidar_data().join("mcap/read_with_mcap_ros2.py");
    let out = Command::new(py)
        .arg(&script)
        .arg(file)
        .output()
        .expect("run python");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stdout)
        .lines()
        .map(|l| serde_json::from_str(l).expect("json"))
        .collect()
}

#[test]
fn mcap_of_live_and_of_cluster_hold_the_same_points_labels_and_boxes() {
    let py = match mcap_python() {
        Ok(py) => py,
        Err(why) if std::env::var("CI").is_ok_and(|v| v == "true") => {
            panic!("the MCAP decoder cannot run under CI: {why}")
        }
        Err(why) => {
            eprintln!("NOT RUN: {why}");
            return;
        }
    };
    let d = lidar_data();
    let (pcap, meta) = fcc_lidar::ouster::SAMPLE_CAPTURES[1];
    let (capture, meta) = (d.join(pcap), d.join(meta));
    let dir = fcc_testkit::tmpdir("live_mcap");
    let (off_mcap, live_mcap) = (dir.join("cluster.mcap"), dir.join("live.mcap"));
    let off = fcc(&[
        "cluster",
        "-i",
        s(&capture),
        "--meta",
        s(&meta),
        "--stream",
        "--mcap",
        s(&off_mcap),
    ]);
    assert!(
        off.status.success(),
        "{}",
        String::from_utf8_lossy(&off.stderr)
    );
    let (live, err) = live_on_replay(
        &capture,
        &[
            "--meta",
            s(&meta),
            "--idle-timeout",
            "1.5",
            "--mcap",
            s(&live_mcap),
        ],
    );
    assert!(live.status.success(), "{err}");
    let (a, b) = (read_mcap(&py, &off_mcap), read_mcap(&py, &live_mcap));
    assert_eq!(a.len(), 2);
    assert_eq!(b.len(), 2);
    let records = String::from_utf8_lossy(&off.stdout).lines().count();
    for (x, y) in a.iter().zip(&b) {
        assert_eq!(x["topic"], y["topic"]);
        for key in ["points", "labels", "fields", "width"] {
            assert_eq!(x[key], y[key], "{key}");
        }
        if let Some(m) = x["markers"].as_array() {
            assert_eq!(m.len(), records + 1);
            let ids = |v: &serde_json::Value| -> Vec<serde_json::Value> {
                v["markers"]
                    .as_array()
                    .unwrap()
                    .iter()
                    .map(|m| m["position"].clone())
                    .collect()
            };
            assert_eq!(ids(x), ids(y));
        }
    }
    // Live Ouster frames carry the sensor's timestamp, in the header too,
    // and `cluster --mcap` stamps the capture's frames the same way.
    let t = b[0]["log_time"].as_u64().unwrap();
    assert!(t > 0);
    assert_eq!(a[0]["log_time"], b[0]["log_time"]);
    assert_eq!(a[0]["stamp"], b[0]["stamp"]);
    assert_eq!(
        b[0]["stamp"],
        serde_json::json!([t / 1_000_000_000, t % 1_000_000_000])
    );
}

#[test]
fn replay_repeat_sends_the_rotation_again_as_new_frames() {
    let d = lidar_data();
    let (pcap, meta) = fcc_lidar::ouster::SAMPLE_CAPTURES[2];
    let (capture, meta) = (d.join(pcap), d.join(meta));
    let (live, port, first) =
        start_live(&["--meta", s(&meta), "--idle-timeout", "1.5", "--latency"]);
    let to = format!("127.0.0.1:{port}");
    let r = fcc(&[
        "replay",
        s(&capture),
        "--udp",
        &to,
        "--rate",
        "2",
        "--repeat",
        "3",
        "--meta",
        s(&meta),
    ]);
    assert!(r.status.success(), "{}", String::from_utf8_lossy(&r.stderr));
    let out = live.wait();
    let err = String::from_utf8_lossy(&first).into_owned() + &String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{err}");
    assert!(
        err.contains("live: 3 frames") && err.contains(" 0 lost"),
        "{err}"
    );
    // Two frames were completed by a packet (the third by the end of the stream).
    assert!(err.contains("over 2 frames"), "{err}");
    let off = fcc(&["cluster", "-i", s(&capture), "--meta", s(&meta), "--stream"]);
    let per_frame = String::from_utf8_lossy(&off.stdout).lines().count();
    assert_eq!(
        String::from_utf8_lossy(&out.stdout).lines().count(),
        3 * per_frame
    );
}

#[test]
fn foxglove_serves_on_the_address_given() {
    let d = lidar_data();
    let meta = d.join(fcc_lidar::ouster::SAMPLE_CAPTURES[1].1);
    let (live, _, first) = start_live(&[
        "--meta",
        s(&meta),
        "--idle-timeout",
        "0.5",
        "--foxglove",
        "127.0.0.1:0",
    ]);
    let out = live.wait();
    let err = String::from_utf8_lossy(&first).into_owned() + &String::from_utf8_lossy(&out.stderr);
    // No packet came: the run ends with its error, after the server started.
    assert_eq!(out.status.code(), Some(2), "{err}");
    let port = err
        .lines()
        .find_map(|l| l.strip_prefix("foxglove: ws://127.0.0.1:"))
        .and_then(|p| p.trim().parse::<u16>().ok());
    assert!(port.is_some_and(|p| p != 0), "{err}");
}

#[test]
fn a_lost_packet_on_the_column_path_drops_its_frame_before_any_record_as_offline() {
    // The sensor origin's column path without --keep-incomplete: a frame
    // that misses a packet writes no record at all (offline drops it whole),
    // even though the columns before the loss became complete with the
    // frame's last packet. Three rotations of a sample capture, the second
    // missing one packet in its middle.
    let d = lidar_data();
    let (pcap, meta) = fcc_lidar::ouster::SAMPLE_CAPTURES[2];
    let (capture, meta_path) = (d.join(pcap), d.join(meta));
    let m = fcc_lidar::ouster::OusterMetadata::from_file(&meta_path).unwrap();
    let mut packets = Vec::new();
    let mut r = fcc_lidar::pcap::PcapReader::open(&capture).unwrap();
    while let Some(d) = r.next_datagram().unwrap() {
        if d.payload.len() == m.packet_size() {
            packets.push(d);
        }
    }
    let lost = packets.len() * 3 / 4;
    let dir = fcc_testkit::tmpdir("live_lost_packet");
    let damaged = dir.join("three_rotations.pcap");
    let mut w = fcc_lidar::pcap::PcapWriter::create(&damaged).unwrap();
    for pass in 0..3u16 {
        for (k, d) in packets.iter().enumerate() {
            if pass == 1 && k == lost {
                continue;
            }
            let mut p = d.payload.clone();
            assert!(fcc_lidar::ouster::bump_frame_id(&m, &mut p, pass));
            w.write_udp(d.src_port, d.dst_port, &p, None).unwrap();
        }
    }
    w.finish().unwrap();
    let common = ["--meta", s(&meta_path), "--ground", "none"];
    let mut off_args = vec!["cluster", "-i", s(&damaged), "--stream"];
    off_args.extend(common);
    let off = fcc(&off_args);
    assert!(off.status.success(), "{}", fcc_testkit::stderr(&off));
    let mut whole_args = vec!["cluster", "-i", s(&capture), "--stream"];
    whole_args.extend(common);
    let whole = fcc(&whole_args);
    let per_frame = String::from_utf8_lossy(&whole.stdout).lines().count();
    assert!(per_frame > 0);
    let mut live_args = vec!["--name", "three_rotations", "--idle-timeout", "1.5"];
    live_args.extend(common);
    let (live, err) = live_on_replay(&damaged, &live_args);
    assert!(live.status.success(), "{err}");
    let n = assert_same_records("three rotations", &off, &live, &err);
    // The whole rotations before and after the damaged one, nothing of it.
    assert_eq!(n, 2 * per_frame, "offline: {}", fcc_testkit::stderr(&off));
    assert!(
        err.contains("1 incomplete frames dropped") && !err.contains("warning: frame"),
        "{err}"
    );
}

/// The resident memory of process `pid`, kB (Linux).
#[cfg(target_os = "linux")]
fn rss_kb(pid: u32) -> Option<u64> {
    let status = std::fs::read_to_string(format!("/proc/{pid}/status")).ok()?;
    status
        .lines()
        .find_map(|l| l.strip_prefix("VmRSS:"))
        .and_then(|v| v.split_whitespace().next())
        .and_then(|v| v.parse().ok())
}

#[cfg(target_os = "linux")]
#[test]
fn memory_stays_bounded_over_hundreds_of_frames() {
    // 200 rotations of a sample capture at twice the recorded rate through
    // the column path: the resident memory once a quarter of the records
    // are out is what it stays at (a leak of one image, record table or
    // packet per frame would add megabytes).
    use std::sync::atomic::{AtomicUsize, Ordering};
    use std::sync::Arc;
    let d = lidar_data();
    let (pcap, meta) = fcc_lidar::ouster::SAMPLE_CAPTURES[1];
    let (capture, meta) = (d.join(pcap), d.join(meta));
    let (mut live, port, first) = start_live(&[
        "--meta",
        s(&meta),
        "--ground",
        "none",
        "--image-origin",
        "sweep",
        "--idle-timeout",
        "2",
    ]);
    let child = live.0.as_mut().expect("a child");
    let pid = child.id();
    let lines = Arc::new(AtomicUsize::new(0));
    let mut out = child.stdout.take().expect("piped");
    let counted = lines.clone();
    std::thread::spawn(move || {
        let mut buf = [0u8; 65_536];
        while let Ok(n) = out.read(&mut buf) {
            if n == 0 {
                break;
            }
            let nl = buf[..n].iter().filter(|&&b| b == b'\n').count();
            counted.fetch_add(nl, Ordering::Relaxed);
        }
    });
    let mut err_pipe = child.stderr.take().expect("piped");
    let err_text = std::thread::spawn(move || {
        let mut v = Vec::new();
        let _ = err_pipe.read_to_end(&mut v);
        v
    });
    let to = format!("127.0.0.1:{port}");
    let (cap, met) = (s(&capture).to_string(), s(&meta).to_string());
    let replay = std::thread::spawn(move || {
        fcc(&[
            "replay", &cap, "--udp", &to, "--rate", "2", "--repeat", "200", "--meta", &met,
        ])
    });
    let start = Instant::now();
    let mut samples: Vec<(usize, u64)> = Vec::new();
    let status = loop {
        if let Some(kb) = rss_kb(pid) {
            samples.push((lines.load(Ordering::Relaxed), kb));
        }
        if let Some(st) = child.try_wait().expect("wait") {
            break st;
        }
        assert!(start.elapsed() < LIMIT, "fcc live did not end");
        std::thread::sleep(Duration::from_millis(50));
    };
    let r = replay.join().expect("replay thread");
    assert!(r.status.success(), "{}", fcc_testkit::stderr(&r));
    let err = String::from_utf8_lossy(&first).into_owned()
        + &String::from_utf8_lossy(&err_text.join().unwrap_or_default());
    assert!(status.success(), "{err}");
    let frames: u64 = err
        .lines()
        .find_map(|l| l.strip_prefix("live: "))
        .and_then(|l| l.split_whitespace().next())
        .and_then(|n| n.parse().ok())
        .unwrap_or(0);
    assert!(frames >= 150, "only {frames} frames: {err}");
    let total = samples.last().map_or(0, |s| s.0);
    let after: Vec<u64> = samples
        .iter()
        .filter(|s| s.0 >= total / 4)
        .map(|s| s.1)
        .collect();
    assert!(after.len() >= 20, "too few samples: {samples:?}");
    let (warm, most) = (after[0], after.iter().copied().max().unwrap_or(0));
    assert!(
        most <= warm + 3 * 1024,
        "resident memory grew from {warm} kB to {most} kB over {frames} frames ({total} records)"
    );
}
