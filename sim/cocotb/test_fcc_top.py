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
from cocotbext.axi import (
    AxiLiteBus,
    AxiLiteMaster,
    AxiStreamBus,
    AxiStreamFrame,
    AxiStreamSink,
    AxiStreamSource,
)

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
    "s_axil_awready",
    "s_axil_wready",
    "s_axil_bvalid",
    "s_axil_arready",
    "s_axil_rvalid",
    "irq",
    "s_axil_bresp",
    "s_axil_rdata",
    "s_axil_rresp",
]
STATUS = X_NAMES[7:14]


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
        self.axil = AxiLiteMaster(
            AxiLiteBus.from_prefix(dut, "s_axil"), dut.clk, dut.rst, reset_active_level=True
        )
        # Not every frame's contents (or register access) in the log.
        self.source.log.setLevel(logging.WARNING)
        self.sink.log.setLevel(logging.WARNING)
        self.axil.write_if.log.setLevel(logging.WARNING)
        self.axil.read_if.log.setLevel(logging.WARNING)
        self.regs = {r["name"]: r for r in manifest["registers"]}
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

    def compare(self, frame, got, status, case, cols=None):
        cols = cols or self.cols
        what = f"{self.m['tag']} case '{case['name']}' seed {case['seed']}"
        exp = frame["labels"]
        if len(got) != len(exp):
            raise BenchError(f"{what}: {len(got)} labels out for a frame of {len(exp)} pixels")
        for i, (e, g) in enumerate(zip(exp, got)):
            if e != g:
                bad = sum(1 for a, b in zip(exp, got) if a != b)
                raise BenchError(
                    f"{what}: first mismatch at row {i // cols} col {i % cols}: "
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

    async def run_frames(self, case, frames, cols=None):
        """Send `frames` back to back and check each against the golden model
        (`cols`: the run's columns when RUN_COLS is not the build's)."""
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
            self.compare(f, self.labels_of(got_frame), status, case, cols or f["cols"])
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

    def field(self, reg, name):
        """(shift, mask) of field `name` of register `reg` (from the build's map)."""
        f = next(f for f in self.regs[reg]["fields"] if f["name"] == name)
        return f["lsb"], ((1 << f["width"]) - 1) << f["lsb"]

    async def read(self, reg):
        r = await self.axil.read(self.regs[reg]["offset"], 4)
        if r.resp != 0:
            raise BenchError(f"{self.m['tag']}: read of {reg}: response {r.resp}, expected OKAY")
        return int.from_bytes(r.data, "little")

    async def write(self, reg, value):
        r = await self.axil.write(self.regs[reg]["offset"], int(value).to_bytes(4, "little"))
        if r.resp != 0:
            raise BenchError(f"{self.m['tag']}: write of {reg}: response {r.resp}, expected OKAY")

    async def expect(self, reg, want, what):
        got = await self.read(reg)
        if got != want:
            raise BenchError(f"{self.m['tag']} {what}: {reg}: expected {want:#x} != got {got:#x}")

    async def registers(self, case, frame):
        """The register file through the AXI4-Lite master: the build constants
        (ID, hash, limits) and the run registers' power-on values; run
        parameters other than the build's programmed, a refused write and its
        ERROR bit; a frame run with them against the golden model; the status
        registers, FRAME_COUNT and irq over that frame; the power-on run
        parameters restored."""
        tag = self.m["tag"]
        for name, r in self.regs.items():
            if r["build_constant"] or name.startswith("RUN_") or name == "CONTROL":
                await self.expect(name, r["reset"], "power-on value")
        h = int(self.m["params_hash"], 16)
        await self.expect("HASH_LO", h & 0xFFFF_FFFF, "hash of fcc_params.json")
        await self.expect("HASH_HI", h >> 32, "hash of fcc_params.json")
        _, irq_en = self.field("CONTROL", "IRQ_ENABLE")
        _, done = self.field("STATUS", "FRAME_DONE")
        _, idle = self.field("STATUS", "IDLE")
        _, clear = self.field("CONTROL", "CLEAR")
        await self.write("CONTROL", irq_en | clear)
        await self.expect("CONTROL", irq_en, "CLEAR reads 0")
        await self.expect("FRAME_COUNT", 0, "after CONTROL.CLEAR")
        # Program the run; then a refused write (an even K) keeps RUN_K.
        run = self.m["run_params"]
        for name, v in run.items():
            await self.write(name, v)
        await self.expect("ERROR", 0, "after valid run parameters")
        for name, v in run.items():
            await self.expect(name, v, "read back")
        _, k_err = self.field("ERROR", "K")
        await self.write("RUN_K", run["RUN_K"] + 1)
        await self.expect("ERROR", k_err, "after RUN_K = even")
        await self.expect("RUN_K", run["RUN_K"], "after a refused write")
        await self.write("ERROR", k_err)
        await self.expect("ERROR", 0, "after clearing ERROR.K")
        if (await self.read("STATUS")) & idle == 0:
            raise BenchError(f"{tag}: STATUS.IDLE low before the frame")
        if int(self.dut.irq.value) != 0:
            raise BenchError(f"{tag}: irq high before the frame")
        status = await self.run_frames(case, [frame], cols=run["RUN_COLS"])
        await ClockCycles(self.dut.clk, 2)
        if int(self.dut.irq.value) != 1:
            raise BenchError(f"{tag}: irq low after the frame with CONTROL.IRQ_ENABLE set")
        await self.expect("STATUS", done | idle, "after the frame")
        await self.expect("FRAME_COUNT", 1, "after one frame")
        regs = {
            "CLUSTERS": status["status_clusters"],
            "PROVISIONAL": status["status_provisional"],
            "UNLABELLED": status["status_unlabelled"],
            "JOINS": status["status_joins"],
            "GEAR_STALLS": status["status_gear_stalls"],
        }
        sh_o, _ = self.field("FRAME_FLAGS", "OVERFLOW")
        sh_e, _ = self.field("FRAME_FLAGS", "FRAME_ERROR")
        regs["FRAME_FLAGS"] = (status["status_overflow"] << sh_o) | (status["status_frame_error"] << sh_e)
        for name, v in regs.items():
            await self.expect(name, v, "frame status (as on the status port)")
        await self.write("STATUS", done)
        await self.expect("STATUS", idle, "after clearing FRAME_DONE")
        await ClockCycles(self.dut.clk, 2)
        if int(self.dut.irq.value) != 0:
            raise BenchError(f"{tag}: irq high after STATUS.FRAME_DONE was cleared")
        for name in run:
            await self.write(name, self.regs[name]["reset"])
        await self.write("CONTROL", 0)
        await self.expect("ERROR", 0, "after restoring the power-on run parameters")


@cocotb.test()
async def fcc_top_against_golden(dut):
    await run_manifest(dut, Bench)


async def run_manifest(dut, bench_class):
    """Every case of the manifest on `dut` with a `bench_class` bench (the
    row-major core's `Bench`, or the column core's in `test_fcc_col_top`)."""
    with open(os.environ["FCC_MANIFEST"]) as fh:
        manifest = json.load(fh)
    frames = {f["name"]: f for f in manifest["frames"]}
    cocotb.start_soon(Clock(dut.clk, 10, unit="ns").start())
    dut.m_axis_tready.value = 0
    dut.s_axis_tvalid.value = 0
    dut.s_axil_awvalid.value = 0
    dut.s_axil_wvalid.value = 0
    dut.s_axil_arvalid.value = 0
    dut.s_axil_bready.value = 0
    dut.s_axil_rready.value = 0
    bench = bench_class(dut, manifest)
    cocotb.start_soon(bench.mon.run())
    await bench.reset(4)
    for case in manifest["cases"]:
        c0 = bench.mon.cycle
        if case["kind"] == "frames" and case["run_cols"] is not None:
            # A run size below the build's: RUN_COLS programmed, then its
            # power-on value restored (each case leaves the power-on values).
            await bench.write("RUN_COLS", case["run_cols"])
            await bench.expect("ERROR", 0, f"case '{case['name']}': RUN_COLS = {case['run_cols']}")
            await bench.run_frames(case, [frames[n] for n in case["frames"]], cols=case["run_cols"])
            await bench.write("RUN_COLS", bench.regs["RUN_COLS"]["reset"])
        elif case["kind"] == "frames":
            await bench.run_frames(case, [frames[n] for n in case["frames"]])
        elif case["kind"] == "reset_mid_frame":
            await bench.reset_mid_frame(case, frames[case["frames"][0]])
        elif case["kind"] == "registers":
            await bench.registers(case, frames[case["frames"][0]])
        else:
            raise BenchError(f"unknown case kind {case['kind']}")
        dut._log.info("%s case '%s': pass (%d cycles)", manifest["tag"], case["name"], bench.mon.cycle - c0)
    # Idle tail: outputs must stay defined while nothing happens.
    await ClockCycles(dut.clk, 32)
    await bench.wait_for(lambda: True, 0, "idle tail")
    dut._log.info("%s: %d cases, %d cycles", manifest["tag"], len(manifest["cases"]), bench.mon.cycle)
