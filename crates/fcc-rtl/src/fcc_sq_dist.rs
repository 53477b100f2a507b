//! `FccSqDist`: is the squared Euclidean distance of two Q7.8 points below a
//! threshold? Seven registered stages, no enable (the front end never stalls).
//!
//! Stage 1 takes the three differences `a - b` as 17-bit two's complement
//! numbers (the inputs are offset binary, so the difference of the unsigned
//! codes is the difference of the values). Three DSP48E1 square them, each with
//! its A/B, M and P registers, and add the squares through the P cascade
//! (x plus the addend `c` on the C port in the first, y added in the second one
//! cycle later, z in the third); the y and z differences wait in alignment
//! registers. The sum is `d2 + c`; the threshold is in `c` (`-th` for
//! `d2 < th`, `-(th + 1)` for `d2 <= th`), so the last stage takes the sum's
//! sign bit and ANDs it with `en_in`, delayed alongside. `c` comes from a
//! register that changes only between frames (the run parameters).
//!
//! Exactness: every difference is exact in 17 bits, every square below 2^32,
//! the sum below 3 * 2^32 < 2^34 and `c` >= -(2^30 + 1), so the 36-bit sum
//! holds the exact signed integer.
//!
//! The Verilog is written by hand (`Verilog::Custom`) so that Yosys and Vivado
//! infer the DSP pipeline, post-adder and cascade; `update` models it cycle
//! for cycle.

use rust_hdl::prelude::*;

/// Cycles from the operands to `hit`.
pub const SQ_LATENCY: usize = 7;

#[derive(LogicBlock)]
pub struct FccSqDist {
    pub clk: Signal<In, Clock>,
    // Operands (offset binary).
    pub ax: Signal<In, Bits<16>>,
    pub ay: Signal<In, Bits<16>>,
    pub az: Signal<In, Bits<16>>,
    pub bx: Signal<In, Bits<16>>,
    pub by: Signal<In, Bits<16>>,
    pub bz: Signal<In, Bits<16>>,
    /// ANDed into the result.
    pub en_in: Signal<In, Bit>,
    /// The addend, 36-bit two's complement: `-th` (or `-(th + 1)`).
    pub c: Signal<In, Bits<36>>,
    /// `en_in & (d2 + c < 0)`, `SQ_LATENCY` cycles later.
    pub hit: Signal<Out, Bit>,
    // Model state: differences, alignment, operands, products, sums, enable.
    _d: [i64; 3],
    _dy1: i64,
    _dz1: i64,
    _dz2: i64,
    _op: [i64; 3],
    _m: [i64; 3],
    _p: [i64; 3],
    _en: [bool; 6],
}

impl FccSqDist {
    pub fn new() -> Self {
        Self {
            clk: Default::default(),
            ax: Default::default(),
            ay: Default::default(),
            az: Default::default(),
            bx: Default::default(),
            by: Default::default(),
            bz: Default::default(),
            en_in: Default::default(),
            c: Default::default(),
            hit: Default::default(),
            _d: [0; 3],
            _dy1: 0,
            _dz1: 0,
            _dz2: 0,
            _op: [0; 3],
            _m: [0; 3],
            _p: [0; 3],
            _en: [false; 6],
        }
    }
}

impl Default for FccSqDist {
    fn default() -> Self {
        Self::new()
    }
}

impl Logic for FccSqDist {
    fn update(&mut self) {
        if self.clk.pos_edge() {
            let v = |s: &Signal<In, Bits<16>>| s.val().index() as i64;
            let c = self.c.val().index() as i64;
            let c = if c >= 1 << 35 { c - (1 << 36) } else { c };
            self.hit.next = self._en[5] && self._p[2] < 0;
            self._p = [
                self._m[0] + c,
                self._p[0] + self._m[1],
                self._p[1] + self._m[2],
            ];
            self._m = [
                self._op[0] * self._op[0],
                self._op[1] * self._op[1],
                self._op[2] * self._op[2],
            ];
            self._op = [self._d[0], self._dy1, self._dz2];
            self._dz2 = self._dz1;
            self._dz1 = self._d[2];
            self._dy1 = self._d[1];
            self._d = [
                v(&self.ax) - v(&self.bx),
                v(&self.ay) - v(&self.by),
                v(&self.az) - v(&self.bz),
            ];
            self._en = [
                self.en_in.val(),
                self._en[0],
                self._en[1],
                self._en[2],
                self._en[3],
                self._en[4],
            ];
        }
    }

    fn connect(&mut self) {
        self.hit.connect();
    }

    fn hdl(&self) -> Verilog {
        Verilog::Custom(
            "// Differences (17-bit two's complement), alignment of y and z, then\n\
             // three DSP48E1: A/B registers, M register, P register and P cascade.\n\
             reg signed [16:0] dx, dy, dz;\n\
             reg signed [16:0] dy1, dz1, dz2;\n\
             reg signed [16:0] xa, ya, za;\n\
             reg signed [33:0] mx, my, mz;\n\
             reg [35:0] px, py;\n\
             // Only the sign of the sum is used (the DSP's P register holds it all).\n\
             /* verilator lint_off UNUSEDSIGNAL */\n\
             reg [35:0] pz;\n\
             /* verilator lint_on UNUSEDSIGNAL */\n\
             reg [5:0] en_d;\n\
             always @(posedge clk) begin\n\
             \x20   dx <= $signed({1'b0, ax}) - $signed({1'b0, bx});\n\
             \x20   dy <= $signed({1'b0, ay}) - $signed({1'b0, by});\n\
             \x20   dz <= $signed({1'b0, az}) - $signed({1'b0, bz});\n\
             \x20   dy1 <= dy;\n\
             \x20   dz1 <= dz;\n\
             \x20   dz2 <= dz1;\n\
             \x20   xa <= dx;\n\
             \x20   ya <= dy1;\n\
             \x20   za <= dz2;\n\
             \x20   mx <= xa * xa;\n\
             \x20   my <= ya * ya;\n\
             \x20   mz <= za * za;\n\
             \x20   px <= {2'b0, mx} + c;\n\
             \x20   py <= px + {2'b0, my};\n\
             \x20   pz <= py + {2'b0, mz};\n\
             \x20   en_d <= {en_d[4:0], en_in};\n\
             \x20   hit <= en_d[5] & pz[35];\n\
             end\n"
                .to_string(),
        )
    }
}
