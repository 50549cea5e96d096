//! A tree of points split at medians, for the points near a segment: the T-vertex search's
//! index, whose cost follows the points near each segment, not the segment's length.

use super::measure::bounding_box;

/// Points split recursively at the median of their widest axis, each node holding its box.
pub(crate) struct PointTree {
    /// Point ids, ordered so that each node's points are a contiguous range.
    ids: Vec<u32>,
    nodes: Vec<Node>,
}

struct Node {
    bounds: [[f64; 3]; 2],
    range: (usize, usize),
    /// The two halves, or `None` for a leaf.
    children: Option<(usize, usize)>,
}

/// Leaves hold at most this many points.
const LEAF: usize = 8;

impl PointTree {
    /// The tree of the points `ids`, at `position(id)` (finite).
    pub(crate) fn new(mut ids: Vec<u32>, position: &impl Fn(u32) -> [f64; 3]) -> Self {
        let mut nodes = Vec::with_capacity(2 * ids.len() / LEAF + 1);
        if !ids.is_empty() {
            let n = ids.len();
            split(&mut ids, 0, n, position, &mut nodes);
        }
        PointTree { ids, nodes }
    }

    /// Calls `visit(id)` for every point whose node box, grown by `reach`, the segment `a b`
    /// crosses: every point within `reach` of the segment, and some others nearby.
    pub(crate) fn near_segment(
        &self,
        a: [f64; 3],
        b: [f64; 3],
        reach: f64,
        mut visit: impl FnMut(u32),
    ) {
        if self.nodes.is_empty() {
            return;
        }
        let mut stack = vec![0];
        while let Some(n) = stack.pop() {
            let node = &self.nodes[n];
            if !segment_meets_box(a, b, node.bounds, reach) {
                continue;
            }
            match node.children {
                Some((low, high)) => stack.extend([low, high]),
                None => self.ids[node.range.0..node.range.1]
                    .iter()
                    .for_each(|&id| visit(id)),
            }
        }
    }
}

/// Builds the node of `ids[start..end]` (and below it) and returns its index.
fn split(
    ids: &mut [u32],
    start: usize,
    end: usize,
    position: &impl Fn(u32) -> [f64; 3],
    nodes: &mut Vec<Node>,
) -> usize {
    let bounds = bounding_box(ids[start..end].iter().map(|&id| position(id)));
    let index = nodes.len();
    nodes.push(Node {
        bounds,
        range: (start, end),
        children: None,
    });
    if end - start > LEAF {
        let axis = (0..3)
            .max_by(|&i, &j| {
                (bounds[1][i] - bounds[0][i]).total_cmp(&(bounds[1][j] - bounds[0][j]))
            })
            .unwrap_or(0);
        let middle = (end - start) / 2;
        ids[start..end].select_nth_unstable_by(middle, |&p, &q| {
            position(p)[axis].total_cmp(&position(q)[axis])
        });
        let low = split(ids, start, start + middle, position, nodes);
        let high = split(ids, start + middle, end, position, nodes);
        nodes[index].children = Some((low, high));
    }
    index
}

/// Whether segment `a b` meets the box `bounds` grown by `reach` on every side (slab test; a
/// conservative answer where rounding makes it close).
fn segment_meets_box(a: [f64; 3], b: [f64; 3], bounds: [[f64; 3]; 2], reach: f64) -> bool {
    let (mut enter, mut leave) = (0.0f64, 1.0f64);
    for k in 0..3 {
        let (low, high) = (bounds[0][k] - reach, bounds[1][k] + reach);
        let d = b[k] - a[k];
        if d == 0.0 {
            if a[k] < low || a[k] > high {
                return false;
            }
            continue;
        }
        let (t0, t1) = ((low - a[k]) / d, (high - a[k]) / d);
        let (t0, t1) = if t0 <= t1 { (t0, t1) } else { (t1, t0) };
        enter = enter.max(t0);
        leave = leave.min(t1);
        if enter > leave {
            return false;
        }
    }
    true
}
