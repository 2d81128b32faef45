//! Stam (1998), Sec. 3: the subdivision matrix A (K × K, K = N + 6) of the net around an
//! extraordinary vertex of valence N, and the picking matrices B₁, B₂, B₃ (12 × K) that give
//! the regular nets of the three sub-triangles that do not touch the extraordinary vertex.
//!
//! Derived here from the rules and the local connectivity ([`LocalMesh::patch`]), not
//! copied: every new point is the vertex or edge point of a point or edge of the old net,
//! named by its lattice position at level 1 (the patch triangle is (0,0), (1,0), (0,1) at
//! level 0; see [`super::regular`]).

use super::regular::REGULAR_NET;
use super::rules::vertex_weights;
use super::topology::{ring, LocalMesh, Topology};
use crate::numeric::Scalar;

/// A dense matrix as rows.
pub(crate) type Mat<S> = Vec<Vec<S>>;

/// The three regular sub-triangles of the patch at level 1, as level-1 lattice corners
/// (q₀, q₁, q₂): k = 1 at r₀, k = 2 the middle one (rotated by π), k = 3 at r₁. The local
/// parameter s of sub-triangle k at level n is t₁ = 2ⁿ(x, y) − (1, 0), t₂ = (1, 1) − 2ⁿ(x, y),
/// t₃ = 2ⁿ(x, y) − (0, 1) (Stam's t_{k,n}).
pub(crate) const SUB_TRIANGLES: [[(i64, i64); 3]; 3] = [
    [(1, 0), (2, 0), (1, 1)],
    [(1, 1), (0, 1), (1, 0)],
    [(0, 1), (1, 1), (0, 2)],
];

/// Net index of a level-0 lattice point of the patch net of valence n, if it has one.
fn lattice_index(n: usize, p: (i64, i64)) -> Option<usize> {
    Some(match p {
        (0, 0) => 0,
        (1, 0) => 1,
        (0, 1) => 2,
        (-1, 1) => 3,
        (1, -1) => n,
        (2, -1) => n + 1,
        (2, 0) => n + 2,
        (1, 1) => n + 3,
        (0, 2) => n + 4,
        (-1, 2) => n + 5,
        _ => return None,
    })
}

/// The Loop matrices of valence n at precision `prec`.
#[derive(Debug, Clone)]
pub struct SubdivisionMatrices<S> {
    /// Valence N.
    pub n: usize,
    /// A: new net = A · old net (K × K).
    pub a: Mat<S>,
    /// B_k: regular net of sub-triangle k = old-net combination (12 × K), k = 1, 2, 3.
    pub pick: [Mat<S>; 3],
}

struct Rows<'a> {
    mesh: &'a LocalMesh,
    n: usize,
    k: usize,
    prec: u32,
}

impl Rows<'_> {
    fn zero<S: Scalar>(&self) -> Vec<S> {
        vec![S::from_i64(0, self.prec); self.k]
    }
    /// Loop's vertex rule at net point v (its whole ring must be in the local mesh).
    fn vertex<S: Scalar>(&self, v: usize) -> Option<Vec<S>> {
        let start = self
            .mesh
            .0
            .iter()
            .find_map(|t| (0..3).find_map(|i| (t[i] == v).then_some(t[(i + 1) % 3])))?;
        let r = ring(self.mesh, v, start, self.k).ok()?;
        let (wc, wr) = vertex_weights::<S>(r.len() as u32, self.prec);
        let mut row = self.zero::<S>();
        row[v] = row[v].add(&wc);
        for x in r {
            row[x] = row[x].add(&wr);
        }
        Some(row)
    }
    /// Loop's edge rule on the edge [a, b] (both its triangles must be in the local mesh).
    fn edge<S: Scalar>(&self, a: usize, b: usize) -> Option<Vec<S>> {
        let c = self.mesh.third(a, b)?;
        let d = self.mesh.third(b, a)?;
        let mut row = self.zero::<S>();
        for (i, w) in [(a, 3), (b, 3), (c, 1), (d, 1)] {
            row[i] = row[i].add(&S::from_ratio(w, 8, self.prec));
        }
        Some(row)
    }
    /// The new point at level-1 lattice position p: a vertex point (even coordinates) or the
    /// point of the edge whose midpoint p is.
    fn lattice<S: Scalar>(&self, p: (i64, i64)) -> Option<Vec<S>> {
        if p.0 % 2 == 0 && p.1 % 2 == 0 {
            return self.vertex(lattice_index(self.n, (p.0 / 2, p.1 / 2))?);
        }
        let d = match (p.0.rem_euclid(2), p.1.rem_euclid(2)) {
            (1, 0) => (1, 0),
            (0, 1) => (0, 1),
            _ => (1, -1),
        };
        let q = ((p.0 - d.0) / 2, (p.1 - d.1) / 2);
        self.edge(
            lattice_index(self.n, q)?,
            lattice_index(self.n, (q.0 + d.0, q.1 + d.1))?,
        )
    }
}

impl<S: Scalar> SubdivisionMatrices<S> {
    /// A and B₁..₃ for valence n ≥ 3. `None` only if the derivation meets a point outside the
    /// net (a bug; the tests build every valence 3..=64).
    pub fn new(n: usize, prec: u32) -> Option<Self> {
        if n < 3 {
            return None;
        }
        let mesh = LocalMesh::patch(n);
        let k = n + 6;
        let rows = Rows {
            mesh: &mesh,
            n,
            k,
            prec,
        };
        let mut a = Vec::with_capacity(k);
        a.push(rows.vertex(0)?);
        for i in 0..n {
            a.push(rows.edge(0, 1 + i)?);
        }
        for &(x, y) in &REGULAR_NET[7..] {
            a.push(rows.lattice((x, y))?);
        }
        let pick = SUB_TRIANGLES.map(|[q0, q1, q2]| {
            REGULAR_NET
                .iter()
                .map(|&(x, y)| {
                    rows.lattice((
                        q0.0 + x * (q1.0 - q0.0) + y * (q2.0 - q0.0),
                        q0.1 + x * (q1.1 - q0.1) + y * (q2.1 - q0.1),
                    ))
                })
                .collect::<Option<Mat<S>>>()
        });
        let [p1, p2, p3] = pick;
        Some(SubdivisionMatrices {
            n,
            a,
            pick: [p1?, p2?, p3?],
        })
    }
}

/// C = A·B for dense matrices.
pub(crate) fn matmul<S: Scalar>(a: &Mat<S>, b: &Mat<S>, prec: u32) -> Mat<S> {
    let cols = b.first().map_or(0, |r| r.len());
    a.iter()
        .map(|ra| {
            (0..cols)
                .map(|j| {
                    ra.iter()
                        .zip(b)
                        .fold(S::from_i64(0, prec), |s, (x, rb)| s.add(&x.mul(&rb[j])))
                })
                .collect()
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::surface::loop_subdiv::topology::gather_net;

    #[test]
    fn loop_eigen_local_net_and_subdivision_rows_sum_to_one() {
        for n in 3..=64usize {
            let mesh = LocalMesh::patch(n);
            let net = gather_net(&mesh, 0, 1, 2, 1000).expect("net");
            assert_eq!(net, (0..n + 6).collect::<Vec<_>>(), "n = {n}");
            let m = SubdivisionMatrices::<f64>::new(n, 53).expect("matrices");
            for row in m.a.iter().chain(m.pick.iter().flatten()) {
                let s: f64 = row.iter().sum();
                assert!((s - 1.0).abs() < 1e-14, "n = {n}: row sum {s}");
            }
            // The ring block does not see the outer points (block lower-triangular A).
            for row in &m.a[..=n] {
                assert!(row[n + 1..].iter().all(|&x| x == 0.0));
            }
        }
    }
}
