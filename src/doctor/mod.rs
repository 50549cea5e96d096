//! The mesh doctor: one call that examines a face list (before any build) or a mesh and reports
//! every defect it finds, each finding naming the elements involved.
//!
//! The findings come in groups, one file each: the input's own diagnostic (malformed faces,
//! non-finite coordinates, non-manifold and inconsistently oriented edges, non-manifold,
//! unreferenced vertices, zero-area faces; see [`Diagnostic`]), the surface's components with
//! their topology and orientation ([`Component`]), its boundary loops and the fans of its
//! non-manifold vertices ([`BoundaryLoop`], [`VertexFans`]), degenerate shapes ([`FoldedEdge`]
//! and the needles, caps and long edges of [`DoctorReport`]) and duplicates ([`TVertex`] and the
//! duplicate vertices and faces). The report is printable as text (its `Display`) and as JSON
//! ([`DoctorReport::to_json`]).
//!
//! Every index is an input index: faces of the face list, vertices of its positions. Faces that
//! are malformed (fewer than 3 corners, an out-of-range index, a repeated vertex) are listed in
//! the diagnostic and left out of every other finding. The doctor never changes its input, and the
//! report's size follows the findings (and the number of components), not the mesh.

mod boundary;
mod components;
mod duplicates;
mod finding;
mod intersections;
mod measure;
mod point_tree;
mod shape;
mod text;

pub use boundary::{BoundaryLoop, VertexFans};
pub use components::Component;
pub use duplicates::TVertex;
pub use finding::{Finding, Highlight};
pub use shape::FoldedEdge;

pub(crate) use components::face_components;
pub(crate) use duplicates::{
    coincident_vertices, duplicate_faces, lies_inside_segment, lowest_at_each_position,
};
pub(crate) use measure::{EMPTY_BOX, bounding_box, distance, grow};
pub(crate) use point_tree::PointTree;

use std::ffi::CStr;

use crate::geom::SelfIntersectionError;
use crate::mesh::Mesh;
use crate::soup::{Diagnostic, FaceList, Inspection, inspect};

/// Thresholds of the findings that need one. [`DoctorOptions::default`] gives the documented
/// defaults.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DoctorOptions {
    /// Distance under which two vertices are near duplicates and a vertex lies on an edge
    /// (a T-vertex), relative to the diagonal of the bounding box of the named vertices.
    /// Default 1e-9; 0 finds exact coincidences only.
    pub relative_tolerance: f64,
    /// A triangle whose smallest angle is below this (degrees) is a needle. Default 5. (The
    /// angle thresholds are compared through cosines: to about 1e-6 degrees near 0 and 180.)
    pub needle_angle_degrees: f64,
    /// A triangle whose largest angle is above this (degrees) is a cap. Default 175.
    pub cap_angle_degrees: f64,
    /// Two faces sharing an edge whose normals make more than this angle (degrees) are folded
    /// onto each other. Default 175.
    pub fold_angle_degrees: f64,
    /// An edge longer than this many times the median edge length is long. Default 10.
    pub long_edge_ratio: f64,
    /// A component is small when its face count, or the diagonal of its bounding box, is at most
    /// this fraction of the largest component's. Default 0.01.
    pub small_component_ratio: f64,
}

impl Default for DoctorOptions {
    fn default() -> Self {
        DoctorOptions {
            relative_tolerance: 1e-9,
            needle_angle_degrees: 5.0,
            cap_angle_degrees: 175.0,
            fold_angle_degrees: 175.0,
            long_edge_ratio: 10.0,
            small_component_ratio: 0.01,
        }
    }
}

/// Why options were refused.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum DoctorError {
    /// The system refused memory the operation needed (see [`OutOfMemory`](crate::OutOfMemory)).
    #[error(transparent)]
    OutOfMemory(#[from] crate::OutOfMemory),
    /// A threshold is NaN, infinite or outside its range.
    #[error("doctor option {name} is {value}: it must be {range}")]
    BadOption {
        /// The option's name.
        name: &'static str,
        /// The value given.
        value: f64,
        /// The values it may take.
        range: &'static str,
    },
    /// The face list as a whole is malformed: nothing else can be examined.
    #[error("malformed face list:\n{0}")]
    MalformedList(Box<Diagnostic>),
    /// The faces cannot be searched for self-intersections (their triangulation is too large
    /// for 32-bit indices).
    #[error("self-intersections: {0}")]
    SelfIntersections(#[from] SelfIntersectionError),
}

/// Everything the doctor found (see the [module docs](self)).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct DoctorReport {
    /// The input's own findings (the lists of what a policy changes are empty).
    pub diagnostic: Diagnostic,
    /// The faces of each fan of every non-manifold vertex.
    pub non_manifold_vertex_fans: Vec<VertexFans>,
    /// The boundary loops (holes), in order of their lowest boundary edge.
    pub boundary_loops: Vec<BoundaryLoop>,
    /// The faces' connected components (faces sharing an edge), in order of their lowest face.
    pub components: Vec<Component>,
    /// The small components, as indices into [`DoctorReport::components`].
    pub small_components: Vec<u32>,
    /// A closed path of faces, each sharing an edge with the next (and the last with the
    /// first), along which the orientation flips: the surface is not orientable. The shortest
    /// such path through the first conflict found; empty when every component is orientable.
    pub non_orientable_witness: Vec<u32>,
    /// Edges whose two ends are at the same position, smaller vertex first.
    pub zero_length_edges: Vec<[u32; 2]>,
    /// Triangles with an angle below [`DoctorOptions::needle_angle_degrees`].
    pub needles: Vec<u32>,
    /// Triangles with an angle above [`DoctorOptions::cap_angle_degrees`].
    pub caps: Vec<u32>,
    /// Edges whose two faces fold onto each other (their normals more than
    /// [`DoctorOptions::fold_angle_degrees`] apart).
    pub folded_edges: Vec<FoldedEdge>,
    /// Edges longer than [`DoctorOptions::long_edge_ratio`] times the median edge length.
    pub long_edges: Vec<[u32; 2]>,
    /// Pairs `[v, first]`: vertex `v` is at exactly the position of the lower vertex `first`.
    pub duplicate_positions: Vec<[u32; 2]>,
    /// Pairs `[v, first]`: vertex `v` is within the tolerance of the lower vertex `first`, but
    /// not at its position. Vertices are grouped greedily in index order, as a merge would: one
    /// within the tolerance of a group's first vertex joins that group, else it starts one.
    pub near_duplicate_vertices: Vec<[u32; 2]>,
    /// Pairs `[f, first]`: face `f` has the vertex set of the lower face `first` (in either
    /// orientation).
    pub duplicate_faces: Vec<[u32; 2]>,
    /// Vertices lying inside a boundary edge they are not an end of.
    pub t_vertices: Vec<TVertex>,
    /// Pairs `[f, g]`, `f < g`, sorted, of faces that intersect other than along the vertices
    /// and edges they share, decided exactly (see [`crate::geom::face_self_intersections`] for
    /// the rules: polygons are tested as their triangles, touching counts). Triangles whose
    /// corners are exactly collinear (their faces are among the diagnostic's zero-area faces)
    /// and faces on non-finite vertices are not tested.
    pub self_intersections: Vec<[u32; 2]>,
}

impl DoctorReport {
    /// Whether the surface is a 2-manifold (possibly with boundary): no non-manifold edge or
    /// vertex, and no malformed face.
    pub fn is_manifold(&self) -> bool {
        let d = &self.diagnostic;
        d.non_manifold_edges.is_empty()
            && d.non_manifold_vertices.is_empty()
            && d.faces_too_small.is_empty()
            && d.faces_out_of_range.is_empty()
            && d.faces_repeated_vertex.is_empty()
    }

    /// Whether the surface has no boundary: no boundary loop, and no face left out as malformed.
    pub fn is_closed(&self) -> bool {
        self.boundary_loops.is_empty() && self.components.iter().all(|c| c.closed)
    }

    /// Whether every component is orientable and consistently oriented.
    pub fn is_oriented(&self) -> bool {
        self.non_orientable_witness.is_empty() && self.diagnostic.inconsistent_edges.is_empty()
    }

    /// `None` when the surface is a closed polyhedron — closed, manifold, consistently oriented,
    /// every component enclosing a positive volume, no self-intersection, with finite
    /// coordinates and no zero-area face; else the first reason it is not, in that order.
    pub fn not_a_closed_polyhedron(&self) -> Option<&'static str> {
        self.closed_polyhedron_fault()
            .map(|reason| reason.to_str().unwrap_or("not a closed polyhedron"))
    }

    /// [`DoctorReport::not_a_closed_polyhedron`] as static C text.
    pub(crate) fn closed_polyhedron_fault(&self) -> Option<&'static CStr> {
        let d = &self.diagnostic;
        if d.has_invalid_input() {
            return Some(c"malformed faces or non-finite coordinates");
        }
        if self.components.is_empty() {
            return Some(c"no faces");
        }
        if !self.is_manifold() {
            return Some(c"not a manifold");
        }
        if !self.is_closed() {
            return Some(c"not closed: it has boundary loops");
        }
        if !self.is_oriented() {
            return Some(c"not consistently oriented");
        }
        if self.components.iter().any(|c| c.outward != Some(true)) {
            return Some(c"a component faces inward or encloses no volume");
        }
        if !self.self_intersections.is_empty() {
            return Some(c"faces intersect each other");
        }
        if !d.degenerate_faces.is_empty() {
            return Some(c"some faces have no area");
        }
        None
    }
}

/// Examines `list` with `options` (see [`DoctorReport`]). Refused only when an option is out of
/// range or the list as a whole is malformed (its diagnostic says why).
pub fn examine(list: &FaceList<'_>, options: &DoctorOptions) -> Result<DoctorReport, DoctorError> {
    check_options(options)?;
    list.ensure_working_room()?;
    let inspection = inspect(list).map_err(DoctorError::MalformedList)?;
    examine_inspected(&inspection, list.positions, options)
}

impl Mesh {
    /// The doctor's report on the mesh (see [`examine`]), its indices those of the face list
    /// [`Mesh::to_soup`] gives: the mesh's own vertex and face ids when nothing is deleted.
    pub fn examine(&self, options: &DoctorOptions) -> Result<DoctorReport, DoctorError> {
        examine(&self.to_soup().as_face_list(), options)
    }
}

fn check_options(options: &DoctorOptions) -> Result<(), DoctorError> {
    let angles = [
        ("needle_angle_degrees", options.needle_angle_degrees),
        ("cap_angle_degrees", options.cap_angle_degrees),
        ("fold_angle_degrees", options.fold_angle_degrees),
    ];
    for (name, value) in angles {
        if !(0.0..=180.0).contains(&value) {
            return Err(DoctorError::BadOption {
                name,
                value,
                range: "between 0 and 180 degrees",
            });
        }
    }
    let ratios = [
        ("relative_tolerance", options.relative_tolerance, 0.0, 1.0),
        (
            "small_component_ratio",
            options.small_component_ratio,
            0.0,
            1.0,
        ),
        ("long_edge_ratio", options.long_edge_ratio, 1.0, f64::MAX),
    ];
    for (name, value, low, high) in ratios {
        if !(low..=high).contains(&value) {
            return Err(DoctorError::BadOption {
                name,
                value,
                range: if high == 1.0 {
                    "between 0 and 1"
                } else {
                    "finite and at least 1"
                },
            });
        }
    }
    Ok(())
}

fn examine_inspected(
    inspection: &Inspection<'_>,
    positions: &[[f64; 3]],
    options: &DoctorOptions,
) -> Result<DoctorReport, DoctorError> {
    let diagnostic = inspection.diagnostic.clone();
    let surface = &inspection.well_formed;
    let pairing = &inspection.pairing;
    let (boundary_loops, non_manifold_vertex_fans) = boundary::loops_and_fans(
        surface,
        pairing,
        positions,
        &diagnostic.non_manifold_vertices,
    );
    let topology = components::components(
        surface,
        pairing,
        positions,
        &diagnostic.non_manifold_vertices,
        &boundary_loops,
    );
    let small_components = components::small(&topology.components, options.small_component_ratio);
    let shapes = shape::shapes(surface, pairing, positions, options);
    let tolerance =
        duplicates::absolute_tolerance(&inspection.table, positions, options.relative_tolerance);
    let near = duplicates::coincident_vertices(positions, tolerance);
    let self_intersections = intersections::self_intersections(surface, positions)?;
    Ok(DoctorReport {
        non_manifold_vertex_fans,
        small_components,
        non_orientable_witness: topology.non_orientable_witness,
        components: topology.components,
        zero_length_edges: shapes.zero_length_edges,
        needles: shapes.needles,
        caps: shapes.caps,
        folded_edges: shapes.folded_edges,
        long_edges: shapes.long_edges,
        duplicate_positions: near.exact,
        near_duplicate_vertices: near.within_tolerance,
        duplicate_faces: duplicates::duplicate_faces(surface),
        t_vertices: duplicates::t_vertices(surface, pairing, positions, tolerance),
        self_intersections,
        boundary_loops: boundary_loops.into_iter().map(|(found, _)| found).collect(),
        diagnostic,
    })
}
