//! Def. 3.1.1: a triangle is a 2-simplex only if its three vertices are affinely independent.

use super::predicates::nondegenerate_projection;
use crate::mesh::RawMesh;
use crate::report::{Check, CheckResult, Witness};
use serde_json::json;

/// Def. 3.1.1, decided exactly: (b − a) × (c − a) ≠ 0 in exact arithmetic on the stored f64
/// values. `candidates[f]` marks faces with in-range, distinct, finite corners (others are
/// reported by their own checks). Returns the check and the per-face non-degeneracy flags.
pub(crate) fn affinely_independent(raw: &RawMesh, candidates: &[bool]) -> (CheckResult, Vec<bool>) {
    let mut r = Check::new("D3.1.1", "triangle vertices affinely independent (exact)");
    let mut ok = vec![false; raw.faces.len()];
    for (f, t) in raw.faces.iter().enumerate() {
        if !candidates.get(f).copied().unwrap_or(false) {
            continue;
        }
        let p = |k: usize| &raw.positions[t[k] as usize];
        ok[f] = nondegenerate_projection(p(0), p(1), p(2)).is_some();
        r.holds(ok[f], || {
            Witness::new(
                format!(
                    "{}: vertices {:?} at {:?}, {:?}, {:?} are collinear (zero area, exact)",
                    raw.describe_face(f),
                    t,
                    p(0),
                    p(1),
                    p(2)
                ),
                json!({"face": f, "corners": t}),
            )
        });
    }
    (
        r.finish("exact sign of the cross product (adaptive-precision predicates)"),
        ok,
    )
}
