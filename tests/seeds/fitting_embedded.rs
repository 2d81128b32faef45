//! Is the fitted surface S embedded (SPEC `AF-embedded`), and the refinement at the base faces
//! where it crosses (SPEC `AF-refine-embedded`): S sampled at a stated level, the sample
//! validated as `ppm check` does, each offending sample triangle located at its base face.

use super::fitting::{fit, torus};
use crate::common::verdicts::{assert_caught, assert_holds_for, record, Seen};
use pseudomanifold::fitting::crossing::{check_embedded, check_sample, triangles_per_face};
use pseudomanifold::fitting::{fit_surface, FitOptions};
use pseudomanifold::mesh::VertexId;
use pseudomanifold::oracle::tsv_diff::diagonal;
use pseudomanifold::report::Verdict;
use pseudomanifold::surface::output::Attributes;

/// The torus's fit at 10⁻² is embedded at level 2 (the fit's own check, run again here), and
/// its last round records no crossing.
#[test]
fn af_embedded_holds_on_the_torus_fit() {
    let k = torus();
    let f = fit(&k, 1e-2);
    let c = check_embedded(&f.fitted.pps, 2);
    assert_eq!(c.triangles, f.surface.k.num_faces() * triangles_per_face(2));
    assert_eq!(c.result.examined, f.surface.k.num_faces() as u64);
    assert_holds_for("torus at 1e-2", &c.result);
    let last = f.rounds.last().expect("a round");
    assert_eq!(last.crossing_triangles, Some(0));
    assert_eq!(last.crossing_faces, Some(0));
    record("AF-embedded", Seen::Holds, c.result.examined);
}

/// Planted: the patches of one base vertex's corners moved across the torus's hole (by −2 times
/// the vertex's distance from the axis), so the sheet near it passes through the tube on the
/// other side: caught, with a witness naming a base face around that vertex and its sample
/// triangles.
#[test]
fn af_planted_crossing_sheets_are_caught_by_af_embedded() {
    let k = torus();
    let mut f = fit(&k, 1e-2);
    let v = VertexId(0);
    let p = f.surface.k.position(v);
    let pps = &mut f.fitted.pps;
    let ids: Vec<_> = pps.gluing.corners_at(v).map(|c| pps.gluing.id(c)).collect();
    for id in ids {
        for q in pps.patch_mut(id) {
            q[0] -= 2.0 * p[0];
            q[1] -= 2.0 * p[1];
        }
    }
    let c = check_embedded(&f.fitted.pps, 2);
    assert_caught(&c.result);
    let star: Vec<u32> = f.surface.k.faces_around(v).iter().map(|g| g.0).collect();
    assert!(
        c.faces.iter().any(|g| star.contains(g)),
        "a crossing base face around vertex 0 ({star:?}) is named: {:?}",
        c.faces
    );
    let w = c
        .result
        .witnesses
        .iter()
        .find(|w| {
            w.data["face"]
                .as_u64()
                .is_some_and(|g| star.contains(&(g as u32)))
        })
        .expect("a witness at a face around vertex 0");
    let g = w.data["face"].as_u64().expect("face") as usize;
    let per = triangles_per_face(2);
    let tris = w.data["triangles"].as_array().expect("triangles");
    assert!(!tris.is_empty());
    for t in tris {
        let t = t.as_u64().expect("a triangle") as usize;
        assert_eq!(t / per, g, "sample triangle {t} samples base face {g}");
    }
    assert!(c.offending_triangles >= tris.len());
    record("AF-planted", Seen::Caught, c.result.examined);
}

/// No sample triangle is `Skipped`, never `Holds`.
#[test]
fn af_embedded_empty_sample_is_skipped() {
    let c = check_sample(&[], &[], 0, 2);
    assert!(
        matches!(c.result.verdict(), Verdict::Skipped { .. }),
        "{:?}",
        c.result.verdict()
    );
    assert!(!c.result.failed() && !c.result.holds_with_evidence());
}

/// Planted: a NaN position of a sample point inside one base face's sample is an offence
/// located at that face; a sample with the wrong number of triangles per base face is an
/// offence (not located), never a pass.
#[test]
fn af_planted_nan_sample_position_is_caught_by_af_embedded() {
    let k = torus();
    let f = fit(&k, 1e-2);
    let m = f
        .fitted
        .pps
        .sample_surface_with(2, Attributes::Positions)
        .expect("the sample");
    let nf = f.surface.k.num_faces();
    let per = triangles_per_face(2);
    let clean = check_sample(&m.positions, &m.faces, nf, 2);
    assert_holds_for("torus sample", &clean.result);
    // A sample point used only by base face 5's triangles (inside that face).
    let mut pos = m.positions.clone();
    let inside = m.faces[5 * per..6 * per]
        .iter()
        .flatten()
        .copied()
        .find(|&p| {
            m.faces
                .iter()
                .enumerate()
                .filter(|(_, tri)| tri.contains(&p))
                .all(|(i, _)| i / per == 5)
        })
        .expect("an inner sample point of base face 5");
    pos[inside as usize] = [f64::NAN; 3];
    let c = check_sample(&pos, &m.faces, nf, 2);
    assert_caught(&c.result);
    assert_eq!(c.faces, vec![5], "the NaN is located at base face 5");
    // The wrong count: one base face fewer than the triangles say.
    let wrong = check_sample(&m.positions, &m.faces, nf - 1, 2);
    assert_caught(&wrong.result);
    assert!(wrong.faces.is_empty());
    record("AF-planted", Seen::Caught, c.result.examined);
}

/// The refinement at crossing base faces (SPEC `AF-refine-embedded`): spot_low_resolution at
/// ε = 10⁻² of the diagonal meets ε in its first round but the level-2 sample of that S
/// crosses (`AF-embedded` fails on it: the fit without the check, one round); the loop
/// refines at the crossing faces and ends with ε at every vertex and the sample embedded.
#[test]
fn af_refine_embedded_ends_with_af_embedded_holding_on_spot() {
    let Some(dir) = crate::common::shared_path("af_refine_embedded", "meshes/good") else {
        return;
    };
    let k = pseudomanifold::mesh::load_surface(&dir.join("spot_low_resolution.obj"))
        .expect("corpus mesh loads");
    let eps = 1e-2 * diagonal(&k);
    let mut o = FitOptions::new(eps);
    o.embed_level = None;
    let plain = fit_surface(&k, &o, |_| {}).expect("the fit without the check");
    assert_eq!(plain.rounds.len(), 1, "ε holds in the first round");
    let before = check_embedded(&plain.fitted.pps, 2);
    assert!(
        before.result.failed() && !before.faces.is_empty(),
        "the first round's S crosses at level 2"
    );
    let f = fit_surface(&k, &FitOptions::new(eps), |_| {}).expect("the fit");
    let first = &f.rounds[0];
    assert_eq!(first.crossing_faces, Some(before.faces.len()));
    assert_eq!(first.crossing_triangles, Some(before.offending_triangles));
    assert!(first.refine.is_some_and(|r| r.inserted > 0));
    let last = f.rounds.last().expect("a round");
    assert_eq!((last.offenders, last.crossing_faces), (0, Some(0)));
    let after = check_embedded(&f.fitted.pps, 2);
    assert_holds_for("spot at 1e-2", &after.result);
    for r in pseudomanifold::fitting::checks::run_fit_checks(&k, &f, 1) {
        assert_holds_for("spot at 1e-2", &r);
    }
    record("AF-embedded", Seen::Holds, after.result.examined);
}
