//! Complexity guards: triangulating a polygon is O(n log n) whatever its shape, in the render
//! buffers and in the half-edge kernel's face triangulation. Each input is sized so that the
//! quadratic behaviour measured before (the 80,002-corner comb: 9.2 s in each; the 12,000-corner
//! face over 3 places read with the repair policy: 281 s in the render buffers) would take more
//! than ten times the bound, which is generous (a debug build on a loaded machine passes it
//! easily): this guards the growth, it measures no speed.

#[path = "../benches/common/polygons.rs"]
mod polygons;

use std::time::{Duration, Instant};

use halfwing::mesh::{BuildPolicy, FaceId, Mesh};
use halfwing::render::{MeshBufferOptions, mesh_buffers};
use halfwing::soup::FaceList;

const BOUND: Duration = Duration::from_secs(5);

/// Runs `work`, failing when it takes longer than [`BOUND`].
fn within_bound<T>(what: &str, work: impl FnOnce() -> T) -> T {
    let start = Instant::now();
    let result = work();
    let took = start.elapsed();
    assert!(took < BOUND, "{what} took {took:?}");
    result
}

/// Renders and triangulates the one face of `positions` and `indices` as a mesh built with
/// `policy`, each within the bound; checks `n − 2` triangles each time.
fn render_and_triangulate(
    what: &str,
    positions: &[[f64; 3]],
    indices: &[u32],
    policy: BuildPolicy,
) {
    let n = indices.len();
    let (mut mesh, _) =
        Mesh::from_face_list(&FaceList::polygons(positions, &[n as u32], indices), policy).unwrap();
    let buffers = within_bound(&format!("{what}: render buffers"), || {
        mesh_buffers(&mesh, None, &MeshBufferOptions::default()).unwrap()
    });
    assert_eq!(buffers.surface.triangles.len(), 3 * (n - 2));
    let faces = within_bound(&format!("{what}: triangulate_face"), || {
        mesh.triangulate_face(FaceId(0)).unwrap()
    });
    assert_eq!(faces.len(), n - 2);
    assert_eq!(mesh.check(), Ok(()));
}

/// Quadratic from the 80,002-corner comb's 9.2 s: about 83 s at 240,002 corners.
#[test]
fn a_comb_of_240_002_corners_is_triangulated_within_the_bound() {
    let comb = polygons::comb(60_000);
    let indices: Vec<u32> = (0..comb.len() as u32).collect();
    render_and_triangulate("comb", &comb, &indices, BuildPolicy::Strict);
}

/// Quadratic from the 12,000-corner face's 281 s: about 1,750 s at 30,000 corners.
#[test]
fn a_face_of_30_000_corners_over_3_places_is_triangulated_within_the_bound() {
    let (positions, indices) = polygons::three_places(30_000);
    render_and_triangulate("3 places", &positions, &indices, BuildPolicy::Repair);
}
