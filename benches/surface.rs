//! Speed targets of Ch. 5: construction (all ψ_v fitted) of koala.obj in < 1 s on 2 cores, and
//! eval at ≥ 1 M points/s in f64. Run: `cargo bench --bench surface` (criterion), or
//! `SURFACE_QUICK=1 cargo bench --bench surface` for a one-shot table (cold builds, per-degree
//! factorization times, eval throughput). Uses `../shared/meshes/good/koala.obj` when present,
//! and always a generated 20,000-triangle torus. `build … authors-code 1 thread` is the
//! construction to compare with the authors' single-threaded C++ code.

use criterion::{Criterion, Throughput};
use pseudomanifold::mesh::generate::torus;
use pseudomanifold::mesh::io::{read_mesh, ReadOptions};
use pseudomanifold::mesh::validate::validate;
use pseudomanifold::mesh::{FaceId, SimplicialSurface};
use pseudomanifold::surface::fit::factor_degree;
use pseudomanifold::surface::{PnTriangles, Pps, PpsOptions, Profile};
use rayon::prelude::*;
use std::path::Path;
use std::time::Instant;

fn build(k: &SimplicialSurface, profile: Profile) -> Pps {
    Pps::build(
        k,
        &PnTriangles::for_profile(k, profile),
        PpsOptions {
            profile,
            ..PpsOptions::default()
        },
    )
}

fn meshes() -> Vec<(String, SimplicialSurface)> {
    let mut meshes = vec![(
        "torus 20k".to_string(),
        validate(&torus(100, 100)).surface.expect("torus"),
    )];
    let koala = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../shared/meshes/good/koala.obj");
    if let Ok(raw) = read_mesh(&koala, &ReadOptions::default()) {
        if let Some(k) = validate(&raw).surface {
            meshes.push(("koala".to_string(), k));
        }
    }
    meshes
}

/// 1 M evaluation points spread over all faces (deterministic).
fn points(nf: usize) -> Vec<(FaceId, [f64; 3])> {
    (0..1_000_000usize)
        .map(|i| {
            let a = ((i * 7919) % 997) as f64 / 997.0;
            let b = ((i * 104729) % 991) as f64 / 991.0 * (1.0 - a);
            (FaceId((i % nf) as u32), [1.0 - a - b, a, b])
        })
        .collect()
}

fn eval_all(pps: &Pps, pts: &[(FaceId, [f64; 3])]) -> f64 {
    pts.par_iter()
        .map(|(f, x)| pps.eval_f64(*f, *x).map(|p| p[0]).unwrap_or(0.0))
        .sum::<f64>()
}

fn eval_batch(pps: &Pps, pts: &[(FaceId, [f64; 3])]) -> f64 {
    pps.eval_batch_f64(pts)
        .iter()
        .map(|r| r.as_ref().map(|p| p[0]).unwrap_or(0.0))
        .sum::<f64>()
}

/// CPU seconds (user + system) of this process so far (Linux /proc; 0 elsewhere): on a
/// shared machine, points per CPU-second is the load-independent figure.
fn cpu_seconds() -> f64 {
    let stat = std::fs::read_to_string("/proc/self/stat").unwrap_or_default();
    let after = stat.rsplit(')').next().unwrap_or("");
    let f: Vec<f64> = after
        .split_whitespace()
        .map(|x| x.parse().unwrap_or(0.0))
        .collect();
    // Fields 14 and 15 (utime, stime) in clock ticks; `after` starts at field 3.
    (f.get(11).unwrap_or(&0.0) + f.get(12).unwrap_or(&0.0)) / 100.0
}

/// Runs `f` `runs` times: (median wall seconds, total CPU seconds / runs).
fn timed(runs: usize, mut f: impl FnMut()) -> (f64, f64) {
    let c0 = cpu_seconds();
    let t: Vec<f64> = (0..runs)
        .map(|_| {
            let t0 = Instant::now();
            f();
            t0.elapsed().as_secs_f64()
        })
        .collect();
    (median(t), (cpu_seconds() - c0) / runs as f64)
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(|a, b| a.total_cmp(b));
    v[v.len() / 2]
}

/// One-shot table: cold builds (median of `runs`), per-degree factorizations, eval rate.
fn quick() {
    let runs: usize = std::env::var("SURFACE_RUNS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(3);
    println!("threads: {}", rayon::current_num_threads());
    for (name, k) in &meshes() {
        let mut degs: Vec<u32> = k.vertices().map(|v| k.degree(v)).collect();
        degs.sort_unstable();
        degs.dedup();
        for profile in [Profile::Paper, Profile::AuthorsCode] {
            let t: Vec<f64> = (0..runs)
                .map(|_| {
                    let t0 = Instant::now();
                    let p = build(k, profile);
                    std::hint::black_box(&p);
                    t0.elapsed().as_secs_f64()
                })
                .collect();
            println!(
                "build {name} {}: {:.3} s (median of {runs})",
                profile.name(),
                median(t)
            );
            if std::env::var("SURFACE_DEGREES").is_ok() {
                for &m in &degs {
                    let t0 = Instant::now();
                    let f = factor_degree(m, profile);
                    println!(
                        "  factor m={m} ({}x{}, rank {}): {:.3} s",
                        f.info.rows,
                        f.info.unknowns,
                        f.info.rank,
                        t0.elapsed().as_secs_f64()
                    );
                }
            }
        }
        if std::env::var("SURFACE_SKIP_EVAL").is_ok() {
            continue;
        }
        // Side by side with the authors' C++ code, which is single-threaded
        // (docs/oracle.md, "Checked against the authors' implementation").
        if let Ok(one) = rayon::ThreadPoolBuilder::new().num_threads(1).build() {
            let (wall, _) = timed(runs, || {
                std::hint::black_box(one.install(|| build(k, Profile::AuthorsCode)));
            });
            println!("build {name} authors-code 1 thread: {wall:.3} s (median of {runs})");
        }
        let pps = build(k, Profile::Paper);
        let pts = points(pps.num_faces());
        let np = pts.len() as f64 / 1e6;
        let (wall, cpu) = timed(runs, || {
            std::hint::black_box(eval_all(&pps, &pts));
        });
        println!(
            "eval f64 {name}: {:.3} M points/s (median of {runs}), {:.3} M points per CPU-s",
            np / wall,
            np / cpu
        );
        let (wall, cpu) = timed(runs, || {
            std::hint::black_box(eval_batch(&pps, &pts));
        });
        println!(
            "eval_batch_f64 {name}: {:.3} M points/s (median of {runs}), {:.3} M points per CPU-s",
            np / wall,
            np / cpu
        );
        if std::env::var("SURFACE_SORTED").is_ok() {
            let mut sorted = pts.clone();
            sorted.sort_by_key(|p| p.0);
            let t: Vec<f64> = (0..runs)
                .map(|_| {
                    let t0 = Instant::now();
                    std::hint::black_box(eval_all(&pps, &sorted));
                    t0.elapsed().as_secs_f64()
                })
                .collect();
            println!(
                "eval f64 {name}, points sorted by face: {:.3} M points/s",
                pts.len() as f64 / median(t) / 1e6
            );
        }
    }
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("surface");
    g.sample_size(10);
    for (name, k) in &meshes() {
        for profile in [Profile::Paper, Profile::AuthorsCode] {
            g.bench_function(format!("build {name} {}", profile.name()), |b| {
                b.iter(|| build(k, profile))
            });
        }
        let pps = build(k, Profile::Paper);
        let pts = points(pps.num_faces());
        g.throughput(Throughput::Elements(pts.len() as u64));
        g.bench_function(format!("eval f64 {name} 1M points (2 threads)"), |b| {
            b.iter(|| eval_all(&pps, &pts))
        });
        g.bench_function(
            format!("eval_batch_f64 {name} 1M points (2 threads)"),
            |b| b.iter(|| eval_batch(&pps, &pts)),
        );
        g.throughput(Throughput::Elements(1));
    }
    g.finish();
}

fn main() {
    if std::env::var("SURFACE_QUICK").is_ok() {
        quick();
        return;
    }
    let mut c = Criterion::default().configure_from_args();
    bench(&mut c);
    c.final_summary();
}
