//! The Vivado deliverables for the boards of [`Board`] (ZC706 by default),
//! written from the same [`FccParams`] and the same generated port list as
//! the RTL:
//!
//! | File | Function | What it does |
//! |---|---|---|
//! | `constraints/fcc_top.xdc` | [`xdc`] | clock, AXI4-Stream and AXI4-Lite port delays, status false paths; out of context only |
//! | `scripts/fcc_build.tcl` | [`tcl`] | non-project synth / opt / place / route with reports |
//! | `scripts/fcc_package_ip.tcl` | [`package_ip_tcl`] | `fcc_top` as an IP with its AXI4-Stream, AXI4-Lite, interrupt, clock and reset interfaces |
//! | `scripts/fcc_<board>_bd.tcl` | [`bd_tcl`] | the board's Zynq PS + AXI DMA + the core (registers on the PS's control master, `irq`) |
//! | `scripts/fcc_<board>_example.c` | [`crate::example::c_example`] | bare-metal C: one frame through the DMA, the register sequence |
//!
//! Vivado is not available where this generator is developed and tested: the
//! scripts are written to the letter of the Vivado Tcl reference (UG835) and
//! the user guides on scripting, IP packaging and IP integrator (UG894,
//! UG1118, UG994), parse-checked and dry-run with every Vivado command
//! stubbed (`tests/vivado.rs`), but never run by Vivado here.
//!
//! Every number in these files comes from [`FccParams`] or from the ports of
//! the generated `fcc_top` ([`top_ports`]); the Tcl and XDC retype nothing.
//!
//! [`FccParams`]: fcc_params::FccParams

mod boards;
mod constraints;
mod names;
mod ports;
mod tcl_bd;
mod tcl_build;
mod tcl_ip;
mod template;

pub use boards::{Board, BoardInfo, Ps, PsInfo, BOARDS};
pub use constraints::xdc;
pub use names::{
    ip_version, ip_vlnv, period_ns, vlnv, AXIL_INTERFACE, AXIS_INTERFACES, BUILD_SCRIPT,
    CLOCK_PORT, DEFAULT_OUT, DMA_LENGTH_WIDTH_MAX, IO_DELAY_FRACTION, IP_LIBRARY, IP_TAXONOMY,
    IP_VENDOR, IRQ_PORT, OOC_CLOCK_BUFFER, PACKAGE_SCRIPT, REGS_HEADER, RESET_PORT, STATUS_PREFIX,
};
pub use ports::{axis_port_maps, status_ports, top_ports, Port, PortDir};
pub use tcl_bd::{bd_tcl, dma_frame_bytes, dma_length_width, fclk_mhz, register_map_lines};
pub use tcl_build::{lut_row, tcl};
pub use tcl_ip::package_ip_tcl;
pub(crate) use template::fill_public;

use crate::{top_module, Generated, Layout, RtlError};

/// The scripts and software that travel with `fcc_build.tcl` for `board`:
/// `fcc_package_ip.tcl`, the block design, a copy of `fcc_regs.h` and the
/// bare-metal C example, for the directories of `layout`.
pub fn extra_scripts(
    g: &Generated,
    layout: &Layout,
    board: Board,
) -> Result<Vec<(&'static str, String)>, RtlError> {
    let ports = top_ports(&g.verilog, &top_module(&g.params));
    let rtl = relative(&layout.scripts, &layout.rtl.join("fcc_top.v"));
    let xdc = relative(&layout.scripts, &layout.constraints.join("fcc_top.xdc"));
    let b = board.info();
    Ok(vec![
        (
            PACKAGE_SCRIPT,
            package_ip_tcl(&g.params, board, &ports, &rtl, &xdc),
        ),
        (b.bd_script, bd_tcl(&g.params, &ports, board)?),
        (REGS_HEADER, g.regs_header.clone()),
        (b.example, crate::example::c_example(&g.params, board)),
    ])
}

/// The path of `to` relative to the directory `from`, both as given (made
/// absolute against the current directory); `/` separated, for Tcl.
pub fn relative(from: &std::path::Path, to: &std::path::Path) -> String {
    use std::path::Component;
    let abs = |p: &std::path::Path| -> Vec<String> {
        let p = if p.is_absolute() {
            p.to_path_buf()
        } else {
            std::env::current_dir().unwrap_or_default().join(p)
        };
        let mut parts: Vec<String> = vec![];
        for c in p.components() {
            match c {
                Component::Normal(s) => parts.push(s.to_string_lossy().into_owned()),
                Component::ParentDir => {
                    parts.pop();
                }
                _ => {}
            }
        }
        parts
    };
    let (f, t) = (abs(from), abs(to));
    let common = f.iter().zip(&t).take_while(|(a, b)| a == b).count();
    let mut out: Vec<String> = vec!["..".to_string(); f.len() - common];
    out.extend(t[common..].iter().cloned());
    out.join("/")
}
