//! Every supported K generates, passes rust-hdl's checks and lints clean.

use std::path::PathBuf;

use fcc_params::{limits, FccParams, Scan};
use fcc_rtl::{generate, lint, write_rtl};

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("fcc-rtl-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

fn small(fsize: usize) -> FccParams {
    FccParams {
        rows: 16,
        cols: 256,
        fsize,
        ..Default::default()
    }
}

/// Whether Verilator runs. Missing, it skips a test, except in CI
/// (`CI=true`), where it fails the test.
fn verilator_present() -> bool {
    let ok = std::process::Command::new("verilator")
        .arg("--version")
        .output()
        .is_ok();
    if !ok && std::env::var("CI").is_ok_and(|v| v == "true") {
        panic!("verilator is not installed and CI=true: install it (Debian: apt-get install verilator)");
    }
    ok
}

#[test]
fn lint_clean_for_every_fsize() {
    if !verilator_present() {
        eprintln!("verilator not installed: lint skipped");
        return;
    }
    for fsize in [3, 5, 7, 9, 11] {
        let dir = scratch(&format!("k{fsize}"));
        write_rtl(&small(fsize), &dir).unwrap();
        let files = (dir.join("fcc_top.v"), dir.join("fcc_lint.vlt"));
        if let Err(e) = lint::lint_files(&small(fsize), &files.0, &files.1) {
            panic!("fsize {fsize}: {e}");
        }
        let _ = std::fs::remove_dir_all(&dir);
    }
}

#[test]
fn lint_clean_default_and_odd_sizes() {
    if !verilator_present() {
        eprintln!("verilator not installed: lint skipped");
        return;
    }
    for p in [
        FccParams::default(),
        FccParams {
            rows: 17,
            cols: 257,
            fsize: 5,
            label_bits: 8,
            labels_per_beat: 1,
            ..Default::default()
        },
        FccParams {
            rows: 128,
            cols: 4096,
            fsize: 3,
            label_bits: 16,
            labels_per_beat: 2,
            ..Default::default()
        },
    ] {
        let dir = scratch(&format!("p{}", p.hash()));
        write_rtl(&p, &dir).unwrap();
        if let Err(e) = lint::lint_files(&p, &dir.join("fcc_top.v"), &dir.join("fcc_lint.vlt")) {
            panic!("{}: {e}", fcc_rtl::param_summary(&p));
        }
        let _ = std::fs::remove_dir_all(&dir);
    }
}

/// The column core (`--scan column`) at every K on its fewest rows, and
/// on the largest frame it takes with 16-bit labels and every stream limit.
#[test]
fn column_core_lints_clean_for_every_fsize_and_the_largest_frame() {
    if !verilator_present() {
        eprintln!("verilator not installed: lint skipped");
        return;
    }
    let column = |fsize: usize, rows: usize, cols: usize, label_bits: u32| FccParams {
        rows,
        cols,
        fsize,
        label_bits,
        scan: Scan::Column,
        ..Default::default()
    };
    let mut all: Vec<FccParams> = [3, 5, 7, 9, 11]
        .map(|k| column(k, limits::hw_column_rows_min(k), 256, 13))
        .to_vec();
    all.push(FccParams {
        bridge: Some(4),
        ring_reach: Some(32),
        open_limit: Some(100),
        ..column(3, 128, limits::HW_COLUMN_COLS_MAX, 16)
    });
    for p in all {
        let dir = scratch(&format!("col{}", p.hash()));
        write_rtl(&p, &dir).unwrap();
        if let Err(e) = lint::lint_files(&p, &dir.join("fcc_top.v"), &dir.join("fcc_lint.vlt")) {
            panic!("{}: {e}", fcc_rtl::param_summary(&p));
        }
        let _ = std::fs::remove_dir_all(&dir);
    }
}

/// The column core has the row-major core's ports, in the same order and
/// widths (so one XDC, block design and Verilator harness serve both).
#[test]
fn the_column_core_has_the_row_cores_ports() {
    let row = small(7);
    let col = FccParams {
        scan: Scan::Column,
        label_bits: 13,
        ..row.clone()
    };
    let ports = |p: &FccParams| {
        let g = generate(p).unwrap();
        fcc_rtl::vivado::top_ports(&g.verilog, &fcc_rtl::top_module(p))
    };
    let (a, b) = (ports(&row), ports(&col));
    assert!(a.len() > 30, "{} ports read", a.len());
    assert_eq!(a, b);
}

/// The column core's limits are errors naming the field and the rule.
#[test]
fn column_core_sizes_are_checked() {
    let p = FccParams {
        scan: Scan::Column,
        ..Default::default()
    };
    for (bad, field, rule) in [
        (
            FccParams {
                cols: 4096,
                ..p.clone()
            },
            "cols",
            "the column core",
        ),
        (
            FccParams {
                rows: 18,
                fsize: 11,
                ..p.clone()
            },
            "rows",
            "19 ..= 128 (the column core at K = 11)",
        ),
    ] {
        let e = generate(&bad).unwrap_err().to_string();
        assert!(e.contains(field) && e.contains(rule), "{e}");
    }
    // The limits the row-major core refuses are its run registers.
    let limited = FccParams {
        bridge: Some(3),
        ring_reach: Some(0),
        open_limit: Some(7),
        ..p.clone()
    };
    let g = generate(&limited).unwrap();
    assert!(g.regs_header.contains("RUN_BRIDGE") && g.params_json.contains("\"scan\": \"column\""));
    let e = generate(&FccParams {
        scan: Scan::Row,
        ..limited
    })
    .unwrap_err()
    .to_string();
    assert!(e.contains("bridge") && e.contains("--scan column"), "{e}");
}

#[test]
fn generation_is_deterministic_and_named() {
    let p = small(5);
    let a = generate(&p).unwrap();
    let b = generate(&p).unwrap();
    assert_eq!(a, b);
    for m in [
        "fcc_top",
        "fcc_intra",
        "fcc_window",
        "fcc_dist_tree",
        "fcc_sort_net",
        "fcc_merge_table",
        "fcc_label_update",
    ] {
        let m = format!("module {m}{}(", p.module_suffix());
        assert!(a.verilog.contains(&m), "missing {m}");
    }
    assert!(a.verilog.contains(&p.hash()));
    assert!(!a.verilog.contains("module top"));
}

#[test]
fn bad_parameters_are_errors_not_panics() {
    let p = FccParams {
        fsize: 13,
        ..Default::default()
    };
    let e = generate(&p).unwrap_err();
    assert!(e.to_string().contains("fsize"), "{e}");
    let p = FccParams {
        cols: 100,
        ..Default::default()
    };
    assert!(generate(&p).unwrap_err().to_string().contains("cols"));
}

/// Whether Yosys runs; as [`verilator_present`].
fn yosys_present() -> bool {
    let ok = std::process::Command::new("yosys")
        .arg("-V")
        .output()
        .is_ok();
    if !ok && std::env::var("CI").is_ok_and(|v| v == "true") {
        panic!("yosys is not installed and CI=true: install it (Debian: apt-get install yosys)");
    }
    ok
}

/// A K and which bench blocks (by index in `BenchBlock::ALL`) lint at it.
type LintRun = (usize, fn(usize) -> bool);

/// Every block of the bench table at `k` for which `pick(index)` holds,
/// generated alone at K = `k`, lints clean with its own waivers, and Yosys
/// (the synthesis flow's reader, stricter than Verilator on some selects)
/// reads it.
fn bench_blocks_lint_clean(runs: &[LintRun]) {
    if !verilator_present() {
        eprintln!("verilator not installed: lint skipped");
        return;
    }
    let yosys = yosys_present();
    for &(fsize, pick) in runs {
        let p = FccParams {
            fsize,
            ..Default::default()
        };
        for (n, block) in fcc_rtl::BenchBlock::ALL.into_iter().enumerate() {
            if !pick(n) {
                continue;
            }
            let dir = scratch(&format!("{}{fsize}", block.name()));
            std::fs::create_dir_all(&dir).unwrap();
            let v = dir.join(format!("{}.v", block.name()));
            let vlt = dir.join(format!("{}.vlt", block.name()));
            std::fs::write(&v, block.generate(&p).unwrap()).unwrap();
            std::fs::write(&vlt, block.waivers(&p)).unwrap();
            if let Err(e) = lint::lint_module(&v, &vlt, &block.module(&p)) {
                panic!("{block:?} at K = {fsize}: {e}");
            }
            if yosys {
                let script = format!(
                    "read_verilog {}; hierarchy -top {}",
                    v.display(),
                    block.module(&p)
                );
                let out = std::process::Command::new("yosys")
                    .args(["-q", "-p", &script])
                    .output()
                    .unwrap();
                assert!(
                    out.status.success(),
                    "{block:?} at K = {fsize}: Yosys cannot read it:\n{}{}",
                    String::from_utf8_lossy(&out.stdout),
                    String::from_utf8_lossy(&out.stderr)
                );
            }
            let _ = std::fs::remove_dir_all(&dir);
        }
    }
}

/// Every bench block at the smallest K, and every other one at the largest
/// (two tests of about equal length, so that they lint side by side: the
/// blocks at K = 11 take most of the time).
#[test]
fn bench_blocks_lint_clean_at_k3_and_half_at_k11() {
    bench_blocks_lint_clean(&[(3, |_| true), (11, |n| n % 2 == 0)]);
}

/// The other bench blocks at the largest K.
#[test]
fn bench_blocks_lint_clean_other_half_at_k11() {
    bench_blocks_lint_clean(&[(11, |n| n % 2 == 1)]);
}

#[test]
fn label_updater_alone_lints_clean_for_every_labels_per_beat() {
    if !verilator_present() {
        eprintln!("verilator not installed: lint skipped");
        return;
    }
    for lpb in [1, 2, 4] {
        let p = FccParams {
            labels_per_beat: lpb,
            ..Default::default()
        };
        let dir = scratch(&format!("label_update{lpb}"));
        std::fs::create_dir_all(&dir).unwrap();
        let v = dir.join("fcc_label_update.v");
        let vlt = dir.join("fcc_label_update.vlt");
        std::fs::write(&v, fcc_rtl::generate_label_update(&p).unwrap()).unwrap();
        std::fs::write(&vlt, lint::label_update_waivers(&p)).unwrap();
        if let Err(e) = lint::lint_module(&v, &vlt, &fcc_rtl::label_update_module(&p)) {
            panic!("labels per beat {lpb}: {e}");
        }
        let _ = std::fs::remove_dir_all(&dir);
    }
}

/// `fcc_regs.h` is plain C99: it compiles warning-free with `-std=c99
/// -pedantic`, and its constants are usable in constant expressions.
#[test]
fn register_header_compiles_as_c99() {
    let cc = std::env::var("CC").unwrap_or_else(|_| "cc".to_string());
    if std::process::Command::new(&cc)
        .arg("--version")
        .output()
        .is_err()
    {
        assert!(
            std::env::var("CI").as_deref() != Ok("true"),
            "{cc} (a C compiler) is required in CI"
        );
        eprintln!("{cc} not installed: C99 check skipped");
        return;
    }
    let p = FccParams::default();
    let dir = scratch("regs-h");
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("fcc_regs.h"), fcc_rtl::regmap::c_header(&p)).unwrap();
    let main = "#include \"fcc_regs.h\"\n\
        typedef char check_offset[(FCC_REG_CONTROL == 0x40u) ? 1 : -1];\n\
        typedef char check_mask[(FCC_STATUS_FRAME_DONE_MASK == 1u) ? 1 : -1];\n\
        int main(void) {\n\
            volatile uint32_t regs[1024];\n\
            uint64_t hash = ((uint64_t)regs[FCC_REG_HASH_HI / 4] << 32) | regs[FCC_REG_HASH_LO / 4];\n\
            regs[FCC_REG_CONTROL / 4] = FCC_CONTROL_IRQ_ENABLE_MASK;\n\
            return hash == FCC_PARAMS_HASH && regs[FCC_REG_ID / 4] == FCC_ID_MAGIC;\n\
        }\n";
    std::fs::write(dir.join("main.c"), main).unwrap();
    let out = std::process::Command::new(&cc)
        .current_dir(&dir)
        .args([
            "-std=c99",
            "-pedantic",
            "-Wall",
            "-Wextra",
            "-Werror",
            "-fsyntax-only",
            "main.c",
        ])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// The names of the modules `verilog` declares.
fn module_names(verilog: &str) -> Vec<String> {
    verilog
        .lines()
        .filter_map(|l| l.trim_start().strip_prefix("module "))
        .map(|r| {
            r.split(['(', ' ', ';'])
                .next()
                .unwrap_or_default()
                .to_string()
        })
        .collect()
}

#[test]
fn every_module_carries_the_suffix_and_two_configurations_share_none() {
    // Differ in one run-register default only: the Verilog differs, K does not.
    let a = small(5);
    let b = FccParams {
        th_h: 0.75,
        ..small(5)
    };
    let (va, vb) = (generate(&a).unwrap().verilog, generate(&b).unwrap().verilog);
    let (ma, mb) = (module_names(&va), module_names(&vb));
    assert!(ma.len() > 7, "{ma:?}");
    for (p, names) in [(&a, &ma), (&b, &mb)] {
        for m in names {
            assert!(
                m.ends_with(&p.module_suffix()),
                "{m} lacks {}",
                p.module_suffix()
            );
        }
    }
    let shared: Vec<&String> = ma.iter().filter(|m| mb.contains(m)).collect();
    assert!(shared.is_empty(), "modules of both: {shared:?}");
    // Every use of a module is renamed with its declaration: nothing
    // instantiates a name that is not declared.
    let inst =
        regex::Regex::new(r"(?m)^\s*(fcc_[A-Za-z0-9_$]+)\s+[A-Za-z_][A-Za-z0-9_$]*\s*\(").unwrap();
    for c in inst.captures_iter(&va) {
        assert!(
            ma.contains(&c[1].to_string()),
            "{} is instantiated, not declared",
            &c[1]
        );
    }
}

/// `verilator --lint-only` of `files` under the top `top` (a wrapper).
fn lint_together(files: &[PathBuf], top: &str) -> (bool, String) {
    let out = std::process::Command::new("verilator")
        // The wrapper leaves the cores' stream ports open on purpose.
        .args(["--lint-only", "-Wno-PINMISSING", "--top-module", top])
        .args(files)
        .output()
        .unwrap();
    let log = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    (out.status.success() && !log.contains("%Error"), log)
}

#[test]
fn two_configurations_compile_together_in_one_design() {
    if !verilator_present() {
        eprintln!("verilator not installed: lint skipped");
        return;
    }
    let dir = scratch("two-configs");
    let (p3, p5) = (small(3), small(5));
    write_rtl(&p3, &dir.join("k3")).unwrap();
    write_rtl(&p5, &dir.join("k5")).unwrap();
    // One design that instantiates both cores (clock and reset only: the
    // point is elaboration of both module sets side by side).
    let wrapper = dir.join("both.v");
    std::fs::write(
        &wrapper,
        format!(
            "module both(input wire clk, input wire rst);\n  \
             {} k3 (.clk(clk), .rst(rst));\n  {} k5 (.clk(clk), .rst(rst));\nendmodule\n",
            fcc_rtl::top_module(&p3),
            fcc_rtl::top_module(&p5)
        ),
    )
    .unwrap();
    // Each configuration's own waivers, as `fcc gen` lints it.
    let vlt = [dir.join("k3/fcc_lint.vlt"), dir.join("k5/fcc_lint.vlt")];
    let (ok, log) = lint_together(
        &[
            vlt[0].clone(),
            vlt[1].clone(),
            wrapper.clone(),
            dir.join("k3/fcc_top.v"),
            dir.join("k5/fcc_top.v"),
        ],
        "both",
    );
    assert!(ok, "K = 3 and K = 5 clash:\n{log}");

    // The check can fail: two copies of one configuration's modules clash.
    std::fs::create_dir_all(dir.join("k3b")).unwrap();
    std::fs::copy(dir.join("k3/fcc_top.v"), dir.join("k3b/fcc_top.v")).unwrap();
    let (ok, log) = lint_together(
        &[
            vlt[0].clone(),
            vlt[1].clone(),
            wrapper,
            dir.join("k3/fcc_top.v"),
            dir.join("k3b/fcc_top.v"),
            dir.join("k5/fcc_top.v"),
        ],
        "both",
    );
    assert!(
        !ok && log.contains("MODDUP"),
        "a duplicate module passed:\n{log}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
