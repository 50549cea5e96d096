//! Fuzzes the mesh doctor and the self-intersection search on any face list: a report or a
//! typed refusal, never a panic; its ids are in range, the pairs sorted and distinct, and the
//! closed-polyhedron verdict agrees with the findings it sums up.
#![no_main]

use halfwing::doctor::{DoctorOptions, Finding, examine};
use halfwing::soup::FaceList;
use libfuzzer_sys::fuzz_target;

#[path = "face_list.rs"]
mod face_list;

fuzz_target!(|bytes: &[u8]| {
    let decoded = face_list::decode(bytes);
    let list = FaceList::polygons(&decoded.positions, &decoded.sizes, &decoded.indices);
    let Ok(report) = examine(&list, &DoctorOptions::default()) else {
        return;
    };
    let pairs = &report.self_intersections;
    assert!(pairs.windows(2).all(|w| w[0] < w[1]));
    assert!(pairs.iter().all(|[f, g]| f < g && (*g as usize) < decoded.sizes.len()));
    for kind in Finding::ALL {
        let (ids, per_item) = report.finding(kind);
        assert_eq!(ids.len() % per_item, 0);
    }
    if report.not_a_closed_polyhedron().is_none() {
        assert!(report.is_closed() && report.is_manifold() && report.is_oriented());
        assert!(pairs.is_empty());
    }
    let _ = halfwing::geom::face_self_intersections(&list);
});
