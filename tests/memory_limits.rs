//! Entry points asked for more memory than the process may have refuse with `OutOfMemory`
//! instead of aborting, and the process stays usable; counts a file declares are checked against
//! its bytes before anything proportional to them is allocated.
//!
//! Each test runs again in a child process of this test binary whose address space is limited
//! (`setrlimit(RLIMIT_AS)`) to what it uses already plus [`HEADROOM`]: an abort there fails the
//! test through the child's exit status, without taking the test runner down.
#![cfg(target_os = "linux")]

use std::process::Command;

use halfwing::OutOfMemory;
use halfwing::io::{IoError, MeshFormat, read_bytes};
use halfwing::mesh::Mesh;
use halfwing::render::{RenderError, SurfaceOptions, surface_buffer};
use halfwing::soup::{BuildError, BuildPolicy, FaceList};
use halfwing::surfaces::{CellFaces, Grid, SurfaceError, grid};
use halfwing::voronoi::{Delaunay, Metric, VoronoiError};
use halfwing::winged::Winged;

/// Set in the child process, which runs the test's body under the limit.
const CHILD: &str = "HALFWING_TEST_UNDER_MEMORY_LIMIT";
/// Address space the child may take beyond what it has when the limit is set.
const HEADROOM: u64 = 256 << 20;

/// Runs `body` in a child process (test `name` of this binary again) whose address space is
/// limited to its current size plus [`HEADROOM`] once `prepare` has run (`prepare` makes the
/// input, which is not what is tested).
fn under_memory_limit<T>(name: &str, prepare: impl FnOnce() -> T, body: impl FnOnce(T)) {
    if std::env::var_os(CHILD).is_none() {
        let output = Command::new(std::env::current_exe().unwrap())
            .args([name, "--exact", "--nocapture", "--test-threads=1"])
            .env(CHILD, "1")
            .output()
            .unwrap();
        let stdout = String::from_utf8_lossy(&output.stdout);
        assert!(
            output.status.success() && stdout.contains("1 passed"),
            "{name} under a memory limit: {}\n{stdout}\n{}",
            output.status,
            String::from_utf8_lossy(&output.stderr)
        );
        return;
    }
    let input = prepare();
    limit_address_space(address_space_in_use() + HEADROOM);
    body(input);
    // Still usable: a small build succeeds under the same limit.
    let cells = grid(&grid_of(8, CellFaces::Quads)).unwrap();
    let (mesh, _) = Mesh::from_soup(&cells, BuildPolicy::Strict).unwrap();
    assert_eq!(mesh.n_faces(), 64);
}

fn address_space_in_use() -> u64 {
    let statm = std::fs::read_to_string("/proc/self/statm").unwrap();
    let pages: u64 = statm.split_whitespace().next().unwrap().parse().unwrap();
    // SAFETY: sysconf only reads a system setting.
    pages * unsafe { libc::sysconf(libc::_SC_PAGESIZE) } as u64
}

fn limit_address_space(bytes: u64) {
    let limit = libc::rlimit {
        rlim_cur: bytes,
        rlim_max: libc::RLIM_INFINITY,
    };
    // SAFETY: a pointer to a live rlimit.
    assert_eq!(unsafe { libc::setrlimit(libc::RLIMIT_AS, &limit) }, 0);
}

fn grid_of(cells: u32, faces: CellFaces) -> Grid {
    Grid {
        width: 1.0,
        height: 1.0,
        cells_x: cells,
        cells_y: cells,
        faces,
    }
}

#[test]
fn a_grid_larger_than_memory_is_refused_with_its_size() {
    under_memory_limit(
        "a_grid_larger_than_memory_is_refused_with_its_size",
        || (),
        |()| {
            let refused = grid(&grid_of(20_000, CellFaces::Quads)).unwrap_err();
            let SurfaceError::OutOfMemory(refusal) = refused else {
                panic!("{refused:?}")
            };
            assert_eq!(
                refusal.to_string(),
                "cannot allocate 9.6 GB for 400040001 vertices"
            );
        },
    );
}

#[test]
fn builds_whose_working_memory_is_not_there_are_refused_before_starting() {
    under_memory_limit(
        "builds_whose_working_memory_is_not_there_are_refused_before_starting",
        // 4M vertices and 16M corners: 180 MB of input, about 1 GB to build.
        || grid(&grid_of(2000, CellFaces::Quads)).unwrap(),
        |soup| {
            let refused = Mesh::from_soup(&soup, BuildPolicy::Repair).unwrap_err();
            assert!(matches!(refused, BuildError::OutOfMemory(_)), "{refused:?}");
            assert!(refused.diagnostic().is_clean());
            let refused =
                Winged::from_face_list(&soup.as_face_list(), BuildPolicy::Strict).unwrap_err();
            let BuildError::OutOfMemory(OutOfMemory { count, what, .. }) = refused else {
                panic!("{refused:?}")
            };
            assert_eq!((count, what), (16_000_000, "corners"));
            let refused = halfwing::doctor::examine(&soup.as_face_list(), &Default::default());
            assert!(
                matches!(refused, Err(halfwing::doctor::DoctorError::OutOfMemory(_))),
                "{refused:?}"
            );
        },
    );
}

#[test]
fn voronoi_diagrams_and_label_images_larger_than_memory_are_refused() {
    under_memory_limit(
        "voronoi_diagrams_and_label_images_larger_than_memory_are_refused",
        || {
            let n = 1_000_000u32;
            let sites: Vec<[f64; 2]> = (0..n)
                .map(|i| {
                    [
                        f64::from(i % 1000),
                        f64::from(i / 1000) + f64::from(i % 7) * 0.1,
                    ]
                })
                .collect();
            let small = Delaunay::new(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]).unwrap();
            (sites, small)
        },
        |(sites, small)| {
            let refused = Delaunay::new(&sites).unwrap_err();
            assert!(
                matches!(refused, VoronoiError::OutOfMemory(_)),
                "{refused:?}"
            );
            let refused = small
                .label_image(Metric::Euclidean, [0.0; 2], [1.0; 2], 40_000, 40_000)
                .unwrap_err();
            let VoronoiError::OutOfMemory(refusal) = refused else {
                panic!("{refused:?}")
            };
            assert_eq!(
                refusal.to_string(),
                "cannot allocate 6.4 GB for 1600000000 pixels"
            );
            assert_eq!(
                small
                    .label_image(Metric::Euclidean, [0.0; 2], [1.0; 2], 4, 4)
                    .unwrap()
                    .labels
                    .len(),
                16
            );
        },
    );
}

#[test]
fn render_buffers_larger_than_memory_are_refused() {
    under_memory_limit(
        "render_buffers_larger_than_memory_are_refused",
        // 640k half-edges, whose buffers need about 90 MB: more than is left once 200 MB of
        // the headroom is taken.
        || {
            let soup = grid(&grid_of(400, CellFaces::Quads)).unwrap();
            Mesh::from_soup(&soup, BuildPolicy::Strict).unwrap().0
        },
        |mesh| {
            let mut taken: Vec<u8> = Vec::new();
            taken.try_reserve_exact(200 << 20).unwrap();
            taken.resize(200 << 20, 1);
            let refused = surface_buffer(&mesh, &SurfaceOptions::default()).unwrap_err();
            assert!(
                matches!(refused, RenderError::OutOfMemory(_)),
                "{refused:?}"
            );
            drop(taken);
            assert!(surface_buffer(&mesh, &SurfaceOptions::default()).is_ok());
        },
    );
}

#[test]
fn a_lying_header_is_refused_without_reserving_what_it_declares() {
    under_memory_limit(
        "a_lying_header_is_refused_without_reserving_what_it_declares",
        || (),
        |()| {
            // A billion vertices declared (24 GB), three given: reserving the declared count
            // would fail under the limit with `OutOfMemory`; the reader finds the file short.
            let off = b"OFF\n1000000000 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
            let refused = read_bytes(MeshFormat::Off, off).unwrap_err();
            assert!(matches!(refused, IoError::Parse { .. }), "{refused:?}");
            let ply = b"ply\nformat ascii 1.0\nelement vertex 1000000000\nproperty float x\n\
                property float y\nproperty float z\nelement face 1000000000\n\
                property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
            let refused = read_bytes(MeshFormat::Ply, ply).unwrap_err();
            assert!(matches!(refused, IoError::Parse { .. }), "{refused:?}");
            let mut binary = b"ply\nformat binary_little_endian 1.0\nelement vertex 1000000000\n\
                property double x\nproperty double y\nproperty double z\nend_header\n"
                .to_vec();
            binary.extend([0u8; 24 * 3]);
            let refused = read_bytes(MeshFormat::Ply, &binary).unwrap_err();
            assert!(matches!(refused, IoError::Parse { .. }), "{refused:?}");
        },
    );
}

/// An OBJ file declares no counts: its arrays grow as its records come, and a file whose
/// vertices take more memory than there is (12 million, 288 MB of positions from 96 MB of text)
/// is refused with `OutOfMemory` instead of aborting in the growth.
#[test]
fn an_obj_file_larger_than_memory_is_refused_as_it_grows() {
    under_memory_limit(
        "an_obj_file_larger_than_memory_is_refused_as_it_grows",
        || b"v 0 0 0\n".repeat(12_000_000),
        |obj| {
            let refused = read_bytes(MeshFormat::Obj, &obj).unwrap_err();
            assert!(
                matches!(refused, IoError::OutOfMemory(ref o) if o.what == "vertices"),
                "{refused:?}"
            );
        },
    );
}

/// The peak memory of reading a file whose header lies stays that of the file, not of its
/// declared counts (measured in the child, whose peak is its own).
#[test]
fn a_lying_header_costs_the_memory_of_the_file_only() {
    under_memory_limit(
        "a_lying_header_costs_the_memory_of_the_file_only",
        || (),
        |()| {
            let peak_before = peak_resident_bytes();
            let off = b"OFF\n100000000 100000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
            assert!(read_bytes(MeshFormat::Off, off).is_err());
            let list = FaceList::triangles(&[[0.0; 3]; 3], &[0, 1, 2]);
            assert!(Mesh::from_face_list(&list, BuildPolicy::Strict).is_ok());
            assert!(peak_resident_bytes() - peak_before < 16 << 20);
        },
    );
}

fn peak_resident_bytes() -> u64 {
    // SAFETY: a zeroed rusage is a valid value to write into.
    let mut usage: libc::rusage = unsafe { std::mem::zeroed() };
    // SAFETY: a pointer to a live rusage.
    assert_eq!(unsafe { libc::getrusage(libc::RUSAGE_SELF, &mut usage) }, 0);
    usage.ru_maxrss as u64 * 1024
}
