//! Mello–Velho Sec. 6.2, L306–L316: K_{i+1} = SUBDIVIDE(K_i, σ_i) inserts k new vertices
//! v_1, …, v_k "in that order" (L312), and the optimiser of L314 runs over st(v_k, K_{i+1}),
//! so that X is recomputed "only in the regions of the mesh that were modified by the
//! subdivision" (L316).
//!
//! The paper does not specify SUBDIVIDE: L310 names it "the subdivision of σ with adaptive
//! propagation" and cites \[15\]. Our stand-in is the newest-vertex bisection of
//! [`Mesh2::bisect`] (bisect σ's refinement edge, first bisecting the neighbour across it when
//! its refinement edge differs). This module records what each call inserts and checks the
//! locality L316 relies on: every triangle a call creates has one of the call's new vertices,
//! so ∪_k st(v_k, K_{i+1}) covers the modified region.

use super::refine::{Mesh2, RefineError};
use crate::report::{CheckResult, Witness};
use serde::Serialize;
use serde_json::json;

/// What one SUBDIVIDE(K, σ) call did.
#[derive(Debug, Clone, Serialize)]
pub struct SubdivideStep {
    /// σ (triangle id).
    pub target: usize,
    /// v_1, …, v_k in insertion order.
    pub new_vertices: Vec<u32>,
    /// Alive triangles created by the call, with their vertices.
    pub created: Vec<(usize, [u32; 3])>,
    /// Triangles the call removed.
    pub removed: Vec<usize>,
}

/// SUBDIVIDE(K, σ) by newest-vertex bisection, recorded.
pub fn subdivide(mesh: &mut Mesh2, id: usize) -> Result<SubdivideStep, RefineError> {
    let (nv, nt) = (mesh.points.len(), mesh.tris.len());
    let before = mesh.alive.clone();
    mesh.bisect(id)?;
    Ok(SubdivideStep {
        target: id,
        new_vertices: (nv as u32..mesh.points.len() as u32).collect(),
        created: (nt..mesh.tris.len())
            .filter(|&t| mesh.alive[t])
            .map(|t| (t, mesh.tris[t]))
            .collect(),
        removed: (0..nt).filter(|&t| before[t] && !mesh.alive[t]).collect(),
    })
}

/// `SD-L316`: every call inserts k ≥ 1 vertices and every triangle it creates lies in the star
/// of one of them. The note gives the distribution of k (k > 1: the propagation of L310).
pub fn check_l316(steps: &[SubdivideStep]) -> CheckResult {
    let mut r = CheckResult::new(
        "SD-L316",
        "L312–L316: the triangles SUBDIVIDE creates lie in ∪_k st(v_k, K_{i+1})",
    );
    let mut hist = std::collections::BTreeMap::<usize, usize>::new();
    for (i, s) in steps.iter().enumerate() {
        r.examined += 1;
        *hist.entry(s.new_vertices.len()).or_default() += 1;
        if s.new_vertices.is_empty() {
            let t = s.target;
            r.offend(|| {
                Witness::new(
                    format!("call {i} on triangle {t}: no vertex inserted"),
                    json!({"call": i, "target": t}),
                )
            });
        }
        for (t, v) in &s.created {
            if !v.iter().any(|x| s.new_vertices.contains(x)) {
                let (t, v) = (*t, *v);
                r.offend(|| {
                    Witness::new(
                        format!("call {i}: created triangle {t} {v:?} has none of the new vertices {:?}", s.new_vertices),
                        json!({"call": i, "triangle": t, "vertices": v, "new": s.new_vertices}),
                    )
                });
            }
        }
    }
    let total: usize = hist.iter().map(|(k, n)| k * n).sum();
    r.note = format!(
        "{} calls, {total} vertices inserted; k (new vertices per call) → calls: {hist:?}",
        steps.len()
    );
    if r.examined == 0 {
        r.skip("no SUBDIVIDE call");
    }
    r
}
