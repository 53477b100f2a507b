//! `FccPointThr`: a point's own thresholds for the range-adaptive join tests
//! (spec §2), computed once as the point enters. Eight registered stages, no
//! enable (the front end never stalls).
//!
//! * P1: each coordinate's coarse magnitude in whole metres,
//!   `m = min((|c| + 128) >> 8, 127)`, from the offset-binary code `u`: for a
//!   negative value `|c| - 1` is `~u[14:0]`, so one adder takes
//!   `u[14:0] + 128` or `~u[14:0] + 129`.
//! * P2: the three squares `m^2` (7-bit inputs: lookup tables, no DSP).
//! * P3: `rc2 = mx^2 + my^2 + mz^2` (at most 48,387), the pair key.
//! * P4 .. P6: two DSP48E1 (A/B, M and P registers): `S_H * rc2` and
//!   `S_V * rc2` (`S < 2^24` on the A port, `rc2 < 2^16` on the B port).
//! * P7: the products again, in fabric flip-flops (a DSP48E1's P output
//!   is too slow to feed a 36-bit compare in the same cycle), the V one
//!   less 256 (the subtraction between flip-flops, not after the DSP's
//!   M register, where its carry chain made the core's longest path).
//! * P8: the `FccSqDist` addends `ch = min(ch_t, ~T_H) = -(max(tH^2, T_H) + 1)`
//!   and `cv = min(cv_t, ~((S_V rc2 - 256) >>> 8)) = -max(tV^2, T_V)` with
//!   `T = (S * rc2) >> 8`, as 36-bit two's complement: `ch_t = -(tH^2 + 1)`
//!   and `cv_t = -tV^2` are the fixed thresholds' addends (`FccThSquare`),
//!   and `~T = -(T + 1)`, `~(T - 1) = -T`. `key` is `rc2`, delayed alongside.
//!
//! Exactness: `S * rc2 < 2^40`, `T < 2^32`, so both addends lie in
//! `[-2^32, -1]` (bits 35..32 set): a store may keep the low 32 bits.
//!
//! The Verilog is written by hand (`Verilog::Custom`) so that the products
//! map to DSP48E1 and the squares to lookup tables; `update` models it cycle
//! for cycle.

use rust_hdl::prelude::*;

/// Cycles from the coordinates to `key`, `ch` and `cv`.
pub const PT_LATENCY: usize = 8;

const MASK36: u64 = (1 << 36) - 1;

#[derive(LogicBlock)]
pub struct FccPointThr {
    pub clk: Signal<In, Clock>,
    /// Clears `key` only, so that it stays a flip-flop behind the key's
    /// delay line (a shift-register LUT's output is slow).
    pub rst: Signal<In, Bit>,
    /// The point (offset binary).
    pub x: Signal<In, Bits<16>>,
    pub y: Signal<In, Bits<16>>,
    pub z: Signal<In, Bits<16>>,
    /// Squared slopes `S = A^2 >> 8` (UQ0.24), from the run parameters.
    pub sh: Signal<In, Bits<24>>,
    pub sv: Signal<In, Bits<24>>,
    /// Fixed thresholds' addends: `-(tH^2 + 1)` and `-tV^2`.
    pub ch_t: Signal<In, Bits<36>>,
    pub cv_t: Signal<In, Bits<36>>,
    /// `PT_LATENCY` cycles later: the coarse squared range (metres^2).
    pub key: Signal<Out, Bits<16>>,
    /// `-(T'_H + 1)`: the addend of `d2 <= T'_H`.
    pub ch: Signal<Out, Bits<36>>,
    /// `-T'_V`: the addend of `d2 < T'_V`.
    pub cv: Signal<Out, Bits<36>>,
    // Model state, one entry per stage.
    _m: [u64; 3],
    _sq: [u64; 3],
    _rc2: [u64; 5],
    _ab: [u64; 3],
    _mul: [u64; 2],
    _p: [i64; 2],
    _pq: [i64; 2],
    _out: [u64; 3],
}

impl FccPointThr {
    pub fn new() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            x: Default::default(),
            y: Default::default(),
            z: Default::default(),
            sh: Default::default(),
            sv: Default::default(),
            ch_t: Default::default(),
            cv_t: Default::default(),
            key: Default::default(),
            ch: Default::default(),
            cv: Default::default(),
            _m: [0; 3],
            _sq: [0; 3],
            _rc2: [0; 5],
            _ab: [0; 3],
            _mul: [0; 2],
            _p: [0; 2],
            _pq: [0; 2],
            _out: [0; 3],
        }
    }
}

impl Default for FccPointThr {
    fn default() -> Self {
        Self::new()
    }
}

/// Coarse magnitude of an offset-binary coordinate, as P1 computes it.
fn metres(u: u64) -> u64 {
    let low = u & 0x7fff;
    let r = if u & 0x8000 != 0 {
        low + 128
    } else {
        (!low & 0x7fff) + 129
    };
    if r & 0x8000 != 0 {
        127
    } else {
        (r >> 8) & 0x7f
    }
}

/// A 36-bit two's complement value as a signed integer.
fn signed36(v: u64) -> i64 {
    if v >= 1 << 35 {
        v as i64 - (1 << 36)
    } else {
        v as i64
    }
}

impl Logic for FccPointThr {
    fn update(&mut self) {
        if self.clk.pos_edge() {
            let ch_t = signed36(self.ch_t.val().index() as u64);
            let cv_t = signed36(self.cv_t.val().index() as u64);
            // P8: the addends (T_H = mul_h >> 8; p_v = S_V rc2 - 256).
            let nh = !(self._pq[0] >> 8);
            let nv = !(self._pq[1] >> 8);
            self._out = [
                if self.rst.val() { 0 } else { self._rc2[4] },
                (ch_t.min(nh) as u64) & MASK36,
                (cv_t.min(nv) as u64) & MASK36,
            ];
            // P7: the products in fabric registers, the V one less 256;
            // P6: the P registers.
            self._pq = [self._p[0], self._p[1] - 256];
            self._p = [self._mul[0] as i64, self._mul[1] as i64];
            // P5: the M registers.
            self._mul = [self._ab[0] * self._ab[2], self._ab[1] * self._ab[2]];
            // P4: the A/B registers; the key waits alongside.
            self._ab = [
                self.sh.val().index() as u64,
                self.sv.val().index() as u64,
                self._rc2[0],
            ];
            self._rc2 = [
                self._sq.iter().sum(),
                self._rc2[0],
                self._rc2[1],
                self._rc2[2],
                self._rc2[3],
            ];
            // P2, P1.
            self._sq = self._m.map(|m| m * m);
            self._m = [
                metres(self.x.val().index() as u64),
                metres(self.y.val().index() as u64),
                metres(self.z.val().index() as u64),
            ];
        }
        self.key.next = self._out[0].to_bits::<16>();
        self.ch.next = self._out[1].to_bits::<36>();
        self.cv.next = self._out[2].to_bits::<36>();
    }

    fn connect(&mut self) {
        self.key.connect();
        self.ch.connect();
        self.cv.connect();
    }

    fn hdl(&self) -> Verilog {
        let mut squares = String::new();
        for m in 0..128u32 {
            squares.push_str(&format!("\x20       7'd{m}: square = 14'd{};\n", m * m));
        }
        Verilog::Custom(format!(
            "// P1: coarse magnitudes; P2: squares (lookup tables); P3: the key;\n\
             // P4 .. P6: two DSP48E1; P7: their products in fabric (V less 256); P8: the addends.\n\
             function [13:0] square;\n\
             \x20   input [6:0] m;\n\
             \x20   case (m)\n\
             {squares}\
             \x20       default: square = 14'd0;\n\
             \x20   endcase\n\
             endfunction\n\
             wire [14:0] ux = x[15] ? x[14:0] : ~x[14:0];\n\
             wire [14:0] uy = y[15] ? y[14:0] : ~y[14:0];\n\
             wire [14:0] uz = z[15] ? z[14:0] : ~z[14:0];\n\
             // Rounded to whole metres: the low 8 bits are dropped.\n\
             /* verilator lint_off UNUSEDSIGNAL */\n\
             wire [15:0] rx = {{1'b0, ux}} + (x[15] ? 16'd128 : 16'd129);\n\
             wire [15:0] ry = {{1'b0, uy}} + (y[15] ? 16'd128 : 16'd129);\n\
             wire [15:0] rz = {{1'b0, uz}} + (z[15] ? 16'd128 : 16'd129);\n\
             /* verilator lint_on UNUSEDSIGNAL */\n\
             reg [6:0] mx, my, mz;\n\
             reg [13:0] sx, sy, sz;\n\
             reg [15:0] rc2, k1, k2, k3, k4;\n\
             reg [23:0] ah, av;\n\
             reg [15:0] b;\n\
             reg [39:0] mh, mv;\n\
             // The low 8 bits of each product are shifted out.\n\
             /* verilator lint_off UNUSEDSIGNAL */\n\
             reg signed [47:0] ph, pv, phq, pvq;\n\
             /* verilator lint_on UNUSEDSIGNAL */\n\
             wire signed [35:0] nh = ~phq[43:8];\n\
             wire signed [35:0] nv = ~pvq[43:8];\n\
             always @(posedge clk) begin\n\
             \x20   mx <= rx[15] ? 7'd127 : rx[14:8];\n\
             \x20   my <= ry[15] ? 7'd127 : ry[14:8];\n\
             \x20   mz <= rz[15] ? 7'd127 : rz[14:8];\n\
             \x20   sx <= square(mx);\n\
             \x20   sy <= square(my);\n\
             \x20   sz <= square(mz);\n\
             \x20   rc2 <= {{2'b0, sx}} + {{2'b0, sy}} + {{2'b0, sz}};\n\
             \x20   k1 <= rc2;\n\
             \x20   k2 <= k1;\n\
             \x20   k3 <= k2;\n\
             \x20   k4 <= k3;\n\
             \x20   ah <= sh;\n\
             \x20   av <= sv;\n\
             \x20   b <= rc2;\n\
             \x20   mh <= {{16'd0, ah}} * {{24'd0, b}};\n\
             \x20   mv <= {{16'd0, av}} * {{24'd0, b}};\n\
             \x20   ph <= $signed({{8'd0, mh}});\n\
             \x20   pv <= $signed({{8'd0, mv}});\n\
             \x20   phq <= ph;\n\
             \x20   pvq <= pv - 48'sd256;\n\
             \x20   key <= rst ? 16'd0 : k4;\n\
             \x20   ch <= ($signed(ch_t) < nh) ? ch_t : nh;\n\
             \x20   cv <= ($signed(cv_t) < nv) ? cv_t : nv;\n\
             end\n"
        ))
    }
}
