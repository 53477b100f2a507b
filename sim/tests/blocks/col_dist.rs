//! The column core's pass-2 distance tests `fcc_col_dist` alone under
//! Verilator, for every K, against the golden model's pass-2 test
//! (`fcc_golden::Thresholds::joins`, spec §2 and §4): a centre and a full
//! window of entries near it (random offsets around the threshold, and
//! offsets exactly at it, where the strict test must say no), unlabelled
//! entries among them, fixed and range-adaptive thresholds. The probe
//! presents each window for one cycle only, so a point, key or addend used
//! a cycle early or late shows. A mismatch prints K, the case, the entry,
//! the points, expected, got and the seed.

use fcc_golden::{Point, Thresholds};
use fcc_params::FccParams;
use fcc_rtl::{BenchBlock, COL_DIST_LATENCY};
use fcc_sim::core_form::{offset_binary as ob, point_addends};
use fcc_sim::{c_struct, load_plain, PlainDut};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

c_struct! {
    /// Inputs of one cycle, named as the ports.
    pub struct CdIn {
        pub rst: u8,
        pub go: u8,
        pub cx: u16,
        pub cy: u16,
        pub cz: u16,
        pub ckey: u16,
        pub ccv: u64,
        pub clabel: u16,
        pub wr: u8,
        pub widx: u8,
        pub wok: u8,
        pub wx: u16,
        pub wy: u16,
        pub wz: u16,
        pub wkey: u16,
        pub wcv: u64,
        pub wlabel: u16,
        pub hsel: u8,
    }
}

c_struct! {
    /// Outputs during one cycle.
    pub struct CdOut {
        pub o_valid: u8,
        pub o_label: u16,
        pub h_hit: u8,
        pub h_label: u16,
    }
}

/// Cycles from `go` to the centre out.
const LATENCY: usize = COL_DIST_LATENCY;

/// A point's key and pass-2 addend (spec §2).
fn key_cv(p: &FccParams, q: Point) -> (u16, u64) {
    let a = point_addends(p, q);
    (a.key, a.cv)
}

/// An entry: labelled or not, its point and label.
struct Entry {
    ok: bool,
    q: Point,
    label: u16,
}

fn run_case(d: &mut PlainDut<CdIn, CdOut>, p: &FccParams, c: Point, ents: &[Entry], at: &str) {
    for (e, en) in ents.iter().enumerate() {
        let (wkey, wcv) = key_cv(p, en.q);
        d.step(&CdIn {
            wr: 1,
            widx: e as u8,
            wok: en.ok as u8,
            wx: ob(en.q[0]),
            wy: ob(en.q[1]),
            wz: ob(en.q[2]),
            wkey,
            wcv,
            wlabel: en.label,
            ..CdIn::default()
        });
    }
    let (ckey, ccv) = key_cv(p, c);
    let clabel = 0x5a5a;
    let o = d.step(&CdIn {
        go: 1,
        cx: ob(c[0]),
        cy: ob(c[1]),
        cz: ob(c[2]),
        ckey,
        ccv,
        clabel,
        ..CdIn::default()
    });
    assert_eq!(o.o_valid, 0, "{at}: a centre out without go");
    for t in 1..=LATENCY {
        let o = d.step(&CdIn::default());
        assert_eq!(
            o.o_valid != 0,
            t == LATENCY,
            "{at}: centre out {t} cycles after go"
        );
    }
    let th = Thresholds::new(p);
    for (e, en) in ents.iter().enumerate() {
        let o = d.step(&CdIn {
            hsel: e as u8,
            ..CdIn::default()
        });
        assert_eq!(o.o_label, clabel, "{at}: centre label");
        let want = en.ok && th.joins(c, en.q);
        assert_eq!(
            (o.h_hit != 0, o.h_label),
            (want, en.label),
            "{at}: entry {e}, centre {c:?}, entry {:?} (labelled: {}): (joins, label)",
            en.q,
            en.ok
        );
    }
}

#[test]
fn every_entry_joins_as_pass_2_says_for_every_k() {
    for k in [3usize, 5, 7, 9, 11] {
        let build = FccParams {
            fsize: k,
            ..FccParams::default()
        };
        let n = build.window_positions();
        let model =
            load_plain::<CdIn, CdOut>(BenchBlock::ColDist, &build).expect("column distance model");
        let mut d = PlainDut::new(model);
        d.step(&CdIn {
            rst: 1,
            ..CdIn::default()
        });
        let seed = 0xd157_0000 + k as u64;
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        for (what, p) in [
            (
                "tV 0.3",
                FccParams {
                    th_v: 0.3,
                    ..build.clone()
                },
            ),
            (
                "tV 0.1, slope 0.05",
                FccParams {
                    th_v: 0.1,
                    th_v_slope: 0.05,
                    ..build.clone()
                },
            ),
        ] {
            let tv = p.th_v_q() as i32;
            for case in 0..40 {
                let at = format!("K = {k}, {what}, case {case}, seed {seed}");
                // Centres near and far (the adaptive threshold grows with range).
                let span = if case % 2 == 0 { 2_000 } else { 30_000 };
                let c: Point = [0; 3].map(|_: i16| rng.gen_range(-span..span) as i16);
                let ents: Vec<Entry> = (0..n)
                    .map(|e| {
                        let off: [i32; 3] = if case % 4 == 3 && e < 3 {
                            // Exactly at and just inside the fixed threshold.
                            let mut o = [0; 3];
                            o[e] = if e == 1 { tv - 1 } else { tv };
                            o
                        } else {
                            let r = tv * rng.gen_range(1..=8) / 4;
                            [0; 3].map(|_: i32| rng.gen_range(-r..=r))
                        };
                        let q =
                            [0, 1, 2].map(|a| (c[a] as i32 + off[a]).clamp(-32_768, 32_767) as i16);
                        Entry {
                            ok: rng.gen_bool(0.85),
                            q,
                            label: rng.gen_range(1..=u16::MAX),
                        }
                    })
                    .collect();
                run_case(&mut d, &p, c, &ents, &at);
            }
        }
    }
}
