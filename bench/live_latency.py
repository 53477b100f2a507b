#!/usr/bin/env python3
"""Latency and CPU of `fcc live` on the loopback (docs/live.md).

A benchmark, not a test: each capture is replayed at its recorded rate
(`fcc replay --rate 1 --repeat N`, 10 Hz) to `fcc live --latency` on
127.0.0.1, and the table gives, per capture and setting:

- the time from receiving the packet that held a cluster's last column to
  writing its record (p50 / p99 / max, ms; `fcc live --latency`);
- the time from the packet that completed a frame to its last record;
- the CPU of `fcc live` (user + system, from the kernel's accounting of the
  finished process) over the replay's duration: the share of one core.

Captures: the four Ouster sample captures, the 600 rpm VLP-16 fixture, and
a 64 x 2048 capture made here from the OS-2-128 one (every other beam, each
column twice, ranges from `fcc convert`'s points, written as LEGACY packets
of an OS-1-64 in 2048x10 mode with no beam azimuth offsets, so that its
image columns complete as their packets arrive): the sample set has no
2048-column capture.

    python3 bench/live_latency.py --fcc target/release/fcc [--repeat 20] [--json out.json]

Two builds compared (the machine's speed drifts, so the CPU of one run says
little against another run's): `--against OTHER_FCC --pairs N` runs each
case (or those whose capture name contains `--only TEXT`) N times with
both builds, the order alternating, and prints the CPU of each and the
median ratio, `--fcc`'s over `--against`'s.

Needs numpy (the `.venv` of ./setup.sh has it). Ports: 127.0.0.1, from
27502 up. Every child is bounded in time.
"""

import argparse
import json
import os
import re
import struct
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "crates", "fcc-lidar", "tests", "data")
OUSTER = [
    ("OS-0-128", "OS-0-128-U1_v2.3.0_1024x10.pcap", "OS-0-128-U1_v2.3.0_1024x10.json"),
    ("OS-1-32", "OS-1-32-G_v2.1.1_1024x10.pcap", "OS-1-32-G_v2.1.1_1024x10.json"),
    ("OS-1-64", "OS-1-64_1024x10_fw20.pcap", "OS-1-64_sensor_config_reduced.json"),
    ("OS-2-128", "OS-2-128-U1_v2.3.0_1024x10.pcap", "OS-2-128-U1_v2.3.0_1024x10.json"),
]
LIMIT_S = 300
# The low-latency setting: no join across the image's seam, runs bridge at
# most 16 empty columns (docs/live.md).
LOW_ARGS = ["--ring-reach", "0", "--bridge", "16"]
LOW = "sweep, " + " ".join(LOW_ARGS)


def pcap_writer(path):
    """A classic pcap of UDP/IPv4 datagrams (Ethernet, microseconds)."""
    f = open(path, "wb")
    f.write(struct.pack("<IHHiIII", 0xA1B2C3D4, 2, 4, 0, 0, 65535, 1))

    def write(t_us, payload, dport=7502):
        udp = struct.pack(">HHHH", 7502, dport, len(payload) + 8, 0) + payload
        ip = struct.pack(">BBHHHBBH4s4s", 0x45, 0, 20 + len(udp), 1, 0, 64, 17, 0,
                         bytes([192, 168, 1, 2]), bytes([192, 168, 1, 1]))
        frame = b"\xff" * 6 + b"\x02" * 6 + b"\x08\x00" + ip + udp
        f.write(struct.pack("<IIII", t_us // 1_000_000, t_us % 1_000_000, len(frame), len(frame)))
        f.write(frame)

    return f, write


def make_64x2048(fcc, tmp):
    """The 64 x 2048 capture and its metadata, from the OS-2-128 capture."""
    import numpy as np

    pcap, meta = OUSTER[3][1], OUSTER[3][2]
    npy = os.path.join(tmp, "os2.npy")
    run([fcc, "convert", "-i", os.path.join(DATA, pcap), "--meta", os.path.join(DATA, meta),
         "-o", npy])
    xyz = np.load(npy)  # (128, 1024, 3), NaN = empty
    rng = np.sqrt((xyz.astype(np.float64) ** 2).sum(axis=2))
    mm = np.where(np.isfinite(rng), np.round(rng * 1000.0), 0).astype(np.uint32)
    mm = np.repeat(mm[::2, :], 2, axis=1)  # (64, 2048)
    src = json.load(open(os.path.join(DATA, meta)))
    m = {
        "prod_line": "OS-1-64",
        "lidar_mode": "2048x10",
        "beam_altitude_angles": src["beam_altitude_angles"][::2],
        "beam_azimuth_angles": [0.0] * 64,
        "lidar_origin_to_beam_origin_mm": src["lidar_origin_to_beam_origin_mm"],
        "lidar_to_sensor_transform": src["lidar_to_sensor_transform"],
        "udp_port_lidar": 7502,
    }
    meta_out = os.path.join(tmp, "os1-64_2048x10.json")
    json.dump(m, open(meta_out, "w"))
    pcap_out = os.path.join(tmp, "os1-64_2048x10.pcap")
    f, write = pcap_writer(pcap_out)
    beams, cols, per_packet = 64, 2048, 16
    for first in range(0, cols, per_packet):
        p = bytearray()
        for v in range(first, first + per_packet):
            t_ns = v * 100_000_000 // cols
            p += struct.pack("<QHHI", t_ns, v, 1, 0)
            for u in range(beams):
                p += struct.pack("<IHHHH", int(mm[u, v]), 100, 0, 0, 0)
            p += struct.pack("<I", 0xFFFFFFFF)
        write(1_000_000 + first * 100_000 // cols, bytes(p))
    f.close()
    return pcap_out, meta_out


def run(cmd):
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=LIMIT_S)
    if r.returncode != 0:
        sys.exit(f"{' '.join(cmd)}: {r.stderr.strip()}")
    return r


def latency(err, what):
    m = re.search(what + r": p50 ([\d.]+) ms, p99 ([\d.]+) ms, max ([\d.]+) ms", err)
    return [float(m.group(k)) for k in (1, 2, 3)] if m else None


def measure(fcc, capture, sensor, repeat, port, extra):
    live = [fcc, "live", "--udp", f"127.0.0.1:{port}", "--latency", "--idle-timeout", "1"]
    live += sensor + extra
    with tempfile.NamedTemporaryFile("w", suffix=".err", delete=False) as err, \
            open(os.devnull, "w") as out:
        err_path = err.name
        p = subprocess.Popen(live, stdout=out, stderr=err)
    deadline = time.time() + 30
    while "listening" not in open(err_path).read():
        if time.time() > deadline or p.poll() is not None:
            p.kill()
            sys.exit(f"{' '.join(live)}: did not start: {open(err_path).read()}")
        time.sleep(0.05)
    replay = [fcc, "replay", capture, "--udp", f"127.0.0.1:{port}", "--rate", "1",
              "--repeat", str(repeat)]
    if sensor[0] == "--meta":
        replay += ["--meta", sensor[1]]
    start = time.time()
    run(replay)
    span = time.time() - start
    deadline = time.time() + LIMIT_S
    while True:
        pid, status, ru = os.wait4(p.pid, os.WNOHANG)
        if pid:
            break
        if time.time() > deadline:
            p.kill()
            sys.exit(f"{' '.join(live)}: did not end")
        time.sleep(0.05)
    p.returncode = os.waitstatus_to_exitcode(status)
    err = open(err_path).read()
    os.unlink(err_path)
    if p.returncode != 0:
        sys.exit(f"{' '.join(live)}: exit {p.returncode}: {err}")
    return {
        "record_ms": latency(err, "to its record written"),
        "frame_ms": latency(err, "to its records written"),
        "cpu": (ru.ru_utime + ru.ru_stime) / span,
        "summary": next((l for l in err.splitlines() if l.startswith("live:")), ""),
    }


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--fcc", default="target/release/fcc")
    ap.add_argument("--repeat", type=int, default=20, help="passes of each capture (10 Hz)")
    ap.add_argument("--json", help="write the rows here as well")
    ap.add_argument("--against", help="a second fcc build: the CPU of the two in pairs")
    ap.add_argument("--pairs", type=int, default=8, help="pairs per case with --against")
    ap.add_argument("--only", default="", help="only the captures whose name contains this")
    a = ap.parse_args()
    with tempfile.TemporaryDirectory(prefix="fcc-live-bench-") as tmp:
        if a.against:
            run_pairs(a, tmp)
        else:
            run_cases(a, tmp)


def run_pairs(a, tmp):
    print("| capture | setting | CPU, --fcc (each pair) | CPU, --against | median ratio |")
    print("|---|---|---|---|--:|")
    for k, (name, _, label, capture, sensor, extra) in enumerate(cases_of(a, tmp)):
        if a.only not in name:
            continue
        mine, theirs = [], []
        for n in range(a.pairs):
            order = [(a.fcc, mine), (a.against, theirs)]
            for fcc, out in order if n % 2 == 0 else order[::-1]:
                out.append(measure(fcc, capture, sensor, a.repeat, 28502 + k, extra)["cpu"])
        ratios = sorted(x / y for x, y in zip(mine, theirs))
        median = (ratios[(len(ratios) - 1) // 2] + ratios[len(ratios) // 2]) / 2
        fmt = lambda v: " ".join(f"{x:.2f}" for x in v)
        print(f"| {name} | {label} | {fmt(mine)} | {fmt(theirs)} | {median:.3f} |", flush=True)


def cases_of(a, tmp):
    """(capture name, frame, setting, capture file, sensor options, live options) per case."""
    cases = []
    for name, pcap, meta in OUSTER:
        frame = {"OS-1-32": "32 x 1024", "OS-1-64": "64 x 1024"}.get(name, "128 x 1024")
        sensor = ["--meta", os.path.join(DATA, meta)]
        for label, extra in [
            ("sweep", ["--image-origin", "sweep"]),
            (LOW, ["--image-origin", "sweep"] + LOW_ARGS),
        ]:
            cases.append((name, frame, label, os.path.join(DATA, pcap), sensor,
                          ["--ground", "none"] + extra))
    pcap, meta = make_64x2048(a.fcc, tmp)
    for label, extra in [("sweep", []), (LOW, LOW_ARGS)]:
        cases.append(("OS-2-128 as 64 x 2048", "64 x 2048", label, pcap, ["--meta", meta],
                      ["--ground", "none", "--image-origin", "sweep"] + extra))
    vlp = os.path.join(DATA, "velodyne", "vlp16_600rpm.pcap")
    cases.append(("VLP-16, 600 rpm", "16 x 1800", "column (rotation end)", vlp,
                  ["--sensor", "velodyne"], ["--ground", "none"]))
    return cases


def run_cases(a, tmp):
    cases = cases_of(a, tmp)
    rows = []
    print("| capture | frame | setting | last column to record: p50 / p99 / max (ms) "
          "| completing packet to last record: p50 / p99 / max (ms) | CPU (share of one core) |")
    print("|---|---|---|---|---|--:|")
    fmt = lambda v: " / ".join(f"{x:.2f}" for x in v) if v else "-"
    for k, (name, frame, label, capture, sensor, extra) in enumerate(cases):
        r = measure(a.fcc, capture, sensor, a.repeat, 27502 + k, extra)
        rows.append({"capture": name, "frame": frame, "setting": label, **r})
        print(f"| {name} | {frame} | {label} | {fmt(r['record_ms'])} | {fmt(r['frame_ms'])} "
              f"| {r['cpu']:.2f} |", flush=True)
    if a.json:
        json.dump(rows, open(a.json, "w"), indent=1)


if __name__ == "__main__":
    main()
