//! How far a new triangle turns: the costs both triangulations minimise (the exact one over all
//! triangulations, the projected one by flips), so that they agree on what a good fill is.
//!
//! A fill should span the hole like the plane across its mean (Newell) normal, bent only as much
//! as the surface around it: a triangle pays for its tilt from the mean normal, for the angle to
//! each new triangle beside it, and, towards a face across the hole's rim, only for the angle
//! beyond the one the mean plane itself makes with that face. Paying the whole angle to the rim
//! instead would let the steepest rim (a hole whose walls stand at right angles to it, say) set
//! the largest cost alone, leaving every triangle free to tilt up to it.

use super::folds::FOLD_ANGLE_DEGREES;
use super::geometry::angle_between;

/// Added to the turn of a triangle that folds against a face beside it (turned more than
/// [`FOLD_ANGLE_DEGREES`]): any triangulation without a fold costs less than one with.
const FOLD_PENALTY: f64 = 4.0 * std::f64::consts::PI;

/// `angle` (radians) between two faces side by side, plus [`FOLD_PENALTY`] when they fold.
fn penalised(angle: f64) -> f64 {
    if angle > FOLD_ANGLE_DEGREES.to_radians() {
        angle + FOLD_PENALTY
    } else {
        angle
    }
}

/// The mean normal of a hole and the costs measured against it.
#[derive(Clone, Copy, Debug)]
pub(super) struct Turns {
    mean: [f64; 3],
}

impl Turns {
    /// Costs against the unit `mean` normal (zero when the hole has none: tilts then cost
    /// nothing and rim angles count whole).
    pub(super) fn new(mean: [f64; 3]) -> Self {
        Turns { mean }
    }

    /// The tilt (radians) of the unit normal `normal` from the mean normal.
    pub(super) fn tilt(&self, normal: [f64; 3]) -> f64 {
        if self.mean == [0.0; 3] {
            0.0
        } else {
            angle_between(normal, self.mean)
        }
    }

    /// The cost of a new triangle with unit normal `normal` beside the rim face with unit normal
    /// `rim` (zero when there is none: no cost): the angle between them beyond the mean plane's
    /// angle to that face, or the whole angle and a penalty when they fold.
    pub(super) fn rim(&self, normal: [f64; 3], rim: [f64; 3]) -> f64 {
        if rim == [0.0; 3] {
            return 0.0;
        }
        let angle = angle_between(normal, rim);
        if penalised(angle) > angle {
            return penalised(angle);
        }
        let base = if self.mean == [0.0; 3] {
            0.0
        } else {
            angle_between(self.mean, rim)
        };
        (angle - base).max(0.0)
    }

    /// The cost of two new triangles side by side, with unit normals `first` and `second`: the
    /// angle between them, and a penalty when they fold.
    pub(super) fn between(&self, first: [f64; 3], second: [f64; 3]) -> f64 {
        penalised(angle_between(first, second))
    }
}
