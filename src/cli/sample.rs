//! `ppm sample` (Sec. 6.2).

use super::choose::{self, ConstructionArgs};
use super::load::surface as load;
use super::progress::Line;
use crate::mesh::SimplicialSurface;
use crate::surface::output::{
    edge_use_counts, write_mesh_with_attributes, Attributes, SampledMesh,
};
use crate::surface::smooth::SmoothSurface;
use crate::surface::Construction;
use std::path::Path;
use std::process::ExitCode;
use std::time::Instant;

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
    let args = ConstructionArgs {
        construction: a.construction,
        profile: a.profile,
        surface: a.surface,
        kappa: a.kappa,
        patch_degree: a.patch_degree,
    };
    let surface = match choose::choice(&k, &args).and_then(|c| choose::build(&k, &c)) {
        Ok(s) => s,
        Err(c) => return c,
    };
    if !a.quiet {
        print_summary(&k, surface.as_ref(), t0);
    }
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

/// What was built: the construction and its fits per degree (Sec. 5.2, SPEC `SV-D11`).
fn print_summary(k: &SimplicialSurface, surface: &dyn SmoothSurface, t0: Instant) {
    eprintln!(
        "ppm sample: {} vertices, {} faces; {} built in {:.2} s",
        k.num_vertices(),
        k.num_faces(),
        surface.name(),
        t0.elapsed().as_secs_f64()
    );
    for f in surface.fit_summary() {
        let l = f.l.map_or(String::new(), |l| format!("l = {l:>2}, "));
        eprintln!(
            "  degree {:>2}: {l}{} samples, {} unknowns, rank {}, κ = {:.2e}",
            f.m, f.rows, f.unknowns, f.rank, f.condition
        );
    }
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
