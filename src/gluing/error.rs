//! Typed errors of the gluing module: every bad input names the file and the field.

use std::path::PathBuf;

/// Errors reading a gluing file; each names the file, and the field when the TOML parsed.
#[derive(Debug, thiserror::Error)]
pub enum GluingFileError {
    /// The file could not be read.
    #[error("{file}: cannot read: {source}")]
    Io {
        /// The gluing file.
        file: PathBuf,
        /// The underlying I/O error.
        #[source]
        source: std::io::Error,
    },
    /// The file is larger than [`crate::gluing::file::MAX_FILE_BYTES`].
    #[error("{file}: {bytes} bytes, more than the {limit} a gluing file may have")]
    TooLarge {
        /// The gluing file.
        file: PathBuf,
        /// Its size.
        bytes: u64,
        /// The limit.
        limit: u64,
    },
    /// The file is not valid TOML.
    #[error("{file}: not valid TOML: {message}")]
    Syntax {
        /// The gluing file.
        file: PathBuf,
        /// The TOML parser's message (with line and column).
        message: String,
    },
    /// A field is missing, unknown, of the wrong type, or violates a requirement of the format.
    #[error("{file}: field `{field}`: {message}")]
    Field {
        /// The gluing file.
        file: PathBuf,
        /// The offending field, as a path such as `glue[2].a` or `(top level)`.
        field: String,
        /// What is wrong with it.
        message: String,
    },
}
