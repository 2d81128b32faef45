//! Adaptive manifold fitting (seed 002, "Adaptive Manifold Fitting", Parts I–II): given a
//! closed triangle mesh S_T and ε > 0, a C^∞ surface S — the (σ, v)-indexed PPS over a base
//! mesh S̃_T whose vertices are vertices of S_T — with ‖S(p_v) − v‖ ≤ ε at the parameter p_v
//! of every vertex v of S_T, with few charts.
//!
//! The pipeline, one module per stage:
//! 1. [`simplify`]: stellar simplification ranked by quadric error, independent sets per level;
//!    it carries the parametrization of S_T onto the base mesh ([`base`]).
//! 2. [`embedded`]: every base edge embedded in |S_T| as a geodesic ([`geodesic`]: an
//!    initial edge path, [`shorten`]: iterative shortening), S_T cut into curved triangles
//!    ([`overlay`]), each mapped onto its base triangle by Floater's mean value
//!    parametrization ([`floater`]); its parameters of the vertices of S_T are the fit's.
//! 3. [`fitted`]: the (σ, v) construction over the base mesh with ψ_(σ,v) fitted by least
//!    squares to the vertices of S_T at those parameters.
//! 4. [`refine`]: where a vertex misses ε, the base mesh is refined locally (stellar face
//!    split at the worst vertex, Lawson flips), and 2–3 are repeated: the embedding only where
//!    the base mesh changed ([`local`]; all of S_T again where that fails), the fit whole.
//!
//! Where the slides are silent, the choices are stated at each module and in SPEC.md
//! (section "Adaptive fitting", rows `AF-…`).

pub mod base;
pub mod checks;
pub(crate) mod disjoint;
pub mod embed_checks;
pub mod embedded;
pub mod fitted;
pub mod floater;
pub mod format;
pub mod geodesic;
pub mod local;
pub mod overlay;
pub mod refine;
pub mod route;
pub mod shorten;
pub mod simplify;
pub mod straighten;
pub mod unblock;

use base::{BaseMesh, RemovalLimits};
use fitted::{BaseSurface, BaseSurfaceError, Fitted, SurfaceParam};
use rayon::prelude::*;
use serde::Serialize;
use simplify::{Hierarchy, SimplifyOptions};

use crate::mesh::SimplicialSurface;
use crate::surface::sigma_v::{SigmaVError, SigmaVPps};

/// Options of [`fit_surface`].
#[derive(Debug, Clone, Copy)]
pub struct FitOptions {
    /// ε, absolute.
    pub epsilon: f64,
    /// The simplification may leave vertices of S_T this many ε from the flat base triangles
    /// (the smooth fit then closes the gap; refinement where it does not).
    pub deviation_ratio: f64,
    /// κ of the (σ, v) construction.
    pub kappa: f64,
    /// Patch degree of ψ_(σ,v).
    pub degree: usize,
    /// Largest base vertex degree.
    pub max_degree: usize,
    /// Refinement rounds at most.
    pub max_rounds: usize,
}

impl FitOptions {
    /// Defaults for a given ε.
    pub fn new(epsilon: f64) -> Self {
        FitOptions {
            epsilon,
            deviation_ratio: 4.0,
            kappa: crate::surface::sigma_v::DEFAULT_KAPPA,
            degree: crate::surface::sigma_v::DEFAULT_PATCH_DEGREE,
            max_degree: 12,
            max_rounds: 40,
        }
    }
}

/// Why a fit failed.
#[derive(Debug, thiserror::Error)]
pub enum FitError {
    /// ε must be a positive finite number.
    #[error("epsilon must be positive and finite, got {0}")]
    BadEpsilon(f64),
    /// The (σ, v) construction refused the base mesh.
    #[error("the (sigma, v) construction refused the base mesh: {0}")]
    SigmaV(#[from] SigmaVError),
    /// The base mesh stayed invalid (classes) after the repair rounds.
    #[error("the base mesh is not a simplicial surface after {rounds} repair rounds: {classes}")]
    BaseInvalid {
        /// Rounds spent.
        rounds: usize,
        /// The validator's defect classes.
        classes: String,
    },
    /// ε was not reached in the allowed rounds.
    #[error("epsilon {epsilon} not reached after {rounds} refinement rounds: {offenders} vertices still further (worst {worst}), {folds} triangles of S_T folded")]
    NotReached {
        /// ε.
        epsilon: f64,
        /// Rounds spent.
        rounds: usize,
        /// Vertices still beyond ε.
        offenders: usize,
        /// Largest error.
        worst: f64,
        /// Triangles of S_T still folded in T_v.
        folds: usize,
    },
}

/// One round of fit and refinement.
#[derive(Debug, Clone, Serialize)]
pub struct Round {
    /// Base vertices (charts: one p-domain per corner, |I| = 3·faces; the vertex count is
    /// what refinement adds to).
    pub base_vertices: usize,
    /// Largest ‖S(p_v) − v‖ over the vertices of S_T.
    pub max_error: f64,
    /// Its 99th percentile.
    pub p99_error: f64,
    /// Vertices beyond ε (error plus rounding bound).
    pub offenders: usize,
    /// Pieces of triangles of S_T folded by Floater's maps (`AF-param-bijective`), reported.
    pub folds: usize,
    /// Refinement done after the round (None for the last).
    pub refine: Option<refine::RefineStats>,
    /// What the round's embedding kept from the previous round's (None: all of S_T was
    /// embedded, [`local`]).
    pub local: Option<local::LocalStats>,
    /// Seconds spent in the round.
    pub seconds: f64,
}

/// A fit and how it was reached.
pub struct Fit {
    /// ε (absolute).
    pub epsilon: f64,
    /// The base mesh with the parametrization of S_T.
    pub base: BaseMesh,
    /// The base mesh as a validated surface.
    pub surface: BaseSurface,
    /// Parameters of the vertices of S_T in the surface's ids (Floater's).
    pub params: Vec<SurfaceParam>,
    /// The embedded base mesh and Floater's maps, or why there are none.
    pub embedded: Result<embedded::Embedded, embedded::Failure>,
    /// Whether `params` are Floater's (else the simplification's: the embedding failed).
    pub floater_params: bool,
    /// The fitted PPS.
    pub fitted: Fitted,
    /// Error of every vertex of S_T.
    pub errors: Vec<f64>,
    /// Bound on the f64 rounding of eval (added to each error before comparing with ε).
    pub rounding_bound: f64,
    /// The simplification.
    pub hierarchy: Hierarchy,
    /// Repair rounds spent on an invalid base mesh.
    pub repairs: usize,
    /// The rounds.
    pub rounds: Vec<Round>,
    /// The base-mesh changes where a base edge had no curve (the AC·CB rule, `unblock`).
    pub unblock: unblock::Walk,
}

/// A bound on |fl(eval) − eval| for the fitted PPS: the operation count of
/// `surface::eval_bound` (patches of degree d: γ_{8d+8}; maps and blend: `MAP_BOUND_ULPS` ulps)
/// times the largest control point. An operation count, not a proof; the checks compare it
/// with 256-bit evaluations on a seeded sample (SPEC `AF-epsilon`).
pub fn rounding_bound(pps: &SigmaVPps) -> f64 {
    use crate::surface::eval_bound::{gamma_n, MAP_BOUND_ULPS};
    (gamma_n(8 * pps.degree + 8) + MAP_BOUND_ULPS * f64::EPSILON) * pps.scale()
}

/// ‖S(p_x) − x‖ for every vertex x of S_T (NaN when eval fails).
pub fn vertex_errors(pps: &SigmaVPps, pos: &[[f64; 3]], params: &[SurfaceParam]) -> Vec<f64> {
    params
        .par_iter()
        .zip(pos.par_iter())
        .map(|(&(f, b), x)| match pps.eval_f64(f, b) {
            Ok(s) => crate::numeric::robust_norm(&[s[0] - x[0], s[1] - x[1], s[2] - x[2]]),
            Err(_) => f64::NAN,
        })
        .collect()
}

fn percentile(v: &[f64], q: f64) -> f64 {
    let mut s: Vec<f64> = v.to_vec();
    s.sort_by(f64::total_cmp);
    s.get(((s.len() as f64 - 1.0) * q).round() as usize)
        .copied()
        .unwrap_or(f64::NAN)
}

/// Repair rounds at most for a base mesh the validator refuses.
const MAX_REPAIRS: usize = 60;

/// The base faces as sorted vertex triples (which base meshes were embedded already).
fn face_key(base: &BaseMesh) -> Vec<[u32; 3]> {
    let mut f: Vec<[u32; 3]> = base.faces().map(|(_, c)| c).collect();
    f.sort_unstable();
    f
}

/// Simplification attempts: a base mesh the repair cannot make valid is simplified again
/// with half the deviation allowance (closer to S_T, so fewer crossings).
const ATTEMPTS: usize = 4;

/// The adaptive fit of S_T = `k` (module doc). `progress` receives one line per stage.
pub fn fit_surface(
    k: &SimplicialSurface,
    opts: &FitOptions,
    mut progress: impl FnMut(&str),
) -> Result<Fit, FitError> {
    if !(opts.epsilon > 0.0 && opts.epsilon.is_finite()) {
        return Err(FitError::BadEpsilon(opts.epsilon));
    }
    let mut o = *opts;
    let mut attempt = 1;
    loop {
        match fit_once(k, &o, &mut progress) {
            Err(FitError::BaseInvalid { .. }) if attempt < ATTEMPTS => {
                o.deviation_ratio /= 2.0;
                attempt += 1;
                progress(&format!(
                    "simplify again: deviation allowance {} epsilon",
                    o.deviation_ratio
                ));
            }
            r => return r,
        }
    }
}

fn fit_once(
    k: &SimplicialSurface,
    opts: &FitOptions,
    progress: &mut impl FnMut(&str),
) -> Result<Fit, FitError> {
    let t0 = std::time::Instant::now();
    let mut base = BaseMesh::new(k);
    let sopts = SimplifyOptions {
        limits: RemovalLimits {
            max_deviation: opts.deviation_ratio * opts.epsilon,
            min_normal_cos: 0.5,
            min_quality: 0.1,
            max_degree: opts.max_degree,
        },
        min_vertices: 4,
        max_levels: 200,
    };
    let hierarchy = simplify::simplify(&mut base, k, &sopts, |lvl, n| {
        progress(&format!("simplify: level {lvl}, {n} base vertices"))
    });
    progress(&format!(
        "simplify: {} levels, {} base vertices of {} ({:.1} s)",
        hierarchy.levels.len(),
        base.base_vertices().len(),
        k.num_vertices(),
        t0.elapsed().as_secs_f64()
    ));
    let pos = base.positions().to_vec();
    let mut rounds: Vec<Round> = Vec::new();
    let mut repairs = 0;
    let mut failed_at: Vec<(Vec<[u32; 3]>, embedded::Failure)> = Vec::new();
    let mut walk = unblock::Walk::default();
    // The last embedding whose every check held, kept for the next round's local update.
    let mut prev: Option<local::Previous> = None;
    loop {
        let tr = std::time::Instant::now();
        let surface = match BaseSurface::new(&base) {
            Ok(s) => s,
            Err(BaseSurfaceError::NotASurface { classes, crossing }) => {
                repairs += 1;
                let names: Vec<&str> = classes.iter().map(|c| c.name()).collect();
                if repairs > MAX_REPAIRS || crossing.is_empty() {
                    return Err(FitError::BaseInvalid {
                        rounds: repairs,
                        classes: names.join(", "),
                    });
                }
                let st = repair(&mut base, &crossing, &pos);
                progress(&format!(
                    "repair: base mesh refused ({}), {} vertices inserted, {} edges flipped",
                    names.join(", "),
                    st.inserted,
                    st.flips
                ));
                if st.inserted == 0 && st.flips == 0 {
                    return Err(FitError::BaseInvalid {
                        rounds: repairs,
                        classes: names.join(", "),
                    });
                }
                continue;
            }
            Err(BaseSurfaceError::SigmaV(e)) => return Err(e.into()),
        };
        // The embedding and Floater's parameters are used when every check of theirs
        // holds; otherwise the simplification's parameters are, and the failure is reported
        // (`AF-embedding`, and the checks of the embedding that exists), never passed on.
        // A base mesh whose embedding failed is not embedded again (the failure is kept).
        // After a refinement, only what changed is embedded again (`local`); the local result
        // is used only when every check of the embedding holds on all of it, else all of S_T
        // is embedded again.
        let key = face_key(&base);
        let mut local_stats = None;
        let mut checked = None;
        let mut emb = match failed_at.iter().find(|(x, _)| *x == key) {
            Some((_, f)) => {
                progress("embed: failed at this base mesh before, not tried again");
                Err(f.clone())
            }
            None => match prev.as_ref().map(|p| local::embed_local(k, &base, p)) {
                None => embedded::embed(k, &base),
                Some(Ok((e, st))) => {
                    let checks = embed_checks::run(k, &base, &e);
                    let bad: Vec<&str> = checks
                        .iter()
                        .filter(|r| r.failed())
                        .map(|r| r.id.as_str())
                        .collect();
                    if bad.is_empty() {
                        local_stats = Some(st);
                        checked = Some(checks);
                        Ok(e)
                    } else {
                        progress(&format!(
                            "embed: the local update fails {}; embedding all of S_T again",
                            bad.join(", ")
                        ));
                        embedded::embed(k, &base)
                    }
                }
                Some(Err(f)) => {
                    progress(&format!(
                        "embed: the local update failed ({}); embedding all of S_T again",
                        f.what
                    ));
                    embedded::embed(k, &base)
                }
            },
        };
        if let Some(f) = emb.as_ref().err().cloned() {
            let new = !failed_at.iter().any(|(x, _)| *x == key);
            if new {
                failed_at.push((key.clone(), f.clone()));
            }
            // A base edge with no curve: the base mesh is changed there by a stellar operation
            // (seed 002 Part II: the AC·CB rule, read as the edge split of AB at a vertex C of
            // S_T; a flip first, once per pair), and embedded again (`unblock`: the walk never
            // repeats a base mesh and is bounded). When it gives up, the failure names the edge.
            if let (true, Some(first)) = (new, f.edge) {
                let blocked = if f.blocked.is_empty() {
                    vec![first]
                } else {
                    f.blocked.clone()
                };
                let (before, walk_before) = (base.clone(), walk.clone());
                let (mut done, mut gave_up) =
                    unblock_all(&mut base, &mut walk, &blocked, &sopts.limits, &failed_at);
                // All the blocked edges are changed before embedding again (each embedding
                // costs the whole of S_T); when the validator refuses the result, only the
                // first blocked edge is changed, as one at a time did before.
                if done.len() > 1 && BaseSurface::new(&base).is_err() {
                    base = before;
                    walk = walk_before;
                    (done, gave_up) = unblock_all(
                        &mut base,
                        &mut walk,
                        &blocked[..1],
                        &sopts.limits,
                        &failed_at,
                    );
                }
                if !done.is_empty() {
                    progress(&format!(
                        "embed: failed ({}; {} base edges without a curve); {}; embedding again",
                        f.what,
                        f.blocked.len().max(1),
                        done.join("; ")
                    ));
                    continue;
                }
                if let Some(g) = gave_up {
                    let f = embedded::Failure {
                        what: format!("{}; {g}", f.what),
                        gave_up: Some(g),
                        ..f
                    };
                    if let Some(last) = failed_at.last_mut() {
                        last.1 = f.clone();
                    }
                    emb = Err(f);
                }
            }
        }
        let mut all_hold = false;
        let usable = match &emb {
            Ok(e) => {
                let checks = checked
                    .take()
                    .unwrap_or_else(|| embed_checks::run(k, &base, e));
                let bad: Vec<&str> = checks
                    .iter()
                    .filter(|r| r.failed())
                    .map(|r| r.id.as_str())
                    .collect();
                let usable = !checks.iter().any(|r| {
                    (r.id == "AF-param-bijective" || r.id == "AF-curved-disk") && r.failed()
                });
                all_hold = bad.is_empty();
                let how = match &local_stats {
                    Some(st) => format!(
                        "local update: {} of {} curves kept, {} of {} curved triangles' maps kept; ",
                        st.kept_curves, st.curves, st.kept_maps, st.maps
                    ),
                    None => String::new(),
                };
                progress(&format!(
                    "embed: {how}{} curves ({} along an edge of S_T, {} in their faces' region, {} widened, {} on all of S_T, {} taken up and traced again, {} restarts), length {:.4e} -> {:.4e} in {} sweeps ({} moves); {} pieces; {}",
                    e.emb.curves.len(),
                    e.emb.stats.on_edges,
                    e.emb.stats.in_region,
                    e.emb.stats.widened,
                    e.emb.stats.unrestricted,
                    e.emb.stats.ripped,
                    e.emb.stats.restarts,
                    e.emb.stats.initial_length,
                    e.emb.stats.length,
                    e.emb.stats.sweeps,
                    e.emb.stats.moves,
                    e.overlay.pieces.len(),
                    match (bad.is_empty(), usable) {
                        (true, _) => "Floater's parameters used".to_string(),
                        (false, true) => format!("failed: {}; Floater's parameters used", bad.join(", ")),
                        (false, false) => format!("failed: {}; the simplification's parameters used", bad.join(", ")),
                    }
                ));
                usable
            }
            Err(f) => {
                progress(&format!(
                    "embed: failed ({}); the simplification's parameters used",
                    f.what
                ));
                false
            }
        };
        let params = match &emb {
            Ok(e) if usable => surface.params_of(&base, &e.params),
            _ => surface.params(&base),
        };
        let fitted = fitted::fit(&surface, &pos, &params, opts.kappa, opts.degree)?;
        let errors = vertex_errors(&fitted.pps, &pos, &params);
        let bound = rounding_bound(&fitted.pps);
        let offenders: Vec<u32> = errors
            .iter()
            .enumerate()
            .filter(|(_, &e)| !(e + bound <= opts.epsilon))
            .map(|(i, _)| i as u32)
            .collect();
        // Pieces folded by Floater's maps are counted per round (SPEC `AF-param-bijective`):
        // reported by the check, never expected.
        let folds = match &emb {
            Ok(e) if usable => embed_checks::check_bijective(&e.overlay, &base, &e.maps).offenders,
            _ => checks::orientations(k, &base).folded.len() as u64,
        } as usize;
        let max_error = errors
            .iter()
            .copied()
            .fold(0.0, crate::report::harness::dev_max);
        let mut round = Round {
            base_vertices: surface.fine_of.len(),
            max_error,
            p99_error: percentile(&errors, 0.99),
            offenders: offenders.len(),
            folds: 0,
            refine: None,
            local: local_stats,
            seconds: 0.0,
        };
        progress(&format!(
            "fit round {}: {} charts (base vertices), max error {:.3e}, p99 {:.3e}, {} vertices beyond epsilon {:.3e}, {} folded triangles",
            rounds.len() + 1,
            round.base_vertices,
            round.max_error,
            round.p99_error,
            round.offenders,
            opts.epsilon,
            folds
        ));
        round.folds = folds;
        if offenders.is_empty() {
            round.seconds = tr.elapsed().as_secs_f64();
            rounds.push(round);
            return Ok(Fit {
                epsilon: opts.epsilon,
                base,
                surface,
                params,
                embedded: emb,
                floater_params: usable,
                fitted,
                errors,
                rounding_bound: bound,
                hierarchy,
                repairs,
                rounds,
                unblock: walk,
            });
        }
        if rounds.len() + 1 >= opts.max_rounds {
            return Err(FitError::NotReached {
                epsilon: opts.epsilon,
                rounds: rounds.len() + 1,
                offenders: offenders.len(),
                worst: max_error,
                folds,
            });
        }
        prev = match emb {
            Ok(e) if usable && all_hold => Some(local::Previous::new(&base, e)),
            _ => None,
        };
        let mut st = refine::RefineStats::default();
        for x in refine::choose(&base, &errors, &offenders) {
            if !base.is_base(x) {
                refine::insert(&mut base, x, &mut st);
            }
        }
        round.refine = Some(st);
        round.seconds = tr.elapsed().as_secs_f64();
        rounds.push(round);
        if st.inserted == 0 {
            return Err(FitError::NotReached {
                epsilon: opts.epsilon,
                rounds: rounds.len(),
                offenders: offenders.len(),
                worst: max_error,
                folds,
            });
        }
    }
}

/// The walk's change at every blocked edge still in the base mesh: what was done, and the first
/// reason it gave up at one.
fn unblock_all(
    base: &mut BaseMesh,
    walk: &mut unblock::Walk,
    blocked: &[(u32, u32)],
    lim: &RemovalLimits,
    failed_at: &[(Vec<[u32; 3]>, embedded::Failure)],
) -> (Vec<String>, Option<unblock::GiveUp>) {
    let mut done = Vec::new();
    let mut gave_up = None;
    for &(a, b) in blocked {
        // An earlier change of this round may have taken the edge away already.
        if base.face_of_edge(a, b).is_none() {
            continue;
        }
        let changed = walk.change(base, a, b, lim, |m| {
            let k = face_key(m);
            failed_at.iter().any(|(x, _)| *x == k)
        });
        match changed {
            Ok(ch) => done.push(describe(a, b, ch)),
            Err(g) => {
                gave_up.get_or_insert(g);
            }
        }
    }
    (done, gave_up)
}

/// One line of the progress report for a base-mesh change at edge a–b.
fn describe(a: u32, b: u32, ch: unblock::Change) -> String {
    match ch {
        unblock::Change::Flipped => format!("base edge {a}-{b} flipped"),
        unblock::Change::Removed { c } => format!(
            "base vertex {c} opposite edge {a}-{b} removed (AC·CB rule, no vertex of S_T left to split at)"
        ),
        unblock::Change::Split { c, edge_split: true } => {
            format!("base edge {a}-{b} split at vertex {c} of S_T (AC·CB rule)")
        }
        unblock::Change::Split { c, edge_split: false } => format!(
            "a base face at edge {a}-{b} split at vertex {c} of S_T (AC·CB rule; the edge's flip refused)"
        ),
    }
}

/// Refine the base mesh at base face slots `faces` (a refused base mesh's crossing faces):
/// insert the vertex of S_T furthest from its flat base triangle
/// among the face's own (else those of the faces around its corners); with none, flip the
/// face's longest flippable edge.
fn repair(base: &mut BaseMesh, faces: &[u32], pos: &[[f64; 3]]) -> refine::RefineStats {
    let mut st = refine::RefineStats::default();
    for &f in faces {
        let mut cand: Vec<u32> = base.members(f).to_vec();
        if cand.is_empty() {
            if let Some(c) = base.face(f) {
                for v in c {
                    for &g in base.faces_around(v) {
                        cand.extend_from_slice(base.members(g));
                    }
                }
            }
        }
        let worst = cand
            .into_iter()
            .max_by(|&a, &b| base.flat_deviation(a).total_cmp(&base.flat_deviation(b)));
        match worst {
            Some(x) if !base.is_base(x) => {
                refine::insert(base, x, &mut st);
            }
            _ => {
                if let Some(c) = base.face(f) {
                    let mut edges: Vec<(f64, u32, u32)> = (0..3)
                        .map(|i| {
                            let (a, b) = (c[i], c[(i + 1) % 3]);
                            (geodesic::dist(pos[a as usize], pos[b as usize]), a, b)
                        })
                        .collect();
                    edges.sort_by(|x, y| y.0.total_cmp(&x.0));
                    if edges.iter().any(|&(_, a, b)| base.flip(a, b).is_ok()) {
                        st.flips += 1;
                    }
                }
            }
        }
    }
    st
}
