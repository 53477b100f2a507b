//! The column core's label pool `fcc_label_pool` alone under Verilator,
//! against a model of spec §9.1's labels in use: seeded random takes (in
//! bursts of one a cycle and sparse) and returns of labels in use, the
//! labels running out and reused many times over (B = 8 wraps the FIFO), a
//! `clear` (frame start) and a reset mid-run. Every cycle: a label handed
//! out is in `1 ..= 2^B - 1` and not in use; `free_count` is the labels
//! free (one cycle late); and the pool has a label to hand out whenever some
//! free label became free at least `POOL_LATENCY` cycles ago. A mismatch
//! prints the cycle, expected, got and the seed.

use std::collections::HashSet;

use fcc_params::FccParams;
use fcc_rtl::{BenchBlock, POOL_LATENCY};
use fcc_sim::{c_struct, load_plain, PlainDut};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

c_struct! {
    /// Inputs of one cycle, named as the ports.
    pub struct PoolIn {
        pub rst: u8,
        pub clear: u8,
        pub take: u8,
        pub ret: u8,
        pub ret_label: u16,
    }
}

c_struct! {
    /// Outputs during one cycle.
    pub struct PoolOut {
        pub free_ok: u8,
        pub free_label: u16,
        pub free_count: u16,
    }
}

/// The labels in use, and when each free label became free (fresh labels
/// at the clear, returned ones at their return), as spec §9.1 counts them.
struct Model {
    max: u16,
    in_use: Vec<u16>,
    used: HashSet<u16>,
    /// The cycle the labels never handed out since the clear became free,
    /// and how many there are.
    fresh_since: u64,
    fresh_left: u32,
    /// Returned labels not handed out again: the cycle each was returned.
    returned: Vec<u64>,
}

impl Model {
    fn new(max: u16, now: u64) -> Model {
        Model {
            max,
            in_use: Vec::new(),
            used: HashSet::new(),
            fresh_since: now,
            fresh_left: u32::from(max),
            returned: Vec::new(),
        }
    }

    fn free(&self) -> u32 {
        u32::from(self.max) - self.in_use.len() as u32
    }

    /// The earliest cycle any free label became free.
    fn oldest_free(&self) -> Option<u64> {
        let fresh = (self.fresh_left > 0).then_some(self.fresh_since);
        fresh.into_iter().chain(self.returned.iter().copied()).min()
    }
}

/// One seeded run of `cycles` cycles on a pool of `label_bits`-bit labels,
/// with a `clear` every `clear_every` cycles and a reset every `reset_every`.
fn run(label_bits: u32, seed: u64, cycles: u64, clear_every: u64, reset_every: u64) {
    let p = FccParams {
        label_bits,
        ..FccParams::default()
    };
    let model = load_plain::<PoolIn, PoolOut>(BenchBlock::LabelPool, &p).expect("label pool model");
    let mut d = PlainDut::new(model);
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let max = p.max_label() as u16;
    d.step(&PoolIn {
        rst: 1,
        ..PoolIn::default()
    });
    // The reset's cycle is 0: fresh labels are free from it.
    let mut m = Model::new(max, 0);
    // Take and return probabilities, changed every few hundred cycles:
    // bursts that run the labels out, sparse takes, returns only.
    let (mut p_take, mut p_ret) = (0.5, 0.5);
    let mut ran_out = 0;
    let mut reused = 0u64;
    for t in 1..=cycles {
        if t <= u64::from(max) + 50 {
            // First, every label handed out: the pool runs dry.
            (p_take, p_ret) = (1.0, 0.0);
        } else if t % 300 == 1 {
            (p_take, p_ret) = match rng.gen_range(0..5) {
                0 => (1.0, 0.1),
                1 => (0.9, 0.9),
                2 => (0.05, 0.3),
                3 => (0.0, 1.0),
                _ => (0.6, 0.5),
            };
        }
        let restart = t % clear_every == 0;
        let reset = t % reset_every == 0;
        let take = rng.gen_bool(p_take);
        let ret = !m.in_use.is_empty() && rng.gen_bool(p_ret) && !restart && !reset;
        let k = if ret {
            rng.gen_range(0..m.in_use.len())
        } else {
            0
        };
        let inp = PoolIn {
            rst: reset as u8,
            clear: restart as u8,
            take: take as u8,
            ret: ret as u8,
            ret_label: if ret { m.in_use[k] } else { 0 },
        };
        let o = d.step(&inp);
        let at = format!("cycle {t}, {label_bits}-bit labels, seed {seed:#x}");
        assert_eq!(
            u32::from(o.free_count),
            m.free(),
            "{at}: free_count: expected {}, got {}",
            m.free(),
            o.free_count
        );
        if o.free_ok == 0 {
            if let Some(since) = m.oldest_free() {
                assert!(
                    since + POOL_LATENCY as u64 > t,
                    "{at}: no label to hand out, but one has been free since cycle {since} ({} free)",
                    m.free()
                );
            }
        } else {
            let l = o.free_label;
            assert!(
                (1..=max).contains(&l) && !m.used.contains(&l),
                "{at}: handed out label {l}, in use or out of range"
            );
        }
        if reset || restart {
            m = Model::new(max, t);
            continue;
        }
        if ret {
            let l = m.in_use.swap_remove(k);
            m.used.remove(&l);
            m.returned.push(t);
        }
        if take && o.free_ok != 0 {
            let l = o.free_label;
            m.in_use.push(l);
            m.used.insert(l);
            // Which free label it was does not matter to the model: the
            // fresh ones while any are left, then the oldest returned.
            if m.fresh_left > 0 {
                m.fresh_left -= 1;
            } else {
                reused += 1;
                let oldest = (0..m.returned.len())
                    .min_by_key(|&i| m.returned[i])
                    .expect("a returned label is free");
                m.returned.swap_remove(oldest);
            }
        }
        ran_out += usize::from(m.free() == 0);
    }
    assert!(
        ran_out > 0 && reused > 2 * u64::from(max),
        "{label_bits}-bit labels, seed {seed:#x}: ran out {ran_out} cycles, {reused} labels reused"
    );
}

#[test]
fn labels_are_handed_out_once_and_free_again_when_returned() {
    run(8, 0x9001_0001, 120_000, 20_011, 47_017);
}

/// The record slots are this pool at 9 bits (`FccLabelPool::with_bits`,
/// slots 1 to 511).
#[test]
fn nine_bits_the_record_slots() {
    run(9, 0x9001_0003, 150_000, 40_009, 97_001);
}

#[test]
fn wider_labels_and_the_corpus_width() {
    run(13, 0x9001_0002, 600_000, 200_003, 310_007);
}
