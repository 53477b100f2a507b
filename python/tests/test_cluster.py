"""fcc.cluster: labels equal `fcc cluster`'s; arrays of any layout are read
correctly; bad input is refused with the CLI's message."""

from __future__ import annotations

import numpy as np
import pytest

import fcc
from conftest import flags

# Small scenes keep the suite quick; one full-size frame is in test_scene_matches_fcc_scene.
ROWS, COLS = 32, 512

CASES = [
    {},
    {"fsize": 3, "merge": "paper"},
    {"fsize": 11, "th_h": 0.3, "th_v": 0.8},
    {"preset": "adaptive"},
    {"th_h_slope": 0.01, "th_v_slope": 0.02},
    {"bridge": 2, "ring_reach": 8},
    {"min_points": 5},
    {"label_bits": 9},
]


@pytest.mark.parametrize("seed", [0, 3])
@pytest.mark.parametrize("kw", CASES, ids=lambda kw: ",".join(f"{k}={v}" for k, v in kw.items()) or "defaults")
def test_labels_equal_fcc_cluster(cli, seed, kw):
    xyz, _ = fcc.scene(seed, rows=ROWS, cols=COLS)
    inp = cli.npy("scene.npy", xyz)
    want = cli.cluster(inp, *flags(**kw))
    with pytest.warns(RuntimeWarning) if kw.get("label_bits") == 9 else _nothing():
        got = fcc.cluster(xyz, **kw)
        res = fcc.cluster_result(xyz, **kw)
    assert got.dtype == np.uint32 and got.shape == (ROWS, COLS)
    np.testing.assert_array_equal(got, want)
    np.testing.assert_array_equal(res.labels, want)


@pytest.mark.parametrize("ground", ["slope", "plane"])
def test_ground_removal_equals_fcc_cluster(cli, ground):
    xyz, _ = fcc.scene(5, rows=ROWS, cols=COLS, keep_ground=True)
    want = cli.cluster(cli.npy("g.npy", xyz), "--ground", ground, "--min-points", "3")
    got = fcc.cluster(xyz, ground=ground, min_points=3)
    np.testing.assert_array_equal(got, want)
    mask = fcc.remove_ground(xyz, ground)
    assert mask.dtype == np.bool_ and mask.shape == (ROWS, COLS) and mask.sum() > 1000
    assert not got[mask].any()


def test_scene_matches_fcc_scene(cli):
    xyz, truth = fcc.scene(2)
    assert xyz.shape == (64, 2048, 3) and xyz.dtype == np.float32
    cli.run("scene", "--seed", "2", "-o", str(cli.tmp / "s.npy"), "--gt", str(cli.tmp / "t.npy"))
    np.testing.assert_array_equal(np.load(cli.tmp / "s.npy"), xyz)
    np.testing.assert_array_equal(np.load(cli.tmp / "t.npy"), truth)
    np.testing.assert_array_equal(fcc.cluster(xyz), cli.cluster(cli.tmp / "s.npy"))


def test_float64_fortran_and_strided_arrays_give_the_same_labels():
    xyz, _ = fcc.scene(1, rows=ROWS, cols=COLS)
    want = fcc.cluster(xyz)
    wide = np.full((ROWS, COLS, 5), 7.0, dtype=np.float32)
    wide[:, :, 1:4] = xyz
    flipped = np.ascontiguousarray(xyz[:, ::-1])[:, ::-1]
    for a in [xyz.astype(np.float64), np.asfortranarray(xyz), wide[:, :, 1:4], flipped]:
        assert not np.shares_memory(a, xyz) or a is xyz
        np.testing.assert_array_equal(fcc.cluster(a), want)
        np.testing.assert_array_equal(fcc.cluster_result(a).labels, want)


def test_float64_is_rounded_to_float32_as_the_npy_reader_does(cli):
    xyz, _ = fcc.scene(4, rows=ROWS, cols=COLS)
    x64 = xyz.astype(np.float64) + 1e-9
    np.testing.assert_array_equal(fcc.cluster(x64), cli.cluster(cli.npy("x64.npy", x64)))


def test_the_array_is_not_modified():
    xyz, _ = fcc.scene(1, rows=ROWS, cols=COLS)
    before = xyz.copy()
    fcc.cluster(xyz)
    fcc.cluster_result(xyz, ground="slope")
    np.testing.assert_array_equal(xyz, before)


def test_nan_inf_and_out_of_range_pixels_are_empty():
    xyz = np.full((16, 256, 3), np.nan, dtype=np.float32)
    xyz[0, 0:4] = [[10.0, 0.0, 0.5], [10.0, 0.1, 0.5], [10.0, 0.2, 0.5], [10.0, 5.0, 0.5]]
    xyz[0, 1, 2] = np.nan  # one coordinate NaN: empty
    xyz[0, 2, 0] = np.inf  # infinite: empty
    labels = fcc.cluster(xyz)
    assert labels[0, :4].tolist() == [1, 0, 0, 2]
    assert (labels[1:] == 0).all()
    empty = np.full((16, 256, 3), np.nan)
    assert not fcc.cluster(empty).any()
    far = empty.copy()
    far[3, 3] = [200.0, 0.0, 0.0]
    with pytest.warns(RuntimeWarning, match="1 points beyond the Q7.8 coordinate range"):
        assert not fcc.cluster(far).any()
    with pytest.warns(RuntimeWarning):
        assert fcc.cluster_result(far).stats["out_of_range"] == 1


def test_label_overflow_warns_with_the_bits_needed():
    xyz, _ = fcc.scene(1, rows=ROWS, cols=COLS)
    with pytest.warns(RuntimeWarning, match=r"label overflow: .* use label_bits=\d+"):
        fcc.cluster(xyz, label_bits=8)
    with pytest.warns(RuntimeWarning):
        stats = fcc.cluster_result(xyz, label_bits=8).stats
    assert stats["overflow"] and stats["unlabelled"] > 0 and stats["labels_needed"] > 255


def test_records_describe_the_clusters():
    xyz, _ = fcc.scene(1, rows=ROWS, cols=COLS)
    res = fcc.cluster_result(xyz)
    rec = res.records
    n = res.clusters
    assert n == res.labels.max() > 0
    assert rec["id"].tolist() == list(range(1, n + 1))
    counts = np.bincount(res.labels.ravel(), minlength=n + 1)[1:]
    np.testing.assert_array_equal(rec["points"], counts)
    for k in ["min", "max", "sum", "centroid", "bounds_min", "bounds_max"]:
        assert rec[k].shape == (n, 3), k
    # The centroid of cluster 1 from its pixels (Q7.8 rounding: within 1/256 m).
    pts = xyz[res.labels == 1]
    np.testing.assert_allclose(rec["centroid"][0], pts.mean(axis=0), atol=1 / 256)
    assert (rec["box_size"][:, 0] >= rec["box_size"][:, 1]).all()
    assert res.stats["points"] == int(np.isfinite(xyz).all(axis=2).sum())
    assert res.stats["joins"] is not None and res.ground.shape == (ROWS, COLS)


@pytest.mark.parametrize("stream", [False, True])
def test_records_equal_the_cli_cluster_table(cli, stream):
    import json

    xyz, _ = fcc.scene(6, rows=ROWS, cols=COLS)
    out = cli.tmp / "clusters.json"
    cli.run("cluster", "-i", str(cli.npy("c.npy", xyz)), "--clusters", str(out), *(["--stream"] if stream else []))
    rows = json.loads(out.read_text())
    rec = fcc.cluster_result(xyz, stream=stream).records
    assert [r["cluster"] for r in rows] == rec["id"].tolist()
    for k, col in [("points", "points"), ("first_row", "first_row"), ("last_row", "last_row"),
                   ("span_first_col", "first_col"), ("span_last_col", "last_col"),
                   ("closed_col", "closed_col"), ("seam", "seam")]:
        assert [r[k] for r in rows] == rec[col].tolist(), k
    for k, col, i in [("box_cx", "box_center", 0), ("box_cy", "box_center", 1), ("box_length", "box_size", 0),
                      ("box_width", "box_size", 1), ("centroid_x", "centroid", 0), ("centroid_z", "centroid", 2)]:
        np.testing.assert_allclose([r[k] for r in rows], rec[col][:, i], atol=1 / 256, err_msg=k)
    np.testing.assert_allclose([r["heading"] for r in rows], rec["heading"], atol=1e-9)


@pytest.mark.parametrize(
    "bad, exc, msg",
    [
        (np.zeros((4, 5), np.float32), ValueError, r"xyz: expected shape \(R, C, 3\), got \(4, 5\)"),
        (np.zeros((4, 5, 2), np.float32), ValueError, r"got \(4, 5, 2\)"),
        (np.zeros((16, 256, 3), np.int32), TypeError, "expected float32 or float64 values, got int32"),
        (np.zeros((16, 256, 3), np.float16), TypeError, "got float16"),
        ([[[1.0, 2.0, 3.0]]], TypeError, "expected a numpy array"),
    ],
)
def test_bad_arrays_are_refused(bad, exc, msg):
    with pytest.raises(exc, match=msg):
        fcc.cluster(bad)
    with pytest.raises(exc, match=msg):
        fcc.cluster_result(bad)


@pytest.mark.parametrize(
    "kw, flag_args",
    [
        ({"fsize": 4}, ["--fsize", "4"]),
        ({"th_h": -1.0}, ["--th-h", "-1"]),
        ({"label_bits": 40}, ["--label-bits", "40"]),
        ({"th_v_slope": 1.5}, ["--th-v-slope", "1.5"]),
    ],
)
def test_bad_parameters_raise_the_cli_message(cli, kw, flag_args):
    xyz, _ = fcc.scene(1, rows=ROWS, cols=COLS)
    inp = cli.npy("p.npy", xyz)
    import subprocess

    r = subprocess.run([str(cli.exe), "cluster", "-i", str(inp), *flag_args], capture_output=True, text=True)
    assert r.returncode != 0
    message = r.stderr.strip().removeprefix("error: ")
    with pytest.raises(ValueError) as e:
        fcc.cluster(xyz, **kw)
    assert str(e.value) == message


def test_unknown_names_and_a_preset_with_thresholds_are_refused():
    xyz, _ = fcc.scene(1, rows=ROWS, cols=COLS)
    with pytest.raises(ValueError, match="unknown merge mode `fast`"):
        fcc.cluster(xyz, merge="fast")
    with pytest.raises(ValueError, match="unknown preset `tight`"):
        fcc.cluster(xyz, preset="tight")
    with pytest.raises(ValueError, match="unknown ground method `flat`"):
        fcc.cluster(xyz, ground="flat")
    with pytest.raises(ValueError, match="preset `adaptive` sets the thresholds and slopes: drop th_h"):
        fcc.cluster(xyz, preset="adaptive", th_h=0.3)
    with pytest.raises(ValueError, match="stream=True clusters exactly"):
        fcc.cluster_result(xyz, stream=True, merge="paper")


def test_pipeline_params_are_the_validated_ones():
    p = fcc.Pipeline(preset="adaptive", fsize=5)
    assert p.params["params"]["fsize"] == 5
    assert p.params["params"]["th_h_slope"] > 0
    assert p.params["merge"] == "exact" and p.params["ground"]["method"] == "none"
    core, quantise = p.time_core(fcc.scene(1, rows=ROWS, cols=COLS)[0], repeats=3)
    assert core > 0 and quantise > 0


class _nothing:
    def __enter__(self):
        return self

    def __exit__(self, *a):
        return False
