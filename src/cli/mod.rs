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
    /// Certified interval proofs of the Chapter 4 conditions for all degree configurations
    /// (issue 6).
    Certify(crate::certify::cli::CertifyArgs),
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
        Command::Certify(a) => crate::certify::cli::run(a),
    }
}
