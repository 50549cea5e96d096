//! Fuzzes edit sequences on the half-edge kernel: a small grid of quads or triangles, then up to
//! 64 edits (flip, split edge, split face, triangulate, collapse, delete face, garbage collect)
//! chosen by the bytes. After each edit the mesh passes `check()`, and a refused edit leaves it
//! unchanged.
#![no_main]

use halfwing::mesh::{BuildPolicy, EdgeId, FaceId, HalfedgeId, Mesh};
use halfwing::surfaces::{CellFaces, Grid, grid};
use libfuzzer_sys::fuzz_target;

fn pick(byte: u8, count: usize) -> u32 {
    (usize::from(byte) % count.max(1)) as u32
}

fuzz_target!(|bytes: &[u8]| {
    let Some((&shape, edits)) = bytes.split_first() else {
        return;
    };
    let soup = grid(&Grid {
        width: 3.0,
        height: 2.0,
        cells_x: 1 + u32::from(shape % 4),
        cells_y: 1 + u32::from(shape / 4 % 4),
        faces: if shape & 0x80 == 0 { CellFaces::Quads } else { CellFaces::Triangles },
    })
    .expect("a valid grid");
    let (mut mesh, _) = Mesh::from_face_list(&soup.as_face_list(), BuildPolicy::Strict)
        .expect("a grid builds");
    for edit in edits.chunks_exact(3).take(64) {
        let before = mesh.clone();
        let (kind, a, b) = (edit[0] % 7, edit[1], edit[2]);
        let h = HalfedgeId(pick(a, mesh.n_halfedge_slots()));
        let done = match kind {
            0 => mesh.flip_edge(EdgeId(pick(a, mesh.n_edge_slots()))).is_ok(),
            1 => {
                let t = f64::from(b) / 255.0;
                mesh.split_edge(EdgeId(pick(a, mesh.n_edge_slots())), [t, 1.0 - t, 0.0])
                    .is_ok()
            }
            2 => {
                let other = HalfedgeId(pick(b, mesh.n_halfedge_slots()));
                mesh.split_face(h, other).is_ok()
            }
            3 => mesh.triangulate_face(FaceId(pick(a, mesh.n_face_slots()))).is_ok(),
            4 => mesh.collapse_halfedge(h).is_ok(),
            5 => mesh
                .delete_face(FaceId(pick(a, mesh.n_face_slots())), b & 1 == 1)
                .is_ok(),
            _ => {
                mesh.garbage_collect();
                true
            }
        };
        mesh.check().expect("every edit keeps every invariant");
        if !done {
            assert_eq!(mesh, before, "a refused edit changed the mesh");
        }
    }
});
