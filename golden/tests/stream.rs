//! The stream (spec §9) against frame mode: the same partition, records equal
//! to a direct computation, each closed at the column the closing rule of
//! spec §9.2 gives on the finished partition, in closing order; the bridge
//! and ring-reach limits against the pixel-level reference.

use fcc_golden::{
    cluster, frame_records, reference::reference_labels, Frame, GoldenError, MergeMode, Point,
    Record, Stream,
};
use fcc_params::FccParams;
use fcc_pixel::record::{frame_beats, FrameEnd, HwRecord, Item, RecordReader};
use fcc_scene::{generate, SceneConfig};
use proptest::prelude::*;

/// One frame through `s`, column by column: the records in emission order
/// and the stream's label image.
fn stream_frame(s: &mut Stream, f: &Frame) -> (Vec<Record>, Vec<u32>) {
    let mut records = Vec::new();
    let mut column: Vec<Option<Point>> = vec![None; f.rows];
    for c in 0..f.cols {
        for (i, v) in column.iter_mut().enumerate() {
            *v = f.get(i, c);
        }
        let got = s.push_column(&column).unwrap();
        assert!(got.iter().all(|r| r.closed_col == c as u32));
        records.extend_from_slice(got);
    }
    records.extend_from_slice(s.finish().unwrap());
    let mut labels = Vec::new();
    s.labels_into(&mut labels).unwrap();
    (records, labels)
}

/// The first pixel (raster order) where two label images are not the same
/// partition, as a message; `None` when they are.
/// The closing column of every cluster (index: id - 1) by spec §9.2 read
/// directly, from the finished frame's label image (0: empty or
/// unlabelled) rather than the stream's state: after column `c` a cluster
/// that has pixels so far is held by (1) a pixel in columns `c + 1 - h ..=
/// c`, (2) a row's latest valid pixel at a column `j` the bridge reaches
/// from `c`, (3) a row's first valid pixel within the ring reach of the
/// last column, (4) a row's latest valid pixel at `j` with the row's first,
/// labelled, within the ring reach of `j`; holds 1 and 2 end with the last
/// column. An unheld cluster closes at `c`; the rest at the frame end, `C`.
/// (A cluster is one component whenever nothing holds it: the stream's
/// partition equals frame mode's, checked apart.)
fn closing_columns(p: &FccParams, f: &Frame, labels: &[u32], n: usize) -> Vec<u32> {
    let (rows, cols, h) = (f.rows, f.cols, p.half());
    let mut closed = vec![None; n];
    let mut last_col = vec![None; n];
    // Per row: the first and latest valid pixel so far (column, label).
    let mut first: Vec<Option<(usize, u32)>> = vec![None; rows];
    let mut latest: Vec<Option<(usize, u32)>> = vec![None; rows];
    let mut held = vec![false; n];
    for c in 0..cols {
        for i in 0..rows {
            if f.get(i, c).is_some() {
                let l = labels[i * cols + c];
                latest[i] = Some((c, l));
                first[i].get_or_insert((c, l));
                if l != 0 {
                    last_col[l as usize - 1] = Some(c);
                }
            }
        }
        let more = c + 1 < cols;
        held.fill(false);
        for x in 0..n {
            held[x] = more && last_col[x].is_some_and(|j| j + h > c);
        }
        for i in 0..rows {
            let labelled_first = first[i].filter(|&(_, l)| l != 0);
            if let Some((fc, l)) = labelled_first {
                if p.ring_reaches(fc, cols - 1) {
                    held[l as usize - 1] = true;
                }
            }
            if let Some((j, l)) = latest[i].filter(|&(_, l)| l != 0) {
                let bridge = more && p.bridges(c - j);
                let ring = labelled_first.is_some_and(|(fc, _)| p.ring_reaches(fc, j));
                if bridge || ring {
                    held[l as usize - 1] = true;
                }
            }
        }
        for x in 0..n {
            if closed[x].is_none() && last_col[x].is_some() && !held[x] {
                closed[x] = Some(c as u32);
            }
        }
    }
    closed
        .into_iter()
        .map(|c| c.unwrap_or(cols as u32))
        .collect()
}

fn partition_mismatch(want: &[u32], got: &[u32], cols: usize) -> Option<String> {
    use std::collections::HashMap;
    let (mut fwd, mut back) = (HashMap::new(), HashMap::new());
    for (k, (&a, &b)) in want.iter().zip(got).enumerate() {
        let bad = (a == 0) != (b == 0)
            || (a != 0 && *fwd.entry(a).or_insert(b) != b)
            || (b != 0 && *back.entry(b).or_insert(a) != a);
        if bad {
            return Some(format!(
                "row {}, col {}: frame label {a}, stream label {b} (frame label {a} was stream {:?}, stream {b} was frame {:?})",
                k / cols,
                k % cols,
                fwd.get(&a),
                back.get(&b)
            ));
        }
    }
    None
}

/// Every check of the stream on one frame; `what` names the frame (and its
/// seed) in a failure.
fn check_stream(p: &FccParams, f: &Frame, what: &str) {
    let mut s = Stream::new(p).unwrap();
    let (records, labels) = stream_frame(&mut s, f);
    // The same frame after another one (its columns reversed) on the same
    // stream: the kept buffers carry nothing over but the frame number.
    {
        let mut reused = Stream::new(p).unwrap();
        let mut other = Frame::empty(f.rows, f.cols);
        for r in 0..f.rows {
            for c in 0..f.cols {
                other.set(r, f.cols - 1 - c, f.get(r, c));
            }
        }
        stream_frame(&mut reused, &other);
        let (again, again_labels) = stream_frame(&mut reused, f);
        let first = again.iter().zip(&records).position(|(a, b)| {
            Record {
                frame: b.frame,
                ..*a
            } != *b
        });
        assert!(
            again.len() == records.len() && first.is_none() && again_labels == labels,
            "{what}: a stream's second frame differs from a new stream's (first record differing: {first:?})"
        );
        assert!(again.iter().all(|r| r.frame == 1), "{what}: frame numbers");
    }
    // The frame's beats (spec §9.4): every record's, then the end beat,
    // which a reader gives back; the end beat says whether a valid pixel
    // was left unlabelled.
    let end = s.frame_end().expect("the frame is finished");
    let refused =
        (0..f.rows * f.cols).any(|k| f.get(k / f.cols, k % f.cols).is_some() && labels[k] == 0);
    assert!(
        end.records as usize == records.len() && end.overflow == refused && !end.frame_error,
        "{what}: end beat {end:?}, {} records, a pixel refused: {refused}",
        records.len()
    );
    let hw: Vec<HwRecord> = records.iter().map(Record::hw).collect();
    let mut beats = Vec::new();
    frame_beats(&hw, end, &mut beats).unwrap_or_else(|e| panic!("{what}: {e}"));
    let mut reader = RecordReader::new();
    let mut back = Vec::new();
    for (k, &(w, last)) in beats.iter().enumerate() {
        match reader.push(w, last) {
            Ok(Some(item)) => back.push(item),
            Ok(None) => {}
            Err(e) => panic!("{what}: beat {k}: {e}"),
        }
    }
    reader.finish().unwrap_or_else(|e| panic!("{what}: {e}"));
    let want: Vec<Item> = hw
        .iter()
        .map(|&r| Item::Record(r))
        .chain([Item::End(end)])
        .collect();
    assert_eq!(back, want, "{what}: the frame's beats read back");
    // Frame mode has no open limit (and refuses one).
    let unlimited = FccParams {
        open_limit: None,
        ..p.clone()
    };
    let stats = s.stats();
    // Open clusters each hold a label in use; one is open while any is.
    assert!(
        stats.peak_open <= stats.peak_labels && (stats.peak_open > 0) == (stats.runs > 0),
        "{what}: {stats:?}"
    );
    // Each union of two clusters leaves one fewer; the per-column peaks lie
    // within the frame's counts.
    assert!(
        stats.merges == stats.runs - stats.clusters
            && stats.peak_col_merges <= stats.merges
            && stats.peak_col_closed <= stats.clusters
            && stats.peak_col_freed <= stats.peak_labels
            && stats.peak_col_freed >= stats.peak_col_closed,
        "{what}: {stats:?}"
    );
    // The stream's runs are pass 1's (spec §3) whenever labels run out in
    // neither, numbered 1, 2, ... in the order their first pixels arrive.
    let mut runs = Vec::new();
    s.runs_into(&mut runs).unwrap();
    let framed_runs = fcc_golden::pass1(&unlimited, f);
    if !stats.overflow && stats.open_refused == 0 && !framed_runs.overflow {
        if let Some(m) = partition_mismatch(&framed_runs.labels, &runs, f.cols) {
            panic!("{what}: runs differ from pass 1's: {m}");
        }
    }
    let mut next = 1;
    for c in 0..f.cols {
        for i in 0..f.rows {
            let r = runs[i * f.cols + c];
            assert!(
                r <= next,
                "{what}: run {r} at row {i}, col {c} starts before run {next}"
            );
            next += (r == next) as u32;
        }
    }
    assert_eq!(next - 1, stats.runs, "{what}: runs numbered");
    let framed = cluster(&unlimited, f, MergeMode::Exact).unwrap();
    // Ids 1..=n in emission order, closing columns non-decreasing, and ties
    // in column order of the first pixel.
    let n = records.len() as u32;
    assert_eq!(stats.clusters, n, "{what}");
    for (k, r) in records.iter().enumerate() {
        assert_eq!(r.id, k as u32 + 1, "{what}: record {k}");
        assert_eq!(r.frame, 0);
    }
    let first_px = |id: u32| {
        (0..f.cols)
            .flat_map(|c| (0..f.rows).map(move |i| (c, i)))
            .find(|&(c, i)| labels[i * f.cols + c] == id)
            .unwrap()
    };
    // Each closes where spec §9.2 says, read on the finished partition.
    let closing = closing_columns(p, f, &labels, records.len());
    for r in &records {
        let want = closing[r.id as usize - 1];
        assert_eq!(
            r.closed_col,
            want,
            "{what}: record {} (columns {} ..= {}, rows {} ..= {}) closed at column {}, the closing rule gives {want}",
            r.id,
            r.first_col,
            r.last_col,
            r.first_row,
            r.last_row,
            r.closed_col
        );
    }
    for w in records.windows(2) {
        assert!(w[0].closed_col <= w[1].closed_col, "{what}: order");
        if w[0].closed_col == w[1].closed_col {
            assert!(first_px(w[0].id) < first_px(w[1].id), "{what}: tie order");
        }
    }
    // Each record, frozen when it closed, equals the direct computation over
    // its pixels in the finished frame: no later pixel joined it. And no
    // pixel of it lies after its closing column.
    let direct = frame_records(&unlimited, f, &labels, n, 0);
    for (r, d) in records.iter().zip(&direct) {
        let d = Record {
            closed_col: r.closed_col,
            ..*d
        };
        assert_eq!(*r, d, "{what}: record {} against its pixels", r.id);
        if r.closed_col < f.cols as u32 {
            // Seam clusters wait for the frame end; before the last column
            // the window holds a cluster h columns past its last one.
            assert!(!r.seam, "{what}: record {}", r.id);
            if (r.closed_col as usize) + 1 < f.cols {
                assert!(
                    r.closed_col >= r.last_col + p.half() as u32,
                    "{what}: record {}",
                    r.id
                );
            }
            let late = (0..f.rows).any(|i| {
                (r.closed_col as usize + 1..f.cols).any(|c| labels[i * f.cols + c] == r.id)
            });
            assert!(!late, "{what}: record {} has a pixel after its close", r.id);
        }
    }
    if stats.overflow || stats.open_refused > 0 || framed.overflow {
        return;
    }
    // The same partition as frame mode, and the same records up to id and
    // closing column.
    assert_eq!(stats.points, framed.points, "{what}");
    if let Some(m) = partition_mismatch(&framed.labels, &labels, f.cols) {
        panic!("{what}: {m}");
    }
    assert_eq!(framed.clusters, n, "{what}");
    let mut by_frame = frame_records(&unlimited, f, &framed.labels, framed.clusters, 0);
    for r in &records {
        let k = (0..f.rows * f.cols).find(|&k| labels[k] == r.id).unwrap();
        let fr = &mut by_frame[framed.labels[k] as usize - 1];
        fr.id = r.id;
        fr.closed_col = r.closed_col;
        assert_eq!(*fr, *r, "{what}: record {} against frame mode", r.id);
    }
    // A second frame through the same stream gives the same records.
    let (again, labels_again) = stream_frame(&mut s, f);
    assert_eq!(labels_again, labels, "{what}: second frame");
    assert_eq!(again.len(), records.len());
    assert!(again
        .iter()
        .zip(&records)
        .all(|(a, b)| a.frame == 1 && Record { frame: 0, ..*a } == *b));
}

/// A random frame: points on a grid at 10 m with jitter, dense patches and
/// dropouts, so there are runs, gaps and seams.
fn random_frame(rows: usize, cols: usize, density: u32, spacing: f64, seed: u64) -> Frame {
    let mut rng = seed | 1;
    let mut next = move || {
        rng ^= rng << 13;
        rng ^= rng >> 7;
        rng ^= rng << 17;
        rng
    };
    let mut f = Frame::empty(rows, cols);
    for i in 0..rows {
        for c in 0..cols {
            if next() % 100 < u64::from(density) {
                let j = |v: u64| (v % 2001) as f64 / 1000.0 - 1.0;
                let (a, b, d) = (j(next()), j(next()), j(next()));
                let x = 10.0 + d * spacing * 3.0;
                let y = c as f64 * spacing + a * spacing * 0.4;
                let z = -(i as f64) * spacing + b * spacing * 0.4;
                f.set(i, c, fcc_golden::quantize_point(x, y, z));
            }
        }
    }
    f
}

fn params(rows: usize, cols: usize, fsize: usize) -> FccParams {
    FccParams {
        rows,
        cols,
        fsize,
        ..FccParams::default()
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 160, ..ProptestConfig::default() })]

    #[test]
    fn stream_equals_frame_on_random_frames(
        rows in 1usize..14,
        cols in 1usize..48,
        k in prop::sample::select(vec![3usize, 5, 7, 9, 11, 13, 15]),
        density in 5u32..100,
        th_h in 0.1f64..1.5,
        th_v in 0.1f64..1.5,
        bits in prop::sample::select(vec![8u32, 12, 20]),
        bridge in prop::option::of(0u32..6),
        ring_reach in prop::option::of(0u32..24),
        slopes in prop::option::of((0.0f64..0.08, 0.0f64..0.12)),
        seed in any::<u64>(),
    ) {
        let (th_h_slope, th_v_slope) = slopes.unwrap_or((0.0, 0.0));
        let p = FccParams {
            th_h,
            th_v,
            th_h_slope,
            th_v_slope,
            label_bits: bits,
            bridge,
            ring_reach,
            ..params(rows, cols, k)
        };
        let f = random_frame(rows, cols, density, 0.3, seed);
        let what = format!("seed {seed}, {p:?}");
        // Frame mode with the limits is the reference's reading of §3.
        let framed = cluster(&p, &f, MergeMode::Exact).unwrap();
        let want = reference_labels(&p, &f);
        if let Some(k) = want.iter().zip(&framed.labels).position(|(a, b)| a != b) {
            panic!("{what}: frame mode differs from the reference at row {}, col {}: expected {}, got {}",
                k / cols, k % cols, want[k], framed.labels[k]);
        }
        check_stream(&p, &f, &what);
    }
}

fn scene(rows: usize, cols: usize, seed: u64) -> Frame {
    let cfg = SceneConfig {
        rows,
        cols,
        seed,
        dropout: 0.05,
        ..SceneConfig::default()
    };
    let s = generate(&cfg).unwrap();
    Frame::from_xyz_f32(rows, cols, &s.xyz)
}

#[test]
fn stream_equals_frame_on_scenes_for_every_fsize() {
    for (seed, k) in [
        (1u64, 3usize),
        (2, 5),
        (3, 7),
        (4, 9),
        (5, 11),
        (6, 13),
        (7, 15),
    ] {
        let f = scene(64, 1024, seed);
        for (bridge, ring_reach, slope) in [
            (None, None, 0.0),
            (Some(16), Some(16), 0.0),
            (Some(2), None, 0.0),
            (None, None, 0.03),
        ] {
            let p = FccParams {
                bridge,
                ring_reach,
                th_v_slope: slope,
                th_h_slope: slope / 2.0,
                ..params(64, 1024, k)
            };
            if slope != 0.0 {
                let got = cluster(&p, &f, MergeMode::Exact).unwrap();
                assert_eq!(
                    got.labels,
                    reference_labels(&p, &f),
                    "scene {seed}, K = {k}, slopes"
                );
                let fixed = cluster(&params(64, 1024, k), &f, MergeMode::Exact).unwrap();
                assert!(
                    got.clusters < fixed.clusters,
                    "scene {seed}: slopes join nothing"
                );
            }
            check_stream(
                &p,
                &f,
                &format!("scene seed {seed}, K = {k}, {bridge:?} {ring_reach:?}"),
            );
        }
    }
}

/// A frame from rows of text: `#` a point at (10, j * s, -i * s), `.` empty.
fn grid(rows: &[&str], s: f64) -> Frame {
    let (r, c) = (rows.len(), rows[0].len());
    let mut f = Frame::empty(r, c);
    for (i, row) in rows.iter().enumerate() {
        for (j, ch) in row.chars().enumerate() {
            if ch == '#' {
                f.set(
                    i,
                    j,
                    fcc_golden::quantize_point(10.0, j as f64 * s, -(i as f64) * s),
                );
            }
        }
    }
    f
}

fn records_of(p: &FccParams, f: &Frame) -> Vec<Record> {
    stream_frame(&mut Stream::new(p).unwrap(), f).0
}

#[test]
fn an_object_closes_h_columns_after_its_last_column() {
    // Two blobs far apart; K = 5 (h = 2), th_V 1.5 m on a 1 m grid.
    let f = grid(
        &[
            "...##.........##....",
            "...##.........##....",
            "....................",
        ],
        1.0,
    );
    let p = FccParams {
        fsize: 5,
        th_h: 1.0,
        th_v: 1.5,
        bridge: Some(0),
        ring_reach: Some(0),
        ..params(3, 20, 5)
    };
    let mut s = Stream::new(&p).unwrap();
    let r = stream_frame(&mut s, &f).0;
    // Each blob: two rows' runs, joined when the lower one's first pixel
    // arrives (column 3, then 14); each closes alone, freeing two labels.
    let st = s.stats();
    assert_eq!(
        (
            st.merges,
            st.peak_col_merges,
            st.peak_col_closed,
            st.peak_col_freed
        ),
        (2, 1, 1, 2)
    );
    assert_eq!(r.len(), 2);
    assert_eq!((r[0].first_col, r[0].last_col, r[0].closed_col), (3, 4, 6));
    assert_eq!(
        (r[1].first_col, r[1].last_col, r[1].closed_col),
        (14, 15, 17)
    );
    // Without a bridge limit the rows' latest points hold the first blob
    // until the next point of its rows: column 14.
    let q = FccParams {
        bridge: None,
        ..p.clone()
    };
    let r = records_of(&q, &f);
    assert_eq!((r[0].last_col, r[0].closed_col), (4, 14));
    // With a bridge of 3, until column 4 + 3 + 1.
    let q = FccParams {
        bridge: Some(3),
        ..p
    };
    let r = records_of(&q, &f);
    assert_eq!((r[0].last_col, r[0].closed_col), (4, 8));
}

#[test]
fn the_seam_holds_first_runs_until_the_frame_end() {
    // Row 0's first point (column 1) and last point (column 18) are 1 m
    // apart across the seam only in the y-wrap sense: here they are made
    // equal so the ring check passes.
    let mut f = grid(&[".#####............#.", "...................."], 1.0);
    f.set(0, 18, f.get(0, 1));
    let p = FccParams {
        th_h: 1.0,
        th_v: 1.5,
        bridge: Some(0),
        ..params(2, 20, 3)
    };
    let r = records_of(&p, &f);
    assert_eq!(r.len(), 1, "{r:?}");
    assert!(r[0].seam);
    assert_eq!(r[0].closed_col, 20);
    // The wrapped span: from column 18 (the part before the seam) round to
    // column 5.
    assert_eq!((r[0].first_col, r[0].last_col), (18, 5));
    // A ring reach of 1 keeps column 1 out of the ring check: two records,
    // the first closed after the window (column 5 + h = 6).
    let q = FccParams {
        ring_reach: Some(1),
        ..p.clone()
    };
    let r = records_of(&q, &f);
    assert_eq!(r.len(), 2);
    assert!(!r[0].seam && r[0].closed_col == 6 && r[1].closed_col == 19);
    // A ring reach of 2 holds the first run to the end: the ring joins it.
    let q = FccParams {
        ring_reach: Some(2),
        ..p
    };
    let r = records_of(&q, &f);
    assert_eq!(r.len(), 1);
    assert!(r[0].seam && r[0].closed_col == 20);
}

#[test]
fn labels_are_reused_once_a_cluster_closes() {
    // B = 8: 300 isolated points in one row would overflow frame mode (§8 G),
    // but with a bridge of 0 each closes h columns later and gives its label
    // back.
    let cols = 600;
    let row: String = (0..cols)
        .map(|c| if c % 2 == 0 { '#' } else { '.' })
        .collect();
    // Points 0.4 m apart (0.2 m grid), all within the Q7.8 range.
    let f = grid(&[row.as_str()], 0.2);
    let p = FccParams {
        label_bits: 8,
        th_h: 0.3,
        th_v: 0.1,
        bridge: Some(0),
        ring_reach: Some(0),
        ..params(1, cols, 3)
    };
    let framed = cluster(&p, &f, MergeMode::Exact).unwrap();
    assert!(framed.overflow && framed.unlabelled == 45);
    let mut s = Stream::new(&p).unwrap();
    let (r, _) = stream_frame(&mut s, &f);
    assert_eq!(r.len(), 300);
    assert!(
        !s.stats().overflow && s.stats().peak_labels <= 2 && s.stats().peak_open <= 2,
        "{:?}",
        s.stats()
    );
    check_stream(&p, &f, "alternating row, bridge 0");
    // Unlimited bridge: every point's label is held until the next point of
    // its row arrives, still few at once.
    let q = FccParams { bridge: None, ..p };
    let mut s = Stream::new(&q).unwrap();
    let (r, _) = stream_frame(&mut s, &f);
    assert_eq!(r.len(), 300);
    assert!(
        !s.stats().overflow && s.stats().peak_labels <= 3,
        "{:?}",
        s.stats()
    );
    check_stream(&q, &f, "alternating row, no bridge limit");
}

#[test]
fn overflow_leaves_the_runs_that_start_while_every_label_is_in_use() {
    // Unlimited bridge and ring: nothing closes before the frame end, so the
    // stream overflows like frame mode here, on the same pixels.
    let cols = 600;
    let row: String = (0..cols)
        .map(|c| if c % 2 == 0 { '#' } else { '.' })
        .collect();
    let f = grid(&[row.as_str(), row.as_str()], 0.2);
    let p = FccParams {
        label_bits: 8,
        th_h: 0.3,
        th_v: 0.1,
        ..params(2, cols, 3)
    };
    let mut s = Stream::new(&p).unwrap();
    let (r, labels) = stream_frame(&mut s, &f);
    let st = s.stats();
    // Row 0's first run is held by the seam; every other run is held by its
    // row's next point until it arrives, so at most a few labels are in use.
    assert!(!st.overflow, "{st:?}");
    assert_eq!(r.len(), 600);
    assert_eq!(labels.iter().filter(|&&l| l != 0).count(), 600);
    // Columns of 255 points each (B = 8) on one column: overflow inside a
    // column, where nothing can close.
    let rows = 300;
    let f = grid(&vec!["#."; rows], 0.2);
    let p = FccParams {
        label_bits: 8,
        th_h: 0.1,
        th_v: 0.1,
        ..params(rows, 2, 3)
    };
    let mut s = Stream::new(&p).unwrap();
    let (r, labels) = stream_frame(&mut s, &f);
    let st = s.stats();
    assert!(
        st.overflow && st.unlabelled == 45 && st.peak_labels == 255,
        "{st:?}"
    );
    assert_eq!(r.len(), 255);
    assert_eq!(
        s.frame_end(),
        Some(FrameEnd {
            records: 255,
            overflow: true,
            frame_error: false
        })
    );
    // The unlabelled pixels are the last 45 rows of column 0.
    assert!((0..rows).all(|i| (labels[i * 2] == 0) == (i >= 255)));
}

#[test]
fn adaptive_thresholds_round_down_and_take_the_nearer_point() {
    use fcc_golden::{point_threshold, Thresholds};
    // A = round(0.1 * 2^16) = 6554, S = A^2 >> 8 = 167,792; a point at
    // 20 m (5120 units) is 20 whole metres, rc2 = 400, own threshold
    // (167,792 * 400) >> 8 = 262,175 units ((2 m)^2 is 262,144: the slope's
    // rounding adds 0.1 mm).
    let p = FccParams {
        th_v_slope: 0.1,
        ..FccParams::default()
    };
    let s = p.th_v_slope_sq();
    assert_eq!(s, (6554 * 6554) >> 8);
    assert_eq!(point_threshold(s, [5120, 0, 0]), ((s * 400) >> 8) as i64);
    assert_eq!(point_threshold(s, [5120, 0, 0]), 262_175);
    // Whole metres round half up and stop at 127: 20.5 m is 21, -127.6 m
    // is 127 (not 128).
    assert_eq!(fcc_golden::coarse_metres(5248), 21);
    assert_eq!(fcc_golden::coarse_metres(5247), 20);
    assert_eq!(fcc_golden::coarse_metres(-32668), 127);
    assert_eq!(
        fcc_golden::coarse_range2([i16::MIN, i16::MAX, -32767]),
        3 * 127 * 127
    );
    let th = Thresholds::new(&p);
    // At 20 m the pair threshold is about 2 m: points 1.9 m apart join,
    // 2.1 m apart do not; at 5 m (0.5 m own) tV = 1 m wins.
    let q = |y: f64, x: f64| fcc_golden::quantize_point(x, y, 0.0).unwrap();
    assert!(th.joins(q(0.0, 20.0), q(1.9, 20.0)));
    assert!(!th.joins(q(0.0, 20.0), q(2.1, 20.0)));
    assert!(th.joins(q(0.0, 5.0), q(0.99, 5.0)) && !th.joins(q(0.0, 5.0), q(1.0, 5.0)));
    // The nearer point sets it: 10 m and 30 m, 1.5 m apart: own 1 m at 10 m.
    assert!(!th.joins(q(0.0, 10.0), [7680, 384, 0]));
    // Slopes 0: the fixed contract.
    let fixed = Thresholds::new(&FccParams::default());
    assert!(!fixed.joins(q(0.0, 20.0), q(1.9, 20.0)));
}

#[test]
fn stream_errors_are_clear() {
    let p = params(2, 3, 3);
    let mut s = Stream::new(&p).unwrap();
    let e = s.push_column(&[None]).unwrap_err();
    assert_eq!(
        e.to_string(),
        "a column holds 1 pixels, the frame has 2 rows"
    );
    assert_eq!(
        s.finish().unwrap_err().to_string(),
        "the frame has 0 of its 3 columns"
    );
    for _ in 0..3 {
        s.push_column(&[None, None]).unwrap();
    }
    assert!(matches!(
        s.push_column(&[None, None]),
        Err(GoldenError::TooManyColumns { cols: 3 })
    ));
    let mut labels = Vec::new();
    assert!(s.labels_into(&mut labels).is_err());
    assert!(s.finish().unwrap().is_empty());
    s.labels_into(&mut labels).unwrap();
    assert_eq!(labels, vec![0; 6]);
    // The next push starts the next frame.
    s.push_column(&[None, None]).unwrap();
    assert_eq!(s.columns_taken(), 1);
    let bad = FccParams { fsize: 4, ..p };
    assert!(Stream::new(&bad).is_err());
}

#[test]
fn the_column_window_is_k_times_h_positions_inside_the_frame() {
    // K = 5 (h = 2) far from the edges: 2h rows in h columns, h rows above.
    let w: Vec<(usize, usize)> = fcc_golden::column_window(20, 2, 10, 10).collect();
    assert_eq!(w.len(), 5 * 2);
    assert_eq!(w[0], (8, 8));
    assert!(w.contains(&(12, 9)) && w.contains(&(9, 10)) && w.contains(&(8, 10)));
    assert!(!w
        .iter()
        .any(|&(r, c)| r == 10 || (c == 10 && r > 10) || c < 8));
    // At the frame's top-left corner: only rows below in earlier columns,
    // none before column 0.
    let w: Vec<(usize, usize)> = fcc_golden::column_window(20, 2, 0, 1).collect();
    assert_eq!(w, [(1, 0), (2, 0)]);
    assert_eq!(fcc_golden::column_window(1, 3, 0, 5).count(), 0);
}

/// The open limit (spec §9.1) read directly on the finished stream. The
/// clusters open after column `c - 1` are the components of the graph of
/// the labelled pixels in columns `0 ..= c - 1` (run edges: the stream's
/// runs; window pairs of spec §4 within the thresholds; no ring check before
/// the frame end), built here column by column with a union-find over runs,
/// less those whose record closed before `c`. A run starting at column `c`
/// (pass 1's runs, labels plentiful, in column order) is labelled exactly
/// when those plus the runs labelled so far in column `c` are fewer than
/// `N_o`; a refused run's pixels are all unlabelled, a labelled run's none.
/// Returns the runs refused.
fn check_open_limit(p: &FccParams, f: &Frame, what: &str) -> u32 {
    let s_max = p.open_limit.expect("an open limit");
    let mut s = Stream::new(p).unwrap();
    let (records, labels) = stream_frame(&mut s, f);
    let mut stream_runs = Vec::new();
    s.runs_into(&mut stream_runs).unwrap();
    let (rows, cols, h) = (f.rows, f.cols, p.half());
    let unlimited = FccParams {
        open_limit: None,
        ..p.clone()
    };
    let runs = fcc_golden::pass1(&unlimited, f);
    assert!(!runs.overflow, "{what}: pass 1 needs more label bits");
    let th = fcc_golden::Thresholds::new(p);
    let mut parent: Vec<u32> = vec![0; stream_runs.iter().max().map_or(0, |&m| m as usize + 1)];
    for (k, v) in parent.iter_mut().enumerate() {
        *v = k as u32;
    }
    fn find(parent: &mut [u32], mut x: u32) -> u32 {
        while parent[x as usize] != x {
            parent[x as usize] = parent[parent[x as usize] as usize];
            x = parent[x as usize];
        }
        x
    }
    let mut components = 0u32;
    let mut closed = 0u32;
    let mut seen_run = std::collections::HashMap::new();
    let mut refused = 0;
    for c in 0..cols {
        if c > 0 {
            closed += records
                .iter()
                .filter(|r| r.closed_col == c as u32 - 1)
                .count() as u32;
        }
        let open_before = components - closed;
        let mut started = 0;
        for i in 0..rows {
            let k = i * cols + c;
            let run = runs.labels[k];
            if run == 0 {
                continue;
            }
            let want = *seen_run.entry(run).or_insert_with(|| {
                let ok = open_before + started < s_max;
                started += ok as u32;
                refused += !ok as u32;
                ok
            });
            assert_eq!(
                labels[k] != 0,
                want,
                "{what}: row {i}, col {c}: {open_before} clusters open after column {}, {started} runs labelled in column {c}, N_o = {s_max}: the run should {}be labelled",
                c as i64 - 1,
                if want { "" } else { "not " }
            );
        }
        // Column c joins the graph: its new runs, then its window pairs.
        for i in 0..rows {
            let k = i * cols + c;
            let a = stream_runs[k];
            if a == 0 {
                continue;
            }
            if c == 0 || !(0..c).any(|j| stream_runs[i * cols + j] == a) {
                components += 1;
            }
            let pa = f.get(i, c).unwrap();
            for (ii, cc) in fcc_golden::column_window(rows, h, i, c) {
                let b = stream_runs[ii * cols + cc];
                if b == 0 || !th.joins(pa, f.get(ii, cc).unwrap()) {
                    continue;
                }
                let (ra, rb) = (find(&mut parent, a), find(&mut parent, b));
                if ra != rb {
                    parent[ra as usize] = rb;
                    components -= 1;
                }
            }
        }
    }
    let stats = s.stats();
    assert_eq!(stats.open_refused, refused, "{what}: {stats:?}");
    assert!(!stats.overflow, "{what}: labels ran out: {stats:?}");
    assert!(
        stats.peak_counted <= s_max && stats.peak_open <= stats.peak_counted,
        "{what}: {stats:?}"
    );
    check_stream(p, f, what);
    refused
}

/// An open limit at the most clusters counted open with none changes
/// nothing; one below refuses a run.
fn check_open_limit_edge(p: &FccParams, f: &Frame, what: &str) {
    let mut s = Stream::new(p).unwrap();
    let (records, labels) = stream_frame(&mut s, f);
    let peak = s.stats().peak_counted;
    assert!(s.stats().peak_open <= peak, "{what}");
    if peak == 0 {
        return;
    }
    let at = FccParams {
        open_limit: Some(peak),
        ..p.clone()
    };
    let mut s = Stream::new(&at).unwrap();
    assert_eq!(
        stream_frame(&mut s, f),
        (records, labels),
        "{what}: N_o = {peak}"
    );
    assert_eq!(check_open_limit(&at, f, what), 0);
    if peak > 1 {
        let below = FccParams {
            open_limit: Some(peak - 1),
            ..p.clone()
        };
        assert!(
            check_open_limit(&below, f, what) > 0,
            "{what}: N_o = {}",
            peak - 1
        );
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 96, ..ProptestConfig::default() })]

    #[test]
    fn the_open_limit_counts_as_the_spec_says(
        rows in 1usize..14,
        cols in 1usize..48,
        k in prop::sample::select(vec![3usize, 5, 7, 11, 15]),
        density in 5u32..100,
        th_h in 0.1f64..1.5,
        th_v in 0.1f64..1.5,
        bridge in prop::option::of(0u32..6),
        ring_reach in prop::option::of(0u32..24),
        limit in 1u32..12,
        seed in any::<u64>(),
    ) {
        let p = FccParams {
            th_h,
            th_v,
            label_bits: 20,
            bridge,
            ring_reach,
            open_limit: Some(limit),
            ..params(rows, cols, k)
        };
        let f = random_frame(rows, cols, density, 0.3, seed);
        let what = format!("seed {seed}, {p:?}");
        check_open_limit(&p, &f, &what);
        check_open_limit_edge(&FccParams { open_limit: None, ..p }, &f, &what);
    }
}

#[test]
fn the_open_limit_on_scenes() {
    for (seed, k) in [(11u64, 3usize), (12, 7), (13, 11)] {
        let f = scene(64, 1024, seed);
        for bridge in [None, Some(4)] {
            let p = FccParams {
                label_bits: 20,
                bridge,
                ..params(64, 1024, k)
            };
            let what = format!("scene seed {seed}, K = {k}, bridge {bridge:?}");
            check_open_limit_edge(&p, &f, &what);
            for limit in [1, 8] {
                let q = FccParams {
                    open_limit: Some(limit),
                    ..p.clone()
                };
                assert!(check_open_limit(&q, &f, &what) > 0, "{what}: N_o = {limit}");
            }
        }
    }
}

#[test]
fn the_open_limit_refuses_the_run_past_it_and_frees_with_the_column() {
    // Three separate objects in column 0 (rows 0, 3, 6), each closed at
    // column 0 + h = 1 (K = 3, bridge 0); N_o = 2 refuses the third, then
    // column 2's three runs count the clusters open after column 1 (none).
    let f = grid(&["#.#", "...", "...", "#.#", "...", "...", "#.#"], 1.0);
    let p = FccParams {
        th_h: 0.5,
        th_v: 0.5,
        bridge: Some(0),
        ring_reach: Some(0),
        open_limit: Some(2),
        ..params(7, 3, 3)
    };
    let mut s = Stream::new(&p).unwrap();
    let (r, labels) = stream_frame(&mut s, &f);
    assert_eq!(labels[6 * 3], 0, "row 6, column 0 refused");
    assert!(labels[0] != 0 && labels[3 * 3] != 0);
    assert_eq!(r.len(), 4, "{r:?}");
    assert_eq!(
        r.iter()
            .map(|r| (r.first_col, r.first_row))
            .collect::<Vec<_>>(),
        [(0, 0), (0, 3), (2, 0), (2, 3)]
    );
    let st = s.stats();
    assert_eq!((st.open_refused, st.unlabelled, st.peak_counted), (2, 2, 2));
    assert_eq!(
        (
            st.merges,
            st.peak_col_merges,
            st.peak_col_closed,
            st.peak_col_freed
        ),
        (0, 0, 2, 2)
    );
    assert!(!st.overflow, "labels did not run out");
    // Frame mode refuses an open limit, naming it.
    let e = cluster(&p, &f, MergeMode::Exact).unwrap_err();
    assert_eq!(e, GoldenError::StreamOnly(2));
    assert!(e.to_string().contains("open_limit"), "{e}");
    check_open_limit(&p, &f, "three objects a column, N_o = 2");
}
