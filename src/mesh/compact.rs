//! Compaction after deletions.

use crate::mesh::Mesh;
use crate::mesh::ids::INVALID_INDEX;
use crate::mesh::structure::Deletions;
use crate::support::index_maps::{IndexMaps, compaction_map};

fn remap(value: u32, map: &[u32]) -> u32 {
    if value == INVALID_INDEX {
        INVALID_INDEX
    } else {
        map[value as usize]
    }
}

/// Keeps the elements whose map entry is valid, in order.
fn compact<T: Copy>(values: &[T], map: &[u32]) -> Vec<T> {
    values
        .iter()
        .zip(map)
        .filter(|&(_, &m)| m != INVALID_INDEX)
        .map(|(&v, _)| v)
        .collect()
}

impl Mesh {
    /// Removes every deleted element, renumbering the live ones in order, and returns the maps
    /// from old to new ids. Attribute columns are compacted with the same maps. A mesh with nothing deleted is left as it is (identity maps).
    pub fn garbage_collect(&mut self) -> IndexMaps {
        let vertices = compaction_map(self.vertex_halfedge.len(), &self.deleted.vertices);
        let edges = compaction_map(self.origin.len() / 2, &self.deleted.edges);
        let faces = compaction_map(self.face_halfedge.len(), &self.deleted.faces);
        let halfedges: Vec<u32> = (0..self.origin.len())
            .map(|h| match edges[h / 2] {
                INVALID_INDEX => INVALID_INDEX,
                e => 2 * e + (h as u32 & 1),
            })
            .collect();

        let keep_halfedge = |values: &[u32]| -> Vec<u32> {
            let mut out = Vec::with_capacity(values.len());
            for (e, &new) in edges.iter().enumerate() {
                if new != INVALID_INDEX {
                    out.push(values[2 * e]);
                    out.push(values[2 * e + 1]);
                }
            }
            out
        };
        let origin: Vec<u32> = keep_halfedge(&self.origin)
            .into_iter()
            .map(|v| remap(v, &vertices))
            .collect();
        let next: Vec<u32> = keep_halfedge(&self.next)
            .into_iter()
            .map(|h| remap(h, &halfedges))
            .collect();
        let prev: Vec<u32> = keep_halfedge(&self.prev)
            .into_iter()
            .map(|h| remap(h, &halfedges))
            .collect();
        let face: Vec<u32> = keep_halfedge(&self.face)
            .into_iter()
            .map(|f| remap(f, &faces))
            .collect();
        let vertex_halfedge: Vec<u32> = compact(&self.vertex_halfedge, &vertices)
            .into_iter()
            .map(|h| remap(h, &halfedges))
            .collect();
        let positions = compact(&self.positions, &vertices);
        let face_halfedge: Vec<u32> = compact(&self.face_halfedge, &faces)
            .into_iter()
            .map(|h| remap(h, &halfedges))
            .collect();

        self.compact_attributes(&vertices, &halfedges, &edges, &faces);
        *self = Mesh {
            origin,
            next,
            prev,
            face,
            vertex_halfedge,
            positions,
            face_halfedge,
            deleted: Deletions::default(),
            may_have_pinched_vertices: true,
            attributes: std::mem::take(&mut self.attributes),
        };
        self.may_have_pinched_vertices = !self.non_manifold_vertices().is_empty();
        IndexMaps {
            vertices,
            halfedges,
            edges,
            faces,
        }
    }
}
