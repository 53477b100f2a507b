//! The front end's credit counter `fcc_credits` alone under Verilator,
//! against a software counter: every slot takes a credit, every drop and
//! every take returns one (both may in one cycle), `room` is registered and
//! high while fewer than `CREDITS` are out, `rst` returns them all. Directed
//! runs to the limit and back, then seeded random traffic that keeps the
//! count within the limit as the core does, with resets. A mismatch prints
//! the cycle, expected, got and the seed.

use fcc_params::FccParams;
use fcc_rtl::{BenchBlock, CREDITS};
use fcc_sim::{c_struct, load_plain, PlainDut};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

c_struct! {
    /// Inputs of one cycle, named as the ports.
    pub struct CrIn {
        pub rst: u8,
        pub slot: u8,
        pub drop: u8,
        pub take: u8,
    }
}

c_struct! {
    /// Outputs during one cycle.
    pub struct CrOut {
        pub room: u8,
    }
}

/// The counter as the module documentation states it.
#[derive(Default)]
struct Model {
    out: usize,
    room: bool,
}

impl Model {
    /// The output before the clock edge, then the edge.
    fn step(&mut self, i: &CrIn) -> bool {
        let room = self.room;
        self.room = self.out < CREDITS;
        self.out = self.out + i.slot as usize - i.drop as usize - i.take as usize;
        if i.rst != 0 {
            self.out = 0;
            self.room = true;
        }
        room
    }
}

/// Run `cycles` through a fresh counter and the model, comparing `room`.
fn run(cycles: &[CrIn], what: &str, seed: u64) {
    let p = FccParams::default();
    let model = load_plain::<CrIn, CrOut>(BenchBlock::Credits, &p).expect("credit counter model");
    let mut dut = PlainDut::new(model);
    let mut m = Model::default();
    for (t, i) in cycles.iter().enumerate() {
        let want = m.step(i);
        let got = dut.step(i).room != 0;
        assert_eq!(
            got, want,
            "{what}: room differs at cycle {t} (input {i:?}, credits out {}): expected {want}, got {got}, seed {seed}",
            m.out
        );
    }
}

fn cycle(rst: bool, slot: bool, drop: bool, take: bool) -> CrIn {
    CrIn {
        rst: rst as u8,
        slot: slot as u8,
        drop: drop as u8,
        take: take as u8,
    }
}

#[test]
fn credits_run_to_the_limit_and_back() {
    let mut c = vec![cycle(true, false, false, false); 2];
    // Take every credit and a few more, so that room falls at the limit.
    c.extend((0..CREDITS + 3).map(|_| cycle(false, true, false, false)));
    // Return two per cycle, then one with a slot beside it, then the rest.
    c.extend((0..CREDITS / 4).map(|_| cycle(false, false, true, true)));
    c.extend((0..8).map(|_| cycle(false, true, true, true)));
    c.extend((0..8).map(|_| cycle(false, true, true, false)));
    let left = CREDITS + 3 - 2 * (CREDITS / 4) - 8;
    c.extend((0..left - 3).map(|_| cycle(false, false, false, true)));
    // A reset with credits out.
    c.extend((0..100).map(|_| cycle(false, true, false, false)));
    c.push(cycle(true, true, true, false));
    c.extend((0..5).map(|_| cycle(false, false, false, false)));
    run(&c, "directed", 0);
}

#[test]
fn seeded_random_traffic_with_resets() {
    for seed in 0..4u64 {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut out = 0usize;
        let mut c = vec![cycle(true, false, false, false)];
        for _ in 0..20_000 {
            let rst = rng.gen_bool(0.002);
            // Busy phases fill the counter, quiet phases drain it.
            let slot = rng.gen_bool(if out < CREDITS { 0.6 } else { 0.1 });
            let drop = out > 0 && rng.gen_bool(0.3);
            let take = out > drop as usize && rng.gen_bool(0.25);
            out = out + slot as usize - drop as usize - take as usize;
            if rst {
                out = 0;
            }
            c.push(cycle(rst, slot, drop, take));
        }
        run(&c, "random", seed);
    }
}
