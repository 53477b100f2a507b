"""Fast Channel Clustering of LiDAR range images, from Python.

The package is the Rust crates of the FCC project behind a numpy interface:
the golden model (``cluster``, ``Stream``), the readers (``open``), the
projection of point clouds (``project``), ground removal, scoring under
``fcc eval``'s rules (``eval``) and the synthetic scene corpus (``scene``).
Parameters are validated by the same code as the ``fcc`` command line, and
labels equal ``fcc cluster``'s.

>>> import fcc
>>> xyz, truth = fcc.scene(seed=1)
>>> labels = fcc.cluster(xyz)
>>> labels.shape, labels.dtype
((64, 2048), dtype('uint32'))
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from typing import Any, Dict, Optional, Sequence, Tuple, Union

import numpy as np

from . import _fcc
from ._fcc import Frame, Frames, Projection, Stream, __version__

__all__ = [
    "ClusterResult",
    "Frame",
    "Frames",
    "Pipeline",
    "Projection",
    "Stream",
    "cluster",
    "cluster_result",
    "eval",
    "open",
    "project",
    "remove_ground",
    "scene",
    "__version__",
]

Image = Union[np.ndarray, Frame]


@dataclass
class ClusterResult:
    """The outcome of one clustering run.

    ``labels``: (R, C) uint32, 0 for empty, ground and dropped pixels,
    clusters 1..clusters (raster order of the first pixel in frame mode,
    closing order with ``stream=True``).
    ``stats``: the figures of ``fcc cluster --stats`` (points,
    ground_points, clusters, provisional, joins, merges, overflow,
    unlabelled, labels_needed, out_of_range, time_ms, ...).
    ``records``: one entry per record field, each a numpy array with one
    row per cluster (``id``, ``points``, ``first_col``, ``last_col``,
    ``closed_col``, ``seam``, ``first_row``, ``last_row``, ``min``/``max``
    (N, 3) int16 Q7.8, ``sum`` (N, 3), ``centroid`` (N, 3) metres,
    ``range`` (N, 2), ``bounds_min``/``bounds_max`` (N, 3), ``heading``,
    ``box_center``/``box_size``/``box_z`` (N, 2), ``box_yaw``); None unless
    asked for.
    ``ground``: (R, C) bool, the pixels ground removal took.
    """

    labels: np.ndarray
    stats: Dict[str, Any]
    records: Optional[Dict[str, np.ndarray]]
    ground: np.ndarray

    @property
    def clusters(self) -> int:
        """Clusters after the min-points filter."""
        return int(self.stats["clusters"])


class Pipeline:
    """Clustering parameters, validated once, for many frames.

    Takes the keyword arguments of :func:`cluster` (all but ``records`` and
    ``stream``). ``params`` holds the validated settings.
    """

    def __init__(
        self,
        *,
        fsize: Optional[int] = None,
        th_h: Optional[float] = None,
        th_v: Optional[float] = None,
        merge: str = "exact",
        label_bits: Optional[int] = None,
        th_h_slope: Optional[float] = None,
        th_v_slope: Optional[float] = None,
        preset: Optional[str] = None,
        bridge: Optional[int] = None,
        ring_reach: Optional[int] = None,
        ground: str = "none",
        ground_max_slope: Optional[float] = None,
        ground_distance: Optional[float] = None,
        min_points: int = 0,
    ) -> None:
        self._inner = _fcc.Pipeline(
            fsize=fsize,
            th_h=th_h,
            th_v=th_v,
            merge=merge,
            label_bits=label_bits,
            th_h_slope=th_h_slope,
            th_v_slope=th_v_slope,
            preset=preset,
            bridge=bridge,
            ring_reach=ring_reach,
            ground=ground,
            ground_max_slope=ground_max_slope,
            ground_distance=ground_distance,
            min_points=min_points,
        )
        self.params: Dict[str, Any] = json.loads(self._inner.params_json)

    def labels(self, xyz: np.ndarray) -> np.ndarray:
        """The (R, C) uint32 label image of an (R, C, 3) range image."""
        return self._inner.labels(xyz)

    def run(
        self, xyz: np.ndarray, records: bool = False, stream: bool = False, *, _stacklevel: int = 2
    ) -> ClusterResult:
        """Labels, statistics, and with ``records=True`` the per-cluster records."""
        labels, stats, recs, ground = self._inner.run(xyz, records, stream, _stacklevel)
        return ClusterResult(labels, json.loads(stats), recs, ground)

    def time_core(self, xyz: np.ndarray, repeats: int = 20) -> Tuple[float, float]:
        """Rust-side milliseconds on this frame, each a median of
        ``repeats`` runs: the golden model's ``cluster_with`` alone on the
        quantised frame, and ``Frame::from_xyz_f32`` (the quantisation that
        precedes it in ``fcc cluster``). For benchmarks."""
        return self._inner.time_core(xyz, repeats)


def _image(xyz: Image, ground: Optional[str]) -> Tuple[np.ndarray, str]:
    if isinstance(xyz, Frame):
        return xyz.xyz, ground if ground is not None else xyz.default_ground
    return xyz, ground if ground is not None else "none"


def cluster(
    xyz: Image,
    fsize: Optional[int] = None,
    th_h: Optional[float] = None,
    th_v: Optional[float] = None,
    merge: str = "exact",
    label_bits: Optional[int] = None,
    th_h_slope: Optional[float] = None,
    th_v_slope: Optional[float] = None,
    preset: Optional[str] = None,
    bridge: Optional[int] = None,
    ring_reach: Optional[int] = None,
    *,
    ground: Optional[str] = None,
    ground_max_slope: Optional[float] = None,
    ground_distance: Optional[float] = None,
    min_points: int = 0,
) -> np.ndarray:
    """Cluster a range image; returns the (R, C) uint32 label image.

    ``xyz``: an (R, C, 3) float32 or float64 array, x y z in metres, NaN
    (or any non-finite coordinate) for no return; or a :class:`Frame` from
    :func:`open`. Labels equal ``fcc cluster``'s with the same options.

    ``fsize``: connection-filter size K (odd, 3..=15; default 7).
    ``th_h``, ``th_v``: intra- and inter-channel thresholds in metres
    (default 0.5 and 1.0). ``merge``: ``"exact"`` connected components or
    the published ``"paper"`` merge table. ``label_bits``: provisional label
    width B (8..=20, default 15). ``th_h_slope``, ``th_v_slope``:
    range-adaptive thresholds, metres per metre (0 <= a < 1, default 0).
    ``preset``: ``"paper"`` or ``"adaptive"`` thresholds and slopes (not
    with th_h, th_v or the slopes). ``bridge``, ``ring_reach``: pass-1
    reach limits in pixels (default unlimited).
    ``ground``: ``"none"``, ``"slope"`` or ``"plane"`` ground removal
    before clustering (default: ``"none"`` for arrays, as ``fcc cluster``
    takes ``.npy`` range images; the CLI's default for the frame's input
    for a Frame). ``ground_max_slope`` (degrees), ``ground_distance``
    (metres): as ``--ground-max-slope``, ``--ground-distance``.
    ``min_points``: drop clusters of this many points or fewer.

    Raises ``ValueError`` for a wrong shape or a parameter out of range
    (with the CLI's message) and ``TypeError`` for a dtype other than
    float32/float64. Label overflow and points beyond the Q7.8 range give a
    ``RuntimeWarning`` (see :func:`cluster_result` for the counts). The GIL
    is released while clustering.
    """
    img, g = _image(xyz, ground)
    p = _fcc.Pipeline(
        fsize=fsize,
        th_h=th_h,
        th_v=th_v,
        merge=merge,
        label_bits=label_bits,
        th_h_slope=th_h_slope,
        th_v_slope=th_v_slope,
        preset=preset,
        bridge=bridge,
        ring_reach=ring_reach,
        ground=g,
        ground_max_slope=ground_max_slope,
        ground_distance=ground_distance,
        min_points=min_points,
    )
    return p.labels(img)


def cluster_result(
    xyz: Image,
    *,
    records: bool = True,
    stream: bool = False,
    ground: Optional[str] = None,
    **params: Any,
) -> ClusterResult:
    """Cluster a range image; returns a :class:`ClusterResult` with the
    labels, the statistics, the per-cluster records and the ground mask.

    Takes the arguments of :func:`cluster`. ``stream=True`` clusters column
    by column with the golden stream (spec §9), as ``fcc cluster --stream``:
    the same partition, clusters numbered in closing order, records with
    their closing column.
    """
    img, g = _image(xyz, ground)
    return Pipeline(ground=g, **params).run(img, records=records, stream=stream, _stacklevel=3)


def open(path: Any, **options: Any) -> Frames:
    """The frames of an input file, in order, as :class:`Frame` objects.

    Reads every input ``fcc cluster`` reads: Ouster captures (.pcap,
    .pcapng with the sensor's JSON metadata beside it or ``meta=``),
    Velodyne captures, ROS 2 recordings (.mcap, PointCloud2), point clouds
    (KITTI .bin, .pcd, .ply, projected with ``rows``, ``cols``, ``fov_up``,
    ``fov_down`` or ``beams``) and .npy range images; the file type is told
    as the CLI tells it. Options (keywords, the CLI's flags): ``truth``,
    ``meta``, ``sensor`` ("auto", "ouster", "velodyne"),
    ``keep_incomplete``, ``lidar_frame``, ``skip_frames``, ``max_frames``,
    ``topic``, ``rows``, ``cols``, ``fov_up``, ``fov_down``, ``beams``,
    ``velodyne_model``, ``velodyne_calibration``, ``velodyne_return``,
    ``velodyne_cols``, ``image_origin`` (``"sensor"`` or ``"sweep"``, as
    ``--image-origin``), ``strict``.

    Frames are decoded on a background thread at most two ahead of the
    caller, so a long capture is never held in memory. A missing file
    raises ``FileNotFoundError``, a file of no known type or a broken one
    ``ValueError``, both with the CLI's message. After the last frame the
    iterator's ``summary`` holds the capture's summary line and
    ``warnings`` its warnings, and ``notes`` the notes on how it was read.
    ``close()`` (or a ``with`` block) stops the reading early.
    """
    frames = _fcc.open(str(path), **{k: _path(v) for k, v in options.items()})
    return frames


def _path(v: Any) -> Any:
    """Path-like options as strings."""
    if hasattr(v, "__fspath__"):
        return str(v)
    return v


def project(
    points: np.ndarray,
    rows: int = 64,
    cols: int = 2048,
    fov_up: float = 3.0,
    fov_down: float = -25.0,
    beams: Optional[Union[Sequence[float], str]] = None,
) -> Projection:
    """Project an (N, 3) point cloud into a range image (nearest point wins
    each pixel), as ``fcc cluster`` projects .bin/.pcd/.ply clouds.

    ``beams``: one elevation per row in degrees (row 0 the top beam), or a
    Velodyne beam table name, instead of the even ``fov_up``..``fov_down``
    rows. The result's ``xyz`` is the image; ``labels_to_points(labels)``
    maps an (R, C) label image back to every input point.
    """
    return _fcc.project(points, rows, cols, fov_up, fov_down, beams)


def remove_ground(
    xyz: np.ndarray,
    method: str = "slope",
    max_slope: Optional[float] = None,
    distance: Optional[float] = None,
) -> np.ndarray:
    """The ground mask (R, C) bool of a range image: ``"slope"`` (column
    walk seeded by a plane fit), ``"plane"`` (RANSAC plane) or ``"none"``;
    ``max_slope`` in degrees (slope, default 10), ``distance`` in metres
    (plane, default 0.2), as ``fcc cluster --ground``."""
    return _fcc.remove_ground(xyz, method, max_slope, distance)


def _labels(given: Any, what: str) -> np.ndarray:
    """An integer label array as uint32, refusing values that do not fit."""
    a: np.ndarray = np.asarray(given)
    if a.dtype == np.uint32:
        return a
    if a.dtype.kind not in "iu":
        raise TypeError(f"{what}: expected integer labels, got {a.dtype}")
    if a.size and (int(a.min()) < 0 or int(a.max()) > 0xFFFFFFFF):
        raise ValueError(f"{what}: labels must lie in 0..=4294967295")
    return a.astype(np.uint32)


def eval(
    labels: np.ndarray,
    truth: np.ndarray,
    xyz: Optional[np.ndarray] = None,
    min_instance_points: int = 1,
) -> Dict[str, Any]:
    """Score a label image against ground-truth instances under
    ``fcc eval``'s rules (class-agnostic, void-aware; docs/lidar.md).

    ``labels`` and ``truth``: (R, C) integer arrays, 0 for no cluster / no
    instance. Returns ``pq``, ``sq``, ``rq``, ``over_segmentation``,
    ``under_segmentation``, ``clusters_per_frame``, ``instances_per_frame``,
    ``counts`` (true and false positives, ...) and, when the range image
    ``xyz`` is given, ``bands``: the same per range band (0-20, 20-40,
    40-80 m, by the mean range of each object).
    """
    out = json.loads(
        _fcc.score(_labels(labels, "labels"), _labels(truth, "truth"), xyz, min_instance_points)
    )
    result: Dict[str, Any] = dict(out["scores"])
    result["counts"] = out["counts"]
    if out["bands"] is not None:
        result["bands"] = [
            dict(lo=b["lo"], hi=b["hi"], counts=b["counts"], **b["scores"]) for b in out["bands"]
        ]
    return result


def scene(
    seed: int = 0,
    rows: int = 64,
    cols: int = 2048,
    keep_ground: bool = False,
    dropout: Optional[float] = None,
    missing: Optional[float] = None,
    range_noise: Optional[float] = None,
) -> Tuple[np.ndarray, np.ndarray]:
    """A synthetic street scene of the project's corpus, as ``fcc scene``
    writes it: the (R, C, 3) float32 range image (NaN empty) and the (R, C)
    uint32 ground-truth instances (0 for empty or ground). The same seed
    gives the same scene, bit for bit. ``keep_ground`` keeps the ground
    returns; ``dropout``, ``missing``, ``range_noise`` (metres) as the CLI's
    flags."""
    return _fcc.scene(seed, rows, cols, keep_ground, dropout, missing, range_noise)
