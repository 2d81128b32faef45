//! `ppm check`: read, validate, report.

use crate::conditions::chapter4::{render as render_ch4, Ch4Options, Precision};
pub use crate::conditions::spec::CheckReport;
use crate::conditions::spec::{SpecOptions, SpecProgress};
use crate::construction::{phi_wu_f64_vs_mp, PpmGluing};
use crate::mesh::io::{read_mesh, ReadOptions};
use crate::mesh::validate::ValidationReport;
use crate::mesh::{RawMesh, VertexId};
use crate::report::{render_text, CheckResult};
use std::path::Path;
use std::process::ExitCode;
use std::time::Instant;

/// Inputs at least this large get progress lines on stderr.
const PROGRESS_FACES: usize = 50_000;

/// Options of the Chapter 4 run of `ppm check --spec`.
#[derive(clap::Args, Debug, Clone)]
pub struct Ch4Args {
    /// Seed of every sampler.
    #[arg(long, default_value_t = 20240601)]
    pub seed: u64,
    /// Samples per category per configuration.
    #[arg(long, default_value_t = 24)]
    pub samples: usize,
    /// `f64` or `mp:BITS` (multi-precision, see `--mp-backend`), e.g. `mp:256`.
    #[arg(long, default_value = "f64")]
    pub precision: String,
    /// Implementation of `mp:BITS`: `astro` (pure Rust, always built) or `mpfr` (feature `mpfr`).
    #[arg(long, default_value = "astro")]
    pub mp_backend: String,
    /// Check at most this many distinct configurations of each kind (seeded subset).
    #[arg(long, requires = "spec")]
    pub max_configs: Option<usize>,
    /// Certificate file of `ppm certify` (JSON, or gzip-compressed JSON `*.json.gz`, recognised
    /// by its magic bytes): each Chapter 4 property is marked certified when the certificate
    /// covers every configuration of the mesh (missing ones are listed).
    #[arg(long, requires = "spec")]
    pub certificates: Option<std::path::PathBuf>,
    /// Run only the Chapter 3.4–4 checks (skip building the surface of Chapter 5).
    #[arg(long, requires = "spec")]
    pub no_surface: bool,
    /// S′ of Chapter 5 (Sec. 6.2): pn | loop (loop also runs the Loop S′ checks).
    #[arg(long, default_value = "pn")]
    pub surface: String,
    /// vertex (the report's, Ch. 4–5) | sigma-v (the tutorial's (σ, v)-indexed PPS, SPEC SV-…).
    #[arg(long, value_enum, default_value_t = crate::surface::Construction::Vertex)]
    pub construction: crate::surface::Construction,
    /// sigma-v: κ of the overlapping point r_{v,σ} = −κ·cos(π/m_v)·b (SPEC SV-D3), in (0, 1).
    #[arg(long, default_value_t = crate::surface::sigma_v::DEFAULT_KAPPA)]
    pub kappa: f64,
    /// sigma-v: degree of the triangular Bézier patches ψ_(σ,v) (SPEC SV-D11), 1..=15.
    #[arg(long, default_value_t = crate::surface::sigma_v::DEFAULT_PATCH_DEGREE,
          value_parser = super::patch_degree_parser)]
    pub patch_degree: usize,
}

impl Ch4Args {
    fn options(&self) -> Result<Ch4Options, String> {
        let precision = match self.precision.as_str() {
            "f64" => Precision::F64,
            other => match other.strip_prefix("mp:").map(str::parse::<u32>) {
                Some(Ok(b)) => Precision::Mp(
                    crate::numeric::check_prec_bits(b)
                        .map_err(|e| format!("--precision {other}: {e}"))?,
                ),
                _ => return Err(format!("--precision {other}: expected f64 or mp:BITS")),
            },
        };
        if crate::surface::SurfaceKind::parse(&self.surface).is_none() {
            return Err(format!("--surface {}: expected pn or loop", self.surface));
        }
        if self.samples == 0 {
            return Err("--samples 0: every sampled check would examine nothing; give at least 1 (checks with too few samples to decide report \"skipped\", not a failure)".into());
        }
        Ok(Ch4Options {
            seed: self.seed,
            samples: self.samples,
            precision,
            mp_backend: crate::numeric::MpBackend::parse(&self.mp_backend)?,
            max_edge_configs: self.max_configs,
            max_triangle_configs: self.max_configs,
            max_star_configs: self.max_configs,
        })
    }
}

/// Why [`check_report`] produced no report: the options or the certificate file, never the
/// mesh (an invalid mesh is a report whose `is_simplicial_surface` is false).
#[derive(Debug, thiserror::Error)]
pub enum CheckError {
    /// An option is out of range (`--precision`, `--surface`, `--samples 0`, ...): exit 2.
    #[error("{0}")]
    Usage(String),
    /// The `--certificates` file could not be read.
    #[error("{0}")]
    Certificate(#[from] crate::certify::CertifyError),
}

impl Ch4Args {
    /// The options of [`crate::conditions::spec::check_report`], the certificate file read.
    pub fn spec_options(&self) -> Result<SpecOptions, CheckError> {
        let ch4 = self.options().map_err(CheckError::Usage)?;
        let certificates = match &self.certificates {
            Some(path) => Some((
                path.display().to_string(),
                crate::certify::read_certificate(path)?,
            )),
            None => None,
        };
        let surface = crate::surface::SurfaceKind::parse(&self.surface).unwrap_or_default();
        Ok(SpecOptions {
            ch4,
            surface: (!self.no_surface).then_some(surface),
            certificates,
        })
    }
}

/// `ppm check` on a mesh already read: [`crate::conditions::spec::check_report`] with the
/// options parsed from flags exactly as `ppm` parses them (see
/// [`super::parse_check_spec_args`]); `progress` shows the progress lines on a terminal. The
/// Python layer's `check()` calls it.
pub fn check_report(
    raw: &RawMesh,
    labels: bool,
    spec: Option<&Ch4Args>,
    progress: bool,
) -> Result<CheckReport, CheckError> {
    let spec = spec.map(Ch4Args::spec_options).transpose()?;
    let big = progress && raw.faces.len() >= PROGRESS_FACES;
    let say = |phase: &'static str| {
        if big {
            eprintln!("ppm: running the {phase} checks ...");
        }
    };
    let l4 = super::progress::Line::new("ppm check --spec", "configurations", progress);
    let l5 = super::progress::Line::new("ppm check --spec (Ch. 5)", "check families", progress);
    let (h4, h5) = (l4.hook(), l5.hook());
    let hooks = SpecProgress {
        chapter4: h4.as_ref().map(|h| h as _),
        chapter5: h5.as_ref().map(|h| h as _),
        phase: Some(&say),
    };
    let rep = crate::conditions::spec::check_report(raw, labels, spec.as_ref(), hooks);
    if spec.is_some() {
        l4.finish();
        if spec.as_ref().is_some_and(|s| s.surface.is_some()) {
            l5.finish();
        }
    }
    Ok(rep)
}

/// `ppm check FILE [--json] [--triangulate] [--labels] [--spec ...]`: prints [`check_report`].
pub fn run(
    file: &Path,
    json: bool,
    triangulate: bool,
    labels: bool,
    spec: Option<&Ch4Args>,
) -> ExitCode {
    let t0 = Instant::now();
    let opts = ReadOptions {
        triangulate,
        ..ReadOptions::default()
    };
    let raw = match read_mesh(file, &opts) {
        Ok(r) => r,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(2);
        }
    };
    let big = raw.faces.len() >= PROGRESS_FACES;
    if big {
        eprintln!(
            "ppm: read {} vertices, {} faces in {:.2} s; validating ...",
            raw.positions.len(),
            raw.faces.len(),
            t0.elapsed().as_secs_f64()
        );
    }
    let mut rep = match check_report(&raw, labels, spec, true) {
        Ok(r) => r,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(2);
        }
    };
    if big {
        eprintln!("ppm: validated in {:.2} s", t0.elapsed().as_secs_f64());
    }
    // The command's time includes reading the file.
    rep.seconds = t0.elapsed().as_secs_f64();
    let secs = rep.seconds;
    let ch5_unexpected = rep.chapter5_unexpected();
    let ok = rep.passes();
    if json {
        match serde_json::to_string_pretty(&rep) {
            Ok(s) => println!("{s}"),
            Err(e) => {
                eprintln!("error: cannot serialise report: {e}");
                return ExitCode::from(2);
            }
        }
    } else {
        print!(
            "{}",
            render_report(&rep.validation, &rep.extra_checks, secs)
        );
        if let Some(r) = &rep.chapter4 {
            print!("{}", render_ch4(r));
        }
        if !rep.chapter5.is_empty() {
            println!("Chapter 5 checks (surface, condition (C), eval of Sec. 6.1.4):");
            print!("{}", crate::report::render_text(&rep.chapter5));
            if ch5_unexpected.is_empty() {
                println!("Chapter 5: no failure");
            } else {
                println!(
                    "Chapter 5: UNEXPECTED failures: {}",
                    ch5_unexpected.join(", ")
                );
            }
        }
    }
    if ok {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    }
}

/// The text report of `ppm check`.
pub(crate) fn render_report(r: &ValidationReport, extra: &[CheckResult], secs: f64) -> String {
    use std::fmt::Write;
    let mut s = String::new();
    let _ = writeln!(
        s,
        "mesh: {} ({} vertices, {} faces in file)",
        r.source.as_deref().unwrap_or("<memory>"),
        r.vertices_in_file,
        r.faces_in_file
    );
    if r.triangulated_polygons > 0 {
        let _ = writeln!(
            s,
            "note: {} polygon(s) with more than 3 sides were fan-split (--triangulate)",
            r.triangulated_polygons
        );
    }
    s.push_str(&render_text(&r.checks));
    s.push_str(&render_text(extra));
    for (i, c) in r.components.iter().enumerate() {
        let _ = writeln!(
            s,
            "component {i}: V={} E={} F={} χ={} genus={}",
            c.vertices,
            c.edges,
            c.faces,
            c.euler_characteristic,
            c.genus.map_or("-".to_string(), |g| g.to_string())
        );
    }
    let hist: Vec<String> = r
        .degree_histogram
        .iter()
        .map(|(d, n)| format!("{d}:{n}"))
        .collect();
    let _ = writeln!(s, "degree histogram (degree:count): {}", hist.join(" "));
    if r.is_simplicial_surface {
        let _ = writeln!(
            s,
            "verdict: a simplicial surface (Def. 3.1.6); by Lemma 3.1.1 |K| is a topological surface  [{secs:.2} s]"
        );
    } else {
        let classes: Vec<&str> = r.error_classes.iter().map(|c| c.name()).collect();
        let _ = writeln!(
            s,
            "verdict: NOT a simplicial surface; defect classes: {}  [{secs:.2} s]",
            classes.join(", ")
        );
    }
    s
}

/// `ppm eval-map`: φ_wu(p) in f64 and in MPFR with their difference.
pub(crate) fn eval_map(
    file: &Path,
    u: u32,
    w: u32,
    p: [f64; 2],
    bits: u32,
    json: bool,
) -> ExitCode {
    let k = match super::load::surface(file) {
        Ok(k) => k,
        Err(c) => return c,
    };
    let g = PpmGluing::new(&k);
    let (u, w) = (VertexId(u), VertexId(w));
    let pair = match g.pair(u, w) {
        Ok(p) => p,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(2);
        }
    };
    match phi_wu_f64_vs_mp(&pair, p, bits) {
        Ok((a, b, d)) => {
            if json {
                println!(
                    "{}",
                    serde_json::json!({"u": u, "w": w, "p": p, "pair": pair, "f64": a, "mp": b, "mp_bits": bits, "difference": d})
                );
            } else {
                println!("φ_{w}{u}({:?}) [Def. 4.1.10, {pair:?}]", p);
                println!("  f64      : ({:e}, {:e})", a[0], a[1]);
                println!(
                    "  mp {bits:>4} : ({:e}, {:e})  (rounded to f64)",
                    b[0], b[1]
                );
                println!("  |f64 − mp| = {d:.3e}");
            }
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("error: φ_{w}{u}({p:?}): {e}");
            ExitCode::from(1)
        }
    }
}
