#!/usr/bin/env python3
"""Write the small ROS 2 recordings (MCAP, sensor_msgs/msg/PointCloud2 in
CDR) the tests of fcc-lidar read, with the `mcap` and `mcap-ros2-support`
packages from PyPI doing all the serialisation.

The scene is the one of ../velodyne/make_fixtures.py, simplified: the
sensor 1.5 m above a flat ground, walls at x = +-15 and y = +-12 m, a box at
x 6..8 m, y -1..1 m up to 0.5 m above the sensor. A 16-beam sensor (+15 to
-15 degrees, 2 degrees apart) with 180 columns sees it.

- `organised.mcap` (zstd chunks): topic /lidar/points, two organised clouds
  (16 x 180), float32 x y z, float32 intensity (ground 10, walls 50, box
  200), NaN where no return; row 0 is the LOWEST beam, as some drivers
  write them. A std_msgs/msg/String on /chatter beside it.
- `unorganised.mcap` (lz4 chunks): topics /velodyne_points and
  /other_points, one unorganised cloud each (height 1), float64 x y z,
  uint8 intensity, no-return points left out.

Run from this folder with `pip install mcap mcap-ros2-support`:
    python3 make_fixtures.py
"""

import math
import struct

from mcap.writer import CompressionType
from mcap_ros2.writer import Writer

POINTCLOUD2 = """std_msgs/Header header
uint32 height
uint32 width
PointField[] fields
bool is_bigendian
uint32 point_step
uint32 row_step
uint8[] data
bool is_dense
================================================================================
MSG: std_msgs/Header
builtin_interfaces/Time stamp
string frame_id
================================================================================
MSG: builtin_interfaces/Time
int32 sec
uint32 nanosec
================================================================================
MSG: sensor_msgs/PointField
uint8 INT8    = 1
uint8 UINT8   = 2
uint8 INT16   = 3
uint8 UINT16  = 4
uint8 INT32   = 5
uint8 UINT32  = 6
uint8 FLOAT32 = 7
uint8 FLOAT64 = 8
string name
uint32 offset
uint8  datatype
uint32 count
"""

HEIGHT = 1.5
BOX = ((6.0, 8.0), (-1.0, 1.0), (-HEIGHT, 0.5))
ROWS, COLS = 16, 180


def ray(elev_deg, az_deg):
    """Point and surface hit by a ray from the origin (azimuth clockwise from +x)."""
    w, a = math.radians(elev_deg), math.radians(az_deg)
    d = (math.cos(w) * math.cos(a), -math.cos(w) * math.sin(a), math.sin(w))
    best = (math.inf, None)
    if d[2] < 0:
        best = min(best, (-HEIGHT / d[2], 10))
    for k, lim in ((0, 15.0), (0, -15.0), (1, 12.0), (1, -12.0)):
        if d[k] != 0 and lim / d[k] > 0:
            best = min(best, (lim / d[k], 50))
    t0, t1 = -math.inf, math.inf
    for v, (lo, hi) in zip(d, BOX):
        if abs(v) < 1e-12:
            if not lo <= 0 <= hi:
                t0, t1 = math.inf, -math.inf
            continue
        p, q = lo / v, hi / v
        t0, t1 = max(t0, min(p, q)), min(t1, max(p, q))
    if t0 <= t1 and t0 > 0:
        best = min(best, (t0, 200))
    t, s = best
    if t > 60:
        return None, 0
    return tuple(t * c for c in d), s


def field(name, offset, datatype):
    return {"name": name, "offset": offset, "datatype": datatype, "count": 1}


def header(sec):
    return {"stamp": {"sec": sec, "nanosec": 500}, "frame_id": "lidar"}


def organised(sec):
    data = b""
    for r in range(ROWS):
        elev = -15.0 + 2.0 * r  # row 0 the lowest beam
        for c in range(COLS):
            az = (c + 0.5) * 360.0 / COLS - 180.0
            p, s = ray(elev, az)
            if p is None:
                data += struct.pack("<4f", math.nan, math.nan, math.nan, 0.0)
            else:
                data += struct.pack("<4f", *p, float(s))
    return {
        "header": header(sec),
        "height": ROWS,
        "width": COLS,
        "fields": [field("x", 0, 7), field("y", 4, 7), field("z", 8, 7), field("intensity", 12, 7)],
        "is_bigendian": False,
        "point_step": 16,
        "row_step": 16 * COLS,
        "data": data,
        "is_dense": False,
    }


def unorganised(sec):
    data = b""
    n = 0
    for r in range(ROWS):
        elev = 15.0 - 2.0 * r
        for c in range(COLS):
            az = (c + 0.5) * 360.0 / COLS - 180.0
            p, s = ray(elev, az)
            if p is not None:
                data += struct.pack("<3dB", *p, s) + b"\0" * 7
                n += 1
    return {
        "header": header(sec),
        "height": 1,
        "width": n,
        "fields": [field("x", 0, 8), field("y", 8, 8), field("z", 16, 8), field("intensity", 24, 2)],
        "is_bigendian": False,
        "point_step": 32,
        "row_step": 32 * n,
        "data": data,
        "is_dense": True,
    }


def main():
    with open("organised.mcap", "wb") as f:
        w = Writer(f, compression=CompressionType.ZSTD)
        pc = w.register_msgdef("sensor_msgs/msg/PointCloud2", POINTCLOUD2)
        st = w.register_msgdef("std_msgs/msg/String", "string data\n")
        for k in range(2):
            t = (100 + k) * 1_000_000_000
            w.write_message("/lidar/points", pc, organised(100 + k), log_time=t, publish_time=t, sequence=k)
            w.write_message("/chatter", st, {"data": "hello"}, log_time=t + 1, publish_time=t + 1, sequence=k)
        w.finish()
    with open("unorganised.mcap", "wb") as f:
        w = Writer(f, compression=CompressionType.LZ4)
        pc = w.register_msgdef("sensor_msgs/msg/PointCloud2", POINTCLOUD2)
        t = 200 * 1_000_000_000
        w.write_message("/velodyne_points", pc, unorganised(200), log_time=t, publish_time=t, sequence=0)
        w.write_message("/other_points", pc, unorganised(201), log_time=t + 1, publish_time=t + 1, sequence=0)
        w.finish()


if __name__ == "__main__":
    main()
