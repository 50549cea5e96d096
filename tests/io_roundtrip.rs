//! Writing a soup and reading it back reproduces it: positions bit for bit, faces, indices, and
//! the attributes each format can hold (OBJ: per corner; OFF and PLY: per vertex, so only when all
//! corners of a vertex agree).

use std::collections::HashMap;

use halfwing::io::{
    MeshFormat, PlyEncoding, read_bytes, read_path, write_obj, write_off, write_path, write_ply,
};
use halfwing::soup::PolygonSoup;
use proptest::prelude::*;

mod test_data;

/// The encodings a soup is written in.
#[derive(Clone, Copy, Debug)]
enum Encoding {
    Obj,
    Off,
    PlyAscii,
    PlyBinary,
    PlyBigEndian,
}

const ENCODINGS: [Encoding; 5] = [
    Encoding::Obj,
    Encoding::Off,
    Encoding::PlyAscii,
    Encoding::PlyBinary,
    Encoding::PlyBigEndian,
];

fn round_trip(soup: &PolygonSoup, encoding: Encoding) -> PolygonSoup {
    let mut bytes = Vec::new();
    let format = match encoding {
        Encoding::Obj => write_obj(&mut bytes, soup).map(|()| MeshFormat::Obj),
        Encoding::Off => write_off(&mut bytes, soup).map(|()| MeshFormat::Off),
        Encoding::PlyAscii => {
            write_ply(&mut bytes, soup, PlyEncoding::Ascii).map(|()| MeshFormat::Ply)
        }
        Encoding::PlyBinary => {
            write_ply(&mut bytes, soup, PlyEncoding::BinaryLittleEndian).map(|()| MeshFormat::Ply)
        }
        Encoding::PlyBigEndian => {
            write_ply(&mut bytes, soup, PlyEncoding::BinaryBigEndian).map(|()| MeshFormat::Ply)
        }
    }
    .unwrap_or_else(|e| panic!("{encoding:?}: write failed: {e}"));
    read_bytes(format, &bytes).unwrap_or_else(|e| panic!("{encoding:?}: read back failed: {e}"))
}

/// Equal bits, or both NaN (text formats write every NaN as `NaN`, dropping sign and payload).
fn same_float(a: f64, b: f64) -> bool {
    a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan())
}

fn same_arrays<const N: usize>(a: &[[f64; N]], b: &[[f64; N]]) -> bool {
    a.len() == b.len()
        && a.iter()
            .flatten()
            .zip(b.iter().flatten())
            .all(|(&x, &y)| same_float(x, y))
}

fn same_attribute<const N: usize>(a: &Option<Vec<[f64; N]>>, b: &Option<Vec<[f64; N]>>) -> bool {
    match (a, b) {
        (None, None) => true,
        (Some(a), Some(b)) => same_arrays(a, b),
        _ => false,
    }
}

/// An attribute as a per-vertex format keeps it: unchanged if all corners of each vertex have the
/// same bits, dropped otherwise.
fn per_vertex_view<const N: usize>(
    values: &Option<Vec<[f64; N]>>,
    indices: &[u32],
) -> Option<Vec<[f64; N]>> {
    let values = values.as_ref()?;
    let mut first: HashMap<u32, [u64; N]> = HashMap::new();
    let consistent = indices.iter().zip(values).all(|(&v, value)| {
        *first.entry(v).or_insert(value.map(f64::to_bits)) == value.map(f64::to_bits)
    });
    consistent.then(|| values.clone())
}

fn assert_round_trips(soup: &PolygonSoup, what: &str) {
    for encoding in ENCODINGS {
        let back = round_trip(soup, encoding);
        assert!(
            same_arrays(&back.positions, &soup.positions),
            "{what} {encoding:?}: positions"
        );
        assert_eq!(
            back.face_sizes, soup.face_sizes,
            "{what} {encoding:?}: face sizes"
        );
        assert_eq!(back.indices, soup.indices, "{what} {encoding:?}: indices");
        let (normals, uvs) = match encoding {
            Encoding::Obj => (soup.corner_normals.clone(), soup.corner_uvs.clone()),
            _ => (
                per_vertex_view(&soup.corner_normals, &soup.indices),
                per_vertex_view(&soup.corner_uvs, &soup.indices),
            ),
        };
        assert!(
            same_attribute(&back.corner_normals, &normals),
            "{what} {encoding:?}: normals"
        );
        assert!(
            same_attribute(&back.corner_uvs, &uvs),
            "{what} {encoding:?}: texture coordinates"
        );
    }
}

#[test]
fn data_set_meshes_round_trip_in_every_format() {
    let dir = test_data::root();
    let names = [
        "meshes/polygonal/cgal_mpi.off",
        "meshes/polygonal/igl_cylinder.obj",
        "meshes/polygonal/tm_negative_indices.obj",
        "meshes/polygonal/om_cube-minimal.ply",
        "meshes/broken/tm_featuretype.ply",
        "meshes/broken/cgaltest_nm_edges_simple.off",
        "meshes/broken/om_cube-minimal-degenerated.obj",
        "meshes/broken/tm_notenoughindices.obj",
        "meshes/open/c3d_stanford-bunny.obj",
        "meshes/closed/nvdiffrec_bob_tri.obj",
        "meshes/closed/pmp_bunny.off",
    ];
    for name in names {
        let soup = read_path(dir.join(name)).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_round_trips(&soup, name);
    }
}

#[test]
fn paths_choose_the_format_by_extension() {
    let soup = PolygonSoup {
        positions: vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.1]],
        face_sizes: vec![3],
        indices: vec![0, 1, 2],
        ..Default::default()
    };
    let dir = std::env::temp_dir().join(format!("halfwing-io-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for name in ["a.obj", "b.OFF", "c.ply"] {
        let path = dir.join(name);
        write_path(&path, &soup).unwrap();
        assert_eq!(read_path(&path).unwrap(), soup, "{name}");
    }
    assert!(write_path(dir.join("d.stl"), &soup).is_err());
    assert!(read_path(dir.join("missing.obj")).is_err());
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn inconsistent_soups_are_refused_by_every_writer() {
    let soup = PolygonSoup {
        positions: vec![[0.0; 3]],
        face_sizes: vec![3],
        indices: vec![0, 0],
        ..Default::default()
    };
    assert!(write_obj(Vec::new(), &soup).is_err());
    assert!(write_off(Vec::new(), &soup).is_err());
    assert!(write_ply(Vec::new(), &soup, PlyEncoding::Ascii).is_err());
    let empty_face = PolygonSoup {
        positions: vec![[0.0; 3]],
        face_sizes: vec![0],
        ..Default::default()
    };
    assert!(
        write_obj(Vec::new(), &empty_face).is_err(),
        "OBJ has no empty face record"
    );
    assert_eq!(round_trip(&empty_face, Encoding::Off), empty_face);
}

/// Any `f64`: special values often, arbitrary bit patterns otherwise.
fn any_float() -> impl Strategy<Value = f64> {
    prop_oneof![
        Just(0.0),
        Just(-0.0),
        Just(f64::NAN),
        Just(f64::INFINITY),
        Just(f64::MIN_POSITIVE / 4.0),
        any::<u64>().prop_map(f64::from_bits),
        -1e3..1e3f64,
    ]
}

prop_compose! {
    fn any_soup()(vertex_count in 1usize..12, sizes in prop::collection::vec(1u32..9, 1..8))
        (positions in prop::collection::vec([any_float(), any_float(), any_float()], vertex_count),
         indices in prop::collection::vec(0..vertex_count as u32, sizes.iter().sum::<u32>() as usize),
         normals in prop::option::of(prop::collection::vec([any_float(), any_float(), any_float()],
             sizes.iter().sum::<u32>() as usize)),
         per_vertex_uvs in prop::option::of(prop::collection::vec([any_float(), any_float()], vertex_count)),
         sizes in Just(sizes))
        -> PolygonSoup
    {
        // Texture coordinates per vertex (they survive every format), normals per corner (OBJ only).
        let corner_uvs = per_vertex_uvs.map(|uvs| indices.iter().map(|&v| uvs[v as usize]).collect());
        PolygonSoup { positions, face_sizes: sizes, indices, corner_normals: normals, corner_uvs }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    #[test]
    fn random_soups_round_trip(soup in any_soup()) {
        assert_round_trips(&soup, "random soup");
    }
}
