#!/usr/bin/env python3
"""Per-block summary of Verilator line and toggle coverage of `fcc_top`.

Reads the `.dat` files that the coverage build of the Verilator regression
writes (`FCC_SIM_COVERAGE=<dir>`, see sim/coverage.sh) and prints Markdown:
one row per block (the generator's top-level blocks: `fcc_top`'s own logic,
`fcc_intra`, `fcc_window`, `fcc_dist_tree`, `fcc_sort_net`, `fcc_merge_table`,
`fcc_label_update`, `fcc_regs`), then, per block, the lines and the signals
(named with their sub-block: `filter.later_min`) that no test reached.

A coverage point is counted once per block, over every instance and every
configuration the regression simulates: a line of a module (or a bit of a
signal toggling 0->1 and 1->0) counts as reached when any instance of any
configuration reached it. Submodules (`fcc_dist_tree__units__3__sq`, ...)
belong to the block named before their first `__`.

With `--json PATH` it also writes the per-block counts as JSON
({command, instances, blocks: [{block, line_hit, line_total, toggle_hit,
toggle_total}]}), which `fcc synth --all --coverage-json PATH` renders into
docs/results.md. Blocks it does not know (new sub-blocks) are listed after the
known ones, by name.

Usage: python3 sim/coverage_summary.py DIR [--command TEXT] [--rtl COMMIT] [--max-list N] [--json PATH]
"""

import argparse
import collections
import glob
import json
import os
import re
import sys

BLOCK_ORDER = [
    "fcc_top",
    "fcc_intra",
    "fcc_window",
    "fcc_dist_tree",
    "fcc_sort_net",
    "fcc_merge_table",
    "fcc_label_update",
    "fcc_regs",
]


def parse_dat(path):
    """Yield (fields, count) of every coverage point of one .dat file."""
    with open(path, encoding="latin1") as fh:
        for line in fh:
            if not line.startswith("C '"):
                continue
            end = line.rindex("'")
            body = line[3:end]
            count = int(line[end + 1 :].strip())
            fields = {}
            for part in body.split("\x01"):
                if "\x02" in part:
                    k, v = part.split("\x02", 1)
                    fields[k] = v
            yield fields, count


class Sources:
    """The generated Verilog each point's file name refers to (models are built
    in `<key>.tmp-<pid>` and renamed to `<key>`), for module-relative line
    numbers and the source text, and the variant of each module's text."""

    def __init__(self):
        self.files = {}
        self.variants = {}

    def get(self, fpath):
        if fpath not in self.files:
            real = re.sub(r"\.tmp-\d+(?=/)", "", fpath)
            lines, starts = None, {}
            try:
                with open(real, encoding="utf-8", errors="replace") as fh:
                    lines = fh.read().splitlines()
                for i, ln in enumerate(lines, 1):
                    m = re.match(r"module\s+([A-Za-z0-9_$]+)", ln)
                    if m:
                        starts[m.group(1)] = i
            except OSError:
                pass
            self.files[fpath] = (lines, starts)
        return self.files[fpath]

    def locate(self, fpath, module, line):
        """(line relative to the module's `module` line or the raw line, text)."""
        lines, starts = self.get(fpath)
        if lines is None or module not in starts:
            return line, ""
        text = lines[line - 1].strip() if 0 < line <= len(lines) else ""
        return line - starts[module], text

    def variant(self, fpath, module):
        """The shape of one module's body: its text with the configuration
        suffixes removed and every number replaced, so two configurations
        that differ only in constants and widths share it (their line numbers
        mean the same lines) and a loop the generator unrolls per K gives
        another variant. None when the source is not found."""
        key = (fpath, module)
        if key not in self.variants:
            lines, starts = self.get(fpath)
            body = None
            if lines is not None and module in starts:
                end = starts[module]
                while end < len(lines) and not lines[end].startswith("endmodule"):
                    end += 1
                body = "\n".join(
                    re.sub(r"\d+", "N", VERILOG_LITERAL.sub("L", CONFIG_SUFFIX_ANY.sub("", ln)))
                    for ln in lines[starts[module] : end]
                )
            self.variants[key] = body
        return self.variants[key]


# Generated module names end in the configuration's suffix, `_k<K>_<8 hex
# digits of the parameter hash>` (FccParams::module_suffix); points of one
# module in several configurations are merged under the name without it.
CONFIG_SUFFIX = re.compile(r"_k(\d+)_[0-9a-f]{8}$")
CONFIG_SUFFIX_ANY = re.compile(r"_k\d+_[0-9a-f]{8}\b")
VERILOG_LITERAL = re.compile(r"\d*'[sS]?[bBoOdDhH][0-9a-fA-FxXzZ_]+")


def k_of(module):
    m = CONFIG_SUFFIX.search(module)
    return int(m.group(1)) if m else None


def base_name(module):
    return CONFIG_SUFFIX.sub("", module)


def block_of(module):
    return module.split("__", 1)[0]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("dir", help="directory of the .dat files")
    ap.add_argument("--command", default="bash sim/coverage.sh", help="command named in the header")
    ap.add_argument("--max-list", type=int, default=12, help="unreached items listed per block and kind")
    ap.add_argument("--json", help="also write the per-block counts to this JSON file")
    ap.add_argument("--rtl", help="the commit whose generator built the models (sim/coverage.sh gives it)")
    a = ap.parse_args()
    files = sorted(glob.glob(os.path.join(a.dir, "*.dat")))
    if not files:
        sys.exit(f"{a.dir}: no coverage .dat files (run the regression with FCC_SIM_COVERAGE={a.dir})")
    # (kind, block, key) -> reached?  key ignores the instance path.
    points = {}
    source = {}  # (module, relative line) -> source text, for the unreached-lines list
    srcs = Sources()
    # A module whose text differs between configurations has its lines
    # counted per text variant (named by the K of the builds that have it);
    # one whose text is the same everywhere is counted once.
    variant_ks = collections.defaultdict(lambda: collections.defaultdict(set))
    for path in files:
        for f, _count in parse_dat(path):
            page = f.get("page", "")
            if page.startswith("v_line/") or page.startswith("v_branch/"):
                full = page.split("/", 1)[1]
                body = srcs.variant(f.get("f", ""), full)
                variant_ks[base_name(full)][body].add(k_of(full))
    for path in files:
        for f, count in parse_dat(path):
            page = f.get("page", "")
            if "/" not in page:
                continue
            kind, full = page.split("/", 1)
            kind = {"v_line": "line", "v_branch": "line", "v_toggle": "toggle"}.get(kind)
            if kind is None:
                continue
            module = base_name(full)
            blk = block_of(module)
            if kind == "line":
                rel, text = srcs.locate(f.get("f", ""), full, int(f.get("l", "0")))
                ks = ""
                if len(variant_ks[module]) > 1:
                    found = sorted(k for k in variant_ks[module][srcs.variant(f.get("f", ""), full)] if k)
                    ks = "K = " + ", ".join(map(str, found))
                key = (module, ks, rel, f.get("n", ""), f.get("o", ""))
                source.setdefault((module, ks, rel), text)
            else:
                key = (module, f.get("o", ""))
            k = (kind, blk, key)
            points[k] = points.get(k, False) or count > 0
    stats = collections.defaultdict(lambda: [0, 0, 0, 0])  # line hit, line all, toggle hit, toggle all
    missed = collections.defaultdict(list)
    for (kind, blk, key), hit in points.items():
        s = stats[blk]
        if kind == "line":
            s[1] += 1
            s[0] += int(hit)
        else:
            s[3] += 1
            s[2] += int(hit)
        if not hit:
            missed[(kind, blk)].append(key)
    blocks = [b for b in BLOCK_ORDER if b in stats] + sorted(b for b in stats if b not in BLOCK_ORDER)
    rev = a.rtl

    if a.json:
        summary = {
            "command": a.command,
            "rtl": rev,
            "instances": len(files),
            "blocks": [
                {
                    "block": b,
                    "line_hit": stats[b][0],
                    "line_total": stats[b][1],
                    "toggle_hit": stats[b][2],
                    "toggle_total": stats[b][3],
                }
                for b in blocks
            ],
        }
        with open(a.json, "w", encoding="utf-8") as fh:
            json.dump(summary, fh, indent=2)
            fh.write("\n")

    def pct(h, n):
        return "-" if n == 0 else f"{100.0 * h / n:.1f} %"

    out = []
    out.append(f"<!-- Generated by `{a.command}`. Do not edit: regenerate. -->\n")
    out.append("# Coverage of the Verilator regression\n")
    out.append(
        f"Verilator line and toggle coverage of the generated `fcc_top` over the tests `{a.command}` ran "
        f"({len(files)} simulated instances, every configuration those tests build"
        + (f"; the RTL of commit {rev}" if rev else "")
        + "). A point counts "
        "once per block: reached when any instance of any configuration reached it. A toggle point is one "
        "bit of one signal in one direction (0->1 or 1->0).\n"
    )
    out.append("| block | lines reached | line coverage | toggles reached | toggle coverage |")
    out.append("|---|---:|---:|---:|---:|")
    tot = [0, 0, 0, 0]
    for b in blocks:
        s = stats[b]
        tot = [x + y for x, y in zip(tot, s)]
        out.append(f"| `{b}` | {s[0]} / {s[1]} | {pct(s[0], s[1])} | {s[2]} / {s[3]} | {pct(s[2], s[3])} |")
    out.append(f"| all | {tot[0]} / {tot[1]} | {pct(tot[0], tot[1])} | {tot[2]} / {tot[3]} | {pct(tot[2], tot[3])} |")
    out.append("")
    out.append("## Not reached, per block\n")
    out.append(
        "Lines are given as `module +N`: N lines below the `module` line of that module in the generated "
        "`fcc_top.v`, with the Verilator point type and the source line. A module whose text differs "
        "between the configurations simulated by more than constants and widths (loops unrolled per K) "
        "is counted per text variant, "
        "named by the K of the builds that have it (`(K = 11)`); a module with one text is counted once.\n"
    )
    for b in blocks:
        lines = sorted(missed.get(("line", b), []), key=lambda k: (k[0], k[1], k[2]))
        toggles = missed.get(("toggle", b), [])
        out.append(f"### `{b}`\n")
        if not lines and not toggles:
            out.append("Everything reached.\n")
            continue
        if lines:
            out.append(f"{len(lines)} line points never reached:\n")
            for m, ks, ln, _n, o in lines[: a.max_list]:
                text = source.get((m, ks, ln), "").strip()
                what = f" {o}" if o else ""
                build = f" ({ks})" if ks else ""
                out.append(f"- `{m}`{build} +{ln}{what}" + (f": `{text}`" if text else ""))
            if len(lines) > a.max_list:
                out.append(f"- ... and {len(lines) - a.max_list} more")
            out.append("")
        if toggles:
            # Group bits of one signal: name[3]:0->1 -> name
            sig = collections.Counter()
            for m, o in toggles:
                # Verilator spells `$` as `__024` in signal names.
                name = re.sub(r"\[\d+\]", "", o.split(":")[0]).replace("__024", "$")
                # The signal with its sub-block (`filter.later_min`), since
                # the ports of small sub-blocks (`d`, `q`) recur in many.
                sub = m[len(b) + 2 :].replace("__", ".") if m.startswith(b + "__") else ""
                sig[f"{sub}.{name}" if sub else name] += 1
            out.append(f"{len(toggles)} toggle points never reached, in {len(sig)} signals; the most:\n")
            for name, n in sig.most_common(a.max_list):
                out.append(f"- `{name}`: {n}")
            if len(sig) > a.max_list:
                out.append(f"- ... and {len(sig) - a.max_list} more signals")
            out.append("")
    print("\n".join(out))


if __name__ == "__main__":
    main()
