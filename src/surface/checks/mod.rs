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
use super::scalar_ext::SurfaceScalar;
use crate::construction::{PpmGluing, P2};
use crate::mesh::{FaceId, SimplicialSurface, VertexId};
use crate::numeric::{Mp, Scalar};
use crate::report::{dev_max, uniform_in_triangle, Check, CheckResult, OnError, Verdict, Witness};
use serde_json::json;

mod condition_c;
mod eval_cases;
mod measured;
mod options;
mod samples;
mod tolerance;
mod weights;

pub use condition_c::*;
pub use eval_cases::*;
pub use measured::*;
pub use options::SurfaceCheckOptions;
pub use samples::examined_vertices;
pub use tolerance::{local_scale, tolerance, COND};
pub use weights::*;

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
