//! `FccThSquare`: squares a threshold for the distance units, serially (shift
//! and add, one multiplier bit per cycle, no DSP): `start` with `a` loads it
//! (`start_acc`, a copy of `start` in the same cycle, clears the sum, so
//! that neither start net drives every register);
//! `busy` stays high until the result is ready (at most 17 cycles), then
//! `c_lt = -a^2` and `c_le = -(a^2 + 1)` (36-bit two's complement, the
//! `FccSqDist` addends of `d2 < a^2` and `d2 <= a^2`) hold until the next
//! `start`, with `s = a^2 >> 8` (24 bits, the squared slope of a slope
//! register, spec §2). For a threshold `a` <= 0x8000, so `a^2` <= 2^30;
//! a slope takes any 16-bit `a`.
//!
//! The Verilog is written by hand (`Verilog::Custom`) for the widening of the
//! 32-bit square to 36 bits; `update` models it cycle for cycle (with
//! `start_acc` equal to `start`).

use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct FccThSquare {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub start: Signal<In, Bit>,
    pub start_acc: Signal<In, Bit>,
    pub a: Signal<In, Bits<16>>,
    pub busy: Signal<Out, Bit>,
    pub c_lt: Signal<Out, Bits<36>>,
    pub c_le: Signal<Out, Bits<36>>,
    pub s: Signal<Out, Bits<24>>,
    // Model state: multiplier, multiplicand, sum, busy.
    _m: u64,
    _c: u64,
    _acc: u64,
    _busy: bool,
}

impl FccThSquare {
    pub fn new() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            start: Default::default(),
            start_acc: Default::default(),
            a: Default::default(),
            busy: Default::default(),
            c_lt: Default::default(),
            c_le: Default::default(),
            s: Default::default(),
            _m: 0,
            _c: 0,
            _acc: 0,
            _busy: false,
        }
    }
}

impl Default for FccThSquare {
    fn default() -> Self {
        Self::new()
    }
}

const MASK36: u64 = (1 << 36) - 1;

impl Logic for FccThSquare {
    fn update(&mut self) {
        if self.clk.pos_edge() {
            // `rst` clears `run` only: the operands and the sum follow
            // `start` and the shifts whatever `rst` is (see `hdl`).
            let step = self._busy && self._m != 0;
            if self.start.val() {
                let a = self.a.val().index() as u64;
                self._m = a;
                self._c = a;
                self._acc = 0;
            } else if step {
                if self._m & 1 == 1 {
                    self._acc = (self._acc + self._c) & 0xffff_ffff;
                }
                self._c = (self._c << 1) & 0xffff_ffff;
                self._m >>= 1;
            }
            self._busy = !self.rst.val() && (self.start.val() || step);
        }
        self.busy.next = self._busy;
        self.c_lt.next = ((1u64 << 36).wrapping_sub(self._acc) & MASK36).to_bits::<36>();
        self.c_le.next = (!self._acc & MASK36).to_bits::<36>();
        self.s.next = (self._acc >> 8).to_bits::<24>();
    }

    fn connect(&mut self) {
        self.busy.connect();
        self.c_lt.connect();
        self.c_le.connect();
        self.s.connect();
    }

    fn hdl(&self) -> Verilog {
        Verilog::Custom(
            "// Shift and add: acc += c for every set bit of m, c doubles, m halves.\n\
             // Only `run` is reset: a start reloads the operands and clears the\n\
             // sum, so `rst` does not reach their enables.\n\
             reg [15:0] m;\n\
             reg [31:0] c;\n\
             reg [31:0] acc;\n\
             reg run;\n\
             always @(posedge clk) begin\n\
             \x20   if (rst) begin\n\
             \x20       run <= 1'b0;\n\
             \x20   end else if (start) begin\n\
             \x20       run <= 1'b1;\n\
             \x20   end else if (run && (m == 16'd0)) begin\n\
             \x20       run <= 1'b0;\n\
             \x20   end\n\
             end\n\
             always @(posedge clk) begin\n\
             \x20   if (start) begin\n\
             \x20       m <= a;\n\
             \x20       c <= {16'd0, a};\n\
             \x20   end else if (run && (m != 16'd0)) begin\n\
             \x20       c <= {c[30:0], 1'b0};\n\
             \x20       m <= {1'b0, m[15:1]};\n\
             \x20   end\n\
             end\n\
             always @(posedge clk) begin\n\
             \x20   if (start_acc) begin\n\
             \x20       acc <= 32'd0;\n\
             \x20   end else if (run && (m != 16'd0) && m[0]) begin\n\
             \x20       acc <= acc + c;\n\
             \x20   end\n\
             end\n\
             always @(*) begin\n\
             \x20   busy = run;\n\
             \x20   c_lt = 36'd0 - {4'd0, acc};\n\
             \x20   c_le = ~{4'd0, acc};\n\
             \x20   s = acc[31:8];\n\
             end\n"
                .to_string(),
        )
    }
}
