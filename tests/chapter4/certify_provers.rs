//! Certified interval provers on small degrees, and their refutations (planted faults and the
//! paper's own failures).

use pseudomanifold::certify::{
    all_configs, coverage, merge, prove_config, prove_inverse, prove_lens_agreement,
    prove_nonempty, prove_star, prove_triangle, run, shard, ConfigKey, Model, Outcome, Settings,
};
use pseudomanifold::construction::maps::{EdgeConfig, TriangleConfig};

fn quick() -> Settings {
    Settings {
        max_depth: 20,
        budget: 200_000,
        fail_tol: 1e-9,
        ..Settings::default()
    }
}

fn ok(o: Outcome) -> bool {
    matches!(o, Outcome::Certified | Outcome::CertifiedOutsideDelta)
}

#[test]
fn d4_1_9_lens_cert_agreement_certified_below_11_refuted_from_11() {
    for m in [3, 6, 10] {
        let r = prove_lens_agreement(m, &Model::paper(), &quick());
        assert!(ok(r.outcome), "m = {m}: {r:?}");
    }
    crate::common::verdicts::record(
        "D4.1.9-lens(cert)",
        crate::common::verdicts::Seen::Certified,
        3,
    );
    let r = prove_lens_agreement(12, &Model::paper(), &quick());
    assert_eq!(r.outcome, Outcome::Refuted, "{r:?}");
    let w = r.witness.expect("witness");
    assert!(w.f64_confirms && w.mp_confirms, "{w:?}");
}

#[test]
fn d4_1_9_lens_cert_planted_lens_radius_refuted() {
    // A lens radius off by 1e-2 is refuted with a witness both evaluators confirm.
    let model = Model {
        lens_radius_offset: 1e-2,
        label_shift: 0,
        fault: None,
    };
    let r = prove_lens_agreement(5, &model, &quick());
    assert_eq!(r.outcome, Outcome::Refuted, "{r:?}");
    let w = r.witness.expect("witness");
    assert!(w.f64_confirms && w.mp_confirms, "{w:?}");
    // Off by 1e-6, the disagreement lives within 1e-6 of ∂E, inside the band of width δ the
    // certificate excludes at this depth: the prover must not claim more than it proved.
    let model = Model {
        lens_radius_offset: 1e-6,
        label_shift: 0,
        fault: None,
    };
    let r = prove_lens_agreement(5, &model, &quick());
    assert_ne!(r.outcome, Outcome::Certified, "{r:?}");
    if r.outcome == Outcome::CertifiedOutsideDelta {
        assert!(r.delta.expect("δ reported") > 1e-6, "{r:?}");
    }
}

#[test]
fn c5_4_at_most_two_cert_and_c4_2_nonadjacent_disjoint_cert_literal_certified() {
    for m in [3, 4, 7, 12] {
        assert!(ok(
            prove_star(m, false, false, &Model::paper(), &quick()).outcome
        ));
        assert!(ok(
            prove_star(m, false, true, &Model::paper(), &quick()).outcome
        ));
    }
    for id in ["C5.4-at-most-two(cert)", "C4.2-nonadjacent-disjoint(cert)"] {
        crate::common::verdicts::record(id, crate::common::verdicts::Seen::Certified, 4);
    }
}

#[test]
fn c5_4_at_most_two_sec6_1_3_cert_refuted_from_11() {
    // Below 11 the lens domains keep the statement (certified on the whole star, as the
    // literal domains; `cert_exact.rs` asserts no δ): the first half of the row's verdict.
    for m in [3, 6, 10] {
        let r = prove_star(m, true, false, &Model::paper(), &quick());
        assert!(ok(r.outcome), "m = {m}: {r:?}");
    }
    crate::common::verdicts::record(
        "C5.4-at-most-two[sec6.1.3](cert)",
        crate::common::verdicts::Seen::Certified,
        3,
    );
    let r = prove_star(12, true, false, &Model::paper(), &quick());
    assert_eq!(r.outcome, Outcome::Refuted, "{r:?}");
    let w = r.witness.expect("witness");
    assert!(w.f64_confirms && w.mp_confirms, "{w:?}");
}

#[test]
fn c4_2_nonadjacent_disjoint_sec6_1_3_cert_refuted_at_12() {
    let r = prove_star(12, true, true, &Model::paper(), &quick());
    assert_eq!(r.outcome, Outcome::Refuted, "{r:?}");
    assert!(r.witness.expect("w").f64_confirms);
    crate::common::verdicts::record(
        "C4.2-nonadjacent-disjoint[sec6.1.3](cert)",
        crate::common::verdicts::Seen::Fails,
        1,
    );
}

#[test]
fn p4_2_1_cert_nonempty_certified() {
    for (a, b) in [(3, 3), (3, 9), (12, 5)] {
        let r = prove_nonempty(a, b, &Model::paper());
        assert_eq!(r.outcome, Outcome::Certified);
        // One certified point per direction; nothing unresolved, so no δ.
        assert_eq!((r.boxes, r.unresolved, r.delta), (2, 0, None), "{r:?}");
    }
    crate::common::verdicts::record("P4.2.1(cert)", crate::common::verdicts::Seen::Certified, 3);
}

#[test]
fn p4_2_3_cert_inverse_certified_and_planted_rotation_refuted() {
    let r = prove_inverse(5, 7, &Model::paper(), &quick());
    assert!(ok(r.outcome), "{r:?}");
    assert!(r.centre_bound.expect("centre bound") < 1e-12);
    let bad = Model {
        lens_radius_offset: 0.0,
        label_shift: 1,
        fault: None,
    };
    let r = prove_inverse(5, 7, &bad, &quick());
    assert_eq!(r.outcome, Outcome::Refuted, "{r:?}");
    let w = r.witness.expect("witness");
    assert!(w.f64_confirms && w.mp_confirms, "{w:?}");
}

#[test]
fn l4_2_1_cert_l4_2_2_cert_triangle_certified_and_planted_rotation_refuted() {
    let key = ConfigKey::Triangle {
        m_u: 3,
        m_w: 5,
        m_x: 7,
        ccw: true,
    };
    let rs = prove_triangle(key, &Model::paper(), &quick());
    assert_eq!(rs.len(), 2);
    for r in &rs {
        assert!(ok(r.outcome), "{r:?}");
    }
    assert!(rs[1].centre_bound.expect("centre") < 1e-12);
    let bad = Model {
        lens_radius_offset: 0.0,
        label_shift: 1,
        fault: None,
    };
    let rs = prove_triangle(key, &bad, &quick());
    assert_eq!(rs[1].outcome, Outcome::Refuted, "{rs:?}");
    assert!(rs[1].witness.as_ref().expect("w").f64_confirms);
}

#[test]
fn l4_2_3_cert_hausdorff_arc_certified() {
    let rs = prove_config(
        ConfigKey::Edge { m_u: 4, m_w: 9 },
        &Model::paper(),
        &quick(),
    );
    let h = rs
        .iter()
        .find(|r| r.property == "L4.2.3(cert)")
        .expect("hausdorff");
    assert!(ok(h.outcome), "{h:?}");
    assert!(h.bound.expect("bound") < 1e-12);
    // The whole open arc |t| < acos(1/√3), up to its ends (no δ): all 256 t-boxes in the
    // branch, none left over, and a positive separation away from the two end intervals
    // (the arc inside Ω_u's canonical image; at the ends the exact identity of the prover).
    assert_eq!(
        (h.outcome, h.boxes, h.unresolved, h.delta),
        (Outcome::Certified, 256, 0, None),
        "{h:?}"
    );
    assert!(h.centre_bound.expect("separation") > 0.0, "{h:?}");
    crate::common::verdicts::record(
        "L4.2.3(cert)",
        crate::common::verdicts::Seen::Certified,
        h.boxes,
    );
}

#[test]
fn cert_shard_merge_and_coverage() {
    let all = all_configs(3);
    assert_eq!(all.len(), 1 + 1 + 2);
    let s = quick();
    let a = run(&shard(&all, 1, 2), 3, &Model::paper(), &s, 1, Some((1, 2))).expect("run");
    let b = run(&shard(&all, 2, 2), 3, &Model::paper(), &s, 1, Some((2, 2))).expect("run");
    let m = merge(vec![a.clone(), b]).expect("merge");
    assert!(merge(vec![a.clone(), a]).is_err());
    let e = EdgeConfig::new(3, 1, 3, 2).expect("edge");
    let t = TriangleConfig::ccw(3, 3, 3, 0, 1, 2).expect("tri");
    let need = ConfigKey::all_for(&[3], &[e], &[t]).expect("keys");
    let cov = coverage(&m, &need);
    assert!(!cov.is_empty());
    for c in &cov {
        assert!(c.certified, "{c:?}");
    }
    let need4 = ConfigKey::all_for(&[4], &[], &[]).expect("keys");
    assert!(coverage(&m, &need4)
        .iter()
        .all(|c| !c.certified && !c.missing.is_empty()));
    crate::common::verdicts::record(
        "CERT-shard-merge",
        crate::common::verdicts::Seen::Holds,
        cov.len() as u64,
    );
}

#[test]
fn l4_2_1_cert_exact_no_delta_every_orientation_including_m_x_3_tangency() {
    // m_x = 3: the wrapped branch of Ω_xw is tangent to Ω_ux at one point (two disks of
    // radius √3/2 whose centres are √3 apart); the exact case analysis closes it, so no box is
    // left unresolved. Large degrees exercise the winding conditions.
    for (a, b, x) in [(3, 3, 3), (4, 9, 3), (7, 3, 5), (16, 11, 13)] {
        for ccw in [true, false] {
            let key = ConfigKey::Triangle {
                m_u: a,
                m_w: b,
                m_x: x,
                ccw,
            };
            let rs = prove_triangle(key, &Model::paper(), &quick());
            for r in &rs {
                assert_eq!(r.outcome, Outcome::Certified, "{r:?}");
                assert_eq!(r.unresolved, 0);
                assert_eq!(r.delta, None);
            }
            assert_eq!(rs[1].bound, Some(0.0), "{:?}", rs[1]);
            assert!(rs[1].centre_bound.expect("centre checks ran") < 1e-12);
        }
    }
    // Certified on the whole set (no δ), bound 0, on these 8 configurations; all 11664 up to
    // degree 20 are the committed summary's (`l4_2_1_cert_docs_…`).
    for id in ["L4.2.1(cert)", "L4.2.2(cert)"] {
        crate::common::verdicts::record(id, crate::common::verdicts::Seen::Certified, 8);
    }
}

#[test]
fn l4_2_1_cert_planted_rotation_not_certified() {
    // With a wrong rotation label the model's literal domains no longer match the closed
    // form: the inclusion prover must not certify (inconclusive or refuted).
    let bad = Model {
        lens_radius_offset: 0.0,
        label_shift: 1,
        fault: None,
    };
    let key = ConfigKey::Triangle {
        m_u: 4,
        m_w: 6,
        m_x: 5,
        ccw: false,
    };
    let rs = prove_triangle(key, &bad, &quick());
    assert!(!ok(rs[0].outcome), "{:?}", rs[0]);
    assert_eq!(rs[1].outcome, Outcome::Refuted, "{:?}", rs[1]);
}

#[test]
fn p4_2_3_cert_exact_bound_zero() {
    for (a, b) in [(3, 16), (12, 4), (7, 7)] {
        let r = prove_inverse(a, b, &Model::paper(), &quick());
        assert_eq!(r.outcome, Outcome::Certified, "{r:?}");
        assert_eq!(r.bound, Some(0.0));
        assert!(r.centre_bound.expect("centre checks ran") < 1e-12);
        crate::common::verdicts::record(
            "P4.2.3(cert)",
            crate::common::verdicts::Seen::Certified,
            r.boxes,
        );
    }
}

#[test]
fn cert_file_compaction_round_trip() {
    let all = all_configs(3);
    let c = run(&all, 3, &Model::paper(), &quick(), 1, None).expect("run");
    let mut f = c.clone();
    f.compact();
    assert!(!f.statements.is_empty());
    assert!(f.results.iter().all(|r| r.statement.is_empty()));
    let text = serde_json::to_string(&f).expect("ser");
    let mut back: pseudomanifold::certify::Certificate = serde_json::from_str(&text).expect("de");
    back.expand();
    assert_eq!(back.results, c.results);
}

#[test]
fn cert_check_spec_certificates_coverage_of_a_mesh() {
    use pseudomanifold::conditions::chapter4::certificate_coverage;
    use pseudomanifold::mesh::generate::octahedron;
    use pseudomanifold::mesh::validate::validate;
    let k = validate(&octahedron())
        .surface
        .expect("octahedron is a surface");
    // A certificate for degrees 3 only misses the octahedron's degree-4 configurations.
    let c3 = run(&all_configs(3), 3, &Model::paper(), &quick(), 1, None).expect("run");
    let cov = certificate_coverage(&k, &c3, "c3");
    assert!(cov.config_errors.is_empty());
    assert!(cov
        .properties
        .iter()
        .all(|p| !p.certified && !p.missing.is_empty()));
    // Degrees up to 4 cover it.
    let c4 = run(&all_configs(4), 4, &Model::paper(), &quick(), 1, None).expect("run");
    let cov = certificate_coverage(&k, &c4, "c4");
    assert!(!cov.properties.is_empty());
    for p in &cov.properties {
        assert!(p.certified, "{p:?}");
        // A complete run carries every property's f64 bound (SPEC CERT-f64-props); the
        // coverage reports the mesh's worst.
        assert!(p.f64_bound.is_some_and(|b| b > 0.0 && b < 1e-11), "{p:?}");
    }
    crate::common::verdicts::record(
        "CERT-check-spec",
        crate::common::verdicts::Seen::Holds,
        cov.properties.len() as u64,
    );
}

/// SPEC `X-planted-certify`: the certify provers under the harness rules, on planted models
/// (`Model::fault`: g_v⁻¹ NaN, or failing, at every point). A NaN enclosure at a box centre
/// of Ω_uw refutes (`enclosure_exceeds`), and both evaluators confirm the witness (they used
/// to compare `v > tol`, false for NaN); an evaluation error at a centre of Ω_uw, where the
/// branch conditions make both maps defined, refutes P4.2.3(cert) (it used to split the box
/// until the depth limit, ending "certified outside δ") and makes the triangle provers
/// inconclusive (their model cross-check fails; never certified); a prover allowed no box
/// examines nothing and is skipped (`boxes` counts evaluated boxes only).
#[test]
fn x_planted_certify_nan_error_and_empty_domain_are_reported() {
    use pseudomanifold::certify::EvalFault;
    use pseudomanifold::report::Verdict;
    let planted = |f| Model {
        fault: Some(f),
        ..Model::paper()
    };
    let key = ConfigKey::Triangle {
        m_u: 3,
        m_w: 5,
        m_x: 7,
        ccw: true,
    };
    // NaN.
    let r = prove_inverse(5, 7, &planted(EvalFault::Nan), &quick());
    assert_eq!(r.outcome, Outcome::Refuted, "{r:?}");
    let w = r.witness.as_ref().expect("witness");
    assert!(w.f64_confirms && w.mp_confirms, "{w:?}");
    let c = r.to_check_result();
    assert!(c.failed() && c.examined > 0, "{c:?}");
    crate::common::assert_caught(&c);
    let rs = prove_triangle(key, &planted(EvalFault::Nan), &quick());
    assert_eq!(rs[1].outcome, Outcome::Refuted, "{rs:?}");
    assert!(rs[1].witness.as_ref().expect("w").f64_confirms, "{rs:?}");
    // An evaluation error.
    let r = prove_inverse(5, 7, &planted(EvalFault::Error), &quick());
    assert_eq!(r.outcome, Outcome::Refuted, "{r:?}");
    let w = r.witness.as_ref().expect("witness");
    assert!(
        w.text.contains("fail to evaluate") && w.f64_confirms && w.mp_confirms,
        "{w:?}"
    );
    let c = r.to_check_result();
    assert!(c.failed() && c.examined > 0, "{c:?}");
    crate::common::assert_caught(&c);
    for r in prove_triangle(key, &planted(EvalFault::Error), &quick()) {
        assert_eq!(r.outcome, Outcome::Inconclusive, "{r:?}");
        assert!(!r.to_check_result().holds_with_evidence(), "{r:?}");
    }
    // Empty: a budget of no box.
    let none = Settings {
        budget: 0,
        ..quick()
    };
    let r = prove_inverse(5, 7, &Model::paper(), &none);
    assert_eq!((r.outcome, r.boxes), (Outcome::Inconclusive, 0), "{r:?}");
    let c = r.to_check_result();
    assert!(
        matches!(c.verdict(), Verdict::Skipped { .. }) && c.examined == 0,
        "{c:?}"
    );
    crate::common::verdicts::record(
        "X-planted-certify",
        crate::common::verdicts::Seen::Caught,
        3,
    );
}

/// `Iv::atan2` on a box that meets the negative x-axis with y straddling 0: Π's range is
/// (−π, π] (Def. 4.1.5), so the enclosure must hold the angles just above −π (y < 0) and
/// those up to π (y ≥ 0); a box off the cut stays in its own half-plane.
#[test]
fn bk_iv_enclose_iv_atan2_over_the_cut_holds_both_branches() {
    use pseudomanifold::numeric::interval::Interval;
    use pseudomanifold::numeric::scalar::Scalar;
    use pseudomanifold::numeric::Iv;
    let iv = |lo: f64, hi: f64| Iv(Interval::try_from((lo, hi)).expect("valid interval"));
    let (y, x) = (iv(-1e-3, 1e-3), iv(-1.0, -0.5));
    let r = y.atan2(&x);
    let mut examined = 0u64;
    for (py, px) in [
        (-1e-3, -1.0),
        (-1e-3, -0.5),
        (0.0, -1.0),
        (1e-3, -0.5),
        (1e-3, -1.0),
    ] {
        let a = f64::atan2(py, px);
        assert!(
            r.0.inf() <= a && a <= r.0.sup(),
            "atan2({py}, {px}) = {a} outside [{}, {}]",
            r.0.inf(),
            r.0.sup()
        );
        examined += 1;
    }
    let off = iv(0.1, 0.2).atan2(&x);
    assert!(
        off.0.inf() > std::f64::consts::FRAC_PI_2 && off.0.sup() <= std::f64::consts::PI + 1e-15
    );
    assert_eq!(examined, 5);
}
