//! The Chapter 5 / Sec. 6.1.4 checks on a mesh (SPEC IDs in `SPEC.md`).
//!
//! [`run_surface_checks`] builds S′ (PN triangles) and the PPS and runs every check; each
//! check is also a public function on a built [`Pps`] so tests can plant faults.
//!
//! Tolerances: `COND · max(1, m/6) · l · ε · S`, with ε the unit roundoff of the scalar in use,
//! S the largest |control point coordinate| of the patches involved (ψ is a convex combination
//! of its control points, θ of the ψ's), l the Bézier degree (bounds the derivative of ψ relative
//! to S, which multiplies the position error of the transition maps), max(1, m/6) the
//! amplification of angles by f_v, and COND = 2¹² for the ~40 operations in a transition map.

use super::consts::Consts;
use super::eval::{canonical_point, Chart};
use super::jet::{Jet, JET_LEN};
use super::pps::{Pps, PpsOptions};
use super::profile::Profile;
use super::scalar_ext::SurfaceScalar;
use crate::construction::{PpmGluing, P2};
use crate::mesh::{FaceId, SimplicialSurface, VertexId};
use crate::numeric::{Mp, Scalar};
use crate::report::{dev_max, uniform_in_triangle, Check, CheckResult, OnError, Verdict, Witness};
use rand::Rng;
use rand_chacha::ChaCha8Rng;
use serde_json::json;

mod condition_c;
mod eval_cases;
mod measured;
mod weights;

pub use condition_c::*;
pub use eval_cases::*;
pub use measured::*;
pub use weights::*;

/// Condition factor of the tolerances (see the module doc).
pub const COND: f64 = 4096.0;

/// Options of the surface checks.
#[derive(Debug, Clone)]
pub struct SurfaceCheckOptions {
    /// Seed of the random samples (each check derives its own stream).
    pub seed: u64,
    /// Random points per examined vertex.
    pub samples_per_vertex: usize,
    /// Examine at most this many vertices (evenly spaced over the vertex list); `None`: all.
    pub max_vertices: Option<usize>,
    /// Vertices re-checked with the multi-precision oracle.
    pub mp_vertices: usize,
    /// Precision (bits) of the multi-precision re-check.
    pub mp_prec: u32,
    /// The parameter profile of the surface under test.
    pub profile: Profile,
    /// Run the measured (C′)/(C″) patch-intersection search.
    pub intersections: bool,
    /// S′ (Sec. 6.2); with the Loop S′ its own checks run too.
    pub surface: super::target::SurfaceKind,
}

impl Default for SurfaceCheckOptions {
    fn default() -> Self {
        SurfaceCheckOptions {
            seed: 20240601,
            samples_per_vertex: 24,
            max_vertices: None,
            mp_vertices: 4,
            mp_prec: crate::numeric::DEFAULT_MP_PREC,
            profile: Profile::Paper,
            intersections: true,
            surface: super::target::SurfaceKind::Pn,
        }
    }
}

/// Build S′ and the PPS and run every check.
pub fn run_surface_checks(k: &SimplicialSurface, opts: &SurfaceCheckOptions) -> Vec<CheckResult> {
    run_surface_checks_with(k, opts, None)
}

/// [`run_surface_checks`] with a progress hook, called with (done, total) check families after
/// the fit and after each family (they are of very unequal cost; the count says where it is).
pub fn run_surface_checks_with(
    k: &SimplicialSurface,
    opts: &SurfaceCheckOptions,
    progress: crate::report::Progress,
) -> Vec<CheckResult> {
    let target = match super::target::SPrime::for_profile(opts.surface, k, opts.profile) {
        Ok(t) => t,
        Err(e) => {
            let mut r = CheckResult::new("LOOP-valence", "the Loop S′ of K can be built");
            r.offend(|| crate::report::Witness::new(e.to_string(), serde_json::Value::Null));
            return vec![r];
        }
    };
    let is_loop = matches!(target, super::target::SPrime::Loop(_));
    let total = 13 + usize::from(opts.intersections) + usize::from(is_loop);
    if let Some(p) = progress {
        p(0, total);
    }
    let pps = match Pps::try_build(
        k,
        target.as_target(),
        PpsOptions {
            profile: opts.profile,
            ..PpsOptions::default()
        },
    ) {
        Ok(p) => p,
        Err(e) => {
            // Nothing of Chapter 5 can be checked: one failing result with the refusal, not
            // results computed on NaN (which read "holds, tolerance 0").
            let mut r = CheckResult::new("D5.2.1", "shape functions fitted (rank, κ per degree)");
            r.offend(|| crate::report::Witness::new(e.to_string(), serde_json::Value::Null));
            return vec![r];
        }
    };
    let g = PpmGluing::new(k);
    let mut done = 0;
    let mut step = |out: &mut Vec<CheckResult>, rs: Vec<CheckResult>| {
        out.extend(rs);
        done += 1;
        if let Some(p) = progress {
            p(done, total);
        }
    };
    let mut out = Vec::new();
    step(&mut out, vec![check_fit(&pps)]);
    step(&mut out, vec![check_membership_literal(&pps, &g, opts)]);
    step(&mut out, vec![check_condition_c(&pps, opts)]);
    step(&mut out, vec![check_condition_c_mp(&pps, opts)]);
    step(&mut out, vec![check_weights(&pps, opts)]);
    step(&mut out, vec![check_j_le_3(&pps, opts)]);
    step(&mut out, vec![check_support(&pps, opts)]);
    step(&mut out, vec![check_smooth_charts(&pps, opts)]);
    step(&mut out, vec![check_regular(&pps, opts)]);
    step(&mut out, check_eval_cases(&pps, opts));
    step(&mut out, vec![check_cover(3.0 / 4.0, opts.seed, 4000)]);
    step(&mut out, vec![check_approx(&pps)]);
    if opts.intersections {
        step(&mut out, check_intersections(&pps, opts));
    }
    step(
        &mut out,
        vec![super::loop_subdiv::checks::check_pps_distance(
            k,
            &pps,
            target.as_target(),
            opts.seed,
        )],
    );
    if let super::target::SPrime::Loop(l) = &target {
        let lo = super::loop_subdiv::checks::LoopCheckOptions {
            seed: opts.seed,
            ..Default::default()
        };
        step(
            &mut out,
            super::loop_subdiv::checks::run_loop_checks(k, l, &lo),
        );
    }
    out
}

/// The examined vertices (evenly spaced subset).
pub fn examined_vertices(pps: &Pps, max: Option<usize>) -> Vec<VertexId> {
    let all: Vec<VertexId> = pps.vertices().collect();
    match max {
        Some(n) if n < all.len() && n > 0 => {
            let step = all.len() as f64 / n as f64;
            (0..n).map(|i| all[(i as f64 * step) as usize]).collect()
        }
        _ => all,
    }
}

pub(super) fn dist3<S: Scalar>(a: &[S; 3], b: &[S; 3]) -> f64 {
    let mut s = 0.0;
    for d in 0..3 {
        let x = a[d].sub(&b[d]).to_f64();
        s += x * x;
    }
    s.sqrt()
}

/// Largest |control point coordinate| of the patches of the given vertices.
pub fn local_scale(pps: &Pps, vs: &[VertexId]) -> f64 {
    vs.iter()
        .flat_map(|&v| pps.patch(v).0.iter().flat_map(|c| c.iter()))
        .fold(0.0f64, |a, &b| a.max(b.abs()))
}

/// Tolerance for comparing θ values around vertex v at unit roundoff `eps`.
pub fn tolerance(pps: &Pps, v: VertexId, eps: f64) -> f64 {
    let m = pps.degree(v);
    let mut vs = vec![v];
    let mut l = pps.patch(v).1;
    for i in 0..m {
        let u = pps.link(v, i);
        vs.push(u);
        l = l.max(pps.patch(u).1);
    }
    let mmax = vs.iter().map(|&u| pps.degree(u)).max().unwrap_or(6);
    COND * (mmax as f64 / 6.0).max(1.0) * l as f64 * eps * local_scale(pps, &vs)
}

/// Uniform random point of Ω_v scaled by `frac` (frac < 1 keeps away from the rim).
pub(super) fn random_in_omega(rng: &mut ChaCha8Rng, radius: f64, frac: f64) -> [f64; 2] {
    loop {
        let x: f64 = rng.gen_range(-1.0..1.0);
        let y: f64 = rng.gen_range(-1.0..1.0);
        if x * x + y * y < 1.0 {
            return [x * radius * frac, y * radius * frac];
        }
    }
}

/// Random points of Ω_v lying in some gluing domain Ω_vu, u ≠ v. A failed J_v(p) is an
/// evaluation error of `chk` (an offence: p ∈ Ω_v is in the domain of Eq. 5.1).
pub(super) fn overlap_points(
    pps: &Pps,
    v: VertexId,
    rng: &mut ChaCha8Rng,
    n: usize,
    chk: &mut Check,
) -> Vec<[f64; 2]> {
    let c = pps.consts_f64();
    let r = c.degree(pps.degree(v)).map(|d| d.radius).unwrap_or(0.5);
    let mut out = Vec::with_capacity(n);
    let mut tries = 0;
    while out.len() < n && tries < 50 * n {
        tries += 1;
        let p = random_in_omega(rng, r, 0.999);
        match pps.terms(v, &P2::new(p[0], p[1]), c, None) {
            Ok(t) if t.len() > 1 => out.push(p),
            Ok(_) => {}
            Err(e) => chk.error(OnError::Offence, &e, || {
                Witness::new(
                    format!("v={v} p={p:?}: J_v(p) failed: {e}"),
                    json!({"v": v, "p": p}),
                )
            }),
        }
    }
    out
}
