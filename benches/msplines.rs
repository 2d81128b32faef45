//! Speed targets of the manifold-spline pipeline (Gu–He–Qin Sec. 5): harmonic + holomorphic
//! forms in < 2 s and the atlas with its Def. 3.4.1 checks in < 10 s on a 50k-vertex mesh.
//! koala.obj (the 50k-vertex corpus mesh) has genus 0, where Sec. 5 has no forms (Thm. 2), so
//! its case times what the forms step spends there: the sparse Cholesky of the cotangent
//! Laplacian and two solves (on d of an integer vertex function). The full pipeline is timed
//! on generated 20k- and 50k-vertex tori and on the corpus's genus ≥ 1 meshes when present.
//! Run: `cargo bench --bench msplines`.

use criterion::Criterion;
use pseudomanifold::mesh::generate::torus;
use pseudomanifold::mesh::io::{read_mesh, ReadOptions};
use pseudomanifold::mesh::validate::validate;
use pseudomanifold::mesh::SimplicialSurface;
use pseudomanifold::msplines::cochain::EdgeIndex;
use pseudomanifold::msplines::harmonic::harmonic_forms;
use pseudomanifold::msplines::{forms, run, Options};
use std::path::Path;

fn corpus(name: &str) -> Option<SimplicialSurface> {
    let p = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../shared/meshes/good")
        .join(name);
    validate(&read_mesh(&p, &ReadOptions::default()).ok()?).surface
}

fn main() {
    let mut c = Criterion::default().sample_size(10).configure_from_args();
    if let Some(k) = corpus("koala.obj") {
        let ei = EdgeIndex::new(&k);
        // Two exact integer cochains d(g) with g(v) = v mod 7 and v mod 5.
        let taus: Vec<Vec<i64>> = [7i64, 5]
            .iter()
            .map(|&m| {
                (0..ei.len())
                    .map(|e| {
                        let h = ei.canonical(pseudomanifold::msplines::cochain::EdgeIdx(e as u32));
                        (k.dest(h).0 as i64 % m) - (k.origin(h).0 as i64 % m)
                    })
                    .collect()
            })
            .collect();
        c.bench_function(
            "koala: cotan Laplacian factor + 2 solves (forms step, genus 0)",
            |b| b.iter(|| harmonic_forms(&k, &ei, &taus).expect("solve")),
        );
    }
    let mut cases = vec![
        (
            "torus 20k".to_string(),
            validate(&torus(100, 100)).surface.expect("torus"),
        ),
        (
            "torus 50k".to_string(),
            validate(&torus(250, 200)).surface.expect("torus"),
        ),
    ];
    for name in [
        "torus.obj",
        "eight.off",
        "skull_low_resolution.obj",
        "boot.obj",
    ] {
        if let Some(k) = corpus(name) {
            cases.push((name.to_string(), k));
        }
    }
    for (name, k) in &cases {
        c.bench_function(&format!("{name}: harmonic + holomorphic forms"), |b| {
            b.iter(|| forms(k).expect("forms"))
        });
        c.bench_function(
            &format!("{name}: whole pipeline (forms, zeros, atlas, checks)"),
            |b| b.iter(|| run(k, &Options::default()).expect("run")),
        );
    }
    c.final_summary();
}
