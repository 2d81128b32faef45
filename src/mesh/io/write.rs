//! Writers for OFF, OBJ and PLY (ascii and binary little-endian). Coordinates are written
//! with Rust's shortest round-trip representation (`{:?}` on f64), so reading a written file
//! back gives bit-identical positions (NaN is written as `NaN` and read back as NaN).

use std::io::Write;
use std::path::Path;

use crate::mesh::error::MeshError;
use crate::mesh::raw::MeshFormat;

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
    mut w: W,
    positions: &[[f64; 3]],
    faces: &[[u32; 3]],
    format: MeshFormat,
) -> std::io::Result<()> {
    match format {
        MeshFormat::Off => {
            writeln!(w, "OFF")?;
            writeln!(w, "{} {} 0", positions.len(), faces.len())?;
            for p in positions {
                writeln!(w, "{:?} {:?} {:?}", p[0], p[1], p[2])?;
            }
            for f in faces {
                writeln!(w, "3 {} {} {}", f[0], f[1], f[2])?;
            }
        }
        MeshFormat::Obj => {
            for p in positions {
                writeln!(w, "v {:?} {:?} {:?}", p[0], p[1], p[2])?;
            }
            for f in faces {
                let [a, b, c] = f.map(|i| u64::from(i) + 1);
                writeln!(w, "f {a} {b} {c}")?;
            }
        }
        MeshFormat::PlyAscii
        | MeshFormat::PlyBinaryLittleEndian
        | MeshFormat::PlyBinaryBigEndian => {
            let enc = match format {
                MeshFormat::PlyBinaryLittleEndian => "binary_little_endian",
                MeshFormat::PlyBinaryBigEndian => "binary_big_endian",
                _ => "ascii",
            };
            writeln!(w, "ply")?;
            writeln!(w, "format {enc} 1.0")?;
            writeln!(w, "comment written by pseudomanifold")?;
            writeln!(w, "element vertex {}", positions.len())?;
            for c in ["x", "y", "z"] {
                writeln!(w, "property double {c}")?;
            }
            writeln!(w, "element face {}", faces.len())?;
            writeln!(w, "property list uchar uint vertex_indices")?;
            writeln!(w, "end_header")?;
            match format {
                MeshFormat::PlyAscii => {
                    for p in positions {
                        writeln!(w, "{:?} {:?} {:?}", p[0], p[1], p[2])?;
                    }
                    for f in faces {
                        writeln!(w, "3 {} {} {}", f[0], f[1], f[2])?;
                    }
                }
                _ => {
                    let be = format == MeshFormat::PlyBinaryBigEndian;
                    for p in positions {
                        for c in p {
                            w.write_all(&if be { c.to_be_bytes() } else { c.to_le_bytes() })?;
                        }
                    }
                    for f in faces {
                        w.write_all(&[3])?;
                        for i in f {
                            w.write_all(&if be { i.to_be_bytes() } else { i.to_le_bytes() })?;
                        }
                    }
                }
            }
        }
    }
    Ok(())
}
