#!/usr/bin/env python3
"""Time fcc.cluster on a 64 x 2048 frame against the Rust golden model on
the same frame, and against scikit-learn's DBSCAN when it is installed.

    python python/bench/bench_cluster.py [--seed 1] [--repeats 50]

What is timed, each the median of --repeats runs after warm-up, one thread:
- python fcc.cluster: the package's call from numpy (float32 array in,
  uint32 labels out), wall time in Python;
- rust cluster_with: fcc_golden::cluster_with alone on the already
  quantised frame, timed in Rust (Pipeline.time_core);
- rust quantise + cluster_with: the same plus Frame::from_xyz_f32, the
  quantisation every caller with float coordinates (fcc cluster included)
  does first;
- fcc bench: the CLI's own per-frame time for K = 7 exact on the
  synthetic scenes, when an `fcc` binary is given (--fcc);
- sklearn DBSCAN (eps = th_H, min_samples = 1) on the frame's points.
"""

from __future__ import annotations

import argparse
import json
import subprocess
import tempfile
import time
from pathlib import Path

import numpy as np

import fcc


def median_ms(f, repeats: int) -> float:
    for _ in range(3):
        f()
    t = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        f()
        t.append((time.perf_counter() - t0) * 1e3)
    return float(np.median(t))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--repeats", type=int, default=50)
    ap.add_argument("--fcc", help="an fcc binary, to add `fcc bench`'s figure")
    args = ap.parse_args()

    xyz, _ = fcc.scene(args.seed, rows=64, cols=2048)
    points = int(np.isfinite(xyz).all(axis=2).sum())
    print(f"frame: synthetic scene seed {args.seed}, 64 x 2048, {points} points, K = 7 exact")
    py_ms = median_ms(lambda: fcc.cluster(xyz), args.repeats)
    core_ms, quant_ms = fcc.Pipeline().time_core(xyz, args.repeats)
    rows = [
        ("python fcc.cluster", py_ms),
        ("rust cluster_with", core_ms),
        ("rust quantise + cluster_with", core_ms + quant_ms),
    ]
    if args.fcc:
        with tempfile.TemporaryDirectory() as d:
            out = Path(d) / "bench.json"
            subprocess.run(
                [args.fcc, "bench", "--fsize", "7", "--frames", "4", "--json", str(out)],
                check=True,
                capture_output=True,
            )
            rows.append(("fcc bench (K=7, scenes 0..4)", _bench_ms(json.loads(out.read_text()))))
    try:
        from sklearn.cluster import DBSCAN  # optional: not installed by setup.sh

        pts = xyz[np.isfinite(xyz).all(axis=2)]
        rows.append(
            (
                "sklearn DBSCAN eps=0.5",
                median_ms(lambda: DBSCAN(eps=0.5, min_samples=1).fit(pts), max(3, args.repeats // 10)),
            )
        )
    except ImportError:
        print("sklearn not installed: DBSCAN not timed")
    for name, ms in rows:
        print(f"{name:32s} {ms:8.3f} ms   {ms / py_ms:6.2f} x fcc.cluster")
    print(
        f"fcc.cluster / rust cluster_with: {py_ms / core_ms:.2f} x; "
        f"fcc.cluster / rust quantise + cluster_with: {py_ms / (core_ms + quant_ms):.2f} x"
    )


def _bench_ms(rows: list) -> float:
    """The exact-merge K = 7 ms per frame of `fcc bench --json`."""
    for r in rows:
        if r.get("fsize") == 7:
            return float(r["exact_ms"])
    raise SystemExit("fcc bench --json has no K = 7 row")


if __name__ == "__main__":
    main()
