//! `FccSqDist`: is the squared Euclidean distance of two Q7.8 points below a
//! threshold? Seven registered stages, no enable (the front end never stalls).
//!
//! Stage 1 takes the three differences `a - b` as 17-bit two's complement
//! numbers (the inputs are offset binary, so the difference of the unsigned
//! codes is the difference of the values). Three DSP48E1 square them, each with
//! its A/B, M and P registers, and add the squares through the P cascade
//! (x in the first, y added in the second one cycle later, z in the third);
//! the y and z differences wait in alignment registers. The last stage compares
//! the sum with the threshold and ANDs it with `en_in`, delayed alongside.
//!
//! Exactness: every difference is exact in 17 bits, every square below 2^32,
//! the sum below 3 * 2^32 < 2^36, so the comparison sees the exact integer.
//!
//! The Verilog is written by hand (`Verilog::Custom`) so that Yosys and Vivado
//! infer the DSP pipeline and cascade; `update` models it cycle for cycle.

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
    /// `en_in & (d2 < th)` (or `<=` when inclusive), `SQ_LATENCY` cycles later.
    pub hit: Signal<Out, Bit>,
    _th: u64,
    _inclusive: bool,
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
    /// `hit` when the squared distance is below `th` (`<= th` if `inclusive`).
    pub fn new(th: u64, inclusive: bool) -> Self {
        assert!(th < (1 << 35));
        Self {
            clk: Default::default(),
            ax: Default::default(),
            ay: Default::default(),
            az: Default::default(),
            bx: Default::default(),
            by: Default::default(),
            bz: Default::default(),
            en_in: Default::default(),
            hit: Default::default(),
            _th: th,
            _inclusive: inclusive,
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

impl Logic for FccSqDist {
    fn update(&mut self) {
        if self.clk.pos_edge() {
            let v = |s: &Signal<In, Bits<16>>| s.val().index() as i64;
            let pz = self._p[2] as u64;
            let pass = if self._inclusive {
                pz <= self._th
            } else {
                pz < self._th
            };
            self.hit.next = self._en[5] && pass;
            self._p = [self._m[0], self._p[0] + self._m[1], self._p[1] + self._m[2]];
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
        let op = if self._inclusive { "<=" } else { "<" };
        Verilog::Custom(format!(
            "// Differences (17-bit two's complement), alignment of y and z, then\n\
             // three DSP48E1: A/B registers, M register, P register and P cascade.\n\
             reg signed [16:0] dx, dy, dz;\n\
             reg signed [16:0] dy1, dz1, dz2;\n\
             reg signed [16:0] xa, ya, za;\n\
             reg signed [33:0] mx, my, mz;\n\
             reg [35:0] px, py, pz;\n\
             reg [5:0] en_d;\n\
             always @(posedge clk) begin\n\
             \x20   dx <= $signed({{1'b0, ax}}) - $signed({{1'b0, bx}});\n\
             \x20   dy <= $signed({{1'b0, ay}}) - $signed({{1'b0, by}});\n\
             \x20   dz <= $signed({{1'b0, az}}) - $signed({{1'b0, bz}});\n\
             \x20   dy1 <= dy;\n\
             \x20   dz1 <= dz;\n\
             \x20   dz2 <= dz1;\n\
             \x20   xa <= dx;\n\
             \x20   ya <= dy1;\n\
             \x20   za <= dz2;\n\
             \x20   mx <= xa * xa;\n\
             \x20   my <= ya * ya;\n\
             \x20   mz <= za * za;\n\
             \x20   px <= {{2'b0, mx}};\n\
             \x20   py <= px + {{2'b0, my}};\n\
             \x20   pz <= py + {{2'b0, mz}};\n\
             \x20   en_d <= {{en_d[4:0], en_in}};\n\
             \x20   hit <= en_d[5] & (pz {op} 36'd{th});\n\
             end\n",
            th = self._th,
        ))
    }
}
