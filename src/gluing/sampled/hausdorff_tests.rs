//! Unit tests of the sampled Hausdorff check (Def. 3.4.1(4)): its ball sampler, the
//! extrapolated limit candidates and the separating radii it reports.

use super::*;
use rand::SeedableRng;

/// The whole plane, glued to itself by the identity (every ball sample is kept).
struct Plane;

impl GluingData<2> for Plane {
    type S = f64;
    fn indices(&self) -> Vec<Idx> {
        vec![0, 1]
    }
    fn in_p_domain(&self, _: Idx, _: &Point<f64, 2>) -> bool {
        true
    }
    fn in_gluing_domain(&self, _: Idx, _: Idx, _: &Point<f64, 2>) -> bool {
        true
    }
    fn phi(&self, _: Idx, _: Idx, p: &Point<f64, 2>) -> Option<Point<f64, 2>> {
        Some(*p)
    }
    fn sample_p_domain(&self, _: Idx, _: &mut ChaCha8Rng, _: usize) -> Vec<Point<f64, 2>> {
        vec![]
    }
    fn sample_gluing_domain(
        &self,
        _: Idx,
        _: Idx,
        _: &mut ChaCha8Rng,
        _: usize,
    ) -> Vec<Point<f64, 2>> {
        vec![]
    }
    fn gluing_boundary_points(
        &self,
        _: Idx,
        _: Idx,
        _: &mut ChaCha8Rng,
        _: usize,
    ) -> Vec<Point<f64, 2>> {
        vec![]
    }
}

/// D3.4.1(4)'s separating balls are searched with 96 points of the ball: in every
/// direction, half at uniform radii, half at the geometric radii 0.999·r·2⁻ᵏ, k < 40 (how
/// close to x a separation must hold). The mutation campaign found nothing checked this.
#[test]
fn d3_4_1_4_ball_samples_are_uniform_and_geometric_in_every_direction() {
    let mut rng = ChaCha8Rng::seed_from_u64(4);
    let (x, r) = ([0.25, -0.5], 0.125);
    let ps = ball_samples(&Plane, 0, 1, &x, r, &mut rng);
    assert!(ps.len() >= 94, "{} of 96 kept", ps.len());
    let radii: Vec<f64> = ps.iter().map(|p| dist(p, &x)).collect();
    assert!(radii.iter().all(|&d| d < r), "a sample outside the ball");
    // Geometric radii, to rounding: 0.999·r·2⁻ᵏ for some k < 40.
    let geometric = |d: f64| (0..40).any(|k| (d - 0.999 * r * 2f64.powi(-k)).abs() <= 1e-14 * r);
    let g = radii.iter().filter(|&&d| geometric(d)).count();
    assert!((44..=50).contains(&g), "{g} geometric radii");
    assert!(radii.iter().any(|&d| d < r * 1e-9), "no radius near x");
    let uniform: Vec<f64> = radii.iter().copied().filter(|&d| !geometric(d)).collect();
    let mean = uniform.iter().sum::<f64>() / uniform.len() as f64;
    assert!(
        (0.3 * r..0.7 * r).contains(&mean),
        "uniform radii mean {mean}"
    );
    // Every quadrant is visited.
    for (sx, sy) in [(1.0, 1.0), (1.0, -1.0), (-1.0, 1.0), (-1.0, -1.0)] {
        assert!(
            ps.iter()
                .any(|p| (p[0] - x[0]) * sx > 0.0 && (p[1] - x[1]) * sy > 0.0),
            "quadrant ({sx}, {sy}) empty"
        );
    }
}

/// Two charts meeting at x = 0: Ω_0 = ℝ², Ω_1 = {y : y_0 < `omega1_max`}, Ω_01 = {p : `dom`(p)},
/// φ_10 = `phi`, Ω_10 = ∅ (so no limit lies in it), and ∂Ω_01 = {0}, ∂Ω_10 = {`y`}. The
/// fixtures of the limit-candidate and separating-radius tests below.
struct Edge {
    dom: fn(&Point<f64, 2>) -> bool,
    phi: fn(&Point<f64, 2>) -> Option<Point<f64, 2>>,
    omega1_max: f64,
    y: Point<f64, 2>,
}

impl GluingData<2> for Edge {
    type S = f64;
    fn indices(&self) -> Vec<Idx> {
        vec![0, 1]
    }
    fn in_p_domain(&self, i: Idx, p: &Point<f64, 2>) -> bool {
        i == 0 || p[0] < self.omega1_max
    }
    fn in_gluing_domain(&self, i: Idx, j: Idx, p: &Point<f64, 2>) -> bool {
        (i, j) == (0, 1) && (self.dom)(p)
    }
    fn phi(&self, j: Idx, i: Idx, p: &Point<f64, 2>) -> Option<Point<f64, 2>> {
        ((j, i) == (1, 0)).then(|| (self.phi)(p)).flatten()
    }
    fn sample_p_domain(&self, _: Idx, _: &mut ChaCha8Rng, _: usize) -> Vec<Point<f64, 2>> {
        vec![]
    }
    fn sample_gluing_domain(
        &self,
        i: Idx,
        j: Idx,
        _: &mut ChaCha8Rng,
        _: usize,
    ) -> Vec<Point<f64, 2>> {
        // One point, only to put (0, 1) in the sampled K.
        if (i, j) == (0, 1) {
            vec![[-0.5, 0.0]]
        } else {
            vec![]
        }
    }
    fn gluing_boundary_points(
        &self,
        i: Idx,
        j: Idx,
        _: &mut ChaCha8Rng,
        _: usize,
    ) -> Vec<Point<f64, 2>> {
        match (i, j) {
            (0, 1) => vec![[0.0, 0.0]],
            (1, 0) => vec![self.y],
            _ => vec![],
        }
    }
}

fn shift_up(p: &Point<f64, 2>) -> Option<Point<f64, 2>> {
    Some([p[0], p[1] + 1.0])
}

fn left(p: &Point<f64, 2>) -> bool {
    p[0] < 0.0
}

/// The candidates of `limit_candidates` at x = 0 for the seeds 0..20, one list per seed.
fn candidates(g: &Edge) -> Vec<Vec<Point<f64, 2>>> {
    (0..20)
        .map(|seed| limit_candidates(g, 0, 1, &[0.0, 0.0], &mut ChaCha8Rng::seed_from_u64(seed)))
        .collect()
}

/// D3.4.1(4): the limit of φ_10 at x is found from any direction into Ω_01, whichever
/// coordinates the direction has: a half-plane {p_0 + p_1 < 0} is entered only along
/// directions u with u_0 + u_1 < 0, and the step there has length t along u/|u|.
#[test]
fn d3_4_1_4_limit_candidates_are_found_along_every_direction_into_the_domain() {
    let g = Edge {
        dom: |p| p[0] + p[1] < 0.0,
        phi: shift_up,
        omega1_max: 1.0,
        y: [0.0, 1.0],
    };
    let c = candidates(&g);
    let found = c.iter().filter(|c| !c.is_empty()).count();
    assert!(
        found >= 18,
        "the limit (0, 1) found for {found} of 20 seeds"
    );
    for y in c.iter().flatten() {
        assert!(dist(y, &[0.0, 1.0]) <= 1e-12, "candidate {y:?}");
    }
}

/// D3.4.1(4): the limit is extrapolated from two points at distances t and 2t from x along a
/// unit direction, so on φ(p) = (p_0 + K p_0², p_1 + 1) its error is 2K(t·û_0)² ≤ 2Kt²,
/// t = scale·2⁻²⁰, whatever the direction.
#[test]
fn d3_4_1_4_limit_candidates_extrapolate_from_steps_t_and_2t() {
    const K: f64 = 1e3;
    let g = Edge {
        dom: left,
        phi: |p| Some([p[0] + K * p[0] * p[0], p[1] + 1.0]),
        omega1_max: 1.0,
        y: [0.0, 1.0],
    };
    let t = 2f64.powi(-20);
    let bound = 2.0 * K * t * t * (1.0 + 1e-9) + 1e-15;
    let c = candidates(&g);
    assert!(c.iter().filter(|c| !c.is_empty()).count() >= 18);
    for y in c.iter().flatten() {
        let e = dist(y, &[0.0, 1.0]);
        assert!(
            e <= bound,
            "candidate {y:?}: error {e:.3e} > 2Kt² = {bound:.3e}"
        );
    }
}

/// D3.4.1(4): a limit is kept only when it lies in the open Ω_j with the margin η on both
/// sides of every coordinate: y = (0, 1) is in Ω_1 = {y_0 < η/2} but y + η·e_0 is not.
#[test]
fn d3_4_1_4_limit_candidates_need_the_margin_on_both_sides() {
    let eta = LIMIT_MARGIN;
    let near = Edge {
        dom: left,
        phi: shift_up,
        omega1_max: eta / 2.0,
        y: [0.0, 1.0],
    };
    assert!(candidates(&near).iter().all(|c| c.is_empty()));
    let inside = Edge {
        omega1_max: 2.0 * eta,
        ..near
    };
    assert!(candidates(&inside).iter().filter(|c| !c.is_empty()).count() >= 18);
}

/// D3.4.1(4): φ(p) = (p_0, p_1 ± 1) (the sign of p_1) has two limits at x, (0, ±1); both are
/// kept as candidates, each once.
#[test]
fn d3_4_1_4_limit_candidates_keep_every_distinct_limit() {
    let g = Edge {
        dom: left,
        phi: |p| Some([p[0], p[1] + p[1].signum()]),
        omega1_max: 1.0,
        y: [0.0, 1.0],
    };
    let c = candidates(&g);
    let both = c.iter().filter(|c| c.len() == 2).count();
    assert!(both >= 10, "both limits found for {both} of 20 seeds");
    for c in &c {
        assert!(c.len() <= 2, "{c:?}");
        for y in c {
            assert!(dist(y, &[0.0, 1.0]).min(dist(y, &[0.0, -1.0])) <= 1e-12);
        }
    }
}

/// Harness rule for D3.4.1(4): a boundary point x near which no sample of Ω_ij has an image
/// (φ undefined there) gives no evidence: nothing is examined and the verdict is "skipped",
/// never "holds".
#[test]
fn d3_4_1_4_no_image_near_x_is_skipped_not_held() {
    let g = Edge {
        dom: left,
        phi: |_| None,
        omega1_max: 1.0,
        y: [0.0, 2.0],
    };
    let (r, seps) = check_4_with_radii(&g, &SampleConfig::default());
    assert_eq!(r.examined, 0);
    assert!(
        matches!(r.verdict(), crate::report::Verdict::Skipped { .. }),
        "{:?}",
        r.verdict()
    );
    assert!(seps.is_empty());
}

/// D3.4.1(4)'s separating radii are reported at a radius where V_x ∩ Ω_ij was sampled: φ is
/// defined only within 2⁻⁵⁰ of x, so the samples of the balls of radius ≥ 2⁻¹⁰ around x
/// (geometric radii down to 2⁻³⁹·r) have no image, and the separation of y = (0, 2) from the
/// limit (0, 1) is found at a smaller radius, with a finite r_y.
#[test]
fn d3_4_1_4_separating_radii_come_from_a_sampled_ball() {
    let g = Edge {
        dom: left,
        phi: |p| (p[0].hypot(p[1]) < 2f64.powi(-50)).then(|| [p[0], p[1] + 1.0]),
        omega1_max: 1.0,
        y: [0.0, 2.0],
    };
    let (r, seps) = check_4_with_radii(&g, &SampleConfig::default());
    assert!(r.examined > 0);
    assert!(
        matches!(r.verdict(), crate::report::Verdict::Holds),
        "{:?}",
        r.verdict()
    );
    let s = seps
        .iter()
        .find(|s| s.y == vec![0.0, 2.0])
        .expect("y = (0, 2) separated");
    assert!(s.r_x <= 2f64.powi(-14), "r_x = {:e}", s.r_x);
    assert!((0.4..0.6).contains(&s.r_y), "r_y = {}", s.r_y);
}
