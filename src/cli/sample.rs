//! `ppm sample` (Sec. 6.2).

use super::load::surface as load;
use super::progress::Line;
use crate::mesh::SimplicialSurface;
use crate::oracle::choice::Choice;
use crate::surface::output::{
    edge_use_counts, write_mesh_with_attributes, Attributes, SampledMesh,
};
use crate::surface::pps::{Pps, PpsOptions};
use crate::surface::profile::Profile;
use crate::surface::smooth::SmoothSurface;
use crate::surface::target::{SPrime, SurfaceKind};
use crate::surface::Construction;
use std::path::Path;
use std::process::ExitCode;
use std::time::Instant;

fn build(k: &SimplicialSurface, profile: &str, surface: &str) -> Result<Pps, ExitCode> {
    let profile = Profile::parse(profile).ok_or_else(|| {
        eprintln!("error: unknown profile {profile:?} (paper | authors-code)");
        ExitCode::from(2)
    })?;
    let kind = SurfaceKind::parse(surface).ok_or_else(|| {
        eprintln!("error: unknown surface {surface:?} (pn | loop)");
        ExitCode::from(2)
    })?;
    let target = SPrime::for_profile(kind, k, profile).map_err(|e| {
        eprintln!("error: S′ = {}: {e}", kind.name());
        ExitCode::from(1)
    })?;
    note_large_fit(k, profile);
    Pps::try_build(
        k,
        target.as_target(),
        PpsOptions {
            profile,
            ..PpsOptions::default()
        },
    )
    .map_err(|e| {
        eprintln!("error: {e}");
        ExitCode::from(2)
    })
}

/// Progress for the large fits (Sec. 5.2) that are admitted: say what is being built (shared
/// by `ppm sample` and `ppm eval`).
pub(super) fn note_large_fit(k: &SimplicialSurface, profile: Profile) {
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

/// The options of `ppm sample` (see `crate::cli`).
pub(crate) struct SampleArgs<'a> {
    /// The mesh K.
    pub file: &'a Path,
    /// Subdivision level (Sec. 6.2).
    pub level: u32,
    /// Output mesh (.obj, .off or .ply).
    pub out: &'a Path,
    /// Chapter 5 profile of the vertex construction.
    pub profile: &'a str,
    /// S′ of the vertex construction: `pn` | `loop`.
    pub surface: &'a str,
    /// `positions` | `normals` | `curvature`.
    pub attributes: &'a str,
    /// No summary lines.
    pub quiet: bool,
    /// Which PPS.
    pub construction: Construction,
    /// κ of the (σ, v) construction.
    pub kappa: f64,
    /// Patch degree of the (σ, v) construction.
    pub patch_degree: usize,
}

/// `ppm sample FILE --level N -o OUT`: sample M by midpoint subdivision through eval (Sec. 6.2)
/// and write it with normals and curvatures. The construction is chosen once, here; the
/// sampling and the writing go through [`SmoothSurface`].
pub(crate) fn run_sample(a: &SampleArgs) -> ExitCode {
    let Some(attrs) = Attributes::parse(a.attributes) else {
        eprintln!(
            "error: unknown --attributes {:?} (positions | normals | curvature)",
            a.attributes
        );
        return ExitCode::from(2);
    };
    let t0 = Instant::now();
    let k = match load(a.file) {
        Ok(k) => k,
        Err(c) => return c,
    };
    let built: Result<Box<dyn SmoothSurface>, ExitCode> = match a.construction {
        Construction::Vertex => build_vertex(&k, a, t0).map(|p| Box::new(p) as _),
        Construction::SigmaV => super::sigma_v::build(&k, a.kappa, a.patch_degree, a.quiet, t0)
            .map(|p| Box::new(p) as _),
        // `ppm msplines sample`'s spline (positions only: `--attributes positions`).
        c @ Construction::ManifoldSpline => Choice::default_of(c).build(&k).map_err(|e| {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }),
    };
    let surface = match built {
        Ok(s) => s,
        Err(c) => return c,
    };
    let line = Line::new("ppm sample", "points", !a.quiet);
    let hook = line.hook();
    let sampled = surface.sample(a.level, attrs, hook.as_ref().map(|h| h as _));
    line.finish();
    let m = match sampled {
        Ok(m) => m,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(1);
        }
    };
    write_sampled("ppm sample", a.out, &m, a.quiet, t0)
}

/// The vertex PPS of `ppm sample`, with its summary (fit per degree, Sec. 5.2).
fn build_vertex(k: &SimplicialSurface, a: &SampleArgs, t0: Instant) -> Result<Pps, ExitCode> {
    let pps = build(k, a.profile, a.surface)?;
    let t_build = t0.elapsed().as_secs_f64();
    if !a.quiet {
        eprintln!(
            "ppm sample: {} vertices, {} faces; PPS ({}, S′ = {}) built in {t_build:.2} s",
            k.num_vertices(),
            k.num_faces(),
            pps.options.profile.name(),
            pps.target_name()
        );
        for f in pps.fit_info() {
            eprintln!(
                "  degree {:>2}: l = {:>2}, {} samples, {} unknowns, rank {}, κ = {:.2e}",
                f.m, f.l, f.rows, f.unknowns, f.rank, f.condition
            );
        }
    }
    Ok(pps)
}

/// Writes a sampled surface (atomically, see `write_mesh_with_attributes`) and reports its
/// edge-use counts (watertight: every edge in two faces); shared by every construction's
/// `ppm sample`.
pub(crate) fn write_sampled(
    cmd: &str,
    out: &Path,
    m: &SampledMesh,
    quiet: bool,
    t0: Instant,
) -> ExitCode {
    let (two, other) = edge_use_counts(&m.faces);
    if let Err(e) = write_mesh_with_attributes(out, m) {
        eprintln!("error: writing {}: {e}", out.display());
        return ExitCode::from(2);
    }
    if !quiet {
        eprintln!(
            "{cmd}: wrote {} ({} vertices, {} faces; {} edges in two faces, {} otherwise) in {:.2} s",
            out.display(),
            m.positions.len(),
            m.faces.len(),
            two,
            other,
            t0.elapsed().as_secs_f64()
        );
    }
    ExitCode::SUCCESS
}
