//! Repairs: operations that fix what the [doctor](crate::doctor) finds, each returning a
//! [`RepairReport`] of what it changed and leaving its input unchanged when it refuses.
//!
//! On indexed face lists ([`PolygonSoup`](crate::soup::PolygonSoup)): [`merge_vertices`] (exact and near duplicates),
//! [`remove_duplicate_faces`], [`remove_unreferenced_vertices`] and
//! [`remove_small_components`], [`orient_faces`], [`repair_non_manifold_edges`] and
//! [`split_non_manifold_vertices`]. On a [`Mesh`](crate::mesh::Mesh): [`remove_degenerate_faces`] (collapsing short edges,
//! flipping caps), [`remove_t_vertices`] (splitting boundary edges where another border's vertex
//! lies on them), [`stitch_borders`], and
//! [`fill_hole`] / [`fill_holes`], which close boundary loops with triangles.
//! The doctor's detection serves them: what it lists as duplicates, unreferenced vertices or
//! small components is what the repairs remove.
//!
//! Kept data follows its element: a kept corner keeps its normal and texture coordinate, a kept
//! vertex its position (and, on a mesh, its attributes), and removed elements' data goes with
//! them; what merged elements keep is said by each operation, and so is what added elements
//! (vertex copies) get. Vertices and faces are renumbered
//! in their order; [`RepairReport::maps`] gives the old-to-new ids.
//!
//! [`repair_mesh`] runs them all in turn, with a repairing build between the face-list and the
//! mesh repairs, and says what became of every input vertex and face ([`RepairFates`]); it
//! fills holes only when [`RepairOptions::fill_holes`] asks. A new repair joins it as one
//! [`RepairStep`].

mod fates;
mod fill_hole;
mod merge_vertices;
mod mesh_maps;
mod orient_faces;
mod remove_degenerate_faces;
mod remove_duplicate_faces;
mod remove_small_components;
mod remove_t_vertices;
mod remove_unreferenced_vertices;
mod repair_mesh;
mod repair_non_manifold_edges;
mod soup_edit;
mod split_non_manifold_vertices;
mod stitch_borders;
mod tolerance;

pub use fates::{FaceFate, Removal, VertexFate};
pub use fill_hole::{
    CROSSING_RETRIES, DEGENERATE_RATIO, DENSITY, EXACT_CORNERS_MAX, FAIR_ITERATIONS_MAX,
    FAIR_TOLERANCE, FOLD_ANGLE_DEGREES, FillError, FillMode, FilledHole, HoleFillOptions,
    HoleFillReport, REFINE_PASSES_MAX, REFINE_ROUNDS_MAX, fill_hole, fill_hole_with, fill_holes,
};
pub use merge_vertices::merge_vertices;
pub use orient_faces::orient_faces;
pub use remove_degenerate_faces::remove_degenerate_faces;
pub use remove_duplicate_faces::remove_duplicate_faces;
pub use remove_small_components::{SmallComponents, remove_small_components};
pub use remove_t_vertices::remove_t_vertices;
pub use remove_unreferenced_vertices::remove_unreferenced_vertices;
pub use repair_mesh::{FateCounts, RepairFates, RepairOptions, RepairStep, repair_mesh};
pub use repair_non_manifold_edges::{NonManifoldEdges, repair_non_manifold_edges};
pub use split_non_manifold_vertices::split_non_manifold_vertices;
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
    /// Vertices added, each a copy of an input vertex: the `i`-th added vertex (id `n + i`, `n`
    /// the vertex count before) copies vertex `vertex_copies[i]` and has its position.
    pub vertex_copies: Vec<u32>,
    /// Faces whose corner order was reversed.
    pub reoriented_faces: Vec<u32>,
    /// Pairs `[cap, across]` of triangles whose shared edge [`remove_degenerate_faces`] flipped:
    /// `cap` had a corner on the edge. Both stay.
    pub flipped_faces: Vec<[u32; 2]>,
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
            && self.vertex_copies.is_empty()
            && self.reoriented_faces.is_empty()
            && self.flipped_faces.is_empty()
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
    /// The repairing build refused the face list (out of memory, or a defect of the list as a
    /// whole).
    #[error("build failed: {0}")]
    Build(crate::soup::BuildError),
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
