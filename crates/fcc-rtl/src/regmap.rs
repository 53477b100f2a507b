//! The register map of `fcc_top`'s AXI4-Lite slave, defined once.
//!
//! The offsets and bit positions are the constants of the `fcc-regmap` crate
//! (re-exported here); the
//! hardware (`FccRegs`) decodes them, and [`registers`] describes every
//! register (access, reset value, fields, meaning) for the three documents
//! derived from it: the C99 header `fcc_regs.h` ([`c_header`]), the
//! `registers` list of `fcc_params.json` ([`json`]) and the table in
//! docs/rtl.md ([`markdown_table`], checked by a test).
//!
//! Every register is 32 bits wide at a 4-byte aligned offset; the slave
//! decodes address bits `ADDR_BITS - 1 : 2`. Reads of an unmapped offset
//! return 0 with OKAY; writes to an unmapped or read-only offset are ignored
//! (OKAY). Write strobes are ignored: every write is a full 32-bit write.

use fcc_params::{limits, FccParams, Scan};
use serde::Serialize;

use crate::GENERATOR_VERSION;

pub use fcc_regmap::{
    bits, offset, ADDR_BITS, ID_MAGIC, LIMIT_MAX, OPEN_LIMIT_MAX, RUN_COLS_MIN, SLOPE_Q_MAX,
    TH_Q_MAX,
};

/// How software may access a register.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Access {
    /// Read-only: a build constant or hardware status.
    #[serde(rename = "RO")]
    ReadOnly,
    /// Read/write control bits, some of them self-clearing.
    #[serde(rename = "RW")]
    ReadWrite,
    /// Read; write 1 to a bit to clear it.
    #[serde(rename = "W1C")]
    WriteOneToClear,
}

impl Access {
    pub fn as_str(self) -> &'static str {
        match self {
            Access::ReadOnly => "RO",
            Access::ReadWrite => "RW",
            Access::WriteOneToClear => "W1C",
        }
    }
}

/// One field of a register.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Field {
    pub name: &'static str,
    pub lsb: u32,
    pub width: u32,
    pub doc: &'static str,
}

/// One register.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Register {
    pub name: &'static str,
    pub offset: u32,
    pub access: Access,
    /// Value after reset (for a build constant: its value in this build).
    pub reset: u32,
    /// The reset value is a property of the build (not the same in every build).
    pub build_constant: bool,
    pub doc: &'static str,
    pub fields: Vec<Field>,
    /// A run parameter: the values a write may take ([`run_range`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub range: Option<RunRange>,
}

/// The values a run-parameter register accepts (inclusive); RUN_K also
/// requires an odd value.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct RunRange {
    pub min: u32,
    pub max: u32,
}

/// Smallest RUN_ROWS a build accepts: a frame of one row runs in the
/// row-major core; the column core needs the rows of its K_MAX
/// (`limits::hw_column_rows_min`).
pub fn run_rows_min(p: &FccParams) -> u32 {
    match p.scan {
        Scan::Row => 1,
        Scan::Column => limits::hw_column_rows_min(p.fsize) as u32,
    }
}

/// Smallest RUN_COLS a build accepts ([`RUN_COLS_MIN`]; every build has
/// at least 256 columns).
pub fn run_cols_min(_p: &FccParams) -> u32 {
    RUN_COLS_MIN
}

/// The range of the run-parameter register at `off` in the build `p`
/// (`None` for any other offset). A write outside it is refused: the
/// register keeps its value and its ERROR bit is set.
pub fn run_range(p: &FccParams, off: u32) -> Option<RunRange> {
    let (min, max) = match off {
        offset::RUN_K => (3, p.fsize as u32),
        offset::RUN_TH_H | offset::RUN_TH_V => (1, TH_Q_MAX),
        offset::RUN_SLOPE_H | offset::RUN_SLOPE_V => (0, SLOPE_Q_MAX),
        offset::RUN_ROWS => (run_rows_min(p), p.rows as u32),
        offset::RUN_COLS => (run_cols_min(p), p.cols as u32),
        offset::RUN_BRIDGE | offset::RUN_RING_REACH => (0, LIMIT_MAX),
        offset::RUN_OPEN_LIMIT => (1, OPEN_LIMIT_MAX),
        _ => return None,
    };
    Some(RunRange { min, max })
}

/// Whether `v` is a value the run-parameter register at `off` accepts.
pub fn run_value_ok(p: &FccParams, off: u32, v: u32) -> bool {
    run_range(p, off)
        .is_some_and(|r| (r.min..=r.max).contains(&v) && (off != offset::RUN_K || v % 2 == 1))
}

/// The ERROR bit of the run-parameter register at `off`.
pub fn run_error_bit(off: u32) -> Option<u32> {
    match off {
        offset::RUN_K => Some(bits::ERROR_K),
        offset::RUN_TH_H => Some(bits::ERROR_TH_H),
        offset::RUN_TH_V => Some(bits::ERROR_TH_V),
        offset::RUN_ROWS => Some(bits::ERROR_ROWS),
        offset::RUN_COLS => Some(bits::ERROR_COLS),
        offset::RUN_SLOPE_H => Some(bits::ERROR_SLOPE_H),
        offset::RUN_SLOPE_V => Some(bits::ERROR_SLOPE_V),
        offset::RUN_BRIDGE => Some(bits::ERROR_BRIDGE),
        offset::RUN_RING_REACH => Some(bits::ERROR_RING_REACH),
        offset::RUN_OPEN_LIMIT => Some(bits::ERROR_OPEN_LIMIT),
        _ => None,
    }
}

/// The generator version as one word: major << 16 | minor << 8 | patch.
pub fn version_word() -> u32 {
    let mut it = GENERATOR_VERSION
        .split('.')
        .map(|s| s.parse::<u32>().unwrap_or(0) & 0xff);
    let major = it.next().unwrap_or(0);
    let minor = it.next().unwrap_or(0);
    let patch = it.next().unwrap_or(0);
    (major << 16) | (minor << 8) | patch
}

/// The 64-bit parameter hash of `p` (the one in every generated file's header).
pub fn hash_value(p: &FccParams) -> u64 {
    u64::from_str_radix(&p.hash(), 16).expect("FccParams::hash is 16 hex digits")
}

/// The requested clock in kHz.
pub fn clock_khz(p: &FccParams) -> u32 {
    (p.clock_mhz * 1000.0).round() as u32
}

fn field(name: &'static str, lsb: u32, width: u32, doc: &'static str) -> Field {
    Field {
        name,
        lsb,
        width,
        doc,
    }
}

fn whole(name: &'static str, width: u32, doc: &'static str) -> Vec<Field> {
    vec![field(name, 0, width, doc)]
}

/// Every register of the build `p`, in offset order.
pub fn registers(p: &FccParams) -> Vec<Register> {
    use Access::*;
    let hash = hash_value(p);
    let build = |name, offset, reset, doc, fields| Register {
        name,
        offset,
        access: ReadOnly,
        reset,
        build_constant: true,
        doc,
        fields,
        range: None,
    };
    let run = |name, offset, reset: usize, doc, fields| Register {
        name,
        offset,
        access: ReadWrite,
        reset: reset as u32,
        build_constant: true,
        doc,
        fields,
        range: run_range(p, offset),
    };
    let status = |name, offset, doc, fields| Register {
        name,
        offset,
        access: ReadOnly,
        reset: 0,
        build_constant: false,
        doc,
        fields,
        range: None,
    };
    let column = p.scan == Scan::Column;
    // The frame status of the column core comes from its end beat.
    let pick = |row: &'static str, col: &'static str| if column { col } else { row };
    let mut error_fields = vec![
        field("K", 0, 1, "a RUN_K write was refused"),
        field("TH_H", 1, 1, "a RUN_TH_H write was refused"),
        field("TH_V", 2, 1, "a RUN_TH_V write was refused"),
        field("ROWS", 3, 1, "a RUN_ROWS write was refused"),
        field("COLS", 4, 1, "a RUN_COLS write was refused"),
        field("SLOPE_H", 5, 1, "a RUN_SLOPE_H write was refused"),
        field("SLOPE_V", 6, 1, "a RUN_SLOPE_V write was refused"),
    ];
    if column {
        error_fields.extend([
            field("BRIDGE", 7, 1, "a RUN_BRIDGE write was refused"),
            field("RING_REACH", 8, 1, "a RUN_RING_REACH write was refused"),
            field("OPEN_LIMIT", 9, 1, "a RUN_OPEN_LIMIT write was refused"),
        ]);
    }
    let mut regs = vec![
        build(
            "ID",
            offset::ID,
            ID_MAGIC,
            "Fixed magic \"FCC1\": an FCC core answers here",
            whole("MAGIC", 32, "0x46434331"),
        ),
        build(
            "VERSION",
            offset::VERSION,
            version_word(),
            "Generator version",
            vec![
                field("PATCH", 0, 8, "patch"),
                field("MINOR", 8, 8, "minor"),
                field("MAJOR", 16, 8, "major"),
            ],
        ),
        build(
            "HASH_LO",
            offset::HASH_LO,
            hash as u32,
            "Parameter hash of the build, bits 31:0",
            whole("HASH", 32, "low word of the hash in the generated files' headers"),
        ),
        build(
            "HASH_HI",
            offset::HASH_HI,
            (hash >> 32) as u32,
            "Parameter hash of the build, bits 63:32",
            whole("HASH", 32, "high word"),
        ),
        build(
            "K_MAX",
            offset::K_MAX,
            p.fsize as u32,
            "Largest filter size K the build runs",
            whole("K", 4, "odd, 3 ..= 11"),
        ),
        build(
            "ROWS_MAX",
            offset::ROWS_MAX,
            p.rows as u32,
            "Most rows per frame",
            whole("ROWS", 8, "16 ..= 128"),
        ),
        build(
            "COLS_MAX",
            offset::COLS_MAX,
            p.cols as u32,
            "Most columns per frame",
            whole("COLS", 13, "256 ..= 4096"),
        ),
        build(
            "LABEL_BITS",
            offset::LABEL_BITS,
            p.label_bits,
            "Provisional label width B (labels 1 ..= 2^B - 1)",
            whole("B", 5, "8 ..= 16"),
        ),
        build(
            "LABELS_PER_BEAT",
            offset::LABELS_PER_BEAT,
            p.labels_per_beat,
            "Labels per output beat L",
            whole("L", 3, "1, 2 or 4"),
        ),
        build(
            "CLOCK_KHZ",
            offset::CLOCK_KHZ,
            clock_khz(p),
            "Clock the build is constrained for, kHz",
            whole("KHZ", 32, "kHz"),
        ),
        Register {
            name: "CONTROL",
            offset: offset::CONTROL,
            access: ReadWrite,
            reset: 0,
            build_constant: false,
            range: None,
            doc: "Control",
            fields: vec![
                field(
                    "SOFT_RESET",
                    0,
                    1,
                    "write 1: reset the pixel pipeline (abandons a frame; registers keep their values); reads 0",
                ),
                field(
                    "IRQ_ENABLE",
                    1,
                    1,
                    "1: `irq` is high while STATUS.FRAME_DONE is set",
                ),
                field(
                    "CLEAR",
                    2,
                    1,
                    "write 1: clear FRAME_COUNT, the frame status registers and STATUS.FRAME_DONE; reads 0",
                ),
            ],
        },
        Register {
            name: "STATUS",
            offset: offset::STATUS,
            access: WriteOneToClear,
            reset: 0,
            build_constant: false,
            range: None,
            doc: "Core status",
            fields: vec![
                field(
                    "FRAME_DONE",
                    0,
                    1,
                    pick(
                        "sticky: a frame's last label beat left (write 1 to clear)",
                        "sticky: a frame's end beat left (write 1 to clear)",
                    ),
                ),
                field(
                    "IDLE",
                    1,
                    1,
                    "read-only: the core waits for the first pixel of a frame",
                ),
            ],
        },
        Register {
            name: "ERROR",
            offset: offset::ERROR,
            access: WriteOneToClear,
            reset: 0,
            build_constant: false,
            range: None,
            doc: "Refused writes of run parameters (sticky, write 1 to clear)",
            fields: error_fields,
        },
        status(
            "FRAME_COUNT",
            offset::FRAME_COUNT,
            "Frames completed since reset or CLEAR (wraps)",
            whole("COUNT", 32, "frames"),
        ),
        status(
            "CLUSTERS",
            offset::CLUSTERS,
            pick(
                "Last frame: clusters (largest label)",
                "Last frame: records (its end beat's count; 0xFFFF: that many or more)",
            ),
            whole("CLUSTERS", 16, "count"),
        ),
        status(
            "PROVISIONAL",
            offset::PROVISIONAL,
            pick(
                "Last frame: provisional labels used",
                "Most provisional labels in use at once since the frame before it ended",
            ),
            whole("PROVISIONAL", 16, "count"),
        ),
        status(
            "UNLABELLED",
            offset::UNLABELLED,
            pick(
                "Last frame: points left with label 0 (labels ran out)",
                "Not counted by the column core (reads 0): its end beat's overflow flags a refused run",
            ),
            whole("UNLABELLED", 20, "count"),
        ),
        status(
            "FRAME_FLAGS",
            offset::FRAME_FLAGS,
            "Last frame: flags",
            vec![
                field("OVERFLOW", 0, 1, "provisional labels ran out"),
                field("FRAME_ERROR", 1, 1, "`tlast` came early or late"),
            ],
        ),
        status(
            "JOINS",
            offset::JOINS,
            pick(
                "Last frame: joins sent to the union engine",
                "Not counted by the column core (reads 0)",
            ),
            whole("JOINS", 24, "count"),
        ),
        status(
            "GEAR_STALLS",
            offset::GEAR_STALLS,
            pick(
                "Last frame: read-back cycles that waited for labels",
                "Cycles a column's first pixel waited for the column before it to settle, since the frame before it ended",
            ),
            whole("STALLS", 24, "cycles"),
        ),
        run(
            "RUN_K",
            offset::RUN_K,
            p.fsize,
            "Run: filter size K, odd, 3 ..= K_MAX",
            whole("K", 4, "odd, 3 ..= K_MAX"),
        ),
        run(
            "RUN_TH_H",
            offset::RUN_TH_H,
            p.th_h_q() as usize,
            "Run: intra-channel threshold tH = floor(th_H * 256 + 0.5), 1 ..= 0x8000",
            whole("TH", 16, "Q7.8 metres"),
        ),
        run(
            "RUN_TH_V",
            offset::RUN_TH_V,
            p.th_v_q() as usize,
            "Run: inter-channel threshold tV = floor(th_V * 256 + 0.5), 1 ..= 0x8000",
            whole("TH", 16, "Q7.8 metres"),
        ),
        run(
            "RUN_ROWS",
            offset::RUN_ROWS,
            p.rows,
            "Run: rows per frame, 1 ..= ROWS_MAX",
            whole("ROWS", 8, "rows"),
        ),
        run(
            "RUN_COLS",
            offset::RUN_COLS,
            p.cols,
            "Run: columns per frame, RUN_COLS_MIN ..= COLS_MAX",
            whole("COLS", 13, "columns"),
        ),
        run(
            "RUN_SLOPE_H",
            offset::RUN_SLOPE_H,
            p.th_h_slope_q() as usize,
            "Run: intra-channel threshold slope aH = floor(a * 65536 + 0.5), 0 ..= 0xFFFF (0: fixed)",
            whole("SLOPE", 16, "UQ0.16 metres per metre"),
        ),
        run(
            "RUN_SLOPE_V",
            offset::RUN_SLOPE_V,
            p.th_v_slope_q() as usize,
            "Run: inter-channel threshold slope aV = floor(a * 65536 + 0.5), 0 ..= 0xFFFF (0: fixed)",
            whole("SLOPE", 16, "UQ0.16 metres per metre"),
        ),
    ];
    if column {
        let [bridge, reach, open] = stream_limit_values(p).map(|(_, _, v)| v as usize);
        regs.extend([
            run(
                "RUN_BRIDGE",
                offset::RUN_BRIDGE,
                bridge,
                "Run: bridge limit (spec §3), 0 ..= 0xFFF (0xFFF: none)",
                whole("BRIDGE", 12, "empty pixels"),
            ),
            run(
                "RUN_RING_REACH",
                offset::RUN_RING_REACH,
                reach,
                "Run: ring-check reach (spec §3), 0 ..= 0xFFF (0: no ring check; RUN_COLS or more: none)",
                whole("REACH", 12, "columns"),
            ),
            run(
                "RUN_OPEN_LIMIT",
                offset::RUN_OPEN_LIMIT,
                open,
                "Run: open limit N_o (spec §9.1), 1 ..= 511 (511: the core's record slots)",
                whole("OPEN", 9, "clusters"),
            ),
        ]);
    }
    regs
}

/// The column core's stream-limit registers and the values that give the
/// limits of `p` (a limit beyond what the registers hold is no limit for
/// the core: 0xFFF columns, or its 511 record slots).
pub fn stream_limit_values(p: &FccParams) -> [(&'static str, u32, u32); 3] {
    let limit = |v: Option<u32>, max: u32| v.map_or(max, |v| v.min(max));
    [
        ("RUN_BRIDGE", offset::RUN_BRIDGE, limit(p.bridge, LIMIT_MAX)),
        (
            "RUN_RING_REACH",
            offset::RUN_RING_REACH,
            limit(p.ring_reach, LIMIT_MAX),
        ),
        (
            "RUN_OPEN_LIMIT",
            offset::RUN_OPEN_LIMIT,
            limit(p.open_limit, OPEN_LIMIT_MAX),
        ),
    ]
}

/// The byte offsets of the registers of `p` that software may write, in
/// map order: the bus adapter's write-enables (`FccAxilAdapter`).
pub fn writable_offsets(p: &FccParams) -> Vec<u32> {
    registers(p)
        .iter()
        .filter(|r| r.access != Access::ReadOnly)
        .map(|r| r.offset)
        .collect()
}

fn field_mask(f: &Field) -> u32 {
    if f.width >= 32 {
        u32::MAX
    } else {
        ((1u32 << f.width) - 1) << f.lsb
    }
}

/// `fcc_regs.h`: offsets, field positions and masks, reset values (the build
/// constants among them), the hash; C99, no includes beyond `<stdint.h>`.
pub fn c_header(p: &FccParams) -> String {
    let mut s = crate::file_header(p, "//");
    s.push_str(
        "// Register map of the fcc_top AXI4-Lite slave (32-bit registers, byte offsets).\n\
         // Unmapped offsets read 0; write strobes are ignored (full-word writes).\n\
         #ifndef FCC_REGS_H\n#define FCC_REGS_H\n\n#include <stdint.h>\n\n",
    );
    s.push_str(&format!(
        "#define FCC_REGS_ADDR_BITS {ADDR_BITS}u\n#define FCC_ID_MAGIC 0x{ID_MAGIC:08X}u\n#define FCC_PARAMS_HASH 0x{:016X}ull\n\
         // The core's Verilog module and packaged IP name (fcc gen names every module\n\
         // of a configuration with the same suffix).\n#define FCC_TOP_MODULE \"{}\"\n\n",
        hash_value(p),
        crate::top_module(p)
    ));
    for r in registers(p) {
        s.push_str(&format!(
            "// {} ({}): {}\n#define FCC_REG_{} 0x{:03X}u\n#define FCC_REG_{}_RESET 0x{:08X}u\n",
            r.name,
            r.access.as_str(),
            r.doc,
            r.name,
            r.offset,
            r.name,
            r.reset
        ));
        if r.fields.len() > 1 || r.fields[0].width < 32 {
            for f in &r.fields {
                s.push_str(&format!(
                    "#define FCC_{}_{}_SHIFT {}u\n#define FCC_{}_{}_MASK 0x{:08X}u\n",
                    r.name,
                    f.name,
                    f.lsb,
                    r.name,
                    f.name,
                    field_mask(f)
                ));
            }
        }
        if let Some(rr) = r.range {
            s.push_str(&format!(
                "#define FCC_{}_MIN {}u\n#define FCC_{}_MAX {}u\n",
                r.name, rr.min, r.name, rr.max
            ));
        }
        s.push('\n');
    }
    if p.scan == fcc_params::Scan::Column {
        s.push_str(&record_layout_c());
    }
    s.push_str("#endif  // FCC_REGS_H\n");
    s
}

/// The column core's output stream in C (spec §9.4, from
/// `fcc_pixel::record`'s layouts): beats per record and, for each field of
/// a record and of the end beat, its beat, shift, width and signedness.
fn record_layout_c() -> String {
    use fcc_pixel::record::{END_LAYOUT, RECORD_LAYOUT, RECORD_WORDS};
    let mut s = format!(
        "// The output stream (spec 9.4): each record is FCC_RECORD_WORDS 64-bit beats,\n\
         // each field in one beat (FCC_REC_<F>_WORD) at bits SHIFT .. SHIFT + BITS - 1,\n\
         // two's complement when SIGNED; bits outside the fields are 0. After the\n\
         // frame's last record comes its end beat (tlast high; its id field is 0).\n\
         #define FCC_RECORD_WORDS {RECORD_WORDS}u\n"
    );
    for l in &RECORD_LAYOUT {
        let n = l.name.to_uppercase();
        s.push_str(&format!(
            "#define FCC_REC_{n}_WORD {}u\n#define FCC_REC_{n}_SHIFT {}u\n#define FCC_REC_{n}_BITS {}u\n#define FCC_REC_{n}_SIGNED {}\n",
            l.word,
            l.lsb,
            l.bits,
            u8::from(l.signed)
        ));
    }
    for l in &END_LAYOUT {
        let n = l.name.to_uppercase();
        s.push_str(&format!(
            "#define FCC_END_{n}_SHIFT {}u\n#define FCC_END_{n}_BITS {}u\n",
            l.lsb, l.bits
        ));
    }
    s.push('\n');
    s
}

/// The register map as a JSON value (the `registers` list of `fcc_params.json`).
pub fn json(p: &FccParams) -> serde_json::Value {
    serde_json::to_value(registers(p)).expect("the register map always serialises")
}

/// The register table of docs/rtl.md. Reset values of build constants are
/// described, not numbered, so the table is the same for every build.
pub fn markdown_table(p: &FccParams) -> String {
    let mut s = String::from(
        "| Offset | Register | Access | Reset | Fields | Meaning |\n|---|---|---|---|---|---|\n",
    );
    for r in registers(p) {
        let reset = if r.name == "ID" {
            format!("`0x{:08X}`", r.reset)
        } else if r.build_constant {
            "build".to_string()
        } else {
            format!("`0x{:X}`", r.reset)
        };
        let fields: Vec<String> = r
            .fields
            .iter()
            .map(|f| {
                let bits = if f.width == 1 {
                    format!("{}", f.lsb)
                } else {
                    format!("{}:{}", f.lsb + f.width - 1, f.lsb)
                };
                if r.fields.len() == 1 {
                    format!("[{bits}]")
                } else {
                    format!("[{bits}] {}: {}", f.name, f.doc)
                }
            })
            .collect();
        s.push_str(&format!(
            "| `0x{:03X}` | {} | {} | {} | {} | {} |\n",
            r.offset,
            r.name,
            r.access.as_str(),
            reset,
            fields.join("; "),
            r.doc
        ));
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn offsets_are_aligned_distinct_and_ascending() {
        let regs = registers(&FccParams::default());
        for w in regs.windows(2) {
            assert!(w[0].offset < w[1].offset, "{} / {}", w[0].name, w[1].name);
        }
        for r in &regs {
            assert_eq!(r.offset % 4, 0, "{}", r.name);
            assert!(r.offset < (1 << ADDR_BITS), "{}", r.name);
            for f in &r.fields {
                assert!(f.lsb + f.width <= 32, "{}.{}", r.name, f.name);
            }
        }
    }

    #[test]
    fn run_ranges_refuse_even_k_zero_thresholds_and_sizes_beyond_the_build() {
        let p = FccParams {
            fsize: 11,
            ..Default::default()
        };
        for k in 0..=16 {
            let ok = k % 2 == 1 && (3..=11).contains(&k);
            assert_eq!(run_value_ok(&p, offset::RUN_K, k), ok, "K {k}");
        }
        for off in [offset::RUN_TH_H, offset::RUN_TH_V] {
            assert!(!run_value_ok(&p, off, 0));
            assert!(run_value_ok(&p, off, 1));
            assert!(run_value_ok(&p, off, TH_Q_MAX));
            assert!(!run_value_ok(&p, off, TH_Q_MAX + 1));
        }
        // The largest threshold the parameters accept quantises to TH_Q_MAX.
        assert_eq!(fcc_params::quantize_threshold(127.999) as u32, TH_Q_MAX);
        for (off, max) in [(offset::RUN_ROWS, p.rows), (offset::RUN_COLS, p.cols)] {
            assert!(run_value_ok(&p, off, max as u32));
            assert!(!run_value_ok(&p, off, max as u32 + 1));
            assert!(!run_value_ok(&p, off, 0));
        }
        assert!(!run_value_ok(&p, offset::CONTROL, 1));
        // Slopes: 0 (fixed) up to the largest the parameters accept.
        for off in [offset::RUN_SLOPE_H, offset::RUN_SLOPE_V] {
            assert!(run_value_ok(&p, off, 0));
            assert!(run_value_ok(&p, off, SLOPE_Q_MAX));
            assert!(!run_value_ok(&p, off, SLOPE_Q_MAX + 1));
        }
        assert_eq!(
            SLOPE_Q_MAX,
            (1 << fcc_params::SLOPE_FRAC_BITS) - 1,
            "a register's slope is UQ0.16"
        );
        assert_eq!(fcc_params::quantize_slope(0.99998) as u32, SLOPE_Q_MAX);
    }

    #[test]
    fn hash_registers_hold_the_parameter_hash() {
        let p = FccParams::default();
        let regs = registers(&p);
        let lo = regs.iter().find(|r| r.name == "HASH_LO").unwrap().reset;
        let hi = regs.iter().find(|r| r.name == "HASH_HI").unwrap().reset;
        assert_eq!(format!("{hi:08x}{lo:08x}"), p.hash());
    }

    #[test]
    fn c_header_names_every_register_and_field() {
        let p = FccParams::default();
        let h = c_header(&p);
        assert!(h.contains("#define FCC_REG_CONTROL 0x040u"), "{h}");
        assert!(h.contains("#define FCC_CONTROL_IRQ_ENABLE_MASK 0x00000002u"));
        assert!(h.contains("#define FCC_REG_K_MAX_RESET 0x00000007u"));
        assert!(
            h.contains("#define FCC_RUN_K_MIN 3u\n#define FCC_RUN_K_MAX 7u"),
            "{h}"
        );
        assert!(h.contains("#define FCC_RUN_TH_V_MAX 32768u"), "{h}");
        assert!(h.contains(&format!("0x{}ull", p.hash().to_uppercase())));
        assert!(!h.contains("#include <cstdint>"));
    }
}
