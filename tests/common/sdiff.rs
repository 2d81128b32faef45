//! Fixtures of the seed-004 tests (`tests/seeds/sdiff_spec.rs`, `tests/seeds/sdiff_sec6.rs`).

use pseudomanifold::mesh::io::{read_mesh, ReadOptions};
use pseudomanifold::sdiff::common::rational::{qr, Q};
use pseudomanifold::sdiff::planar::complex::{validate, PlanarComplex};
use pseudomanifold::sdiff::planar::objectives::Handle;
use std::path::{Path, PathBuf};

/// A file of `tests/data/sdiff/`.
pub fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/sdiff")
        .join(name)
}

/// square.off, validated.
pub fn square() -> PlanarComplex {
    let raw = read_mesh(&data("square.off"), &ReadOptions::default()).unwrap();
    validate(&raw).unwrap().0
}

/// The handles of `SD-L262`/`SD-L268`: O's crossings of the three crossed edges of square.off
/// (f = kink_values), with p(ε) on (0, 2) at `u02`, and the rational unit normal (24/25, 7/25).
pub fn handles(u02: Q) -> Vec<Handle> {
    let n = [qr(24, 25), qr(7, 25)];
    vec![
        Handle {
            edge: (0, 1),
            u: qr(1, 2),
            n: n.clone(),
        },
        Handle {
            edge: (0, 2),
            u: u02,
            n: n.clone(),
        },
        Handle {
            edge: (2, 3),
            u: qr(2, 3),
            n,
        },
    ]
}
