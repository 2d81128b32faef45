//! Issue 5 speed targets: construction (all ψ_v fitted) of koala.obj in < 1 s on 2 cores, and
//! eval at ≥ 1 M points/s in f64. Run: `cargo bench --bench surface`. Uses
//! `../shared/meshes/good/koala.obj` when present, and always a generated 20,000-triangle torus.

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use pseudomanifold::mesh::generate::torus;
use pseudomanifold::mesh::io::{read_mesh, ReadOptions};
use pseudomanifold::mesh::validate::validate;
use pseudomanifold::mesh::{FaceId, SimplicialSurface};
use pseudomanifold::surface::{PnTriangles, Pps, PpsOptions, Profile};
use rayon::prelude::*;
use std::path::Path;

fn build(k: &SimplicialSurface, profile: Profile) -> Pps {
    Pps::build(
        k,
        &PnTriangles::new(k),
        PpsOptions {
            profile,
            ..PpsOptions::default()
        },
    )
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("surface");
    g.sample_size(10);
    let mut meshes = vec![(
        "torus 20k".to_string(),
        validate(&torus(100, 100)).surface.expect("torus"),
    )];
    let koala = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/meshes/good/koala.obj");
    if let Ok(raw) = read_mesh(&koala, &ReadOptions::default()) {
        if let Some(k) = validate(&raw).surface {
            meshes.push(("koala".to_string(), k));
        }
    }
    for (name, k) in &meshes {
        for profile in [Profile::Paper, Profile::AuthorsCode] {
            g.bench_function(format!("build {name} {}", profile.name()), |b| {
                b.iter(|| build(k, profile))
            });
        }
        let pps = build(k, Profile::Paper);
        let nf = pps.num_faces();
        let pts: Vec<(FaceId, [f64; 3])> = (0..1_000_000usize)
            .map(|i| {
                let a = ((i * 7919) % 997) as f64 / 997.0;
                let b = ((i * 104729) % 991) as f64 / 991.0 * (1.0 - a);
                (FaceId((i % nf) as u32), [1.0 - a - b, a, b])
            })
            .collect();
        g.throughput(Throughput::Elements(pts.len() as u64));
        g.bench_function(format!("eval f64 {name} 1M points (2 threads)"), |b| {
            b.iter(|| {
                pts.par_iter()
                    .map(|(f, x)| pps.eval_f64(*f, *x).map(|p| p[0]).unwrap_or(0.0))
                    .sum::<f64>()
            })
        });
        g.throughput(Throughput::Elements(1));
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
