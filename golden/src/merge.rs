//! Pass 3: the merge table and label update (spec §5 and §7).

use crate::pass1::Pass1;
use crate::pass2::JoinSink;

/// Exact connected components: a union-find over provisional labels with
/// path halving, linking the larger root under the smaller, so every root
/// is the smallest label of its component (its first run in raster order).
#[derive(Debug, Clone, Default)]
pub struct ExactMerge {
    parent: Vec<u32>,
    /// Joins that united two different components.
    pub merges: u64,
}

impl ExactMerge {
    /// A table for labels `1 ..= provisional` (entry 0 is unused).
    pub fn new(provisional: u32) -> Self {
        ExactMerge {
            parent: (0..=provisional).collect(),
            merges: 0,
        }
    }

    /// Start again with labels `1 ..= provisional`, keeping the allocation.
    pub fn reset(&mut self, provisional: u32) {
        self.parent.clear();
        self.parent.extend(0..=provisional);
        self.merges = 0;
    }

    /// The root (smallest label) of `l`'s component, halving the path.
    pub fn find(&mut self, mut l: u32) -> u32 {
        while self.parent[l as usize] != l {
            let grand = self.parent[self.parent[l as usize] as usize];
            self.parent[l as usize] = grand;
            l = grand;
        }
        l
    }

    /// Join the components of `a` and `b`.
    pub fn union(&mut self, a: u32, b: u32) {
        let (ra, rb) = (self.find(a), self.find(b));
        if ra != rb {
            self.link_roots(ra, rb);
        }
    }

    /// Link two different roots, the larger under the smaller.
    pub(crate) fn link_roots(&mut self, ra: u32, rb: u32) {
        debug_assert!(ra != rb && self.parent[ra as usize] == ra && self.parent[rb as usize] == rb);
        let (lo, hi) = if ra < rb { (ra, rb) } else { (rb, ra) };
        self.parent[hi as usize] = lo;
        self.merges += 1;
    }

    /// Point every label straight at its root and return the roots, as
    /// [`representatives`](Self::representatives) without consuming the table.
    pub fn flatten(&mut self) -> &[u32] {
        // A parent is smaller than its child, so it is already flattened.
        for l in 0..self.parent.len() {
            let p = self.parent[l] as usize;
            self.parent[l] = self.parent[p];
        }
        &self.parent
    }

    /// Representative of every label: `rep[l]` is the root of `l`.
    pub fn representatives(mut self) -> Vec<u32> {
        (0..self.parent.len() as u32)
            .map(|l| self.find(l))
            .collect()
    }
}

impl JoinSink for ExactMerge {
    #[inline]
    fn centre(&mut self, _label: u32) {}
    #[inline]
    fn join(&mut self, centre: u32, other: u32) {
        // Most joins repeat one already made: equal parents mean one set.
        if self.parent[centre as usize] != self.parent[other as usize] {
            self.union(centre, other);
        }
    }
    #[inline]
    fn row_end(&mut self) {}
}

/// The merge table of the published Algorithm 2, kept so its losses can be
/// reproduced and measured (spec §6). Not connected components in general.
#[derive(Debug, Clone, Default)]
pub struct PaperMerge {
    table: Vec<u32>,
    current: u32,
    collected: Vec<u32>,
}

impl PaperMerge {
    /// `T[l] = l` for labels `0 ..= provisional`.
    pub fn new(provisional: u32) -> Self {
        let mut m = PaperMerge::default();
        m.reset(provisional);
        m
    }

    /// Start again with `T[l] = l` for labels `0 ..= provisional`, keeping
    /// the buffers (no allocation once they have grown).
    pub fn reset(&mut self, provisional: u32) {
        self.table.clear();
        self.table.extend(0..=provisional);
        self.current = 0;
        self.collected.clear();
    }

    fn collect(&mut self, l: u32) {
        let t = self.table[l as usize];
        if !self.collected.contains(&t) {
            self.collected.push(t);
        }
    }

    /// `T[L] = T[min]` for every collected L, in ascending order.
    fn flush(&mut self) {
        if self.collected.is_empty() {
            return;
        }
        self.collected.sort_unstable();
        let target = self.table[self.collected[0] as usize];
        for &l in &self.collected {
            self.table[l as usize] = target;
        }
        self.collected.clear();
    }

    /// The output lookup `T[T[l]]` of every label.
    pub fn representatives(mut self) -> Vec<u32> {
        let mut rep = Vec::new();
        self.representatives_into(&mut rep);
        rep
    }

    /// As [`representatives`](Self::representatives), into `rep`'s buffer.
    pub fn representatives_into(&mut self, rep: &mut Vec<u32>) {
        self.flush();
        let t = &self.table;
        rep.clear();
        rep.extend(t.iter().map(|&l| t[l as usize]));
    }
}

impl JoinSink for PaperMerge {
    fn centre(&mut self, label: u32) {
        if label != self.current {
            self.flush();
            self.current = label;
        }
    }
    fn join(&mut self, centre: u32, other: u32) {
        self.collect(centre);
        self.collect(other);
    }
    fn row_end(&mut self) {
        self.flush();
        self.current = 0;
    }
}

/// Final labels: 0 for unlabelled pixels, otherwise the representatives
/// numbered 1..N in raster order of their first pixel. Returns (labels, N).
pub fn renumber(provisional_labels: &[u32], rep: &[u32]) -> (Vec<u32>, u32) {
    let mut id = vec![0u32; rep.len()];
    let mut n = 0u32;
    let labels = provisional_labels
        .iter()
        .map(|&l| {
            if l == 0 {
                return 0;
            }
            let r = rep[l as usize] as usize;
            if id[r] == 0 {
                n += 1;
                id[r] = n;
            }
            id[r]
        })
        .collect();
    (labels, n)
}

/// [`renumber`] run by run, in place: the provisional labels of `p1` become
/// the final labels. Returns the number of clusters.
/// `id` is scratch space.
pub(crate) fn renumber_runs(p1: &mut Pass1, cols: usize, rep: &[u32], id: &mut Vec<u32>) -> u32 {
    id.clear();
    id.resize(rep.len(), 0);
    let mut n = 0u32;
    for (i, bounds) in p1.row_runs.windows(2).enumerate() {
        for run in &p1.runs[bounds[0]..bounds[1]] {
            let r = rep[run.label as usize] as usize;
            if id[r] == 0 {
                n += 1;
                id[r] = n;
            }
            let v = id[r];
            let row = i * cols;
            // Between its ends a run's row holds only its own pixels and
            // empty ones.
            for l in &mut p1.labels[row + run.first as usize..=row + run.last as usize] {
                if *l != 0 {
                    *l = v;
                }
            }
        }
    }
    n
}
