//! The typed errors of Chapter 5: parametrizations, the fit of Sec. 5.2 and `eval`
//! (Sec. 6.1.4).

use crate::construction::MapError;
use crate::mesh::{FaceId, VertexId};

/// Errors of the parametrizations and of `eval`.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SurfaceError {
    /// The vertex is not a vertex of K (degree < 3 or out of range).
    #[error("vertex {0} is not a vertex of K")]
    NoSuchVertex(VertexId),
    /// The face index is out of range.
    #[error("face {0} is not a face of K")]
    NoSuchFace(FaceId),
    /// [v, u] is not an edge of K, where a label s_v(u) was needed.
    #[error("[{0}, {1}] is not an edge of K")]
    NoSuchEdge(VertexId, VertexId),
    /// θ_v was asked at a point p ∉ Ω_v.
    #[error("p = ({x}, {y}) is not in Ω_{v} (Def. 4.1.1)")]
    NotInOmega {
        /// The chart's vertex.
        v: VertexId,
        /// p's first coordinate (as f64).
        x: f64,
        /// p's second coordinate (as f64).
        y: f64,
    },
    /// The [`Consts`](super::consts::Consts) in use were built without this degree.
    #[error("no constants for degree {0} at this precision (build Consts with it)")]
    MissingDegree(u32),
    /// eval got barycentric coordinates below −1e-12 or whose sum is off 1 by more than 1e-9.
    #[error(
        "barycentric coordinates must be ≥ 0 (−1e−12 tolerated) and sum to 1 (±1e−9), got {0:?}"
    )]
    BadBarycentric([f64; 3]),
    /// The denominator Σ_u Γ_uv(p) of θ_v at p ∈ Ω_v is not decided positive (names v).
    #[error("Σ_u Γ_uv(p) is not decided positive (zero, negative, NaN or an enclosure containing 0) at p in Ω_{0}: θ undefined")]
    ZeroWeight(VertexId),
    /// Sec. 6.2 sampling at a level whose output would not fit the memory budget (no silent
    /// clamp: the estimate is reported).
    #[error("sampling level {level} would produce about {points} points and need about {bytes} bytes (limit {limit} bytes, Sec. 6.2 sampling); choose a lower --level")]
    LevelTooLarge {
        /// The requested subdivision level.
        level: u32,
        /// Estimated number of output vertices.
        points: u128,
        /// Estimated memory of the sampled mesh in bytes.
        bytes: u128,
        /// The budget in bytes.
        limit: u128,
    },
    /// A Chapter 4 map failed (Π at the origin, or undecided).
    #[error("map: {0}")]
    Map(#[from] MapError),
    /// The least-squares fits of Sec. 5.2 would exceed the memory budget (estimated before
    /// building; `surface::admissible`).
    #[error("vertex {v} has degree {degree}: the {profile} profile fits ψ_v with Bézier degree l = {l} (Sec. 5.2), and the fits of this mesh would need about {bytes} bytes (limit {limit}); the authors-code profile caps l at 7 (--profile authors-code)")]
    FitTooLarge {
        /// A vertex of the largest degree.
        v: VertexId,
        /// Its degree m_v.
        degree: u32,
        /// The Bézier bi-degree l of its shape function.
        l: usize,
        /// The profile's name.
        profile: String,
        /// Estimated memory of all the fits, in bytes.
        bytes: u128,
        /// The budget in bytes.
        limit: u128,
    },
    /// A coordinate so large that normals and curvatures (size⁴) overflow f64.
    #[error("vertex {v}: coordinate {value:e} is outside ±2^200 (≈ 1.6e60), where normals and curvatures (which scale like size⁴) overflow f64; rescale the mesh")]
    CoordinateOutOfRange {
        /// The vertex.
        v: VertexId,
        /// The offending coordinate.
        value: f64,
    },
    /// A mesh so small that normals and curvatures (size⁴) underflow f64.
    #[error("the bounding-box diagonal {diagonal:e} is below 2^-200 (≈ 6.2e-61), where normals and curvatures (which scale like size⁴) underflow f64; rescale the mesh")]
    ExtentTooSmall {
        /// The bounding-box diagonal.
        diagonal: f64,
    },
}
