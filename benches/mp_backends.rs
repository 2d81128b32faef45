//! The multi-precision backends side by side (docs/multiprecision.md): the MP parts of
//! `ppm check --spec` (the Chapter 4 checks at `mp:256` on one mesh, a seeded subset of
//! configurations) and of the oracle (θ_v and eval at 256 bits), in the pure-Rust default `Mp`
//! and, with `--features mpfr`, in MPFR; the ratio astro/MPFR is printed.
//! Run: `cargo bench --bench mp_backends --features mpfr`.
//!
//! The ratio is printed by the run; record it in docs/multiprecision.md ("Speed").

use criterion::{criterion_group, criterion_main, Criterion};
use pseudomanifold::conditions::chapter4::{run_chapter4, Ch4Options, Precision};
use pseudomanifold::construction::P2;
use pseudomanifold::mesh::generate::icosahedron;
use pseudomanifold::mesh::validate::validate;
use pseudomanifold::mesh::SimplicialSurface;
use pseudomanifold::numeric::MpBackend;
use pseudomanifold::surface::{PnTriangles, Pps, PpsOptions, SurfaceScalar};
use std::time::{Duration, Instant};

fn oracle_work<S: SurfaceScalar>(k: &SimplicialSurface, pps: &Pps) -> f64 {
    let c = pps.consts::<S>(256);
    let mut acc = 0.0;
    for f in k.faces().take(8) {
        let b = [0.2, 0.3, 0.5].map(|x| S::from_f64(x, 256));
        if let Ok(e) = pps.eval(f, &b, &c) {
            acc += e.point[0].to_f64();
        }
    }
    for v in k.vertices().take(4) {
        if let Ok(t) = pps.theta(v, &P2::<S>::from_f64(0.1, 0.05, 256), &c) {
            acc += t[0].to_f64();
        }
    }
    acc
}

fn time(f: impl Fn()) -> Duration {
    f();
    let t = Instant::now();
    for _ in 0..3 {
        f();
    }
    t.elapsed() / 3
}

fn bench(c: &mut Criterion) {
    let Some(k) = validate(&icosahedron()).surface else {
        return;
    };
    let pps = Pps::build(&k, &PnTriangles::new(&k), PpsOptions::default());
    let ch4 = |b: MpBackend| Ch4Options {
        precision: Precision::Mp(256),
        mp_backend: b,
        samples: 4,
        max_edge_configs: Some(8),
        max_triangle_configs: Some(8),
        max_star_configs: Some(4),
        ..Ch4Options::default()
    };
    for b in MpBackend::available() {
        let t4 = time(|| {
            run_chapter4(&k, &ch4(b));
        });
        let to = time(|| {
            let _ = match b {
                MpBackend::PureRust => oracle_work::<pseudomanifold::numeric::Mp>(&k, &pps),
                #[cfg(feature = "mpfr")]
                MpBackend::Mpfr => oracle_work::<pseudomanifold::numeric::MpMpfr>(&k, &pps),
            };
        });
        eprintln!(
            "{}: chapter 4 at mp:256 {:.3} s; oracle (8 eval + 4 θ) {:.4} s",
            b.describe(),
            t4.as_secs_f64(),
            to.as_secs_f64()
        );
    }
    let mut g = c.benchmark_group("mp_backends");
    g.sample_size(10);
    for b in MpBackend::available() {
        g.bench_function(
            format!("chapter4 mp:256 icosahedron ({})", b.name()),
            |bb| bb.iter(|| run_chapter4(&k, &ch4(b)).checks.len()),
        );
        g.bench_function(format!("oracle eval+theta 256 bits ({})", b.name()), |bb| {
            bb.iter(|| match b {
                MpBackend::PureRust => oracle_work::<pseudomanifold::numeric::Mp>(&k, &pps),
                #[cfg(feature = "mpfr")]
                MpBackend::Mpfr => oracle_work::<pseudomanifold::numeric::MpMpfr>(&k, &pps),
            })
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
