//! The column core's slot buffer `fcc_col_slot_buf` (behind
//! `FccColSlotBufProbe`) alone under Verilator, against a model of its
//! module documentation: the input takes a slot only in the cycle after
//! `room` (registered: fewer than `SLOT_CREDITS` credits out at the last
//! edge), as the input stage's registered ready does, and each slot
//! reaches the buffer `FRONT_LATENCY + 1` cycles after it was taken (the
//! stage's slot register and the front), and the consumer takes the head at random,
//! in bursts, or every cycle. Every slot must leave in order with its
//! fields, hits and labels; the buffer never holds more than `SLOT_BUF`;
//! a slot waiting six cycles is at the head; with the consumer taking
//! every cycle, a slot leaves every cycle; a reset empties it and returns
//! every credit. At K = 3, 7 and 11 (one, six and fourteen label lanes).
//! A mismatch prints K, the cycle, expected, got and the seed.

use std::collections::VecDeque;

use fcc_params::FccParams;
use fcc_rtl::{BenchBlock, FRONT_LATENCY, SLOT_BUF, SLOT_CREDITS};
use fcc_sim::{c_struct, load_plain, PlainDut};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

c_struct! {
    /// Inputs of one cycle, named as the probe's ports.
    pub struct SbIn {
        pub hits: u64,
        pub lw0: u64,
        pub lw1: u64,
        pub lw2: u64,
        pub lw3: u64,
        pub lw4: u64,
        pub lw5: u64,
        pub lw6: u64,
        pub lw7: u64,
        pub lw8: u64,
        pub lw9: u64,
        pub lw10: u64,
        pub lw11: u64,
        pub lw12: u64,
        pub lw13: u64,
        pub col: u16,
        pub label: u16,
        pub rst: u8,
        pub slot: u8,
        pub push: u8,
        pub row: u8,
        pub start: u8,
        pub take: u8,
    }
}

c_struct! {
    /// Outputs during one cycle.
    pub struct SbOut {
        pub o_hits: u64,
        pub o0: u64,
        pub o1: u64,
        pub o2: u64,
        pub o3: u64,
        pub o4: u64,
        pub o5: u64,
        pub o6: u64,
        pub o7: u64,
        pub o8: u64,
        pub o9: u64,
        pub o10: u64,
        pub o11: u64,
        pub o12: u64,
        pub o13: u64,
        pub o_col: u16,
        pub o_label: u16,
        pub room: u8,
        pub valid: u8,
        pub o_valid: u8,
        pub o_row: u8,
        pub o_start: u8,
    }
}

/// One slot as pushed: a few centre fields, the hits, the label words.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
struct Slot {
    row: u8,
    col: u16,
    label: u16,
    start: u8,
    hits: u64,
    words: [u64; 14],
}

impl Slot {
    fn random(rng: &mut ChaCha8Rng, n: usize) -> Slot {
        let mut words = [0u64; 14];
        for (w, word) in words.iter_mut().enumerate() {
            for m in 0..4 {
                if 4 * w + m < n {
                    *word |= u64::from(rng.gen::<u16>()) << (16 * m);
                }
            }
        }
        Slot {
            row: rng.gen_range(0..128),
            col: rng.gen_range(0..4096),
            label: rng.gen(),
            start: rng.gen_range(0..2),
            hits: rng.gen::<u64>() & ((1u64 << n) - 1),
            words,
        }
    }

    fn of(o: &SbOut) -> Slot {
        Slot {
            row: o.o_row,
            col: o.o_col,
            label: o.o_label,
            start: o.o_start,
            hits: o.o_hits,
            words: [
                o.o0, o.o1, o.o2, o.o3, o.o4, o.o5, o.o6, o.o7, o.o8, o.o9, o.o10, o.o11, o.o12,
                o.o13,
            ],
        }
    }
}

/// How the consumer takes the head.
#[derive(Clone, Copy, Debug)]
enum Take {
    Random(f64),
    Bursts,
    Always,
}

/// Run `cycles` cycles at K = `k`; returns the slots that left.
fn run(k: usize, take: Take, offer: f64, resets: f64, cycles: usize, seed: u64) -> usize {
    let build = FccParams {
        fsize: k,
        ..FccParams::default()
    };
    let n = build.window_positions();
    let model = load_plain::<SbIn, SbOut>(BenchBlock::ColSlotBuf, &build).expect("slot buffer");
    let mut dut = PlainDut::new(model);
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let delay = FRONT_LATENCY + 1;
    // The front: slots taken, on their way to the buffer.
    let mut front: VecDeque<Option<Slot>> = VecDeque::from(vec![None; delay]);
    // In the buffer, with the cycle each was pushed.
    let mut queue: VecDeque<(Slot, usize)> = VecDeque::new();
    let (mut credits, mut room, mut ready) = (0usize, true, false);
    let mut left = 0;
    let mut burst = false;
    let mut rst = true;
    for t in 0..cycles {
        let at = format!("K = {k}, {take:?}, cycle {t}, seed {seed}");
        // The stage's ready: `room` of the cycle before.
        let slot = ready && !rst && rng.gen_bool(offer);
        let pushed = front.pop_front().unwrap();
        let taking = match take {
            Take::Random(p) => rng.gen_bool(p),
            Take::Bursts => {
                if rng.gen_bool(0.02) {
                    burst = !burst;
                }
                burst
            }
            Take::Always => true,
        };
        let mut i = SbIn {
            rst: rst as u8,
            slot: slot as u8,
            take: taking as u8,
            ..SbIn::default()
        };
        if let Some(s) = pushed.filter(|_| !rst) {
            i.push = 1;
            (i.row, i.col, i.label, i.start, i.hits) = (s.row, s.col, s.label, s.start, s.hits);
            [
                i.lw0, i.lw1, i.lw2, i.lw3, i.lw4, i.lw5, i.lw6, i.lw7, i.lw8, i.lw9, i.lw10,
                i.lw11, i.lw12, i.lw13,
            ] = s.words;
        }
        let o = dut.step(&i);
        if !rst {
            assert_eq!(o.room != 0, room, "{at}: room");
            if let Some(&(_, since)) = queue.front() {
                assert!(
                    o.valid != 0 || t < since + 6,
                    "{at}: a slot pushed at cycle {since} is not at the head"
                );
            }
            if o.valid != 0 {
                let (want, _) = queue
                    .front()
                    .copied()
                    .unwrap_or_else(|| panic!("{at}: a head with no slot in the buffer"));
                assert_eq!(o.o_valid, 1, "{at}: the head's centre is not valid");
                assert_eq!(Slot::of(&o), want, "{at}: the head");
                if taking {
                    queue.pop_front();
                    left += 1;
                }
            }
        }
        // The edge.
        let popped = !rst && taking && o.valid != 0;
        if let Some(s) = pushed.filter(|_| !rst) {
            queue.push_back((s, t));
            assert!(
                queue.len() <= SLOT_BUF,
                "{at}: {} slots in the buffer",
                queue.len()
            );
        }
        ready = room && !rst;
        room = credits < SLOT_CREDITS;
        credits = credits + usize::from(slot) - usize::from(popped);
        front.push_back(slot.then(|| Slot::random(&mut rng, n)));
        if rst {
            queue.clear();
            credits = 0;
            room = true;
            front.iter_mut().for_each(|s| *s = None);
        }
        rst = rng.gen_bool(resets);
    }
    left
}

#[test]
fn slots_leave_in_order_and_the_credits_keep_it_from_overflowing() {
    for (k, seed) in [(3, 1u64), (7, 2), (11, 3)] {
        for (take, offer) in [
            (Take::Random(0.5), 0.9),
            (Take::Random(0.95), 1.0),
            (Take::Bursts, 1.0),
            (Take::Random(0.1), 0.6),
        ] {
            let left = run(k, take, offer, 0.0, 6_000, seed);
            assert!(left > 300, "K = {k}, {take:?}: only {left} slots left");
        }
        run(k, Take::Random(0.7), 0.9, 0.002, 20_000, seed + 10);
    }
}

/// With the consumer taking every cycle and a slot offered every cycle, a
/// slot leaves every cycle once the first has come through.
#[test]
fn a_slot_a_cycle_while_the_consumer_takes() {
    let cycles = 4_000;
    let left = run(7, Take::Always, 1.0, 0.0, cycles, 7);
    let through = cycles - (FRONT_LATENCY + 1) - 8;
    assert!(
        left >= through,
        "{left} slots left in {cycles} cycles, fewer than {through}"
    );
}
