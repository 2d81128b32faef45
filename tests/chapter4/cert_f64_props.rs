//! CERT-f64-props: the bounds on what the f64 evaluator computes for each certified property
//! (derived from CERT-f64-rounding and CERT-f64-g-chart by `certify::attach_f64_bounds`),
//! checked against 256-bit evaluations of the same generic maps at seeded points, and planted
//! faults (a mutated f64 g_v⁻¹, bounds divided by a factor) that the check must catch.

use super::cert_f64_rounding::{dist, qerr};
use pseudomanifold::certify::{run, Certificate, ConfigKey, F64Bound, Model, Settings};
use pseudomanifold::construction::maps::{self, omega_radius, EdgeConfig, Ppm, TriangleConfig, P2};
use pseudomanifold::construction::Paper;
use pseudomanifold::numeric::{Mp, Scalar};
use rand::{Rng, SeedableRng};

/// Triangles (m_u, m_w, m_x) checked: small and large degrees, both sides of 6.
const TRIANGLES: [(u32, u32, u32); 4] = [(3, 4, 7), (7, 3, 5), (8, 8, 8), (5, 9, 3)];

/// A certificate of the paper's model holding the vertices, edges and triangles needed.
fn cert() -> Certificate {
    let mut keys: Vec<ConfigKey> = Vec::new();
    for (a, b, x) in TRIANGLES {
        for (p, q) in [(a, b), (x, b), (a, x), (b, a)] {
            keys.push(ConfigKey::Edge { m_u: p, m_w: q });
        }
        keys.push(ConfigKey::Triangle {
            m_u: a,
            m_w: b,
            m_x: x,
            ccw: true,
        });
    }
    keys.extend([ConfigKey::Vertex { m: 4 }, ConfigKey::Vertex { m: 11 }]);
    keys.extend((3..=11).map(|w| ConfigKey::Edge { m_u: 4, m_w: w }));
    keys.extend([
        ConfigKey::Edge { m_u: 11, m_w: 11 },
        ConfigKey::Edge { m_u: 4, m_w: 4 },
    ]);
    keys.sort();
    keys.dedup();
    // What `ppm certify` runs on these configurations (results in their order, bounds
    // attached).
    run(&keys, 11, &Model::paper(), &Settings::default(), 1, None).expect("certify")
}

fn bound(c: &Certificate, key: ConfigKey, prop: &str) -> F64Bound {
    c.results
        .iter()
        .find(|r| r.key == key && r.property == prop)
        .and_then(|r| r.f64_bound.clone())
        .unwrap_or_else(|| panic!("{key} {prop}: no f64 bound"))
}

fn phi(c: &Certificate, m_u: u32, m_w: u32) -> f64 {
    c.results
        .iter()
        .find(|r| r.key == ConfigKey::Edge { m_u, m_w } && r.f64_rounding.is_some())
        .and_then(|r| r.f64_rounding.as_ref().and_then(|f| f.phi))
        .expect("φ bounded")
}

fn mp(p: [f64; 2]) -> P2<Mp> {
    P2::<Mp>::from_f64(p[0], p[1], 256)
}

/// Seeded points of u's chart in Ω_ux ∩ Ω_uw (= φ_xu⁻¹(Ω_xu ∩ Ω_xw), decided at 256 bits).
fn triangle_points(t: &TriangleConfig, n: usize, seed: u64) -> Vec<[f64; 2]> {
    let mut rng = rand::rngs::StdRng::seed_from_u64(seed);
    let r_u = (std::f64::consts::PI / t.m_u as f64).cos();
    let mut out = Vec::new();
    let mut tries = 0;
    while out.len() < n && tries < 200 * n {
        tries += 1;
        let (a, r) = (
            rng.gen_range(-std::f64::consts::PI..std::f64::consts::PI),
            r_u * rng.gen_range(0.0f64..1.0).sqrt(),
        );
        let p = [r * a.cos(), r * a.sin()];
        let pm = mp(p);
        if Paper.in_omega_uw_literal(&t.ux(), &pm).is_true()
            && Paper.in_omega_uw_literal(&t.uw(), &pm).is_true()
        {
            out.push(p);
        }
    }
    out
}

/// The f64 cocycle gap at p and its parts against 256 bits: (gap, |φ̂_wu − φ_wu|,
/// |φ̂_wx(φ̂_xu) − φ_wx(φ_xu)|), with the f64 g_v⁻¹ moved by `plant` in x.
fn cocycle(t: &TriangleConfig, p: [f64; 2], plant: f64) -> (f64, f64, f64) {
    // (A translated h would not do: (z ↦ a − e^{−iπ/3}z)³ = id for every a, so the cocycle
    // of such a model holds exactly.)
    struct Planted(f64);
    impl Ppm<f64> for Planted {
        fn g_v_inv(&self, m: u32, q: &P2<f64>) -> Result<P2<f64>, maps::MapError> {
            let p = Paper.g_v_inv(m, q)?;
            Ok(P2::new(p.x + self.0, p.y))
        }
    }
    let f = Planted(plant);
    let (pf, pm) = (P2::new(p[0], p[1]), mp(p));
    let l = f.g_uw_formula(&t.uw(), &pf).expect("f64 φ_wu");
    let r = f
        .g_uw_formula(&t.xw(), &f.g_uw_formula(&t.ux(), &pf).expect("f64 φ_xu"))
        .expect("f64 φ_wx");
    let lm = Paper.g_uw_formula(&t.uw(), &pm).expect("mp φ_wu");
    let rm = Paper
        .g_uw_formula(&t.xw(), &Paper.g_uw_formula(&t.ux(), &pm).expect("mp"))
        .expect("mp");
    (l.dist_f64(&r), dist(&l, &lm), dist(&r, &rm))
}

/// The two tested quantities of the f64 literal test of `e` at the f64 point p, and their
/// 256-bit values at p: [(f64, exact); 2].
fn literal_quantities(e: &EdgeConfig, p: [f64; 2]) -> [(f64, Mp); 2] {
    let (pf, pm) = (P2::new(p[0], p[1]), mp(p));
    let er = e.reversed();
    let qf = Paper.g_uw_inv(&er, &pf).expect("f64 q");
    let qm = Paper.g_uw_inv(&er, &pm).expect("mp q");
    [
        (
            pf.norm2() - omega_radius::<f64>(e.m_u, 53).sqr(),
            pm.norm2().sub(&omega_radius::<Mp>(e.m_u, 256).sqr()),
        ),
        (
            qf.norm2() - omega_radius::<f64>(e.m_w, 53).sqr(),
            qm.norm2().sub(&omega_radius::<Mp>(e.m_w, 256).sqr()),
        ),
    ]
}

/// The lens test's quantities |c|², |c − (1,0)|² at p (f64, exact).
fn lens_quantities(e: &EdgeConfig, p: [f64; 2]) -> Option<[(f64, Mp); 2]> {
    let (pf, pm) = (P2::new(p[0], p[1]), mp(p));
    let cf = Paper.h(&Paper.g_v(e.m_u, &Paper.r_uw(e, &pf)).ok()?);
    let cm = Paper.h(&Paper.g_v(e.m_u, &Paper.r_uw(e, &pm)).ok()?);
    let one_f = P2::new(1.0, 0.0);
    let one_m = P2::<Mp>::from_f64(1.0, 0.0, 256);
    Some([
        (cf.norm2(), cm.norm2()),
        (cf.sub(&one_f).norm2(), cm.sub(&one_m).norm2()),
    ])
}

#[test]
fn cert_f64_props_bounds_hold_against_mp256_at_seeded_points() {
    let c = cert();
    let (mut worst_gap, mut worst_comp, mut worst_margin): (f64, f64, f64) = (0.0, 0.0, 0.0);
    let mut n = 0u64;
    for (i, (a, b, x)) in TRIANGLES.into_iter().enumerate() {
        let key = ConfigKey::Triangle {
            m_u: a,
            m_w: b,
            m_x: x,
            ccw: true,
        };
        let coc = bound(&c, key, "L4.2.2(cert)");
        let incl = bound(&c, key, "L4.2.1(cert)");
        let (g, l) = (coc.bound.expect("gap bounded"), coc.lipschitz.expect("L"));
        let comp = phi(&c, x, b) + l * phi(&c, a, x);
        let marg = incl.bound.expect("margin bounded");
        assert_eq!(incl.decided, Some(true), "{key}");
        assert!(g < 1e-10 && marg < 1e-10, "{key}: {coc:?} {incl:?}");
        let mut rng = rand::rngs::StdRng::seed_from_u64(40 + i as u64);
        // Random labels: the bounds hold for every label triple.
        let t = TriangleConfig::ccw(
            a,
            b,
            x,
            rng.gen_range(0..a),
            rng.gen_range(0..b),
            rng.gen_range(0..x),
        )
        .expect("labels");
        let pts = triangle_points(&t, 150, 7 + i as u64);
        assert!(pts.len() >= 100, "{key}: {} points", pts.len());
        for p in pts {
            let (gap, dl, dr) = cocycle(&t, p, 0.0);
            assert!(gap <= g, "{key} p = {p:?}: f64 gap {gap:e} > {g:e}");
            assert!(
                dl <= phi(&c, a, b) && dr <= comp,
                "{key} p = {p:?}: {dl:e}, {dr:e}"
            );
            worst_gap = worst_gap.max(gap / g);
            worst_comp = worst_comp.max(dr / comp);
            // The three literal tests of L4.2.1's check, at p, at q̂ = φ̂_xu(p), at p.
            let qhat = Paper
                .g_uw_formula(&t.ux(), &P2::new(p[0], p[1]))
                .expect("q̂");
            for (e, at) in [(t.ux(), p), (t.xw(), [qhat.x, qhat.y]), (t.uw(), p)] {
                for (f, m) in literal_quantities(&e, at) {
                    let d = qerr(f, &m);
                    assert!(d <= marg, "{key} {e:?} at {at:?}: {d:e} > {marg:e}");
                    worst_margin = worst_margin.max(d / marg);
                }
            }
            n += 1;
        }
    }
    // L4.2.3: f64 points of Ω_uw next to the inner arc (b = 1 − (√3/2)e^{it}, pulled in by
    // 1e−9 in |b − 1| and rounded to f64).
    let mut worst_radius: f64 = 0.0;
    for (a, b) in [(3u32, 4u32), (7, 3), (8, 8), (4, 11)] {
        let fb = bound(&c, ConfigKey::Edge { m_u: a, m_w: b }, "L4.2.3(cert)");
        let rb = fb.bound.expect("radius bounded");
        let e = EdgeConfig::new(a, 1 % a, b, 2 % b).expect("labels");
        let tmax = (1.0f64 / 3f64.sqrt()).acos();
        for k in 0..64 {
            let t = -tmax + 2.0 * tmax * (k as f64 + 0.5) / 64.0;
            let s = 3f64.sqrt() / 2.0 * (1.0 - 1e-9);
            let bm = P2::<Mp>::from_f64(1.0 - s * t.cos(), -s * t.sin(), 256);
            let pm = Paper.r_uw_inv(&e, &Paper.g_v_inv(a, &Paper.h(&bm)).expect("arc"));
            let p = [pm.x.to_f64(), pm.y.to_f64()];
            if !Paper.in_omega_uw_literal(&e, &mp(p)).is_true() {
                continue;
            }
            let qf = Paper.g_uw_formula(&e, &P2::new(p[0], p[1])).expect("f64");
            let qm = Paper.g_uw_formula(&e, &mp(p)).expect("mp");
            let d = qerr(qf.norm2().sqrt(), &qm.norm2().sqrt());
            assert!(d <= rb, "({a},{b}) t = {t}: {d:e} > {rb:e}");
            worst_radius = worst_radius.max(d / rb);
            n += 1;
        }
    }
    // The lens rows: the lens test's quantities at seeded points of Ω_v, every label.
    let mut worst_lens: f64 = 0.0;
    for m in [4u32, 11] {
        let lb = bound(
            &c,
            ConfigKey::Vertex { m },
            "C5.4-at-most-two[sec6.1.3](cert)",
        )
        .bound
        .expect("lens margin");
        let db = bound(&c, ConfigKey::Vertex { m }, "D4.1.9-lens(cert)");
        if m == 4 {
            assert!(db.bound.is_some_and(|d| d >= lb), "{db:?}");
            assert_eq!(db.decided, Some(true));
        } else {
            // "Any m_w": the certificate lacks the edges (11, w), w < 11: no claim.
            assert_eq!(db.bound, None, "{db:?}");
        }
        let mut rng = rand::rngs::StdRng::seed_from_u64(m as u64);
        let r_v = (std::f64::consts::PI / m as f64).cos();
        for _ in 0..200 {
            let (a, r) = (
                rng.gen_range(-std::f64::consts::PI..std::f64::consts::PI),
                r_v * rng.gen_range(0.0f64..1.0).sqrt(),
            );
            let p = [r * a.cos(), r * a.sin()];
            let e = EdgeConfig::new(m, rng.gen_range(0..m), m, 0).expect("labels");
            for (f, q) in lens_quantities(&e, p).expect("off the origin") {
                let d = qerr(f, &q);
                assert!(d <= lb, "m = {m} p = {p:?}: {d:e} > {lb:e}");
                worst_lens = worst_lens.max(d / lb);
            }
            n += 1;
        }
    }
    // P4.2.1: its witness decisions are certified exact.
    for (a, b) in [(3u32, 4u32), (8, 8), (3, 7)] {
        let p = bound(&c, ConfigKey::Edge { m_u: a, m_w: b }, "P4.2.1(cert)");
        assert_eq!(p.decided, Some(true), "({a},{b}): {p:?}");
    }
    eprintln!(
        "worst measured / bound: gap {worst_gap:.3e}, composition {worst_comp:.3e}, literal quantities {worst_margin:.3e}, radius {worst_radius:.3e}, lens {worst_lens:.3e}"
    );
    assert!(worst_gap > 0.0 && worst_comp > 0.0 && worst_radius > 0.0 && worst_lens > 0.0);
    crate::common::verdicts::record(
        "CERT-f64-props",
        crate::common::verdicts::Seen::Certified,
        n,
    );
}

#[test]
fn cert_f64_props_planted_g_inv_off_by_1e_10_and_shrunk_bounds_are_caught() {
    let c = cert();
    let (a, b, x) = TRIANGLES[0];
    let key = ConfigKey::Triangle {
        m_u: a,
        m_w: b,
        m_x: x,
        ccw: true,
    };
    let g = bound(&c, key, "L4.2.2(cert)").bound.expect("gap bounded");
    let t = TriangleConfig::ccw(a, b, x, 0, 0, 0).expect("labels");
    let pts = triangle_points(&t, 100, 3);
    // A mutated f64 g_v⁻¹ (off by 1e−10): the f64 gap leaves the bound at every point.
    let caught = pts.iter().filter(|p| cocycle(&t, **p, 1e-10).0 > g).count();
    assert!(
        pts.len() >= 50 && caught == pts.len(),
        "{caught} of {}",
        pts.len()
    );
    // The bound divided by a factor: the measured gaps exceed it where they are large.
    let worst = pts
        .iter()
        .map(|p| cocycle(&t, *p, 0.0).0)
        .fold(0.0f64, f64::max);
    let shrunk = g / SHRINK;
    assert!(
        worst > shrunk,
        "worst gap {worst:e} vs bound/{SHRINK} = {shrunk:e}"
    );
    crate::common::verdicts::record(
        "CERT-f64-props",
        crate::common::verdicts::Seen::Caught,
        pts.len() as u64,
    );
}

/// The factor a planted too-small bound is divided by: the proven gap bound is a worst case
/// over every box and label of three edges, about 1100 times the largest gap measured at these
/// seeded points (4.5e−16 against 5.0e−13 at (3, 4, 7)).
const SHRINK: f64 = 4096.0;

#[test]
fn cert_f64_props_oracle_prints_the_decision_margin_with_member_answers() {
    use pseudomanifold::certify::write_certificate;
    use pseudomanifold::oracle::protocol::MemberTest;
    use pseudomanifold::oracle::{Request, Session};
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    // The octahedron: every degree 4.
    let keys = [
        ConfigKey::Vertex { m: 4 },
        ConfigKey::Edge { m_u: 4, m_w: 4 },
    ];
    let c = run(&keys, 4, &Model::paper(), &Settings::default(), 1, None).expect("certify");
    let lens = bound(
        &c,
        ConfigKey::Vertex { m: 4 },
        "C5.4-at-most-two[sec6.1.3](cert)",
    )
    .bound
    .expect("lens margin");
    let path = std::env::temp_dir().join(format!("cert_f64_props_{}.json.gz", std::process::id()));
    write_certificate(&c, &path).expect("write");
    let mut o = Session::new();
    o.handle(&Request::Load {
        path: root.join("tests/data/octahedron.obj"),
    })
    .expect("octahedron");
    let w = o
        .handle(&Request::Labels { v: 0 })
        .ok()
        .and_then(|r| r.value)
        .and_then(|v| v[0][0].as_u64())
        .expect("a neighbour of 0") as u32;
    let margin_of = |r: &pseudomanifold::oracle::Response| {
        r.info
            .as_ref()
            .and_then(|i| i.get("f64_decision_margin"))
            .and_then(|b| b.as_f64())
    };
    let member = |o: &mut Session, p: [f64; 2], test: MemberTest| {
        o.handle(&Request::Member { u: 0, w, p, test })
            .expect("member answer")
    };
    assert_eq!(
        margin_of(&member(&mut o, [0.3, 0.1], MemberTest::Literal)),
        None
    );
    o.handle(&Request::SetCertificate { path: path.clone() })
        .expect("the certificate reads");
    let _ = std::fs::remove_file(&path);
    let mut rng = rand::rngs::StdRng::seed_from_u64(17);
    let mut answered = 0;
    for _ in 0..60 {
        let p = [rng.gen_range(-0.7..0.7), rng.gen_range(-0.7..0.7)];
        for test in [MemberTest::Literal, MemberTest::Lens] {
            let r = member(&mut o, p, test);
            let m = margin_of(&r).expect("a certified configuration carries the margin");
            assert!(m > 0.0 && m < 1e-11, "{m:e}");
            if test == MemberTest::Lens {
                assert_eq!(m, lens);
            }
            // Random points miss the margins: f64 and MPFR decide alike.
            assert_eq!(r.difference, Some(0.0), "{p:?} {test:?}: {r:?}");
            answered += 1;
        }
    }
    assert_eq!(answered, 120);
}
