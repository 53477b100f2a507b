//! The column core's record stream `fcc_record_out` (its beats from
//! `FccRecBeats`) alone under Verilator, against the golden records' beats
//! (`fcc_golden::Acc::record(..).hw().pack()`, spec §9.3 and §9.4): seeded
//! random accumulators (a few pixels to many, at the ends of the Q7.8
//! range, seam clusters with columns in both halves or one), ids and
//! closing columns up to their widths, sent with random back-pressure; the
//! beats start the second cycle after the load, a beat must hold while
//! `valid` and not `ready`, no record beat has `last`, `idle` marks the end.
//! Then frames of records and end beats (spec §9.4's frame end), read back
//! by `fcc_pixel::record::RecordReader`: counts, flags, `last` on the end
//! beat alone, frames without records, end requests refused while busy or
//! beside a load. A mismatch prints the record, the beat, expected, got and
//! the seed.

use fcc_golden::{Acc, Point};
use fcc_params::FccParams;
use fcc_pixel::record::{FrameEnd, Item, RecordReader, RECORD_WORDS};
use fcc_rtl::BenchBlock;
use fcc_sim::core_form::CoreAcc;
use fcc_sim::{c_struct, load_plain, PlainDut};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

c_struct! {
    /// Inputs of one cycle, named as the ports.
    pub struct RoIn {
        pub rst: u8,
        pub load: u8,
        pub id: u32,
        pub closed_col: u16,
        pub points: u32,
        pub min_col: u16,
        pub max_col: u16,
        pub lo_has: u8,
        pub lo_max: u16,
        pub hi_has: u8,
        pub hi_min: u16,
        pub first_row: u8,
        pub last_row: u8,
        pub min_x: u16,
        pub min_y: u16,
        pub min_z: u16,
        pub max_x: u16,
        pub max_y: u16,
        pub max_z: u16,
        pub r2_min: u32,
        pub r2_max: u32,
        pub sa: u64,
        pub sb: u64,
        pub sc: u64,
        pub sxx: u64,
        pub syy: u64,
        pub sab: u64,
        pub seam: u8,
        pub load_end: u8,
        pub overflow: u8,
        pub frame_error: u8,
        pub ready: u8,
    }
}

c_struct! {
    /// Outputs during one cycle.
    pub struct RoOut {
        pub idle: u8,
        pub valid: u8,
        pub beat: u64,
        pub last: u8,
    }
}

/// The load of a record: the accumulator in the core's form (`AccWord`).
fn load(a: &Acc, id: u32, closed_col: u16) -> RoIn {
    let c = CoreAcc::of(a);
    RoIn {
        load: 1,
        id,
        closed_col,
        points: c.points as u32,
        min_col: c.min_col as u16,
        max_col: c.max_col as u16,
        lo_has: c.lo_has as u8,
        lo_max: c.lo_max as u16,
        hi_has: c.hi_has as u8,
        hi_min: c.hi_min as u16,
        first_row: c.first_row as u8,
        last_row: c.last_row as u8,
        min_x: c.min[0] as u16,
        min_y: c.min[1] as u16,
        min_z: c.min[2] as u16,
        max_x: c.max[0] as u16,
        max_y: c.max[1] as u16,
        max_z: c.max[2] as u16,
        r2_min: c.r2_min as u32,
        r2_max: c.r2_max as u32,
        sa: c.sa,
        sb: c.sb,
        sc: c.sc,
        sxx: c.sxx,
        syy: c.syy,
        sab: c.sab,
        seam: c.seam as u8,
        ..RoIn::default()
    }
}

fn coord(rng: &mut ChaCha8Rng) -> i16 {
    match rng.gen_range(0..6) {
        0 => i16::MIN,
        1 => i16::MAX,
        _ => rng.gen(),
    }
}

/// A random accumulator of up to `n` pixels of a `cols`-column frame.
fn random_acc(rng: &mut ChaCha8Rng, cols: u32, n: u32) -> Acc {
    let mut a = Acc::default();
    let half = cols / 2;
    let (c0, spread) = (rng.gen_range(0..cols), rng.gen_range(1..=cols));
    for _ in 0..rng.gen_range(1..=n) {
        let p: Point = [coord(rng), coord(rng), coord(rng)];
        let col = (c0 + rng.gen_range(0..spread)) % cols;
        a.add(rng.gen_range(0..128), col, p, half);
    }
    a.seam = rng.gen_bool(0.3);
    a
}

#[test]
fn records_leave_as_the_golden_records_beats() {
    let model = load_plain::<RoIn, RoOut>(BenchBlock::RecordOut, &FccParams::default())
        .expect("record output model");
    let mut d = PlainDut::new(model);
    let seed = 0x4ec0_0001;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    d.step(&RoIn {
        rst: 1,
        ..RoIn::default()
    });
    let mut many = Acc::default();
    // One record of the largest frame: 2^19 points at one end of the range.
    for k in 0..1u32 << 19 {
        many.add(k % 128, k / 128, [i16::MIN, i16::MAX, i16::MIN], 2048);
    }
    for case in 0..400 {
        let cols = [256u32, 1024, 2048, 4096][case % 4];
        let a = if case == 0 {
            many
        } else {
            random_acc(&mut rng, cols, [1, 3, 40, 2000][case % 4])
        };
        let id = if case % 7 == 0 {
            (1 << 20) - 1
        } else {
            rng.gen_range(1..1 << 20)
        };
        let closed = rng.gen_range(0..=cols) as u16;
        let want = a.record(0, id, u32::from(closed)).hw().pack().unwrap();
        let at = format!(
            "case {case} ({} points, seam {}), seed {seed:#x}",
            a.points, a.seam
        );
        let o = d.step(&RoIn {
            ready: 0,
            ..RoIn::default()
        });
        assert_eq!(o.idle, 1, "{at}: not idle before the load");
        d.step(&load(&a, id, closed));
        // One cycle to register the record's fields.
        let o = d.step(&RoIn::default());
        assert_eq!((o.valid, o.idle), (0, 0), "{at}: preparing");
        let mut got = Vec::new();
        let mut held: Option<u64> = None;
        for cycle in 0..200 {
            let ready = rng.gen_bool(0.6);
            let o = d.step(&RoIn {
                ready: ready as u8,
                // A load while sending is ignored.
                load: (cycle == 3) as u8,
                ..RoIn::default()
            });
            if o.valid == 0 {
                assert_eq!(
                    got.len(),
                    RECORD_WORDS,
                    "{at}: idle after {} beats",
                    got.len()
                );
                assert_eq!(o.idle, 1, "{at}: not idle after the last beat");
                break;
            }
            if let Some(h) = held {
                assert_eq!(o.beat, h, "{at}: beat {} changed while held", got.len());
            }
            assert_eq!(o.last, 0, "{at}: last on record beat {}", got.len());
            if ready {
                let k = got.len();
                assert_eq!(
                    o.beat, want[k],
                    "{at}: beat {k}: expected {:#x}, got {:#x}",
                    want[k], o.beat
                );
                got.push(o.beat);
                held = None;
            } else {
                held = Some(o.beat);
            }
        }
        assert_eq!(got.len(), RECORD_WORDS, "{at}: beats sent");
    }
}

#[test]
fn frames_of_records_end_with_their_end_beat() {
    let model = load_plain::<RoIn, RoOut>(BenchBlock::RecordOut, &FccParams::default())
        .expect("record output model");
    let mut d = PlainDut::new(model);
    let seed = 0x4ec0_0002;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    d.step(&RoIn {
        rst: 1,
        ..RoIn::default()
    });
    let mut want = Vec::new();
    let mut reader = RecordReader::new();
    let mut got = Vec::new();
    let mut held: Option<(u64, u8)> = None;
    // Step one cycle with `i` (plus a random `ready`), taking what leaves.
    let mut step = |d: &mut PlainDut<RoIn, RoOut>, rng: &mut ChaCha8Rng, i: RoIn, at: &str| {
        let ready = rng.gen_bool(0.6);
        let o = d.step(&RoIn {
            ready: ready as u8,
            ..i
        });
        if o.valid == 1 {
            if let Some(h) = held {
                assert_eq!((o.beat, o.last), h, "{at}: a beat changed while held");
            }
            if ready {
                let k = reader.beats();
                match reader.push(o.beat, o.last != 0) {
                    Ok(Some(item)) => got.push(item),
                    Ok(None) => {}
                    Err(e) => panic!("{at}: output beat {k}: {e} (beat {:#x})", o.beat),
                }
                held = None;
            } else {
                held = Some((o.beat, o.last));
            }
        }
        o
    };
    for frame in 0..80 {
        let n = [0, 1, 2, 5, 0, 3][frame % 6];
        for id in 1..=n {
            let at = format!("frame {frame} record {id}, seed {seed:#x}");
            let a = random_acc(&mut rng, 2048, 20);
            let closed = rng.gen_range(0..=2048u16);
            want.push(Item::Record(a.record(0, id, u32::from(closed)).hw()));
            while step(&mut d, &mut rng, RoIn::default(), &at).idle == 0 {}
            // A load with an end request beside it: the load is taken, the
            // end request is not.
            let beside = rng.gen_bool(0.3) as u8;
            step(
                &mut d,
                &mut rng,
                RoIn {
                    load_end: beside,
                    ..load(&a, id, closed)
                },
                &at,
            );
            // End requests while the record is sent are not taken.
            for _ in 0..rng.gen_range(0..4) {
                let i = RoIn {
                    load_end: rng.gen_bool(0.5) as u8,
                    overflow: 1,
                    ..RoIn::default()
                };
                step(&mut d, &mut rng, i, &at);
            }
        }
        let at = format!("frame {frame} end, seed {seed:#x}");
        let end = FrameEnd {
            records: n,
            overflow: rng.gen_bool(0.5),
            frame_error: rng.gen_bool(0.3),
        };
        want.push(Item::End(end));
        while step(&mut d, &mut rng, RoIn::default(), &at).idle == 0 {}
        let i = RoIn {
            load_end: 1,
            overflow: end.overflow as u8,
            frame_error: end.frame_error as u8,
            ..RoIn::default()
        };
        let o = step(&mut d, &mut rng, i, &at);
        assert_eq!(o.idle, 1, "{at}: not idle at the end request");
    }
    for _ in 0..64 {
        step(&mut d, &mut rng, RoIn::default(), "tail");
    }
    reader
        .finish()
        .unwrap_or_else(|e| panic!("the stream's end: {e}, seed {seed:#x}"));
    let first = want.iter().zip(&got).position(|(w, g)| w != g);
    assert!(
        got.len() == want.len() && first.is_none(),
        "{} items out for {}; first differing item {first:?}: expected {:?}, got {:?}, seed {seed:#x}",
        got.len(),
        want.len(),
        first.map(|k| want[k]),
        first.map(|k| got[k])
    );
}
