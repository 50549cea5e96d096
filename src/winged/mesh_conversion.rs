//! Conversion to and from the half-edge [`Mesh`], record for record.
//!
//! The two structures hold the same information: edge `e` of the winged structure is edge `e` of
//! the mesh, its left use (walked `start → end`) is half-edge `2e` and its right use half-edge
//! `2e + 1`; a wing is the edge of a half-edge's `next`/`prev`; vertex and face ids and their
//! stored edges correspond one to one. So both conversions copy arrays in one linear pass, with
//! no pairing, and `Winged::from_mesh(&m).to_mesh() == m` for a mesh without deletions.

use super::error::WingedError;
use super::ids::{EdgeId, EdgeUse, FaceId, Side, VertexId};
use super::record::EdgeRecord;
use super::structure::Winged;
use crate::mesh::{INVALID_INDEX, Mesh, MeshArrays};

/// The mesh half-edge of a winged edge use.
#[inline]
fn halfedge_of(u: EdgeUse) -> u32 {
    2 * u.edge.0 + u32::from(u.side == Side::Right)
}

/// The winged edge of a mesh half-edge (invalid stays invalid).
#[inline]
fn edge_of(h: u32) -> EdgeId {
    if h == INVALID_INDEX {
        EdgeId::INVALID
    } else {
        EdgeId(h >> 1)
    }
}

/// Dense new ids of a mesh's live elements (`u32::MAX` for deleted ones).
struct DenseIds {
    vertices: Vec<u32>,
    edges: Vec<u32>,
    faces: Vec<u32>,
}

impl DenseIds {
    fn of(mesh: &Mesh) -> Self {
        let dense = |n: usize, deleted: &dyn Fn(u32) -> bool| {
            let mut next = 0u32;
            (0..n as u32)
                .map(|i| {
                    if deleted(i) {
                        INVALID_INDEX
                    } else {
                        next += 1;
                        next - 1
                    }
                })
                .collect()
        };
        DenseIds {
            vertices: dense(mesh.n_vertex_slots(), &|v| {
                mesh.is_vertex_deleted(crate::mesh::VertexId(v))
            }),
            edges: dense(mesh.n_edge_slots(), &|e| {
                mesh.is_edge_deleted(crate::mesh::EdgeId(e))
            }),
            faces: dense(mesh.n_face_slots(), &|f| {
                mesh.is_face_deleted(crate::mesh::FaceId(f))
            }),
        }
    }
}

/// An id map: the identity, or a dense renumbering (invalid ids stay invalid).
#[derive(Clone, Copy)]
enum Remap<'a> {
    Same,
    Dense(&'a [u32]),
}

impl Remap<'_> {
    #[inline]
    fn get(self, id: u32) -> u32 {
        match self {
            Remap::Dense(map) if id != INVALID_INDEX => map[id as usize],
            _ => id,
        }
    }
}

impl Winged {
    /// The winged-edge structure of a half-edge mesh: same vertex, edge and face ids, each edge
    /// directed as its even half-edge, each face starting at its stored half-edge, each vertex
    /// storing the edge of its stored half-edge (so rings start at the same place). Boundary
    /// loops become the hole sides' wings; non-manifold vertices are kept as they are.
    ///
    /// Deleted elements of the mesh are left out and the live ones renumbered densely in their
    /// order (as [`Mesh::to_soup`] numbers vertices).
    pub fn from_mesh(mesh: &Mesh) -> Self {
        let (origin, next, prev, face) = (
            mesh.halfedge_origins(),
            mesh.halfedge_nexts(),
            mesh.halfedge_prevs(),
            mesh.halfedge_faces(),
        );
        let renumber = mesh.has_deleted_elements().then(|| DenseIds::of(mesh));
        let (vertex, edge, face_id) = match &renumber {
            Some(ids) => (
                Remap::Dense(&ids.vertices),
                Remap::Dense(&ids.edges),
                Remap::Dense(&ids.faces),
            ),
            None => (Remap::Same, Remap::Same, Remap::Same),
        };
        let edges: Vec<EdgeRecord> = (0..mesh.n_edge_slots())
            .filter(|&e| !mesh.is_edge_deleted(crate::mesh::EdgeId(e as u32)))
            .map(|e| {
                let (h, t) = (2 * e, 2 * e + 1);
                let wing = |h: u32| EdgeId(edge.get(edge_of(h).0));
                EdgeRecord {
                    start: VertexId(vertex.get(origin[h])),
                    end: VertexId(vertex.get(origin[t])),
                    left_face: FaceId(face_id.get(face[h])),
                    right_face: FaceId(face_id.get(face[t])),
                    left_prev: wing(prev[h]),
                    left_next: wing(next[h]),
                    right_prev: wing(prev[t]),
                    right_next: wing(next[t]),
                }
            })
            .collect();
        let positions: Vec<[f64; 3]> = (0..mesh.n_vertex_slots())
            .filter(|&v| !mesh.is_vertex_deleted(crate::mesh::VertexId(v as u32)))
            .map(|v| mesh.positions()[v])
            .collect();
        let vertex_edge: Vec<EdgeId> = (0..mesh.n_vertex_slots())
            .filter(|&v| !mesh.is_vertex_deleted(crate::mesh::VertexId(v as u32)))
            .map(|v| EdgeId(edge.get(edge_of(mesh.vertex_halfedges()[v]).0)))
            .collect();
        let face_edge: Vec<EdgeId> = (0..mesh.n_face_slots())
            .filter(|&f| !mesh.is_face_deleted(crate::mesh::FaceId(f as u32)))
            .map(|f| EdgeId(edge.get(edge_of(mesh.face_halfedges()[f]).0)))
            .collect();
        Winged {
            vertex_alive: vec![true; positions.len()],
            face_alive: vec![true; face_edge.len()],
            n_live_vertices: positions.len() as u32,
            n_live_edges: edges.len() as u32,
            n_live_faces: face_edge.len() as u32,
            positions,
            vertex_edge,
            face_edge,
            edges,
            point_faces: Vec::new(),
            may_have_pinched_vertices: mesh.may_have_pinched_vertices(),
        }
    }

    /// The half-edge mesh of this structure (the inverse of [`Winged::from_mesh`]): edge `e`
    /// becomes half-edges `2e` (its left use) and `2e + 1` (its right use); vertices, faces and
    /// their stored elements keep their ids. Deleted elements stay in place, deleted in the mesh
    /// too (as the builders hold input vertices with a non-finite coordinate), so ids agree
    /// across the two structures; [`Mesh::garbage_collect`] or [`Winged::garbage_collect`]
    /// compacts them. So [`Winged::from_face_list`]'s structure converts to the very mesh
    /// [`Mesh::from_face_list`] builds from the same list, under every policy.
    ///
    /// Refused with [`WingedError::NotConvertible`] when a face has no edges (a point face made
    /// by MVFS: a half-edge face needs a half-edge) or when the result would break a half-edge
    /// invariant (checked with [`Mesh::check`]; a structure made by the builders or the Euler
    /// operators never does, apart from point faces).
    pub fn to_mesh(&self) -> Result<Mesh, WingedError> {
        if let Some(&(f, _)) = self.point_faces.first() {
            return Err(WingedError::NotConvertible(format!(
                "{f} has no edges (a point face)"
            )));
        }
        let corrupted = || WingedError::NotConvertible("a wing does not meet its edge".into());
        let n_halfedges = 2 * self.edges.len();
        let mut origin = Vec::with_capacity(n_halfedges);
        let mut next = Vec::with_capacity(n_halfedges);
        let mut prev = Vec::with_capacity(n_halfedges);
        let mut face = Vec::with_capacity(n_halfedges);
        for (e, r) in self.edges.iter().enumerate() {
            if r.is_deleted() {
                // Both half-edges of a deleted edge are deleted; their links are never read.
                for array in [&mut origin, &mut next, &mut prev, &mut face] {
                    array.extend([INVALID_INDEX; 2]);
                }
                continue;
            }
            for side in [Side::Left, Side::Right] {
                let u = EdgeUse::new(EdgeId(e as u32), side);
                origin.push(r.tail(side).0);
                face.push(r.face(side).0);
                next.push(halfedge_of(self.use_next(u).ok_or_else(corrupted)?));
                prev.push(halfedge_of(self.use_prev(u).ok_or_else(corrupted)?));
            }
        }
        let vertex_halfedge = (0..self.positions.len())
            .map(|v| {
                let v = VertexId(v as u32);
                match self.vertex_edge[v.index()] {
                    e if !e.is_valid() || !self.vertex_alive[v.index()] => Ok(INVALID_INDEX),
                    _ => self
                        .vertex_first_use(v)
                        .map(halfedge_of)
                        .ok_or_else(corrupted),
                }
            })
            .collect::<Result<Vec<u32>, WingedError>>()?;
        let face_halfedge = (0..self.face_edge.len())
            .map(|f| match self.face_alive[f] {
                false => Ok(INVALID_INDEX),
                true => self
                    .face_first_use(FaceId(f as u32))
                    .map(halfedge_of)
                    .ok_or_else(corrupted),
            })
            .collect::<Result<Vec<u32>, WingedError>>()?;
        Mesh::from_arrays(MeshArrays {
            origin,
            next,
            prev,
            face,
            vertex_halfedge,
            positions: self.positions.clone(),
            face_halfedge,
            deleted_vertices: self.vertex_alive.iter().map(|&alive| !alive).collect(),
            deleted_edges: self.edges.iter().map(EdgeRecord::is_deleted).collect(),
            deleted_faces: self.face_alive.iter().map(|&alive| !alive).collect(),
        })
        .map_err(|broken| WingedError::NotConvertible(broken.to_string()))
    }
}
