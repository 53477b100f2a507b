//! What the pre-route critical path cannot see: fanout and routing hops.
//!
//! The `sta` estimate ([`crate::sta`]) adds cell delays only. After place and
//! route a 7-series path is mostly wire, and two properties of the netlist say
//! where the wire will be: nets that drive many loads (they are spread over
//! the die and get long, slow routes) and paths that cross many general
//! routing links between cells. Both are read here from the flat netlist that
//! Yosys writes after synthesis (`write_json`).
//!
//! - **Fanout** of a net: the cell input pins and top-level outputs it drives.
//!   The clock (any net that reaches a clock pin) is left out: it has its own
//!   dedicated network. A net that carries a `max_fanout` attribute at or
//!   below [`FANOUT_LIMIT`] (the generator sets it where Vivado is to
//!   replicate the driver) is reported with it; Yosys does not replicate, so
//!   such a net may still show more loads here than it will have in Vivado.
//! - **Hops** of a path: the general-routing links it crosses, from the
//!   launching element (a flip-flop, block RAM, registered DSP output,
//!   distributed RAM or shift register clocked output, or a top-level input)
//!   to the capturing one. A link is one net from a driving pin to a load
//!   pin. Links inside a slice or on dedicated wires do not count: the carry
//!   chain (`CARRY4.CO -> CARRY4.CI`), the wide multiplexers (`LUT -> MUXF7`,
//!   `MUXF7 -> MUXF8`), a LUT into its carry's `S` input, and the DSP cascade
//!   (`PCOUT -> PCIN`). A link into an inverter does not count either: Vivado
//!   folds an `INV` into the LUT or register next to it.
//!   Distributed RAM and shift registers are combinational from their read
//!   address pins to their outputs; a DSP48E1 without its `P` register is
//!   combinational from its data inputs to `P`.

use std::collections::{BTreeMap, HashMap};

use serde::{Deserialize, Serialize};

use crate::sta::CLOCK_PINS;

/// Loads above which a net is reported as high fanout: the generator's
/// fanout target.
pub const FANOUT_LIMIT: usize = fcc_rtl::MAX_FANOUT;
/// Hops above which a path is reported as too long to route at 200 MHz.
pub const HOP_LIMIT: u32 = 5;
/// Nets listed in [`Routing::top_fanout`].
pub const TOP_NETS: usize = 10;
/// Paths listed in [`Routing::worst_paths`].
pub const TOP_PATHS: usize = 5;

/// One net and its loads.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct NetFanout {
    /// The net's name (the shortest public name Yosys keeps for the bit).
    pub net: String,
    /// Cell input pins and top-level outputs it drives.
    pub loads: usize,
    /// The cell (and its type) or top-level input that drives it.
    pub driver: String,
    /// The net's `max_fanout` attribute: Vivado replicates its driver until
    /// no copy drives more loads than this.
    #[serde(default)]
    pub max_fanout: Option<usize>,
}

/// One path in routing hops.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct HopPath {
    /// General-routing links from start to end.
    pub hops: u32,
    /// The launching element: `cell (TYPE.PIN)` or `port (primary input)`.
    pub start: String,
    /// The capturing element: `cell (TYPE.PIN)` or `port (primary output)`.
    pub end: String,
    /// The cells between them (`cell (TYPE)`), in order.
    pub through: Vec<String>,
}

/// Fanout and hop figures of one netlist.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Routing {
    /// The highest-fanout nets, highest first (at most [`TOP_NETS`]).
    pub top_fanout: Vec<NetFanout>,
    /// Nets with more than [`FANOUT_LIMIT`] loads (clock excluded).
    pub nets_over_limit: usize,
    /// Of those, the nets without a `max_fanout` at or below the limit:
    /// nothing replicates their drivers (`None` in reports written before
    /// the attribute was read).
    #[serde(default)]
    pub unreplicated_over_limit: Option<usize>,
    /// The highest-fanout nets without such a `max_fanout`, highest first
    /// (at most [`TOP_NETS`]).
    #[serde(default)]
    pub top_unreplicated: Vec<NetFanout>,
    /// The most hops on any path.
    pub worst_hops: u32,
    /// The longest paths in hops, one per capturing register (the bits of a
    /// bus count once; at most [`TOP_PATHS`]).
    pub worst_paths: Vec<HopPath>,
    /// Capturing pins reached by a path of more than [`HOP_LIMIT`] hops.
    pub endpoints_over_limit: usize,
}

/// A pin of a cell (`cell` indexes the cell list).
#[derive(Debug, Clone, Copy)]
struct Pin<'a> {
    cell: usize,
    name: &'a str,
}

/// How a signal leaves or enters a cell, for the hop count.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Role {
    /// An output that launches a path (clock-to-out).
    Launch,
    /// An input that captures a path.
    Capture,
    /// An input that passes combinationally to the cell's outputs.
    Through,
    /// A clock pin (neither).
    Clock,
}

#[derive(Deserialize)]
struct JsonDesign {
    modules: BTreeMap<String, JsonModule>,
}

#[derive(Deserialize)]
struct JsonModule {
    #[serde(default)]
    ports: BTreeMap<String, JsonPort>,
    #[serde(default)]
    cells: BTreeMap<String, JsonCell>,
    #[serde(default)]
    netnames: BTreeMap<String, JsonNet>,
}

#[derive(Deserialize)]
struct JsonPort {
    direction: String,
    bits: Vec<serde_json::Value>,
}

#[derive(Deserialize)]
struct JsonCell {
    #[serde(rename = "type")]
    cell_type: String,
    #[serde(default)]
    parameters: BTreeMap<String, serde_json::Value>,
    #[serde(default)]
    port_directions: BTreeMap<String, String>,
    #[serde(default)]
    connections: BTreeMap<String, Vec<serde_json::Value>>,
}

#[derive(Deserialize)]
struct JsonNet {
    #[serde(default)]
    hide_name: u8,
    bits: Vec<serde_json::Value>,
    #[serde(default)]
    attributes: BTreeMap<String, serde_json::Value>,
}

/// A net's `max_fanout` attribute (Yosys writes attribute integers as
/// binary strings).
fn max_fanout_attr(net: &JsonNet) -> Option<usize> {
    match net.attributes.get("max_fanout")? {
        serde_json::Value::Number(n) => n.as_u64().map(|v| v as usize),
        serde_json::Value::String(s) => usize::from_str_radix(s, 2).ok(),
        _ => None,
    }
}

/// A net bit: Yosys numbers signals from 2; constants are strings.
fn bit(v: &serde_json::Value) -> Option<u64> {
    v.as_u64()
}

/// A Yosys parameter that is a binary string or a number, as an integer.
fn param(cell: &JsonCell, name: &str) -> Option<u64> {
    match cell.parameters.get(name)? {
        serde_json::Value::Number(n) => n.as_u64(),
        serde_json::Value::String(s) => u64::from_str_radix(s, 2).ok(),
        _ => None,
    }
}

fn is_combinational(t: &str) -> bool {
    t.starts_with("LUT")
        || matches!(
            t,
            "MUXF7" | "MUXF8" | "CARRY4" | "INV" | "BUF" | "MUXCY" | "XORCY"
        )
}

/// Distributed RAM or shift register: clocked writes, combinational reads.
fn is_lut_memory(t: &str) -> bool {
    t.starts_with("RAM") && !t.starts_with("RAMB") || t.starts_with("SRL")
}

/// A read-address pin of a distributed RAM or shift register.
fn is_read_address(pin: &str) -> bool {
    pin.starts_with("ADDR")
        || pin.starts_with("DPRA")
        || pin == "A"
        || (pin.starts_with('A') && pin[1..].chars().all(|c| c.is_ascii_digit()))
}

fn role(cell: &JsonCell, pin: &str, input: bool) -> Role {
    let t = cell.cell_type.as_str();
    if input && CLOCK_PINS.contains(&pin) {
        return Role::Clock;
    }
    if is_combinational(t) {
        return if input { Role::Through } else { Role::Launch };
    }
    if is_lut_memory(t) {
        return if !input {
            // Both: launched by the clock, and reached through the address.
            Role::Launch
        } else if is_read_address(pin) {
            Role::Through
        } else {
            Role::Capture
        };
    }
    if t == "DSP48E1" && param(cell, "PREG") == Some(0) {
        return if input { Role::Through } else { Role::Launch };
    }
    // Flip-flops, block RAM, registered DSPs and anything else: a boundary.
    if input {
        Role::Capture
    } else {
        Role::Launch
    }
}

/// A link on a dedicated wire or inside a slice: no general routing.
fn is_dedicated(from_type: &str, from_pin: &str, to_type: &str, to_pin: &str) -> bool {
    match (to_type, to_pin) {
        ("CARRY4", "CI") => from_type == "CARRY4",
        ("CARRY4", "S") => from_type.starts_with("LUT"),
        ("MUXF7", "I0" | "I1") => from_type.starts_with("LUT"),
        ("MUXF8", "I0" | "I1") => from_type == "MUXF7",
        ("DSP48E1", "PCIN" | "ACIN" | "BCIN" | "CARRYCASCIN" | "MULTSIGNIN") => {
            from_type == "DSP48E1" && from_pin.ends_with("OUT")
        }
        ("INV", _) => true,
        _ => false,
    }
}

fn clean(name: &str) -> &str {
    name.trim_start_matches('\\')
}

/// Read the flat netlist of `top` from Yosys's `write_json` output and measure it.
pub fn analyse(json: &str, top: &str) -> Result<Routing, String> {
    let design: JsonDesign =
        serde_json::from_str(json).map_err(|e| format!("not a Yosys JSON netlist: {e}"))?;
    let module = design
        .modules
        .get(top)
        .ok_or_else(|| format!("no module `{top}` in the netlist"))?;
    let cells: Vec<(&String, &JsonCell)> = module.cells.iter().collect();

    // Drivers and loads of every bit.
    let mut driver: HashMap<u64, Pin> = HashMap::new();
    let mut loads: HashMap<u64, Vec<Pin>> = HashMap::new();
    let mut port_loads: HashMap<u64, Vec<&str>> = HashMap::new();
    let mut port_drivers: HashMap<u64, &str> = HashMap::new();
    let mut clock_bits: Vec<u64> = vec![];
    for (name, port) in &module.ports {
        for b in port.bits.iter().filter_map(bit) {
            match port.direction.as_str() {
                "input" => {
                    port_drivers.insert(b, name);
                }
                _ => port_loads.entry(b).or_default().push(name),
            }
        }
    }
    for (i, (name, cell)) in cells.iter().enumerate() {
        for (pin, conns) in &cell.connections {
            let dir = cell.port_directions.get(pin).map(String::as_str);
            let input = match dir {
                Some("input") => true,
                Some("output") => false,
                _ => {
                    return Err(format!(
                        "pin {pin} of cell {} ({}) has no direction",
                        clean(name),
                        cell.cell_type
                    ))
                }
            };
            for b in conns.iter().filter_map(bit) {
                let p = Pin { cell: i, name: pin };
                if input {
                    if CLOCK_PINS.contains(&pin.as_str()) {
                        clock_bits.push(b);
                    }
                    loads.entry(b).or_default().push(p);
                } else {
                    driver.insert(b, p);
                }
            }
        }
    }

    // A readable name per bit: the shortest public name, then any name.
    let mut bit_name: HashMap<u64, (bool, String)> = HashMap::new();
    // The smallest `max_fanout` of any name a bit has.
    let mut bit_max_fanout: HashMap<u64, usize> = HashMap::new();
    for (name, net) in &module.netnames {
        let public = net.hide_name == 0;
        let attr = max_fanout_attr(net);
        for (k, b) in net.bits.iter().enumerate() {
            let Some(b) = bit(b) else { continue };
            if let Some(m) = attr {
                let e = bit_max_fanout.entry(b).or_insert(m);
                *e = (*e).min(m);
            }
            let label = if net.bits.len() > 1 {
                format!("{}[{k}]", clean(name))
            } else {
                clean(name).to_string()
            };
            let better = match bit_name.get(&b) {
                None => true,
                Some((p, old)) => (public && !p) || (public == *p && label.len() < old.len()),
            };
            if better {
                bit_name.insert(b, (public, label));
            }
        }
    }
    let name_of = |b: u64| {
        bit_name
            .get(&b)
            .map(|(_, n)| n.clone())
            .unwrap_or_else(|| format!("${b}"))
    };
    let describe_driver = |b: u64| match (driver.get(&b), port_drivers.get(&b)) {
        (Some(p), _) => format!(
            "{} ({}.{})",
            clean(cells[p.cell].0),
            cells[p.cell].1.cell_type,
            p.name
        ),
        (None, Some(port)) => format!("{port} (primary input)"),
        _ => "(undriven)".to_string(),
    };

    // Fanout.
    clock_bits.sort_unstable();
    clock_bits.dedup();
    let mut fanout: Vec<(usize, u64)> = loads
        .iter()
        .filter(|(b, _)| clock_bits.binary_search(b).is_err())
        .map(|(b, l)| (l.len() + port_loads.get(b).map_or(0, Vec::len), *b))
        .collect();
    fanout.sort_unstable_by(|a, b| b.0.cmp(&a.0).then(a.1.cmp(&b.1)));
    let nets_over_limit = fanout.iter().filter(|(n, _)| *n > FANOUT_LIMIT).count();
    let net_fanout = |&(n, b): &(usize, u64)| NetFanout {
        net: name_of(b),
        loads: n,
        driver: describe_driver(b),
        max_fanout: bit_max_fanout.get(&b).copied(),
    };
    let replicated = |b: u64| bit_max_fanout.get(&b).is_some_and(|&m| m <= FANOUT_LIMIT);
    let top_fanout = fanout.iter().take(TOP_NETS).map(net_fanout).collect();
    let unreplicated: Vec<&(usize, u64)> = fanout.iter().filter(|(_, b)| !replicated(*b)).collect();
    let unreplicated_over_limit = Some(
        unreplicated
            .iter()
            .filter(|(n, _)| *n > FANOUT_LIMIT)
            .count(),
    );
    let top_unreplicated = unreplicated
        .into_iter()
        .take(TOP_NETS)
        .map(net_fanout)
        .collect();

    // Hops: longest path through the combinational cells, in topological order.
    // `cell_hops[i]` is the hops at the outputs of combinational cell i, and
    // `cell_from[i]` the input bit that gave it (for the path).
    let n = cells.len();
    let mut cell_hops: Vec<Option<u32>> = vec![None; n];
    let mut cell_from: Vec<Option<u64>> = vec![None; n];
    let through_cell = |i: usize| {
        let cell = cells[i].1;
        cell.connections.iter().any(|(pin, _)| {
            cell.port_directions.get(pin).map(String::as_str) == Some("input")
                && role(cell, pin, true) == Role::Through
        })
    };
    // Hops at a net (its driver's output), given the hops of combinational cells.
    // Launching drivers and primary inputs start at 0.
    let net_hops = |b: u64, cell_hops: &[Option<u32>]| -> u32 {
        match driver.get(&b) {
            Some(p) if through_cell(p.cell) => cell_hops[p.cell].unwrap_or(0),
            _ => 0,
        }
    };
    let link = |b: u64, to: Pin| -> u32 {
        match driver.get(&b) {
            Some(from)
                if is_dedicated(
                    &cells[from.cell].1.cell_type,
                    from.name,
                    &cells[to.cell].1.cell_type,
                    to.name,
                ) =>
            {
                0
            }
            _ => 1,
        }
    };
    // Iterative depth-first topological evaluation (no recursion: paths are deep).
    #[derive(Clone, Copy, PartialEq)]
    enum Mark {
        New,
        Open,
        Done,
    }
    let mut mark = vec![Mark::New; n];
    let through_inputs = |i: usize| -> Vec<(u64, Pin)> {
        let cell = cells[i].1;
        let mut v = vec![];
        for (pin, conns) in &cell.connections {
            if cell.port_directions.get(pin).map(String::as_str) == Some("input")
                && role(cell, pin, true) == Role::Through
            {
                for b in conns.iter().filter_map(bit) {
                    v.push((b, Pin { cell: i, name: pin }));
                }
            }
        }
        v
    };
    for root in 0..n {
        if mark[root] != Mark::New || !through_cell(root) {
            continue;
        }
        let mut stack: Vec<usize> = vec![root];
        while let Some(&i) = stack.last() {
            if mark[i] == Mark::Done {
                stack.pop();
                continue;
            }
            let inputs = through_inputs(i);
            if mark[i] == Mark::New {
                mark[i] = Mark::Open;
                let mut pushed = false;
                for (b, _) in &inputs {
                    if let Some(p) = driver.get(b) {
                        if through_cell(p.cell) {
                            match mark[p.cell] {
                                Mark::New => {
                                    stack.push(p.cell);
                                    pushed = true;
                                }
                                Mark::Open => {
                                    return Err(format!(
                                        "combinational loop through {}",
                                        clean(cells[p.cell].0)
                                    ))
                                }
                                Mark::Done => {}
                            }
                        }
                    }
                }
                if pushed {
                    continue;
                }
            }
            // Every driver is done: evaluate.
            let mut best: Option<(u32, u64)> = None;
            for (b, to) in &inputs {
                let h = net_hops(*b, &cell_hops) + link(*b, *to);
                if best.map_or(true, |(bh, _)| h > bh) {
                    best = Some((h, *b));
                }
            }
            cell_hops[i] = Some(best.map_or(0, |(h, _)| h));
            cell_from[i] = best.map(|(_, b)| b);
            mark[i] = Mark::Done;
            stack.pop();
        }
    }

    // Endpoints: capturing pins and primary outputs.
    let mut ends: Vec<(u32, u64, String, Option<usize>)> = vec![];
    for (i, (name, cell)) in cells.iter().enumerate() {
        for (pin, conns) in &cell.connections {
            if cell.port_directions.get(pin).map(String::as_str) != Some("input")
                || role(cell, pin, true) != Role::Capture
            {
                continue;
            }
            for b in conns.iter().filter_map(bit) {
                if !driver.contains_key(&b) && !port_drivers.contains_key(&b) {
                    continue;
                }
                let h = net_hops(b, &cell_hops) + link(b, Pin { cell: i, name: pin });
                ends.push((
                    h,
                    b,
                    format!("{} ({}.{pin})", clean(name), cell.cell_type),
                    Some(i),
                ));
            }
        }
    }
    for (b, ports) in &port_loads {
        if !driver.contains_key(b) && !port_drivers.contains_key(b) {
            continue;
        }
        for port in ports {
            ends.push((
                net_hops(*b, &cell_hops) + 1,
                *b,
                format!("{port} (primary output)"),
                None,
            ));
        }
    }
    ends.sort_by(|a, b| b.0.cmp(&a.0).then(a.2.cmp(&b.2)));
    let worst_hops = ends.first().map_or(0, |e| e.0);
    let endpoints_over_limit = ends.iter().filter(|e| e.0 > HOP_LIMIT).count();
    let mut worst_paths: Vec<HopPath> = vec![];
    // One path per register: the bits of a bus (`x_FDRE_Q`, `x_FDRE_Q_1`, ...)
    // are one entry.
    let mut seen: Vec<String> = vec![];
    for (hops, b, end, cell) in &ends {
        if worst_paths.len() == TOP_PATHS {
            break;
        }
        let register = match cell {
            Some(i) => {
                let name = clean(cells[*i].0);
                name.trim_end_matches(|c: char| c.is_ascii_digit())
                    .trim_end_matches('_')
                    .to_string()
            }
            None => end.clone(),
        };
        if seen.contains(&register) {
            continue;
        }
        seen.push(register);
        // Walk back through the combinational cells.
        let mut through = vec![];
        let mut at = *b;
        let mut guard = 0;
        while let Some(p) = driver.get(&at) {
            if !through_cell(p.cell) || guard > n {
                break;
            }
            guard += 1;
            through.push(format!(
                "{} ({})",
                clean(cells[p.cell].0),
                cells[p.cell].1.cell_type
            ));
            match cell_from[p.cell] {
                Some(prev) => at = prev,
                None => break,
            }
        }
        through.reverse();
        worst_paths.push(HopPath {
            hops: *hops,
            start: describe_driver(at),
            end: end.clone(),
            through,
        });
    }
    Ok(Routing {
        top_fanout,
        nets_over_limit,
        unreplicated_over_limit,
        top_unreplicated,
        worst_hops,
        worst_paths,
        endpoints_over_limit,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A pin: name, direction, bits.
    type PinSpec = (&'static str, &'static str, &'static [u64]);
    /// A cell: name, type, pins.
    type CellSpec<'a> = (&'static str, &'static str, &'a [PinSpec]);
    /// A cell with its pins owned.
    type OwnedCell = (&'static str, &'static str, Vec<PinSpec>);

    /// A netlist in Yosys's JSON form: `cells` as (name, type, [(pin, dir, bits)]).
    fn netlist(ports: &[PinSpec], cells: &[CellSpec]) -> String {
        let ports: serde_json::Map<String, serde_json::Value> = ports
            .iter()
            .map(|(n, d, b)| {
                (
                    n.to_string(),
                    serde_json::json!({"direction": d, "bits": b}),
                )
            })
            .collect();
        let cells: serde_json::Map<String, serde_json::Value> = cells
            .iter()
            .map(|(n, t, pins)| {
                let dirs: serde_json::Map<String, serde_json::Value> = pins
                    .iter()
                    .map(|(p, d, _)| (p.to_string(), serde_json::json!(d)))
                    .collect();
                let conns: serde_json::Map<String, serde_json::Value> = pins
                    .iter()
                    .map(|(p, _, b)| (p.to_string(), serde_json::json!(b)))
                    .collect();
                (
                    n.to_string(),
                    serde_json::json!({"type": t, "port_directions": dirs, "connections": conns}),
                )
            })
            .collect();
        serde_json::json!({"modules": {"top": {"ports": ports, "cells": cells, "netnames": {
            "clk": {"hide_name": 0, "bits": [2]},
            "q": {"hide_name": 0, "bits": [10]},
        }}}})
        .to_string()
    }

    fn ff(name: &'static str, d: &'static [u64], q: &'static [u64]) -> OwnedCell {
        (
            name,
            "FDRE",
            vec![("C", "input", &[2]), ("D", "input", d), ("Q", "output", q)],
        )
    }

    fn analyse_cells(cells: Vec<OwnedCell>) -> Routing {
        let c: Vec<CellSpec> = cells
            .iter()
            .map(|(n, t, p)| (*n, *t, p.as_slice()))
            .collect();
        analyse(&netlist(&[("clk", "input", &[2])], &c), "top").unwrap()
    }

    #[test]
    fn two_luts_between_flip_flops_are_three_hops() {
        let r = analyse_cells(vec![
            ff("a", &[12], &[10]),
            (
                "l1",
                "LUT1",
                vec![("I0", "input", &[10]), ("O", "output", &[11])],
            ),
            (
                "l2",
                "LUT1",
                vec![("I0", "input", &[11]), ("O", "output", &[12])],
            ),
        ]);
        assert_eq!(r.worst_hops, 3);
        let p = &r.worst_paths[0];
        assert_eq!(p.start, "a (FDRE.Q)");
        assert_eq!(p.end, "a (FDRE.D)");
        assert_eq!(p.through, vec!["l1 (LUT1)", "l2 (LUT1)"]);
        assert_eq!(r.endpoints_over_limit, 0);
    }

    #[test]
    fn carry_chain_and_wide_multiplexers_are_free() {
        let r = analyse_cells(vec![
            ff("a", &[16], &[10]),
            (
                "l",
                "LUT6",
                vec![("I0", "input", &[10]), ("O", "output", &[11])],
            ),
            (
                "m7",
                "MUXF7",
                vec![("I0", "input", &[11]), ("O", "output", &[12])],
            ),
            (
                "m8",
                "MUXF8",
                vec![("I0", "input", &[12]), ("O", "output", &[13])],
            ),
            (
                "c0",
                "CARRY4",
                vec![("S", "input", &[13]), ("CO", "output", &[14])],
            ),
            (
                "c1",
                "CARRY4",
                vec![("CI", "input", &[14]), ("O", "output", &[15])],
            ),
            (
                "inv",
                "INV",
                vec![("I", "input", &[15]), ("O", "output", &[16])],
            ),
        ]);
        // a.Q -> l (1), l -> m7, m7 -> m8, m8 -> c0.S (1: a MUXF8 is not a LUT),
        // c0 -> c1, c1 -> inv (free), inv -> a.D (1).
        assert_eq!(r.worst_hops, 3);
    }

    #[test]
    fn fanout_counts_loads_and_leaves_out_the_clock() {
        let mut cells = vec![ff("src", &[10], &[10])];
        let names: Vec<&'static str> = (0..70)
            .map(|i| &*Box::leak(format!("d{i}").into_boxed_str()))
            .collect();
        for n in &names {
            cells.push(ff(n, &[10], &[]));
        }
        let r = analyse_cells(cells);
        assert_eq!(r.top_fanout[0].net, "q");
        assert_eq!(r.top_fanout[0].loads, 71);
        assert_eq!(r.top_fanout[0].driver, "src (FDRE.Q)");
        assert_eq!(r.nets_over_limit, 1);
        assert!(r.top_fanout.iter().all(|f| f.net != "clk"));
    }

    #[test]
    fn nets_marked_for_replication_are_told_apart() {
        // Three flip-flops, 70 loads each: `q` unmarked, `held` marked at
        // the limit (Yosys's binary form), `wide` marked above it.
        let mut cells = vec![
            ff("src", &[10], &[10]),
            ff("src2", &[11], &[11]),
            ff("src3", &[12], &[12]),
        ];
        let names: Vec<&'static str> = (0..69)
            .map(|i| &*Box::leak(format!("d{i}").into_boxed_str()))
            .collect();
        for n in &names {
            cells.push(ff(n, &[10, 11, 12], &[]));
        }
        let c: Vec<CellSpec> = cells
            .iter()
            .map(|(n, t, p)| (*n, *t, p.as_slice()))
            .collect();
        let mut json: serde_json::Value =
            serde_json::from_str(&netlist(&[("clk", "input", &[2])], &c)).unwrap();
        let nets = &mut json["modules"]["top"]["netnames"];
        nets["held"] = serde_json::json!({"hide_name": 0, "bits": [11],
            "attributes": {"max_fanout": format!("{:032b}", FANOUT_LIMIT)}});
        nets["wide"] = serde_json::json!({"hide_name": 0, "bits": [12],
            "attributes": {"max_fanout": 2 * FANOUT_LIMIT}});
        let r = analyse(&json.to_string(), "top").unwrap();
        assert_eq!(r.nets_over_limit, 3);
        assert_eq!(r.unreplicated_over_limit, Some(2));
        let held = r.top_fanout.iter().find(|n| n.net == "held").unwrap();
        assert_eq!(held.max_fanout, Some(FANOUT_LIMIT));
        let unmarked: Vec<&str> = r.top_unreplicated.iter().map(|n| n.net.as_str()).collect();
        assert!(unmarked.contains(&"q") && unmarked.contains(&"wide"));
        assert!(!unmarked.contains(&"held"));
    }

    #[test]
    fn distributed_ram_reads_are_combinational() {
        let r = analyse_cells(vec![
            ff("a", &[13], &[10]),
            (
                "ram",
                "RAM64M",
                vec![
                    ("WCLK", "input", &[2]),
                    ("ADDRA", "input", &[10]),
                    ("DIA", "input", &[10]),
                    ("DOA", "output", &[11]),
                ],
            ),
            (
                "l",
                "LUT2",
                vec![("I0", "input", &[11]), ("O", "output", &[13])],
            ),
        ]);
        // a.Q -> ram.ADDRA -> l -> a.D.
        assert_eq!(r.worst_hops, 3);
        assert_eq!(r.worst_paths[0].through, vec!["ram (RAM64M)", "l (LUT2)"]);
    }

    #[test]
    fn a_combinational_loop_is_an_error() {
        let c: Vec<CellSpec> = vec![
            (
                "x",
                "LUT1",
                &[("I0", "input", &[11]), ("O", "output", &[10])],
            ),
            (
                "y",
                "LUT1",
                &[("I0", "input", &[10]), ("O", "output", &[11])],
            ),
        ];
        let e = analyse(&netlist(&[], &c), "top").unwrap_err();
        assert!(e.contains("combinational loop"), "{e}");
    }

    #[test]
    fn missing_module_and_bad_json_are_errors() {
        assert!(analyse("{", "top")
            .unwrap_err()
            .contains("not a Yosys JSON netlist"));
        let e = analyse(&netlist(&[], &[]), "other").unwrap_err();
        assert!(e.contains("no module `other`"), "{e}");
    }
}
