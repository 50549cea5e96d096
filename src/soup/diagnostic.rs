//! The report every build returns: every defect of a face list, named by index.

use std::fmt;

use crate::support::counted::counted;

/// How many elements of one list [`Diagnostic::summary`] names before it only counts the rest.
const SUMMARY_SAMPLE: usize = 8;

/// An undirected edge, given by its two input vertex indices (smaller first), and the input
/// faces that use it, in increasing face order.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct EdgeReport {
    /// The two vertex indices, `vertices[0] < vertices[1]`.
    pub vertices: [u32; 2],
    /// Input face indices using this edge, ascending.
    pub faces: Vec<u32>,
}

/// A problem with the face list as a whole (not with one face): nothing can be built.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ListProblem {
    /// Face sizes add up to `expected` corners but `actual` indices were given.
    CornerCountMismatch {
        /// Sum of the face sizes.
        expected: u64,
        /// Length of the index array.
        actual: u64,
    },
    /// With a uniform face size, the index count is not a multiple of it (or the size is 0).
    RaggedUniform {
        /// The uniform face size.
        size: u32,
        /// Length of the index array.
        indices: u64,
    },
    /// A per-corner attribute array (`what`: "corner normals", "corner uvs") does not have one
    /// entry per index.
    CornerAttributeMismatch {
        /// Which attribute.
        what: &'static str,
        /// Number of indices (corners).
        expected: u64,
        /// Length of the attribute array.
        actual: u64,
    },
    /// A count does not fit the `u32` ids the kernels use (indices must stay below `u32::MAX`,
    /// and every corner may need two half-edges).
    TooManyElements {
        /// Which count overflowed ("vertices", "faces", "corners").
        what: &'static str,
        /// The offending count.
        count: u64,
    },
}

impl fmt::Display for ListProblem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ListProblem::CornerCountMismatch { expected, actual } => write!(
                f,
                "face sizes add up to {expected} corners but {actual} indices were given"
            ),
            ListProblem::RaggedUniform { size, indices } => {
                write!(
                    f,
                    "{indices} indices do not split into faces of {size} corners"
                )
            }
            ListProblem::CornerAttributeMismatch {
                what,
                expected,
                actual,
            } => write!(f, "{actual} {what} given for {expected} corners"),
            ListProblem::TooManyElements { what, count } => {
                write!(f, "{count} {what} exceed the 32-bit index range")
            }
        }
    }
}

/// Everything wrong with an input face list, by index, and what a build's policy changed.
///
/// The findings (every list but the last three) describe the input as it is, the same for a
/// build under any policy and for [`Mesh::diagnose`](crate::mesh::Mesh::diagnose). Faces with
/// fewer than 3 corners, an out-of-range index or a repeated vertex are listed as such and left
/// out of the edge, fan and area findings. The last three lists say what the policy changed:
/// [`Diagnostic::skipped_faces`], [`Diagnostic::reoriented_faces`],
/// [`Diagnostic::vertex_copies`]. All face indices refer to the input face list, vertex indices
/// to the input positions.
///
/// Lists are sorted ascending. An empty diagnostic ([`Diagnostic::is_clean`]) means a clean,
/// closed-or-bordered, consistently oriented 2-manifold.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Diagnostic {
    /// A defect of the list as a whole; when set, nothing else was analysed.
    pub list_problem: Option<ListProblem>,
    /// Faces with fewer than 3 corners (after repair collapsed repeated consecutive corners).
    pub faces_too_small: Vec<u32>,
    /// Faces with a vertex index beyond the positions.
    pub faces_out_of_range: Vec<u32>,
    /// Faces that name one vertex more than once.
    pub faces_repeated_vertex: Vec<u32>,
    /// Vertices with a NaN or infinite coordinate.
    pub non_finite_vertices: Vec<u32>,
    /// Edges used by three or more faces.
    pub non_manifold_edges: Vec<EdgeReport>,
    /// Edges used by exactly two faces that traverse it in the same direction.
    pub inconsistent_edges: Vec<EdgeReport>,
    /// Vertices whose faces form more than one fan, faces being in one fan when they share an
    /// edge at the vertex (e.g. two cones touching at a tip). `Strict` refuses them; `Skip` and
    /// `Repair` give every fan but the first a copy of the vertex.
    pub non_manifold_vertices: Vec<u32>,
    /// Vertices no face names (kept, with no half-edge). A vertex whose every face the policy
    /// left out is in the structure without a face too, but not listed here.
    pub isolated_vertices: Vec<u32>,
    /// Faces with zero area (Newell vector negligible against their edge lengths).
    pub degenerate_faces: Vec<u32>,
    /// Faces left out of the built structure (by `Skip`, or the faces `Repair` cannot keep; see
    /// [`BuildPolicy`](super::BuildPolicy)). Kept faces keep their relative order: built face `i`
    /// is the `i`-th input face not listed here.
    pub skipped_faces: Vec<u32>,
    /// Faces `Repair` built the other way round from the input, so that they agree with their
    /// neighbours or so that their closed component faces outward.
    pub reoriented_faces: Vec<u32>,
    /// Vertices added by `Skip` or `Repair` (splitting non-manifold vertices, cutting along
    /// problem edges): built vertex `n_input_vertices + i` copies input vertex
    /// `vertex_copies[i]` (same position).
    pub vertex_copies: Vec<u32>,
}

impl Diagnostic {
    /// Nothing found (what [`Diagnostic::default`] gives, as a constant).
    pub const EMPTY: Diagnostic = Diagnostic {
        list_problem: None,
        faces_too_small: Vec::new(),
        faces_out_of_range: Vec::new(),
        faces_repeated_vertex: Vec::new(),
        non_finite_vertices: Vec::new(),
        non_manifold_edges: Vec::new(),
        inconsistent_edges: Vec::new(),
        non_manifold_vertices: Vec::new(),
        isolated_vertices: Vec::new(),
        degenerate_faces: Vec::new(),
        skipped_faces: Vec::new(),
        reoriented_faces: Vec::new(),
        vertex_copies: Vec::new(),
    };

    /// `true` when nothing at all was found.
    pub fn is_clean(&self) -> bool {
        self == &Diagnostic::default()
    }

    /// `true` when some face is malformed (too small, out-of-range or repeated index), a
    /// coordinate is not finite, or the list as a whole is malformed.
    pub fn has_invalid_input(&self) -> bool {
        self.list_problem.is_some()
            || !self.faces_too_small.is_empty()
            || !self.faces_out_of_range.is_empty()
            || !self.faces_repeated_vertex.is_empty()
            || !self.non_finite_vertices.is_empty()
    }

    /// `true` when some edge is non-manifold or inconsistently oriented.
    pub fn has_edge_defects(&self) -> bool {
        !self.non_manifold_edges.is_empty() || !self.inconsistent_edges.is_empty()
    }

    /// A human-readable account: one line per non-empty list (no newline after the last), with its count and
    /// its first 8 elements (`12 isolated vertices: v0 v1 v2 v3 v4 v5 v6 v7 … and 4 more`); an
    /// edge names its first 8 faces the same way. Its size does not grow with the input: a few
    /// kilobytes at most.
    pub fn summary(&self) -> String {
        self.to_string()
    }
}

/// Writes the first [`SUMMARY_SAMPLE`] of `items`, each after a space, then ` … and N more` when
/// there are others: every list the summary shows goes through here, so its size stays bounded
/// whatever the input (a million copies of one face put a million faces on each of its edges).
fn write_sample<T>(
    f: &mut fmt::Formatter<'_>,
    items: &[T],
    mut write_item: impl FnMut(&mut fmt::Formatter<'_>, &T) -> fmt::Result,
) -> fmt::Result {
    for item in items.iter().take(SUMMARY_SAMPLE) {
        f.write_str(" ")?;
        write_item(f, item)?;
    }
    if items.len() > SUMMARY_SAMPLE {
        write!(f, " … and {} more", items.len() - SUMMARY_SAMPLE)?;
    }
    Ok(())
}

/// The line of one list of ids, when it is not empty: its count with `label` (singular and
/// plural: the count's noun comes first), then a sample of the ids, each after `prefix`.
fn ids_line(label: [&str; 2], prefix: &str, ids: &[u32]) -> Option<String> {
    (!ids.is_empty()).then(|| {
        format!(
            "{}:{}",
            counted(ids.len(), label[0], label[1]),
            Sample(ids, |f: &mut fmt::Formatter<'_>, id: &u32| write!(
                f,
                "{prefix}{id}"
            ))
        )
    })
}

/// The line of one list of edges, as [`ids_line`], each edge with a sample of its faces.
fn edges_line(label: [&str; 2], edges: &[EdgeReport]) -> Option<String> {
    (!edges.is_empty()).then(|| {
        let edge = |f: &mut fmt::Formatter<'_>, edge: &EdgeReport| {
            let face = |f: &mut fmt::Formatter<'_>, face: &u32| write!(f, "f{face}");
            let [u, v] = edge.vertices;
            write!(f, "(v{u}-v{v} in faces{})", Sample(&edge.faces, face))
        };
        format!(
            "{}:{}",
            counted(edges.len(), label[0], label[1]),
            Sample(edges, edge)
        )
    })
}

/// A list shown through [`write_sample`].
struct Sample<'a, T, W>(&'a [T], W);

impl<T, W: Fn(&mut fmt::Formatter<'_>, &T) -> fmt::Result> fmt::Display for Sample<'_, T, W> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write_sample(f, self.0, &self.1)
    }
}

/// One line per non-empty list, separated by newlines (no newline after the last).
impl fmt::Display for Diagnostic {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.is_clean() {
            return f.write_str("no defects found");
        }
        let lines = [
            self.list_problem
                .as_ref()
                .map(|problem| format!("malformed face list: {problem}")),
            ids_line(
                [
                    "face with fewer than 3 corners",
                    "faces with fewer than 3 corners",
                ],
                "f",
                &self.faces_too_small,
            ),
            ids_line(
                [
                    "face with out-of-range vertex indices",
                    "faces with out-of-range vertex indices",
                ],
                "f",
                &self.faces_out_of_range,
            ),
            ids_line(
                [
                    "face with a repeated vertex",
                    "faces with a repeated vertex",
                ],
                "f",
                &self.faces_repeated_vertex,
            ),
            ids_line(
                [
                    "vertex with NaN/infinite coordinates",
                    "vertices with NaN/infinite coordinates",
                ],
                "v",
                &self.non_finite_vertices,
            ),
            edges_line(
                [
                    "non-manifold edge (3+ faces)",
                    "non-manifold edges (3+ faces)",
                ],
                &self.non_manifold_edges,
            ),
            edges_line(
                [
                    "inconsistently oriented edge",
                    "inconsistently oriented edges",
                ],
                &self.inconsistent_edges,
            ),
            ids_line(
                ["non-manifold vertex", "non-manifold vertices"],
                "v",
                &self.non_manifold_vertices,
            ),
            ids_line(
                ["isolated vertex", "isolated vertices"],
                "v",
                &self.isolated_vertices,
            ),
            ids_line(
                [
                    "degenerate (zero-area) face",
                    "degenerate (zero-area) faces",
                ],
                "f",
                &self.degenerate_faces,
            ),
            ids_line(["face skipped", "faces skipped"], "f", &self.skipped_faces),
            ids_line(
                ["face reversed by repair", "faces reversed by repair"],
                "f",
                &self.reoriented_faces,
            ),
            ids_line(
                [
                    "vertex duplicated, copies of",
                    "vertices duplicated, copies of",
                ],
                "v",
                &self.vertex_copies,
            ),
        ];
        let mut first = true;
        for line in lines.into_iter().flatten() {
            if !first {
                f.write_str("\n")?;
            }
            first = false;
            f.write_str(&line)?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn summary_names_every_non_empty_list() {
        let diagnostic = Diagnostic {
            faces_too_small: vec![3],
            non_manifold_edges: vec![EdgeReport {
                vertices: [1, 2],
                faces: vec![0, 4, 5],
            }],
            isolated_vertices: (0..20).collect(),
            ..Diagnostic::default()
        };
        let text = diagnostic.summary();
        assert!(
            text.contains("1 face with fewer than 3 corners: f3\n"),
            "{text}"
        );
        assert!(text.contains("(v1-v2 in faces f0 f4 f5)"), "{text}");
        assert!(
            text.contains("20 isolated vertices: v0 v1 v2 v3 v4 v5 v6 v7 … and 12 more"),
            "{text}"
        );
        assert!(!diagnostic.is_clean());
        assert!(diagnostic.has_invalid_input());
        assert_eq!(Diagnostic::default().summary(), "no defects found");
    }

    #[test]
    fn summary_names_reversed_faces() {
        // Before: a diagnostic whose only finding was reversed faces summarised as "".
        let diagnostic = Diagnostic {
            reoriented_faces: vec![1, 4],
            ..Diagnostic::default()
        };
        assert_eq!(diagnostic.summary(), "2 faces reversed by repair: f1 f4");
    }

    #[test]
    fn faces_on_an_edge_are_counted_beyond_the_first_few() {
        // A million copies of one triangle: each of its three edges is used by every copy.
        // Before: the summary listed every face of every edge, 23.7 MB.
        let faces: Vec<u32> = (0..1_000_000).collect();
        let edges = [[0, 1], [1, 2], [0, 2]].map(|vertices| EdgeReport {
            vertices,
            faces: faces.clone(),
        });
        let diagnostic = Diagnostic {
            non_manifold_edges: edges.to_vec(),
            ..Diagnostic::default()
        };
        let text = diagnostic.summary();
        assert!(text.len() < 1024, "{} bytes", text.len());
        assert!(
            text.starts_with(
                "3 non-manifold edges (3+ faces): \
                 (v0-v1 in faces f0 f1 f2 f3 f4 f5 f6 f7 … and 999992 more) (v1-v2 in faces"
            ),
            "{text}"
        );
    }
}
