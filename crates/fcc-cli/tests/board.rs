//! `fcc board run --virtual` end to end: the four Ouster captures at their
//! own size, with the `paper` thresholds (two with `adaptive` too), on one
//! K_max = 11, 128 x 2048 core (programmed through its run registers, never
//! rebuilt) through the driver, the AXI DMA model and the
//! Verilator model of the core, every label checked against the golden
//! model by the command itself; its outputs equal those of `fcc cluster`;
//! and its refusals.

use std::path::Path;
use std::process::Output;

use fcc_lidar::ouster::SAMPLE_CAPTURES;
use fcc_testkit::{lidar_data, s, text, tmpdir};

fn fcc(args: &[&str]) -> Output {
    fcc_testkit::run_in(env!("CARGO_BIN_EXE_fcc"), None, args)
}

/// Held by a test while its first `fcc board run` may build the shared
/// Verilator model, so that two processes never build it at once (each
/// would, a few CPU minutes); later runs load it from the cache.
static FIRST_BUILD: std::sync::Mutex<()> = std::sync::Mutex::new(());

fn first_build() -> std::sync::MutexGuard<'static, ()> {
    FIRST_BUILD.lock().unwrap_or_else(|e| e.into_inner())
}

/// Each capture at its own size (32, 64 and 128 beams x 1024), K = 7, with
/// fixed and with range-adaptive thresholds (the slopes are run registers),
/// on the K_max = 11, 128 x 2048, B = 16 core of slopes 0: the same
/// Verilator model as fcc-sim's `run_size` test (shared through the cache).
/// The first run builds the model; the others then run two at a time (each
/// an `fcc` process simulating on one core).
#[test]
fn ouster_captures_on_the_virtual_board_equal_the_golden_model() {
    let d = tmpdir("ouster");
    // Every capture with `paper`; the 32-beam and the long-range 128-beam
    // sensor (where far objects gain most) with `adaptive` too.
    let runs: Vec<_> = SAMPLE_CAPTURES
        .iter()
        .flat_map(|c| {
            let adaptive = c.0.starts_with("OS-1-32") || c.0.starts_with("OS-2-128");
            let presets: &[&str] = if adaptive {
                &["paper", "adaptive"]
            } else {
                &["paper"]
            };
            presets.iter().map(move |preset| (*c, *preset))
        })
        .collect();
    let (first, rest) = runs.split_first().expect("sample captures");
    {
        let _building = first_build();
        capture_on_the_board(&d, *first);
    }
    let next = std::sync::atomic::AtomicUsize::new(0);
    std::thread::scope(|sc| {
        for _ in 0..2 {
            sc.spawn(|| loop {
                let i = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                match rest.get(i) {
                    Some(&run) => capture_on_the_board(&d, run),
                    None => break,
                }
            });
        }
    });
    let _ = std::fs::remove_dir_all(&d);
}

/// One capture through the virtual board with `preset`, checked by the
/// command against the golden model, its labels then against `fcc cluster`.
fn capture_on_the_board(d: &Path, ((pcap, json), preset): ((&str, &str), &str)) {
    let data = lidar_data();
    let stem = format!("{}_{preset}", pcap.trim_end_matches(".pcap"));
    let (hw, sw) = (
        d.join(format!("{stem}_hw.npy")),
        d.join(format!("{stem}_sw.npy")),
    );
    let input = data.join(pcap);
    let meta = data.join(json);
    let o = fcc(&[
        "board",
        "run",
        "--virtual",
        "--preset",
        preset,
        "--input",
        s(&input),
        "--meta",
        s(&meta),
        "--output",
        s(&hw),
    ]);
    let out = text(&o);
    assert!(o.status.success(), "{pcap} {preset}: {out}");
    assert!(out.contains("labels equal to the golden model's"), "{out}");
    assert!(out.contains("K_max 11"), "one K_max = 11 core: {out}");
    assert!(out.contains("PASS: 1 frame through the core"), "{out}");
    eprintln!("{out}");
    let o = fcc(&[
        "cluster",
        "--preset",
        preset,
        "--label-bits",
        "16",
        "--input",
        s(&input),
        "--meta",
        s(&meta),
        "--output",
        s(&sw),
    ]);
    assert!(o.status.success(), "{pcap} {preset}: {}", text(&o));
    let (a, b) = (
        fcc_npy::read_labels(&hw).unwrap(),
        fcc_npy::read_labels(&sw).unwrap(),
    );
    assert_eq!((a.rows, a.cols), (b.rows, b.cols), "{pcap} {preset}");
    if let Some(i) = (0..a.labels.len()).find(|&i| a.labels[i] != b.labels[i]) {
        panic!(
            "{pcap} {preset}: board output differs from fcc cluster at row {} col {}: expected {} != got {}",
            i / a.cols,
            i % a.cols,
            b.labels[i],
            a.labels[i]
        );
    }
}

/// A K the core cannot run is refused by the core (its ERROR register),
/// named, and the command stops before sending the frame. The next frame
/// on the same core after a refusal is checked in fcc-sim's board test.
#[test]
fn run_value_the_core_refuses_names_the_register() {
    let data = Path::new(env!("CARGO_MANIFEST_DIR")).join("../fcc-lidar/tests/data");
    let (pcap, json) = SAMPLE_CAPTURES[0];
    // The refusal comes from the core: the model is built (or waited for).
    let building = first_build();
    let o = fcc(&[
        "board",
        "run",
        "--virtual",
        "--fsize",
        "13",
        "--input",
        s(&data.join(pcap)),
        "--meta",
        s(&data.join(json)),
    ]);
    let out = text(&o);
    assert!(!o.status.success(), "{out}");
    assert!(out.contains("the core refused RUN_K = 13"), "{out}");
    assert!(out.contains("K_MAX 11"), "{out}");
    assert!(!out.contains("PASS"), "{out}");
    drop(building);
    let o = fcc(&[
        "board",
        "run",
        "--virtual",
        "--label-bits",
        "12",
        "--input",
        s(&data.join(pcap)),
        "--meta",
        s(&data.join(json)),
    ]);
    let out = text(&o);
    assert!(!o.status.success(), "{out}");
    assert!(
        out.contains("--label-bits 12 differs from the core's B = 16"),
        "{out}"
    );
}

#[test]
fn board_run_says_where_the_core_must_be_and_refuses_paper_merging() {
    let data = lidar_data();
    let input = data.join(SAMPLE_CAPTURES[1].0);
    let o = fcc(&["board", "run", "--input", s(&input)]);
    assert!(!o.status.success());
    assert!(
        text(&o).contains("--virtual, or --uio NAME"),
        "{}",
        text(&o)
    );
    let o = fcc(&["board", "run", "--uio", "fcc", "--input", s(&input)]);
    assert!(!o.status.success());
    assert!(text(&o).contains("--params"), "{}", text(&o));
    let o = fcc(&[
        "board",
        "run",
        "--virtual",
        "--merge",
        "paper",
        "--input",
        s(&input),
    ]);
    assert!(!o.status.success());
    assert!(text(&o).contains("drop --merge paper"), "{}", text(&o));
}

#[test]
fn board_run_reads_the_build_from_fcc_params_json_and_refuses_garbage() {
    let d = tmpdir("params");
    let bad = d.join("fcc_params.json");
    std::fs::write(&bad, "{\"rows\": 64}").unwrap();
    let data = lidar_data();
    let input = data.join(SAMPLE_CAPTURES[1].0);
    let o = fcc(&[
        "board",
        "run",
        "--uio",
        "fcc",
        "--params",
        s(&bad),
        "--input",
        s(&input),
    ]);
    assert!(!o.status.success());
    assert!(text(&o).contains("not an fcc_params.json"), "{}", text(&o));
    // A valid build, but no UIO device of that name on this machine.
    let good = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../rtl_out/fcc_params.json");
    let o = fcc(&[
        "board",
        "run",
        "--uio",
        "no-such-core",
        "--params",
        s(&good),
        "--input",
        s(&input),
    ]);
    assert!(!o.status.success());
    assert!(text(&o).contains("UIO"), "{}", text(&o));
    let _ = std::fs::remove_dir_all(&d);
}

/// The column core (`--scan column`) on the virtual board: the 32- and
/// 64-beam captures through its K_max = 11, 128 x 2048, B = 16 build, every
/// record and end beat checked by the command against the golden stream's;
/// the records it writes (JSON lines on stdout) are those of
/// `fcc cluster --stream` with the core's open limit; and the capture's
/// packets replayed to `fcc live --virtual` give the same lines.
#[test]
fn ouster_captures_on_the_virtual_column_core_equal_the_golden_stream() {
    let data = lidar_data();
    let runs: Vec<_> = SAMPLE_CAPTURES
        .iter()
        .filter(|c| c.0.starts_with("OS-1-"))
        .collect();
    assert_eq!(runs.len(), 2);
    for (i, (pcap, json)) in runs.into_iter().enumerate() {
        let (input, meta) = (data.join(pcap), data.join(json));
        // The second with range-adaptive thresholds and stream limits.
        let extra: &[&str] = if i == 0 {
            &[]
        } else {
            &[
                "--preset",
                "adaptive",
                "--bridge",
                "16",
                "--ring-reach",
                "16",
            ]
        };
        let mut args = vec!["board", "run", "--virtual", "--scan", "column"];
        args.extend(extra);
        args.extend(["--input", s(&input), "--meta", s(&meta)]);
        let o = fcc(&args);
        let err = fcc_testkit::stderr(&o);
        assert!(o.status.success(), "{pcap}: {}", text(&o));
        assert!(err.contains("column-streaming core for K_max 11"), "{err}");
        assert!(
            err.contains("records equal to the golden stream's"),
            "{err}"
        );
        assert!(
            err.contains("PASS: 1 frame through the core, every record equal"),
            "{err}"
        );
        let mut sw = vec![
            "cluster",
            "--stream",
            "--label-bits",
            "16",
            "--open-limit",
            "511",
        ];
        sw.extend(extra);
        sw.extend(["--input", s(&input), "--meta", s(&meta)]);
        let g = fcc(&sw);
        assert!(g.status.success(), "{pcap}: {}", text(&g));
        let (hw, gold) = (
            String::from_utf8_lossy(&o.stdout),
            String::from_utf8_lossy(&g.stdout),
        );
        assert!(hw.lines().count() > 40, "{pcap}: {hw}");
        if let Some((n, (a, b))) = hw
            .lines()
            .zip(gold.lines())
            .enumerate()
            .find(|(_, (a, b))| a != b)
        {
            panic!("{pcap}: record line {n}: expected {b} != got {a}");
        }
        assert_eq!(hw.lines().count(), gold.lines().count(), "{pcap}");
        // The capture's packets to `fcc live --virtual`: the same records.
        let stem = Path::new(pcap)
            .file_stem()
            .and_then(|n| n.to_str())
            .unwrap();
        let mut live = vec![
            "--virtual",
            "--meta",
            s(&meta),
            "--name",
            stem,
            "--idle-timeout",
            "1.5",
        ];
        live.extend(extra);
        let (o, err) = fcc_testkit::live::live_on_replay(
            env!("CARGO_BIN_EXE_fcc"),
            &input,
            &live,
            &["--meta", s(&meta)],
        );
        assert!(o.status.success(), "{pcap}: {err}");
        for says in [
            "frame path: each frame through the column core",
            "records equal to the golden stream's",
            "PASS: 1 frame through the core, every record equal",
            "live: 1 frames",
        ] {
            assert!(err.contains(says), "{pcap}: no `{says}` in {err}");
        }
        let live = String::from_utf8_lossy(&o.stdout);
        if let Some((n, (a, b))) = live
            .lines()
            .zip(gold.lines())
            .enumerate()
            .find(|(_, (a, b))| a != b)
        {
            panic!("{pcap}: fcc live --virtual, record line {n}: expected {b} != got {a}");
        }
        assert_eq!(live.lines().count(), gold.lines().count(), "{pcap}: {err}");
    }
}

/// What the column core cannot do is refused before a model is built, by
/// `fcc board run` and `fcc live`.
#[test]
fn column_core_refuses_open_limits_past_its_slots_and_min_points() {
    let data = lidar_data();
    let input = data.join(SAMPLE_CAPTURES[1].0);
    for (extra, says) in [
        (
            &["--open-limit", "600"][..],
            "--open-limit 600: the column core holds at most 511",
        ),
        (&["--min-points", "5"], "drop --min-points 5"),
    ] {
        let mut args = vec!["board", "run", "--virtual", "--scan", "column"];
        args.extend(extra);
        args.extend(["--input", s(&input)]);
        let o = fcc(&args);
        assert!(!o.status.success());
        assert!(text(&o).contains(says), "{}", text(&o));
        assert!(!text(&o).contains("building"), "{}", text(&o));
        // As `fcc live --virtual` refuses them, before it listens.
        let mut args = vec!["live", "--virtual", "--udp", "127.0.0.1:0"];
        args.extend(extra);
        let o = fcc(&args);
        assert!(!o.status.success());
        assert!(text(&o).contains(says), "{}", text(&o));
        assert!(!text(&o).contains("listening"), "{}", text(&o));
    }
    let o = fcc(&[
        "board",
        "run",
        "--virtual",
        "--stream",
        "--input",
        s(&input),
    ]);
    assert!(!o.status.success());
    assert!(text(&o).contains("--scan column"), "{}", text(&o));
}
