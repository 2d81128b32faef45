//! The whole pipeline on small arbitrary meshes: read (format from the first byte) → validate
//! (Sec. 3.1) → gluing data of a few edges and one face (Def. 4.1.4 labels, Sec. 6.1.2) → the
//! Chapter 4 checks at low density, asserting the statements that hold (SPEC_ROWS.md) hold.
#![no_main]
use libfuzzer_sys::fuzz_target;
use pseudomanifold::mesh::io::{read_mesh_from_bytes, ReadOptions};
use pseudomanifold::mesh::MeshFormat;

fuzz_target!(|data: &[u8]| {
    let Some((&sel, body)) = data.split_first() else {
        return;
    };
    let format = match sel % 3 {
        0 => MeshFormat::Off,
        1 => MeshFormat::Obj,
        _ => MeshFormat::PlyAscii,
    };
    let opts = ReadOptions {
        triangulate: sel & 0x80 != 0,
        ..Default::default()
    };
    let Ok(raw) = read_mesh_from_bytes(body, format, "fuzz", &opts) else {
        return;
    };
    if raw.faces.len() > 2000 {
        return; // "small arbitrary meshes": keep each execution well under a second
    }
    if let Some(s) = pseudomanifold_fuzz::validate_checked(&raw) {
        pseudomanifold_fuzz::chapter4_low_density(&s, sel as u64, 2, 3);
    }
});
