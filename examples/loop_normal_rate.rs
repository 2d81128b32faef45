//! Diagnostic for `LOOP-normal-mask` (SPEC.md): the angle between the Loop S′ normal at
//! (1 − 2δ, δ, δ) and the limit normal t₁ × t₂ of the tangent masks, for δ = 2^−4, 2^−12, …, 2^−164,
//! at one vertex. Run: `cargo run --release --example loop_normal_rate MESH VERTEX`.
use pseudomanifold::mesh::io::{read_mesh, ReadOptions};
use pseudomanifold::mesh::validate::validate;
use pseudomanifold::mesh::VertexId;
use pseudomanifold::surface::loop_subdiv::checks::masks;
use pseudomanifold::surface::loop_subdiv::LoopSurface;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let (Some(path), Some(v)) = (args.get(1), args.get(2).and_then(|s| s.parse::<u32>().ok()))
    else {
        eprintln!("usage: loop_normal_rate MESH VERTEX");
        std::process::exit(2);
    };
    let raw = match read_mesh(std::path::Path::new(path), &ReadOptions::default()) {
        Ok(r) => r,
        Err(e) => {
            eprintln!("error: {e}");
            std::process::exit(2);
        }
    };
    let Some(k) = validate(&raw).surface else {
        eprintln!("error: not a simplicial surface");
        std::process::exit(2);
    };
    let v = VertexId(v);
    let l = match LoopSurface::new(&k) {
        Ok(l) => l,
        Err(e) => {
            eprintln!("error: {e}");
            std::process::exit(2);
        }
    };
    let (_, nm) = masks(&k, v);
    let cross = |a: [f64; 3], b: [f64; 3]| {
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    };
    let angle = |a: [f64; 3], b: [f64; 3]| {
        let c = cross(a, b);
        let s = (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]).sqrt();
        let d = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        s.atan2(d)
    };
    println!("vertex {} valence {}", v.0, k.degree(v));
    for f in k.faces() {
        let c = k.face(f);
        let Some(i) = c.iter().position(|&x| x == v) else {
            continue;
        };
        let corners = [c[i], c[(i + 1) % 3], c[(i + 2) % 3]];
        let mut line = format!("face {}:", f.0);
        for kk in (4..=168).step_by(8) {
            let d = 2f64.powi(-kk);
            let a = match l.jet::<f64>(f, corners, &[1.0 - 2.0 * d, d, d], true) {
                Ok(j) => {
                    j.d.map(|j| angle(cross(j[0], j[1]), nm))
                        .unwrap_or(f64::NAN)
                }
                Err(_) => f64::NAN,
            };
            line += &format!(" {a:.2e}");
        }
        println!("{line}");
    }
}
