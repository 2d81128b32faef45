//! S′ on one face as fixed weights over vertices of K (the fit of Sec. 5.2, tabulated).
//!
//! The Loop limit point at a parameter point is a linear combination of vertex positions of K
//! whose weights depend only on the combinatorics around the face: the valences and how the
//! rings of its corners meet. The fit samples S′ at the same barycentric points for every
//! vertex of one degree, so instead of evaluating S′ ~150 times per vertex it can apply one
//! precomputed matrix per (degree, sector, local combinatorics) to the positions
//! (`surface::pps`, the linear path). This module gives that combinatorial key and the
//! weights; the weights come from the same tables as the f64 hot path (`super::fast`) and are
//! checked against point evaluation (`loop_linear_weights_reproduce_the_limit_points` in
//! `tests/surface/loop_sprime.rs`).

use super::plan::{plan_of, split_patch_point, Patch, Plan, PointTable, Stencil};
use super::stam::regular_weights_f64;
use super::surface::LoopSurface;
use super::topology::link_from;
use crate::mesh::{FaceId, SimplicialSurface, VertexId};
use crate::surface::b_sigma::{FaceStencil, LinearTarget};

/// A point of the point table as weights over vertices of K: (vertex, weight).
fn expansion(table: &PointTable, i: u32) -> Option<Vec<(VertexId, f64)>> {
    Some(match table.stencil(i as usize).ok()?? {
        Stencil::Base => vec![(VertexId(i), 1.0)],
        Stencil::Vertex(c, r) => {
            let (wc, wr) = super::rules::vertex_weights::<f64>(r.len() as u32, 53);
            let mut e = vec![(c, wc)];
            e.extend(r.iter().map(|&x| (x, wr)));
            e
        }
        Stencil::Edge([a, b, c, d]) => vec![(a, 0.375), (b, 0.375), (c, 0.125), (d, 0.125)],
        Stencil::Unused => return None,
    })
}

impl LoopSurface {
    /// Weights over the patch net at patch coordinates (x, y), written into `w` (resized to
    /// the net's length).
    fn patch_weights(&self, patch: &Patch, x: f64, y: f64, w: &mut Vec<f64>) -> Option<()> {
        if patch.valence == 6 {
            w.clear();
            w.extend_from_slice(&regular_weights_f64(&self.basis_f64, x, y));
            return Some(());
        }
        let lin = self.linear_tables()?.get(&patch.valence)?;
        w.resize(lin.k, 0.0);
        lin.weights_into(&self.basis_f64, x, y, w)
    }
}

impl LinearTarget for LoopSurface {
    /// The union of the closed rings of the corners, each ring counter-clockwise from the
    /// next corner (in the orientation of K), numbered by first appearance from v, a, b; the
    /// key is that numbering (ring lengths and which entries coincide) and the orientation of
    /// (v, a, b). Every point of every sub-net of f (one Loop step) is a combination of these
    /// vertices, so equal keys give equal weights.
    fn stencil_into(
        &self,
        k: &SimplicialSurface,
        _f: FaceId,
        corners: [VertexId; 3],
        out: &mut FaceStencil,
    ) -> Option<()> {
        if self.authors_origin.is_some() {
            return None;
        }
        let [v, a, b] = corners;
        // third(v, a) is the entry after a in v's link (`SimplicialSurface::link`).
        let link = k.link(v);
        let ia = link.iter().position(|&x| x == a)?;
        let ccw = link[(ia + 1) % link.len()] == b;
        let order = if ccw { [v, a, b] } else { [v, b, a] };
        let FaceStencil { key, verts } = out;
        verts.clear();
        key.clear();
        verts.extend([v, a, b]);
        key.push(ccw as u32);
        for j in 0..3 {
            // The ring of order[j] from order[j + 1].
            key.push(k.degree(order[j]));
            // A ring has no repeated entry (K is simplicial), so its entries can only meet
            // the corners and the earlier rings.
            let seen = verts.len();
            for x in link_from(k, order[j], order[(j + 1) % 3])? {
                let at = match verts[..seen].iter().position(|&y| y == x) {
                    Some(p) => p,
                    None => {
                        verts.push(x);
                        verts.len() - 1
                    }
                };
                key.push(at as u32);
            }
        }
        Some(())
    }

    fn weights(
        &self,
        f: FaceId,
        corners: [VertexId; 3],
        verts: &[VertexId],
        barys: &[[f64; 3]],
    ) -> Option<Vec<f64>> {
        let stored = self.corners(f)?;
        let perm: [usize; 3] =
            std::array::from_fn(|i| corners.iter().position(|&c| c == stored[i]).unwrap_or(3));
        if perm.contains(&3) || perm[0] == perm[1] || perm[1] == perm[2] || perm[0] == perm[2] {
            return None;
        }
        let k: &SimplicialSurface = &self.topo;
        let plan = plan_of(k, f).ok()?;
        let table = PointTable {
            k,
            slots: k.vertex_slots(),
        };
        let local = |v: VertexId| verts.iter().position(|&u| u == v);
        // Each patch's net points as weights over the stencil.
        let patches: Vec<&Patch> = match &plan {
            Plan::Direct { patch, .. } => vec![patch],
            Plan::Split(ps) => ps.iter().collect(),
        };
        let mut nets: Vec<Vec<Vec<(usize, f64)>>> = Vec::with_capacity(patches.len());
        for p in &patches {
            let mut net = Vec::with_capacity(p.net.len());
            for &i in p.net.iter() {
                let e = expansion(&table, i)?;
                net.push(
                    e.into_iter()
                        .map(|(v, w)| Some((local(v)?, w)))
                        .collect::<Option<Vec<_>>>()?,
                );
            }
            nets.push(net);
        }
        let len = verts.len();
        let mut out = vec![0.0; barys.len() * len];
        let mut w = Vec::new();
        for (bary, row) in barys.iter().zip(out.chunks_mut(len)) {
            let sb = [bary[perm[0]], bary[perm[1]], bary[perm[2]]];
            let (j, x, y) = match &plan {
                Plan::Direct { rot, .. } => {
                    let r = *rot as usize;
                    (0, sb[(r + 1) % 3], sb[(r + 2) % 3])
                }
                Plan::Split(_) => split_patch_point(&sb),
            };
            self.patch_weights(patches.get(j)?, x, y, &mut w)?;
            for (wi, e) in w.iter().zip(nets.get(j)?) {
                for &(l, c) in e {
                    row[l] += wi * c;
                }
            }
        }
        out.iter().all(|x| x.is_finite()).then_some(out)
    }

    fn positions(&self) -> &[[f64; 3]] {
        &self.base
    }

    /// The per-valence weight tables (Stam's sub-nets composed with the eigen-projection).
    fn prepare(&self) {
        let _ = self.linear_tables();
    }
}
