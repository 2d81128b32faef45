//! The `ppm` command line: `ppm check FILE` validates a mesh as a simplicial surface
//! (Sec. 3.1) and prints every check with its offending elements.

mod certify;
pub mod check;
mod choose;
mod eval;
mod fit;
mod load;
mod msplines;
mod oracle;
mod progress;
pub(crate) mod render;
mod results;
mod sample;
mod sd;
mod sd3;
mod sigma_v;
mod tsv_diff;

use crate::surface::Construction;
use clap::{Parser, Subcommand};
use std::path::PathBuf;
use std::process::ExitCode;

#[derive(Parser, Debug)]
#[command(
    name = "ppm",
    version,
    about = "Parametric pseudo-manifold reference implementation"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Check that a mesh (OFF, OBJ, PLY) is a simplicial surface (Defs. 3.1.1–3.1.6) and
    /// print each check; exit status 0 only when it is.
    Check {
        /// The mesh file.
        file: PathBuf,
        /// Print the report as JSON instead of text.
        #[arg(long)]
        json: bool,
        /// Fan-split convex polygons with more than three sides (the report says how many).
        #[arg(long)]
        triangulate: bool,
        /// Also print the s_v labelling check (Def. 4.1.4) for a valid surface.
        #[arg(long)]
        labels: bool,
        /// Also run the Chapter 4 conformance checks (every statement of SPEC.md that is
        /// checked on data) on the valid surface.
        #[arg(long)]
        spec: bool,
        #[command(flatten)]
        ch4: check::Ch4Args,
    },
    /// Check a user-written 1-D set of gluing data (TOML, see examples/gluing/README.md)
    /// against every condition of Def. 3.4.1, decided exactly; prints the verdict table.
    Gluing {
        /// The gluing data file.
        file: PathBuf,
        #[arg(long)]
        json: bool,
    },
    /// Answer reference queries on stdin, one JSON request per line (docs/oracle.md).
    Oracle {
        /// Load this mesh first (or send {"op":"load","path":...}).
        #[arg(long)]
        mesh: Option<PathBuf>,
        /// MPFR precision of the reference values (2..=65536).
        #[arg(long, default_value_t = 256, value_parser = prec_bits_parser())]
        bits: u32,
        /// Chapter 5 profile (paper | authors-code); also {"op":"set_profile",...}.
        #[arg(long, default_value = "paper")]
        profile: String,
        /// S′ (Sec. 6.2): pn | loop; also {"op":"set_surface",...}.
        #[arg(long, default_value = "pn")]
        sprime: String,
        /// A certificate (`ppm certify`, JSON or `*.json.gz`): `phi` answers carry its proven
        /// f64 error bound (SPEC CERT-f64-rounding), `g` and `g_inv` answers on the chart square
        /// |x|, |y| ≤ 1 theirs (SPEC CERT-f64-g-chart); also {"op":"set_certificate","path":...}.
        #[arg(long)]
        certificate: Option<PathBuf>,
    },
    /// Compare another implementation's answers against the reference: a table of queries
    /// (JSON lines: a request plus "value") or, with --surface, a sampled surface (OFF, PLY,
    /// OBJ; Sec. 6.2); exit status 1 when a deviation exceeds --tolerance (docs/oracle.md).
    Diff {
        /// The mesh the answers refer to.
        #[arg(long)]
        mesh: PathBuf,
        /// The table of answers: JSON lines, or a TSV table of points (header `face lambda
        /// mu nu` plus `pps_x pps_y pps_z` and/or `sprime_x sprime_y sprime_z`; deviations
        /// relative to the bounding-box diagonal, default tolerance 1e-9).
        #[arg(required_unless_present = "surface", conflicts_with = "surface")]
        table: Option<PathBuf>,
        /// The other implementation's sampled surface (OFF, PLY or OBJ), vertices in eval
        /// order if known.
        #[arg(long)]
        surface: Option<PathBuf>,
        /// Subdivision level of the sampled surface (default: inferred from its vertex count).
        #[arg(long)]
        level: Option<u32>,
        /// order (vertex i ↔ reference vertex i, when the counts agree) | nearest (R*-tree);
        /// default order.
        #[arg(long = "match")]
        matching: Option<String>,
        /// Chapter 5 profile of the reference surface: paper | authors-code.
        #[arg(long, default_value = "paper")]
        profile: String,
        /// S′ of the reference surface (Sec. 6.2): pn | loop (`--surface` names the file);
        /// default pn. Not for a TSV table (its S′ is the profile's PN triangles).
        #[arg(long)]
        sprime: Option<String>,
        /// Reference construction of a JSON-lines table's `eval` lines, or of --surface: vertex
        /// (the report's, Ch. 4–5) | sigma-v (the tutorial's (σ, v)-indexed PPS, SPEC SV-D13;
        /// a table's other ops keep the vertex construction; with --surface it has no f64 error
        /// analysis, so give --tolerance). Not for a TSV table.
        #[arg(long, value_enum, default_value_t = Construction::Vertex)]
        construction: Construction,
        /// sigma-v: κ of the overlapping point r_{v,σ} (SPEC SV-D3), in (0, 1); default 1/4.
        #[arg(long)]
        kappa: Option<f64>,
        /// Largest accepted deviation (table default 1e-12; surface default: at each vertex
        /// twice its f64 bound).
        #[arg(long)]
        tolerance: Option<f64>,
        /// MPFR precision of the reference / spot checks (2..=65536, default 256). Not for a
        /// TSV table (compared in f64).
        #[arg(long, value_parser = prec_bits_parser())]
        bits: Option<u32>,
        /// How many of the worst items to list.
        #[arg(long, default_value_t = 10)]
        worst: usize,
        /// Print the report as JSON.
        #[arg(long)]
        json: bool,
    },
    /// Draw Ω_u, P_u, T_u, the gluing domains of all neighbours and the image of a grid under
    /// φ_wu for an edge with degrees m_u, m_w (like Figs. 4.1–4.6), as SVG.
    Figure {
        /// `m_u,m_w`, e.g. `5,7`.
        #[arg(long)]
        degrees: String,
        #[arg(short = 'o', long)]
        output: PathBuf,
    },
    /// Evaluate the transition map φ_wu(p) (Def. 4.1.10: from Ω_uw to Ω_wu) of a mesh in f64
    /// and in multi-precision, and print both with their difference (oracle use).
    EvalMap {
        /// The mesh file.
        file: PathBuf,
        /// u (the map goes from Ω_uw ⊂ Ω_u …).
        u: u32,
        /// w (… to Ω_wu ⊂ Ω_w).
        w: u32,
        /// x coordinate of p in Ω_u.
        x: f64,
        /// y coordinate of p in Ω_u.
        y: f64,
        /// MPFR precision in bits (2..=65536).
        #[arg(long, default_value_t = 256, value_parser = prec_bits_parser())]
        bits: u32,
        #[arg(long)]
        json: bool,
    },
    /// Certified interval proofs of the Chapter 4 conditions for all degree configurations
    Certify(certify::CertifyArgs),
    /// Sample the C^∞ surface M by midpoint subdivision through eval (Sec. 6.2) and write it
    /// with per-vertex normals and curvatures (.obj, .off, .ply; PLY also with colours).
    Sample {
        file: PathBuf,
        #[arg(long, default_value_t = 1)]
        level: u32,
        #[arg(short = 'o', long)]
        output: PathBuf,
        /// paper | authors-code
        #[arg(long, default_value = "paper")]
        profile: String,
        /// S′ (Sec. 6.2): pn | loop
        #[arg(long, default_value = "pn")]
        surface: String,
        /// What to compute per vertex: positions | normals | curvature (each costs more:
        /// plain eval, order-1 jets, order-2 jets).
        #[arg(long, default_value = "curvature")]
        attributes: String,
        #[arg(long)]
        quiet: bool,
        /// vertex (the report's) | sigma-v (the tutorial's (σ, v)-indexed PPS).
        #[arg(long, value_enum, default_value_t = Construction::Vertex)]
        construction: Construction,
        /// sigma-v: κ of r_{v,σ} (SPEC SV-D3).
        #[arg(long, default_value_t = crate::surface::sigma_v::DEFAULT_KAPPA)]
        kappa: f64,
        /// sigma-v: degree of the triangular patches (SPEC SV-D11), 1..=15.
        #[arg(long, default_value_t = crate::surface::sigma_v::DEFAULT_PATCH_DEGREE,
              value_parser = patch_degree_parser)]
        patch_degree: usize,
    },
    /// Draw K, S′ or the PPS coloured by curvature to a PNG (software rendering; Figs. 6.4–6.7
    /// with --panels).
    Render(render::RenderArgs),
    /// Adaptive manifold fitting (seed 002, Parts I–II): a C-infinity (sigma, v) PPS within
    /// epsilon of every vertex of a dense mesh, with few charts (SPEC rows AF-…).
    Fit(fit::FitArgs),
    /// Simplicial diffeomorphisms of a planar complex (Mello–Velho): check a map, write curved
    /// isocurves, search the injectivity claims (SPEC rows SD-…).
    Sd(sd::SdArgs),
    /// Manifold splines (Gu–He–Qin): holomorphic 1-form, zero points, affine atlas (SPEC MS-*).
    #[command(subcommand)]
    Msplines(msplines::MsCommand),
    /// Evaluate one point of M: eval(σ, λ, μ, ν) of Sec. 6.1.4, with the chart eval chose and
    /// (from the jets) its normal and curvatures. FILE is a mesh or a fitted-surface file
    /// (`ppm fit -o`).
    Eval {
        file: PathBuf,
        face: u32,
        lambda: f64,
        mu: f64,
        nu: f64,
        #[arg(long, default_value = "paper")]
        profile: String,
        /// S′ (Sec. 6.2): pn | loop
        #[arg(long, default_value = "pn")]
        surface: String,
        /// vertex (the report's, default) | sigma-v (the tutorial's (σ, v)-indexed PPS) |
        /// manifold-spline (Gu–He–Qin Secs. 5.5–5.6 with `ppm msplines sample`'s defaults;
        /// positions only). Not for a fitted-surface file.
        #[arg(long, value_enum)]
        construction: Option<Construction>,
        /// sigma-v: κ of r_{v,σ} (SPEC SV-D3).
        #[arg(long, default_value_t = crate::surface::sigma_v::DEFAULT_KAPPA)]
        kappa: f64,
        /// sigma-v: degree of the triangular patches (SPEC SV-D11), 1..=15.
        #[arg(long, default_value_t = crate::surface::sigma_v::DEFAULT_PATCH_DEGREE,
              value_parser = patch_degree_parser)]
        patch_degree: usize,
        /// positions | normals | curvature (default: curvature for a mesh, positions for a
        /// fitted-surface file).
        #[arg(long)]
        attributes: Option<String>,
    },
}

/// Parser of a `--bits` argument: refuses precisions outside the one limit
/// [`crate::numeric::PREC_BITS`] (shared with `check`, the oracle and the scalar types).
fn prec_bits_parser() -> clap::builder::RangedI64ValueParser<u32> {
    let r = &crate::numeric::PREC_BITS;
    clap::value_parser!(u32).range(i64::from(*r.start())..=i64::from(*r.end()))
}

/// Parser of `--patch-degree`: refuses degrees the (σ,v) patches do not support instead of
/// letting the library round them into 1..=`MAX_PATCH_DEGREE` (SPEC SV-D11).
fn patch_degree_parser(s: &str) -> Result<usize, String> {
    let max = crate::surface::sigma_v::patch::MAX_PATCH_DEGREE;
    let d: usize = s.parse().map_err(|e| format!("{s:?}: {e}"))?;
    if (1..=max).contains(&d) {
        Ok(d)
    } else {
        Err(format!(
            "patch degree {d} out of range 1..={max} (SPEC SV-D11)"
        ))
    }
}

/// The options of `ppm check --spec FLAGS...` parsed from `flags` exactly as `ppm` parses
/// them (same defaults, same validation): the library callers of [`check::check_report`] (the
/// Python layer's `check()`) get the command's behaviour without restating its defaults.
/// `flags` are the options only, e.g. `["--seed", "7", "--precision", "mp:128"]`.
pub fn parse_check_spec_args<I, S>(flags: I) -> Result<check::Ch4Args, String>
where
    I: IntoIterator<Item = S>,
    S: Into<std::ffi::OsString> + Clone,
{
    let argv = ["ppm", "check", "--spec", "-"]
        .into_iter()
        .map(std::ffi::OsString::from)
        .chain(flags.into_iter().map(Into::into));
    match Cli::try_parse_from(argv) {
        Ok(Cli {
            command: Command::Check { ch4, .. },
        }) => Ok(ch4),
        Ok(_) => Err("not a check command".into()),
        Err(e) => Err(e.to_string()),
    }
}

/// Entry point of the `ppm` binary.
pub fn main() -> ExitCode {
    main_from(std::env::args_os())
}

/// [`main`] on the given command line (`args[0]` is the program name): the same commands from
/// another host, e.g. the `ppm` console script of the Python package (docs/python.md). Like the
/// binary, a usage error or `--help` prints and exits the process (clap).
pub fn main_from<I, T>(args: I) -> ExitCode
where
    I: IntoIterator<Item = T>,
    T: Into<std::ffi::OsString> + Clone,
{
    let cli = Cli::parse_from(args);
    match cli.command {
        Command::Check {
            file,
            json,
            triangulate,
            labels,
            spec,
            ch4,
        } => match ch4.construction {
            _ if spec && crate::fitting::format::is_fit_file(&file) => {
                fit::check_fit_file(&file, json, ch4.seed)
            }
            Construction::Vertex => {
                check::run(&file, json, triangulate, labels, spec.then_some(&ch4))
            }
            Construction::SigmaV if spec => sigma_v::run_check(
                &file,
                json,
                &crate::surface::sigma_v::checks::SvCheckOptions {
                    seed: ch4.seed,
                    samples: ch4.samples,
                    max_views: ch4.max_configs.unwrap_or(2),
                    kappa: ch4.kappa,
                    patch_degree: ch4.patch_degree,
                    ..Default::default()
                },
            ),
            Construction::SigmaV => {
                eprintln!("error: --construction sigma-v: runs with --spec only");
                ExitCode::from(2)
            }
            Construction::ManifoldSpline => {
                eprintln!("error: --construction manifold-spline: its checks are `ppm msplines check` (SPEC MS-*)");
                ExitCode::from(2)
            }
        },
        Command::Oracle {
            mesh,
            bits,
            profile,
            sprime,
            certificate,
        } => oracle::run_oracle(
            mesh.as_deref(),
            bits,
            &profile,
            &sprime,
            certificate.as_deref(),
        ),
        Command::Diff {
            mesh,
            table,
            surface,
            level,
            matching,
            profile,
            sprime,
            construction,
            kappa,
            tolerance,
            bits,
            worst,
            json,
        } => match (table, surface) {
            // Options of the other mode are refused, not ignored.
            (Some(_), None) if level.is_some() || matching.is_some() => {
                eprintln!("error: --level and --match apply to --surface only, not to a table");
                ExitCode::from(2)
            }
            (t, None)
                if (construction != Construction::Vertex || kappa.is_some())
                    && t.as_deref().is_some_and(tsv_diff::is_tsv) =>
            {
                eprintln!("error: --construction and --kappa apply to a JSON-lines table (its eval lines) or --surface, not to a TSV table");
                ExitCode::from(2)
            }
            (_, Some(surface)) => oracle::run_diff_surface(
                &mesh,
                &surface,
                &oracle::SurfaceArgs {
                    level,
                    matching: matching.unwrap_or_else(|| "order".into()),
                    profile,
                    tolerance,
                    bits: bits.unwrap_or(crate::numeric::DEFAULT_MP_PREC),
                    worst,
                    json,
                    sprime: sprime.unwrap_or_else(|| "pn".into()),
                    construction,
                    kappa,
                },
            ),
            (Some(table), None) if tsv_diff::is_tsv(&table) => {
                if bits.is_some() {
                    eprintln!("error: --bits does not apply to a TSV table of points (compared in f64 against the profile's S′ and PPS)");
                    return ExitCode::from(2);
                }
                tsv_diff::run(
                    &mesh,
                    &table,
                    &profile,
                    &sprime.unwrap_or_else(|| "pn".into()),
                    tolerance.unwrap_or(1e-9),
                    worst,
                    json,
                )
            }
            (Some(table), None) => oracle::run_diff(
                &mesh,
                &table,
                &oracle::TableArgs {
                    bits: bits.unwrap_or(crate::numeric::DEFAULT_MP_PREC),
                    tolerance: tolerance.unwrap_or(1e-12),
                    worst,
                    json,
                    profile,
                    sprime: sprime.unwrap_or_else(|| "pn".into()),
                    construction,
                    kappa,
                },
            ),
            (None, None) => {
                eprintln!("error: give a TABLE of answers or --surface FILE");
                ExitCode::from(2)
            }
        },
        Command::Figure { degrees, output } => {
            let parsed: Vec<Option<u32>> =
                degrees.split(',').map(|x| x.trim().parse().ok()).collect();
            let (mu, mw) = match parsed.as_slice() {
                [Some(a), Some(b)] => (*a, *b),
                _ => {
                    eprintln!("error: --degrees {degrees}: expected m_u,m_w (integers ≥ 3)");
                    return ExitCode::from(2);
                }
            };
            match crate::construction::figure::render_svg(mu, mw) {
                Ok(svg) => match std::fs::write(&output, svg) {
                    Ok(()) => ExitCode::SUCCESS,
                    Err(e) => {
                        eprintln!("error: {}: {e}", output.display());
                        ExitCode::from(2)
                    }
                },
                Err(e) => {
                    eprintln!("error: --degrees {degrees}: {e}");
                    ExitCode::from(2)
                }
            }
        }
        Command::Certify(a) => certify::run(a),
        Command::Render(a) => render::run(a),
        Command::Fit(a) => fit::run(a),
        Command::Sd(a) => sd::run(a),
        Command::Gluing { file, json } => match crate::gluing::report::gluing_report(&file, json) {
            Ok((text, all_hold)) => {
                print!("{text}");
                if all_hold {
                    ExitCode::SUCCESS
                } else {
                    ExitCode::from(1)
                }
            }
            Err(e) => {
                eprintln!("error: {e}");
                ExitCode::from(2)
            }
        },
        Command::EvalMap {
            file,
            u,
            w,
            x,
            y,
            bits,
            json,
        } => check::eval_map(&file, u, w, [x, y], bits, json),
        Command::Sample {
            file,
            level,
            output,
            profile,
            surface,
            attributes,
            quiet,
            construction,
            kappa,
            patch_degree,
        } => {
            if crate::fitting::format::is_fit_file(&file) {
                fit::sample_fit(&file, level, &output, quiet)
            } else {
                sample::run_sample(&sample::SampleArgs {
                    file: &file,
                    level,
                    out: &output,
                    profile: &profile,
                    surface: &surface,
                    attributes: &attributes,
                    quiet,
                    construction,
                    kappa,
                    patch_degree,
                })
            }
        }
        Command::Msplines(c) => msplines::run_command(c),
        Command::Eval {
            file,
            face,
            lambda,
            mu,
            nu,
            profile,
            surface,
            construction,
            kappa,
            patch_degree,
            attributes,
        } => eval::run(&eval::EvalArgs {
            file: &file,
            face,
            bary: [lambda, mu, nu],
            profile: &profile,
            surface: &surface,
            construction,
            kappa,
            patch_degree,
            attributes: attributes.as_deref(),
        }),
    }
}
