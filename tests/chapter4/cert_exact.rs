//! The exact arguments that close the certificates with no δ (module `certify::sector`, the
//! end intervals of `certify::prove_hausdorff`), and the planted faults each must refuse: a
//! moved lens corner (lens radius), a wrong sector bound, an arc stopping short of its end.

use pseudomanifold::certify::sector::{candidates, max_sheet, SectorBound};
use pseudomanifold::certify::{
    interval::{c, iv, Deg, Domain},
    prove_hausdorff_with, prove_lens_agreement, prove_star, prove_star_with, Model, Outcome,
    Settings,
};
use pseudomanifold::construction::maps::{in_omega_uw, in_omega_uw_lens, EdgeConfig, P2};

fn quick() -> Settings {
    Settings {
        max_depth: 20,
        budget: 200_000,
        fail_tol: 1e-9,
        ..Settings::default()
    }
}

fn lens(offset: f64) -> Model {
    Model {
        lens_radius_offset: offset,
        ..Model::paper()
    }
}

/// Both star properties, literal domains for every m ≤ 16 and lens domains for m ≤ 10, are
/// certified on the whole star: nothing unresolved, no δ (the tangency of non-adjacent lenses
/// at (1/2)e^{iπ/3} is decided by the sector argument). From m = 11 the lens domains still
/// refute, with witnesses both evaluators confirm: the exact argument hides no failure.
#[test]
fn c5_4_at_most_two_cert_c4_2_nonadjacent_disjoint_cert_exact_no_delta() {
    let mut n = 0;
    for m in 3..=16 {
        for nonadj in [false, true] {
            let r = prove_star(m, false, nonadj, &Model::paper(), &quick());
            assert_eq!(
                (r.outcome, r.unresolved, r.delta),
                (Outcome::Certified, 0, None),
                "m = {m}: {r:?}"
            );
            if m <= 10 {
                let r = prove_star(m, true, nonadj, &Model::paper(), &quick());
                assert_eq!(
                    (r.outcome, r.unresolved, r.delta),
                    (Outcome::Certified, 0, None),
                    "lens m = {m}: {r:?}"
                );
            }
        }
        n += 1;
    }
    for id in ["C5.4-at-most-two(cert)", "C4.2-nonadjacent-disjoint(cert)"] {
        crate::common::verdicts::record(id, crate::common::verdicts::Seen::Certified, n);
    }
    crate::common::verdicts::record(
        "C5.4-at-most-two[sec6.1.3](cert)",
        crate::common::verdicts::Seen::Certified,
        8,
    );
    for m in [11, 12, 13] {
        for nonadj in [false, true] {
            let r = prove_star(m, true, nonadj, &Model::paper(), &quick());
            assert_eq!(r.outcome, Outcome::Refuted, "lens m = {m}: {r:?}");
            let w = r.witness.expect("witness");
            assert!(w.f64_confirms && w.mp_confirms, "{w:?}");
        }
    }
}

/// A moved lens corner: lens radius cos(π/6) + 1e−2 makes non-adjacent lenses overlap near
/// their former tangency (refuted, witness confirmed); + 1e−6 leaves an overlap thinner than
/// the boxes, and Lemma A's premise R² ≤ 3/4 fails: never certified. A smaller radius keeps
/// the premise and the statement (certified).
#[test]
fn c4_2_nonadjacent_disjoint_sec6_1_3_cert_planted_moved_corner_refused() {
    for nonadj in [false, true] {
        let r = prove_star(6, true, nonadj, &lens(1e-2), &quick());
        assert_eq!(r.outcome, Outcome::Refuted, "{r:?}");
        let w = r.witness.expect("witness");
        assert!(w.f64_confirms && w.mp_confirms, "{w:?}");
        let r = prove_star(6, true, nonadj, &lens(1e-6), &quick());
        assert_ne!(r.outcome, Outcome::Certified, "{r:?}");
        let r = prove_star(6, true, nonadj, &lens(-1e-3), &quick());
        assert_eq!(r.outcome, Outcome::Certified, "{r:?}");
    }
    crate::common::verdicts::record(
        "C4.2-nonadjacent-disjoint[sec6.1.3](cert)",
        crate::common::verdicts::Seen::Fails,
        1,
    );
}

/// A wrong sector bound: h = π/6 (Lemma A false for R = √3/2) is refused by its premise, and
/// h = π/2 (true, too weak to separate sectors two apart) leaves the tangency open: neither
/// is certified; bounds outside 1..=3 are never applicable.
#[test]
fn c5_4_at_most_two_cert_planted_wrong_sector_bound_refused() {
    assert!(SectorBound::paper().premise(c(0.75)));
    assert!(!SectorBound::paper().premise(iv(0.75, 0.75 + f64::EPSILON)));
    assert!(!SectorBound { sixths: 1 }.premise(c(0.75)));
    for k in [0, 1, 3, 4, 7] {
        for nonadj in [false, true] {
            let r = prove_star_with(
                7,
                false,
                nonadj,
                &Model::paper(),
                &quick(),
                SectorBound { sixths: k },
            );
            assert_ne!(r.outcome, Outcome::Certified, "k = {k}: {r:?}");
            assert!(r.unresolved > 0 && r.delta.is_some(), "k = {k}: {r:?}");
        }
    }
}

/// Lemma B against the model's generic maps (f64): at every sample point of Ω_x that the
/// model puts in Ω_xk (literal, and the lens test for m ≤ 10), |α − πn_k/3| < π/3 with
/// n_k = k + m·w_k from p's principal angle, and the sector candidates of a point box contain
/// n_k. Samples: a polar grid and a ring around the tangency point (1/2)e^{iπ/3}.
#[test]
fn c5_4_at_most_two_cert_sector_lemma_holds_at_model_points() {
    use std::f64::consts::PI;
    let mut checked = 0u64;
    for m in [3u32, 4, 5, 7, 10, 13] {
        let d = Deg::new(m);
        let rm = (PI / m as f64).cos();
        let k_m = (PI / 6.0).cos() / rm;
        let mut pts: Vec<(f64, f64)> = Vec::new();
        for i in 0..180 {
            for l in 1..40 {
                pts.push((
                    -PI + 2.0 * PI * (i as f64 + 0.5) / 180.0,
                    rm * l as f64 / 40.0,
                ));
            }
        }
        // Around the tangency: α = π/3 (θ = 2π/m), ρ = 1/2.
        for i in 0..64 {
            let a = 2.0 * PI * i as f64 / 64.0;
            for eps in [1e-3, 1e-5, 1e-7] {
                let (t, rr) = (2.0 * PI / m as f64, 0.5 / k_m);
                pts.push((t + eps * a.cos() / rr, rr + eps * a.sin()));
            }
        }
        for (t, r) in pts {
            let p = P2::<f64>::new(r * t.cos(), r * t.sin());
            let mut inside = Vec::new();
            for k in 0..m {
                let e = EdgeConfig {
                    m_u: m,
                    i: k,
                    m_w: m,
                    j: 0,
                };
                let lit = in_omega_uw(&e, &p).is_true();
                let lns = m <= 10 && in_omega_uw_lens(&e, &p).is_true();
                if !(lit || lns) {
                    continue;
                }
                let tk = t - 2.0 * PI * k as f64 / m as f64;
                let w = (tk / (2.0 * PI)).round() as i64;
                let n = k as i64 + m as i64 * w;
                let off = m as f64 * t / 6.0 - PI * n as f64 / 3.0;
                assert!(
                    off.abs() < PI / 3.0 + 1e-9,
                    "m = {m}, k = {k}, θ = {t}, r = {r}"
                );
                let dom = if lit {
                    Domain::Literal
                } else {
                    Domain::Lens { r2: c(0.75) }
                };
                let cs = candidates(&d, k, c(t), c(r), dom, SectorBound::paper()).expect("premise");
                assert!(
                    cs.iter().any(|x| x.n == n),
                    "m = {m}, k = {k}: {cs:?} lacks {n}"
                );
                if lit {
                    inside.push(n);
                }
                checked += 1;
            }
            // The theorem on the model's literal domains: ≤ 2 labels, sector indices adjacent.
            assert!(inside.len() <= 2, "m = {m}, θ = {t}, r = {r}: {inside:?}");
            if let [a, b] = inside[..] {
                assert_eq!((a - b).abs(), 1, "m = {m}, θ = {t}, r = {r}");
            }
        }
        assert_eq!(max_sheet(m, Domain::Literal), 0);
        assert_eq!(
            max_sheet(m, Domain::Lens { r2: c(0.75) }),
            i64::from(m >= 11)
        );
    }
    assert!(checked > 10_000, "{checked}");
}

/// D4.1.9-lens(cert) exactly: certified with no δ for every m_u ≤ 10 — m_u = 10, whose cut
/// ray θ = π is tangent to D, included — and refuted from m_u = 11 (witness confirmed).
#[test]
fn d4_1_9_lens_cert_exact_no_delta_through_10() {
    for m in 3..=10 {
        let r = prove_lens_agreement(m, &Model::paper(), &quick());
        assert_eq!(
            (r.outcome, r.unresolved, r.delta),
            (Outcome::Certified, 0, None),
            "m = {m}: {r:?}"
        );
    }
    crate::common::verdicts::record(
        "D4.1.9-lens(cert)",
        crate::common::verdicts::Seen::Certified,
        8,
    );
    let r = prove_lens_agreement(11, &Model::paper(), &quick());
    assert_eq!(r.outcome, Outcome::Refuted, "{r:?}");
    let w = r.witness.expect("witness");
    assert!(w.f64_confirms && w.mp_confirms, "{w:?}");
}

/// L4.2.3(cert) to the arc ends: the t-intervals reach T = acos(1/√3) (|b|² ≥ 3/4 certified at
/// the last endpoint), certified with no δ. Planted: the range stopping 1e−9 or 1e−3 short of
/// the ends (a moved corner) is not certified, its gap reported as δ.
#[test]
fn l4_2_3_cert_arc_to_the_ends_and_planted_short_arc_refused() {
    for (mu, mw) in [(3, 3), (4, 9), (10, 32), (32, 3)] {
        let r = prove_hausdorff_with(mu, mw, &Model::paper(), &quick(), 1e-12);
        assert_eq!(
            (r.outcome, r.boxes, r.unresolved, r.delta),
            (Outcome::Certified, 256, 0, None),
            "({mu}, {mw}): {r:?}"
        );
        assert!(r.bound.expect("bound") < 1e-12 && r.centre_bound.expect("sep") > 0.0);
        for gap in [1e-9, 1e-3] {
            let r = prove_hausdorff_with(mu, mw, &Model::paper(), &quick(), -gap);
            assert_eq!(r.outcome, Outcome::CertifiedOutsideDelta, "{r:?}");
            assert!(r.delta.expect("gap") >= 0.99 * gap, "{r:?}");
        }
    }
    crate::common::verdicts::record("L4.2.3(cert)", crate::common::verdicts::Seen::Certified, 4);
}
