//! Cutting off the corners that enclose nothing: a corner at the same place as a neighbour (a
//! side of no length), and the tip of a spike (the boundary runs out along a line and straight
//! back). Each goes in a triangle of no area with its two neighbours, which changes nothing the
//! polygon covers, and cutting one can make its neighbour such a corner in turn (a spike of many
//! corners retracts corner by corner). Linear time. Corners in the middle of a straight side are
//! kept: they belong in proper triangles.

use robust::{Coord, orient2d};

use super::perturbed::lies_between;

/// Scratch buffers for [`DegenerateCorners::cut`].
#[derive(Debug, Default)]
pub(super) struct DegenerateCorners {
    prev: Vec<u32>,
    next: Vec<u32>,
    cut: Vec<bool>,
    pending: Vec<u32>,
}

impl DegenerateCorners {
    /// Appends a triangle (corners in increasing order) to `out` for each corner of `points`
    /// cut off, as long as more than 3 corners are left, and sets `ring` to the corners left,
    /// in increasing order.
    pub(super) fn cut(
        &mut self,
        points: &[Coord<f64>],
        out: &mut Vec<[u32; 3]>,
        ring: &mut Vec<u32>,
    ) {
        let n = points.len() as u32;
        self.prev.clear();
        self.prev
            .extend((0..n).map(|i| if i == 0 { n - 1 } else { i - 1 }));
        self.next.clear();
        self.next
            .extend((0..n).map(|i| if i + 1 == n { 0 } else { i + 1 }));
        self.cut.clear();
        self.cut.resize(n as usize, false);
        self.pending.clear();
        self.pending.extend((0..n).rev());
        let mut left = n;
        while left > 3 {
            let Some(c) = self.pending.pop() else { break };
            if self.cut[c as usize] {
                continue;
            }
            let (p, q) = (self.prev[c as usize], self.next[c as usize]);
            if !encloses_nothing(points, p, c, q) {
                continue;
            }
            let mut triangle = [p, c, q];
            triangle.sort_unstable();
            out.push(triangle);
            self.cut[c as usize] = true;
            self.next[p as usize] = q;
            self.prev[q as usize] = p;
            left -= 1;
            self.pending.extend([q, p]);
        }
        ring.clear();
        ring.extend((0..n).filter(|&c| !self.cut[c as usize]));
    }
}

/// `true` when corner `c`, between `p` and `q`, shares its place with one of them or is the tip
/// of a spike: all three on a line, `c` not between the other two.
fn encloses_nothing(points: &[Coord<f64>], p: u32, c: u32, q: u32) -> bool {
    let (p, c, q) = (points[p as usize], points[c as usize], points[q as usize]);
    let same = |a: Coord<f64>, b: Coord<f64>| a.x == b.x && a.y == b.y;
    same(p, c) || same(c, q) || (orient2d(p, c, q) == 0.0 && !lies_between(p, c, q))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cut(xy: &[[f64; 2]]) -> (Vec<[u32; 3]>, Vec<u32>) {
        let points: Vec<Coord<f64>> = xy.iter().map(|p| Coord { x: p[0], y: p[1] }).collect();
        let (mut out, mut ring) = (Vec::new(), Vec::new());
        DegenerateCorners::default().cut(&points, &mut out, &mut ring);
        (out, ring)
    }

    #[test]
    fn repeats_and_spikes_go_straight_corners_stay() {
        // A unit square with corner 1 repeated, a straight corner 4 on the top side and a spike
        // out of the left side through corners 7 and 8 (8 the tip, 7 halfway).
        let (triangles, ring) = cut(&[
            [0.0, 0.0],
            [1.0, 0.0],
            [1.0, 0.0],
            [1.0, 1.0],
            [0.5, 1.0],
            [0.0, 1.0],
            [0.0, 0.5],
            [-1.0, 0.5],
            [-2.0, 0.5],
            [-1.0, 0.5],
            [0.0, 0.5],
        ]);
        assert_eq!(ring, vec![0, 2, 3, 4, 5, 10]);
        assert_eq!(triangles.len(), 5);
        assert!(triangles.contains(&[0, 1, 2]));
    }

    #[test]
    fn a_polygon_of_one_place_keeps_three_corners() {
        let (triangles, ring) = cut(&[[3.0, 4.0]; 7]);
        assert_eq!((triangles.len(), ring.len()), (4, 3));
    }
}
