//! `ppm sample --attributes curvature` writes no NaN (SPEC `C6.2-sample-finite`): on every good
//! corpus mesh and every bundled fixture, at levels 0–2, with S′ = PN triangles and S′ = the
//! Loop limit surface, every sampled normal, Gaussian and mean curvature is finite (the
//! library call behind the command: `surface::output::sample_surface_with`).

use crate::common;
use pseudomanifold::mesh::load_surface;
use pseudomanifold::surface::output::{sample_surface_with, Attributes};
use pseudomanifold::surface::pps::{Pps, PpsOptions};
use pseudomanifold::surface::profile::Profile;
use pseudomanifold::surface::target::{SPrime, SurfaceKind};
use std::path::{Path, PathBuf};

/// (sample values examined, the first non-finite one) of one mesh, one S′, levels 0–2.
fn sample_values(path: &Path, kind: SurfaceKind) -> (u64, Option<String>) {
    let k = load_surface(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let target = SPrime::for_profile(kind, &k, Profile::Paper)
        .unwrap_or_else(|e| panic!("{}: S′ = {}: {e}", path.display(), kind.name()));
    let pps = Pps::build(&k, target.as_target(), PpsOptions::default());
    let mut examined = 0u64;
    for level in 0..=2 {
        let m = sample_surface_with(&pps, level, Attributes::Curvature, None)
            .unwrap_or_else(|e| panic!("{} level {level}: {e}", path.display()));
        assert_eq!(m.normals.len(), m.positions.len());
        assert_eq!(m.gaussian.len(), m.positions.len());
        assert_eq!(m.mean.len(), m.positions.len());
        for (i, p) in m.positions.iter().enumerate() {
            let n = m.normals[i];
            let values = [p[0], p[1], p[2], n[0], n[1], n[2], m.gaussian[i], m.mean[i]];
            examined += 1;
            if let Some(bad) = values.iter().find(|x| !x.is_finite()) {
                return (
                    examined,
                    Some(format!(
                        "{} (S′ = {}), level {level}, sample {i} at {p:?}: non-finite value {bad} (normal {n:?}, K = {}, H = {})",
                        path.display(),
                        kind.name(),
                        m.gaussian[i],
                        m.mean[i]
                    )),
                );
            }
        }
    }
    (examined, None)
}

#[test]
fn c6_2_sample_finite_curvature_on_every_good_mesh_levels_0_to_2_pn_and_loop() {
    let mut meshes: Vec<PathBuf> = common::bundled_good();
    meshes.extend(
        common::corpus("c6_2_sample_finite_curvature_on_every_good_mesh_levels_0_to_2_pn_and_loop")
            .into_iter()
            .filter(|m| m.good)
            .map(|m| m.path),
    );
    assert!(!meshes.is_empty());
    let mut total = 0u64;
    for path in &meshes {
        for kind in [SurfaceKind::Pn, SurfaceKind::Loop] {
            let (n, bad) = sample_values(path, kind);
            assert!(bad.is_none(), "{}", bad.unwrap_or_default());
            assert!(n > 0, "{}: nothing sampled", path.display());
            total += n;
        }
    }
    eprintln!(
        "C6.2-sample-finite: {} meshes × (PN, Loop) × levels 0–2: {total} sample points, every normal and curvature finite",
        meshes.len()
    );
    crate::common::verdicts::record(
        "C6.2-sample-finite",
        crate::common::verdicts::Seen::Holds,
        total,
    );
}
