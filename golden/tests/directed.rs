//! Hand-worked frames for each pass and for the whole model (spec examples).

use fcc_golden::{
    cluster, pass1, pass1_released, pass2, reference::reference_labels, renumber, runs_needed,
    split_components, Frame, GoldenError, JoinSink, MergeMode, PaperMerge,
};
use fcc_params::FccParams;

/// A frame from ASCII art: `#` is a point on a vertical grid at 10 m range,
/// `spacing` metres apart in both directions; `.` is empty.
fn grid(art: &str, spacing: f64) -> Frame {
    let lines: Vec<&str> = art.split_whitespace().collect();
    let (rows, cols) = (lines.len(), lines[0].len());
    let mut xyz = Vec::new();
    for (r, line) in lines.iter().enumerate() {
        assert_eq!(line.len(), cols);
        for (c, ch) in line.chars().enumerate() {
            if ch == '#' {
                xyz.extend([10.0, c as f64 * spacing, -(r as f64) * spacing]);
            } else {
                xyz.extend([f64::NAN; 3]);
            }
        }
    }
    Frame::from_xyz_f64(rows, cols, &xyz)
}

fn params_for(f: &Frame, fsize: usize, th_h: f64, th_v: f64) -> FccParams {
    FccParams {
        rows: f.rows,
        cols: f.cols,
        fsize,
        th_h,
        th_v,
        ..FccParams::default()
    }
}

fn run(f: &Frame, p: &FccParams) -> Vec<u32> {
    let got = cluster(p, f, MergeMode::Exact).unwrap();
    assert_eq!(got.labels, reference_labels(p, f), "model != reference");
    got.labels
}

#[test]
fn pass1_empty_pixels_do_not_break_a_run() {
    let f = grid("#..#.#", 0.1);
    // Consecutive valid pixels are 0.3 m and 0.2 m apart.
    let p = params_for(&f, 3, 0.3, 1.0);
    let p1 = pass1(&p, &f);
    assert_eq!(p1.labels, vec![1, 0, 0, 1, 0, 1]);
    assert_eq!(p1.provisional, 1);
    let p = params_for(&f, 3, 0.25, 1.0);
    assert_eq!(pass1(&p, &f).labels, vec![1, 0, 0, 2, 0, 2]);
}

#[test]
fn pass1_threshold_is_inclusive() {
    // Exactly 0.5 m apart (128 Q7.8 units): d2 == tH^2 continues the run.
    let f = grid("##", 0.5);
    assert_eq!(pass1(&params_for(&f, 3, 0.5, 1.0), &f).labels, vec![1, 1]);
    assert_eq!(pass1(&params_for(&f, 3, 0.49, 1.0), &f).labels, vec![1, 2]);
}

#[test]
fn pass1_labels_in_raster_order() {
    let f = grid("#.# .#.", 1.0);
    let p1 = pass1(&params_for(&f, 3, 0.5, 0.5), &f);
    assert_eq!(p1.labels, vec![1, 0, 2, 0, 3, 0]);
    assert_eq!(p1.provisional, 3);
}

#[test]
fn ring_check_joins_first_and_last_runs() {
    // A ring of points on a circle of radius 2 m: first and last are neighbours.
    let cols = 16;
    let mut xyz = Vec::new();
    for c in 0..cols {
        let a = std::f64::consts::TAU * c as f64 / cols as f64;
        if c == 8 {
            xyz.extend([f64::NAN; 3]); // a gap splits the ring into two runs
        } else {
            xyz.extend([2.0 * a.cos(), 2.0 * a.sin(), 0.0]);
        }
    }
    let f = Frame::from_xyz_f64(1, cols, &xyz);
    // Neighbours are 0.78 m apart; across the gap 1.53 m.
    let p = params_for(&f, 3, 0.8, 1.0);
    let p1 = pass1(&p, &f);
    assert_eq!(
        p1.labels,
        vec![1, 1, 1, 1, 1, 1, 1, 1, 0, 2, 2, 2, 2, 2, 2, 2]
    );
    assert_eq!(p1.ring_joins, vec![(1, 2)]);
    assert_eq!(
        run(&f, &p),
        vec![1, 1, 1, 1, 1, 1, 1, 1, 0, 1, 1, 1, 1, 1, 1, 1]
    );
}

#[test]
fn ring_check_needs_two_runs_and_close_ends() {
    let f = grid("#.....#", 0.1);
    let p = params_for(&f, 3, 0.2, 1.0);
    let p1 = pass1(&p, &f);
    assert!(p1.ring_joins.is_empty(), "ends are 0.6 m apart");
    let f = grid("..#....", 0.1);
    assert!(pass1(&p, &f).ring_joins.is_empty(), "a single point");
}

#[test]
fn label_overflow_leaves_pixels_unlabelled() {
    // 300 isolated points in one row with 8-bit labels: 255 labels, 45 unlabelled.
    let art: String = "#.".repeat(300);
    let f = grid(&art, 0.2);
    let p = FccParams {
        label_bits: 8,
        ..params_for(&f, 3, 0.3, 0.3)
    };
    let got = cluster(&p, &f, MergeMode::Exact).unwrap();
    assert!(got.overflow);
    assert_eq!(got.unlabelled, 45);
    assert_eq!(got.provisional, 255);
    assert_eq!(got.clusters, 255);
    assert_eq!(got.labels[2 * 254], 255);
    assert_eq!(got.labels[2 * 255], 0);
    assert_eq!(got.labels, reference_labels(&p, &f));
}

#[test]
fn label_overflow_says_how_many_labels_and_bits_would_fit() {
    // The 300 runs above need 300 labels: 9 bits.
    let f = grid(&"#.".repeat(300), 0.2);
    let p = FccParams {
        label_bits: 8,
        ..params_for(&f, 3, 0.3, 0.3)
    };
    assert_eq!(runs_needed(&p, &f), 300);
    assert_eq!(FccParams::label_bits_for(runs_needed(&p, &f)), 9);
    // Without overflow it is exactly what pass 1 allocates.
    let wide = FccParams {
        label_bits: 9,
        ..p.clone()
    };
    assert_eq!(
        runs_needed(&wide, &f),
        u64::from(pass1(&wide, &f).provisional)
    );
    // Empty pixels do not break a run (points 0.05 m apart per column).
    let f = grid("##..##.#", 0.05);
    assert_eq!(runs_needed(&params_for(&f, 3, 0.3, 0.3), &f), 1);
}

#[test]
fn overflowed_runs_take_part_in_no_join() {
    // Row 0 uses the only label; row 1's point sits under it but is unlabelled.
    let f = grid("#. #.", 0.1);
    let p = FccParams {
        label_bits: 8,
        ..params_for(&f, 3, 0.05, 1.0)
    };
    let mut f2 = Frame::empty(2, 300);
    // 255 isolated runs in row 0, then one point right under the last one.
    for c in 0..255 {
        f2.set(0, c, Some([2560, (c as i16) * 100, 0]));
    }
    f2.set(1, 254, Some([2560, 25400, -10]));
    let p2 = FccParams {
        rows: 2,
        cols: 300,
        ..p.clone()
    };
    let got = cluster(&p2, &f2, MergeMode::Exact).unwrap();
    assert!(got.overflow);
    assert_eq!(got.labels[300 + 254], 0);
    assert_eq!(got.unlabelled, 1);
    assert_eq!(got.labels, reference_labels(&p2, &f2));
    assert!(!cluster(&p, &f, MergeMode::Exact).unwrap().overflow);
}

#[test]
fn pass2_threshold_is_strict() {
    // Vertical neighbours exactly 1.0 m apart do not join when th_V = 1.0.
    let f = grid("# #", 1.0);
    assert_eq!(run(&f, &params_for(&f, 3, 0.5, 1.0)), vec![1, 2]);
    assert_eq!(run(&f, &params_for(&f, 3, 0.5, 1.01)), vec![1, 1]);
}

#[test]
fn pass2_window_reaches_h_rows_up_and_h_columns_across() {
    // The top-left point is 2 rows up and 2 columns left of the bottom-right one.
    let f = grid("#.... ..... ..#..", 0.1);
    let th_v = 0.5; // larger than the 0.28 m distance
    assert_eq!(
        run(&f, &params_for(&f, 3, 0.05, th_v)),
        vec![1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 0, 0]
    );
    assert_eq!(
        run(&f, &params_for(&f, 5, 0.05, th_v)),
        vec![1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0]
    );
}

#[test]
fn pass2_does_not_wrap_at_the_image_edges() {
    // Same 3-D point at the left and right edges, one row apart: no join.
    let mut f = Frame::empty(2, 8);
    f.set(0, 7, Some([2560, 0, 0]));
    f.set(1, 0, Some([2560, 0, 0]));
    let p = params_for(&f, 3, 0.01, 1.0);
    assert_eq!(
        run(&f, &p),
        vec![0, 0, 0, 0, 0, 0, 0, 1, 2, 0, 0, 0, 0, 0, 0, 0]
    );
}

#[test]
fn clusters_numbered_by_first_pixel_in_raster_order() {
    // A U-shape: the right arm starts first in raster order only on row 0.
    let f = grid("..#.# ..#.# ..###", 1.0);
    let p = params_for(&f, 3, 1.0, 1.5);
    let l = run(&f, &p);
    assert_eq!(l, vec![0, 0, 1, 0, 1, 0, 0, 1, 0, 1, 0, 0, 1, 1, 1]);
    let f = grid("#..#. #..#. .....", 1.0);
    assert_eq!(
        run(&f, &params_for(&f, 3, 0.5, 1.5)),
        vec![1, 0, 0, 2, 0, 1, 0, 0, 2, 0, 0, 0, 0, 0, 0]
    );
}

#[test]
fn checkerboard_joins_diagonally_only() {
    let f = grid("#.#.#. .#.#.# #.#.#.", 1.0);
    // Diagonal neighbours are 1.41 m apart; horizontal valid neighbours 2 m.
    assert_eq!(run(&f, &params_for(&f, 3, 1.0, 1.5)).iter().max(), Some(&1));
    let l = run(&f, &params_for(&f, 3, 1.0, 1.4));
    assert_eq!(l.iter().filter(|&&x| x > 0).count(), 9);
    assert_eq!(l.iter().max(), Some(&9));
}

#[test]
fn paper_merge_overwrite_splits_a_component() {
    // Worked example of spec §6: run 3 is first linked to run 1 (T[3] = 1),
    // then the flush of run 8 overwrites T[3] = T[2] = 2, cutting runs 1, 4
    // and 7 off from the rest. Exact merging keeps one component.
    let f = grid(
        ".......#
         ##...#.#
         .#..#.##
         ..##....",
        1.0,
    );
    let p = params_for(&f, 3, 1.0, 1.5);
    assert_eq!(pass1(&p, &f).provisional, 8);
    let exact = cluster(&p, &f, MergeMode::Exact).unwrap();
    let paper = cluster(&p, &f, MergeMode::Paper).unwrap();
    assert_eq!(exact.clusters, 1);
    assert_eq!(exact.labels, reference_labels(&p, &f));
    assert_eq!(paper.clusters, 2);
    assert_eq!(
        paper.labels,
        vec![
            0, 0, 0, 0, 0, 0, 0, 1, //
            2, 2, 0, 0, 0, 2, 0, 1, //
            0, 2, 0, 0, 2, 0, 1, 1, //
            0, 0, 2, 2, 0, 0, 0, 0,
        ]
    );
    assert_eq!(split_components(&exact.labels, &paper.labels), 1);
    assert_eq!(split_components(&exact.labels, &exact.labels), 0);
}

/// A frame from ASCII art on a vertical cylinder: `cols` columns around a
/// circle whose neighbouring columns are 1 m apart, also across the seam
/// (column C-1 to column 0); rows 1 m apart.
fn cylinder(art: &str) -> Frame {
    let lines: Vec<&str> = art.split_whitespace().collect();
    let (rows, cols) = (lines.len(), lines[0].len());
    let radius = 1.0 / (2.0 * (std::f64::consts::PI / cols as f64).sin());
    let mut xyz = Vec::new();
    for (r, line) in lines.iter().enumerate() {
        assert_eq!(line.len(), cols);
        for (c, ch) in line.chars().enumerate() {
            let a = std::f64::consts::TAU * c as f64 / cols as f64;
            if ch == '#' {
                xyz.extend([radius * a.cos(), radius * a.sin(), -(r as f64)]);
            } else {
                xyz.extend([f64::NAN; 3]);
            }
        }
    }
    Frame::from_xyz_f64(rows, cols, &xyz)
}

#[test]
fn paper_ring_relabels_the_seam_run_and_keeps_the_object_whole() {
    // Spec §8, example H.
    let f = cylinder(
        ".#....#.
         #..#..##
         #.......",
    );
    let p = params_for(&f, 3, 1.1, 1.5);
    let p1 = pass1(&p, &f);
    assert_eq!(
        p1.labels,
        vec![
            0, 1, 0, 0, 0, 0, 2, 0, //
            3, 0, 0, 4, 0, 0, 5, 5, //
            6, 0, 0, 0, 0, 0, 0, 0,
        ]
    );
    assert_eq!(p1.ring_joins, vec![(3, 5)]);
    // The released code: run 5 takes label 3 and label 5 goes to row 2.
    let released = pass1_released(&p, &f);
    assert_eq!(
        released.labels,
        vec![
            0, 1, 0, 0, 0, 0, 2, 0, //
            3, 0, 0, 4, 0, 0, 3, 3, //
            5, 0, 0, 0, 0, 0, 0, 0,
        ]
    );
    assert!(released.ring_joins.is_empty());
    assert_eq!(released.provisional, 5);

    let exact = cluster(&p, &f, MergeMode::Exact).unwrap();
    let paper = cluster(&p, &f, MergeMode::Paper).unwrap();
    let whole = vec![
        0, 1, 0, 0, 0, 0, 1, 0, //
        1, 0, 0, 2, 0, 0, 1, 1, //
        1, 0, 0, 0, 0, 0, 0, 0,
    ];
    assert_eq!(exact.labels, whole);
    assert_eq!(exact.labels, reference_labels(&p, &f));
    assert_eq!(paper.labels, whole, "paper splits the seam object");
    assert_eq!(paper.provisional, 5);

    // The paper's text: the ring join is a table write before pass 2, which
    // row 1's last flush overwrites (T[3] = 2), cutting run 1 off.
    let mut text = PaperMerge::new(p1.provisional);
    for &(a, b) in &p1.ring_joins {
        text.join(a, b);
        text.row_end();
    }
    pass2(&p, &f, &p1, &mut text);
    let (as_text, clusters) = renumber(&p1.labels, &text.representatives());
    assert_eq!(clusters, 3);
    assert_eq!(
        as_text,
        vec![
            0, 1, 0, 0, 0, 0, 2, 0, //
            2, 0, 0, 3, 0, 0, 2, 2, //
            2, 0, 0, 0, 0, 0, 0, 0,
        ]
    );
    assert_eq!(split_components(&exact.labels, &as_text), 1);
}

#[test]
fn paper_ring_on_a_row_of_one_run_gives_no_label_back() {
    // Row 0 is one run all the way round; its ends are neighbours, so the
    // ring check passes on a single run. The released code would give its
    // label back and row 1's point would reuse label 1; here it gets 2.
    let f = cylinder(
        "########
         ...#....",
    );
    let p = params_for(&f, 3, 1.1, 0.5);
    let released = pass1_released(&p, &f);
    assert_eq!(
        released.labels,
        vec![1, 1, 1, 1, 1, 1, 1, 1, 0, 0, 0, 2, 0, 0, 0, 0]
    );
    assert_eq!(released.provisional, 2);
    let paper = cluster(&p, &f, MergeMode::Paper).unwrap();
    assert_eq!(paper.clusters, 2, "th_V = 0.5 m: the rows stay apart");
    assert_eq!(
        paper.labels,
        cluster(&p, &f, MergeMode::Exact).unwrap().labels
    );
}

#[test]
fn paper_empty_pixels_are_not_points_at_the_origin() {
    // Two points 0.3 m from the sensor, 0.6 m apart, an empty pixel between
    // them: fed as a zero (the released code) the empty pixel would chain
    // them into one run at th_H = 0.5. Empty pixels are skipped here.
    let xyz = [0.3, 0.0, 0.0, f64::NAN, 0.0, 0.0, -0.3, 0.0, 0.0];
    let f = Frame::from_xyz_f64(1, 3, &xyz);
    let p = params_for(&f, 3, 0.5, 1.0);
    let paper = cluster(&p, &f, MergeMode::Paper).unwrap();
    assert_eq!(paper.labels, vec![1, 0, 2]);
    assert_eq!(
        paper.labels,
        cluster(&p, &f, MergeMode::Exact).unwrap().labels
    );
}

#[test]
fn shape_mismatch_is_an_error() {
    let f = Frame::empty(2, 3);
    let p = FccParams {
        rows: 3,
        cols: 3,
        ..FccParams::default()
    };
    let e = cluster(&p, &f, MergeMode::Exact).unwrap_err();
    assert_eq!(e.to_string(), "frame is 2 x 3 but the parameters say 3 x 3");
    assert!(matches!(e, GoldenError::Shape { .. }));
}

#[test]
fn invalid_params_are_an_error() {
    let f = Frame::empty(2, 3);
    let p = FccParams {
        rows: 2,
        cols: 3,
        fsize: 4,
        ..FccParams::default()
    };
    let e = cluster(&p, &f, MergeMode::Exact).unwrap_err();
    assert!(e.to_string().starts_with("fsize = 4"), "{e}");
}

#[test]
fn empty_frame_has_no_clusters() {
    let f = Frame::empty(4, 5);
    let got = cluster(&params_for(&f, 3, 0.5, 1.0), &f, MergeMode::Exact).unwrap();
    assert_eq!(got.clusters, 0);
    assert_eq!(got.labels, vec![0; 20]);
    assert!(!got.overflow);
}
