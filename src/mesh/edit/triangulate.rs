//! Triangulating a polygon face.

use std::collections::{HashMap, HashSet};

use super::{EditError, refuse};
use crate::geom::PolygonTriangulator;
use crate::mesh::{FaceId, HalfedgeId, Mesh, VertexId};

const TRIANGULATE: &str = "face triangulation";

/// Corners tried as fan apexes when the first triangulation needs an edge that exists: a fan
/// from a corner joined to no other corner needs none, and covers a convex face.
const FAN_APEXES: usize = 2;

/// Pairs of corners looked at per edge among the face's vertices when choosing fan apexes.
const PAIRS_LOOKED_AT: usize = 16;

impl Mesh {
    /// Splits face `f` into triangles, the ones the render buffers draw for it (see
    /// [`PolygonTriangulator`]): non-convex faces come out with every triangle facing the face's
    /// way, and a simple polygon is covered exactly once. When one of those triangles' diagonals
    /// already exists as an edge (the two corners are joined outside the face), a few other
    /// triangulations are tried — sweeps in other directions, fans from corners joined to no
    /// other corner — and the first that needs no existing edge is cut instead. Returns the
    /// faces, `f` first. O(n log n) for `n` corners, plus the valences of the face's vertices.
    ///
    /// # Errors
    /// Refused, with the mesh unchanged, when every triangulation tried needs a diagonal that
    /// already exists as an edge or joins a vertex to itself (a face that visits a vertex
    /// twice): a second edge between two vertices would make the mesh non-manifold.
    pub fn triangulate_face(&mut self, f: FaceId) -> Result<Vec<FaceId>, EditError> {
        self.check_face(f)?;
        let loop_: Vec<HalfedgeId> = self.face_loop(f).collect();
        let n = loop_.len();
        if n <= 3 {
            return Ok(vec![f]);
        }
        // Corner k is the target of loop_[k].
        let vertices: Vec<VertexId> = loop_.iter().map(|&h| self.target(h)).collect();
        let corners: Vec<[f64; 3]> = vertices.iter().map(|&v| self.position(v)).collect();
        let joined = JoinedCorners::new(self, &vertices);
        let mut chords = Vec::with_capacity(n - 3);
        let mut triangles = Vec::with_capacity(n - 2);
        let found = PolygonTriangulator::new().triangulate_choosing(
            &corners,
            &joined.free_corners(FAN_APEXES),
            &mut triangles,
            |candidate| {
                chords_of(candidate, n as u32, &mut chords);
                joined.allows(&chords)
            },
        );
        if found.is_none() {
            return refuse(
                TRIANGULATE,
                "every triangulation tried needs a diagonal that already exists as an edge",
            );
        }
        chords_of(&triangles, n as u32, &mut chords);
        self.cut_along_chords(f, loop_, &chords)
    }

    /// Cuts face `f` into triangles along `chords`, pairs `(a, c)`, `a < c`, of corners that
    /// join no vertices an edge joins (see [`JoinedCorners::allows`]) and that nest, as
    /// [`chords_of`] gives for a triangulation of the face's ring of corners. `into[k]` is the
    /// half-edge of `f` into corner `k`. Returns the faces, `f` first.
    pub(crate) fn cut_along_chords(
        &mut self,
        f: FaceId,
        mut into: Vec<HalfedgeId>,
        chords: &[(u32, u32)],
    ) -> Result<Vec<FaceId>, EditError> {
        let needed_edges = chords.len() as u64;
        if self.origin.len() as u64 + 2 * needed_edges >= u64::from(u32::MAX)
            || self.face_halfedge.len() as u64 + needed_edges >= u64::from(u32::MAX)
        {
            return Err(EditError::Full {
                operation: TRIANGULATE,
            });
        }
        // A chord (a, c), a < c, splits `f` from corner a to corner c: the new face takes the
        // corners between them, and `f` the rest, where the new half-edge a → c leads into c.
        // Taking the chords from the shortest span up, every chord within (a, c) has been cut
        // already, so the new face is a triangle.
        let mut chords = chords.to_vec();
        chords.sort_unstable_by_key(|&(a, c)| c - a);
        let mut faces = Vec::with_capacity(chords.len() + 1);
        faces.push(f);
        for &(a, c) in &chords {
            // The chords passed `JoinedCorners::allows` and nest: `split_face`'s checks hold.
            let new_into_c = self.cut_face(into[a as usize], into[c as usize])?;
            into[c as usize] = new_into_c;
            faces.push(FaceId((self.face_halfedge.len() - 1) as u32));
        }
        Ok(faces)
    }
}

/// Sets `chords` to the diagonals `(a, c)`, `a < c`, of a triangulation of the ring of corners
/// `0..n`: the triangle sides that are not sides of the ring, each once.
pub(crate) fn chords_of(triangles: &[[u32; 3]], n: u32, chords: &mut Vec<(u32, u32)>) {
    chords.clear();
    for t in triangles {
        for k in 0..3 {
            let (a, c) = (t[k].min(t[(k + 1) % 3]), t[k].max(t[(k + 1) % 3]));
            if c - a >= 2 && !(a == 0 && c == n - 1) {
                chords.push((a, c));
            }
        }
    }
    // Each diagonal is a side of the two triangles beside it.
    chords.sort_unstable();
    chords.dedup();
}

/// Which corners of a face may not be joined by a new edge: those whose vertices an edge
/// already joins, and two corners of one vertex.
pub(crate) struct JoinedCorners<'a> {
    vertices: &'a [VertexId],
    /// The pairs `(u, v)`, `u < v`, of the face's vertices that an edge joins.
    edges: HashSet<(u32, u32)>,
    /// Per corner: whether some other corner than its two neighbours may not be joined to it.
    blocked: Vec<bool>,
}

impl<'a> JoinedCorners<'a> {
    /// The edges among the face's `vertices` (corner k at `vertices[k]`), from every fan: one
    /// scan of all half-edges when some vertex may have fans its walk misses, else a walk round
    /// each vertex.
    pub(crate) fn new(mesh: &Mesh, vertices: &'a [VertexId]) -> Self {
        let n = vertices.len();
        let mut corners_of: HashMap<u32, Vec<u32>> = HashMap::with_capacity(n);
        for (k, v) in vertices.iter().enumerate() {
            corners_of.entry(v.0).or_default().push(k as u32);
        }
        let mut edges = HashSet::new();
        let mut record = |u: VertexId, v: VertexId| {
            if corners_of.contains_key(&v.0) {
                edges.insert((u.0.min(v.0), u.0.max(v.0)));
            }
        };
        if mesh.may_have_pinched_vertices {
            for h in (0..mesh.n_halfedge_slots() as u32).map(HalfedgeId) {
                if !mesh.is_halfedge_deleted(h) && corners_of.contains_key(&mesh.origin(h).0) {
                    record(mesh.origin(h), mesh.target(h));
                }
            }
        } else {
            for &u in corners_of.keys() {
                for h in mesh.outgoing_halfedges(VertexId(u)) {
                    record(VertexId(u), mesh.target(h));
                }
            }
        }
        let mut blocked = vec![false; n];
        let mut block = |at_u: &[u32], at_v: &[u32]| {
            if at_u.len() * at_v.len() > PAIRS_LOOKED_AT {
                // Vertices named that often are rare; blocking them all keeps this linear.
                at_u.iter()
                    .chain(at_v)
                    .for_each(|&k| blocked[k as usize] = true);
                return;
            }
            for &a in at_u {
                for &b in at_v {
                    let d = a.abs_diff(b) as usize;
                    if d != 0 && d != 1 && d != n - 1 {
                        blocked[a as usize] = true;
                        blocked[b as usize] = true;
                    }
                }
            }
        };
        // Two corners of one vertex may not be joined, nor the corners of two joined vertices.
        for at in corners_of.values().filter(|at| at.len() > 1) {
            block(at, at);
        }
        for (u, v) in &edges {
            block(&corners_of[u], &corners_of[v]);
        }
        Self {
            vertices,
            edges,
            blocked,
        }
    }

    /// Up to `count` corners that every other corner may be joined to, first ones first.
    pub(crate) fn free_corners(&self, count: usize) -> Vec<u32> {
        (0..self.blocked.len() as u32)
            .filter(|&k| !self.blocked[k as usize])
            .take(count)
            .collect()
    }

    /// Whether new edges may be cut along `chords` (pairs of corners): none joins a vertex to
    /// itself or two vertices an edge or another chord joins.
    pub(crate) fn allows(&self, chords: &[(u32, u32)]) -> bool {
        let mut cut = HashSet::with_capacity(chords.len());
        chords.iter().all(|&(a, c)| {
            let (u, v) = (self.vertices[a as usize].0, self.vertices[c as usize].0);
            self.may_join(a, c) && cut.insert((u.min(v), u.max(v)))
        })
    }

    /// Whether corners `a` and `c` may be joined by a new edge: they are two vertices no edge
    /// joins.
    pub(crate) fn may_join(&self, a: u32, c: u32) -> bool {
        let (u, v) = (self.vertices[a as usize].0, self.vertices[c as usize].0);
        u != v && !self.edges.contains(&(u.min(v), u.max(v)))
    }
}
