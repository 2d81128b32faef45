//! Def. 3.1.6 validator on arbitrary face lists over small integer coordinates (so collinear,
//! coplanar, coincident and touching configurations are common and the exact predicates of
//! Def. 3.1.3(ii) are exercised), with a few arbitrary f64 coordinates (NaN, ±∞, subnormals).
#![no_main]
use arbitrary::Arbitrary;
use libfuzzer_sys::fuzz_target;
use pseudomanifold::mesh::RawMesh;

#[derive(Arbitrary, Debug)]
struct Input {
    coords: Vec<[i8; 3]>,
    specials: Vec<(u8, u8, f64)>,
    faces: Vec<[u8; 3]>,
}

fuzz_target!(|inp: Input| {
    let mut positions: Vec<[f64; 3]> = inp
        .coords
        .iter()
        .take(64)
        .map(|c| c.map(|x| x as f64 / 4.0))
        .collect();
    if positions.is_empty() {
        return;
    }
    for &(v, k, x) in inp.specials.iter().take(4) {
        let n = positions.len();
        positions[v as usize % n][k as usize % 3] = x;
    }
    // Indices up to 255 with at most 64 vertices: out-of-range indices are part of the input
    // space on purpose.
    let faces: Vec<[u32; 3]> = inp
        .faces
        .iter()
        .take(256)
        .map(|t| t.map(u32::from))
        .collect();
    let raw = RawMesh::from_arrays(positions, faces);
    pseudomanifold_fuzz::validate_checked(&raw);
});
