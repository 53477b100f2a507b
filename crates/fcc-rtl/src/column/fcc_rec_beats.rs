//! `FccRecBeats`: beat `sel` of a record (spec §9.4) from its accumulator
//! (`AccWord`, field by field), id and closing column given the cycle
//! before: the record's fields are registered (every cycle), the beat is
//! chosen from them combinationally. `sum_xy` takes one cycle more (two
//! carry chains); its beat, 9, is read nine cycles after the first, so the
//! model registers every field once. The record's fields follow from the
//! accumulator here: the signed sums from
//! the offset-binary ones (`sum_x = sa - n 2^15`, `sum_xy = sab - 2^15 (sa
//! + sb) + n 2^30`, exact modulo their widths, which hold them), the box
//! from offset binary, and a seam cluster's wrapped column span. The
//! Verilog is written from `fcc_pixel::record::RECORD_LAYOUT` (the one
//! layout); `update` models it with `HwRecord::pack`.

use fcc_pixel::record::{HwRecord, RecordField, RECORD_LAYOUT, RECORD_WORDS};
use rust_hdl::prelude::*;

#[derive(LogicBlock, Default)]
pub struct FccRecBeats {
    pub clk: Signal<In, Clock>,
    pub sel: Signal<In, Bits<4>>,
    pub id: Signal<In, Bits<20>>,
    pub closed_col: Signal<In, Bits<13>>,
    pub points: Signal<In, Bits<20>>,
    pub min_col: Signal<In, Bits<12>>,
    pub max_col: Signal<In, Bits<12>>,
    pub lo_has: Signal<In, Bit>,
    pub lo_max: Signal<In, Bits<12>>,
    pub hi_has: Signal<In, Bit>,
    pub hi_min: Signal<In, Bits<12>>,
    pub first_row: Signal<In, Bits<7>>,
    pub last_row: Signal<In, Bits<7>>,
    pub min_x: Signal<In, Bits<16>>,
    pub min_y: Signal<In, Bits<16>>,
    pub min_z: Signal<In, Bits<16>>,
    pub max_x: Signal<In, Bits<16>>,
    pub max_y: Signal<In, Bits<16>>,
    pub max_z: Signal<In, Bits<16>>,
    pub r2_min: Signal<In, Bits<32>>,
    pub r2_max: Signal<In, Bits<32>>,
    pub sa: Signal<In, Bits<35>>,
    pub sb: Signal<In, Bits<35>>,
    pub sc: Signal<In, Bits<35>>,
    pub sxx: Signal<In, Bits<50>>,
    pub syy: Signal<In, Bits<50>>,
    pub sab: Signal<In, Bits<51>>,
    pub seam: Signal<In, Bit>,
    pub beat: Signal<Out, Bits<64>>,
    /// Model state: the registered record's beats.
    _words: [u64; RECORD_WORDS],
}

/// The Verilog wire holding a field's value, and its width.
fn wire(field: RecordField) -> (&'static str, u32) {
    match field {
        RecordField::Id => ("f_id", 20),
        RecordField::Points => ("f_points", 20),
        RecordField::FirstRow => ("f_first_row", 7),
        RecordField::LastRow => ("f_last_row", 7),
        RecordField::Seam => ("f_seam", 1),
        RecordField::FirstCol => ("f_first_col", 13),
        RecordField::LastCol => ("f_last_col", 13),
        RecordField::ClosedCol => ("f_closed_col", 13),
        RecordField::Min(0) => ("f_min_x", 16),
        RecordField::Min(1) => ("f_min_y", 16),
        RecordField::Min(_) => ("f_min_z", 16),
        RecordField::Max(0) => ("f_max_x", 16),
        RecordField::Max(1) => ("f_max_y", 16),
        RecordField::Max(_) => ("f_max_z", 16),
        RecordField::Range2Min => ("f_r2_min", 32),
        RecordField::Range2Max => ("f_r2_max", 32),
        RecordField::Sum(0) => ("f_sum_x", 35),
        RecordField::Sum(1) => ("f_sum_y", 35),
        RecordField::Sum(_) => ("f_sum_z", 35),
        RecordField::SumXx => ("f_sxx", 50),
        RecordField::SumXy => ("f_sum_xy", 51),
        RecordField::SumYy => ("f_syy", 50),
    }
}

/// The case items: each beat's fields from its top bit down, gaps zero.
fn beat_cases() -> String {
    let mut s = String::new();
    for w in 0..RECORD_WORDS {
        let mut fields: Vec<_> = RECORD_LAYOUT.iter().filter(|l| l.word == w).collect();
        fields.sort_by_key(|l| std::cmp::Reverse(l.lsb));
        let mut parts = Vec::new();
        let mut top = 64;
        for l in fields {
            let (name, bits) = wire(l.field);
            assert_eq!(
                bits, l.bits,
                "field {} has {} bits in the layout",
                l.name, l.bits
            );
            if top > l.lsb + l.bits {
                parts.push(format!("{}'d0", top - l.lsb - l.bits));
            }
            parts.push(name.to_string());
            top = l.lsb;
        }
        if top > 0 {
            parts.push(format!("{top}'d0"));
        }
        s.push_str(&format!(
            "\x20   4'd{w}: beat = {{{}}};\n",
            parts.join(", ")
        ));
    }
    s
}

impl Logic for FccRecBeats {
    fn update(&mut self) {
        if self.clk.pos_edge() {
            self._words = self.words();
        }
        let sel = self.sel.val().index();
        self.beat.next = self._words.get(sel).copied().unwrap_or(0).to_bits();
    }

    fn connect(&mut self) {
        self.beat.connect();
    }

    fn hdl(&self) -> Verilog {
        Verilog::Custom(format!(
            "// The record's fields, registered.\n\
             reg [12:0] f_first_col, f_last_col;\n\
             reg [15:0] f_min_x, f_min_y, f_min_z, f_max_x, f_max_y, f_max_z;\n\
             reg [34:0] f_sum_x, f_sum_y, f_sum_z;\n\
             reg [50:0] f_sum_xy;\n\
             reg [19:0] f_id, f_points;\n\
             reg [6:0] f_first_row, f_last_row;\n\
             reg f_seam;\n\
             reg [12:0] f_closed_col;\n\
             reg [31:0] f_r2_min, f_r2_max;\n\
             reg [49:0] f_sxx, f_syy;\n\
             // A seam cluster's span wraps (spec §9.3).\n\
             wire wrap = seam & lo_has & hi_has;\n\
             // sum_xy in two steps (its beat, 9, is read nine cycles after\n\
             // the first): sa + sb and sab + n 2^30, then the difference.\n\
             reg [35:0] sum_ab;\n\
             reg [50:0] sab_n;\n\
             always @(posedge clk) begin\n\
             \x20   f_first_col <= {{1'b0, wrap ? hi_min : min_col}};\n\
             \x20   f_last_col <= {{1'b0, wrap ? lo_max : max_col}};\n\
             \x20   // The box in two's complement.\n\
             \x20   f_min_x <= min_x ^ 16'h8000;\n\
             \x20   f_min_y <= min_y ^ 16'h8000;\n\
             \x20   f_min_z <= min_z ^ 16'h8000;\n\
             \x20   f_max_x <= max_x ^ 16'h8000;\n\
             \x20   f_max_y <= max_y ^ 16'h8000;\n\
             \x20   f_max_z <= max_z ^ 16'h8000;\n\
             \x20   // The signed sums from the offset-binary ones.\n\
             \x20   f_sum_x <= sa - {{points, 15'd0}};\n\
             \x20   f_sum_y <= sb - {{points, 15'd0}};\n\
             \x20   f_sum_z <= sc - {{points, 15'd0}};\n\
             \x20   sum_ab <= {{1'b0, sa}} + {{1'b0, sb}};\n\
             \x20   sab_n <= sab + {{1'b0, points, 30'd0}};\n\
             \x20   f_sum_xy <= sab_n - {{sum_ab, 15'd0}};\n\
             \x20   f_id <= id;\n\
             \x20   f_points <= points;\n\
             \x20   f_first_row <= first_row;\n\
             \x20   f_last_row <= last_row;\n\
             \x20   f_seam <= seam;\n\
             \x20   f_closed_col <= closed_col;\n\
             \x20   f_r2_min <= r2_min;\n\
             \x20   f_r2_max <= r2_max;\n\
             \x20   f_sxx <= sxx;\n\
             \x20   f_syy <= syy;\n\
             end\n\
             always @(*) begin\n\
             \x20   case (sel)\n\
             {cases}\
             \x20   default: beat = 64'd0;\n\
             \x20   endcase\n\
             end\n",
            cases = beat_cases()
        ))
    }
}

impl FccRecBeats {
    /// The beats of the record at the inputs.
    fn words(&self) -> [u64; RECORD_WORDS] {
        let u = |v: u64| v as i64;
        let n = self.points.val().index() as i64;
        let (sa, sb, sc) = (
            u(self.sa.val().index() as u64),
            u(self.sb.val().index() as u64),
            u(self.sc.val().index() as u64),
        );
        let s16 = |v: Bits<16>| (v.index() as u16 ^ 0x8000) as i16;
        let wrap = self.seam.val() && self.lo_has.val() && self.hi_has.val();
        let (first_col, last_col) = if wrap {
            (self.hi_min.val().index(), self.lo_max.val().index())
        } else {
            (self.min_col.val().index(), self.max_col.val().index())
        };
        let r = HwRecord {
            id: self.id.val().index() as u32,
            points: n as u32,
            first_col: first_col as u32,
            last_col: last_col as u32,
            closed_col: self.closed_col.val().index() as u32,
            seam: self.seam.val(),
            first_row: self.first_row.val().index() as u32,
            last_row: self.last_row.val().index() as u32,
            min: [
                s16(self.min_x.val()),
                s16(self.min_y.val()),
                s16(self.min_z.val()),
            ],
            max: [
                s16(self.max_x.val()),
                s16(self.max_y.val()),
                s16(self.max_z.val()),
            ],
            range2_min: self.r2_min.val().index() as u64,
            range2_max: self.r2_max.val().index() as u64,
            sum: [sa - (n << 15), sb - (n << 15), sc - (n << 15)],
            sum_xx: u(self.sxx.val().index() as u64),
            sum_xy: u(self.sab.val().index() as u64) - ((sa + sb) << 15) + (n << 30),
            sum_yy: u(self.syy.val().index() as u64),
        };
        r.pack().unwrap_or([0; RECORD_WORDS])
    }
}
