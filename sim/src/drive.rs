//! Driving frames through the core over its AXI4-Stream ports.

use fcc_golden::Frame;
use fcc_pixel::{label_of_beat, LABEL_SLOT_BITS, LABEL_SLOT_BYTES};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

use crate::axil::{AxilM, AxilPort, AxilS};
use crate::model::{Dut, FccIn, FccOut};
use crate::SimError;

/// The TKEEP bits of a label slot that holds a label.
const SLOT_KEEP: u8 = (1 << LABEL_SLOT_BYTES) - 1;

/// Where `tlast` goes in the input stream.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Tlast {
    /// On the frame's last pixel.
    Normal,
    /// On pixel `at` (< last): the frame is cut short there.
    Early { at: usize },
    /// Missing on the last pixel; `extra` more beats follow, the last with `tlast`.
    Late { extra: usize },
}

/// How to drive one frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Drive {
    /// Probability that no input beat is offered in a cycle (between beats).
    pub gap: f64,
    /// Probability that the output is not ready in a cycle.
    pub backpressure: f64,
    /// Seed of the gap and back-pressure patterns.
    pub seed: u64,
    pub tlast: Tlast,
    /// Give up after this many cycles.
    pub max_cycles: u64,
}

impl Default for Drive {
    fn default() -> Self {
        Drive {
            gap: 0.0,
            backpressure: 0.0,
            seed: 0,
            tlast: Tlast::Normal,
            max_cycles: 50_000_000,
        }
    }
}

/// What came out of one frame.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct FrameRun {
    /// Labels in raster order (R x C of them).
    pub labels: Vec<u32>,
    pub clusters: u32,
    pub provisional: u32,
    pub overflow: bool,
    pub unlabelled: u32,
    pub frame_error: bool,
    /// Unique joins that reached the merge table.
    pub joins: u32,
    /// Read-back cycles that waited for flattened labels.
    pub gear_stalls: u32,
    /// First pixel accepted to last label beat accepted, inclusive.
    pub cycles: u64,
    /// Last input beat accepted to last label beat accepted.
    pub latency: u64,
    /// Cycles in which an input beat was offered but not accepted.
    pub input_stalls: u64,
    /// Output beats.
    pub beats: u64,
}

pub use fcc_pixel::pixel_beat;

/// The input beats of a frame: (tdata, tlast).
pub fn frame_beats(frame: &Frame, tlast: Tlast) -> Vec<(u64, bool)> {
    let n = frame.points.len();
    let mut beats: Vec<(u64, bool)> = frame
        .points
        .iter()
        .enumerate()
        .map(|(i, p)| (pixel_beat(*p), i + 1 == n))
        .collect();
    match tlast {
        Tlast::Normal => {}
        Tlast::Early { at } => {
            beats.truncate(at + 1);
            if let Some(b) = beats.last_mut() {
                b.1 = true;
            }
        }
        Tlast::Late { extra } => {
            if let Some(b) = beats.last_mut() {
                b.1 = false;
            }
            for i in 0..extra {
                beats.push((pixel_beat(Some([i as i16, 0, 0])), i + 1 == extra));
            }
        }
    }
    beats
}

impl Dut {
    /// Hold reset for `cycles` cycles.
    pub fn reset(&mut self, cycles: u64) {
        let inp = FccIn {
            rst: 1,
            m_axis_tready: 1,
            ..Default::default()
        };
        for _ in 0..cycles {
            self.step(&inp);
        }
        self.frames_seen = 0;
    }

    /// Offer the first `n` beats of `frame` (no gaps, output always ready)
    /// and stop: used to interrupt a frame with a reset.
    pub fn feed_partial(
        &mut self,
        frame: &Frame,
        n: usize,
        max_cycles: u64,
    ) -> Result<(), SimError> {
        let beats = frame_beats(frame, Tlast::Normal);
        let mut i = 0;
        let start = self.cycle;
        while i < n.min(beats.len()) {
            let inp = FccIn {
                s_axis_tdata: beats[i].0,
                s_axis_tvalid: 1,
                s_axis_tlast: u8::from(beats[i].1),
                m_axis_tready: 1,
                ..Default::default()
            };
            let out = self.step(&inp);
            if out.s_axis_tready != 0 {
                i += 1;
            }
            if self.cycle - start > max_cycles {
                return Err(SimError::Timeout {
                    cycles: max_cycles,
                    accepted: i,
                    emitted: 0,
                });
            }
        }
        Ok(())
    }

    /// Drive one frame in and collect its labels.
    pub fn run_frame(&mut self, frame: &Frame, drive: &Drive) -> Result<FrameRun, SimError> {
        self.run_frame_from(frame, drive, 0)
    }

    /// [`run_frame`](Self::run_frame) for a frame whose first `skip` beats
    /// were already accepted (by [`feed_partial`](Self::feed_partial)):
    /// drive the rest and collect the frame's labels.
    pub fn run_frame_from(
        &mut self,
        frame: &Frame,
        drive: &Drive,
        skip: usize,
    ) -> Result<FrameRun, SimError> {
        let p = self.params().clone();
        let lpb = p.labels_per_beat as usize;
        let beats = frame_beats(frame, drive.tlast);
        let mut rng = ChaCha8Rng::seed_from_u64(drive.seed);
        let mut run = FrameRun::default();
        let mut idx = skip.min(beats.len());
        let mut offering = false;
        let mut first_in: Option<u64> = None;
        let mut last_in = 0u64;
        let mut last_out: Option<u64> = None;
        let mut done = false;
        let start = self.cycle;
        while !(done && idx == beats.len()) {
            if self.cycle - start > drive.max_cycles {
                return Err(SimError::Timeout {
                    cycles: drive.max_cycles,
                    accepted: idx,
                    emitted: run.labels.len(),
                });
            }
            if !offering && idx < beats.len() {
                offering = drive.gap <= 0.0 || rng.gen::<f64>() >= drive.gap;
            }
            let ready = drive.backpressure <= 0.0 || rng.gen::<f64>() >= drive.backpressure;
            let (tdata, tlast) = if offering { beats[idx] } else { (0, false) };
            let inp = FccIn {
                s_axis_tdata: tdata,
                s_axis_tvalid: u8::from(offering),
                s_axis_tlast: u8::from(tlast),
                m_axis_tready: u8::from(ready),
                ..Default::default()
            };
            let now = self.cycle;
            let out: FccOut = self.step(&inp);
            if offering {
                if out.s_axis_tready != 0 {
                    first_in.get_or_insert(now);
                    last_in = now;
                    idx += 1;
                    offering = false;
                } else if first_in.is_some() {
                    run.input_stalls += 1;
                }
            }
            if out.m_axis_tvalid != 0 && ready {
                if done || last_out.is_some() {
                    return Err(SimError::Protocol(format!(
                        "output beat after the frame's last beat (cycle {now})"
                    )));
                }
                run.beats += 1;
                for s in 0..lpb {
                    let keep = (out.m_axis_tkeep >> (LABEL_SLOT_BYTES * s)) & SLOT_KEEP;
                    match keep {
                        SLOT_KEEP => run.labels.push(label_of_beat(out.m_axis_tdata, s)),
                        0 => {}
                        _ => {
                            return Err(SimError::Protocol(format!(
                                "tkeep {:#04x} splits a {LABEL_SLOT_BITS}-bit slot (cycle {now})",
                                out.m_axis_tkeep
                            )))
                        }
                    }
                }
                if out.m_axis_tlast != 0 {
                    last_out = Some(now);
                }
            }
            if out.status_frame_done != 0 {
                if last_out.is_none() {
                    return Err(SimError::Protocol(format!(
                        "frame_done before the last label beat (cycle {now})"
                    )));
                }
                done = true;
                run.clusters = out.status_clusters;
                run.provisional = out.status_provisional;
                run.overflow = out.status_overflow != 0;
                run.unlabelled = out.status_unlabelled;
                run.frame_error = out.status_frame_error != 0;
                run.joins = out.status_joins;
                run.gear_stalls = out.status_gear_stalls;
            }
        }
        let first = first_in.unwrap_or(start);
        let last = last_out.unwrap_or(self.cycle);
        run.cycles = last + 1 - first;
        run.latency = last.saturating_sub(last_in);
        let pixels = frame.rows * frame.cols;
        if run.labels.len() != pixels {
            return Err(SimError::Protocol(format!(
                "{} labels out for a frame of {pixels} pixels",
                run.labels.len(),
            )));
        }
        Ok(run)
    }
}

impl AxilPort for Dut {
    /// One cycle of register access with the pixel stream idle and the
    /// label stream ready.
    fn axil_cycle(&mut self, m: &AxilM) -> AxilS {
        let idle = FccIn {
            m_axis_tready: 1,
            ..Default::default()
        };
        let o = self.step(&crate::axil::axil_inputs!(FccIn, m, idle));
        crate::axil::axil_outputs!(o)
    }
}
