//! The column core's column-start check `fcc_col_start` alone under
//! Verilator, against its contract (docs/column-core.md, "Slot
//! overflow"): the slots in use, the starts on their way and the free
//! labels move by a start or a close a cycle, as the core's do, columns'
//! first pixels come and are taken when not held, the previous column is
//! settled or not. Checked every cycle: a column goes on its fast path
//! only if, with the counts of that very cycle, two columns of starts fit
//! under the open limit and in the free labels, and then its room is `R`;
//! on the settled path its room is `N_o` less the slots in use; with counts steady and room to spare it is never held; the
//! room holds between columns. A mismatch prints the cycle, expected,
//! got and the seed.

use fcc_params::FccParams;
use fcc_rtl::BenchBlock;
use fcc_sim::{c_struct, load_plain, PlainDut};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

c_struct! {
    /// Inputs of one cycle, named as the ports.
    pub struct CsIn {
        pub rst: u8,
        pub rows: u8,
        pub n_o: u16,
        pub slots_used: u16,
        pub in_flight: u16,
        pub labels_free: u16,
        pub settled: u8,
        pub first: u8,
        pub accept: u8,
    }
}

c_struct! {
    /// Outputs during one cycle.
    pub struct CsOut {
        pub hold: u8,
        pub open_room: u16,
    }
}

/// Starts the check's counts may be late by (`COUNT_MARGIN`).
const MARGIN: i64 = 4;

struct Totals {
    columns: u64,
    fast: u64,
    settled: u64,
    held: u64,
}

fn run(seed: u64, rows: u8, n_o: u16, cycles: u64, t: &mut Totals) {
    let model = load_plain::<CsIn, CsOut>(BenchBlock::ColStart, &FccParams::default())
        .expect("column-start check model");
    let mut d = PlainDut::new(model);
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let what = format!("R {rows}, N_o {n_o}, seed {seed:#x}");
    let (r, no) = (i64::from(rows), i64::from(n_o));
    let mut inp = CsIn {
        rst: 1,
        rows,
        n_o,
        ..CsIn::default()
    };
    d.step(&inp);
    inp.rst = 0;
    let (mut used, mut flight, mut free) = (0i64, 0i64, 8191i64);
    // The counts of the last three cycles (steady: no hold expected).
    let mut hist: Vec<(i64, i64, i64)> = vec![(used, flight, free); 3];
    let mut room: Option<u16> = None;
    // Drift towards a level picked every few hundred cycles, in and out
    // of the fast path's reach.
    let (mut aim_used, mut aim_free) = (0i64, 8191i64);
    let mut first = false;
    for cycle in 0..cycles {
        if cycle % 300 == 0 {
            aim_used = rng.gen_range(0..=no);
            aim_free = rng.gen_range(0..=4 * r);
        }
        // A start or a close a cycle at most each way, as the core's.
        if rng.gen_bool(0.5) {
            if flight > 0 && rng.gen_bool(0.5) {
                flight -= 1;
                used += 1;
            } else if used + flight < aim_used && used + flight < 511 {
                flight += 1;
            } else if used > 0 && used + flight > aim_used {
                used -= 1;
            }
        }
        // A label taken a cycle at most; returns in bursts.
        if free > aim_free && rng.gen_bool(0.7) {
            free -= 1;
        } else if free < aim_free {
            free = (free + rng.gen_range(0..32)).min(8191);
        }
        let settled = rng.gen_bool(0.02);
        if !first && rng.gen_bool(0.05) {
            first = true;
        }
        let accept = first && rng.gen_bool(0.8);
        inp.slots_used = used as u16;
        inp.in_flight = flight as u16;
        inp.labels_free = free as u16;
        inp.settled = settled as u8;
        inp.first = first as u8;
        inp.accept = accept as u8;
        let o = d.step(&inp);
        hist.remove(0);
        hist.push((used, flight, free));
        let at = format!("{what}, cycle {cycle}, used {used}, in flight {flight}, free {free}");
        if let Some(room) = room {
            assert_eq!(o.open_room, room, "{at}: the room held between columns");
        }
        let steady = hist.iter().all(|&h| h == (used, flight, free));
        let fits = used + flight + 2 * r + MARGIN <= no && free >= 2 * r + MARGIN;
        if first && steady && fits {
            assert_eq!(o.hold, 0, "{at}: held with room to spare");
        }
        if !first {
            assert_eq!(o.hold, 0, "{at}: hold with no first pixel");
        }
        if first && o.hold == 0 && accept {
            // Released: the room shows from the next cycle.
            let fast_safe = used + flight + 2 * r <= no && free >= 2 * r;
            let exact = (no - used) as u16;
            let got = d.step(&CsIn {
                first: 0,
                accept: 0,
                ..inp
            });
            hist.remove(0);
            hist.push((used, flight, free));
            t.columns += 1;
            if got.open_room == u16::from(rows) && (!settled || exact != u16::from(rows)) {
                assert!(
                    fast_safe || settled,
                    "{at}: a column let go with no room for two columns of starts"
                );
                t.fast += 1;
            } else {
                assert!(settled, "{at}: room {} on neither path", got.open_room);
                assert_eq!(got.open_room, exact, "{at}: the settled room");
                t.settled += 1;
            }
            room = Some(got.open_room);
            first = false;
        } else if first && o.hold != 0 {
            t.held += 1;
        }
    }
}

#[test]
fn a_column_starts_only_when_no_run_of_it_can_be_refused_wrongly() {
    let mut t = Totals {
        columns: 0,
        fast: 0,
        settled: 0,
        held: 0,
    };
    for (seed, rows, n_o) in [
        (0xc01_0001, 128, 511),
        (0xc01_0002, 64, 300),
        (0xc01_0003, 16, 40),
        (0xc01_0004, 128, 200),
    ] {
        run(seed, rows, n_o, 60_000, &mut t);
    }
    eprintln!(
        "{} columns: {} on the fast path, {} settled; first pixels held {} cycles",
        t.columns, t.fast, t.settled, t.held
    );
    assert!(
        t.fast > 1_000 && t.settled > 100 && t.held > 10_000,
        "too easy a trace"
    );
}
