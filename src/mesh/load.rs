//! Read a mesh file and validate it as a simplicial surface (Def. 3.1.6): the one loader of
//! every command that needs a surface.

use super::io::{read_mesh, ReadOptions};
use super::validate::{validate, ErrorClass};
use super::{MeshError, SimplicialSurface};
use std::path::{Path, PathBuf};
use thiserror::Error;

/// Why a mesh file did not give a simplicial surface.
#[derive(Debug, Error)]
pub enum LoadError {
    /// The file could not be read or parsed (the error names file, line or element).
    #[error("{0}")]
    Read(#[from] MeshError),
    /// The mesh was read but fails a check of Sec. 3.1 (`ppm check` lists the witnesses).
    #[error("{} is not a simplicial surface (run `ppm check` for details)", path.display())]
    NotASurface {
        /// The file.
        path: PathBuf,
        /// The defect classes found.
        classes: Vec<ErrorClass>,
    },
}

/// Read `path` (OFF, OBJ or PLY) and validate it (Sec. 3.1).
pub fn load_surface(path: &Path) -> Result<SimplicialSurface, LoadError> {
    let raw = read_mesh(path, &ReadOptions::default())?;
    let v = validate(&raw);
    v.surface.ok_or_else(|| LoadError::NotASurface {
        path: path.to_path_buf(),
        classes: v.report.error_classes,
    })
}
