//! The one place a construction is chosen and built as a `Box<dyn SmoothSurface>`: the
//! report's vertex PPS (Ch. 4–5, with its profile and S′ of Sec. 5.1), the tutorial's (σ, v)
//! PPS (SPEC `SV-D13`), the manifold spline F(M) (seed 003 Secs. 5.5–5.6), or the (σ, v) PPS
//! fitted by `ppm fit` and read back from its file (docs/fit-format.md). The oracle session's
//! `eval` and `ppm eval` both build their surface here and evaluate it through the trait only,
//! so each accepts every construction; an operation a construction lacks is the trait's
//! `SmoothError::Unsupported`.

use crate::fitting::format::{read_fit, FitFormatError};
use crate::mesh::SimplicialSurface;
use crate::msplines::smooth::{OwnedSpline, SplineParams};
use crate::msplines::MsError;
use crate::surface::sigma_v::SigmaVPps;
use crate::surface::smooth::{SmoothError, SmoothSurface};
use crate::surface::{Construction, PnTriangles, Pps, PpsOptions, Profile, SPrime, SurfaceKind};
use serde_json::{json, Value};
use std::path::Path;

/// A construction with its parameters: what a command line or a session chose.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Choice {
    /// The vertex PPS with the Chapter 5 profile and S′.
    Vertex {
        /// Chapter 5's parameters.
        profile: Profile,
        /// S′ (Sec. 6.2): PN triangles or the Loop limit surface.
        sprime: SurfaceKind,
    },
    /// The (σ, v) PPS on S′ = PN triangles.
    SigmaV {
        /// κ of r_{v,σ} (SPEC `SV-D3`), in (0, 1).
        kappa: f64,
        /// Degree of the triangular patches (SPEC `SV-D11`).
        patch_degree: usize,
    },
    /// The manifold spline on ring-3 charts.
    Spline(SplineParams),
}

/// Why a chosen construction could not be built.
#[derive(Debug, thiserror::Error)]
pub enum BuildError {
    /// S′ could not be built (the Loop limit surface's limits).
    #[error("S′ = {kind}: {msg}")]
    Target {
        /// The S′ asked for.
        kind: &'static str,
        /// Why not.
        msg: String,
    },
    /// The PPS could not be built (its fit, Sec. 5.2 / SPEC `SV-D11`).
    #[error(transparent)]
    Surface(#[from] SmoothError),
    /// The manifold spline could not be built (genus 0 per Thm. 2, …).
    #[error(transparent)]
    Spline(#[from] MsError),
    /// The fitted-surface file could not be read.
    #[error(transparent)]
    Fit(#[from] FitFormatError),
}

impl Choice {
    /// The default of each construction (the commands' defaults).
    pub fn default_of(c: Construction) -> Choice {
        match c {
            Construction::Vertex => Choice::Vertex {
                profile: Profile::default(),
                sprime: SurfaceKind::default(),
            },
            Construction::SigmaV => Choice::SigmaV {
                kappa: crate::surface::sigma_v::DEFAULT_KAPPA,
                patch_degree: crate::surface::sigma_v::DEFAULT_PATCH_DEGREE,
            },
            Construction::ManifoldSpline => Choice::Spline(SplineParams::default()),
        }
    }

    /// Which construction.
    pub fn construction(&self) -> Construction {
        match self {
            Choice::Vertex { .. } => Construction::Vertex,
            Choice::SigmaV { .. } => Construction::SigmaV,
            Choice::Spline(_) => Construction::ManifoldSpline,
        }
    }

    /// The surface of this construction built from K.
    pub fn build(&self, k: &SimplicialSurface) -> Result<Box<dyn SmoothSurface>, BuildError> {
        Ok(match *self {
            Choice::Vertex { profile, sprime } => Box::new(vertex_pps(k, profile, sprime)?.1),
            Choice::SigmaV {
                kappa,
                patch_degree,
            } => Box::new(
                SigmaVPps::build(k, &PnTriangles::new(k), kappa, patch_degree)
                    .map_err(SmoothError::from)?,
            ),
            Choice::Spline(p) => Box::new(OwnedSpline::build(k.clone(), p)?),
        })
    }

    /// What the oracle's `eval` answers add to `info` to name their reference (nothing for
    /// the vertex PPS, the protocol's default).
    pub(crate) fn info(&self) -> Option<Value> {
        match *self {
            Choice::Vertex { .. } => None,
            Choice::SigmaV { kappa, .. } => {
                Some(json!({"construction": "sigma-v", "kappa": kappa}))
            }
            Choice::Spline(p) => Some(json!({
                "construction": Construction::ManifoldSpline.name(),
                "form": p.form,
                "degree": p.degree,
                "seed": p.seed,
            })),
        }
    }
}

/// The vertex PPS of K with its S′ (the oracle session keeps both: its other Chapter 5
/// queries need the concrete type).
pub(crate) fn vertex_pps(
    k: &SimplicialSurface,
    profile: Profile,
    sprime: SurfaceKind,
) -> Result<(SPrime, Pps), BuildError> {
    let target = SPrime::for_profile(sprime, k, profile).map_err(|e| BuildError::Target {
        kind: sprime.name(),
        msg: e.to_string(),
    })?;
    let pps = Pps::try_build(
        k,
        target.as_target(),
        PpsOptions {
            profile,
            ..PpsOptions::default()
        },
    )
    .map_err(SmoothError::from)?;
    Ok((target, pps))
}

/// A fitted surface read from its file (`ppm fit -o FIT`, docs/fit-format.md): the base mesh
/// K (its faces are eval's σ) and the fitted (σ, v) PPS, with what `eval` answers add to
/// `info` to name it.
pub struct Fitted {
    /// The base mesh.
    pub k: SimplicialSurface,
    /// The fitted PPS.
    pub surface: Box<dyn SmoothSurface>,
    /// ε of the fit (absolute).
    pub epsilon: f64,
    /// `{"construction": "fit", "kappa", "epsilon"}`.
    pub info: Value,
}

/// Read a fitted-surface file.
pub fn read_fitted(path: &Path) -> Result<Fitted, BuildError> {
    let f = read_fit(path)?;
    let info = json!({"construction": "fit", "kappa": f.pps.gluing.kappa, "epsilon": f.epsilon});
    Ok(Fitted {
        k: f.k,
        surface: Box::new(f.pps),
        epsilon: f.epsilon,
        info,
    })
}
