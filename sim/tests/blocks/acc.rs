//! The column core's record accumulator (`FccAccPixel` and `FccAccMerge`
//! over the four registers of `FccAccProbe`) under Verilator, against the
//! golden record accumulator (`fcc_golden::Acc`, spec §9.3): seeded random
//! pixels (each given `ACC_PIXEL_LATENCY` cycles before its add) added to
//! slots, slots merged into others and emptied, resets;
//! each cycle one slot is read and must hold the golden accumulator's
//! values in the core's unsigned form (offset-binary sums, `sum(a b)` for
//! `sum_xy`; see `AccWord`). Coordinates at the ends of the Q7.8 range and
//! columns on both sides of `C/2` are among the pixels. A mismatch prints
//! the cycle, the slot, expected, got and the seed.

use fcc_golden::{Acc, Point};
use fcc_params::FccParams;
use fcc_rtl::{BenchBlock, ACC_PIXEL_LATENCY};
use fcc_sim::core_form::{offset_binary as ob, CoreAcc};
use fcc_sim::{c_struct, load_plain, PlainDut};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

c_struct! {
    /// Inputs of one cycle, named as the ports.
    pub struct AcIn {
        pub rst: u8,
        pub add: u8,
        pub merge: u8,
        pub clear: u8,
        pub s: u8,
        pub t: u8,
        pub x: u16,
        pub y: u16,
        pub z: u16,
        pub row: u8,
        pub col: u16,
        pub half: u16,
        pub rsel: u8,
    }
}

c_struct! {
    /// Outputs during one cycle: slot `rsel`.
    pub struct AcOut with acc_out {
    }
}

const SLOTS: usize = 4;
/// The fields of an accumulator in the core's form, as a comparable list
/// (a seam span's half compared only where the accumulator has it).
fn core_form(a: &Acc) -> Vec<(&'static str, u64)> {
    let c = CoreAcc::of(a);
    let mut v = vec![
        ("points", c.points),
        ("min_col", c.min_col),
        ("max_col", c.max_col),
        ("lo_has", c.lo_has),
        ("hi_has", c.hi_has),
        ("first_row", c.first_row),
        ("last_row", c.last_row),
        ("min_x", c.min[0]),
        ("min_y", c.min[1]),
        ("min_z", c.min[2]),
        ("max_x", c.max[0]),
        ("max_y", c.max[1]),
        ("max_z", c.max[2]),
        ("r2_min", c.r2_min),
        ("r2_max", c.r2_max),
        ("sa", c.sa),
        ("sb", c.sb),
        ("sc", c.sc),
        ("sxx", c.sxx),
        ("syy", c.syy),
        ("sab", c.sab),
        ("seam", c.seam),
    ];
    if c.lo_has != 0 {
        v.push(("lo_max", c.lo_max));
    }
    if c.hi_has != 0 {
        v.push(("hi_min", c.hi_min));
    }
    v
}

fn got_form(o: &AcOut, name: &str) -> u64 {
    match name {
        "points" => u64::from(o.o_points),
        "min_col" => u64::from(o.o_min_col),
        "max_col" => u64::from(o.o_max_col),
        "lo_has" => u64::from(o.o_lo_has),
        "lo_max" => u64::from(o.o_lo_max),
        "hi_has" => u64::from(o.o_hi_has),
        "hi_min" => u64::from(o.o_hi_min),
        "first_row" => u64::from(o.o_first_row),
        "last_row" => u64::from(o.o_last_row),
        "min_x" => u64::from(o.o_min_x),
        "min_y" => u64::from(o.o_min_y),
        "min_z" => u64::from(o.o_min_z),
        "max_x" => u64::from(o.o_max_x),
        "max_y" => u64::from(o.o_max_y),
        "max_z" => u64::from(o.o_max_z),
        "r2_min" => u64::from(o.o_r2_min),
        "r2_max" => u64::from(o.o_r2_max),
        "sa" => o.o_sa,
        "sb" => o.o_sb,
        "sc" => o.o_sc,
        "sxx" => o.o_sxx,
        "syy" => o.o_syy,
        "sab" => o.o_sab,
        "seam" => u64::from(o.o_seam),
        _ => unreachable!("{name}"),
    }
}

fn coord(rng: &mut ChaCha8Rng) -> i16 {
    match rng.gen_range(0..8) {
        0 => i16::MIN,
        1 => i16::MAX,
        2 => 0,
        3 => rng.gen_range(-3..=3),
        _ => rng.gen(),
    }
}

#[test]
fn accumulators_equal_the_golden_records_accumulators() {
    let model = load_plain::<AcIn, AcOut>(BenchBlock::Acc, &FccParams::default())
        .expect("record accumulator model");
    let mut d = PlainDut::new(model);
    for seed in 0..4u64 {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let cols: u32 = [256, 1024, 2048, 4096][seed as usize];
        let half = cols / 2;
        let mut slots = [Acc::default(); SLOTS];
        d.step(&AcIn {
            rst: 1,
            ..AcIn::default()
        });
        // The cycles' operations, then each pixel moved to the cycle its
        // accumulator needs it in.
        let mut ops: Vec<AcIn> = (0..20_000)
            .map(|_| {
                // Two different slots (a merge takes one into the other).
                let s = rng.gen_range(0..SLOTS);
                let t = (s + rng.gen_range(1..SLOTS)) % SLOTS;
                let mut i = AcIn {
                    s: s as u8,
                    t: t as u8,
                    half: half as u16,
                    rsel: rng.gen_range(0..SLOTS) as u8,
                    ..AcIn::default()
                };
                // Mostly pixels (clusters grow), some merges, few clears.
                match rng.gen_range(0..100) {
                    0..=79 => {
                        let p: Point = [coord(&mut rng), coord(&mut rng), coord(&mut rng)];
                        let (row, col) = (rng.gen_range(0..128u32), rng.gen_range(0..cols));
                        (i.add, i.x, i.y, i.z, i.row, i.col) =
                            (1, ob(p[0]), ob(p[1]), ob(p[2]), row as u8, col as u16);
                    }
                    80..=95 => i.merge = 1,
                    96..=98 => i.clear = 1,
                    _ => i.rst = 1,
                }
                i
            })
            .collect();
        // A reset clears the pixel's output stage: no add right after one.
        for k in 1..ops.len() {
            if ops[k - 1].rst != 0 {
                ops[k].add = 0;
            }
        }
        let pixels: Vec<(u16, u16, u16, u8, u16)> =
            ops.iter().map(|i| (i.x, i.y, i.z, i.row, i.col)).collect();
        for (k, i) in ops.iter_mut().enumerate() {
            (i.x, i.y, i.z, i.row, i.col) = pixels
                .get(k + ACC_PIXEL_LATENCY)
                .copied()
                .unwrap_or_default();
        }
        // The first pixels, ahead of the first operations.
        for &(x, y, z, row, col) in &pixels[..ACC_PIXEL_LATENCY] {
            d.step(&AcIn {
                x,
                y,
                z,
                row,
                col,
                half: half as u16,
                ..AcIn::default()
            });
        }
        for (cycle, i) in ops.iter().enumerate() {
            let (s, t, rsel) = (i.s as usize, i.t as usize, i.rsel as usize);
            let pixel = pixels[cycle];
            let o = d.step(i);
            for (name, want) in core_form(&slots[rsel]) {
                let got = got_form(&o, name);
                assert_eq!(
                    got, want,
                    "cycle {cycle}, slot {rsel} ({} points), field {name}: expected {want:#x}, got {got:#x}, seed {seed}",
                    slots[rsel].points
                );
            }
            // The model, after the cycle.
            if i.rst != 0 {
                slots = [Acc::default(); SLOTS];
            } else if i.add != 0 {
                let p = [pixel.0, pixel.1, pixel.2].map(|v| (v ^ 0x8000) as i16);
                slots[s].add(u32::from(pixel.3), u32::from(pixel.4), p, half);
            } else if i.merge != 0 {
                let other = slots[t];
                slots[s].merge(&other);
                slots[t] = Acc::default();
            } else if i.clear != 0 {
                slots[s] = Acc::default();
            }
        }
    }
}

#[test]
fn the_largest_frame_of_extreme_points_fits() {
    // 2^19 pixels (128 x 4096) at either end of the Q7.8 range, in one
    // slot each: every sum at its largest magnitude.
    let model = load_plain::<AcIn, AcOut>(BenchBlock::Acc, &FccParams::default())
        .expect("record accumulator model");
    let mut d = PlainDut::new(model);
    d.step(&AcIn {
        rst: 1,
        ..AcIn::default()
    });
    let ends: [Point; 2] = [[i16::MIN; 3], [i16::MAX, i16::MIN, i16::MAX]];
    let mut slots = [Acc::default(); 2];
    let n = 1u32 << 19;
    let at = |k: u32| (k % 128, k / 128);
    for (s, p) in ends.iter().enumerate() {
        // Pixel k is given ACC_PIXEL_LATENCY cycles before its add.
        let lat = ACC_PIXEL_LATENCY as u32;
        for k in 0..n + lat {
            let (row, col) = at(k);
            let add = k >= lat;
            d.step(&AcIn {
                add: add as u8,
                s: s as u8,
                x: ob(p[0]),
                y: ob(p[1]),
                z: ob(p[2]),
                row: row as u8,
                col: col as u16,
                half: 2048,
                ..AcIn::default()
            });
            if add {
                let (row, col) = at(k - lat);
                slots[s].add(row, col, *p, 2048);
            }
        }
    }
    for (s, acc) in slots.iter().enumerate() {
        let o = d.step(&AcIn {
            rsel: s as u8,
            ..AcIn::default()
        });
        for (name, want) in core_form(acc) {
            assert_eq!(got_form(&o, name), want, "slot {s}, field {name}");
        }
    }
}
