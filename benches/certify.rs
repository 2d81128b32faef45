//! Speed of the interval provers. Run: `cargo bench --bench certify`.
//! Small degrees only (the full M = 16 run is `ppm certify --max-degree 16 --jobs 2`, see
//! `certificates/`): one triangle configuration (L4.2.1 + L4.2.2), one edge (P4.2.3, L4.2.3,
//! P4.2.1), one vertex (the four star provers and the lens agreement), and a whole run for
//! M = 4 on one thread.

use criterion::{criterion_group, criterion_main, Criterion};
use pseudomanifold::certify::{all_configs, prove_config, run, ConfigKey, Model, Settings};

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("certify");
    g.sample_size(10);
    let (m, s) = (Model::paper(), Settings::default());
    for key in [
        ConfigKey::Triangle {
            m_u: 5,
            m_w: 7,
            m_x: 3,
            ccw: true,
        },
        ConfigKey::Triangle {
            m_u: 16,
            m_w: 16,
            m_x: 16,
            ccw: false,
        },
        ConfigKey::Edge { m_u: 7, m_w: 12 },
        ConfigKey::Vertex { m: 7 },
    ] {
        g.bench_function(format!("{key}"), |b| b.iter(|| prove_config(key, &m, &s)));
    }
    let all = all_configs(4);
    g.bench_function("all configurations, M = 4, 1 job", |b| {
        b.iter(|| run(&all, 4, &m, &s, 1, None).map(|c| c.results.len()))
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
