//! The coordinates that clipping works in: the diagram's own, or, for a region that is small
//! beside its distance from the origin (or of extreme size), coordinates relative to one of its
//! corners and scaled by a power of two so that the region is about 1 wide.
//!
//! Far from the origin doubles are sparse: a region a few ulps wide at `1e15` holds only a few
//! representable points, and the Voronoi vertices and crossings inside it, rounded to them,
//! collapsed cells of sites inside the region (and put a side a third of the region's width off
//! where it belongs). In the local frame the diagram is placed again: every vertex is recomputed
//! from its sites with each coordinate rounded once, and triangles share a vertex only where
//! their sites are exactly cocircular or their centres coincide in the local frame. Which vertex
//! lies where and which crossing comes first along the boundary are then decided as if the
//! doubles were dense there; only the output positions are rounded, once, back to the input's
//! coordinates.

use super::clip_region::ClipPolygon;
use super::diagram::{SplitCentre, Voronoi};
use super::expansion::two_diff;
use super::predicates::normalising_scale_of_box;

/// How a point of the input maps into the coordinates clipping works in:
/// `(p - origin) · scale`, `scale` a power of two.
#[derive(Clone, Copy, Debug)]
pub(crate) struct FrameMap {
    pub origin: [f64; 2],
    pub scale: f64,
}

impl FrameMap {
    /// The input's own coordinates.
    pub(crate) const IDENTITY: FrameMap = FrameMap {
        origin: [0.0, 0.0],
        scale: 1.0,
    };
}

/// The diagram and region moved to a local frame: a point `p` of the frame is
/// `map.origin + p / map.scale` in the diagram's coordinates.
pub(crate) struct LocalFrame {
    pub diagram: Voronoi,
    pub clip: ClipPolygon,
    /// How a point of the input maps into the frame.
    pub map: FrameMap,
}

/// A region whose extent is below this fraction of its largest coordinate has fewer than
/// `2^(52 - 10)` representable positions across it: it is clipped in a local frame.
const SPARSE_FRACTION: f64 = 1.0 / 1024.0;

/// Regions whose extent lies outside `[1 / EXTREME_EXTENT, EXTREME_EXTENT]` are clipped in a
/// local frame too, where their extent is near 1 (nothing under- or overflows).
const EXTREME_EXTENT: f64 = 1.0e250;

/// Local coordinates are kept within this bound (a far vertex keeps its direction from the
/// region, which is all that clipping reads of it).
const FARTHEST: f64 = 1.0e300;

impl Voronoi {
    /// The local frame for clipping to `clip`, or `None` when the diagram's own coordinates
    /// are dense enough there (see the module documentation).
    pub(crate) fn local_clip_frame(&self, clip: &ClipPolygon) -> Option<LocalFrame> {
        let corners = clip.vertices();
        let (mut min, mut max) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for p in corners {
            for k in 0..2 {
                min[k] = min[k].min(p[k]);
                max[k] = max[k].max(p[k]);
            }
        }
        let magnitude = [min, max]
            .iter()
            .flatten()
            .fold(0.0_f64, |m, c| m.max(c.abs()));
        // Halves: the extent of a region from -1e308 to 1e308 stays finite.
        let extent = (0.5 * max[0] - 0.5 * min[0]).max(0.5 * max[1] - 0.5 * min[1]);
        let is_dense = extent >= SPARSE_FRACTION * 0.5 * magnitude
            && (1.0 / EXTREME_EXTENT..=EXTREME_EXTENT).contains(&extent);
        if is_dense {
            return None;
        }
        let origin = corners[0];
        let scale = normalising_scale_of_box([[-extent, -extent], [extent, extent]]);
        // The region must be an exact translate and scaling of the given one, so that the
        // positions map back: corners a few ulps apart far out always are (their differences
        // are exact).
        let exact_offset = |p: [f64; 2]| -> Option<[f64; 2]> {
            let offset = [0, 1].map(|k| two_diff(p[k], origin[k]));
            offset
                .iter()
                .all(|&(_, error)| error == 0.0)
                .then(|| offset.map(|(d, _)| d * scale))
                .filter(|d| {
                    d.iter()
                        .all(|&x| x.is_finite() && x / scale == x * (1.0 / scale))
                })
        };
        let local_corners = corners
            .iter()
            .map(|&p| exact_offset(p))
            .collect::<Option<Vec<_>>>()?;
        let local_clip = ClipPolygon::convex(&local_corners).ok()?;
        if local_clip.vertices() != local_corners.as_slice() {
            return None;
        }
        let sites = self.delaunay.sites();
        let local_sites = sites
            .iter()
            .map(|&p| local_offset(p, [0.0; 2], origin, scale));
        let delaunay = self.delaunay.with_sites(local_sites.collect());
        let d = &self.delaunay;
        let unscale = d.scale.recip();
        let diagram = Voronoi::from_delaunay_by(delaunay, |_, t| {
            let [a, b, c] = d.triangle_points(t);
            let split = SplitCentre::of(a, b, c);
            let offset = split.offset.map(|x| x * unscale);
            // The corners' own coordinates, which the scaled points are exact multiples of.
            let base = [0, 1].map(|k| {
                let corner = d.triangles[3 * t as usize + split.corner[k]];
                sites[corner as usize][k]
            });
            let centre = local_offset(base, offset, origin, scale);
            let [ux, uy] = split.from_first.map(|x| x * unscale);
            (centre, (ux.abs() + uy.abs()) * scale)
        });
        Some(LocalFrame {
            diagram,
            clip: local_clip,
            map: FrameMap { origin, scale },
        })
    }
}

/// `(p + offset - origin) · scale`, brought back within [`FARTHEST`] along its own direction.
fn local_offset(p: [f64; 2], offset: [f64; 2], origin: [f64; 2], scale: f64) -> [f64; 2] {
    // `p - origin` exactly as a pair: it is exact for the points near a region far out.
    let moved = |high: f64, low: f64, offset: f64| (high + offset) + low;
    let exact = [0, 1].map(|k| {
        let (high, low) = two_diff(p[k], origin[k]);
        moved(high, low, offset[k])
    });
    // Halves where the sum itself overflows (across the whole range of doubles).
    let sum = if exact.iter().all(|x| x.is_finite()) {
        exact
    } else {
        [0, 1].map(|k| 0.5 * p[k] - 0.5 * origin[k] + 0.5 * offset[k])
    };
    let largest = sum[0].abs().max(sum[1].abs());
    if largest * scale <= FARTHEST {
        sum.map(|x| x * scale)
    } else if largest.is_finite() {
        sum.map(|x| x / largest * FARTHEST)
    } else {
        // A centre beyond the range of doubles (see `Voronoi`): its infinite coordinates give
        // its direction (`inf / inf` would be NaN).
        sum.map(|x| {
            if x.is_infinite() {
                x.signum() * FARTHEST
            } else {
                0.0
            }
        })
    }
}

impl LocalFrame {
    /// Moves `positions` (all but the first `corners.len()`, which are the region's corners)
    /// from the frame back to the diagram's coordinates; the corners become `corners` exactly.
    pub(crate) fn to_diagram(&self, positions: &mut [[f64; 2]], corners: &[[f64; 2]]) {
        let FrameMap { origin, scale } = self.map;
        let unscale = 1.0 / scale;
        positions[..corners.len()].copy_from_slice(corners);
        for p in &mut positions[corners.len()..] {
            *p = [0, 1].map(|k| origin[k] + p[k] * unscale);
        }
    }
}
