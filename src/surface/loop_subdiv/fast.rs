//! The f64 hot path of the Loop S′ (what the fit of Sec. 5.2 calls hundreds of times per
//! vertex): per patch, the net is gathered and projected onto the eigen-structure once
//! ([`FastPlan`], built on first use), so a point costs Stam's sub-net and one regular patch —
//! the same arithmetic as [`super::stam::extraordinary_jet_as`] and
//! [`super::stam::regular_point_f64`], without the generic scalar's allocations. Checked
//! against the generic path (`loop_fast_path_equals_the_generic_evaluation` in
//! `tests/surface/loop_sprime.rs`).

use super::eigen::EigenStructure;
use super::plan::split_patch_point;
use super::stam::{depth_cap, regular_point_f64, stam_tile};
use std::sync::Arc;

/// One patch, ready for f64 evaluation.
#[derive(Debug, Clone)]
pub(super) enum FastPatch {
    /// All corners of valence 6: the 12-point net of the box spline.
    Regular(Box<[[f64; 3]; 12]>),
    /// First corner of valence N ≠ 6: the net in eigen-coordinates, translated by its limit
    /// point ℓ (so the entries shrink with λ₁ᵐ, as in the generic path).
    Extraordinary {
        es: Arc<EigenStructure<f64>>,
        table: Arc<SubNetTable>,
        cin: Box<[[f64; 3]]>,
        cout: [[f64; 3]; 5],
        limit: [f64; 3],
    },
}

/// Levels below which Stam's sub-net B_k Aᵐ is tabulated (a point reaches level m within
/// 2^−m of the extraordinary vertex; deeper points use the formula directly).
const TABULATED_LEVELS: usize = 40;

/// B_k Aᵐ in eigen-coordinates as 12 × K matrices for m < [`TABULATED_LEVELS`] and the three
/// sub-triangles k, one table per valence (and per authors' model): the sub-net is linear in
/// the eigen-coordinates, so each column is [`EigenStructure::sub_net_as`] of a unit vector.
#[derive(Debug)]
pub(super) struct SubNetTable {
    k: usize,
    entries: Vec<f64>,
}

impl SubNetTable {
    pub(super) fn new(es: &EigenStructure<f64>, authors_jordan: bool) -> SubNetTable {
        let n_in = es.n + 1;
        let k = n_in + 5;
        let mut entries = vec![0.0; TABULATED_LEVELS * 3 * 12 * k];
        let zero = vec![[0.0; 3]; n_in];
        let zero_out = [[0.0; 3]; 5];
        for m in 0..TABULATED_LEVELS {
            for sub in 0..3 {
                // Three unit vectors per call, one in each coordinate (the map acts on the
                // coordinates separately): a third of the calls.
                for first in (0..k).step_by(3) {
                    let (mut cin, mut cout) = (zero.clone(), zero_out);
                    for (d, col) in (first..k.min(first + 3)).enumerate() {
                        if col < n_in {
                            cin[col][d] = 1.0;
                        } else {
                            cout[col - n_in][d] = 1.0;
                        }
                    }
                    let q = es.sub_net_as(sub, m as u64, &cin, &cout, authors_jordan);
                    for (row, qr) in q.iter().enumerate() {
                        for (d, col) in (first..k.min(first + 3)).enumerate() {
                            entries[((m * 3 + sub) * 12 + row) * k + col] = qr[d];
                        }
                    }
                }
            }
        }
        SubNetTable { k, entries }
    }

    /// B_k Aᵐ (12 × K, row-major) for sub-triangle `sub` at level m, if m is tabulated.
    pub(super) fn block(&self, sub: usize, m: usize) -> Option<&[f64]> {
        if m >= TABULATED_LEVELS || sub >= 3 {
            return None;
        }
        let base = (m * 3 + sub) * 12 * self.k;
        self.entries.get(base..base + 12 * self.k)
    }

    /// B_k Aᵐ applied to the eigen-coordinates (cin, cout), if m is tabulated.
    fn apply(
        &self,
        sub: usize,
        m: usize,
        cin: &[[f64; 3]],
        cout: &[[f64; 3]; 5],
    ) -> Option<[[f64; 3]; 12]> {
        if m >= TABULATED_LEVELS || cin.len() + 5 != self.k {
            return None;
        }
        let base = (m * 3 + sub) * 12 * self.k;
        let rows = self.entries.get(base..base + 12 * self.k)?;
        let mut q = [[0.0; 3]; 12];
        for (row, qr) in q.iter_mut().enumerate() {
            let w = &rows[row * self.k..(row + 1) * self.k];
            for (c, p) in w.iter().zip(cin.iter().chain(cout.iter())) {
                qr[0] += c * p[0];
                qr[1] += c * p[1];
                qr[2] += c * p[2];
            }
        }
        Some(q)
    }
}

/// One face: a patch (with the stored corner it starts at) or four sub-patches.
#[derive(Debug, Clone)]
pub(super) enum FastPlan {
    /// One patch; `rot` = which stored corner is its first corner.
    Direct { rot: u8, patch: FastPatch },
    /// After one internal Loop step: corner sub-triangles c₀, c₁, c₂, then the middle one.
    Split(Box<[FastPatch; 4]>),
}

impl FastPatch {
    /// The patch's net in eigen-coordinates (extraordinary) or as points (regular).
    pub(super) fn new(
        net: Vec<[f64; 3]>,
        es: Option<(Arc<EigenStructure<f64>>, Arc<SubNetTable>)>,
    ) -> Option<Self> {
        match es {
            None => Some(FastPatch::Regular(Box::new(net.try_into().ok()?))),
            Some((es, table)) => {
                let (mut cin, mut cout) = es.project(&net);
                let limit = *cin.first()?;
                cin[0] = [0.0; 3];
                for (a, ca) in cout.iter_mut().enumerate() {
                    for d in 0..3 {
                        ca[d] = if a < 3 {
                            ca[d] - limit[d]
                        } else {
                            ca[d] + limit[d]
                        };
                    }
                }
                Some(FastPatch::Extraordinary {
                    es,
                    table,
                    cin: cin.into_boxed_slice(),
                    cout: cout.try_into().ok()?,
                    limit,
                })
            }
        }
    }

    /// The point at patch coordinates (x, y), x, y ≥ 0, x + y ≤ 1.
    pub(super) fn point(
        &self,
        basis: &[[f64; 15]; 12],
        x: f64,
        y: f64,
        authors_jordan: bool,
    ) -> [f64; 3] {
        let (es, table, cin, cout, limit) = match self {
            FastPatch::Regular(net) => return regular_point_f64(basis, net, x, y),
            FastPatch::Extraordinary {
                es,
                table,
                cin,
                cout,
                limit,
            } => (es, table, cin, cout, limit),
        };
        // Stam's tile, with the generic path's cap beyond which the point is the vertex limit.
        let Some((n, k, s, _)) = stam_tile(&x, &y, depth_cap(53), 53) else {
            return *limit;
        };
        let q = match table.apply(k, (n - 1) as usize, cin, cout) {
            Some(q) => q,
            None => es.sub_net_as(k, n - 1, cin, cout, authors_jordan),
        };
        let p = regular_point_f64(basis, &q, s.0, s.1);
        [p[0] + limit[0], p[1] + limit[1], p[2] + limit[2]]
    }
}

impl FastPlan {
    /// The point at barycentric coordinates `sb` w.r.t. the stored corners.
    pub(super) fn point(
        &self,
        basis: &[[f64; 15]; 12],
        sb: [f64; 3],
        authors_jordan: bool,
    ) -> [f64; 3] {
        match self {
            FastPlan::Direct { rot, patch } => {
                let r = *rot as usize;
                patch.point(basis, sb[(r + 1) % 3], sb[(r + 2) % 3], authors_jordan)
            }
            FastPlan::Split(ps) => {
                let (j, x, y) = split_patch_point(&sb);
                ps[j].point(basis, x, y, authors_jordan)
            }
        }
    }
}
