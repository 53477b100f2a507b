#!/usr/bin/env python3
"""Decode a Velodyne capture into range images, independently of fcc.

Written from the user manuals' data packet format and the range-image rules
of docs/lidar.md (Velodyne captures: geometry, range image, rotations,
return modes), sharing no code with fcc, with the standard library only.
The tests of fcc-lidar run it on the Velodyne fixtures and on captures they
build, and compare fcc's range images with these pixel by pixel.

    python3 decode_images.py CAPTURE [--calibration FILE] [--return first|second] [--keep-incomplete]

CAPTURE is a classic pcap of Ethernet (or raw IP) frames; FILE is a ROS
driver calibration YAML (required for the HDL-64E). For every complete
rotation (cut at azimuth wraps, without gaps) it prints `rotation ROWS COLS`, then `ROW COL X Y Z` (metres, x
forward, y left, z up) for every pixel holding a return, then `end`;
with --keep-incomplete the partial rotations too.
"""

import math
import struct
import sys

# Laser tables of the manuals: (elevation deg, rot_correction deg, vertical offset m).
VLP16 = [(-15 + k if k % 2 == 0 else k, 0.0, v / 1000.0) for k, v in enumerate(
    [11.2, -0.7, 9.7, -2.2, 8.1, -3.7, 6.6, -5.1, 5.1, -6.6, 3.7, -8.1, 2.2, -9.7, 0.7, -11.2])]
HDL32E = [(round((-92 + 4 * (k // 2) if k % 2 == 0 else -28 + 4 * (k // 2)) / 3.0, 2), 0.0, 0.0)
          for k in range(32)]
# VLP-32C: elevation and azimuth offset; a laser points at the block azimuth
# plus its offset, so rot_correction is minus the offset.
VLP32C = [(e, -off, 0.0) for e, off in [
    (-25.0, 1.4), (-1.0, -4.2), (-1.667, 1.4), (-15.639, -1.4), (-11.31, 1.4), (0.0, -1.4),
    (-0.667, 4.2), (-8.843, -1.4), (-7.254, 1.4), (0.333, -4.2), (-0.333, 1.4), (-6.148, -1.4),
    (-5.333, 4.2), (1.333, -1.4), (0.667, 4.2), (-4.0, -1.4), (-4.667, 1.4), (1.667, -4.2),
    (1.0, 1.4), (-3.667, -4.2), (-3.333, 4.2), (3.333, -1.4), (2.333, 1.4), (-2.667, -1.4),
    (-3.0, 1.4), (7.0, -1.4), (4.667, 1.4), (-2.333, -4.2), (-2.0, 4.2), (15.0, -1.4),
    (10.333, 1.4), (-1.333, -1.4)]]
PRODUCT = {0x22: "vlp16", 0x28: "vlp32c", 0x21: "hdl32e"}


def firing_time(model, k):
    """Microseconds from the start of a firing sequence to slot k, and the sequence length."""
    if model == "vlp16":
        return 2.304 * k, 55.296
    if model == "vlp32c":
        return 2.304 * (k // 2), 55.296
    if model == "hdl32e":
        return 1.152 * k, 46.08
    return 6.0 * (k // 4) + (0.0, 1.26, 2.46, 3.66)[k % 4], 48.0


class Laser:
    def __init__(self, elev_rad, rot_rad, vert=0.0, horiz=0.0, dist=0.0, dx=0.0, dy=0.0, two=False):
        self.elev, self.rot, self.vert, self.horiz = elev_rad, rot_rad, vert, horiz
        self.dist, self.dx, self.dy, self.two = dist, dx, dy, two


def nominal(model):
    table = {"vlp16": VLP16, "vlp32c": VLP32C, "hdl32e": HDL32E}[model]
    return [Laser(math.radians(e), math.radians(r), v) for e, r, v in table], (
        0.004 if model == "vlp32c" else 0.002)


def read_yaml(path):
    """The ROS driver's calibration: `lasers:` items of `key: value` pairs (flow or block style)."""
    items, resolution = [], 0.002
    for raw in open(path):
        line = raw.split("#")[0].rstrip()
        if not line.strip():
            continue
        text = line.strip()
        if text.startswith("-"):
            items.append(text[1:])
        elif line[0] in " \t" and items:
            items[-1] += "," + text
        elif text.startswith("distance_resolution:"):
            resolution = float(text.split(":", 1)[1])
    lasers = {}
    for body in items:
        f = {}
        for pair in body.replace("{", ",").replace("}", ",").split(","):
            if ":" in pair:
                k, v = pair.split(":", 1)
                f[k.strip()] = v.strip()
        num = lambda k: float(f.get(k, 0.0))
        two = f.get("two_pt_correction_available", "false").lower() == "true"
        lasers[int(f["laser_id"])] = Laser(num("vert_correction"), num("rot_correction"),
                                           num("vert_offset_correction"), num("horiz_offset_correction"),
                                           num("dist_correction"), num("dist_correction_x"),
                                           num("dist_correction_y"), two)
    return lasers, resolution


def udp_payloads(path):
    data = open(path, "rb").read()
    magic = data[:4]
    if magic in (b"\xd4\xc3\xb2\xa1", b"\x4d\x3c\xb2\xa1"):
        end = "<"
    elif magic in (b"\xa1\xb2\xc3\xd4", b"\xa1\xb2\x3c\x4d"):
        end = ">"
    else:
        sys.exit(f"{path}: not a classic pcap")
    link = struct.unpack(end + "I", data[20:24])[0] & 0x0FFFFFFF
    at = 24
    while at + 16 <= len(data):
        _, _, incl, _ = struct.unpack(end + "IIII", data[at:at + 16])
        frame = data[at + 16:at + 16 + incl]
        at += 16 + incl
        if len(frame) < incl:
            break
        if link == 1:
            kind, off = struct.unpack("!H", frame[12:14])[0], 14
            while kind in (0x8100, 0x88A8):
                kind, off = struct.unpack("!H", frame[off + 2:off + 4])[0], off + 4
            if kind != 0x0800:
                continue
            ip = frame[off:]
        else:
            ip = frame
        if len(ip) < 20 or ip[0] >> 4 != 4 or ip[9] != 17:
            continue
        if struct.unpack("!H", ip[6:8])[0] & 0x3FFF:
            continue  # fragments: not in these captures
        ihl = (ip[0] & 15) * 4
        length = struct.unpack("!H", ip[ihl + 4:ihl + 6])[0]
        yield ip[ihl + 8:ihl + length]


def point(l, azimuth_centideg, count, resolution):
    """x forward, y left, z up (docs/lidar.md, geometry)."""
    beta = math.radians(azimuth_centideg / 100.0 - math.degrees(l.rot))
    sb, cb = math.sin(beta), math.cos(beta)
    sw, cw = math.sin(l.elev), math.cos(l.elev)
    r = count * resolution + l.dist
    rx = ry = r
    if l.two:
        h = r * cw - l.vert * sw
        ax, ay = abs(h * sb - l.horiz * cb), abs(h * cb + l.horiz * sb)
        rx = r + (l.dist - l.dx) * (ax - 2.4) / (25.04 - 2.4) + l.dx - l.dist
        ry = r + (l.dist - l.dy) * (ay - 1.93) / (25.04 - 1.93) + l.dy - l.dist
    xr = (rx * cw - l.vert * sw) * sb - l.horiz * cb
    yf = (ry * cw - l.vert * sw) * cb + l.horiz * sb
    return yf, -xr, ry * sw + l.vert * cw


class Rotation:
    def __init__(self, at_wrap):
        self.at_wrap, self.gap = at_wrap, False
        self.blocks = []  # (position, sequences [(azimuth, [(laser, count, intensity)])])
        self.sequences = 0
        self.first_seq_az = self.last_seq_az = None  # first and last firing sequence's azimuth
        self.first = self.last = None  # (azimuth, position) of the first and latest block used
        self.bank_last = {}


def decode(path, calibration, want):
    model = lasers = resolution = None
    rotations, current, prev_az = [], Rotation(False), None
    for p in udp_payloads(path):
        if len(p) != 1206:
            continue
        blocks = []
        for b in range(12):
            flag, az = struct.unpack("<HH", p[100 * b:100 * b + 4])
            blocks.append((flag, az, p[100 * b + 4:100 * b + 100]))
        if any(f not in (0xEEFF, 0xDDFF) or a >= 36000 for f, a, _ in blocks):
            continue
        lower_seen = any(f == 0xDDFF for f, _, _ in blocks)
        if model is None:
            model = "hdl64e" if lower_seen else PRODUCT[p[1205]]
            if calibration:
                table, resolution = read_yaml(calibration)
                lasers = [table[i] for i in range(64 if model == "hdl64e" else len(nominal(model)[0]))]
            else:
                lasers, resolution = nominal(model)
        if model != "hdl64e" and (lower_seen or PRODUCT.get(p[1205], model) != model):
            continue
        distinct = []
        for _, a, _ in blocks:
            if a not in distinct:
                distinct.append(a)
        step = (distinct[-1] - distinct[0]) % 36000 / (len(distinct) - 1) if len(distinct) > 1 else 0.0
        seqs = 2 if model == "vlp16" else 1
        seen = []
        for flag, az, body in blocks:
            key = (flag, az)
            nth = seen.count(key)
            seen.append(key)
            pair = sum(1 for f, a, _ in blocks if (f, a) == key) > 1
            if nth != (want if pair else 0):
                continue
            if prev_az is not None:
                if az < prev_az and prev_az - az > 18000:
                    rotations.append((current, True))
                    current = Rotation(True)
                elif az - prev_az > max(200.0, 3 * step):
                    current.gap = True
            prev_az = az
            # Block position: steps since the latest block, at least one past
            # the latest block of the same bank.
            lower = flag == 0xDDFF
            if current.last is None:
                pos = 0
            else:
                advance = math.floor((az - current.last[0]) / step + 0.5) if step > 0 else 0
                pos = max(0, current.last[1] + advance)
            if lower in current.bank_last:
                pos = max(pos, current.bank_last[lower] + 1)
            current.bank_last[lower] = pos
            if current.first is None:
                current.first = (az, pos)
            current.last = (az, pos)
            if not lower:
                current.sequences += seqs
                if current.first_seq_az is None:
                    current.first_seq_az = az
                current.last_seq_az = az + step / seqs * (seqs - 1)
            seq_list = []
            for s in range(seqs):
                seq_az = az + step / seqs * s
                fired = []
                for k in range(32 // seqs):
                    slot = s * (32 // seqs) + k
                    count, inten = struct.unpack("<HB", body[3 * slot:3 * slot + 3])
                    if count:
                        t, period = firing_time(model, k)
                        fired.append((k + (32 if lower else 0), seq_az + step / seqs * t / period,
                                      count, inten))
                seq_list.append(fired)
            current.blocks.append((pos, seq_list))
    rotations.append((current, False))
    return model, lasers, resolution, rotations


def main():
    args = sys.argv[1:]
    capture, calibration, want = args[0], None, 0
    keep_incomplete = "--keep-incomplete" in args
    if "--calibration" in args:
        calibration = args[args.index("--calibration") + 1]
    if "--return" in args:
        want = {"first": 0, "second": 1}[args[args.index("--return") + 1]]
    model, lasers, resolution, rotations = decode(capture, calibration, want)
    seqs = 2 if model == "vlp16" else 1
    order = sorted(range(len(lasers)), key=lambda i: -lasers[i].elev)
    row_of = {laser: row for row, laser in enumerate(order)}
    cols = None
    out = []
    for rot, ended_at_wrap in rotations:
        complete = rot.at_wrap and ended_at_wrap and not rot.gap
        if rot.sequences == 0 or not (complete or keep_incomplete):
            continue
        if cols is None:
            if complete:
                n = rot.sequences
            else:
                span = (rot.last_seq_az - rot.first_seq_az) % 36000.0
                n = math.floor((rot.sequences - 1) * 36000.0 / max(span, 1.0) + 0.5)
            cols = min(max(n, 2), 1 << 14)
        # Columns: the first firing sequence's column by its azimuth, then
        # round(j * num / den) columns on for the sequence at position j.
        (a0, _), (a1, p1) = rot.first, rot.last
        if complete:
            num, den = cols, seqs * (p1 + 1)
        elif p1 > 0 and a1 > a0:
            num, den = cols * (a1 - a0), 36000 * seqs * p1
        else:
            num, den = 1, 1
        c0 = (a0 + 18000) * cols // 36000
        shift = [math.floor(-math.degrees(l.rot) * cols / 360.0 + 0.5) for l in lasers]
        best = {}
        for pos, seq_list in rot.blocks:
            for s, fired in enumerate(seq_list):
                j = seqs * pos + s
                col = (c0 + (2 * j * num + den) // (2 * den)) % cols
                for laser, az, count, _ in fired:
                    p = point(lasers[laser], az, count, resolution)
                    rng = math.sqrt(p[0] ** 2 + p[1] ** 2 + p[2] ** 2)
                    key = (row_of[laser], (col + shift[laser]) % cols)
                    if key not in best or rng < best[key][0]:
                        best[key] = (rng, p)
        out.append(f"rotation {len(lasers)} {cols}")
        for (row, col) in sorted(best):
            x, y, z = best[(row, col)][1]
            out.append(f"{row} {col} {x:.7f} {y:.7f} {z:.7f}")
        out.append("end")
    sys.stdout.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
