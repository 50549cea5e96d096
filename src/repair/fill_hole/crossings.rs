//! Whether a fill would intersect the mesh: its new triangles are tested exactly (as
//! [`crate::geom::self_intersections`] tests pairs) against the mesh's faces whose boxes they
//! overlap, found in box trees, and against each other.
//!
//! For many holes, the mesh's faces are held as fans of triangles. Filled patches are added as
//! they are cut in, in trees of doubling sizes (a new tree absorbs every smaller one), so that
//! filling many holes costs O(n log² n) for the trees and each query O(log² n + k).
//!
//! For one hole, a tree over the whole mesh would cost more than the fill: the query instead
//! scans the faces' boxes (one pass over the corners' positions, no sorting) for those meeting
//! the new triangles' overall box, and builds a tree over these few only. The answers are the
//! same: a face whose box misses the overall box misses every new triangle's box.

use std::collections::HashMap;

use crate::geom::box_tree::{BoundingBox, BoxTree, Boxed};
use crate::geom::exact_orientation::ExponentRange;
use crate::geom::triangle_intersection::{is_degenerate_exactly, triangles_meet_exactly};
use crate::mesh::{FaceId, Mesh, VertexId};

/// A non-degenerate triangle on mesh vertices, ready for exact tests.
#[derive(Clone, Copy, Debug)]
struct Nearby {
    bounds: BoundingBox,
    ids: [u32; 3],
    points: [[f64; 3]; 3],
    exponents: ExponentRange,
}

impl Boxed for Nearby {
    fn bounding_box(&self) -> &BoundingBox {
        &self.bounds
    }
}

impl Nearby {
    /// The triangle on vertices `ids` at `points`, or `None` when it is degenerate or a
    /// coordinate is not finite (no intersection can be decided with it).
    fn new(ids: [u32; 3], points: [[f64; 3]; 3]) -> Option<Nearby> {
        if !points.iter().flatten().all(|x| x.is_finite()) {
            return None;
        }
        let exponents = ExponentRange::of(points.iter().flatten().copied());
        (!is_degenerate_exactly(points, exponents)).then(|| Nearby {
            bounds: BoundingBox::of_points(&points),
            ids,
            points,
            exponents,
        })
    }

    fn meets(&self, other: &Nearby) -> bool {
        triangles_meet_exactly(
            (self.ids, self.points, self.exponents),
            (other.ids, other.points, other.exponents),
        )
    }
}

/// The faces of a mesh, as triangles in box trees, that fills must not cross.
pub(super) struct Surroundings {
    /// Trees of strictly decreasing sizes.
    trees: Vec<BoxTree<Nearby>>,
    /// Vertices welded into another (see [`Surroundings::weld`]): the trees keep their old ids.
    welded: HashMap<u32, u32>,
    /// The mesh's faces are not in the trees: each query scans the mesh for those near it.
    scans_mesh: bool,
}

impl Surroundings {
    /// The live faces of `mesh` (fans from their first corner), in trees for many queries.
    /// O(n log n).
    pub(super) fn new(mesh: &Mesh) -> Surroundings {
        let mut surroundings = Surroundings {
            trees: Vec::new(),
            welded: HashMap::new(),
            scans_mesh: false,
        };
        surroundings.add(mesh, live_faces(mesh));
        surroundings
    }

    /// The faces of the mesh each query is given, found by a scan of the mesh per query: for
    /// one hole (a few queries), where a tree over the whole mesh costs more than the fill.
    pub(super) fn scanned() -> Surroundings {
        Surroundings {
            trees: Vec::new(),
            welded: HashMap::new(),
            scans_mesh: true,
        }
    }

    /// Adds the faces `faces` of `mesh` (nothing to do when the mesh is scanned: they are in it).
    pub(super) fn add(&mut self, mesh: &Mesh, faces: impl IntoIterator<Item = FaceId>) {
        if self.scans_mesh {
            return;
        }
        let mut triangles = fan_triangles(mesh, faces);
        while self
            .trees
            .last()
            .is_some_and(|tree| tree.len() <= triangles.len())
        {
            let tree = self.trees.pop().expect("checked");
            triangles.extend(tree.into_items());
        }
        if !triangles.is_empty() {
            self.trees.push(BoxTree::new(triangles));
        }
    }

    /// Records that vertex `gone` is now vertex `kept` (its fan moved when a hole's boundary
    /// was pinched), or, with `None`, that it is itself again.
    pub(super) fn weld(&mut self, gone: u32, kept: Option<u32>) {
        match kept {
            Some(kept) => self.welded.insert(gone, kept),
            None => self.welded.remove(&gone),
        };
    }

    /// `triangle` with its welded vertices renamed.
    fn current(&self, triangle: &Nearby) -> Nearby {
        let mut current = *triangle;
        if !self.welded.is_empty() {
            current.ids = current.ids.map(|v| *self.welded.get(&v).unwrap_or(&v));
        }
        current
    }

    /// The indices of the triangles of `triangles` (corner indices into `ids` and `points`, the
    /// hole's corners' vertex ids and positions) that meet a face of the surroundings (of
    /// `mesh`'s faces, when scanned) or, when `among_themselves`, another of `triangles`.
    /// Degenerate triangles are not listed: the fold test refuses them.
    pub(super) fn crossing_triangles(
        &self,
        mesh: &Mesh,
        ids: &[u32],
        points: &[[f64; 3]],
        triangles: &[[u32; 3]],
        among_themselves: bool,
    ) -> Vec<usize> {
        let new: Vec<(usize, Nearby)> = triangles
            .iter()
            .enumerate()
            .filter_map(|(t, tri)| {
                Nearby::new(
                    tri.map(|k| ids[k as usize]),
                    tri.map(|k| points[k as usize]),
                )
                .map(|nearby| (t, nearby))
            })
            .collect();
        let near = match new.split_first() {
            Some((&(_, first), rest)) if self.scans_mesh => {
                let overall = rest
                    .iter()
                    .fold(first.bounds, |b, (_, n)| b.union(&n.bounds));
                Some(BoxTree::new(fan_triangles(
                    mesh,
                    faces_meeting(mesh, &overall),
                )))
            }
            _ => None,
        };
        let mut crossing = vec![false; triangles.len()];
        for &(t, ref triangle) in &new {
            for tree in self.trees.iter().chain(&near) {
                if crossing[t] {
                    break;
                }
                tree.visit_overlapping(&triangle.bounds, |other| {
                    crossing[t] = crossing[t] || triangle.meets(&self.current(other));
                });
            }
        }
        if among_themselves && new.len() > 1 {
            let pairs = BoxTree::new(new.iter().map(|&(t, n)| Indexed(t, n)).collect())
                .overlapping_pairs(|a, b| a.1.meets(&b.1).then_some([a.0, b.0]));
            for [a, b] in pairs {
                crossing[a] = true;
                crossing[b] = true;
            }
        }
        (0..triangles.len()).filter(|&t| crossing[t]).collect()
    }
}

/// The live faces of `mesh`.
fn live_faces(mesh: &Mesh) -> impl Iterator<Item = FaceId> + '_ {
    (0..mesh.n_face_slots() as u32)
        .map(FaceId)
        .filter(|&f| mesh.check_face(f).is_ok())
}

/// The non-degenerate triangles of fans of `faces` of `mesh` from their first corner.
fn fan_triangles(mesh: &Mesh, faces: impl IntoIterator<Item = FaceId>) -> Vec<Nearby> {
    let mut triangles = Vec::new();
    let mut corners = Vec::new();
    for f in faces {
        corners.clear();
        corners.extend(mesh.face_vertices(f).map(|v| v.0));
        for i in 1..corners.len().saturating_sub(1) {
            let ids = [corners[0], corners[i], corners[i + 1]];
            triangles.extend(Nearby::new(ids, ids.map(|v| mesh.position(VertexId(v)))));
        }
    }
    triangles
}

/// The live faces of `mesh` whose boxes meet `bounds`, in one pass over the raw arrays (no
/// handle checks, no allocation but the answer).
fn faces_meeting(mesh: &Mesh, bounds: &BoundingBox) -> Vec<FaceId> {
    let (nexts, origins, positions) = (
        mesh.halfedge_nexts(),
        mesh.halfedge_origins(),
        mesh.positions(),
    );
    let deleted = mesh.face_deletion_marks();
    let mut faces = Vec::new();
    for (f, &first) in mesh.face_halfedges().iter().enumerate() {
        if deleted.get(f).copied().unwrap_or(false) || first == u32::MAX {
            continue;
        }
        let p = positions[origins[first as usize] as usize];
        let mut face_box = BoundingBox { min: p, max: p };
        let mut h = nexts[first as usize];
        // A face has fewer corners than half-edges: the bound only guards a broken loop.
        for _ in 0..nexts.len() {
            if h == first {
                break;
            }
            face_box.extend(positions[origins[h as usize] as usize]);
            h = nexts[h as usize];
        }
        if face_box.overlaps(bounds) {
            faces.push(FaceId(f as u32));
        }
    }
    faces
}

/// A new triangle and its index, for the search among new triangles.
#[derive(Clone, Copy, Debug)]
struct Indexed(usize, Nearby);

impl Boxed for Indexed {
    fn bounding_box(&self) -> &BoundingBox {
        &self.1.bounds
    }
}
