//! The weight form of Stam's tables per valence ≠ 6 (the fit's linear path, `linear`): a
//! point's weights over its patch net from the same tabulated sub-nets as the f64 hot path
//! (`fast`).

use super::eigen::EigenStructure;
use super::fast::SubNetTable;
use super::stam::{depth_cap, regular_weights_f64, stam_tile};

/// Per valence N ≠ 6: Stam's tabulated sub-nets composed with the eigen-projection P (the
/// K × K matrix with (C_in, C_out) = P · net, K = N + 6), so a point's weights over the patch
/// net cost one 12 × K product (φᵀ · B_k Aᵐ P) instead of that plus a K × K one.
pub(super) struct LinearValence {
    /// Per (level m, sub-triangle k): B_k Aᵐ P, 12 × K row-major; m below the tabulated levels.
    sub_nets: Vec<f64>,
    /// Row 0 of P: the weights of the vertex limit (coordinate 0 of C_in).
    limit: Vec<f64>,
    pub(super) k: usize,
}

impl LinearValence {
    pub(super) fn new(es: &EigenStructure<f64>, table: &SubNetTable) -> LinearValence {
        let k = es.n + 6;
        let mut proj = vec![0.0; k * k];
        // The projection is linear: column j is the projection of the j-th unit net.
        for j in 0..k {
            let mut net = vec![[0.0; 3]; k];
            net[j][0] = 1.0;
            let (cin, cout) = es.project(&net);
            for (i, c) in cin.iter().chain(cout.iter()).enumerate() {
                proj[i * k + j] = c[0];
            }
        }
        let mut sub_nets = Vec::new();
        for m in 0.. {
            let Some(blocks) = (0..3)
                .map(|sub| table.block(sub, m))
                .collect::<Option<Vec<_>>>()
            else {
                break;
            };
            for e in blocks {
                for row in e.chunks_exact(k) {
                    let start = sub_nets.len();
                    sub_nets.resize(start + k, 0.0);
                    let out = &mut sub_nets[start..];
                    for (c, p) in row.iter().zip(proj.chunks_exact(k)) {
                        for (o, pj) in out.iter_mut().zip(p) {
                            *o += c * pj;
                        }
                    }
                }
            }
        }
        LinearValence {
            sub_nets,
            limit: proj[..k].to_vec(),
            k,
        }
    }

    /// Weights over the patch net of the point (x, y), written into `w` (length K); `None`
    /// past the tabulated levels.
    pub(super) fn weights_into(
        &self,
        basis: &[[f64; 15]; 12],
        x: f64,
        y: f64,
        w: &mut [f64],
    ) -> Option<()> {
        let (n, sub, s) = match stam_tile(&x, &y, depth_cap(53), 53) {
            None => {
                w.copy_from_slice(&self.limit);
                return Some(());
            }
            Some((n, sub, s, _)) => (n, sub, s),
        };
        let phi = regular_weights_f64(basis, s.0, s.1);
        let k = self.k;
        let base = ((n as usize - 1) * 3 + sub) * 12 * k;
        let rows = self.sub_nets.get(base..base + 12 * k)?;
        w.fill(0.0);
        for (f, row) in phi.iter().zip(rows.chunks_exact(k)) {
            for (wj, r) in w.iter_mut().zip(row) {
                *wj += f * r;
            }
        }
        Some(())
    }
}
