//! What the Chapter 5 construction can be built for within bounded memory and within the range
//! of f64: checked before [`Pps::build`] (by [`Pps::try_build`]) so that a mesh beyond either
//! gets a typed refusal naming the element, never an abort or NaN output.
//!
//! * Fit size (Sec. 5.2). The paper profile takes l = max(m_v + 1, 7): the least-squares
//!   problem of a vertex of degree m has (2l)² grid rows and (l + 1)² unknowns, so its
//!   pseudo-inverse grows like m⁴ in memory and the SVD like m⁶ in time (degree 70: ~1.7 GB,
//!   ~25 s). The estimate counts, per distinct degree, the kept A⁺ and A⁺W plus one working
//!   copy of A for the largest, and the control points of every vertex.
//! * Scale. Normals and curvatures square lengths twice (EG − F² ~ size⁴, Sec. 6.2), so a mesh
//!   whose coordinates approach 2^±256 overflows or underflows f64 (a tetrahedron at 1e308
//!   sampled to NaN, at 1e±77 the normals vanished). Coordinates must lie within
//!   [`MAX_COORDINATE`] and the bounding box must be at least [`MIN_EXTENT`] across.

use super::pps::{Pps, PpsOptions, SurfaceError};
use super::profile::Profile;
use super::target::TargetSurface;
use crate::mesh::SimplicialSurface;
use std::collections::BTreeMap;

/// Memory budget of the fits of one pseudo-surface, in bytes (2 GiB).
pub const FIT_MEMORY_LIMIT: u128 = 2 << 30;

/// Largest accepted |coordinate|: 2^200 ≈ 1.6e60, so that size⁴ stays far inside f64.
pub const MAX_COORDINATE: f64 = 1.606_938_044_258_990_3e60;

/// Smallest accepted bounding-box diagonal: 2^−200 ≈ 6.2e−61.
pub const MIN_EXTENT: f64 = 6.223_015_277_861_142e-61;

/// Estimated bytes of the least-squares fit of one degree m (Sec. 5.2): rows ≤ side², A⁺
/// ((l+1)² × rows) kept, A⁺W ((l+1)² × 10m) kept.
pub fn fit_bytes(m: u32, profile: Profile) -> (usize, u128, u128) {
    let l = profile.bezier_degree(m);
    let side = profile.grid_side(l) as u128;
    let unknowns = ((l as u128) + 1).pow(2);
    let rows = side * side;
    let kept = 8 * unknowns * (rows + 10 * m as u128);
    let working = 8 * unknowns * rows;
    (l, kept, working)
}

/// The estimated memory of building the pseudo-surface of `k` with `profile`, or the typed
/// refusal naming the vertex of largest degree.
pub fn check_fit_size(k: &SimplicialSurface, profile: Profile) -> Result<u128, SurfaceError> {
    // Highest-degree vertex per degree (the one named) and the control points of all.
    let mut degrees: BTreeMap<u32, crate::mesh::VertexId> = BTreeMap::new();
    let mut cps: u128 = 0;
    for v in k.vertices() {
        let m = k.degree(v);
        degrees.entry(m).or_insert(v);
        if m >= 3 {
            cps += 24 * ((profile.bezier_degree(m) as u128) + 1).pow(2);
        }
    }
    let mut total = cps;
    let mut working = 0u128;
    for &m in degrees.keys().filter(|&&m| m >= 3) {
        let (_, kept, w) = fit_bytes(m, profile);
        total = total.saturating_add(kept);
        working = working.max(w);
    }
    total = total.saturating_add(working);
    if total > FIT_MEMORY_LIMIT {
        if let Some((&m, &v)) = degrees.iter().next_back() {
            return Err(SurfaceError::FitTooLarge {
                v,
                degree: m,
                l: profile.bezier_degree(m),
                profile: profile.name().to_string(),
                bytes: total,
                limit: FIT_MEMORY_LIMIT,
            });
        }
    }
    Ok(total)
}

/// Coordinates within ±[`MAX_COORDINATE`] and a bounding box at least [`MIN_EXTENT`] across.
pub fn check_scale(k: &SimplicialSurface) -> Result<(), SurfaceError> {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for v in k.vertices() {
        let p = k.position(v);
        for (d, &c) in p.iter().enumerate() {
            if c.is_nan() || c.abs() > MAX_COORDINATE {
                return Err(SurfaceError::CoordinateOutOfRange { v, value: c });
            }
            lo[d] = lo[d].min(c);
            hi[d] = hi[d].max(c);
        }
    }
    let ext: Vec<f64> = (0..3).map(|d| (hi[d] - lo[d]).max(0.0)).collect();
    let diagonal = crate::numeric::robust_norm(&ext);
    if diagonal < MIN_EXTENT {
        return Err(SurfaceError::ExtentTooSmall { diagonal });
    }
    Ok(())
}

impl Pps {
    /// [`Pps::build`] after the checks of this module: the fit fits the memory budget and the
    /// coordinates are within the range where f64 normals and curvatures are meaningful.
    pub fn try_build(
        k: &SimplicialSurface,
        target: &dyn TargetSurface,
        options: PpsOptions,
    ) -> Result<Pps, SurfaceError> {
        check_scale(k)?;
        check_fit_size(k, options.profile)?;
        Ok(Pps::build(k, target, options))
    }
}
