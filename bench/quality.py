#!/usr/bin/env python3
"""Clustering quality of FCC (paper and adaptive thresholds) beside DBSCAN.

A benchmark, not a test: it renders the project's synthetic scenes, scores
FCC's labels with `fcc eval` and DBSCAN's (scikit-learn) with
`fcc eval --predicted`, so both are scored by the same rules and range
bands, and writes the summary that `fcc synth --quality-json` renders into
docs/results.md.

- Scenes: seeds 1..24 of `fcc scene` (64 x 2048, no ground: both
  clusterers see the same points, as after a perfect ground removal).
  Seeds 1..12 are the tuning scenes (the adaptive preset was tuned on them,
  DBSCAN's eps and min_samples are chosen on them here), 13..24 are held
  out; the table reports the held-out scenes and all 24.
- FCC: `fcc eval --fsize 3,7,11 --merge exact`, with and without
  `--preset adaptive`.
- DBSCAN: sklearn.cluster.DBSCAN on each scene's points (x, y, z in
  metres), noise as unclustered, over a grid of eps and min_samples.
- Time per frame: `fcc bench` (golden model, one thread) at K = 7 for both
  presets; DBSCAN's fit on the held-out scenes at its tuned setting.

    python3 -m venv /tmp/bench-venv
    /tmp/bench-venv/bin/pip install -r bench/requirements.txt
    /tmp/bench-venv/bin/python bench/quality.py --fcc target/release/fcc \\
        --json docs/quality.json
"""

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

TUNE = list(range(1, 13))
HELD_OUT = list(range(13, 25))
EPS_GRID = "0.7,1.0,1.4,2.0"
MIN_SAMPLES_GRID = "5,10,20"


def run(cmd):
    """Run a command; on failure print it with its stderr and stop."""
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f"quality: {' '.join(cmd)} failed ({p.returncode}):\n{p.stderr}")
    return p.stdout


def render(fcc, work, seed, rows, cols):
    xyz, gt = os.path.join(work, f"s{seed}.npy"), os.path.join(work, f"g{seed}.npy")
    if not os.path.exists(gt):
        run([fcc, "scene", "--seed", str(seed), "--rows", str(rows), "--cols", str(cols),
             "--output", xyz, "--gt", gt])
    return xyz, gt


def eval_json(fcc, work, cmd_tail, name):
    out = os.path.join(work, name + ".json")
    run([fcc, "eval"] + cmd_tail + ["--json", out])
    with open(out) as f:
        return json.load(f)


def summary(row):
    """The numbers the table keeps from one `fcc eval` row."""
    return {
        "pq": row["pq"], "sq": row["sq"], "rq": row["rq"],
        "over_segmentation": row["over_segmentation"],
        "under_segmentation": row["under_segmentation"],
        "bands": [{"lo": b["lo"], "hi": b["hi"], "pq": b["pq"],
                   "instances": b["counts"]["instances"]} for b in row["bands"]],
    }


def dbscan_labels(np, DBSCAN, xyz_path, eps, min_samples, jobs):
    xyz = np.load(xyz_path)
    valid = np.isfinite(xyz[..., 0])
    t = time.perf_counter()
    lab = DBSCAN(eps=eps, min_samples=min_samples, n_jobs=jobs).fit_predict(
        xyz[valid].astype(np.float64))
    dt = time.perf_counter() - t
    img = np.zeros(valid.shape, dtype=np.uint32)
    img[valid] = (lab + 1).astype(np.uint32)  # noise (-1) -> 0, unclustered
    return img, dt


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--fcc", default="fcc", help="the fcc binary (default: fcc on PATH)")
    ap.add_argument("--rows", type=int, default=64)
    ap.add_argument("--cols", type=int, default=2048)
    ap.add_argument("--fsize", default="3,7,11", help="filter sizes of FCC's rows")
    ap.add_argument("--work", help="scene and label directory (default: a temporary one)")
    ap.add_argument("--eps", default=EPS_GRID, help="DBSCAN's eps values to try, metres")
    ap.add_argument("--min-samples", default=MIN_SAMPLES_GRID,
                    help="DBSCAN's min_samples values to try")
    ap.add_argument("--jobs", type=int, default=None, help="DBSCAN's n_jobs")
    ap.add_argument("--json", help="write the summary here (docs/quality.json)")
    args = ap.parse_args()
    try:
        import numpy as np
        from sklearn import __version__ as sk_version
        from sklearn.cluster import DBSCAN
    except ImportError as e:
        sys.exit(f"quality: {e}: install the benchmark's packages: "
                 "pip install -r bench/requirements.txt")
    work = args.work or tempfile.mkdtemp(prefix="fcc-quality-")
    os.makedirs(work, exist_ok=True)
    fsizes = [int(k) for k in args.fsize.split(",")]

    print(f"rendering {len(TUNE) + len(HELD_OUT)} scenes into {work}", file=sys.stderr)
    scenes = {s: render(args.fcc, work, s, args.rows, args.cols) for s in TUNE + HELD_OUT}

    def inputs(seeds):
        return (["--input"] + [scenes[s][0] for s in seeds]
                + ["--truth"] + [scenes[s][1] for s in seeds])

    rows = []
    for preset in ["paper", "adaptive"]:
        for split, seeds in [("held_out", HELD_OUT), ("all", TUNE + HELD_OUT)]:
            t = eval_json(args.fcc, work, inputs(seeds) + [
                "--fsize", ",".join(map(str, fsizes)), "--merge", "exact",
                "--preset", preset], f"fcc-{preset}-{split}")
            for r in t["rows"]:
                rows.append({"clusterer": "fcc", "preset": preset, "fsize": r["fsize"],
                             "split": split, **summary(r)})
        print(f"FCC {preset}: done", file=sys.stderr)

    def score_dbscan(seeds, eps, ms, name):
        preds, secs = [], []
        for s in seeds:
            img, dt = dbscan_labels(np, DBSCAN, scenes[s][0], eps, ms, args.jobs)
            p = os.path.join(work, f"dbscan-{s}.npy")
            np.save(p, img)
            preds.append(p)
            secs.append(dt)
        t = eval_json(args.fcc, work, inputs(seeds) + ["--predicted"] + preds, name)
        return t["rows"][0], secs

    grid = []
    for eps in [float(e) for e in args.eps.split(",")]:
        for ms in [int(m) for m in args.min_samples.split(",")]:
            r, _ = score_dbscan(TUNE, eps, ms, f"dbscan-tune-{eps}-{ms}")
            grid.append({"eps": eps, "min_samples": ms, "pq": r["pq"]})
            print(f"DBSCAN eps {eps} min_samples {ms}: tuning PQ {r['pq']:.3f}",
                  file=sys.stderr)
    best = max(grid, key=lambda g: g["pq"])
    held, secs = score_dbscan(HELD_OUT, best["eps"], best["min_samples"], "dbscan-held-out")
    # The tuning scenes again at the chosen setting (the grid overwrote them).
    score_dbscan(TUNE, best["eps"], best["min_samples"], "dbscan-tune")
    # All 24: the two halves' scenes scored together.
    preds = [os.path.join(work, f"dbscan-{s}.npy") for s in TUNE + HELD_OUT]
    every = eval_json(args.fcc, work, inputs(TUNE + HELD_OUT) + ["--predicted"] + preds,
                      "dbscan-all")["rows"][0]
    for split, r in [("held_out", held), ("all", every)]:
        rows.append({"clusterer": "dbscan", "eps": best["eps"],
                     "min_samples": best["min_samples"], "split": split, **summary(r)})

    timing = {}
    for preset in ["paper", "adaptive"]:
        out = os.path.join(work, f"bench-{preset}.json")
        run([args.fcc, "bench", "--fsize", "7", "--frames", "4", "--repeat", "5",
             "--preset", preset, "--json", out])
        with open(out) as f:
            timing[f"fcc_{preset}_k7_ms"] = json.load(f)[0]["exact_ms"]
    secs.sort()
    timing["dbscan_ms"] = 1000.0 * secs[len(secs) // 2]

    result = {
        "generated_by": "bench/quality.py",
        "scenes": {"rows": args.rows, "cols": args.cols, "tune_seeds": [TUNE[0], TUNE[-1]],
                   "held_out_seeds": [HELD_OUT[0], HELD_OUT[-1]], "ground": "none"},
        "dbscan": {"library": f"scikit-learn {sk_version}", "grid": grid,
                   "eps": best["eps"], "min_samples": best["min_samples"]},
        "timing_ms_per_frame": timing,
        "rows": rows,
    }
    text = json.dumps(result, indent=2) + "\n"
    if args.json:
        tmp = args.json + ".tmp"
        with open(tmp, "w") as f:
            f.write(text)
        os.replace(tmp, args.json)
    print("| clusterer | PQ held out | PQ all | 0-20 m | 20-40 m | 40-80 m (held out) |")
    print("|---|--:|--:|--:|--:|--:|")
    for r in rows:
        if r["split"] != "held_out":
            continue
        allpq = next(x["pq"] for x in rows if x["split"] == "all"
                     and x["clusterer"] == r["clusterer"] and x.get("preset") == r.get("preset")
                     and x.get("fsize") == r.get("fsize"))
        name = (f"FCC K={r['fsize']} {r['preset']}" if r["clusterer"] == "fcc"
                else f"DBSCAN eps {r['eps']} min_samples {r['min_samples']}")
        bands = " | ".join(f"{b['pq']:.3f}" for b in r["bands"])
        print(f"| {name} | {r['pq']:.3f} | {allpq:.3f} | {bands} |")
    print(json.dumps(timing))


if __name__ == "__main__":
    main()
