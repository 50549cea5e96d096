//! Every mesh of the test data set reads without panicking, with the vertex and face counts and
//! the face-size histogram that `data/MANIFEST.md` states, and every OBJ agrees with `tobj`.
//!
//! The data is the repository's `tests/data`; set `HALFWING_DATA` to point at a fuller set.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use halfwing::io::{IoError, read_path};
use halfwing::soup::PolygonSoup;

mod test_data;

fn data_dir() -> PathBuf {
    let dir = test_data::root();
    assert!(
        dir.join("MANIFEST.md").is_file(),
        "test data not found at {} (set HALFWING_DATA)",
        dir.display()
    );
    dir
}

/// What the manifest says about one mesh file.
#[derive(Debug)]
struct Expected {
    vertices: usize,
    faces: usize,
    /// Face size → number of faces.
    histogram: BTreeMap<u32, usize>,
}

/// Reads `### \`meshes/…\`` sections and their `- Counts: V=…; F=…; faces: tri x4, 5-gon x2` lines.
fn manifest(dir: &Path) -> BTreeMap<String, Expected> {
    let text = std::fs::read_to_string(dir.join("MANIFEST.md")).unwrap();
    let mut entries = BTreeMap::new();
    let mut current: Option<String> = None;
    for line in text.lines() {
        if let Some(name) = line
            .strip_prefix("### `")
            .and_then(|rest| rest.strip_suffix('`'))
        {
            current = name.starts_with("meshes/").then(|| name.to_owned());
        } else if let (Some(name), Some(counts)) = (&current, line.strip_prefix("- Counts: ")) {
            let mut fields = counts.split("; ");
            let mut number = |key: &str| -> usize {
                fields
                    .next()
                    .and_then(|f| f.strip_prefix(key))
                    .unwrap()
                    .parse()
                    .unwrap()
            };
            let vertices = number("V=");
            let faces = number("F=");
            let histogram = fields
                .next()
                .and_then(|f| f.strip_prefix("faces: "))
                .unwrap()
                .split(", ")
                .map(|entry| {
                    let (kind, count) = entry.split_once(" x").unwrap();
                    let size = match kind {
                        "tri" => 3,
                        "quad" => 4,
                        _ => kind.strip_suffix("-gon").unwrap().parse().unwrap(),
                    };
                    (size, count.parse().unwrap())
                })
                .collect();
            entries.insert(
                name.clone(),
                Expected {
                    vertices,
                    faces,
                    histogram,
                },
            );
            current = None;
        }
    }
    entries
}

fn mesh_files(dir: &Path) -> Vec<PathBuf> {
    let mut files = Vec::new();
    let mut pending = vec![dir.join("meshes")];
    while let Some(folder) = pending.pop() {
        for entry in std::fs::read_dir(&folder).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                pending.push(path);
            } else {
                files.push(path);
            }
        }
    }
    files.sort();
    files
}

fn histogram(soup: &PolygonSoup) -> BTreeMap<u32, usize> {
    let mut histogram = BTreeMap::new();
    for &size in &soup.face_sizes {
        *histogram.entry(size).or_insert(0) += 1;
    }
    histogram
}

/// The one file the readers refuse on purpose: face `f 4 5 7` names a seventh vertex of six.
const REFUSED: (&str, u64) = ("meshes/broken/tobj_invalid_index.obj", 12);

#[test]
fn every_mesh_reads_with_the_manifest_counts() {
    let dir = data_dir();
    let expected = manifest(&dir);
    let files = mesh_files(&dir);
    assert!(files.len() >= 70, "only {} mesh files found", files.len());
    for path in &files {
        let name = path
            .strip_prefix(&dir)
            .unwrap()
            .to_str()
            .unwrap()
            .to_owned();
        let result = read_path(path);
        if name == REFUSED.0 {
            let error = result.expect_err("an out-of-range index must be refused");
            assert!(matches!(error, IoError::Parse { .. }), "{name}: {error}");
            assert_eq!(error.line(), Some(REFUSED.1), "{name}: {error}");
            assert!(
                error.to_string().contains("vertex index 7 is out of range"),
                "{error}"
            );
            continue;
        }
        let soup = result.unwrap_or_else(|e| panic!("{name}: {e}"));
        let want = expected
            .get(&name)
            .unwrap_or_else(|| panic!("{name} is not in the manifest"));
        assert_eq!(soup.positions.len(), want.vertices, "{name}: vertex count");
        assert_eq!(soup.n_faces(), want.faces, "{name}: face count");
        assert_eq!(histogram(&soup), want.histogram, "{name}: face sizes");
        assert_eq!(
            soup.indices.len() as u64,
            soup.face_sizes.iter().map(|&s| u64::from(s)).sum::<u64>()
        );
        assert!(
            soup.indices
                .iter()
                .all(|&i| (i as usize) < soup.positions.len()),
            "{name}"
        );
    }
    assert_eq!(
        files.len(),
        expected.len(),
        "files and manifest entries differ"
    );
}

#[test]
fn attributes_are_kept_where_files_have_them() {
    let dir = data_dir().join("meshes");
    let soup = read_path(dir.join("polygonal/igl_cylinder.obj")).unwrap();
    assert!(
        soup.corner_normals.is_some() && soup.corner_uvs.is_some(),
        "igl_cylinder has vt and vn"
    );
    let soup = read_path(dir.join("closed/c3d_spot.obj")).unwrap();
    assert!(
        soup.corner_normals.is_none() && soup.corner_uvs.is_some(),
        "spot has vt only"
    );
    let soup = read_path(dir.join("broken/cgaltest_nm_edges_simple.off")).unwrap();
    assert_eq!(
        soup.corner_normals.as_ref().map(Vec::len),
        Some(soup.indices.len()),
        "NOFF normals"
    );
    // Negative indices: the first face `-8/-13/-6 -4/-12/-6 …` after 8 v, 14 vt and 6 vn records.
    let soup = read_path(dir.join("polygonal/tm_negative_indices.obj")).unwrap();
    assert_eq!(&soup.indices[..4], &[0, 4, 6, 2]);
    assert_eq!(soup.corner_uvs.as_ref().unwrap()[0], [0.875, 0.5]);
    assert_eq!(soup.corner_normals.as_ref().unwrap()[0], [0.0, 1.0, 0.0]);
}

/// Every OBJ gives, face after face, the corner positions tobj gives (tobj reads `f32` and
/// renumbers vertices, so positions are compared per corner, in single precision).
#[test]
// `tobj::Float` is `f32`, or `f64` when another crate enables tobj's `use_f64`: keep the casts.
#[allow(clippy::unnecessary_cast)]
fn obj_files_agree_with_tobj() {
    let dir = data_dir();
    let options = tobj::LoadOptions {
        single_index: false,
        triangulate: false,
        ..Default::default()
    };
    let mut compared = 0;
    for path in mesh_files(&dir)
        .iter()
        .filter(|p| p.extension().is_some_and(|e| e == "obj"))
    {
        let name = path.strip_prefix(&dir).unwrap().to_str().unwrap();
        if name == REFUSED.0 {
            continue;
        }
        let soup = read_path(path).unwrap();
        let mut file = std::io::BufReader::new(std::fs::File::open(path).unwrap());
        let (models, _) = tobj::load_obj_buf(&mut file, &options, |_| {
            Err(tobj::LoadError::OpenFileFailed)
        })
        .unwrap_or_else(|e| panic!("tobj refuses {name}: {e}"));
        let mut theirs: Vec<Vec<[f32; 3]>> = Vec::new();
        for model in &models {
            let mesh = &model.mesh;
            let sizes = if mesh.face_arities.is_empty() {
                vec![3; mesh.indices.len() / 3]
            } else {
                mesh.face_arities.clone()
            };
            let mut corner = 0;
            for size in sizes {
                let face = (corner..corner + size as usize)
                    .map(|c| {
                        let v = mesh.indices[c] as usize * 3;
                        [
                            mesh.positions[v] as f32,
                            mesh.positions[v + 1] as f32,
                            mesh.positions[v + 2] as f32,
                        ]
                    })
                    .collect();
                theirs.push(face);
                corner += size as usize;
            }
        }
        let mut corners = soup.indices.iter();
        let ours: Vec<Vec<[f32; 3]>> = soup
            .face_sizes
            .iter()
            .map(|&size| {
                corners
                    .by_ref()
                    .take(size as usize)
                    .map(|&v| soup.positions[v as usize].map(|x| x as f32))
                    .collect()
            })
            .collect();
        assert_eq!(ours.len(), theirs.len(), "{name}: face count");
        assert!(
            ours == theirs,
            "{name}: corner positions differ from tobj's"
        );
        compared += 1;
    }
    assert!(compared >= 20, "only {compared} OBJ files compared");
}
