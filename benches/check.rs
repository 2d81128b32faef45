//! Speed target of Sec. 3.1: `ppm check` (read + every Sec. 3.1 check, including the exact
//! self-intersection test) on the largest good corpus mesh finishes in seconds.
//! Run: `cargo bench --bench check`. Uses `../shared/meshes/good/koala.obj` when present
//! (99,994 triangles), and always a generated 80,000-triangle torus.

use criterion::{criterion_group, criterion_main, Criterion};
use pseudomanifold::mesh::generate::torus;
use pseudomanifold::mesh::io::{read_mesh, ReadOptions};
use pseudomanifold::mesh::validate::validate;
use std::path::Path;

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("check");
    g.sample_size(10);
    let t = torus(200, 200);
    g.bench_function("validate torus 80k triangles", |b| {
        b.iter(|| validate(&t).report.is_simplicial_surface)
    });
    let koala = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../shared/meshes/good/koala.obj");
    if koala.exists() {
        g.bench_function("read+validate koala.obj 100k triangles", |b| {
            b.iter(|| {
                let raw = read_mesh(&koala, &ReadOptions::default()).expect("koala readable");
                validate(&raw).report.is_simplicial_surface
            })
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
