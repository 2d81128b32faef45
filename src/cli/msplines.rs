//! `ppm msplines check MESH`: the manifold-spline pipeline of Gu–He–Qin Sec. 5 with every
//! check (SPEC `MS-*`), as text or JSON. Exit status 0 when nothing fails but documented
//! errata whose corrected rows hold, 1 when any other check fails, 2 on unusable input (with
//! the typed reason, e.g. genus 0 per Thm. 2).

use crate::gluing::sampled::SampleConfig;
use crate::msplines::pipeline::{spline, spline_checks};
use crate::msplines::smooth::SplineSurface;
use crate::msplines::{run, Options};
use crate::report::render_text;
use crate::surface::output::Attributes;
use crate::surface::smooth::SmoothSurface;
use clap::{Args, Subcommand};
use std::path::PathBuf;
use std::process::ExitCode;

/// `ppm msplines …`
#[derive(Subcommand, Debug)]
pub(super) enum MsCommand {
    /// Holomorphic 1-form, zero points and affine atlas of a closed mesh (Sec. 5), with the
    /// checks of every statement (SPEC MS-*), including Def. 3.4.1 on the atlas.
    Check(MsCheckArgs),
    /// Sample the manifold spline surface F(M) (Secs. 5.5–5.6, DMS basis of degree 2 on
    /// ring-3 charts) to a mesh file, like `ppm sample`.
    Sample(MsSampleArgs),
}

/// Arguments of `ppm msplines sample`.
#[derive(Args, Debug)]
pub(super) struct MsSampleArgs {
    /// The mesh file (OFF, OBJ, PLY): the domain M.
    pub file: PathBuf,
    /// Output mesh (.obj, .off or .ply).
    #[arg(long, default_value = "msplines.obj")]
    pub out: PathBuf,
    /// Subdivision level: every face of M sampled on the barycentric grid of step 2^-level.
    #[arg(long, default_value_t = 2)]
    pub level: u32,
    /// Which basis form ω_k (Sec. 5.1 step 2).
    #[arg(long, default_value_t = 0)]
    pub form: usize,
    /// Degree k of the DMS spline (Sec. 3.1.2).
    #[arg(long, default_value_t = 2)]
    pub degree: usize,
    /// Seed of the knot clouds (Sec. 5.5).
    #[arg(long, default_value_t = 0x5eed)]
    pub seed: u64,
    /// Suppress the summary line.
    #[arg(long)]
    pub quiet: bool,
}

/// Arguments of `ppm msplines check`.
#[derive(Args, Debug)]
pub(super) struct MsCheckArgs {
    /// The mesh file (OFF, OBJ, PLY).
    pub file: PathBuf,
    /// Print the report as JSON.
    #[arg(long)]
    pub json: bool,
    /// k of the k-ring charts (Sec. 5.4 step 3).
    #[arg(long, default_value_t = 1)]
    pub ring: u32,
    /// Which basis form ω_k = h_k + i∗h_k (Sec. 5.1 step 2).
    #[arg(long, default_value_t = 0)]
    pub form: usize,
    /// Seed of the Def. 3.4.1 sampling.
    #[arg(long, default_value_t = 0x5eed)]
    pub seed: u64,
    /// Samples per domain in the Def. 3.4.1 checks.
    #[arg(long, default_value_t = 24)]
    pub samples: usize,
    /// Chart neighbourhoods visited by the Def. 3.4.1 checks.
    #[arg(long, default_value_t = 64)]
    pub views: usize,
    /// Also build the degree-2 manifold spline on ring-3 charts (Secs. 5.5–5.6) and check
    /// Def. 13 on it at this many seeded faces (0: off).
    #[arg(long, default_value_t = 0)]
    pub spline_faces: usize,
}

/// Run a `ppm msplines` subcommand.
pub(crate) fn run_command(c: MsCommand) -> ExitCode {
    match c {
        MsCommand::Check(a) => check(&a),
        MsCommand::Sample(a) => sample(&a),
    }
}

fn sample(a: &MsSampleArgs) -> ExitCode {
    let t0 = std::time::Instant::now();
    let k = match super::load::surface(&a.file) {
        Ok(k) => k,
        Err(c) => return c,
    };
    let (at, sp) = match spline(&k, a.form, 3, a.degree, a.seed) {
        Ok(x) => x,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(2);
        }
    };
    let f = SplineSurface {
        k: &k,
        atlas: &at,
        spline: &sp,
    };
    match f.sample(a.level, Attributes::Positions, None) {
        Ok(m) => super::sample::write_sampled("ppm msplines sample", &a.out, &m, a.quiet, t0),
        Err(e) => {
            eprintln!("error: {}: {e}", a.file.display());
            ExitCode::from(1)
        }
    }
}

fn check(a: &MsCheckArgs) -> ExitCode {
    let k = match super::load::surface(&a.file) {
        Ok(k) => k,
        Err(c) => return c,
    };
    let opt = Options {
        ring: a.ring,
        form: a.form,
        sample: SampleConfig {
            seed: a.seed,
            n: a.samples,
        },
        views: a.views,
    };
    let (mut rep, _, _) = match run(&k, &opt) {
        Ok(x) => x,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(2);
        }
    };
    if a.spline_faces > 0 {
        match spline(&k, a.form, 3, 2, a.seed) {
            Ok((at, sp)) => rep
                .checks
                .extend(spline_checks(&k, &at, &sp, a.seed, a.spline_faces)),
            Err(e) => {
                eprintln!("error: {e}");
                return ExitCode::from(2);
            }
        }
    }
    if a.json {
        match serde_json::to_string_pretty(&rep) {
            Ok(s) => println!("{s}"),
            Err(e) => {
                eprintln!("error: {e}");
                return ExitCode::from(2);
            }
        }
    } else {
        println!(
            "{}: V = {}, E = {}, F = {}, genus {}",
            rep.file, rep.counts[0], rep.counts[1], rep.counts[2], rep.genus
        );
        println!(
            "intersection matrix of the cocycle basis: {:?}",
            rep.intersection
        );
        println!("zero points (vertex, order): {:?}", rep.zeros);
        println!(
            "atlas: {} charts, {} overlapping pairs (k = {})",
            rep.charts, rep.pairs, a.ring
        );
        println!(
            "time: forms {:.3} s, zeros + atlas {:.3} s, checks {:.3} s",
            rep.seconds[0], rep.seconds[1], rep.seconds[2]
        );
        print!("{}", render_text(&rep.checks));
        let errata: Vec<&str> = crate::msplines::pipeline::ERRATA
            .iter()
            .map(|(w, _)| *w)
            .collect();
        println!(
            "documented errata (fail as written, corrected rows checked): {errata:?}; failing here with the corrected row holding: {:?}",
            rep.errata_failing()
        );
    }
    if rep.failed() {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}
