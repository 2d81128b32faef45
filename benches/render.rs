//! Speed targets of `ppm render` and of the sampling it rests on (Sec. 6.2), side by side:
//! * a 1024×1024 render of good/koala.obj's PPS at level 1 (target < 2 s on 2 cores), whole
//!   pipeline from the built PPS: sampling with order-2 jets, raster, shading, PNG;
//! * `ppm sample --level 2` on koala (target ≤ 3 s with normals and curvatures): sampling
//!   with curvature (order-2 jets), normals only (order-1 jets) and positions only (f64 eval),
//!   next to the order-3 jets the sampler used before.
//!
//! Run: `cargo bench --bench render` (criterion; needs ../shared/meshes/good/koala.obj, else
//! a generated 20,000-triangle torus). The build of the PPS is not timed here (bench `surface`).

use criterion::Criterion;
use pseudomanifold::mesh::generate::torus;
use pseudomanifold::mesh::io::{read_mesh, ReadOptions};
use pseudomanifold::mesh::validate::validate;
use pseudomanifold::mesh::SimplicialSurface;
use pseudomanifold::render::source::pps_scene;
use pseudomanifold::render::{render_scene, RenderOptions};
use pseudomanifold::surface::jet::Jet;
use pseudomanifold::surface::output::{sample_pattern, sample_surface_with, Attributes};
use pseudomanifold::surface::{Consts, PnTriangles, Pps, PpsOptions};
use rayon::prelude::*;
use std::path::Path;

fn mesh() -> (String, SimplicialSurface) {
    let koala = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../shared/meshes/good/koala.obj");
    if let Ok(raw) = read_mesh(&koala, &ReadOptions::default()) {
        if let Some(k) = validate(&raw).surface {
            return ("koala".into(), k);
        }
    }
    (
        "torus 20k".into(),
        validate(&torus(100, 100)).surface.expect("torus"),
    )
}

fn bench(c: &mut Criterion) {
    let (name, k) = mesh();
    let pps = Pps::build(&k, &PnTriangles::new(&k), PpsOptions::default());
    let mut g = c.benchmark_group("render");
    g.sample_size(10);
    g.bench_function(format!("render {name} PPS level 1 1024x1024"), |b| {
        b.iter(|| {
            let scene = pps_scene(&pps, 1, true).expect("sample");
            let o = RenderOptions {
                width: 1024,
                height: 1024,
                ..RenderOptions::default()
            };
            render_scene(&scene, &o)
                .expect("render")
                .0
                .to_png()
                .expect("png")
                .len()
        })
    });
    for attrs in [
        Attributes::Curvature,
        Attributes::Normals,
        Attributes::Positions,
    ] {
        g.bench_function(format!("sample {name} level 2 {attrs:?}"), |b| {
            b.iter(|| {
                sample_surface_with(&pps, 2, attrs, None)
                    .expect("sample")
                    .positions
                    .len()
            })
        });
    }
    g.bench_function(
        format!("sample {name} level 2 order-3 jets (before)"),
        |b| {
            let pattern = sample_pattern(&pps, 2).expect("pattern");
            let cj: Consts<Jet<f64>> = pps.consts(53);
            b.iter(|| {
                pattern
                    .points
                    .par_iter()
                    .map(|s| pps.eval_geometry(s.face, s.bary, &cj).map(|x| x.2.gaussian))
                    .filter(|r| r.is_ok())
                    .count()
            })
        },
    );
    g.finish();
}

fn main() {
    let mut c = Criterion::default().configure_from_args();
    bench(&mut c);
    c.final_summary();
}
