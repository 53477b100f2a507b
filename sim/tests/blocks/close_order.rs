//! The column core's closer's sorted entries `fcc_close_order` alone under
//! Verilator, against a model of its contract (docs/column-core.md, item
//! 4): entries taken and the head given up, one of each a cycle at most,
//! in phases that fill the array, drain it, keep it half full and push
//! into it full (each push then drops the largest entry, the new one
//! included); keys over a few values (many equal, which leave in the order
//! they came), over the whole range and at its ends; resets mid-run. Every
//! cycle the head, `full` and the entry dropped are checked. A mismatch
//! prints the cycle, expected, got and the seed.

use std::collections::VecDeque;

use fcc_params::FccParams;
use fcc_rtl::{BenchBlock, CLOSE_ENTRIES, CLOSE_KEY_BITS};
use fcc_sim::{c_struct, load_plain, PlainDut};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

c_struct! {
    /// Inputs of one cycle, named as the ports.
    pub struct CoIn {
        pub rst: u8,
        pub in_valid: u8,
        pub in_key: u32,
        pub in_slot: u16,
        pub pop: u8,
    }
}

c_struct! {
    /// Outputs during one cycle.
    pub struct CoOut {
        pub full: u8,
        pub head_valid: u8,
        pub head_key: u32,
        pub head_slot: u16,
        pub drop_valid: u8,
        pub drop_key: u32,
        pub drop_slot: u16,
    }
}

/// The largest key.
const KEY_MAX: u32 = (1 << CLOSE_KEY_BITS) - 1;

fn key(rng: &mut ChaCha8Rng, spread: u32) -> u32 {
    match rng.gen_range(0..20) {
        0 => 0,
        1 => KEY_MAX,
        _ if spread == 0 => rng.gen_range(0..=KEY_MAX),
        _ => rng.gen_range(0..spread),
    }
}

/// What one bench run saw.
#[derive(Default)]
struct Seen {
    pushes: u64,
    pops: u64,
    full: u64,
    /// Old last entries dropped, and new ones.
    dropped_old: u64,
    dropped_new: u64,
}

/// Seeded traffic.
fn run(seed: u64, cycles: u64) -> Seen {
    let model = load_plain::<CoIn, CoOut>(BenchBlock::CloseOrder, &FccParams::default())
        .expect("close order model");
    let mut d = PlainDut::new(model);
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut want: VecDeque<(u32, u16)> = VecDeque::new();
    let mut seen = Seen::default();
    let (mut push_p, mut pop_p, mut spread) = (0.5, 0.5, 8);
    d.step(&CoIn {
        rst: 1,
        ..CoIn::default()
    });
    for cycle in 0..cycles {
        if cycle % 500 == 0 {
            (push_p, pop_p) =
                [(0.9, 0.1), (0.1, 0.9), (0.5, 0.5), (1.0, 1.0), (0.3, 0.0)][rng.gen_range(0..5)];
            spread = [0, 4, 64, 4096][rng.gen_range(0..4)];
        }
        let rst = rng.gen_range(0..20_000) == 0;
        let inp = CoIn {
            rst: rst as u8,
            in_valid: rng.gen_bool(push_p) as u8,
            in_key: key(&mut rng, spread),
            in_slot: rng.gen_range(0..512),
            pop: (rng.gen_bool(pop_p) && !want.is_empty()) as u8,
        };
        let o = d.step(&inp);
        let mut next = want.clone();
        let mut dropped = None;
        if inp.pop != 0 {
            next.pop_front();
        }
        if inp.in_valid != 0 {
            // After the entries of an equal key.
            let at = next.partition_point(|&(k, _)| k <= inp.in_key);
            next.insert(at, (inp.in_key, inp.in_slot));
            if next.len() > CLOSE_ENTRIES {
                dropped = next.pop_back();
            }
        }
        let got = (
            o.full,
            o.head_valid,
            (o.head_valid != 0).then_some((o.head_key, o.head_slot)),
            (o.drop_valid != 0).then_some((o.drop_key, o.drop_slot)),
        );
        let expected = (
            (want.len() == CLOSE_ENTRIES) as u8,
            !want.is_empty() as u8,
            want.front().copied(),
            dropped,
        );
        assert_eq!(
            expected, got,
            "seed {seed:#x}, cycle {cycle}: (full, head_valid, head, dropped) expected (left), got (right)"
        );
        seen.full += u64::from(o.full != 0);
        if rst {
            want.clear();
            continue;
        }
        seen.pushes += u64::from(inp.in_valid);
        seen.pops += u64::from(inp.pop);
        if let Some(d) = dropped {
            if d == (inp.in_key, inp.in_slot) {
                seen.dropped_new += 1;
            } else {
                seen.dropped_old += 1;
            }
        }
        want = next;
    }
    seen
}

#[test]
fn the_head_is_the_smallest_key_first_come_among_equals() {
    let mut all = Seen::default();
    for seed in [0xc1, 0xc2, 0xc3] {
        let s = run(seed, 60_000);
        println!(
            "seed {seed:#x}: {} entries in, {} heads given up, {} cycles full, \
             {} old last entries and {} new ones dropped",
            s.pushes, s.pops, s.full, s.dropped_old, s.dropped_new
        );
        all.pushes += s.pushes;
        all.pops += s.pops;
        all.full += s.full;
        all.dropped_old += s.dropped_old;
        all.dropped_new += s.dropped_new;
    }
    assert!(
        all.pushes > 50_000
            && all.pops > 50_000
            && all.full > 5_000
            && all.dropped_old > 1_000
            && all.dropped_new > 1_000,
        "too little traffic"
    );
}
