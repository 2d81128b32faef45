//! Sec. 3.3's stereographic atlas of Sⁿ (n = 1, 2) in the sampled backend, and Def. 3.5.1 /
//! Prop. 3.5.1 (parametric pseudo-manifolds) on it and on the exact circle.

use crate::common;

use pseudomanifold::gluing::data::Idx;
use pseudomanifold::gluing::exact1d::Exact1d;
use pseudomanifold::gluing::file::read_gluing_file;
use pseudomanifold::gluing::ppm::{check_c, check_c_prime, check_c_second, check_p3_5_1};
use pseudomanifold::gluing::sampled::{self, SampleConfig};
use pseudomanifold::gluing::stereo::*;
use pseudomanifold::gluing::GluingData;
use pseudomanifold::report::CheckResult;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

fn load(name: &str) -> Exact1d {
    let p = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join(format!("examples/gluing/{name}.toml"));
    read_gluing_file(&p).expect("parses").data
}

fn caught(r: &CheckResult, kind: &str) {
    assert!(r.failed(), "{} missed the planted fault: {r:?}", r.id);
    assert!(r.witnesses.iter().any(|w| w.data["kind"] == kind), "{r:?}");
}

fn vd(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y) * (x - y))
        .sum::<f64>()
        .sqrt()
}

#[test]
fn d3_3_3_stereographic_atlas_is_an_atlas_n1_n2() {
    for n in [1, 2] {
        let mut rng = ChaCha8Rng::seed_from_u64(3);
        let r = check_atlas(n, inversion, 2000, &mut rng, 3);
        common::assert_holds(&r);
        assert_eq!(r.examined, 2000);
        // Planted: the wrong transition u/‖u‖ is caught.
        let bad = |u: &[f64]| {
            let s = u.iter().map(|c| c * c).sum::<f64>().sqrt();
            u.iter().map(|c| c / s).collect::<Vec<f64>>()
        };
        caught(&check_atlas(n, bad, 200, &mut rng, 3), "transition");
    }
}

#[test]
fn d3_3_1_stereographic_charts_are_homeomorphisms_onto_rn() {
    let mut rng = ChaCha8Rng::seed_from_u64(11);
    let mut worst: f64 = 0.0;
    for n in [1, 2, 3] {
        for _ in 0..500 {
            let x = random_sphere_point(n, &mut rng);
            if x[n] < 0.99 {
                worst = worst.max(vd(&phi_north_inv(&phi_north(&x)), &x));
            }
            if x[n] > -0.99 {
                worst = worst.max(vd(&phi_south_inv(&phi_south(&x)), &x));
            }
            // Onto ℝⁿ: any u has a preimage on the sphere.
            let u: Vec<f64> = x.iter().take(n).map(|c| 5.0 * c).collect();
            let p = phi_north_inv(&u);
            assert!((p.iter().map(|c| c * c).sum::<f64>() - 1.0).abs() < 1e-12);
            worst = worst.max(vd(&phi_north(&p), &u) / 25.0);
        }
    }
    assert!(worst < 1e-9, "worst deviation {worst}");
    common::verdicts::record("D3.3.1", common::verdicts::Seen::Holds, 3);
}

#[test]
fn d3_3_2_transition_functions_compose_charts_and_are_mutually_inverse() {
    let mut rng = ChaCha8Rng::seed_from_u64(12);
    for n in [1, 2] {
        for _ in 0..500 {
            let x = random_sphere_point(n, &mut rng);
            if x[n].abs() > 0.99 {
                continue;
            }
            let (un, us) = (phi_north(&x), phi_south(&x));
            // φ_SN = φ_S ∘ φ_N⁻¹ and φ_NS = φ_N ∘ φ_S⁻¹ = φ_SN⁻¹.
            let sn = phi_south(&phi_north_inv(&un));
            let ns = phi_north(&phi_south_inv(&us));
            assert!(vd(&sn, &us) < 1e-9 && vd(&ns, &un) < 1e-9);
            assert!(vd(&phi_north(&phi_south_inv(&sn)), &un) < 1e-9);
        }
    }
    common::verdicts::record("D3.3.2", common::verdicts::Seen::Holds, 2);
}

#[test]
fn c3_3_stereo_transition_is_inversion_on_rn_minus_origin() {
    let mut rng = ChaCha8Rng::seed_from_u64(13);
    for n in [1, 2, 3] {
        let mut worst: f64 = 0.0;
        for _ in 0..500 {
            let x = random_sphere_point(n, &mut rng);
            if x[n].abs() > 0.99 {
                continue;
            }
            let u = phi_north(&x);
            worst = worst.max(vd(&phi_south(&phi_north_inv(&u)), &inversion(&u)));
            worst = worst.max(vd(&inversion(&inversion(&u)), &u)); // a bijection: an involution
        }
        assert!(worst < 1e-12, "n = {n}: {worst}");
    }
    common::verdicts::record("C3.3-stereo-transition", common::verdicts::Seen::Holds, 3);
}

#[test]
fn c3_4_1_sphere_two_discs_glued_along_annulus_satisfy_def_3_4_1() {
    // The paper (end of Sec. 3.4): a 2-sphere from two open discs glued along an annulus is
    // reachable with Def. 3.4.1 (not with Grimm's embeddability requirement).
    let cfg = SampleConfig { seed: 1, n: 300 };
    let s1 = StereoSphere::<1>::new(2.0);
    for r in sampled::check_all(&s1, &cfg) {
        common::assert_holds_for("S¹", &r);
    }
    let s2 = StereoSphere::<2>::new(2.0);
    for r in sampled::check_all(&s2, &cfg) {
        common::assert_holds_for("S²", &r);
    }
    let (r, seps) = sampled::hausdorff::check_4_with_radii(&s2, &cfg);
    common::assert_holds(&r);
    assert!(!seps.is_empty());
    // Limits of the inner boundary ‖u‖ = 1/2 land on ‖v‖ = 2 = ∂Ω_2, far from every y on
    // ‖v‖ = 1/2: the radii found are large, not a numerical accident.
    assert!(
        seps.iter().all(|s| s.r_x >= 0.5 && s.r_y > 0.2),
        "{:?}",
        &seps[..2]
    );
    common::verdicts::record("C3.4.1-sphere-two-discs", common::verdicts::Seen::Holds, 2);
}

#[test]
fn d3_4_1_4_sampled_planted_shrunk_annulus_is_not_hausdorff() {
    // Gluing only 1/1.5 < ‖u‖ < 1.5 of discs of radius 2: the inner boundary circle of Ω_12
    // maps onto the outer boundary circle of Ω_21, which lies inside Ω_2 — a 2-D "fork".
    let cfg = SampleConfig { seed: 2, n: 200 };
    let mut s2 = StereoSphere::<2>::new(2.0);
    s2.glue_outer = 1.5;
    caught(&sampled::check_4(&s2, &cfg), "not_separated");
    common::assert_holds(&sampled::check_3c(&s2, &cfg));
}

#[test]
fn d3_5_1_c_stereographic_ppm_and_planted_wrong_parametrization() {
    let cfg = SampleConfig { seed: 4, n: 300 };
    let s2 = StereoSphere::<2>::new(2.0);
    let r = check_c(&s2, |i, p| s2.theta(i, p), &cfg);
    common::assert_holds(&r);
    assert!(r.examined > 100 && r.worst_deviation.is_some() && r.tolerance.is_some());
    // Planted: θ_2 = φ_N⁻¹ as well (wrong chart).
    let wrong = |i: Idx, p: &[f64; 2]| phi_north_inv(&s2.local(i, p));
    caught(&check_c(&s2, wrong, &cfg), "c");
}

#[test]
fn d3_5_1_c_prime_measured_on_stereo_and_planted_partial_gluing() {
    let cfg = SampleConfig { seed: 5, n: 200 };
    let s1 = StereoSphere::<1>::new(2.0);
    let r = check_c_prime(&s1, |i, p| s1.theta(i, p), &cfg);
    common::assert_holds(&r);
    // The measured gap is positive (θ_1 of the unglued cap stays away from θ_2(Ω_2)).
    assert!(r.worst_deviation.unwrap_or(0.0) > r.tolerance.unwrap_or(1.0));
    // Planted: glue only part of the overlap; θ_1(Ω_1) ∩ θ_2(Ω_2) is larger than θ_1(Ω_12).
    let mut part = StereoSphere::<1>::new(2.0);
    part.glue_outer = 1.5;
    caught(
        &check_c_prime(&part, |i, p| part.theta(i, p), &cfg),
        "coincidence",
    );
    let mut part2 = StereoSphere::<2>::new(2.0);
    part2.glue_outer = 1.5;
    caught(
        &check_c_prime(&part2, |i, p| part2.theta(i, p), &cfg),
        "coincidence",
    );
}

#[test]
fn d3_5_1_c_second_measured_and_planted_overlapping_unglued_charts() {
    // Two unglued intervals parametrized as disjoint segments of ℝ², then as overlapping ones.
    let mut g = Exact1d::default();
    g.add_domain(1, pseudomanifold::gluing::exact1d::data::iv(0, 2));
    g.add_domain(2, pseudomanifold::gluing::exact1d::data::iv(10, 12));
    let g = g.with_default_diagonal();
    let cfg = SampleConfig { seed: 6, n: 100 };
    let apart = |i: Idx, p: &[f64; 1]| {
        if i == 1 {
            vec![p[0], 0.0]
        } else {
            vec![p[0] - 10.0, 1.0]
        }
    };
    let r = check_c_second(&g, apart, &cfg);
    common::assert_holds(&r);
    assert!(
        (r.worst_deviation.unwrap_or(0.0) - 1.0).abs() < 1e-9,
        "gap is the segments' distance 1: {r:?}"
    );
    let overlap = |i: Idx, p: &[f64; 1]| {
        if i == 1 {
            vec![p[0], 0.0]
        } else {
            vec![p[0] - 9.0, 0.0]
        }
    };
    caught(&check_c_second(&g, overlap, &cfg), "coincidence");
}

/// θ for the circle glued from three intervals: the angle 2πw/6 of the world coordinate.
fn circle_theta(i: Idx, x: f64) -> Vec<f64> {
    let w = x - [0.0, 8.0, 16.0][(i as usize).saturating_sub(1).min(2)];
    let t = std::f64::consts::PI * w / 3.0;
    vec![t.cos(), t.sin()]
}

#[test]
fn d3_5_1_c_and_c_prime_hold_for_the_exact_circle_in_r2() {
    let g = load("circle3");
    let cfg = SampleConfig { seed: 8, n: 200 };
    common::assert_holds(&check_c(&g, |i, p| circle_theta(i, p[0]), &cfg));
    common::assert_holds(&check_c_prime(&g, |i, p| circle_theta(i, p[0]), &cfg));
}

#[test]
fn c3_5_1_overlap_c_implies_equal_images_of_gluing_domains() {
    // (C) ⇒ θ_i(Ω_ij) = θ_j(Ω_ji): each θ_i(x), x ∈ Ω_ij, is θ_j(φ_ji(x)) with φ_ji(x) ∈ Ω_ji,
    // and conversely through φ_ij. Checked on samples of the circle for every (i, j) ∈ K.
    let g = load("circle3");
    let mut rng = ChaCha8Rng::seed_from_u64(9);
    let mut n = 0;
    for (i, j) in g.k() {
        for x in g.sample_gluing_domain(i, j, &mut rng, 50) {
            let y = GluingData::<1>::phi(&g, j, i, &x).expect("φ_ji defined on Ω_ij");
            assert!(GluingData::<1>::in_gluing_domain(&g, j, i, &y));
            assert!(vd(&circle_theta(i, x[0]), &circle_theta(j, y[0])) < 1e-12);
            n += 1;
        }
    }
    assert!(n > 300);
    common::verdicts::record("C3.5.1-overlap", common::verdicts::Seen::Holds, n);
}

#[test]
fn p3_5_1_theta_factors_through_m_g_and_planted_inconsistent_theta() {
    let g = load("circle3");
    let r = check_p3_5_1(&g, circle_theta, 24);
    common::assert_holds(&r);
    assert!(r.examined > 50, "{r:?}");
    // Planted: θ_3 rotated — violates (C), so Θ is not well defined on M_G.
    let bad = |i: Idx, x: f64| {
        if i == 3 {
            circle_theta(i, x + 0.25)
        } else {
            circle_theta(i, x)
        }
    };
    caught(&check_p3_5_1(&g, bad, 24), "theta_not_constant");
}
