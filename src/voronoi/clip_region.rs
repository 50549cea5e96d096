//! Convex clip regions for Voronoi cells.

use super::error::VoronoiError;
use super::predicates::{normalising_scale_of_box, orient2d};

/// A convex polygon, stored counter-clockwise, that Voronoi cells are clipped to.
#[derive(Clone, Debug, PartialEq)]
pub struct ClipPolygon {
    vertices: Vec<[f64; 2]>,
    /// `edges[i]` runs from vertex `i` to the next: the edge functions of every Voronoi vertex
    /// read them, so they are computed once here.
    edges: Vec<[f64; 2]>,
    /// Every edge with each axis scaled as [`AxisScale`] says (about halved and times the power
    /// of two that brings the longest extent along that axis near 1): edge functions (an edge
    /// times an offset) neither overflow nor underflow for regions of any size or shape (a box
    /// `1e-323` wide and `1` tall). Scaling each axis by a positive factor multiplies every edge
    /// function by one and the same positive number, so their signs and ratios are kept.
    unit_edges: Vec<[f64; 2]>,
    axis_scales: [AxisScale; 2],
    /// Every vertex with each axis times its scale's `pre` factor (see [`AxisScale`]).
    pre_scaled_vertices: Vec<[f64; 2]>,
    area: f64,
}

impl ClipPolygon {
    /// The axis-aligned rectangle `[min.x, max.x] × [min.y, max.y]`; refused when it has zero
    /// area, is inverted, or has a non-finite corner.
    pub fn rectangle(min: [f64; 2], max: [f64; 2]) -> Result<Self, VoronoiError> {
        if !(min.iter().chain(&max).all(|c| c.is_finite())) {
            return Err(VoronoiError::DegenerateClip("non-finite rectangle corner"));
        }
        if !(min[0] < max[0] && min[1] < max[1]) {
            return Err(VoronoiError::DegenerateClip(
                "rectangle has zero or negative extent",
            ));
        }
        Self::convex(&[min, [max[0], min[1]], max, [min[0], max[1]]])
    }

    /// A convex polygon given in either orientation. Vertices lying exactly on the segment
    /// between their neighbours (and exact repeats) are dropped; the rest must turn the same way
    /// at every vertex and wind once. Exact orientation tests decide convexity.
    pub fn convex(vertices: &[[f64; 2]]) -> Result<Self, VoronoiError> {
        if vertices
            .iter()
            .any(|p| !(p[0].is_finite() && p[1].is_finite()))
        {
            return Err(VoronoiError::DegenerateClip("non-finite vertex"));
        }
        let mut v: Vec<[f64; 2]> = Vec::with_capacity(vertices.len());
        for &p in vertices {
            if v.last() != Some(&p) {
                v.push(p);
            }
        }
        while v.len() > 1 && v.first() == v.last() {
            v.pop();
        }
        if v.len() < 3 {
            return Err(VoronoiError::DegenerateClip(
                "fewer than three distinct vertices",
            ));
        }
        // The sign of the area, from vertices whose axes are brought near 1 by powers of two
        // (which keeps the sign): the area itself may under- or overflow for a valid region.
        let units = point_units(&v);
        let signed_area = shoelace(
            &v.iter()
                .map(|p| [p[0] * units[0], p[1] * units[1]])
                .collect::<Vec<_>>(),
        );
        if signed_area == 0.0 || !signed_area.is_finite() {
            return Err(VoronoiError::DegenerateClip("zero area"));
        }
        if signed_area < 0.0 {
            v.reverse();
        }
        // Drop vertices that do not turn (straight continuation); refuse any right turn or
        // reversal.
        let mut i = 0;
        while i < v.len() && v.len() >= 3 {
            let n = v.len();
            let (a, b, c) = (v[(i + n - 1) % n], v[i], v[(i + 1) % n]);
            let o = orient2d(a, b, c);
            if o < 0.0 || (o == 0.0 && !super::incremental::strictly_between(a, c, b)) {
                return Err(VoronoiError::NonConvexClip { vertex: i });
            }
            if o == 0.0 {
                v.remove(i);
                i = i.saturating_sub(1);
            } else {
                i += 1;
            }
        }
        if v.len() < 3 {
            return Err(VoronoiError::DegenerateClip("all vertices collinear"));
        }
        // Left turns everywhere still allow a star that winds twice: total turning must be 2π.
        let n = v.len();
        let turning: f64 = (0..n)
            .map(|i| {
                let (a, b, c) = (v[(i + n - 1) % n], v[i], v[(i + 1) % n]);
                let (u, w) = ([b[0] - a[0], b[1] - a[1]], [c[0] - b[0], c[1] - b[1]]);
                (u[0] * w[1] - u[1] * w[0]).atan2(u[0] * w[0] + u[1] * w[1])
            })
            .sum();
        if turning > 3.0 * std::f64::consts::PI {
            return Err(VoronoiError::NonConvexClip { vertex: 0 });
        }
        let area = shoelace(&v);
        let sides: Vec<[[f64; 2]; 2]> = (0..n).map(|i| [v[i], v[(i + 1) % n]]).collect();
        let axis_scales = side_units(&sides).map(AxisScale::for_unit);
        let unit_edges = sides
            .iter()
            .map(|&[a, b]| [0, 1].map(|k| axis_scales[k].offset(b[k], a[k])))
            .collect();
        let pre_scaled_vertices = v
            .iter()
            .map(|p| [0, 1].map(|k| p[k] * axis_scales[k].pre))
            .collect();
        let edges = sides
            .iter()
            .map(|&[a, b]| {
                [0, 1].map(|k| {
                    let d = b[k] - a[k];
                    // Halves first where the side spans more than the doubles' range.
                    if d.is_finite() {
                        d
                    } else {
                        2.0 * (0.5 * b[k] - 0.5 * a[k])
                    }
                })
            })
            .collect();
        Ok(ClipPolygon {
            vertices: v,
            edges,
            unit_edges,
            axis_scales,
            pre_scaled_vertices,
            area,
        })
    }

    /// Vertices, counter-clockwise. Edge `i` runs from vertex `i` to vertex `i + 1`.
    pub fn vertices(&self) -> &[[f64; 2]] {
        &self.vertices
    }

    /// Area (positive; zero or infinite for a region whose area lies beyond the range of
    /// doubles, which is still clipped to).
    pub fn area(&self) -> f64 {
        self.area
    }

    /// Is `p` inside or on the boundary (floating-point test)?
    pub fn contains(&self, p: [f64; 2]) -> bool {
        (0..self.vertices.len()).all(|i| self.edge_function(i, p) >= 0.0)
    }

    /// Signed area-like distance of `p` to edge `i`'s line: `≥ 0` on the inner side. (One
    /// power-of-two multiple of it for all edges: see `unit_edges`.)
    #[inline(always)]
    pub(crate) fn edge_function(&self, i: usize, p: [f64; 2]) -> f64 {
        self.half_plane(
            self.pre_scaled_vertices[i],
            self.unit_edges[i],
            self.pre_scaled(p),
        )
    }

    /// The smallest edge function of `p` over all edges: `> 0` strictly inside, `0` on the
    /// boundary.
    #[inline]
    pub(crate) fn lowest_edge_function(&self, p: [f64; 2]) -> f64 {
        let p = self.pre_scaled(p);
        self.pre_scaled_vertices
            .iter()
            .zip(&self.unit_edges)
            .map(|(&a, &e)| self.half_plane(a, e, p))
            .fold(f64::INFINITY, f64::min)
    }

    /// Cross product of edge `i` with direction `d`: how fast `edge_function` grows along `d`.
    #[inline(always)]
    pub(crate) fn edge_rate(&self, i: usize, d: [f64; 2]) -> f64 {
        let e = self.unit_edges[i];
        let [dx, dy] = [0, 1].map(|k| clamp_offset(self.axis_scales[k].offset(d[k], 0.0)));
        e[0] * dy - e[1] * dx
    }

    /// Where `x`, a point on edge `i`'s line, falls along it: its parameter `t` measured from
    /// the start (0 there, 1 at the end) and, past the middle, from the end (`-1` at the start,
    /// 0 at the end; `t - 1` elsewhere), each from its own corner, so that a point near the end
    /// of a long edge keeps its offset from that end (which `1 - t` rounds away). Along the
    /// axis the edge runs farther on, halved so that nothing overflows, and without products
    /// that could underflow.
    #[inline]
    pub(crate) fn edge_parameters(&self, i: usize, x: [f64; 2]) -> [f64; 2] {
        let e = self.unit_edges[i];
        let units = self.axis_scales.map(|scale| scale.pre * scale.post);
        let k = if (e[0] / units[0]).abs() >= (e[1] / units[1]).abs() {
            0
        } else {
            1
        };
        let scale = self.axis_scales[k];
        let t = scale.offset(x[k], self.vertices[i][k]) / e[k];
        if t <= 0.5 {
            return [t, t - 1.0];
        }
        let end = self.vertices[(i + 1) % self.vertices.len()];
        [t, scale.offset(x[k], end[k]) / e[k]]
    }

    /// `p` with each axis times its scale's `pre` factor.
    #[inline(always)]
    fn pre_scaled(&self, p: [f64; 2]) -> [f64; 2] {
        [0, 1].map(|k| p[k] * self.axis_scales[k].pre)
    }

    /// Edge function of `p` for the edge from `a` along the scaled edge `e` (`a` and `p`
    /// pre-scaled).
    #[inline(always)]
    fn half_plane(&self, a: [f64; 2], e: [f64; 2], p: [f64; 2]) -> f64 {
        let [dx, dy] = [0, 1].map(|k| clamp_offset((p[k] - a[k]) * self.axis_scales[k].post));
        e[0] * dy - e[1] * dx
    }

    /// The vector from vertex `i` to the next.
    #[inline(always)]
    pub(crate) fn edge_vector(&self, i: usize) -> [f64; 2] {
        self.edges[i]
    }

    /// Centroid of the polygon.
    pub fn centroid(&self) -> [f64; 2] {
        polygon_area_centroid(&self.vertices).1
    }
}

/// Bound of scaled offsets: times a scaled edge (below 2), twice over, still finite.
const FARTHEST_OFFSET: f64 = 1.0e300;

/// A scaled offset kept within `±FARTHEST_OFFSET`, so that the edge functions of points
/// astronomically far from the region stay finite (their sign is all that is read of them).
#[inline(always)]
fn clamp_offset(offset: f64) -> f64 {
    offset.clamp(-FARTHEST_OFFSET, FARTHEST_OFFSET)
}

/// How one axis of the region is scaled: an offset `to - from` becomes
/// `(to·pre - from·pre)·post`, about half of it times the power of two that brings the region's
/// extent along the axis near 1 (`unit`). Chosen once per region, so that an offset costs one
/// subtraction and one multiplication (the `pre` products of a point are shared by every edge).
#[derive(Clone, Copy, Debug, PartialEq)]
struct AxisScale {
    pre: f64,
    post: f64,
}

impl AxisScale {
    /// Where an overflowing difference times `unit / 2` still lies beyond [`FARTHEST_OFFSET`],
    /// the difference itself is scaled (`pre = 1`): an overflow is then clamped as the exact
    /// value would be, and halving first would round a difference of one subnormal to zero (and
    /// every edge function of a region that narrow to 0). Otherwise (extents above about 1e8)
    /// the halves are subtracted, which never overflows; the bits halving loses lie far below
    /// what scaling by so small a `unit` keeps.
    fn for_unit(unit: f64) -> AxisScale {
        let half_unit = 0.5 * unit;
        if half_unit * f64::MAX >= FARTHEST_OFFSET {
            AxisScale {
                pre: 1.0,
                post: half_unit,
            }
        } else {
            AxisScale {
                pre: 0.5,
                post: unit,
            }
        }
    }

    /// `to - from` in this axis's scaled frame (unclamped).
    #[inline(always)]
    fn offset(self, to: f64, from: f64) -> f64 {
        (to * self.pre - from * self.pre) * self.post
    }
}

/// Per axis, the power of two that brings the longest of the sides `[a, b]` near 1: their
/// whole extent where it is finite, half of it where it overflows.
fn side_units(sides: &[[[f64; 2]; 2]]) -> [f64; 2] {
    [0, 1].map(|k| {
        let full = sides
            .iter()
            .fold(0.0_f64, |m, [a, b]| m.max((b[k] - a[k]).abs()));
        let largest = if full.is_finite() {
            full
        } else {
            sides
                .iter()
                .fold(0.0_f64, |m, [a, b]| m.max((0.5 * b[k] - 0.5 * a[k]).abs()))
        };
        normalising_scale_of_box([[-largest, 0.0], [largest, 0.0]])
    })
}

/// Per axis, the power of two that brings the largest magnitude of `points` near 1.
fn point_units(points: &[[f64; 2]]) -> [f64; 2] {
    [0, 1].map(|k| {
        let largest = points.iter().fold(0.0_f64, |m, p| m.max(p[k].abs()));
        normalising_scale_of_box([[-largest, 0.0], [largest, 0.0]])
    })
}

fn shoelace(v: &[[f64; 2]]) -> f64 {
    polygon_area_centroid(v).0
}

/// Signed area and centroid of a simple polygon (shoelace, relative to the first vertex for
/// precision). The centroid of a zero-area polygon is its first vertex.
///
/// The offsets from the first vertex are halved (so they cannot overflow) and scaled by a power
/// of two (exact) so that the largest lies in `[1, 2)`: the products of degree three below then
/// neither overflow nor underflow, and the centroid is finite for every finite polygon (cells of
/// sites near `1e+150` used to get an infinite or NaN centroid, tiny ones a zero area and the
/// first vertex as centroid). Only an area beyond the `f64` range is infinite (or zero).
pub fn polygon_area_centroid(v: &[[f64; 2]]) -> (f64, [f64; 2]) {
    let Some(&o) = v.first() else {
        return (0.0, [f64::NAN; 2]);
    };
    let half_offset = |p: [f64; 2]| [0.5 * p[0] - 0.5 * o[0], 0.5 * p[1] - 0.5 * o[1]];
    let largest = v
        .iter()
        .map(|&p| {
            let d = half_offset(p);
            d[0].abs().max(d[1].abs())
        })
        .fold(0.0_f64, f64::max);
    let scale = normalising_scale_of_box([[-largest, -largest], [largest, largest]]);
    let offset = |p: [f64; 2]| {
        let d = half_offset(p);
        [d[0] * scale, d[1] * scale]
    };
    let (mut a2, mut cx, mut cy) = (0.0, 0.0, 0.0);
    for w in v.windows(2).skip(1) {
        let (p, q) = (offset(w[0]), offset(w[1]));
        let cross = p[0] * q[1] - q[0] * p[1];
        a2 += cross;
        cx += (p[0] + q[0]) * cross;
        cy += (p[1] + q[1]) * cross;
    }
    if a2 == 0.0 {
        return (0.0, o);
    }
    // Back to the input's units: offsets were multiplied by `scale / 2`.
    let unit = 1.0 / scale;
    let area = (2.0 * a2) * unit * unit;
    let centre = |c: f64| (c / (3.0 * a2)) * 2.0 * unit;
    (area, [o[0] + centre(cx), o[1] + centre(cy)])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rectangle_is_counter_clockwise_with_its_area() {
        let r = ClipPolygon::rectangle([0.0, 0.0], [2.0, 3.0]).unwrap();
        assert_eq!(r.area(), 6.0);
        assert_eq!(r.centroid(), [1.0, 1.5]);
        assert!(r.contains([1.0, 1.0]) && r.contains([0.0, 3.0]) && !r.contains([-0.1, 1.0]));
    }

    #[test]
    fn clockwise_input_is_reversed_and_collinear_vertices_dropped() {
        let p = ClipPolygon::convex(&[[0.0, 0.0], [0.0, 1.0], [1.0, 1.0], [1.0, 0.5], [1.0, 0.0]])
            .unwrap();
        assert_eq!(p.vertices().len(), 4);
        assert_eq!(p.area(), 1.0);
    }

    #[test]
    fn a_region_one_subnormal_wide_tells_inside_from_outside() {
        // Halving a side one subnormal long rounded it to zero: every edge function was 0 and
        // every point of the plane inside.
        let tiny = f64::from_bits(1);
        let r = ClipPolygon::rectangle([0.0, 0.0], [tiny, 1.0]).unwrap();
        assert!(r.contains([0.0, 0.5]) && r.contains([tiny, 1.0]));
        assert!(!r.contains([2.0 * tiny, 0.5]) && !r.contains([-tiny, 0.5]));
        assert!(!r.contains([0.0, 2.0]) && !r.contains([0.0, -1.0]));
        assert!(r.edge_function(0, [0.0, 0.5]) > 0.0);
        assert!(r.edge_rate(1, [-1.0, 0.0]) > 0.0);
        assert_eq!(r.edge_parameters(0, [tiny, 0.0]), [1.0, 0.0]);
    }

    #[test]
    fn bad_regions_are_refused() {
        assert!(matches!(
            ClipPolygon::rectangle([0.0, 0.0], [0.0, 1.0]),
            Err(VoronoiError::DegenerateClip(_))
        ));
        assert!(matches!(
            ClipPolygon::rectangle([0.0, f64::NAN], [1.0, 1.0]),
            Err(VoronoiError::DegenerateClip(_))
        ));
        assert!(matches!(
            ClipPolygon::convex(&[[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]]),
            Err(VoronoiError::DegenerateClip(_))
        ));
        let dart = [[0.0, 0.0], [2.0, 1.0], [4.0, 0.0], [2.0, 3.0]];
        assert!(matches!(
            ClipPolygon::convex(&dart),
            Err(VoronoiError::NonConvexClip { .. })
        ));
        let star: Vec<[f64; 2]> = (0..5)
            .map(|k| {
                let a = (2 * k) as f64 * 2.0 * std::f64::consts::PI / 5.0;
                [a.cos(), a.sin()]
            })
            .collect();
        assert!(matches!(
            ClipPolygon::convex(&star),
            Err(VoronoiError::NonConvexClip { .. })
        ));
    }
}
