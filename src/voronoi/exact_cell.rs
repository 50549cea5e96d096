//! Whether a clipped Voronoi cell has an interior, decided without rounding.
//!
//! A cell narrower than an ulp comes out of floating-point clipping as positions that coincide
//! once rounded, and whether it is a true sliver or only touches the region along its boundary
//! (and must be empty) is beyond the rounded positions. Here the region is cut by the
//! half-planes nearer to the site than to each neighbour, every line in integers of any size and
//! every corner of the cut polygon kept as the pair of lines that meet there, so nothing is
//! rounded. Only cells of zero floating-point area come here.

use crate::geom::exact_orientation::integer_list;
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

/// Does the part of the convex region with counter-clockwise `corners` strictly nearer to `site`
/// than to every one of `neighbours` have an interior?
#[cold]
pub(crate) fn cell_has_interior(
    site: [f64; 2],
    neighbours: &[[f64; 2]],
    corners: &[[f64; 2]],
) -> bool {
    let values: Vec<f64> = [site]
        .iter()
        .chain(neighbours)
        .chain(corners)
        .flatten()
        .copied()
        .collect();
    let integers = integer_list(&values);
    let point = |k: usize| [&integers[2 * k], &integers[2 * k + 1]];
    let m = corners.len();
    let first_corner = 1 + neighbours.len();
    let mut lines: Vec<Line> = (0..m)
        .map(|i| {
            let ([px, py], [qx, qy]) = (point(first_corner + i), point(first_corner + (i + 1) % m));
            Line {
                a: py.sub(qy),
                b: qx.sub(px),
                c: px.mul(qy).sub(&py.mul(qx)),
            }
        })
        .collect();
    // The polygon as its sides' lines, counter-clockwise: its corner `k` is where side `k - 1`
    // meets side `k`.
    let mut polygon: Vec<usize> = (0..m).collect();
    let [sx, sy] = point(0);
    let squared = |x: &WideInteger, y: &WideInteger| x.mul(x).add(&y.mul(y));
    for k in 1..=neighbours.len() {
        let [tx, ty] = point(k);
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
            return false;
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
    true
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
