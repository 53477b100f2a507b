//! The column core's run accumulators `fcc_run_acc` alone under Verilator:
//! every pixel slot of seeded frames in column order, with its run's label
//! and its row's hold changes worked out from the golden stream's runs
//! (spec §3, §9.2), against a model of when each run is over (its row
//! drops its hold, its row starts another run, or the frame ends) and the
//! golden accumulator of its pixels (`fcc_golden::Acc`, in the core's
//! form). Checked: the flushes in order, each run's label and accumulator,
//! every run flushed once, `done` after the frame end's flushes, the
//! input held (`ready` low) while they run, and `bad` (a run continued
//! that its row does not have open) set only by such input. Fixed and range-adaptive
//! thresholds, bridge and ring-reach limits, bubbles, frames back to back
//! on one instance, and a reset mid-frame. A mismatch prints the frame,
//! the flush, expected, got and the seed.

use crate::column;

use column::{build, pixels, random_frame, run_params, Pix};
use fcc_golden::{Acc, Frame};
use fcc_params::FccParams;
use fcc_rtl::{BenchBlock, RUN_ACC_LATENCY};
use fcc_sim::core_form::{offset_binary as ob, CoreAcc};
use fcc_sim::{c_struct, core_acc_out, load_plain, PlainDut};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

c_struct! {
    /// Inputs of one cycle, named as the ports.
    pub struct RaIn {
        pub rst: u8,
        pub valid: u8,
        pub lok: u8,
        pub row: u8,
        pub col: u16,
        pub x: u16,
        pub y: u16,
        pub z: u16,
        pub label: u16,
        pub start: u8,
        pub hold_drop: u16,
        pub last: u8,
        pub ring_hold: u8,
        pub half: u16,
        pub last_row: u8,
        pub drain_go: u8,
    }
}

c_struct! {
    /// Outputs during one cycle.
    pub struct RaOut with acc_out {
        pub ready: u8,
        pub f_valid: u8,
        pub f_label: u16,
        pub f_end: u8,
        pub f_ring: u8,
        pub done: u8,
        pub bad: u8,
    }
}

/// A flush: the run's label and accumulator (a seam half the accumulator
/// does not have reads 0).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Flush {
    label: u16,
    acc: CoreAcc,
    /// The frame end's flush, not a pixel's.
    end: bool,
    /// A frame end's flush of a run its row holds by hold 4.
    ring: bool,
}

impl Flush {
    fn got(o: &RaOut) -> Flush {
        let acc = core_acc_out!(o);
        Flush {
            label: o.f_label,
            acc,
            end: o.f_end != 0,
            ring: o.f_ring != 0,
        }
    }
}

/// Why the model flushes a run (each must occur in the random cases).
#[derive(Debug, Default, Clone, Copy)]
struct Why {
    start: u64,
    drop: u64,
    end: u64,
}

/// The flushes a frame must give, in order: per pixel slot in column order
/// at most one (a run starting while its row's run is open flushes that
/// one; a row dropping its open run flushes it, the pixel included when it
/// continued it), then at the frame end every row's open run, row by row.
/// Labels are the golden run numbers. Beside each flush, the pixel
/// (its index in `px`) that made it, none at the frame end.
fn expected(
    p: &FccParams,
    f: &Frame,
    px: &[Pix],
    why: &mut Why,
) -> (Vec<Flush>, Vec<Option<usize>>) {
    let half = (p.cols / 2) as u32;
    let mut open: Vec<Option<(u32, Acc)>> = vec![None; p.rows];
    let (mut out, mut from) = (Vec::new(), Vec::new());
    let flush = |run: u32, a: &Acc| Flush {
        label: run as u16,
        acc: CoreAcc::of(a),
        end: false,
        ring: false,
    };
    for (n, x) in px.iter().enumerate() {
        let r = x.row;
        if x.run != 0 {
            let pt = f.get(r, x.col).expect("a labelled pixel has a point");
            if x.start {
                if let Some((run, a)) = open[r].take() {
                    out.push(flush(run, &a));
                    from.push(Some(n));
                    why.start += 1;
                }
                open[r] = Some((x.run, Acc::default()));
            }
            let (run, a) = open[r].as_mut().expect("a run continues an open one");
            assert_eq!(*run, x.run, "row {r}, column {}: the run continued", x.col);
            a.add_in_scan(r as u32, x.col as u32, pt, half);
        }
        if let Some((before, _)) = x.hold {
            if before != 0 && open[r].as_ref().is_some_and(|(run, _)| *run == before) {
                let (run, a) = open[r].take().expect("checked");
                out.push(flush(run, &a));
                from.push(Some(n));
                why.drop += 1;
            }
        }
    }
    for (r, o) in open.iter_mut().enumerate() {
        if let Some((run, a)) = o.take() {
            out.push(Flush {
                end: true,
                ring: ring_hold(p, r, p.cols - 1),
                ..flush(run, &a)
            });
            from.push(None);
            why.end += 1;
        }
    }
    (out, from)
}

/// Whether the bench says the row holds its latest run by hold 4 at this
/// slot: at the last column, every third row (the frame end's flush of
/// that row's run must say so, and no other flush).
fn ring_hold(p: &FccParams, row: usize, col: usize) -> bool {
    col + 1 == p.cols && row % 3 == 1
}

/// A cycle without a pixel, with the frame's run parameters.
fn idle(p: &FccParams) -> RaIn {
    RaIn {
        half: (p.cols / 2) as u16,
        last_row: (p.rows - 1) as u8,
        drain_go: 1,
        ..RaIn::default()
    }
}

struct Bench {
    dut: PlainDut<RaIn, RaOut>,
    got: Vec<Flush>,
    /// The cycle of each flush got, and of each pixel taken; `drain_go`
    /// each cycle.
    got_at: Vec<u64>,
    took_at: Vec<u64>,
    go: Vec<bool>,
    /// The frame end's flush reads a row in a cycle with probability
    /// `go_rate` (`drain_go`).
    go_rate: f64,
    rng: ChaCha8Rng,
    done: u32,
    /// Cycles with `ready` low, and with `bad` set.
    held: u64,
    bad: u64,
}

impl Bench {
    fn new(build: &FccParams) -> Bench {
        let model =
            load_plain::<RaIn, RaOut>(BenchBlock::RunAcc, build).expect("run accumulators model");
        let mut b = Bench {
            dut: PlainDut::new(model),
            got: Vec::new(),
            got_at: Vec::new(),
            took_at: Vec::new(),
            go: Vec::new(),
            go_rate: 1.0,
            rng: ChaCha8Rng::seed_from_u64(0),
            done: 0,
            held: 0,
            bad: 0,
        };
        b.step(&RaIn {
            rst: 1,
            ..RaIn::default()
        });
        b
    }

    /// One cycle; returns `ready` as it was during it. `drain_go` is the
    /// bench's (high with probability `go_rate`).
    fn step(&mut self, i: &RaIn) -> bool {
        let go = self.go_rate >= 1.0 || self.rng.gen_bool(self.go_rate);
        let o = self.dut.step(&RaIn {
            drain_go: u8::from(go),
            ..*i
        });
        self.go.push(go);
        if o.f_valid != 0 {
            self.got.push(Flush::got(&o));
            self.got_at.push(self.go.len() as u64 - 1);
        }
        self.done += u32::from(o.done);
        self.held += u64::from(o.ready == 0);
        self.bad += u64::from(o.bad);
        o.ready != 0
    }

    /// Feed the frame's pixels (a bubble before each with probability
    /// `bubbles`), each held until taken; the last is the frame's last
    /// when `ends`.
    fn feed(
        &mut self,
        p: &FccParams,
        f: &Frame,
        px: &[Pix],
        ends: bool,
        bubbles: f64,
        rng: &mut ChaCha8Rng,
    ) {
        self.feed_gaps(p, f, px, ends, |_| {
            let mut n = 0;
            while rng.gen_bool(bubbles) {
                n += 1;
            }
            n
        });
    }

    /// Feed the frame's pixels with `gap(n)` bubbles before pixel `n`.
    fn feed_gaps(
        &mut self,
        p: &FccParams,
        f: &Frame,
        px: &[Pix],
        ends: bool,
        mut gap: impl FnMut(usize) -> usize,
    ) {
        let idle = idle(p);
        for (n, x) in px.iter().enumerate() {
            for _ in 0..gap(n) {
                self.step(&idle);
            }
            let [px_x, px_y, px_z] = f.get(x.row, x.col).unwrap_or([0; 3]);
            let i = RaIn {
                valid: 1,
                lok: (x.run != 0) as u8,
                row: x.row as u8,
                col: x.col as u16,
                x: ob(px_x),
                y: ob(px_y),
                z: ob(px_z),
                label: x.run as u16,
                start: x.start as u8,
                hold_drop: x.hold.map_or(0, |(before, _)| before as u16),
                last: (ends && n + 1 == px.len()) as u8,
                ring_hold: ring_hold(p, x.row, x.col) as u8,
                ..idle
            };
            while !self.step(&i) {}
            self.took_at.push(self.go.len() as u64 - 1);
        }
    }

    /// Forget the flushes and pixels of earlier frames.
    fn clear(&mut self) {
        self.got.clear();
        self.got_at.clear();
        self.took_at.clear();
        self.done = 0;
    }

    /// A pixel's flush came [`RUN_ACC_LATENCY`] cycles after it was taken;
    /// a frame end's flush five cycles after a cycle with `drain_go` (its
    /// row's read).
    fn check_timing(&self, from: &[Option<usize>], what: &str) {
        for (n, (&at, src)) in self.got_at.iter().zip(from).enumerate() {
            match src {
                Some(x) => assert_eq!(
                    at - self.took_at[*x],
                    RUN_ACC_LATENCY as u64,
                    "{what}: flush {n}, of pixel {x}: cycles after the pixel was taken"
                ),
                None => assert!(
                    self.go[at as usize - 5],
                    "{what}: flush {n}, at the frame end: its row read without drain_go"
                ),
            }
        }
    }

    /// Cycles enough for the frame end's flushes with `drain_go` high.
    fn settle(&mut self, p: &FccParams) {
        let idle = idle(p);
        for _ in 0..p.rows + 16 {
            self.step(&idle);
        }
    }

    /// Cycles until the frame end's flushes are done, and a few more.
    fn finish(&mut self, p: &FccParams, what: &str) {
        let idle = idle(p);
        let mut left = 100 * p.rows + 100;
        while self.done == 0 {
            self.step(&idle);
            left -= 1;
            assert!(left > 0, "{what}: the frame end's flushes never done");
        }
        for _ in 0..16 {
            self.step(&idle);
        }
    }
}

/// The golden runs of `f` and its pixels as the block gets them.
fn frame_pixels(p: &FccParams, f: &Frame) -> Vec<Pix> {
    let runs = column::closing(p, f).runs;
    assert!(
        runs.iter().all(|&r| r < u32::from(u16::MAX)),
        "labels are run numbers: too many runs"
    );
    pixels(p, f, &runs)
}

fn check(got: &[Flush], want: &[Flush], what: &str) {
    for (n, (g, w)) in got.iter().zip(want).enumerate() {
        assert_eq!(
            g,
            w,
            "{what}: flush {n} of {} (run {})",
            want.len(),
            w.label
        );
    }
    assert_eq!(
        got.len(),
        want.len(),
        "{what}: flushes, got {} expected {}",
        got.len(),
        want.len()
    );
}

#[test]
fn runs_flush_their_golden_accumulators() {
    let build = build();
    let adaptive = FccParams {
        th_h_slope: 0.02,
        th_v_slope: 0.03,
        ..run_params(40, 60)
    };
    let cases: [(&str, FccParams, f64); 7] = [
        ("unlimited", run_params(16, 40), 0.0),
        // The fewest rows the block takes: a row's write just before its
        // next read.
        ("five rows", run_params(5, 80), 0.0),
        (
            "bridge 2",
            FccParams {
                bridge: Some(2),
                ..run_params(23, 50)
            },
            0.2,
        ),
        (
            "bridge 0, ring 3",
            FccParams {
                bridge: Some(0),
                ring_reach: Some(3),
                ..run_params(build.rows, 30)
            },
            0.1,
        ),
        (
            "ring 0",
            FccParams {
                ring_reach: Some(0),
                ..run_params(32, 45)
            },
            0.3,
        ),
        ("adaptive", adaptive, 0.05),
        (
            "bridge 5, seam",
            FccParams {
                bridge: Some(5),
                ..run_params(16, 64)
            },
            0.0,
        ),
    ];
    let mut b = Bench::new(&build);
    let mut why = Why::default();
    for (n, (name, p, bubbles)) in cases.iter().enumerate() {
        for seed in 0..3u64 {
            let seed = 100 * n as u64 + seed;
            let mut rng = ChaCha8Rng::seed_from_u64(seed);
            let f = random_frame(p.rows, p.cols, 0.8, 0.05, name.ends_with("seam"), &mut rng);
            let px = frame_pixels(p, &f);
            let (want, from) = expected(p, &f, &px, &mut why);
            b.clear();
            // The frame end's flush reads its rows every cycle, or now and
            // then (held for places where its accumulators wait).
            b.go_rate = [1.0, 0.3, 0.05][seed as usize % 3];
            let what = format!("{name}, seed {seed}, drain_go {}", b.go_rate);
            // Frames back to back: the next one waits for this one's end.
            b.feed(p, &f, &px, true, *bubbles, &mut rng);
            b.finish(p, &what);
            check(&b.got, &want, &what);
            b.check_timing(&from, &what);
            assert_eq!(b.done, 1, "{what}: done once after the frame end");
            assert_eq!(b.bad, 0, "{what}: bad set");
        }
    }
    // Every reason to flush was exercised, and the frame end held the input.
    assert!(why.start > 0 && why.drop > 0 && why.end > 0, "{why:?}");
    assert!(b.held > 0, "the frame end never held the input");
}

/// The frame end's flushes come after every pixel's, whatever the bubbles
/// before the last pixels: here frames whose last or second-to-last pixel
/// flushes a run, fed back to back but for one to three bubbles before
/// one of the last three pixels (so the frame end's reads could start
/// before the last pixels have read their rows).
#[test]
fn the_frame_end_flushes_after_the_last_pixels() {
    let build = build();
    let p = FccParams {
        bridge: Some(1),
        ..run_params(8, 12)
    };
    let mut b = Bench::new(&build);
    let mut frames = 0;
    for seed in 0..400u64 {
        let mut rng = ChaCha8Rng::seed_from_u64(900 + seed);
        let f = random_frame(p.rows, p.cols, 0.6, 0.3, false, &mut rng);
        let px = frame_pixels(&p, &f);
        let (want, from) = expected(&p, &f, &px, &mut Why::default());
        let n = px.len();
        if !from.iter().any(|x| matches!(x, Some(i) if *i + 2 >= n)) {
            continue;
        }
        for (before, bubbles) in [(n - 1, 1), (n - 2, 1), (n - 3, 2), (n - 2, 3)] {
            b.clear();
            b.feed_gaps(&p, &f, &px, true, |i| if i == before { bubbles } else { 0 });
            let what = format!(
                "seed {}, {bubbles} bubbles before pixel {before} of {n}",
                900 + seed
            );
            b.finish(&p, &what);
            check(&b.got, &want, &what);
            b.check_timing(&from, &what);
        }
        frames += 1;
        if frames == 12 {
            break;
        }
    }
    assert_eq!(frames, 12, "frames whose last pixels flush");
}

#[test]
fn a_reset_mid_frame_starts_afresh() {
    let build = build();
    let p = FccParams {
        bridge: Some(3),
        ..run_params(20, 36)
    };
    let mut b = Bench::new(&build);
    for seed in 0..3u64 {
        let mut rng = ChaCha8Rng::seed_from_u64(700 + seed);
        let f = random_frame(p.rows, p.cols, 0.8, 0.05, false, &mut rng);
        let px = frame_pixels(&p, &f);
        // Half a frame, cut off by a reset (no `last`)...
        let cut = rng.gen_range(p.rows..px.len() - p.rows);
        b.feed(&p, &f, &px[..cut], false, 0.1, &mut rng);
        b.step(&RaIn {
            rst: 1,
            ..RaIn::default()
        });
        // ... then the whole frame: its flushes only, nothing left of the
        // half frame's open runs.
        b.clear();
        b.feed(&p, &f, &px, true, 0.1, &mut rng);
        let what = format!("reset mid-frame, seed {}", 700 + seed);
        b.finish(&p, &what);
        let (want, from) = expected(&p, &f, &px, &mut Why::default());
        check(&b.got, &want, &what);
        b.check_timing(&from, &what);
        assert_eq!(b.done, 1, "{what}: done once");
        assert_eq!(b.bad, 0, "{what}: bad set");
    }
}

/// A pixel that continues a run its row does not have open (here: after a
/// reset, a frame fed from its second column) sets `bad` until a reset.
#[test]
fn a_run_continued_without_its_start_is_bad() {
    let build = build();
    let p = run_params(16, 24);
    let mut b = Bench::new(&build);
    let mut rng = ChaCha8Rng::seed_from_u64(800);
    let f = random_frame(p.rows, p.cols, 0.9, 0.0, false, &mut rng);
    let px = frame_pixels(&p, &f);
    assert!(
        px[p.rows..2 * p.rows]
            .iter()
            .any(|x| x.run != 0 && !x.start),
        "the second column continues runs"
    );
    b.feed(&p, &f, &px[p.rows..2 * p.rows], false, 0.0, &mut rng);
    b.settle(&p);
    assert!(b.bad > 0, "bad not set");
    b.step(&RaIn {
        rst: 1,
        ..RaIn::default()
    });
    b.bad = 0;
    b.feed(&p, &f, &px, true, 0.0, &mut rng);
    b.settle(&p);
    assert_eq!(b.bad, 0, "bad not cleared by the reset");
}
