//! The sweep's status: the polygon edges the sweep line crosses with the polygon to their east,
//! in west-to-east order, as a splay tree (amortised O(log n) per operation, whatever the order
//! of the operations). An edge is named by its upper corner. Edges are placed by a test against
//! a corner, never by comparing two edges, and removed by name: a test that contradicts itself
//! (a polygon that crosses itself) can misplace an edge but never corrupt the tree.

const NONE: u32 = u32::MAX;

#[derive(Debug, Default)]
pub(super) struct SweepStatus {
    left: Vec<u32>,
    right: Vec<u32>,
    parent: Vec<u32>,
    root: u32,
}

impl SweepStatus {
    /// An empty status for edges named `0..n`.
    pub(super) fn reset(&mut self, n: usize) {
        for links in [&mut self.left, &mut self.right, &mut self.parent] {
            links.clear();
            links.resize(n, NONE);
        }
        self.root = NONE;
    }

    /// The easternmost edge for which `is_west(edge)` holds, when the edges west of the point
    /// asked about come first in the tree (as they do while the status is consistent).
    pub(super) fn last_west_of(&mut self, mut is_west: impl FnMut(u32) -> bool) -> Option<u32> {
        let (mut node, mut last, mut found) = (self.root, NONE, None);
        while node != NONE {
            last = node;
            if is_west(node) {
                found = Some(node);
                node = self.right[node as usize];
            } else {
                node = self.left[node as usize];
            }
        }
        if last != NONE {
            // Splaying the deepest node visited pays for the walk down.
            self.splay(last);
        }
        found
    }

    /// Inserts `edge` just east of `after`, or westernmost when `after` is `None`.
    pub(super) fn insert_after(&mut self, after: Option<u32>, edge: u32) {
        let e = edge as usize;
        match after {
            Some(a) => {
                self.splay(a);
                let east = self.right[a as usize];
                self.left[e] = a;
                self.right[e] = east;
                self.parent[a as usize] = edge;
                if east != NONE {
                    self.parent[east as usize] = edge;
                }
                self.right[a as usize] = NONE;
            }
            None => {
                self.left[e] = NONE;
                self.right[e] = self.root;
                if self.root != NONE {
                    self.parent[self.root as usize] = edge;
                }
            }
        }
        self.parent[e] = NONE;
        self.root = edge;
    }

    /// Removes `edge`, which must be in the status.
    pub(super) fn remove(&mut self, edge: u32) {
        self.splay(edge);
        let e = edge as usize;
        let (west, east) = (self.left[e], self.right[e]);
        self.left[e] = NONE;
        self.right[e] = NONE;
        if west == NONE {
            self.root = east;
            if east != NONE {
                self.parent[east as usize] = NONE;
            }
            return;
        }
        // The easternmost edge of the west part becomes its root, then takes the east part.
        self.parent[west as usize] = NONE;
        let mut last = west;
        while self.right[last as usize] != NONE {
            last = self.right[last as usize];
        }
        self.splay(last);
        self.right[last as usize] = east;
        if east != NONE {
            self.parent[east as usize] = last;
        }
        self.root = last;
    }

    /// The edges in west-to-east order (tests only).
    #[cfg(test)]
    fn in_order(&self) -> Vec<u32> {
        let (mut out, mut stack, mut node) = (Vec::new(), Vec::new(), self.root);
        while node != NONE || !stack.is_empty() {
            while node != NONE {
                stack.push(node);
                node = self.left[node as usize];
            }
            let top = stack.pop().expect("the loop condition");
            out.push(top);
            node = self.right[top as usize];
        }
        out
    }

    /// Moves `x` to the root of its tree (the tree whose root has no parent).
    fn splay(&mut self, x: u32) {
        loop {
            let p = self.parent[x as usize];
            if p == NONE {
                break;
            }
            let g = self.parent[p as usize];
            if g != NONE {
                let zig_zig = (self.left[g as usize] == p) == (self.left[p as usize] == x);
                self.rotate(if zig_zig { p } else { x });
            }
            self.rotate(x);
        }
        self.root = x;
    }

    /// Rotates `x` above its parent.
    fn rotate(&mut self, x: u32) {
        let p = self.parent[x as usize];
        let g = self.parent[p as usize];
        if self.left[p as usize] == x {
            let moved = self.right[x as usize];
            self.left[p as usize] = moved;
            if moved != NONE {
                self.parent[moved as usize] = p;
            }
            self.right[x as usize] = p;
        } else {
            let moved = self.left[x as usize];
            self.right[p as usize] = moved;
            if moved != NONE {
                self.parent[moved as usize] = p;
            }
            self.left[x as usize] = p;
        }
        self.parent[p as usize] = x;
        self.parent[x as usize] = g;
        if g != NONE {
            if self.left[g as usize] == p {
                self.left[g as usize] = x;
            } else {
                self.right[g as usize] = x;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A status of integer keys standing for edges at those x positions, checked against a
    /// sorted vector through a scripted sequence of inserts, searches and removals.
    #[test]
    fn keeps_order_through_inserts_searches_and_removals() {
        let n = 200u32;
        let mut status = SweepStatus::default();
        status.reset(n as usize);
        let x = |e: u32| (e * 73) % 211; // distinct positions
        let mut expected: Vec<u32> = Vec::new();
        for e in 0..n {
            let after = status.last_west_of(|other| x(other) < x(e));
            status.insert_after(after, e);
            let at = expected.partition_point(|&o| x(o) < x(e));
            expected.insert(at, e);
            if e % 3 == 2 {
                let gone = expected.remove((e as usize * 7) % expected.len());
                status.remove(gone);
            }
            assert_eq!(status.in_order(), expected);
        }
        for probe in 0..211 {
            let found = status.last_west_of(|e| x(e) < probe);
            let want = expected.iter().rev().find(|&&e| x(e) < probe).copied();
            assert_eq!(found, want);
        }
        while let Some(e) = expected.pop() {
            status.remove(e);
            assert_eq!(status.in_order(), expected);
        }
    }

    #[test]
    fn a_self_contradicting_test_never_breaks_the_tree() {
        let mut status = SweepStatus::default();
        status.reset(64);
        let mut flip = 0u32;
        for e in 0..64 {
            let after = status.last_west_of(|_| {
                flip = flip.wrapping_mul(1_103_515_245).wrapping_add(12_345);
                flip & 0x100 != 0
            });
            status.insert_after(after, e);
        }
        let mut all = status.in_order();
        all.sort_unstable();
        assert_eq!(all, (0..64).collect::<Vec<_>>());
        for e in (0..64).step_by(2) {
            status.remove(e);
        }
        let mut odd = status.in_order();
        odd.sort_unstable();
        assert_eq!(odd, (1..64).step_by(2).collect::<Vec<_>>());
    }
}
