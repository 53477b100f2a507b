//! `FccRowPack` and `FccRowUnpack`: the window rows of a centre-buffer record
//! as RAM words (one per row) and back. Row r's word holds the row's K 16-bit
//! values in bits 16K-1 .. 0 (value n in bits 16n+15 .. 16n), then its K
//! flags `f` (flag n in bit 16K+n), then its K flags `g` (flag n in bit
//! 17K+n), zeros above. Inputs and outputs are indexed
//! like the window, e = r*K + n.
//!
//! rust-hdl cannot index a struct's fields or a vector's bit slices with a
//! loop variable, nor a child's vector port inside a vector of children, so
//! these two are written by hand.

use rust_hdl::prelude::*;

use crate::types::MAX_K;

/// Bits of a row word: room for the largest K.
pub const ROW_BITS: usize = 18 * MAX_K;

/// Bits of a row word used for `k` positions.
pub fn row_bits(k: usize) -> usize {
    18 * k
}

#[derive(LogicBlock)]
pub struct FccRowPack {
    pub v: Vec<Signal<In, Bits<16>>>,
    pub f: Vec<Signal<In, Bit>>,
    pub g: Vec<Signal<In, Bit>>,
    pub word: Vec<Signal<Out, Bits<ROW_BITS>>>,
    _k: usize,
}

impl FccRowPack {
    /// `h` rows of `k` positions.
    pub fn new(k: usize, h: usize) -> Self {
        assert!((1..=MAX_K).contains(&k));
        Self {
            v: (0..k * h).map(|_| Default::default()).collect(),
            f: (0..k * h).map(|_| Default::default()).collect(),
            g: (0..k * h).map(|_| Default::default()).collect(),
            word: (0..h).map(|_| Default::default()).collect(),
            _k: k,
        }
    }
}

impl Logic for FccRowPack {
    fn update(&mut self) {
        let k = self._k;
        for (r, word) in self.word.iter_mut().enumerate() {
            let mut w = Bits::<ROW_BITS>::default();
            for n in 0..k {
                let v = self.v[r * k + n].val();
                for b in 0..16 {
                    w = w.replace_bit(16 * n + b, v.get_bit(b));
                }
                w = w.replace_bit(16 * k + n, self.f[r * k + n].val());
                w = w.replace_bit(17 * k + n, self.g[r * k + n].val());
            }
            word.next = w;
        }
    }

    fn connect(&mut self) {
        for w in self.word.iter_mut() {
            w.connect();
        }
    }

    fn hdl(&self) -> Verilog {
        let k = self._k;
        let mut s = String::from("always @(*) begin\n");
        for r in 0..self.word.len() {
            let mut parts: Vec<String> = vec![];
            if k < MAX_K {
                parts.push(format!("{}'d0", ROW_BITS - row_bits(k)));
            }
            parts.extend((0..k).rev().map(|n| format!("g${}", r * k + n)));
            parts.extend((0..k).rev().map(|n| format!("f${}", r * k + n)));
            parts.extend((0..k).rev().map(|n| format!("v${}", r * k + n)));
            s.push_str(&format!("    word${r} = {{{}}};\n", parts.join(", ")));
        }
        s.push_str("end\n");
        Verilog::Custom(s)
    }
}

#[derive(LogicBlock)]
pub struct FccRowUnpack {
    pub word: Vec<Signal<In, Bits<ROW_BITS>>>,
    pub v: Vec<Signal<Out, Bits<16>>>,
    pub f: Vec<Signal<Out, Bit>>,
    pub g: Vec<Signal<Out, Bit>>,
    _k: usize,
}

impl FccRowUnpack {
    /// `h` rows of `k` positions.
    pub fn new(k: usize, h: usize) -> Self {
        assert!((1..=MAX_K).contains(&k));
        Self {
            word: (0..h).map(|_| Default::default()).collect(),
            v: (0..k * h).map(|_| Default::default()).collect(),
            f: (0..k * h).map(|_| Default::default()).collect(),
            g: (0..k * h).map(|_| Default::default()).collect(),
            _k: k,
        }
    }
}

impl Logic for FccRowUnpack {
    fn update(&mut self) {
        let k = self._k;
        for (r, word) in self.word.iter().enumerate() {
            let w = word.val();
            for n in 0..k {
                self.v[r * k + n].next = w.get_bits::<16>(16 * n);
                self.f[r * k + n].next = w.get_bit(16 * k + n);
                self.g[r * k + n].next = w.get_bit(17 * k + n);
            }
        }
    }

    fn connect(&mut self) {
        for v in self.v.iter_mut() {
            v.connect();
        }
        for f in self.f.iter_mut() {
            f.connect();
        }
        for g in self.g.iter_mut() {
            g.connect();
        }
    }

    fn hdl(&self) -> Verilog {
        let k = self._k;
        let h = self.word.len();
        let mut s = String::new();
        if k < MAX_K {
            let rows: Vec<String> = (0..h)
                .map(|r| format!("word${r}[{}:{}]", ROW_BITS - 1, row_bits(k)))
                .collect();
            s.push_str(&format!(
                "// Bits above 18K are unused for this K.\n\
                 /* verilator lint_off UNUSEDSIGNAL */\n\
                 wire unused_ok = &{{1'b0, {}}};\n\
                 /* verilator lint_on UNUSEDSIGNAL */\n",
                rows.join(", ")
            ));
        }
        s.push_str("always @(*) begin\n");
        for r in 0..h {
            for n in 0..k {
                let e = r * k + n;
                s.push_str(&format!(
                    "    v${e} = word${r}[{}:{}];\n",
                    16 * n + 15,
                    16 * n
                ));
                s.push_str(&format!("    f${e} = word${r}[{}];\n", 16 * k + n));
                s.push_str(&format!("    g${e} = word${r}[{}];\n", 17 * k + n));
            }
        }
        s.push_str("end\n");
        Verilog::Custom(s)
    }
}
