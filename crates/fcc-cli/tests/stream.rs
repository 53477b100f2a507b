//! `fcc cluster --stream` (spec §9): on the Ouster captures the label image
//! is the frame's partition, with and without the reach limits; one JSON
//! record per cluster in closing order; the latency in `--stats`; the
//! row-major core refuses the limits and the stream; `--beats`, the record
//! beats the column-streaming core sends, read back.

use fcc_pixel::record::{FrameEnd, Item, RecordReader, RECORD_WORDS};
use fcc_testkit::{lidar_data, s, same_partition, stderr, tmpdir};
use std::path::Path;
use std::process::Output;

fn fcc(args: &[&str]) -> Output {
    fcc_testkit::run_in(env!("CARGO_BIN_EXE_fcc"), None, args)
}

const CAPTURES: [(&str, &str); 4] = [
    (
        "OS-0-128-U1_v2.3.0_1024x10.pcap",
        "OS-0-128-U1_v2.3.0_1024x10.json",
    ),
    (
        "OS-1-32-G_v2.1.1_1024x10.pcap",
        "OS-1-32-G_v2.1.1_1024x10.json",
    ),
    (
        "OS-1-64_1024x10_fw20.pcap",
        "OS-1-64_sensor_config_reduced.json",
    ),
    (
        "OS-2-128-U1_v2.3.0_1024x10.pcap",
        "OS-2-128-U1_v2.3.0_1024x10.json",
    ),
];

/// A 16 x 256 synthetic scene written into `dir`.
fn small_scene(dir: &Path) -> std::path::PathBuf {
    let npy = dir.join("f.npy");
    let o = fcc(&[
        "scene",
        "--seed",
        "1",
        "--rows",
        "16",
        "--cols",
        "256",
        "--output",
        s(&npy),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    npy
}

fn labels(p: &Path) -> Vec<u32> {
    fcc_npy::read_labels(p).unwrap().labels
}

#[test]
fn streamed_captures_have_the_frames_partition_and_records_in_closing_order() {
    let d = tmpdir("stream-captures");
    for (pcap, meta) in CAPTURES {
        let (pcap, meta) = (lidar_data().join(pcap), lidar_data().join(meta));
        for limits in [&[][..], &["--bridge", "16", "--ring-reach", "16"][..]] {
            let (framed, streamed) = (d.join("frame.npy"), d.join("stream.npy"));
            let mut args = vec![
                "cluster",
                "--input",
                s(&pcap),
                "--meta",
                s(&meta),
                "--max-frames",
                "1",
            ];
            args.extend_from_slice(limits);
            let mut a = args.clone();
            a.extend(["--output", s(&framed)]);
            let o = fcc(&a);
            assert!(o.status.success(), "{}", stderr(&o));
            let mut a = args.clone();
            a.extend(["--stream", "--stats", "--output", s(&streamed)]);
            let o = fcc(&a);
            assert!(o.status.success(), "{}", stderr(&o));
            let what = format!("{} {limits:?}", pcap.display());
            let (f, st) = (labels(&framed), labels(&streamed));
            assert!(same_partition(&f, &st), "{what}: partitions differ");
            let out = String::from_utf8(o.stdout).unwrap();
            let lines: Vec<serde_json::Value> = out
                .lines()
                .map(|l| serde_json::from_str(l).unwrap())
                .collect();
            let (records, stats) = lines.split_at(lines.len() - 1);
            let stats = &stats[0];
            let n = stats["clusters"].as_u64().unwrap();
            assert_eq!(records.len() as u64, n, "{what}");
            assert_eq!(u64::from(*st.iter().max().unwrap()), n, "{what}");
            let mut last_closed = 0;
            for (k, r) in records.iter().enumerate() {
                assert_eq!(r["cluster"].as_u64(), Some(k as u64 + 1), "{what}");
                let closed = r["closed_col"].as_u64().unwrap();
                assert!(closed >= last_closed, "{what}: closing order");
                last_closed = closed;
                // The record's points are the label image's pixels of its id.
                let px = st.iter().filter(|&&l| u64::from(l) == k as u64 + 1).count();
                assert_eq!(r["points"].as_u64(), Some(px as u64), "{what}");
            }
            let lat = &stats["stream"];
            assert_eq!(lat["records"].as_u64(), Some(n));
            if !limits.is_empty() {
                // With a bridge of 16, nothing but the seam holds a cluster
                // more than 17 columns past its last column.
                assert!(lat["max"].as_u64().unwrap() <= 17, "{what}: {lat}");
            }
        }
    }
}

#[test]
fn frame_mode_cluster_table_has_the_record_fields() {
    let d = tmpdir("stream-table");
    let (pcap, meta) = (
        lidar_data().join(CAPTURES[2].0),
        lidar_data().join(CAPTURES[2].1),
    );
    let csv = d.join("c.csv");
    let o = fcc(&[
        "cluster",
        "--input",
        s(&pcap),
        "--meta",
        s(&meta),
        "--max-frames",
        "1",
        "--clusters",
        s(&csv),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&csv).unwrap();
    let header: Vec<&str> = text.lines().next().unwrap().split(',').collect();
    let col = |name: &str| header.iter().position(|h| *h == name).unwrap();
    let (closed, span_last, length, width) = (
        col("closed_col"),
        col("span_last_col"),
        col("box_length"),
        col("box_width"),
    );
    let rows: Vec<Vec<&str>> = text
        .lines()
        .skip(1)
        .map(|l| l.split(',').collect())
        .collect();
    assert!(rows.len() > 10);
    for r in &rows {
        // Frame mode: every record closes at the frame end.
        assert_eq!(r[closed], "1024", "{r:?}");
        assert!(r[span_last].parse::<u32>().unwrap() < 1024);
        let (l, w): (f64, f64) = (r[length].parse().unwrap(), r[width].parse().unwrap());
        assert!(l >= w && w >= 0.0, "{r:?}");
    }
}

#[test]
fn the_row_major_core_refuses_limits_and_the_stream() {
    let d = tmpdir("stream-refusals");
    let npy = small_scene(&d);
    for (args, why) in [
        (
            vec![
                "board",
                "run",
                "--virtual",
                "--input",
                s(&npy),
                "--bridge",
                "4",
            ],
            "unlimited contract",
        ),
        (
            vec!["board", "run", "--virtual", "--input", s(&npy), "--stream"],
            "drop --stream",
        ),
        (
            vec![
                "board",
                "run",
                "--virtual",
                "--input",
                s(&npy),
                "--open-limit",
                "64",
            ],
            "drop --bridge, --ring-reach and --open-limit",
        ),
        (
            vec!["cluster", "--input", s(&npy), "--open-limit", "64"],
            "open_limit = 64 applies to the stream only",
        ),
        (
            vec!["sim", "--input", s(&npy), "--ring-reach", "16"],
            "row-major core",
        ),
        (
            vec![
                "cluster",
                "--input",
                s(&npy),
                "--stream",
                "--merge",
                "paper",
            ],
            "drop --merge paper",
        ),
    ] {
        let o = fcc(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        let e = stderr(&o);
        assert!(e.lines().count() == 1 && e.contains(why), "{args:?}: {e}");
    }
}

/// The second table of `fcc stream-report` (two scenes, K = 3 and 7): per
/// row, the joined runs per pixel within the most at one pixel, the merges
/// of a frame bound those of a column, a column's records each free at
/// least one label, both models send every merge, the union-find
/// reads at least two words a join, and the records closed at a column
/// were all waiting to close at it.
fn check_load_table(md: &str) {
    let lines: Vec<&str> = md.lines().collect();
    let header: Vec<&str> = lines[0].split('|').map(str::trim).collect();
    let col = |name: &str| {
        header
            .iter()
            .position(|h| *h == name)
            .unwrap_or_else(|| panic!("no column {name}: {md}"))
    };
    let (frame, column) = (col("merges per frame"), col("merges in a column"));
    let (closed, freed) = (col("records in a column"), col("labels freed in a column"));
    let waiting = col("waiting to close");
    let (mean, most) = (col("joined runs per pixel"), col("joined runs at a pixel"));
    let (offered, merges) = (col("row roots: offered per slot"), col("merges per slot"));
    let beyond = col("offered beyond one a slot");
    let (reps, reps_beyond) = (
        col("representatives: joins per slot"),
        col("joins beyond one a slot"),
    );
    let reps_column = col("joins in a column");
    let (uf, uf_column, walk) = (
        col("union-find reads per slot"),
        col("reads in a column"),
        col("longest walk"),
    );
    assert_eq!(lines.len(), 2 + 2 * 4, "{md}");
    for l in &lines[2..] {
        let r: Vec<&str> = l.split('|').map(str::trim).collect();
        let n = |c: usize| -> u32 { r[c].parse().unwrap() };
        // A surface's pixel joins the runs of the rows around it: more
        // joined runs than merges, which only join clusters not yet one.
        let m: f64 = r[mean].parse().unwrap();
        assert!(m > 0.5 && f64::from(n(most)) >= m, "{l}");
        // The row-root model offers every merge, and a few it finds done.
        let f = |c: usize| -> f64 { r[c].parse().unwrap() };
        assert!(f(offered) >= f(merges) && f(merges) > 0.0, "{l}");
        assert!(f(beyond) < f(offered), "{l}");
        // Representatives differ across clusters: every merge is a join,
        // and a pixel's joins beyond its first are fewer than all.
        assert!(f(reps) >= f(merges), "{l}");
        assert!(f(reps_beyond) < f(reps) && n(reps_column) > 0, "{l}");
        // Each join walks from two labels, one read a node at least, and
        // a merge puts a run under a root.
        assert!(
            f(uf) >= 2.0 * f(reps) && n(uf_column) >= 2 * n(reps_column),
            "{l}"
        );
        assert!(n(walk) >= 2, "{l}");
        assert!(
            n(frame) >= n(column) && n(column) > 0 && n(closed) > 0 && n(freed) >= n(closed),
            "{l}"
        );
        // The records closed at a column were all waiting at it.
        assert!(n(waiting) >= n(closed), "{l}");
    }
}

/// `--open-limit` (spec §9.1): a limit below what the frame counts open
/// leaves runs unlabelled and says so (`--strict` makes it an error); one at
/// the frame's count changes nothing.
#[test]
fn the_open_limit_leaves_runs_unlabelled_and_says_so() {
    let d = tmpdir("stream-open-limit");
    let npy = small_scene(&d);
    let run = |limit: Option<&str>, extra: &[&str]| {
        let out = d.join("l.npy");
        let mut a = vec![
            "cluster",
            "--input",
            s(&npy),
            "--stream",
            "--output",
            s(&out),
        ];
        if let Some(l) = limit {
            a.extend(["--open-limit", l]);
        }
        a.extend_from_slice(extra);
        let o = fcc(&a);
        (o, labels(&out))
    };
    let (o, free) = run(None, &[]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(!stderr(&o).contains("open limit"), "{}", stderr(&o));
    let labelled = |l: &[u32]| l.iter().filter(|&&v| v != 0).count();
    let (o, limited) = run(Some("2"), &[]);
    assert!(o.status.success(), "{}", stderr(&o));
    let e = stderr(&o);
    assert!(
        e.contains("open limit: ")
            && e.contains("runs left unlabelled")
            && e.contains("raise --open-limit"),
        "{e}"
    );
    assert!(labelled(&limited) < labelled(&free));
    let (o, _) = run(Some("2"), &["--strict"]);
    assert!(
        !o.status.success() && stderr(&o).contains("open limit"),
        "{}",
        stderr(&o)
    );
    let (o, same) = run(Some("4000"), &[]);
    assert!(
        o.status.success() && !stderr(&o).contains("open limit"),
        "{}",
        stderr(&o)
    );
    assert_eq!(same, free);
}

/// `fcc stream-report` on two small synthetic scenes: one row per K and
/// setting, and per row the labels the stream holds at once (what a
/// column-streaming core must store) within the frame's runs, which frame
/// mode labels all at once, and the clusters open at once within those.
#[test]
fn stream_report_counts_the_labels_in_use() {
    let out = fcc(&[
        "stream-report",
        "--scenes",
        "2",
        "--rows",
        "16",
        "--fsize",
        "3,7",
    ]);
    assert!(out.status.success(), "{}", stderr(&out));
    let all = String::from_utf8_lossy(&out.stdout).into_owned();
    let (md, load) = all
        .split_once("\n\n")
        .unwrap_or_else(|| panic!("two tables: {all}"));
    check_load_table(load);
    let header: Vec<&str> = md
        .lines()
        .next()
        .unwrap()
        .split('|')
        .map(str::trim)
        .collect();
    let col = |name: &str| {
        header
            .iter()
            .position(|h| *h == name)
            .unwrap_or_else(|| panic!("no column {name}: {md}"))
    };
    let (runs, peak, open) = (col("runs"), col("peak labels"), col("peak open"));
    let counted = col("peak counted");
    let source = col("source");
    let separator = md.lines().nth(1).unwrap();
    assert_eq!(separator.matches("---|").count() + 2, header.len(), "{md}");
    let rows: Vec<Vec<&str>> = md
        .lines()
        .skip(2)
        .map(|l| l.split('|').map(str::trim).collect())
        .collect();
    assert_eq!(rows.len(), 2 * 4, "{md}");
    for r in rows {
        assert!(r[source].contains("2 scenes, 16 x 2048"), "{md}");
        let n = |c: usize| -> u32 { r[c].parse().unwrap() };
        let (runs, peak, open) = (n(runs), n(peak), n(open));
        assert!(
            peak > 0 && peak < runs,
            "peak labels {peak} of {runs} runs: {md}"
        );
        assert!(
            open > 0 && open <= peak,
            "peak open {open}, peak labels {peak}: {md}"
        );
        // Counted open (spec §9.1): the open clusters and the runs started
        // in the column, each holding a label in use.
        let counted = n(counted);
        assert!(
            open <= counted && counted <= peak,
            "peak open {open}, counted {counted}, labels {peak}: {md}"
        );
    }
}

/// The beats of `--beats` (spec §9.4) read back: a record's 11 words, or an
/// end beat (id 0, `tlast`) at a record boundary.
fn read_beats(path: &Path) -> Vec<Item> {
    let bytes = std::fs::read(path).unwrap();
    assert_eq!(bytes.len() % 8, 0, "{}: whole words", path.display());
    let words: Vec<u64> = bytes
        .chunks_exact(8)
        .map(|c| u64::from_le_bytes(c.try_into().unwrap()))
        .collect();
    let mut reader = RecordReader::new();
    let mut items = Vec::new();
    let mut k = 0;
    while k < words.len() {
        let n = if FrameEnd::is_end(words[k]) {
            1
        } else {
            RECORD_WORDS
        };
        for (j, &w) in words[k..(k + n).min(words.len())].iter().enumerate() {
            let last = n == 1;
            match reader.push(w, last) {
                Ok(Some(item)) => items.push(item),
                Ok(None) => {}
                Err(e) => panic!("{}: word {}: {e}", path.display(), k + j),
            }
        }
        k += n;
    }
    reader.finish().unwrap();
    items
}

#[test]
fn beats_are_the_streamed_records_then_the_end_beat() {
    let d = tmpdir("stream-beats");
    let npy = small_scene(&d);
    let beats = d.join("b.bin");
    let run = |extra: &[&str]| {
        let mut a = vec![
            "cluster",
            "--input",
            s(&npy),
            "--stream",
            "--beats",
            s(&beats),
        ];
        a.extend_from_slice(extra);
        fcc(&a)
    };
    let o = run(&[]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = String::from_utf8(o.stdout).unwrap();
    let lines: Vec<serde_json::Value> = out
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    let items = read_beats(&beats);
    let (end, records) = items.split_last().expect("an end beat");
    assert!(lines.len() > 3, "a scene with clusters: {out}");
    assert_eq!(
        *end,
        Item::End(FrameEnd {
            records: lines.len() as u32,
            overflow: false,
            frame_error: false
        })
    );
    assert_eq!(records.len(), lines.len());
    for (r, l) in records.iter().zip(&lines) {
        let Item::Record(r) = r else {
            panic!("{r:?}: not a record")
        };
        assert_eq!(
            (
                u64::from(r.id),
                u64::from(r.points),
                u64::from(r.closed_col)
            ),
            (
                l["cluster"].as_u64().unwrap(),
                l["points"].as_u64().unwrap(),
                l["closed_col"].as_u64().unwrap()
            ),
            "record {r:?} against its line {l}"
        );
    }
    // Runs refused by the open limit show in the end beat.
    let o = run(&["--open-limit", "2"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let items = read_beats(&beats);
    assert!(
        matches!(items.last(), Some(Item::End(e)) if e.overflow),
        "{:?}",
        items.last()
    );
    // What the core does not send, or nothing to write it from.
    let o = fcc(&["cluster", "--input", s(&npy), "--beats", s(&beats)]);
    assert!(
        !o.status.success() && stderr(&o).contains("add --stream"),
        "{}",
        stderr(&o)
    );
    let o = run(&["--min-points", "5"]);
    assert!(
        !o.status.success() && stderr(&o).contains("drop --min-points 5"),
        "{}",
        stderr(&o)
    );
    // An output naming the input is refused, the input kept.
    let before = std::fs::read(&npy).unwrap();
    let o = fcc(&[
        "cluster",
        "--input",
        s(&npy),
        "--stream",
        "--beats",
        s(&npy),
    ]);
    assert!(!o.status.success(), "--beats over the input ran");
    assert_eq!(std::fs::read(&npy).unwrap(), before, "the input changed");
}
