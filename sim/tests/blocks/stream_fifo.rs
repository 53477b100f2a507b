//! The stream FIFO `fcc_stream_fifo` (16-bit words, 16 deep) alone under
//! Verilator, against its contract: words leave in the order pushed, as
//! pushed; a word pushed at cycle `t` is at the head from `t + 4` at the
//! soonest, and the head is valid exactly when the oldest word not taken
//! was pushed four cycles ago or earlier (so a consumer taking every cycle
//! is never kept waiting once the words are in); `level` counts the words
//! pushed and not taken one cycle late; `rst` empties it. Directed runs
//! (one word, a burst through, full and drained), then seeded random
//! traffic with resets. A mismatch prints the cycle, expected, got and the
//! seed.

use std::collections::VecDeque;

use fcc_params::FccParams;
use fcc_rtl::BenchBlock;
use fcc_sim::{c_struct, load_plain, PlainDut};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

c_struct! {
    /// Inputs of one cycle, named as the ports.
    pub struct SfIn {
        pub rst: u8,
        pub push: u8,
        pub din: u16,
        pub take: u8,
    }
}

c_struct! {
    /// Outputs during one cycle.
    pub struct SfOut {
        pub valid: u8,
        pub dout: u16,
        pub level: u8,
    }
}

/// Words the FIFO holds.
const DEPTH: usize = 16;
/// Cycles from a push to the word's soonest cycle at the head.
const SHOWS_AFTER: u64 = 4;

/// The contract, cycle by cycle.
struct Bench {
    dut: PlainDut<SfIn, SfOut>,
    seed: u64,
    cycle: u64,
    /// Words not taken, oldest first, with the cycle each was pushed.
    words: VecDeque<(u64, u16)>,
    /// Words not taken after the last edge, and `level` as registered.
    count: u8,
    level: u8,
}

impl Bench {
    fn new(seed: u64) -> Bench {
        let model = load_plain::<SfIn, SfOut>(BenchBlock::StreamFifo, &FccParams::default())
            .expect("stream FIFO model");
        let mut b = Bench {
            dut: PlainDut::new(model),
            seed,
            cycle: 0,
            words: VecDeque::new(),
            count: 0,
            level: 0,
        };
        b.step(true, None, false);
        b
    }

    fn room(&self) -> bool {
        self.words.len() < DEPTH
    }

    /// One cycle: outputs checked against the contract, then the edge.
    /// Returns whether a word was taken.
    fn step(&mut self, rst: bool, push: Option<u16>, take: bool) -> bool {
        let o = self.dut.step(&SfIn {
            rst: u8::from(rst),
            push: u8::from(push.is_some()),
            din: push.unwrap_or(0),
            take: u8::from(take),
        });
        let what = format!("cycle {}, seed {:#x}", self.cycle, self.seed);
        let head = self
            .words
            .front()
            .filter(|(t, _)| t + SHOWS_AFTER <= self.cycle);
        assert_eq!(
            o.valid != 0,
            head.is_some(),
            "{what}: valid: expected {}, got {} (words held, with their push cycles: {:?})",
            head.is_some(),
            o.valid != 0,
            self.words
        );
        if let Some(&(_, w)) = head {
            assert_eq!(
                o.dout, w,
                "{what}: the head: expected {w:#x}, got {:#x}",
                o.dout
            );
        }
        assert_eq!(
            o.level, self.level,
            "{what}: level: expected {}, got {}",
            self.level, o.level
        );
        let took = take && head.is_some();
        if rst {
            self.words.clear();
            self.count = 0;
            self.level = 0;
        } else {
            self.level = self.count;
            if took {
                self.words.pop_front();
            }
            if let Some(w) = push {
                assert!(
                    self.words.len() < DEPTH,
                    "{what}: the bench pushed into a full FIFO"
                );
                self.words.push_back((self.cycle, w));
            }
            self.count = self.words.len() as u8;
        }
        self.cycle += 1;
        took
    }
}

#[test]
fn stream_fifo_directed() {
    let mut b = Bench::new(0);
    // One word: at the head four cycles later, then taken.
    b.step(false, Some(0x1234), false);
    for _ in 0..6 {
        b.step(false, None, false);
    }
    assert!(b.step(false, None, true), "the one word was not taken");
    // A burst pushed and taken every cycle: one word leaves every cycle.
    let mut taken = 0;
    for i in 0..40u16 {
        let push = (i < 30).then_some(0x100 + i);
        if b.step(false, push, true) {
            taken += 1;
        }
    }
    assert_eq!(taken, 30, "a burst taken every cycle");
    // Filled to the brim, then drained every cycle.
    for i in 0..DEPTH as u16 {
        b.step(false, Some(0x200 + i), false);
    }
    for _ in 0..8 {
        b.step(false, None, false);
    }
    let mut run = 0;
    while b.step(false, None, true) {
        run += 1;
    }
    assert_eq!(run, DEPTH, "a full FIFO drained one word a cycle");
    // A reset with words held and in flight.
    for i in 0..6u16 {
        b.step(false, Some(0x300 + i), i % 2 == 0);
    }
    b.step(true, Some(0x3ff), true);
    for _ in 0..8 {
        b.step(false, None, true);
    }
}

#[test]
fn stream_fifo_random_traffic() {
    for seed in 1..=6u64 {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut b = Bench::new(seed);
        let (mut pushed, mut taken) = (0u64, 0u64);
        for phase in 0..80 {
            let offer: f64 = rng.gen_range(0.05..1.0);
            let take: f64 = [0.0, 0.3, 0.9, 1.0][phase % 4];
            for _ in 0..rng.gen_range(10..120) {
                let push = (b.room() && rng.gen_bool(offer)).then(|| rng.gen::<u16>());
                pushed += u64::from(push.is_some());
                if b.step(false, push, rng.gen_bool(take)) {
                    taken += 1;
                }
            }
            if rng.gen_bool(0.1) {
                let push = rng.gen_bool(0.5).then(|| rng.gen::<u16>());
                b.step(true, push, rng.gen_bool(0.5));
            }
        }
        assert!(
            pushed > 1500 && taken > 1500,
            "seed {seed:#x}: too little traffic ({pushed} pushed, {taken} taken)"
        );
    }
}
