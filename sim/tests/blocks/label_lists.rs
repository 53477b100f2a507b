//! The column core's label lists `fcc_label_lists` alone under Verilator,
//! against a model of its contract (docs/column-core.md, item 3):
//! clusters made with a free label each, united (the kept list's tail
//! linked to the gone list's head) and closed (their list queued and
//! walked), their labels free again once returned and made again, many
//! times over, so that every `next` is written over and over; long lists
//! and short ones, closes in bursts (the queue filling, closes held while
//! `walk_room` is low) and sparse; resets mid-run. Every label returned
//! must be the next the model expects (the lists in the order queued,
//! each head to tail), and a walk returns a label every other cycle, the
//! next list's head right after a tail. A mismatch prints the cycle,
//! expected, got and the seed.

use std::collections::VecDeque;

use fcc_params::FccParams;
use fcc_rtl::BenchBlock;
use fcc_sim::{c_struct, load_plain, PlainDut, PlainModel};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

c_struct! {
    /// Inputs of one cycle, named as the ports.
    pub struct LlIn {
        pub rst: u8,
        pub link_valid: u8,
        pub link_from: u16,
        pub link_to: u16,
        pub walk_valid: u8,
        pub walk_head: u16,
        pub walk_tail: u16,
    }
}

c_struct! {
    /// Outputs during one cycle.
    pub struct LlOut {
        pub walk_room: u8,
        pub ret_valid: u8,
        pub ret_label: u16,
        pub idle: u8,
    }
}

/// Cycles from a list queued into an idle block to its head returned (the
/// queue's write, its read two cycles, its output register).
const QUEUE_IN: u64 = 4;

/// What the runs saw, to show each rule was exercised.
#[derive(Debug, Default, Clone, Copy)]
struct Seen {
    links: u64,
    walks: u64,
    returned: u64,
    longest: usize,
    /// Cycles `walk_room` was low.
    no_room: u64,
    /// Labels made again after their return.
    remade: u64,
}

struct Bench {
    d: PlainDut<LlIn, LlOut>,
    /// Free labels, never made first.
    free: VecDeque<u16>,
    made: Vec<bool>,
    clusters: Vec<VecDeque<u16>>,
    /// Labels due back, in order, each with whether it ends its list.
    expect: VecDeque<(u16, bool)>,
    /// The cycle of the last label returned, and whether it ended a list.
    last_ret: Option<(u64, bool)>,
    cycle: u64,
    seen: Seen,
    what: String,
}

impl Bench {
    fn new(model: &PlainModel<LlIn, LlOut>, max_label: u16, what: String) -> Bench {
        let mut b = Bench {
            d: PlainDut::new(model.clone()),
            free: VecDeque::new(),
            made: vec![],
            clusters: vec![],
            expect: VecDeque::new(),
            last_ret: None,
            cycle: 0,
            seen: Seen::default(),
            what,
        };
        b.reset(max_label);
        b
    }

    fn reset(&mut self, max_label: u16) {
        self.step(LlIn {
            rst: 1,
            ..LlIn::default()
        });
        self.free = (1..=max_label).collect();
        self.made = vec![false; max_label as usize + 1];
        self.clusters.clear();
        self.expect.clear();
        self.last_ret = None;
    }

    fn step(&mut self, inp: LlIn) -> LlOut {
        let o = self.d.step(&inp);
        let now = self.cycle;
        self.cycle += 1;
        if inp.rst != 0 {
            return o;
        }
        self.seen.no_room += u64::from(o.walk_room == 0);
        if o.ret_valid != 0 {
            let (want, ends) = self.expect.pop_front().unwrap_or_else(|| {
                panic!(
                    "{}, cycle {now}: label {} returned, none due",
                    self.what, o.ret_label
                )
            });
            assert_eq!(
                want, o.ret_label,
                "{}, cycle {now}: label returned expected (left), got (right)",
                self.what
            );
            // Every other cycle within a list; the next list's head may
            // follow a tail at once.
            if let Some((t, tail)) = self.last_ret {
                if !tail {
                    assert_eq!(
                        now - t,
                        2,
                        "{}, cycle {now}: cycles since the label before",
                        self.what
                    );
                }
            }
            self.last_ret = Some((now, ends));
            self.free.push_back(want);
            self.seen.returned += 1;
        }
        if o.idle != 0 {
            assert!(
                self.expect.is_empty(),
                "{}, cycle {now}: idle with {} labels due",
                self.what,
                self.expect.len()
            );
        }
        o
    }

    fn make(&mut self) {
        if let Some(l) = self.free.pop_front() {
            self.seen.remade += u64::from(self.made[l as usize]);
            self.made[l as usize] = true;
            self.clusters.push(VecDeque::from([l]));
        }
    }

    /// One cycle of seeded traffic: makes `p_make`, joins `p_join`,
    /// closes `p_close` (of the clusters, at one link or walk a cycle).
    fn traffic(&mut self, rng: &mut ChaCha8Rng, p: (f64, f64, f64), room: bool) -> bool {
        let (p_make, p_join, p_close) = p;
        if rng.gen_bool(p_make) {
            self.make();
        }
        let mut inp = LlIn::default();
        let mut walked = VecDeque::new();
        let n = self.clusters.len();
        if n >= 2 && rng.gen_bool(p_join) {
            let k = rng.gen_range(0..n);
            let mut g = rng.gen_range(0..n - 1);
            g += usize::from(g >= k);
            let gone = self.clusters[g].clone();
            let kept = &mut self.clusters[k];
            (inp.link_valid, inp.link_from, inp.link_to) = (1, *kept.back().unwrap(), gone[0]);
            kept.extend(gone);
            self.clusters.swap_remove(g);
            self.seen.links += 1;
        } else if n >= 1 && room && rng.gen_bool(p_close) {
            let c = self.clusters.swap_remove(rng.gen_range(0..n));
            (inp.walk_valid, inp.walk_head, inp.walk_tail) = (1, c[0], *c.back().unwrap());
            self.seen.walks += 1;
            self.seen.longest = self.seen.longest.max(c.len());
            walked = c;
        }
        let room = self.step(inp).walk_room != 0;
        // Due from the cycle after its push (the cycle's outputs are the
        // registers' before it).
        let last = walked.len().saturating_sub(1);
        self.expect
            .extend(walked.into_iter().enumerate().map(|(i, l)| (l, i == last)));
        room
    }

    fn drain(&mut self, limit: u64) {
        let start = self.cycle;
        loop {
            let idle = self.step(LlIn::default()).idle != 0;
            if idle && self.expect.is_empty() {
                break;
            }
            assert!(self.cycle - start < limit, "{}: labels left", self.what);
        }
    }
}

fn model(label_bits: u32) -> PlainModel<LlIn, LlOut> {
    let p = FccParams {
        label_bits,
        ..FccParams::default()
    };
    load_plain::<LlIn, LlOut>(BenchBlock::LabelLists, &p).expect("label lists model")
}

#[test]
fn every_label_comes_back_in_list_order() {
    let mut all = Seen::default();
    for (seed, label_bits, cycles) in [(0xe1, 8, 60_000), (0xe2, 13, 60_000), (0xe3, 8, 30_000)] {
        let model = model(label_bits);
        let max = ((1u32 << label_bits) - 1) as u16;
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut b = Bench::new(
            &model,
            max,
            format!("seed {seed:#x}, {label_bits}-bit labels"),
        );
        let mut room = true;
        let mut p = (0.5, 0.3, 0.1);
        for cycle in 0..cycles {
            if cycle % 2_000 == 0 {
                // Long lists (many joins, few closes or none), bursts of
                // closes (the queue fills), or short lists closed as made.
                p = [
                    (0.5, 0.45, 0.02),
                    (0.7, 0.6, 0.0),
                    (0.3, 0.0, 1.0),
                    (0.9, 0.2, 0.6),
                    (0.2, 0.1, 0.1),
                ][rng.gen_range(0..5)];
            }
            if cycle == cycles / 2 && seed == 0xe3 {
                b.reset(max);
                continue;
            }
            room = b.traffic(&mut rng, p, room);
        }
        b.drain(1 << 20);
        println!("seed {seed:#x}, {label_bits}-bit labels: {:?}", b.seen);
        let s = b.seen;
        all.links += s.links;
        all.walks += s.walks;
        all.returned += s.returned;
        all.longest = all.longest.max(s.longest);
        all.no_room += s.no_room;
        all.remade += s.remade;
    }
    println!("in all: {all:?}");
    assert!(
        all.links > 10_000
            && all.walks > 10_000
            && all.longest > 200
            && all.no_room > 100
            && all.remade > 20_000,
        "too little of some traffic: {all:?}"
    );
}

/// Three lists, the longest of 5,200 labels (more than the corpus's
/// largest return at one column, 5,186), queued in three cycles: every
/// label back in order, two cycles apart within a list, the next list's
/// head the cycle after a tail.
#[test]
fn a_long_list_comes_back_a_label_every_other_cycle() {
    let model = model(13);
    let mut b = Bench::new(&model, 8_191, "long lists".into());
    let sizes = [5_200, 1, 40];
    let mut lists = vec![];
    for &n in &sizes {
        let first = b.clusters.len();
        for _ in 0..n {
            b.make();
        }
        // Join them one by one into the first: each join a link.
        while b.clusters.len() > first + 1 {
            let gone = b.clusters.pop().unwrap();
            let kept = &mut b.clusters[first];
            let inp = LlIn {
                link_valid: 1,
                link_from: *kept.back().unwrap(),
                link_to: gone[0],
                ..LlIn::default()
            };
            kept.extend(gone);
            b.step(inp);
        }
        lists.push(b.clusters.pop().unwrap());
    }
    let start = b.cycle;
    for c in lists {
        let inp = LlIn {
            walk_valid: 1,
            walk_head: c[0],
            walk_tail: *c.back().unwrap(),
            ..LlIn::default()
        };
        b.step(inp);
        let last = c.len() - 1;
        b.expect
            .extend(c.into_iter().enumerate().map(|(i, l)| (l, i == last)));
    }
    b.drain(1 << 16);
    let total: usize = sizes.iter().sum();
    let first = start;
    let (end, _) = b.last_ret.expect("labels returned");
    println!(
        "{total} labels in {} lists back in {} cycles from the first queued",
        sizes.len(),
        end - first + 1
    );
    assert_eq!(b.seen.returned, total as u64);
    // Two cycles a label but for each list's head (one), and the first
    // head's way through the queue.
    let want = 2 * total as u64 - sizes.len() as u64 + QUEUE_IN;
    assert_eq!(end - first + 1, want, "cycles expected (left), got (right)");
}
