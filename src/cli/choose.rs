//! The construction of a command line (`--construction` and its parameters), chosen once and
//! built through `oracle::choice` — the one place `ppm sample` and `ppm eval` build a surface
//! from K.

use crate::mesh::SimplicialSurface;
use crate::oracle::choice::{BuildError, Choice};
use crate::surface::profile::Profile;
use crate::surface::smooth::SmoothSurface;
use crate::surface::target::SurfaceKind;
use crate::surface::Construction;
use std::process::ExitCode;

/// What a command line says about the construction.
pub(super) struct ConstructionArgs<'a> {
    /// Which PPS.
    pub construction: Construction,
    /// Chapter 5 profile of the vertex construction.
    pub profile: &'a str,
    /// S′ of the vertex construction: `pn` | `loop`.
    pub surface: &'a str,
    /// κ of the (σ, v) construction.
    pub kappa: f64,
    /// Patch degree of the (σ, v) construction.
    pub patch_degree: usize,
}

fn usage(msg: String) -> ExitCode {
    eprintln!("error: {msg}");
    ExitCode::from(2)
}

/// The construction of the command line (a note on stderr before a large vertex fit).
pub(super) fn choice(k: &SimplicialSurface, a: &ConstructionArgs) -> Result<Choice, ExitCode> {
    Ok(match a.construction {
        Construction::Vertex => {
            let profile = Profile::parse(a.profile).ok_or_else(|| {
                usage(format!(
                    "unknown profile {:?} (paper | authors-code)",
                    a.profile
                ))
            })?;
            let sprime = SurfaceKind::parse(a.surface)
                .ok_or_else(|| usage(format!("unknown surface {:?} (pn | loop)", a.surface)))?;
            note_large_fit(k, profile);
            Choice::Vertex { profile, sprime }
        }
        Construction::SigmaV => Choice::SigmaV {
            kappa: a.kappa,
            patch_degree: a.patch_degree,
        },
        c @ Construction::ManifoldSpline => Choice::default_of(c),
    })
}

/// The chosen surface built from K; exit 1 when S′ cannot be built (the Loop limit surface's
/// limits), 2 when the surface cannot.
pub(super) fn build(
    k: &SimplicialSurface,
    choice: &Choice,
) -> Result<Box<dyn SmoothSurface>, ExitCode> {
    choice.build(k).map_err(|e| {
        eprintln!("error: {e}");
        match e {
            BuildError::Target { .. } => ExitCode::from(1),
            _ => ExitCode::from(2),
        }
    })
}

/// Progress for the large fits (Sec. 5.2) that are admitted: say what is being built.
fn note_large_fit(k: &SimplicialSurface, profile: Profile) {
    if let Ok(bytes) = crate::surface::admissible::check_fit_size(k, profile) {
        if bytes > 1 << 28 {
            let max_m = k.vertices().map(|v| k.degree(v)).max().unwrap_or(0);
            eprintln!(
                "ppm: fitting the shape functions (Sec. 5.2, {} profile, largest degree {max_m}, l = {}): about {} MB; this may take a while",
                profile.name(),
                profile.bezier_degree(max_m),
                bytes >> 20
            );
        }
    }
}
