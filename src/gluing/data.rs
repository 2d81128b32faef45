//! The abstract set of gluing data of Def. 3.4.1, as a small trait that every backend implements
//! (the exact 1-D backend here, the stereographic atlas, later the Ch. 4 mesh construction).
//!
//! **Index convention (kept literally from the paper).** For a pair (i, j) ∈ I × I the gluing
//! domain Ω_ij is a subset of the p-domain Ω_i, and the transition function
//! φ_ji : Ω_ij → Ω_ji goes *from* Ω_ij *to* Ω_ji. Hence [`GluingData::phi`]`(j, i, p)` takes a
//! point p ∈ Ω_ij (the second index names the source domain) and returns φ_ji(p) ∈ Ω_ji.

use rand_chacha::ChaCha8Rng;

/// Index of a p-domain (an element of the countable index set I).
pub type Idx = u32;

/// A point of ℝᴺ with scalar type `S`.
pub type Point<S, const N: usize> = [S; N];

/// Def. 3.4.1: a set of gluing data G = ((Ω_i)_{i∈I}, (Ω_ij)_{(i,j)∈I×I}, (φ_ji)_{(i,j)∈K}) in
/// ℝᴺ over the scalar type `Self::S`. Only membership, evaluation and sampling are required, so
/// the sampled checkers in [`crate::gluing::sampled`] work for any implementor.
pub trait GluingData<const N: usize> {
    /// The scalar type of the coordinates.
    type S: num_traits::Float + std::fmt::Debug;

    /// Def. 3.4.1: the index set I (finite here; must be non-empty for a valid set of data).
    fn indices(&self) -> Vec<Idx>;

    /// Def. 3.4.1(1): p ∈ Ω_i.
    fn in_p_domain(&self, i: Idx, p: &Point<Self::S, N>) -> bool;

    /// Def. 3.4.1(2): p ∈ Ω_ij (a subset of Ω_i).
    fn in_gluing_domain(&self, i: Idx, j: Idx, p: &Point<Self::S, N>) -> bool;

    /// Def. 3.4.1(3): the transition function φ_ji : Ω_ij → Ω_ji evaluated at p ∈ Ω_ij.
    /// Note the order of the arguments: `phi(j, i, p)` maps *from* Ω_ij *to* Ω_ji. Returns
    /// `None` when p ∉ Ω_ij (φ_ji is undefined there).
    fn phi(&self, j: Idx, i: Idx, p: &Point<Self::S, N>) -> Option<Point<Self::S, N>>;

    /// Seeded samples of Ω_i: uniform plus near-boundary points. Empty iff Ω_i = ∅.
    fn sample_p_domain(&self, i: Idx, rng: &mut ChaCha8Rng, n: usize) -> Vec<Point<Self::S, N>>;

    /// Seeded samples of Ω_ij: uniform plus near-boundary points. Empty iff Ω_ij = ∅, so the
    /// set K of Def. 3.4.1(3) is `{(i, j) | !sample_gluing_domain(i, j, ..).is_empty()}`.
    fn sample_gluing_domain(
        &self,
        i: Idx,
        j: Idx,
        rng: &mut ChaCha8Rng,
        n: usize,
    ) -> Vec<Point<Self::S, N>>;

    /// Samples of ∂(Ω_ij) ∩ Ω_i, the points condition (4) of Def. 3.4.1 speaks about.
    fn gluing_boundary_points(
        &self,
        i: Idx,
        j: Idx,
        rng: &mut ChaCha8Rng,
        n: usize,
    ) -> Vec<Point<Self::S, N>>;

    /// Characteristic size of the data (used to scale tolerances and search radii).
    fn scale(&self) -> f64 {
        1.0
    }

    /// Error amplification of the transition maps: a bound on how much a composition of two
    /// transitions (φ_ij∘φ_ji, φ_kj∘φ_ji) magnifies the rounding error of its input. The
    /// equation checks of 3(a)–3(c) multiply their tolerance 64·ε·|value| by it. 1 for maps
    /// that are (near-)isometries, as the 1-D affine data with |a| ≤ 1 and the stereographic
    /// charts away from the poles.
    fn amplification(&self) -> f64 {
        1.0
    }
}

/// Boxed gluing data (a construction's view chosen at run time, as
/// `surface::smooth::SmoothSurface::gluing_view` returns it) are gluing data: every method
/// forwards, so the sampled checkers take the box as they take the view.
impl<G: GluingData<N> + ?Sized, const N: usize> GluingData<N> for Box<G> {
    type S = G::S;
    fn indices(&self) -> Vec<Idx> {
        (**self).indices()
    }
    fn in_p_domain(&self, i: Idx, p: &Point<Self::S, N>) -> bool {
        (**self).in_p_domain(i, p)
    }
    fn in_gluing_domain(&self, i: Idx, j: Idx, p: &Point<Self::S, N>) -> bool {
        (**self).in_gluing_domain(i, j, p)
    }
    fn phi(&self, j: Idx, i: Idx, p: &Point<Self::S, N>) -> Option<Point<Self::S, N>> {
        (**self).phi(j, i, p)
    }
    fn sample_p_domain(&self, i: Idx, rng: &mut ChaCha8Rng, n: usize) -> Vec<Point<Self::S, N>> {
        (**self).sample_p_domain(i, rng, n)
    }
    fn sample_gluing_domain(
        &self,
        i: Idx,
        j: Idx,
        rng: &mut ChaCha8Rng,
        n: usize,
    ) -> Vec<Point<Self::S, N>> {
        (**self).sample_gluing_domain(i, j, rng, n)
    }
    fn gluing_boundary_points(
        &self,
        i: Idx,
        j: Idx,
        rng: &mut ChaCha8Rng,
        n: usize,
    ) -> Vec<Point<Self::S, N>> {
        (**self).gluing_boundary_points(i, j, rng, n)
    }
    fn scale(&self) -> f64 {
        (**self).scale()
    }
    fn amplification(&self) -> f64 {
        (**self).amplification()
    }
}

/// Euclidean distance, in f64.
pub fn dist<S: num_traits::Float, const N: usize>(a: &Point<S, N>, b: &Point<S, N>) -> f64 {
    a.iter()
        .zip(b.iter())
        .map(|(x, y)| {
            let d = (*x - *y).to_f64().unwrap_or(f64::NAN);
            d * d
        })
        .sum::<f64>()
        .sqrt()
}

/// Euclidean norm, in f64.
pub fn norm<S: num_traits::Float, const N: usize>(a: &Point<S, N>) -> f64 {
    a.iter()
        .map(|x| {
            let d = x.to_f64().unwrap_or(f64::NAN);
            d * d
        })
        .sum::<f64>()
        .sqrt()
}

/// Render a point for witnesses.
pub(crate) fn fmt_point<S: num_traits::Float, const N: usize>(p: &Point<S, N>) -> String {
    let v: Vec<String> = p
        .iter()
        .map(|x| format!("{}", x.to_f64().unwrap_or(f64::NAN)))
        .collect();
    if N == 1 {
        v.join("")
    } else {
        format!("({})", v.join(", "))
    }
}

/// Point as a JSON array of f64.
pub(crate) fn point_json<S: num_traits::Float, const N: usize>(
    p: &Point<S, N>,
) -> serde_json::Value {
    serde_json::Value::from(
        p.iter()
            .map(|x| x.to_f64().unwrap_or(f64::NAN))
            .collect::<Vec<f64>>(),
    )
}

/// f64 → scalar (0 if unrepresentable, which no finite f64 is for f32/f64).
pub fn from_f64<S: num_traits::Float>(v: f64) -> S {
    <S as num_traits::NumCast>::from(v).unwrap_or_else(S::zero)
}

/// scalar → f64 (NaN if unrepresentable).
pub fn to_f64<S: num_traits::Float>(v: S) -> f64 {
    <S as num_traits::ToPrimitive>::to_f64(&v).unwrap_or(f64::NAN)
}
