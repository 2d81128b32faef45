//! `ppm sd check3|iso3|claims3`: simplicial diffeomorphisms of a tetrahedral complex
//! (Mello–Velho with m = 3; SPEC rows `SD-…(3-D)`; the `.tets` format in docs/sdiff-3d.md).

use super::results::{emit, fail};
use crate::mesh::io::output_format;
use crate::report::{render_text, CheckResult};
use crate::sdiff::common::positivity::Budget;
use crate::sdiff::planar::claims;
use crate::sdiff::tet;
use crate::sdiff::tet::checks::{check_all3, Options3};
use crate::sdiff::tet::complex::{TetComplex, TetComplexError};
use crate::sdiff::tet::params::{MapSpec3, TetMap};
use clap::Subcommand;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// The 3-D subcommands of `ppm sd`.
#[derive(Subcommand, Debug)]
pub(super) enum Sd3Command {
    /// Validate the tetrahedral complex (exact) and check the map of PARAMS on it: Eq. (1),
    /// Def. 1 (faces, inside), agreement on shared triangles, the family's hypotheses, det DX > 0
    /// on every closed tetrahedron (exact, and by intervals with the agreement check).
    /// Exit 1 on any failure, 2 on unreadable or invalid input.
    Check3 {
        /// The complex (`.tets`).
        complex: PathBuf,
        /// The map (TOML; format in src/sdiff/tet/params.rs).
        params: PathBuf,
        /// Box budget of the interval route per tetrahedron.
        #[arg(long, default_value_t = 20_000)]
        boxes: usize,
        #[arg(long)]
        json: bool,
    },
    /// Write the curved isosurface 𝒪 = (f̂∘X)⁻¹(c) (Sec. 4) of PARAMS' [iso] in the format of
    /// OUTPUT's extension (.obj, .off, .ply) and compare its topology with the linear one (X = id).
    Iso3 {
        complex: PathBuf,
        params: PathBuf,
        #[arg(short = 'o', long)]
        output: PathBuf,
        /// Also write the linear isosurface O here.
        #[arg(long)]
        linear: Option<PathBuf>,
        /// Lattice level N: each tetrahedron is cut into N³ for marching tetrahedra.
        #[arg(long, default_value_t = 8)]
        level: usize,
        #[arg(long)]
        json: bool,
    },
    /// Seeded exact search of the rational family (Eq. (11)) on the tetrahedron: L161 (fixed
    /// control points, q > 0) for n = 1..3, and adjusted non-fixed maps (no claim).
    Claims3 {
        #[arg(long, default_value_t = 20)]
        samples: usize,
        #[arg(long, default_value_t = 161)]
        seed: u64,
        #[arg(long)]
        json: bool,
    },
}

fn load3(
    complex: &Path,
    params: &Path,
) -> Result<(TetComplex, MapSpec3, Vec<TetMap>, Vec<CheckResult>), String> {
    let raw = tet::file::read(complex).map_err(|e| e.to_string())?;
    let (k, rep) = match tet::complex::validate(&raw) {
        Ok(x) => x,
        Err(TetComplexError::Invalid(rep)) => {
            return Err(format!(
                "{}: not a tetrahedral complex\n{}",
                complex.display(),
                render_text(&rep)
            ))
        }
        Err(e) => return Err(e.to_string()),
    };
    let spec = tet::params::read(params).map_err(|e| e.to_string())?;
    let maps = spec.build(&k, params).map_err(|e| e.to_string())?;
    Ok((k, spec, maps, rep))
}

/// Runs one 3-D subcommand.
pub(super) fn run(c: Sd3Command) -> ExitCode {
    match c {
        Sd3Command::Check3 {
            complex,
            params,
            boxes,
            json,
        } => match load3(&complex, &params) {
            Ok((k, _, maps, mut rep)) => {
                let opts = Options3 {
                    interval_boxes: boxes,
                    ..Options3::default()
                };
                rep.extend(check_all3(&k, &maps, &opts));
                emit(&rep, json)
            }
            Err(e) => fail(e),
        },
        Sd3Command::Iso3 {
            complex,
            params,
            output,
            linear,
            level,
            json,
        } => {
            let (k, spec, maps, _) = match load3(&complex, &params) {
                Ok(x) => x,
                Err(e) => return fail(e),
            };
            let Some((f, c)) = spec.iso.clone() else {
                return fail(format!("{}: no [iso] table", params.display()));
            };
            let iso = match tet::iso::isosurfaces(&k, &maps, &f, &c, level) {
                Ok(x) => x,
                Err(e) => return fail(e.to_string()),
            };
            let write = |m: &tet::iso::TriMesh, p: &Path| {
                let format = output_format(p)?;
                std::fs::write(p, m.encode(format)?)
            };
            if let Err(e) = write(&iso.curved, output.as_path()) {
                return fail(format!("{}: {e}", output.display()));
            }
            if let Some(p) = linear {
                if let Err(e) = write(&iso.linear, p.as_path()) {
                    return fail(format!("{}: {e}", p.display()));
                }
            }
            emit(&iso.report, json)
        }
        Sd3Command::Claims3 {
            samples,
            seed,
            json,
        } => {
            let b = Budget::default();
            let mut out = Vec::new();
            for n in 1..=3 {
                let s = tet::search::search3(samples, seed, b, |r| {
                    tet::search::random_rational_fixed4(n, r)
                });
                out.push(claims::universal(
                    "SD-L161(3-D)",
                    &format!("Sec. 3.3: fixed points, q > 0 ⇒ injective (tetrahedron, n = {n})"),
                    &s,
                    samples,
                    seed,
                ));
            }
            let s = tet::search::search3(samples, seed, b, |r| {
                tet::search::random_rational_adjusted4(2, r)
            });
            let mut r = claims::universal(
                "SD-L161(3-D)",
                "beyond Sec. 3.3: adjusted, not fixed, q > 0, n = 2 (no claim: a warning if refuted)",
                &s,
                samples,
                seed,
            );
            if r.failed() {
                r.mark_warning();
            }
            out.push(r);
            emit(&out, json)
        }
    }
}
