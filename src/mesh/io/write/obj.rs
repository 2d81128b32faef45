//! The OBJ writer: an optional `# comment` line, `v x y z`, `vn x y z` when there are normals,
//! and `f a b c` (1-based; `f a//a b//b c//c` with normals).

use super::super::decimal::{push_f64x3, push_uint};
use super::lines::write_lines;
use super::mesh_out::MeshOut;
use std::io::Write;

pub(super) fn write(w: &mut impl Write, m: &MeshOut) -> std::io::Result<()> {
    let (ps, ns, fs) = (m.positions, m.normals, m.faces);
    if let Some(c) = m.comment {
        writeln!(w, "# {c}")?;
    }
    write_lines(w, ps.len(), |i, b| {
        b.extend_from_slice(b"v ");
        push_f64x3(b, ps[i]);
        b.push(b'\n');
        Ok(())
    })?;
    write_lines(w, ns.len(), |i, b| {
        b.extend_from_slice(b"vn ");
        push_f64x3(b, ns[i]);
        b.push(b'\n');
        Ok(())
    })?;
    write_lines(w, fs.len(), |i, b| {
        b.push(b'f');
        for x in fs[i].map(|x| u64::from(x) + 1) {
            b.push(b' ');
            push_uint(b, x);
            if !ns.is_empty() {
                b.extend_from_slice(b"//");
                push_uint(b, x);
            }
        }
        b.push(b'\n');
        Ok(())
    })
}
