//! `ppm eval FILE FACE λ μ ν`: one point of the smooth surface, eval(σ, λ, μ, ν) of Sec. 6.1.4,
//! with the chart eval chose and (from the jets) its normal and curvatures. The construction
//! is chosen once (`oracle::choice`: `--construction`, or the fitted surface of a FIT file)
//! and evaluated through `SmoothSurface` only; what a construction lacks (the manifold
//! spline's jets) is its typed refusal.

use super::choose::{self, ConstructionArgs};
use super::load::surface as load;
use crate::fitting::format::is_fit_file;
use crate::mesh::FaceId;
use crate::oracle::choice::read_fitted;
use crate::surface::output::Attributes;
use crate::surface::smooth::{ChartAt, SmoothError, SmoothSurface};
use crate::surface::Construction;
use std::path::Path;
use std::process::ExitCode;

/// The options of `ppm eval` (see `crate::cli`).
pub(crate) struct EvalArgs<'a> {
    /// The mesh K, or a fitted-surface file.
    pub file: &'a Path,
    /// σ.
    pub face: u32,
    /// (λ, μ, ν).
    pub bary: [f64; 3],
    /// Chapter 5 profile of the vertex construction.
    pub profile: &'a str,
    /// S′ of the vertex construction: `pn` | `loop`.
    pub surface: &'a str,
    /// The construction (default: the vertex PPS; refused for a FIT file).
    pub construction: Option<Construction>,
    /// κ of the (σ, v) construction.
    pub kappa: f64,
    /// Patch degree of the (σ, v) construction.
    pub patch_degree: usize,
    /// `positions` | `normals` | `curvature` (default: curvature for a mesh, positions for a
    /// FIT file).
    pub attributes: Option<&'a str>,
}

fn usage(msg: String) -> ExitCode {
    eprintln!("error: {msg}");
    ExitCode::from(2)
}

/// The surface of the command line: the FIT file's, or the construction built from K.
fn surface(a: &EvalArgs) -> Result<Box<dyn SmoothSurface>, ExitCode> {
    if is_fit_file(a.file) {
        if let Some(c) = a.construction {
            return Err(usage(format!(
                "--construction {}: a fitted-surface file is evaluated as its fitted (σ, v) PPS",
                c.name()
            )));
        }
        return read_fitted(a.file)
            .map(|f| f.surface)
            .map_err(|e| usage(e.to_string()));
    }
    let k = load(a.file)?;
    let choice = choose::choice(
        &k,
        &ConstructionArgs {
            construction: a.construction.unwrap_or_default(),
            profile: a.profile,
            surface: a.surface,
            kappa: a.kappa,
            patch_degree: a.patch_degree,
        },
    )?;
    choose::build(&k, &choice)
}

/// The chart eval chose, as the JSON fields of the answer (`"chart"` and `"vertex"` for the
/// vertex PPS, `"corner"` for a (σ, v) PPS, nothing for the manifold spline).
fn chart_fields(c: Option<&ChartAt<f64>>) -> String {
    match c {
        Some(ChartAt::Vertex { chart, vertex, .. }) => {
            format!(", \"chart\": \"{chart:?}\", \"vertex\": {vertex}")
        }
        Some(ChartAt::Corner { v, k, .. }) => format!(", \"corner\": {{\"v\": {v}, \"k\": {k}}}"),
        None => String::new(),
    }
}

/// `ppm eval`: prints one JSON object; exit status 1 when the point cannot be evaluated (or
/// the construction lacks the asked attributes), 2 on unusable input.
pub(crate) fn run(a: &EvalArgs) -> ExitCode {
    let default = if is_fit_file(a.file) {
        "positions"
    } else {
        "curvature"
    };
    let attributes = a.attributes.unwrap_or(default);
    let Some(attrs) = Attributes::parse(attributes) else {
        return usage(format!(
            "unknown --attributes {attributes:?} (positions | normals | curvature)"
        ));
    };
    let s = match surface(a) {
        Ok(s) => s,
        Err(c) => return c,
    };
    let (face, bary, f) = (a.face, a.bary, FaceId(a.face));
    let at = match s.eval_located(f, bary) {
        Ok(at) => at,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(1);
        }
    };
    let chart = chart_fields(at.chart.as_ref());
    if attrs == Attributes::Positions {
        println!(
            "{{\"face\": {face}, \"bary\": {bary:?}{chart}, \"point\": {:?}}}",
            at.point
        );
        return ExitCode::SUCCESS;
    }
    // The point of the jets (the vertex PPS's output since `ppm eval` existed).
    match s.eval_geometry(f, bary) {
        Ok(g) if attrs == Attributes::Normals => {
            println!(
                "{{\"face\": {face}, \"bary\": {bary:?}{chart}, \"point\": {:?}, \"normal\": {:?}}}",
                g.point, g.normal
            );
            ExitCode::SUCCESS
        }
        Ok(g) => {
            println!(
                "{{\"face\": {face}, \"bary\": {bary:?}{chart}, \"point\": {:?}, \"normal\": {:?}, \"gaussian\": {}, \"mean\": {}}}",
                g.point, g.normal, g.gaussian, g.mean
            );
            ExitCode::SUCCESS
        }
        Err(e @ SmoothError::Unsupported { .. }) => {
            eprintln!("error: {e} (--attributes positions evaluates the point only)");
            ExitCode::from(1)
        }
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(1)
        }
    }
}
