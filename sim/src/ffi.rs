//! The structs passed between Rust and the C++ shims, defined once.
//!
//! [`c_struct!`] declares a `#[repr(C)]` Rust struct and, from the same field
//! list, its C declaration; [`header`] writes those declarations into
//! `fcc_ffi.h`, which every model build places beside its shim. The header also
//! states the Rust layout (`sizeof` and each field's `offsetof`) as
//! `static_assert`s, so a C++ compiler that lays a struct out differently fails
//! the model build instead of exchanging shifted fields.

use std::fmt::Write;

/// A Rust field type with a fixed-width C counterpart.
pub trait CType {
    const C: &'static str;
}

impl CType for u8 {
    const C: &'static str = "uint8_t";
}
impl CType for u16 {
    const C: &'static str = "uint16_t";
}
impl CType for u32 {
    const C: &'static str = "uint32_t";
}
impl CType for u64 {
    const C: &'static str = "uint64_t";
}

/// A `#[repr(C)]` struct that can state its own C declaration.
pub trait CStruct {
    /// The struct's name, in Rust and in C.
    const NAME: &'static str;
    /// Its fields, in order.
    const FIELDS: &'static [&'static str];
    /// The C `struct` with layout `static_assert`s.
    fn c_decl() -> String;
}

/// Declare a `#[repr(C)]` struct of fixed-width integers and implement
/// [`CStruct`] for it from the same field list. Exported, so that a plain
/// block's bench declares its ports' structs in its own test file.
///
/// `pub struct Name with acc_out { ... }` adds the 24 fields of an
/// accumulator (`AccWord`) that the column core's probes bring out as
/// `o_points` ... `o_seam`, which [`core_acc_out!`](crate::core_acc_out)
/// reads back.
#[macro_export]
macro_rules! c_struct {
    (
        $(#[$meta:meta])*
        pub struct $name:ident with acc_out {
            $( $(#[$fmeta:meta])* pub $field:ident : $ty:ty, )*
        }
    ) => {
        $crate::c_struct! {
            $(#[$meta])*
            pub struct $name {
                $( $(#[$fmeta])* pub $field: $ty, )*
                pub o_points: u32,
                pub o_min_col: u16,
                pub o_max_col: u16,
                pub o_lo_has: u8,
                pub o_lo_max: u16,
                pub o_hi_has: u8,
                pub o_hi_min: u16,
                pub o_first_row: u8,
                pub o_last_row: u8,
                pub o_min_x: u16,
                pub o_min_y: u16,
                pub o_min_z: u16,
                pub o_max_x: u16,
                pub o_max_y: u16,
                pub o_max_z: u16,
                pub o_r2_min: u32,
                pub o_r2_max: u32,
                pub o_sa: u64,
                pub o_sb: u64,
                pub o_sc: u64,
                pub o_sxx: u64,
                pub o_syy: u64,
                pub o_sab: u64,
                pub o_seam: u8,
            }
        }
    };
    (
        $(#[$meta:meta])*
        pub struct $name:ident {
            $( $(#[$fmeta:meta])* pub $field:ident : $ty:ty, )*
        }
    ) => {
        $(#[$meta])*
        #[repr(C)]
        #[derive(Debug, Clone, Copy, Default)]
        pub struct $name {
            $( $(#[$fmeta])* pub $field: $ty, )*
        }

        impl $crate::ffi::CStruct for $name {
            const NAME: &'static str = stringify!($name);
            const FIELDS: &'static [&'static str] = &[$(stringify!($field)),*];
            fn c_decl() -> String {
                let name = stringify!($name);
                let mut fields = Vec::new();
                $(
                    fields.push((
                        <$ty as $crate::ffi::CType>::C,
                        stringify!($field),
                        std::mem::offset_of!($name, $field),
                    ));
                )*
                $crate::ffi::decl(name, std::mem::size_of::<$name>(), &fields)
            }
        }
    };
}
pub use crate::c_struct;

/// The C text of one struct: `(C type, field, Rust offset)` in order.
pub fn decl(name: &str, size: usize, fields: &[(&str, &str, usize)]) -> String {
    let mut s = format!("struct {name} {{\n");
    for (ty, field, _) in fields {
        let _ = writeln!(s, "    {ty} {field};");
    }
    s.push_str("};\n");
    let _ = writeln!(
        s,
        "static_assert(sizeof({name}) == {size}, \"{name}: size differs from the Rust struct\");"
    );
    for (_, field, off) in fields {
        let _ = writeln!(
            s,
            "static_assert(offsetof({name}, {field}) == {off}, \"{name}.{field}: offset differs from the Rust struct\");"
        );
    }
    s
}

/// Name of the generated header in a model's build directory.
pub const HEADER: &str = "fcc_ffi.h";

/// How a struct meets its model's ports: its fields are named as the ports
/// they drive or sample, so the shim's code for them is generated.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Ports {
    /// Inputs: `FCC_DRIVE_<Name>(t, in)` sets every port `t->f = in->f`.
    Drive,
    /// Outputs: `FCC_SAMPLE_<Name>(t, out)` reads every port `out->f = t->f`.
    Sample,
}

/// One struct of the header: its declaration and its port macro (none for
/// a struct whose shim maps it by hand).
pub(crate) fn entry<S: CStruct>(ports: Option<Ports>) -> (&'static str, String) {
    let mut s = S::c_decl();
    let Some(ports) = ports else {
        return (S::NAME, s);
    };
    let (verb, arg, assign): (&str, &str, fn(&str, &str) -> String) = match ports {
        Ports::Drive => ("DRIVE", "in", |a, f| format!("(t)->{f} = ({a})->{f};")),
        Ports::Sample => ("SAMPLE", "out", |a, f| format!("({a})->{f} = (t)->{f};")),
    };
    let _ = write!(
        s,
        "#define FCC_{verb}_{}(t, {arg}) \\\n    do {{ \\\n",
        S::NAME
    );
    for f in S::FIELDS {
        let _ = writeln!(s, "        {} \\", assign(arg, f));
    }
    s.push_str("    } while (0)\n");
    (S::NAME, s)
}

/// The table of the hand-written shims' structs: those benches' inputs and
/// outputs, each with its port macro (a plain bench's shim declares its
/// own, `crate::plain`).
pub fn structs() -> Vec<(&'static str, String)> {
    use crate::axil_adapter_bench::{AdIn, AdOut};
    use crate::model::{FccIn, FccOut};
    use crate::regs_bench::{RegsIn, RegsOut};
    use crate::sort_net_bench::{SnIn, SnOut};
    use crate::window_bench::{WinIn, WinOut};
    const DRIVE: Option<Ports> = Some(Ports::Drive);
    const SAMPLE: Option<Ports> = Some(Ports::Sample);
    vec![
        entry::<FccIn>(DRIVE),
        entry::<FccOut>(SAMPLE),
        entry::<RegsIn>(DRIVE),
        entry::<RegsOut>(SAMPLE),
        entry::<AdIn>(DRIVE),
        entry::<AdOut>(SAMPLE),
        entry::<WinIn>(DRIVE),
        entry::<WinOut>(SAMPLE),
        // By hand: `jready` is the bench's, and the shim derives the
        // `jtake` port from it within the cycle.
        entry::<SnIn>(None),
        entry::<SnOut>(SAMPLE),
    ]
}

/// `fcc_ffi.h`: every struct the shims exchange with Rust.
pub fn header() -> String {
    let mut s = String::from(
        "// Generated by fcc-sim from the Rust structs (sim/src/ffi.rs); do not edit.\n\
         #pragma once\n#include <cstddef>\n#include <cstdint>\n\nextern \"C\" {\n\n",
    );
    for (_, d) in structs() {
        s.push_str(&d);
        s.push('\n');
    }
    s.push_str("}  // extern \"C\"\n");
    s
}

/// Life-cycle of a Verilator model shared by the shims (`csrc/vl_model.h`).
pub const VL_MODEL_H: &str = include_str!("../csrc/vl_model.h");

/// The files every shim includes, to be written beside it.
pub fn support_files() -> [(&'static str, String); 2] {
    [(HEADER, header()), ("vl_model.h", VL_MODEL_H.to_string())]
}

#[cfg(test)]
mod tests {
    use super::*;

    c_struct! {
        /// A struct with padding after the first field.
        pub struct Padded {
            pub a: u8,
            pub b: u32,
            pub c: u16,
        }
    }

    #[test]
    fn padded_struct_states_rust_offsets_and_size() {
        let d = Padded::c_decl();
        assert!(
            d.contains("    uint8_t a;\n    uint32_t b;\n    uint16_t c;\n"),
            "{d}"
        );
        assert!(d.contains("sizeof(Padded) == 12,"), "{d}");
        assert!(d.contains("offsetof(Padded, b) == 4,"), "{d}");
        assert!(d.contains("offsetof(Padded, c) == 8,"), "{d}");
    }

    #[test]
    fn header_declares_every_shim_struct_once() {
        let h = header();
        let names: Vec<_> = structs().into_iter().map(|(n, _)| n).collect();
        assert_eq!(names.len(), 10);
        for name in names {
            assert_eq!(h.matches(&format!("struct {name} {{")).count(), 1, "{name}");
            let macros = usize::from(name != "SnIn");
            assert_eq!(h.matches(&format!("_{name}(t, ")).count(), macros, "{name}");
        }
    }

    #[test]
    fn port_macros_assign_every_field_by_its_port_name() {
        let (_, d) = entry::<Padded>(Some(Ports::Drive));
        assert!(
            d.contains(
                "#define FCC_DRIVE_Padded(t, in) \\\n    do { \\\n        (t)->a = (in)->a; \\\n"
            ),
            "{d}"
        );
        assert!(d.contains("(t)->c = (in)->c; \\\n    } while (0)\n"), "{d}");
        let (_, d) = entry::<Padded>(Some(Ports::Sample));
        assert!(d.contains("#define FCC_SAMPLE_Padded(t, out)"), "{d}");
        assert!(d.contains("(out)->b = (t)->b; \\"), "{d}");
        let (_, d) = entry::<Padded>(None);
        assert!(!d.contains("#define"), "{d}");
    }
}
