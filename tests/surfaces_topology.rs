//! Topology and orientation of every generated surface, computed independently on the soup:
//! Euler characteristic, boundary loops, consistent orientation and signed volume.

use std::collections::HashMap;
use std::f64::consts::{PI, TAU};

use glam::DVec3;
use halfwing::soup::PolygonSoup;
use halfwing::surfaces::*;

/// What the soup's combinatorics and geometry say about the surface.
#[derive(Debug)]
struct Shape {
    vertices: usize,
    edges: usize,
    faces: usize,
    boundary_edges: usize,
    boundary_loops: usize,
    /// No directed edge is used twice and no undirected edge by more than two faces.
    consistently_oriented: bool,
    signed_volume: f64,
}

impl Shape {
    fn euler(&self) -> i64 {
        self.vertices as i64 - self.edges as i64 + self.faces as i64
    }

    fn closed(&self) -> bool {
        self.boundary_edges == 0
    }
}

fn find(parent: &mut [usize], mut x: usize) -> usize {
    while parent[x] != x {
        parent[x] = parent[parent[x]];
        x = parent[x];
    }
    x
}

fn analyse(soup: &PolygonSoup) -> Shape {
    let mut directed: HashMap<(u32, u32), usize> = HashMap::new();
    let mut used = vec![false; soup.positions.len()];
    let mut signed_volume = 0.0;
    let mut start = 0;
    for &size in &soup.face_sizes {
        let face = &soup.indices[start..start + size as usize];
        start += size as usize;
        assert!(face.len() >= 3, "face with {} corners", face.len());
        let p = |k: usize| DVec3::from_array(soup.positions[face[k] as usize]);
        for k in 0..face.len() {
            used[face[k] as usize] = true;
            *directed
                .entry((face[k], face[(k + 1) % face.len()]))
                .or_default() += 1;
            if k >= 1 && k + 1 < face.len() {
                signed_volume += p(0).dot(p(k).cross(p(k + 1))) / 6.0;
            }
        }
        let mut sorted = face.to_vec();
        sorted.sort_unstable();
        sorted.dedup();
        assert_eq!(sorted.len(), face.len(), "face repeats a vertex: {face:?}");
    }
    let mut undirected: HashMap<(u32, u32), usize> = HashMap::new();
    for (&(a, b), &count) in &directed {
        *undirected.entry((a.min(b), a.max(b))).or_default() += count;
    }
    let consistently_oriented =
        directed.values().all(|&c| c == 1) && undirected.values().all(|&c| c <= 2);
    let boundary: Vec<(u32, u32)> = undirected
        .iter()
        .filter(|&(_, &c)| c == 1)
        .map(|(&e, _)| e)
        .collect();
    let mut parent: Vec<usize> = (0..soup.positions.len()).collect();
    for &(a, b) in &boundary {
        let (ra, rb) = (find(&mut parent, a as usize), find(&mut parent, b as usize));
        parent[ra] = rb;
    }
    let mut roots: Vec<usize> = boundary
        .iter()
        .map(|&(a, _)| find(&mut parent, a as usize))
        .collect();
    roots.sort_unstable();
    roots.dedup();
    Shape {
        vertices: used.iter().filter(|&&u| u).count(),
        edges: undirected.len(),
        faces: soup.n_faces(),
        boundary_edges: boundary.len(),
        boundary_loops: roots.len(),
        consistently_oriented,
        signed_volume,
    }
}

fn assert_closed(soup: &PolygonSoup, genus: i64) -> Shape {
    let s = analyse(soup);
    assert!(s.consistently_oriented, "{s:?}");
    assert!(s.closed(), "{s:?}");
    assert_eq!(s.euler(), 2 - 2 * genus, "{s:?}");
    assert!(s.signed_volume > 0.0, "faces point inwards: {s:?}");
    assert_eq!(s.vertices, soup.positions.len(), "unused vertices");
    s
}

fn assert_open(soup: &PolygonSoup, euler: i64, loops: usize) -> Shape {
    let s = analyse(soup);
    assert!(s.consistently_oriented, "{s:?}");
    assert_eq!((s.euler(), s.boundary_loops), (euler, loops), "{s:?}");
    assert_eq!(s.vertices, soup.positions.len(), "unused vertices");
    s
}

fn circle(n: usize, radius: f64, z: f64) -> Vec<[f64; 3]> {
    (0..n)
        .map(|i| {
            let (s, c) = (TAU * i as f64 / n as f64).sin_cos();
            [radius * c, radius * s, z]
        })
        .collect()
}

/// Half a circle in the xz plane from the south pole to the north pole.
fn meridian(n: usize) -> Vec<[f64; 3]> {
    (0..=n)
        .map(|i| {
            let (s, c) = (PI * i as f64 / n as f64 - PI / 2.0).sin_cos();
            [c.max(0.0), 0.0, s]
        })
        .collect()
}

fn revolve(
    profile: &[[f64; 3]],
    closed_profile: bool,
    turn: Turn,
    caps: Caps,
    faces: CellFaces,
) -> PolygonSoup {
    revolution_surface(&Revolution {
        profile,
        closed_profile,
        axis_origin: [0.0; 3],
        axis_direction: [0.0, 0.0, 1.0],
        turn,
        steps: 24,
        caps,
        faces,
    })
    .unwrap()
}

#[test]
fn seed_tetrahedron_is_a_closed_outward_sphere_with_the_right_volume() {
    let s = assert_closed(&tetrahedron(), 0);
    assert_eq!((s.vertices, s.edges, s.faces), (4, 6, 4));
    assert!((s.signed_volume - 2f64.sqrt() / 12.0).abs() < 1e-15);
}

#[test]
fn cube_is_closed_with_volume_side_cubed() {
    let s = assert_closed(&cube(3.0).unwrap(), 0);
    assert_eq!((s.vertices, s.edges, s.faces), (8, 12, 6));
    assert!((s.signed_volume - 27.0).abs() < 1e-12);
}

#[test]
fn icospheres_are_closed_and_converge_to_the_ball_volume() {
    let mut previous = 0.0;
    for level in 0..5 {
        let s = assert_closed(&icosphere(1.0, level).unwrap(), 0);
        assert!(s.signed_volume > previous && s.signed_volume < 4.0 * PI / 3.0);
        previous = s.signed_volume;
    }
    assert!((previous - 4.0 * PI / 3.0).abs() < 0.01);
}

#[test]
fn torus_has_genus_one_in_quads_and_triangles() {
    for faces in [CellFaces::Quads, CellFaces::Triangles] {
        let t = Torus {
            major_radius: 3.0,
            minor_radius: 1.0,
            major_steps: 48,
            minor_steps: 32,
            faces,
        };
        let s = assert_closed(&torus(&t).unwrap(), 1);
        let exact = 2.0 * PI * PI * 3.0;
        assert!(
            (s.signed_volume - exact).abs() < 0.02 * exact,
            "{}",
            s.signed_volume
        );
    }
}

#[test]
fn grid_is_a_disc_with_its_perimeter_as_boundary() {
    for faces in [CellFaces::Quads, CellFaces::Triangles] {
        let g = grid(&Grid {
            width: 2.0,
            height: 1.0,
            cells_x: 5,
            cells_y: 3,
            faces,
        })
        .unwrap();
        let s = assert_open(&g, 1, 1);
        assert_eq!(s.boundary_edges, 2 * (5 + 3));
    }
}

#[test]
fn swept_closed_curve_is_a_tube_and_open_curve_a_disc() {
    let ring = circle(16, 1.0, 0.0);
    let tube = cylindrical_surface(&Sweep {
        profile: &ring,
        closed_profile: true,
        direction: [0.2, 0.0, 2.0],
        steps: 4,
        faces: CellFaces::Quads,
    })
    .unwrap();
    let s = assert_open(&tube, 0, 2);
    assert_eq!(s.boundary_edges, 32);
    let wall = cylindrical_surface(&Sweep {
        profile: &ring,
        closed_profile: false,
        direction: [0.0, 0.0, 1.0],
        steps: 2,
        faces: CellFaces::Triangles,
    })
    .unwrap();
    assert_open(&wall, 1, 1);
}

#[test]
fn revolved_meridian_is_a_sphere_with_two_poles_and_no_seam() {
    for faces in [CellFaces::Quads, CellFaces::Triangles] {
        let sphere = revolve(&meridian(12), false, Turn::Full, Caps::None, faces);
        let s = assert_closed(&sphere, 0);
        assert_eq!(s.vertices, 2 + 11 * 24);
        // An inscribed polyhedron: a little smaller than the ball.
        let ball = 4.0 * PI / 3.0;
        assert!(
            s.signed_volume < ball && s.signed_volume > 0.95 * ball,
            "{}",
            s.signed_volume
        );
    }
}

#[test]
fn partial_revolution_is_open() {
    let lune = revolve(
        &meridian(12),
        false,
        Turn::Partial(PI / 2.0),
        Caps::None,
        CellFaces::Quads,
    );
    let s = assert_open(&lune, 1, 1);
    assert_eq!(s.vertices, 2 + 11 * 25);
    let band = revolve(
        &[[1.0, 0.0, 0.0], [1.0, 0.0, 1.0]],
        false,
        Turn::Partial(PI),
        Caps::None,
        CellFaces::Quads,
    );
    assert_open(&band, 1, 1);
}

#[test]
fn caps_close_the_open_ends_of_a_profile() {
    let profile = [[1.0, 0.0, 0.0], [1.5, 0.0, 0.5], [1.0, 0.0, 1.0]];
    for caps in [Caps::Polygon, Caps::Fan] {
        let closed = revolve(&profile, false, Turn::Full, caps, CellFaces::Quads);
        assert_closed(&closed, 0);
        let wedge = revolve(
            &profile,
            false,
            Turn::Partial(2.0),
            caps,
            CellFaces::Triangles,
        );
        assert_open(&wedge, 1, 1);
    }
    let open = revolve(&profile, false, Turn::Full, Caps::None, CellFaces::Quads);
    assert_open(&open, 0, 2);
    // A pole end needs no cap: one cap closes a bowl.
    let bowl = revolve(
        &[[0.0, 0.0, 0.0], [1.0, 0.0, 0.5]],
        false,
        Turn::Full,
        Caps::Fan,
        CellFaces::Quads,
    );
    assert_closed(&bowl, 0);
}

#[test]
fn revolving_a_closed_profile_gives_a_torus() {
    let tube: Vec<[f64; 3]> = circle(16, 0.5, 0.0)
        .iter()
        .map(|p| [2.0 + p[0], 0.0, p[1]])
        .collect();
    let s = assert_closed(
        &revolve(&tube, true, Turn::Full, Caps::Fan, CellFaces::Quads),
        1,
    );
    assert_eq!(s.faces, 16 * 24);
}

#[test]
fn revolution_about_an_arbitrary_axis_is_a_rigid_copy() {
    let profile = meridian(8);
    let z_axis = revolve(&profile, false, Turn::Full, Caps::None, CellFaces::Quads);
    // Move the profile with the same rigid motion that takes the z axis to the new axis.
    let origin = DVec3::new(1.0, -2.0, 0.5);
    let rotation = glam::DQuat::from_rotation_arc(DVec3::Z, DVec3::new(1.0, 1.0, 1.0).normalize());
    let moved: Vec<[f64; 3]> = profile
        .iter()
        .map(|p| (origin + rotation * DVec3::from_array(*p)).to_array())
        .collect();
    let tilted = revolution_surface(&Revolution {
        profile: &moved,
        closed_profile: false,
        axis_origin: origin.to_array(),
        axis_direction: [2.0, 2.0, 2.0],
        turn: Turn::Full,
        steps: 24,
        caps: Caps::None,
        faces: CellFaces::Quads,
    })
    .unwrap();
    assert_eq!(tilted.indices, z_axis.indices);
    let a = assert_closed(&z_axis, 0);
    let b = assert_closed(&tilted, 0);
    assert!((a.signed_volume - b.signed_volume).abs() < 1e-9);
}

#[test]
fn ruled_surfaces_between_open_and_closed_curves() {
    let bottom = circle(12, 1.0, 0.0);
    let top = circle(12, 0.5, 1.0);
    let frustum_side = ruled_surface(&Ruling {
        first: &bottom,
        second: &top,
        closed: true,
        steps: 3,
        faces: CellFaces::Quads,
    })
    .unwrap();
    assert_open(&frustum_side, 0, 2);
    let strip = ruled_surface(&Ruling {
        first: &bottom,
        second: &top,
        closed: false,
        steps: 1,
        faces: CellFaces::Triangles,
    })
    .unwrap();
    assert_open(&strip, 1, 1);
}
