//! The column core's closer's sorted entries `fcc_close_order` alone under
//! Verilator, against a model of its contract (docs/column-core.md, item
//! 4): entries taken and the head given up, one of each a cycle at most,
//! in phases that fill the array, drain it and keep it half full; keys
//! over a few values (many equal, which leave in the order they came),
//! over the whole range and at its ends; resets mid-run. Every cycle the
//! head and `in_ready` are checked. A mismatch prints the cycle, expected,
//! got and the seed.

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
        pub in_ready: u8,
        pub head_valid: u8,
        pub head_key: u32,
        pub head_slot: u16,
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

/// Seeded traffic; returns (entries taken, heads given up, cycles full).
fn run(seed: u64, cycles: u64) -> (u64, u64, u64) {
    let model = load_plain::<CoIn, CoOut>(BenchBlock::CloseOrder, &FccParams::default())
        .expect("close order model");
    let mut d = PlainDut::new(model);
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut want: VecDeque<(u32, u16)> = VecDeque::new();
    let (mut pushes, mut pops, mut full) = (0, 0, 0);
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
        let got = (
            o.in_ready,
            o.head_valid,
            (o.head_valid != 0).then_some((o.head_key, o.head_slot)),
        );
        let expected = (
            (want.len() < CLOSE_ENTRIES) as u8,
            !want.is_empty() as u8,
            want.front().copied(),
        );
        assert_eq!(
            expected, got,
            "seed {seed:#x}, cycle {cycle}: (in_ready, head_valid, head) expected (left), got (right)"
        );
        if rst {
            want.clear();
            continue;
        }
        if inp.pop != 0 {
            want.pop_front();
            pops += 1;
        }
        if inp.in_valid != 0 && o.in_ready != 0 {
            // After the entries of an equal key.
            let at = want.partition_point(|&(k, _)| k <= inp.in_key);
            want.insert(at, (inp.in_key, inp.in_slot));
            pushes += 1;
        }
        full += u64::from(o.in_ready == 0);
    }
    (pushes, pops, full)
}

#[test]
fn the_head_is_the_smallest_key_first_come_among_equals() {
    let (mut pushes, mut pops, mut full) = (0, 0, 0);
    for seed in [0xc1, 0xc2, 0xc3] {
        let (a, b, c) = run(seed, 60_000);
        println!("seed {seed:#x}: {a} entries taken, {b} heads given up, {c} cycles full");
        (pushes, pops, full) = (pushes + a, pops + b, full + c);
    }
    assert!(
        pushes > 50_000 && pops > 50_000 && full > 5_000,
        "too little traffic"
    );
}
