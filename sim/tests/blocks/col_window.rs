//! The column core's pass-2 window `fcc_col_window` alone under Verilator,
//! for every K, against spec §4 read in column order (§9.1: a pixel's pairs
//! are the labelled points at most `h` rows and `h` columns from it in
//! earlier columns, other rows, and the `h` rows above it in its own
//! column; none outside the frame, none beyond the run's K). Seeded random
//! frames of labelled points, empty pixels and unlabelled points go in
//! column order, frames back to back on one instance, with a reset
//! mid-frame: spaced out (each pixel's whole window read entry by entry
//! while the window holds) and back to back with random bubbles (one
//! random entry per pixel). A mismatch prints K, the frame, the pixel, the
//! entry, expected, got and the seed.

use fcc_params::FccParams;
use fcc_rtl::{BenchBlock, COL_WINDOW_LATENCY};
use fcc_sim::{c_struct, load_plain, PlainDut};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

c_struct! {
    /// Inputs of one cycle, named as the ports.
    pub struct CwIn {
        pub rst: u8,
        pub valid: u8,
        pub lok: u8,
        pub x: u16,
        pub y: u16,
        pub z: u16,
        pub key: u16,
        pub cv: u64,
        pub label: u16,
        pub row: u8,
        pub col: u16,
        pub last_row: u8,
        pub run_k: u8,
        pub ent_sel: u8,
    }
}

c_struct! {
    /// Outputs during one cycle.
    pub struct CwOut {
        pub c_valid: u8,
        pub c_row: u8,
        pub c_col: u16,
        pub c_label: u16,
        pub e_ok: u8,
        pub e_x: u16,
        pub e_y: u16,
        pub e_z: u16,
        pub e_key: u16,
        pub e_cv: u64,
        pub e_label: u16,
    }
}

/// Cycles from a pixel to its window.
const LATENCY: usize = COL_WINDOW_LATENCY;

/// A pixel's word: x, y, z, key, label, and the pass-2 addend.
type Word = ([u16; 5], u64);

/// A pixel: its word and whether it is a labelled point; `None` for an
/// empty pixel.
type Px = Option<(Word, bool)>;

/// A frame in column order: `px[c][i]`.
struct Frame {
    rows: usize,
    px: Vec<Vec<Px>>,
}

fn random_frame(rows: usize, cols: usize, rng: &mut ChaCha8Rng) -> Frame {
    let px = (0..cols)
        .map(|_| {
            (0..rows)
                .map(|_| {
                    rng.gen_bool(0.7).then(|| {
                        let lok = rng.gen_bool(0.8);
                        let label = if lok { rng.gen_range(1..=u16::MAX) } else { 0 };
                        let cv = rng.gen::<u64>() & ((1 << 36) - 1);
                        (
                            ([rng.gen(), rng.gen(), rng.gen(), rng.gen(), label], cv),
                            lok,
                        )
                    })
                })
                .collect()
        })
        .collect();
    Frame { rows, px }
}

/// Entry `e` of the window of the pixel at (`i`, `c`) by spec §4 in
/// column order: the pixel's word when the position is a pair.
fn expected(f: &Frame, k: usize, run_k: usize, i: usize, c: usize, e: usize) -> Option<Word> {
    let (h, hr) = ((k - 1) / 2, (run_k - 1) / 2);
    let (row, col, reach) = if e < 2 * h * h {
        // Line r (column c - h + r), position p (rows i - h ..= i + h
        // without i).
        let (r, p) = (e / (k - 1), e % (k - 1));
        let n = if p < h { p } else { p + 1 };
        (
            i as isize - h as isize + n as isize,
            c as isize - h as isize + r as isize,
            n.abs_diff(h).max(h - r),
        )
    } else {
        // Row i - m of column c.
        let m = e - 2 * h * h + 1;
        (i as isize - m as isize, c as isize, m)
    };
    if row < 0 || row >= f.rows as isize || col < 0 || reach > hr {
        return None;
    }
    match f.px[col as usize][row as usize] {
        Some((w, true)) => Some(w),
        _ => None,
    }
}

struct Bench {
    dut: PlainDut<CwIn, CwOut>,
    k: usize,
    seed: u64,
}

impl Bench {
    fn slot(f: &Frame, run_k: usize, i: usize, c: usize) -> CwIn {
        let ((w, cv), lok) = f.px[c][i].unwrap_or((([0; 5], 0), false));
        CwIn {
            valid: 1,
            lok: lok as u8,
            x: w[0],
            y: w[1],
            z: w[2],
            key: w[3],
            cv,
            label: w[4],
            row: i as u8,
            col: c as u16,
            last_row: (f.rows - 1) as u8,
            run_k: run_k as u8,
            ..CwIn::default()
        }
    }

    fn idle(f: &Frame, run_k: usize, ent_sel: usize) -> CwIn {
        CwIn {
            last_row: (f.rows - 1) as u8,
            run_k: run_k as u8,
            ent_sel: ent_sel as u8,
            ..CwIn::default()
        }
    }

    /// Compare one entry of the centre at (`i`, `c`).
    fn check(
        &self,
        o: &CwOut,
        f: &Frame,
        run_k: usize,
        (i, c): (usize, usize),
        e: usize,
        what: &str,
    ) {
        let at = format!(
            "K = {}, run K = {run_k}, {what}: pixel row {i}, col {c}, entry {e}, seed {}",
            self.k, self.seed
        );
        let want = expected(f, self.k, run_k, i, c, e);
        assert_eq!(o.e_ok != 0, want.is_some(), "{at}: is a pair");
        if let Some(w) = want {
            assert_eq!(
                ([o.e_x, o.e_y, o.e_z, o.e_key, o.e_label], o.e_cv),
                w,
                "{at}: word"
            );
        }
    }

    /// One frame, each pixel's whole window read while the window holds.
    fn spaced(&mut self, f: &Frame, run_k: usize, what: &str) {
        let n = self.k * ((self.k - 1) / 2);
        for c in 0..f.px.len() {
            for i in 0..f.rows {
                self.dut.step(&Self::slot(f, run_k, i, c));
                for _ in 1..LATENCY {
                    self.dut.step(&Self::idle(f, run_k, 0));
                }
                for e in 0..n {
                    let o = self.dut.step(&Self::idle(f, run_k, e));
                    if e == 0 {
                        // The window shows with its centre, then holds.
                        assert_eq!(
                            (o.c_valid, o.c_row as usize, o.c_col as usize),
                            (1, i, c),
                            "K = {}: {what}: the centre with its window (seed {})",
                            self.k,
                            self.seed
                        );
                    }
                    self.check(&o, f, run_k, (i, c), e, what);
                }
            }
        }
    }

    /// One frame back to back with random bubbles (and a reset after
    /// `reset_after` slots, the frame then sent again from its start): one
    /// random entry per centre.
    fn streamed(
        &mut self,
        f: &Frame,
        run_k: usize,
        reset_after: Option<usize>,
        rng: &mut ChaCha8Rng,
        what: &str,
    ) {
        let n = self.k * ((self.k - 1) / 2);
        let mut order: Vec<(usize, usize)> = Vec::new();
        if let Some(cut) = reset_after {
            for s in 0..cut {
                let (c, i) = (s / f.rows, s % f.rows);
                self.dut.step(&Self::slot(f, run_k, i, c));
            }
            self.dut.step(&CwIn {
                rst: 1,
                ..Self::idle(f, run_k, 0)
            });
            for _ in 0..LATENCY {
                let o = self.dut.step(&Self::idle(f, run_k, 0));
                assert_eq!(
                    o.c_valid, 0,
                    "K = {}: {what}: a slot survived the reset",
                    self.k
                );
            }
        }
        for c in 0..f.px.len() {
            for i in 0..f.rows {
                order.push((i, c));
            }
        }
        let mut sent = 0;
        let mut seen = 0;
        // Per cycle: the entry asked for (the centre's, when one shows).
        while seen < order.len() {
            let e = rng.gen_range(0..n);
            let inp = if sent < order.len() && !rng.gen_bool(0.2) {
                let (i, c) = order[sent];
                sent += 1;
                CwIn {
                    ent_sel: e as u8,
                    ..Self::slot(f, run_k, i, c)
                }
            } else {
                Self::idle(f, run_k, e)
            };
            let o = self.dut.step(&inp);
            if o.c_valid != 0 {
                let (i, c) = order[seen];
                assert_eq!(
                    (o.c_row as usize, o.c_col as usize, o.c_label),
                    (i, c, f.px[c][i].map_or(0, |((w, _), _)| w[4])),
                    "K = {}: {what}: centre {seen}",
                    self.k
                );
                self.check(&o, f, run_k, (i, c), e, what);
                seen += 1;
            }
        }
    }
}

#[test]
fn every_pair_position_for_every_k() {
    for k in [3usize, 5, 7, 9, 11] {
        let build = FccParams {
            fsize: k,
            ..FccParams::default()
        };
        let model =
            load_plain::<CwIn, CwOut>(BenchBlock::ColWindow, &build).expect("column window model");
        let seed = 0xc01_0000 + k as u64;
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut b = Bench {
            dut: PlainDut::new(model),
            k,
            seed,
        };
        b.dut.step(&CwIn {
            rst: 1,
            ..CwIn::default()
        });
        // Small frames spaced out, every run K; then larger ones streamed.
        for run_k in (3..=k).step_by(2) {
            let f = random_frame(16, 9, &mut rng);
            b.spaced(&f, run_k, "spaced");
        }
        for (rows, cols) in [(16, 40), (23, 30), (build.rows, 20)] {
            let f = random_frame(rows, cols, &mut rng);
            b.streamed(&f, k, None, &mut rng, "streamed");
        }
        let f = random_frame(20, 30, &mut rng);
        b.streamed(&f, k, Some(20 * 7 + 5), &mut rng, "reset mid-frame");
        let f = random_frame(16, 30, &mut rng);
        b.streamed(&f, 3.max(k - 2), None, &mut rng, "streamed, smaller run K");
    }
}
