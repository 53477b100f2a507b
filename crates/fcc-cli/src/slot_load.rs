//! What a column core's slot table is offered (`fcc stream-report`'s second
//! table, docs/column-core.md): per labelled pixel, the distinct runs it
//! joins in its column window other than its own; and the joins between
//! clusters a core would send its merge engine if it kept, per row, the
//! clusters of the row's last `h + 1` runs ("row roots", rewritten by each
//! merge [`ROOTS_LATE`] slots after it). A window row spans `h + 1` columns,
//! so every joined pixel's run is among its row's last `h + 1`: the model
//! checks it and never looks a label up.

use std::collections::VecDeque;

use fcc_golden::{column_window, Frame, Stream, Thresholds};
use fcc_params::FccParams;

/// Slots between a merge and the row roots' rewrite in the model: about
/// the pipeline from a pixel's entry to its merges.
pub const ROOTS_LATE: u64 = 24;

/// Counts over frames.
#[derive(Debug, Default, Clone, Copy)]
pub struct SlotLoad {
    /// Pixel slots (rows x columns).
    pub slots: u64,
    /// Labelled pixels, the distinct runs they join other than their own,
    /// the most at one pixel.
    pub labelled: u64,
    pub joined_runs: u64,
    pub joined_runs_max: u32,
    /// The row-root model's joins between clusters it believes different,
    /// those beyond the first at each pixel (a core sending one a slot
    /// waits a slot for each), and the merges they make.
    pub offered: u64,
    pub offered_more: u64,
    pub merges: u64,
    /// The representative model's joins (a row keeps a representative
    /// label per run, not its cluster: a label of the same cluster, set
    /// when a pixel names the run), those beyond the first at each pixel,
    /// and the most sent in one column.
    pub rep_joins: u64,
    pub rep_joins_more: u64,
    pub rep_joins_col: u32,
    /// The union-find behind the representatives ([`uf_walk`]): the reads
    /// its walks make for the representative joins (two finds each) and
    /// the runs (one find each, as the run ends), the most in one column,
    /// and the deepest run at the frame end (no walk is longer).
    pub uf_reads: u64,
    pub uf_reads_col: u32,
    pub uf_walk_max: u32,
}

/// A union-find walk as a core's engine makes it, one read a node, the
/// parent always older than the child (the run that started first), no
/// path compression: the root of `x` and the reads taken.
pub fn uf_walk(parent: &[u32], mut x: u32) -> (u32, u32) {
    let mut reads = 1;
    while parent[x as usize] != x {
        x = parent[x as usize];
        reads += 1;
    }
    (x, reads)
}

/// Unite the sets of `a` and `b` in the walk model's forest, the older
/// root keeping its place; the reads of the two walks.
fn uf_join(parent: &mut [u32], a: u32, b: u32) -> u32 {
    let ((ra, na), (rb, nb)) = (uf_walk(parent, a), uf_walk(parent, b));
    parent[ra.max(rb) as usize] = ra.min(rb);
    na + nb
}

fn find(parent: &mut [u32], mut x: u32) -> u32 {
    while parent[x as usize] != x {
        parent[x as usize] = parent[parent[x as usize] as usize];
        x = parent[x as usize];
    }
    x
}

/// Add one frame's counts to `t` (the frame clustered by the golden stream
/// with `params`). In the representative model the runs a pixel names take
/// its representative `reps_late` slots after it (1: the next pixel sees
/// it).
pub fn measure(
    params: &FccParams,
    frame: &Frame,
    reps_late: u64,
    t: &mut SlotLoad,
) -> anyhow::Result<()> {
    let mut stream = Stream::new(params)?;
    let mut column = vec![None; frame.rows];
    for c in 0..frame.cols {
        for (i, v) in column.iter_mut().enumerate() {
            *v = frame.get(i, c);
        }
        stream.push_column(&column)?;
    }
    stream.finish()?;
    let mut runs = Vec::new();
    stream.runs_into(&mut runs)?;
    let (rows, cols, h) = (frame.rows, frame.cols, params.half());
    let th = Thresholds::new(params);
    let n = runs.iter().copied().max().unwrap_or(0) as usize + 1;
    let mut parent: Vec<u32> = (0..n as u32).collect();
    // Per row: its latest labelled run, and the cluster the core believes
    // it in; merges waiting to rewrite those beliefs.
    let per_row = h + 1;
    let mut latest = vec![vec![0u32; per_row]; rows];
    let mut view = vec![vec![0u32; per_row]; rows];
    let mut pending: VecDeque<(u64, u32, u32)> = VecDeque::new();
    let mut joined: Vec<u32> = Vec::new();
    let mut offered: Vec<u32> = Vec::new();
    // The representative model: per run a label of its cluster.
    let mut rep: Vec<u32> = (0..n as u32).collect();
    let mut reps: Vec<u32> = Vec::new();
    let mut rep_writes: VecDeque<(u64, u32, u32)> = VecDeque::new();
    // The union-find behind the representatives, over run indices.
    let mut uf: Vec<u32> = (0..n as u32).collect();
    let mut slot = 0u64;
    for c in 0..cols {
        let mut col_joins = 0u32;
        let mut col_reads = 0u32;
        for i in 0..rows {
            slot += 1;
            while rep_writes.front().is_some_and(|&(at, _, _)| at <= slot) {
                let (_, run, least) = rep_writes.pop_front().expect("checked");
                rep[run as usize] = least;
            }
            while pending.front().is_some_and(|&(at, _, _)| at <= slot) {
                let (_, from, to) = pending.pop_front().expect("checked");
                for v in view.iter_mut().flatten().filter(|v| **v == from) {
                    *v = to;
                }
            }
            let own = runs[i * cols + c];
            let Some(p) = frame.get(i, c).filter(|_| own != 0) else {
                continue;
            };
            if latest[i][0] != own {
                // The row's run before is over: one find for its flush.
                if latest[i][0] != 0 {
                    col_reads += uf_walk(&uf, latest[i][0]).1;
                }
                latest[i].rotate_right(1);
                view[i].rotate_right(1);
                latest[i][0] = own;
                view[i][0] = own;
            }
            joined.clear();
            offered.clear();
            for (ii, cc) in column_window(rows, h, i, c) {
                let r = runs[ii * cols + cc];
                if r == 0
                    || r == own
                    || joined.contains(&r)
                    || !frame.get(ii, cc).is_some_and(|q| th.joins(p, q))
                {
                    continue;
                }
                joined.push(r);
                let Some(k) = latest[ii].iter().position(|&l| l == r) else {
                    anyhow::bail!(
                        "row {ii}, column {cc}: a joined run not among its row's last {per_row} (a bug)"
                    );
                };
                let cluster = view[ii][k];
                if cluster != view[i][0] && !offered.contains(&cluster) {
                    offered.push(cluster);
                }
            }
            // One join per representative other than the smallest among
            // the pixel's run's and its joined runs'; all of them then take
            // the smallest, `reps_late` slots later (the rows' entries in
            // the window are rewritten).
            reps.clear();
            reps.push(rep[own as usize]);
            for &r in &joined {
                if !reps.contains(&rep[r as usize]) {
                    reps.push(rep[r as usize]);
                }
            }
            let sent = reps.len() as u64 - 1;
            let least = reps.iter().copied().min().expect("one at least");
            for &x in reps.iter().filter(|&&x| x != least) {
                col_reads += uf_join(&mut uf, x, least);
            }
            rep_writes.push_back((slot + reps_late, own, least));
            for &r in &joined {
                rep_writes.push_back((slot + reps_late, r, least));
            }
            t.rep_joins += sent;
            t.rep_joins_more += sent.saturating_sub(1);
            col_joins += sent as u32;
            for &x in &offered {
                let (a, b) = (find(&mut parent, own), find(&mut parent, x));
                if a != b {
                    let (keep, gone) = (a.min(b), a.max(b));
                    parent[gone as usize] = keep;
                    pending.push_back((slot + ROOTS_LATE, gone, keep));
                    t.merges += 1;
                }
            }
            view[i][0] = find(&mut parent, own);
            t.labelled += 1;
            t.joined_runs += joined.len() as u64;
            t.joined_runs_max = t.joined_runs_max.max(joined.len() as u32);
            t.offered += offered.len() as u64;
            t.offered_more += offered.len().saturating_sub(1) as u64;
        }
        t.rep_joins_col = t.rep_joins_col.max(col_joins);
        t.uf_reads += u64::from(col_reads);
        t.uf_reads_col = t.uf_reads_col.max(col_reads);
    }
    // The frame end flushes every row's run still open.
    for row in &latest {
        if row[0] != 0 {
            t.uf_reads += u64::from(uf_walk(&uf, row[0]).1);
        }
    }
    t.uf_walk_max = t
        .uf_walk_max
        .max((1..n as u32).map(|x| uf_walk(&uf, x).1).max().unwrap_or(0));
    t.slots += (rows * cols) as u64;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A flat patch, three rows by six columns, 0.1 m apart: one cluster of
    /// three runs (one per row), joined when the second and third rows'
    /// first pixels arrive; every later pixel finds its neighbours' rows
    /// in its own cluster and offers nothing.
    #[test]
    fn a_patch_offers_its_two_merges_and_nothing_else() {
        let mut f = Frame::empty(3, 6);
        for i in 0..3 {
            for c in 0..6 {
                f.set(i, c, Some([2560, (c * 26) as i16, -((i * 26) as i16)]));
            }
        }
        let p = FccParams {
            rows: 3,
            cols: 6,
            fsize: 3,
            ..FccParams::default()
        };
        let mut t = SlotLoad::default();
        measure(&p, &f, 1, &mut t).unwrap();
        assert_eq!((t.slots, t.labelled), (18, 18));
        assert_eq!((t.merges, t.offered, t.offered_more), (2, 2, 0));
        // The representatives: the same two joins (rows 1 and 2 meet the
        // row above once), then every run of the window shares one.
        assert_eq!((t.rep_joins, t.rep_joins_more, t.rep_joins_col), (2, 0, 2));
        // The union-find: each join finds two roots at once (runs 2 and
        // 1, then 3 and 1), four reads in column 0; at the frame end the
        // three runs' flushes read 1, 2 and 2 words (2 and 3 under 1).
        assert_eq!((t.uf_reads, t.uf_reads_col, t.uf_walk_max), (9, 4, 2));
        // Taken late, the representatives leave the pixels after those two
        // to send the same joins again; the merges are the same.
        let mut late = SlotLoad::default();
        measure(&p, &f, 100, &mut late).unwrap();
        assert_eq!(late.merges, t.merges);
        assert!(late.rep_joins > t.rep_joins + 4, "{late:?}");
        // K = 3: the rows above and below, one run each.
        assert_eq!(t.joined_runs_max, 2);
        // Column 0: (1, 0) and (2, 0) join the row above. Later columns:
        // (1, c) rows 0 and 2, (0, c) and (2, c) row 1.
        assert_eq!(t.joined_runs, 1 + 1 + 5 * (1 + 2 + 1));
    }
}
