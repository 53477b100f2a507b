"""fcc.eval scores as `fcc eval` does."""

from __future__ import annotations

import json

import numpy as np
import pytest

import fcc


def test_perfect_labels_score_one():
    _, truth = fcc.scene(1, rows=32, cols=512)
    s = fcc.eval(truth, truth)
    assert s["pq"] == s["sq"] == s["rq"] == 1.0
    assert s["counts"]["true_positives"] == len(np.unique(truth)) - 1


@pytest.mark.parametrize("fsize", [3, 7])
def test_scores_equal_fcc_eval(cli, fsize):
    xyz, truth = fcc.scene(2, rows=64, cols=1024)
    img, gt = cli.npy("img.npy", xyz), cli.npy("gt.npy", truth)
    out = cli.tmp / "eval.json"
    cli.run(
        "eval", "--input", str(img), "--truth", str(gt), "--fsize", str(fsize),
        "--merge", "exact", "--json", str(out),
    )
    row = json.loads(out.read_text())["rows"][0]
    got = fcc.eval(fcc.cluster(xyz, fsize=fsize), truth, xyz=xyz)
    for k in ["pq", "sq", "rq", "over_segmentation", "under_segmentation"]:
        assert got[k] == pytest.approx(row[k], abs=1e-12), k
    # Sums over hash maps: equal up to the order of the additions.
    assert got["counts"] == pytest.approx(row["counts"], abs=1e-9)
    assert len(got["bands"]) == len(row["bands"]) == 3
    for band, want in zip(got["bands"], row["bands"]):
        assert (band["lo"], band["hi"]) == (want["lo"], want["hi"])
        assert band["pq"] == pytest.approx(want["pq"], abs=1e-12)
        assert band["counts"] == pytest.approx(want["counts"], abs=1e-9)


def test_eval_checks_shapes_and_types():
    _, truth = fcc.scene(1, rows=32, cols=512)
    with pytest.raises(ValueError, match=r"truth: expected shape \(32, 512\) like labels, got \(32, 100\)"):
        fcc.eval(truth, truth[:, :100])
    with pytest.raises(TypeError, match="expected integer labels, got float64"):
        fcc.eval(truth.astype(np.float64), truth)
    with pytest.raises(ValueError, match="labels must lie in"):
        fcc.eval(truth.astype(np.int64) - 1, truth)
    # Integer labels of another width are taken.
    assert fcc.eval(truth.astype(np.int64), truth)["pq"] == 1.0
