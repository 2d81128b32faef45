//! CERT-f64-rounding on the ε-neighbourhood of Ω_uw and off it (module `certify::f64_outside`):
//! the bounds at f64 points in the band just outside Ω_uw and on the rest of Ω_u, checked
//! against 256-bit evaluations; planted faults the new arguments must refuse or catch.

use super::cert_f64_rounding::{dist, labelled_disk_point, qerr};
use pseudomanifold::certify::{
    attach_f64_bounds, prove_f64_rounding, run, ConfigKey, F64Rounding, Model, Settings, F64_NBHD,
};
use pseudomanifold::construction::maps::{self, omega_radius, EdgeConfig, Ppm, P2};
use pseudomanifold::construction::Paper;
use pseudomanifold::numeric::{Mp, Scalar, Trit};
use rand::{Rng, SeedableRng};

/// Both sides of 6, and degrees with the winding ≠ 0 sheets (m_u ≥ 11; 12 and 24 reach Π's cut).
const CONFIGS: [(u32, u32); 6] = [(3, 3), (4, 7), (8, 8), (12, 5), (24, 7), (32, 3)];

fn mp(p: [f64; 2]) -> P2<Mp> {
    P2::<Mp>::from_f64(p[0], p[1], 256)
}

fn in_uw(e: &EdgeConfig, p: [f64; 2]) -> bool {
    Paper.in_omega_uw_literal(e, &mp(p)).is_true()
}

/// The literal test's quantities |p|² − r_u², |q|² − r_w² at 256 bits and in f64.
fn quantities(e: &EdgeConfig, p: [f64; 2]) -> Option<[(f64, Mp); 2]> {
    let (pf, pm) = (P2::new(p[0], p[1]), mp(p));
    let er = e.reversed();
    let qf = Paper.g_uw_inv(&er, &pf).ok()?;
    let qm = Paper.g_uw_inv(&er, &pm).ok()?;
    Some([
        (
            pf.norm2() - omega_radius::<f64>(e.m_u, 53).sqr(),
            pm.norm2().sub(&omega_radius::<Mp>(e.m_u, 256).sqr()),
        ),
        (
            qf.norm2() - omega_radius::<f64>(e.m_w, 53).sqr(),
            qm.norm2().sub(&omega_radius::<Mp>(e.m_w, 256).sqr()),
        ),
    ])
}

/// Seeded f64 points within 0.9·ε of Ω_uw but outside it (decided at 256 bits): from a point
/// of Ω_uw along a random direction, the last point inside by bisection, then a random step
/// of at most 0.9·ε.
fn band_points(m_u: u32, m_w: u32, n: usize, seed: u64) -> Vec<(EdgeConfig, [f64; 2])> {
    let mut rng = rand::rngs::StdRng::seed_from_u64(seed);
    let mut out = Vec::new();
    let mut tries = 0;
    while out.len() < n && tries < 50 * n {
        tries += 1;
        let (e, p0) = labelled_disk_point(&mut rng, m_u, m_w);
        if !in_uw(&e, p0) {
            continue;
        }
        let a: f64 = rng.gen_range(-std::f64::consts::PI..std::f64::consts::PI);
        let dir = [a.cos(), a.sin()];
        let at = |s: f64| [p0[0] + s * dir[0], p0[1] + s * dir[1]];
        let (mut lo, mut hi) = (0.0f64, 2.0f64);
        // Past ~55 halvings `at(mid)` rounds to f64 points already decided: each is decided
        // once (the same answers, without repeating the 256-bit evaluation).
        let mut decided: Vec<([f64; 2], bool)> = Vec::new();
        let mut inside_uw = |q: [f64; 2]| match decided.iter().find(|(x, _)| *x == q) {
            Some(&(_, b)) => b,
            None => {
                let b = in_uw(&e, q);
                decided.push((q, b));
                b
            }
        };
        for _ in 0..80 {
            let mid = 0.5 * (lo + hi);
            if inside_uw(at(mid)) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        let inside = at(lo);
        if !in_uw(&e, inside) {
            continue;
        }
        let s = rng.gen_range(0.0..0.9 * F64_NBHD);
        let p = [inside[0] + s * dir[0], inside[1] + s * dir[1]];
        // f64 rounding of the step moves p by ≤ 1 ulp: still within ε of `inside`.
        if !in_uw(&e, p) && Paper.in_omega_uw_literal(&e, &mp(p)).is_false() {
            out.push((e, p));
        }
    }
    out
}

/// Seeded f64 points of Ω_u outside Ω_uw (256 bits), random labels; half of them within 1e−3
/// of Ω_uw's boundary (a point of Ω_u pushed out of Ω_uw along a random direction).
fn off_points(m_u: u32, m_w: u32, n: usize, seed: u64) -> Vec<(EdgeConfig, [f64; 2])> {
    let mut rng = rand::rngs::StdRng::seed_from_u64(seed);
    let mut out = Vec::new();
    while out.len() < n {
        let (e, p) = labelled_disk_point(&mut rng, m_u, m_w);
        let pm = mp(p);
        if maps::in_omega_v(m_u, &pm).is_true() && Paper.in_omega_uw_literal(&e, &pm).is_false() {
            out.push((e, p));
        }
    }
    out
}

fn proven(m_u: u32, m_w: u32) -> F64Rounding {
    let b = prove_f64_rounding(m_u, m_w, &Settings::default());
    assert_eq!(b.nbhd, Some(F64_NBHD), "({m_u},{m_w})");
    assert!(b.phi.is_some_and(|p| p < F64_NBHD), "({m_u},{m_w}): {b:?}");
    let o = b.outside.as_ref().expect("outside pass");
    assert_eq!(o.unresolved, 0, "({m_u},{m_w}): {o:?}");
    assert!(o.inner.is_some_and(|x| x < 1e-11), "({m_u},{m_w}): {o:?}");
    b
}

/// Is the f64 literal answer at p "out" unless a quantity lies within its margin of 0?
fn out_unless_margin(e: &EdgeConfig, p: [f64; 2], outer: f64, margin: f64) -> (bool, bool) {
    let ans = Paper.in_omega_uw_literal(e, &P2::new(p[0], p[1]));
    let within = quantities(e, p).is_some_and(|[(_, a), (_, b)]| {
        a.abs().to_f64() <= outer || (b.to_f64() >= 0.0 && b.to_f64() <= margin)
    });
    (ans == Trit::False, within)
}

#[test]
fn cert_f64_rounding_nbhd_and_outside_bounds_hold_against_mp256() {
    let (mut band_n, mut off_n, mut sheet_n, mut near_n) = (0u64, 0u64, 0u64, 0u64);
    let (mut phi_ratio, mut inner_ratio): (f64, f64) = (0.0, 0.0);
    for (i, (m_u, m_w)) in CONFIGS.into_iter().enumerate() {
        let b = proven(m_u, m_w);
        let (phi, inner) = (b.phi.expect("φ"), b.inner.expect("inner"));
        let o_inner = b.outside.as_ref().and_then(|o| o.inner).expect("margin");
        // The band: φ and inner hold there; the f64 test answers "out" unless a margin.
        for (e, p) in band_points(m_u, m_w, 60, 100 + i as u64) {
            let qf = Paper.g_uw_formula(&e, &P2::new(p[0], p[1])).expect("f64 φ");
            let qm = Paper.g_uw_formula(&e, &mp(p)).expect("mp φ");
            let d = dist(&qf, &qm);
            assert!(d <= phi, "({m_u},{m_w}) {e:?} p = {p:?}: {d:e} > {phi:e}");
            phi_ratio = phi_ratio.max(d / phi);
            let [(f1, x1), (f2, x2)] = quantities(&e, p).expect("q");
            assert!(qerr(f1, &x1) <= b.outer && qerr(f2, &x2) <= inner);
            inner_ratio = inner_ratio.max(qerr(f2, &x2) / inner);
            let (out, within) = out_unless_margin(&e, p, b.outer, inner);
            assert!(out || within, "({m_u},{m_w}) band p = {p:?}");
            band_n += 1;
        }
        // The rest of Ω_u: "out" unless |p|² − r_u² within outer or |q|² − r_w² ∈ [0, margin].
        let margin = inner.max(o_inner);
        for (e, p) in off_points(m_u, m_w, 300, 200 + i as u64) {
            let (out, within) = out_unless_margin(&e, p, b.outer, margin);
            assert!(out || within, "({m_u},{m_w}) {e:?} off p = {p:?}");
            let q = quantities(&e, p).expect("q");
            if q[1].1.to_f64() < 0.0 {
                // Exactly in Ω_w − {0}: out by the round trip (a winding ≠ 0 sheet).
                sheet_n += 1;
            } else if q[1].1.to_f64() < 1e-3 {
                near_n += 1;
            }
            off_n += 1;
        }
    }
    // Not vacuous: the band points exercise the bounds, the sheets occur (m_u ≥ 11).
    assert!(band_n >= 200 && off_n >= 1800, "{band_n} {off_n}");
    assert!(sheet_n > 20, "sheets {sheet_n}");
    assert!(
        phi_ratio > 1e-4 && inner_ratio > 1e-5,
        "{phi_ratio:e} {inner_ratio:e}"
    );
    eprintln!("CERT-f64-rounding nbhd/outside: {band_n} band points (φ ratio {phi_ratio:.2e}, inner {inner_ratio:.2e}), {off_n} points off Ω_uw ({sheet_n} in winding ≠ 0 sheets, {near_n} with |q|² − r_w² < 1e−3)");
    crate::common::verdicts::record(
        "CERT-f64-rounding",
        crate::common::verdicts::Seen::Certified,
        band_n + off_n,
    );
}

#[test]
fn cert_f64_rounding_planted_map_perturbed_just_outside_omega_uw_exceeds_the_bound() {
    /// h off by 1e−12 in f64 only where h's argument b lies outside the lens E (|b|² ≥ 3/4:
    /// p ∉ Ω_u, or |b − (1,0)|² ≥ 3/4: q ∉ Ω_w, both outside Ω_uw); the paper's h elsewhere.
    struct OffOutside;
    impl Ppm<f64> for OffOutside {
        fn h(&self, p: &P2<f64>) -> P2<f64> {
            let q = maps::h(p);
            if q.norm2() >= 0.75 || p.norm2() >= 0.75 {
                P2::new(q.x + 1e-12, q.y)
            } else {
                q
            }
        }
    }
    let (m_u, m_w) = (4, 7);
    let phi = proven(m_u, m_w).phi.expect("φ");
    let pts = band_points(m_u, m_w, 60, 9);
    let mut caught = 0;
    for (e, p) in &pts {
        let qf = OffOutside
            .g_uw_formula(e, &P2::new(p[0], p[1]))
            .expect("f64 φ");
        let qm = Paper.g_uw_formula(e, &mp(*p)).expect("mp φ");
        caught += (dist(&qf, &qm) > phi) as usize;
    }
    // Every band point sees the fault; the bound is exceeded there.
    assert!(
        pts.len() >= 40 && caught == pts.len(),
        "{caught} of {}",
        pts.len()
    );
    crate::common::verdicts::record(
        "CERT-f64-rounding",
        crate::common::verdicts::Seen::Caught,
        caught as u64,
    );
}

#[test]
fn cert_f64_rounding_outside_planted_shrunk_margin_is_exceeded() {
    // At points of Ω_u off Ω_uw with q ∉ Ω_w (exact |q|² ≥ r_w²) the measured f64 error of
    // |q|² − r_w² stays below the proven margin; the margin divided by 4096 is exceeded.
    let (m_u, m_w) = (8, 8);
    let b = proven(m_u, m_w);
    let margin = b
        .inner
        .expect("inner")
        .max(b.outside.as_ref().and_then(|o| o.inner).expect("m"));
    let mut worst: f64 = 0.0;
    for (e, p) in off_points(m_u, m_w, 400, 31) {
        let [_, (f, x)] = quantities(&e, p).expect("q");
        if x.to_f64() >= 0.0 {
            let d = qerr(f, &x);
            assert!(d <= margin, "{e:?} p = {p:?}: {d:e} > {margin:e}");
            worst = worst.max(d);
        }
    }
    assert!(
        worst > margin / 4096.0,
        "worst {worst:e} vs margin/4096 {:e}",
        margin / 4096.0
    );
    crate::common::verdicts::record(
        "CERT-f64-rounding",
        crate::common::verdicts::Seen::Caught,
        1,
    );
}

#[test]
fn l4_2_2_cert_l4_2_1_cert_planted_nbhd_below_phi_is_refused() {
    let (a, b, x) = (3u32, 4u32, 7u32);
    let mut keys = vec![
        ConfigKey::Edge { m_u: a, m_w: b },
        ConfigKey::Edge { m_u: x, m_w: b },
        ConfigKey::Edge { m_u: a, m_w: x },
        ConfigKey::Triangle {
            m_u: a,
            m_w: b,
            m_x: x,
            ccw: true,
        },
    ];
    keys.sort();
    let mut c = run(&keys, 7, &Model::paper(), &Settings::default(), 1, None).expect("certify");
    let tri = |c: &pseudomanifold::certify::Certificate, p: &str| {
        c.results
            .iter()
            .find(|r| matches!(r.key, ConfigKey::Triangle { .. }) && r.property == p)
            .and_then(|r| r.f64_bound.clone())
            .and_then(|f| f.bound)
    };
    let (gap, incl) = (tri(&c, "L4.2.2(cert)"), tri(&c, "L4.2.1(cert)"));
    assert!(gap.is_some() && incl.is_some(), "{gap:?} {incl:?}");
    // No band any more.
    assert!(c
        .results
        .iter()
        .all(|r| r.f64_bound.as_ref().is_none_or(|f| f.band.is_none())));
    let phi_ax = c
        .results
        .iter()
        .find_map(|r| match (r.key, &r.f64_rounding) {
            (ConfigKey::Edge { m_u, m_w }, Some(f)) if (m_u, m_w) == (a, x) => f.phi,
            _ => None,
        })
        .expect("φ(u,x)");
    // The planted neighbourhood of Ω_xw: smaller than φ(u, x), which it must cover.
    for plant in [Some(phi_ax / 2.0), None] {
        for r in c.results.iter_mut() {
            if let (ConfigKey::Edge { m_u, m_w }, Some(f)) = (r.key, r.f64_rounding.as_mut()) {
                if (m_u, m_w) == (x, b) {
                    f.nbhd = plant;
                }
            }
        }
        attach_f64_bounds(&mut c);
        assert_eq!(tri(&c, "L4.2.2(cert)"), None, "{plant:?}");
        assert_eq!(tri(&c, "L4.2.1(cert)"), None, "{plant:?}");
    }
    crate::common::verdicts::record("CERT-f64-props", crate::common::verdicts::Seen::Caught, 2);
}
