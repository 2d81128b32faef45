//! Sec. 6.2, Table 6.2 side by side, and the Loop S′ speed targets: construction with the
//! Loop S′ within 1.5× of the PN construction on good/koala.obj, and S′ evaluation
//! ≥ 1 M points/s per core in f64.
//!
//! `cargo bench --bench loop_sprime` (criterion), or `LOOP_QUICK=1 cargo bench --bench
//! loop_sprime` for the one-shot table (median of `LOOP_RUNS`, default 3): per mesh the
//! construction time with PN and with Loop, the Loop/PN ratio, and the paper's Table 6.2
//! figures (its models are not public; the ratio is what compares). Uses the corpus meshes in
//! `../shared/meshes/good/` when present and always a generated torus and icosahedron;
//! `LOOP_ONLY=koala.obj` keeps one mesh.

use criterion::{Criterion, Throughput};
use pseudomanifold::mesh::generate::{icosahedron, torus};
use pseudomanifold::mesh::io::{read_mesh, ReadOptions};
use pseudomanifold::mesh::validate::validate;
use pseudomanifold::mesh::{FaceId, SimplicialSurface};
use pseudomanifold::surface::loop_subdiv::LoopSurface;
use pseudomanifold::surface::{PnTriangles, Pps, PpsOptions, TargetSurface};
use std::path::Path;
use std::time::Instant;

/// Table 6.2 of the paper: (model, n_v, PN ms, Loop ms) on a single-core 3.2 GHz Xeon.
const PAPER: [(&str, u32, f64, f64); 4] = [
    ("model 1", 172, 540.0, 577.0),
    ("model 2", 50, 1971.0, 2112.0),
    ("model 3", 3674, 41160.0, 44274.0),
    ("model 4", 60880, 679588.0, 735221.0),
];

fn meshes() -> Vec<(String, SimplicialSurface)> {
    let mut v = vec![
        (
            "icosahedron".to_string(),
            validate(&icosahedron()).surface.expect("ico"),
        ),
        (
            "torus 20k".to_string(),
            validate(&torus(100, 100)).surface.expect("torus"),
        ),
    ];
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../shared/meshes/good");
    for name in ["cube.obj", "bob_small.ply", "bunny.off", "koala.obj"] {
        if let Ok(raw) = read_mesh(&dir.join(name), &ReadOptions::default()) {
            if let Some(k) = validate(&raw).surface {
                v.push((name.to_string(), k));
            }
        }
    }
    v
}

fn build_pn(k: &SimplicialSurface) -> Pps {
    Pps::build(k, &PnTriangles::new(k), PpsOptions::default())
}

fn build_loop(k: &SimplicialSurface) -> Pps {
    let s = LoopSurface::new(k).expect("Loop S′");
    Pps::build(k, &s, PpsOptions::default())
}

fn points(k: &SimplicialSurface, n: usize) -> Vec<(FaceId, [f64; 3])> {
    let nf = k.num_faces();
    (0..n)
        .map(|i| {
            let a = ((i * 7919) % 997) as f64 / 997.0;
            let b = ((i * 104729) % 991) as f64 / 991.0 * (1.0 - a);
            (FaceId((i % nf) as u32), [1.0 - a - b, a, b])
        })
        .collect()
}

fn eval_all(k: &SimplicialSurface, s: &LoopSurface, pts: &[(FaceId, [f64; 3])]) -> f64 {
    pts.iter().map(|&(f, b)| s.eval(f, k.face(f), b)[0]).sum()
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(|a, b| a.total_cmp(b));
    v[v.len() / 2]
}

fn quick() {
    let runs: usize = std::env::var("LOOP_RUNS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(3);
    let time = |f: &dyn Fn()| {
        median(
            (0..runs)
                .map(|_| {
                    let t0 = Instant::now();
                    f();
                    t0.elapsed().as_secs_f64() * 1e3
                })
                .collect(),
        )
    };
    println!(
        "threads: {}; median of {runs} runs",
        rayon::current_num_threads()
    );
    println!("| mesh | n_v | PN (ms) | Loop (ms) | of which Loop S′ built (ms) | Loop/PN |");
    println!("|---|---|---|---|---|---|");
    // LOOP_ONLY=name restricts the table to one mesh (for profiling).
    let only = std::env::var("LOOP_ONLY").ok();
    let all = meshes();
    let chosen: Vec<&(String, SimplicialSurface)> = all
        .iter()
        .filter(|(n, _)| only.as_deref().map_or(true, |o| o == n))
        .collect();
    for (name, k) in chosen.iter().copied() {
        let pn = time(&|| {
            std::hint::black_box(build_pn(k));
        });
        let lp = time(&|| {
            std::hint::black_box(build_loop(k));
        });
        let sp = time(&|| {
            std::hint::black_box(LoopSurface::new(k).expect("Loop S′"));
        });
        println!(
            "| {name} | {} | {pn:.1} | {lp:.1} | {sp:.1} | {:.3} |",
            k.num_vertices(),
            lp / pn
        );
    }
    println!("\nPaper, Table 6.2 (single core, 3.2 GHz Xeon):");
    for (m, nv, pn, lp) in PAPER {
        println!("| {m} | {nv} | {pn} | {lp} | {:.3} |", lp / pn);
    }
    for (name, k) in chosen.iter().copied() {
        let s = LoopSurface::new(k).expect("Loop S′");
        let pts = points(k, 1_000_000);
        let t = time(&|| {
            std::hint::black_box(eval_all(k, &s, &pts));
        });
        println!(
            "S′ eval f64 {name} (1 thread, {} regular / {} extraordinary / {} split faces): {:.3} M points/s",
            s.stats.regular_faces,
            s.stats.extraordinary_faces,
            s.stats.split_faces,
            1e3 / t
        );
    }
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("loop_sprime");
    g.sample_size(10);
    for (name, k) in &meshes() {
        g.bench_function(format!("construction PN {name}"), |b| {
            b.iter(|| build_pn(k))
        });
        g.bench_function(format!("construction Loop {name}"), |b| {
            b.iter(|| build_loop(k))
        });
        let s = LoopSurface::new(k).expect("Loop S′");
        let pts = points(k, 100_000);
        g.throughput(Throughput::Elements(pts.len() as u64));
        g.bench_function(
            format!("S′ eval f64 {name} 100k points (1 thread)"),
            |b| b.iter(|| eval_all(k, &s, &pts)),
        );
        g.throughput(Throughput::Elements(1));
    }
    g.finish();
}

fn main() {
    if std::env::var("LOOP_QUICK").is_ok() {
        quick();
        return;
    }
    let mut c = Criterion::default().configure_from_args();
    bench(&mut c);
    c.final_summary();
}
