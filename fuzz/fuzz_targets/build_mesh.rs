//! Fuzzes the half-edge bulk build: any face list, under every policy, gives a mesh that passes
//! `check()` (and rebuilds from its own faces) or a typed error — never a panic or a corrupt mesh.
#![no_main]

use halfwing::mesh::Mesh;
use halfwing::soup::{BuildPolicy, FaceList};
use libfuzzer_sys::fuzz_target;

#[path = "face_list.rs"]
mod face_list;

fuzz_target!(|bytes: &[u8]| {
    let decoded = face_list::decode(bytes);
    let list = FaceList::polygons(&decoded.positions, &decoded.sizes, &decoded.indices);
    let _ = Mesh::diagnose(&list);
    for policy in [BuildPolicy::Strict, BuildPolicy::Skip, BuildPolicy::Repair] {
        if let Ok((mesh, _diagnostic)) = Mesh::from_face_list(&list, policy) {
            mesh.check().expect("a built mesh satisfies every invariant");
            let soup = mesh.to_soup();
            let (again, _) = Mesh::from_face_list(&soup.as_face_list(), BuildPolicy::Repair)
                .expect("a mesh's own faces build again");
            assert_eq!(again.n_faces(), mesh.n_faces());
        }
    }
});
