"""cocotb test of the generated column-streaming core (`fcc gen --scan
column`; 4-state, Icarus Verilog).

The core has the row-major core's ports, so the bench top, the drivers, the
X/Z checker and the cases are `test_fcc_top`'s; what differs is the output:
one packet a frame of 64-bit record beats and the end beat (spec §9.4),
compared beat for beat with the golden stream's (`fcc cluster --stream
--beats`, in the manifest that `run_bench.py` writes), and the status: the
end beat's count of records, overflow and input error.
"""

import cocotb

from test_fcc_top import Bench, BenchError, run_manifest


class ColBench(Bench):
    """`Bench` reading records instead of labels."""

    def limit(self):
        # The column core takes about a cycle a pixel, up to about 12 on
        # frames of many small clusters (docs/column-core.md).
        return 64 * self.rows * self.cols + 10_000

    def labels_of(self, frame):
        """The output packet's 64-bit beats (every byte kept)."""
        data = bytes(frame.tdata)
        if len(data) % 8:
            raise BenchError(f"{len(data)} bytes in the output packet: not whole 64-bit beats")
        return [int.from_bytes(data[i : i + 8], "little") for i in range(0, len(data), 8)]

    def compare(self, frame, got, status, case, cols=None):
        what = f"{self.m['tag']} case '{case['name']}' seed {case['seed']} frame {frame['name']}"
        exp = list(frame["beats_out"])
        if case["tlast"] != "normal":
            exp[-1] |= 1 << self.m["end_frame_error_shift"]
        for i, (e, g) in enumerate(zip(exp, got)):
            if e != g:
                words = self.m["record_words"]
                raise BenchError(
                    f"{what}: first difference at output beat {i} (record {i // words + 1}, beat {i % words}) "
                    f"of {len(exp)}: expected {e:#018x} != got {g:#018x}"
                )
        if len(got) != len(exp):
            raise BenchError(f"{what}: {len(got)} output beats, expected {len(exp)}")
        want = {
            "status_clusters": min(frame["records"], 0xFFFF),
            "status_overflow": int(frame["overflow"]),
            "status_frame_error": int(case["tlast"] != "normal"),
        }
        for n, e in want.items():
            if status[n] != e:
                raise BenchError(f"{what}: {n}: expected {e} != got {status[n]}")


@cocotb.test()
async def fcc_col_top_against_golden(dut):
    await run_manifest(dut, ColBench)
