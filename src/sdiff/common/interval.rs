//! What the interval routes of both dimensions share (the planar `interval`, the tetrahedral
//! `tet::interval`): their verdict, and the enclosure of an exact rational.

use super::rational::{to_f64, Q};
use crate::numeric::interval::{down, up, Interval as I};

/// Outcome of the interval route.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[serde(rename_all = "snake_case", tag = "kind")]
pub enum IntervalVerdict {
    /// det DX > 0 on every box covering the triangle.
    Certified {
        /// Boxes in the cover.
        boxes: usize,
        /// Smallest lower bound of det over the cover.
        lower_bound: f64,
    },
    /// Some box could not be decided within the budget.
    Unknown {
        /// Boxes examined.
        boxes: usize,
    },
}

/// An interval enclosing the rational `x` (one ulp either side of the nearest f64).
pub fn enclose(x: &Q) -> I {
    let f = to_f64(x);
    if f.is_finite() && Q::from_float(f).as_ref() == Some(x) {
        return I::try_from((f, f)).unwrap_or(I::ENTIRE);
    }
    I::try_from((down(f), up(f))).unwrap_or(I::ENTIRE)
}
