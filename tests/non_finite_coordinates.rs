//! One rule for every way coordinates enter a structure: a NaN or infinite coordinate never
//! enters a mesh or a winged structure. Builds refuse it (Strict) or leave its faces out with the
//! vertex deleted (Skip, Repair); single-vertex edits and generators refuse it; a refusal
//! changes nothing.

use halfwing::io::{MeshFormat, read_bytes};
use halfwing::mesh::{EdgeId, EditError, Mesh, VertexId};
use halfwing::render::{SurfaceOptions, surface_buffer};
use halfwing::soup::{BuildError, BuildPolicy, FaceList};
use halfwing::surfaces::{
    Caps, CellFaces, Grid, Revolution, Ruling, SurfaceError, Sweep, Torus, Turn, cube,
    cylindrical_surface, grid, icosphere, revolution_surface, ruled_surface, torus,
};
use halfwing::winged::{Winged, WingedError};

const NON_FINITE: [f64; 3] = [f64::NAN, f64::INFINITY, f64::NEG_INFINITY];

/// Three triangles in a strip, the last on vertex 4; vertex 5 isolated.
const POSITIONS: [[f64; 3]; 6] = [
    [0.0, 0.0, 0.0],
    [1.0, 0.0, 0.0],
    [1.0, 1.0, 0.0],
    [0.0, 1.0, 0.0],
    [2.0, 0.0, 0.0],
    [2.0, 1.0, 0.0],
];
const TRIANGLES: [u32; 9] = [0, 1, 2, 0, 2, 3, 2, 1, 4];

fn all_finite(positions: &[[f64; 3]]) -> bool {
    positions.iter().flatten().all(|c| c.is_finite())
}

fn small_mesh() -> Mesh {
    Mesh::from_face_list(
        &FaceList::triangles(&POSITIONS, &TRIANGLES),
        BuildPolicy::Strict,
    )
    .unwrap()
    .0
}

#[test]
fn builds_under_every_policy_keep_non_finite_coordinates_out() {
    for value in NON_FINITE {
        let mut positions = POSITIONS;
        positions[4][2] = value;
        let list = FaceList::triangles(&positions, &TRIANGLES);
        assert!(matches!(
            Mesh::from_face_list(&list, BuildPolicy::Strict),
            Err(BuildError::InvalidInput(_))
        ));
        assert!(Winged::from_face_list(&list, BuildPolicy::Strict).is_err());
        for policy in [BuildPolicy::Skip, BuildPolicy::Repair] {
            let (mesh, diagnostic) = Mesh::from_face_list(&list, policy).unwrap();
            assert_eq!(diagnostic.non_finite_vertices, [4]);
            assert_eq!(diagnostic.skipped_faces, [2]);
            assert!(mesh.is_vertex_deleted(VertexId(4)));
            assert!(all_finite(mesh.positions()));
            // Nothing non-finite reaches the normals or the render buffers either.
            let buffer = surface_buffer(&mesh, &SurfaceOptions::default()).unwrap();
            assert!(
                buffer
                    .positions
                    .iter()
                    .chain(&buffer.normals)
                    .all(|c| c.is_finite())
            );
            let (winged, _) = Winged::from_face_list(&list, policy).unwrap();
            assert!(!winged.is_vertex(halfwing::winged::VertexId(4)));
            assert_eq!(winged.n_faces(), 2);
        }
    }
}

#[test]
fn files_with_non_finite_coordinates_build_without_them() {
    for token in ["nan", "inf", "-inf"] {
        let off = format!("OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 {token}\n0 1 0\n3 0 1 2\n3 0 2 3\n");
        let Ok(soup) = read_bytes(MeshFormat::Off, off.as_bytes()) else {
            continue; // refused by the reader: it never gets near a mesh
        };
        assert!(Mesh::from_soup(&soup, BuildPolicy::Strict).is_err());
        for policy in [BuildPolicy::Skip, BuildPolicy::Repair] {
            let (mesh, diagnostic) = Mesh::from_soup(&soup, policy).unwrap();
            assert_eq!(diagnostic.non_finite_vertices, [2], "{token}");
            assert_eq!(mesh.n_faces(), 0);
            assert!(all_finite(mesh.positions()));
        }
    }
}

#[test]
fn mesh_vertex_edits_refuse_non_finite_positions_and_change_nothing() {
    for value in NON_FINITE {
        let mut mesh = small_mesh();
        let before = mesh.clone();
        let point = [0.5, value, 0.0];
        assert_eq!(
            mesh.add_vertex(point),
            Err(EditError::NonFinitePosition { vertex: 6 })
        );
        assert_eq!(
            mesh.set_position(VertexId(2), point),
            Err(EditError::NonFinitePosition { vertex: 2 })
        );
        assert_eq!(
            mesh.split_edge(EdgeId(0), point),
            Err(EditError::NonFinitePosition { vertex: 6 })
        );
        assert_eq!(mesh.positions(), before.positions());
        assert_eq!(mesh.n_vertices(), before.n_vertices());
        assert_eq!(mesh.n_edges(), before.n_edges());
        mesh.check().unwrap();
    }
    let mut mesh = small_mesh();
    let v = mesh.add_vertex([3.0, 3.0, 3.0]).unwrap();
    mesh.set_position(v, [4.0, 4.0, 4.0]).unwrap();
    assert_eq!(mesh.position(v), [4.0, 4.0, 4.0]);
    assert!(matches!(
        mesh.set_position(VertexId(99), [0.0; 3]),
        Err(EditError::Handle(_))
    ));
}

#[test]
fn winged_operators_taking_positions_refuse_non_finite_ones() {
    for value in NON_FINITE {
        let point = [value, 0.0, 0.0];
        let mut winged = Winged::new();
        assert!(matches!(
            winged.mvfs(point),
            Err(WingedError::NonFinitePosition { .. })
        ));
        let (v, f) = winged.mvfs([0.0; 3]).unwrap();
        assert!(matches!(
            winged.mev(f, v, point),
            Err(WingedError::NonFinitePosition { .. })
        ));
        assert!(matches!(
            winged.set_position(v, point),
            Err(WingedError::NonFinitePosition { .. })
        ));
        assert_eq!(winged.positions(), [[0.0; 3]]);
        winged.check().unwrap();
    }
}

#[test]
fn generators_refuse_non_finite_parameters_and_overflowing_coordinates() {
    let profile = [[1.0, 0.0, 0.0], [1.0, 0.0, 1.0], [0.5, 0.0, 2.0]];
    let other = [[2.0, 1.0, 0.0], [2.0, 1.0, 1.0], [1.5, 1.0, 2.0]];
    let sweep = |profile: &[[f64; 3]], direction| {
        cylindrical_surface(&Sweep {
            profile,
            closed_profile: false,
            direction,
            steps: 2,
            faces: CellFaces::Quads,
        })
    };
    let revolve = |profile: &[[f64; 3]], axis_origin, axis_direction, turn| {
        revolution_surface(&Revolution {
            profile,
            closed_profile: false,
            axis_origin,
            axis_direction,
            turn,
            steps: 8,
            caps: Caps::None,
            faces: CellFaces::Quads,
        })
    };
    let rule = |first: &[[f64; 3]], second: &[[f64; 3]]| {
        ruled_surface(&Ruling {
            first,
            second,
            closed: false,
            steps: 2,
            faces: CellFaces::Quads,
        })
    };
    let z = [0.0, 0.0, 1.0];
    assert!(sweep(&profile, [1.0, 1.0, 0.0]).is_ok());
    assert!(revolve(&profile, [0.0; 3], z, Turn::Full).is_ok());
    assert!(rule(&profile, &other).is_ok());
    for value in NON_FINITE {
        let mut bad_profile = profile;
        bad_profile[1][2] = value;
        let refusals = [
            grid(&Grid {
                width: value,
                height: 1.0,
                cells_x: 2,
                cells_y: 2,
                faces: CellFaces::Quads,
            }),
            torus(&Torus {
                major_radius: 2.0,
                minor_radius: value,
                major_steps: 8,
                minor_steps: 4,
                faces: CellFaces::Triangles,
            }),
            icosphere(value, 1),
            cube(value),
            sweep(&profile, [1.0, value, 0.0]),
            sweep(&bad_profile, [1.0, 1.0, 0.0]),
            revolve(&profile, [value, 0.0, 0.0], z, Turn::Full),
            revolve(&profile, [0.0; 3], [0.0, value, 1.0], Turn::Full),
            revolve(&profile, [0.0; 3], z, Turn::Partial(value)),
            revolve(&bad_profile, [0.0; 3], z, Turn::Full),
            rule(&bad_profile, &other),
            rule(&profile, &bad_profile),
        ];
        for (i, refused) in refusals.into_iter().enumerate() {
            assert!(refused.is_err(), "generator {i} with {value}: {refused:?}");
        }
    }
    // Finite parameters whose surface does not fit in doubles: the tube's outer ring.
    let huge = torus(&Torus {
        major_radius: 1.7e308,
        minor_radius: 1.6e308,
        major_steps: 8,
        minor_steps: 4,
        faces: CellFaces::Quads,
    });
    assert_eq!(huge.unwrap_err(), SurfaceError::CoordinatesOverflow);
}
