//! A clipped Voronoi cell without rounding: whether it has an interior, and its corners.
//!
//! A cell narrower than an ulp comes out of floating-point clipping as positions that coincide
//! once rounded, or collapses altogether, and whether it is a true sliver or only touches the
//! region along its boundary (and must be empty) is beyond the rounded positions. Here the
//! region is cut by the half-planes nearer to the site than to each neighbour, every line in
//! integers of any size and every corner of the cut polygon kept as the pair of lines that meet
//! there, so nothing is rounded until a corner is wanted as a position. Only cells of zero
//! floating-point area, or collapsed ones, come here.

use super::clip_frame::FrameMap;
use crate::geom::exact_orientation::{dyadic, integer_list, smallest_unit};
use crate::geom::wide_integer::WideInteger;

/// The open half-plane `a·x + b·y + c > 0`.
struct Line {
    a: WideInteger,
    b: WideInteger,
    c: WideInteger,
}

/// The sign of `line` at the point where `first` and `second` meet (0 where they are parallel).
fn side(line: &Line, first: &Line, second: &Line) -> i32 {
    let x = first.b.mul(&second.c).sub(&second.b.mul(&first.c));
    let y = first.c.mul(&second.a).sub(&second.c.mul(&first.a));
    let w = first.a.mul(&second.b).sub(&second.a.mul(&first.b));
    let value = line.a.mul(&x).add(&line.b.mul(&y)).add(&line.c.mul(&w));
    value.signum() * w.signum()
}

/// The part of a convex region strictly nearer to a site than to each of its neighbours, in
/// integers: the region cut by one half-plane per neighbour.
struct ExactCell {
    /// The region's sides, then the cuts.
    lines: Vec<Line>,
    /// The cell's sides as indices into `lines`, counter-clockwise: its corner `k` is where
    /// side `k - 1` meets side `k`.
    polygon: Vec<usize>,
    /// The frame's origin in the integers' unit.
    origin: [WideInteger; 2],
    /// Every integer is a multiple of `2^unit`.
    unit: i64,
}

impl ExactCell {
    /// The cell of `site` among `neighbours` in the convex region with counter-clockwise
    /// `corners`, with `origin` in the integers' unit; `None` when it has no interior.
    fn new(
        site: [f64; 2],
        neighbours: &[[f64; 2]],
        corners: &[[f64; 2]],
        origin: [f64; 2],
    ) -> Option<ExactCell> {
        let values: Vec<f64> = [site, origin]
            .iter()
            .chain(neighbours)
            .chain(corners)
            .flatten()
            .copied()
            .collect();
        let unit = i64::from(smallest_unit(&values));
        let integers = integer_list(&values);
        let point = |k: usize| [&integers[2 * k], &integers[2 * k + 1]];
        let m = corners.len();
        let first_corner = 2 + neighbours.len();
        let mut lines: Vec<Line> = (0..m)
            .map(|i| {
                let ([px, py], [qx, qy]) =
                    (point(first_corner + i), point(first_corner + (i + 1) % m));
                Line {
                    a: py.sub(qy),
                    b: qx.sub(px),
                    c: px.mul(qy).sub(&py.mul(qx)),
                }
            })
            .collect();
        let mut polygon: Vec<usize> = (0..m).collect();
        let [sx, sy] = point(0);
        let squared = |x: &WideInteger, y: &WideInteger| x.mul(x).add(&y.mul(y));
        for k in 0..neighbours.len() {
            let [tx, ty] = point(2 + k);
            // Nearer to the site: 2 (s - t)·x + |t|² - |s|² > 0.
            let (dx, dy) = (sx.sub(tx), sy.sub(ty));
            lines.push(Line {
                a: dx.add(&dx),
                b: dy.add(&dy),
                c: squared(tx, ty).sub(&squared(sx, sy)),
            });
            let cut = lines.len() - 1;
            let n = polygon.len();
            let signs: Vec<i32> = (0..n)
                .map(|k| {
                    side(
                        &lines[cut],
                        &lines[polygon[(k + n - 1) % n]],
                        &lines[polygon[k]],
                    )
                })
                .collect();
            if signs.iter().all(|&s| s <= 0) {
                return None;
            }
            if signs.iter().all(|&s| s > 0) {
                continue;
            }
            let mut kept = Vec::with_capacity(n + 1);
            for k in 0..n {
                let (start, end) = (signs[k] > 0, signs[(k + 1) % n] > 0);
                if start || end {
                    kept.push(polygon[k]);
                }
                if start && !end {
                    kept.push(cut);
                }
            }
            polygon = kept;
        }
        let [ox, oy] = point(1);
        Some(ExactCell {
            lines,
            polygon,
            origin: [ox.clone(), oy.clone()],
            unit,
        })
    }

    /// The corners, counter-clockwise, each as `(p - origin) · scale`: a corner of the region
    /// (`region`, already in that frame) exactly, every other one within about two ulps of its
    /// exact value (see [`WideInteger::ratio`]).
    fn rounded_corners(&self, region: &[[f64; 2]], scale: f64) -> Vec<[f64; 2]> {
        let (_, _, scale_exponent) = dyadic(scale);
        let exponent = self.unit + i64::from(scale_exponent);
        let n = self.polygon.len();
        (0..n)
            .map(|k| {
                let (before, after) = (self.polygon[(k + n - 1) % n], self.polygon[k]);
                // Lines below `region.len()` are the region's sides; side `i` starts at corner
                // `i`.
                if before < region.len() && after < region.len() {
                    return region[after];
                }
                let (first, second) = (&self.lines[before], &self.lines[after]);
                // The meeting point in homogeneous coordinates (x / w, y / w).
                let x = first.b.mul(&second.c).sub(&second.b.mul(&first.c));
                let y = first.c.mul(&second.a).sub(&second.c.mul(&first.a));
                let w = first.a.mul(&second.b).sub(&second.a.mul(&first.b));
                let [ox, oy] = &self.origin;
                [x.sub(&ox.mul(&w)), y.sub(&oy.mul(&w))].map(|u| u.ratio(&w, exponent))
            })
            .collect()
    }
}

/// Does the part of the convex region with counter-clockwise `corners` strictly nearer to `site`
/// than to every one of `neighbours` have an interior?
#[cold]
pub(crate) fn cell_has_interior(
    site: [f64; 2],
    neighbours: &[[f64; 2]],
    corners: &[[f64; 2]],
) -> bool {
    ExactCell::new(site, neighbours, corners, [0.0; 2]).is_some()
}

/// The corners of the cell that [`cell_has_interior`] decides, counter-clockwise, each rounded
/// from its exact place into `frame` (`None` when the cell has no interior). Corners where
/// several sides meet are listed once per side, so some may coincide.
#[cold]
pub(crate) fn exact_cell_corners(
    site: [f64; 2],
    neighbours: &[[f64; 2]],
    corners: &[[f64; 2]],
    frame: FrameMap,
) -> Option<Vec<[f64; 2]>> {
    let FrameMap { origin, scale } = frame;
    // Exact: clipping runs in a local frame only where the region's corners map into it
    // exactly (see `clip_frame`).
    let region: Vec<[f64; 2]> = corners
        .iter()
        .map(|p| [0, 1].map(|k| (p[k] - origin[k]) * scale))
        .collect();
    ExactCell::new(site, neighbours, corners, origin)
        .map(|cell| cell.rounded_corners(&region, scale))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cells_touching_the_region_along_a_side_have_no_interior() {
        let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        // The bisector of the two sites is the square's top side.
        assert!(!cell_has_interior([0.5, 1.5], &[[0.5, 0.5]], &square));
        assert!(cell_has_interior([0.5, 0.5], &[[0.5, 1.5]], &square));
        // One ulp below the top side: a sliver 2^-53 thick.
        let below = 1.0 - f64::EPSILON / 2.0;
        assert!(cell_has_interior(
            [0.5, 1.5],
            &[[0.5, below - 0.5]],
            &square
        ));
        // The corner only.
        assert!(!cell_has_interior(
            [2.0, 2.0],
            &[[0.0, 2.0], [2.0, 0.0], [0.0, 0.0]],
            &square
        ));
    }
}
