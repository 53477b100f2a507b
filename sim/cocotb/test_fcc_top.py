"""cocotb test of the generated `fcc_top` (4-state, Icarus Verilog).

The AXI4-Stream input and output are driven by cocotbext-axi with random
pauses on both sides. The cases, their input beats and the expected labels
and status (from the `fcc` binary, i.e. the golden model) come from the
manifest written by `run_bench.py` (environment variable FCC_MANIFEST).

The toplevel is `fcc_bench_top.v`: the core with its ports passed through and
a checker that looks for X/Z on every output every cycle after reset (rules
in that file); a failure names the signal, the cycle and the value.
"""

import json
import logging
import os
import random

import cocotb
from cocotb.clock import Clock
from cocotb.triggers import ClockCycles, ReadOnly, RisingEdge
from cocotbext.axi import AxiStreamBus, AxiStreamFrame, AxiStreamSink, AxiStreamSource

# Index x_sig of fcc_bench_top.v -> signal.
X_NAMES = [
    "s_axis_tready",
    "m_axis_tvalid",
    "status_frame_done",
    "status_idle",
    "m_axis_tdata",
    "m_axis_tkeep",
    "m_axis_tlast",
    "status_clusters",
    "status_provisional",
    "status_overflow",
    "status_unlabelled",
    "status_frame_error",
    "status_joins",
    "status_gear_stalls",
]
STATUS = X_NAMES[7:]


class BenchError(Exception):
    pass


def pauses(seed, prob):
    """An endless seeded pause pattern: True (pause) with probability `prob`."""
    rng = random.Random(seed)
    while True:
        yield prob > 0.0 and rng.random() < prob


class Monitor:
    """The counters and the X/Z checker of fcc_bench_top.v, and the status
    captured at every status_frame_done pulse."""

    def __init__(self, dut):
        self.dut = dut
        self.done = []

    @property
    def cycle(self):
        return int(self.dut.cycle.value)

    @property
    def in_beats(self):
        return int(self.dut.in_beats.value)

    @property
    def out_beats(self):
        return int(self.dut.out_beats.value)

    @property
    def error(self):
        if int(self.dut.x_fail.value):
            n = X_NAMES[int(self.dut.x_sig.value)]
            return BenchError(f"X/Z on {n} at cycle {int(self.dut.x_cycle.value)} (see the log line above)")
        return None

    async def run(self):
        while True:
            await RisingEdge(self.dut.status_frame_done)
            await ReadOnly()
            self.done.append({n: int(getattr(self.dut, n).value) for n in STATUS})


class Bench:
    def __init__(self, dut, manifest):
        self.dut = dut
        self.m = manifest
        self.rows = manifest["rows"]
        self.cols = manifest["cols"]
        self.lpb = manifest["labels_per_beat"]
        self.mon = Monitor(dut)
        self.source = AxiStreamSource(
            AxiStreamBus.from_prefix(dut, "s_axis"), dut.clk, dut.rst, reset_active_level=True, byte_size=64
        )
        self.sink = AxiStreamSink(AxiStreamBus.from_prefix(dut, "m_axis"), dut.clk, dut.rst, reset_active_level=True)
        # Not every frame's contents in the log.
        self.source.log.setLevel(logging.WARNING)
        self.sink.log.setLevel(logging.WARNING)
        self.joins = {}

    async def reset(self, cycles=4):
        self.dut.rst.value = 1
        await ClockCycles(self.dut.clk, cycles)
        self.dut.rst.value = 0

    async def wait_for(self, cond, limit, what, step=16):
        """Wait until `cond()` holds, checked every `step` cycles; fail on an
        X/Z report or after `limit` cycles."""
        start = self.mon.cycle
        while not cond():
            if self.mon.error is not None:
                raise self.mon.error
            if self.mon.cycle - start > limit:
                raise BenchError(
                    f"{self.m['tag']} {what}: nothing after {limit} cycles (cycle {self.mon.cycle}, "
                    f"{self.mon.in_beats} input beats, {self.mon.out_beats} output beats accepted)"
                )
            await ClockCycles(self.dut.clk, step)
        if self.mon.error is not None:
            raise self.mon.error

    def limit(self):
        return 10 * self.rows * self.cols + (1 << self.m["label_bits"]) + 10_000

    def labels_of(self, frame):
        """Labels of an output frame: little-endian 16-bit slots whose tkeep bytes are set."""
        data = bytes(frame.tdata)
        if len(data) % 2:
            raise BenchError(f"odd byte count {len(data)} in the output frame")
        return [int.from_bytes(data[i : i + 2], "little") for i in range(0, len(data), 2)]

    def compare(self, frame, got, status, case):
        what = f"{self.m['tag']} case '{case['name']}' seed {case['seed']}"
        exp = frame["labels"]
        if len(got) != len(exp):
            raise BenchError(f"{what}: {len(got)} labels out for a frame of {len(exp)} pixels")
        for i, (e, g) in enumerate(zip(exp, got)):
            if e != g:
                bad = sum(1 for a, b in zip(exp, got) if a != b)
                raise BenchError(
                    f"{what}: first mismatch at row {i // self.cols} col {i % self.cols}: "
                    f"expected {e} != got {g} ({bad} pixels differ)"
                )
        want = {
            "status_clusters": frame["clusters"],
            "status_provisional": frame["provisional"],
            "status_overflow": int(frame["overflow"]),
            "status_unlabelled": frame["unlabelled"],
            "status_frame_error": int(case["tlast"] != "normal"),
        }
        for n, e in want.items():
            if status[n] != e:
                raise BenchError(f"{what}: {n}: expected {e} != got {status[n]}")

    async def run_frames(self, case, frames):
        """Send `frames` back to back and check each against the golden model."""
        self.source.set_pause_generator(pauses(case["seed"], case["gap"]))
        self.sink.set_pause_generator(pauses(case["seed"] + 1, case["backpressure"]))
        ndone = len(self.mon.done)
        for f in frames:
            await self.source.send(AxiStreamFrame(tdata=f["beats"]))
        for k, f in enumerate(frames):
            got_frame = None

            async def recv():
                nonlocal got_frame
                got_frame = await self.sink.recv()

            task = cocotb.start_soon(recv())
            await self.wait_for(lambda: task.done(), self.limit(), f"case '{case['name']}' output frame {k}")
            await self.wait_for(
                lambda: len(self.mon.done) > ndone + k, 16, f"case '{case['name']}' status_frame_done {k}", step=1
            )
            status = self.mon.done[ndone + k]
            self.compare(f, self.labels_of(got_frame), status, case)
            self.joins.setdefault(f["name"], status["status_joins"])
        return status

    async def reset_mid_frame(self, case, frame):
        """Feed part of `frame`, reset, then run the whole frame: its labels and
        its `status_joins` must be those of a clean run of the same frame."""
        self.source.set_pause_generator(pauses(case["seed"], case["gap"]))
        self.sink.set_pause_generator(None)
        start = self.mon.in_beats
        await self.source.send(AxiStreamFrame(tdata=frame["beats"]))
        await self.wait_for(
            lambda: self.mon.in_beats - start >= case["reset_after"], self.limit(), f"case '{case['name']}' partial feed"
        )
        await self.reset(3)
        await self.wait_for(lambda: self.source.idle(), 64, "source flushed by reset", step=1)
        self.sink.clear()
        status = await self.run_frames(case, [frame])
        clean = self.joins.get(frame["name"])
        if clean is not None and status["status_joins"] != clean:
            raise BenchError(
                f"{self.m['tag']} case '{case['name']}': status_joins after a reset in the middle of a frame "
                f"{status['status_joins']} != {clean} of a clean run of the same frame"
            )


@cocotb.test()
async def fcc_top_against_golden(dut):
    with open(os.environ["FCC_MANIFEST"]) as fh:
        manifest = json.load(fh)
    frames = {f["name"]: f for f in manifest["frames"]}
    cocotb.start_soon(Clock(dut.clk, 10, unit="ns").start())
    dut.m_axis_tready.value = 0
    dut.s_axis_tvalid.value = 0
    bench = Bench(dut, manifest)
    cocotb.start_soon(bench.mon.run())
    await bench.reset(4)
    for case in manifest["cases"]:
        c0 = bench.mon.cycle
        if case["kind"] == "frames":
            await bench.run_frames(case, [frames[n] for n in case["frames"]])
        elif case["kind"] == "reset_mid_frame":
            await bench.reset_mid_frame(case, frames[case["frames"][0]])
        else:
            raise BenchError(f"unknown case kind {case['kind']}")
        dut._log.info("%s case '%s': pass (%d cycles)", manifest["tag"], case["name"], bench.mon.cycle - c0)
    # Idle tail: outputs must stay defined while nothing happens.
    await ClockCycles(dut.clk, 32)
    await bench.wait_for(lambda: True, 0, "idle tail")
    dut._log.info("%s: %d cases, %d cycles", manifest["tag"], len(manifest["cases"]), bench.mon.cycle)
