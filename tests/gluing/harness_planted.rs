//! The check harness (`report::harness`) on every checker family: a model that returns NaN at
//! some samples, one that returns an error, and one whose domain is empty must each be
//! reported — `Fails` (NaN, error) or `Skipped` (nothing examined) — never "holds".
use pseudomanifold::construction::checks::*;
use pseudomanifold::construction::maps::*;
use pseudomanifold::construction::*;
use pseudomanifold::gluing::data::{GluingData, Idx};
use pseudomanifold::gluing::sampled::{check_all, SampleConfig};
use pseudomanifold::mesh::generate::icosahedron;
use pseudomanifold::mesh::validate::validate;
use pseudomanifold::mesh::VertexId;
use pseudomanifold::numeric::{Scalar, Trit};
use pseudomanifold::report::{CheckResult, Verdict};
use pseudomanifold::surface::checks::*;
use pseudomanifold::surface::*;
use rand::Rng;
use rand_chacha::ChaCha8Rng;

const SEED: u64 = 7;
const N: usize = 60;

fn holds(r: &CheckResult) -> bool {
    matches!(
        r.verdict(),
        Verdict::Holds | Verdict::HoldsRestricted { .. }
    )
}
fn assert_fails(r: &CheckResult) {
    assert!(
        r.failed(),
        "{} should fail: {:?} ({})",
        r.id,
        r.verdict(),
        r.note
    );
    assert!(!r.witnesses.is_empty(), "{} failed without a witness", r.id);
}
fn assert_reported(r: &CheckResult) {
    assert!(
        !holds(r),
        "{} must not hold: {:?} ({})",
        r.id,
        r.verdict(),
        r.note
    );
}
fn assert_skipped(r: &CheckResult) {
    assert!(
        matches!(r.verdict(), Verdict::Skipped { .. }),
        "{} should be skipped: {:?} (examined {})",
        r.id,
        r.verdict(),
        r.examined
    );
}
fn nan<S: Scalar>(p: &P2<S>) -> P2<S> {
    P2::new(p.x.like_f64(f64::NAN), p.y.like_f64(f64::NAN))
}
fn upper<S: Scalar>(p: &P2<S>) -> bool {
    p.y.sign() == Some(std::cmp::Ordering::Greater)
}

// ------------------------------------------------------------------ Chapter 4 models

/// Π with θ = NaN on the upper half-plane.
struct NanPolar;
impl<S: Scalar> Ppm<S> for NanPolar {
    fn polar(&self, p: &P2<S>) -> Result<Polar<S>, MapError> {
        let q = polar(p)?;
        Ok(if upper(p) {
            Polar {
                theta: p.x.like_f64(f64::NAN),
                r: q.r,
            }
        } else {
            q
        })
    }
}
/// Π failing everywhere.
struct ErrPolar;
impl<S: Scalar> Ppm<S> for ErrPolar {
    fn polar(&self, _: &P2<S>) -> Result<Polar<S>, MapError> {
        Err(MapError::Undecided("planted"))
    }
}
/// g_v = NaN on the upper half-plane.
struct NanG;
impl<S: Scalar> Ppm<S> for NanG {
    fn g_v(&self, m: u32, p: &P2<S>) -> Result<P2<S>, MapError> {
        let q = g_v(m, p)?;
        Ok(if upper(p) { nan(&q) } else { q })
    }
}
/// g_v failing everywhere.
struct ErrG;
impl<S: Scalar> Ppm<S> for ErrG {
    fn g_v(&self, _: u32, _: &P2<S>) -> Result<P2<S>, MapError> {
        Err(MapError::Undecided("planted"))
    }
}
/// φ_wu = NaN on the upper half-plane.
struct NanPhi;
impl<S: Scalar> Ppm<S> for NanPhi {
    fn phi_wu(&self, pair: &VertexPair, p: &P2<S>) -> Result<P2<S>, MapError> {
        let q = Paper.phi_wu(pair, p)?;
        Ok(if upper(p) { nan(&q) } else { q })
    }
}
/// φ_wu failing on its whole domain.
struct ErrPhi;
impl<S: Scalar> Ppm<S> for ErrPhi {
    fn phi_wu(&self, _: &VertexPair, _: &P2<S>) -> Result<P2<S>, MapError> {
        Err(MapError::Undecided("planted"))
    }
}
/// Every gluing domain Ω_uw empty.
struct EmptyOmega;
impl<S: Scalar> Ppm<S> for EmptyOmega {
    fn in_omega_uw_literal(&self, _: &EdgeConfig, _: &P2<S>) -> Trit {
        Trit::False
    }
}

fn edge() -> EdgeConfig {
    EdgeConfig::new(6, 0, 6, 0).unwrap()
}
fn triangle() -> TriangleConfig {
    TriangleConfig::ccw(6, 6, 6, 0, 0, 0).unwrap()
}
fn by_id<'a>(rs: &'a [CheckResult], id: &str) -> &'a CheckResult {
    rs.iter()
        .find(|r| r.id == id)
        .unwrap_or_else(|| panic!("no {id}"))
}

#[test]
fn x_harness_construction_nan_is_an_offence() {
    assert_fails(&check_d4_1_5_polar::<f64, _>(&NanPolar, SEED, N, 53));
    for r in check_c4_1_6_gv_bijective::<f64, _>(&NanG, 6, SEED, N, 53) {
        assert_fails(&r);
    }
    for r in check_c4_1_6_gv_smooth::<f64, _>(&NanG, 6, SEED, N, 53) {
        assert_fails(&r);
    }
    let e = edge();
    assert_fails(&check_p4_1_2::<f64, _>(&NanG, &e, SEED, N, 53)[0]);
    assert_fails(&check_p4_2_3::<f64, _>(&NanPhi, &e, SEED, N, 53)[0]);
    let t = check_l4_2_1_l4_2_2::<f64, _>(&NanPhi, &triangle(), SEED, N, 53);
    assert!(t.iter().any(|r| r.failed()), "NaN φ not reported: {t:#?}");
    assert_reported(by_id(&t, "L4.2.2"));
    // A planted fault of this family reported as the harness demands (SPEC `X-harness`).
    crate::common::verdicts::record("X-harness", crate::common::verdicts::Seen::Holds, 1);
}

#[test]
fn x_harness_construction_errors_are_reported() {
    let r = check_d4_1_5_polar::<f64, _>(&ErrPolar, SEED, N, 53);
    assert_fails(&r);
    assert!(r.eval_errors > 0 || r.offenders > 0);
    for r in check_c4_1_6_gv_bijective::<f64, _>(&ErrG, 6, SEED, N, 53) {
        assert_fails(&r);
    }
    // The Jacobian test cannot run where F fails: every sample is a counted skip, and with
    // nothing examined the result is skipped, not "holds".
    for r in check_c4_1_6_gv_smooth::<f64, _>(&ErrG, 6, SEED, N, 53) {
        assert_reported(&r);
        assert!(r.eval_errors > 0, "{}: errors not counted", r.id);
    }
    let e = edge();
    for r in check_p4_2_3::<f64, _>(&ErrPhi, &e, SEED, N, 53) {
        assert_fails(&r);
    }
    let t = check_l4_2_1_l4_2_2::<f64, _>(&ErrPhi, &triangle(), SEED, N, 53);
    assert_fails(by_id(&t, "L4.2.1"));
    // A planted fault of this family reported as the harness demands (SPEC `X-harness`).
    crate::common::verdicts::record("X-harness", crate::common::verdicts::Seen::Holds, 1);
}

#[test]
fn x_harness_construction_empty_domain_is_skipped() {
    let e = edge();
    for r in check_p4_2_3::<f64, _>(&EmptyOmega, &e, SEED, N, 53) {
        assert_skipped(&r);
    }
    for r in check_l4_2_1_l4_2_2::<f64, _>(&EmptyOmega, &triangle(), SEED, N, 53) {
        assert_skipped(&r);
    }
    // No samples at all: both forms of a restricted pair are skipped.
    for r in check_c4_1_6_gv_bijective::<f64, _>(&Paper, 6, SEED, 0, 53) {
        assert_skipped(&r);
    }
    // A planted fault of this family reported as the harness demands (SPEC `X-harness`).
    crate::common::verdicts::record("X-harness", crate::common::verdicts::Seen::Holds, 1);
}

// ------------------------------------------------------------------ Chapter 5 (surface)

fn pps() -> Pps {
    let k = validate(&icosahedron()).surface.expect("valid");
    Pps::build(&k, &PnTriangles::new(&k), PpsOptions::default())
}
fn sopts() -> SurfaceCheckOptions {
    SurfaceCheckOptions {
        samples_per_vertex: 8,
        max_vertices: Some(6),
        mp_vertices: 1,
        intersections: false,
        ..SurfaceCheckOptions::default()
    }
}

#[test]
fn x_harness_surface_nan_is_an_offence() {
    // One NaN control point of ψ_0: θ_0 and the θ_u blending it are NaN near vertex 0.
    let mut p = pps();
    p.patch_mut(VertexId(0))[0] = [f64::NAN; 3];
    let o = SurfaceCheckOptions {
        max_vertices: None,
        ..sopts()
    };
    assert_fails(&check_condition_c(&p, &o));
    assert_fails(&check_smooth_charts(&p, &o));
    assert_fails(&check_approx(&p));
    for r in check_eval_cases(&p, &o) {
        assert_fails(&r);
    }
    // A planted fault of this family reported as the harness demands (SPEC `X-harness`).
    crate::common::verdicts::record("X-harness", crate::common::verdicts::Seen::Holds, 1);
}

#[test]
fn x_harness_surface_errors_are_reported() {
    // Σ Γ multiplied by 0: θ_v is undefined (SurfaceError::ZeroWeight) everywhere.
    let p = pps().with_options(
        Membership::Literal,
        Some(Fault::Denominator { factor: 0.0 }),
    );
    let o = sopts();
    for r in [
        check_condition_c(&p, &o),
        check_smooth_charts(&p, &o),
        check_approx(&p),
    ] {
        assert_fails(&r);
        assert!(r.eval_errors > 0, "{}: errors not counted", r.id);
    }
    // ω_uv = Γ_uv / 0 is not an error but a non-finite weight: an offence.
    assert_fails(&check_weights(&p, &o));
    // A planted fault of this family reported as the harness demands (SPEC `X-harness`).
    crate::common::verdicts::record("X-harness", crate::common::verdicts::Seen::Holds, 1);
}

#[test]
fn x_harness_surface_empty_domain_is_skipped() {
    let p = pps();
    let o = SurfaceCheckOptions {
        samples_per_vertex: 0,
        ..sopts()
    };
    let k = validate(&icosahedron()).surface.expect("valid");
    let g = PpmGluing::new(&k);
    for r in [
        check_condition_c(&p, &o),
        check_weights(&p, &o),
        check_j_le_3(&p, &o),
        check_membership_literal(&p, &g, &o),
    ] {
        assert_skipped(&r);
    }
    for r in check_eval_cases(&p, &o) {
        assert_skipped(&r);
    }
    // A planted fault of this family reported as the harness demands (SPEC `X-harness`).
    crate::common::verdicts::record("X-harness", crate::common::verdicts::Seen::Holds, 1);
}

// ------------------------------------------------------------------ Secs. 3.4–3.5 (gluing)

/// Two p-domains (0, 1) and (2, 3), glued along (1/2, 1) ↔ (2, 5/2) by translation — except φ
/// returns NaN on part of its domain (mode 0), is undefined (mode 1), or every domain is empty
/// (mode 2).
struct Planted {
    mode: u8,
}
impl Planted {
    fn lo(i: Idx) -> f64 {
        2.0 * i as f64
    }
}
impl GluingData<1> for Planted {
    type S = f64;
    fn indices(&self) -> Vec<Idx> {
        vec![0, 1]
    }
    fn in_p_domain(&self, i: Idx, p: &[f64; 1]) -> bool {
        self.mode != 2 && p[0] > Self::lo(i) && p[0] < Self::lo(i) + 1.0
    }
    fn in_gluing_domain(&self, i: Idx, j: Idx, p: &[f64; 1]) -> bool {
        let t = p[0] - Self::lo(i);
        self.in_p_domain(i, p)
            && match (i, j) {
                _ if i == j => true,
                (0, 1) => t > 0.5,
                (1, 0) => t < 0.5,
                _ => false,
            }
    }
    fn phi(&self, j: Idx, i: Idx, p: &[f64; 1]) -> Option<[f64; 1]> {
        if !self.in_gluing_domain(i, j, p) {
            return None;
        }
        let y = p[0] - Self::lo(i)
            + if i == j {
                0.0
            } else if i == 0 {
                -0.5
            } else {
                0.5
            };
        match self.mode {
            0 if i != j && p[0] - Self::lo(i) > 0.7 => Some([f64::NAN]),
            1 if i != j => None,
            _ => Some([y + Self::lo(j)]),
        }
    }
    fn sample_p_domain(&self, i: Idx, rng: &mut ChaCha8Rng, n: usize) -> Vec<[f64; 1]> {
        (0..n)
            .map(|_| [Self::lo(i) + rng.gen_range(0.001..0.999)])
            .filter(|p| self.in_p_domain(i, p))
            .collect()
    }
    fn sample_gluing_domain(
        &self,
        i: Idx,
        j: Idx,
        rng: &mut ChaCha8Rng,
        n: usize,
    ) -> Vec<[f64; 1]> {
        (0..n)
            .map(|_| [Self::lo(i) + rng.gen_range(0.001..0.999)])
            .filter(|p| self.in_gluing_domain(i, j, p))
            .collect()
    }
    fn gluing_boundary_points(
        &self,
        i: Idx,
        j: Idx,
        _: &mut ChaCha8Rng,
        _: usize,
    ) -> Vec<[f64; 1]> {
        if i == j || self.mode == 2 {
            Vec::new()
        } else {
            vec![[Self::lo(i) + 0.5]]
        }
    }
}

#[test]
fn x_harness_gluing_nan_error_empty() {
    let cfg = SampleConfig::default();
    let inverse = |rs: &[CheckResult]| rs.iter().find(|r| r.id == "D3.4.1(3b)").cloned().unwrap();
    let nan = check_all(&Planted { mode: 0 }, &cfg);
    assert_fails(&inverse(&nan));
    let err = check_all(&Planted { mode: 1 }, &cfg);
    let by = |rs: &[CheckResult], id: &str| rs.iter().find(|r| r.id == id).cloned().unwrap();
    assert_fails(&by(&err, "D3.4.1(3)"));
    // 3(b) cannot examine where φ_ji is undefined: counted as skipped samples, not dropped.
    assert!(by(&err, "D3.4.1(3b)").eval_errors > 0);
    let empty = check_all(&Planted { mode: 2 }, &cfg);
    assert_fails(&by(&empty, "D3.4.1(1)"));
    for id in [
        "D3.4.1(3)",
        "D3.4.1(3a)",
        "D3.4.1(3b)",
        "D3.4.1(3c)",
        "D3.4.1(4)",
    ] {
        assert_skipped(&by(&empty, id));
    }
    // A planted fault of this family reported as the harness demands (SPEC `X-harness`).
    crate::common::verdicts::record("X-harness", crate::common::verdicts::Seen::Holds, 1);
}

#[test]
fn x_harness_sampled_cocycle_counts_undefined_phi() {
    // φ_ji undefined off the diagonal (mode 1): the cocycle checks cannot examine those
    // samples; they are counted, never dropped, and the strict reading (which claims the right
    // side defined) fails.
    let err = check_all(&Planted { mode: 1 }, &SampleConfig::default());
    let by = |id: &str| err.iter().find(|r| r.id == id).cloned().unwrap();
    for id in ["D3.4.1(3c)", "CA.2-GH", "CA.2-GH-strict"] {
        assert!(by(id).eval_errors > 0, "{id}: undefined φ not counted");
    }
    assert_fails(&by("CA.2-GH-strict"));
    // A planted fault of this family reported as the harness demands (SPEC `X-harness`).
    crate::common::verdicts::record("X-harness", crate::common::verdicts::Seen::Holds, 1);
}

// ------------------------------------------------------------------ Sec. 3.1 (mesh validators)

fn validated(raw: &pseudomanifold::mesh::RawMesh) -> Vec<CheckResult> {
    validate(raw).report.checks
}

#[test]
fn x_harness_mesh_nan_is_an_offence() {
    // A NaN coordinate: reported by X-finite with a witness, and no geometric check holds by
    // examining the NaN face (the faces around it are not examined by D3.1.1).
    let mut raw = icosahedron();
    raw.positions[0][1] = f64::NAN;
    let rs = validated(&raw);
    assert_fails(by_id(&rs, "X-finite"));
    let affine = by_id(&rs, "D3.1.1");
    assert_eq!(affine.examined, raw.faces.len() as u64 - 5);
    assert!(validate(&raw).surface.is_none());
    // A planted fault of this family reported as the harness demands (SPEC `X-harness`).
    crate::common::verdicts::record("X-harness", crate::common::verdicts::Seen::Holds, 1);
}

#[test]
fn x_harness_mesh_bad_index_is_reported() {
    // An index out of range (the mesh analogue of an evaluation error): reported with a
    // witness naming the face, never skipped.
    let mut raw = icosahedron();
    raw.faces[3][2] = 99;
    let rs = validated(&raw);
    let r = by_id(&rs, "D3.1.3(i)");
    assert_fails(r);
    assert!(r.witnesses[0].text.contains("99"), "{:?}", r.witnesses);
    assert!(validate(&raw).surface.is_none());
    // A planted fault of this family reported as the harness demands (SPEC `X-harness`).
    crate::common::verdicts::record("X-harness", crate::common::verdicts::Seen::Holds, 1);
}

#[test]
fn x_harness_mesh_empty_is_skipped() {
    // No triangles: X-nonempty fails; every check that examines elements examined none and is
    // skipped, never "holds".
    let raw = pseudomanifold::mesh::RawMesh::from_arrays(vec![], vec![]);
    let rs = validated(&raw);
    assert_fails(by_id(&rs, "X-nonempty"));
    for r in rs.iter().filter(|r| r.id != "X-nonempty") {
        assert_skipped(r);
    }
    // A planted fault of this family reported as the harness demands (SPEC `X-harness`).
    crate::common::verdicts::record("X-harness", crate::common::verdicts::Seen::Holds, 1);
}

// ------------------------------------------------------------------ Sec. 3.4 (exact 1-D deciders)

mod exact1d {
    use super::*;
    use pseudomanifold::gluing::exact1d::data::{iv, q};
    use pseudomanifold::gluing::exact1d::decide;
    use pseudomanifold::gluing::exact1d::Exact1d;

    /// Ω_1 = (0, 1), Ω_2 = (10, 11), glued by translation on (0, 1) ↔ (10, 11), except that
    /// φ_12 maps (10, 11) to (5, 6), outside Ω_12: φ_12 ∘ φ_21 is undefined on all of Ω_12.
    fn undefined_inverse() -> Exact1d {
        let mut g = Exact1d::default();
        g.add_domain(1, iv(0, 1));
        g.add_domain(2, iv(10, 11));
        g.add_piece(1, 2, iv(0, 1), q(1, 1), q(10, 1));
        g.add_piece(2, 1, iv(10, 11), q(1, 1), q(-5, 1));
        g.with_default_diagonal()
    }

    #[test]
    fn x_harness_exact1d_error_is_reported() {
        let r = decide::check_3b(&undefined_inverse());
        assert_fails(&r);
        assert!(
            r.eval_errors > 0,
            "undefined composition not counted: {r:?}"
        );
        // φ_ii defined on part of Ω_i only: id_Ω_i is not φ_ii, reported as an error.
        let mut g = Exact1d::default();
        g.add_domain(1, iv(0, 2));
        g.add_piece(1, 1, iv(0, 1), q(1, 1), q(0, 1));
        let r = decide::check_3a(&g);
        assert_fails(&r);
        assert!(r.eval_errors > 0);
    }

    #[test]
    fn x_harness_exact1d_empty_domain_is_skipped() {
        // I = ∅: (1) fails (I must be non-empty); every other condition examines nothing.
        let rs = decide::check_all(&Exact1d::default());
        assert_fails(by_id(&rs, "D3.4.1(1)"));
        for r in rs.iter().filter(|r| r.id != "D3.4.1(1)") {
            assert_skipped(r);
        }
        // Non-empty p-domains but K = ∅ (no φ at all, not even φ_ii): the conditions over K
        // are skipped, not "hold".
        let mut g = Exact1d::default();
        g.add_domain(1, iv(0, 1));
        for id in [
            "D3.4.1(3)",
            "D3.4.1(3b)",
            "D3.4.1(3c)",
            "CA.2-GH",
            "D3.4.1(4)",
        ] {
            assert_skipped(by_id(&decide::check_all(&g), id));
        }
    }
}
