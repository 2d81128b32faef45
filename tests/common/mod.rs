//! Shared test fixtures: the public mesh corpus in `../shared/meshes/` and the authors'
//! reference tables in `../shared/reference/`, located by [`shared_dir`] (the one rule for
//! missing data: present in CI, where its absence is an error; absent on a fresh clone, where
//! the tests that need it skip their corpus part and the binary says how many at exit), and
//! the bundled fixtures under `tests/data/`, always present.

#![allow(dead_code)]

pub mod sdiff;
pub mod verdicts;

#[allow(unused_imports)]
pub use verdicts::{assert_caught, assert_fails_as_written, assert_holds, assert_holds_for};

use pseudomanifold::report::{CheckResult, Verdict};
use std::collections::BTreeSet;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::{Mutex, Once};

/// Names of the tests of this binary that skipped their `../shared` part.
static SKIPPED: Mutex<BTreeSet<String>> = Mutex::new(BTreeSet::new());
static AT_EXIT: Once = Once::new();

extern "C" {
    fn atexit(cb: extern "C" fn()) -> i32;
}

/// Prints the skip count once, at process exit: libtest captures `eprintln!` of passing tests
/// and prints nothing after its summary, so this is the only line a reader of a fresh clone's
/// `cargo test` sees about the missing data. Written to fd 2 directly (not captured).
extern "C" fn print_skips() {
    let n = SKIPPED
        .lock()
        .map_or_else(|e| e.into_inner().len(), |s| s.len());
    if n > 0 {
        let _ = writeln!(
            std::io::stderr(),
            "note: ../shared/ not found: {n} test{} of this binary skipped {} corpus part \
             (set PPM_SHARED or clone beside shared/)",
            if n == 1 { "" } else { "s" },
            if n == 1 { "its" } else { "their" },
        );
    }
}

/// Where `../shared` would be: `PPM_SHARED` when set (nothing else is tried, so
/// `PPM_SHARED=/nonexistent` simulates a fresh clone), else `../shared` beside the checkout or
/// two levels up (a worktree nested in the main checkout's parent).
fn shared_candidates() -> Vec<PathBuf> {
    match std::env::var_os("PPM_SHARED") {
        Some(p) => vec![PathBuf::from(p)],
        None => {
            let root = Path::new(env!("CARGO_MANIFEST_DIR"));
            vec![root.join("../shared"), root.join("../../shared")]
        }
    }
}

/// The `../shared` directory, or None after recording that `test` skipped its corpus part.
/// With `CI=true` its absence is an error: CI must run every corpus test.
pub fn shared_dir(test: &str) -> Option<PathBuf> {
    let candidates = shared_candidates();
    if let Some(d) = candidates.iter().find(|d| d.is_dir()) {
        return Some(d.clone());
    }
    if std::env::var("CI").is_ok_and(|v| v == "true") {
        panic!(
            "{test}: CI needs ../shared beside the clone (or PPM_SHARED); looked in {:?}",
            candidates
        );
    }
    AT_EXIT.call_once(|| {
        // SAFETY: registers a plain function with no arguments, as C's atexit expects.
        let rc = unsafe { atexit(print_skips) };
        assert_eq!(rc, 0, "atexit failed");
    });
    SKIPPED
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .insert(test.to_string());
    None
}

/// `rel` inside `../shared`, or None (skip recorded) when `../shared` is absent. A present
/// `../shared` without `rel` is an error, not a skip: the data is incomplete.
pub fn shared_path(test: &str, rel: &str) -> Option<PathBuf> {
    let p = shared_dir(test)?.join(rel);
    assert!(
        p.exists(),
        "{test}: {} is missing from ../shared",
        p.display()
    );
    Some(p)
}

/// Every result holds on something ([`assert_holds`]) except those named in `skipped`, which
/// must each be present and `Skipped` (a precondition the input legitimately lacks). Lists every
/// departure at once.
#[track_caller]
pub fn assert_hold_except_skipped(what: &str, rs: &[CheckResult], skipped: &[&str]) {
    let wrong: Vec<&CheckResult> = rs
        .iter()
        .filter(|r| {
            if skipped.contains(&r.id.as_str()) {
                !matches!(r.verdict(), Verdict::Skipped { .. })
            } else {
                !r.holds_with_evidence()
            }
        })
        .collect();
    let missing: Vec<&&str> = skipped
        .iter()
        .filter(|id| !rs.iter().any(|r| r.id == **id))
        .collect();
    assert!(
        wrong.is_empty() && missing.is_empty(),
        "{what}: expected every result to hold on something, skipped exactly {skipped:?}; \
         missing {missing:?}; departures:\n{}",
        pseudomanifold::report::render_text(&wrong.into_iter().cloned().collect::<Vec<_>>())
    );
    // Each result that held is a verdict asserted on real input, recorded as by `assert_holds`.
    for r in rs.iter().filter(|r| !skipped.contains(&r.id.as_str())) {
        let seen = match r.verdict() {
            Verdict::HoldsRestricted { .. } => verdicts::Seen::Restricted,
            _ => verdicts::Seen::Holds,
        };
        verdicts::record(&r.id, seen, r.examined);
    }
}

/// `raw` written as the OFF file `name` in a temporary directory of its own (`dir` names it
/// with the process id), for tests that run `ppm` on a generated mesh: (the directory, for the
/// test's other files and its clean-up; the mesh's path).
pub fn temp_off(dir: &str, name: &str, raw: &pseudomanifold::mesh::RawMesh) -> (PathBuf, PathBuf) {
    let dir = std::env::temp_dir().join(format!("{dir}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let path = dir.join(name);
    pseudomanifold::mesh::io::write_mesh(
        &path,
        &raw.positions,
        &raw.faces,
        pseudomanifold::mesh::MeshFormat::Off,
    )
    .expect("write the generated mesh");
    (dir, path)
}

/// One row of `../shared/meshes/manifest.tsv`.
#[derive(Debug, Clone)]
pub struct CorpusMesh {
    pub path: PathBuf,
    pub file: String,
    pub good: bool,
    pub vertices: u64,
    pub faces: u64,
    pub genus: Option<i64>,
    pub min_degree: u32,
    pub max_degree: u32,
    pub error_classes: Vec<String>,
}

/// `../shared/meshes`, or None (skip recorded for `test`) when `../shared` is absent.
pub fn corpus_dir(test: &str) -> Option<PathBuf> {
    let manifest = shared_path(test, "meshes/manifest.tsv")?;
    Some(manifest.parent().expect("meshes/").to_path_buf())
}

/// Every mesh of the corpus, or an empty list (skip recorded for `test`) when it is absent.
pub fn corpus(test: &str) -> Vec<CorpusMesh> {
    let Some(dir) = corpus_dir(test) else {
        return vec![];
    };
    let text = std::fs::read_to_string(dir.join("manifest.tsv")).expect("manifest.tsv");
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap_or("").split('\t').collect();
    let col = |name: &str| header.iter().position(|h| *h == name).expect(name);
    let (c_file, c_kind, c_v, c_f, c_g, c_min, c_max, c_err) = (
        col("file"),
        col("kind"),
        col("V"),
        col("F"),
        col("genus"),
        col("min_degree"),
        col("max_degree"),
        col("error_classes"),
    );
    lines
        .filter(|l| !l.trim().is_empty())
        .map(|l| {
            let f: Vec<&str> = l.split('\t').collect();
            CorpusMesh {
                path: dir.join(f[c_file]),
                file: f[c_file].to_string(),
                good: f[c_kind] == "good",
                vertices: f[c_v].parse().expect("V"),
                faces: f[c_f].parse().expect("F"),
                genus: f[c_g].parse().ok(),
                min_degree: f[c_min].parse().expect("min degree"),
                max_degree: f[c_max].parse().expect("max degree"),
                error_classes: f[c_err]
                    .split(',')
                    .filter(|s| !s.is_empty())
                    .map(String::from)
                    .collect(),
            }
        })
        .collect()
}

/// Bundled closed-surface fixtures (always present).
pub fn bundled_good() -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data");
    let mut v: Vec<PathBuf> = std::fs::read_dir(&dir)
        .map(|rd| {
            rd.filter_map(|e| e.ok().map(|e| e.path()))
                .filter(|p| {
                    p.is_file()
                        && matches!(
                            p.extension().and_then(|e| e.to_str()),
                            Some("off" | "obj" | "ply")
                        )
                        && !p
                            .file_name()
                            .and_then(|n| n.to_str())
                            .is_some_and(|n| n.contains("quad"))
                })
                .collect()
        })
        .unwrap_or_default();
    v.sort();
    v
}

/// The (rows compared, max deviation) of the quantity `name` (`"sprime"`, `"pps"`) of a TSV
/// diff, asserting that every row was evaluable.
pub fn tsv_quantity(r: &pseudomanifold::oracle::tsv_diff::TsvReport, name: &str) -> (usize, f64) {
    let q = r
        .quantities
        .iter()
        .find(|q| q.name == name)
        .unwrap_or_else(|| panic!("no {name} columns"));
    assert_eq!(q.point.errors, 0, "{name}: rows not evaluable");
    (q.point.count, q.point.max)
}

/// S′ and the PPS of `--profile authors-code` (PN triangles as their code builds them), the
/// model the authors' tables are compared with (AU-tables).
pub fn authors_code_pps(
    k: &pseudomanifold::mesh::SimplicialSurface,
) -> (
    pseudomanifold::surface::PnTriangles,
    pseudomanifold::surface::Pps,
) {
    use pseudomanifold::surface::{PnTriangles, Pps, PpsOptions, Profile};
    let pn = PnTriangles::for_profile(k, Profile::AuthorsCode);
    let pps = Pps::build(
        k,
        &pn,
        PpsOptions {
            profile: Profile::AuthorsCode,
            ..PpsOptions::default()
        },
    );
    (pn, pps)
}
