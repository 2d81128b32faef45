//! `ppm fit MESH --epsilon E [--relative] -o FIT`: adaptive manifold fitting (seed 002,
//! "Adaptive Manifold Fitting", Parts I–II; SPEC rows `AF-…`).

use super::load::surface as load;
use crate::fitting::{fit_surface, FitOptions};
use crate::report::{render_text, CheckResult};
use crate::surface::sigma_v::checks::sv_erratum;
use clap::Args;
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

/// Arguments of `ppm fit`.
#[derive(Args, Debug)]
pub(super) struct FitArgs {
    /// The dense mesh S_T (OFF, OBJ, PLY; a closed simplicial surface).
    pub file: PathBuf,
    /// ε: the largest distance allowed between a vertex of S_T and the fitted surface at its
    /// parameter.
    #[arg(long)]
    pub epsilon: f64,
    /// ε is relative to the diagonal of S_T's bounding box.
    #[arg(long)]
    pub relative: bool,
    /// Write the fitted surface here (docs/fit-format.md); `ppm sample`, `ppm eval` and
    /// `ppm check --spec` accept the file in place of a mesh.
    #[arg(short, long)]
    pub output: Option<PathBuf>,
    /// κ of the (σ, v) construction (SPEC SV-D3).
    #[arg(long, default_value_t = crate::surface::sigma_v::DEFAULT_KAPPA)]
    pub kappa: f64,
    /// Degree of the triangular patches ψ_(σ,v), 1..=15.
    #[arg(long, default_value_t = crate::surface::sigma_v::DEFAULT_PATCH_DEGREE,
          value_parser = super::patch_degree_parser)]
    pub patch_degree: usize,
    /// How far (in ε) the simplification may leave S_T from the flat base triangles.
    #[arg(long, default_value_t = 4.0)]
    pub deviation_ratio: f64,
    /// Refinement rounds at most.
    #[arg(long, default_value_t = 40)]
    pub max_rounds: usize,
    /// S is sampled at this level and the sample validated (SPEC AF-embedded); base faces
    /// whose sample crosses are refined until it does not (SPEC AF-refine-embedded).
    #[arg(long, default_value_t = crate::fitting::crossing::DEFAULT_EMBED_LEVEL,
          value_parser = clap::value_parser!(u32).range(0..=6))]
    pub embed_level: u32,
    /// Refuse the fit when its memory, estimated from the size of S_T before anything is
    /// allocated (docs/fitting-scale.md), exceeds this many GiB.
    #[arg(long, default_value_t = 8.0)]
    pub max_memory: f64,
    /// Print the summary as JSON.
    #[arg(long)]
    pub json: bool,
    /// Seed of the sampled checks.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// No progress lines on stderr.
    #[arg(long)]
    pub quiet: bool,
}

/// Run `ppm fit`.
pub(super) fn run(a: FitArgs) -> ExitCode {
    let t0 = Instant::now();
    let k = match load(&a.file) {
        Ok(k) => k,
        Err(c) => return c,
    };
    let diag = crate::oracle::tsv_diff::diagonal(&k);
    let eps = if a.relative {
        a.epsilon * diag
    } else {
        a.epsilon
    };
    let mut o = FitOptions::new(eps);
    o.kappa = a.kappa;
    o.degree = a.patch_degree;
    o.deviation_ratio = a.deviation_ratio;
    o.max_rounds = a.max_rounds;
    o.embed_level = Some(a.embed_level);
    if !(a.max_memory > 0.0 && a.max_memory.is_finite()) {
        eprintln!(
            "error: --max-memory must be a positive number of GiB, got {}",
            a.max_memory
        );
        return ExitCode::from(2);
    }
    // A limit past u64's bytes is no limit (the cast saturates).
    o.memory_limit = (a.max_memory * (1u64 << 30) as f64) as u64;
    let quiet = a.quiet;
    let fit = match fit_surface(&k, &o, |line| {
        if !quiet {
            eprintln!("[{:7.1} s] {line}", t0.elapsed().as_secs_f64());
        }
    }) {
        Ok(f) => f,
        Err(e) => {
            eprintln!("error: {}: {e}", a.file.display());
            return ExitCode::from(1);
        }
    };
    if let Some(out) = &a.output {
        if let Err(e) = crate::fitting::format::write_fit(out, &fit) {
            eprintln!("error: {e}");
            return ExitCode::from(2);
        }
    }
    if !quiet {
        eprintln!("[{:7.1} s] checking the fit", t0.elapsed().as_secs_f64());
    }
    let checks = crate::fitting::checks::run_all_checks(&k, &fit, a.seed);
    let unexpected = crate::fitting::checks::unexpected_failures(&checks);
    let last = fit.rounds.last();
    let summary = serde_json::json!({
        "mesh": a.file.display().to_string(),
        "vertices": k.num_vertices(),
        "epsilon": eps,
        "diagonal": diag,
        "charts": fit.surface.fine_of.len(),
        "base_faces": fit.surface.k.num_faces(),
        "max_error": last.map(|r| r.max_error),
        "p99_error": last.map(|r| r.p99_error),
        "rounding_bound": fit.rounding_bound,
        "hierarchy": fit.hierarchy,
        "repairs": fit.repairs,
        "embed_level": fit.embed_level,
        "rounds": fit.rounds,
        "snaps": fit.base.snaps,
        "checks": checks,
        "unexpected_failures": unexpected,
        "seconds": t0.elapsed().as_secs_f64(),
    });
    if a.json {
        println!(
            "{}",
            serde_json::to_string_pretty(&summary).unwrap_or_default()
        );
    } else {
        println!(
            "fit: {} — {} vertices, epsilon {:.3e}{}: {} charts (base vertices), {} rounds, max error {:.3e}, p99 {:.3e} (rounding bound {:.1e})  [{:.2} s]",
            a.file.display(),
            k.num_vertices(),
            eps,
            if a.relative { format!(" ({} of the diagonal {:.4})", a.epsilon, diag) } else { String::new() },
            fit.surface.fine_of.len(),
            fit.rounds.len(),
            last.map_or(f64::NAN, |r| r.max_error),
            last.map_or(f64::NAN, |r| r.p99_error),
            fit.rounding_bound,
            t0.elapsed().as_secs_f64()
        );
    }
    if !a.json {
        print_checks(&checks, &unexpected);
    }
    status(&unexpected)
}

/// The check table, the documented errata met, and the verdict line.
fn print_checks(checks: &[CheckResult], unexpected: &[String]) {
    print!("{}", render_text(checks));
    for r in checks.iter().filter(|r| r.failed()) {
        if let Some(why) = sv_erratum(&r.id) {
            println!("documented erratum {}: {why}", r.id);
        }
    }
    if unexpected.is_empty() {
        println!("verdict: no failure beyond the documented errata");
    } else {
        println!("verdict: unexpected failures: {}", unexpected.join(", "));
    }
}

/// Exit 1 on a failure that is not a documented erratum.
fn status(unexpected: &[String]) -> ExitCode {
    if unexpected.is_empty() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    }
}

/// Read a fitted-surface file, printing the typed error (file and line) on failure.
fn read(file: &std::path::Path) -> Result<crate::fitting::format::FitFile, ExitCode> {
    crate::fitting::format::read_fit(file).map_err(|e| {
        eprintln!("error: {e}");
        ExitCode::from(2)
    })
}

/// `ppm sample FIT --level N -o OUT`: the fitted surface sampled through eval.
pub(super) fn sample_fit(
    file: &std::path::Path,
    level: u32,
    out: &std::path::Path,
    quiet: bool,
) -> ExitCode {
    let t0 = Instant::now();
    let f = match read(file) {
        Ok(f) => f,
        Err(c) => return c,
    };
    if !quiet {
        eprintln!(
            "ppm sample: fitted (σ, v) PPS, {} charts, {} p-domains, epsilon {:.3e}",
            f.k.num_vertices(),
            f.pps.gluing.len(),
            f.epsilon
        );
    }
    match f.pps.sample_surface(level) {
        Ok(m) => super::sample::write_sampled("ppm sample", out, &m, quiet, t0),
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(1)
        }
    }
}

/// `ppm check --spec FIT`: the (σ, v) checks (Def. 3.4.1, condition (C), smoothness, eval) on
/// the fitted PPS read back, and S embedded at the default sample level (SPEC `AF-embedded`);
/// the ε statement needs S_T and is checked by `ppm fit`.
pub(super) fn check_fit_file(file: &std::path::Path, json: bool, seed: u64) -> ExitCode {
    let f = match read(file) {
        Ok(f) => f,
        Err(c) => return c,
    };
    let mut checks = crate::fitting::checks::fitted_pps_checks(&f.k, &f.pps, seed);
    checks.push(
        crate::fitting::crossing::check_embedded(
            &f.pps,
            crate::fitting::crossing::DEFAULT_EMBED_LEVEL,
        )
        .result,
    );
    let unexpected = crate::fitting::checks::unexpected_failures(&checks);
    if json {
        let out = serde_json::json!({"fit": file.display().to_string(), "checks": checks, "unexpected_failures": unexpected});
        println!("{}", serde_json::to_string_pretty(&out).unwrap_or_default());
    } else {
        println!(
            "fit: {} — {} charts, epsilon {:.3e}",
            file.display(),
            f.k.num_vertices(),
            f.epsilon
        );
        print_checks(&checks, &unexpected);
    }
    status(&unexpected)
}
