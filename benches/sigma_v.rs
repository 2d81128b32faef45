//! Speed targets of the tutorial's (σ, v)-indexed construction (SPEC `SV-bench`): construction
//! of koala.obj (3·n_t ≈ 300k patches; the least-squares matrix factored once per (m, d)) under
//! 3 s, eval ≥ 500k points/s in f64. `SIGMAV_QUICK=1 cargo bench --bench sigma_v` prints a
//! one-shot table; otherwise criterion. Uses `../shared/meshes/good/koala.obj` when present and
//! always a generated 20,000-triangle torus.

use criterion::{Criterion, Throughput};
use pseudomanifold::mesh::generate::torus;
use pseudomanifold::mesh::io::{read_mesh, ReadOptions};
use pseudomanifold::mesh::validate::validate;
use pseudomanifold::mesh::{FaceId, SimplicialSurface};
use pseudomanifold::surface::sigma_v::{SigmaVPps, DEFAULT_KAPPA, DEFAULT_PATCH_DEGREE};
use pseudomanifold::surface::PnTriangles;
use rayon::prelude::*;
use std::path::Path;
use std::time::Instant;

fn meshes() -> Vec<(String, SimplicialSurface)> {
    let mut out = vec![(
        "torus 20k".to_string(),
        validate(&torus(100, 100)).surface.expect("torus"),
    )];
    let koala = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../shared/meshes/good/koala.obj");
    if let Ok(raw) = read_mesh(&koala, &ReadOptions::default()) {
        if let Some(k) = validate(&raw).surface {
            out.push(("koala".to_string(), k));
        }
    }
    out
}

fn build(k: &SimplicialSurface) -> SigmaVPps {
    SigmaVPps::build(k, &PnTriangles::new(k), DEFAULT_KAPPA, DEFAULT_PATCH_DEGREE)
        .expect("default κ")
}

fn points(nf: usize, n: usize) -> Vec<(FaceId, [f64; 3])> {
    (0..n)
        .map(|i| {
            let a = ((i * 7919) % 997) as f64 / 997.0;
            let b = ((i * 104729) % 991) as f64 / 991.0 * (1.0 - a);
            (FaceId((i % nf) as u32), [1.0 - a - b, a, b])
        })
        .collect()
}

fn eval_all(pps: &SigmaVPps, pts: &[(FaceId, [f64; 3])]) -> f64 {
    pts.par_iter()
        .map(|(f, x)| pps.eval_f64(*f, *x).map(|p| p[0]).unwrap_or(f64::NAN))
        .sum()
}

fn main() {
    let ms = meshes();
    if std::env::var("SIGMAV_QUICK").is_ok() {
        for (name, k) in &ms {
            let t = Instant::now();
            let pps = build(k);
            let tb = t.elapsed().as_secs_f64();
            let pts = points(k.num_faces(), 1_000_000);
            let t = Instant::now();
            let s = eval_all(&pps, &pts);
            let te = t.elapsed().as_secs_f64();
            println!(
                "{name}: {} patches, build {tb:.2} s; eval {:.0} points/s (checksum {s:.3})",
                pps.gluing.len(),
                pts.len() as f64 / te
            );
        }
        return;
    }
    let mut c = Criterion::default().sample_size(10).configure_from_args();
    for (name, k) in &ms {
        c.bench_function(&format!("sigma-v build {name}"), |b| b.iter(|| build(k)));
        let pps = build(k);
        let pts = points(k.num_faces(), 200_000);
        let mut g = c.benchmark_group(format!("sigma-v eval {name}"));
        g.throughput(Throughput::Elements(pts.len() as u64));
        g.bench_function("eval_f64 (rayon)", |b| b.iter(|| eval_all(&pps, &pts)));
        g.finish();
    }
    c.final_summary();
}
