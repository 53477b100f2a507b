//! `FccRegMux`: the read multiplexer of the register file. One `case` on the
//! word address (written by hand, `Verilog::Custom`, so that synthesis sees a
//! parallel multiplexer and not a chain of priority `if`s); build constants
//! are literals, counters are inputs of their own width (`w16`, `w20`,
//! `w24`, `w32`, zero-extended here), registers of single-bit fields are
//! concatenated from inputs `flags`; unmapped addresses read 0.
//!
//! Fanout: the low half of the word (bits 15:0) is selected by `addr`, the
//! high half by `addr_hi`, a copy of the same address register, so that no
//! address bit selects all 32 bits of every register (80 loads).

use rust_hdl::prelude::*;

use crate::regmap::ADDR_BITS;

/// Word-address bits decoded (byte address bits `ADDR_BITS - 1 : 2`).
pub const WORD_BITS: usize = ADDR_BITS - 2;

/// Where the value of one mapped word comes from.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum MuxSrc {
    /// A build constant.
    Const(u32),
    /// Input `w16[i]`.
    W16(usize),
    /// Input `w20[i]`.
    W20(usize),
    /// Input `w24[i]`.
    W24(usize),
    /// Input `w32[i]`.
    W32(usize),
    /// Bit `b` is input `flags[f[b]]` (`None`: 0); higher bits are 0.
    Flags(Vec<Option<usize>>),
}

#[derive(LogicBlock)]
pub struct FccRegMux {
    /// The word address, for bits 15:0 and (a copy) for bits 31:16.
    pub addr: Signal<In, Bits<WORD_BITS>>,
    pub addr_hi: Signal<In, Bits<WORD_BITS>>,
    pub w16: Vec<Signal<In, Bits<16>>>,
    pub w20: Vec<Signal<In, Bits<20>>>,
    pub w24: Vec<Signal<In, Bits<24>>>,
    pub w32: Vec<Signal<In, Bits<32>>>,
    pub flags: Vec<Signal<In, Bit>>,
    pub data: Signal<Out, Bits<32>>,
    _entries: Vec<(u32, MuxSrc)>,
}

impl FccRegMux {
    /// `entries`: (byte offset, source) of every mapped register; the
    /// inputs each source names are created.
    pub fn new(entries: Vec<(u32, MuxSrc)>) -> Self {
        let count = |f: &dyn Fn(&MuxSrc) -> Option<usize>| {
            entries
                .iter()
                .filter_map(|(_, s)| f(s))
                .map(|i| i + 1)
                .max()
                .unwrap_or(0)
        };
        let n16 = count(&|s| {
            if let MuxSrc::W16(i) = s {
                Some(*i)
            } else {
                None
            }
        });
        let n20 = count(&|s| {
            if let MuxSrc::W20(i) = s {
                Some(*i)
            } else {
                None
            }
        });
        let n24 = count(&|s| {
            if let MuxSrc::W24(i) = s {
                Some(*i)
            } else {
                None
            }
        });
        let n32 = count(&|s| {
            if let MuxSrc::W32(i) = s {
                Some(*i)
            } else {
                None
            }
        });
        let nf = count(&|s| {
            if let MuxSrc::Flags(f) = s {
                f.iter().flatten().copied().max()
            } else {
                None
            }
        });
        for (off, src) in &entries {
            assert_eq!(off % 4, 0);
            assert!((*off as usize) < (1 << ADDR_BITS));
            if let MuxSrc::Flags(f) = src {
                assert!(f.len() <= 32);
            }
        }
        Self {
            addr: Default::default(),
            addr_hi: Default::default(),
            w16: (0..n16).map(|_| Default::default()).collect(),
            w20: (0..n20).map(|_| Default::default()).collect(),
            w24: (0..n24).map(|_| Default::default()).collect(),
            w32: (0..n32).map(|_| Default::default()).collect(),
            flags: (0..nf).map(|_| Default::default()).collect(),
            data: Default::default(),
            _entries: entries,
        }
    }
}

impl Logic for FccRegMux {
    fn update(&mut self) {
        let lo = self.word(self.addr.val().index() as u32 * 4) & 0xffff;
        let hi = self.word(self.addr_hi.val().index() as u32 * 4) & 0xffff_0000;
        self.data.next = (lo | hi).to_bits();
    }

    fn connect(&mut self) {
        self.data.connect();
    }

    fn hdl(&self) -> Verilog {
        let mut s = String::from(
            "// Each case keeps the half of the word its address selects.\n\
             /* verilator lint_off UNUSEDSIGNAL */\n\
             reg [31:0] by_lo;\n\
             reg [31:0] by_hi;\n\
             /* verilator lint_on UNUSEDSIGNAL */\n",
        );
        for (var, sel) in [("by_lo", "addr"), ("by_hi", "addr_hi")] {
            s.push_str(&format!("always @(*) begin\n    case ({sel})\n"));
            for (off, src) in &self._entries {
                s.push_str(&format!(
                    "        {WORD_BITS}'d{}: {var} = {};\n",
                    off / 4,
                    Self::value(src)
                ));
            }
            s.push_str(&format!(
                "        default: {var} = 32'h00000000;\n    endcase\nend\n"
            ));
        }
        s.push_str("always @(*) begin\n    data = {by_hi[31:16], by_lo[15:0]};\nend\n");
        Verilog::Custom(s)
    }
}

impl FccRegMux {
    /// The word at byte offset `word` (0 when unmapped).
    fn word(&self, word: u32) -> u64 {
        let mut v = 0u64;
        for (off, src) in &self._entries {
            if *off == word {
                v = match src {
                    MuxSrc::Const(c) => u64::from(*c),
                    MuxSrc::W16(i) => self.w16[*i].val().index() as u64,
                    MuxSrc::W20(i) => self.w20[*i].val().index() as u64,
                    MuxSrc::W24(i) => self.w24[*i].val().index() as u64,
                    MuxSrc::W32(i) => self.w32[*i].val().index() as u64,
                    MuxSrc::Flags(f) => f
                        .iter()
                        .enumerate()
                        .filter(|(_, i)| i.is_some_and(|i| self.flags[i].val()))
                        .map(|(b, _)| 1u64 << b)
                        .sum(),
                };
            }
        }
        v
    }

    /// The Verilog expression of a source, 32 bits wide.
    fn value(src: &MuxSrc) -> String {
        match src {
            MuxSrc::Const(c) => format!("32'h{c:08x}"),
            MuxSrc::W16(i) => format!("{{16'd0, w16${i}}}"),
            MuxSrc::W20(i) => format!("{{12'd0, w20${i}}}"),
            MuxSrc::W24(i) => format!("{{8'd0, w24${i}}}"),
            MuxSrc::W32(i) => format!("w32${i}"),
            MuxSrc::Flags(f) => {
                let mut parts = vec![format!("{}'d0", 32 - f.len())];
                for i in f.iter().rev() {
                    parts.push(match i {
                        Some(i) => format!("flags${i}"),
                        None => "1'b0".to_string(),
                    });
                }
                format!("{{{}}}", parts.join(", "))
            }
        }
    }
}
