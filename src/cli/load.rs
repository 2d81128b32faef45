//! Mesh loading for every command that needs a simplicial surface, written once: the error is
//! printed; a file that cannot be read is exit status 2, a mesh that is not a simplicial
//! surface (Def. 3.1.6) exit status 1.

use crate::mesh::{load_surface, LoadError, SimplicialSurface};
use std::path::Path;
use std::process::ExitCode;

/// The validated surface of `file`, or the exit status after printing why not.
pub(super) fn surface(file: &Path) -> Result<SimplicialSurface, ExitCode> {
    load_surface(file).map_err(|e| {
        eprintln!("error: {e}");
        match e {
            LoadError::Read(_) => ExitCode::from(2),
            LoadError::NotASurface { .. } => ExitCode::from(1),
        }
    })
}
