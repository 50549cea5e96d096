//! Malformed input never panics: it gives a parse error that says where and what. Counts at the
//! 2^32 scale are refused or run into the end of the file without reserving memory for them.

use halfwing::io::{
    IoError, Location, MeshFormat, PlyEncoding, read_bytes, write_obj, write_off, write_ply,
};
use halfwing::soup::PolygonSoup;
use proptest::prelude::*;

fn error(format: MeshFormat, text: &[u8]) -> IoError {
    read_bytes(format, text).expect_err("malformed input must be refused")
}

fn assert_error_at(format: MeshFormat, text: &str, line: u64, message: &str) {
    let error = error(format, text.as_bytes());
    assert_eq!(error.line(), Some(line), "{text:?}: {error}");
    assert!(error.to_string().contains(message), "{text:?}: {error}");
}

#[test]
fn text_errors_give_the_line_and_the_problem() {
    use MeshFormat::{Obj, Off, Ply};
    let ply_header = "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n\
property float z\nelement face 1\nproperty list uchar uint vertex_indices\nend_header\n";
    let cases: Vec<(MeshFormat, String, u64, &str)> = vec![
        (Obj, "v 1 2 3\nv 1 2\n".into(), 2, "2 components"),
        (
            Obj,
            "v 1 2 3\n# c\nf 1 1 2\n".into(),
            3,
            "vertex index 2 is out of range",
        ),
        (
            Obj,
            "v 1 2 3\nvn 0 0 1\nf 1//2 1//1 1//1\n".into(),
            3,
            "normal index 2 is out of range",
        ),
        (Obj, "v 1 2 3e\n".into(), 1, "not a number: `3e`"),
        (
            Obj,
            "v 0 0 0\nf 1 1 99999999999999999999\n".into(),
            2,
            "not an integer",
        ),
        (
            Off,
            "OFF\n1 1 0\n0 0 0\n3 0 0 -1\n".into(),
            4,
            "index -1 is out of range",
        ),
        (
            Off,
            "OFF\n1 1 0\n0 0 0\n3 0 0\n".into(),
            4,
            "declares 3 vertices but lists 2",
        ),
        (Off, "OFF\n2 0 0\n0 0 0\n".into(), 4, "1 of 2 vertices"),
        (Off, "NOFF\n1 0 0\n0 0 0 1 1\n".into(), 3, "2 of 3 normal"),
        (
            Ply,
            format!("{ply_header}0 0 0\n1 1 1\n3 0 1 2\n"),
            12,
            "index 2 is out of range",
        ),
        (
            Ply,
            format!("{ply_header}0 0 0\n1 1 one\n"),
            11,
            "`one` is not a number",
        ),
        (
            Ply,
            format!("{ply_header}0 0 0\n1 1 1\n-3 0 1 1\n"),
            12,
            "negative",
        ),
    ];
    for (format, text, line, message) in cases {
        assert_error_at(format, &text, line, message);
    }
}

#[test]
fn binary_errors_give_the_element_and_record() {
    let soup = PolygonSoup {
        positions: vec![[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
        face_sizes: vec![3, 3],
        indices: vec![0, 1, 2, 2, 1, 0],
        ..Default::default()
    };
    let mut bytes = Vec::new();
    write_ply(&mut bytes, &soup, PlyEncoding::BinaryLittleEndian).unwrap();
    // The last index of face 1 becomes 7: out of range of the 3 declared vertices.
    let last = bytes.len() - 4;
    bytes[last..].copy_from_slice(&7u32.to_le_bytes());
    let error = error(MeshFormat::Ply, &bytes);
    let expected = Location::Record {
        element: "face".to_owned(),
        index: 1,
    };
    assert!(
        matches!(&error, IoError::Parse { location, .. } if *location == expected),
        "{error}"
    );
    assert!(
        error.to_string().contains("index 7 is out of range"),
        "{error}"
    );
}

#[test]
fn counts_at_the_2_pow_32_scale_do_not_allocate_or_wrap() {
    let too_many = "OFF\n4294967296 0 0\n";
    assert!(
        error(MeshFormat::Off, too_many.as_bytes())
            .to_string()
            .contains("32-bit")
    );
    // Declared counts far beyond the data run into the end of the file.
    assert_error_at(
        MeshFormat::Off,
        "OFF\n4294967295 4294967295 0\n0 0 0\n",
        4,
        "1 of 4294967295 vertices",
    );
    let ply = "ply\nformat binary_little_endian 1.0\nelement vertex 4294967296\nproperty float x\n\
property float y\nproperty float z\nend_header\n";
    assert!(
        error(MeshFormat::Ply, ply.as_bytes())
            .to_string()
            .contains("32-bit")
    );
    let mut ply = b"ply\nformat binary_little_endian 1.0\nelement vertex 0\nproperty float x\nproperty float y\n\
property float z\nelement face 4294967295\nproperty list uint uint vertex_indices\nend_header\n"
        .to_vec();
    ply.extend_from_slice(&u32::MAX.to_le_bytes());
    let error = error(MeshFormat::Ply, &ply);
    assert!(
        error.to_string().contains("unexpected end of file"),
        "{error}"
    );
    assert_error_at(
        MeshFormat::Obj,
        "v 0 0 0\nf 1 1 4294967296\n",
        2,
        "too large",
    );
    // An element whose records hold nothing is not walked record by record.
    let empty_records = "ply\nformat ascii 1.0\nelement nothing 9223372036854775807\nelement vertex 1\n\
property float x\nproperty float y\nproperty float z\nend_header\n1 2 3\n";
    let soup = read_bytes(MeshFormat::Ply, empty_records.as_bytes()).unwrap();
    assert_eq!(soup.positions, vec![[1.0, 2.0, 3.0]]);
}

fn sample_files() -> Vec<(MeshFormat, Vec<u8>)> {
    let soup = PolygonSoup {
        positions: vec![
            [0.5, -1.25, 3.0],
            [1e-9, 2.0, 0.0],
            [0.0, 1.0, 7.5],
            [4.0, 4.0, 4.0],
        ],
        face_sizes: vec![3, 4],
        indices: vec![0, 1, 2, 3, 2, 1, 0],
        corner_normals: Some(vec![[0.0, 0.0, 1.0]; 7]),
        corner_uvs: Some(vec![[0.25, 0.5]; 7]),
    };
    let mut files = Vec::new();
    let mut bytes = Vec::new();
    write_obj(&mut bytes, &soup).unwrap();
    files.push((MeshFormat::Obj, std::mem::take(&mut bytes)));
    write_off(&mut bytes, &soup).unwrap();
    files.push((MeshFormat::Off, std::mem::take(&mut bytes)));
    for encoding in [PlyEncoding::Ascii, PlyEncoding::BinaryLittleEndian] {
        write_ply(&mut bytes, &soup, encoding).unwrap();
        files.push((MeshFormat::Ply, std::mem::take(&mut bytes)));
    }
    files
}

/// Every prefix of a valid file reads or fails cleanly; a successful read is a consistent soup.
#[test]
fn truncated_files_never_panic() {
    for (format, bytes) in sample_files() {
        for end in 0..bytes.len() {
            if let Ok(soup) = read_bytes(format, &bytes[..end]) {
                assert_consistent(&soup);
            }
        }
    }
}

fn assert_consistent(soup: &PolygonSoup) {
    let corners: u64 = soup.face_sizes.iter().map(|&s| u64::from(s)).sum();
    assert_eq!(corners, soup.indices.len() as u64);
    assert!(
        soup.indices
            .iter()
            .all(|&i| (i as usize) < soup.positions.len())
    );
    for len in [
        soup.corner_normals.as_ref().map(Vec::len),
        soup.corner_uvs.as_ref().map(Vec::len),
    ] {
        assert!(len.is_none_or(|len| len == soup.indices.len()));
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    /// Random byte edits of valid files: never a panic, and any soup read is consistent.
    #[test]
    fn mutated_files_never_panic(
        file in 0usize..4,
        edits in prop::collection::vec((any::<prop::sample::Index>(), any::<u8>()), 1..6),
    ) {
        let (format, mut bytes) = sample_files().swap_remove(file);
        for (at, byte) in edits {
            let at = at.index(bytes.len());
            bytes[at] = byte;
        }
        if let Ok(soup) = read_bytes(format, &bytes) {
            assert_consistent(&soup);
        }
    }

    /// Arbitrary bytes after a plausible start.
    #[test]
    fn arbitrary_bytes_never_panic(tail in prop::collection::vec(any::<u8>(), 0..200), start in 0usize..4) {
        let prefix: &[u8] = [&b"OFF\n"[..], b"ply\nformat ascii 1.0\n", b"v 1 2 3\nf ", b""][start];
        let bytes = [prefix, &tail].concat();
        for format in [MeshFormat::Obj, MeshFormat::Off, MeshFormat::Ply] {
            if let Ok(soup) = read_bytes(format, &bytes) {
                assert_consistent(&soup);
            }
        }
    }
}

/// Errors of the operating system name the file and what was being done, once, without
/// Rust's "(os error N)" suffix.
#[test]
fn file_errors_name_the_file() {
    let dir = std::env::temp_dir().join(format!("halfwing-io-errors-{}", std::process::id()));
    let missing = dir.join("missing.obj");
    let error = halfwing::io::read_path(&missing).expect_err("no such file");
    assert_eq!(
        error.to_string(),
        format!(
            "cannot open '{}': No such file or directory",
            missing.display()
        )
    );
    let soup = halfwing::soup::PolygonSoup::default();
    let error = halfwing::io::write_path(&missing, &soup).expect_err("no such folder");
    assert_eq!(
        error.to_string(),
        format!(
            "cannot create '{}': No such file or directory",
            missing.display()
        )
    );
}

/// A binary file is refused by the OBJ reader (which skips unknown statements) instead of
/// reading as an empty mesh, and the bytes of a bad token are escaped in messages.
#[test]
fn binary_bytes_are_refused_and_never_echoed() {
    let png = b"\x89PNG\r\n\x1a\n\0\0\0\rIHDR";
    let error = halfwing::io::read_obj_bytes(png).expect_err("not text");
    assert_eq!(
        error.to_string(),
        "OBJ parse error at line 3: the file holds a NUL byte: it is not a text file"
    );
    let error = halfwing::io::read_obj_bytes(b"v 1 2 3\nf 1 2 \xff\xfe\x01\x02abc\n")
        .expect_err("bad index");
    assert_eq!(
        error.to_string(),
        "OBJ parse error at line 2: vertex index `\\xff\\xfe\\x01\\x02abc` is not an integer"
    );
}
