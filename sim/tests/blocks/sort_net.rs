//! The sort network `fcc_sort_net` (sort filter, centre buffer, serializer,
//! join queue) alone under Verilator, against the golden pass 2: driven one
//! centre per cycle as `fcc_top` drives it (every pixel of the frame a valid
//! centre, its window's hit bits from the golden threshold, the upper pixels'
//! representatives as the block itself wrote them back, the row's ring join
//! on its last pixel, input credits, random idle cycles and back-pressure
//! from the union engine), for build K = 3, 7 and 11 (the smallest, the
//! default, the largest; the Verilator regression and the cocotb bench run
//! the whole core at every K), on seeded random frames, the
//! directed frames and scenes. The joins it emits must connect exactly the
//! components the golden join set (pass-2 joins and ring joins) connects: a
//! join the golden set keeps apart, or a golden join left unconnected, fails
//! with the frame, the pixel, expected, got and the seed. It may drop
//! redundant joins; each K prints how many (`SORT_NET` lines).

use std::collections::{HashSet, VecDeque};

use fcc_golden::{dist2, pass1, pass2, Frame, JoinSink, Pass1};
use fcc_params::FccParams;
use fcc_rtl::{CREDITS, JQ_HIGH_LEVEL};
use fcc_sim::{frames, load_sort_net, pack_centre, SnCentre, SnIn, SortNetDut};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

fn build(fsize: usize) -> FccParams {
    FccParams {
        rows: 16,
        cols: 256,
        fsize,
        ..Default::default()
    }
}

/// How the bench drives the block: idle cycles between centres and how
/// often the union engine is ready for a join.
#[derive(Clone, Copy)]
struct Drive {
    gap: f64,
    ready: f64,
}

const FREE: Drive = Drive {
    gap: 0.0,
    ready: 1.0,
};
const STRESSED: Drive = Drive {
    gap: 0.2,
    ready: 0.15,
};

/// A union-find over labels 0 ..= n.
struct Sets(Vec<u32>);

impl Sets {
    fn new(n: u32) -> Self {
        Sets((0..=n).collect())
    }
    fn find(&mut self, mut a: u32) -> u32 {
        while self.0[a as usize] != a {
            let up = self.0[self.0[a as usize] as usize];
            self.0[a as usize] = up;
            a = up;
        }
        a
    }
    /// Unite `a` and `b`; true when they were apart.
    fn union(&mut self, a: u32, b: u32) -> bool {
        let (ra, rb) = (self.find(a), self.find(b));
        if ra != rb {
            self.0[ra.max(rb) as usize] = ra.min(rb);
        }
        ra != rb
    }
}

/// One golden join: the centre pixel that made it (ring joins: the row's
/// last pixel) and its two labels.
#[derive(Debug, Clone, Copy)]
struct GoldenJoin {
    pixel: (usize, usize),
    a: u32,
    b: u32,
}

/// Collects pass 2's joins with the centre pixel of each.
struct Collect<'a> {
    /// The labelled pixels in raster order: the n-th `centre` call is the n-th.
    centres: &'a [(usize, usize)],
    next: usize,
    joins: Vec<GoldenJoin>,
}

impl JoinSink for Collect<'_> {
    fn centre(&mut self, _label: u32) {
        self.next += 1;
    }
    fn join(&mut self, centre: u32, other: u32) {
        self.joins.push(GoldenJoin {
            pixel: self.centres[self.next - 1],
            a: centre,
            b: other,
        });
    }
    fn row_end(&mut self) {}
}

/// The golden join set of `f`: pass-2 joins, then ring joins.
fn golden(p: &FccParams, f: &Frame) -> (Pass1, Vec<GoldenJoin>) {
    let p1 = pass1(p, f);
    let centres: Vec<(usize, usize)> = (0..f.rows * f.cols)
        .filter(|&q| p1.labels[q] != 0)
        .map(|q| (q / f.cols, q % f.cols))
        .collect();
    let mut sink = Collect {
        centres: &centres,
        next: 0,
        joins: Vec::new(),
    };
    pass2(p, f, &p1, &mut sink);
    let mut joins = sink.joins;
    for &(a, b) in &p1.ring_joins {
        let q = p1.labels.iter().position(|&l| l == b).expect("ring label");
        joins.push(GoldenJoin {
            pixel: (q / f.cols, f.cols - 1),
            a,
            b,
        });
    }
    (p1, joins)
}

/// Joins counted over a K: the golden set's distinct label pairs, the
/// merges they make, and the joins the block emitted.
#[derive(Default)]
struct Count {
    frames: usize,
    golden_pairs: usize,
    merges: usize,
    emitted: usize,
    /// Cycles a centre waited for an input credit.
    credit_stalls: usize,
    /// Most joins waiting in the join queue at once.
    max_queued: usize,
}

/// A sort network of build `p` that runs frames back to back, as `fcc_top`
/// does (each frame drained before the next starts).
struct Bench {
    p: FccParams,
    dut: SortNetDut,
    rng: ChaCha8Rng,
    seed: u64,
    count: Count,
}

impl Bench {
    fn new(p: &FccParams, seed: u64) -> Self {
        let model = match load_sort_net(p) {
            Ok(m) => m,
            Err(e) => panic!("{e}"),
        };
        let mut dut = SortNetDut::new(model, p);
        let n = p.window_positions();
        let rst = SnIn {
            rst: 1,
            ..Default::default()
        };
        for _ in 0..4 {
            dut.step(&rst, &vec![0; n], &vec![0; n]);
        }
        // The sub-blocks' resets are registered copies of `rst`: they leave
        // reset one cycle after it.
        dut.step(&SnIn::default(), &vec![0; n], &vec![0; n]);
        Bench {
            p: p.clone(),
            dut,
            rng: ChaCha8Rng::seed_from_u64(seed),
            seed,
            count: Count::default(),
        }
    }

    /// Run `f` and compare its joins' connectivity with the golden set.
    fn frame(&mut self, name: &str, f: &Frame, d: Drive) {
        let p = &self.p;
        let (k, h, n) = (p.fsize, p.half(), p.window_positions());
        let (rows, cols) = (f.rows, f.cols);
        let ctx = format!("K {k}, frame {name}, seed {}", self.seed);
        let (p1, gold) = golden(p, f);
        let labels = &p1.labels;
        let th = p.th_v_sq();
        let rings: Vec<Option<(u32, u32)>> = (0..rows)
            .map(|i| {
                p1.ring_joins
                    .iter()
                    .copied()
                    .find(|&(_, b)| labels[i * cols..(i + 1) * cols].contains(&b))
            })
            .collect();
        // Representatives the block wrote back, per pixel; the centres
        // whose write is still due, oldest first.
        let mut rep_of: Vec<Option<u16>> = vec![None; rows * cols];
        let mut due: VecDeque<usize> = VecDeque::new();
        let mut credits = 0usize;
        let mut next = 0usize;
        let mut emitted: Vec<(u32, u32)> = Vec::new();
        let (mut last_done, mut quiet) = (false, 0);
        // Cycles without a centre sent, a credit returned or a join taken.
        let mut idle = 0usize;
        let (mut hit, mut rep) = (vec![0u8; n], vec![0u16; n]);
        // The join counter clears at the start of a frame.
        let clear = SnIn {
            clear: 1,
            ..Default::default()
        };
        self.dut.step(&clear, &hit, &rep);
        for cycle in 0.. {
            assert!(
                idle < 10_000,
                "{ctx}: stuck at cycle {cycle}: {next} centres sent, {} joins taken, {credits} \
                 credits out",
                emitted.len()
            );
            idle += 1;
            let mut c = SnCentre::default();
            hit.fill(0);
            rep.fill(0);
            if next < rows * cols && credits >= CREDITS {
                self.count.credit_stalls += 1;
            }
            let send = next < rows * cols && credits < CREDITS && !self.rng.gen_bool(d.gap);
            if send {
                let (i, j) = (next / cols, next % cols);
                let lc = labels[next];
                c = SnCentre {
                    valid: true,
                    lok: lc != 0,
                    label: lc as u16,
                    col: j as u16,
                    last: next + 1 == rows * cols,
                    ..Default::default()
                };
                if j + 1 == cols {
                    if let Some((a, b)) = rings[i] {
                        (c.ring, c.ring_a, c.ring_b) = (true, a as u16, b as u16);
                    }
                }
                for r in 0..h {
                    for m in 0..k {
                        if i + r < h || j + m < h || j + m - h >= cols {
                            continue;
                        }
                        let q = (i + r - h) * cols + j + m - h;
                        let e = r * k + m;
                        rep[e] = rep_of[q].unwrap_or(0);
                        let close = match (f.points[next], f.points[q]) {
                            (Some(a), Some(b)) => dist2(a, b) < th,
                            _ => false,
                        };
                        if lc != 0 && labels[q] != 0 && close {
                            hit[e] = 1;
                            assert!(
                                rep_of[q].is_some(),
                                "{ctx}: pixel ({}, {}) in the window of ({i}, {j}) has no \
                                 representative written back yet",
                                q / cols,
                                q % cols
                            );
                        }
                    }
                }
                idle = 0;
                due.push_back(next);
                credits += 1;
                next += 1;
            }
            let jready = self.rng.gen_bool(d.ready);
            let inp = SnIn {
                centre: pack_centre(&c),
                jready: u8::from(jready),
                ..Default::default()
            };
            let out = self.dut.step(&inp, &hit, &rep);
            if out.rep_we != 0 {
                let Some(q) = due.pop_front() else {
                    panic!("{ctx}: representative written with no centre in flight");
                };
                assert_eq!(
                    usize::from(out.rep_waddr),
                    q % cols,
                    "{ctx}: representative of ({}, {}) written to the wrong column",
                    q / cols,
                    q % cols
                );
                rep_of[q] = Some(out.rep_wdata);
            }
            for returned in [out.drop, out.take] {
                if returned != 0 {
                    assert!(credits > 0, "{ctx}: more credits returned than taken");
                    credits -= 1;
                    idle = 0;
                }
            }
            if out.jv != 0 && jready {
                let (a, b) = (u32::from(out.ja), u32::from(out.jb));
                if out.jsame != 0 {
                    let prev = emitted.last().map(|j| j.0);
                    assert_eq!(
                        prev,
                        Some(a),
                        "{ctx}: jsame with a new ja, join {}",
                        emitted.len()
                    );
                }
                emitted.push((a, b));
                idle = 0;
            }
            // `joins` counts the joins written to the queue.
            let queued = out.joins as usize - emitted.len();
            self.count.max_queued = self.count.max_queued.max(queued);
            last_done |= out.last_done != 0;
            quiet = if last_done && next == rows * cols && out.jv == 0 && out.jq_empty != 0 {
                quiet + 1
            } else {
                0
            };
            if quiet == 4 {
                assert_eq!(credits, 0, "{ctx}: input credits not returned");
                assert!(
                    due.is_empty(),
                    "{ctx}: {} representatives not written",
                    due.len()
                );
                assert_eq!(
                    out.joins as usize,
                    emitted.len(),
                    "{ctx}: join counter against the joins taken"
                );
                break;
            }
        }
        self.compare(&ctx, p1.provisional, &gold, &emitted);
    }

    fn compare(&mut self, ctx: &str, prov: u32, gold: &[GoldenJoin], emitted: &[(u32, u32)]) {
        let mut want = Sets::new(prov);
        let mut merges = 0;
        let mut pairs = HashSet::new();
        for g in gold {
            merges += usize::from(want.union(g.a, g.b));
            pairs.insert((g.a.min(g.b), g.a.max(g.b)));
        }
        let mut got = Sets::new(prov);
        for (x, &(a, b)) in emitted.iter().enumerate() {
            assert!(
                (1..=prov).contains(&a) && (1..=prov).contains(&b),
                "{ctx}: join {x} ({a}, {b}) outside the labels 1..={prov}"
            );
            assert_eq!(
                want.find(a),
                want.find(b),
                "{ctx}: join {x} ({a}, {b}) connects components the golden set keeps apart \
                 (expected roots {} and {}, got one component)",
                want.find(a),
                want.find(b)
            );
            got.union(a, b);
        }
        for g in gold {
            assert_eq!(
                got.find(g.a),
                got.find(g.b),
                "{ctx}: golden join ({}, {}) of pixel {:?} dropped: expected one component, \
                 got roots {} and {} after {} joins",
                g.a,
                g.b,
                g.pixel,
                got.find(g.a),
                got.find(g.b),
                emitted.len()
            );
        }
        self.count.frames += 1;
        self.count.golden_pairs += pairs.len();
        self.count.merges += merges;
        self.count.emitted += emitted.len();
    }

    fn report(&self, what: &str) {
        let c = &self.count;
        eprintln!(
            "SORT_NET fsize {} {what}: {} frames, golden pairs {}, merges needed {}, joins emitted {}, \
             dropped {} ({:.1} %), credit stalls {}, most joins queued {}",
            self.p.fsize,
            c.frames,
            c.golden_pairs,
            c.merges,
            c.emitted,
            c.golden_pairs as i64 - c.emitted as i64,
            100.0 * (c.golden_pairs as f64 - c.emitted as f64) / (c.golden_pairs.max(1) as f64),
            c.credit_stalls,
            c.max_queued
        );
    }
}

/// Seeded random frames, the directed frames and two scenes, free-running;
/// then random frames and a scene with idle cycles and a slow union engine.
fn every_frame_kind(fsize: usize) {
    let p = build(fsize);
    let seed = 0x50f7 + fsize as u64;
    let mut b = Bench::new(&p, seed);
    for s in 0..4 {
        b.frame(&format!("random {s}"), &frames::random(&p, seed + s), FREE);
    }
    for (name, f) in frames::directed(&p) {
        b.frame(name, &f, FREE);
    }
    for s in [1u64, 2] {
        let cfg = fcc_scene::SceneConfig {
            rows: p.rows,
            cols: p.cols,
            seed: s,
            ..Default::default()
        };
        let scene = fcc_scene::generate(&cfg).unwrap();
        let f = Frame::from_xyz_f32(p.rows, p.cols, &scene.xyz);
        b.frame(&format!("scene {s}"), &f, FREE);
    }
    b.report("free-running");
    let mut b = Bench::new(&p, seed ^ 0xbac0);
    for s in 0..2 {
        b.frame(
            &format!("random {s} stressed"),
            &frames::random(&p, seed + 100 + s),
            STRESSED,
        );
    }
    let cfg = fcc_scene::SceneConfig {
        rows: p.rows,
        cols: p.cols,
        seed: 3,
        ..Default::default()
    };
    let scene = fcc_scene::generate(&cfg).unwrap();
    let f = Frame::from_xyz_f32(p.rows, p.cols, &scene.xyz);
    b.frame("scene 3 stressed", &f, STRESSED);
    b.report("stressed");
}

/// Columns alternately near and far: every pixel is its own run, and each
/// matches the same-range pixels of the rows above, so every centre keeps
/// joins. A union engine ready one cycle in five lets the joins pile up, the
/// serializer and the centre buffer back up, and the input credits run out
/// (the test fails if they never do). From K = 5 on, a centre keeps several
/// joins and the join queue fills: the serializer waits for its room (the
/// test fails if the queue never reaches its high level). At K = 3 a centre
/// has one join, 3,840 in the frame, fewer than the queue holds. At K = 9
/// and 11 the same stripes, 120 columns wide, must fill the queue even with a
/// union engine ready every other cycle, the core's fastest.
fn striped_frame_backs_up_to_the_input(fsize: usize) {
    let p = build(fsize);
    let f = frames::stripes(&p, p.cols);
    let mut b = Bench::new(&p, 0xb10b + fsize as u64);
    b.frame(
        "striped",
        &f,
        Drive {
            gap: 0.0,
            ready: 0.2,
        },
    );
    b.report("striped, slow union engine");
    assert!(
        b.count.credit_stalls > 0,
        "K {fsize}: the input never waited for a credit"
    );
    if fsize >= 5 {
        assert!(
            b.count.max_queued >= JQ_HIGH_LEVEL,
            "K {fsize}: the join queue never filled ({} joins at most, room goes low at {})",
            b.count.max_queued,
            JQ_HIGH_LEVEL
        );
    }
    // The frame of the top-level test `join_queue_fills_and_holds_the_input`.
    if fsize >= 9 {
        let mut b = Bench::new(&p, 0xba9d + fsize as u64);
        let band = Drive {
            gap: 0.0,
            ready: 0.5,
        };
        b.frame("stripes, 120 columns", &frames::stripes(&p, 120), band);
        b.report("stripes 120 columns, union engine ready every other cycle");
        assert!(
            b.count.max_queued >= JQ_HIGH_LEVEL,
            "K {fsize}: 120 columns of stripes never filled the join queue ({} joins at most)",
            b.count.max_queued
        );
    }
}

macro_rules! per_k {
    ($($k:literal: $all:ident, $blob:ident;)*) => {$(
        #[test]
        fn $all() {
            every_frame_kind($k);
        }
        #[test]
        fn $blob() {
            striped_frame_backs_up_to_the_input($k);
        }
    )*};
}

per_k! {
    3: random_directed_and_scene_frames_connect_as_golden_fsize3, striped_frame_with_slow_union_engine_fsize3;
    7: random_directed_and_scene_frames_connect_as_golden_fsize7, striped_frame_with_slow_union_engine_fsize7;
    11: random_directed_and_scene_frames_connect_as_golden_fsize11, striped_frame_with_slow_union_engine_fsize11;
}
