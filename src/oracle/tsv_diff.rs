//! `ppm diff MESH TABLE.tsv`: compare a table of another implementation's surface points
//! (tab-separated, header line naming the columns: `face lambda mu nu` and any of `pps_x
//! pps_y pps_z`, `sprime_x sprime_y sprime_z`) against this implementation: `pps_*` against
//! eval(σ, λ, μ, ν) (Sec. 6.1.4), `sprime_*` against S′ = b_σ(λ, μ, ν) (Sec. 5.1). `face` is
//! the 0-based triangle of the mesh file and (λ, μ, ν) refer to its corners in file order.
//! Deviations are reported relative to the bounding-box diagonal of the mesh: per column
//! (|Δx|, |Δy|, |Δz|) and per point (Euclidean), max / p50 / p99, with the worst rows.

use crate::mesh::{FaceId, SimplicialSurface, VertexId};
use crate::surface::{Pps, TargetSurface};
use serde::Serialize;
use thiserror::Error;

/// A table that cannot be read (names the line).
#[derive(Debug, Clone, PartialEq, Error)]
pub enum TsvError {
    /// The table has no header line.
    #[error("the table is empty (expected a header line naming the columns)")]
    Empty,
    /// A required column is absent from the header.
    #[error("line 1: the header has no column {0:?}")]
    MissingColumn(String),
    /// The header has neither the pps_* nor the sprime_* columns.
    #[error("line 1: the header has neither pps_x/pps_y/pps_z nor sprime_x/sprime_y/sprime_z")]
    NothingToCompare,
    /// A line has a different number of fields than the header.
    #[error("line {line}: {found} fields, the header has {expected}")]
    FieldCount {
        /// 1-based line.
        line: usize,
        /// Fields found.
        found: usize,
        /// Fields in the header.
        expected: usize,
    },
    /// A field is not a finite number (or the face not an index).
    #[error("line {line}: column {column:?}: {value:?} is not a {what}")]
    Number {
        /// 1-based line.
        line: usize,
        /// Column name.
        column: String,
        /// The text found.
        value: String,
        /// "finite number" or "face index".
        what: &'static str,
    },
    /// The face index is not a triangle of the mesh.
    #[error("line {line}: face {face} is not a triangle of the mesh ({faces} faces)")]
    NoSuchFace {
        /// 1-based line.
        line: usize,
        /// The face index.
        face: u64,
        /// Number of faces of the mesh.
        faces: usize,
    },
    /// Too many lines (bounded memory).
    #[error("more than {0} rows")]
    TooLarge(usize),
}

/// Largest number of rows read.
pub const MAX_ROWS: usize = 10_000_000;

/// One row of the table.
#[derive(Debug, Clone, Serialize)]
pub struct Row {
    /// 1-based line in the table.
    pub line: usize,
    /// Face (file index).
    pub face: u32,
    /// (λ, μ, ν) w.r.t. the face's corners in file order.
    pub bary: [f64; 3],
    /// Their eval point, if the column is present.
    pub pps: Option<[f64; 3]>,
    /// Their S′ point, if the column is present.
    pub sprime: Option<[f64; 3]>,
}

/// Parse a table (see the module doc).
pub fn parse_tsv(text: &str, faces: usize) -> Result<Vec<Row>, TsvError> {
    let mut lines = text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty());
    let (_, header) = lines.next().ok_or(TsvError::Empty)?;
    let names: Vec<&str> = header.split('\t').map(str::trim).collect();
    let col = |n: &str| names.iter().position(|&c| c == n);
    let need = |n: &str| col(n).ok_or_else(|| TsvError::MissingColumn(n.to_string()));
    let key = [need("face")?, need("lambda")?, need("mu")?, need("nu")?];
    let triple = |p: &str| -> Option<[usize; 3]> {
        Some([
            col(&format!("{p}_x"))?,
            col(&format!("{p}_y"))?,
            col(&format!("{p}_z"))?,
        ])
    };
    let (pc, sc) = (triple("pps"), triple("sprime"));
    if pc.is_none() && sc.is_none() {
        return Err(TsvError::NothingToCompare);
    }
    let mut rows = Vec::new();
    for (i, l) in lines {
        let line = i + 1;
        if rows.len() >= MAX_ROWS {
            return Err(TsvError::TooLarge(MAX_ROWS));
        }
        let f: Vec<&str> = l.split('\t').map(str::trim).collect();
        if f.len() != names.len() {
            return Err(TsvError::FieldCount {
                line,
                found: f.len(),
                expected: names.len(),
            });
        }
        let num = |c: usize| -> Result<f64, TsvError> {
            f[c].parse::<f64>()
                .ok()
                .filter(|x| x.is_finite())
                .ok_or_else(|| TsvError::Number {
                    line,
                    column: names[c].to_string(),
                    value: f[c].to_string(),
                    what: "finite number",
                })
        };
        let face: u64 = f[key[0]].parse().map_err(|_| TsvError::Number {
            line,
            column: "face".into(),
            value: f[key[0]].to_string(),
            what: "face index",
        })?;
        if face >= faces as u64 {
            return Err(TsvError::NoSuchFace { line, face, faces });
        }
        let bary = [num(key[1])?, num(key[2])?, num(key[3])?];
        let point = |t: Option<[usize; 3]>| -> Result<Option<[f64; 3]>, TsvError> {
            t.map(|[a, b, c]| Ok([num(a)?, num(b)?, num(c)?]))
                .transpose()
        };
        rows.push(Row {
            line,
            face: face as u32,
            bary,
            pps: point(pc)?,
            sprime: point(sc)?,
        });
    }
    Ok(rows)
}

/// Deviation statistics of one compared quantity, relative to the diagonal.
#[derive(Debug, Clone, Serialize, Default)]
pub struct RelStats {
    /// Rows compared.
    pub count: usize,
    /// Rows that could not be evaluated here (counted as failures).
    pub errors: usize,
    /// Largest deviation / diagonal.
    pub max: f64,
    /// Median (nearest rank).
    pub p50: f64,
    /// 99th percentile (nearest rank).
    pub p99: f64,
}

fn stats(mut v: Vec<f64>, errors: usize) -> RelStats {
    v.sort_by(|a, b| a.total_cmp(b));
    let rank = |p: f64| -> f64 {
        if v.is_empty() {
            return 0.0;
        }
        let i = ((p * v.len() as f64).ceil() as usize).clamp(1, v.len()) - 1;
        v[i]
    };
    RelStats {
        count: v.len(),
        errors,
        max: v.last().copied().unwrap_or(0.0),
        p50: rank(0.5),
        p99: rank(0.99),
    }
}

/// A worst row of one quantity.
#[derive(Debug, Clone, Serialize)]
pub struct WorstRow {
    /// 1-based line of the table.
    pub line: usize,
    /// Face (file index).
    pub face: u32,
    /// (λ, μ, ν), file order.
    pub bary: [f64; 3],
    /// Their value.
    pub theirs: [f64; 3],
    /// Ours (NaN when not evaluable).
    pub ours: [f64; 3],
    /// Euclidean distance / diagonal (∞ when not evaluable).
    pub relative: f64,
    /// Why it could not be evaluated here, if so.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub problem: Option<String>,
}

/// The comparison of one quantity (`pps` or `sprime`).
#[derive(Debug, Clone, Serialize)]
pub struct Quantity {
    /// `pps` (eval, Sec. 6.1.4) or `sprime` (S′, Sec. 5.1).
    pub name: String,
    /// Euclidean distance per row.
    pub point: RelStats,
    /// |Δ| per coordinate column (`_x`, `_y`, `_z`).
    pub columns: [RelStats; 3],
    /// The worst rows, largest first.
    pub worst: Vec<WorstRow>,
}

/// The report of `ppm diff` on a TSV table.
#[derive(Debug, Clone, Serialize)]
pub struct TsvReport {
    /// Rows read.
    pub rows: usize,
    /// Bounding-box diagonal of the mesh vertices (the unit of every deviation).
    pub diagonal: f64,
    /// The profile the reference was built with.
    pub profile: String,
    /// S′ of the reference (`pn-triangles` or `loop-limit`, the target's name).
    pub sprime: String,
    /// The tolerance (relative to the diagonal).
    pub tolerance: f64,
    /// The compared quantities.
    pub quantities: Vec<Quantity>,
    /// Some row compared, every row evaluated and every deviation ≤ tolerance.
    pub within_tolerance: bool,
}

/// Bounding-box diagonal of the vertices of K.
pub fn diagonal(k: &SimplicialSurface) -> f64 {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for v in k.vertices() {
        let p = k.position(v);
        for d in 0..3 {
            lo[d] = lo[d].min(p[d]);
            hi[d] = hi[d].max(p[d]);
        }
    }
    (0..3).map(|d| (hi[d] - lo[d]).powi(2)).sum::<f64>().sqrt()
}

/// (λ, μ, ν) w.r.t. the file corners `file` → w.r.t. the stored corners `stored` (the
/// validator may have reversed a face to orient K consistently).
fn to_stored(file: [u32; 3], stored: [VertexId; 3], b: [f64; 3]) -> [f64; 3] {
    std::array::from_fn(|i| {
        file.iter()
            .position(|&c| c == stored[i].0)
            .map_or(f64::NAN, |j| b[j])
    })
}

/// Compare `rows` against `pps` (eval) and `target` (S′). `file_faces` are the faces as in
/// the mesh file (the table's corner order).
pub fn diff_rows(
    k: &SimplicialSurface,
    file_faces: &[[u32; 3]],
    pps: &Pps,
    target: &dyn TargetSurface,
    rows: &[Row],
    tolerance: f64,
    worst: usize,
) -> TsvReport {
    let diag = diagonal(k);
    let mut quantities = Vec::new();
    type Pick = fn(&Row) -> Option<[f64; 3]>;
    let picks: [(&str, Pick); 2] = [("pps", |r| r.pps), ("sprime", |r| r.sprime)];
    for (name, pick) in picks {
        if rows.iter().all(|r| pick(r).is_none()) {
            continue;
        }
        let ours: Vec<Result<[f64; 3], String>> = rows
            .iter()
            .map(|r| {
                let f = FaceId(r.face);
                let file = file_faces[r.face as usize];
                if name == "pps" {
                    pps.eval_f64(f, to_stored(file, k.face(f), r.bary))
                        .map_err(|e| e.to_string())
                } else {
                    Ok(target.eval(f, file.map(VertexId), r.bary))
                }
            })
            .collect();
        let mut dist = Vec::new();
        let mut cols: [Vec<f64>; 3] = Default::default();
        let mut all: Vec<WorstRow> = Vec::new();
        let mut errors = 0;
        for (r, o) in rows.iter().zip(&ours) {
            let Some(theirs) = pick(r) else { continue };
            let (o, rel, problem) = match o {
                Ok(o) if o.iter().all(|x| x.is_finite()) => {
                    let d: [f64; 3] = std::array::from_fn(|i| (o[i] - theirs[i]).abs());
                    for i in 0..3 {
                        cols[i].push(d[i] / diag);
                    }
                    let rel = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt() / diag;
                    dist.push(rel);
                    (*o, rel, None)
                }
                Ok(o) => {
                    errors += 1;
                    (*o, f64::INFINITY, Some("not finite".to_string()))
                }
                Err(e) => {
                    errors += 1;
                    ([f64::NAN; 3], f64::INFINITY, Some(e.clone()))
                }
            };
            all.push(WorstRow {
                line: r.line,
                face: r.face,
                bary: r.bary,
                theirs,
                ours: o,
                relative: rel,
                problem,
            });
        }
        all.sort_by(|a, b| b.relative.total_cmp(&a.relative));
        all.truncate(worst);
        let [cx, cy, cz] = cols;
        quantities.push(Quantity {
            name: name.to_string(),
            point: stats(dist, errors),
            columns: [stats(cx, errors), stats(cy, errors), stats(cz, errors)],
            worst: all,
        });
    }
    // Zero rows compared is "nothing checked", never agreement.
    let within = !quantities.is_empty()
        && quantities
            .iter()
            .all(|q| q.point.count > 0 && q.point.errors == 0 && q.point.max <= tolerance);
    TsvReport {
        rows: rows.len(),
        diagonal: diag,
        profile: pps.options.profile.name().to_string(),
        sprime: target.name().to_string(),
        tolerance,
        quantities,
        within_tolerance: within,
    }
}

/// Errors of [`diff_tsv_files`].
#[derive(Debug, Clone, PartialEq, Error)]
pub enum TsvDiffError {
    /// The mesh could not be read.
    #[error("{0}")]
    Mesh(String),
    /// The mesh is not a simplicial surface.
    #[error("{0}: not a simplicial surface (run `ppm check`)")]
    NotSurface(String),
    /// The table could not be read.
    #[error("{path}: {error}")]
    Table {
        /// The table file.
        path: String,
        /// What went wrong.
        error: String,
    },
    /// S′ could not be built for the mesh (e.g. a Loop valence above the supported maximum).
    #[error("{mesh}: S′ = {kind}: {error}")]
    SPrime {
        /// The mesh file.
        mesh: String,
        /// The requested S′.
        kind: String,
        /// What went wrong.
        error: String,
    },
}

/// Read the mesh and the table, build S′ = PN triangles and the PPS with `profile`, compare.
pub fn diff_tsv_files(
    mesh: &std::path::Path,
    table: &std::path::Path,
    profile: crate::surface::Profile,
    tolerance: f64,
    worst: usize,
) -> Result<TsvReport, TsvDiffError> {
    diff_tsv_files_with(
        mesh,
        table,
        profile,
        crate::surface::SurfaceKind::Pn,
        tolerance,
        worst,
    )
}

/// As [`diff_tsv_files`] with S′ of kind `kind` (`SPrime::for_profile`: with `authors-code`
/// the Loop S′ is what the authors' evaluator computes, docs/authors-code.md).
pub fn diff_tsv_files_with(
    mesh: &std::path::Path,
    table: &std::path::Path,
    profile: crate::surface::Profile,
    kind: crate::surface::SurfaceKind,
    tolerance: f64,
    worst: usize,
) -> Result<TsvReport, TsvDiffError> {
    use crate::mesh::io::{read_mesh, ReadOptions};
    use crate::surface::{PpsOptions, SPrime};
    let raw =
        read_mesh(mesh, &ReadOptions::default()).map_err(|e| TsvDiffError::Mesh(e.to_string()))?;
    let k = crate::mesh::validate::validate(&raw)
        .surface
        .ok_or_else(|| TsvDiffError::NotSurface(mesh.display().to_string()))?;
    let text = super::read_text_table(table).map_err(|e| TsvDiffError::Table {
        path: table.display().to_string(),
        error: e,
    })?;
    let rows = parse_tsv(&text, k.num_faces()).map_err(|e| TsvDiffError::Table {
        path: table.display().to_string(),
        error: e.to_string(),
    })?;
    let sprime = SPrime::for_profile(kind, &k, profile).map_err(|e| TsvDiffError::SPrime {
        mesh: mesh.display().to_string(),
        kind: kind.name().to_string(),
        error: e.to_string(),
    })?;
    let pps = Pps::try_build(
        &k,
        sprime.as_target(),
        PpsOptions {
            profile,
            ..PpsOptions::default()
        },
    )
    .map_err(|e| TsvDiffError::Mesh(e.to_string()))?;
    Ok(diff_rows(
        &k,
        &raw.faces,
        &pps,
        sprime.as_target(),
        &rows,
        tolerance,
        worst,
    ))
}

/// Whether a table file is a TSV table of points (its first line names `face` first).
pub(crate) fn looks_like_tsv(text_start: &str) -> bool {
    text_start.trim_start().starts_with("face\t")
}

/// The report as text.
pub(crate) fn render_tsv(r: &TsvReport) -> String {
    let mut s = format!(
        "rows {}, bounding-box diagonal {:.6e}, profile {}, S′ {}; deviations relative to the diagonal\n",
        r.rows, r.diagonal, r.profile, r.sprime
    );
    for q in &r.quantities {
        let what = if q.name == "pps" {
            "eval(σ, λ, μ, ν) (Sec. 6.1.4)"
        } else {
            "S′ (Sec. 5.1)"
        };
        s += &format!(
            "{}_* vs {what}: {} rows, {} not evaluable\n  {:<8} {:>10} {:>10} {:>10}\n",
            q.name, q.point.count, q.point.errors, "", "max", "p50", "p99"
        );
        let mut line = |n: &str, st: &RelStats| {
            s += &format!(
                "  {:<8} {:>10.3e} {:>10.3e} {:>10.3e}\n",
                n, st.max, st.p50, st.p99
            );
        };
        line("point", &q.point);
        for (c, st) in ["x", "y", "z"].iter().zip(&q.columns) {
            line(&format!("{}_{c}", q.name), st);
        }
        s += "  worst rows (line, face, λ μ ν, theirs, ours, distance/diagonal):\n";
        for w in &q.worst {
            s += &format!(
                "    {} face {} ({:.17} {:.17} {:.17}) [{:.17e} {:.17e} {:.17e}] [{:.17e} {:.17e} {:.17e}] {:.3e}{}\n",
                w.line, w.face, w.bary[0], w.bary[1], w.bary[2], w.theirs[0], w.theirs[1],
                w.theirs[2], w.ours[0], w.ours[1], w.ours[2], w.relative,
                w.problem.as_ref().map(|p| format!(" ({p})")).unwrap_or_default()
            );
        }
    }
    s += &format!(
        "{} (tolerance {:e} of the diagonal)\n",
        if r.within_tolerance {
            "WITHIN TOLERANCE"
        } else {
            "BEYOND TOLERANCE"
        },
        r.tolerance
    );
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tsv_parse_errors_name_the_line() {
        assert_eq!(parse_tsv("", 1).unwrap_err(), TsvError::Empty);
        assert!(matches!(
            parse_tsv("face\tlambda\tmu\n", 1),
            Err(TsvError::MissingColumn(_))
        ));
        assert_eq!(
            parse_tsv("face\tlambda\tmu\tnu\n", 1).unwrap_err(),
            TsvError::NothingToCompare
        );
        let h = "face\tlambda\tmu\tnu\tsprime_x\tsprime_y\tsprime_z\n";
        assert!(matches!(
            parse_tsv(&format!("{h}0\t1\t0\t0\t1\t2\n"), 1),
            Err(TsvError::FieldCount { line: 2, .. })
        ));
        assert!(matches!(
            parse_tsv(&format!("{h}0\t1\t0\t0\t1\tNaN\t3\n"), 1),
            Err(TsvError::Number { line: 2, .. })
        ));
        assert!(matches!(
            parse_tsv(&format!("{h}5\t1\t0\t0\t1\t2\t3\n"), 2),
            Err(TsvError::NoSuchFace {
                line: 2,
                face: 5,
                ..
            })
        ));
        let rows = parse_tsv(&format!("{h}1\t0.5\t0.25\t0.25\t1\t2\t3\n"), 2).expect("parsed");
        assert_eq!(rows[0].sprime, Some([1.0, 2.0, 3.0]));
        assert_eq!(rows[0].pps, None);
    }

    #[test]
    fn tsv_stats_nearest_rank() {
        let s = stats((1..=100).map(f64::from).collect(), 0);
        assert_eq!((s.max, s.p50, s.p99), (100.0, 50.0, 99.0));
        assert_eq!(stats(vec![], 0).count, 0);
    }
}
