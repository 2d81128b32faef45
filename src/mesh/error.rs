//! Typed errors for reading meshes. Every error names the file and the place in it.

use std::path::PathBuf;
use thiserror::Error;

/// Where in a file an error was found.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Location {
    /// 1-based line number in a text file (or a text header).
    Line(u64),
    /// Byte offset in a binary file.
    Byte(u64),
    /// An element by kind and 0-based index (e.g. vertex 12 of a binary PLY).
    Element {
        /// Element kind as the format names it, e.g. `"vertex"` or `"face"`.
        kind: &'static str,
        /// 0-based index among the elements of that kind.
        index: u64,
    },
    /// The file as a whole (empty file, unknown format).
    File,
}

impl std::fmt::Display for Location {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Location::Line(l) => write!(f, "line {l}"),
            Location::Byte(b) => write!(f, "byte {b}"),
            Location::Element { kind, index } => write!(f, "{kind} {index}"),
            Location::File => write!(f, "file"),
        }
    }
}

/// Errors from the mesh readers and writers.
#[derive(Debug, Error)]
pub enum MeshError {
    /// The file could not be read (open or read failed).
    #[error("{path}: cannot read: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// The underlying I/O error.
        #[source]
        source: std::io::Error,
    },
    /// Neither the content (`ply` magic, OFF header keyword) nor the extension identifies the format.
    #[error("{path}: unknown mesh format (expected .off, .obj or .ply)")]
    UnknownFormat {
        /// The file.
        path: PathBuf,
    },
    /// Malformed content: a bad token, a wrong count, data after the declared elements.
    #[error("{path}: {at}: {msg}")]
    Parse {
        /// The file.
        path: PathBuf,
        /// Where the malformed content is.
        at: Location,
        /// What was expected and what was found.
        msg: String,
    },
    /// A text format (OFF, OBJ, ASCII PLY) contains bytes that are not UTF-8.
    #[error("{path}: {at}: not valid UTF-8 in a text format")]
    Encoding {
        /// The file.
        path: PathBuf,
        /// The line with the invalid bytes.
        at: Location,
    },
    /// The file ends before all declared vertices, faces or header lines were read.
    #[error("{path}: {at}: unexpected end of file: {msg}")]
    Truncated {
        /// The file.
        path: PathBuf,
        /// Where the data stopped.
        at: Location,
        /// What was still missing.
        msg: String,
    },
    /// A declared or running element count exceeds its [`Limits`](crate::mesh::io::Limits) bound;
    /// raised before anything is allocated.
    #[error(
        "{path}: {at}: {what} count {count} exceeds what the file can hold or the limit {limit}"
    )]
    TooLarge {
        /// The file.
        path: PathBuf,
        /// The header line or element declaring the count.
        at: Location,
        /// What was counted: `"vertex"`, `"face"` or `"element"` (other PLY elements).
        what: &'static str,
        /// The declared (or, for OBJ, running) count.
        count: u64,
        /// The configured bound it exceeds.
        limit: u64,
    },
    /// A polygon with more than 3 sides was read without `--triangulate`.
    #[error("{path}: {at}: polygon with {sides} sides; only triangles are accepted (use --triangulate to fan-split convex polygons)")]
    NotTriangle {
        /// The file.
        path: PathBuf,
        /// The polygon's line or face element.
        at: Location,
        /// Number of sides of the polygon.
        sides: usize,
    },
    /// With `--triangulate`, a polygon cannot be fan-split: a repeated or out-of-range index, a
    /// non-finite corner, or a non-planar or non-convex polygon.
    #[error("{path}: {at}: polygon with {sides} sides cannot be fan-split: {why}")]
    CannotTriangulate {
        /// The file.
        path: PathBuf,
        /// The polygon's line or face element.
        at: Location,
        /// Number of sides of the polygon.
        sides: usize,
        /// Why the fan split was refused.
        why: String,
    },
    /// A face lists fewer than 3 vertices.
    #[error("{path}: {at}: face with {sides} vertices; a face needs at least 3")]
    TooFewSides {
        /// The file.
        path: PathBuf,
        /// The face's line or element.
        at: Location,
        /// Number of vertices the face lists.
        sides: usize,
    },
    /// The file was read completely but contains no faces.
    #[error("{path}: the file has no faces")]
    Empty {
        /// The file.
        path: PathBuf,
    },
    /// Creating or writing an output mesh failed.
    #[error("{path}: cannot write: {source}")]
    Write {
        /// The output file.
        path: PathBuf,
        /// The underlying I/O error.
        #[source]
        source: std::io::Error,
    },
}
