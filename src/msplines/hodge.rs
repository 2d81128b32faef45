//! Sec. 5.2 step (4) and Def. 10: the conjugate forms ∗h (Hodge star, "rotate ω_x about the
//! normal by a right angle", Sec. 3.4.2) and the holomorphic 1-forms ω = h + i∗h.
//!
//! On a face f a closed 1-form h is the constant vector g_f(h) in the plane of f with
//! ⟨g_f(h), x_j − x_i⟩ = h[v_i, v_j]. The rotated field n_f × g_f(h) is not a closed discrete
//! form, so ∗h_k is its L² projection onto the harmonic space: ∗h_k = Σ_m Λ_km h_m with
//! G Λ_k = (Σ_f A_f ⟨g_f(h_l), n_f × g_f(h_k)⟩)_l and G_lm = Σ_f A_f ⟨g_f(h_l), g_f(h_m)⟩.

use super::cochain::{face_halfedges, EdgeIndex};
use crate::mesh::{FaceId, SimplicialSurface};
use nalgebra::DMatrix;

type V3 = [f64; 3];

use crate::numeric::vec3::{cross, dot, sub};

/// Geometry of one face: edge vectors e1 = x1 − x0, e2 = x2 − x0, unit normal, area.
#[derive(Debug, Clone, Copy)]
pub(crate) struct FaceFrame {
    e1: V3,
    e2: V3,
    /// Unit normal (orientation of the face).
    pub n: V3,
    /// Area.
    pub area: f64,
}

impl FaceFrame {
    /// The frame of face f.
    pub(crate) fn new(k: &SimplicialSurface, f: FaceId) -> Self {
        let [a, b, c] = k.face(f).map(|v| k.position(v));
        let (e1, e2) = (sub(b, a), sub(c, a));
        let cr = cross(e1, e2);
        let len = dot(cr, cr).sqrt();
        FaceFrame {
            e1,
            e2,
            n: [cr[0] / len, cr[1] / len, cr[2] / len],
            area: 0.5 * len,
        }
    }
    /// g_f: the in-plane vector with ⟨g, e1⟩ = a01 and ⟨g, e2⟩ = a02.
    pub(crate) fn gradient(&self, a01: f64, a02: f64) -> V3 {
        let (g11, g12, g22) = (
            dot(self.e1, self.e1),
            dot(self.e1, self.e2),
            dot(self.e2, self.e2),
        );
        let det = g11 * g22 - g12 * g12;
        let s = (g22 * a01 - g12 * a02) / det;
        let t = (g11 * a02 - g12 * a01) / det;
        [
            s * self.e1[0] + t * self.e2[0],
            s * self.e1[1] + t * self.e2[1],
            s * self.e1[2] + t * self.e2[2],
        ]
    }
    /// n × g.
    pub(crate) fn rotate(&self, g: V3) -> V3 {
        cross(self.n, g)
    }
}

/// g_f(form) from the stored values ω\[v0,v1\] and −ω\[v2,v0\] = ω\[v0,v2\].
pub(crate) fn face_vector(ei: &EdgeIndex, fr: &FaceFrame, form: &[f64], f: FaceId) -> V3 {
    let [h01, _, h20] = face_halfedges(f);
    fr.gradient(ei.eval(form, h01), -ei.eval(form, h20))
}

/// The conjugate basis and its diagnostics.
#[derive(Debug, Clone)]
pub struct Conjugate {
    /// Λ: ∗h_k = Σ_m Λ\[k\]\[m\] h_m.
    pub lambda: Vec<Vec<f64>>,
    /// ∗h_k per edge.
    pub star: Vec<Vec<f64>>,
    /// Per-edge magnitude bound Σ_m |Λ_km||h_m| (+ the inputs' own), for rounding tolerances.
    pub star_magnitude: Vec<Vec<f64>>,
    /// max |Λ² + I| entry (∗∗ = −1 in the smooth theory).
    pub star_star_defect: f64,
    /// Area-weighted relative L² Cauchy–Riemann defect of each ω_k: ‖g(∗h) − n×g(h)‖/‖g(h)‖.
    pub cr_defect: Vec<f64>,
    /// Condition number of the Gram matrix G.
    pub gram_condition: f64,
}

/// Compute ∗h_k for every harmonic basis form.
pub(crate) fn conjugate(
    k: &SimplicialSurface,
    ei: &EdgeIndex,
    h: &[Vec<f64>],
    h_mag: &[Vec<f64>],
) -> Conjugate {
    let m = h.len();
    let mut gram = DMatrix::<f64>::zeros(m, m);
    let mut rot = DMatrix::<f64>::zeros(m, m);
    let frames: Vec<FaceFrame> = k.faces().map(|f| FaceFrame::new(k, f)).collect();
    for f in k.faces() {
        let fr = &frames[f.idx()];
        let g: Vec<V3> = h.iter().map(|form| face_vector(ei, fr, form, f)).collect();
        let ng: Vec<V3> = g.iter().map(|&x| fr.rotate(x)).collect();
        for l in 0..m {
            for c in 0..m {
                gram[(l, c)] += fr.area * dot(g[l], g[c]);
                rot[(l, c)] += fr.area * dot(g[l], ng[c]);
            }
        }
    }
    let sv = gram.clone().singular_values();
    let gram_condition = sv.max() / sv.min();
    // Column k of G⁻¹R holds Λ_k.
    let sol = gram
        .clone()
        .lu()
        .solve(&rot)
        .unwrap_or_else(|| DMatrix::from_element(m, m, f64::NAN));
    let lambda: Vec<Vec<f64>> = (0..m)
        .map(|kk| (0..m).map(|mm| sol[(mm, kk)]).collect())
        .collect();
    let ne = ei.len();
    let mut star = vec![vec![0.0; ne]; m];
    let mut star_magnitude = vec![vec![0.0; ne]; m];
    for kk in 0..m {
        for mm in 0..m {
            let l = lambda[kk][mm];
            for e in 0..ne {
                star[kk][e] += l * h[mm][e];
                star_magnitude[kk][e] += l.abs() * (h[mm][e].abs() + h_mag[mm][e]);
            }
        }
    }
    let lm = DMatrix::from_fn(m, m, |a, b| lambda[a][b]);
    let sq = &lm * &lm + DMatrix::<f64>::identity(m, m);
    let star_star_defect =
        sq.iter().fold(
            0.0f64,
            |a, &x| if x.is_nan() { f64::NAN } else { a.max(x.abs()) },
        );
    let cr_defect = (0..m)
        .map(|kk| {
            let (mut num, mut den) = (0.0, 0.0);
            for f in k.faces() {
                let fr = &frames[f.idx()];
                let gx = face_vector(ei, fr, &h[kk], f);
                let gy = face_vector(ei, fr, &star[kk], f);
                let d = sub(gy, fr.rotate(gx));
                num += fr.area * dot(d, d);
                den += fr.area * dot(gx, gx);
            }
            (num / den).sqrt()
        })
        .collect();
    Conjugate {
        lambda,
        star,
        star_magnitude,
        star_star_defect,
        cr_defect,
        gram_condition,
    }
}

/// A holomorphic 1-form ω = ω_x + iω_y stored per edge (Sec. 6.1: half-edge → ℝ²).
#[derive(Debug, Clone)]
pub struct OneForm {
    /// ω_x per edge.
    pub x: Vec<f64>,
    /// ω_y per edge.
    pub y: Vec<f64>,
    /// Per-edge magnitude bounds of the inputs of x and y (rounding tolerances).
    pub mag: Vec<f64>,
}

impl OneForm {
    /// ω\[h\] ∈ ℝ².
    pub fn at(&self, ei: &EdgeIndex, h: crate::mesh::HalfedgeId) -> [f64; 2] {
        [ei.eval(&self.x, h), ei.eval(&self.y, h)]
    }
    /// c·ω for a complex c = (re, im): (a + ib)(x + iy).
    pub fn scaled(&self, c: [f64; 2]) -> OneForm {
        let x = self
            .x
            .iter()
            .zip(&self.y)
            .map(|(x, y)| c[0] * x - c[1] * y)
            .collect();
        let y = self
            .x
            .iter()
            .zip(&self.y)
            .map(|(x, y)| c[1] * x + c[0] * y)
            .collect();
        let s = c[0].abs() + c[1].abs();
        OneForm {
            x,
            y,
            mag: self.mag.iter().map(|m| s * m).collect(),
        }
    }
    /// The complex conjugate ω̄ = ω_x − iω_y (anti-holomorphic: a planted fault).
    pub fn conjugated(&self) -> OneForm {
        OneForm {
            x: self.x.clone(),
            y: self.y.iter().map(|v| -v).collect(),
            mag: self.mag.clone(),
        }
    }
}
