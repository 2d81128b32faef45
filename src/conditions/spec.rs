//! `ppm check [--labels] [--spec]` as a library call: every chapter run on one mesh, the report
//! as data and its verdict. The CLI and the Python layer only parse options, print the report
//! and map [`CheckReport::passes`] to an exit status.

use super::chapter4::{certificate_coverage, run_chapter4_with, Ch4Options, Ch4Report};
use crate::mesh::star::check_star_isomorphism;
use crate::mesh::validate::{validate, ValidationReport};
use crate::mesh::RawMesh;
use crate::report::{CheckResult, Progress};
use crate::surface::SurfaceKind;
use serde::Serialize;
use std::time::Instant;

/// What `--spec` runs: the Chapter 4 options, the S′ of Chapter 5 (or none), and a
/// certificate file already read.
#[derive(Debug, Clone)]
pub struct SpecOptions {
    /// Seeds, samples, precision and configuration limits of Chapters 3.4–4.
    pub ch4: Ch4Options,
    /// S′ of Chapter 5 (Sec. 6.2); `None` runs only Chapters 3.4–4 (`--no-surface`).
    pub surface: Option<SurfaceKind>,
    /// `--certificates`: the file's name and its certificate.
    pub certificates: Option<(String, crate::certify::Certificate)>,
}

/// Progress hooks of the two long phases (configurations of Ch. 4, check families of Ch. 5);
/// the library prints nothing.
#[derive(Default, Clone, Copy)]
pub(crate) struct SpecProgress<'a> {
    /// Called with (done, total) Chapter 4 configurations.
    pub chapter4: Progress<'a>,
    /// Called with (done, total) Chapter 5 check families.
    pub chapter5: Progress<'a>,
    /// Called with "chapter 4" or "chapter 5" as each phase starts.
    pub phase: Option<&'a (dyn Fn(&'static str) + Sync)>,
}

/// The report of `ppm check [--labels] [--spec] --json`, as data: serialised with serde it is
/// exactly the JSON the command prints (SPEC `PY-check-report`).
#[derive(Debug, Serialize)]
pub struct CheckReport {
    /// Sec. 3.1: every check of the validator, components, degree histogram.
    #[serde(flatten)]
    pub validation: ValidationReport,
    /// The s_v labelling check (Def. 4.1.4), with `--labels` or `--spec` on a valid surface.
    pub extra_checks: Vec<CheckResult>,
    /// Chapters 3.4–4 (with `--spec` on a valid surface).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub chapter4: Option<Ch4Report>,
    /// Chapter 5 and Sec. 6.1.4 (with `--spec`, unless `--no-surface`).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub chapter5: Vec<CheckResult>,
    /// Wall-clock seconds of the run.
    pub seconds: f64,
}

impl CheckReport {
    /// The IDs of the Chapter 5 checks that fail (Chapter 5 has no documented erratum, SPEC.md
    /// "Errata found": each one fails the run).
    pub fn chapter5_unexpected(&self) -> Vec<&str> {
        self.chapter5
            .iter()
            .filter(|c| c.failed())
            .map(|c| c.id.as_str())
            .collect()
    }

    /// The verdict `ppm check` exits 0 for: a simplicial surface, no failing extra or Chapter 5
    /// check, and a Chapter 4 run (if any) whose failures are all errata on their domains.
    pub fn passes(&self) -> bool {
        self.validation.is_simplicial_surface
            && self.chapter5_unexpected().is_empty()
            && self.extra_checks.iter().all(|c| !c.failed())
            && self.chapter4.as_ref().map_or(true, |r| r.passes())
    }
}

/// Validate `raw` (Sec. 3.1) and, on a simplicial surface, run the s_v labelling check
/// (`labels`) and, with `spec`, Chapters 3.4–4 and Chapter 5. An invalid mesh is a report whose
/// `is_simplicial_surface` is false, never an error.
pub(crate) fn check_report(
    raw: &RawMesh,
    labels: bool,
    spec: Option<&SpecOptions>,
    progress: SpecProgress,
) -> CheckReport {
    let t0 = Instant::now();
    let v = validate(raw);
    let mut extra = Vec::new();
    let mut ch4 = None;
    let mut ch5 = Vec::new();
    if let Some(k) = &v.surface {
        if labels || spec.is_some() {
            extra.push(check_star_isomorphism(k, |a, b| k.s(a, b)));
        }
        if let Some(s) = spec {
            if let Some(f) = progress.phase {
                f("chapter 4");
            }
            let mut rep = run_chapter4_with(k, &s.ch4, progress.chapter4);
            if let Some((file, c)) = &s.certificates {
                rep.certificates = Some(certificate_coverage(k, c, file));
            }
            ch4 = Some(rep);
            if let Some(surface) = s.surface {
                if let Some(f) = progress.phase {
                    f("chapter 5");
                }
                let sopts = crate::surface::checks::SurfaceCheckOptions {
                    seed: s.ch4.seed,
                    samples_per_vertex: s.ch4.samples.max(1),
                    max_vertices: s.ch4.max_star_configs,
                    surface,
                    ..Default::default()
                };
                ch5 = crate::surface::checks::run_surface_checks_with(k, &sopts, progress.chapter5);
            }
        }
    }
    CheckReport {
        validation: v.report,
        extra_checks: extra,
        chapter4: ch4,
        chapter5: ch5,
        seconds: t0.elapsed().as_secs_f64(),
    }
}
