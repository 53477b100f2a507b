"""Type stubs of the native module (the Rust crates behind ``fcc``)."""

from typing import Any, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np

__version__: str

class Pipeline:
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
    ) -> None: ...
    @property
    def params_json(self) -> str: ...
    def labels(self, xyz: np.ndarray) -> np.ndarray: ...
    def run(
        self, xyz: np.ndarray, records: bool = False, stream: bool = False, stacklevel: int = 2
    ) -> Tuple[np.ndarray, str, Optional[Dict[str, np.ndarray]], np.ndarray]: ...
    def time_core(self, xyz: np.ndarray, repeats: int = 20) -> Tuple[float, float]: ...

class Stream:
    """The golden stream (spec §9): push the columns of a frame, get the
    records of the clusters as they close."""

    def __init__(
        self,
        rows: int,
        cols: int,
        *,
        fsize: Optional[int] = None,
        th_h: Optional[float] = None,
        th_v: Optional[float] = None,
        label_bits: Optional[int] = None,
        th_h_slope: Optional[float] = None,
        th_v_slope: Optional[float] = None,
        preset: Optional[str] = None,
        bridge: Optional[int] = None,
        ring_reach: Optional[int] = None,
    ) -> None: ...
    @property
    def rows(self) -> int: ...
    @property
    def cols(self) -> int: ...
    @property
    def columns_taken(self) -> int: ...
    def push_column(self, column: np.ndarray) -> Dict[str, np.ndarray]: ...
    def finish(self) -> Dict[str, np.ndarray]: ...
    def labels(self) -> np.ndarray: ...
    def stats(self) -> Dict[str, Any]: ...

class Frame:
    """One range image of an input, with what came with it."""

    name: str
    xyz: np.ndarray
    range_image: bool
    intensity: Optional[np.ndarray]
    truth: Optional[np.ndarray]
    truth_points: Optional[np.ndarray]
    points: Optional[np.ndarray]
    point_pixel: Optional[np.ndarray]
    timestamp_ns: Optional[int]
    input_points: int
    outside_fov: int
    pixel_shared: int
    unprojected: int
    @property
    def projected(self) -> bool: ...
    @property
    def default_ground(self) -> str: ...
    def labels_to_points(self, labels: np.ndarray) -> np.ndarray: ...

class Frames:
    """The frames of one input, in order."""

    notes: List[str]
    warnings: List[str]
    summary: Optional[str]
    frames_used: int
    def __iter__(self) -> "Frames": ...
    def __next__(self) -> Frame: ...
    def close(self) -> None: ...
    def __enter__(self) -> "Frames": ...
    def __exit__(self, *args: Any) -> bool: ...

class Projection:
    """A point cloud projected into a range image."""

    xyz: np.ndarray
    point_pixel: np.ndarray
    pixel_point: np.ndarray
    outside_fov: int
    def labels_to_points(self, labels: np.ndarray) -> np.ndarray: ...

def open(path: str, **options: Any) -> Frames: ...
def project(
    points: np.ndarray,
    rows: int = 64,
    cols: int = 2048,
    fov_up: float = 3.0,
    fov_down: float = -25.0,
    beams: Optional[Union[Sequence[float], str]] = None,
) -> Projection: ...
def remove_ground(
    xyz: np.ndarray,
    method: str = "slope",
    max_slope: Optional[float] = None,
    distance: Optional[float] = None,
) -> np.ndarray: ...
def score(
    labels_: np.ndarray,
    truth: np.ndarray,
    xyz: Optional[np.ndarray] = None,
    min_instance_points: int = 1,
) -> str: ...
def scene(
    seed: int = 0,
    rows: Optional[int] = None,
    cols: Optional[int] = None,
    keep_ground: bool = False,
    dropout: Optional[float] = None,
    missing: Optional[float] = None,
    range_noise: Optional[float] = None,
) -> Tuple[np.ndarray, np.ndarray]: ...
