//! Turns fuzzer bytes into a small, often broken, indexed face list: few vertices so that edges
//! collide (non-manifold and inconsistently oriented edges, pinched vertices), indices that may
//! run past the positions, faces of 0 to 7 corners, and coordinates that may be NaN or infinite.

/// An owned face list decoded from bytes.
pub struct Decoded {
    pub positions: Vec<[f64; 3]>,
    pub sizes: Vec<u32>,
    pub indices: Vec<u32>,
}

fn coordinate(byte: u8) -> f64 {
    match byte {
        0xFD => f64::NAN,
        0xFE => f64::INFINITY,
        0xFF => -1e300,
        b => f64::from(b % 16) - 8.0,
    }
}

pub fn decode(bytes: &[u8]) -> Decoded {
    let mut bytes = bytes.iter().copied();
    let n_vertices = usize::from(bytes.next().unwrap_or(0) % 24);
    let positions = (0..n_vertices)
        .map(|_| {
            let mut c = || coordinate(bytes.next().unwrap_or(0));
            [c(), c(), c()]
        })
        .collect();
    let (mut sizes, mut indices) = (Vec::new(), Vec::new());
    while let Some(size) = bytes.next() {
        let size = u32::from(size % 8);
        sizes.push(size);
        for _ in 0..size {
            // Two past the end, to reach out-of-range indices now and then.
            let index = bytes.next().unwrap_or(0) % (n_vertices as u8 + 2);
            indices.push(u32::from(index));
        }
    }
    Decoded {
        positions,
        sizes,
        indices,
    }
}
