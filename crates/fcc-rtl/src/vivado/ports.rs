//! Ports of the generated top module.

use crate::{RtlError, TOP_NAME};

use super::STATUS_PREFIX;

/// Direction of a top-level port.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PortDir {
    In,
    Out,
}

/// One port of `fcc_top` as the generated Verilog declares it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Port {
    pub name: String,
    pub dir: PortDir,
    pub width: u32,
}

/// The ports of the module `top` (see [`top_module`](crate::top_module)), in declaration
/// order, read from the generated Verilog (`input wire [63:0]
/// s_axis_tdata;` ...). Empty if the module is missing.
pub fn top_ports(verilog: &str, top: &str) -> Vec<Port> {
    let decl = regex::Regex::new(
        r"^\s*(input|output)\s+(?:wire|reg)?\s*(?:\[(\d+):(\d+)\])?\s*([A-Za-z_][A-Za-z0-9_]*)\s*;",
    )
    .expect("valid regex");
    let header = format!("module {top}(");
    let mut ports = vec![];
    let mut inside = false;
    for line in verilog.lines() {
        if !inside {
            inside = line.trim_start().starts_with(&header);
            continue;
        }
        if line.trim_start().starts_with("endmodule") {
            break;
        }
        if let Some(c) = decl.captures(line) {
            let width = match (c.get(2), c.get(3)) {
                (Some(hi), Some(lo)) => {
                    let hi: u32 = hi.as_str().parse().unwrap_or(0);
                    let lo: u32 = lo.as_str().parse().unwrap_or(0);
                    hi.abs_diff(lo) + 1
                }
                _ => 1,
            };
            ports.push(Port {
                name: c[4].to_string(),
                dir: if &c[1] == "input" {
                    PortDir::In
                } else {
                    PortDir::Out
                },
                width,
            });
        }
    }
    ports
}

pub(super) fn port<'a>(ports: &'a [Port], name: &str) -> Result<&'a Port, RtlError> {
    ports.iter().find(|p| p.name == name).ok_or_else(|| {
        RtlError::Check(format!(
            "{TOP_NAME} has no port {name}; the Vivado scripts need it"
        ))
    })
}

/// Ports of one AXI4-Stream interface with their IP-XACT logical names:
/// `s_axis_tdata` is `TDATA` of `s_axis`.
pub fn axis_port_maps<'a>(ports: &'a [Port], interface: &str) -> Vec<(String, &'a Port)> {
    let prefix = format!("{interface}_");
    ports
        .iter()
        .filter_map(|p| {
            p.name
                .strip_prefix(&prefix)
                .map(|logical| (logical.to_uppercase(), p))
        })
        .collect()
}

/// The status ports, in declaration order.
pub fn status_ports(ports: &[Port]) -> Vec<&Port> {
    ports
        .iter()
        .filter(|p| p.name.starts_with(STATUS_PREFIX))
        .collect()
}
