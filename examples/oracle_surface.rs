//! The Chapter 5 reference quantities in f64 and in MPFR, with the difference as the error
//! estimate of the f64 value: θ_v(p) (Def. 5.4.2), its derivatives to order 3 (jets over f64
//! and over MPFR), and eval(σ, λ, μ, ν) (Sec. 6.1.4).
//!
//! Run: `cargo run --example oracle_surface -- tests/data/icosahedron_binary_le.ply`

use pseudomanifold::construction::P2;
use pseudomanifold::mesh::io::{read_mesh, ReadOptions};
use pseudomanifold::mesh::validate::validate;
use pseudomanifold::mesh::FaceId;
use pseudomanifold::numeric::{Mp, Scalar};
use pseudomanifold::oracle::mp_distance;
use pseudomanifold::surface::{Consts, Jet, PnTriangles, Pps, PpsOptions};
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
    let pps = Pps::build(&k, &PnTriangles::new(&k), PpsOptions::default());
    let bits = 256;
    let cm: Consts<Mp> = pps.consts(bits);
    let v = pps.vertices().next().ok_or("no vertices")?;
    let p = [0.3, 0.1];
    let fast = pps.theta_f64(v, p)?;
    let reference = pps.theta(v, &P2::<Mp>::from_f64(p[0], p[1], bits), &cm)?;
    println!(
        "θ_{v}({p:?}) = {fast:?}, |f64 − MPFR-{bits}| = {:.3e}",
        mp_distance(&fast, &reference)
    );
    // Derivatives: θ on jets, in f64 and in MPFR.
    let jf = pps.theta_jet(v, p, &pps.consts(53), None)?;
    let cj: Consts<Jet<Mp>> = pps.consts(bits);
    let (x, y) = Jet::variables(Mp::from_f64(p[0], bits), Mp::from_f64(p[1], bits));
    let jm = pps.theta(v, &P2::new(x, y), &cj)?;
    for (i, j) in [(1, 0), (0, 1), (2, 0), (1, 1), (0, 2), (3, 0)] {
        let a: Vec<f64> = jf.iter().map(|d| d.derivative(i, j)).collect();
        let b: Vec<Mp> = jm.iter().map(|d| d.derivative(i, j)).collect();
        println!(
            "  ∂^{}θ/∂x^{i}∂y^{j} = {a:?}, |f64 − MPFR| = {:.3e}",
            i + j,
            mp_distance(&a, &b)
        );
    }
    let bary = [0.25, 0.25, 0.5];
    let e = pps.eval(FaceId(0), &bary, pps.consts_f64())?;
    let em = pps.eval(FaceId(0), &bary.map(|t| Mp::from_f64(t, bits)), &cm)?;
    println!(
        "eval(σ0, {bary:?}) = {:?} (chart {:?}, θ_{} at q = ({:e}, {:e})), |f64 − MPFR| = {:.3e}",
        e.point,
        e.chart,
        e.vertex,
        e.q.x,
        e.q.y,
        mp_distance(&e.point, &em.point)
    );
    Ok(())
}
