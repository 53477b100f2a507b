//! The word window `fcc_word_window` (one 16-bit lane behind
//! `FccWordWindowProbe`) alone under Verilator, for every K, against a
//! software window: h line buffers that read first and show a read two
//! cycles later (holding it until the next), a K x h block of registers that
//! shifts by one column (the last column from buffer h-1-r for row r), and
//! the cascade (buffer 0 takes the input word, buffer j the centre column of
//! row h-j). Words never written are unknown and not compared.
//!
//! First a frame scanned as the row-major core scans it (one pixel per busy
//! cycle with random gaps: its read at column (j + h) mod C in T0, its shift
//! and writes at column j in T2), where each entry of an in-image position
//! must also be the pixel h-r rows above and n-h columns beside the centre;
//! then seeded random enables and addresses (a few columns, so reads and
//! writes meet). One entry is compared per cycle, `ent_sel` chosen at
//! random. A mismatch prints K, the cycle, the entry, expected, got and the
//! seed.

use fcc_params::FccParams;
use fcc_rtl::BenchBlock;
use fcc_sim::{c_struct, load_plain, PlainDut, PlainModel};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

c_struct! {
    /// Inputs of one cycle, named as the ports.
    pub struct WwIn {
        pub read_addr: u16,
        pub in_data: u16,
        pub wr0_addr: u16,
        pub cas_addr: u16,
        pub read_en: u8,
        pub wr0_en: u8,
        pub cas_en: u8,
        pub shift: u8,
        pub ent_sel: u8,
    }
}

c_struct! {
    /// Outputs during one cycle.
    pub struct WwOut {
        pub ent: u16,
    }
}

/// Columns of every bench build (the smallest the hardware takes).
const COLS: usize = 256;

/// The window as the module documentation states it; `None` is a word never
/// written.
struct Model {
    k: usize,
    h: usize,
    mem: Vec<Vec<Option<u16>>>,
    /// Each buffer's read register and its output.
    rd1: Vec<Option<u16>>,
    rdata: Vec<Option<u16>>,
    win: Vec<Option<u16>>,
}

impl Model {
    fn new(k: usize) -> Self {
        let h = (k - 1) / 2;
        Model {
            k,
            h,
            mem: vec![vec![None; COLS]; h],
            rd1: vec![None; h],
            rdata: vec![None; h],
            win: vec![None; k * h],
        }
    }

    /// The entry `e` before the clock edge (zero past the last entry).
    fn entry(&self, e: usize) -> Option<u16> {
        if e < self.win.len() {
            self.win[e]
        } else {
            Some(0)
        }
    }

    /// The clock edge.
    fn step(&mut self, i: &WwIn) {
        let (k, h) = (self.k, self.h);
        let view: Vec<Option<u16>> = (0..k * h)
            .map(|e| {
                let (r, n) = (e / k, e % k);
                if n + 1 < k {
                    self.win[e + 1]
                } else {
                    self.rdata[h - 1 - r]
                }
            })
            .collect();
        for j in 0..h {
            self.rdata[j] = self.rd1[j];
            if i.read_en != 0 {
                self.rd1[j] = self.mem[j][i.read_addr as usize];
            }
        }
        if i.wr0_en != 0 {
            self.mem[0][i.wr0_addr as usize] = Some(i.in_data);
        }
        if i.cas_en != 0 {
            for j in 1..h {
                self.mem[j][i.cas_addr as usize] = view[(h - j) * k + h];
            }
        }
        if i.shift != 0 {
            self.win = view;
        }
    }
}

fn load(fsize: usize) -> PlainModel<WwIn, WwOut> {
    let p = FccParams {
        fsize,
        cols: COLS,
        ..FccParams::default()
    };
    load_plain::<WwIn, WwOut>(BenchBlock::WordWindow, &p).expect("word window model")
}

/// Run `cycles` through a fresh window and the model, comparing the entry
/// `ent_sel` of every cycle whose word is known; `check` sees the model
/// before each edge. Returns the number of entries compared.
fn run(
    fsize: usize,
    cycles: &[WwIn],
    what: &str,
    seed: u64,
    mut check: impl FnMut(usize, &Model),
) -> usize {
    let mut dut = PlainDut::new(load(fsize));
    let mut m = Model::new(fsize);
    let mut compared = 0;
    for (t, i) in cycles.iter().enumerate() {
        check(t, &m);
        let want = m.entry(i.ent_sel as usize);
        let got = dut.step(i).ent;
        if let Some(want) = want {
            assert_eq!(
                got, want,
                "{what}: K = {fsize}, entry {} differs at cycle {t} (input {i:?}): expected {want:#06x}, got {got:#06x}, seed {seed}",
                i.ent_sel
            );
            compared += 1;
        }
        m.step(i);
    }
    compared
}

/// The word of pixel (row, col) in the scanned frame.
fn word(row: usize, col: usize) -> u16 {
    ((row * COLS + col) as u16).wrapping_mul(40503) ^ 0x5a5a
}

#[test]
fn row_major_scan_builds_the_window_of_the_rows_above() {
    let rows = 7;
    for fsize in [3, 5, 7, 9, 11] {
        let seed = fsize as u64;
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let (k, h) = (fsize, (fsize - 1) / 2);
        // One slot per cycle: the pixel entering T0, or a gap.
        let mut slots: Vec<Option<(usize, usize)>> = Vec::new();
        for p in 0..rows * COLS {
            while rng.gen_bool(0.2) {
                slots.push(None);
            }
            slots.push(Some((p / COLS, p % COLS)));
        }
        slots.extend([None; 4]);
        let at = |t: usize| if t < slots.len() { slots[t] } else { None };
        let cycles: Vec<WwIn> = (0..slots.len())
            .map(|t| {
                let mut i = WwIn {
                    ent_sel: rng.gen_range(0..(k * h + 2)) as u8,
                    ..WwIn::default()
                };
                if let Some((_, col)) = at(t) {
                    i.read_en = 1;
                    i.read_addr = ((col + h) % COLS) as u16;
                }
                if let Some((row, col)) = t.checked_sub(2).and_then(at) {
                    i.shift = 1;
                    i.wr0_en = 1;
                    i.cas_en = 1;
                    i.wr0_addr = col as u16;
                    i.cas_addr = col as u16;
                    i.in_data = word(row, col);
                }
                i
            })
            .collect();
        // The centre of T3: every in-image position holds its pixel.
        let mut centres = 0;
        let compared = run(fsize, &cycles, "scan", seed, |t, m| {
            let Some((row, col)) = t.checked_sub(3).and_then(at) else {
                return;
            };
            centres += 1;
            for e in 0..k * h {
                let (r, n) = (e / k, e % k);
                let (Some(pr), Some(pc)) = ((row + r).checked_sub(h), (col + n).checked_sub(h))
                else {
                    continue;
                };
                if pc >= COLS {
                    continue;
                }
                assert_eq!(
                    m.win[e],
                    Some(word(pr, pc)),
                    "scan model: K = {fsize}, centre ({row}, {col}), entry {e} is not pixel ({pr}, {pc}), seed {seed}"
                );
            }
        });
        assert_eq!(centres, rows * COLS);
        assert!(
            compared > rows * COLS / 2,
            "K = {fsize}: only {compared} entries compared"
        );
    }
}

#[test]
fn seeded_random_enables_and_addresses() {
    for fsize in [3, 5, 7, 9, 11] {
        for seed in 0..2u64 {
            let mut rng = ChaCha8Rng::seed_from_u64(100 + seed);
            let (k, h) = (fsize, (fsize - 1) / 2);
            // A few columns, so that reads and writes meet on one address.
            let addr = |rng: &mut ChaCha8Rng| -> u16 {
                if rng.gen_bool(0.8) {
                    rng.gen_range(0..6)
                } else {
                    rng.gen_range(0..COLS as u16)
                }
            };
            let cycles: Vec<WwIn> = (0..20_000)
                .map(|_| WwIn {
                    read_addr: addr(&mut rng),
                    in_data: rng.gen(),
                    wr0_addr: addr(&mut rng),
                    cas_addr: addr(&mut rng),
                    read_en: rng.gen_bool(0.5) as u8,
                    wr0_en: rng.gen_bool(0.5) as u8,
                    cas_en: rng.gen_bool(0.5) as u8,
                    shift: rng.gen_bool(0.5) as u8,
                    ent_sel: rng.gen_range(0..(k * h + 2)) as u8,
                })
                .collect();
            let compared = run(fsize, &cycles, "random", 100 + seed, |_, _| {});
            assert!(
                compared > 10_000,
                "K = {fsize}: only {compared} entries compared"
            );
        }
    }
}
