//! The column-streaming core (`fcc gen --scan column`) under Verilator:
//! frames in column order in, back to back, and the record stream out,
//! read by `RecordReader` and compared item by item with the golden
//! `Stream` (spec §9). The core has the row-major core's ports, so the same
//! model and [`Dut`] drive it.

use std::collections::VecDeque;

use fcc_golden::{Frame, Stream};
use fcc_params::FccParams;
use fcc_pixel::pixel_beat;
use fcc_pixel::record::{FrameEnd, Item, RecordReader};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

use crate::model::{Dut, FccIn};
use crate::{SimError, Tlast};

/// The input beats of a frame in column order (rows `0 .. R-1` of column
/// 0, then of column 1, ...).
pub fn column_beats(p: &FccParams, f: &Frame) -> Vec<u64> {
    (0..p.pixels())
        .map(|k| pixel_beat(f.get(k % p.rows, k / p.rows)))
        .collect()
}

/// The golden stream's items of one frame: its records in order and its
/// end beat, with `frame_error` as the input gave it.
pub fn golden_items(p: &FccParams, f: &Frame, frame_error: bool) -> Result<Vec<Item>, SimError> {
    let mut s = Stream::new(p)?;
    let mut items = Vec::new();
    let mut column = vec![None; p.rows];
    for c in 0..p.cols {
        for (r, v) in column.iter_mut().enumerate() {
            *v = f.get(r, c);
        }
        let recs = s.push_column(&column)?;
        items.extend(recs.iter().map(|r| Item::Record(r.hw())));
    }
    let recs = s.finish()?;
    items.extend(recs.iter().map(|r| Item::Record(r.hw())));
    let end = s.frame_end().ok_or_else(|| {
        SimError::Mismatch("the golden stream has no frame end after finish".into())
    })?;
    items.push(Item::End(FrameEnd { frame_error, ..end }));
    Ok(items)
}

/// One frame for the core: its beats (with `tlast` on the last) and the
/// items it must give.
#[derive(Debug, Clone)]
pub struct ColFrame {
    pub name: String,
    /// The frame's size.
    pub rows: usize,
    pub cols: usize,
    pub beats: Vec<u64>,
    pub items: Vec<Item>,
}

impl ColFrame {
    /// `f` with its `tlast` as `tlast` says: early (`at`: the index of the
    /// beat with `tlast`; the rest of the frame is empty) or late (`extra`
    /// beats after the last pixel, dropped); either sets `frame_error`.
    pub fn new(p: &FccParams, f: &Frame, tlast: Tlast, name: &str) -> Result<Self, SimError> {
        let mut beats = column_beats(p, f);
        let items = match tlast {
            Tlast::Normal => golden_items(p, f, false)?,
            Tlast::Early { at } => {
                let mut short = f.clone();
                for k in at + 1..p.pixels() {
                    short.set(k % p.rows, k / p.rows, None);
                }
                beats.truncate(at + 1);
                golden_items(p, &short, true)?
            }
            Tlast::Late { extra } => {
                beats.extend((0..extra).map(|i| pixel_beat(Some([i as i16, 7, -7]))));
                golden_items(p, f, true)?
            }
        };
        Ok(ColFrame {
            name: name.to_string(),
            rows: p.rows,
            cols: p.cols,
            beats,
            items,
        })
    }

    /// The frame's records (its end beat's count).
    pub fn records(&self) -> u32 {
        match self.items.last() {
            Some(Item::End(e)) => e.records,
            _ => 0,
        }
    }
}

/// How frames are offered and the records taken.
#[derive(Debug, Clone, Copy)]
pub struct ColDrive {
    /// Probability that no beat is offered in a cycle.
    pub gap: f64,
    /// Probability that the output is not ready in a cycle.
    pub backpressure: f64,
    pub seed: u64,
    /// Give up after this many cycles.
    pub max_cycles: u64,
}

impl Default for ColDrive {
    fn default() -> Self {
        ColDrive {
            gap: 0.0,
            backpressure: 0.0,
            seed: 0,
            max_cycles: 20_000_000,
        }
    }
}

/// What a run of frames gave.
#[derive(Debug, Clone, Default)]
pub struct ColRun {
    /// Cycles from the first beat offered to the last end beat taken.
    pub cycles: u64,
    /// Cycles from the first beat offered to the last frame's last beat
    /// taken.
    pub in_cycles: u64,
    /// Records read, over all frames.
    pub records: usize,
    /// Per frame, the status registers' snapshot as the port gives it after
    /// `status_frame_done`: (clusters, provisional, gear_stalls).
    pub status: Vec<(u32, u32, u32)>,
    /// Per record closed before its frame's end, the cycles from the last
    /// pixel of its closing column (`closed_col`) taken to its first beat
    /// taken.
    pub latency: Vec<u64>,
    /// Per record closed at its frame's end, the cycles from the frame's
    /// last pixel taken to its first beat taken.
    pub end_latency: Vec<u64>,
}

impl ColRun {
    /// Cycles per pixel in: the input's cycles over the pixels of `frames`.
    pub fn cycles_per_pixel(&self, frames: &[ColFrame], p: &FccParams) -> f64 {
        self.in_cycles as f64 / (frames.len() * p.pixels()) as f64
    }
}

/// The `q`-quantile (0 ..= 1) of `v` (sorted here), 0 for none.
pub fn quantile(v: &[u64], q: f64) -> u64 {
    let mut s = v.to_vec();
    s.sort_unstable();
    match s.len() {
        0 => 0,
        n => s[((n - 1) as f64 * q).round() as usize],
    }
}

/// An item in one line.
pub fn short(i: &Item) -> String {
    match i {
        Item::Record(r) => format!(
            "record {}: {} points, columns {}..{} closed at {}, rows {}..{}, seam {}",
            r.id, r.points, r.first_col, r.last_col, r.closed_col, r.first_row, r.last_row, r.seam
        ),
        Item::End(e) => format!(
            "end beat: {} records, overflow {}, frame_error {}",
            e.records, e.overflow, e.frame_error
        ),
    }
}

/// The first item where `got` differs from `want` (a frame's records and
/// end beat): "item I of N: expected ... != got ...", `None` when equal.
pub fn first_difference(want: &[Item], got: &[Item]) -> Option<String> {
    let i = (0..want.len().max(got.len())).find(|&i| want.get(i) != got.get(i))?;
    let show = |v: Option<&Item>| v.map_or("nothing".to_string(), short);
    Some(format!(
        "item {i} of {}: expected {} != got {}",
        want.len(),
        show(want.get(i)),
        show(got.get(i))
    ))
}

impl Dut {
    /// Send `frames` back to back (random gaps and back-pressure as
    /// `drive` says) and check every item read against the frames' golden
    /// items, the status ports against each end beat, and the AXI4-Stream
    /// rules (`tkeep` all ones; `tdata`, `tlast` held while not taken).
    /// The first difference is an error naming the frame, the item, what
    /// was expected and what came, and the seed.
    pub fn run_columns(
        &mut self,
        frames: &[ColFrame],
        drive: &ColDrive,
    ) -> Result<ColRun, SimError> {
        let mut rng = ChaCha8Rng::seed_from_u64(drive.seed);
        let mut want: VecDeque<(usize, usize, Item)> = frames
            .iter()
            .enumerate()
            .flat_map(|(n, f)| f.items.iter().enumerate().map(move |(i, it)| (n, i, *it)))
            .collect();
        let mut ends: VecDeque<FrameEnd> = VecDeque::new();
        let mut reader = RecordReader::new();
        let (mut frame, mut pos) = (0usize, 0usize);
        let mut run = ColRun::default();
        let start = self.cycle;
        let mut held: Option<(u64, u8)> = None;
        // Per frame sent, the cycle each column's last pixel was taken (a
        // frame cut short: its last beat's for the rest).
        let mut col_done: Vec<Vec<u64>> = vec![Vec::new(); frames.len()];
        // The frame being read and the cycle its current item began.
        let (mut reading, mut item_start) = (0usize, None::<u64>);
        while !want.is_empty() || !ends.is_empty() {
            let offer = frame < frames.len() && !rng.gen_bool(drive.gap);
            let take = !rng.gen_bool(drive.backpressure);
            let beats = frames.get(frame).map(|f| f.beats.as_slice()).unwrap_or(&[]);
            let inp = FccIn {
                s_axis_tdata: if offer { beats[pos] } else { 0 },
                s_axis_tvalid: u8::from(offer),
                s_axis_tlast: u8::from(offer && pos + 1 == beats.len()),
                m_axis_tready: u8::from(take),
                ..Default::default()
            };
            let o = self.step(&inp);
            if self.cycle - start > drive.max_cycles {
                return Err(SimError::Timeout {
                    cycles: drive.max_cycles,
                    accepted: frame,
                    emitted: run.records,
                });
            }
            if offer && o.s_axis_tready != 0 {
                pos += 1;
                let (rows, cols) = (frames[frame].rows, frames[frame].cols);
                let upto = if pos == beats.len() {
                    cols
                } else {
                    (pos / rows).min(cols)
                };
                let done = &mut col_done[frame];
                while done.len() < upto {
                    done.push(self.cycle);
                }
                if pos == beats.len() {
                    (frame, pos) = (frame + 1, 0);
                    if frame == frames.len() {
                        run.in_cycles = self.cycle - start;
                    }
                }
            }
            if o.status_frame_done != 0 {
                let e = ends.pop_front().ok_or_else(|| {
                    SimError::Mismatch(format!(
                        "status_frame_done without an end beat (seed {:#x})",
                        drive.seed
                    ))
                })?;
                let clusters = e.records.min(0xFFFF);
                if o.status_clusters != clusters
                    || (o.status_overflow != 0) != e.overflow
                    || (o.status_frame_error != 0) != e.frame_error
                {
                    return Err(SimError::Mismatch(format!(
                        "frame {}: status clusters {}, overflow {}, frame_error {}; its end beat: {} (seed {:#x})",
                        run.status.len(),
                        o.status_clusters,
                        o.status_overflow,
                        o.status_frame_error,
                        short(&Item::End(e)),
                        drive.seed
                    )));
                }
                run.status.push((
                    o.status_clusters,
                    o.status_provisional,
                    o.status_gear_stalls,
                ));
            }
            if o.m_axis_tvalid == 0 {
                if held.is_some() {
                    return Err(SimError::Protocol(format!(
                        "m_axis_tvalid fell before the beat was taken (cycle {})",
                        self.cycle
                    )));
                }
                continue;
            }
            if o.m_axis_tkeep != 0xFF {
                return Err(SimError::Protocol(format!(
                    "m_axis_tkeep {:#x} (cycle {})",
                    o.m_axis_tkeep, self.cycle
                )));
            }
            if let Some(h) = held {
                if h != (o.m_axis_tdata, o.m_axis_tlast) {
                    return Err(SimError::Protocol(format!(
                        "m_axis_tdata or tlast changed while not taken (cycle {})",
                        self.cycle
                    )));
                }
            }
            if !take {
                held = Some((o.m_axis_tdata, o.m_axis_tlast));
                continue;
            }
            held = None;
            let begun = *item_start.get_or_insert(self.cycle);
            let got = reader
                .push(o.m_axis_tdata, o.m_axis_tlast != 0)
                .map_err(|e| {
                    SimError::Mismatch(format!("the record stream: {e} (seed {:#x})", drive.seed))
                })?;
            let Some(got) = got else { continue };
            item_start = None;
            let Some((n, i, exp)) = want.pop_front() else {
                return Err(SimError::Mismatch(format!(
                    "an item after the last frame's end beat: {} (seed {:#x})",
                    short(&got),
                    drive.seed
                )));
            };
            if got != exp {
                return Err(SimError::Mismatch(format!(
                    "frame {n} ({}), item {i}: the first difference\n  expected {}\n  got      {}\nexpected {exp:?}\ngot      {got:?}\n(seed {:#x})",
                    frames[n].name,
                    short(&exp),
                    short(&got),
                    drive.seed
                )));
            }
            match got {
                Item::Record(r) => {
                    run.records += 1;
                    let done = &col_done[reading];
                    let last = *done.last().unwrap_or(&begun);
                    match done.get(r.closed_col as usize) {
                        Some(&at) => run.latency.push(begun.saturating_sub(at)),
                        None => run.end_latency.push(begun.saturating_sub(last)),
                    }
                }
                Item::End(e) => {
                    ends.push_back(e);
                    reading += 1;
                }
            }
            run.cycles = self.cycle - start;
        }
        Ok(run)
    }

    /// Offer the first `n` beats of `frame` (no gaps, records taken) and
    /// stop: a frame to interrupt with a reset.
    pub fn feed_columns(&mut self, frame: &ColFrame, n: usize) -> Result<(), SimError> {
        let mut i = 0;
        let start = self.cycle;
        while i < n.min(frame.beats.len()) {
            let o = self.step(&FccIn {
                s_axis_tdata: frame.beats[i],
                s_axis_tvalid: 1,
                s_axis_tlast: u8::from(i + 1 == frame.beats.len()),
                m_axis_tready: 1,
                ..Default::default()
            });
            if o.s_axis_tready != 0 {
                i += 1;
            }
            if self.cycle - start > 1_000_000 {
                return Err(SimError::Timeout {
                    cycles: 1_000_000,
                    accepted: i,
                    emitted: 0,
                });
            }
        }
        Ok(())
    }
}
