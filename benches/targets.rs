//! The construction's speed targets side by side, in one run, as ratios (docs/performance.md):
//!
//! * koala level 0, positions: read + validate (Sec. 3.1), build (Sec. 5.2), sample (Sec. 6.2);
//! * koala level 2 with normals and curvatures (order-2 jets);
//! * the (σ, v) construction (tutorial, Part IV) at level 1 next to the vertex construction at
//!   level 1, positions and curvatures, build included: the ratio is the target (≤ 1.3).
//!
//! Run: `RAYON_NUM_THREADS=1 cargo bench --bench targets` (and without the variable for all
//! cores). Each row is the median of `TARGETS_RUNS` runs (default 3). Uses
//! `../shared/meshes/good/koala.obj` when present, else a generated 20,000-triangle torus. The
//! whole process (`ppm sample`, file writing included) is timed by hyperfine, see
//! docs/performance.md.

use pseudomanifold::mesh::generate::torus;
use pseudomanifold::mesh::io::{read_mesh, ReadOptions};
use pseudomanifold::mesh::validate::validate;
use pseudomanifold::mesh::{RawMesh, SimplicialSurface};
use pseudomanifold::surface::output::{sample_surface_with, Attributes};
use pseudomanifold::surface::sigma_v::{SigmaVPps, DEFAULT_KAPPA, DEFAULT_PATCH_DEGREE};
use pseudomanifold::surface::{PnTriangles, Pps, PpsOptions};
use std::path::Path;
use std::time::Instant;

fn raw_mesh() -> (String, RawMesh) {
    let koala = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../shared/meshes/good/koala.obj");
    match read_mesh(&koala, &ReadOptions::default()) {
        Ok(raw) => ("koala".into(), raw),
        Err(_) => ("torus 20k".into(), torus(100, 100)),
    }
}

/// Median wall time of `runs` calls of `f`, in seconds.
fn median(runs: usize, mut f: impl FnMut()) -> f64 {
    let mut t: Vec<f64> = (0..runs)
        .map(|_| {
            let s = Instant::now();
            f();
            s.elapsed().as_secs_f64()
        })
        .collect();
    t.sort_by(f64::total_cmp);
    t[t.len() / 2]
}

fn vertex(k: &SimplicialSurface) -> Pps {
    Pps::build(k, &PnTriangles::new(k), PpsOptions::default())
}

fn sigma_v(k: &SimplicialSurface) -> SigmaVPps {
    SigmaVPps::build(k, &PnTriangles::new(k), DEFAULT_KAPPA, DEFAULT_PATCH_DEGREE)
        .expect("default κ")
}

fn main() {
    let runs = std::env::var("TARGETS_RUNS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(3usize)
        .max(1);
    let (name, raw) = raw_mesh();
    let threads = rayon::current_num_threads();
    let k = validate(&raw).surface.expect("a simplicial surface");
    println!("{name}, {threads} thread(s), median of {runs} runs");
    let row = |what: &str, t: f64, base: Option<f64>| match base {
        Some(b) => println!("  {what:<52} {t:>8.3} s  {:>6.2}×", t / b),
        None => println!("  {what:<52} {t:>8.3} s"),
    };
    let t_valid = median(runs, || assert!(validate(&raw).surface.is_some()));
    let t_build = median(runs, || drop(vertex(&k)));
    let pps = vertex(&k);
    let t_l0 = median(runs, || {
        sample_surface_with(&pps, 0, Attributes::Positions, None).expect("level 0");
    });
    let total = t_valid + t_build + t_l0;
    println!("level 0, positions (share of the sum):");
    row("validate (Sec. 3.1)", t_valid, Some(total));
    row("build the vertex PPS (Sec. 5.2)", t_build, Some(total));
    row("sample level 0, positions", t_l0, Some(total));
    row("sum", total, None);
    let t_l2c = median(runs, || {
        sample_surface_with(&pps, 2, Attributes::Curvature, None).expect("level 2");
    });
    let t_l2p = median(runs, || {
        sample_surface_with(&pps, 2, Attributes::Positions, None).expect("level 2");
    });
    println!("level 2 (ratio to positions):");
    row("sample level 2, positions", t_l2p, Some(t_l2p));
    row("sample level 2, normals and curvatures", t_l2c, Some(t_l2p));
    row(
        "validate + build + sample level 2 with curvatures",
        t_valid + t_build + t_l2c,
        None,
    );
    let v1p = median(runs, || {
        sample_surface_with(&vertex(&k), 1, Attributes::Positions, None).expect("vertex");
    });
    let s1p = median(runs, || {
        sigma_v(&k)
            .sample_surface_with(1, Attributes::Positions)
            .expect("sigma-v");
    });
    let v1c = median(runs, || {
        sample_surface_with(&vertex(&k), 1, Attributes::Curvature, None).expect("vertex");
    });
    let s1c = median(runs, || {
        sigma_v(&k)
            .sample_surface_with(1, Attributes::Curvature)
            .expect("sigma-v");
    });
    println!("build + sample level 1, (σ, v) / vertex (target ≤ 1.3):");
    row("vertex, positions", v1p, Some(v1p));
    row("(σ, v), positions", s1p, Some(v1p));
    row("vertex, normals and curvatures", v1c, Some(v1c));
    row("(σ, v), normals and curvatures", s1c, Some(v1c));
}
