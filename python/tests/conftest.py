"""Shared fixtures: the repository, the `fcc` binary to compare with, and a
runner for it.

The binary is the one `cargo test` built (`FCC_BIN`, set by
crates/fcc-cli/tests/python_package.rs), else target/release/fcc or
target/debug/fcc. Tests that compare with it are skipped without one,
except under CI=true, where they fail.
"""

from __future__ import annotations

import os
import subprocess
from pathlib import Path
from typing import List

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT / "crates" / "fcc-lidar" / "tests" / "data"


def _binary() -> Path | None:
    given = os.environ.get("FCC_BIN")
    if given:
        return Path(given)
    for p in (ROOT / "target" / "release" / "fcc", ROOT / "target" / "debug" / "fcc"):
        if p.exists():
            return p
    return None


class Cli:
    """The `fcc` command line."""

    def __init__(self, exe: Path, tmp: Path) -> None:
        self.exe = exe
        self.tmp = tmp
        self.n = 0

    def run(self, *args: str) -> subprocess.CompletedProcess:
        r = subprocess.run([str(self.exe), *args], capture_output=True, text=True)
        if r.returncode != 0:
            raise AssertionError(f"fcc {' '.join(args)} failed: {r.stderr}")
        return r

    def cluster(self, inp: Path, *flags: str) -> np.ndarray:
        """The labels `fcc cluster -i INP FLAGS -o labels.npy` writes."""
        self.n += 1
        out = self.tmp / f"labels{self.n}.npy"
        self.run("cluster", "-i", str(inp), "-o", str(out), *flags)
        return np.load(out)

    def npy(self, name: str, a: np.ndarray) -> Path:
        p = self.tmp / name
        np.save(p, a)
        return p


@pytest.fixture
def cli(tmp_path: Path) -> Cli:
    exe = _binary()
    if exe is None or not exe.exists():
        if os.environ.get("CI") == "true":
            pytest.fail("no fcc binary to compare with: set FCC_BIN or build it (cargo build)")
        pytest.skip("no fcc binary (set FCC_BIN or run cargo build)")
    return Cli(exe, tmp_path)


def flags(**kw: object) -> List[str]:
    """Keyword arguments as the CLI's flags (`th_h=0.3` -> `--th-h 0.3`)."""
    out: List[str] = []
    for k, v in kw.items():
        out += [f"--{k.replace('_', '-')}", str(v)]
    return out
