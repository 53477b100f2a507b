//! The label updater `fcc_label_update` alone under Verilator: frame-buffer
//! codes in, compact labels pushed into the gearbox as the merge table's
//! flatten pass does (no more than it holds), output beats out with random
//! back-pressure, compared with a software model of the beat packing
//! (labels per beat, 16-bit slots, `tkeep`, `tlast`). Directed frames, then
//! seeded random frames back to back; a mismatch prints the frame, the first
//! differing beat, expected, got and the seed.

use fcc_params::FccParams;
use fcc_sim::{load_label_update, LuDut, LuIn, LuOut};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// Frame-buffer codes (`fcc_label_update`'s module documentation).
const EMPTY: u8 = 0;
const CONTINUES: u8 = 1;
const LABELLED: u8 = 2;
const UNLABELLED: u8 = 3;

/// Entries of the gearbox: the bench never pushes into a full one.
const GEAR_SLOTS: u8 = 8;

/// One frame: the code of every pixel, and the compact label of the k-th
/// labelled run (as flatten emits them, in order).
#[derive(Debug, Clone)]
struct Frame {
    codes: Vec<u8>,
    compact: Vec<u16>,
}

impl Frame {
    fn new(codes: Vec<u8>, rng: &mut ChaCha8Rng) -> Self {
        let n = codes.iter().filter(|&&c| c == LABELLED).count();
        let compact = (0..n).map(|_| rng.gen_range(1..=u16::MAX)).collect();
        Frame { codes, compact }
    }
}

/// An output beat as the bench sees it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Beat {
    tdata: u64,
    tkeep: u8,
    tlast: bool,
}

impl std::fmt::Display for Beat {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "tdata {:016x} tkeep {:02x} tlast {}",
            self.tdata, self.tkeep, self.tlast
        )
    }
}

/// The software model: a pixel's label is 0 when empty, the next compact
/// label where a labelled run starts, 0 in an unlabelled run, the run's
/// label where it continues; `l` labels per beat from bit 0.
fn model(f: &Frame, l: usize) -> Vec<Beat> {
    let mut labels = Vec::with_capacity(f.codes.len());
    let mut run = 0u16;
    let mut next = f.compact.iter();
    for &c in &f.codes {
        labels.push(match c {
            EMPTY => 0,
            CONTINUES => run,
            LABELLED => {
                run = *next.next().expect("one compact label per labelled run");
                run
            }
            _ => {
                run = 0;
                0
            }
        });
    }
    let beats = labels.len().div_ceil(l);
    labels
        .chunks(l)
        .enumerate()
        .map(|(b, chunk)| Beat {
            tdata: chunk
                .iter()
                .enumerate()
                .fold(0u64, |d, (i, &v)| d | (u64::from(v) << (16 * i))),
            tkeep: ((1u16 << (2 * chunk.len())) - 1) as u8,
            tlast: b + 1 == beats,
        })
        .collect()
}

/// Random gaps and back-pressure of one run.
#[derive(Debug, Clone, Copy)]
struct Pace {
    /// Probability of an idle cycle between written pixels.
    write_gap: f64,
    /// Probability that flatten pushes no label in a cycle.
    push_gap: f64,
    /// Probability that the sink is not ready in a cycle.
    backpressure: f64,
}

const STEADY: Pace = Pace {
    write_gap: 0.0,
    push_gap: 0.0,
    backpressure: 0.0,
};

fn dut(p: &FccParams) -> LuDut {
    let model = match load_label_update(p) {
        Ok(m) => m,
        Err(e) => panic!("{e}"),
    };
    let mut d = LuDut::new(model);
    for _ in 0..2 {
        d.step(&LuIn {
            rst: 1,
            ..Default::default()
        });
    }
    // The sub-blocks' resets are registered copies of `rst`: they leave
    // reset one cycle after it.
    d.step(&LuIn::default());
    d
}

/// Write `f`, read it back, return the beats accepted by the sink.
fn run_frame(d: &mut LuDut, f: &Frame, pace: Pace, rng: &mut ChaCha8Rng, what: &str) -> Vec<Beat> {
    let mut i = 0;
    while i < f.codes.len() {
        if rng.gen_bool(pace.write_gap) {
            d.step(&LuIn::default());
            continue;
        }
        d.step(&LuIn {
            wr_valid: 1,
            wr_state: f.codes[i],
            wr_last: u8::from(i + 1 == f.codes.len()),
            ..Default::default()
        });
        i += 1;
    }
    d.step(&LuIn::default());
    d.step(&LuIn {
        rb_start: 1,
        ..Default::default()
    });
    let mut got = Vec::new();
    let mut pushed = 0;
    // Labels the gearbox may hold now: its count seen last cycle (before
    // that cycle's pops) plus that cycle's push.
    let mut gear_used = 0u8;
    let mut pushed_last = false;
    let limit = 40 * f.codes.len() + 1000;
    for cycle in 0..limit {
        let push = pushed < f.compact.len()
            && gear_used + u8::from(pushed_last) < GEAR_SLOTS
            && !rng.gen_bool(pace.push_gap);
        let tready = !rng.gen_bool(pace.backpressure);
        let o: LuOut = d.step(&LuIn {
            fv: u8::from(push),
            fval: if push { f.compact[pushed] } else { 0 },
            m_axis_tready: u8::from(tready),
            ..Default::default()
        });
        assert!(
            o.gear_used <= GEAR_SLOTS,
            "{what}: gearbox holds {} labels at read-back cycle {cycle}",
            o.gear_used
        );
        gear_used = o.gear_used;
        pushed_last = push;
        if push {
            pushed += 1;
        }
        if o.m_axis_tvalid != 0 && tready {
            got.push(Beat {
                tdata: o.m_axis_tdata,
                tkeep: o.m_axis_tkeep,
                tlast: o.m_axis_tlast != 0,
            });
        }
        let sent_last = o.m_axis_tvalid != 0 && tready && o.m_axis_tlast != 0;
        assert_eq!(
            o.rb_done != 0,
            sent_last,
            "{what}: rb_done at read-back cycle {cycle} must mark the last beat's transfer"
        );
        if sent_last {
            return got;
        }
    }
    panic!(
        "{what}: no last beat within {limit} cycles ({} beats out, {pushed} of {} labels pushed)",
        got.len(),
        f.compact.len()
    );
}

/// Compare, printing the first differing beat.
fn check(expected: &[Beat], got: &[Beat], what: &str) {
    for (b, (e, g)) in expected.iter().zip(got).enumerate() {
        assert!(e == g, "{what}: beat {b}: expected {e} != got {g}");
    }
    assert_eq!(
        expected.len(),
        got.len(),
        "{what}: expected {} beats, got {}",
        expected.len(),
        got.len()
    );
}

/// Small builds (the frame buffer holds 16 x 256 pixels), one per labels-per-beat.
fn builds() -> Vec<FccParams> {
    [4, 2, 1]
        .into_iter()
        .map(|l| FccParams {
            rows: 16,
            cols: 256,
            labels_per_beat: l,
            ..Default::default()
        })
        .collect()
}

/// Codes of `n` pixels: runs of random length, labelled, unlabelled or empty.
fn random_codes(n: usize, rng: &mut ChaCha8Rng) -> Vec<u8> {
    let mut codes = Vec::with_capacity(n);
    while codes.len() < n {
        let len = if rng.gen_bool(0.5) {
            1
        } else {
            rng.gen_range(1..=12)
        };
        let start = match rng.gen_range(0..10) {
            0..=2 => EMPTY,
            3 => UNLABELLED,
            _ => LABELLED,
        };
        for k in 0..len {
            if codes.len() == n {
                break;
            }
            codes.push(if start == EMPTY || k == 0 {
                start
            } else {
                CONTINUES
            });
        }
    }
    codes
}

#[test]
fn directed_frames_one_pixel_empty_all_new_labels_long_runs_partial_last_beat() {
    for p in builds() {
        let l = p.labels_per_beat as usize;
        let n = p.pixels();
        let mut rng = ChaCha8Rng::seed_from_u64(1);
        let mut frames: Vec<(&str, Vec<u8>)> = vec![
            ("one labelled pixel", vec![LABELLED]),
            ("one empty pixel", vec![EMPTY]),
            ("all empty", vec![EMPTY; n]),
            // Every pixel a new label: four a beat, more than the gearbox
            // delivers in one cycle.
            ("every pixel a new label", vec![LABELLED; n]),
            ("one run over the whole frame", {
                let mut c = vec![CONTINUES; n];
                c[0] = LABELLED;
                c
            }),
            ("one unlabelled run over the whole frame", {
                let mut c = vec![CONTINUES; n];
                c[0] = UNLABELLED;
                c
            }),
            // Runs that continue across beats and after empty pixels.
            (
                "runs across beats",
                (0..n)
                    .map(|i| match i % 7 {
                        0 => LABELLED,
                        3 => EMPTY,
                        5 if i % 3 == 0 => UNLABELLED,
                        _ => CONTINUES,
                    })
                    .collect(),
            ),
        ];
        for short in [2, 3, 5, 6, 7] {
            frames.push((
                "short frame, partial last beat",
                random_codes(short, &mut rng),
            ));
        }
        frames.push(("full frame less one pixel", random_codes(n - 1, &mut rng)));
        let mut d = dut(&p);
        for (name, codes) in frames {
            for (pace_name, pace) in [
                ("steady", STEADY),
                (
                    "stalls",
                    Pace {
                        write_gap: 0.2,
                        push_gap: 0.5,
                        backpressure: 0.5,
                    },
                ),
            ] {
                let f = Frame::new(codes.clone(), &mut rng);
                let what = format!("L = {l}, {name} ({} pixels), {pace_name}", codes.len());
                let got = run_frame(&mut d, &f, pace, &mut rng, &what);
                check(&model(&f, l), &got, &what);
            }
        }
    }
}

#[test]
fn seeded_random_frames_back_to_back_with_backpressure_match_the_beat_model() {
    for p in builds() {
        let l = p.labels_per_beat as usize;
        let n = p.pixels();
        for seed in 0..3u64 {
            let mut rng = ChaCha8Rng::seed_from_u64(seed);
            let mut d = dut(&p);
            for frame in 0..4 {
                let pixels = if rng.gen_bool(0.5) {
                    n
                } else {
                    rng.gen_range(1..=n)
                };
                let f = Frame::new(random_codes(pixels, &mut rng), &mut rng);
                let pace = Pace {
                    write_gap: rng.gen_range(0.0..0.5),
                    push_gap: rng.gen_range(0.0..0.9),
                    backpressure: rng.gen_range(0.0..0.9),
                };
                let what =
                    format!("L = {l}, seed {seed}, frame {frame} ({pixels} pixels, {pace:?})");
                let got = run_frame(&mut d, &f, pace, &mut rng, &what);
                check(&model(&f, l), &got, &what);
            }
        }
    }
}

/// The bench can fail: a model that drops the carried run disagrees.
#[test]
fn model_of_a_run_across_beats_carries_its_label() {
    let mut rng = ChaCha8Rng::seed_from_u64(0);
    let f = Frame::new(
        vec![LABELLED, CONTINUES, CONTINUES, CONTINUES, CONTINUES, EMPTY],
        &mut rng,
    );
    let b = model(&f, 4);
    let c = u64::from(f.compact[0]);
    assert_eq!(b.len(), 2);
    assert_eq!(b[0].tdata, c | c << 16 | c << 32 | c << 48);
    assert_eq!(
        b[1],
        Beat {
            tdata: c,
            tkeep: 0x0f,
            tlast: true
        }
    );
}
