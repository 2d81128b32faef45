//! Why the Loop surface of K cannot be built or evaluated, and the highest valence it takes.

use super::topology::MissingTriangle;

/// Highest valence evaluated; a higher one is [`LoopError::ValenceTooHigh`] (the eigen-
/// structure is closed-form for any N, but the per-point cost grows as N²).
pub const MAX_VALENCE: u32 = 512;

/// Why the Loop surface of K cannot be built or evaluated.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum LoopError {
    /// A vertex has a valence above [`MAX_VALENCE`].
    #[error(
        "vertex {vertex} has valence {valence} > {max} (Loop S′ evaluates valences 3..={max})"
    )]
    ValenceTooHigh {
        /// The vertex.
        vertex: u32,
        /// Its valence.
        valence: u32,
        /// [`MAX_VALENCE`].
        max: u32,
    },
    /// A patch net could not be gathered around a face (K is not a closed simplicial surface).
    #[error("face {face}: {source}")]
    Net {
        /// The face.
        face: u32,
        /// What was missing.
        source: MissingTriangle,
    },
    /// The corners given are not the corners of the face.
    #[error("face {face}: {corners:?} are not its corners")]
    WrongCorners {
        /// The face.
        face: u32,
        /// The corners given.
        corners: [u32; 3],
    },
    /// A vertex or edge point of one Loop step could not be gathered (K is not a closed
    /// simplicial surface).
    #[error("Loop point table: {0}")]
    PointTable(MissingTriangle),
    /// The point table of one Loop step would have more than 2³² entries.
    #[error("K is too large for the Loop point table ({points} entries > 2^32)")]
    TooLarge {
        /// Entries needed.
        points: usize,
    },
    /// No such face.
    #[error("no face {0}")]
    NoSuchFace(u32),
    /// Barycentric coordinates not ≥ −1e−12 or not summing to 1 within 1e−9.
    #[error("barycentric coordinates {0:?} are not a point of the triangle (each ≥ −1e-12, sum 1 ± 1e-9)")]
    BadBarycentric([f64; 3]),
    /// The eigen-structure of a valence could not be derived (a defect, reported).
    #[error("no eigen-structure for valence {0}")]
    Eigen(usize),
}
