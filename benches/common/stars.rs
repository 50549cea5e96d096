//! Face lists around a vertex or an edge that many faces share, for the `high_degree` benchmark
//! and the tests of `tests/build_high_degree.rs`.

/// How `k` triangles share their vertex or edge.
#[derive(Clone, Copy, Debug)]
pub enum Star {
    /// Faces `(0, 1, i + 2)`: every face on edge 0–1, walked the same way.
    AtEdge,
    /// Faces `(0, 2i + 1, 2i + 2)`: faces sharing vertex 0 and nothing else.
    AtVertex,
    /// Faces `(0, i + 1, i + 2)`: an open disc of faces around vertex 0.
    ManifoldFan,
}

/// The `k` triangles of `star`, with positions no three of which are on a line, vertex `v`
/// renumbered `n - 1 - v` when `hub_last` (the shared vertices then come last instead of
/// first); and the renumbering.
pub fn star(star: Star, k: u32, hub_last: bool) -> (Vec<[f64; 3]>, Vec<u32>, impl Fn(u32) -> u32) {
    let (n_vertices, faces): (u32, Vec<[u32; 3]>) = match star {
        Star::AtEdge => (k + 2, (0..k).map(|i| [0, 1, i + 2]).collect()),
        Star::AtVertex => (
            2 * k + 1,
            (0..k).map(|i| [0, 2 * i + 1, 2 * i + 2]).collect(),
        ),
        Star::ManifoldFan => (k + 2, (0..k).map(|i| [0, i + 1, i + 2]).collect()),
    };
    let renumber = move |v: u32| if hub_last { n_vertices - 1 - v } else { v };
    let mut positions = vec![[0.0; 3]; n_vertices as usize];
    for v in 0..n_vertices {
        // A spiral rising around the hub, which sits below it.
        let t = f64::from(v);
        let radius = 1.0 + t * 1e-3;
        positions[renumber(v) as usize] = [radius * t.cos(), radius * t.sin(), t * 1e-4];
    }
    positions[renumber(0) as usize] = [0.0, 0.0, -1.0];
    let indices = faces.iter().flatten().map(|&v| renumber(v)).collect();
    (positions, indices, renumber)
}
