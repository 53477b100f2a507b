//! The critical path from Yosys's `sta` report.
//!
//! `sta` propagates arrival times through the `specify` delays of the cell
//! models (`read_verilog -lib -specify +/xilinx/cells_sim.v`): every primary
//! input, the clock included, arrives at 0; a flip-flop's or RAM's output
//! arrives at its clock-to-out delay; each LUT, MUXF and CARRY4 adds its
//! pin-to-pin delay; an endpoint adds its setup time. There is no routing, no
//! clock skew, no input or output delay. Delays are in picoseconds in the
//! report and in nanoseconds here.
//!
//! The report lists the path from its endpoint back to the primary input:
//!
//! ```text
//! Latest arrival time in 'fcc_top' is 2946:
//!     2946 q_FDRE_Q_2 (FDRE.D)
//!            \q_FDRE_Q_D [13]
//!     2946 sum_CARRY4 (CARRY4.CI->O)
//!            \mem.0.0_DOB [1]
//!     1161 mem.0.18 (RAM64M.WCLK->DOB)
//!        0   \clk (<primary input>)
//! ```

use serde::{Deserialize, Serialize};

/// Pins of the Xilinx primitives that are clocks: an arc from one of them is
/// a clock-to-out arc, so the path starts at that cell.
pub const CLOCK_PINS: [&str; 6] = ["C", "CLK", "WCLK", "CLKARDCLK", "CLKBWRCLK", "CLKA"];

/// One cell on the path and the net it drives.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PathStep {
    /// Arrival time at `net`, ns.
    pub arrival_ns: f64,
    /// Instance name, or the port name for a primary input.
    pub cell: String,
    /// Cell type (`LUT6`, `CARRY4`, ...), or `<primary input>`.
    pub cell_type: String,
    /// Input pin of the arc (empty for a primary input).
    pub from_pin: String,
    /// Output pin of the arc (empty for a primary input).
    pub to_pin: String,
    /// The net the arc drives, as Yosys names it (empty for a primary input).
    pub net: String,
}

impl PathStep {
    fn is_primary_input(&self) -> bool {
        self.cell_type == PRIMARY_INPUT
    }

    /// `cell (TYPE.FROM->TO)`, or `port (primary input)`.
    pub fn describe(&self) -> String {
        if self.is_primary_input() {
            format!("{} (primary input)", clean(&self.cell))
        } else {
            format!(
                "{} ({}.{}->{})",
                clean(&self.cell),
                self.cell_type,
                self.from_pin,
                self.to_pin
            )
        }
    }
}

/// The critical path of one design.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Timing {
    /// Latest arrival at any endpoint, setup included, ns.
    pub critical_path_ns: f64,
    /// `1000 / critical_path_ns`: the clock this path would allow with no routing.
    pub fmax_mhz: f64,
    /// Where the path starts: the clocked cell (`name (TYPE.C->Q)`) or a primary input.
    pub start: String,
    /// Where it ends: `name (TYPE.PIN)` or `(primary output)`.
    pub end: String,
    /// Cells between start and end (LUTs, MUXFs, CARRY4s, ...): Vivado's "logic levels".
    pub logic_levels: u32,
    /// The path, start to end, beginning at the primary input it is timed from.
    pub steps: Vec<PathStep>,
    /// The blocks the path runs through, in order, with the logic levels in
    /// each: the first part of each cell's hierarchical name (`top` when it
    /// has none). Yosys names cells it creates after nearby nets, so the
    /// split is approximate at block boundaries.
    #[serde(default)]
    pub through: Vec<(String, u32)>,
    /// Warnings of `sta` (cells without timing arcs, paths without an endpoint).
    pub warnings: Vec<String>,
}

const PRIMARY_INPUT: &str = "<primary input>";

/// A name as printed by Yosys, without the leading `\` of public names.
fn clean(name: &str) -> String {
    name.trim_start_matches('\\').to_string()
}

fn ps_to_ns(ps: i64) -> f64 {
    ps as f64 / 1000.0
}

/// Split `"  2946 name (TYPE.A->B)"` into arrival, name and the bracketed tail.
fn numbered(line: &str) -> Option<(i64, &str, &str)> {
    let t = line.trim_start();
    let (num, rest) = t.split_once(char::is_whitespace)?;
    let arrival: i64 = num.parse().ok()?;
    let rest = rest.trim();
    let open = rest.rfind('(')?;
    let inner = rest[open + 1..].strip_suffix(')')?;
    Some((arrival, rest[..open].trim(), inner))
}

impl Timing {
    /// Parse the log of one `sta` run on a flattened module.
    pub fn from_sta_log(text: &str) -> Result<Timing, String> {
        // Port resizing warnings come from re-reading the cell models and say
        // nothing about timing; the rest (cells without arcs, paths without an
        // endpoint) do.
        let mut warnings: Vec<String> = text
            .lines()
            .filter_map(|l| l.trim().strip_prefix("Warning: "))
            .filter(|w| !w.starts_with("Resizing cell port"))
            .map(str::to_string)
            .collect();
        warnings.dedup();
        if text.contains("No timing paths found.") {
            return Err("sta found no timing paths (no cell of the design has timing arcs; were the cell models read with -specify?)".into());
        }
        let mut lines = text
            .lines()
            .skip_while(|l| !l.starts_with("Latest arrival time in "));
        let header = lines
            .next()
            .ok_or("no `Latest arrival time` line: this is not the log of `sta`")?;
        let total: i64 = header
            .trim_end_matches(':')
            .rsplit(' ')
            .next()
            .and_then(|n| n.parse().ok())
            .ok_or_else(|| format!("cannot read the arrival time in `{header}`"))?;
        let body: Vec<&str> = lines.take_while(|l| !l.trim().is_empty()).collect();
        let (_, end_name, end_inner) = body
            .first()
            .and_then(|l| numbered(l))
            .ok_or("no endpoint line after `Latest arrival time`")?;
        let end = if end_name.is_empty() {
            end_inner.trim_matches(|c| c == '<' || c == '>').to_string()
        } else {
            format!("{} ({end_inner})", clean(end_name))
        };
        // The rest alternates: the net a cell drives, then the cell and its arc.
        let mut back = vec![];
        let mut net = String::new();
        for line in &body[1..] {
            match numbered(line) {
                None => net = line.trim().to_string(),
                Some((arrival, name, inner)) => {
                    let step = if inner == PRIMARY_INPUT {
                        PathStep {
                            arrival_ns: ps_to_ns(arrival),
                            cell: name.to_string(),
                            cell_type: PRIMARY_INPUT.to_string(),
                            from_pin: String::new(),
                            to_pin: String::new(),
                            net: String::new(),
                        }
                    } else {
                        let (ty, arc) = inner
                            .split_once('.')
                            .ok_or_else(|| format!("cannot read the arc in `{line}`"))?;
                        let (from, to) = arc
                            .split_once("->")
                            .ok_or_else(|| format!("cannot read the arc in `{line}`"))?;
                        PathStep {
                            arrival_ns: ps_to_ns(arrival),
                            cell: name.to_string(),
                            cell_type: ty.to_string(),
                            from_pin: from.to_string(),
                            to_pin: to.to_string(),
                            net: std::mem::take(&mut net),
                        }
                    };
                    back.push(step);
                }
            }
        }
        back.reverse();
        let steps = back;
        if steps.is_empty() {
            return Err("the critical path has no cells".into());
        }
        // A path timed from the clock input starts at the first clocked cell.
        let start_idx = match steps.get(1) {
            Some(s) if steps[0].is_primary_input() && CLOCK_PINS.contains(&s.from_pin.as_str()) => {
                1
            }
            _ => 0,
        };
        let critical_path_ns = ps_to_ns(total);
        if critical_path_ns <= 0.0 {
            return Err(format!(
                "critical path of {total} ps: no cell delays were applied"
            ));
        }
        let mut through: Vec<(String, u32)> = vec![];
        for step in &steps[start_idx + 1..] {
            let name = clean(&step.cell);
            let block = match name.split_once('.') {
                Some((b, _)) => b.to_string(),
                None => "top".to_string(),
            };
            match through.last_mut() {
                Some((b, n)) if *b == block => *n += 1,
                _ => through.push((block, 1)),
            }
        }
        Ok(Timing {
            critical_path_ns,
            through,
            fmax_mhz: 1000.0 / critical_path_ns,
            start: steps[start_idx].describe(),
            end,
            logic_levels: (steps.len() - start_idx - 1) as u32,
            steps,
            warnings,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const LOG: &str = "
5. Executing STA pass (static timing analysis).
Latest arrival time in 'fcc_top' is 2946:
    2946 q_FDRE_Q_2 (FDRE.D)
           \\q_FDRE_Q_D [13]
    2946 s_CARRY4 (CARRY4.CI->O)
           \\s_CO [3]
    2384 s_CARRY4_3 (CARRY4.S->CO)
           \\mem_DOB [1]
    1161 mem.0.18 (RAM64M.WCLK->DOB)
       0   \\clk (<primary input>)

Arrival histogram:
 legend: * represents 1 endpoint(s)
(  2966,   2821] |*****
";

    #[test]
    fn clocked_path_starts_at_the_ram() {
        let t = Timing::from_sta_log(LOG).unwrap();
        assert_eq!(t.critical_path_ns, 2.946);
        assert!((t.fmax_mhz - 339.44).abs() < 0.01, "{}", t.fmax_mhz);
        assert_eq!(t.start, "mem.0.18 (RAM64M.WCLK->DOB)");
        assert_eq!(t.end, "q_FDRE_Q_2 (FDRE.D)");
        assert_eq!(t.logic_levels, 2);
        assert_eq!(t.steps.len(), 4);
        assert_eq!(t.steps[1].net, "\\mem_DOB [1]");
        assert_eq!(t.steps[3].cell_type, "CARRY4");
        assert_eq!(t.steps[3].arrival_ns, 2.946);
        assert_eq!(t.through, vec![("top".to_string(), 2)]);
    }

    #[test]
    fn path_through_blocks_counts_levels_per_block() {
        let log = "Latest arrival time in 'top' is 900:
     900 b.q_FDRE (FDRE.D)
           \\b.d
     800 b.x_LUT2 (LUT2.I0->O)
           \\a.y
     600 a.y_LUT2 (LUT2.I0->O)
           \\a.x
     400 a.x_LUT2 (LUT2.I0->O)
           \\a.q
     303 a.q_FDRE (FDRE.C->Q)
       0   \\clk (<primary input>)
";
        let t = Timing::from_sta_log(log).unwrap();
        assert_eq!(t.start, "a.q_FDRE (FDRE.C->Q)");
        assert_eq!(t.through, vec![("a".to_string(), 2), ("b".to_string(), 1)]);
    }

    #[test]
    fn combinational_path_from_an_input_to_an_output() {
        let log = "Latest arrival time in 'top' is 250:
       250 (<primary output>)
           \\y
       250 y_LUT2 (LUT2.I1->O)
           \\a
       0   \\a (<primary input>)
";
        let t = Timing::from_sta_log(log).unwrap();
        assert_eq!(t.start, "a (primary input)");
        assert_eq!(t.end, "primary output");
        assert_eq!(t.logic_levels, 1);
    }

    #[test]
    fn warnings_are_kept() {
        let log = format!(
            "Warning: Resizing cell port top.m.DIADI from 64 bits to 32 bits.\n\
             Warning: Cell type 'FOO' not recognised! Ignoring.\n{LOG}"
        );
        let t = Timing::from_sta_log(&log).unwrap();
        assert_eq!(
            t.warnings,
            vec!["Cell type 'FOO' not recognised! Ignoring."]
        );
    }

    #[test]
    fn no_paths_says_what_to_check() {
        let e = Timing::from_sta_log("Executing STA pass\nNo timing paths found.\n").unwrap_err();
        assert!(e.contains("-specify"), "{e}");
    }

    #[test]
    fn not_an_sta_log() {
        let e = Timing::from_sta_log("hello\n").unwrap_err();
        assert!(e.contains("not the log of `sta`"), "{e}");
    }

    #[test]
    fn malformed_arc_is_an_error_not_a_panic() {
        let log = "Latest arrival time in 'top' is 10:\n    10 x (FDRE.D)\n    10 y (LUT2)\n";
        assert!(Timing::from_sta_log(log).is_err());
    }
}
