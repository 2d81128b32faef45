//! Adaptive fitting at the tutorial's scale (seed 002 Parts VI–VII; docs/fitting-scale.md):
//! one `ppm fit` of a dense mesh, stage by stage, with the wall time and the peak memory of
//! each stage and the targets as ratios (whole fit ≤ 10 minutes, ≤ 8 GiB, on 2 cores).
//!
//! ```sh
//! cargo bench --bench dense_fit                                   # good/koala.obj (50k vertices)
//! cargo run --release --example dense_input -- ../shared/meshes/good/armadillo.obj armadillo-l3.ply --loop 3
//! cargo bench --bench dense_fit -- armadillo-l3.ply               # 933,442 vertices, ~20 min
//! cargo bench --bench dense_fit -- koala-l2.ply 1e-3             # FILE [EPSILON, of the diagonal]
//! ```
//!
//! The stages are the fit's own progress lines (`fitting::fit_surface`): each line ends the
//! stage it names (`simplify`, `embed`, `fit round`, `refine`, …), so the time since the line
//! before is that stage's; then the checks `ppm fit` runs (`fitting::checks::run_all_checks`).
//! Peak memory per stage is the process's resident high-water mark (Linux `VmHWM`), reset at
//! every line through `/proc/self/clear_refs`; elsewhere it is not measured and says so. One
//! run, not a median: a dense fit takes minutes, so its scatter is small beside the targets.
//! The whole process is what `/usr/bin/time -v ppm fit …` measures in the doc's tables.

use pseudomanifold::fitting::checks::{run_all_checks, unexpected_failures};
use pseudomanifold::fitting::{fit_surface, FitOptions, DEFAULT_MEMORY_LIMIT};
use pseudomanifold::mesh::load_surface;
use pseudomanifold::oracle::tsv_diff::diagonal;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

/// The time target of the whole fit on a 2-core machine; the memory target is the fit's own
/// default limit (`FitOptions::memory_limit`, 8 GiB).
const TARGET_SECONDS: f64 = 600.0;

/// One stage's totals (a stage named by several lines adds them up).
struct Stage {
    name: String,
    lines: usize,
    seconds: f64,
    peak: Option<u64>,
}

/// The resident high-water mark since the last reset, in bytes (Linux only).
fn high_water() -> Option<u64> {
    let s = std::fs::read_to_string("/proc/self/status").ok()?;
    let kb = s.lines().find_map(|l| l.strip_prefix("VmHWM:"))?;
    kb.trim()
        .trim_end_matches("kB")
        .trim()
        .parse::<u64>()
        .ok()
        .map(|k| k * 1024)
}

/// Starts a new high-water interval: "5" resets VmHWM to the current RSS (Linux ≥ 4.0).
fn reset_high_water() -> bool {
    std::fs::write("/proc/self/clear_refs", "5").is_ok()
}

/// The stage a progress line ends: its words before the first ':' or '(' (without the round
/// number of "fit round N"); an embedding is a local update (`AF-refine-local`) or one of all of
/// S_T.
fn stage_of(line: &str) -> String {
    if line.starts_with("embed: local update") || line.starts_with("embed: the local update") {
        return "embed (local update)".to_string();
    }
    let head = line.split([':', '(']).next().unwrap_or(line).trim();
    match head.strip_prefix("fit round") {
        Some(_) => "fit round".to_string(),
        None => head.to_string(),
    }
}

struct Recorder {
    stages: Vec<Stage>,
    last: Instant,
    resets: bool,
}

impl Recorder {
    fn new() -> Self {
        Recorder {
            stages: Vec::new(),
            last: Instant::now(),
            resets: reset_high_water(),
        }
    }

    /// Ends the current interval as part of stage `name`.
    fn end(&mut self, name: String) {
        let seconds = self.last.elapsed().as_secs_f64();
        let peak = if self.resets { high_water() } else { None };
        match self.stages.iter_mut().find(|s| s.name == name) {
            Some(s) => {
                s.lines += 1;
                s.seconds += seconds;
                s.peak = s.peak.max(peak);
            }
            None => self.stages.push(Stage {
                name,
                lines: 1,
                seconds,
                peak,
            }),
        }
        self.resets = reset_high_water();
        self.last = Instant::now();
    }
}

fn mb(b: Option<u64>) -> String {
    b.map_or("not measured".to_string(), |b| {
        format!("{:.0}", b as f64 / 1e6)
    })
}

fn default_input() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../shared/meshes/good/koala.obj")
}

fn main() -> ExitCode {
    // `cargo bench` passes `--bench`; the other arguments are the input and ε.
    let args: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| !a.starts_with("--"))
        .collect();
    let input = args
        .first()
        .map(PathBuf::from)
        .unwrap_or_else(default_input);
    let rel: f64 = match args.get(1).map(|e| e.parse::<f64>()) {
        None => 1e-3,
        Some(Ok(e)) if e > 0.0 && e.is_finite() => e,
        Some(_) => {
            eprintln!("dense_fit: EPSILON must be a positive number (of the diagonal)");
            return ExitCode::from(2);
        }
    };
    if !input.exists() {
        println!(
            "dense_fit: {} not found, nothing measured (the corpus ../shared/meshes is not beside this clone)",
            input.display()
        );
        return ExitCode::SUCCESS;
    }
    let t0 = Instant::now();
    let mut rec = Recorder::new();
    let k = match load_surface(&input) {
        Ok(k) => k,
        Err(e) => {
            eprintln!("dense_fit: {}: {e}", input.display());
            return ExitCode::from(2);
        }
    };
    rec.end("read and validate (Sec. 3.1)".into());
    let diag = diagonal(&k);
    let o = FitOptions::new(rel * diag);
    let fit = match fit_surface(&k, &o, |line| {
        eprintln!("[{:7.1} s] {line}", t0.elapsed().as_secs_f64());
        rec.end(stage_of(line));
    }) {
        Ok(f) => f,
        Err(e) => {
            eprintln!("dense_fit: {}: {e}", input.display());
            return ExitCode::from(1);
        }
    };
    rec.end("rest of the fit".into());
    let checks = run_all_checks(&k, &fit, 1);
    rec.end("checks (AF-…, SV-…)".into());
    let wall = t0.elapsed().as_secs_f64();
    let failed = checks.iter().filter(|r| r.failed()).count();
    let unexpected = unexpected_failures(&checks);
    let peak = rec.stages.iter().filter_map(|s| s.peak).max();
    let last = fit.rounds.last();
    let threads = rayon::current_num_threads();

    println!(
        "dense_fit: {} ({} vertices), ε = {rel:e} of the diagonal {diag:.4}, {threads} threads",
        input.display(),
        k.num_vertices()
    );
    println!();
    println!("| stage | lines | wall (s) | share | peak RSS (MB) |");
    println!("|---|---:|---:|---:|---:|");
    for s in &rec.stages {
        println!(
            "| {} | {} | {:.1} | {:.0} % | {} |",
            s.name,
            s.lines,
            s.seconds,
            100.0 * s.seconds / wall,
            mb(s.peak)
        );
    }
    println!("| **all** | | **{wall:.1}** | 100 % | **{}** |", mb(peak));
    println!();
    println!(
        "{} charts, {} rounds, max error {:.3} ε, p99 {:.3} ε; {} checks, {} failed ({} documented errata), unexpected: {:?}",
        fit.surface.fine_of.len(),
        fit.rounds.len(),
        last.map_or(f64::NAN, |r| r.max_error / o.epsilon),
        last.map_or(f64::NAN, |r| r.p99_error / o.epsilon),
        checks.len(),
        failed,
        failed - unexpected.len(),
        unexpected
    );
    println!(
        "targets: wall {wall:.0} s / {TARGET_SECONDS:.0} s = {:.2}×; peak {} / 8 GiB = {}",
        wall / TARGET_SECONDS,
        mb(peak),
        peak.map_or("not measured".to_string(), |p| format!(
            "{:.2}×",
            p as f64 / DEFAULT_MEMORY_LIMIT as f64
        ))
    );
    if unexpected.is_empty() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    }
}
