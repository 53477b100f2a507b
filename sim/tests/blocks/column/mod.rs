//! What the column core's block benches share: the build they generate,
//! the run parameters of their frames, seeded frames of objects, and each
//! pixel as the column core's blocks see it, worked out from the golden
//! stream's runs (spec §3's runs and ring checks, §9.2's held runs, §4's
//! pairs as window entries). Each bench uses part of it.
#![allow(dead_code)]

pub mod forest;
pub mod pack_io;
pub mod rep_io;

use fcc_golden::{Frame, Point, Stream, Thresholds};
use fcc_params::FccParams;
use rand::Rng;
use rand_chacha::ChaCha8Rng;

/// One pixel as the column core's blocks get it, runs named by golden run
/// number (0: none).
#[derive(Debug, Clone, Default)]
pub struct Pix {
    pub row: usize,
    pub col: usize,
    pub ok: bool,
    pub run: u32,
    pub start: bool,
    pub ring_first: bool,
    /// The ring check's runs (first, last), at the last column.
    pub ring: Option<(u32, u32)>,
    /// The row's held run before and after (changed only).
    pub hold: Option<(u32, u32)>,
    /// Per window entry: a hit, and the run it names.
    pub hits: Vec<(usize, u32)>,
}

/// Window entry `e`'s offset (rows, columns) from the pixel, in
/// `FccColWindow`'s order: line `r` (column `c - h + r`) position `p` (rows
/// `i - h ..= i + h` but `i`), then row `i - m` of the pixel's column.
pub fn entry_offset(k: usize, e: usize) -> (isize, isize) {
    let h = (k - 1) / 2;
    if e < 2 * h * h {
        let (r, p) = (e / (k - 1), e % (k - 1));
        let n = if p < h { p } else { p + 1 };
        (n as isize - h as isize, r as isize - h as isize)
    } else {
        (-((e - 2 * h * h + 1) as isize), 0)
    }
}

/// The frame's pixels for the block, from the golden runs: spec §3's runs
/// and ring check, §9.2's held runs, §4's pairs as window entries.
pub fn pixels(p: &FccParams, f: &Frame, runs: &[u32]) -> Vec<Pix> {
    let (rows, cols, k) = (p.rows, p.cols, p.fsize);
    let th = Thresholds::new(p);
    let mut latest: Vec<Option<(usize, Point, u32)>> = vec![None; rows];
    let mut first: Vec<Option<(usize, Point, u32)>> = vec![None; rows];
    let mut held = vec![0u32; rows];
    let mut out = Vec::with_capacity(rows * cols);
    for c in 0..cols {
        for r in 0..rows {
            let run = runs[r * cols + c];
            let mut px = Pix {
                row: r,
                col: c,
                ..Pix::default()
            };
            if let Some(q) = f.get(r, c) {
                px.ok = true;
                px.run = run;
                px.start = run != 0 && latest[r].is_none_or(|(_, _, lr)| lr != run);
                px.ring_first = first[r].is_none() && run != 0 && p.ring_reaches(c, cols - 1);
                if run != 0 {
                    for e in 0..k * ((k - 1) / 2) {
                        let (dr, dc) = entry_offset(k, e);
                        let (ii, cc) = (r as isize + dr, c as isize + dc);
                        if ii < 0 || ii >= rows as isize || cc < 0 {
                            continue;
                        }
                        let (ii, cc) = (ii as usize, cc as usize);
                        let other = runs[ii * cols + cc];
                        if other != 0 && f.get(ii, cc).is_some_and(|o| th.joins(q, o)) {
                            px.hits.push((e, other));
                        }
                    }
                }
                latest[r] = Some((c, q, run));
                if first[r].is_none() {
                    first[r] = Some((c, q, run));
                }
            }
            if c == cols - 1 {
                if let (Some((fc, fp, fr)), Some((lc, lp, lr))) = (first[r], latest[r]) {
                    if fr != 0
                        && lr != 0
                        && fr != lr
                        && p.ring_reaches(fc, lc)
                        && th.continues(fp, lp)
                    {
                        px.ring = Some((fr, lr));
                    }
                }
            }
            let want = match latest[r] {
                Some((lc, _, lr)) if lr != 0 => {
                    let bridge = c != cols - 1 && p.bridges(c - lc);
                    let ring =
                        first[r].is_some_and(|(fc, _, fr)| fr != 0 && p.ring_reaches(fc, lc));
                    if bridge || ring {
                        lr
                    } else {
                        0
                    }
                }
                _ => 0,
            };
            if want != held[r] {
                px.hold = Some((held[r], want));
                held[r] = want;
            }
            out.push(px);
        }
    }
    out
}

/// The golden stream over a frame, as the column core's benches check
/// against it: the frame's runs (by pixel, row-major) and, per column, the
/// clusters closed at it.
pub struct Closing {
    /// Each pixel's golden run (0: none), row-major.
    pub runs: Vec<u32>,
    /// Per column (the frame end's at `cols`), the runs of each cluster
    /// closed there, each cluster's sorted and once each.
    pub at: Vec<Vec<Vec<u32>>>,
}

/// Stream `f` through the golden `Stream` column by column (spec §9) and
/// collect its runs and, by column, its closed clusters' runs.
pub fn closing(p: &FccParams, f: &Frame) -> Closing {
    let (rows, cols) = (p.rows, p.cols);
    let mut stream = Stream::new(p).expect("the golden stream");
    let mut column = vec![None; rows];
    let mut pixels: Vec<Vec<Vec<u32>>> = vec![Vec::new(); cols + 1];
    for (c, closed) in pixels.iter_mut().take(cols).enumerate() {
        for (r, v) in column.iter_mut().enumerate() {
            *v = f.get(r, c);
        }
        let n = stream.push_column(&column).expect("a column").len();
        closed.extend((0..n).map(|k| stream.pixels_of(k).to_vec()));
    }
    let n = stream.finish().expect("the frame end").len();
    pixels[cols].extend((0..n).map(|k| stream.pixels_of(k).to_vec()));
    let mut runs = Vec::new();
    stream.runs_into(&mut runs).expect("runs");
    let at = pixels
        .iter()
        .map(|recs| {
            recs.iter()
                .map(|px| {
                    let mut rs: Vec<u32> = px.iter().map(|&k| runs[k as usize]).collect();
                    rs.sort_unstable();
                    rs.dedup();
                    rs
                })
                .collect()
        })
        .collect();
    Closing { runs, at }
}

/// A seeded frame of objects whose rows meet and part: a range profile
/// along the columns with jumps, rows scattered about it, optionally
/// coming back to the first columns' ranges at the end (the seam).
pub fn random_frame(
    rows: usize,
    cols: usize,
    density: f64,
    jump: f64,
    seam: bool,
    rng: &mut ChaCha8Rng,
) -> Frame {
    let mut f = Frame::empty(rows, cols);
    let mut base: i32 = rng.gen_range(300..1_200);
    let mut profile = Vec::with_capacity(cols);
    for _ in 0..cols {
        if rng.gen_bool(jump) {
            base = (base + rng.gen_range(-400..400)).clamp(200, 20_000);
        }
        base = (base + rng.gen_range(-10..10)).clamp(200, 20_000);
        profile.push(base);
    }
    if seam {
        // The last columns come back to the first ones' ranges.
        let tail = cols / 4;
        for c in cols - tail..cols {
            let t = (c + 1 - (cols - tail)) as i32;
            profile[c] += (profile[0] - profile[c]) * t / tail as i32;
        }
    }
    let mut off: Vec<i32> = vec![0; rows];
    for (c, &at) in profile.iter().enumerate() {
        for (r, o) in off.iter_mut().enumerate() {
            *o = (*o + rng.gen_range(-12..12)).clamp(-60, 60);
            if rng.gen_bool(jump / 2.0) {
                *o = rng.gen_range(-300..300);
            }
            if rng.gen_bool(density) {
                let range = at + *o;
                let along = if seam { c.min(cols - 1 - c) } else { c };
                let y = (along as i32 * 20 - 2_000).clamp(-32_000, 32_000);
                let z = (r as i32 * 25 - 400).clamp(-32_000, 32_000);
                f.set(r, c, Some([range as i16, y as i16, z as i16]));
            }
        }
    }
    f
}

/// Frames of `rows` x `cols` with thresholds that make runs part often.
pub fn run_params(rows: usize, cols: usize) -> FccParams {
    FccParams {
        rows,
        cols,
        th_h: 0.3,
        th_v: 0.3,
        label_bits: 16,
        ..FccParams::default()
    }
}

/// The block is built once, for the default build (its rows bound the
/// frames', its K is theirs).
pub fn build() -> FccParams {
    FccParams::default()
}
