//! The column core's packer `fcc_set_pack` alone under Verilator: pixel
//! slots and their joins as `FccRepJoins` sends them (a pixel's first join
//! in its cycle, its others after it while `j_more` is high, which falls
//! with the last join or in a cycle of its own; no pixel in the cycle
//! after one with `j_more` high), columns of a few rows, bubbles, a reset
//! mid-stream. Each cycle's entry, a cycle later, must be what the
//! contract of docs/column-core.md, item 3 makes of the scenario: the
//! pixel's cycle gives its flush (a find of its run's representative, when
//! its row drops a run), its make, its first join and, at the column's
//! last row with no join to come, the column's marker; a further join an
//! entry of its own, the last row's marker with the join after which
//! `j_more` falls or alone in the cycle it falls; a cycle with no op no
//! entry. A mismatch prints the cycle, expected, got and the seed.

use crate::column;
use column::pack_io::{PkIn, PkOut};

use fcc_params::FccParams;
use fcc_rtl::BenchBlock;
use fcc_sim::{load_plain, PlainDut};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// An entry of the queue, the fields its parts define: a find's label; a
/// make's label, first pixel and ring flag; a join's pair and whether it
/// files a run just started (`under`); a marker's column.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
struct Entry {
    find: Option<u16>,
    make: Option<(u16, u16, u8, bool)>,
    join: Option<(u16, u16, bool)>,
    mark: Option<u16>,
}

impl Entry {
    fn any(&self) -> bool {
        self.find.is_some() || self.make.is_some() || self.join.is_some() || self.mark.is_some()
    }
}

fn got(o: &PkOut) -> Option<Entry> {
    if o.q_valid == 0 {
        return None;
    }
    Some(Entry {
        find: (o.q_find != 0).then_some(o.q_f),
        make: (o.q_make != 0).then_some((o.q_m, o.q_col, o.q_row, o.q_ring != 0)),
        join: (o.q_join != 0).then_some((o.q_ja, o.q_jb, o.q_under != 0)),
        mark: (o.q_mark != 0).then_some(o.q_col),
    })
}

struct Bench {
    dut: PlainDut<PkIn, PkOut>,
    /// The entry the last cycle's inputs must give.
    due: Option<Entry>,
    cycle: u64,
    entries: u64,
    marks_alone: u64,
    seed: u64,
}

impl Bench {
    fn new(seed: u64) -> Bench {
        let model = load_plain::<PkIn, PkOut>(BenchBlock::SetPack, &FccParams::default())
            .expect("set pack model");
        let mut b = Bench {
            dut: PlainDut::new(model),
            due: None,
            cycle: 0,
            entries: 0,
            marks_alone: 0,
            seed,
        };
        b.step(
            PkIn {
                rst: 1,
                ..PkIn::default()
            },
            None,
        );
        b
    }

    /// One cycle: `i` in, `want` the entry it must give (checked a cycle
    /// later), and this cycle's output checked against the last cycle's.
    fn step(&mut self, i: PkIn, want: Option<Entry>) {
        let o = self.dut.step(&i);
        if i.rst == 0 || self.cycle > 0 {
            assert_eq!(
                got(&o),
                self.due,
                "cycle {}: the entry of the cycle before (seed {})",
                self.cycle,
                self.seed
            );
        }
        self.entries += u64::from(o.q_valid);
        self.due = want.filter(Entry::any);
        self.cycle += 1;
    }
}

/// A pixel slot: its fields and its joins (the ring check's last).
#[derive(Debug, Clone)]
struct Px {
    row: u8,
    col: u16,
    start: Option<(u16, bool)>,
    drop: Option<(u16, u16)>,
    joins: Vec<(u16, u16, bool)>,
}

fn random_px(rng: &mut ChaCha8Rng, row: u8, col: u16, last_col: bool) -> Px {
    let label = |rng: &mut ChaCha8Rng| rng.gen_range(1..=u16::MAX);
    let start = rng.gen_bool(0.3).then(|| (label(rng), rng.gen_bool(0.5)));
    let drop = rng.gen_bool(0.3).then(|| (label(rng), label(rng)));
    let n = match rng.gen_range(0..10) {
        0..=4 => 0,
        5..=7 => 1,
        8 => 2,
        _ => rng.gen_range(3..6),
    };
    let mut joins: Vec<(u16, u16, bool)> = (0..n)
        .map(|_| (label(rng), label(rng), rng.gen_bool(0.3)))
        .collect();
    if last_col && rng.gen_bool(0.5) {
        joins.push((label(rng), label(rng), false));
    }
    Px {
        row,
        col,
        start,
        drop,
        joins,
    }
}

/// Send `px` as `FccRepJoins` does: the pixel with its first join, the
/// others after it (up to two idle cycles before each), `j_more` high
/// until the last join's cycle or one cycle after it (`late`).
fn send(b: &mut Bench, rng: &mut ChaCha8Rng, px: &Px, last_row: u8) {
    let base = PkIn {
        last_row,
        // Fields of an invalid pixel are whatever they were: random.
        p_row: rng.gen_range(0..128),
        p_col: rng.gen_range(0..4096),
        p_label: rng.gen(),
        p_hold_rep: rng.gen(),
        ..PkIn::default()
    };
    let is_last = px.row == last_row;
    let late = px.joins.len() > 1 && rng.gen_bool(0.5);
    let n = px.joins.len();
    let mut i = PkIn {
        p_valid: 1,
        p_row: px.row,
        p_col: px.col,
        p_start: px.start.is_some() as u8,
        p_label: px.start.map_or(rng.gen(), |s| s.0),
        p_ring_first: px.start.is_some_and(|s| s.1) as u8,
        p_hold_drop: px.drop.map_or(0, |d| d.0),
        p_hold_rep: px.drop.map_or(rng.gen(), |d| d.1),
        j_more: (n > 1) as u8,
        ..base
    };
    let mut want = Entry {
        find: px.drop.map(|d| d.1),
        make: px.start.map(|(l, ring)| (l, px.col, px.row, ring)),
        mark: (is_last && n <= 1).then_some(px.col),
        ..Entry::default()
    };
    if let Some(&(a, b2, under)) = px.joins.first() {
        (i.j_valid, i.j_a, i.j_b, i.j_under) = (1, a, b2, under as u8);
        want.join = Some((a, b2, under));
    }
    b.step(i, Some(want));
    for (k, &(a, j, under)) in px.joins.iter().enumerate().skip(1) {
        for _ in 0..rng.gen_range(0..3) {
            b.step(PkIn { j_more: 1, ..base }, None);
        }
        let last = k + 1 == n;
        b.step(
            PkIn {
                j_valid: 1,
                j_a: a,
                j_b: j,
                j_under: under as u8,
                j_more: (!last || late) as u8,
                ..base
            },
            Some(Entry {
                join: Some((a, j, under)),
                mark: (is_last && last && !late).then_some(px.col),
                ..Entry::default()
            }),
        );
    }
    if late {
        b.step(
            base,
            Some(Entry {
                mark: is_last.then_some(px.col),
                ..Entry::default()
            }),
        );
        b.marks_alone += u64::from(is_last);
    }
}

/// `cols` columns of `rows` pixel slots, bubbles between slots.
fn run(b: &mut Bench, rng: &mut ChaCha8Rng, rows: u8, cols: u16, bubbles: f64) {
    for c in 0..cols {
        for r in 0..rows {
            while rng.gen_bool(bubbles) {
                b.step(
                    PkIn {
                        last_row: rows - 1,
                        p_row: rng.gen_range(0..128),
                        p_col: rng.gen(),
                        ..PkIn::default()
                    },
                    None,
                );
            }
            let px = random_px(rng, r, c, c + 1 == cols);
            send(b, rng, &px, rows - 1);
        }
    }
}

#[test]
fn each_cycles_ops_make_one_entry_in_the_queues_order() {
    for seed in 0..6u64 {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut b = Bench::new(seed);
        let rows = [2u8, 3, 8, 16, 64, 128][seed as usize];
        let cols = (4000 / rows as u16).max(4);
        run(
            &mut b,
            &mut rng,
            rows,
            cols,
            if seed % 2 == 0 { 0.0 } else { 0.3 },
        );
        b.step(PkIn::default(), None);
        b.step(PkIn::default(), None);
        eprintln!(
            "seed {seed}: {rows} rows x {cols} columns, {} cycles, {} entries, {} markers alone",
            b.cycle, b.entries, b.marks_alone
        );
        assert!(
            b.marks_alone > 0 || rows > 16,
            "seed {seed}: no marker alone"
        );
    }
}

#[test]
fn a_reset_forgets_a_marker_waiting_for_joins() {
    let seed = 100;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut b = Bench::new(seed);
    // The last row's pixel with joins to come: its marker waits.
    b.step(
        PkIn {
            p_valid: 1,
            p_row: 3,
            p_col: 9,
            j_valid: 1,
            j_a: 5,
            j_b: 2,
            j_more: 1,
            last_row: 3,
            ..PkIn::default()
        },
        Some(Entry {
            join: Some((5, 2, false)),
            ..Entry::default()
        }),
    );
    // A reset while the joins' block still says more come (its own reset
    // takes effect at the same edge): no entry out of the reset cycle, no
    // marker after it.
    b.step(
        PkIn {
            rst: 1,
            j_more: 1,
            last_row: 3,
            ..PkIn::default()
        },
        None,
    );
    b.step(
        PkIn {
            last_row: 3,
            ..PkIn::default()
        },
        None,
    );
    run(&mut b, &mut rng, 4, 50, 0.2);
    b.step(PkIn::default(), None);
}
