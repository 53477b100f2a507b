//! The column core's flushes' wait `fcc_flush_wait` alone under Verilator
//! (built for the run accumulators' flush latency), against its contract:
//! an upstream shaped as `FccRunAcc` lets a pixel in only while `room`
//! (each flushing, if at all, exactly `RUN_ACC_LATENCY` cycles later), then
//! a frame end's rows, one a cycle while `room` (each flushing five cycles
//! later); a consumer takes the head now and then, in bursts, or not for
//! a while. Checked every cycle: the accumulators leave in the order they
//! came, every field as pushed; `bad` never set while upstream honours
//! `room`; with every pixel flushing and nothing taken the places fill to
//! exactly [`FLUSH_WAIT`], no fewer (so `room` falls no earlier than it
//! must); `idle` exactly when none waits. And `bad` set by a push with
//! every place held, or a take with none, until a reset, which empties
//! the places. A mismatch prints the cycle, expected, got and the seed.

use std::collections::VecDeque;

use fcc_params::FccParams;
use fcc_rtl::{BenchBlock, FLUSH_WAIT, RUN_ACC_LATENCY};
use fcc_sim::{c_struct, load_plain, PlainDut};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

c_struct! {
    /// Inputs of one cycle, named as the ports.
    pub struct FwIn {
        pub rst: u8,
        pub push: u8,
        pub tag: u64,
        pub take: u8,
        pub take_none: u8,
    }
}

c_struct! {
    /// Outputs during one cycle.
    pub struct FwOut {
        pub took: u8,
        pub valid: u8,
        pub o_tag: u64,
        pub o_agree: u8,
        pub room: u8,
        pub idle: u8,
        pub bad: u8,
    }
}

/// A frame end's row flushes this many cycles after it is let in.
const DRAIN_LATENCY: usize = 5;
const TAG_MASK: u64 = (1 << 51) - 1;

/// One phase of traffic: cycles, the chance a pixel is offered in a
/// cycle, that a pixel flushes, that the consumer takes the head.
#[derive(Debug, Clone, Copy)]
struct Phase {
    cycles: usize,
    offer: f64,
    flush: f64,
    take: f64,
    /// After the phase, a frame end: `rows` rows, each flushing with
    /// chance `flush`.
    rows: usize,
}

struct Bench {
    dut: PlainDut<FwIn, FwOut>,
    rng: ChaCha8Rng,
    seed: u64,
    cycle: u64,
    /// Tags on their way from upstream, by cycles left (0: pushes now).
    line: VecDeque<Option<u64>>,
    /// Tags waiting, oldest first, as the block should hold them.
    want: VecDeque<u64>,
    next_tag: u64,
    pushed: u64,
    taken: u64,
    peak: usize,
    held_cycles: u64,
}

impl Bench {
    fn new(seed: u64) -> Bench {
        let model = load_plain::<FwIn, FwOut>(BenchBlock::FlushWait, &FccParams::default())
            .expect("flushes' wait model");
        let mut b = Bench {
            dut: PlainDut::new(model),
            rng: ChaCha8Rng::seed_from_u64(seed),
            seed,
            cycle: 0,
            line: VecDeque::from(vec![None; RUN_ACC_LATENCY + 1]),
            want: VecDeque::new(),
            next_tag: seed << 32,
            pushed: 0,
            taken: 0,
            peak: 0,
            held_cycles: 0,
        };
        b.reset();
        b
    }

    fn reset(&mut self) {
        self.dut.step(&FwIn {
            rst: 1,
            ..FwIn::default()
        });
        self.line.iter_mut().for_each(|x| *x = None);
        self.want.clear();
        self.cycle += 1;
    }

    fn tag(&mut self) -> u64 {
        self.next_tag += 1;
        (self.next_tag.wrapping_mul(0x9e37_79b9_7f4a_7c15) >> 7) & TAG_MASK
    }

    /// One cycle: upstream lets in an item (`offer`: pixel or frame-end
    /// row, with its latency) only if `room` shows, the consumer takes the
    /// head with chance `take`; every output checked. Returns whether the
    /// item was let in.
    fn step(&mut self, offer: Option<usize>, flush: f64, take: f64) -> bool {
        let push = self.line.pop_front().expect("the line's length is fixed");
        self.line.push_back(None);
        let what = format!("cycle {}, seed {:#x}", self.cycle, self.seed);
        // The consumer takes the head, if one shows (`took`).
        let o = self.dut.step(&FwIn {
            rst: 0,
            push: u8::from(push.is_some()),
            tag: push.unwrap_or(0),
            take: u8::from(self.rng.gen_bool(take)),
            take_none: 0,
        });
        let taking = o.took != 0;
        assert_eq!(o.took & !o.valid & 1, 0, "{what}: took with no head");
        assert_eq!(o.bad, 0, "{what}: bad set");
        assert_eq!(
            o.idle != 0,
            self.want.is_empty(),
            "{what}: idle, with {} waiting",
            self.want.len()
        );
        if o.valid != 0 {
            let head = *self.want.front().unwrap_or_else(|| {
                panic!(
                    "{what}: a head shown with none waiting (tag {:#x})",
                    o.o_tag
                )
            });
            assert_eq!(o.o_tag, head, "{what}: the head's tag");
            assert_eq!(o.o_agree, 1, "{what}: a field of the head not as pushed");
        }
        if taking {
            self.want.pop_front();
            self.taken += 1;
        }
        if let Some(t) = push {
            self.want.push_back(t);
            self.pushed += 1;
        }
        self.peak = self.peak.max(self.want.len());
        self.cycle += 1;
        // Upstream's decision this cycle, on `room` as shown.
        let Some(latency) = offer else {
            return false;
        };
        if o.room == 0 {
            self.held_cycles += 1;
            return false;
        }
        if self.rng.gen_bool(flush) {
            let t = self.tag();
            // Pushed `latency` cycles after this one.
            self.line[latency - 1] = Some(t);
        }
        true
    }

    fn run(&mut self, ph: Phase) {
        for _ in 0..ph.cycles {
            let offer = self.rng.gen_bool(ph.offer).then_some(RUN_ACC_LATENCY);
            self.step(offer, ph.flush, ph.take);
        }
        // The frame end: pixels already let in first (the rows read once
        // the last pixel has been), then a row a cycle while `room`; the
        // consumer takes now and then at least, or the rows never end.
        let take = ph.take.max(0.05);
        for _ in 0..RUN_ACC_LATENCY - DRAIN_LATENCY {
            self.step(None, 0.0, take);
        }
        let (mut left, mut cycles) = (ph.rows, 0);
        while left > 0 {
            if self.step(Some(DRAIN_LATENCY), ph.flush, take) {
                left -= 1;
            }
            cycles += 1;
            assert!(
                cycles < 100 * (ph.rows + FLUSH_WAIT),
                "seed {:#x}: room never came back at the frame end ({} waiting)",
                self.seed,
                self.want.len()
            );
        }
    }

    /// Take everything left; the block must end idle, with room.
    fn drain(&mut self) {
        for _ in 0..4 * FLUSH_WAIT + 2 * RUN_ACC_LATENCY {
            self.step(None, 0.0, 1.0);
        }
        let what = format!("seed {:#x}", self.seed);
        assert!(self.want.is_empty(), "{what}: {} left", self.want.len());
        let o = self.dut.step(&FwIn::default());
        assert!(o.idle == 1 && o.room == 1 && o.valid == 0, "{what}: {o:?}");
    }
}

/// Every pixel flushing and nothing taken: the places fill to exactly
/// [`FLUSH_WAIT`], upstream then held until the consumer takes; the frame
/// end's rows too. Then emptied in order.
#[test]
fn the_places_fill_exactly_and_empty_in_order() {
    let mut b = Bench::new(0xf1);
    b.run(Phase {
        cycles: 400,
        offer: 1.0,
        flush: 1.0,
        take: 0.0,
        rows: 0,
    });
    assert_eq!(
        b.peak, FLUSH_WAIT,
        "pixels flushing every cycle: the most held"
    );
    assert!(
        b.held_cycles > 200,
        "upstream held {} cycles",
        b.held_cycles
    );
    b.drain();
    // A frame end's rows alone, every one flushing, nothing taken: they
    // flush sooner than a pixel, so they stop with the pixels' margin
    // less their own latency unused.
    b.peak = 0;
    let mut rows = 0;
    for _ in 0..400 {
        rows += usize::from(b.step(Some(DRAIN_LATENCY), 1.0, 0.0));
    }
    let want = FLUSH_WAIT - RUN_ACC_LATENCY + DRAIN_LATENCY;
    assert_eq!(
        (rows, b.peak),
        (want, want),
        "frame-end rows alone: let in, held at most"
    );
    b.drain();
    assert_eq!(b.pushed, b.taken);
}

/// Seeded traffic: pixels offered, flushing, the consumer taking, at
/// rates from sparse to saturated, with frame ends of up to 128 rows.
#[test]
fn random_traffic_keeps_order_and_never_overflows() {
    for seed in 0..6u64 {
        let mut b = Bench::new(0x100 + seed);
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        for _ in 0..12 {
            let ph = Phase {
                cycles: rng.gen_range(50..1500),
                offer: [0.3, 0.8, 1.0][rng.gen_range(0..3)],
                flush: [0.15, 0.5, 1.0][rng.gen_range(0..3)],
                take: [0.0, 0.05, 0.3, 0.5, 1.0][rng.gen_range(0..5)],
                rows: [0, 5, 64, 128][rng.gen_range(0..4)],
            };
            b.run(ph);
        }
        b.drain();
        assert!(
            b.peak > FLUSH_WAIT / 2,
            "seed {seed}: at most {} held",
            b.peak
        );
        assert_eq!(b.pushed, b.taken, "seed {seed}");
        eprintln!(
            "seed {seed}: {} accumulators through, {} held at most, upstream held {} cycles",
            b.pushed, b.peak, b.held_cycles
        );
    }
}

/// A push with every place held and none taken, or a take with none
/// waiting, sets `bad` until a reset; the reset empties the places.
#[test]
fn overflow_and_a_take_of_none_are_bad_until_reset() {
    let mut b = Bench::new(0xbad);
    let step = |b: &mut Bench, push: bool, take: bool| {
        b.next_tag += 1;
        b.dut.step(&FwIn {
            rst: 0,
            push: u8::from(push),
            tag: b.next_tag & TAG_MASK,
            take: 0,
            take_none: u8::from(take),
        })
    };
    // A take with none waiting.
    let o = step(&mut b, false, true);
    assert_eq!(o.bad, 0);
    let o = step(&mut b, false, false);
    assert_eq!(o.bad, 1, "a take of none");
    b.reset();
    let o = step(&mut b, false, false);
    assert_eq!(o.bad, 0, "bad not cleared by the reset");
    // Every place, then one more, ignoring `room`.
    for n in 0..FLUSH_WAIT {
        let o = step(&mut b, true, false);
        assert_eq!(o.bad, 0, "push {n}");
    }
    // With every place held, a push and a take together are fine.
    for _ in 0..3 {
        step(&mut b, false, false);
    }
    let o = step(&mut b, true, true);
    assert_eq!((o.bad, o.room, o.valid), (0, 0, 1), "a push with a take");
    let o = step(&mut b, true, false);
    assert_eq!(o.bad, 0);
    let o = step(&mut b, false, false);
    assert_eq!(o.bad, 1, "a push with every place held");
    let o = step(&mut b, false, false);
    assert_eq!(o.bad, 1, "bad is sticky");
    b.reset();
    let o = b.dut.step(&FwIn::default());
    assert_eq!(
        (o.bad, o.valid, o.idle, o.room),
        (0, 0, 1, 1),
        "after the reset: empty"
    );
}
