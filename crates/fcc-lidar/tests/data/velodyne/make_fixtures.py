#!/usr/bin/env python3
"""Write the small Velodyne captures the tests of fcc-lidar read.

Each capture is a classic pcap (written by dpkt: Ethernet, IPv4, UDP to port
2368) of Velodyne data packets built here byte by byte from the packet format
in the user manuals (see docs/lidar.md). The sensor sits 1.5 m above a flat
ground in a room with walls at x = +15, x = -15, y = +12 and y = -12 m; a box
(x 6..8 m, y -1..1 m, up to 0.5 m above the sensor) stands in front of it.
Every firing is ray-cast against that scene at the azimuth the manuals give
for its firing time, its distance rounded to the model's resolution.
Intensity tells the surface apart: ground 10, walls 50, box 200.

Each capture starts at azimuth 300 degrees and runs one and a half turns at 2
degrees per data block, so it holds one complete rotation between two
partial ones. Beside each capture, `<name>_points.json` lists the expected point of
every 97th firing of the complete rotation (laser, x, y, z in metres, the
decoder's frame: x forward, y left, z up).

Run from this folder with `pip install dpkt`:  python3 make_fixtures.py
"""

import json
import math
import struct

import dpkt

HEIGHT = 1.5
BOX = ((6.0, 8.0), (-1.0, 1.0), (-HEIGHT, 0.5))
WALLS_X = (15.0, -15.0)
WALLS_Y = (12.0, -12.0)
STEP_CENTIDEG = 200
START_CENTIDEG = 30000

# VLP-16: elevation, azimuth offset, and the manual's vertical offsets (mm).
VLP16_VERTICAL_MM = [11.2, -0.7, 9.7, -2.2, 8.1, -3.7, 6.6, -5.1, 5.1, -6.6, 3.7, -8.1, 2.2, -9.7, 0.7, -11.2]
VLP16 = [(-15 + i if i % 2 == 0 else i, 0.0) for i in range(16)]
HDL32E = [
    (round((-92 + 4 * (i // 2) if i % 2 == 0 else -28 + 4 * (i // 2)) / 3.0, 2), 0.0)
    for i in range(32)
]
# VLP-32C: elevation and the manual's azimuth offset (a laser points at the
# block azimuth plus its offset).
VLP32C = [
    (-25.0, 1.4), (-1.0, -4.2), (-1.667, 1.4), (-15.639, -1.4), (-11.31, 1.4),
    (0.0, -1.4), (-0.667, 4.2), (-8.843, -1.4), (-7.254, 1.4), (0.333, -4.2),
    (-0.333, 1.4), (-6.148, -1.4), (-5.333, 4.2), (1.333, -1.4), (0.667, 4.2),
    (-4.0, -1.4), (-4.667, 1.4), (1.667, -4.2), (1.0, 1.4), (-3.667, -4.2),
    (-3.333, 4.2), (3.333, -1.4), (2.333, 1.4), (-2.667, -1.4), (-3.0, 1.4),
    (7.0, -1.4), (4.667, 1.4), (-2.333, -4.2), (-2.0, 4.2), (15.0, -1.4),
    (10.333, 1.4), (-1.333, -1.4),
]


def hdl64e_calibration():
    """A made-up HDL-64E calibration: upper lasers +2 .. -8.33 deg, lower
    -8.83 .. -24.33 deg, azimuth corrections of a few degrees, distance
    corrections of about 1.4 m and origin offsets of a few centimetres."""
    lasers = []
    for i in range(64):
        if i < 32:
            elev = 2.0 - i * (10.33 / 31)
        else:
            elev = -8.83 - (i - 32) * 0.5
        lasers.append(
            {
                "laser_id": i,
                "rot_correction": math.radians(((i * 7) % 11 - 5) * 0.9),
                "vert_correction": math.radians(elev),
                "dist_correction": 1.3 + 0.01 * (i % 20),
                "dist_correction_x": 0.0,
                "dist_correction_y": 0.0,
                "two_pt_correction_available": False,
                "vert_offset_correction": 0.21 if i < 32 else 0.15,
                "horiz_offset_correction": 0.026 if i % 2 == 0 else -0.026,
            }
        )
    return lasers


def ray_cast(origin, d):
    """Distance along unit direction d from origin to the scene, and the surface."""
    best = (math.inf, None)
    ox, oy, oz = origin
    dx, dy, dz = d
    if dz < 0:
        t = (-HEIGHT - oz) / dz
        best = min(best, (t, "ground"), key=lambda b: b[0])
    for wx in WALLS_X:
        if dx != 0:
            t = (wx - ox) / dx
            if t > 0:
                best = min(best, (t, "wall"), key=lambda b: b[0])
    for wy in WALLS_Y:
        if dy != 0:
            t = (wy - oy) / dy
            if t > 0:
                best = min(best, (t, "wall"), key=lambda b: b[0])
    # Slab test for the box.
    t0, t1 = -math.inf, math.inf
    for o, v, (lo, hi) in zip(origin, d, BOX):
        if abs(v) < 1e-12:
            if not lo <= o <= hi:
                t0, t1 = math.inf, -math.inf
            continue
        a, b = (lo - o) / v, (hi - o) / v
        t0, t1 = max(t0, min(a, b)), min(t1, max(a, b))
    if t0 <= t1 and t0 > 0:
        best = min(best, (t0, "box"), key=lambda b: b[0])
    return best


INTENSITY = {"ground": 10, "wall": 50, "box": 200}


def laser_ray(laser, az_deg):
    """Origin and unit direction of a laser at azimuth az (degrees clockwise
    from forward), in the x-forward, y-left, z-up frame. `laser` holds
    elevation and rot correction in degrees and offsets in metres."""
    elev, rot, vo, ho = laser
    a = math.radians(az_deg - rot)
    w = math.radians(elev)
    # Velodyne's frame: xv right, yv forward. A return at distance r lies at
    # xv = (r cos w - vo sin w) sin a - ho cos a,
    # yv = (r cos w - vo sin w) cos a + ho sin a,
    # z = r sin w + vo cos w.
    def at(r):
        h = r * math.cos(w) - vo * math.sin(w)
        xv = h * math.sin(a) - ho * math.cos(a)
        yv = h * math.cos(a) + ho * math.sin(a)
        z = r * math.sin(w) + vo * math.cos(w)
        return (yv, -xv, z)

    o = at(0.0)
    p = at(1.0)
    return o, tuple(q - s for q, s in zip(p, o)), at


def firing(laser, az_deg, resolution, dist_correction=0.0, extra_m=0.0):
    """Raw distance, intensity and expected point of one firing."""
    o, d, at = laser_ray(laser, az_deg)
    t, surface = ray_cast(o, d)
    r = t + extra_m
    raw = int(round((r - dist_correction) / resolution))
    if not 0 < raw < 65536:
        return 0, 0, None
    return raw, INTENSITY[surface], at(raw * resolution + dist_correction)


def timing(model, k):
    """Firing time of slot k after the start of its sequence, and the
    sequence length, microseconds (the manuals' timing tables)."""
    if model == "vlp16":
        return 2.304 * k, 55.296
    if model == "vlp32c":
        return 2.304 * (k // 2), 55.296
    if model == "hdl32e":
        return 1.152 * k, 46.08
    # HDL-64E S2: four lasers of a bank every 6 us, in a 48 us period.
    return 6.0 * (k // 4) + [0.0, 1.26, 2.46, 3.66][k % 4], 48.0


def build(name, model, lasers, resolution, product, mode=0x37, dual=False, dist=None):
    """Write `<name>.pcap` and `<name>_points.json`."""
    seqs = 2 if model == "vlp16" else 1
    per_seq = 32 // seqs
    blocks = []  # (flag, azimuth, [(raw, intensity)] * 32, [points])
    az = START_CENTIDEG
    turns = 0
    complete = []
    firing_no = 0
    total = int(36000 * 1.5 / STEP_CENTIDEG)
    for n in range(total):
        banks = [(0xEEFF, 0)] if model != "hdl64e" else [(0xEEFF, 0), (0xDDFF, 32)]
        returns = [0.0, 1.0] if dual else [0.0]
        for extra in returns:
            for flag, base in banks:
                data = []
                for s in range(seqs):
                    seq_az = az + STEP_CENTIDEG / seqs * s
                    for k in range(per_seq):
                        t, period = timing(model, k)
                        a = (seq_az + STEP_CENTIDEG / seqs * t / period) / 100.0
                        laser = lasers[base + k]
                        dc = dist[base + k] if dist else 0.0
                        raw, inten, p = firing(laser, a, resolution, dc, extra)
                        data.append((raw, inten))
                        if turns == 1 and extra == 0.0 and p is not None:
                            firing_no += 1
                            if firing_no % 97 == 0:
                                complete.append(
                                    {"laser": base + k, "x": p[0], "y": p[1], "z": p[2]}
                                )
                blocks.append((flag, az, data))
        az += STEP_CENTIDEG
        if az >= 36000:
            az -= 36000
            turns += 1
    w = dpkt.pcap.Writer(open(name + ".pcap", "wb"))
    per_packet = 12
    for i in range(0, len(blocks) - per_packet + 1, per_packet):
        payload = b""
        for flag, a, data in blocks[i : i + per_packet]:
            payload += struct.pack("<HH", flag, a)
            for raw, inten in data:
                payload += struct.pack("<HB", raw, inten)
        payload += struct.pack("<I", i * 10)
        payload += bytes([mode, product])
        assert len(payload) == 1206
        udp = dpkt.udp.UDP(sport=2368, dport=2368, data=payload)
        udp.ulen = len(udp)
        ip = dpkt.ip.IP(src=bytes([192, 168, 1, 201]), dst=bytes([255, 255, 255, 255]),
                        p=dpkt.ip.IP_PROTO_UDP, data=udp)
        ip.len = len(ip)
        eth = dpkt.ethernet.Ethernet(src=b"\x60\x76\x88\x00\x00\x01", dst=b"\xff" * 6,
                                     type=dpkt.ethernet.ETH_TYPE_IP, data=ip)
        w.writepkt(bytes(eth), ts=1_600_000_000 + i * 1e-4)
    w.close()
    with open(name + "_points.json", "w") as f:
        json.dump({"model": model, "expected": complete}, f, separators=(",", ":"))


def write_yaml(path, lasers):
    with open(path, "w") as f:
        f.write("# Made-up HDL-64E calibration for tests (ROS driver layout).\n")
        f.write("distance_resolution: 0.002\nlasers:\n")
        for l in lasers:
            f.write("- {" + ", ".join(f"{k}: {str(v).lower() if isinstance(v, bool) else v}"
                                      for k, v in l.items()) + "}\n")
        f.write("num_lasers: 64\n")


def main():
    flat = lambda table: [(e, r, 0.0, 0.0) for e, r in table]
    vlp16 = [(e, 0.0, VLP16_VERTICAL_MM[i] / 1000.0, 0.0) for i, (e, _) in enumerate(VLP16)]
    build("vlp16", "vlp16", vlp16, 0.002, 0x22)
    build("vlp16_dual", "vlp16", vlp16, 0.002, 0x22, mode=0x39, dual=True)
    # laser_ray takes the rot correction: minus the azimuth offset.
    build("vlp32c", "vlp32c", [(e, -off, 0.0, 0.0) for e, off in VLP32C], 0.004, 0x28, mode=0x38)
    build("hdl32e", "hdl32e", flat(HDL32E), 0.002, 0x21)
    cal = hdl64e_calibration()
    write_yaml("hdl64e.yaml", cal)
    lasers = [
        (math.degrees(l["vert_correction"]), math.degrees(l["rot_correction"]),
         l["vert_offset_correction"], l["horiz_offset_correction"])
        for l in cal
    ]
    # The HDL-64E has no product id: status type and value take those bytes.
    build("hdl64e", "hdl64e", lasers, 0.002, 0x00, mode=0x48,
          dist=[l["dist_correction"] for l in cal])


if __name__ == "__main__":
    main()
