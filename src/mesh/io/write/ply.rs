//! The PLY writer, ascii and binary (little- and big-endian): `x y z`, then `nx ny nz` when
//! there is a normal per vertex, then, with the mean and Gaussian curvature too, the colour
//! of the mean curvature (`red green blue`, clipped at its 98th percentile, named in a header
//! comment) and both curvatures.

use super::super::decimal::{push_f64, push_f64x3, push_uint};
use super::lines::{face_line, write_lines};
use super::mesh_out::{MeshOut, PlyIndex};
use crate::mesh::raw::MeshFormat;
use std::io::Write;

/// Diverging colour map for a curvature value, clipped at ±`range`: blue (negative), white,
/// red (positive).
fn curvature_colour(x: f64, range: f64) -> [u8; 3] {
    if !x.is_finite() || range <= 0.0 {
        return [128, 128, 128];
    }
    let t = (x / range).clamp(-1.0, 1.0);
    let a = (255.0 * (1.0 - t.abs())) as u8;
    if t >= 0.0 {
        [255, a, a]
    } else {
        [a, a, 255]
    }
}

/// 98th percentile of |x| (the colour range).
fn robust_range(xs: &[f64]) -> f64 {
    let mut v: Vec<f64> = xs
        .iter()
        .filter(|x| x.is_finite())
        .map(|x| x.abs())
        .collect();
    if v.is_empty() {
        return 1.0;
    }
    v.sort_by(|a, b| a.total_cmp(b));
    v[((v.len() - 1) as f64 * 0.98) as usize].max(f64::MIN_POSITIVE)
}

pub(super) fn write(w: &mut impl Write, m: &MeshOut, format: MeshFormat) -> std::io::Result<()> {
    let (ps, ns, fs) = (m.positions, m.normals, m.faces);
    let normals = ns.len() == ps.len() && !ps.is_empty();
    let curvature = normals && m.mean.len() == ps.len() && m.gaussian.len() == ps.len();
    let range = robust_range(m.mean);
    let enc = match format {
        MeshFormat::PlyBinaryLittleEndian => "binary_little_endian",
        MeshFormat::PlyBinaryBigEndian => "binary_big_endian",
        _ => "ascii",
    };
    writeln!(w, "ply\nformat {enc} 1.0")?;
    if let Some(c) = m.comment {
        writeln!(w, "comment {c}")?;
    }
    if curvature {
        writeln!(
            w,
            "comment ppm sample: colours = mean curvature clipped at ±{range:e}"
        )?;
    }
    writeln!(w, "element vertex {}", ps.len())?;
    let mut props = vec!["x", "y", "z"];
    if normals {
        props.extend(["nx", "ny", "nz"]);
    }
    for p in props {
        writeln!(w, "property double {p}")?;
    }
    if curvature {
        for p in ["red", "green", "blue"] {
            writeln!(w, "property uchar {p}")?;
        }
        writeln!(
            w,
            "property double gaussian_curvature\nproperty double mean_curvature"
        )?;
    }
    writeln!(w, "element face {}", fs.len())?;
    let index = match m.ply_index {
        PlyIndex::UInt => "uint",
        PlyIndex::Int => "int",
    };
    writeln!(w, "property list uchar {index} vertex_indices\nend_header")?;
    let colour = |i: usize| curvature_colour(m.mean[i], range);
    if format == MeshFormat::PlyAscii {
        write_lines(w, ps.len(), |i, b| {
            push_f64x3(b, ps[i]);
            if normals {
                b.push(b' ');
                push_f64x3(b, ns[i]);
            }
            if curvature {
                for c in colour(i) {
                    b.push(b' ');
                    push_uint(b, c.into());
                }
                b.push(b' ');
                push_f64(b, m.gaussian[i]);
                b.push(b' ');
                push_f64(b, m.mean[i]);
            }
            b.push(b'\n');
            Ok(())
        })?;
        return write_lines(w, fs.len(), |i, b| face_line(b, fs[i]));
    }
    let be = format == MeshFormat::PlyBinaryBigEndian;
    let double = |x: f64| if be { x.to_be_bytes() } else { x.to_le_bytes() };
    for i in 0..ps.len() {
        for x in ps[i] {
            w.write_all(&double(x))?;
        }
        if normals {
            for x in ns[i] {
                w.write_all(&double(x))?;
            }
        }
        if curvature {
            w.write_all(&colour(i))?;
            w.write_all(&double(m.gaussian[i]))?;
            w.write_all(&double(m.mean[i]))?;
        }
    }
    for f in fs {
        w.write_all(&[3])?;
        for i in f {
            w.write_all(&if be { i.to_be_bytes() } else { i.to_le_bytes() })?;
        }
    }
    Ok(())
}
