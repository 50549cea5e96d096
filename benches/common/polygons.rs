//! Polygons that are hard for a quadratic triangulation, for the `triangulation` benchmark and the
//! complexity tests of `tests/triangulation_complexity.rs` and `tests/mesh_edit.rs`.

#![allow(dead_code)] // each user takes what it needs

/// A comb of `teeth` teeth (`4 · teeth + 2` corners, counter-clockwise in the xy plane): a bar
/// `[0, teeth] × [0, 1]` with teeth of width 0.5 and height 1 standing on it. Every tooth is an
/// ear, but an ear clipper that starts along the bar tests them all again for each ear.
pub fn comb(teeth: u32) -> Vec<[f64; 3]> {
    let mut corners = vec![[0.0, 0.0, 0.0], [f64::from(teeth), 0.0, 0.0]];
    for t in (0..teeth).rev() {
        let x = f64::from(t);
        corners.extend(
            [[x + 1.0, 1.0], [x + 0.5, 1.0], [x + 0.5, 2.0], [x, 2.0]].map(|[x, y]| [x, y, 0.0]),
        );
    }
    corners
}

/// A face of `n` corners that names the 3 vertices of a unit right triangle in turn, as a file
/// can: `(0, 1, 2, 0, 1, 2, …)`. Built with the repair policy, every repeat becomes a copy of
/// its vertex, so the mesh has one face of `n` corners at 3 places, winding round `n / 3` times.
pub fn three_places(n: u32) -> (Vec<[f64; 3]>, Vec<u32>) {
    let positions = vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
    (positions, (0..n).map(|k| k % 3).collect())
}
