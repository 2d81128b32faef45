//! The `ppm` command line: `ppm check FILE` validates a mesh as a simplicial surface
//! (Sec. 3.1) and prints every check with its offending elements.

mod check;

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
    },
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
        #[arg(long)]
        quiet: bool,
    },
    /// Evaluate one point of M: eval(σ, λ, μ, ν) of Sec. 6.1.4.
    Eval {
        file: PathBuf,
        face: u32,
        lambda: f64,
        mu: f64,
        nu: f64,
        #[arg(long, default_value = "paper")]
        profile: String,
    },
}

/// Entry point of the `ppm` binary.
pub fn main() -> ExitCode {
    let cli = Cli::parse();
    match cli.command {
        Command::Check {
            file,
            json,
            triangulate,
            labels,
        } => check::run(&file, json, triangulate, labels),
        Command::Sample {
            file,
            level,
            output,
            profile,
            quiet,
        } => crate::surface::cli::run_sample(&file, level, &output, &profile, quiet),
        Command::Eval {
            file,
            face,
            lambda,
            mu,
            nu,
            profile,
        } => crate::surface::cli::run_eval(&file, face, [lambda, mu, nu], &profile),
    }
}
