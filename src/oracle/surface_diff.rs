//! `ppm diff --surface`: compare another implementation's sampled surface (OFF, PLY, OBJ)
//! against the reference sampling of Sec. 6.2.
//!
//! The reference samples M = (G, (θ_v)) "in a triangle midpoint subdivision manner": level N
//! evaluates eval(σ, λ, μ, ν) (Sec. 6.1.4) at every barycentric grid point (i, j, k)/2^N of
//! every triangle σ of K, sharing the points on edges and corners. The vertex order is that of
//! [`crate::surface::output::sample_surface`] (and so of `ppm sample`): triangles in file order,
//! within a triangle (i, j) row by row, each point numbered when first met — [`sample_points`]
//! reproduces it with the (face, barycentric) argument of every vertex.
//!
//! Matching. When the other surface has exactly as many vertices as the reference at that
//! level, vertex i is compared with reference vertex i ("eval order"). Otherwise, or with
//! [`MatchMode::Nearest`], each of its vertices is matched to the nearest reference point
//! through an R*-tree, and the report says so (and also gives the reverse distances, reference
//! → other, which reveal missing parts of the surface).
//!
//! Deviations are Euclidean distances to the f64 reference. The worst items, and a spread of
//! others, are re-evaluated in MPFR (spot checks): each then shows its distance to the MPFR
//! value and the f64 reference's own error |f64 − MPFR|.
//!
//! The reference is any [`SmoothSurface`]: the report's vertex-indexed PPS (Ch. 4–5), whose
//! f64 eval carries an error bound (SPEC `R-diff-f64-bound`, the default tolerance), or the
//! tutorial's (σ, v)-indexed PPS (SPEC `SV-D13`), which has no such analysis: it needs an
//! explicit tolerance, and its spot checks report its own f64 error without judging it.

use super::diff::Stats;
use super::mp_values::mp_distance;
use super::protocol::OracleError;
use crate::mesh::FaceId;
use crate::report::harness::dev_max;
use crate::surface::eval_bound::BoundedPoint;
use crate::surface::smooth::SmoothSurface;
use rayon::prelude::*;
use rstar::primitives::GeomWithData;
use rstar::RTree;
use serde::Serialize;
use std::collections::HashSet;

/// Largest accepted subdivision level (as `sample_surface`).
pub const MAX_LEVEL: u32 = 12;

/// The map-and-blend part of the per-vertex f64 bound, in units of ε·scale; the patch part
/// grows with the fit's conditioning and degree (`surface::eval_bound`, SPEC
/// `R-diff-f64-bound`).
pub const F64_BOUND_ULPS: f64 = crate::surface::eval_bound::MAP_BOUND_ULPS;

/// How the other surface's vertices are paired with the reference's.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum MatchMode {
    /// Vertex i ↔ reference vertex i (eval order), when the counts agree; otherwise falls
    /// back to nearest neighbours and says so.
    #[default]
    Order,
    /// Each vertex ↔ the nearest reference point (R*-tree).
    Nearest,
}

impl MatchMode {
    /// Parse `order` / `nearest`.
    pub fn parse(s: &str) -> Option<MatchMode> {
        match s {
            "order" => Some(MatchMode::Order),
            "nearest" => Some(MatchMode::Nearest),
            _ => None,
        }
    }
}

pub use crate::surface::output::{SamplePattern, SamplePoint};

/// The Sec. 6.2 sampling pattern at `level` (the vertex order and triangles of
/// [`crate::surface::output::sample_surface`], which evaluates this same pattern).
pub fn sample_points(r: &dyn SmoothSurface, level: u32) -> Result<SamplePattern, OracleError> {
    if level > MAX_LEVEL {
        return Err(OracleError::Malformed(format!(
            "level {level} > {MAX_LEVEL}"
        )));
    }
    Ok(crate::surface::output::sample_pattern_faces(
        &r.face_corners()?,
        level,
    )?)
}

/// Number of sampled vertices at `level` for a surface with `v` vertices, `e` edges and `f`
/// faces: V + E(n − 1) + F(n − 1)(n − 2)/2 with n = 2^level.
pub fn sample_count(v: u64, e: u64, f: u64, level: u32) -> u64 {
    let n = 1u64 << level.min(MAX_LEVEL);
    v + e * (n - 1) + f * (n - 1) * n.saturating_sub(2) / 2
}

/// The level whose sampling has exactly `count` vertices, if any.
pub(crate) fn infer_level(r: &dyn SmoothSurface, count: usize) -> Option<u32> {
    let faces = r.face_corners().ok()?;
    let nf = faces.len() as u64;
    let mut edges = HashSet::new();
    let mut verts = HashSet::new();
    for c in faces {
        for t in 0..3 {
            let (a, b) = (c[t].0, c[(t + 1) % 3].0);
            edges.insert((a.min(b), a.max(b)));
            verts.insert(a);
        }
    }
    (0..=MAX_LEVEL)
        .find(|&l| sample_count(verts.len() as u64, edges.len() as u64, nf, l) == count as u64)
}

/// Options of [`diff_surface`].
#[derive(Debug, Clone)]
pub struct SurfaceDiffOptions {
    /// Subdivision level; `None`: inferred from the vertex count.
    pub level: Option<u32>,
    /// Largest accepted deviation; `None`: at each vertex twice its f64 bound.
    pub tolerance: Option<f64>,
    /// Pairing of the vertices.
    pub matching: MatchMode,
    /// How many worst items to list (each re-evaluated in MPFR).
    pub worst: usize,
    /// How many further, evenly spread items to re-evaluate in MPFR.
    pub spot_checks: usize,
    /// MPFR precision of the spot checks.
    pub bits: u32,
    /// A planted fault for the tests of `R-diff-f64-bound`: multiplies every vertex's f64
    /// bound (`None`: the analysis' bound).
    pub planted_bound_factor: Option<f64>,
}

impl Default for SurfaceDiffOptions {
    fn default() -> Self {
        SurfaceDiffOptions {
            level: None,
            tolerance: None,
            matching: MatchMode::Order,
            worst: 10,
            spot_checks: 32,
            bits: crate::numeric::DEFAULT_MP_PREC,
            planted_bound_factor: None,
        }
    }
}

/// The MPFR re-evaluation of one item.
#[derive(Debug, Clone, Serialize)]
pub struct MpCheck {
    /// |other − MPFR|.
    pub deviation: f64,
    /// |f64 reference − MPFR|: the f64 reference's own error.
    pub reference_error: f64,
    /// The f64 bound at this vertex (`reference_error` must not exceed it); `None` when the
    /// reference construction has no error analysis.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bound: Option<f64>,
}

/// One compared vertex.
#[derive(Debug, Clone, Serialize)]
pub struct SurfaceItem {
    /// Index of the vertex in the other file.
    pub vertex: usize,
    /// Index of the matched reference vertex (eval order).
    pub reference_vertex: usize,
    /// The eval argument of the reference vertex.
    pub face: u32,
    /// (λ, μ, ν).
    pub bary: [f64; 3],
    /// The other implementation's point.
    pub theirs: [f64; 3],
    /// The f64 reference point.
    pub reference: [f64; 3],
    /// |theirs − reference| (∞ for a non-finite coordinate).
    pub deviation: f64,
    /// The tolerance at this vertex.
    pub tolerance: f64,
    /// The MPFR spot check, for the listed items.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mp: Option<MpCheck>,
}

/// The report of [`diff_surface`].
#[derive(Debug, Clone, Serialize)]
pub struct SurfaceDiffReport {
    /// The reference construction ([`SmoothSurface::name`]).
    pub reference: String,
    /// Subdivision level of the reference sampling.
    pub level: u32,
    /// Whether the level was inferred from the vertex count.
    pub level_inferred: bool,
    /// Vertices in the other file.
    pub their_vertices: usize,
    /// Vertices of the reference sampling at `level`.
    pub reference_vertices: usize,
    /// The pairing actually used.
    pub matching: MatchMode,
    /// Why / how (always printed).
    pub matching_note: String,
    /// In eval order: whether the other file's triangles are the reference's.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub faces_identical: Option<bool>,
    /// Deviations other → reference.
    pub stats: Stats,
    /// Nearest matching only: distances reference → other.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reverse: Option<Stats>,
    /// Nearest matching only: reference vertices matched by more than one other vertex.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reference_matched_twice: Option<usize>,
    /// Vertices with a non-finite coordinate (not compared; they fail the verdict).
    pub non_finite: usize,
    /// The first [`NAMED_NON_FINITE`] of them (indices in the other file).
    pub non_finite_vertices: Vec<usize>,
    /// Nearest matching only: reference points farther than the tolerance from every point of
    /// theirs (a missing part of the surface; they fail the verdict).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reference_missing: Option<usize>,
    /// The level whose vertex count equals theirs, when it differs from `level` (a level
    /// mismatch: the verdict then rests on the reverse distances).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub count_matches_level: Option<u32>,
    /// Largest |coordinate| of the reference sampling.
    pub scale: f64,
    /// The largest per-vertex f64 bound: patch part (γ_{8l+8}·Σ ω|b|BB) plus the map part;
    /// this and the next three are `None` when the reference has no error analysis.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub f64_bound: Option<f64>,
    /// The map-and-blend part of every vertex's bound: [`F64_BOUND_ULPS`]·ε·scale.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub f64_bound_maps: Option<f64>,
    /// The largest patch part of a vertex's bound.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub f64_bound_patch_max: Option<f64>,
    /// The largest Σ_u ω_u max_d Σ|b_jk\[d\]| B_j B_k at a vertex, over scale: how much the
    /// fit's control points cancel (1 for a patch with no cancellation).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cancellation_max: Option<f64>,
    /// Spot checks whose f64 reference error exceeds that vertex's bound: the error analysis
    /// is wrong there (they fail the verdict).
    pub bound_violations: usize,
    /// Vertices whose deviation exceeds their tolerance.
    pub outside: usize,
    /// MPFR precision of the spot checks.
    pub mp_bits: u32,
    /// Spot checks done (worst items + spread).
    pub spot_checks: usize,
    /// Largest |f64 reference − MPFR| over the spot checks.
    pub reference_error_max: f64,
    /// Largest |other − MPFR| over the spot checks.
    pub mp_deviation_max: f64,
    /// The tolerance applied.
    pub tolerance: f64,
    /// Where the tolerance came from.
    pub tolerance_source: String,
    /// The worst items, largest deviation first, with MPFR spot checks.
    pub worst: Vec<SurfaceItem>,
    /// Every deviation ≤ tolerance and every vertex finite.
    pub within_tolerance: bool,
}

fn dist(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    super::diff::robust_norm(&[a[0] - b[0], a[1] - b[1], a[2] - b[2]])
}

/// How many non-finite vertices the report names.
pub const NAMED_NON_FINITE: usize = 8;

type Tree = RTree<GeomWithData<[f64; 3], usize>>;

fn tree(points: &[[f64; 3]]) -> Tree {
    RTree::bulk_load(
        points
            .iter()
            .enumerate()
            .filter(|(_, p)| p.iter().all(|c| c.is_finite()))
            .map(|(i, p)| GeomWithData::new(*p, i))
            .collect(),
    )
}

/// Compare `theirs` (the other implementation's vertex positions, in its file order, and its
/// triangles if known) against the reference sampling of `pps`.
pub fn diff_surface(
    pps: &dyn SmoothSurface,
    theirs: &[[f64; 3]],
    their_faces: Option<&[[u32; 3]]>,
    opts: &SurfaceDiffOptions,
) -> Result<SurfaceDiffReport, OracleError> {
    let (level, level_inferred) = match opts.level {
        Some(l) => (l, false),
        None => match infer_level(pps, theirs.len()) {
            Some(l) => (l, true),
            None => {
                return Err(OracleError::Malformed(format!(
                    "{} vertices is not the vertex count of any subdivision level 0..={MAX_LEVEL} of this mesh: give --level",
                    theirs.len()
                )))
            }
        },
    };
    let pattern = sample_points(pps, level)?;
    let evaluated: Vec<([f64; 3], Option<BoundedPoint>)> = pattern
        .points
        .par_iter()
        .map(|s| pps.eval_bounded(s.face, s.bary))
        .collect::<Result<_, _>>()?;
    let reference: Vec<[f64; 3]> = evaluated.iter().map(|b| b.0).collect();
    // Either every point has a bound (the construction has an error analysis) or none.
    let bounded: Option<Vec<BoundedPoint>> = evaluated.into_iter().map(|b| b.1).collect();
    if bounded.is_none() && opts.tolerance.is_none() {
        return Err(OracleError::Malformed(format!(
            "the reference, {}, has no f64 error analysis to derive a tolerance from: give --tolerance",
            pps.name()
        )));
    }
    let scale = reference
        .iter()
        .flat_map(|p| p.iter())
        .fold(0.0f64, |a, &b| a.max(b.abs()));
    let f64_bound_maps = bounded
        .as_ref()
        .map(|_| F64_BOUND_ULPS * f64::EPSILON * scale.max(1.0));
    let factor = opts.planted_bound_factor.unwrap_or(1.0);
    let bound: Option<Vec<f64>> = bounded
        .as_ref()
        .map(|bs| bs.iter().map(|b| b.bound(scale) * factor).collect());
    let f64_bound = bound
        .as_ref()
        .map(|b| b.iter().fold(0.0f64, |a, &x| a.max(x)));
    let f64_bound_patch_max = bounded
        .as_ref()
        .map(|bs| bs.iter().fold(0.0f64, |a, b| a.max(b.patch_bound)));
    let cancellation_max = bounded
        .as_ref()
        .map(|bs| bs.iter().fold(0.0f64, |a, b| a.max(b.abs_size)) / scale.max(f64::MIN_POSITIVE));
    let bound_at = |r: usize| bound.as_ref().map(|b| b[r]);
    // With no analysis the tolerance was given (checked above).
    let tol_at = |r: usize| {
        opts.tolerance
            .unwrap_or_else(|| 2.0 * bound_at(r).unwrap_or(0.0))
    };
    let same_count = theirs.len() == reference.len();
    let (matching, matching_note) = match (opts.matching, same_count) {
        (MatchMode::Order, true) => (
            MatchMode::Order,
            format!(
                "vertex counts agree ({}): compared vertex by vertex in eval order",
                theirs.len()
            ),
        ),
        (MatchMode::Order, false) => (
            MatchMode::Nearest,
            format!(
                "vertex counts differ (theirs {}, reference {} at level {level}): vertex order unknown, matched each vertex to the NEAREST reference point (R*-tree)",
                theirs.len(),
                reference.len()
            ),
        ),
        (MatchMode::Nearest, _) => (
            MatchMode::Nearest,
            "--match nearest: vertex order not used, matched each vertex to the NEAREST reference point (R*-tree)".to_string(),
        ),
    };
    let bad: Vec<usize> = theirs
        .iter()
        .enumerate()
        .filter(|(_, p)| !p.iter().all(|c| c.is_finite()))
        .map(|(i, _)| i)
        .collect();
    let non_finite = bad.len();
    let non_finite_vertices: Vec<usize> = bad.into_iter().take(NAMED_NON_FINITE).collect();
    let count_matches_level = if level_inferred {
        None
    } else {
        infer_level(pps, theirs.len()).filter(|&l| l != level)
    };
    // Pair every finite vertex of theirs with a reference index.
    let pairs: Vec<(usize, usize)> = match matching {
        MatchMode::Order => (0..theirs.len()).map(|i| (i, i)).collect(),
        MatchMode::Nearest => {
            let t = tree(&reference);
            theirs
                .par_iter()
                .enumerate()
                .filter(|(_, p)| p.iter().all(|c| c.is_finite()))
                .filter_map(|(i, p)| t.nearest_neighbor(p).map(|n| (i, n.data)))
                .collect()
        }
    };
    let mut items: Vec<SurfaceItem> = pairs
        .iter()
        .map(|&(i, r)| {
            let d = dist(&theirs[i], &reference[r]);
            SurfaceItem {
                vertex: i,
                reference_vertex: r,
                face: pattern.points[r].face.0,
                bary: pattern.points[r].bary,
                theirs: theirs[i],
                reference: reference[r],
                deviation: if d.is_nan() { f64::INFINITY } else { d },
                tolerance: tol_at(r),
                mp: None,
            }
        })
        .collect();
    let stats = Stats::of(
        items
            .iter()
            .filter(|it| it.theirs.iter().all(|c| c.is_finite()))
            .map(|it| it.deviation)
            .collect(),
    );
    let (reverse, twice, rev) = if matching == MatchMode::Nearest {
        let t = tree(theirs);
        // A reference point with no finite point of theirs at all is infinitely far.
        let rev: Vec<f64> = reference
            .par_iter()
            .map(|p| {
                t.nearest_neighbor(p)
                    .map_or(f64::INFINITY, |n| dist(p, n.geom()))
            })
            .collect();
        let mut hits = vec![0u32; reference.len()];
        for &(_, r) in &pairs {
            hits[r] += 1;
        }
        (
            Some(Stats::of(rev.clone())),
            Some(hits.iter().filter(|&&h| h > 1).count()),
            Some(rev),
        )
    } else {
        (None, None, None)
    };
    let faces_identical = match (matching, their_faces) {
        (MatchMode::Order, Some(f)) => Some(f == pattern.faces.as_slice()),
        _ => None,
    };
    // Worst items first (relative to their tolerance), then spot checks in MPFR: evenly
    // spread, and at the worst-conditioned vertices, where the f64 bound is most at risk.
    let n_items = items.len();
    let outside = items
        .iter()
        .filter(|it| !(it.deviation <= it.tolerance))
        .count();
    let key = |it: &SurfaceItem| {
        if it.tolerance > 0.0 {
            it.deviation / it.tolerance
        } else {
            it.deviation
        }
    };
    items.sort_by(|a, b| key(b).total_cmp(&key(a)));
    let mut chosen: Vec<usize> = (0..opts.worst.min(n_items)).collect();
    if opts.spot_checks > 0 && n_items > 0 {
        let step = (n_items / opts.spot_checks).max(1);
        chosen.extend((opts.worst.min(n_items)..n_items).step_by(step));
        if let Some(bs) = &bounded {
            let mut by_size: Vec<usize> = (0..n_items).collect();
            by_size.sort_by(|&a, &b| {
                let (ra, rb) = (items[a].reference_vertex, items[b].reference_vertex);
                bs[rb].abs_size.total_cmp(&bs[ra].abs_size)
            });
            chosen.extend(by_size.into_iter().take(opts.worst));
        }
        chosen.sort_unstable();
        chosen.dedup();
    }
    let eval_mp = pps.mp_eval(opts.bits)?;
    let checks: Vec<(usize, Result<MpCheck, OracleError>)> = chosen
        .par_iter()
        .map(|&k| {
            let it = &items[k];
            let r = eval_mp(FaceId(it.face), it.bary)
                .map_err(OracleError::from)
                .map(|e| MpCheck {
                    deviation: if it.theirs.iter().all(|c| c.is_finite()) {
                        mp_distance(&it.theirs, &e)
                    } else {
                        f64::INFINITY
                    },
                    reference_error: mp_distance(&it.reference, &e),
                    bound: bound_at(it.reference_vertex),
                });
            (k, r)
        })
        .collect();
    let mut reference_error_max = 0.0f64;
    let mut mp_deviation_max = 0.0f64;
    let mut bound_violations = 0;
    let mut spot: Vec<SurfaceItem> = Vec::new();
    for (k, r) in checks {
        let c = r?;
        reference_error_max = dev_max(reference_error_max, c.reference_error);
        mp_deviation_max = dev_max(mp_deviation_max, c.deviation);
        let violated = c.bound.is_some_and(|b| !(c.reference_error <= b));
        items[k].mp = Some(c);
        if violated {
            bound_violations += 1;
            if k >= opts.worst {
                spot.push(items[k].clone());
            }
        }
    }
    let spot_checks = chosen.len();
    items.truncate(opts.worst);
    // A violated bound is listed with the worst items: it is the witness of a wrong analysis.
    items.extend(spot.into_iter().take(opts.worst));
    let (tolerance, tolerance_source) = match opts.tolerance {
        Some(t) => (t, "--tolerance".to_string()),
        None => (
            2.0 * f64_bound.unwrap_or(0.0),
            "default: at each vertex 2 × its f64 bound (both f64 evaluations are within it of the exact value); the largest is printed".to_string(),
        ),
    };
    // Both directions count: every point of theirs near the surface, and every reference
    // point near one of theirs (a 3-vertex file is not the surface).
    let reference_missing = rev.as_ref().map(|r| {
        r.iter()
            .enumerate()
            .filter(|&(k, &d)| !(d <= tol_at(k)))
            .count()
    });
    let within_tolerance = non_finite == 0
        && !theirs.is_empty()
        && outside == 0
        && bound_violations == 0
        && reference_missing.unwrap_or(0) == 0;
    Ok(SurfaceDiffReport {
        reference: pps.name(),
        level,
        level_inferred,
        their_vertices: theirs.len(),
        reference_vertices: reference.len(),
        matching,
        matching_note,
        faces_identical,
        stats,
        reverse,
        reference_matched_twice: twice,
        non_finite,
        non_finite_vertices,
        reference_missing,
        count_matches_level,
        scale,
        f64_bound,
        f64_bound_maps,
        f64_bound_patch_max,
        cancellation_max,
        bound_violations,
        outside,
        mp_bits: opts.bits,
        spot_checks,
        reference_error_max,
        mp_deviation_max,
        tolerance,
        tolerance_source,
        worst: items,
        within_tolerance,
    })
}

/// Text rendering of a [`SurfaceDiffReport`].
pub fn render_surface(r: &SurfaceDiffReport) -> String {
    use std::fmt::Write;
    let mut s = String::new();
    let _ = writeln!(
        s,
        "reference: {}, midpoint subdivision level {}{} (Sec. 6.2), {} vertices in eval order; other surface: {} vertices",
        r.reference,
        r.level,
        if r.level_inferred { " (inferred from the vertex count)" } else { "" },
        r.reference_vertices,
        r.their_vertices
    );
    let _ = writeln!(s, "matching: {}", r.matching_note);
    if let Some(fi) = r.faces_identical {
        let _ = writeln!(
            s,
            "triangles: {}",
            if fi {
                "identical to the reference's"
            } else {
                "differ from the reference's (positions compared anyway)"
            }
        );
    }
    let st = &r.stats;
    let _ = writeln!(
        s,
        "deviation |theirs − reference| over {} vertices: max {:.3e}, mean {:.3e}, p50 {:.3e}, p90 {:.3e}, p99 {:.3e}",
        st.count, st.max, st.mean, st.p50, st.p90, st.p99
    );
    if let Some(rev) = &r.reverse {
        let _ = writeln!(
            s,
            "reverse (each reference point to the nearest of theirs): max {:.3e}, mean {:.3e}, p99 {:.3e}; {} reference points matched more than once",
            rev.max,
            rev.mean,
            rev.p99,
            r.reference_matched_twice.unwrap_or(0)
        );
    }
    if let Some(l) = r.count_matches_level {
        let _ = writeln!(
            s,
            "level mismatch: their vertex count is that of level {l}, not of the requested level {}",
            r.level
        );
    }
    if let Some(n) = r.reference_missing.filter(|&n| n > 0) {
        let _ = writeln!(
            s,
            "{n} reference points are farther than the tolerance from every point of theirs: that part of the surface is missing"
        );
    }
    if r.non_finite > 0 {
        let named: Vec<String> = r
            .non_finite_vertices
            .iter()
            .map(|i| i.to_string())
            .collect();
        let _ = writeln!(
            s,
            "{} vertices with non-finite coordinates (not compared): vertex {}{}",
            r.non_finite,
            named.join(", "),
            if r.non_finite > named.len() {
                ", …"
            } else {
                ""
            }
        );
    }
    match (
        r.f64_bound_patch_max,
        r.cancellation_max,
        r.f64_bound_maps,
        r.f64_bound,
    ) {
        (Some(patch), Some(canc), Some(maps), Some(all)) => {
            let _ = writeln!(
                s,
                "f64 bound per vertex (SPEC R-diff-f64-bound): patches γ_(8l+8)·Σω|b|BB, max {patch:.3e} (control points cancel up to {canc:.3e}× the scale) + maps {}·ε·scale = {maps:.3e} (scale = max |coordinate| = {:.3e}); largest {all:.3e}",
                F64_BOUND_ULPS, r.scale
            );
        }
        _ => {
            let _ = writeln!(
                s,
                "f64 bound per vertex: none (this construction has no f64 error analysis; the spot checks measure the reference's own error, scale = max |coordinate| = {:.3e})",
                r.scale
            );
        }
    }
    let _ = writeln!(
        s,
        "MPFR {}-bit spot checks on {} vertices: reference f64 error max {:.3e}, theirs vs MPFR max {:.3e}; {} where the reference's error exceeds its bound{}",
        r.mp_bits,
        r.spot_checks,
        r.reference_error_max,
        r.mp_deviation_max,
        r.bound_violations,
        if r.bound_violations > 0 { " (the error analysis is WRONG there: listed below)" } else { "" }
    );
    let _ = writeln!(
        s,
        "tolerance {:.3e} ({}); {} vertices outside their tolerance",
        r.tolerance, r.tolerance_source, r.outside
    );
    let _ = writeln!(s, "worst vertices (eval argument: face, (λ, μ, ν)):");
    for w in &r.worst {
        let mp =
            w.mp.as_ref()
                .map(|m| {
                    let bound = m.bound.map_or("none".to_string(), |b| format!("{b:.3e}"));
                    format!(
                        "  vs MPFR {:.3e} (reference error {:.3e}, bound {bound})",
                        m.deviation, m.reference_error
                    )
                })
                .unwrap_or_default();
        let _ = writeln!(
            s,
            "  vertex {:>7} ↔ ref {:>7}: deviation {:.3e} (tolerance {:.3e})  face {} bary ({}, {}, {})  theirs {:?} reference {:?}{mp}",
            w.vertex, w.reference_vertex, w.deviation, w.tolerance, w.face, w.bary[0], w.bary[1], w.bary[2], w.theirs, w.reference
        );
    }
    let _ = writeln!(
        s,
        "verdict: {}",
        if r.within_tolerance {
            "within tolerance"
        } else {
            "OUTSIDE tolerance"
        }
    );
    s
}
