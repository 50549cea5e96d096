//! The property every reader target checks, shared so the three targets cannot drift apart.

use halfwing::io::{MeshFormat, PlyEncoding, read_bytes, write_obj, write_off, write_ply};

/// Reads `bytes`; when that succeeds, checks the soup's consistency and that writing it in the
/// same format and reading it again keeps its faces and indices.
pub fn check(format: MeshFormat, bytes: &[u8]) {
    let Ok(soup) = read_bytes(format, bytes) else {
        return;
    };
    let corners: u64 = soup.face_sizes.iter().map(|&size| u64::from(size)).sum();
    assert_eq!(corners, soup.indices.len() as u64);
    assert!(
        soup.indices
            .iter()
            .all(|&index| (index as usize) < soup.positions.len())
    );
    let mut written = Vec::new();
    let result = match format {
        MeshFormat::Obj => write_obj(&mut written, &soup),
        MeshFormat::Off => write_off(&mut written, &soup),
        MeshFormat::Ply => write_ply(&mut written, &soup, PlyEncoding::BinaryLittleEndian),
    };
    result.expect("a soup the reader produced must be writable");
    let again = read_bytes(format, &written).expect("a written soup must read back");
    assert_eq!(again.face_sizes, soup.face_sizes);
    assert_eq!(again.indices, soup.indices);
    assert_eq!(again.positions.len(), soup.positions.len());
}
