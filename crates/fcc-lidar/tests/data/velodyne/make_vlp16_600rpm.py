#!/usr/bin/env python3
"""Write `vlp16_600rpm.pcap`: a VLP-16 at 600 rpm whose block azimuths fall
on multiples of 0.2 degrees, as a real unit often sends them.

Written from the VLP-16 user manual's packet format only (no code of fcc,
no capture library): a data packet is a 1206-byte UDP payload to port 2368,
12 blocks of 100 bytes (flag 0xFFEE, azimuth in hundredths of a degree,
then two firing sequences of 16 lasers, each a 2-byte distance in 2 mm
units and a 1-byte reflectivity), a 4-byte timestamp in microseconds past
the hour, the return mode (0x37, strongest) and the product id (0x22).
A firing sequence lasts 55.296 us and laser k fires 2.304 * k us into it;
a block holds two sequences, so at 600 rpm a turn is 900 blocks of 0.4
degrees, 1800 firing sequences of 0.2 degrees: the block azimuths are
multiples of 0.4 degrees and the second sequences, half a block later,
multiples of 0.2, every one of them on a column edge of an 1800-column
image. The pcap, Ethernet, IPv4 and UDP layers are written with `struct`.

Each firing is ray-cast at the azimuth of its firing time against a small
scene: the sensor 1.5 m above a ground disc of radius 20 m, a box (x 5..7 m,
y -1..1 m, up to 0.3 m), a pole (radius 0.15 m at x -4 m, y 3 m) and a wall
(y = -8 m, x -6..6 m, up to 1 m); rays that miss everything within 30 m give
no return (distance 0). Lasers use the manual's elevations and vertical
offsets of the laser origins. Reflectivity tells the surface apart: ground
10, wall 50, pole 120, box 200.

The capture starts at 359.2 degrees and holds one complete turn between two
partial ones (77 packets). Beside it, `vlp16_600rpm.json` gives the returns
of the complete turn.

Run from this folder (python3 only):  python3 make_vlp16_600rpm.py
"""

import json
import math
import struct

HEIGHT = 1.5
BOX = ((5.0, 7.0), (-1.0, 1.0), (-HEIGHT, 0.3))
POLE = (-4.0, 3.0, 0.15)
WALL_Y, WALL_X, WALL_TOP = -8.0, (-6.0, 6.0), 1.0
GROUND_RADIUS = 20.0
MAX_RANGE = 30.0
BLOCK_STEP = 40  # hundredths of a degree: 900 blocks per turn
START = 35920
BLOCKS = 12
PACKETS = 77
SEQ_US, LASER_US = 55.296, 2.304
VERTICAL_MM = [11.2, -0.7, 9.7, -2.2, 8.1, -3.7, 6.6, -5.1, 5.1, -6.6, 3.7, -8.1, 2.2, -9.7, 0.7, -11.2]
ELEVATION = [-15 + k if k % 2 == 0 else k for k in range(16)]


def ray(k, az_deg):
    """Origin, unit direction and point-at-distance of laser k at azimuth
    az (degrees clockwise from forward), x forward, y left, z up."""
    a, w, vo = math.radians(az_deg), math.radians(ELEVATION[k]), VERTICAL_MM[k] / 1000.0

    def at(r):
        h = r * math.cos(w) - vo * math.sin(w)
        return (h * math.cos(a), -h * math.sin(a), r * math.sin(w) + vo * math.cos(w))

    o, p = at(0.0), at(1.0)
    return o, tuple(q - s for q, s in zip(p, o))


def cast(o, d):
    """Distance along d to the scene and the surface's reflectivity."""
    hits = []
    if d[2] < 0:
        t = (-HEIGHT - o[2]) / d[2]
        if math.hypot(o[0] + t * d[0], o[1] + t * d[1]) <= GROUND_RADIUS:
            hits.append((t, 10))
    if d[1] != 0:
        t = (WALL_Y - o[1]) / d[1]
        x, z = o[0] + t * d[0], o[2] + t * d[2]
        if t > 0 and WALL_X[0] <= x <= WALL_X[1] and -HEIGHT <= z <= WALL_TOP:
            hits.append((t, 50))
    # Pole: a vertical cylinder.
    px, py, pr = POLE
    a = d[0] ** 2 + d[1] ** 2
    b = 2 * ((o[0] - px) * d[0] + (o[1] - py) * d[1])
    c = (o[0] - px) ** 2 + (o[1] - py) ** 2 - pr ** 2
    disc = b * b - 4 * a * c
    if a > 0 and disc >= 0:
        t = (-b - math.sqrt(disc)) / (2 * a)
        if t > 0 and o[2] + t * d[2] >= -HEIGHT:
            hits.append((t, 120))
    # Box: slab test.
    t0, t1 = -math.inf, math.inf
    for oo, v, (lo, hi) in zip(o, d, BOX):
        if abs(v) < 1e-12:
            if not lo <= oo <= hi:
                t0, t1 = math.inf, -math.inf
            continue
        u, w = (lo - oo) / v, (hi - oo) / v
        t0, t1 = max(t0, min(u, w)), min(t1, max(u, w))
    if t0 <= t1 and t0 > 0:
        hits.append((t0, 200))
    hits = [h for h in hits if h[0] <= MAX_RANGE]
    return min(hits) if hits else (0.0, 0)


def ip_checksum(h):
    s = sum(struct.unpack("!10H", h))
    while s > 0xFFFF:
        s = (s & 0xFFFF) + (s >> 16)
    return ~s & 0xFFFF


def frame(payload, ident):
    udp = struct.pack("!HHHH", 2368, 2368, 8 + len(payload), 0) + payload
    ip = struct.pack("!BBHHHBBH4s4s", 0x45, 0, 20 + len(udp), ident, 0, 64, 17, 0,
                     bytes([192, 168, 1, 201]), bytes([255, 255, 255, 255]))
    ip = ip[:10] + struct.pack("!H", ip_checksum(ip)) + ip[12:]
    eth = b"\xff" * 6 + b"\x60\x76\x88\x00\x00\x01" + struct.pack("!H", 0x0800)
    return eth + ip + udp


def main():
    out = [struct.pack("<IHHiIII", 0xA1B2C3D4, 2, 4, 0, 0, 65535, 1)]
    az, turns, returns = START, 0, 0
    t_us = 0.0
    for n in range(PACKETS):
        payload = b""
        stamp = int(t_us)
        for _ in range(BLOCKS):
            payload += struct.pack("<HH", 0xEEFF, az)
            for s in range(2):
                for k in range(16):
                    frac = (s * SEQ_US + k * LASER_US) / (2 * SEQ_US)
                    o, d = ray(k, (az + BLOCK_STEP * frac) / 100.0)
                    t, refl = cast(o, d)
                    raw = int(round(t / 0.002))
                    if raw == 0:
                        refl = 0
                    elif turns == 1:
                        returns += 1
                    payload += struct.pack("<HB", raw, refl)
            t_us += 2 * SEQ_US
            az += BLOCK_STEP
            if az >= 36000:
                az -= 36000
                turns += 1
        payload += struct.pack("<I", stamp) + bytes([0x37, 0x22])
        assert len(payload) == 1206
        pkt = frame(payload, n + 1)
        sec, usec = 1_600_000_000 + stamp // 1_000_000, stamp % 1_000_000
        out.append(struct.pack("<IIII", sec, usec, len(pkt), len(pkt)) + pkt)
    assert turns == 2, turns
    with open("vlp16_600rpm.pcap", "wb") as f:
        f.write(b"".join(out))
    with open("vlp16_600rpm.json", "w") as f:
        json.dump(
            {
                "model": "vlp16",
                "rpm": 600,
                "sequences_per_turn": 1800,
                "block_azimuths": "multiples of 0.4 degrees, the second sequences multiples of 0.2",
                "returns_in_complete_turn": returns,
            },
            f,
            indent=1,
        )
        f.write("\n")


if __name__ == "__main__":
    main()
