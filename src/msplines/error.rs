//! Typed errors of the manifold-spline pipeline (Gu–He–Qin, Sec. 5): every refusal says which
//! statement of the paper makes the input unusable.

use thiserror::Error;

/// Why the pipeline of Sec. 5 cannot run on a (validated) surface.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum MsError {
    /// Genus 0: no non-zero holomorphic 1-form exists (Sec. 3.4.2) and no affine atlas
    /// (Thm. 2, Benzécri: a closed affine surface has χ = 0).
    #[error(
        "{file}: genus 0 (χ = 2): a closed genus-0 surface carries no non-zero holomorphic \
         1-form (Sec. 3.4.2) and, by Thm. 2 (Benzécri), no affine atlas; Sec. 5 needs genus ≥ 1 \
         (SPEC MS-T2)"
    )]
    GenusZero {
        /// The mesh file (or `"<generated>"`).
        file: String,
    },
    /// The requested basis form ω_k does not exist (the basis has 2g forms, Sec. 5.1 step 2).
    #[error("{file}: form {form} requested, but the basis has {count} forms ω_0..ω_{last} (2g, Sec. 5.1 step 2)", last = count.saturating_sub(1))]
    FormOutOfRange {
        /// The mesh file.
        file: String,
        /// The requested index k.
        form: usize,
        /// How many basis forms there are.
        count: usize,
    },
    /// More than one connected component.
    #[error("{file}: {components} connected components; Sec. 5 works on one closed surface")]
    Disconnected {
        /// The mesh file.
        file: String,
        /// Number of components found.
        components: usize,
    },
    /// A cotangent weight is not finite (an angle of 0 or π in the stored f64 geometry).
    #[error("{file}: face {face}: cotangent weight not finite (degenerate angle)")]
    NonFiniteWeight {
        /// The mesh file.
        file: String,
        /// The offending face.
        face: u32,
    },
    /// The sparse Cholesky factorisation of the pinned cotangent Laplacian failed.
    #[error("{file}: sparse Cholesky of the cotangent Laplacian failed: {reason}")]
    Factorisation {
        /// The mesh file.
        file: String,
        /// faer's reason.
        reason: String,
    },
    /// A k-ring radius outside the supported range.
    #[error("chart radius k = {k} not supported (Sec. 5.4 step 3 uses k-rings; 1 ≤ k ≤ 4)")]
    RingRadius {
        /// The requested k.
        k: u32,
    },
}
