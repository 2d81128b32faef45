//! Parameter files (TOML) for a simplicial map on a tetrahedral complex, and the per-tetrahedron
//! maps x = (N_0, N_1, N_2, N_3) / D they define (Mello–Velho Eqs. (9)–(11) with m = 3).
//!
//! The same format as the planar `params` with points in ℝ³ and `tet = f` for a per-tetrahedron
//! override. Keys are global vertex multisets, so tetrahedra sharing a face share its control
//! points and weights by construction (Sec. 3, "share the same control parameters in its common
//! face"); an override is how a disagreement is planted.
//!
//! ```toml
//! family = "rational"       # polynomial | rational | monotonic
//! degree = 2
//! [[control]]               # unlisted control points are fixed: c_I = Σ I_i v_i / n
//! at = [0, 1]               # the multiset I of global vertex ids, |I| = degree
//! point = ["1/3", "0", "0"] # c_I in ℝ³
//! [[weight]]                # rational only; unlisted weights are 1
//! at = [0, 0]
//! q = "2"
//! [[g]]                     # monotonic only; unlisted g are g(t) = t
//! vertex = 0
//! coeffs = ["0", "1", "1/2"]
//! [iso]                     # optional: f per vertex and the level c (Sec. 4)
//! f = ["-1", "1", "1", "1"]
//! c = "0"
//! ```

use super::complex::TetComplex;
use super::maps::{bernstein4, fixed_control4, multi_indices4};
use super::poly::Poly3;
use crate::sdiff::common::params::{parse_spec, read_spec, FamilySpec, Multiset, ParamError, Spec};
use crate::sdiff::common::poly1::Poly1;
use crate::sdiff::common::rational::{q, Q};
use num_traits::Zero;
use std::path::Path;

/// Largest degree accepted in 3-D (the Jacobian numerator of Eq. (11) has degree 4n − 3).
pub(crate) const MAX_DEGREE_3D: usize = 6;

/// A parsed 3-D parameter file (the planar format with points in ℝ³, `params::Spec`).
pub type MapSpec3 = Spec<3>;

/// Which family of Sec. 3 a tetrahedron's map belongs to.
pub(crate) type Family3 = FamilySpec;

/// One map of the reference tetrahedron, x = (N_0, N_1, N_2, N_3) / D in barycentric
/// components over the chart (s, t, r) = (w_1, w_2, w_3).
#[derive(Debug, Clone)]
pub struct TetMap {
    /// The family.
    pub family: Family3,
    /// Degree n (Eqs. (10), (11)); 0 for Eq. (9).
    pub degree: usize,
    /// Control points b_I (barycentric, in ℚ⁴), indexed by `multi_indices4(degree)`.
    pub control: Vec<[Q; 4]>,
    /// Weights q_I (all 1 for Eq. (10)).
    pub weights: Vec<Q>,
    /// g_0..g_3 of Eq. (9); empty otherwise.
    pub g: Vec<Poly1>,
    /// Numerators N_0..N_3.
    pub num: [Poly3; 4],
    /// Denominator D (1 for Eq. (10)).
    pub den: Poly3,
}

impl TetMap {
    /// Eqs. (10) (`weights` = None) and (11).
    pub fn bezier(n: usize, control: Vec<[Q; 4]>, weights: Option<Vec<Q>>) -> TetMap {
        let family = if weights.is_some() {
            FamilySpec::Rational
        } else {
            FamilySpec::Polynomial
        };
        let weights = weights.unwrap_or_else(|| vec![q(1); control.len()]);
        let mut num: [Poly3; 4] = Default::default();
        let mut den = Poly3::default();
        for (k, i) in multi_indices4(n).into_iter().enumerate() {
            let b = bernstein4(i);
            for (c, nc) in num.iter_mut().enumerate() {
                let coef = &weights[k] * &control[k][c];
                if !coef.is_zero() {
                    *nc = nc.axpy(&coef, &b);
                }
            }
            den = den.axpy(&weights[k], &b);
        }
        if family == FamilySpec::Polynomial {
            den = Poly3::constant(q(1));
        }
        TetMap {
            family,
            degree: n,
            control,
            weights,
            g: Vec::new(),
            num,
            den,
        }
    }
    /// Eq. (9): x^i = g_i(w^i) / Σ_j g_j(w^j).
    pub fn monotonic(g: [Poly1; 4]) -> TetMap {
        let num: [Poly3; 4] = std::array::from_fn(|i| compose(&g[i], &Poly3::w(i)));
        let den = num
            .iter()
            .fold(Poly3::default(), |acc, x| acc.axpy(&q(1), x));
        TetMap {
            family: FamilySpec::Monotonic,
            degree: 0,
            control: Vec::new(),
            weights: Vec::new(),
            g: g.to_vec(),
            num,
            den,
        }
    }
    /// Σ_c N_c − D (the zero polynomial iff Eq. (1) holds for x).
    pub fn unity_defect(&self) -> Poly3 {
        self.num
            .iter()
            .fold(self.den.axpy(&q(-2), &self.den), |acc, x| {
                acc.axpy(&q(1), x)
            })
    }
    /// N_1..N_3 (the chart components).
    pub(crate) fn chart_num(&self) -> [Poly3; 3] {
        [
            self.num[1].clone(),
            self.num[2].clone(),
            self.num[3].clone(),
        ]
    }
}

/// g∘w as a trivariate polynomial (Horner).
pub(crate) fn compose(g: &Poly1, w: &Poly3) -> Poly3 {
    g.0.iter().rev().fold(Poly3::default(), |acc, c| {
        acc.mul(w).axpy(&q(1), &Poly3::constant(c.clone()))
    })
}

/// Reads and parses a 3-D parameter file.
pub fn read(path: &Path) -> Result<MapSpec3, ParamError> {
    read_spec(path, MAX_DEGREE_3D)
}

/// Parses the text of a 3-D parameter file (`path` only names it in errors).
pub fn parse(text: &str, path: &Path) -> Result<MapSpec3, ParamError> {
    parse_spec(text, path, MAX_DEGREE_3D)
}

impl MapSpec3 {
    /// Checks every key names vertices of the complex and a face of some tetrahedron (of the
    /// named one for an override); then builds one map per tetrahedron.
    pub fn build(&self, k: &TetComplex, path: &Path) -> Result<Vec<TetMap>, ParamError> {
        self.check_keys(path, k.points.len(), &k.tets, "tetrahedron")?;
        Ok((0..k.tets.len()).map(|f| self.map_of(k, f)).collect())
    }

    /// The global multiset of a local multi-index in tetrahedron f.
    pub(crate) fn global_key(k: &TetComplex, f: usize, i: [usize; 4]) -> Multiset {
        let t = k.tets[f];
        let mut m: Vec<u32> = (0..4)
            .flat_map(|c| std::iter::repeat(t[c]).take(i[c]))
            .collect();
        m.sort_unstable();
        m
    }

    fn map_of(&self, k: &TetComplex, f: usize) -> TetMap {
        match self.family {
            FamilySpec::Monotonic => {
                let t = k.tets[f];
                TetMap::monotonic(
                    t.map(|v| self.g.get(&v).cloned().unwrap_or_else(Poly1::identity)),
                )
            }
            FamilySpec::Polynomial | FamilySpec::Rational => {
                let n = self.degree;
                let fixed = fixed_control4(n);
                let mut control = Vec::new();
                let mut weights = Vec::new();
                for (idx, i) in multi_indices4(n).into_iter().enumerate() {
                    let key = Self::global_key(k, f, i);
                    let (c, w) = self.entry(f, key);
                    control.push(match c {
                        Some(p) => k.barycentric(f, p),
                        None => fixed[idx].clone(),
                    });
                    weights.push(w);
                }
                let weights = (self.family == FamilySpec::Rational).then_some(weights);
                TetMap::bezier(n, control, weights)
            }
        }
    }
}
