#!/usr/bin/env python3
"""The cocotb bench of the generated `fcc_top` on Icarus Verilog.

For every configuration (16 x 256, each K, 8..10 label bits, K = 9 with
range-adaptive thresholds) this
1. generates the RTL with `fcc gen`, and a copy with every `initial` block
   removed (flip-flops start as X: reset alone must bring the core up);
2. writes the test frames as `.npy` and gets their expected labels and status
   from `fcc cluster` (the golden model); the directed and `tlast` cases'
   frames are 16 x 128, run with RUN_COLS programmed (`SMALL_COLS`);
3. simulates both variants with cocotb (`test_fcc_top.py`), several at once,
   each configuration's as soon as it is prepared.

Usage (from the repository root, in the virtual environment of
`sim/cocotb/requirements.txt`):

    python sim/cocotb/run_bench.py --fcc target/release/fcc [--fsize 3,7] [--jobs 2]

It ends with one line `N passed, M failed` and exits non-zero on a failure.
"""

import argparse
import json
import os
import re
import resource
import shutil
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

import frames as fr  # noqa: E402

ROWS = 16
COLS = 256
TH_H = 0.5
TH_V = 1.0
# (label bits, labels per beat) of each K: every K, 8..10 label bits, and
# every output width.
CONFIGS = {3: (8, 1), 5: (9, 2), 7: (10, 4), 9: (9, 2), 11: (8, 4)}
# Threshold slopes (th_h_slope, th_v_slope) a configuration is generated
# with (power-on values of RUN_SLOPE_H and RUN_SLOPE_V; spec §2): K = 9 runs
# every case with range-adaptive thresholds (the `adaptive` preset's
# slopes), the others with fixed thresholds.
SLOPES = {9: (0.02, 0.05)}
VARIANTS = ("generated", "reset_only")
ALL_CASES = (
    "empty",
    "one point",
    "all one cluster",
    "label overflow",
    "random",
    "early tlast",
    "late tlast",
    "back to back",
    "reset in the middle of a frame",
    "registers",
)
# The cases each configuration runs, per variant. Icarus is slow on this
# design and slower the larger K (measured CPU per cycle: K = 3 about 1.5 ms,
# K = 9 about 12 ms, K = 11 about 16 ms), so every case runs as generated on
# one of K = 3 and 5 (the directed frames on K = 3; the union engine, label
# overflow at K = 9's label width, reset and register cases on K = 5) and the
# larger K a share of them: the seeded random frame at full size at every K
# (on K = 7 reset-only alone), with the window's largest joins and the
# widest output beats, and K = 7 and 9 the `tlast` errors. Label overflow at every K is the Verilator
# regression's (its directed frames exhaust the labels). The reset-only
# copies (no power-up values) run a reset in the middle of a frame at every
# K: its partial frame starts from the power-on reset alone, and its whole
# frame after the reset must give the golden labels and status. On K = 3, 5
# and 7 the seeded random frame runs first, so its clean `status_joins` is
# also the reference after the reset (the union engine's work, which the
# golden model does not count); K = 9 and 11 leave that check to the smaller
# K and keep their CPU for the window. The register file through the
# AXI4-Lite master ("registers": a short frame with run parameters other
# than the build's) runs on K = 5 as generated and on K = 3 reset-only.
CASES = {
    3: {"generated": ("empty", "one point", "label overflow", "early tlast", "back to back"),
        "reset_only": ("random", "reset in the middle of a frame", "registers")},
    5: {"generated": ("all one cluster", "label overflow", "random", "late tlast", "reset in the middle of a frame",
                      "registers"),
        "reset_only": ("random", "reset in the middle of a frame")},
    7: {"generated": ("all one cluster", "early tlast"),
        "reset_only": ("random", "reset in the middle of a frame")},
    9: {"generated": ("random", "late tlast"), "reset_only": ("reset in the middle of a frame",)},
    11: {"generated": ("random",), "reset_only": ("reset in the middle of a frame",)},
}


# The column-streaming core (`fcc gen --scan column`): K -> label bits, at
# COL_ROWS x COLS (24 rows: at least K + 8 at K = 11). Its cases are the row
# core's that concern a stream of records (the directed frames, late `tlast`
# and frames back to back are the Verilator regression's). On K = 3 the
# reset-only copy runs a seeded random frame at full size and a reset in
# the middle of a frame, the generated one early `tlast` at RUN_COLS =
# SMALL_COLS and the reset in the middle of a frame (its RAMs then hold the
# partial frame's words, not power-up zeros); on K = 11, where Icarus takes
# some 25 ms a cycle (K = 3: 6 ms), both copies run the early `tlast` frame
# (a third of a 24 x 128 frame). The reset-only copy found that the
# union-find chased roots it had not recorded (X after reset), which
# stopped the core (docs/column-core.md, "cocotb on Icarus").
COL_ROWS = 24
COL_CONFIGS = {3: 9, 11: 9}
COL_CASES = {
    3: {"generated": ("early tlast", "reset in the middle of a frame"),
        "reset_only": ("random", "reset in the middle of a frame")},
    11: {"generated": ("early tlast",), "reset_only": ("early tlast",)},
}
SCANS = ("row", "column")


def log(msg):
    print(msg, flush=True)


def run(cmd, **kw):
    r = subprocess.run(cmd, capture_output=True, text=True, **kw)
    if r.returncode != 0:
        raise RuntimeError(f"{' '.join(map(str, cmd))} failed ({r.returncode}):\n{r.stdout}\n{r.stderr}")
    return r.stdout


def strip_initial(text):
    """Remove every `initial begin ... end` block (the generator's power-up values)."""
    out, n = re.subn(r"^[ \t]*initial[ \t]+begin\b.*?^[ \t]*end\b[^\n]*\n", "", text, flags=re.M | re.S)
    if n == 0 or re.search(r"\binitial\b", out):
        raise RuntimeError(f"could not strip the initial blocks ({n} removed, some left)")
    return out, n


# The "registers" case: a frame of RUN_ROWS x RUN_COLS run with K = 3 and
# these thresholds, programmed through RUN_* (the register values are those
# `fcc gen` gives a core generated for them, so no rule is written twice).
RUN_ROWS = 8
RUN_COLS = 128
RUN_K = 3
RUN_TH_H = 0.25
RUN_TH_V = 0.75
RUN_SLOPES = (0.01, 0.035)


# The directed and `tlast` cases run their frames at RUN_COLS = SMALL_COLS
# (the bench programs it before the case and restores the power-on value
# after it), so the build's full size is left to the seeded random frames,
# "back to back" and the reset in the middle of a frame (whose whole frame
# after the reset runs on the power-on run size, as reset alone leaves it):
# Icarus's time goes with the cycles, and every configuration also runs the
# core at a run size below its build.
SMALL_COLS = 128
SMALL_CASES = ("empty", "one point", "all one cluster", "label overflow", "early tlast", "late tlast")


def cases(k, rows, cols):
    """The frames (name -> pixels, tlast, columns) and the cases of one configuration."""
    seed = 1000 * k
    sc = SMALL_COLS
    frames = {
        "empty": (fr.empty(rows, sc), "normal", sc),
        "one_point": (fr.one_point(rows, sc), "normal", sc),
        "one_cluster": (fr.one_cluster(rows, sc), "normal", sc),
        "label_overflow": (fr.label_overflow(rows, sc), "normal", sc),
        f"random_{seed}": (fr.random_frame(rows, cols, seed), "normal", cols),
        f"random_{seed + 1}_early_tlast": (fr.random_frame(rows, sc, seed + 1), "early", sc),
        f"random_{seed + 2}_late_tlast": (fr.random_frame(rows, sc, seed + 2), "late", sc),
        f"random_{seed + 3}": (fr.random_frame(rows, cols, seed + 3), "normal", cols),
        "one_cluster_full": (fr.one_cluster(rows, cols), "normal", cols),
        "empty_full": (fr.empty(rows, cols), "normal", cols),
    }
    cs = [
        ("empty", ["empty"], 0.0, 0.0),
        ("one point", ["one_point"], 0.3, 0.3),
        ("all one cluster", ["one_cluster"], 0.1, 0.6),
        ("label overflow", ["label_overflow"], 0.0, 0.5),
        ("random", [f"random_{seed}"], 0.3, 0.3),
        ("early tlast", [f"random_{seed + 1}_early_tlast"], 0.2, 0.2),
        ("late tlast", [f"random_{seed + 2}_late_tlast"], 0.0, 0.4),
        ("back to back", [f"random_{seed + 3}", "one_cluster_full", "empty_full"], 0.0, 0.0),
    ]
    out = [
        {
            "kind": "frames",
            "name": n,
            "frames": f,
            "gap": g,
            "backpressure": b,
            "seed": seed + i,
            "tlast": frames[f[0]][1],
            # The run's columns when not the build's (RUN_COLS programmed).
            "run_cols": sc if n in SMALL_CASES else None,
        }
        for i, (n, f, g, b) in enumerate(cs)
    ]
    out.append(
        {
            "kind": "reset_mid_frame",
            "name": "reset in the middle of a frame",
            "frames": [f"random_{seed}"],
            "gap": 0.1,
            "backpressure": 0.0,
            "seed": seed + 99,
            "tlast": "normal",
            "reset_after": rows * cols // 2,
        }
    )
    frames["run_params"] = (fr.random_frame(RUN_ROWS, RUN_COLS, seed + 7), "normal", RUN_COLS)
    out.append(
        {
            "kind": "registers",
            "name": "registers",
            "frames": ["run_params"],
            "gap": 0.2,
            "backpressure": 0.3,
            "seed": seed + 77,
            "tlast": "normal",
        }
    )
    return frames, out


def golden(fcc, work, name, pixels, k, bits, rows=ROWS, cols=COLS, th_h=TH_H, th_v=TH_V, slopes=(0.0, 0.0)):
    """Expected labels and status of one frame from `fcc cluster`."""
    npy = work / f"{name}.npy"
    lab = work / f"{name}.labels.npy"
    fr.write_npy_f32(npy, rows, cols, pixels)
    out = run(
        [
            fcc, "cluster", "--input", npy, "--output", lab, "--stats",
            "--fsize", str(k), "--th-h", str(th_h), "--th-v", str(th_v), "--label-bits", str(bits),
            "--th-h-slope", str(slopes[0]), "--th-v-slope", str(slopes[1]),
        ]
    )
    stats = json.loads([line for line in out.splitlines() if line.startswith("{")][-1])
    return {
        "labels": fr.read_npy_u32(lab),
        "clusters": stats["clusters"],
        "provisional": stats["provisional"],
        "overflow": stats["overflow"],
        "unlabelled": stats["unlabelled"],
    }


def gen(fcc, out, k, bits, lpb, th_h=TH_H, th_v=TH_V, slopes=(0.0, 0.0)):
    """`fcc gen` of one configuration into `out` (no lint)."""
    run(
        [
            fcc, "gen", "--fsize", str(k), "--rows", str(ROWS), "--cols", str(COLS),
            "--th-h", str(th_h), "--th-v", str(th_v), "--label-bits", str(bits),
            "--th-h-slope", str(slopes[0]), "--th-v-slope", str(slopes[1]),
            "--labels-per-beat", str(lpb), "--rtl", out, "--constraints", out / "xdc",
            "--scripts", out / "tcl", "--no-lint",
        ]
    )
    return json.loads((out / "fcc_params.json").read_text())


def prepare(fcc, root, k):
    """Generate one configuration's RTL (both variants) and its manifest."""
    bits, lpb = CONFIGS[k]
    work = root / f"k{k}"
    if work.exists():
        shutil.rmtree(work)
    gen_dir = work / "gen"
    slopes = SLOPES.get(k, (0.0, 0.0))
    build = gen(fcc, gen_dir, k, bits, lpb, slopes=slopes)
    # The thresholds, slopes and K of the "registers" case as register words.
    run_build = gen(fcc, work / "gen_run", RUN_K, bits, lpb, RUN_TH_H, RUN_TH_V, RUN_SLOPES)
    run_regs = {r["name"]: r["reset"] for r in run_build["registers"]}
    run_params = {
        "RUN_K": run_regs["RUN_K"],
        "RUN_TH_H": run_regs["RUN_TH_H"],
        "RUN_TH_V": run_regs["RUN_TH_V"],
        "RUN_SLOPE_H": run_regs["RUN_SLOPE_H"],
        "RUN_SLOPE_V": run_regs["RUN_SLOPE_V"],
        "RUN_ROWS": RUN_ROWS,
        "RUN_COLS": RUN_COLS,
    }
    text = (gen_dir / "fcc_top.v").read_text()
    stripped, n = strip_initial(text)
    (work / "reset_only").mkdir(parents=True)
    (work / "reset_only" / "fcc_top.v").write_text(stripped)
    (work / "generated").mkdir(parents=True)
    shutil.copy(gen_dir / "fcc_top.v", work / "generated" / "fcc_top.v")
    # The bench top instantiates `FCC_TOP_MODULE, the configuration's name.
    for v in VARIANTS:
        shutil.copy(gen_dir / "fcc_params.vh", work / v / "fcc_params.vh")
    frames, cs = cases(k, ROWS, COLS)
    fdir = work / "frames"
    fdir.mkdir()
    flist = []
    for name, (pixels, tlast, fcols) in frames.items():
        if tlast == "early":
            at = ROWS * fcols // 3
            g = golden(fcc, fdir, name, fr.cut_after(pixels, at), k, bits, cols=fcols, slopes=slopes)
            beats = [fr.beat(p) for p in pixels[: at + 1]]
        elif tlast == "late":
            g = golden(fcc, fdir, name, pixels, k, bits, cols=fcols, slopes=slopes)
            beats = [fr.beat(p) for p in pixels] + [fr.beat((i, 0, 0)) for i in range(7)]
        elif name == "run_params":
            g = golden(fcc, fdir, name, pixels, RUN_K, bits, RUN_ROWS, RUN_COLS, RUN_TH_H, RUN_TH_V, RUN_SLOPES)
            beats = [fr.beat(p) for p in pixels]
        else:
            g = golden(fcc, fdir, name, pixels, k, bits, cols=fcols, slopes=slopes)
            beats = [fr.beat(p) for p in pixels]
        flist.append({"name": name, "beats": beats, "cols": fcols, **g})
    if not next(f for f in flist if f["name"] == "label_overflow")["overflow"]:
        raise RuntimeError(f"K={k}: the label_overflow frame does not exhaust {bits}-bit labels")
    manifest = {
        "fsize": k,
        "rows": ROWS,
        "cols": COLS,
        "label_bits": bits,
        "labels_per_beat": lpb,
        "frames": flist,
        "cases": cs,
        # The register map of the build (offsets, fields, reset values), its
        # parameter hash, and the run parameters of the "registers" case.
        "registers": build["registers"],
        "params_hash": build["params_hash"],
        "run_params": run_params,
    }
    for v in VARIANTS:
        vc = [c for c in cs if c["name"] in CASES[k][v]]
        m = dict(manifest, cases=vc, tag=f"K={k} {ROWS}x{COLS} B={bits} L={lpb} slopes={slopes[0]},{slopes[1]} {v}")
        (work / v / "manifest.json").write_text(json.dumps(m))
    return work, n


def header_value(text, name):
    """The value of `#define name Nu` in a generated C header."""
    m = re.search(rf"^#define {name} (\d+)u$", text, flags=re.M)
    if m is None:
        raise RuntimeError(f"fcc_regs.h has no {name}")
    return int(m.group(1))


def column_order(pixels, rows, cols):
    """A row-major frame's pixels in column order (the column core's input)."""
    return [pixels[r * cols + c] for c in range(cols) for r in range(rows)]


def golden_column(fcc, work, name, pixels, k, bits, open_limit, rows, cols):
    """The golden stream's record beats (and end beat) of one frame, from
    `fcc cluster --stream --beats` with the build's open limit."""
    npy = work / f"{name}.npy"
    out = work / f"{name}.beats"
    fr.write_npy_f32(npy, rows, cols, pixels)
    run(
        [
            fcc, "cluster", "--stream", "--input", npy, "--beats", out,
            "--fsize", str(k), "--th-h", str(TH_H), "--th-v", str(TH_V), "--label-bits", str(bits),
            "--open-limit", str(open_limit),
        ]
    )
    data = out.read_bytes()
    return [int.from_bytes(data[i : i + 8], "little") for i in range(0, len(data), 8)]


def prepare_column(fcc, root, k):
    """Generate one column-core configuration's RTL (both variants) and its
    manifest: the input beats in column order, the expected output beats."""
    bits = COL_CONFIGS[k]
    rows = COL_ROWS
    work = root / f"col_k{k}"
    if work.exists():
        shutil.rmtree(work)
    gen_dir = work / "gen"
    run(
        [
            fcc, "gen", "--scan", "column", "--fsize", str(k), "--rows", str(rows), "--cols", str(COLS),
            "--th-h", str(TH_H), "--th-v", str(TH_V), "--label-bits", str(bits),
            "--rtl", gen_dir, "--constraints", gen_dir / "xdc", "--scripts", gen_dir / "tcl", "--no-lint",
        ]
    )
    build = json.loads((gen_dir / "fcc_params.json").read_text())
    resets = {r["name"]: r["reset"] for r in build["registers"]}
    header = (gen_dir / "fcc_regs.h").read_text()
    limit_none = header_value(header, "FCC_RUN_BRIDGE_MAX")
    if resets["RUN_BRIDGE"] != limit_none or resets["RUN_RING_REACH"] != limit_none:
        raise RuntimeError("the bench's column build has no bridge or ring-reach limit")
    open_limit = resets["RUN_OPEN_LIMIT"]
    words = header_value(header, "FCC_RECORD_WORDS")
    text = (gen_dir / "fcc_top.v").read_text()
    stripped, n = strip_initial(text)
    for v in VARIANTS:
        (work / v).mkdir(parents=True)
        shutil.copy(gen_dir / "fcc_params.vh", work / v / "fcc_params.vh")
    (work / "reset_only" / "fcc_top.v").write_text(stripped)
    shutil.copy(gen_dir / "fcc_top.v", work / "generated" / "fcc_top.v")
    frames, cs = cases(k, rows, COLS)
    fdir = work / "frames"
    fdir.mkdir()
    flist = []
    used = {f for c in cs if any(c["name"] in COL_CASES[k].get(v, ()) for v in VARIANTS) for f in c["frames"]}
    for name, (pixels, tlast, fcols) in frames.items():
        if name not in used:
            continue
        order = column_order(pixels, rows, fcols)
        if tlast == "early":
            at = rows * fcols // 3
            seen = set(range(at + 1))
            cut = [p if (i % fcols) * rows + i // fcols in seen else None for i, p in enumerate(pixels)]
            beats_out = golden_column(fcc, fdir, name, cut, k, bits, open_limit, rows, fcols)
            beats = [fr.beat(p) for p in order[: at + 1]]
        elif tlast == "late":
            beats_out = golden_column(fcc, fdir, name, pixels, k, bits, open_limit, rows, fcols)
            beats = [fr.beat(p) for p in order] + [fr.beat((i, 0, 0)) for i in range(7)]
        else:
            beats_out = golden_column(fcc, fdir, name, pixels, k, bits, open_limit, rows, fcols)
            beats = [fr.beat(p) for p in order]
        end = beats_out[-1]
        flist.append(
            {
                "name": name,
                "beats": beats,
                "cols": fcols,
                "beats_out": beats_out,
                "records": (len(beats_out) - 1) // words,
                "overflow": (end >> header_value(header, "FCC_END_OVERFLOW_SHIFT")) & 1,
            }
        )
    manifest = {
        "fsize": k,
        "rows": rows,
        "cols": COLS,
        "label_bits": bits,
        "labels_per_beat": build["params"]["labels_per_beat"],
        "record_words": words,
        "end_frame_error_shift": header_value(header, "FCC_END_FRAME_ERROR_SHIFT"),
        "frames": flist,
        "registers": build["registers"],
        "params_hash": build["params_hash"],
        "test_module": "test_fcc_col_top",
    }
    for v in VARIANTS:
        vc = [c for c in cs if c["name"] in COL_CASES[k].get(v, ())]
        m = dict(manifest, cases=vc, tag=f"column K={k} {rows}x{COLS} B={bits} {v}")
        (work / v / "manifest.json").write_text(json.dumps(m))
    return work, n


def simulate(work, variant):
    """Build and run one variant with cocotb's Icarus runner (in this process)."""
    from cocotb_tools.runner import get_runner

    vdir = work / variant
    test_module = json.loads((vdir / "manifest.json").read_text()).get("test_module", "test_fcc_top")
    runner = get_runner("icarus")
    runner.build(
        sources=[vdir / "fcc_top.v", HERE / "fcc_bench_top.v"],
        includes=[vdir],
        hdl_toplevel="fcc_bench_top",
        build_dir=vdir / "build",
        timescale=("1ns", "1ps"),
        always=True,
        log_file=vdir / "build.log",
    )
    xml = runner.test(
        hdl_toplevel="fcc_bench_top",
        test_module=test_module,
        build_dir=vdir / "build",
        test_dir=vdir,
        extra_env={"FCC_MANIFEST": str(vdir / "manifest.json")},
        log_file=vdir / "sim.log",
    )
    from cocotb_tools.check_results import get_results

    _, fails = get_results(xml)
    return fails


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--fcc", required=True, help="the fcc binary")
    ap.add_argument("--work", default="target/cocotb", help="work directory (default target/cocotb)")
    ap.add_argument("--fsize", default=",".join(map(str, CONFIGS)), help="K values, comma separated")
    ap.add_argument("--variants", default=",".join(VARIANTS), help="generated and/or reset_only")
    ap.add_argument("--scan", default=",".join(SCANS), help="the cores: row and/or column")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1, help="simulations at once")
    ap.add_argument("--one", nargs=2, metavar=("DIR", "VARIANT"), help=argparse.SUPPRESS)
    a = ap.parse_args()
    if a.one:
        fails = simulate(Path(a.one[0]), a.one[1])
        ru = [resource.getrusage(w) for w in (resource.RUSAGE_SELF, resource.RUSAGE_CHILDREN)]
        print(f"cpu={sum(r.ru_utime + r.ru_stime for r in ru):.1f}", flush=True)
        sys.exit(1 if fails else 0)
    for tool in ("iverilog", "vvp"):
        if shutil.which(tool) is None:
            sys.exit(f"{tool} not found: install Icarus Verilog (Debian: apt-get install iverilog)")
    fcc = str(Path(a.fcc).resolve())
    root = Path(a.work).resolve()
    ks = [int(x) for x in a.fsize.split(",") if x]
    variants = [v for v in a.variants.split(",") if v]
    scans = [x for x in a.scan.split(",") if x]
    for x in scans:
        if x not in SCANS:
            sys.exit(f"--scan {x}: expected one of {', '.join(SCANS)}")
    for k in ks:
        if k not in CONFIGS:
            sys.exit(f"--fsize {k}: the bench has configurations for K in {sorted(CONFIGS)}")
    # (scan, K) of every configuration to run, the longest first.
    configs = [("row", k) for k in ks if "row" in scans] + [("column", k) for k in ks if "column" in scans and k in COL_CONFIGS]
    configs.sort(key=lambda c: (-c[1], c[0] != "column"))
    for v in variants:
        if v not in VARIANTS:
            sys.exit(f"--variants {v}: expected one of {', '.join(VARIANTS)}")
    t0 = time.time()

    def one(job):
        tag, work, v = job
        t = time.time()
        r = subprocess.run(
            [sys.executable, str(Path(__file__).resolve()), "--fcc", fcc, "--one", str(work), v],
            capture_output=True,
            text=True,
        )
        dt = time.time() - t
        ok = r.returncode == 0
        cpu = next((ln[4:] for ln in r.stdout.splitlines() if ln.startswith("cpu=")), "?")
        summary = ""
        sim_log = work / v / "sim.log"
        if sim_log.exists():
            lines = sim_log.read_text(errors="replace").splitlines()
            if ok:
                summary = next((ln.strip() for ln in reversed(lines) if "cases," in ln), "")
            else:
                bad = [ln for ln in lines if "Error" in ln or "FAIL" in ln or "X/Z" in ln or "mismatch" in ln]
                summary = "\n    ".join(bad[-12:]) or "\n    ".join(lines[-20:])
        else:
            summary = (r.stdout + r.stderr)[-3000:]
        log(f"{tag} {v}: {'pass' if ok else 'FAIL'} in {dt:.0f} s ({cpu} s CPU)  {summary}")
        return ok

    # Largest K first: the longest simulations start first, each as soon as
    # its configuration is prepared (the next one is prepared meanwhile).
    with ThreadPoolExecutor(max_workers=max(1, a.jobs)) as ex:
        futures = []
        for scan, k in configs:
            if scan == "row":
                work, n = prepare(fcc, root, k)
                tag = f"K={k}"
                log(f"{tag}: RTL generated ({n} initial blocks stripped for reset_only), golden labels from fcc cluster")
            else:
                work, n = prepare_column(fcc, root, k)
                tag = f"column K={k}"
                log(f"{tag}: RTL generated ({n} initial blocks stripped for reset_only), golden records from fcc cluster --stream")
            futures += [
                ex.submit(one, (tag, work, v))
                for v in variants
                if scan == "row" or COL_CASES[k].get(v)
            ]
        results = [f.result() for f in futures]
    passed = sum(results)
    failed = len(results) - passed
    log(f"cocotb bench on Icarus: {len(results)} simulations in {time.time() - t0:.0f} s")
    log(f"{passed} passed, {failed} failed")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
