//! The distance under which two positions count as one, and the clusters it makes.

use super::RepairError;
use crate::doctor::{bounding_box, coincident_vertices, distance, lowest_at_each_position};
use crate::mesh::{Mesh, VertexId};

/// How close two positions must be to be merged or stitched.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Tolerance {
    /// At most this distance apart; 0 means exactly at the same position (−0 and 0 are one
    /// coordinate).
    Absolute(f64),
    /// At most this fraction (between 0 and 1) of the diagonal of the bounding box of the
    /// vertices (those with finite coordinates; on a mesh, the live ones).
    Relative(f64),
}

impl Tolerance {
    /// Only identical positions.
    pub const EXACT: Tolerance = Tolerance::Absolute(0.0);

    /// The absolute distance, `diagonal` being the bounding-box diagonal a relative tolerance
    /// scales; refused when negative, NaN, infinite or (relative) above 1.
    pub(crate) fn absolute(self, diagonal: f64) -> Result<f64, RepairError> {
        let refuse = |value, reason| Err(RepairError::BadTolerance { value, reason });
        match self {
            Tolerance::Absolute(t) if t.is_nan() || t < 0.0 => {
                refuse(t, "it must be 0 or more (not NaN)")
            }
            Tolerance::Absolute(t) if t.is_infinite() => refuse(t, "it must be finite"),
            Tolerance::Absolute(t) => Ok(t),
            Tolerance::Relative(r) if !(0.0..=1.0).contains(&r) => {
                refuse(r, "a relative tolerance must be between 0 and 1")
            }
            Tolerance::Relative(r) if diagonal.is_finite() => Ok(r * diagonal),
            Tolerance::Relative(_) => Ok(0.0),
        }
    }
}

/// The absolute distance of `tolerance` on `mesh`: a relative one scales the diagonal of the
/// live vertices' bounding box. Refused as [`Tolerance::absolute`] refuses.
pub(crate) fn absolute_on_mesh(tolerance: Tolerance, mesh: &Mesh) -> Result<f64, RepairError> {
    let live = (0..mesh.n_vertex_slots() as u32)
        .filter(|&v| !mesh.is_vertex_deleted(VertexId(v)))
        .map(|v| mesh.positions()[v as usize]);
    let [low, high] = bounding_box(live);
    tolerance.absolute(distance(low, high))
}

/// The kept position of every position: the lowest of its cluster (`kept[v] <= v`; non-finite
/// positions are each their own). Exact duplicates always share a cluster; with a tolerance,
/// each group of exact duplicates then joins the cluster of the first lower kept position found
/// within the tolerance of its lowest member, greedily in index order, so kept positions are
/// more than the tolerance apart. The rule is not transitive: of three points spaced just under
/// the tolerance, the third may keep its own cluster.
///
/// Refuses a positive tolerance below 2^-48 of the positions' extent: the cells of the grid that
/// finds near positions in linear time could not be numbered exactly (use 0 for exact
/// duplicates).
pub(crate) fn clusters(positions: &[[f64; 3]], tolerance: f64) -> Result<Vec<u32>, RepairError> {
    if tolerance > 0.0 {
        let [low, high] = crate::doctor::bounding_box(positions.iter().copied());
        let extent = distance(low, high);
        if extent.is_finite() && tolerance < extent * 2f64.powi(-48) {
            return Err(RepairError::BadTolerance {
                value: tolerance,
                reason: "it is positive but below 2^-48 of the positions' extent (use 0 to \
                         merge exact duplicates only)",
            });
        }
    }
    if tolerance == 0.0 {
        let mut kept = lowest_at_each_position(positions);
        for (v, k) in kept.iter_mut().enumerate() {
            if *k == u32::MAX {
                *k = v as u32;
            }
        }
        return Ok(kept);
    }
    let found = coincident_vertices(positions, tolerance);
    // Near duplicates name the group leader they joined; exact duplicates the lowest vertex at
    // their position, whose own cluster decides theirs.
    let mut leader: Vec<u32> = (0..positions.len() as u32).collect();
    for &[v, first] in &found.within_tolerance {
        leader[v as usize] = first;
    }
    let mut kept = leader.clone();
    for &[v, first] in &found.exact {
        kept[v as usize] = leader[first as usize];
    }
    Ok(kept)
}
