//! Mesh readers and writers: OFF, OBJ and PLY (ascii, binary little- and big-endian).
//! Sec. 3.1: triangle meshes in, simplicial surfaces out; the one writer per format
//! ([`write_out`]) writes both meshes as read and the sampled surfaces of Sec. 6.2.
//!
//! The readers produce a [`RawMesh`] exactly as stored: no welding, no reordering, no removal
//! of anything. Out-of-range vertex indices are *not* a reader error (the validator lists all
//! of them); malformed syntax is, and every error names the file and the line (text) or the
//! element (binary PLY).
//!
//! # Why hand-written parsers
//!
//! The parsers are small hand-written loops (line-based for the text formats, a byte cursor
//! for binary PLY) rather than crates: `ply-rs` is unmaintained, and neither it nor `tobj`
//! reports errors with a line or element location, and neither bounds its allocations by what
//! the input can actually hold (a header announcing 10^12 vertices must fail fast, not
//! allocate). Each reader reads the file once into memory and makes one linear pass over it;
//! every `Vec::with_capacity` is capped by the number of elements the remaining bytes could
//! possibly encode and by [`Limits`]. All arithmetic on input-derived values is checked.

mod context;
pub(crate) mod decimal;
mod limits;
mod obj;
mod off;
mod ply;
mod polygon;
pub(crate) mod text;
mod write;

use std::path::{Path, PathBuf};

pub use context::ReadOptions;
pub(crate) use context::{parse_coord, Ctx};
pub use limits::Limits;
pub use write::{
    output_format, write_mesh, write_mesh_file, write_mesh_to, write_out, MeshOut, PlyIndex,
};

use super::error::MeshError;
use super::raw::{MeshFormat, RawMesh};

/// Reads a mesh file. The format is detected from the content (a `ply` magic line or an OFF
/// header keyword) and otherwise from the extension (`.off`, `.obj`, `.ply`, case-insensitive).
pub fn read_mesh(path: &Path, opts: &ReadOptions) -> Result<RawMesh, MeshError> {
    let bytes = std::fs::read(path).map_err(|source| MeshError::Io {
        path: path.to_path_buf(),
        source,
    })?;
    let format = detect_format(&bytes, path).ok_or_else(|| MeshError::UnknownFormat {
        path: path.to_path_buf(),
    })?;
    let mut mesh = read_bytes(&bytes, format, path, opts)?;
    mesh.source = Some(path.to_path_buf());
    Ok(mesh)
}

/// Reads a mesh from memory; `name` is used in error messages and as [`RawMesh::source`].
/// Any of the three PLY variants of `format` selects the PLY reader, which takes the actual
/// encoding from the header.
pub fn read_mesh_from_bytes(
    bytes: &[u8],
    format: MeshFormat,
    name: &str,
    opts: &ReadOptions,
) -> Result<RawMesh, MeshError> {
    let path = PathBuf::from(name);
    let mut mesh = read_bytes(bytes, format, &path, opts)?;
    mesh.source = Some(path);
    Ok(mesh)
}

/// The format of a file: by magic first (`ply` line, OFF header keyword), then by extension.
/// For PLY the returned variant is [`MeshFormat::PlyAscii`] when only the extension is known.
pub fn detect_format(bytes: &[u8], path: &Path) -> Option<MeshFormat> {
    if let Some(f) = ply::sniff(bytes) {
        return Some(f);
    }
    if off::sniff(bytes) {
        return Some(MeshFormat::Off);
    }
    let ext = path.extension()?.to_str()?.to_ascii_lowercase();
    match ext.as_str() {
        "off" => Some(MeshFormat::Off),
        "obj" => Some(MeshFormat::Obj),
        "ply" => Some(MeshFormat::PlyAscii),
        _ => None,
    }
}

fn read_bytes(
    bytes: &[u8],
    format: MeshFormat,
    path: &Path,
    opts: &ReadOptions,
) -> Result<RawMesh, MeshError> {
    let ctx = Ctx { path, opts };
    let mesh = match format {
        MeshFormat::Off => off::read(bytes, &ctx)?,
        MeshFormat::Obj => obj::read(bytes, &ctx)?,
        MeshFormat::PlyAscii
        | MeshFormat::PlyBinaryLittleEndian
        | MeshFormat::PlyBinaryBigEndian => ply::read(bytes, &ctx)?,
    };
    if mesh.faces.is_empty() {
        return Err(MeshError::Empty {
            path: path.to_path_buf(),
        });
    }
    Ok(mesh)
}
