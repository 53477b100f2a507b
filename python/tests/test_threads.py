"""Several threads at once: the GIL is released while clustering, each
thread keeps its own buffers, and the results are those of one thread."""

from __future__ import annotations

from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

import fcc


def test_cluster_from_several_threads_at_once():
    scenes = [fcc.scene(seed, rows=32, cols=1024)[0] for seed in range(6)]
    jobs = [(x, kw) for x in scenes for kw in ({}, {"fsize": 3}, {"ground": "slope"})] * 3
    want = [fcc.cluster(x, **kw) for x, kw in jobs]
    with ThreadPoolExecutor(max_workers=4) as pool:
        got = list(pool.map(lambda j: fcc.cluster(j[0], **j[1]), jobs))
    for g, w in zip(got, want):
        np.testing.assert_array_equal(g, w)


def test_results_streams_and_readers_from_several_threads():
    xyz, truth = fcc.scene(3, rows=32, cols=1024)
    want = fcc.cluster_result(xyz, stream=True)

    def work(_):
        r = fcc.cluster_result(xyz, stream=True)
        s = fcc.Stream(32, 1024)
        for c in range(1024):
            s.push_column(xyz[:, c])
        s.finish()
        return r.labels, s.labels(), fcc.eval(r.labels, truth)["pq"]

    with ThreadPoolExecutor(max_workers=4) as pool:
        for labels, streamed, pq in pool.map(work, range(8)):
            np.testing.assert_array_equal(labels, want.labels)
            np.testing.assert_array_equal(streamed, want.labels)
            assert pq == pytest.approx(fcc.eval(want.labels, truth)["pq"], abs=1e-12)
