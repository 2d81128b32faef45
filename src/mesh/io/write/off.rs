//! The OFF writer: `OFF` (or `NOFF` with normals), the counts, one line per vertex (the
//! normal after the position) and `3 a b c` per triangle.

use super::super::decimal::push_f64x3;
use super::lines::{face_line, write_lines};
use super::mesh_out::MeshOut;
use std::io::Write;

pub(super) fn write(w: &mut impl Write, m: &MeshOut) -> std::io::Result<()> {
    let (ps, ns, fs) = (m.positions, m.normals, m.faces);
    writeln!(w, "{}", if ns.is_empty() { "OFF" } else { "NOFF" })?;
    writeln!(w, "{} {} 0", ps.len(), fs.len())?;
    write_lines(w, ps.len(), |i, b| {
        push_f64x3(b, ps[i]);
        if let Some(n) = ns.get(i) {
            b.push(b' ');
            push_f64x3(b, *n);
        }
        b.push(b'\n');
        Ok(())
    })?;
    write_lines(w, fs.len(), |i, b| face_line(b, fs[i]))
}
