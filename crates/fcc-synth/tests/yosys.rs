//! Yosys end to end on a small design, and the parsers on committed reports.
//!
//! The reports in `tests/fixtures/` were written by Yosys 0.23: `stat_small_top.json`,
//! `stat_blocks_small_top.json` and `sta_small_top.log` from `small_top.v`;
//! `stat_fcc_top_k3.json` and `sta_fcc_top_k3.log` from an early generated
//! `fcc_top` with K = 3 (a snapshot of the format, not of today's design).
//! Tests that run Yosys are skipped, with a note, when it is not installed
//! (and fail when `CI=true`), and take a lock so that only one Yosys runs at a time.

use std::path::{Path, PathBuf};
use std::sync::Mutex;

use fcc_synth::yosys::{self, YosysConfig};
use fcc_synth::{Resources, SynthError, Timing};

static ONE_YOSYS: Mutex<()> = Mutex::new(());

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures")
        .join(name)
}

fn read(name: &str) -> String {
    std::fs::read_to_string(fixture(name)).unwrap()
}

fn have_yosys() -> bool {
    let ok = yosys::version(Path::new("yosys")).is_ok();
    if !ok && std::env::var("CI").is_ok_and(|v| v == "true") {
        panic!("yosys is not installed and CI=true: install it (Debian: apt-get install yosys)");
    }
    if !ok {
        eprintln!("yosys is not installed: skipping (apt-get install yosys)");
    }
    ok
}

#[test]
fn committed_stat_of_the_small_design() {
    let r = Resources::from_stat_json(&read("stat_small_top.json")).unwrap();
    assert_eq!(
        r.dsp48e1, 1,
        "the multiplier and its registers fit one DSP48E1"
    );
    assert_eq!(r.ramb18e1, 1, "1024 x 16 fits one RAMB18E1");
    assert_eq!(r.bram36, 0.5);
    assert_eq!(r.ff, 18);
    assert_eq!(r.carry4, 5);
    assert_eq!(r.slice_luts, 16);
    assert_eq!(r.unmapped, 0);
}

#[test]
fn committed_stat_of_a_generated_core() {
    let r = Resources::from_stat_json(&read("stat_fcc_top_k3.json")).unwrap();
    assert_eq!(r.lut_logic, 84 + 55 + 817 + 761 + 363 + 333 + 799);
    assert_eq!(r.srl, 174);
    assert_eq!(r.slice_luts, r.lut_logic + 174);
    assert_eq!(r.ff, 1722 + 36);
    assert_eq!(r.dsp48e1, 15);
    assert_eq!((r.ramb36e1, r.ramb18e1), (42, 3));
    assert_eq!(r.bram36, 43.5);
    assert_eq!(r.muxf7 + r.muxf8, 190 + 70);
}

#[test]
fn committed_by_block_stat() {
    let b =
        Resources::blocks_from_stat_json(&read("stat_blocks_small_top.json"), "fcc_top").unwrap();
    assert_eq!(b.len(), 3);
    assert_eq!(b["fcc_mul"].dsp48e1, 1);
    assert_eq!(b["fcc_mem"].ramb18e1, 1);
    assert_eq!(b["fcc_mem"].ff, 18);
    assert_eq!(
        b["fcc_top"].by_type.len(),
        0,
        "the top only instantiates blocks"
    );
}

#[test]
fn committed_sta_of_the_small_design() {
    let t = Timing::from_sta_log(&read("sta_small_top.log")).unwrap();
    assert_eq!(t.critical_path_ns, 3.896);
    assert_eq!(t.start, "mem.ram.0.0 (RAMB18E1.CLKARDCLK->DOADO)");
    assert_eq!(t.end, "mem.acc.s_o_FDRE_Q (FDRE.D)");
    assert_eq!(t.logic_levels, 6, "a LUT2 and five CARRY4");
    assert!(t.warnings.is_empty(), "{:?}", t.warnings);
}

#[test]
fn committed_sta_of_a_generated_core() {
    let t = Timing::from_sta_log(&read("sta_fcc_top_k3.log")).unwrap();
    assert_eq!(t.critical_path_ns, 8.694);
    assert_eq!(t.start, "sort_net.m2$0.q_FDRE_Q_12 (FDRE.C->Q)");
    assert_eq!(t.end, "intra.ring.mx.q_FDSE_Q_1 (FDSE.S)");
    assert_eq!(t.logic_levels, 22);
    let names: Vec<&str> = t.through.iter().map(|(b, _)| b.as_str()).collect();
    assert_eq!(names, ["sort_net", "in_done", "intra"]);
    assert_eq!(t.through.iter().map(|(_, n)| n).sum::<u32>(), 22);
    assert_eq!(t.steps.first().unwrap().cell, "\\clk");
}

#[test]
fn yosys_measures_the_small_design() {
    if !have_yosys() {
        return;
    }
    let _one = ONE_YOSYS.lock().unwrap_or_else(|e| e.into_inner());
    let work = tempfile::tempdir().unwrap();
    let cfg = YosysConfig {
        by_block: true,
        ..Default::default()
    };
    let run = yosys::synthesize(&[fixture("small_top.v")], &cfg, work.path()).unwrap();
    assert!(
        run.yosys_version.starts_with("Yosys "),
        "{}",
        run.yosys_version
    );
    let r = &run.resources;
    assert_eq!(r.dsp48e1, 1);
    assert_eq!(r.bram36, 0.5);
    assert_eq!(r.unmapped, 0);
    assert!(r.ff >= 18, "{r:?}");
    assert!(!r.by_type.contains_key("IBUF"), "-noiopad: no I/O buffers");
    assert!(
        !r.by_type.contains_key("BUFG"),
        "-noclkbuf: no clock buffer"
    );
    let t = run.timing.as_ref().unwrap();
    assert!(
        t.critical_path_ns > 0.5 && t.critical_path_ns < 10.0,
        "{t:?}"
    );
    assert!(
        t.start.contains("RAMB18E1") || t.start.contains("FDRE"),
        "{}",
        t.start
    );
    let blocks = run.by_block.as_ref().unwrap();
    assert_eq!(blocks["fcc_mul"].dsp48e1, 1);
    assert_eq!(blocks["fcc_mem"].ramb18e1, 1);
    // Fanout and hops from the netlist: `rst` (a primary input) is among the
    // highest-fanout nets, the list is sorted, the clock is not in it, and
    // every output is registered, so every path is short.
    let routing = run.routing.as_ref().unwrap();
    let rst = routing
        .top_fanout
        .iter()
        .find(|n| n.net == "rst")
        .unwrap_or_else(|| panic!("rst among the highest-fanout nets: {routing:?}"));
    assert!(rst.loads >= 1, "{rst:?}");
    assert!(
        routing
            .top_fanout
            .windows(2)
            .all(|w| w[0].loads >= w[1].loads),
        "{routing:?}"
    );
    assert!(rst.driver.contains("primary input"), "{rst:?}");
    assert!(
        routing.top_fanout.iter().all(|n| n.net != "clk"),
        "the clock is left out: {routing:?}"
    );
    assert!(
        routing.worst_hops >= 1 && routing.worst_hops <= 4,
        "{routing:?}"
    );
    for f in [
        yosys::SCRIPT_FILE,
        yosys::LOG_FILE,
        yosys::STAT_FILE,
        yosys::NETLIST_FILE,
        yosys::STA_SCRIPT_FILE,
        yosys::STA_LOG_FILE,
        yosys::STA_FILE,
    ] {
        assert!(work.path().join(f).is_file(), "{f} is kept for inspection");
    }
    // The committed parser fixture was captured the same way; a newer Yosys may
    // map differently, so compare only when the versions agree.
    if run.yosys_version.starts_with("Yosys 0.23 ") {
        let committed = Resources::from_stat_json(&read("stat_small_top.json")).unwrap();
        assert_eq!(r, &committed);
    }
}

#[test]
fn broken_verilog_names_the_read_step_and_shows_the_error() {
    if !have_yosys() {
        return;
    }
    let _one = ONE_YOSYS.lock().unwrap_or_else(|e| e.into_inner());
    let work = tempfile::tempdir().unwrap();
    let bad = work.path().join("bad.v");
    std::fs::write(
        &bad,
        "module fcc_top(input wire a);\n  assign = ;\nendmodule\n",
    )
    .unwrap();
    let e = yosys::synthesize(&[bad], &YosysConfig::default(), &work.path().join("y")).unwrap_err();
    let msg = e.to_string();
    match e {
        SynthError::ToolFailed { step, tail, .. } => {
            assert_eq!(step, "read", "{msg}");
            assert!(tail.contains("ERROR"), "{msg}");
        }
        other => panic!("expected a tool failure, got {other}"),
    }
    assert!(msg.contains("failed in step `read`"), "{msg}");
}

#[test]
fn unknown_top_names_the_synth_step() {
    if !have_yosys() {
        return;
    }
    let _one = ONE_YOSYS.lock().unwrap_or_else(|e| e.into_inner());
    let work = tempfile::tempdir().unwrap();
    let cfg = YosysConfig {
        top: "fcc_no_such_top".into(),
        ..Default::default()
    };
    let e = yosys::synthesize(&[fixture("small_top.v")], &cfg, work.path()).unwrap_err();
    assert!(
        matches!(&e, SynthError::ToolFailed { step, .. } if step == "synth"),
        "{e}"
    );
}

#[test]
fn missing_yosys_is_a_clear_error() {
    let work = tempfile::tempdir().unwrap();
    let cfg = YosysConfig {
        program: PathBuf::from("fcc-no-such-yosys"),
        ..Default::default()
    };
    let e = yosys::synthesize(&[fixture("small_top.v")], &cfg, work.path()).unwrap_err();
    assert_eq!(
        e.to_string(),
        "cannot run `fcc-no-such-yosys` (not found); install it \
         (Debian/Ubuntu: `apt-get install yosys`) or put it on PATH"
    );
}

#[test]
fn missing_input_file_is_named() {
    if !have_yosys() {
        return;
    }
    let work = tempfile::tempdir().unwrap();
    let e = yosys::synthesize(
        &[PathBuf::from("no/such/file.v")],
        &YosysConfig::default(),
        work.path(),
    )
    .unwrap_err();
    assert!(
        e.to_string().starts_with("cannot read no/such/file.v:"),
        "{e}"
    );
}
