//! Chapter 4 maps: unit identities, f64 vs Mp agreement, findings, and planted faults.
use crate::common;
use pseudomanifold::construction::checks::*;
use pseudomanifold::construction::maps::*;
use pseudomanifold::construction::*;
use pseudomanifold::numeric::{Mp, Scalar, Trit};
use pseudomanifold::report::{CheckResult, Verdict};

const SEED: u64 = 20240601;
const N: usize = 240;

fn get<'a>(rs: &'a [CheckResult], id: &str) -> &'a CheckResult {
    rs.iter()
        .find(|r| r.id == id)
        .unwrap_or_else(|| panic!("no result {id}"))
}
fn holds(r: &CheckResult) -> bool {
    matches!(
        r.verdict(),
        Verdict::Holds | Verdict::HoldsRestricted { .. }
    )
}
fn assert_fails_with_witness(r: &CheckResult) {
    assert!(r.failed(), "{} should fail: {:?}", r.id, r.verdict());
    assert!(!r.witnesses.is_empty(), "{} failed without witness", r.id);
}
fn e(mu: u32, i: u32, mw: u32, j: u32) -> EdgeConfig {
    EdgeConfig::new(mu, i, mw, j).unwrap()
}

// ------------------------------------------------------------------ planted-fault models

/// Π with the IEEE branch [−π, π] (atan2 raw): θ = −π for y = −0.0.
struct RawAtan2;
impl<S: Scalar> Ppm<S> for RawAtan2 {
    fn polar(&self, p: &P2<S>) -> Result<Polar<S>, MapError> {
        Ok(Polar {
            theta: p.y.atan2(&p.x),
            r: p.norm2().sqrt(),
        })
    }
}
/// h(x, y) = (1 − (1 + 1e−6)x, −y): no longer an involution.
struct ScaledH;
impl<S: Scalar> Ppm<S> for ScaledH {
    fn h(&self, p: &P2<S>) -> P2<S> {
        let k = p.x.like_f64(1.0 + 1e-6);
        P2::new(p.x.like_f64(1.0).sub(&k.mul(&p.x)), p.y.neg())
    }
}
/// h(x, y) = (1/2 − x, −y): sends (1/2, 0) ∈ int C to the origin.
struct HalfH;
impl<S: Scalar> Ppm<S> for HalfH {
    fn h(&self, p: &P2<S>) -> P2<S> {
        P2::new(p.x.like_ratio(1, 2).sub(&p.x), p.y.neg())
    }
}
/// g_v with a jump of 1e−6 across the x-axis (both halves).
struct KinkG;
impl<S: Scalar> Ppm<S> for KinkG {
    fn g_v(&self, m: u32, p: &P2<S>) -> Result<P2<S>, MapError> {
        let q = g_v(m, p)?;
        let up = p.y.sign() == Some(std::cmp::Ordering::Greater);
        Ok(if up {
            P2::new(q.x.add(&q.x.like_f64(1e-6)), q.y)
        } else {
            q
        })
    }
}
/// g_v with radial factor ×0.99.
struct ShrunkG;
impl<S: Scalar> Ppm<S> for ShrunkG {
    fn g_v(&self, m: u32, p: &P2<S>) -> Result<P2<S>, MapError> {
        let q = g_v(m, p)?;
        Ok(q.scale(&p.x.like_ratio(99, 100)))
    }
}
/// Canonical lens with D centred at (4/5, 0) instead of (1, 0).
struct ShiftedLens;
impl<S: Scalar> Ppm<S> for ShiftedLens {
    fn in_canonical_lens(&self, q: &P2<S>) -> Trit {
        in_lens_with_centre(q, 4, 0, 5)
    }
}
/// φ_wu(p) + (1e−6, 0).
struct ShiftedPhi;
impl<S: Scalar> Ppm<S> for ShiftedPhi {
    fn phi_wu(&self, pair: &VertexPair, p: &P2<S>) -> Result<P2<S>, MapError> {
        let q = Paper.phi_wu(pair, p)?;
        Ok(P2::new(q.x.add(&q.x.like_f64(1e-6)), q.y))
    }
}
/// φ_wu(p) + (1e−6, 0) on one side of the lens axis (in the g_u∘R_(u,w) frame): a jump.
struct KinkPhi;
impl<S: Scalar> Ppm<S> for KinkPhi {
    fn phi_wu(&self, pair: &VertexPair, p: &P2<S>) -> Result<P2<S>, MapError> {
        let q = Paper.phi_wu(pair, p)?;
        if let VertexPair::Edge(e) = pair {
            let y = rotate_frac(p, -(e.i as i64), e.m_u as i64).y;
            if y.sign() == Some(std::cmp::Ordering::Greater) {
                return Ok(P2::new(q.x.add(&q.x.like_f64(1e-6)), q.y));
            }
        }
        Ok(q)
    }
}
/// g_(u,w) formula + (1e−6, 0).
struct ShiftedG;
impl<S: Scalar> Ppm<S> for ShiftedG {
    fn g_uw_formula(&self, e: &EdgeConfig, p: &P2<S>) -> Result<P2<S>, MapError> {
        let q = Paper.g_uw_formula(e, p)?;
        Ok(P2::new(q.x.add(&q.x.like_f64(1e-6)), q.y))
    }
}
/// Wrong rotation index: in a star of degree `m`, label `label` is rotated as label+1.
struct WrongRotation {
    m: u32,
    label: u32,
}
impl WrongRotation {
    fn idx(&self, e: &EdgeConfig) -> i64 {
        if e.m_u == self.m && e.i == self.label {
            (e.i as i64 + 1) % e.m_u as i64
        } else {
            e.i as i64
        }
    }
}
impl<S: Scalar> Ppm<S> for WrongRotation {
    fn r_uw(&self, e: &EdgeConfig, p: &P2<S>) -> P2<S> {
        rotate_frac(p, -self.idx(e), e.m_u as i64)
    }
    fn r_uw_inv(&self, e: &EdgeConfig, p: &P2<S>) -> P2<S> {
        rotate_frac(p, self.idx(e), e.m_u as i64)
    }
}
/// Membership test that declares Ω_uw empty whenever s_u(w) = 0.
struct EmptyWhenLabelZero;
impl<S: Scalar> Ppm<S> for EmptyWhenLabelZero {
    fn in_omega_uw_literal(&self, e: &EdgeConfig, p: &P2<S>) -> Trit {
        if e.i == 0 {
            Trit::False
        } else {
            Paper.in_omega_uw_literal(e, p)
        }
    }
}

// ------------------------------------------------------------------ unit identities

#[test]
fn d4_1_5_negative_axis_theta_is_pi_for_both_zeros() {
    for y in [0.0f64, -0.0] {
        let q = polar(&P2::new(-0.5f64, y)).unwrap();
        assert_eq!(q.theta, std::f64::consts::PI);
        let qm = polar(&P2::<Mp>::from_f64(-0.5, y, 200)).unwrap();
        assert_eq!(qm.theta, Mp::pi(200));
    }
    assert_eq!(polar(&P2::new(0.0f64, -0.0)), Err(MapError::AtOrigin));
}

#[test]
fn d4_1_5_pi_roundtrip_holds() {
    common::assert_holds(&check_d4_1_5_polar::<f64, _>(&Paper, SEED, N, 53));
    common::assert_holds(&check_d4_1_5_polar::<Mp, _>(&Paper, SEED, N, 256));
}

#[test]
fn d4_1_5_planted_fault_caught() {
    assert_fails_with_witness(&check_d4_1_5_polar::<f64, _>(&RawAtan2, SEED, N, 53));
}

#[test]
fn d4_1_7_h_involution_and_c4_1_7_h_identity_holds() {
    let p = P2::new(0.3f64, -0.7);
    assert!(h(&h(&p)).dist_f64(&p) <= f64::EPSILON);
    assert!(h_identity_lhs(&p).dist_f64(&p) < 1e-15);
    common::assert_holds(&check_c4_1_7_h_identity::<f64, _>(&Paper, SEED, N, 53));
    let r = check_c4_1_7_h_identity::<Mp, _>(&Paper, SEED, N, 256);
    assert!(holds(&r) && r.worst_deviation.unwrap() < 1e-70, "{r:?}");
}

#[test]
fn c4_1_7_h_identity_planted_fault_caught() {
    assert_fails_with_witness(&check_c4_1_7_h_identity::<f64, _>(&ScaledH, SEED, N, 53));
}

#[test]
fn d4_1_8_config_validation_is_typed() {
    assert!(matches!(
        EdgeConfig::new(2, 0, 6, 0),
        Err(ConfigError::DegreeTooSmall { m: 2 })
    ));
    assert!(matches!(
        EdgeConfig::new(6, 6, 6, 0),
        Err(ConfigError::LabelOutOfRange { .. })
    ));
    assert!(matches!(
        EdgeConfig::new(6, 0, 5, 5),
        Err(ConfigError::LabelOutOfRange { .. })
    ));
    // u's labels not adjacent
    assert!(TriangleConfig::new(
        Corner {
            m: 6,
            next: 0,
            prev: 2
        },
        Corner {
            m: 6,
            next: 1,
            prev: 0
        },
        Corner {
            m: 6,
            next: 0,
            prev: 1
        }
    )
    .is_err());
    // mixed orientations
    assert!(TriangleConfig::new(
        Corner {
            m: 6,
            next: 0,
            prev: 1
        },
        Corner {
            m: 6,
            next: 5,
            prev: 0
        },
        Corner {
            m: 6,
            next: 0,
            prev: 5
        }
    )
    .is_err());
    assert!(TriangleConfig::ccw(5, 7, 3, 4, 6, 2).is_ok());
    let bad = EdgeConfig {
        m_u: 6,
        i: 9,
        m_w: 6,
        j: 0,
    };
    let rs = run_edge_checks::<f64>(&bad, SEED, 10, 53);
    assert!(matches!(rs[0].verdict(), Verdict::Skipped { .. }));
    assert!(phi_wu(&VertexPair::NotAdjacent, &P2::new(0.1f64, 0.0)).is_err());
}

#[test]
fn d4_1_10_phi_same_vertex_is_identity_and_outside_is_error() {
    let p = P2::new(0.2f64, 0.1);
    assert_eq!(phi_wu(&VertexPair::Same { m: 5 }, &p).unwrap(), p);
    let far = P2::new(0.95f64, 0.0);
    assert!(matches!(
        phi_wu(&VertexPair::Same { m: 5 }, &far),
        Err(MapError::NotInDomain(_))
    ));
    let e = e(6, 0, 6, 0);
    // On the far side of Ω_u (opposite w) p is not in Ω_uw.
    assert!(matches!(
        phi_wu(&VertexPair::Edge(e), &P2::new(-0.5f64, 0.0)),
        Err(MapError::NotInDomain(_))
    ));
}

#[test]
fn d4_1_10_f64_vs_mp_agreement_within_eps_bound() {
    for cfg in [e(6, 0, 6, 0), e(5, 2, 7, 3), e(3, 1, 12, 11)] {
        let pair = VertexPair::Edge(cfg);
        // a point of Ω_uw: pull back (0.5, 0.1) ∈ E
        let q = P2::new(0.5f64, 0.1);
        let p = Paper.r_uw_inv(&cfg, &g_v_inv(cfg.m_u, &q).unwrap());
        let (a, b, d) = phi_wu_f64_vs_mp(&pair, p.to_f64(), 256).unwrap();
        let bound = maps::ROUNDTRIP_COND * 2.0f64.powi(-53);
        assert!(d < bound, "{cfg:?}: {a:?} vs {b:?}: {d:e} ≥ {bound:e}");
        // The f64 value is φ_wu's own (a point of Ω_wu: not the origin), and the Mp one,
        // rounded to f64, agrees with it to the bound.
        let pf = P2::new(p.to_f64()[0], p.to_f64()[1]);
        assert_eq!(a, phi_wu(&pair, &pf).unwrap().to_f64(), "{cfg:?}");
        assert!(a[0].hypot(a[1]) > 0.1, "{cfg:?}: {a:?}");
        let ab = (a[0] - b[0]).hypot(a[1] - b[1]);
        assert!(ab < bound, "{cfg:?}: {ab:e}");
    }
}

/// p ≠ 0 three-valued: the origin is not in the punctured sets, in f64 and in Mp, and a
/// point on an axis is.
#[test]
fn d4_1_1_is_nonzero_refuses_only_the_origin() {
    let zero = P2::new(0.0f64, 0.0);
    assert_eq!(is_nonzero(&zero), Trit::False);
    assert_eq!(in_omega_v_punctured(6, &zero), Trit::False);
    assert_eq!(in_int_c_punctured(&zero), Trit::False);
    assert_eq!(is_nonzero(&P2::<Mp>::from_f64(0.0, 0.0, 128)), Trit::False);
    for p in [[0.0, 0.25], [-0.25, 0.0], [0.1, -0.1]] {
        assert_eq!(is_nonzero(&P2::new(p[0], p[1])), Trit::True, "{p:?}");
        assert_eq!(
            in_omega_v_punctured(6, &P2::new(p[0], p[1])),
            Trit::True,
            "{p:?}"
        );
    }
}

#[test]
fn c4_1_6_gv_bijective_holds_m6_fails_as_written_otherwise() {
    let r = check_c4_1_6_gv_bijective::<f64, _>(&Paper, 6, SEED, N, 53);
    assert!(holds(&r[0]) && holds(&r[1]));
    for m in [3, 5, 7, 12] {
        let r = check_c4_1_6_gv_bijective::<f64, _>(&Paper, m, SEED, N, 53);
        common::assert_fails_as_written(&r[0]);
        assert!(
            matches!(r[1].verdict(), Verdict::HoldsRestricted { .. }),
            "m = {m}: {:?}",
            r[1]
        );
    }
}

#[test]
fn c4_1_6_gv_bijective_planted_fault_caught() {
    let r = check_c4_1_6_gv_bijective::<f64, _>(&ShrunkG, 6, SEED, N, 53);
    assert_fails_with_witness(&r[0]);
    assert_fails_with_witness(&r[1]);
}

#[test]
fn c4_1_6_gv_smooth_fails_as_written_unless_6_divides_m() {
    for m in [3, 4, 5, 7, 11] {
        let r = check_c4_1_6_gv_smooth::<f64, _>(&Paper, m, SEED, N, 53);
        common::assert_fails_as_written(&r[0]);
        assert!(
            matches!(r[1].verdict(), Verdict::HoldsRestricted { .. }),
            "m = {m}: {:?}",
            r[1]
        );
    }
    for m in [6, 12] {
        let r = check_c4_1_6_gv_smooth::<f64, _>(&Paper, m, SEED, N, 53);
        assert!(holds(&r[0]), "m = {m}: {:?}", r[0].witnesses);
        // 6 | m: the statement holds as written, so its restricted twin is no restriction.
        assert_eq!(r[1].verdict(), Verdict::Holds, "m = {m}");
    }
}

#[test]
fn c4_1_6_gv_smooth_planted_fault_caught() {
    let r = check_c4_1_6_gv_smooth::<f64, _>(&KinkG, 6, SEED, N, 53);
    assert_fails_with_witness(&r[0]);
}

/// g_v plus the smooth bump c·p·exp(−|p|²/s²), s = 0.02: its Jacobian differs from g_v's by
/// about c within |p| ≈ s and by nothing measurable beyond |p| ≈ 5s.
struct BumpG(f64);
impl<S: Scalar> Ppm<S> for BumpG {
    fn g_v(&self, m: u32, p: &P2<S>) -> Result<P2<S>, MapError> {
        let q = g_v(m, p)?;
        let b = p.x.like_f64(self.0 * (-p.norm2().to_f64() / 4e-4).exp());
        Ok(P2::new(q.x.add(&p.x.mul(&b)), q.y.add(&p.y.mul(&b))))
    }
}

/// The finite-difference tolerance of the smoothness tests is 16·(h²·L·k²/(6r²) + ε(|F(p)| +
/// L·r)/h) with h = ε^{1/3}·r: for g_v at m_v = 6 about 8·10⁻¹⁰ at every radius r. A Jacobian
/// off by 10⁻⁸ only near the centre must fail there; a rounding term that grew like 1/r² near
/// the centre (L/r in place of L·r) would excuse it.
#[test]
fn c4_1_6_gv_smooth_fd_tolerance_does_not_grow_near_the_centre() {
    let r = check_c4_1_6_gv_smooth::<f64, _>(&BumpG(1e-8), 6, SEED, N, 53);
    assert_fails_with_witness(&r[0]);
    let p = &r[0].witnesses[0].data["p"];
    let (x, y) = (p[0].as_f64(), p[1].as_f64());
    let rad = x.zip(y).map(|(x, y)| x.hypot(y));
    assert!(rad.is_some_and(|r| r < 0.05), "witness at {p}");
}

#[test]
fn c4_1_8_onto_intc_fails_for_small_degree_holds_otherwise() {
    let r = check_c4_1_8_onto_int_c::<f64, _>(&Paper, &e(4, 1, 6, 0), SEED, N, 53);
    common::assert_fails_as_written(&r[0]);
    // The restriction is the sector |β| < m_u·π/6 = 2π/3 for m_u = 4, and it says so.
    let sector = format!("{:.6}", 4.0 * std::f64::consts::PI / 6.0);
    assert!(
        matches!(&r[1].verdict(), Verdict::HoldsRestricted { domain } if domain.contains(&sector)),
        "{:?}",
        r[1].verdict()
    );
    let r = check_c4_1_8_onto_int_c::<f64, _>(&Paper, &e(7, 1, 6, 0), SEED, N, 53);
    assert!(holds(&r[0]));
}

#[test]
fn c4_1_8_onto_intc_planted_fault_caught() {
    let r = check_c4_1_8_onto_int_c::<f64, _>(&ShrunkG, &e(6, 1, 6, 0), SEED, N, 53);
    assert_fails_with_witness(&r[0]);
}

#[test]
fn c4_1_8_lens_in_q_holds_and_planted_fault_caught() {
    common::assert_holds(&check_c4_1_8_lens_in_q::<f64, _>(&Paper, SEED, N, 53));
    common::assert_holds(&check_c4_1_8_lens_in_q::<Mp, _>(&Paper, SEED, N, 256));
    assert_fails_with_witness(&check_c4_1_8_lens_in_q::<f64, _>(&ShiftedLens, SEED, N, 53));
}

#[test]
fn c4_1_8_guw_bijective_fails_for_m_u_above_6_and_planted_fault_caught() {
    let r = check_c4_1_8_guw_bijective::<f64, _>(&Paper, &e(7, 2, 4, 1), SEED, N, 53);
    common::assert_fails_as_written(&r[0]);
    assert!(matches!(r[1].verdict(), Verdict::HoldsRestricted { .. }));
    let r = check_c4_1_8_guw_bijective::<f64, _>(&Paper, &e(5, 2, 7, 1), SEED, N, 53);
    assert!(holds(&r[0]));
    let r = check_c4_1_8_guw_bijective::<f64, _>(&ScaledH, &e(5, 2, 7, 1), SEED, N, 53);
    assert_fails_with_witness(&r[1]);
}

#[test]
fn p4_1_1_fails_as_written_unless_6_divides_m_u() {
    let r = check_p4_1_1_guw_smooth::<f64, _>(&Paper, &e(5, 1, 6, 0), SEED, N, 53);
    common::assert_fails_as_written(&r[0]);
    assert!(
        matches!(r[1].verdict(), Verdict::HoldsRestricted { .. }),
        "{:?}",
        r[1]
    );
    let r = check_p4_1_1_guw_smooth::<f64, _>(&Paper, &e(12, 1, 5, 0), SEED, N, 53);
    assert!(holds(&r[0]), "{:?}", r[0].witnesses);
}

#[test]
fn p4_1_1_planted_fault_caught() {
    let r = check_p4_1_1_guw_smooth::<f64, _>(&KinkG, &e(6, 1, 6, 0), SEED, N, 53);
    assert_fails_with_witness(&r[0]);
}

#[test]
fn p4_1_2_holds_proof_step_fails_and_planted_fault_caught() {
    let r = check_p4_1_2::<f64, _>(&Paper, &e(5, 1, 6, 0), SEED, N, 53);
    common::assert_holds(&r[0]);
    common::assert_fails_as_written(&r[1]);
    let r = check_p4_1_2::<f64, _>(&HalfH, &e(6, 1, 6, 0), SEED, N, 53);
    assert_fails_with_witness(&r[0]);
}

/// g_(u,w) constant at (r, 0) on Ω_u − {0}: every image has norm r.
struct ConstG(f64);
impl<S: Scalar> Ppm<S> for ConstG {
    fn g_uw(&self, _e: &EdgeConfig, p: &P2<S>) -> Result<P2<S>, MapError> {
        Ok(P2::new(p.x.like_f64(self.0), p.x.like_f64(0.0)))
    }
}

/// P4.1.2's bound is δ = (1 − cos π/6)·cos(π/m_w)/cos(π/6), no other: images of norm 1 % above
/// δ hold and 1 % below fail, at m_w = 4 (δ ≈ 0.1094, below 1 − cos π/6) and m_w = 12
/// (δ ≈ 0.1494, above it), so a δ off by the factor cos(π/m_w)/cos(π/6) either way is caught.
#[test]
fn p4_1_2_delta_is_the_stated_bound_planted_norms_either_side() {
    use std::f64::consts::PI;
    for m_w in [4u32, 12] {
        let delta = (1.0 - (PI / 6.0).cos()) * (PI / m_w as f64).cos() / (PI / 6.0).cos();
        let r = check_p4_1_2::<f64, _>(&ConstG(delta * 1.01), &e(5, 1, m_w, 0), SEED, N, 53);
        common::assert_holds(&r[0]);
        let r = check_p4_1_2::<f64, _>(&ConstG(delta * 0.99), &e(5, 1, m_w, 0), SEED, N, 53);
        assert_fails_with_witness(&r[0]);
    }
}

#[test]
fn p4_1_3_inverse_fails_for_m_u_ge_11_holds_below() {
    let r = check_p4_1_3::<f64, _>(&Paper, &e(12, 3, 6, 0), SEED, N, 53);
    common::assert_holds(&r[0]);
    common::assert_fails_as_written(&r[1]);
    assert!(matches!(r[2].verdict(), Verdict::HoldsRestricted { .. }));
    let r = check_p4_1_3::<f64, _>(&Paper, &e(10, 3, 4, 0), SEED, N, 53);
    assert!(holds(&r[1]));
}

#[test]
fn p4_1_3_planted_fault_caught() {
    let r = check_p4_1_3::<f64, _>(&ScaledH, &e(6, 3, 6, 0), SEED, N, 53);
    assert_fails_with_witness(&r[1]);
}

#[test]
fn d4_1_9_lens_agreement_holds_below_11_fails_from_11() {
    for cfg in [e(6, 0, 6, 0), e(3, 2, 10, 4), e(10, 9, 3, 0)] {
        assert!(
            holds(&check_d4_1_9_lens_agreement::<f64, _>(
                &Paper, &cfg, SEED, N, 53
            )),
            "{cfg:?}"
        );
    }
    for cfg in [e(11, 0, 6, 3), e(12, 3, 6, 0)] {
        common::assert_fails_as_written(&check_d4_1_9_lens_agreement::<f64, _>(
            &Paper, &cfg, SEED, N, 53,
        ));
    }
}

#[test]
fn d4_1_9_lens_planted_fault_caught() {
    assert_fails_with_witness(&check_d4_1_9_lens_agreement::<f64, _>(
        &ShiftedLens,
        &e(6, 1, 6, 2),
        SEED,
        N,
        53,
    ));
}

/// g_v constant at (x, y), and a lens test that answers the opposite of the literal Def. 4.1.9
/// at every point: every sample disagrees, with g_u∘R_(u,w)(p) = (x, y).
struct DisagreeAt(f64, f64);
impl<S: Scalar> Ppm<S> for DisagreeAt {
    fn g_v(&self, _m: u32, p: &P2<S>) -> Result<P2<S>, MapError> {
        Ok(P2::new(p.x.like_f64(self.0), p.x.like_f64(self.1)))
    }
    fn in_omega_uw_lens(&self, e: &EdgeConfig, p: &P2<S>) -> Trit {
        match self.in_omega_uw_literal(e, p) {
            Trit::True => Trit::False,
            _ => Trit::True,
        }
    }
}

/// D4.1.9-lens ignores a disagreement only within the rounding margin of ∂E, the two circles of
/// radius √3/2 centred at (0, 0) and (1, 0) that bound the lens: with g_u∘R_(u,w)(p) on either
/// one, every sample's disagreement is ignored (and the note counts them all); on the circle
/// centred at (−1, 0), or off every circle, none is.
#[test]
fn d4_1_9_lens_margin_is_to_the_two_circles_of_the_lens() {
    let r3 = 0.75f64.sqrt();
    for (x, ignored) in [
        (r3, true),
        (1.0 - r3, true),
        (r3 - 1.0, false),
        (0.5, false),
    ] {
        let r =
            check_d4_1_9_lens_agreement::<f64, _>(&DisagreeAt(x, 0.0), &e(6, 1, 6, 2), SEED, N, 53);
        if ignored {
            common::assert_holds(&r);
            let all = format!("{} disagreements within the rounding margin", r.examined);
            assert!(r.note.contains(&all), "x = {x}: {}", r.note);
        } else {
            assert_fails_with_witness(&r);
        }
    }
}

#[test]
fn p4_2_1_holds_and_planted_fault_caught() {
    common::assert_holds(&check_p4_2_1::<f64, _>(&Paper, &e(5, 0, 7, 3), SEED, N, 53));
    assert_fails_with_witness(&check_p4_2_1::<f64, _>(
        &EmptyWhenLabelZero,
        &e(5, 0, 7, 3),
        SEED,
        N,
        53,
    ));
}

#[test]
fn p4_2_3_phi_inverse_holds() {
    for cfg in [e(6, 0, 6, 0), e(3, 2, 13, 4), e(12, 5, 4, 1)] {
        let r = check_p4_2_3::<f64, _>(&Paper, &cfg, SEED, N, 53);
        assert!(holds(&r[0]) && holds(&r[1]), "{cfg:?}: {:?}", r);
        common::assert_holds_for(&format!("{cfg:?}"), &r[0]);
        common::assert_holds_for(&format!("{cfg:?}"), &r[1]);
    }
    let r = check_p4_2_3::<Mp, _>(&Paper, &e(5, 1, 7, 2), SEED, 80, 192);
    assert!(
        holds(&r[0]) && r[0].worst_deviation.unwrap() < 1e-50,
        "{r:?}"
    );
}

#[test]
fn p4_2_3_planted_fault_caught() {
    let r = check_p4_2_3::<f64, _>(&ShiftedPhi, &e(6, 0, 6, 0), SEED, N, 53);
    assert_fails_with_witness(&r[0]);
}

#[test]
fn l4_2_3_holds_and_planted_fault_caught() {
    common::assert_holds(&check_l4_2_3::<f64, _>(&Paper, &e(4, 1, 9, 2), SEED, N, 53));
    assert_fails_with_witness(&check_l4_2_3::<f64, _>(
        &ShiftedG,
        &e(4, 1, 9, 2),
        SEED,
        N,
        53,
    ));
}

#[test]
fn l4_2_4_phi_smooth_holds_and_planted_fault_caught() {
    for cfg in [e(5, 1, 7, 2), e(3, 0, 11, 5)] {
        assert!(
            holds(&check_l4_2_4::<f64, _>(&Paper, &cfg, SEED, N, 53)),
            "{cfg:?}"
        );
    }
    assert_fails_with_witness(&check_l4_2_4::<f64, _>(
        &KinkPhi,
        &e(5, 1, 7, 2),
        SEED,
        N,
        53,
    ));
}

#[test]
fn l4_2_2_cocycle_holds_on_sampled_triangles() {
    for (mu, mw, mx) in [
        (6, 6, 6),
        (3, 5, 7),
        (3, 3, 3),
        (12, 4, 11),
        (4, 12, 5),
        (13, 3, 9),
    ] {
        let t = TriangleConfig::ccw(mu, mw, mx, 1 % mu, 2 % mw, 0).unwrap();
        let r = check_l4_2_1_l4_2_2::<f64, _>(&Paper, &t, SEED, N, 53);
        for x in &r {
            assert!(holds(x), "{t:?}: {} {:?}", x.id, x.witnesses.first());
            common::assert_holds_for(&format!("{t:?}"), x);
        }
        assert!(r[1].examined > 20, "too few samples in Ω_xu ∩ Ω_xw");
    }
}

#[test]
fn l4_2_1_l4_2_2_cocycle_planted_fault_caught() {
    let t = TriangleConfig::ccw(7, 6, 5, 1, 2, 0).unwrap();
    // u's label of w (1) rotated as 2 = u's label of x (only u has degree 7).
    let r = check_l4_2_1_l4_2_2::<f64, _>(&WrongRotation { m: 7, label: 1 }, &t, SEED, N, 53);
    assert!(r[0].failed() || r[1].failed(), "{r:?}");
    let r = check_l4_2_1_l4_2_2::<f64, _>(&ShiftedPhi, &t, SEED, N, 53);
    assert_fails_with_witness(&r[1]);
}

#[test]
fn p4_2_4_fails_as_written_for_m_u_3_holds_otherwise() {
    let t = TriangleConfig::ccw(3, 5, 7, 1, 2, 0).unwrap();
    let r = run_triangle_checks::<f64>(&t, SEED, N, 53);
    common::assert_fails_as_written(get(&r, "P4.2.4(i,ii)"));
    common::assert_holds(get(&r, "P4.2.4(iii,iv)"));
    for mu in [4, 5, 6, 9, 12] {
        let t = TriangleConfig::ccw(mu, 5, 7, 1, 2, 0).unwrap();
        let r = run_triangle_checks::<f64>(&t, SEED, N, 53);
        common::assert_holds_for(&format!("m_u = {mu}"), get(&r, "P4.2.4(i,ii)"));
    }
}

#[test]
fn p4_2_4_planted_fault_caught() {
    let ew = e(6, 2, 6, 0);
    let ez = e(6, 1, 6, 0);
    let r = check_p4_2_4::<f64, _>(&WrongRotation { m: 6, label: 2 }, &ew, &ez, SEED, N, 53);
    assert_fails_with_witness(&r[1]);
}

#[test]
fn c5_4_at_most_two_holds_literal_fails_sec613_from_11() {
    for m in [3, 6, 10, 11, 12] {
        let s = StarConfig::uniform(m, 6).unwrap();
        let r = check_star_overlaps::<f64, _>(&Paper, &s, false, SEED, 120, 53);
        assert!(holds(&r[0]) && holds(&r[1]), "m = {m}");
        // Every sample is examined by both halves: the "at most two" count once per point, the
        // non-adjacency once per point in fewer than two domains and once per pair otherwise.
        let samples: u64 = r[0]
            .note
            .split_whitespace()
            .next()
            .and_then(|n| n.parse().ok())
            .expect("the note starts with the sample count");
        assert_eq!(r[0].examined, samples, "m = {m}");
        assert!(
            r[1].examined >= samples,
            "m = {m}: {} < {samples}",
            r[1].examined
        );
    }
    let s = StarConfig::uniform(12, 6).unwrap();
    let r = check_star_overlaps::<f64, _>(&Paper, &s, true, SEED, 120, 53);
    assert_fails_with_witness(&r[0]);
    assert_fails_with_witness(&r[1]);
}

#[test]
fn c5_4_at_most_two_planted_fault_caught() {
    let s = StarConfig::uniform(6, 6).unwrap();
    let r =
        check_star_overlaps::<f64, _>(&WrongRotation { m: 6, label: 0 }, &s, false, SEED, 120, 53);
    assert_fails_with_witness(&r[1]);
}

#[test]
fn edge_checks_same_verdicts_in_f64_and_mp() {
    for cfg in [e(6, 1, 6, 4), e(5, 2, 7, 0)] {
        let a = run_edge_checks::<f64>(&cfg, SEED, 60, 53);
        let b = run_edge_checks::<Mp>(&cfg, SEED, 60, 128);
        assert_eq!(a.len(), b.len());
        for (x, y) in a.iter().zip(&b) {
            assert_eq!(
                (x.id.as_str(), x.verdict().label()),
                (y.id.as_str(), y.verdict().label()),
                "{cfg:?}"
            );
        }
    }
}
