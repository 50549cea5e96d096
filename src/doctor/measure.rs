//! Distances and boxes, shared by the findings.

/// The distance between `a` and `b`, scaled so that it neither overflows nor underflows when
/// the coordinates are huge or tiny.
pub(crate) fn distance(a: [f64; 3], b: [f64; 3]) -> f64 {
    let d = [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
    let squared = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    // Squares of ordinary sizes are exact enough as they are; only those that under- or
    // overflow need the scaled sum.
    if (1e-280..1e280).contains(&squared) {
        return squared.sqrt();
    }
    let scale = d.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    if scale == 0.0 || !scale.is_finite() {
        return scale;
    }
    let s = d.map(|x| x / scale);
    scale * (s[0] * s[0] + s[1] * s[1] + s[2] * s[2]).sqrt()
}

/// A box containing nothing yet: [`grow`] it.
pub(crate) const EMPTY_BOX: [[f64; 3]; 2] = [[f64::INFINITY; 3], [f64::NEG_INFINITY; 3]];

/// Grows `bounds` (lowest corner, highest corner) to contain `p`.
pub(crate) fn grow(bounds: &mut [[f64; 3]; 2], p: [f64; 3]) {
    for (k, &x) in p.iter().enumerate() {
        bounds[0][k] = bounds[0][k].min(x);
        bounds[1][k] = bounds[1][k].max(x);
    }
}

/// The box around the finite ones of `points` ([`EMPTY_BOX`] when there are none).
pub(crate) fn bounding_box(points: impl Iterator<Item = [f64; 3]>) -> [[f64; 3]; 2] {
    let mut bounds = EMPTY_BOX;
    for p in points.filter(|p| p.iter().all(|x| x.is_finite())) {
        grow(&mut bounds, p);
    }
    bounds
}
