//! `ppm sd …`: simplicial diffeomorphisms of a planar complex (Mello–Velho; SPEC rows SD-…);
//! the 3-D subcommands (`check3`, `iso3`, `claims3`) are in `sd3`.

use super::results::{emit, fail};
use crate::mesh::io::{read_mesh, ReadOptions};
use crate::report::{render_text, CheckResult};
use crate::sdiff::common::positivity::Budget;
use crate::sdiff::planar::{
    c1, checks, claims, complex, handles, implicit, iso, normals, params, polygonize,
};
use clap::{Args, Subcommand};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// `ppm sd` arguments.
#[derive(Args, Debug)]
pub(super) struct SdArgs {
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
        /// The map (TOML; format in src/sdiff/planar/params.rs and tests/data/sdiff/).
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
    /// Sec. 5, L197–L203: the one-sided normals of 𝒪 where it crosses interior edges (exact, at
    /// the rational point nearest each crossing) and the derivative-jump claim (SPEC SD-L203).
    Normals {
        mesh: PathBuf,
        /// The map, with an [iso] table.
        params: PathBuf,
        #[arg(long)]
        json: bool,
    },
    /// Sec. 5, Eq. (12), L213–L225: build the C¹ system for the control points of PARAMS,
    /// solve it exactly, look for weights q_I > 0 (Fourier–Motzkin), verify C¹ as polynomial
    /// identities (SPEC SD-L219, SD-E12). Exit 1 when a check fails.
    C1 {
        mesh: PathBuf,
        /// Degree and control points (polynomial or rational family) and the [iso] table.
        params: PathBuf,
        /// Impose (12) only on the interior edges crossed by O (default: all, as L217 says).
        #[arg(long)]
        crossed_only: bool,
        /// Inequality budget of Fourier–Motzkin.
        #[arg(long, default_value_t = 20_000)]
        budget: usize,
        /// Write the solved rational map here (TOML).
        #[arg(short = 'o', long)]
        output: Option<PathBuf>,
        #[arg(long)]
        json: bool,
    },
    /// Sec. 6.1: move the handle of edge A,B (where 𝒪 should cross it) in STEPS steps; each
    /// position is realised by the quadratic X_1 and certified or refuted exactly
    /// (SPEC SD-6.1(handle)).
    Handle {
        mesh: PathBuf,
        /// A file with an [iso] table (f per vertex, level c).
        params: PathBuf,
        /// The edge, as two vertex ids "A,B".
        #[arg(long, value_delimiter = ',')]
        edge: Vec<u32>,
        #[arg(long, default_value_t = 32)]
        steps: usize,
        #[arg(long)]
        json: bool,
    },
    /// Sec. 6.2: adaptive polygonization of Taubin's quartic (L330) or the circle of Fig. 4;
    /// writes 𝒪 (and O, the triangulation) and measures it (SPEC SD-6.2(…), SD-L302, SD-L324).
    Polygonize {
        /// taubin | circle.
        #[arg(long, default_value = "taubin")]
        curve: String,
        /// K_0 is a GRID × GRID Kuhn triangulation of the curve's box.
        #[arg(long, default_value_t = 9)]
        grid: usize,
        /// Largest number of bisections.
        #[arg(long, default_value_t = 400)]
        steps: usize,
        /// The curved isocurve 𝒪 (OBJ lines).
        #[arg(short = 'o', long)]
        output: PathBuf,
        /// Also write O here (OBJ lines).
        #[arg(long)]
        linear: Option<PathBuf>,
        /// Also write the triangulation here (OFF).
        #[arg(long)]
        mesh: Option<PathBuf>,
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
    #[command(flatten)]
    D3(super::sd3::Sd3Command),
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

/// The complex, its map and the \[iso\] table (f per vertex, level c) the Secs. 5–6 commands need.
type IsoInput = (
    complex::PlanarComplex,
    params::MapSpec,
    params::ComplexMap,
    Vec<crate::sdiff::common::rational::Q>,
    crate::sdiff::common::rational::Q,
);

fn load_iso(mesh: &Path, params_path: &Path) -> Result<IsoInput, String> {
    let (k, spec, cm, _) = load(mesh, params_path)?;
    let Some((f, c)) = spec.iso.clone() else {
        return Err(format!("{}: no [iso] table", params_path.display()));
    };
    Ok((k, spec, cm, f, c))
}

/// Runs `ppm sd …`.
pub(super) fn run(a: SdArgs) -> ExitCode {
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
        SdCommand::Normals {
            mesh,
            params: p,
            json,
        } => {
            let (k, _, cm, f, c) = match load_iso(&mesh, &p) {
                Ok(x) => x,
                Err(e) => return fail(e),
            };
            let (r, points) = normals::check_l203(&k, &cm, &f, &c);
            if json {
                let v = serde_json::json!({"report": [r], "points": points});
                println!("{}", serde_json::to_string_pretty(&v).unwrap_or_default());
                return if r.failed() {
                    ExitCode::from(1)
                } else {
                    ExitCode::SUCCESS
                };
            }
            for p in &points {
                println!(
                    "edge {:?} at u = {:.6}: O kink angle {:.6} rad, 𝒪 angle {:.3e} rad, 𝒪 C¹: {}, DX jumps: {}",
                    p.edge,
                    p.u_f64,
                    p.linear_angle,
                    p.curved_angle,
                    p.curved_smooth,
                    p.dx_jumps
                );
            }
            emit(&[r], false)
        }
        SdCommand::C1 {
            mesh,
            params: p,
            crossed_only,
            budget,
            output,
            json,
        } => {
            let (k, spec, _, f, c) = match load_iso(&mesh, &p) {
                Ok(x) => x,
                Err(e) => return fail(e),
            };
            if spec.family == crate::sdiff::common::params::FamilySpec::Monotonic {
                return fail(format!("{}: (12) is for the rational family (Eq. (11)); give degree and control points", p.display()));
            }
            let scope = if crossed_only {
                c1::Scope::CrossedEdges
            } else {
                c1::Scope::AllInteriorEdges
            };
            match c1::run(&k, &spec, &f, &c, scope, budget) {
                Ok(run) => {
                    if let (Some(out), Some(sol)) = (output, &run.solution) {
                        if let Err(e) = std::fs::write(&out, sol.to_toml()) {
                            return fail(format!("{}: {e}", out.display()));
                        }
                    }
                    emit(&run.report, json)
                }
                Err(e) => fail(e.to_string()),
            }
        }
        SdCommand::Handle {
            mesh,
            params: p,
            edge,
            steps,
            json,
        } => {
            let (k, _, _, f, c) = match load_iso(&mesh, &p) {
                Ok(x) => x,
                Err(e) => return fail(e),
            };
            if edge.len() != 2 || !(2..=4096).contains(&steps) {
                return fail("--edge needs two vertex ids and --steps 2..=4096".into());
            }
            match handles::sweep(&k, &f, &c, (edge[0], edge[1]), steps, Budget::default()) {
                Ok(s) => {
                    let r = handles::judge(&s);
                    if json {
                        let v = serde_json::json!({"report": r, "sweep": s});
                        println!("{}", serde_json::to_string_pretty(&v).unwrap_or_default());
                        return if r.iter().any(|x| x.failed()) {
                            ExitCode::from(1)
                        } else {
                            ExitCode::SUCCESS
                        };
                    }
                    emit(&r, false)
                }
                Err(e) => fail(e.to_string()),
            }
        }
        SdCommand::Polygonize {
            curve,
            grid,
            steps,
            output,
            linear,
            mesh,
            json,
        } => {
            let g = match curve.as_str() {
                "taubin" => implicit::Implicit::taubin(),
                "circle" => implicit::Implicit::circle(),
                other => return fail(format!("--curve {other}: taubin or circle")),
            };
            if grid == 0 || grid > 256 || steps > 100_000 {
                return fail("--grid 1..=256 and --steps ≤ 100000".into());
            }
            let opts = polygonize::Options {
                grid,
                max_steps: steps,
                ..Default::default()
            };
            match polygonize::polygonize(&g, &opts) {
                Ok(out) => {
                    let mesh_off = match polygonize::to_off(&out.mesh) {
                        Ok(b) => b,
                        Err(e) => return fail(format!("the triangulation: {e}")),
                    };
                    let files = [
                        (Some(output), out.iso.curved.to_obj().into_bytes()),
                        (linear, out.iso.linear.to_obj().into_bytes()),
                        (mesh, mesh_off),
                    ];
                    for (path, text) in files {
                        if let Some(path) = path {
                            if let Err(e) = std::fs::write(&path, text) {
                                return fail(format!("{}: {e}", path.display()));
                            }
                        }
                    }
                    emit(&out.report, json)
                }
                Err(e) => fail(e.to_string()),
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
            let s = crate::sdiff::tet::poly::search_monotonic(samples.min(60), seed, b);
            out.push(claims::universal(
                "SD-L115(3-D)",
                "Sec. 3.1: monotonic ⇒ injective, on the tetrahedron (chart w_1..w_3)",
                &s,
                samples.min(60),
                seed,
            ));
            emit(&out, json)
        }
        SdCommand::D3(c) => super::sd3::run(c),
    }
}
