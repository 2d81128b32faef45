//! `ppm sd …`: simplicial diffeomorphisms of a planar complex (Mello–Velho; SPEC rows SD-…).

use crate::mesh::io::{read_mesh, ReadOptions};
use crate::report::{render_text, CheckResult};
use crate::sdiff::{checks, claims, complex, iso, params, positivity::Budget};
use clap::{Args, Subcommand};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// `ppm sd` arguments.
#[derive(Args, Debug)]
pub struct SdArgs {
    #[command(subcommand)]
    cmd: SdCommand,
}

#[derive(Subcommand, Debug)]
enum SdCommand {
    /// Validate the planar complex and check the map of PARAMS on it: Def. 1 (K-invariance),
    /// agreement on shared edges, the family's hypotheses, det DX > 0 on every closed triangle
    /// (exact and by intervals), the inversion spot check. Exit 1 on any failure.
    Check {
        /// The planar complex (OFF/OBJ/PLY, z = 0).
        mesh: PathBuf,
        /// The map (TOML; format in src/sdiff/params.rs and tests/data/sdiff/).
        params: PathBuf,
        #[arg(long)]
        json: bool,
        /// Seed of the inversion spot check.
        #[arg(long, default_value_t = 1)]
        seed: u64,
    },
    /// Write the curved isocurve 𝒪 = X⁻¹(f̂⁻¹(c)) (Sec. 4) of PARAMS' [iso] as OBJ lines, and
    /// check its topology against the linear one.
    Iso {
        mesh: PathBuf,
        params: PathBuf,
        #[arg(short = 'o', long)]
        output: PathBuf,
        /// Also write the linear isocurve O here.
        #[arg(long)]
        linear: Option<PathBuf>,
        #[arg(long)]
        json: bool,
    },
    /// Search the injectivity claims of Sec. 3 exactly on random maps of the reference triangle.
    Claims {
        #[arg(long, default_value_t = 200)]
        samples: usize,
        #[arg(long, default_value_t = 1)]
        seed: u64,
        #[arg(long)]
        json: bool,
    },
}

fn load(
    mesh: &Path,
    params_path: &Path,
) -> Result<
    (
        complex::PlanarComplex,
        params::MapSpec,
        params::ComplexMap,
        Vec<CheckResult>,
    ),
    String,
> {
    let raw = read_mesh(mesh, &ReadOptions::default()).map_err(|e| e.to_string())?;
    let (k, rep) = match complex::validate(&raw) {
        Ok(x) => x,
        Err(complex::ComplexError::Invalid(rep)) => {
            return Err(format!(
                "{}: not a planar simplicial complex\n{}",
                mesh.display(),
                render_text(&rep)
            ))
        }
        Err(e) => return Err(format!("{}: {e}", mesh.display())),
    };
    let spec = params::read(params_path).map_err(|e| e.to_string())?;
    let cm = spec.build(&k, params_path).map_err(|e| e.to_string())?;
    Ok((k, spec, cm, rep))
}

fn emit(results: &[CheckResult], json: bool) -> ExitCode {
    if json {
        match serde_json::to_string_pretty(results) {
            Ok(s) => println!("{s}"),
            Err(e) => {
                eprintln!("error: {e}");
                return ExitCode::from(2);
            }
        }
    } else {
        print!("{}", render_text(results));
    }
    if results.iter().any(|r| r.failed()) {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}

/// Runs `ppm sd …`.
pub fn run(a: SdArgs) -> ExitCode {
    match a.cmd {
        SdCommand::Check {
            mesh,
            params,
            json,
            seed,
        } => match load(&mesh, &params) {
            Ok((k, _, cm, mut rep)) => {
                let opts = checks::Options {
                    seed,
                    ..Default::default()
                };
                rep.extend(checks::check_all(&k, &cm, &opts));
                emit(&rep, json)
            }
            Err(e) => {
                eprintln!("error: {e}");
                ExitCode::from(2)
            }
        },
        SdCommand::Iso {
            mesh,
            params: p,
            output,
            linear,
            json,
        } => {
            let (k, spec, cm, _) = match load(&mesh, &p) {
                Ok(x) => x,
                Err(e) => {
                    eprintln!("error: {e}");
                    return ExitCode::from(2);
                }
            };
            let Some((f, c)) = spec.iso.clone() else {
                eprintln!(
                    "error: {}: no [iso] table (f per vertex and the level c)",
                    p.display()
                );
                return ExitCode::from(2);
            };
            match iso::isocurves(&k, &cm, &f, &c) {
                Ok(out) => {
                    for (path, poly) in [(Some(output), &out.curved), (linear, &out.linear)] {
                        if let Some(path) = path {
                            if let Err(e) = std::fs::write(&path, poly.to_obj()) {
                                eprintln!("error: {}: {e}", path.display());
                                return ExitCode::from(2);
                            }
                        }
                    }
                    emit(&out.report, json)
                }
                Err(e) => {
                    eprintln!("error: {}: {e}", p.display());
                    ExitCode::from(2)
                }
            }
        }
        SdCommand::Claims {
            samples,
            seed,
            json,
        } => {
            let b = Budget::default();
            let mut out = Vec::new();
            let s = claims::search(samples, seed, b, |r| claims::random_adjusted(2, r));
            out.push(claims::universal(
                "SD-L141",
                "Sec. 3.2: adjusted quadratic maps are injective",
                &s,
                samples,
                seed,
            ));
            let s = claims::search(samples, seed, b, |r| claims::random_adjusted(3, r));
            out.push(claims::universal(
                "SD-L139",
                "Sec. 3.2 (implied): adjusted cubic maps are injective",
                &s,
                samples,
                seed,
            ));
            let s = claims::search(samples, seed, b, |r| claims::random_adjusted(4, r));
            out.push(claims::existential(
                "SD-L139",
                "Sec. 3.2: an adjusted quartic can be non-injective",
                &s,
                samples,
                seed,
            ));
            let s = claims::search(samples, seed, b, claims::random_fixed_solitary3);
            out.push(claims::universal(
                "SD-L146",
                "Sec. 3.2: fixed non-solitary ⇒ injective (cubic, 2-D)",
                &s,
                samples,
                seed,
            ));
            for n in 1..=4 {
                let s = claims::search(samples, seed, b, |r| claims::random_rational_fixed(n, r));
                out.push(claims::universal(
                    "SD-L161",
                    &format!("Sec. 3.3: fixed points, q > 0 ⇒ injective (n = {n})"),
                    &s,
                    samples,
                    seed,
                ));
            }
            let s = claims::search(samples, seed, b, claims::random_monotonic);
            out.push(claims::universal(
                "SD-L115",
                "Sec. 3.1: monotonic ⇒ injective",
                &s,
                samples,
                seed,
            ));
            emit(&out, json)
        }
    }
}
