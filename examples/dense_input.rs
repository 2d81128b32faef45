//! The dense inputs of the fitting benchmark (docs/fitting-scale.md), made reproducibly from a
//! corpus mesh: N steps of Loop subdivision of the mesh itself (Loop 1987: edge points
//! 3/8·(a + b) + 1/8·(c + d), vertex points (1 − nβ(n))·v + β(n)·Σ ring, β from
//! `surface::loop_subdiv::rules`), then optional seeded normal noise: each vertex moves along its
//! area-weighted vertex normal by σ·h·z, z a standard normal draw and h the mean edge length of
//! the subdivided mesh, so σ is in units of the sampling density.
//!
//! `cargo run --release --example dense_input -- IN OUT [--loop N] [--sigma S] [--seed K]`
//! (defaults N = 0, σ = 0, seed 1). Each step multiplies the faces by 4 (koala, 100k faces:
//! two steps, 800k vertices). OUT's extension picks the format (off, obj, or binary ply);
//! positions round-trip exactly, so the same command makes the same bytes.

use pseudomanifold::mesh::io::write_mesh;
use pseudomanifold::mesh::{load_surface, MeshFormat};
use pseudomanifold::numeric::vec3::{cross, norm, sub};
use pseudomanifold::surface::loop_subdiv::rules::vertex_weights;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::collections::HashMap;
use std::path::PathBuf;
use std::process::ExitCode;

fn main() -> ExitCode {
    match run() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("dense_input: {e}");
            ExitCode::from(2)
        }
    }
}

fn run() -> Result<(), String> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (mut steps, mut sigma, mut seed, mut files) = (0u32, 0.0f64, 1u64, Vec::new());
    let mut it = args.iter();
    while let Some(a) = it.next() {
        match a.as_str() {
            "--loop" => steps = parse(it.next(), "--loop")?,
            "--sigma" => sigma = parse(it.next(), "--sigma")?,
            "--seed" => seed = parse(it.next(), "--seed")?,
            _ => files.push(PathBuf::from(a)),
        }
    }
    let [input, output] = <[PathBuf; 2]>::try_from(files)
        .map_err(|_| "usage: dense_input IN OUT [--loop N] [--sigma S] [--seed K]".to_string())?;
    if !(sigma.is_finite() && sigma >= 0.0) {
        return Err(format!("--sigma must be finite and ≥ 0, got {sigma}"));
    }
    let format = match output.extension().and_then(|e| e.to_str()) {
        Some("off") => MeshFormat::Off,
        Some("obj") => MeshFormat::Obj,
        Some("ply") => MeshFormat::PlyBinaryLittleEndian,
        _ => {
            return Err(format!(
                "{}: the extension must be off, obj or ply",
                output.display()
            ))
        }
    };
    if steps > 4 {
        return Err(format!(
            "--loop {steps}: at most 4 steps (256 times the faces)"
        ));
    }
    let k = load_surface(&input).map_err(|e| e.to_string())?;
    let mut pos: Vec<[f64; 3]> = k.vertices().map(|v| k.position(v)).collect();
    let mut faces: Vec<[u32; 3]> = k.faces().map(|f| k.face(f).map(|v| v.0)).collect();
    for _ in 0..steps {
        (pos, faces) = loop_step(&pos, &faces)?;
    }
    let h = mean_edge_length(&pos, &faces);
    let normals = vertex_normals(&pos, &faces);
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    if sigma > 0.0 {
        for (p, n) in pos.iter_mut().zip(&normals) {
            let d = sigma * h * standard_normal(&mut rng);
            *p = [p[0] + d * n[0], p[1] + d * n[1], p[2] + d * n[2]];
        }
    }
    write_mesh(&output, &pos, &faces, format).map_err(|e| e.to_string())?;
    eprintln!(
        "dense_input: {steps} Loop steps, {} vertices, {} faces, mean edge length h = {h:.6e}, noise σ·h = {:.6e} along the normals, seed {seed}",
        pos.len(),
        faces.len(),
        sigma * h
    );
    Ok(())
}

fn parse<T: std::str::FromStr>(v: Option<&String>, flag: &str) -> Result<T, String> {
    v.and_then(|s| s.parse().ok())
        .ok_or_else(|| format!("{flag} needs a number"))
}

/// Positions and faces of a triangle mesh.
type Mesh = (Vec<[f64; 3]>, Vec<[u32; 3]>);

/// One Loop step of a closed triangle mesh (every edge in exactly two faces, checked).
fn loop_step(pos: &[[f64; 3]], faces: &[[u32; 3]]) -> Result<Mesh, String> {
    // The opposite corners of each undirected edge, and each vertex's ring.
    let mut opposite: HashMap<(u32, u32), Vec<u32>> = HashMap::with_capacity(faces.len() * 3 / 2);
    let mut ring: Vec<Vec<u32>> = vec![Vec::new(); pos.len()];
    for f in faces {
        for i in 0..3 {
            let (a, b, c) = (f[i], f[(i + 1) % 3], f[(i + 2) % 3]);
            opposite.entry((a.min(b), a.max(b))).or_default().push(c);
            ring[a as usize].push(b);
        }
    }
    let mut edge_ids: Vec<(u32, u32)> = opposite.keys().copied().collect();
    edge_ids.sort_unstable();
    let mut new_pos: Vec<[f64; 3]> = Vec::with_capacity(pos.len() + edge_ids.len());
    for (v, r) in ring.iter().enumerate() {
        let n = r.len() as u32;
        if n < 3 {
            return Err(format!(
                "vertex {v} has {n} neighbours: not a closed surface"
            ));
        }
        let (wc, wr) = vertex_weights::<f64>(n, 53);
        let mut p = pos[v].map(|c| wc * c);
        for &u in r {
            for (a, b) in p.iter_mut().zip(pos[u as usize]) {
                *a += wr * b;
            }
        }
        new_pos.push(p);
    }
    let mut edge_point: HashMap<(u32, u32), u32> = HashMap::with_capacity(edge_ids.len());
    for &(a, b) in &edge_ids {
        let [c, d] = opposite[&(a, b)][..] else {
            return Err(format!("edge ({a}, {b}) is not in exactly two faces"));
        };
        let q = |i: usize| {
            0.375 * (pos[a as usize][i] + pos[b as usize][i])
                + 0.125 * (pos[c as usize][i] + pos[d as usize][i])
        };
        edge_point.insert((a, b), new_pos.len() as u32);
        new_pos.push([q(0), q(1), q(2)]);
    }
    let mid = |a: u32, b: u32| edge_point[&(a.min(b), a.max(b))];
    let mut new_faces = Vec::with_capacity(faces.len() * 4);
    for &[a, b, c] in faces {
        let (ab, bc, ca) = (mid(a, b), mid(b, c), mid(c, a));
        new_faces.extend([[a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]]);
    }
    Ok((new_pos, new_faces))
}

fn mean_edge_length(pos: &[[f64; 3]], faces: &[[u32; 3]]) -> f64 {
    let (mut sum, mut n) = (0.0, 0usize);
    for f in faces {
        let c = f.map(|v| pos[v as usize]);
        for i in 0..3 {
            let d = sub(c[(i + 1) % 3], c[i]);
            sum += norm(d);
            n += 1;
        }
    }
    // Every edge of a closed surface is counted twice, which leaves the mean unchanged.
    if n == 0 {
        0.0
    } else {
        sum / n as f64
    }
}

/// Area-weighted vertex normals (the sum of the faces' cross products), unit length; a vertex
/// whose faces' normals cancel keeps the zero vector and is not moved.
fn vertex_normals(pos: &[[f64; 3]], faces: &[[u32; 3]]) -> Vec<[f64; 3]> {
    let mut n = vec![[0.0f64; 3]; pos.len()];
    for &c in faces {
        let p = c.map(|v| pos[v as usize]);
        let (u, w) = (sub(p[1], p[0]), sub(p[2], p[0]));
        let x = cross(u, w);
        for v in c {
            for (a, b) in n[v as usize].iter_mut().zip(x) {
                *a += b;
            }
        }
    }
    for v in &mut n {
        let l = norm(*v);
        if l > 0.0 {
            *v = v.map(|c| c / l);
        }
    }
    n
}

/// One standard normal draw (Box–Muller; rand_distr is not a dependency for one function).
fn standard_normal(rng: &mut ChaCha8Rng) -> f64 {
    let u1: f64 = 1.0 - rng.gen::<f64>(); // (0, 1]: ln is finite
    let u2: f64 = rng.gen();
    (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos()
}
