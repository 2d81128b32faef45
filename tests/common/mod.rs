//! Shared test fixtures: the public mesh corpus in `../shared/meshes/` (present in CI, absent
//! on a fresh clone, in which case corpus tests print a note and pass vacuously on it — they
//! also run on the bundled fixtures under `tests/data/`).

#![allow(dead_code)]

pub mod sdiff;

use std::path::{Path, PathBuf};

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

pub fn corpus_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/meshes")
}

/// Every mesh of the corpus, or an empty list (with a note on stderr) when it is absent.
pub fn corpus() -> Vec<CorpusMesh> {
    let dir = corpus_dir();
    let text = match std::fs::read_to_string(dir.join("manifest.tsv")) {
        Ok(t) => t,
        Err(_) => {
            eprintln!("note: {} not present; corpus tests skipped", dir.display());
            return vec![];
        }
    };
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
