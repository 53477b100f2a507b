//! A plain, slow, pixel-level union-find reading of the contract, written
//! independently of the passes. Tests (and only tests) compare against it.

use crate::frame::{dist2, Frame, Point};
use fcc_params::FccParams;

struct Dsu(Vec<usize>);

impl Dsu {
    fn find(&mut self, x: usize) -> usize {
        let mut r = x;
        while self.0[r] != r {
            r = self.0[r];
        }
        let mut x = x;
        while self.0[x] != r {
            let n = self.0[x];
            self.0[x] = r;
            x = n;
        }
        r
    }
    fn union(&mut self, a: usize, b: usize) {
        let (a, b) = (self.find(a), self.find(b));
        if a != b {
            self.0[a.max(b)] = a.min(b);
        }
    }
}

/// A pair's squared threshold by spec §2, `max(t^2, (S * min rc2) >> 8)`,
/// written from the definitions (whole metres per coordinate, rounded half
/// up and capped at 127).
fn pair_threshold(t_sq: i64, slope_sq: u64, p: Point, q: Point) -> i64 {
    let metres = |c: i16| ((i64::from(c).abs() + 128) / 256).min(127);
    let rc2 = |v: Point| v.iter().map(|&c| metres(c).pow(2)).sum::<i64>() as u128;
    let own = (u128::from(slope_sq) * rc2(p).min(rc2(q))) >> 8;
    t_sq.max(own as i64)
}

/// Final labels by the contract, straight from the definitions: pixels are
/// the nodes, each rule adds edges, components are numbered by first pixel.
pub fn reference_labels(params: &FccParams, frame: &Frame) -> Vec<u32> {
    let (rows, cols) = (frame.rows, frame.cols);
    let n = rows * cols;
    let idx = |r: usize, c: usize| r * cols + c;
    let h_ok = |p: Point, q: Point| {
        dist2(p, q) <= pair_threshold(params.th_h_sq(), params.th_h_slope_sq(), p, q)
    };
    let v_ok = |p: Point, q: Point| {
        dist2(p, q) < pair_threshold(params.th_v_sq(), params.th_v_slope_sq(), p, q)
    };
    // Which pixels are labelled: count run starts in raster order.
    let mut labelled = vec![false; n];
    let mut runs = 0u64;
    for r in 0..rows {
        let mut prev = None;
        let mut on = false;
        for c in 0..cols {
            if let Some(p) = frame.get(r, c) {
                let cont = matches!(prev, Some((b, q)) if params.bridges(c - b - 1) && h_ok(p, q));
                if !cont {
                    runs += 1;
                    on = runs <= u64::from(params.max_label());
                }
                labelled[idx(r, c)] = on;
                prev = Some((c, p));
            }
        }
    }
    let mut dsu = Dsu((0..n).collect());
    for r in 0..rows {
        let valid: Vec<usize> = (0..cols).filter(|&c| frame.get(r, c).is_some()).collect();
        for w in valid.windows(2) {
            let (a, b) = (idx(r, w[0]), idx(r, w[1]));
            if labelled[a]
                && labelled[b]
                && params.bridges(w[1] - w[0] - 1)
                && h_ok(frame.get(r, w[0]).unwrap(), frame.get(r, w[1]).unwrap())
            {
                dsu.union(a, b);
            }
        }
        if valid.len() >= 2 {
            let (f, l) = (valid[0], valid[valid.len() - 1]);
            let (a, b) = (idx(r, f), idx(r, l));
            if labelled[a]
                && labelled[b]
                && params.ring_reaches(f, l)
                && h_ok(frame.get(r, f).unwrap(), frame.get(r, l).unwrap())
            {
                dsu.union(a, b);
            }
        }
    }
    let h = params.half() as isize;
    for r in 0..rows {
        for c in 0..cols {
            let a = idx(r, c);
            if !labelled[a] {
                continue;
            }
            for m in 1..=h {
                for dn in -h..=h {
                    let (rr, cc) = (r as isize - m, c as isize + dn);
                    if rr < 0 || cc < 0 || cc >= cols as isize {
                        continue;
                    }
                    let b = idx(rr as usize, cc as usize);
                    if labelled[b] && v_ok(frame.points[a].unwrap(), frame.points[b].unwrap()) {
                        dsu.union(a, b);
                    }
                }
            }
        }
    }
    let mut id = vec![0u32; n];
    let mut next = 0;
    (0..n)
        .map(|a| {
            if !labelled[a] {
                return 0;
            }
            let r = dsu.find(a);
            if id[r] == 0 {
                next += 1;
                id[r] = next;
            }
            id[r]
        })
        .collect()
}
