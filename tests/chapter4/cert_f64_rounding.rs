//! CERT-f64-rounding: the proven bounds on the f64 evaluator's rounding, checked against
//! 256-bit evaluations of the same generic maps at seeded points, and planted faults (a too
//! small libm claim, a mutated f64 map) that the check must catch.

use pseudomanifold::certify::{
    prove_f64_rounding, prove_f64_rounding_with, RoundTripVerdict, Settings,
};
use pseudomanifold::construction::maps::{self, omega_radius, EdgeConfig, Ppm, P2};
use pseudomanifold::construction::Paper;
use pseudomanifold::numeric::rounding::{Fe, LibmModel};
use pseudomanifold::numeric::{Interval, Mp, Scalar};
use rand::{Rng, SeedableRng};

const CONFIGS: [(u32, u32); 5] = [(3, 3), (4, 7), (6, 5), (7, 3), (8, 8)];

/// A libm claimed exact (0 ulp): false for the platform's sin, cos and atan2.
#[derive(Clone, Copy, Debug, Default)]
struct ZeroUlp;
impl LibmModel for ZeroUlp {
    const LIBM_ULPS: f64 = 0.0;
}

/// The paper's maps with h off by 1e−12 in f64 (a deliberately worse operation).
struct Sloppy;
impl Ppm<f64> for Sloppy {
    fn h(&self, p: &P2<f64>) -> P2<f64> {
        let q = maps::h(p);
        P2::new(q.x + 1e-12, q.y)
    }
}

/// |f64 point − exact point| (Euclidean), the exact one at 256 bits (`Mp`).
pub(crate) fn dist(a: &P2<f64>, b: &P2<Mp>) -> f64 {
    b.sub(&P2::<Mp>::from_f64(a.x, a.y, 256))
        .norm2()
        .sqrt()
        .to_f64()
}

/// |f64 − exact| of a scalar.
pub(crate) fn qerr(f: f64, m: &Mp) -> f64 {
    m.sub(&Mp::from_f64(f, 256)).abs().to_f64()
}

/// One seeded draw: an edge configuration with random labels and an f64 point of the disk of
/// radius r_u (uniform by area).
pub(crate) fn labelled_disk_point(
    rng: &mut rand::rngs::StdRng,
    m_u: u32,
    m_w: u32,
) -> (EdgeConfig, [f64; 2]) {
    let r_u = (std::f64::consts::PI / m_u as f64).cos();
    let e = EdgeConfig::new(m_u, rng.gen_range(0..m_u), m_w, rng.gen_range(0..m_w))
        .expect("valid labels");
    let (t, r) = (
        rng.gen_range(-std::f64::consts::PI..std::f64::consts::PI),
        r_u * rng.gen_range(0.0f64..1.0).sqrt(),
    );
    (e, [r * t.cos(), r * t.sin()])
}

/// Seeded points of Ω_uw (decided at 256 bits), random labels: (edge, point).
fn points(m_u: u32, m_w: u32, n: usize, seed: u64) -> Vec<(EdgeConfig, [f64; 2])> {
    let mut rng = rand::rngs::StdRng::seed_from_u64(seed);
    let mut out = Vec::new();
    while out.len() < n {
        let (e, p) = labelled_disk_point(&mut rng, m_u, m_w);
        if Paper
            .in_omega_uw_literal(&e, &P2::<Mp>::from_f64(p[0], p[1], 256))
            .is_true()
        {
            out.push((e, p));
        }
    }
    out
}

#[test]
fn cert_f64_rounding_bounds_hold_against_mp256_at_seeded_points() {
    let s = Settings::default();
    let (mut ratio, mut rt_ratio, mut g_ratio): (f64, f64, f64) = (0.0, 0.0, 0.0);
    let mut worst_rt: f64 = 0.0;
    let mut checked = 0u64;
    for (m_u, m_w) in CONFIGS {
        let b = prove_f64_rounding(m_u, m_w, &s);
        let (phi, inner, rt) = (
            b.phi.expect("φ bounded"),
            b.inner.expect("inner bounded"),
            b.roundtrip.expect("round trip bounded"),
        );
        assert_eq!(b.unresolved, 0, "({m_u},{m_w}): {b:?}");
        assert!(
            phi < 1e-12 && inner < 1e-12 && b.outer < 1e-14,
            "({m_u},{m_w}): {b:?}"
        );
        // The stage-wise bound (module `certify::f64_roundtrip`) is below the literal test's
        // tolerance: the round-trip decision is certified exact; the bound is checked below.
        assert!(rt < b.roundtrip_tol, "({m_u},{m_w}): {b:?}");
        assert!(b.roundtrip_exact, "({m_u},{m_w}): {b:?}");
        assert_eq!(b.roundtrip_verdict, Some(RoundTripVerdict::Exact));
        assert_eq!(b.roundtrip_unresolved, Some(0));
        let (gv, gvi) = (
            b.g_v.expect("g_v bounded"),
            b.g_v_inv.expect("g_v⁻¹ bounded"),
        );
        for (e, p) in points(m_u, m_w, 300, 11 * m_u as u64 + m_w as u64) {
            let (pf, pm) = (P2::new(p[0], p[1]), P2::<Mp>::from_f64(p[0], p[1], 256));
            // φ_wu (Def. 4.1.10; the membership of p is decided above).
            let qf = Paper.g_uw_formula(&e, &pf).expect("f64 φ");
            let qm = Paper.g_uw_formula(&e, &pm).expect("mp φ");
            let d = dist(&qf, &qm);
            assert!(d <= phi, "({m_u},{m_w}) {e:?} p = {p:?}: {d:e} > {phi:e}");
            ratio = ratio.max(d / phi);
            // The three decisions of the literal test.
            let s1 = |q: &P2<f64>| q.norm2() - omega_radius::<f64>(e.m_u, 53).sqr();
            let s1m = pm.norm2().sub(&omega_radius::<Mp>(e.m_u, 256).sqr());
            assert!(qerr(s1(&pf), &s1m) <= b.outer);
            let er = e.reversed();
            let (gf, gm) = (
                Paper.g_uw_inv(&er, &pf).expect("f64 q"),
                Paper.g_uw_inv(&er, &pm).expect("mp q"),
            );
            let s2f = gf.norm2() - omega_radius::<f64>(m_w, 53).sqr();
            let s2m = gm.norm2().sub(&omega_radius::<Mp>(m_w, 256).sqr());
            assert!(qerr(s2f, &s2m) <= inner, "({m_u},{m_w}) p = {p:?}");
            let bf = Paper.g_uw_formula(&er, &gf).expect("f64 round trip");
            let bm = Paper.g_uw_formula(&er, &gm).expect("mp round trip");
            assert!(dist(&bf, &bm) <= rt, "({m_u},{m_w}) p = {p:?}");
            rt_ratio = rt_ratio.max(dist(&bf, &bm) / rt);
            worst_rt = worst_rt.max(dist(&bf, &bm));
            // g_v and g_v⁻¹ alone at the f64 points φ_wu feeds them: a = R_(u,w)(p) and
            // c = h(g_u(a)) (exact inputs for both evaluators).
            let a = Paper.r_uw(&e, &pf);
            let (am, ga) = (a.convert::<Mp>(256), maps::g_v(m_u, &a).expect("g_u"));
            let d = dist(&ga, &maps::g_v(m_u, &am).expect("mp g_u"));
            assert!(d <= gv, "({m_u},{m_w}) p = {p:?}: g_v {d:e} > {gv:e}");
            let cc = maps::h(&ga);
            let gi = maps::g_v_inv(m_w, &cc).expect("g_w⁻¹");
            let d = dist(
                &gi,
                &maps::g_v_inv(m_w, &cc.convert::<Mp>(256)).expect("mp"),
            );
            assert!(d <= gvi, "({m_u},{m_w}) p = {p:?}: g_v⁻¹ {d:e} > {gvi:e}");
            g_ratio = g_ratio.max(d / gvi);
            checked += 1;
        }
    }
    // Not vacuous: the worst point uses a visible part of the bound.
    assert!(ratio > 1e-3, "max |f64 − mp| / bound = {ratio:e}");
    assert!(
        rt_ratio > 1e-3,
        "round trip: max |f64 − mp| / bound = {rt_ratio:e}"
    );
    eprintln!("CERT-f64-rounding: {checked} points, max |f64 − mp| / bound (φ) = {ratio:.3e}, round trip {rt_ratio:.3e} (worst {worst_rt:.3e}), g_v⁻¹ {g_ratio:.3e}");
    crate::common::verdicts::record(
        "CERT-f64-rounding",
        crate::common::verdicts::Seen::Certified,
        checked,
    );
}

#[test]
fn cert_f64_rounding_planted_mutated_map_exceeds_the_bound() {
    let (m_u, m_w) = (4, 7);
    let phi = prove_f64_rounding(m_u, m_w, &Settings::default())
        .phi
        .expect("φ bounded");
    let pts = points(m_u, m_w, 100, 5);
    let caught = pts
        .iter()
        .filter(|(e, p)| {
            let qf = Sloppy.g_uw_formula(e, &P2::new(p[0], p[1])).expect("f64 φ");
            let qm = Paper
                .g_uw_formula(e, &P2::<Mp>::from_f64(p[0], p[1], 256))
                .expect("mp φ");
            dist(&qf, &qm) > phi
        })
        .count();
    assert_eq!(caught, pts.len(), "bound {phi:e}");
    crate::common::verdicts::record(
        "CERT-f64-rounding",
        crate::common::verdicts::Seen::Caught,
        pts.len() as u64,
    );
}

/// The paper's maps with h scaled by 1 + 1e−10 in f64 (h∘h is no longer the identity; a
/// constant shift would cancel in the round trip, h being an involution).
struct SloppyScale;
impl Ppm<f64> for SloppyScale {
    fn h(&self, p: &P2<f64>) -> P2<f64> {
        let q = maps::h(p);
        P2::new(q.x * (1.0 + 1e-10), q.y)
    }
}

/// |f64 round trip − exact round trip| of the literal test (Def. 4.1.9) for the model `m`.
fn roundtrip_err(m: &impl Ppm<f64>, e: &EdgeConfig, p: [f64; 2]) -> f64 {
    let er = e.reversed();
    let (pf, pm) = (P2::new(p[0], p[1]), P2::<Mp>::from_f64(p[0], p[1], 256));
    let gf = m.g_uw_inv(&er, &pf).expect("f64 q");
    let gm = Paper.g_uw_inv(&er, &pm).expect("mp q");
    let bf = m.g_uw_formula(&er, &gf).expect("f64 round trip");
    let bm = Paper.g_uw_formula(&er, &gm).expect("mp round trip");
    dist(&bf, &bm)
}

#[test]
fn cert_f64_rounding_planted_too_small_roundtrip_bound_is_violated() {
    // (a) The bound computed with the unit roundoff taken as 2⁻⁶³ instead of 2⁻⁵³: every term
    // of the stage-wise bound is linear in u (up to the 2⁻¹⁰⁷⁴ underflow terms), so it is the
    // certified bound / 2¹⁰. MPFR-256 at seeded points exceeds it.
    // (b) A mutated f64 map (h scaled by 1 + 1e−10) exceeds the certified bound at almost every
    // point.
    let s = Settings::default();
    let (mut violated, mut caught, mut n) = (0, 0, 0);
    for (m_u, m_w) in CONFIGS {
        let rt = prove_f64_rounding(m_u, m_w, &s)
            .roundtrip
            .expect("round trip bounded");
        let planted = rt / 1024.0;
        for (e, p) in points(m_u, m_w, 300, 11 * m_u as u64 + m_w as u64) {
            violated += (roundtrip_err(&Paper, &e, p) > planted) as u32;
            caught += (roundtrip_err(&SloppyScale, &e, p) > rt) as u32;
            n += 1;
        }
    }
    assert!(violated > 0, "{violated}");
    // Measured: 1497 of 1500 (where the two scaled h nearly undo each other it stays within).
    assert!(
        caught * 10 >= n * 9,
        "mutated h caught at {caught} of {n} points"
    );
    eprintln!("planted round-trip bound (u = 2⁻⁶³) violated at {violated} of {n} points, mutated h at {caught}");
    crate::common::verdicts::record(
        "CERT-f64-rounding",
        crate::common::verdicts::Seen::Caught,
        violated as u64 + caught as u64,
    );
}

#[test]
fn cert_f64_rounding_planted_zero_ulp_libm_claim_is_violated() {
    // Each libm function under a 0-ulp claim: the f64 result differs from the exact one by more
    // than the claimed enclosure at some seeded point.
    let mut rng = rand::rngs::StdRng::seed_from_u64(3);
    let pt = |x: f64| Fe::<ZeroUlp>::exact(Interval::try_from((x, x)).expect("finite"));
    let (mut sin, mut cos, mut atan2) = (0, 0, 0);
    for _ in 0..500 {
        let (x, y): (f64, f64) = (rng.gen_range(0.1..3.0), rng.gen_range(0.1..3.0));
        let m = |v: f64| Mp::from_f64(v, 256);
        sin += (qerr(x.sin(), &m(x).sin()) > pt(x).sin().err()) as u32;
        cos += (qerr(x.cos(), &m(x).cos()) > pt(x).cos().err()) as u32;
        atan2 += (qerr(f64::atan2(y, x), &m(y).atan2(&m(x))) > pt(y).atan2(&pt(x)).err()) as u32;
    }
    assert!(sin > 0 && cos > 0 && atan2 > 0, "{sin} {cos} {atan2}");
    // The whole-domain bound depends on the claim: a smaller claim gives a smaller bound.
    let s = Settings::default();
    let (a, b) = (
        prove_f64_rounding(3, 5, &s).phi.expect("bounded"),
        prove_f64_rounding_with::<ZeroUlp>(3, 5, &s)
            .phi
            .expect("bounded"),
    );
    assert!(b < a, "{b:e} ≥ {a:e}");
}

#[test]
fn cert_f64_rounding_old_certificate_results_still_read() {
    let line = r#"{"key":{"kind":"edge","m_u":3,"m_w":3},"property":"P4.2.3(cert)","outcome":"certified","statement":"","bound":0.0,"centre_bound":8.245041225185166e-15,"delta":null,"boxes":247,"max_depth":8,"unresolved":0,"witness":null,"millis":26}"#;
    let r: pseudomanifold::certify::PropertyResult =
        serde_json::from_str(line).expect("a result without f64_rounding");
    assert!(r.f64_rounding.is_none());
}

#[test]
fn cert_f64_rounding_oracle_prints_the_certificate_bound_with_phi() {
    use pseudomanifold::certify::{prove_config, write_certificate, Certificate, ConfigKey, Model};
    use pseudomanifold::oracle::{Request, Session};
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let key = ConfigKey::Edge { m_u: 4, m_w: 4 };
    let cert = Certificate {
        format: "pseudomanifold-certificate/1".into(),
        max_degree: 4,
        model: "paper".into(),
        shard: None,
        configs: 1,
        results: prove_config(key, &Model::paper(), &Settings::default()),
        wall_millis: 0,
        jobs: 1,
        statements: Default::default(),
    };
    let path = std::env::temp_dir().join(format!("cert_f64_rounding_{}.json", std::process::id()));
    write_certificate(&cert, &path).expect("write");
    let mut s = Session::new();
    s.handle(&Request::Load {
        path: root.join("tests/data/octahedron.obj"),
    })
    .expect("octahedron");
    // Without a certificate: no bound. With it: the bound, and the measured difference obeys it.
    let before = (0..6)
        .find_map(|w| {
            s.handle(&Request::Phi {
                u: 0,
                w,
                p: [0.33, 0.0],
            })
            .ok()
        })
        .expect("a phi answer");
    let bound_of = |r: &pseudomanifold::oracle::Response| {
        r.info
            .as_ref()
            .and_then(|i| i.get("f64_error_bound"))
            .and_then(|b| b.as_f64())
    };
    assert_eq!(bound_of(&before), None);
    s.handle(&Request::SetCertificate { path: path.clone() })
        .expect("certificate");
    let _ = std::fs::remove_file(&path);
    let mut answered = 0;
    for w in 0..6 {
        // Points towards each label direction of the degree-4 vertex (one Ω_0w each).
        for k in 0..8 {
            let t = std::f64::consts::FRAC_PI_4 * k as f64 + 0.1;
            let p = [0.33 * t.cos(), 0.33 * t.sin()];
            let Ok(r) = s.handle(&Request::Phi { u: 0, w, p }) else {
                continue;
            };
            let (Some(d), Some(b)) = (r.difference, bound_of(&r)) else {
                continue;
            };
            assert!(d <= b, "w = {w}, p = {p:?}: difference {d:e} > bound {b:e}");
            answered += 1;
        }
    }
    assert!(answered >= 3, "{answered}");
}

#[test]
fn cert_f64_rounding_committed_m8_certificate_has_the_roundtrip_exact() {
    // The committed M = 8 certificate (SPEC `CERT-f64-rounding`): every edge configuration's
    // round trip certified exact by the stage-wise bound, with g_v and g_v⁻¹ bounded.
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let cert = pseudomanifold::certify::read_certificate(
        &root.join("certificates/certificate_M8.json.gz"),
    )
    .expect("certificates/certificate_M8.json.gz");
    let fr: Vec<_> = cert
        .results
        .iter()
        .filter_map(|r| r.f64_rounding.as_ref())
        .collect();
    assert_eq!(fr.len(), 36);
    for f in fr {
        assert!(f.roundtrip_exact, "{f:?}");
        assert_eq!(f.roundtrip_verdict, Some(RoundTripVerdict::Exact), "{f:?}");
        assert_eq!(f.roundtrip_unresolved, Some(0), "{f:?}");
        let rt = f.roundtrip.expect("bounded");
        assert!(rt < f.roundtrip_tol, "{f:?}");
        assert!(f.g_v.is_some_and(|g| g < 1e-14) && f.g_v_inv.is_some_and(|g| g < 1e-14));
    }
}

/// The rounding model's atan2 carries the error of either argument into its bound, also when
/// the other is exact: ∂atan2(y, x)/∂y = x/(x² + y²) = 0.8 and ∂/∂x = −y/(x² + y²) = −0.4 at
/// (x, y) = (1, 0.5). With both exact only libm's error is left.
#[test]
fn cert_f64_rounding_atan2_propagates_the_error_of_either_argument() {
    let pt = |x: f64| Interval::try_from((x, x)).expect("a point");
    let e = Interval::try_from((-1e-10, 1e-10)).expect("an interval");
    let (x, y): (Fe, Fe) = (Fe::exact(pt(1.0)), Fe::exact(pt(0.5)));
    let only_libm = y.atan2(&x).err();
    assert!(only_libm > 0.0 && only_libm < 1e-15, "{only_libm:e}");
    let y_err: Fe = Fe::new(pt(0.5), e);
    let x_err: Fe = Fe::new(pt(1.0), e);
    for (what, bound, least) in [
        ("y inexact", y_err.atan2(&x).err(), 0.8e-10),
        ("x inexact", y.atan2(&x_err).err(), 0.4e-10),
        ("both inexact", y_err.atan2(&x_err).err(), 0.8e-10),
    ] {
        assert!(bound >= least, "{what}: bound {bound:e} < {least:e}");
        assert!(
            bound < 1e-8,
            "{what}: bound {bound:e} is not a bound near 1e-10"
        );
    }
}
