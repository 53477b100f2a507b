//! The union-find over labels as the column core's benches model it
//! (`FccLabelSets`' contract): a forest over labels, each root with its
//! record slot; on a join the second label's root kept when the first is
//! a run just started filed under the second's cluster (`under`), else the
//! smaller root; each
//! open cluster's labels, so that a bench can close it.

pub struct Forest {
    pub parent: Vec<u16>,
    pub slot: Vec<u16>,
    pub made: Vec<bool>,
    /// Per open cluster: its labels, the first its first made.
    pub clusters: Vec<Vec<u16>>,
    /// The longest walk seen, and the words read by all (one a node).
    pub walk_max: u32,
    pub reads: u64,
}

impl Forest {
    /// No label made, of `1 ..= labels`.
    pub fn new(labels: usize) -> Forest {
        Forest {
            parent: vec![0; labels + 1],
            slot: vec![0; labels + 1],
            made: vec![false; labels + 1],
            clusters: Vec::new(),
            walk_max: 0,
            reads: 0,
        }
    }

    /// The root of `x`'s set (which must be made), counting the words read.
    pub fn root(&mut self, mut x: u16) -> u16 {
        assert!(self.made[x as usize], "the bench names label {x}, not made");
        let mut reads = 1;
        while self.parent[x as usize] != x {
            x = self.parent[x as usize];
            reads += 1;
        }
        self.walk_max = self.walk_max.max(reads);
        self.reads += u64::from(reads);
        x
    }

    /// The words a walk from `x` to its root reads (uncounted).
    pub fn depth(&self, mut x: u16) -> u64 {
        let mut words = 1;
        while self.parent[x as usize] != x {
            x = self.parent[x as usize];
            words += 1;
        }
        words
    }

    /// Label `l` made a cluster of its own, with slot `s`.
    pub fn make(&mut self, l: u16, s: u16) {
        self.parent[l as usize] = l;
        self.slot[l as usize] = s;
        self.made[l as usize] = true;
        self.clusters.push(vec![l]);
    }

    fn cluster_of(&mut self, l: u16) -> usize {
        let r = self.root(l);
        (0..self.clusters.len())
            .find(|&c| self.root(self.clusters[c][0]) == r)
            .expect("every made label is in a cluster")
    }

    /// The sets of `a` and `b` united: the root kept (`b`'s with `under`,
    /// else the smaller), the root gone and whether they were two.
    pub fn join(&mut self, a: u16, b: u16, under: bool) -> (u16, u16, bool) {
        let (ra, rb) = (self.root(a), self.root(b));
        let (keep, gone) = if under || rb < ra { (rb, ra) } else { (ra, rb) };
        if ra != rb {
            let (ck, cg) = (self.cluster_of(keep), self.cluster_of(gone));
            let moved = std::mem::take(&mut self.clusters[cg]);
            self.clusters[ck].extend(moved);
            self.clusters.swap_remove(cg);
            self.parent[gone as usize] = keep;
        }
        (keep, gone, ra != rb)
    }

    /// Cluster `c` closed: its labels, no longer made, and its slot.
    pub fn close(&mut self, c: usize) -> (Vec<u16>, u16) {
        let labels = self.clusters.swap_remove(c);
        let r = self.root(labels[0]);
        let s = self.slot[r as usize];
        for &l in &labels {
            self.made[l as usize] = false;
        }
        (labels, s)
    }
}
