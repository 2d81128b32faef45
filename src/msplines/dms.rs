//! Sec. 3.1.2 beyond one B-patch: the triangular B-spline (DMS, \[3\]) basis over a planar
//! triangulation with a knot cloud per vertex, F(u) = Σ_I Σ_{|β|=k} c_β^I N_β^I(u) with
//! N_β^I = |det Δ_β^I| · M(u | V_β^I), V_β^I the k+3 knots t_{i,0..β_i} of L139 and M the
//! bivariate simplex spline (Micchelli's recurrence M(u|V) = Σ_j λ_j(u) M(u|V∖w_j), λ the
//! barycentric coordinates of u in an affinely independent W = {w_0, w_1, w_2} ⊂ V; base
//! case M(u|{a,b,c}) = 1_{[a,b,c)}(u) / |det(b−a, c−a)|).
//!
//! Generic over the scalar so the same recurrence runs exactly (BigRational, the checks) and
//! in f64 (sampling a surface). The half-open triangle [a,b,c) is the closed triangle
//! perturbed by u + ε(1,0) + ε²(0,1): a point on a knot line belongs to exactly one side.

use super::polar::{multi_indices, KnotClouds, Q};
use super::poly2::Poly2;
use num_traits::{Num, One, Signed, Zero};
use std::collections::{BTreeMap, HashMap};

/// The ordered fields the recurrence runs in (BigRational, f64), with an exact orientation sign
/// so the half-open decisions are exact for the stored values in both
/// ([`crate::numeric::predicates`]): a point on a knot line then belongs to one side only,
/// consistently for every triangle having that line as an edge.
pub trait KnotField: Clone + Num + Signed + PartialOrd + std::fmt::Debug {
    /// The exact sign of det(b − a, c − a); `None` when it has none (a NaN coordinate).
    fn orient(a: &Pt<Self>, b: &Pt<Self>, c: &Pt<Self>) -> Option<std::cmp::Ordering>;
}

impl KnotField for f64 {
    fn orient(a: &Pt<f64>, b: &Pt<f64>, c: &Pt<f64>) -> Option<std::cmp::Ordering> {
        crate::numeric::predicates::orient2(*a, *b, *c)
    }
}

impl KnotField for Q {
    fn orient(a: &Pt<Q>, b: &Pt<Q>, c: &Pt<Q>) -> Option<std::cmp::Ordering> {
        Some(det(a, b, c).cmp(&Q::zero()))
    }
}

/// A point of the parameter plane.
pub type Pt<S> = [S; 2];

/// Why a basis function cannot be evaluated.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum DmsError {
    /// Δ_β^I is degenerate or all of V_β^I is collinear: N_β^I has no density in the plane
    /// (DMS require proper triangles Δ_β^I).
    #[error("triangle {triangle}, β = {beta:?}: knots {knots:?} of V_β are collinear (Δ_β degenerate or V_β on a line)")]
    Collinear {
        /// Triangle I.
        triangle: usize,
        /// β.
        beta: [usize; 3],
        /// Indices into V_β^I of Δ_β (or of the whole set).
        knots: Vec<usize>,
    },
    /// A corner has fewer than k+1 knots.
    #[error("triangle {triangle}: corner {corner} has {have} knots, degree {k} needs k+1")]
    ShortCloud {
        /// Triangle I.
        triangle: usize,
        /// Corner 0..3.
        corner: usize,
        /// Knots present.
        have: usize,
        /// Degree.
        k: usize,
    },
}

/// det(b − a, c − a).
pub fn det<S: KnotField>(a: &Pt<S>, b: &Pt<S>, c: &Pt<S>) -> S {
    crate::numeric::predicates::det2(a, b, c)
}

/// Barycentric coordinates of u in [a, b, c] (det ≠ 0 assumed by the caller).
fn bary<S: KnotField>(t: [&Pt<S>; 3], u: &Pt<S>, d: &S) -> [S; 3] {
    [
        det(u, t[1], t[2]) / d.clone(),
        det(t[0], u, t[2]) / d.clone(),
        det(t[0], t[1], u) / d.clone(),
    ]
}

/// u ∈ [a, b, c) with the perturbation u + ε(1,0) + ε²(0,1) (lexicographic sign test on
/// exact orientation signs; the perturbation's first-order terms are differences of
/// coordinates, whose signs are exact in f64 too).
///
/// A NaN knot or point cannot be placed: it is reported inside, so the base value 1/|det| (or
/// the λ_j of the recurrence) carries the NaN to the checks instead of a silent 0.
pub fn half_open_inside<S: KnotField>(t: [&Pt<S>; 3], u: &Pt<S>) -> bool {
    use std::cmp::Ordering::{Equal, Greater, Less};
    let Some(o) = S::orient(t[0], t[1], t[2]) else {
        return true;
    };
    if o == Equal {
        return false;
    }
    let cmp = |a: &S, b: &S| a.partial_cmp(b).unwrap_or(Equal);
    (0..3).all(|i| {
        // λ_i ∝ det(u, t_{i+1}, t_{i+2}); its gradient in u is (y_{i+1} − y_{i+2}, x_{i+2} − x_{i+1}).
        let (b, c) = (t[(i + 1) % 3], t[(i + 2) % 3]);
        let Some(ou) = S::orient(u, b, c) else {
            return true;
        };
        let signs = [ou, cmp(&b[1], &c[1]), cmp(&c[0], &b[0])];
        let first = signs.into_iter().find(|s| *s != Equal).unwrap_or(Equal);
        let first = if o == Less { first.reverse() } else { first };
        first == Greater
    })
}

/// A planted fault in the recurrence.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Planted {
    /// The recurrence as stated.
    #[default]
    None,
    /// Weight λ_j paired with M(u|V∖w_{j+1}) instead of M(u|V∖w_j).
    WrongWeight,
}

/// The bivariate simplex spline M(·|V) (normalised as in DMS: ∫M = 1/((n+1)(n+2))).
pub struct SimplexSpline<'a, S> {
    /// V, in general position.
    pub knots: &'a [Pt<S>],
    /// Planted fault.
    pub planted: Planted,
}

fn members(mask: u32) -> Vec<usize> {
    (0..32).filter(|i| mask & (1 << i) != 0).collect()
}

impl<S: KnotField> SimplexSpline<'_, S> {
    /// The first affinely independent triple of the subset (in index order).
    fn independent(&self, idx: &[usize]) -> Option<[usize; 3]> {
        let v = self.knots;
        for a in 0..idx.len() {
            for b in a + 1..idx.len() {
                for c in b + 1..idx.len() {
                    // A NaN triple is taken as independent so its NaN reaches the value.
                    let o = S::orient(&v[idx[a]], &v[idx[b]], &v[idx[c]]);
                    if o != Some(std::cmp::Ordering::Equal) {
                        return Some([idx[a], idx[b], idx[c]]);
                    }
                }
            }
        }
        None
    }
    /// M(u|V_mask). A collinear subset is a measure on its line; in the recurrence it is
    /// always multiplied by a λ_j that vanishes on that line (the other two points of W lie
    /// on it), so it contributes 0 — which is how three collinear knots lower the smoothness
    /// instead of breaking the evaluation.
    fn value(&self, mask: u32, u: &Pt<S>, memo: &mut HashMap<u32, S>) -> S {
        if let Some(x) = memo.get(&mask) {
            return x.clone();
        }
        let idx = members(mask);
        let v = self.knots;
        let out = if idx.len() == 3 {
            let d = det(&v[idx[0]], &v[idx[1]], &v[idx[2]]);
            if half_open_inside([&v[idx[0]], &v[idx[1]], &v[idx[2]]], u) {
                S::one() / d.abs()
            } else {
                S::zero()
            }
        } else if let Some(w) = self.independent(&idx) {
            let d = det(&v[w[0]], &v[w[1]], &v[w[2]]);
            let l = bary([&v[w[0]], &v[w[1]], &v[w[2]]], u, &d);
            let mut s = S::zero();
            for (j, lj) in l.iter().enumerate() {
                if lj.is_zero() {
                    continue;
                }
                let drop = match self.planted {
                    Planted::None => w[j],
                    Planted::WrongWeight => w[(j + 1) % 3],
                };
                s = s + lj.clone() * self.value(mask & !(1 << drop), u, memo);
            }
            s
        } else {
            S::zero()
        };
        memo.insert(mask, out.clone());
        out
    }
    /// M(u|V); Err when V itself is collinear (no density in the plane).
    pub fn at(&self, u: &Pt<S>) -> Result<S, Vec<usize>> {
        let idx: Vec<usize> = (0..self.knots.len()).collect();
        if self.independent(&idx).is_none() {
            return Err(idx);
        }
        let full = (1u32 << self.knots.len()) - 1;
        Ok(self.value(full, u, &mut HashMap::new()))
    }
}

impl SimplexSpline<'_, Q> {
    /// The polynomial that equals M(·|V) on the open cell (of the arrangement of lines through
    /// pairs of knots) containing u; u must lie on no such line.
    pub fn piece(&self, u: &Pt<Q>) -> Result<Poly2, Vec<usize>> {
        let idx: Vec<usize> = (0..self.knots.len()).collect();
        if self.independent(&idx).is_none() {
            return Err(idx);
        }
        let full = (1u32 << self.knots.len()) - 1;
        Ok(self.piece_of(full, u, &mut HashMap::new()))
    }
    fn piece_of(&self, mask: u32, u: &Pt<Q>, memo: &mut HashMap<u32, Poly2>) -> Poly2 {
        if let Some(x) = memo.get(&mask) {
            return x.clone();
        }
        let idx = members(mask);
        let v = self.knots;
        let out = if idx.len() == 3 {
            let d = det(&v[idx[0]], &v[idx[1]], &v[idx[2]]);
            let inside = !d.is_zero() && half_open_inside([&v[idx[0]], &v[idx[1]], &v[idx[2]]], u);
            Poly2::constant(if inside {
                Q::one() / d.abs()
            } else {
                Q::zero()
            })
        } else if let Some(w) = self.independent(&idx) {
            let t = [&v[w[0]], &v[w[1]], &v[w[2]]];
            let d = det(t[0], t[1], t[2]);
            let o = [Q::zero(), Q::zero()];
            let l0 = bary(t, &o, &d);
            let lx = bary(t, &[Q::one(), Q::zero()], &d);
            let ly = bary(t, &[Q::zero(), Q::one()], &d);
            let mut s = Poly2::default();
            for j in 0..3 {
                let lam = Poly2::affine(&lx[j] - &l0[j], &ly[j] - &l0[j], l0[j].clone());
                let drop = match self.planted {
                    Planted::None => w[j],
                    Planted::WrongWeight => w[(j + 1) % 3],
                };
                s = s.add(&lam.mul(&self.piece_of(mask & !(1 << drop), u, memo)));
            }
            s
        } else {
            Poly2::default()
        };
        memo.insert(mask, out.clone());
        out
    }
}

/// A triangulation of (part of) the plane with a knot cloud t_{v,0..k} per vertex
/// (t_{v,0} = the vertex), eq. (1). `overrides[(I, corner)]` replaces the cloud one triangle
/// sees at one corner (planted: a knot moved on one side only).
#[derive(Debug, Clone)]
pub struct Dms<S> {
    /// Degree k.
    pub k: usize,
    /// Knot clouds, one per vertex.
    pub clouds: Vec<Vec<Pt<S>>>,
    /// Triangles (vertex indices, positively oriented).
    pub triangles: Vec<[usize; 3]>,
    /// Per-triangle cloud replacements.
    pub overrides: BTreeMap<(usize, usize), Vec<Pt<S>>>,
    /// Planted recurrence fault.
    pub planted: Planted,
}

/// Knots of N_β^I that span no triangle.
fn collinear(triangle: usize, beta: &[usize; 3], knots: Vec<usize>) -> DmsError {
    DmsError::Collinear {
        triangle,
        beta: *beta,
        knots,
    }
}

impl<S: KnotField> Dms<S> {
    /// The cloud triangle I sees at corner c.
    pub fn corner_cloud(&self, i: usize, c: usize) -> &[Pt<S>] {
        self.overrides
            .get(&(i, c))
            .map(|v| v.as_slice())
            .unwrap_or(&self.clouds[self.triangles[i][c]])
    }
    /// V_β^I = {t_{0,0..β0}, t_{1,0..β1}, t_{2,0..β2}} (k+3 knots, L139), and the indices of
    /// Δ_β^I = [t_{0,β0}, t_{1,β1}, t_{2,β2}] in it.
    pub fn v_beta(&self, i: usize, b: &[usize; 3]) -> Result<(Vec<Pt<S>>, [usize; 3]), DmsError> {
        let mut v = Vec::new();
        let mut delta = [0; 3];
        for (c, &bc) in b.iter().enumerate() {
            let cl = self.corner_cloud(i, c);
            if cl.len() <= bc {
                return Err(DmsError::ShortCloud {
                    triangle: i,
                    corner: c,
                    have: cl.len(),
                    k: self.k,
                });
            }
            v.extend(cl[..=bc].iter().cloned());
            delta[c] = v.len() - 1;
        }
        Ok((v, delta))
    }
    /// V_β^I and the scale |det Δ_β^I| of N_β^I; a collinear Δ_β^I is an error.
    fn scaled_knots(&self, i: usize, b: &[usize; 3]) -> Result<(Vec<Pt<S>>, S), DmsError> {
        let (v, d) = self.v_beta(i, b)?;
        let scale = det(&v[d[0]], &v[d[1]], &v[d[2]]).abs();
        if scale.is_zero() {
            return Err(collinear(i, b, d.to_vec()));
        }
        Ok((v, scale))
    }
    /// N_β^I(u) = |det Δ_β^I| · M(u|V_β^I).
    pub fn basis(&self, i: usize, b: &[usize; 3], u: &Pt<S>) -> Result<S, DmsError> {
        let (v, scale) = self.scaled_knots(i, b)?;
        let m = SimplexSpline {
            knots: &v,
            planted: self.planted,
        };
        let val = m.at(u).map_err(|knots| collinear(i, b, knots))?;
        Ok(scale * val)
    }
    /// Σ_{I ∈ tris} Σ_β c(I, β)·N_β^I(u).
    pub fn eval(
        &self,
        tris: &[usize],
        c: &dyn Fn(usize, &[usize; 3]) -> S,
        u: &Pt<S>,
    ) -> Result<S, DmsError> {
        let mut s = S::zero();
        for &i in tris {
            for b in multi_indices(self.k) {
                let n = self.basis(i, &b, u)?;
                if !n.is_zero() {
                    s = s + c(i, &b) * n;
                }
            }
        }
        Ok(s)
    }
    /// Triangles whose knots' bounding box contains u (the only ones that can be non-zero at
    /// u, by the base case; a pre-filter that assumes nothing of Sec. 3.1.3(1)).
    pub fn candidates(&self, u: &Pt<S>) -> Vec<usize> {
        (0..self.triangles.len())
            .filter(|&i| {
                let pts: Vec<&Pt<S>> = (0..3).flat_map(|c| self.corner_cloud(i, c)).collect();
                (0..2).all(|a| pts.iter().any(|p| p[a] <= u[a]) && pts.iter().any(|p| p[a] >= u[a]))
            })
            .collect()
    }
}

impl Dms<Q> {
    /// The B-patch of triangle I (eq. (1)–(4)): its corner clouds as [`KnotClouds`], so the
    /// control points f(X_β^I) of Sec. 3.1.3(3) come from the same X^β as recurrence (4).
    pub fn patch(&self, i: usize) -> KnotClouds {
        KnotClouds {
            k: self.k,
            clouds: [0, 1, 2].map(|c| self.corner_cloud(i, c).to_vec()),
        }
    }
    /// The polynomial piece of N_β^I on the cell containing u.
    pub fn basis_piece(&self, i: usize, b: &[usize; 3], u: &Pt<Q>) -> Result<Poly2, DmsError> {
        let (v, scale) = self.scaled_knots(i, b)?;
        let m = SimplexSpline {
            knots: &v,
            planted: self.planted,
        };
        let p = m.piece(u).map_err(|knots| collinear(i, b, knots))?;
        Ok(p.scale(&scale))
    }
}
