//! The validation steps the planar (m = 2) and the tetrahedral (m = 3) complexes share
//! (Mello–Velho Sec. 1: K a simplicial complex in ℝ^m with boundary), generic over the number
//! N = m + 1 of vertices per cell: ids in range and distinct, purity, positive orientation (the
//! exact sign comes from the caller), every facet a face of at most two cells, and the sweep
//! over bounding boxes that yields the candidate pairs of the overlap test.
//!
//! What stays per dimension, and why: reading (a mesh file with z = 0 against `.tets`), the
//! exact orientation predicate (det2 against det3) and the exact interior test of a candidate
//! pair (separating axes of two triangles against those of two tetrahedra, which need the
//! edge × edge cross products); writing those over m would need a generic exact determinant
//! and a generic separating-axis enumeration for two cases.

use crate::numeric::Q;
use crate::report::{CheckResult, Witness};
use num_traits::{Signed, Zero};
use serde_json::{json, Map, Value};
use std::collections::HashMap;

/// An input complex as read: its cells (vertex ids, unchecked) and how witnesses name things.
pub(crate) trait RawCells<const N: usize> {
    /// The cells as read.
    fn cells(&self) -> &[[u32; N]];
    /// The number of vertices read.
    fn vertex_count(&self) -> usize;
    /// Cell `f` in a message, with its place in the file.
    fn describe_cell(&self, f: usize) -> String;
    /// Vertex `v` in a message, with its place in the file.
    fn describe_vertex(&self, v: usize) -> String;
    /// The JSON fields naming cell `f` in a witness.
    fn cell_fields(&self, f: usize) -> Map<String, Value>;
    /// The JSON fields naming vertex `v` in a witness.
    fn vertex_fields(&self, v: usize) -> Map<String, Value>;
}

/// The words of one dimension: "triangle"/"edge" or "tetrahedron"/"triangle".
pub(crate) struct Words {
    /// A cell.
    pub cell: &'static str,
    /// Cells.
    pub cells: &'static str,
    /// A facet of a cell.
    pub facet: &'static str,
}

fn with(mut m: Map<String, Value>, key: &str, v: Value) -> Value {
    m.insert(key.into(), v);
    Value::Object(m)
}

/// Ids in range and distinct; returns the check and the cells that pass it.
pub(crate) fn indices<const N: usize>(
    raw: &impl RawCells<N>,
    id: &str,
    statement: &str,
) -> (CheckResult, Vec<usize>) {
    let nv = raw.vertex_count();
    let mut r = CheckResult::new(id, statement);
    let mut ok = Vec::new();
    for (f, t) in raw.cells().iter().enumerate() {
        r.examined += 1;
        if let Some(&v) = t.iter().find(|&&v| v as usize >= nv) {
            r.offend(|| {
                Witness::new(
                    format!(
                        "{} names vertex {v}, the file has {nv}",
                        raw.describe_cell(f)
                    ),
                    with(raw.cell_fields(f), "vertex", json!(v)),
                )
            });
        } else if (0..N).any(|a| (a + 1..N).any(|b| t[a] == t[b])) {
            r.offend(|| {
                Witness::new(
                    format!("{} repeats a vertex: {t:?}", raw.describe_cell(f)),
                    Value::Object(raw.cell_fields(f)),
                )
            });
        } else {
            ok.push(f);
        }
    }
    (r, ok)
}

/// Purity: every vertex is a vertex of some cell of `ok`.
pub(crate) fn purity<const N: usize>(
    raw: &impl RawCells<N>,
    ok: &[usize],
    words: &Words,
    id: &str,
    statement: &str,
) -> CheckResult {
    let mut r = CheckResult::new(id, statement);
    let mut used = vec![false; raw.vertex_count()];
    for &f in ok {
        for &v in &raw.cells()[f] {
            used[v as usize] = true;
        }
    }
    for (v, u) in used.iter().enumerate() {
        r.examined += 1;
        if !u {
            r.offend(|| {
                Witness::new(
                    format!("{} is in no {}", raw.describe_vertex(v), words.cell),
                    Value::Object(raw.vertex_fields(v)),
                )
            });
        }
    }
    r
}

/// How the orientation check words its witnesses.
pub(crate) struct OrientationWords {
    /// A cell of sign zero, e.g. "degenerate (collinear)".
    pub degenerate: &'static str,
    /// A cell of negative sign, e.g. "clockwise".
    pub negative: &'static str,
    /// The JSON key of the signed measure, e.g. "twice_area".
    pub key: &'static str,
}

/// Every cell of `ok` has a positive exact `measure` (the signed determinant of its edge
/// vectors); returns the check and the positively oriented cells.
pub(crate) fn orientation<const N: usize>(
    raw: &impl RawCells<N>,
    ok: &[usize],
    measure: impl Fn(&[u32; N]) -> Q,
    words: &OrientationWords,
    id: &str,
    statement: &str,
) -> (CheckResult, Vec<usize>) {
    let mut r = CheckResult::new(id, statement);
    let mut positive = Vec::new();
    for &f in ok {
        r.examined += 1;
        let o = measure(&raw.cells()[f]);
        if o.is_positive() {
            positive.push(f);
        } else {
            let what = if o.is_zero() {
                words.degenerate
            } else {
                words.negative
            };
            r.offend(|| {
                Witness::new(
                    format!("{} is {what}", raw.describe_cell(f)),
                    with(raw.cell_fields(f), words.key, json!(o.to_string())),
                )
            });
        }
    }
    (r, positive)
}

/// The N facets of a cell with N vertices, each the sorted ids of the other M = N − 1.
pub(crate) fn facets_of<const N: usize, const M: usize>(t: &[u32; N]) -> [[u32; M]; N] {
    std::array::from_fn(|skip| {
        let mut f = [0u32; M];
        for (j, (_, &v)) in t.iter().enumerate().filter(|(k, _)| *k != skip).enumerate() {
            f[j] = v;
        }
        f.sort_unstable();
        f
    })
}

/// Each facet of the cells `ok` (indices into `cells`) and the cells it is a facet of, in
/// the order of `ok`.
pub(crate) fn facet_map<const N: usize, const M: usize>(
    cells: &[[u32; N]],
    ok: impl IntoIterator<Item = usize>,
) -> HashMap<[u32; M], Vec<usize>> {
    let mut m: HashMap<[u32; M], Vec<usize>> = HashMap::new();
    for f in ok {
        for facet in facets_of::<N, M>(&cells[f]) {
            m.entry(facet).or_default().push(f);
        }
    }
    m
}

/// Every facet is a facet of at most two cells of `ok`.
pub(crate) fn facets<const N: usize, const M: usize>(
    raw: &impl RawCells<N>,
    ok: &[usize],
    words: &Words,
    id: &str,
    statement: &str,
) -> CheckResult {
    let mut r = CheckResult::new(id, statement);
    let by_facet = facet_map::<N, M>(raw.cells(), ok.iter().copied());
    let mut keys: Vec<_> = by_facet.keys().copied().collect();
    keys.sort_unstable();
    for key in keys {
        r.examined += 1;
        let fs = &by_facet[&key];
        if fs.len() > 2 {
            let named: Vec<String> = fs.iter().map(|&f| raw.describe_cell(f)).collect();
            let fields: Vec<Value> = fs
                .iter()
                .map(|&f| Value::Object(raw.cell_fields(f)))
                .collect();
            r.offend(|| {
                Witness::new(
                    format!(
                        "{} {key:?} is a face of {} {}: {}",
                        words.facet,
                        fs.len(),
                        words.cells,
                        named.join(", ")
                    ),
                    json!({"facet": key.to_vec(), "cells": fields}),
                )
            });
        }
    }
    r
}

/// An axis-aligned bounding box (lower corner, upper corner) and its cell.
pub(crate) type Bbox<const D: usize> = ([f64; D], [f64; D], usize);

/// The box of a cell from the vertex positions as read.
pub(crate) fn bbox<const N: usize, const D: usize>(
    cell: &[u32; N],
    positions: impl Fn(usize) -> [f64; D],
    f: usize,
) -> Bbox<D> {
    let mut lo = [f64::INFINITY; D];
    let mut hi = [f64::NEG_INFINITY; D];
    for &v in cell {
        let p = positions(v as usize);
        for k in 0..D {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    (lo, hi, f)
}

/// Calls `pair(f, g)` (f < g) for every two boxes that overlap (closed), sweeping over the
/// first axis so the work follows the overlaps, not the square of the count. Returns the
/// number of pairs, or `Err` with the count once it passes `limit`.
pub(crate) fn sweep_pairs<const D: usize>(
    mut boxes: Vec<Bbox<D>>,
    limit: Option<u64>,
    mut pair: impl FnMut(usize, usize),
) -> Result<u64, u64> {
    boxes.sort_by(|p, q| p.0[0].total_cmp(&q.0[0]).then(p.2.cmp(&q.2)));
    let mut examined = 0u64;
    let mut active: Vec<Bbox<D>> = Vec::new();
    for cur in boxes {
        active.retain(|a| a.1[0] >= cur.0[0]);
        for a in &active {
            if (1..D).any(|k| a.0[k] > cur.1[k] || cur.0[k] > a.1[k]) {
                continue;
            }
            examined += 1;
            if limit.is_some_and(|l| examined > l) {
                return Err(examined);
            }
            pair(a.2.min(cur.2), a.2.max(cur.2));
        }
        active.push(cur);
    }
    Ok(examined)
}
