"""fcc.Stream: columns in, records out; the same partition as frame mode."""

from __future__ import annotations

import numpy as np
import pytest

import fcc

ROWS, COLS = 32, 512


def same_partition(a: np.ndarray, b: np.ndarray) -> bool:
    """Whether two label images group the same pixels (0 in the same places)."""
    a, b = a.ravel(), b.ravel()
    if not np.array_equal(a == 0, b == 0):
        return False
    pairs = np.unique(np.stack([a[a != 0], b[b != 0]]), axis=1)
    return len(np.unique(pairs[0])) == len(np.unique(pairs[1])) == pairs.shape[1]


def run_stream(s: fcc.Stream, xyz: np.ndarray):
    records = []
    for c in range(xyz.shape[1]):
        records.append(s.push_column(xyz[:, c]))
    records.append(s.finish())
    return records


@pytest.mark.parametrize("seed", [0, 1, 2])
@pytest.mark.parametrize("kw", [{}, {"fsize": 3}, {"preset": "adaptive"}, {"bridge": 3}])
def test_stream_gives_the_frame_mode_partition(seed, kw):
    xyz, _ = fcc.scene(seed, rows=ROWS, cols=COLS)
    s = fcc.Stream(ROWS, COLS, **kw)
    recs = run_stream(s, xyz)
    frame = fcc.cluster(xyz, **kw)
    labels = s.labels()
    assert labels.shape == (ROWS, COLS) and labels.dtype == np.uint32
    assert same_partition(labels, frame)
    ids = np.concatenate([r["id"] for r in recs])
    assert ids.tolist() == list(range(1, frame.max() + 1))
    points = np.concatenate([r["points"] for r in recs])
    np.testing.assert_array_equal(points, np.bincount(labels.ravel())[1:])
    # Every record closes at or after its last column.
    for c, r in enumerate(recs):
        assert (r["closed_col"] == min(c, COLS)).all()
    assert s.stats()["clusters"] == frame.max()
    # The pipeline's stream (`fcc cluster --stream`) numbers the same way.
    np.testing.assert_array_equal(fcc.cluster_result(xyz, stream=True, **kw).labels, labels)


def test_a_stream_takes_frame_after_frame():
    a, _ = fcc.scene(0, rows=ROWS, cols=COLS)
    b, _ = fcc.scene(1, rows=ROWS, cols=COLS)
    s = fcc.Stream(ROWS, COLS)
    for xyz in [a, b, a]:
        recs = run_stream(s, xyz)
        assert same_partition(s.labels(), fcc.cluster(xyz))
    assert recs[-1]["frame"].tolist() == [2] * len(recs[-1]["frame"])


def test_stream_records_match_frame_mode_records():
    xyz, _ = fcc.scene(4, rows=ROWS, cols=COLS)
    s = fcc.Stream(ROWS, COLS)
    recs = run_stream(s, xyz)
    stream_points = sorted(np.concatenate([r["points"] for r in recs]).tolist())
    frame = fcc.cluster_result(xyz).records
    assert stream_points == sorted(frame["points"].tolist())
    sums = sorted(map(tuple, np.concatenate([r["sum"] for r in recs]).tolist()))
    assert sums == sorted(map(tuple, frame["sum"].tolist()))


def test_stream_errors():
    s = fcc.Stream(ROWS, COLS)
    with pytest.raises(ValueError, match=r"column: expected shape \(32, 3\), got \(16, 3\)"):
        s.push_column(np.zeros((16, 3), np.float32))
    with pytest.raises(TypeError, match="float32 or float64"):
        s.push_column(np.zeros((32, 3), np.int64))
    s.push_column(np.full((32, 3), np.nan))
    with pytest.raises(ValueError):
        s.finish()
    with pytest.raises(ValueError):
        s.labels()
    with pytest.raises(ValueError, match="fsize = 4 is out of range"):
        fcc.Stream(ROWS, COLS, fsize=4)


def test_the_open_limit_refuses_runs_past_the_count():
    """``open_limit`` (spec §9.1): at the frame's peak count nothing changes;
    below it runs stay unlabelled, counted in the stats; frame mode refuses it."""
    xyz, _ = fcc.scene(2, rows=ROWS, cols=COLS)
    free = fcc.Stream(ROWS, COLS)
    run_stream(free, xyz)
    st = free.stats()
    assert st["open_refused"] == 0 and 0 < st["peak_open"] <= st["peak_counted"] <= st["peak_labels"]
    assert st["merges"] == st["runs"] - st["clusters"] >= st["peak_col_merges"]
    assert 0 < st["peak_col_closed"] <= st["peak_col_freed"] <= st["peak_labels"]
    at = fcc.Stream(ROWS, COLS, open_limit=st["peak_counted"])
    run_stream(at, xyz)
    np.testing.assert_array_equal(at.labels(), free.labels())
    below = fcc.Stream(ROWS, COLS, open_limit=2)
    run_stream(below, xyz)
    sb = below.stats()
    assert sb["open_refused"] > 0 and not sb["overflow"] and sb["peak_counted"] <= 2
    assert (below.labels() != 0).sum() == sb["points"] - sb["unlabelled"] < st["points"]
    with pytest.raises(ValueError, match="open_limit"):
        fcc.Stream(ROWS, COLS, open_limit=0)
