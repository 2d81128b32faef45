//! Per-pixel shading: the normal interpolated from the triangle's corners (then normalised)
//! lights the base colour with a Lambert term for a light above and to the left of the viewer;
//! a face turned away from the light (or a normal of the wrong sign) is dark.

use crate::numeric::vec3::{dot, norm};

/// Fraction of light that reaches every point.
pub(crate) const AMBIENT: f64 = 0.25;

/// The light direction in camera terms: mostly from the viewer, a little from above-left.
pub(crate) fn light_direction(right: [f64; 3], up: [f64; 3], towards: [f64; 3]) -> [f64; 3] {
    let l: [f64; 3] = std::array::from_fn(|d| towards[d] + 0.45 * up[d] - 0.3 * right[d]);
    let n = norm(l);
    l.map(|x| x / n)
}

/// Brightness factor in [AMBIENT, 1] of the interpolated normal `n` (any length) under the
/// light `l`; a zero or non-finite normal (singular point) gets the ambient term alone.
pub(crate) fn brightness(n: [f64; 3], l: [f64; 3]) -> f64 {
    // A zero, infinite or NaN normal makes the cosine non-finite (0/0, ∞/∞, NaN).
    let cos = dot(n, l) / norm(n);
    if !cos.is_finite() {
        return AMBIENT;
    }
    AMBIENT + (1.0 - AMBIENT) * cos.max(0.0)
}

/// `base` lit by `brightness`.
pub(crate) fn lit(base: [f64; 3], brightness: f64) -> [f64; 3] {
    base.map(|c| c * brightness)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Lambert's term for a normal facing the light, none for one facing away, and the ambient
    /// term alone for a singular normal (zero, infinite or NaN: a chart centre's undefined
    /// normal is drawn, not hidden).
    #[test]
    fn render_brightness_lambert_and_singular_normals() {
        let l = [0.0, 0.0, 1.0];
        assert_eq!(brightness([0.0, 0.0, 2.0], l), 1.0);
        assert_eq!(brightness([0.0, 0.0, -1.0], l), AMBIENT);
        let half = brightness([0.0, 1.0, 1.0], l);
        assert!((half - (AMBIENT + (1.0 - AMBIENT) * 0.5f64.sqrt())).abs() < 1e-15);
        for n in [
            [0.0; 3],
            [f64::NAN, 0.0, 1.0],
            [f64::INFINITY, 0.0, 1.0],
            [1e-200, 0.0, 0.0],
        ] {
            assert_eq!(brightness(n, l), AMBIENT, "{n:?}");
        }
    }
}
