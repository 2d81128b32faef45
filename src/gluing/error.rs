//! Typed errors of the gluing module: every bad input names the file and the field.

use std::path::PathBuf;

#[derive(Debug, thiserror::Error)]
pub enum GluingError {
    #[error("{file}: cannot read: {source}")]
    Io {
        file: PathBuf,
        #[source]
        source: std::io::Error,
    },
    #[error("{file}: not valid TOML: {message}")]
    Syntax { file: PathBuf, message: String },
    #[error("{file}: field `{field}`: {message}")]
    Field {
        file: PathBuf,
        field: String,
        message: String,
    },
}
