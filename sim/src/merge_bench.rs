//! The merge table `fcc_merge_table` alone under Verilator: built (once,
//! cached) from `fcc_rtl::generate_merge_table`, fed joins with random gaps,
//! flattened against random gearbox back-pressure, and compared with the
//! golden model's `ExactMerge`.

use fcc_golden::{renumber, ExactMerge};
use fcc_params::FccParams;
use rand::rngs::StdRng;
use rand::Rng;

use crate::ffi::c_struct;
use crate::plain::{load_plain, PlainDut, PlainModel};
use crate::SimError;

c_struct! {
    /// Inputs of one cycle (declared to the shim by the generated `fcc_ffi.h`).
    pub struct MergeIn {
        pub provisional: u32,
        pub ja: u16,
        pub jb: u16,
        pub rst: u8,
        pub jv: u8,
        pub jsame: u8,
        pub flat_start: u8,
        pub gear_used: u8,
    }
}

c_struct! {
    /// Outputs during one cycle.
    pub struct MergeOut {
        pub fval: u16,
        pub clusters: u16,
        pub jtake: u8,
        pub init_busy: u8,
        pub union_idle: u8,
        pub fv: u8,
    }
}

/// A loaded Verilator model of `fcc_merge_table`.
pub type MergeModel = PlainModel<MergeIn, MergeOut>;

/// Load the merge-table model of the build `p`, building it if needed.
pub fn load_merge_table(p: &FccParams) -> Result<MergeModel, SimError> {
    load_plain(fcc_rtl::BenchBlock::MergeTable, p)
}

/// One frame for the merge table: labels `1 ..= provisional` and the joins
/// between them, in stream order.
#[derive(Debug, Clone, Default)]
pub struct MergeFrame {
    pub provisional: u32,
    pub joins: Vec<(u32, u32)>,
}

impl MergeFrame {
    /// The golden compact label of every label `1 ..= provisional` (index
    /// `l - 1`) and the number of components, from `ExactMerge`.
    pub fn expected(&self) -> (Vec<u32>, u32) {
        let mut m = ExactMerge::new(self.provisional);
        for &(a, b) in &self.joins {
            m.union(a, b);
        }
        let rep = m.representatives();
        let labels: Vec<u32> = (1..=self.provisional).collect();
        renumber(&labels, &rep)
    }
}

/// How hard the bench pushes on the table's two streams.
#[derive(Debug, Clone, Copy)]
pub struct Pressure {
    /// Probability that a waiting join is not offered in a cycle.
    pub join_gap: f64,
    /// Probability that the gearbox reports itself full in a cycle (else it
    /// reports a random fill level it has room beside).
    pub gear_full: f64,
    /// Probability that a join with the same `a` as the join before it is
    /// offered with `jsame` set.
    pub use_same: f64,
}

impl Pressure {
    pub const NONE: Pressure = Pressure {
        join_gap: 0.0,
        gear_full: 0.0,
        use_same: 1.0,
    };
    pub const RANDOM: Pressure = Pressure {
        join_gap: 0.3,
        gear_full: 0.3,
        use_same: 0.7,
    };
}

/// What a frame through the table gave.
#[derive(Debug, Clone, PartialEq)]
pub struct MergeResult {
    /// Compact labels in emission order.
    pub labels: Vec<u32>,
    pub clusters: u32,
    /// Cycles from the first join offered to the last join taken.
    pub union_cycles: u64,
    /// Cycles from `flat_start` to the last compact label.
    pub flatten_cycles: u64,
}

/// One simulated merge table.
pub struct MergeDut {
    dut: PlainDut<MergeIn, MergeOut>,
    label_bits: u32,
    cycles: u64,
}

impl MergeDut {
    pub fn new(model: MergeModel, p: &FccParams) -> Self {
        let dut = PlainDut::new(model);
        MergeDut {
            dut,
            label_bits: p.label_bits,
            cycles: 0,
        }
    }

    /// One cycle with `inp`.
    pub fn step(&mut self, inp: &MergeIn) -> MergeOut {
        self.cycles += 1;
        self.dut.step(inp)
    }

    /// Cycles simulated so far.
    pub fn cycles(&self) -> u64 {
        self.cycles
    }

    /// Reset, then wait until the table has made every word a root.
    pub fn reset_and_init(&mut self) -> Result<(), String> {
        for _ in 0..2 {
            self.step(&MergeIn {
                rst: 1,
                ..Default::default()
            });
        }
        let limit = (1u64 << self.label_bits) + 16;
        for _ in 0..limit {
            if self.step(&MergeIn::default()).init_busy == 0 {
                return Ok(());
            }
        }
        Err(format!("init still busy after {limit} cycles"))
    }

    /// Run one frame: offer the joins (holding each until taken), wait for
    /// the union engine to go idle, flatten, and collect the compact labels.
    pub fn run(
        &mut self,
        frame: &MergeFrame,
        pressure: Pressure,
        rng: &mut StdRng,
    ) -> Result<MergeResult, String> {
        let p = frame.provisional;
        // Generous bounds: a walk is at most P steps of two cycles.
        let walk = 2 * u64::from(p) + 64;
        let start = self.cycles;
        let mut prev_a: Option<u32> = None;
        for (i, &(a, b)) in frame.joins.iter().enumerate() {
            let same = prev_a == Some(a) && rng.gen_bool(pressure.use_same);
            let mut waited = 0u64;
            loop {
                let offer = !rng.gen_bool(pressure.join_gap);
                let out = self.step(&MergeIn {
                    jv: u8::from(offer),
                    ja: a as u16,
                    jb: b as u16,
                    jsame: u8::from(same),
                    provisional: p,
                    ..Default::default()
                });
                if offer && out.jtake != 0 {
                    break;
                }
                waited += 1;
                if waited > walk * 4 {
                    return Err(format!("join {i} ({a}, {b}) not taken in {waited} cycles"));
                }
            }
            prev_a = Some(a);
        }
        let union_cycles = self.cycles - start;
        let mut waited = 0u64;
        while self
            .step(&MergeIn {
                provisional: p,
                ..Default::default()
            })
            .union_idle
            == 0
        {
            waited += 1;
            if waited > walk * 4 {
                return Err(format!(
                    "union engine not idle {waited} cycles after the last join"
                ));
            }
        }
        let flat_start = self.cycles;
        self.step(&MergeIn {
            provisional: p,
            flat_start: 1,
            ..Default::default()
        });
        let mut labels = Vec::with_capacity(p as usize);
        let mut clusters = 0;
        let mut quiet = 0u64;
        let limit = 8 * u64::from(p) + 256;
        // After the last label, a few quiet cycles: no label may follow.
        while quiet < 16 {
            let gear_used = if rng.gen_bool(pressure.gear_full) {
                7
            } else {
                rng.gen_range(0..=3)
            };
            let out = self.step(&MergeIn {
                provisional: p,
                gear_used,
                ..Default::default()
            });
            if out.fv != 0 {
                labels.push(u32::from(out.fval));
            }
            clusters = u32::from(out.clusters);
            if labels.len() >= p as usize {
                quiet += 1;
            }
            if self.cycles - flat_start > limit {
                return Err(format!(
                    "flatten gave {} of {p} labels in {limit} cycles",
                    labels.len()
                ));
            }
        }
        Ok(MergeResult {
            labels,
            clusters,
            union_cycles,
            flatten_cycles: self.cycles - flat_start,
        })
    }
}

/// Compare a result with the golden numbering: the first differing label,
/// expected and got, or `None` when they agree.
pub fn first_mismatch(frame: &MergeFrame, got: &MergeResult) -> Option<String> {
    let (want, n) = frame.expected();
    for (i, w) in want.iter().enumerate() {
        match got.labels.get(i) {
            Some(g) if g == w => {}
            Some(g) => {
                return Some(format!(
                    "label {}: expected compact label {w}, got {g}",
                    i + 1
                ))
            }
            None => {
                return Some(format!(
                    "label {}: expected compact label {w}, got nothing ({} labels emitted)",
                    i + 1,
                    got.labels.len()
                ))
            }
        }
    }
    if got.labels.len() > want.len() {
        return Some(format!(
            "{} labels emitted, expected {}",
            got.labels.len(),
            want.len()
        ));
    }
    if got.clusters != n {
        return Some(format!("clusters: expected {n}, got {}", got.clusters));
    }
    None
}
