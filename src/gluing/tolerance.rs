//! Tolerances of the sampled backend, derived from the machine epsilon of the scalar type and the
//! magnitude of the compared values (never a bare constant).

/// Absolute tolerance for comparing values of magnitude `magnitude` computed with a few
/// floating-point operations: 64·ε·max(1, |magnitude|).
pub(crate) fn tol<S: num_traits::Float>(magnitude: f64) -> f64 {
    let eps = S::epsilon().to_f64().unwrap_or(f64::EPSILON);
    64.0 * eps * magnitude.abs().max(1.0)
}
