//! Repairs: operations that fix what the [doctor](crate::doctor) finds, each returning a
//! [`RepairReport`] of what it changed and leaving its input unchanged when it refuses.
//!
//! On indexed face lists ([`PolygonSoup`]): [`merge_vertices`] (exact and near duplicates),
//! [`remove_duplicate_faces`], [`remove_unreferenced_vertices`] and
//! [`remove_small_components`]. On a [`Mesh`](crate::mesh::Mesh): [`stitch_borders`], and
//! [`fill_hole`] / [`fill_holes`], which close boundary loops with triangles.
//! The doctor's detection serves them: what it lists as duplicates, unreferenced vertices or
//! small components is what the repairs remove.
//!
//! Kept data follows its element: a kept corner keeps its normal and texture coordinate, a kept
//! vertex its position (and, on a mesh, its attributes), and removed elements' data goes with
//! them; what merged elements keep is said by each operation. Vertices and faces are renumbered
//! in their order; [`RepairReport::maps`] gives the old-to-new ids.

mod fill_hole;
mod merge_vertices;
mod remove_duplicate_faces;
mod remove_small_components;
mod remove_unreferenced_vertices;
mod soup_edit;
mod stitch_borders;
mod tolerance;

pub use fill_hole::{
    DEGENERATE_RATIO, EXACT_CORNERS_MAX, FOLD_ANGLE_DEGREES, FillError, FilledHole,
    HoleFillOptions, HoleFillReport, fill_hole, fill_holes,
};
pub use merge_vertices::merge_vertices;
pub use remove_duplicate_faces::remove_duplicate_faces;
pub use remove_small_components::{SmallComponents, remove_small_components};
pub use remove_unreferenced_vertices::remove_unreferenced_vertices;
pub use stitch_borders::stitch_borders;
pub use tolerance::Tolerance;

use crate::mesh::IndexMaps;
use crate::soup::ListProblem;

/// What a repair changed. Ids are those of the input unless a field says otherwise; lists are
/// sorted ascending.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct RepairReport {
    /// Old-to-new ids (`u32::MAX` for removed elements). A face list's repairs fill `vertices`
    /// and `faces` (and leave `halfedges` and `edges` empty); a mesh's fill all four.
    pub maps: IndexMaps,
    /// Pairs `[removed, kept]`: vertex `removed` was merged into vertex `kept`.
    pub merged_vertices: Vec<[u32; 2]>,
    /// Vertices removed (merged ones included).
    pub removed_vertices: Vec<u32>,
    /// Faces removed.
    pub removed_faces: Vec<u32>,
    /// Pairs `[removed, kept]`: face `removed` was a duplicate of face `kept`.
    pub duplicate_faces: Vec<[u32; 2]>,
    /// Pairs `[a, b]` of boundary half-edges glued by [`stitch_borders`]: `a`'s edge is the
    /// stitched edge, `b`'s was removed.
    pub stitched_halfedges: Vec<[u32; 2]>,
    /// Corners dropped from faces that were kept (a corner repeating its predecessor's vertex
    /// after a merge).
    pub removed_corners: usize,
}

impl RepairReport {
    /// Whether the repair changed nothing.
    pub fn is_empty(&self) -> bool {
        self.merged_vertices.is_empty()
            && self.removed_vertices.is_empty()
            && self.removed_faces.is_empty()
            && self.stitched_halfedges.is_empty()
            && self.removed_corners == 0
    }
}

/// Why a repair refused (its input is unchanged).
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum RepairError {
    /// The tolerance cannot be used.
    #[error("tolerance {value} refused: {reason}")]
    BadTolerance {
        /// The value given.
        value: f64,
        /// Why it was refused.
        reason: &'static str,
    },
    /// An option other than the tolerance is out of range.
    #[error("option {name} is {value}: it must be {range}")]
    BadOption {
        /// The option's name.
        name: &'static str,
        /// The value given.
        value: f64,
        /// The values it may take.
        range: &'static str,
    },
    /// The face list as a whole is malformed (sizes and indices disagree, attributes are not
    /// one per corner, counts beyond 32-bit ids).
    #[error("malformed face list: {0}")]
    MalformedList(ListProblem),
    /// A face names a vertex that does not exist.
    #[error("face {face} names vertex {vertex}, but there are {n_vertices} vertices")]
    IndexOutOfRange {
        /// The face.
        face: u32,
        /// The index it holds.
        vertex: u32,
        /// The number of vertices.
        n_vertices: usize,
    },
}
