//! The kinds of finding that are lists of elements, by one name in Rust, C and the text report,
//! and what each one highlights (faces, edges, vertices or component boxes) for drawing.

use super::DoctorReport;

/// A kind of finding that is a list of items (see each [`DoctorReport`] field of the same name).
/// The C API numbers them in this order from `HW_DOCTOR_FINDING_FIRST`
/// (`HW_DOCTOR_FINDING_SMALL_COMPONENTS`, …).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Finding {
    /// [`DoctorReport::small_components`]: one component index per item.
    SmallComponents,
    /// [`DoctorReport::non_orientable_witness`]: one face per item.
    NonOrientableWitness,
    /// [`DoctorReport::zero_length_edges`]: two vertices per item.
    ZeroLengthEdges,
    /// [`DoctorReport::needles`]: one face per item.
    Needles,
    /// [`DoctorReport::caps`]: one face per item.
    Caps,
    /// [`DoctorReport::folded_edges`]: two vertices then two faces per item.
    FoldedEdges,
    /// [`DoctorReport::long_edges`]: two vertices per item.
    LongEdges,
    /// [`DoctorReport::duplicate_positions`]: the vertex, then the lowest at its position.
    DuplicatePositions,
    /// [`DoctorReport::near_duplicate_vertices`]: the vertex, then its group's first.
    NearDuplicateVertices,
    /// [`DoctorReport::duplicate_faces`]: the face, then the lowest on its vertex set.
    DuplicateFaces,
    /// [`DoctorReport::t_vertices`]: the vertex, the edge's two ends, the edge's face.
    TVertices,
    /// [`DoctorReport::self_intersections`]: two faces per item.
    SelfIntersections,
}

impl Finding {
    /// Every kind, in the C API's order.
    pub const ALL: [Finding; 12] = [
        Finding::SmallComponents,
        Finding::NonOrientableWitness,
        Finding::ZeroLengthEdges,
        Finding::Needles,
        Finding::Caps,
        Finding::FoldedEdges,
        Finding::LongEdges,
        Finding::DuplicatePositions,
        Finding::NearDuplicateVertices,
        Finding::DuplicateFaces,
        Finding::TVertices,
        Finding::SelfIntersections,
    ];

    /// The kind numbered `index` in [`Finding::ALL`].
    pub fn from_index(index: u32) -> Option<Finding> {
        Finding::ALL.get(index as usize).copied()
    }

    /// The name the text report and the C API give it.
    pub fn name(self) -> &'static str {
        self.c_name().to_str().unwrap_or("finding")
    }

    /// [`Finding::name`] as static C text.
    pub(crate) fn c_name(self) -> &'static std::ffi::CStr {
        match self {
            Finding::SmallComponents => c"small components",
            Finding::NonOrientableWitness => c"faces on a path that flips orientation",
            Finding::ZeroLengthEdges => c"zero-length edges",
            Finding::Needles => c"needles",
            Finding::Caps => c"caps",
            Finding::FoldedEdges => c"folded edges",
            Finding::LongEdges => c"long edges",
            Finding::DuplicatePositions => c"duplicate positions",
            Finding::NearDuplicateVertices => c"near-duplicate vertices",
            Finding::DuplicateFaces => c"duplicate faces",
            Finding::TVertices => c"T-vertices",
            Finding::SelfIntersections => c"intersecting face pairs",
        }
    }
}

/// What to draw of a finding: per item, the faces, edges and vertices it names, and for small
/// components the component's bounding box. Each element comes with its item's index.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Highlight {
    /// `(item, face)`.
    pub faces: Vec<(u32, u32)>,
    /// `(item, [a, b])`: the edge between vertices `a` and `b`.
    pub edges: Vec<(u32, [u32; 2])>,
    /// `(item, vertex)`.
    pub vertices: Vec<(u32, u32)>,
    /// `(item, [low, high])`: the corners of a component's bounding box.
    pub boxes: Vec<(u32, [[f64; 3]; 2])>,
}

impl DoctorReport {
    /// The items of `kind` as one flat array of ids, and the ids per item (see [`Finding`]).
    pub fn finding(&self, kind: Finding) -> (&[u32], usize) {
        match kind {
            Finding::SmallComponents => (&self.small_components, 1),
            Finding::NonOrientableWitness => (&self.non_orientable_witness, 1),
            Finding::ZeroLengthEdges => (self.zero_length_edges.as_flattened(), 2),
            Finding::Needles => (&self.needles, 1),
            Finding::Caps => (&self.caps, 1),
            Finding::FoldedEdges => (flat_quads(&self.folded_edges), 4),
            Finding::LongEdges => (self.long_edges.as_flattened(), 2),
            Finding::DuplicatePositions => (self.duplicate_positions.as_flattened(), 2),
            Finding::NearDuplicateVertices => (self.near_duplicate_vertices.as_flattened(), 2),
            Finding::DuplicateFaces => (self.duplicate_faces.as_flattened(), 2),
            Finding::TVertices => (flat_quads(&self.t_vertices), 4),
            Finding::SelfIntersections => (self.self_intersections.as_flattened(), 2),
        }
    }

    /// The elements `kind` names, for drawing: faces as faces, edges as edges, vertices as
    /// vertices (a duplicate or near-duplicate vertex with an edge to the vertex it repeats, a
    /// T-vertex with the edge it lies on), small components as their bounding boxes.
    pub fn highlight(&self, kind: Finding) -> Highlight {
        let (ids, per_item) = self.finding(kind);
        let items = ids.chunks_exact(per_item).zip(0u32..);
        let mut found = Highlight::default();
        match kind {
            Finding::SmallComponents => {
                found.boxes = items
                    .map(|(c, item)| (item, self.components[c[0] as usize].bounding_box))
                    .collect();
            }
            Finding::NonOrientableWitness
            | Finding::Needles
            | Finding::Caps
            | Finding::DuplicateFaces
            | Finding::SelfIntersections => {
                for (faces, item) in items {
                    found.faces.extend(faces.iter().map(|&f| (item, f)));
                }
            }
            Finding::ZeroLengthEdges => {
                found.vertices = items.map(|(e, item)| (item, e[0])).collect();
            }
            Finding::LongEdges => {
                found.edges = items.map(|(e, item)| (item, [e[0], e[1]])).collect();
            }
            Finding::FoldedEdges => {
                for (e, item) in items {
                    found.edges.push((item, [e[0], e[1]]));
                    found.faces.extend([(item, e[2]), (item, e[3])]);
                }
            }
            Finding::DuplicatePositions | Finding::NearDuplicateVertices => {
                for (pair, item) in items {
                    found.vertices.push((item, pair[0]));
                    found.edges.push((item, [pair[0], pair[1]]));
                }
            }
            Finding::TVertices => {
                for (t, item) in items {
                    found.vertices.push((item, t[0]));
                    found.edges.push((item, [t[1], t[2]]));
                }
            }
        }
        found
    }
}

/// A list of four-`u32` records as one flat array.
fn flat_quads<T: FourIds>(records: &[T]) -> &[u32] {
    // SAFETY: `FourIds` types are `repr(C)` records of exactly four `u32` and no padding.
    unsafe { std::slice::from_raw_parts(records.as_ptr().cast::<u32>(), 4 * records.len()) }
}

/// Records laid out as four `u32` (`repr(C)`, no padding).
///
/// # Safety
/// Implementors must have exactly that layout.
unsafe trait FourIds {}
// SAFETY: both are `repr(C)` with four `u32` fields.
unsafe impl FourIds for super::FoldedEdge {}
// SAFETY: as above.
unsafe impl FourIds for super::TVertex {}
