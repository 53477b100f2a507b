"""Test frames of the cocotb bench and their `.npy` form.

Frames are made here as Q7.8 integer points (what the core takes), so the
float32 `.npy` handed to the `fcc` binary holds exactly `q / 256` and the
golden model quantises it back to the same integers. Nothing here clusters:
expected labels always come from `fcc cluster`.
"""

import math
import random
import struct

# Elevation of row 0 and of the last row, degrees (an HDL-64E-like fan).
ELEV_TOP = 2.0
ELEV_BOTTOM = -24.8


def point(rows, cols, r, c, rng_m):
    """The Q7.8 point of pixel (r, c) at range `rng_m` metres."""
    az = 2.0 * math.pi * c / cols
    el = math.radians(ELEV_TOP + (ELEV_BOTTOM - ELEV_TOP) * r / max(rows - 1, 1))
    xyz = (
        rng_m * math.cos(el) * math.cos(az),
        rng_m * math.cos(el) * math.sin(az),
        rng_m * math.sin(el),
    )
    return tuple(max(-32768, min(32767, int(round(v * 256.0)))) for v in xyz)


def beat(p):
    """The input beat of one pixel: x, y, z in bits 47:0, bit 48 = valid."""
    if p is None:
        return 0
    x, y, z = p
    return (x & 0xFFFF) | ((y & 0xFFFF) << 16) | ((z & 0xFFFF) << 32) | (1 << 48)


def empty(rows, cols):
    return [None] * (rows * cols)


def one_point(rows, cols):
    f = empty(rows, cols)
    r, c = rows // 2, cols // 3
    f[r * cols + c] = point(rows, cols, r, c, 7.0)
    return f


def one_cluster(rows, cols):
    """Every pixel on a cylinder of 5 m: one cluster, closed across the seam."""
    return [point(rows, cols, i // cols, i % cols, 5.0) for i in range(rows * cols)]


def label_overflow(rows, cols):
    """Every pixel a run of its own (ranges alternate 4 m / 12 m along a row),
    after a leading gap so that the labels run out in the middle of a row."""
    f = empty(rows, cols)
    lead = cols // 4
    for i in range(lead, rows * cols):
        r, c = divmod(i, cols)
        f[i] = point(rows, cols, r, c, 4.0 if c % 2 == 0 else 12.0)
    return f


def random_frame(rows, cols, seed):
    """Seeded street-like frame: boxes at random ranges, with dropouts,
    range noise and stray points (which split runs, so rows join and merge)."""
    rng = random.Random(seed)
    rmap = [None] * (rows * cols)
    for _ in range(rng.randint(4, 14)):
        r0 = rng.randrange(rows)
        c0 = rng.randrange(cols)
        h = rng.randint(1, rows)
        w = rng.randint(1, cols // 4)
        dist = rng.uniform(2.0, 40.0)
        slope = rng.uniform(-0.05, 0.05)
        for r in range(r0, min(rows, r0 + h)):
            for dc in range(w):
                c = (c0 + dc) % cols
                rmap[r * cols + c] = dist + slope * dc
    holes = rng.uniform(0.0, 0.3)
    stray = rng.uniform(0.02, 0.12)
    f = []
    for i, d in enumerate(rmap):
        r, c = divmod(i, cols)
        if rng.random() < stray:
            f.append(point(rows, cols, r, c, rng.uniform(1.0, 80.0)))
        elif d is None or rng.random() < holes:
            f.append(None)
        else:
            f.append(point(rows, cols, r, c, d + rng.uniform(-0.03, 0.03)))
    return f


def cut_after(frame, at):
    """The frame as the core sees it after a `tlast` on pixel `at`."""
    return frame[: at + 1] + [None] * (len(frame) - at - 1)


def write_npy_f32(path, rows, cols, frame):
    """A (rows, cols, 3) float32 range image, NaN for an empty pixel."""
    header = "{'descr': '<f4', 'fortran_order': False, 'shape': (%d, %d, 3), }" % (rows, cols)
    pad = 64 - (10 + len(header) + 1) % 64
    header = header + " " * pad + "\n"
    nan = struct.pack("<f", float("nan"))
    body = bytearray()
    for p in frame:
        if p is None:
            body += nan * 3
        else:
            body += struct.pack("<3f", *(v / 256.0 for v in p))
    with open(path, "wb") as fh:
        fh.write(b"\x93NUMPY\x01\x00" + struct.pack("<H", len(header)) + header.encode("latin1"))
        fh.write(body)


def read_npy_u32(path):
    """The labels of a (rows, cols) uint32 `.npy` written by `fcc cluster`."""
    with open(path, "rb") as fh:
        data = fh.read()
    if data[:6] != b"\x93NUMPY":
        raise ValueError(f"{path}: not a .npy file")
    major = data[6]
    if major == 1:
        hlen = struct.unpack("<H", data[8:10])[0]
        start = 10 + hlen
    else:
        hlen = struct.unpack("<I", data[8:12])[0]
        start = 12 + hlen
    header = data[start - hlen : start].decode("latin1")
    if "'<u4'" not in header or "True" in header:
        raise ValueError(f"{path}: expected a C-order uint32 array, header {header.strip()}")
    n = (len(data) - start) // 4
    return list(struct.unpack("<%dI" % n, data[start : start + 4 * n]))
