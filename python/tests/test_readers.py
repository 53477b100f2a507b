"""fcc.open: every reader `fcc cluster` has, through the same source layer;
labels of each frame equal `fcc cluster`'s on the file."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import fcc
from conftest import DATA

# The captures hold returns beyond the Q7.8 range, which fcc.cluster warns about.
pytestmark = pytest.mark.filterwarnings("ignore:.*Q7.8 coordinate range:RuntimeWarning")

OUSTER = [
    ("OS-0-128-U1_v2.3.0_1024x10.pcap", None),
    ("OS-1-32-G_v2.1.1_1024x10.pcap", None),
    ("OS-1-64_1024x10_fw20.pcap", "OS-1-64_sensor_config_reduced.json"),
    ("OS-2-128-U1_v2.3.0_1024x10.pcap", None),
]


def only_frame(path, **kw):
    frames = fcc.open(path, **kw)
    got = list(frames)
    assert len(got) == 1, [f.name for f in got]
    assert frames.frames_used == 1
    return frames, got[0]


@pytest.mark.parametrize("capture, meta", OUSTER)
def test_ouster_captures_cluster_as_fcc_cluster_does(cli, capture, meta):
    kw = {"meta": DATA / meta} if meta else {}
    frames, f = only_frame(DATA / capture, **kw)
    assert "frames used of" in frames.summary
    r, c, _ = f.xyz.shape
    assert f.xyz.dtype == np.float32 and f.intensity.shape == (r, c)
    assert not f.range_image and f.default_ground == "slope" and not f.projected
    # The sensor's stamp of the frame's first column.
    assert isinstance(f.timestamp_ns, int) and f.timestamp_ns > 0
    flags = ["--meta", str(DATA / meta)] if meta else []
    want = cli.cluster(DATA / capture, *flags)
    np.testing.assert_array_equal(fcc.cluster(f), want)
    np.testing.assert_array_equal(fcc.cluster(f.xyz, ground="slope"), want)
    np.testing.assert_array_equal(fcc.cluster_result(f).labels, want)
    # The stream gives the same partition (numbered in closing order).
    np.testing.assert_array_equal(
        fcc.cluster_result(f, stream=True).labels, cli.cluster(DATA / capture, "--stream", *flags)
    )


def test_sweep_origin_is_the_sensor_image_rotated_as_fcc_cluster_makes_it(cli):
    capture = DATA / OUSTER[1][0]
    _, sensor = only_frame(capture)
    _, sweep = only_frame(capture, image_origin="sweep")
    # Rotated by the largest destaggering shift: find it, then check it whole.
    shift = next(s for s in range(1, sensor.xyz.shape[1]) if np.array_equal(
        np.roll(sensor.xyz, -s, axis=1), sweep.xyz, equal_nan=True))
    assert shift > 0
    np.testing.assert_array_equal(np.roll(sensor.intensity, -shift, axis=1), sweep.intensity)
    np.testing.assert_array_equal(fcc.cluster(sweep), cli.cluster(capture, "--image-origin", "sweep"))
    with pytest.raises(ValueError, match="unknown image origin `north`"):
        fcc.open(capture, image_origin="north")


def test_ouster_frames_round_trip_through_fcc_convert(cli):
    _, f = only_frame(DATA / OUSTER[1][0])
    out = cli.tmp / "img.npy"
    cli.run("convert", "-i", str(DATA / OUSTER[1][0]), "-o", str(out))
    np.testing.assert_array_equal(np.load(out), f.xyz)


VELODYNE = [
    ("vlp16.pcap", {}),
    ("vlp16_dual.pcap", {"velodyne_return": "second"}),
    ("vlp32c.pcap", {}),
    ("hdl32e.pcap", {}),
    ("hdl64e.pcap", {"velodyne_calibration": DATA / "velodyne" / "hdl64e.yaml"}),
]


@pytest.mark.parametrize("capture, kw", VELODYNE, ids=[v[0] for v in VELODYNE])
def test_velodyne_captures_cluster_as_fcc_cluster_does(cli, capture, kw):
    path = DATA / "velodyne" / capture
    frames = fcc.open(path, **kw)
    got = list(frames)
    assert got and "Velodyne" in frames.summary
    flags = []
    for k, v in kw.items():
        flags += [f"--{k.replace('_', '-')}", str(v)]
    if len(got) == 1:
        want = [cli.cluster(path, *flags)]
    else:
        cli.run("cluster", "-i", str(path), "-o", str(cli.tmp / "v.npy"), *flags)
        want = [np.load(cli.tmp / f"v_{f.name}.npy") for f in got]
    for f, w in zip(got, want):
        assert f.intensity is not None and f.intensity.shape == f.xyz.shape[:2]
        assert f.timestamp_ns is None
        np.testing.assert_array_equal(fcc.cluster(f), w)


def test_hdl64e_without_calibration_is_refused_with_the_cli_message(cli):
    import subprocess

    path = DATA / "velodyne" / "hdl64e.pcap"
    r = subprocess.run([str(cli.exe), "cluster", "-i", str(path)], capture_output=True, text=True)
    with pytest.raises(ValueError) as e:
        list(fcc.open(path))
    assert str(e.value) == r.stderr.strip().removeprefix("error: ")


@pytest.mark.parametrize("name, topic", [("organised.mcap", None), ("unorganised.mcap", "/velodyne_points")])
def test_mcap_recordings_cluster_as_fcc_cluster_does(cli, name, topic):
    path = DATA / "mcap" / name
    frames = fcc.open(path, topic=topic)
    got = list(frames)
    assert got and "PointCloud2 messages used" in frames.summary
    flags = ["--topic", topic] if topic else []
    cli.run("cluster", "-i", str(path), "-o", str(cli.tmp / "m.npy"), *flags)
    for f in got:
        want_path = cli.tmp / f"m_{f.name}.npy"
        want = np.load(want_path if want_path.exists() else cli.tmp / "m.npy")
        np.testing.assert_array_equal(fcc.cluster(f), want)
        # The message's header stamp (the fixtures stamp k s + 500 ns).
        assert f.timestamp_ns % 10**9 == 500 and 100 <= f.timestamp_ns // 10**9 <= 201
        if f.projected:
            assert f.points.shape[1] == 3 and f.point_pixel.shape == (f.points.shape[0],)


def cloud(seed=1):
    """Points of a synthetic scene (with its ground) and their instances."""
    xyz, truth = fcc.scene(seed, keep_ground=True)
    ok = np.isfinite(xyz).all(axis=2)
    return xyz[ok], truth[ok]


def write_bin(path: Path, pts: np.ndarray) -> None:
    four = np.zeros((len(pts), 4), np.float32)
    four[:, :3] = pts
    four[:, 3] = 0.5
    four.tofile(path)


def write_ply(path: Path, pts: np.ndarray) -> None:
    head = f"ply\nformat ascii 1.0\nelement vertex {len(pts)}\nproperty float x\nproperty float y\nproperty float z\nend_header\n"
    path.write_text(head + "\n".join(f"{x:.6f} {y:.6f} {z:.6f}" for x, y, z in pts) + "\n")


def write_pcd(path: Path, pts: np.ndarray) -> None:
    head = (
        "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n"
        f"WIDTH {len(pts)}\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS {len(pts)}\nDATA ascii\n"
    )
    path.write_text(head + "\n".join(f"{x:.6f} {y:.6f} {z:.6f}" for x, y, z in pts) + "\n")


@pytest.mark.parametrize("ext, write", [("bin", write_bin), ("ply", write_ply), ("pcd", write_pcd)])
def test_point_clouds_project_and_cluster_as_fcc_cluster_does(cli, ext, write):
    pts, _ = cloud()
    pts = pts[::3]
    path = cli.tmp / f"cloud.{ext}"
    write(path, pts)
    _, f = only_frame(path)
    assert f.projected and f.points.shape == (len(pts), 3) and f.input_points == len(pts)
    assert f.xyz.shape == (64, 2048, 3)
    if ext == "bin":
        assert f.intensity.shape == (len(pts),)
    labels = fcc.cluster(f)
    np.testing.assert_array_equal(labels, cli.cluster(path))
    # Per point, as `fcc cluster --label` writes them (instance id in the upper 16 bits).
    per_point = f.labels_to_points(labels)
    cli.run("cluster", "-i", str(path), "--label", str(cli.tmp / "p.label"))
    raw = np.fromfile(cli.tmp / "p.label", dtype=np.uint32)
    np.testing.assert_array_equal(per_point != 0, (raw >> 16) != 0)
    # fcc.project on the points the reader read gives the same image.
    proj = fcc.project(f.points)
    np.testing.assert_array_equal(proj.xyz, f.xyz)
    np.testing.assert_array_equal(proj.point_pixel, f.point_pixel)
    np.testing.assert_array_equal(proj.labels_to_points(labels), per_point)


def test_projection_options_and_beams(cli):
    pts, _ = cloud(2)
    proj = fcc.project(pts, rows=32, cols=1024, fov_up=2.0, fov_down=-24.9)
    assert proj.xyz.shape == (32, 1024, 3) and proj.pixel_point.shape == (32, 1024)
    beams = list(np.linspace(2.0, -24.9, 16))
    assert fcc.project(pts, beams=beams, cols=512).xyz.shape == (16, 512, 3)
    with pytest.raises(ValueError, match="projection of 0 x 1024 pixels"):
        fcc.project(pts, rows=0, cols=1024)
    with pytest.raises(ValueError, match=r"points: expected shape \(N, 3\)"):
        fcc.project(pts[:, :2])


def test_npy_range_images_with_truth(cli):
    xyz, truth = fcc.scene(3, rows=32, cols=512)
    img, gt = cli.npy("img.npy", xyz), cli.npy("gt.npy", truth)
    _, f = only_frame(img, truth=gt)
    assert f.range_image and f.default_ground == "none" and f.name == "img"
    np.testing.assert_array_equal(f.xyz, xyz)
    np.testing.assert_array_equal(f.truth, truth)
    np.testing.assert_array_equal(fcc.cluster(f), cli.cluster(img))
    bad = cli.npy("gt_small.npy", truth[:, :100])
    with pytest.raises(ValueError, match="ground truth is 32 x 100 but"):
        list(fcc.open(img, truth=bad))


def test_several_topics_need_a_topic():
    with pytest.raises(ValueError, match="several PointCloud2 topics: choose one with --topic"):
        fcc.open(DATA / "mcap" / "unorganised.mcap")


def test_missing_and_unknown_files_raise_the_cli_message(cli, tmp_path):
    import subprocess

    def cli_error(p):
        r = subprocess.run([str(cli.exe), "cluster", "-i", str(p)], capture_output=True, text=True)
        return r.stderr.strip().removeprefix("error: ")

    for name in ["nothing.npy", "nothing.pcap", "nothing.bin", "nothing.mcap"]:
        p = tmp_path / name
        with pytest.raises(FileNotFoundError) as e:
            fcc.open(p)
        assert str(e.value) == cli_error(p)
    odd = tmp_path / "notes.txt"
    odd.write_text("x")
    with pytest.raises(ValueError) as e:
        fcc.open(odd)
    assert str(e.value) == cli_error(odd)
    # An Ouster capture without its metadata beside it.
    cap = tmp_path / "lone.pcap"
    cap.write_bytes((DATA / OUSTER[1][0]).read_bytes())
    with pytest.raises(ValueError) as e:
        list(fcc.open(cap, sensor="ouster"))
    assert "needs its metadata JSON" in str(e.value)
    with pytest.raises(ValueError, match="unknown sensor `lidar`"):
        fcc.open(cap, sensor="lidar")


def test_skip_and_max_frames_and_an_abandoned_iterator():
    path = DATA / "velodyne" / "vlp16.pcap"
    all_frames = [f.name for f in fcc.open(path)]
    assert [f.name for f in fcc.open(path, max_frames=1)] == all_frames[:1]
    assert [f.name for f in fcc.open(path, skip_frames=1)] == all_frames[1:]
    # Dropping or closing an iterator half way stops its reading thread.
    for _ in range(20):
        it = fcc.open(path)
        next(it)
        del it
    with fcc.open(path) as it:
        first = next(it)
    assert first.name == all_frames[0] and list(it) == []
    it = fcc.open(path)
    it.close()
    assert list(it) == []
