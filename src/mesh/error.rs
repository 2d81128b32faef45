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
    Element { kind: &'static str, index: u64 },
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
    #[error("{path}: cannot read: {source}")]
    Io {
        path: PathBuf,
        #[source]
        source: std::io::Error,
    },
    #[error("{path}: unknown mesh format (expected .off, .obj or .ply)")]
    UnknownFormat { path: PathBuf },
    #[error("{path}: {at}: {msg}")]
    Parse {
        path: PathBuf,
        at: Location,
        msg: String,
    },
    #[error("{path}: {at}: not valid UTF-8 in a text format")]
    Encoding { path: PathBuf, at: Location },
    #[error("{path}: {at}: unexpected end of file: {msg}")]
    Truncated {
        path: PathBuf,
        at: Location,
        msg: String,
    },
    #[error(
        "{path}: {at}: {what} count {count} exceeds what the file can hold or the limit {limit}"
    )]
    TooLarge {
        path: PathBuf,
        at: Location,
        what: &'static str,
        count: u64,
        limit: u64,
    },
    #[error("{path}: {at}: polygon with {sides} sides; only triangles are accepted (use --triangulate to fan-split convex polygons)")]
    NotTriangle {
        path: PathBuf,
        at: Location,
        sides: usize,
    },
    #[error("{path}: {at}: polygon with {sides} sides cannot be fan-split: {why}")]
    CannotTriangulate {
        path: PathBuf,
        at: Location,
        sides: usize,
        why: String,
    },
    #[error("{path}: the file has no faces")]
    Empty { path: PathBuf },
    #[error("{path}: cannot write: {source}")]
    Write {
        path: PathBuf,
        #[source]
        source: std::io::Error,
    },
}
