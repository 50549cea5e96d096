//! Axis-aligned bounds of what a buffer draws, so a viewer can frame it.

/// An axis-aligned box; `min > max` (the [`Bounds::EMPTY`] box) when there is nothing inside.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bounds {
    /// Smallest x, y, z.
    pub min: [f32; 3],
    /// Largest x, y, z.
    pub max: [f32; 3],
}

impl Default for Bounds {
    fn default() -> Self {
        Self::EMPTY
    }
}

impl Bounds {
    /// The box that holds nothing.
    pub const EMPTY: Bounds = Bounds {
        min: [f32::INFINITY; 3],
        max: [f32::NEG_INFINITY; 3],
    };

    /// The box of `xyz` (three floats per point); non-finite coordinates are ignored.
    pub fn of_points(xyz: &[f32]) -> Self {
        let mut bounds = Self::EMPTY;
        for point in xyz.chunks_exact(3) {
            if point.iter().all(|c| c.is_finite()) {
                for (axis, &c) in point.iter().enumerate() {
                    bounds.min[axis] = bounds.min[axis].min(c);
                    bounds.max[axis] = bounds.max[axis].max(c);
                }
            }
        }
        bounds
    }

    /// The smallest box holding both.
    pub fn union(self, other: Bounds) -> Bounds {
        Bounds {
            min: [0, 1, 2].map(|k| self.min[k].min(other.min[k])),
            max: [0, 1, 2].map(|k| self.max[k].max(other.max[k])),
        }
    }

    /// `true` when no point was added.
    pub fn is_empty(&self) -> bool {
        (0..3).any(|axis| self.min[axis] > self.max[axis])
    }

    /// Centre of the box (the origin when empty).
    pub fn center(&self) -> [f32; 3] {
        if self.is_empty() {
            return [0.0; 3];
        }
        std::array::from_fn(|axis| 0.5 * (self.min[axis] + self.max[axis]))
    }

    /// Length of the diagonal (0 when empty).
    pub fn diagonal(&self) -> f32 {
        if self.is_empty() {
            return 0.0;
        }
        (0..3)
            .map(|axis| (self.max[axis] - self.min[axis]).powi(2))
            .sum::<f32>()
            .sqrt()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bounds_of_points_skip_non_finite_coordinates() {
        let bounds = Bounds::of_points(&[0.0, 1.0, 2.0, -1.0, 3.0, f32::NAN, 2.0, -2.0, 0.5]);
        assert_eq!(bounds.min, [0.0, -2.0, 0.5]);
        assert_eq!(bounds.max, [2.0, 1.0, 2.0]);
        assert_eq!(bounds.center(), [1.0, -0.5, 1.25]);
    }

    #[test]
    fn empty_bounds_have_no_size() {
        let bounds = Bounds::of_points(&[]);
        assert!(bounds.is_empty());
        assert_eq!(bounds.diagonal(), 0.0);
        assert_eq!(bounds.center(), [0.0; 3]);
    }
}
