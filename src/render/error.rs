//! Errors of `ppm render`, each naming what was wrong.

use crate::surface::SurfaceError;

/// A render failure.
#[derive(Debug, thiserror::Error)]
pub enum RenderError {
    /// `--size` not of the form WxH with 16 ≤ W, H ≤ 8192.
    #[error("image size {0:?}: expected WxH with 16 ≤ W, H ≤ 8192")]
    BadSize(String),
    /// `--view` not two finite angles in degrees.
    #[error("view {0:?}: expected azimuth,elevation in degrees (finite numbers)")]
    BadView(String),
    /// `--range a,b` not finite with a ≤ 0 ≤ b, a < b.
    #[error("range {0:?}: expected a,b finite with a ≤ 0 ≤ b and a < b (the colour map is centred at 0)")]
    BadRange(String),
    /// The scene has no triangle, or no vertex with a finite position.
    #[error("nothing to draw: {0}")]
    Empty(String),
    /// A triangle names a vertex that does not exist.
    #[error("triangle {face} names vertex {index}, but there are {count} vertices")]
    IndexOutOfRange {
        /// The triangle.
        face: usize,
        /// The offending index.
        index: u32,
        /// Number of vertices.
        count: usize,
    },
    /// Per-vertex arrays of different lengths.
    #[error("{what} has {got} entries for {expected} vertices")]
    LengthMismatch {
        /// Which array.
        what: &'static str,
        /// Its length.
        got: usize,
        /// Number of vertices.
        expected: usize,
    },
    /// Colouring by curvature was asked for a source that carries none.
    #[error("--colour {0}: this source carries no curvature (use --colour none)")]
    NoCurvature(&'static str),
    /// Evaluating the surface failed.
    #[error("surface: {0}")]
    Surface(#[from] SurfaceError),
    /// The input is not a simplicial surface.
    #[error("{0}")]
    Mesh(String),
    /// PNG encoding failed.
    #[error("PNG encoding: {0}")]
    Png(String),
    /// Reading or writing a file failed.
    #[error("{path}: {source}")]
    Io {
        /// The file.
        path: String,
        /// The cause.
        source: std::io::Error,
    },
}
