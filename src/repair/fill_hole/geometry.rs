//! Vector arithmetic shared by the hole-filling triangulations and their fold test.

pub(super) fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

pub(super) fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

pub(super) fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

pub(super) fn norm(a: [f64; 3]) -> f64 {
    dot(a, a).sqrt()
}

/// `a` scaled to unit length, zero when it has no (finite) length.
pub(super) fn unit(a: [f64; 3]) -> [f64; 3] {
    let len = norm(a);
    if len > 0.0 && len.is_finite() {
        [a[0] / len, a[1] / len, a[2] / len]
    } else {
        [0.0; 3]
    }
}

/// Unit normal of the triangle `a b c` and its area; a zero normal when it has no area.
pub(super) fn triangle_normal(a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> ([f64; 3], f64) {
    let n = cross(sub(b, a), sub(c, a));
    (unit(n), 0.5 * norm(n))
}

/// Area of the triangle `a b c`.
pub(super) fn triangle_area(a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> f64 {
    0.5 * norm(cross(sub(b, a), sub(c, a)))
}

/// Angle between two unit normals; π (the worst) when either is zero (no area: no direction).
pub(super) fn angle_between(n1: [f64; 3], n2: [f64; 3]) -> f64 {
    if n1 == [0.0; 3] || n2 == [0.0; 3] {
        return std::f64::consts::PI;
    }
    dot(n1, n2).clamp(-1.0, 1.0).acos()
}
