//! The SPEC `SV-…` rows checked on a mesh: the abstract Def. 3.4.1 checkers and (C), (C′),
//! (C″) run unchanged on [`SigmaVView`]s (renamed `SV-<id>`), plus the claims of the tutorial
//! that are its own (count, first attempt, emptiness of the declared-empty pairs, eval,
//! smoothness, fit).

use super::gluing::{g_uw_on_domain, omega_uw_grid, Corner, PairCase, SigmaV, SigmaVError};
use super::surface::{SigmaVPps, SvConsts};
use super::view::{SigmaVView, Version};
use super::wedge::WedgeTable;
use crate::construction::maps::{EdgeConfig, P2};
use crate::gluing::data::{GluingData, Idx, Point};
use crate::gluing::sampled::{check_all, SampleConfig};
use crate::mesh::{FaceId, SimplicialSurface, VertexId};
use crate::report::{dev_max, Check, CheckResult, OnError, Verdict, Witness};
use crate::surface::jet::Jet;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde_json::json;
use std::collections::BTreeSet;

/// IDs whose failure is a documented erratum of the tutorial (SPEC.md, "Tutorial errata").
pub const SV_ERRATA: &[(&str, &str)] = &[
    (
        "SV-first",
        "the first attempt's wedges overlap (T 2092–2100: \"So, I did NOT make it right\")",
    ),
    (
        "SV-E-gu-factor",
        "g_u's angular factor 6/m_u (T 2174) is inverted; m_u/6 as in the report (R 690)",
    ),
    (
        "SV-E-angle-range",
        "g_u on [0, 2π) (T 2172, 2211) is not closed under θ ↦ m_uθ/6; the report's (−π, π] with R_(u,w)",
    ),
    (
        "SV-E-equilateral",
        "\"(1/2, √2/3)\" (T 2678) is not a vertex of the equilateral triangle; (1/2, −√3/2) (R 1360)",
    ),
];

/// The documented reason when `id` is a documented erratum of the tutorial.
pub fn sv_erratum(id: &str) -> Option<&'static str> {
    SV_ERRATA.iter().find(|(e, _)| *e == id).map(|(_, w)| *w)
}

/// The IDs of the failing checks among `checks` that are not documented errata
/// ([`sv_erratum`]): the failures that make `ppm check --spec --construction sigma-v` and
/// `ppm fit` exit 1.
pub fn unexpected_failures(checks: &[CheckResult]) -> Vec<String> {
    checks
        .iter()
        .filter(|r| r.failed() && sv_erratum(&r.id).is_none())
        .map(|r| r.id.clone())
        .collect()
}

/// Options of the run.
#[derive(Debug, Clone, Copy)]
pub struct SvCheckOptions {
    /// Seed of every sampler.
    pub seed: u64,
    /// Samples per domain in the abstract checkers.
    pub samples: usize,
    /// Triangles whose three vertices' corners form one abstract view (seeded subset).
    pub max_views: usize,
    /// κ of r_{v,σ}.
    pub kappa: f64,
    /// Patch degree.
    pub patch_degree: usize,
    /// Run the (C′)/(C″) coincidence searches (slow).
    pub c_prime: bool,
}

impl Default for SvCheckOptions {
    fn default() -> Self {
        SvCheckOptions {
            seed: 20240601,
            samples: 24,
            max_views: 2,
            kappa: super::DEFAULT_KAPPA,
            patch_degree: super::DEFAULT_PATCH_DEGREE,
            c_prime: false,
        }
    }
}

/// Merge `b` into `a` (same check on another view): counts (examined, offenders, evaluation
/// errors) add, the worst deviation is the NaN-propagating maximum, a failure anywhere fails
/// the merge, a view that examined something replaces a skipped verdict, and distinct notes
/// are joined with ` | `.
fn merge(a: &mut CheckResult, b: CheckResult) {
    let b_verdict = b.stored_verdict().clone();
    a.examined += b.examined;
    a.offenders += b.offenders;
    a.eval_errors += b.eval_errors;
    for w in b.witnesses {
        if a.witnesses.len() < crate::report::MAX_WITNESSES {
            a.witnesses.push(w);
        }
    }
    a.worst_deviation = match (a.worst_deviation, b.worst_deviation) {
        (Some(x), Some(y)) => Some(dev_max(x, y)),
        (x, y) => x.or(y),
    };
    a.tolerance = match (a.tolerance, b.tolerance) {
        (Some(x), Some(y)) => Some(dev_max(x, y)),
        (x, y) => x.or(y),
    };
    if b_verdict.is_failure() {
        a.adopt_verdict(Verdict::Fails);
    } else if matches!(a.stored_verdict(), Verdict::Skipped { .. })
        && !matches!(b_verdict, Verdict::Skipped { .. })
    {
        a.adopt_verdict(b_verdict);
    }
    // Each view's note (its skips, its tolerance) is kept: distinct notes are joined.
    if a.note.is_empty() {
        a.note = b.note;
    } else if !b.note.is_empty() && !a.note.split(" | ").any(|n| n == b.note) {
        a.note.push_str(" | ");
        a.note.push_str(&b.note);
    }
}

fn renamed(mut r: CheckResult, prefix: &str) -> CheckResult {
    r.id = format!("{prefix}{}", r.id);
    r
}

/// The triangles whose vertices form the abstract views (seeded choice).
pub fn view_faces(k: &SimplicialSurface, n: usize, seed: u64) -> Vec<FaceId> {
    let nf = k.num_faces();
    if nf == 0 {
        return vec![];
    }
    let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0x5157);
    let mut out: Vec<FaceId> = (0..n.min(nf))
        .map(|_| FaceId(rng.gen_range(0..nf as u32)))
        .collect();
    out.sort_unstable();
    out.dedup();
    out
}

/// SPEC `SV-count` (T 3240): |I| = 3·n_t = Σ_v m_v.
pub fn check_count(g: &SigmaV) -> CheckResult {
    let mut r = Check::new("SV-count", "|I| = 3·n_t p-domains and patches (T 3240)");
    let (a, b) = (g.len(), g.num_faces());
    r.holds(a == 3 * b, || {
        Witness::new(format!("|I| = {a} ≠ 3·{b}"), json!({"I": a, "n_t": b}))
    });
    r.finish("")
}

/// SPEC `SV-first` (T 2037–2100): the first attempt (all wedges in one plane) violates
/// Def. 3.4.1(1). Runs the abstract `check_1` on the corners of v and reports it under this ID.
pub fn check_first_attempt(g: &SigmaV, v: VertexId, cfg: &SampleConfig) -> CheckResult {
    let view = SigmaVView::at_vertices(g, &[v], Version::FirstAttempt);
    let mut r = crate::gluing::sampled::check_1(&view, cfg);
    r.id = "SV-first".into();
    r.name = "first attempt: Ω_(σ,v) = D_v ∩ int Δ pairwise disjoint (Def. 3.4.1(1))".into();
    r
}

/// The corners at u (case-(3) relative to w) and their wedges, for the emptiness scan.
fn declared_empty_pairs(g: &SigmaV, u: VertexId, w: VertexId) -> Vec<(Corner, Corner)> {
    let mut out = Vec::new();
    for i in g.corners_at(u) {
        for j in g.corners_at(w) {
            if matches!(g.case(i, j), PairCase::DeclaredEmptyEdge(_)) {
                out.push((i, j));
            }
        }
    }
    out
}

/// SPEC `SV-H`: for every edge [u, w] (one per degree pair), the pairs of case (3) declared
/// empty by T 2430–2442 have W_i ∩ g_(w,u)(W_j ∖ {0}) = ∅ (scanned on a grid of Ω_uw).
pub fn check_declared_empty(
    k: &SimplicialSurface,
    g: &SigmaV,
    t: &WedgeTable<f64>,
    side: usize,
) -> CheckResult {
    let mut r = Check::new(
        "SV-H",
        "case-(3) pairs with [u,w] an edge are empty: W_i ∩ g_(w,u)(W_j−{0}) = ∅",
    )
    .with_note(format!(
        "grid of {side}² points of the canonical lens pulled back into Ω_uw, one edge per (m_u, m_w), κ = {}",
        g.kappa
    ));
    let mut seen = BTreeSet::new();
    for (u, w) in k.edges() {
        for (a, b) in [(u, w), (w, u)] {
            let key = (g.degree(a), g.degree(b));
            if !seen.insert(key) {
                continue;
            }
            // Every edge of K has a label at both ends; a missing one is an offence (the
            // statement is about every edge).
            let Some(l) = g.label(a, b) else {
                r.holds(false, || {
                    Witness::new(
                        format!("edge [{a},{b}] of K has no label at {a}"),
                        json!({"u": a, "w": b}),
                    )
                });
                continue;
            };
            let e = g.edge_config(a, l);
            let pairs = declared_empty_pairs(g, a, b);
            for q in omega_uw_grid(&e, side) {
                r.examined(1);
                for &(i, j) in &pairs {
                    if let Some(y) = g.case3_formula(t, j, i, &q) {
                        r.offend(|| {
                            Witness::new(
                                format!(
                                    "edge [{a},{b}] (m = {}, {}), i = ({a}, k={}), j = ({b}, k={}): q = ({:.6}, {:.6}) ∈ W_i and g_(u,w)(q) = ({:.6}, {:.6}) ∈ W_j",
                                    key.0, key.1, i.k, j.k, q.x, q.y, y.x, y.y
                                ),
                                json!({"u": a, "w": b, "i_k": i.k, "j_k": j.k, "q": [q.x, q.y], "y": [y.x, y.y], "kappa": g.kappa}),
                            )
                        });
                    }
                }
            }
        }
    }
    // Rule 3: no grid point examined is skipped, not holds.
    r.finish("")
}

/// The smallest κ on the grid `kappas` at which SV-H fails for degrees (m_u, m_w) (labels 0),
/// with a witness; `None` when it holds at every κ given.
pub fn emptiness_threshold(
    m_u: u32,
    m_w: u32,
    kappas: &[f64],
    side: usize,
) -> Option<(f64, [f64; 2])> {
    let e = EdgeConfig {
        m_u,
        i: 0,
        m_w,
        j: 0,
    };
    for &kappa in kappas {
        let tu = super::wedge::WedgeConsts::<f64>::new(m_u, kappa, 53);
        let tw = super::wedge::WedgeConsts::<f64>::new(m_w, kappa, 53);
        for q in omega_uw_grid(&e, side) {
            let Some(y) = g_uw_on_domain(&e, &q) else {
                continue;
            };
            // case (3): w ∉ τ (label 0 ∉ {k, k+1}) and u ∉ η (0 ∉ {k', k'+1}).
            for ki in 1..m_u - 1 {
                if !tu.in_wedge(ki, &q) {
                    continue;
                }
                for kj in 1..m_w - 1 {
                    if tw.in_wedge(kj, &y) {
                        return Some((kappa, [q.x, q.y]));
                    }
                }
            }
        }
    }
    None
}

/// The plane point of an abstract point of the view (for θ).
fn theta_fn<'a>(
    pps: &'a SigmaVPps,
    view: &'a SigmaVView<'a>,
) -> impl Fn(Idx, &Point<f64, 2>) -> Vec<f64> + 'a {
    move |i, x| {
        let (Some(c), Some(q)) = (view.corner(i), view.to_plane(i, x)) else {
            return vec![f64::NAN; 3];
        };
        pps.theta_f64(c, [q.x, q.y])
            .map(|t| t.to_vec())
            .unwrap_or_else(|_| vec![f64::NAN; 3])
    }
}

/// SPEC `SV-D13`: eval's point lies in W_(σ,c*) and θ is defined there; samples of every
/// face (up to `max_faces`).
pub fn check_eval(pps: &SigmaVPps, max_faces: usize, seed: u64) -> CheckResult {
    let mut r = Check::new(
        "SV-D13",
        "eval(σ,λ,μ,ν): q ∈ W_(σ,c*) and θ defined (T 2649–2747)",
    )
    .with_seed(seed ^ 0xe7a1);
    let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0xe7a1);
    let nf = pps.gluing.num_faces();
    let c = pps.consts_f64();
    for fi in 0..nf.min(max_faces) {
        let f = FaceId(fi as u32);
        let mut pts: Vec<[f64; 3]> = vec![
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
            [1.0 / 3.0; 3],
        ];
        // The edge midpoints and their neighbours one and two ulps away: there the chart
        // rule's circle (radius √3/2 about the opposite corner) is tangent to the edge and
        // the rounded distance can pick a chart whose p-domain excludes the point.
        let below = |x: f64, k: u64| f64::from_bits(x.to_bits() - k);
        for z in 0..3 {
            for t in [0.5, below(0.5, 1), below(0.5, 2), 1.0 - below(0.5, 2)] {
                let mut b = [0.0; 3];
                b[(z + 1) % 3] = t;
                b[(z + 2) % 3] = 1.0 - t;
                pts.push(b);
            }
        }
        for _ in 0..8 {
            pts.push(crate::report::uniform_in_triangle(&mut rng));
        }
        for b in pts {
            match pps.eval(f, &b, c) {
                Ok((corner, q, x)) => r.holds(x.iter().all(|v| v.is_finite()), || {
                    Witness::new(
                        format!("face {fi} bary {b:?}: θ = {x:?} at corner {corner:?}, q = {q:?}"),
                        json!({"face": fi, "bary": b}),
                    )
                }),
                // The statement: eval is defined at every point of every face.
                Err(e) => r.error(OnError::Offence, &e, || {
                    Witness::new(
                        format!("face {fi} bary {b:?}: {e}"),
                        json!({"face": fi, "bary": b, "error": e.to_string()}),
                    )
                }),
            }
        }
    }
    r.finish("")
}

/// What `SV-smooth` differentiates: θ_i as a jet at a plane point q of P_v (the construction,
/// or a planted fault in tests).
pub trait ThetaJets {
    /// θ_i at q = f_i(p), with its derivatives to order 3 (as [`SigmaVPps::theta_plane`]).
    fn theta_jet(&self, i: Corner, q: &P2<Jet<f64>>) -> Result<[Jet<f64>; 3], SigmaVError>;
}

/// The construction's θ with its jet constants (built once).
pub struct PpsJets<'a> {
    pps: &'a SigmaVPps,
    cj: SvConsts<Jet<f64>>,
}

impl<'a> PpsJets<'a> {
    /// The jets of `pps`'s θ.
    pub fn new(pps: &'a SigmaVPps) -> Self {
        PpsJets {
            pps,
            cj: pps.consts(53),
        }
    }
}

impl ThetaJets for PpsJets<'_> {
    fn theta_jet(&self, i: Corner, q: &P2<Jet<f64>>) -> Result<[Jet<f64>; 3], SigmaVError> {
        self.pps.theta_plane(i, q, &self.cj)
    }
}

/// Rule 2 for θ: `NotInOmega` says the point (a sample, or p ± h of its stencil) lies outside
/// Ω_i, outside the statement's domain: skipped. Any other error (Σγ not positive, …) at a
/// point of Ω_i contradicts "θ_i is defined and C^∞ on Ω_i": an offence.
fn theta_on_error(e: &SigmaVError) -> OnError {
    match e {
        SigmaVError::NotInOmega { .. } => OnError::Skip,
        _ => OnError::Offence,
    }
}

/// The first stencil half-width of `SV-smooth`, in the plane coordinates of P_v.
pub const SMOOTH_H0: f64 = 1e-3;
/// How often `SV-smooth` halves the stencil at one sample (h down to 1e-3/64 ≈ 1.6e-5,
/// where the rounding term 4ε·|θ|/h² is still ≤ 3.7e-6·|θ|).
pub const SMOOTH_HALVINGS: u32 = 6;

/// SPEC `SV-smooth` (T 3230): θ_i is C^∞ — measured as agreement of the analytic jet with
/// central differences at points of ∂Ω_ij (where terms enter J(p)) and of Ω_i.
///
/// The tolerance per point is Taylor's bound: for θ of class C³ the central second difference
/// errs by at most h·M₃/3, M₃ = max |θ'''| over the segment [p − h, p + h], plus rounding
/// 4ε·|θ|/h². M₃ is estimated by the largest third derivative of the jets at the five stencil
/// points (taken twice: 2h·M̂₃/3). That estimate bounds M₃ only where the stencil resolves θ''';
/// where θ''' varies on a scale below h (narrow wedges at a vertex of high degree, where the
/// weights γ switch on within a fraction of the wedge) it can be many times smaller. So the
/// stencil is halved (at most [`SMOOTH_HALVINGS`] times) while the bound is exceeded: as h → 0
/// the five-point estimate tends to M₃ for a C³ θ whose jets are its derivatives, while a jet
/// whose second derivative is off by δ stays δ away at every h and fails once the tolerance
/// is below δ. A stencil point outside Ω_i is retried at a smaller h too.
pub fn check_smooth(pps: &SigmaVPps, view: &SigmaVView, cfg: &SampleConfig) -> CheckResult {
    check_smooth_with(&PpsJets::new(pps), view, cfg)
}

/// [`check_smooth`] over several views, one result (counts and the note's skipped samples
/// over all views).
pub fn check_smooth_views(
    pps: &SigmaVPps,
    views: &[SigmaVView],
    cfg: &SampleConfig,
) -> CheckResult {
    check_smooth_views_with(&PpsJets::new(pps), views, cfg)
}

/// [`check_smooth`] on any source of θ's jets. Every sample goes through [`Check`]: a
/// non-finite jet coefficient (value or any derivative to order 3) at one of the five stencil
/// points is a NaN deviation, an offence (C^∞ claims every derivative exists).
pub fn check_smooth_with(
    src: &dyn ThetaJets,
    view: &SigmaVView,
    cfg: &SampleConfig,
) -> CheckResult {
    check_smooth_views_with(src, std::slice::from_ref(view), cfg)
}

/// One stencil's outcome at one sample of `SV-smooth`.
enum Stencil {
    /// The deviation relative to the tolerance (NaN when a jet coefficient is not finite).
    Measured(f64),
    /// An evaluation failed at offset (dx, dy).
    Failed(f64, f64, SigmaVError),
}

/// The central second differences at q with half-width h against the jet at q (`t0`).
fn smooth_stencil(
    src: &dyn ThetaJets,
    c: Corner,
    q: &P2<f64>,
    t0: &[Jet<f64>; 3],
    h: f64,
) -> Stencil {
    let mut jets: Vec<[Jet<f64>; 3]> = Vec::with_capacity(5);
    jets.push(t0.clone());
    for (dx, dy) in [(h, 0.0), (-h, 0.0), (0.0, h), (0.0, -h)] {
        let (a, b) = Jet::variables(q.x + dx, q.y + dy);
        match src.theta_jet(c, &P2::new(a, b)) {
            Ok(t) => jets.push(t),
            Err(e) => return Stencil::Failed(dx, dy, e),
        }
    }
    let [t0, px, mx, py, my] = [0, 1, 2, 3, 4].map(|k| &jets[k]);
    let finite = jets
        .iter()
        .all(|t| t.iter().all(|d| d.c.iter().all(|x| x.is_finite())));
    if !finite {
        return Stencil::Measured(f64::NAN);
    }
    let third = |t: &[Jet<f64>; 3]| -> f64 {
        t.iter()
            .flat_map(|d| {
                [
                    d.derivative(3, 0),
                    d.derivative(2, 1),
                    d.derivative(1, 2),
                    d.derivative(0, 3),
                ]
            })
            .fold(0.0f64, |a, b| dev_max(a, b.abs()))
    };
    let t3 = jets.iter().map(third).fold(0.0f64, dev_max);
    let mag = t0.iter().map(|d| d.value().abs()).fold(1.0f64, dev_max);
    let tol = 2.0 * h * t3 / 3.0 + 4.0 * f64::EPSILON * mag / (h * h);
    let mut dev = 0.0f64;
    for d in 0..3 {
        let fxx = (px[d].value() - 2.0 * t0[d].value() + mx[d].value()) / (h * h);
        let fyy = (py[d].value() - 2.0 * t0[d].value() + my[d].value()) / (h * h);
        dev = dev_max(dev, (fxx - t0[d].derivative(2, 0)).abs() / tol);
        dev = dev_max(dev, (fyy - t0[d].derivative(0, 2)).abs() / tol);
    }
    Stencil::Measured(dev)
}

/// [`check_smooth_with`] over several views.
pub fn check_smooth_views_with(
    src: &dyn ThetaJets,
    views: &[SigmaVView],
    cfg: &SampleConfig,
) -> CheckResult {
    let mut r = Check::sampled(
        "SV-smooth",
        "θ_(σ,v) is C^∞ (jet vs central differences, order ≤ 2)",
        cfg.seed,
        1.0,
    );
    // Samples measured at a stencil smaller than SMOOTH_H0 (because the bound was exceeded
    // at a larger h, or a stencil point left Ω_i), and the smallest h used.
    let (mut by_bound, mut by_outside) = (0u64, 0u64);
    let mut h_min = SMOOTH_H0;
    for view in views {
        let mut rng = cfg.rng(77);
        let ids = view.indices();
        for &i in &ids {
            // Every index of the view has a corner (SigmaVView::new keeps only those of I).
            let Some(c) = view.corner(i) else {
                r.error(OnError::Offence, "index without a corner", || {
                    Witness::new(format!("corner {i}: not a corner of I"), json!({"i": i}))
                });
                continue;
            };
            let mut pts: Vec<Point<f64, 2>> = view.sample_p_domain(i, &mut rng, cfg.n / 4 + 1);
            for &j in &ids {
                if j != i {
                    pts.extend(view.gluing_boundary_points(i, j, &mut rng, 2));
                }
            }
            for x in pts {
                // f_i is defined on i's whole copy (the wedge table has every degree of K).
                let Some(q) = view.to_plane(i, &x) else {
                    r.error(OnError::Offence, "f_i undefined", || {
                        Witness::new(
                            format!(
                                "corner {i} at x = ({:.6}, {:.6}): f_i undefined",
                                x[0], x[1]
                            ),
                            json!({"i": i, "x": x}),
                        )
                    });
                    continue;
                };
                let failed = |r: &mut Check, dx: f64, dy: f64, e: &SigmaVError| {
                    r.error(theta_on_error(e), e, || {
                        Witness::new(
                            format!(
                                "corner {i} at q = ({:.6}, {:.6}) + ({dx}, {dy}): {e}",
                                q.x, q.y
                            ),
                            json!({"i": i, "q": [q.x, q.y], "offset": [dx, dy], "error": e.to_string()}),
                        )
                    })
                };
                let (a, b) = Jet::variables(q.x, q.y);
                let t0 = match src.theta_jet(c, &P2::new(a, b)) {
                    Ok(t) => t,
                    Err(e) => {
                        failed(&mut r, 0.0, 0.0, &e);
                        continue;
                    }
                };
                // The smallest deviation over the stencils measured (a NaN is kept and ends
                // the search), with its h; the last stencil that left Ω_i; an offence.
                let mut best: Option<(f64, f64)> = None;
                let mut outside: Option<(f64, f64, SigmaVError)> = None;
                let mut offence: Option<(f64, f64, SigmaVError)> = None;
                let mut exceeded = false;
                for k in 0..=SMOOTH_HALVINGS {
                    let h = SMOOTH_H0 / f64::from(1u32 << k);
                    match smooth_stencil(src, c, &q, &t0, h) {
                        Stencil::Failed(dx, dy, e) => match theta_on_error(&e) {
                            OnError::Skip => outside = Some((dx, dy, e)),
                            OnError::Offence => {
                                offence = Some((dx, dy, e));
                                break;
                            }
                        },
                        Stencil::Measured(d) => {
                            if d.is_nan() || best.map_or(true, |(b, _)| d < b) {
                                best = Some((d, h));
                            }
                            if !(d > 1.0) {
                                break;
                            }
                            exceeded = true;
                        }
                    }
                }
                if let Some((dx, dy, e)) = offence {
                    failed(&mut r, dx, dy, &e);
                    continue;
                }
                let Some((dev, h)) = best else {
                    // Every stencil left Ω_i: outside the statement's domain.
                    if let Some((dx, dy, e)) = outside {
                        failed(&mut r, dx, dy, &e);
                    }
                    continue;
                };
                if h < SMOOTH_H0 {
                    if exceeded {
                        by_bound += 1;
                    } else {
                        by_outside += 1;
                    }
                    h_min = h_min.min(h);
                }
                let finite = !dev.is_nan();
                let what = if finite {
                    "second difference off the jet by"
                } else {
                    "non-finite jet coefficient; deviation"
                };
                r.deviation(dev, || {
                    Witness::new(
                        format!(
                            "corner {i} at q = ({:.6}, {:.6}), h = {h:.3e}: {what} {dev:.3e}× the tolerance",
                            q.x, q.y
                        ),
                        json!({"i": i, "q": [q.x, q.y], "h": h, "ratio": dev, "finite": finite}),
                    )
                });
            }
        }
    }
    r.finish(format!(
        "h = {SMOOTH_H0}, halved up to {SMOOTH_HALVINGS} times where the five-point third-derivative bound is exceeded ({by_bound} samples) or a stencil point leaves Ω_i ({by_outside}); smallest h {h_min:.3e}; deviation relative to the per-point tolerance"
    ))
}

/// Every check of the tutorial's construction on K (the `ppm check --spec --construction
/// sigma-v` run).
pub fn run_sigma_v_checks(
    k: &SimplicialSurface,
    target: &dyn crate::surface::TargetSurface,
    o: &SvCheckOptions,
) -> Vec<CheckResult> {
    let mut out = Vec::new();
    let g = match SigmaV::new(k, o.kappa) {
        Ok(g) => g,
        Err(e) => {
            let mut r = CheckResult::new("SV-D3", "the overlapping-point parameter");
            r.offend(|| Witness::new(e.to_string(), json!({"kappa": o.kappa})));
            return vec![r];
        }
    };
    let cfg = SampleConfig {
        seed: o.seed,
        n: o.samples.max(1),
    };
    out.push(check_count(&g));
    out.extend(super::errata::run_errata(g.degrees()));
    let faces = view_faces(k, o.max_views.max(1), o.seed);
    if let Some(&f) = faces.first() {
        out.push(check_first_attempt(&g, k.face(f)[0], &cfg));
    }
    let t = WedgeTable::<f64>::new(g.degrees().iter().copied(), g.kappa, 53);
    out.push(check_declared_empty(k, &g, &t, 160));
    let pps = match SigmaVPps::build(k, target, o.kappa, o.patch_degree) {
        Ok(p) => p,
        Err(e) => {
            let mut r = CheckResult::new("SV-D11", "shape functions");
            r.offend(|| Witness::new(e.to_string(), json!({})));
            out.push(r);
            return out;
        }
    };
    let mut fit = Check::new(
        "SV-psi",
        "ψ by least squares: full rank per (m, d) (T 2916)",
    );
    for f in pps.fit_info() {
        fit.holds(f.rank == f.unknowns, || {
            let f = f.clone();
            Witness::new(
                format!("degree {}: rank {} < {} unknowns", f.m, f.rank, f.unknowns),
                json!(f),
            )
        });
    }
    // Reported, not judged; NaN-propagating so a NaN condition number shows.
    let worst_cond = pps
        .fit_info()
        .iter()
        .map(|f| f.condition)
        .fold(0.0, dev_max);
    out.push(fit.finish(format!("largest κ(A) = {worst_cond:.3e}")));
    out.extend(check_built(k, &g, &pps, o));
    out
}

/// The checks of a built (σ, v) PPS over K: Def. 3.4.1 and condition (C) on the abstract
/// views at seeded faces, smoothness, eval. Shared by the sampled construction and the
/// adaptive fit (`fitting`), whose ψ are fitted otherwise.
pub fn check_built(
    k: &SimplicialSurface,
    g: &SigmaV,
    pps: &SigmaVPps,
    o: &SvCheckOptions,
) -> Vec<CheckResult> {
    let mut out = Vec::new();
    let cfg = SampleConfig {
        seed: o.seed,
        n: o.samples.max(1),
    };
    let faces = view_faces(k, o.max_views.max(1), o.seed);
    let mut merged: Vec<CheckResult> = Vec::new();
    for &f in &faces {
        let view = SigmaVView::at_vertices(g, &k.face(f), Version::Fixed);
        let mut rs: Vec<CheckResult> = check_all(&view, &cfg)
            .into_iter()
            .map(|r| renamed(r, "SV-"))
            .collect();
        let th = theta_fn(pps, &view);
        rs.push(renamed(
            crate::gluing::ppm::check_c(&view, &th, &cfg),
            "SV-",
        ));
        if o.c_prime {
            rs.push(renamed(
                crate::gluing::ppm::check_c_prime(&view, &th, &cfg),
                "SV-",
            ));
            rs.push(renamed(
                crate::gluing::ppm::check_c_second(&view, &th, &cfg),
                "SV-",
            ));
        }
        for r in rs {
            match merged.iter_mut().find(|m| m.id == r.id) {
                Some(m) => merge(m, r),
                None => merged.push(r),
            }
        }
    }
    out.extend(merged);
    // One result over the views, so its note counts every view's skipped samples.
    let views: Vec<SigmaVView> = faces
        .iter()
        .map(|&f| SigmaVView::at_vertices(g, &k.face(f), Version::Fixed))
        .collect();
    out.push(check_smooth_views(pps, &views, &cfg));
    out.push(check_eval(pps, 2000, o.seed));
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn merge_adds_counts_and_keeps_every_views_note() {
        let view = |note: &str, examined: u64| {
            let mut r = CheckResult::new("SV-x", "one check on one view");
            r.note = note.to_string();
            r.examined = examined;
            r
        };
        let mut a = view("view 1: 2 samples skipped", 3);
        merge(&mut a, view("view 2: 5 samples skipped", 4));
        merge(&mut a, view("view 2: 5 samples skipped", 1));
        merge(&mut a, view("", 1));
        assert_eq!(
            a.note,
            "view 1: 2 samples skipped | view 2: 5 samples skipped"
        );
        assert_eq!(a.examined, 9);
    }
}
