//! The stream (spec §9): columns in scan order in, one [`Record`] per
//! cluster out as soon as no later pixel can join it.
//!
//! Runs get an index in the order they start (column order); a union-find
//! over run indices holds the clusters, each root with its record being
//! accumulated ([`Acc`]) and a list of its pixels. After each column the
//! holds of spec §9.2 are marked on the roots that have them; every open
//! root without one closes. All buffers are kept from one frame to the next.

use crate::frame::Point;
use crate::records::{Acc, Record};
use crate::threshold::{JoinsWith, Thresholds};
use crate::GoldenError;
use fcc_params::FccParams;
use fcc_pixel::record::FrameEnd;
use serde::Serialize;

/// No run: an empty or unlabelled pixel; the end of a pixel list.
const NONE: u32 = u32::MAX;

/// More than one run (a row's older window columns).
const MIXED: u32 = u32::MAX - 1;

/// A row's first or latest valid pixel: column, point, run (or [`NONE`]).
#[derive(Debug, Clone, Copy)]
struct Seen {
    col: u32,
    p: Point,
    run: u32,
}

/// The root of `x`'s set, halving the path on the way.
#[inline]
fn find(parent: &mut [u32], mut x: u32) -> u32 {
    loop {
        let p = parent[x as usize];
        if p == x {
            return x;
        }
        let g = parent[p as usize];
        parent[x as usize] = g;
        x = g;
    }
}

/// One entry of the window: a labelled pixel's run, a node of its set
/// that was its root when last looked at (still the root while it has no
/// parent: most lookups end there, among the few open roots, without
/// walking from the run), and its point.
#[derive(Debug, Clone, Copy)]
struct Win {
    run: u32,
    root: u32,
    p: Point,
}

impl Win {
    /// No labelled pixel.
    const EMPTY: Win = Win {
        run: NONE,
        root: NONE,
        p: [0; 3],
    };
}

/// The runs' sets: per run a union-find parent and, at roots, the record
/// being accumulated, the labels held, the pixel list (head and tail, the
/// next pixel per pixel), the column-order index of the first pixel and
/// the record id once closed.
#[derive(Debug, Clone)]
struct Sets {
    parent: Vec<u32>,
    acc: Vec<Acc>,
    labels_held: Vec<u32>,
    head: Vec<u32>,
    tail: Vec<u32>,
    first_px: Vec<u32>,
    id: Vec<u32>,
    /// Holds the first run of a row whose last pixel may join it at the
    /// frame end (hold 3 of spec §9.2: fixed once the row's first pixel is).
    ring_held: Vec<bool>,
    /// Per pixel (raster order): the next pixel of its cluster's list.
    next_px: Vec<u32>,
    /// Clusters open: runs labelled less unions of two clusters less
    /// records emitted.
    open_clusters: u32,
    /// Unions of two clusters in the frame so far.
    merges: u32,
}

impl Sets {
    /// Pass 2 for one window entry `q` of a pixel (`p`, its pairs' test)
    /// in the cluster of `root`: unite the two when they join (spec §4); `known` is a run of
    /// the entry's row already in the pixel's cluster (its entries skipped).
    #[inline(always)]
    fn visit(&mut self, q: &mut Win, p: &JoinsWith, root: &mut u32, known: &mut u32) {
        if q.run == *known || q.run == NONE {
            return;
        }
        if q.root != *root && self.parent[q.root as usize] != q.root {
            q.root = find(&mut self.parent, q.root);
        }
        if q.root == *root {
            *known = q.run;
        } else if p.joins(q.p) {
            *root = self.union(*root, q.root);
            *known = q.run;
        }
    }

    /// Unite the clusters of runs `a` and `b`; returns the root (the
    /// smaller run index).
    fn union(&mut self, a: u32, b: u32) -> u32 {
        let (ra, rb) = (find(&mut self.parent, a), find(&mut self.parent, b));
        if ra == rb {
            return ra;
        }
        let (root, other) = (ra.min(rb), ra.max(rb));
        debug_assert!(self.id[root as usize] == 0 && self.id[other as usize] == 0);
        self.open_clusters -= 1;
        self.merges += 1;
        let (r, o) = (root as usize, other as usize);
        self.parent[o] = root;
        let moved = self.acc[o];
        self.acc[r].merge(&moved);
        self.labels_held[r] += self.labels_held[o];
        self.ring_held[r] |= self.ring_held[o];
        self.first_px[r] = self.first_px[r].min(self.first_px[o]);
        self.next_px[self.tail[r] as usize] = self.head[o];
        self.tail[r] = self.tail[o];
        root
    }
}

/// The window positions (row, column) of spec §4 whose pairs with pixel
/// `(i, c)` have it as the later pixel in column order: rows `i - h ..= i +
/// h` except `i` in columns `c - h ..= c - 1`, and rows `i - h ..= i - 1` of
/// column `c`, inside a frame of `rows` rows (no wrap), by column then row.
/// What a column core's window presents with the pixel.
pub fn column_window(
    rows: usize,
    h: usize,
    i: usize,
    c: usize,
) -> impl Iterator<Item = (usize, usize)> {
    let lo = i.saturating_sub(h);
    let hi = (i + h + 1).min(rows);
    (c.saturating_sub(h)..=c).flat_map(move |cc| {
        (lo..hi)
            .filter(move |&ii| ii != i && (cc < c || ii < i))
            .map(move |ii| (ii, cc))
    })
}

/// What the stream reports per frame besides the records.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize)]
pub struct StreamStats {
    /// Valid pixels.
    pub points: usize,
    /// Runs that received a provisional label.
    pub runs: u32,
    /// Clusters (records) of the frame.
    pub clusters: u32,
    /// Some run started while every provisional label was in use.
    pub overflow: bool,
    /// Runs left unlabelled by the open limit (spec §9.1), labels being free.
    pub open_refused: u32,
    /// Valid pixels left unlabelled, by label overflow or the open limit.
    pub unlabelled: usize,
    /// Most provisional labels in use at once.
    pub peak_labels: u32,
    /// Most clusters open at once (each holds one or more of the labels in
    /// use): what a record accumulator per open cluster must hold.
    pub peak_open: u32,
    /// Most clusters counted open by the open limit's rule (spec §9.1): an
    /// open limit above it refuses no run.
    pub peak_counted: u32,
    /// Unions of two clusters (pass-2 joins and ring checks between
    /// clusters not yet one), and the most at one column (the frame end's
    /// ring checks as a column of their own): what a core's merge engine
    /// absorbs.
    pub merges: u32,
    pub peak_col_merges: u32,
    /// The most records emitted at one column, and the most labels they
    /// free, before the frame end (whose records free labels the next
    /// frame's start frees anyway): what a core's closing and label return
    /// absorb.
    pub peak_col_closed: u32,
    pub peak_col_freed: u32,
}

impl StreamStats {
    /// The end beat of the frame these stats report (spec §9.4): its
    /// records, and whether a run was refused a label (label overflow or
    /// the open limit); `frame_error` is the input's framing, the caller's.
    pub fn frame_end(&self) -> FrameEnd {
        FrameEnd {
            records: self.clusters,
            overflow: self.overflow || self.open_refused > 0,
            frame_error: false,
        }
    }
}

/// The golden stream. Make one with [`Stream::new`], then per frame call
/// [`push_column`](Self::push_column) for columns `0 .. C-1` and
/// [`finish`](Self::finish); the next push starts the next frame.
#[derive(Debug, Clone)]
pub struct Stream {
    params: FccParams,
    /// Frames finished so far: the `frame` of the current frame's records.
    frame: u64,
    /// Columns taken in the current frame.
    col: usize,
    /// The current frame has been finished (its labels can be read).
    finished: bool,
    first: Vec<Option<Seen>>,
    latest: Vec<Option<Seen>>,
    /// The last h + 1 columns, `h + 1` entries per row (row `i`, column `c`
    /// at `i * (h + 1) + c % (h + 1)`), so that the window columns of one
    /// row are adjacent.
    win: Vec<Win>,
    /// Per row, the run of its window columns before the current one when
    /// they hold one run ([`MIXED`] for more, [`NONE`] for none), with a
    /// node of its set.
    older: Vec<Win>,
    /// The runs' sets: union-find, records, pixel lists.
    sets: Sets,
    /// Per run: hold stamp.
    held: Vec<u32>,
    /// Per pixel (raster order): its run, its point (when labelled).
    pixel_run: Vec<u32>,
    pixel_point: Vec<Point>,
    /// Roots of the open clusters (and roots merged away, dropped lazily).
    open: Vec<u32>,
    closing: Vec<(u32, u32)>,
    in_use: u32,
    /// Clusters open after the previous column closed, plus the runs
    /// labelled in this column: what the open limit counts (spec §9.1).
    counted_open: u32,
    /// Unions of the frame before the current column.
    merges_before: u32,
    stats: StreamStats,
    out: Vec<Record>,
    out_points: Vec<Point>,
    /// The pixels (raster index) of `out_points`, in the same order.
    out_pixels: Vec<u32>,
    out_ranges: Vec<(usize, usize)>,
}

impl Stream {
    /// A stream for frames of `params.rows` x `params.cols`.
    pub fn new(params: &FccParams) -> Result<Stream, GoldenError> {
        params.validate()?;
        let (r, n) = (params.rows, params.pixels());
        Ok(Stream {
            params: params.clone(),
            frame: 0,
            col: 0,
            finished: false,
            first: vec![None; r],
            latest: vec![None; r],
            win: vec![Win::EMPTY; r * (params.half() + 1)],
            older: vec![Win::EMPTY; r],
            sets: Sets {
                parent: Vec::new(),
                acc: Vec::new(),
                labels_held: Vec::new(),
                head: Vec::new(),
                tail: Vec::new(),
                first_px: Vec::new(),
                id: Vec::new(),
                ring_held: Vec::new(),
                next_px: vec![NONE; n],
                open_clusters: 0,
                merges: 0,
            },
            held: Vec::new(),
            pixel_run: vec![NONE; n],
            pixel_point: vec![[0; 3]; n],
            open: Vec::new(),
            closing: Vec::new(),
            in_use: 0,
            counted_open: 0,
            merges_before: 0,
            stats: StreamStats::default(),
            out: Vec::new(),
            out_points: Vec::new(),
            out_pixels: Vec::new(),
            out_ranges: Vec::new(),
        })
    }

    /// The parameters of this stream.
    pub fn params(&self) -> &FccParams {
        &self.params
    }

    /// Columns taken in the current frame.
    pub fn columns_taken(&self) -> usize {
        if self.finished {
            0
        } else {
            self.col
        }
    }

    /// Take the next column (`R` pixels, row 0 first) and return the records
    /// of the clusters that closed at it, in id order.
    pub fn push_column(&mut self, column: &[Option<Point>]) -> Result<&[Record], GoldenError> {
        let (rows, cols) = (self.params.rows, self.params.cols);
        if column.len() != rows {
            return Err(GoldenError::ColumnLength {
                rows,
                got: column.len(),
            });
        }
        if self.finished {
            self.start_frame();
        }
        if self.col == cols {
            return Err(GoldenError::TooManyColumns { cols });
        }
        let c = self.col;
        self.out.clear();
        self.out_points.clear();
        self.out_pixels.clear();
        self.out_ranges.clear();
        self.take_column(c, column);
        self.col = c + 1;
        self.close_unheld(c);
        Ok(&self.out)
    }

    /// End the frame after its `C` columns: apply the ring checks and return
    /// the records of every cluster still open (`closed_col = C`).
    pub fn finish(&mut self) -> Result<&[Record], GoldenError> {
        let (rows, cols) = (self.params.rows, self.params.cols);
        let taken = self.columns_taken();
        if taken != cols {
            return Err(GoldenError::Unfinished { cols, got: taken });
        }
        self.out.clear();
        self.out_points.clear();
        self.out_pixels.clear();
        self.out_ranges.clear();
        self.merges_before = self.sets.merges;
        for i in 0..rows {
            let (Some(f), Some(l)) = (self.first[i], self.latest[i]) else {
                continue;
            };
            if f.run == NONE
                || l.run == NONE
                || f.run == l.run
                || !self.params.ring_reaches(f.col as usize, l.col as usize)
                || !Thresholds::new(&self.params).continues(f.p, l.p)
            {
                continue;
            }
            let root = self.sets.union(f.run, l.run);
            self.sets.acc[root as usize].seam = true;
        }
        self.closing.clear();
        for k in 0..self.open.len() {
            let x = self.open[k];
            if self.sets.parent[x as usize] == x {
                self.closing.push((self.sets.first_px[x as usize], x));
            }
        }
        self.open.clear();
        self.emit(cols as u32);
        debug_assert_eq!(
            self.sets.open_clusters, 0,
            "every open cluster closes at the frame end"
        );
        self.finished = true;
        self.frame += 1;
        Ok(&self.out)
    }

    /// The records of the last [`push_column`](Self::push_column) or
    /// [`finish`](Self::finish) (what it returned).
    pub fn closed(&self) -> &[Record] {
        &self.out
    }

    /// The points of the `k`-th record of the last call's result.
    pub fn points_of(&self, k: usize) -> &[Point] {
        let (a, b) = self.out_ranges[k];
        &self.out_points[a..b]
    }

    /// The pixels (raster index `row * C + col`) of the `k`-th record of
    /// the last call's result, in the order of [`points_of`](Self::points_of).
    pub fn pixels_of(&self, k: usize) -> &[u32] {
        let (a, b) = self.out_ranges[k];
        &self.out_pixels[a..b]
    }

    /// The clusters open now: after the last column taken closed (spec
    /// §9.2), before the next. Spec §9.1's open limit counts these, plus the
    /// runs labelled in the next column.
    pub fn open_clusters(&self) -> u32 {
        if self.finished {
            0
        } else {
            self.sets.open_clusters
        }
    }

    /// What the finished frame (or the frame so far) reported.
    pub fn stats(&self) -> StreamStats {
        self.stats
    }

    /// The finished frame's end beat (spec §9.4): its records, and whether
    /// a run was refused a label (label overflow or the open limit). The
    /// input's framing is the caller's: `frame_error` is false. `None` until
    /// the frame is finished.
    pub fn frame_end(&self) -> Option<FrameEnd> {
        self.finished.then_some(self.stats.frame_end())
    }

    /// The label image of the finished frame, raster order, numbered by
    /// record id (0 for empty and unlabelled pixels). Valid until the next
    /// push.
    pub fn labels_into(&mut self, out: &mut Vec<u32>) -> Result<(), GoldenError> {
        if !self.finished {
            return Err(GoldenError::Unfinished {
                cols: self.params.cols,
                got: self.col,
            });
        }
        out.clear();
        out.reserve(self.pixel_run.len());
        for k in 0..self.pixel_run.len() {
            let r = self.pixel_run[k];
            out.push(if r == NONE {
                0
            } else {
                let root = self.find(r);
                self.sets.id[root as usize]
            });
        }
        Ok(())
    }

    /// The runs of pass 1 (spec §3) in the finished frame, raster order:
    /// each labelled pixel's run numbered 1, 2, ... in the order the runs
    /// started (column order, the order their labels were taken), 0 for
    /// empty and unlabelled pixels. Valid until the next push.
    pub fn runs_into(&self, out: &mut Vec<u32>) -> Result<(), GoldenError> {
        if !self.finished {
            return Err(GoldenError::Unfinished {
                cols: self.params.cols,
                got: self.col,
            });
        }
        out.clear();
        out.extend(
            self.pixel_run
                .iter()
                .map(|&r| if r == NONE { 0 } else { r + 1 }),
        );
        Ok(())
    }

    fn start_frame(&mut self) {
        self.finished = false;
        self.col = 0;
        self.first.fill(None);
        self.latest.fill(None);
        for v in [
            &mut self.sets.parent,
            &mut self.sets.labels_held,
            &mut self.sets.head,
            &mut self.sets.tail,
            &mut self.sets.first_px,
            &mut self.sets.id,
            &mut self.held,
        ] {
            v.clear();
        }
        self.sets.acc.clear();
        self.sets.ring_held.clear();
        self.sets.open_clusters = 0;
        self.sets.merges = 0;
        self.merges_before = 0;
        // The window's columns before column 0 are empty.
        self.win.fill(Win::EMPTY);
        self.pixel_run.fill(NONE);
        self.open.clear();
        self.in_use = 0;
        self.stats = StreamStats::default();
    }

    #[inline]
    fn find(&mut self, x: u32) -> u32 {
        find(&mut self.sets.parent, x)
    }

    /// A new run starting at column-order pixel `key`, if a label is free
    /// and the open limit allows it.
    fn new_run(&mut self, key: u32) -> u32 {
        if self.in_use >= self.params.max_label() {
            self.stats.overflow = true;
            return NONE;
        }
        if !self.params.opens(self.counted_open) {
            self.stats.open_refused += 1;
            return NONE;
        }
        self.counted_open += 1;
        self.stats.peak_counted = self.stats.peak_counted.max(self.counted_open);
        self.in_use += 1;
        self.stats.peak_labels = self.stats.peak_labels.max(self.in_use);
        self.sets.open_clusters += 1;
        self.stats.peak_open = self.stats.peak_open.max(self.sets.open_clusters);
        self.stats.runs += 1;
        let run = self.sets.parent.len() as u32;
        self.sets.parent.push(run);
        self.sets.acc.push(Acc::default());
        self.sets.labels_held.push(1);
        self.sets.head.push(NONE);
        self.sets.tail.push(NONE);
        self.sets.first_px.push(key);
        self.held.push(0);
        self.sets.id.push(0);
        self.sets.ring_held.push(false);
        self.open.push(run);
        run
    }

    /// Pass 1 and pass 2 for the pixels of column `c`.
    fn take_column(&mut self, c: usize, column: &[Option<Point>]) {
        let (rows, cols) = (self.params.rows, self.params.cols);
        let h = self.params.half();
        let w = h + 1;
        let th = Thresholds::new(&self.params);
        let half = (cols / 2) as u32;
        let slot = c % w;
        self.counted_open = self.sets.open_clusters;
        self.merges_before = self.sets.merges;
        for (row, o) in self.win.chunks_exact_mut(w).zip(&mut self.older) {
            // Column c's slot is emptied for the column's pixels; the rest
            // are the row's columns c - h .. c - 1. Their one run, if they
            // hold one (any of its entries: each keeps a node of its set).
            row[slot].run = NONE;
            *o = Win::EMPTY;
            for q in row.iter() {
                if q.run == NONE || q.run == o.run {
                    continue;
                }
                if o.run != NONE {
                    o.run = MIXED;
                    break;
                }
                *o = *q;
            }
        }
        for (i, p) in column.iter().enumerate() {
            let Some(p) = *p else { continue };
            self.stats.points += 1;
            let run = match self.latest[i] {
                Some(q) if self.params.bridges(c - q.col as usize - 1) && th.continues(p, q.p) => {
                    q.run
                }
                _ => self.new_run((c * rows + i) as u32),
            };
            let seen = Seen {
                col: c as u32,
                p,
                run,
            };
            self.latest[i] = Some(seen);
            let row_first = self.first[i].is_none();
            if row_first {
                self.first[i] = Some(seen);
            }
            let k = i * cols + c;
            self.pixel_run[k] = run;
            if run == NONE {
                self.stats.unlabelled += 1;
                continue;
            }
            let mut root = self.find(run);
            let r = root as usize;
            if row_first && self.params.ring_reaches(c, cols - 1) {
                self.sets.ring_held[r] = true;
            }
            self.sets.acc[r].add_in_scan(i as u32, c as u32, p, half);
            self.pixel_point[k] = p;
            self.sets.next_px[k] = NONE;
            if self.sets.head[r] == NONE {
                self.sets.head[r] = k as u32;
            } else {
                self.sets.next_px[self.sets.tail[r] as usize] = k as u32;
            }
            self.sets.tail[r] = k as u32;
            // The window pairs whose later pixel this is: columns c - h ..= c,
            // rows within h (in column c only the rows above are filled;
            // before column 0 the window is empty), each row's entries from
            // column c back to c - h. A row's entries mostly belong to one
            // run: once a run is known to be in this pixel's cluster, its
            // other pixels are skipped, and when the row's older columns
            // hold one run already in it, all of them are.
            let (lo, end) = (i.saturating_sub(h), (i + h + 1).min(rows));
            let pj = th.joins_with(p);
            for rr in lo..i {
                self.window_row::<true>(rr, w, slot, &pj, &mut root);
            }
            for rr in i + 1..end {
                self.window_row::<false>(rr, w, slot, &pj, &mut root);
            }
            self.win[i * w + slot] = Win { run, root, p };
        }
    }

    /// The window pairs of a pixel at `p` (cluster `root`) with row `rr`'s
    /// `w` entries: its current column's (slot `slot`) when the row is
    /// `ABOVE` the pixel, then its older columns' unless they hold no run or one
    /// run already in the pixel's cluster.
    #[inline(always)]
    fn window_row<const ABOVE: bool>(
        &mut self,
        rr: usize,
        w: usize,
        slot: usize,
        p: &JoinsWith,
        root: &mut u32,
    ) {
        let base = rr * w;
        let mut known = NONE;
        if ABOVE {
            let q = &mut self.win[base + slot];
            self.sets.visit(q, p, root, &mut known);
        }
        let o = &mut self.older[rr];
        if o.run == NONE || o.run == known {
            return;
        }
        if o.run != MIXED {
            if o.root != *root && self.sets.parent[o.root as usize] != o.root {
                o.root = find(&mut self.sets.parent, o.root);
            }
            if o.root == *root {
                return;
            }
        }
        // Columns c - 1 down to c - h: slots `slot - 1` down to 0, then
        // w - 1 down to `slot + 1`.
        let (newer, older) = self.win[base..base + w].split_at_mut(slot);
        for q in newer.iter_mut().rev() {
            self.sets.visit(q, p, root, &mut known);
        }
        for q in older[1..].iter_mut().rev() {
            self.sets.visit(q, p, root, &mut known);
        }
    }

    /// Close every open cluster that no hold of spec §9.2 keeps after
    /// column `c`.
    fn close_unheld(&mut self, c: usize) {
        let cols = self.params.cols;
        let h = self.params.half();
        let last = c + 1 == cols;
        let stamp = c as u32 + 1;
        for i in 0..self.params.rows {
            // Hold 3 is the sets' `ring_held`.
            let first = self.first[i].filter(|f| f.run != NONE);
            let Some(l) = self.latest[i].filter(|l| l.run != NONE) else {
                continue;
            };
            // Hold 2: the next pixel of the row may continue the run.
            let bridge = !last && self.params.bridges(c - l.col as usize);
            // Hold 4: this pixel may turn out to be the row's last.
            let ring =
                first.is_some_and(|f| self.params.ring_reaches(f.col as usize, l.col as usize));
            if bridge || ring {
                let r = self.find(l.run);
                self.held[r as usize] = stamp;
            }
        }
        self.closing.clear();
        let mut k = 0;
        while k < self.open.len() {
            let x = self.open[k] as usize;
            if self.sets.parent[x] != x as u32 {
                self.open.swap_remove(k);
                continue;
            }
            // Hold 1: a pixel within h columns of the next column.
            let window = !last && self.sets.acc[x].max_col as usize + h > c;
            if window || self.held[x] == stamp || self.sets.ring_held[x] {
                k += 1;
                continue;
            }
            self.closing.push((self.sets.first_px[x], x as u32));
            self.open.swap_remove(k);
        }
        self.emit(c as u32);
    }

    /// Emit the records of `self.closing`, by first pixel in column order.
    /// Called once per column and at the frame end.
    fn emit(&mut self, closed_col: u32) {
        let st = &mut self.stats;
        st.merges = self.sets.merges;
        st.peak_col_merges = st
            .peak_col_merges
            .max(self.sets.merges - self.merges_before);
        // The frame end's records free labels the next frame's start frees
        // anyway: the column peaks count the columns' closes only.
        if (closed_col as usize) < self.params.cols {
            st.peak_col_closed = st.peak_col_closed.max(self.closing.len() as u32);
            let freed: u32 = self
                .closing
                .iter()
                .map(|&(_, root)| self.sets.labels_held[root as usize])
                .sum();
            st.peak_col_freed = st.peak_col_freed.max(freed);
        }
        self.closing.sort_unstable();
        for k in 0..self.closing.len() {
            let root = self.closing[k].1 as usize;
            self.stats.clusters += 1;
            let id = self.stats.clusters;
            self.sets.id[root] = id;
            self.in_use -= self.sets.labels_held[root];
            self.sets.open_clusters -= 1;
            self.out
                .push(self.sets.acc[root].record(self.frame, id, closed_col));
            let start = self.out_points.len();
            let mut px = self.sets.head[root];
            while px != NONE {
                self.out_points.push(self.pixel_point[px as usize]);
                self.out_pixels.push(px);
                px = self.sets.next_px[px as usize];
            }
            self.out_ranges.push((start, self.out_points.len()));
        }
    }
}
