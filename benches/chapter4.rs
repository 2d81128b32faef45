//! Performance target: the full Chapter 4 conformance run (`ppm check --spec`'s
//! Chapter 4 part) in f64 per corpus mesh at default density — the whole `good/` corpus in
//! under a minute on 2 cores — and checks per second in f64 vs MPFR.
//! Run: `cargo bench --bench chapter4` (needs `../shared/meshes/`; otherwise generated meshes).

use criterion::{criterion_group, criterion_main, Criterion};
use pseudomanifold::conditions::chapter4::{run_chapter4, Ch4Options, Precision};
use pseudomanifold::mesh::generate::{icosahedron, torus};
use pseudomanifold::mesh::io::{read_mesh, ReadOptions};
use pseudomanifold::mesh::validate::validate;
use pseudomanifold::mesh::SimplicialSurface;
use std::path::Path;
use std::time::Instant;

fn surfaces() -> Vec<(String, SimplicialSurface)> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../shared/meshes/good");
    let mut v: Vec<(String, SimplicialSurface)> = std::fs::read_dir(&dir)
        .map(|rd| {
            rd.flatten()
                .filter_map(|e| {
                    let p = e.path();
                    let raw = read_mesh(&p, &ReadOptions::default()).ok()?;
                    let k = validate(&raw).surface?;
                    Some((p.file_name()?.to_string_lossy().into_owned(), k))
                })
                .collect()
        })
        .unwrap_or_default();
    if v.is_empty() {
        for (n, m) in [("icosahedron", icosahedron()), ("torus", torus(40, 30))] {
            if let Some(k) = validate(&m).surface {
                v.push((n.to_string(), k));
            }
        }
    }
    v.sort_by(|a, b| a.0.cmp(&b.0));
    v
}

fn bench(c: &mut Criterion) {
    let all = surfaces();
    // One timed pass over the whole corpus, printed (the target is about the total).
    let t0 = Instant::now();
    let mut checks = 0u64;
    for (name, k) in &all {
        let t = Instant::now();
        let r = run_chapter4(k, &Ch4Options::default());
        let n: u64 = r.checks.iter().map(|c| c.examined).sum();
        checks += n;
        eprintln!(
            "{name}: {:.2} s, {n} checked items, {} unexpected failures",
            t.elapsed().as_secs_f64(),
            r.unexpected_failures.len()
        );
    }
    let total = t0.elapsed().as_secs_f64();
    eprintln!(
        "whole corpus, f64, default density: {total:.1} s, {:.0} checked items/s",
        checks as f64 / total
    );
    let mut g = c.benchmark_group("chapter4");
    g.sample_size(10);
    let small = all
        .iter()
        .min_by_key(|(_, k)| k.num_faces())
        .map(|(n, k)| (n.clone(), k.clone()));
    if let Some((name, k)) = small {
        for (label, precision) in [("f64", Precision::F64), ("mp256", Precision::Mp(256))] {
            let opts = Ch4Options {
                precision,
                samples: 4,
                max_edge_configs: Some(8),
                max_triangle_configs: Some(8),
                max_star_configs: Some(4),
                ..Ch4Options::default()
            };
            g.bench_function(format!("{name} {label} (8 configs each, 4 samples)"), |b| {
                b.iter(|| run_chapter4(&k, &opts).checks.len())
            });
        }
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
