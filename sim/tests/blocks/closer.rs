//! The column core's closer `FccCloser` alone under Verilator, against a
//! model of its contract (docs/column-core.md, item 4). Frames of columns,
//! each with the record store's quiet reports of its ops (quiet column
//! the op's, last column up to a few columns back, due `max(last + h,
//! quiet column)`, `last + h` at most the frame's last column) and then
//! its marker, now and then after a few reports
//! of the next column; sparse columns, busy ones, floods of a hundred
//! reports due at one column (more closes than sorted entries: passes
//! again) and of reports that fill the wait list (the reports then wait
//! for `room`, the store's ops in flight still coming); keys over a few
//! values (many equal) and the whole range; closes taken at once and
//! under back-pressure; the frame end (`clear`, every slot in use
//! reported `ending`, the end column marked); resets mid-run. Every close
//! must be the next one the model expects: the column's entries due, by
//! key (equal keys in any order); `caught_up` only with none due. A
//! mismatch prints the cycle, expected, got and the seed.

use std::collections::VecDeque;

use fcc_params::FccParams;
use fcc_rtl::{BenchBlock, CLOSE_ENTRIES, CLOSE_KEY_BITS, WAIT_ADDR_BITS};
use fcc_sim::{c_struct, load_plain, PlainDut, PlainModel};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

c_struct! {
    /// Inputs of one cycle, named as the ports.
    pub struct ClIn {
        pub rst: u8,
        pub clear: u8,
        pub half: u8,
        pub last_col: u16,
        pub ending: u8,
        pub end_col: u16,
        pub q_valid: u8,
        pub q_slot: u16,
        pub q_first: u32,
        pub q_last: u16,
        pub q_col: u16,
        pub mark_valid: u8,
        pub mark_col: u16,
        pub close_take: u8,
    }
}

c_struct! {
    /// Outputs during one cycle.
    pub struct ClOut {
        pub room: u8,
        pub close_valid: u8,
        pub close_slot: u16,
        pub close_key: u32,
        pub close_col: u16,
        pub caught_up: u8,
    }
}

/// Entries the wait list holds.
const WAIT: usize = 1 << WAIT_ADDR_BITS;
/// Cycles a column takes at least (its pixels, 128 rows).
const ROWS: u32 = 128;
/// Reports the store may still send once `room` is low (its ops in flight).
const IN_FLIGHT: u32 = 4;

/// A quiet report: slot, first pixel, last column, quiet column.
#[derive(Debug, Clone, Copy)]
struct Report {
    slot: u16,
    key: u32,
    last: u16,
    col: u16,
}

#[derive(Debug, Clone, Copy)]
enum Event {
    Report(Report),
    Mark(u16),
    /// The frame end: the top waits for `caught_up`, clears, and reports
    /// every slot in use `ending` (the reports after it), due at this
    /// column.
    EndStart(u16),
    /// A frame starts.
    Clear,
    Reset,
    /// Cycles with no report or marker: a column's pixels take `R` cycles.
    Idle(u32),
}

/// What the runs saw, to show each rule was exercised.
#[derive(Debug, Default, Clone, Copy)]
struct Seen {
    reports: u64,
    closes: u64,
    /// Columns with more closes than sorted entries.
    long_columns: u64,
    /// Cycles `room` was low.
    no_room: u64,
    end_closes: u64,
    /// Reports whose `last + h` is past the frame's last column (due
    /// there: hold 1 ends with the frame).
    past_end: u64,
    /// The most cycles from a marker to the last close of its column.
    worst_wait: u64,
    /// The most entries waiting at once (the model's, those due and not
    /// yet sent included; the list holds `WAIT`).
    most_waiting: usize,
}

struct Bench {
    d: PlainDut<ClIn, ClOut>,
    half: u16,
    /// The frame's last column (a run parameter: set before its frame).
    last_col: u16,
    /// Entries waiting: (due, key, slot).
    waiting: Vec<(u16, u32, u16)>,
    /// Closes due, in order: (column, key, slot, marker cycle).
    expect: VecDeque<(u16, u32, u16, u64)>,
    ending: Option<u16>,
    /// `caught_up` in the last cycle.
    caught: bool,
    lag: u32,
    cycle: u64,
    seen: Seen,
    what: String,
}

impl Bench {
    fn new(model: &PlainModel<ClIn, ClOut>, half: u16, what: String) -> Bench {
        let mut b = Bench {
            d: PlainDut::new(model.clone()),
            half,
            last_col: 4095,
            waiting: vec![],
            expect: VecDeque::new(),
            ending: None,
            caught: false,
            lag: IN_FLIGHT,
            cycle: 0,
            seen: Seen::default(),
            what,
        };
        b.step(ClIn {
            rst: 1,
            ..ClIn::default()
        });
        b
    }

    /// One cycle; checks the close offered (taken if `take`) and `caught_up`.
    fn step(&mut self, mut inp: ClIn) -> ClOut {
        inp.half = self.half as u8;
        inp.last_col = self.last_col;
        inp.ending = self.ending.is_some() as u8;
        inp.end_col = self.ending.unwrap_or(0);
        let o = self.d.step(&inp);
        let now = self.cycle;
        self.cycle += 1;
        self.seen.no_room += u64::from(o.room == 0);
        self.caught = o.caught_up != 0;
        if inp.rst != 0 || inp.clear != 0 {
            self.waiting.clear();
            self.expect.clear();
            return o;
        }
        if o.close_valid != 0 && inp.close_take != 0 {
            let got = (o.close_col, o.close_key, o.close_slot);
            let at = self
                .expect
                .iter()
                .take_while(|e| (e.0, e.1) == (got.0, got.1))
                .position(|e| e.2 == got.2);
            let Some(at) = at else {
                panic!(
                    "{}, cycle {now}: close (column, key, slot) expected (left), got (right): \
                     {:?}, {got:?}",
                    self.what,
                    self.expect.front().map(|e| (e.0, e.1, e.2))
                );
            };
            let (col, _, _, marked) = self.expect.remove(at).unwrap();
            self.seen.closes += 1;
            self.seen.end_closes += u64::from(Some(col) == self.ending);
            if !self.expect.iter().any(|e| e.0 == col) {
                self.seen.worst_wait = self.seen.worst_wait.max(now - marked);
            }
        }
        if o.caught_up != 0 {
            assert!(
                self.expect.is_empty(),
                "{}, cycle {now}: caught up with {} closes due, first {:?}",
                self.what,
                self.expect.len(),
                self.expect.front()
            );
        }
        if inp.q_valid != 0 {
            self.seen.reports += 1;
            let due = match self.ending {
                Some(end) => end,
                None => {
                    let reach = inp.q_last + self.half;
                    self.seen.past_end += u64::from(reach > self.last_col);
                    reach.min(self.last_col).max(inp.q_col)
                }
            };
            self.waiting.push((due, inp.q_first, inp.q_slot));
            let waiting = self.waiting.len() + self.expect.len();
            self.seen.most_waiting = self.seen.most_waiting.max(waiting);
        }
        if inp.mark_valid != 0 {
            // Every entry due by the column, by key.
            let c = inp.mark_col;
            let mut due: Vec<_> = self.waiting.iter().filter(|e| e.0 <= c).copied().collect();
            self.waiting.retain(|e| e.0 > c);
            due.sort();
            self.seen.long_columns += due
                .chunk_by(|a, b| a.0 == b.0)
                .filter(|g| g.len() > CLOSE_ENTRIES)
                .count() as u64;
            self.expect
                .extend(due.into_iter().map(|(d, k, s)| (d, k, s, now)));
        }
        o
    }

    /// Feed `events` at `rate`, closes taken with probability `take`.
    fn run(&mut self, rng: &mut ChaCha8Rng, events: Vec<Event>, rate: f64, take: f64) {
        let mut events = VecDeque::from(events);
        let mut room = true;
        let start = self.cycle;
        while let Some(&ev) = events.front() {
            assert!(
                self.cycle - start < 40 * 1_000_000,
                "{}: events left",
                self.what
            );
            let mut inp = ClIn {
                close_take: rng.gen_bool(take) as u8,
                ..ClIn::default()
            };
            if room {
                self.lag = IN_FLIGHT;
            }
            let may_report = room || self.lag > 0;
            if rng.gen_bool(rate) {
                match ev {
                    Event::Report(r) if may_report => {
                        (inp.q_valid, inp.q_slot, inp.q_first, inp.q_last, inp.q_col) =
                            (1, r.slot, r.key, r.last, r.col);
                        events.pop_front();
                        self.lag = self.lag.saturating_sub(u32::from(!room));
                        // A marker may come in the same cycle.
                        if let Some(&Event::Mark(c)) = events.front() {
                            if rng.gen_bool(0.5) {
                                (inp.mark_valid, inp.mark_col) = (1, c);
                                events.pop_front();
                            }
                        }
                    }
                    Event::Report(_) => {}
                    Event::Mark(c) => {
                        (inp.mark_valid, inp.mark_col) = (1, c);
                        events.pop_front();
                    }
                    Event::EndStart(c) => {
                        if self.caught && self.expect.is_empty() {
                            inp.clear = 1;
                            self.ending = Some(c);
                            events.pop_front();
                        }
                    }
                    Event::Idle(n) => {
                        events.pop_front();
                        if n > 1 {
                            events.push_front(Event::Idle(n - 1));
                        }
                    }
                    Event::Reset => {
                        inp.rst = 1;
                        self.ending = None;
                        events.pop_front();
                    }
                    Event::Clear => {
                        if self.caught && self.expect.is_empty() {
                            inp.clear = 1;
                            self.ending = None;
                            events.pop_front();
                        }
                    }
                }
            }
            room = self.step(inp).room != 0;
        }
    }

    /// Step with closes taken until caught up (at most `limit` cycles).
    fn drain(&mut self, limit: u64) {
        let start = self.cycle;
        while !(self.caught && self.expect.is_empty()) {
            self.step(ClIn {
                close_take: 1,
                ..ClIn::default()
            });
            assert!(
                self.cycle - start < limit,
                "{}: {} closes left after {limit} cycles",
                self.what,
                self.expect.len()
            );
        }
    }
}

/// How busy a stretch of columns is.
#[derive(Debug, Clone, Copy)]
enum Load {
    /// 0 to 2 reports a column.
    Sparse,
    /// 0 to 12.
    Busy,
    /// 12 a column, due `h` columns on: the list holds about `12 (h + 1)`.
    Fill,
}

fn key(rng: &mut ChaCha8Rng, spread: u32) -> u32 {
    match spread {
        0 => rng.gen_range(0..1 << CLOSE_KEY_BITS),
        s => rng.gen_range(0..s),
    }
}

/// A frame of `cols` columns: each column's reports, its marker (now and
/// then after a few of the next column's reports), floods of reports all
/// due at one column now and then; then the frame end (`ends` slots in
/// use) and the next frame's clear; a reset at column `reset_at`.
fn frame(rng: &mut ChaCha8Rng, cols: u16, ends: usize, reset_at: Option<u16>) -> Vec<Event> {
    let mut events = vec![];
    let mut late_mark: Option<(u16, usize)> = None;
    let (mut load, mut spread) = (Load::Busy, 0);
    for x in 0..cols {
        if x % 50 == 0 {
            load = [Load::Sparse, Load::Busy, Load::Busy, Load::Fill][rng.gen_range(0..4)];
            spread = [0, 0, 8, 4096][rng.gen_range(0..4)];
        }
        if reset_at == Some(x) {
            events.push(Event::Reset);
            late_mark = None;
        }
        let flood = rng.gen_range(0..150) == 0;
        let n = match load {
            _ if flood => [40, 100, 300][rng.gen_range(0..3)],
            Load::Sparse => rng.gen_range(0..=2),
            Load::Busy => rng.gen_range(0..=12),
            Load::Fill => 12,
        };
        for k in 0..n {
            if let Some((c, at)) = late_mark {
                if at == k {
                    events.push(Event::Mark(c));
                    late_mark = None;
                }
            }
            let last = match load {
                // All due at `x` (`max(last + h, x)` with `last <= x - h`).
                _ if flood => x.saturating_sub(8),
                Load::Fill => x,
                _ => x - rng.gen_range(0..=x.min(6)),
            };
            events.push(Event::Report(Report {
                slot: rng.gen_range(0..512),
                key: key(rng, spread),
                last,
                col: x,
            }));
        }
        if let Some((c, _)) = late_mark.take() {
            events.push(Event::Mark(c));
        }
        if rng.gen_range(0..3) == 0 {
            late_mark = Some((x, rng.gen_range(1..4)));
        } else {
            events.push(Event::Mark(x));
        }
        events.push(Event::Idle(ROWS));
    }
    if let Some((c, _)) = late_mark {
        events.push(Event::Mark(c));
    }
    events.push(Event::EndStart(cols));
    for _ in 0..ends {
        events.push(Event::Report(Report {
            slot: rng.gen_range(0..512),
            key: key(rng, 0),
            last: rng.gen_range(0..cols),
            col: rng.gen_range(0..cols),
        }));
    }
    events.push(Event::Mark(cols));
    events.push(Event::Clear);
    events
}

fn model() -> PlainModel<ClIn, ClOut> {
    load_plain::<ClIn, ClOut>(BenchBlock::Closer, &FccParams::default()).expect("closer model")
}

#[test]
fn closes_come_by_column_then_first_pixel() {
    let model = model();
    let mut all = Seen::default();
    for (seed, rate, take) in [
        (0xd1, 1.0, 1.0),
        (0xd2, 0.5, 0.7),
        (0xd3, 0.9, 0.2),
        (0xd4, 0.2, 1.0),
    ] {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let half = rng.gen_range(1..=5);
        let what = format!("seed {seed:#x}, h = {half}");
        let mut b = Bench::new(&model, half, what);
        for f in 0..3 {
            let cols = [300, 700, 200][f];
            let ends = [0, 60, 512][(seed as usize + f) % 3];
            let reset_at = (f == 1).then(|| rng.gen_range(10..cols));
            let events = frame(&mut rng, cols, ends, reset_at);
            b.last_col = cols - 1;
            b.run(&mut rng, events, rate, take);
        }
        b.drain(1_000_000);
        let s = b.seen;
        println!("seed {seed:#x}, h = {half}: {} cycles, {s:?}", b.cycle);
        all.reports += s.reports;
        all.closes += s.closes;
        all.long_columns += s.long_columns;
        all.no_room += s.no_room;
        all.end_closes += s.end_closes;
        all.past_end += s.past_end;
        all.worst_wait = all.worst_wait.max(s.worst_wait);
        all.most_waiting = all.most_waiting.max(s.most_waiting);
    }
    println!("in all: {all:?}");
    assert!(
        all.reports > 30_000
            && all.closes > 30_000
            && all.long_columns > 20
            && all.no_room > 1_000
            && all.end_closes > 1_000
            && all.past_end > 50
            && all.most_waiting > WAIT,
        "too little of some traffic: {all:?}"
    );
}

/// Cycles from column `c`'s marker to its last close taken, with `wait`
/// entries waiting for later columns and `due` due at `c`, every close
/// taken at once.
fn pass_cycles(model: &PlainModel<ClIn, ClOut>, half: u16, wait: usize, due: usize) -> u64 {
    let mut rng = ChaCha8Rng::seed_from_u64(0xd5 + (wait * 1000 + due) as u64);
    let mut b = Bench::new(model, half, format!("{wait} waiting, {due} due"));
    let c = 100;
    let report = |rng: &mut ChaCha8Rng, last| {
        Event::Report(Report {
            slot: rng.gen_range(0..512),
            key: key(rng, 0),
            last,
            col: c,
        })
    };
    let mut events: Vec<Event> = (0..wait).map(|_| report(&mut rng, c)).collect();
    events.extend((0..due).map(|_| report(&mut rng, c - half)));
    events.push(Event::Idle(8));
    events.push(Event::Mark(c));
    b.run(&mut rng, events, 1.0, 1.0);
    b.drain(100_000);
    assert_eq!(b.seen.closes, due as u64, "{}: closes", b.what);
    b.seen.worst_wait
}

#[test]
fn a_pass_reads_each_entry_in_two_cycles_and_sends_a_close_a_cycle() {
    let model = model();
    for (wait, due) in [
        (0, 1),
        (0, 10),
        (40, 10),
        (100, 1),
        (100, 32),
        (0, 33),
        (50, 64),
        (5, 100),
    ] {
        let got = pass_cycles(&model, 3, wait, due);
        // The marker's way in and the first pass's start: 5 cycles; each
        // pass reads every entry in the list (2 cycles an entry) and sends
        // up to `CLOSE_ENTRIES`; a pass after the first starts 4 cycles
        // after the one before has sent its last.
        let mut want = 5;
        let mut left = due;
        while left > 0 {
            let sent = left.min(CLOSE_ENTRIES);
            want += 2 * (wait + left) + sent + if left < due { 4 } else { 0 };
            left -= sent;
        }
        println!("{wait} waiting, {due} due: {got} cycles from the marker to the last close");
        assert_eq!(
            got, want as u64,
            "{wait} waiting, {due} due: cycles expected (left), got (right)"
        );
    }
}
