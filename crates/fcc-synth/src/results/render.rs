//! The results document in Markdown, and the one-line summary of a row.

use crate::Resources;

use super::{
    check_targets, paper_row, CycleMeasure, QualityRow, Report, ResultRow, PAPER_CLOCK_MHZ,
    PAPER_CPU_S_PER_FRAME, PAPER_FRAME_MS, TARGETS,
};

/// `12345` as `12,345`.
pub fn thousands(n: u64) -> String {
    let digits: Vec<char> = n.to_string().chars().collect();
    let groups: Vec<String> = digits
        .rchunks(3)
        .rev()
        .map(|g| g.iter().collect())
        .collect();
    groups.join(",")
}

/// A BRAM figure: whole numbers without decimals, halves with one.
pub(super) fn bram(x: f64) -> String {
    if x.fract() == 0.0 {
        thousands(x as u64)
    } else {
        format!("{x:.1}")
    }
}

pub(super) fn opt<T>(v: Option<T>, f: impl Fn(T) -> String) -> String {
    v.map(f).unwrap_or_else(|| "–".to_string())
}

/// First line of an error, with `|` escaped for a table cell.
pub(super) fn cell_text(s: &str) -> String {
    s.lines().next().unwrap_or("").replace('|', "\\|")
}

/// A path point for a table cell: code-quoted, `|` escaped.
pub(super) fn code(s: &str) -> String {
    format!("`{}`", s.replace('|', "\\|"))
}

/// The plain-text header of [`summary_row`].
pub fn summary_header() -> String {
    "| K | Slice LUTs | FF | DSP48E1 | RAMB36E1 | RAMB18E1 | BRAM (36 eq.) | critical path (ns) | est. fmax (MHz) |\n\
     |--:|--:|--:|--:|--:|--:|--:|--:|--:|"
        .to_string()
}

/// One row: K, LUT, FF, DSP48E1, RAMB36E1, RAMB18E1, BRAM36-equivalent, critical path, est. fmax.
pub fn summary_row(row: &ResultRow) -> String {
    match (&row.resources, &row.synth_error) {
        (Some(r), _) => format!(
            "| {} | {} | {} | {} | {} | {} | {} | {} | {} |",
            row.fsize,
            thousands(r.slice_luts),
            thousands(r.ff),
            r.dsp48e1,
            r.ramb36e1,
            r.ramb18e1,
            bram(r.bram36),
            opt(row.timing.as_ref(), |t| format!(
                "{:.3}",
                t.critical_path_ns
            )),
            opt(row.timing.as_ref(), |t| format!("{:.0}", t.fmax_mhz)),
        ),
        (None, e) => format!(
            "| {} | synthesis failed: {} |||||||| ",
            row.fsize,
            cell_text(e.as_deref().unwrap_or("no result"))
        )
        .trim_end()
        .to_string(),
    }
}

/// The fanout and routing-hop tables.
fn render_routing(s: &mut String, report: &Report) {
    use crate::routing::{FANOUT_LIMIT, HOP_LIMIT};
    s.push_str("\n## Fanout and routing hops\n\n");
    s.push_str(&format!(
        "What the pre-route estimate cannot see, read from the synthesised netlist: \
         general-routing hops between the launching and the capturing element (carry-chain, \
         wide-multiplexer, LUT-to-carry and DSP-cascade links do not count; targets: no \
         path over {HOP_LIMIT} hops) and the loads of every net but the clock (target: none \
         over {FANOUT_LIMIT}). Where copying a driver by hand does not fit the \
         resource budget, the generator marks it with Vivado's `max_fanout = {FANOUT_LIMIT}` \
         and Vivado's synthesis replicates it; Yosys does not, so the netlist still shows \
         those nets whole, and they are counted apart (\"nothing replicates\": nets over \
         {FANOUT_LIMIT} loads without the attribute). These are the netlist's figures \
         before placement.\n\n"
    ));
    s.push_str(&format!(
        "| K | most hops | endpoints over {HOP_LIMIT} hops | longest path from | to | nets over {FANOUT_LIMIT} loads | of them nothing replicates | most loads | most loads nothing replicates |\n\
         |--:|--:|--:|---|---|--:|--:|--:|--:|\n"
    ));
    for row in &report.rows {
        match &row.routing {
            Some(r) => {
                let (from, to) = r
                    .worst_paths
                    .first()
                    .map(|p| (code(&p.start), code(&p.end)))
                    .unwrap_or_default();
                let loads = |n: Option<&crate::routing::NetFanout>| {
                    n.map_or("–".to_string(), |n| thousands(n.loads as u64))
                };
                s.push_str(&format!(
                    "| {} | {} | {} | {from} | {to} | {} | {} | {} | {} |\n",
                    row.fsize,
                    r.worst_hops,
                    thousands(r.endpoints_over_limit as u64),
                    r.nets_over_limit,
                    r.unreplicated_over_limit
                        .map_or("–".to_string(), |n| n.to_string()),
                    loads(r.top_fanout.first()),
                    if r.unreplicated_over_limit.is_some() {
                        loads(r.top_unreplicated.first())
                    } else {
                        "–".to_string()
                    },
                ));
            }
            None => s.push_str(&format!(
                "| {} | – | – | {} | | – | – | – | – |\n",
                row.fsize,
                cell_text(row.synth_error.as_deref().unwrap_or("not measured"))
            )),
        }
    }
    let measured: Vec<&ResultRow> = report.rows.iter().filter(|r| r.routing.is_some()).collect();
    if measured.is_empty() {
        return;
    }
    let net_rows = |s: &mut String, nets: &[crate::routing::NetFanout], fsize: usize| {
        for n in nets {
            s.push_str(&format!(
                "| {fsize} | {} | {} | {} | {} |\n",
                code(&n.net),
                thousands(n.loads as u64),
                code(&n.driver),
                n.max_fanout.map_or("–".to_string(), |m| m.to_string()),
            ));
        }
    };
    s.push_str("\nThe ten highest-fanout nets of each K:\n\n");
    s.push_str("| K | net | loads | driven by | `max_fanout` |\n|--:|---|--:|---|--:|\n");
    for row in &measured {
        let r = row.routing.as_ref().expect("filtered");
        net_rows(s, &r.top_fanout, row.fsize);
    }
    let unmarked: Vec<&&ResultRow> = measured
        .iter()
        .filter(|r| {
            r.routing
                .as_ref()
                .is_some_and(|x| x.unreplicated_over_limit.is_some())
        })
        .collect();
    if unmarked.is_empty() {
        return;
    }
    s.push_str(&format!(
        "\nThe ten highest-fanout nets that nothing replicates (no `max_fanout` at or \
         below {FANOUT_LIMIT}):\n\n"
    ));
    s.push_str("| K | net | loads | driven by | `max_fanout` |\n|--:|---|--:|---|--:|\n");
    for row in unmarked {
        let r = row.routing.as_ref().expect("filtered");
        net_rows(s, &r.top_unreplicated, row.fsize);
    }
}

/// A percentage of `hit` over `total`, or a dash when there is nothing to reach.
fn percent(hit: u64, total: u64) -> String {
    if total == 0 {
        "–".into()
    } else {
        format!("{:.1} %", 100.0 * hit as f64 / total as f64)
    }
}

fn render_coverage(s: &mut String, report: &Report) {
    s.push_str("\n## Coverage of the Verilator regression\n\n");
    let Some(c) = &report.coverage else {
        s.push_str("Not measured yet (`bash sim/coverage.sh`).\n");
        return;
    };
    s.push_str(&format!(
        "Verilator line and toggle coverage of `fcc_top` per block, from `{}` ({} simulated \
         instances{}); a point counts when any instance of any configuration reached it. What is \
         never reached, per block: [coverage.md](coverage.md).\n\n",
        c.command,
        c.instances,
        c.rtl
            .as_deref()
            .map(|r| format!("; the RTL of commit {r}"))
            .unwrap_or_default()
    ));
    s.push_str(
        "| block | lines reached | line coverage | toggles reached | toggle coverage |\n\
         |---|--:|--:|--:|--:|\n",
    );
    let mut tot = [0u64; 4];
    for b in &c.blocks {
        for (t, x) in tot
            .iter_mut()
            .zip([b.line_hit, b.line_total, b.toggle_hit, b.toggle_total])
        {
            *t += x;
        }
        s.push_str(&format!(
            "| `{}` | {} / {} | {} | {} / {} | {} |\n",
            b.block,
            thousands(b.line_hit),
            thousands(b.line_total),
            percent(b.line_hit, b.line_total),
            thousands(b.toggle_hit),
            thousands(b.toggle_total),
            percent(b.toggle_hit, b.toggle_total)
        ));
    }
    s.push_str(&format!(
        "| all | {} / {} | {} | {} / {} | {} |\n",
        thousands(tot[0]),
        thousands(tot[1]),
        percent(tot[0], tot[1]),
        thousands(tot[2]),
        thousands(tot[3]),
        percent(tot[2], tot[3])
    ));
}

fn render_quality(s: &mut String, report: &Report) {
    s.push_str("\n## Clustering quality (golden model)\n\n");
    let Some(q) = &report.quality else {
        s.push_str("Not measured yet (`bench/quality.py`).\n");
        return;
    };
    let sc = &q.scenes;
    let t = &q.timing_ms_per_frame;
    s.push_str(&format!(
        "Panoptic quality by `fcc eval`'s rules on the synthetic scenes of `fcc scene` \
         ({} x {}, ground `{}`: both clusterers see the same points), seeds {}-{} held out; \
         the adaptive preset was tuned, and DBSCAN's setting chosen, on seeds {}-{}. \
         DBSCAN is {} on the points' x, y, z (noise unclustered), its labels scored by \
         `fcc eval --predicted`; its best tuning-scene setting is eps = {} m, \
         min_samples = {} (grid: {}). Time per frame: the golden model at K = 7 on one \
         thread {:.2} ms (paper) and {:.2} ms (adaptive), DBSCAN {:.0} ms. Made by \
         `bench/quality.py` ([lidar.md](lidar.md) has the rules).\n\n",
        sc.rows,
        sc.cols,
        sc.ground,
        sc.held_out_seeds[0],
        sc.held_out_seeds[1],
        sc.tune_seeds[0],
        sc.tune_seeds[1],
        q.dbscan.library,
        q.dbscan.eps,
        q.dbscan.min_samples,
        q.dbscan
            .grid
            .iter()
            .map(|g| format!("{} / {}: {:.3}", g.eps, g.min_samples, g.pq))
            .collect::<Vec<_>>()
            .join(", "),
        t.fcc_paper_k7_ms,
        t.fcc_adaptive_k7_ms,
        t.dbscan_ms
    ));
    let bands = q
        .rows
        .first()
        .map(|r| r.bands.as_slice())
        .unwrap_or_default();
    s.push_str("| clusterer | PQ (held out) | SQ | RQ | over-seg | under-seg | PQ (all) |");
    for b in bands {
        s.push_str(&format!(" {}-{} m |", b.lo, b.hi));
    }
    s.push_str(&format!(
        "\n|---|--:|--:|--:|--:|--:|--:|{}\n",
        "--:|".repeat(bands.len())
    ));
    let name = |r: &QualityRow| match (r.clusterer.as_str(), r.fsize) {
        ("fcc", Some(k)) => format!("FCC K = {k}, {}", r.preset.as_deref().unwrap_or("paper")),
        ("dbscan", _) => "DBSCAN".to_string(),
        (c, _) => c.to_string(),
    };
    for r in q.rows.iter().filter(|r| r.split == "held_out") {
        let all = q
            .rows
            .iter()
            .find(|x| x.split == "all" && name(x) == name(r))
            .map_or("–".to_string(), |x| format!("{:.3}", x.pq));
        s.push_str(&format!(
            "| {} | {:.3} | {:.3} | {:.3} | {:.4} | {:.4} | {} |",
            name(r),
            r.pq,
            r.sq,
            r.rq,
            r.over_segmentation,
            r.under_segmentation,
            all
        ));
        for b in &r.bands {
            s.push_str(&format!(" {:.3} ({}) |", b.pq, b.instances));
        }
        s.push('\n');
    }
    s.push_str(
        "\nRange bands: PQ of the held-out scenes over the instances and clusters whose mean \
         range falls in the band (instances in brackets).\n",
    );
}

/// The results document.
pub fn render_markdown(report: &Report) -> String {
    if report.base.scan == fcc_params::Scan::Column {
        // A column core's report alone: its section, without the row-major core.
        let mut s = String::from("# FCC hardware results: the column-streaming core\n\n");
        s.push_str(&format!(
            "<!-- Generated by `{}`. Do not edit: regenerate. -->\n",
            report.command
        ));
        super::render_column(&mut s, report, None);
        return s;
    }
    let b = &report.base;
    let mut s = String::new();
    s.push_str("# FCC hardware results\n\n");
    s.push_str(&format!(
        "<!-- Generated by `{}`. Do not edit: regenerate. -->\n\n",
        report.command
    ));
    s.push_str(&format!(
        "Configuration: {} x {} range image, th_H = {} m, th_V = {} m, {}-bit labels, \
         {} labels per output beat, XDC clock {} MHz. Synthesis: {}, \
         `synth_xilinx -family xc7 -flatten -noiopad -noclkbuf`. \
         How each number is measured: [results-method.md](results-method.md).\n\n",
        b.rows,
        b.cols,
        b.th_h,
        b.th_v,
        b.label_bits,
        b.labels_per_beat,
        b.clock_mhz,
        report
            .yosys_version
            .as_deref()
            .unwrap_or("Yosys (version not recorded)"),
    ));

    // Resources.
    s.push_str("## Resources\n\n");
    s.push_str(
        "Yosys cell counts after synthesis (before place and route) beside the paper's \
         Table I (Vivado). Slice LUTs are LUTs used as logic plus LUTs used as memory \
         (distributed RAM, shift registers); block RAM is counted in RAMB36 \
         equivalents (a RAMB18E1 is half).\n\n",
    );
    s.push_str(
        "| K | Slice LUTs | paper | FF | paper | DSP48E1 | paper | RAMB36E1 | RAMB18E1 | BRAM (36 eq.) | paper |\n\
         |--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n",
    );
    for row in &report.rows {
        let p = paper_row(row.fsize);
        match &row.resources {
            Some(r) => s.push_str(&format!(
                "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
                row.fsize,
                thousands(r.slice_luts),
                opt(p, |p| thousands(p.lut)),
                thousands(r.ff),
                opt(p, |p| thousands(p.ff)),
                r.dsp48e1,
                opt(p, |p| p.dsp.to_string()),
                r.ramb36e1,
                r.ramb18e1,
                bram(r.bram36),
                opt(p, |p| bram(p.bram36)),
            )),
            None => s.push_str(&format!(
                "| {} | synthesis failed: {} | | | | | | | | | |\n",
                row.fsize,
                cell_text(row.synth_error.as_deref().unwrap_or("no result"))
            )),
        }
    }
    let unmapped: Vec<String> = report
        .rows
        .iter()
        .filter_map(|r| {
            r.resources
                .as_ref()
                .filter(|x| x.unmapped > 0 || x.latch > 0)
                .map(|x| {
                    format!(
                        "K = {}: {} unmapped cells, {} latches",
                        r.fsize, x.unmapped, x.latch
                    )
                })
        })
        .collect();
    if !unmapped.is_empty() {
        s.push_str(&format!("\nWarning: {}.\n", unmapped.join("; ")));
    }

    // Timing.
    s.push_str("\n## Pre-route timing estimate\n\n");
    s.push_str(
        "Yosys `sta` with the `specify` delays of the Xilinx cell models: cell delays only, \
         no routing, no clock skew, ideal clock. **This is not Vivado timing**: routing \
         adds to every hop, so a routed path is longer than this. The estimated fmax is \
         1000 / critical path; logic levels are the cells between the launching and the \
         capturing element.\n\n",
    );
    s.push_str(
        "| K | critical path (ns) | est. fmax (MHz) | XDC clock (MHz) | logic levels | from | to |\n\
         |--:|--:|--:|--:|--:|---|---|\n",
    );
    for row in &report.rows {
        match &row.timing {
            Some(t) => s.push_str(&format!(
                "| {} | {:.3} | {:.0} | {} | {} | {} | {} |\n",
                row.fsize,
                t.critical_path_ns,
                t.fmax_mhz,
                b.clock_mhz,
                t.logic_levels,
                code(&t.start),
                code(&t.end)
            )),
            None => s.push_str(&format!(
                "| {} | – | – | {} | – | {} | |\n",
                row.fsize,
                b.clock_mhz,
                cell_text(row.synth_error.as_deref().unwrap_or("not measured"))
            )),
        }
    }

    render_routing(&mut s, report);

    // Cycles.
    s.push_str("\n## Cycles and frame rate (Verilator)\n\n");
    let cycle_rows: Vec<(usize, &CycleMeasure)> = report
        .rows
        .iter()
        .flat_map(|r| r.cycles.iter().map(move |c| (r.fsize, c)))
        .collect();
    if cycle_rows.is_empty() {
        s.push_str("Not measured yet.\n");
    } else {
        s.push_str(&format!(
            "Cycles from the first input pixel to the last output beat (mean over the corpus), \
             latency from the last input pixel to the last output beat, and the frame time \
             at the paper's {PAPER_CLOCK_MHZ} MHz and at the XDC's {} MHz. The paper: \
             {PAPER_FRAME_MS} ms per frame at {PAPER_CLOCK_MHZ} MHz.\n\n",
            b.clock_mhz
        ));
        s.push_str(&format!(
            "| K | corpus | frames | cycles / frame | worst cycles / pixel | latency (cycles) | ms / frame @ {PAPER_CLOCK_MHZ} MHz | frames/s @ {PAPER_CLOCK_MHZ} MHz | ms / frame @ {} MHz | frames/s @ {} MHz |\n\
             |--:|---|--:|--:|--:|--:|--:|--:|--:|--:|\n",
            b.clock_mhz, b.clock_mhz
        ));
        for (k, c) in cycle_rows {
            s.push_str(&format!(
                "| {k} | {} | {} | {} | {:.3} | {} | {:.3} | {:.0} | {:.3} | {:.0} |\n",
                c.corpus,
                c.frames,
                thousands(c.cycles_per_frame.round() as u64),
                c.max_cycles_per_pixel,
                thousands(c.latency_cycles.round() as u64),
                c.at_paper_clock.frame_ms,
                c.at_paper_clock.frames_per_s,
                c.at_xdc_clock.frame_ms,
                c.at_xdc_clock.frames_per_s,
            ));
        }
    }

    // Golden model.
    s.push_str("\n## Golden model (software)\n\n");
    if report.rows.iter().all(|r| r.golden.is_none()) {
        s.push_str("Not measured yet.\n");
    } else {
        s.push_str(&format!(
            "`fcc bench` on synthetic {} x {} scenes, release build: milliseconds per frame on \
             one thread, and frames per second of a batch on `threads` threads (speed-up: batch rate \
             over the same batch's rate on one thread), for `exact` merging and the published `paper` merge. \
             The paper's CPU implementation (Table III): {} s to {} s per frame.\n\n",
            b.rows, b.cols, PAPER_CPU_S_PER_FRAME[0], PAPER_CPU_S_PER_FRAME[1]
        ));
        s.push_str(
            "| K | exact ms / frame (1 thread) | exact batch frames/s | speed-up | paper ms / frame \
             (1 thread) | paper batch frames/s | threads |\n|--:|--:|--:|--:|--:|--:|--:|\n",
        );
        for row in &report.rows {
            if let Some(g) = &row.golden {
                s.push_str(&format!(
                    "| {} | {:.2} | {:.0} | {} | {} | {} | {} |\n",
                    row.fsize,
                    g.exact_ms,
                    g.batch_frames_per_s,
                    opt(g.speedup, |x| format!("{x:.2} x")),
                    opt(g.paper_ms, |m| format!("{m:.2}")),
                    opt(g.paper_batch_frames_per_s, |f| format!("{f:.0}")),
                    opt(g.threads, |t| t.to_string())
                ));
            }
        }
    }

    render_coverage(&mut s, report);
    render_quality(&mut s, report);

    // Targets.
    let t = TARGETS;
    s.push_str(&format!(
        "\n## Targets: K = {} on {} x {}\n\n",
        t.fsize, t.rows, t.cols
    ));
    let target_row = report.rows.iter().find(|r| r.fsize == t.fsize);
    match target_row {
        Some(row) if t.applies_to(&report.params_for(row.fsize)) => {
            s.push_str(
                "| metric | target | measured | result | dominated by |\n|---|--:|--:|---|---|\n",
            );
            for c in check_targets(row, &t) {
                let result = match c.met {
                    Some(true) => format!("met, {}", c.margin),
                    Some(false) => format!("**missed**, {}", c.margin),
                    None => c.margin.clone(),
                };
                s.push_str(&format!(
                    "| {} | {} | {} | {} | {} |\n",
                    c.metric,
                    c.target,
                    c.measured.as_deref().unwrap_or("–"),
                    result,
                    c.dominated_by.replace('|', "\\|")
                ));
            }
            if let Some(blocks) = &row.by_block {
                s.push_str(&format!(
                    "\nBy block (K = {}; a second synthesis that keeps the blocks apart, so its \
                     totals differ slightly from the flat run above):\n\n",
                    row.fsize
                ));
                s.push_str(
                    "| block | Slice LUTs | FF | DSP48E1 | BRAM (36 eq.) | CARRY4 |\n|---|--:|--:|--:|--:|--:|\n",
                );
                let mut v: Vec<(&String, &Resources)> = blocks.iter().collect();
                v.sort_by(|a, b| {
                    b.1.slice_luts
                        .cmp(&a.1.slice_luts)
                        .then_with(|| a.0.cmp(b.0))
                });
                for (name, r) in v {
                    let label = if name == fcc_rtl::TOP_NAME {
                        format!("{name} (between blocks)")
                    } else {
                        name.clone()
                    };
                    s.push_str(&format!(
                        "| {label} | {} | {} | {} | {} | {} |\n",
                        thousands(r.slice_luts),
                        thousands(r.ff),
                        r.dsp48e1,
                        bram(r.bram36),
                        thousands(r.carry4)
                    ));
                }
            }
        }
        _ => s.push_str(&format!(
            "The targets are for K = {} on {} x {}; this report has no such row.\n",
            t.fsize, t.rows, t.cols
        )),
    }
    if let Some(col) = &report.column {
        super::render_column(&mut s, col, Some(report));
    }
    s
}
