//! The mesh writers: one per format (OFF, OBJ, PLY ascii and binary little- and big-endian),
//! used by every output of the crate — a mesh as read ([`write_mesh`], [`write_mesh_to`]) and
//! the sampled surfaces of Sec. 6.2 with per-vertex normals and curvatures
//! (`surface::output::write_mesh_with_attributes`, through [`write_mesh_file`]).
//!
//! Coordinates are written as Rust's shortest round-trip text (`{:?}` on f64, by
//! [`super::decimal`]), so reading a written file back gives bit-identical positions (NaN is
//! written as `NaN` and read back as NaN). Text lines are formatted in parallel batches and
//! written in order ([`write_lines`]): the bytes of a sequential loop.

mod lines;
mod mesh_out;
mod obj;
mod off;
mod ply;

pub use mesh_out::{MeshOut, PlyIndex};

use std::io::Write;
use std::path::Path;

use crate::mesh::error::MeshError;
use crate::mesh::raw::MeshFormat;

/// The PLY comment of [`MeshOut::plain`].
const PLAIN_PLY_COMMENT: &str = "written by pseudomanifold";

/// Writes a triangle mesh to `path` in `format`.
pub fn write_mesh(
    path: &Path,
    positions: &[[f64; 3]],
    faces: &[[u32; 3]],
    format: MeshFormat,
) -> Result<(), MeshError> {
    let err = |source| MeshError::Write {
        path: path.to_path_buf(),
        source,
    };
    let file = std::fs::File::create(path).map_err(err)?;
    let mut w = std::io::BufWriter::new(file);
    write_mesh_to(&mut w, positions, faces, format).map_err(err)?;
    w.flush().map_err(err)?;
    w.into_inner()
        .map_err(|e| err(e.into_error()))?
        .sync_all()
        .map_err(err)
}

/// Writes a triangle mesh to any writer in `format`.
pub fn write_mesh_to<W: Write>(
    w: W,
    positions: &[[f64; 3]],
    faces: &[[u32; 3]],
    format: MeshFormat,
) -> std::io::Result<()> {
    let mut m = MeshOut::plain(positions, faces);
    if !matches!(format, MeshFormat::Obj | MeshFormat::Off) {
        m.comment = Some(PLAIN_PLY_COMMENT);
    }
    write_out(w, &m, format)
}

/// Writes `m` to any writer in `format`: the one writer of each format.
pub fn write_out<W: Write>(mut w: W, m: &MeshOut, format: MeshFormat) -> std::io::Result<()> {
    match format {
        MeshFormat::Obj => obj::write(&mut w, m),
        MeshFormat::Off => off::write(&mut w, m),
        MeshFormat::PlyAscii
        | MeshFormat::PlyBinaryLittleEndian
        | MeshFormat::PlyBinaryBigEndian => ply::write(&mut w, m, format),
    }
}

/// The output format of `path` by its extension (case-insensitive): `.obj`, `.off`, `.ply`
/// (ascii). Any other extension is refused (`InvalidInput`), never guessed.
pub fn output_format(path: &Path) -> std::io::Result<MeshFormat> {
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .unwrap_or("")
        .to_ascii_lowercase();
    match ext.as_str() {
        "obj" => Ok(MeshFormat::Obj),
        "off" => Ok(MeshFormat::Off),
        "ply" => Ok(MeshFormat::PlyAscii),
        _ => Err(std::io::Error::new(
            std::io::ErrorKind::InvalidInput,
            format!(
                "unknown output format {:?} for {}: use .obj, .off or .ply",
                ext,
                path.display()
            ),
        )),
    }
}

/// Writes `m` to `path` in `format`, atomically: the file is written next to `path` under a
/// temporary name and renamed into place, so a failed write never leaves a truncated `path`.
pub fn write_mesh_file(path: &Path, m: &MeshOut, format: MeshFormat) -> std::io::Result<()> {
    let mut tmp_name = path.file_name().unwrap_or_default().to_os_string();
    tmp_name.push(format!(".{}.partial", std::process::id()));
    let tmp = path.with_file_name(tmp_name);
    let written = std::fs::File::create(&tmp)
        .and_then(|file| {
            let mut w = std::io::BufWriter::new(file);
            write_out(&mut w, m, format)?;
            w.into_inner().map_err(|e| e.into_error())?.sync_all()
        })
        .and_then(|()| std::fs::rename(&tmp, path));
    if written.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    written
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A mesh as read is written byte for byte as `writeln!` with `{:?}` writes it (the
    /// former writer of meshes as read), in every text format, for coordinates of every kind.
    #[test]
    fn plain_text_is_the_write_macro_text() {
        let ps = [
            [0.0, -0.0, 1.5],
            [f64::NAN, f64::INFINITY, f64::NEG_INFINITY],
            [1e-300, 5e-324, 1e16],
            // -85113420695635.125: halfway between two shortest decimals (`decimal`).
            [
                f64::from_bits(0xc2d3_5a40_cd32_14c8),
                0.1 + 0.2,
                123456.789e-7,
            ],
        ];
        let fs = [[0, 1, 2], [1, 3, 2]];
        let mut off = String::from("OFF\n4 2 0\n");
        let mut obj = String::new();
        let mut ply = String::from(
            "ply\nformat ascii 1.0\ncomment written by pseudomanifold\nelement vertex 4\nproperty double x\nproperty double y\nproperty double z\nelement face 2\nproperty list uchar uint vertex_indices\nend_header\n",
        );
        for p in ps {
            let line = format!("{:?} {:?} {:?}\n", p[0], p[1], p[2]);
            off += &line;
            obj += &format!("v {line}");
            ply += &line;
        }
        for f in fs {
            let line = format!("3 {} {} {}\n", f[0], f[1], f[2]);
            off += &line;
            obj += &format!("f {} {} {}\n", f[0] + 1, f[1] + 1, f[2] + 1);
            ply += &line;
        }
        for (format, want) in [
            (MeshFormat::Off, off),
            (MeshFormat::Obj, obj),
            (MeshFormat::PlyAscii, ply),
        ] {
            let mut got = Vec::new();
            write_mesh_to(&mut got, &ps, &fs, format).expect("vec");
            assert_eq!(String::from_utf8(got).ok(), Some(want), "{format:?}");
        }
    }
}
