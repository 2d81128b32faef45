//! Evaluate the transition map φ_wu of a mesh in f64 and in MPFR, as a faster implementation
//! would when comparing itself with the reference.
//!
//! Run: `cargo run --example oracle -- tests/data/icosahedron_binary_le.ply`

use pseudomanifold::construction::{Paper, Ppm, PpmGluing, P2};
use pseudomanifold::mesh::io::{read_mesh, ReadOptions};
use pseudomanifold::mesh::validate::validate;
use pseudomanifold::numeric::Mp;
use std::path::PathBuf;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let path: PathBuf = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "tests/data/icosahedron_binary_le.ply".into())
        .into();
    let raw = read_mesh(&path, &ReadOptions::default())?;
    let k = validate(&raw)
        .surface
        .ok_or("the mesh is not a simplicial surface (see `ppm check`)")?;
    let g = PpmGluing::new(&k);
    let (u, w) = k.edges().next().ok_or("no edges")?;
    let e = g.edge_config(u, w)?;
    // A point of Ω_uw: the centre of the canonical lens pulled back to Ω_u.
    let p = Paper.r_uw_inv(&e, &Paper.g_v_inv(e.m_u, &P2::new(0.5, 0.1))?);
    let fast = g.phi::<f64>(w, u, &p)?;
    let reference = g.phi::<Mp>(w, u, &P2::<Mp>::from_f64(p.x, p.y, 256))?;
    let err = reference.dist_f64(&P2::<Mp>::from_f64(fast.x, fast.y, 256));
    println!("edge [{u}, {w}] with configuration {e:?}");
    println!("p = ({:e}, {:e}) ∈ Ω_uw", p.x, p.y);
    println!(
        "φ_wu(p): f64 ({:e}, {:e}), |f64 − MPFR-256| = {err:.3e}",
        fast.x, fast.y
    );
    Ok(())
}
