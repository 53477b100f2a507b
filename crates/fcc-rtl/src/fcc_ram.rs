//! `FccRam`: a simple dual-port block RAM (one read port, one write port,
//! one clock) whose depth is a run-time parameter.
//!
//! rust-hdl's own `RAM` widget always holds `2^A` words, which would waste
//! block RAM for the frame buffer and line buffers, so this one is written as
//! `Verilog::Custom` with the exact depth. Reads are read-first: a read of the
//! address written in the same cycle returns the old word; users that need the
//! new word forward it themselves. Unwritten words are undefined in Verilog
//! (0 in the rust-hdl model); every user writes before it reads.
//!
//! The read latency is 2 by default: the block RAM's own output register and
//! one fabric register behind it, so nothing but a flip-flop ever hangs off a
//! block RAM output (its clock-to-out is most of a 200 MHz cycle). The read
//! issued with `read_en` in cycle t shows on `read_data` in cycle t+2 and holds
//! until the next read arrives.

use rust_hdl::prelude::*;

use crate::types::clog2;

#[derive(LogicBlock)]
pub struct FccRam<T: Synth, const A: usize> {
    pub clk: Signal<In, Clock>,
    // Read port.
    pub read_en: Signal<In, Bit>,
    pub read_addr: Signal<In, Bits<A>>,
    pub read_data: Signal<Out, T>,
    // Write port.
    pub write_en: Signal<In, Bit>,
    pub write_addr: Signal<In, Bits<A>>,
    pub write_data: Signal<In, T>,
    _depth: usize,
    _stored_bits: usize,
    _lut_ram: bool,
    _mem: Vec<T>,
    _rd1: T,
}

impl<T: Synth, const A: usize> FccRam<T, A> {
    /// A RAM of `depth` words (`2 <= depth <= 2^A`) storing all bits of `T`.
    pub fn new(depth: usize) -> Self {
        Self::with_stored_bits(depth, T::BITS)
    }

    /// A RAM that stores only the low `stored_bits` bits of each word (the
    /// upper bits read back as zero). Values written must fit.
    pub fn with_stored_bits(depth: usize, stored_bits: usize) -> Self {
        assert!(
            (2..=(1usize << A)).contains(&depth),
            "FccRam depth {depth} does not fit {A} address bits"
        );
        assert!((1..=T::BITS).contains(&stored_bits));
        Self {
            clk: Default::default(),
            read_en: Default::default(),
            read_addr: Default::default(),
            read_data: Default::default(),
            write_en: Default::default(),
            write_addr: Default::default(),
            write_data: Default::default(),
            _depth: depth,
            _stored_bits: stored_bits,
            _lut_ram: false,
            _mem: vec![T::default(); depth],
            _rd1: T::default(),
        }
    }
}

impl<T: Synth, const A: usize> FccRam<T, A> {
    /// Kept in LUT RAM (`ram_style = "distributed"`, which Vivado and
    /// Yosys both follow) instead of where the tool finds it cheapest: a
    /// few wide words that would take block RAM for their width alone.
    pub fn in_lut_ram(mut self) -> Self {
        self._lut_ram = true;
        self
    }
}

impl<T: Synth, const A: usize> Logic for FccRam<T, A> {
    fn update(&mut self) {
        if self.clk.pos_edge() {
            self.read_data.next = self._rd1;
            if self.read_en.val() {
                let a = self.read_addr.val().index();
                self._rd1 = self._mem.get(a).copied().unwrap_or_default();
            }
            if self.write_en.val() {
                let a = self.write_addr.val().index();
                if let Some(w) = self._mem.get_mut(a) {
                    *w = self.write_data.val();
                }
            }
        }
    }

    fn connect(&mut self) {
        self.read_data.connect();
    }

    fn hdl(&self) -> Verilog {
        let aw = clog2(self._depth);
        let sw = self._stored_bits;
        let tw = T::BITS;
        let idx = |port: &str| {
            if aw == A {
                port.to_string()
            } else {
                format!("{port}[{}:0]", aw - 1)
            }
        };
        let mut unused = vec![];
        if aw < A {
            unused.push(format!("read_addr[{}:{aw}]", A - 1));
            unused.push(format!("write_addr[{}:{aw}]", A - 1));
        }
        let (wdata, rdata) = if sw < tw {
            unused.push(format!("write_data[{}:{sw}]", tw - 1));
            (
                format!("write_data[{}:0]", sw - 1),
                format!("{{{}'d0, rd1}}", tw - sw),
            )
        } else {
            ("write_data".to_string(), "rd1".to_string())
        };
        let unused_decl = if unused.is_empty() {
            String::new()
        } else {
            format!(
                "// Address bits above the depth and data bits above the stored width are\n\
                 // not used by this instance.\n\
                 /* verilator lint_off UNUSEDSIGNAL */\n\
                 wire unused_ok = &{{1'b0, {}}};\n\
                 /* verilator lint_on UNUSEDSIGNAL */\n",
                unused.join(", ")
            )
        };
        let style = if self._lut_ram {
            "(* ram_style = \"distributed\" *)\n"
        } else {
            ""
        };
        Verilog::Custom(format!(
            "{unused_decl}{style}reg [{sw_m1}:0] mem [0:{depth_m1}];\n\
             // The block RAM's output register, then a fabric register.\n\
             reg [{sw_m1}:0] rd1;\n\
             always @(posedge clk) begin\n\
             \x20   if (read_en) begin\n\
             \x20       rd1 <= mem[{raddr}];\n\
             \x20   end\n\
             \x20   if (write_en) begin\n\
             \x20       mem[{waddr}] <= {wdata};\n\
             \x20   end\n\
             \x20   read_data <= {rdata};\n\
             end\n",
            sw_m1 = sw - 1,
            depth_m1 = self._depth - 1,
            raddr = idx("read_addr"),
            waddr = idx("write_addr"),
        ))
    }
}
