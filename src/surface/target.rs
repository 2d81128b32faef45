//! Sec. 5.1: the surface S′ = ∪_σ b_σ(Δ) that the parametrizations approximate.
//!
//! The construction only needs b_σ at barycentric coordinates of σ ([`TargetSurface::eval`]);
//! S′ is pluggable (a Loop-surface evaluator, Sec. 6.2, implements the same trait). The one
//! provided is the PN-triangle surface of Vlachos, Peters, Boyd and Mitchell (2001), the first
//! choice of Sec. 6.2.
//!
//! Common affine frame Δ: barycentric coordinates. A point r = λa + νb + ηc of Δ = [a, b, c]
//! is identified with (λ, ν, η), with a, b, c the images of the corners of σ in the order the
//! caller names them; b_σ does not depend on that order.

pub use super::b_sigma::{FaceStencil, LinearTarget, TargetSurface};
use super::profile::{NormalRule, Profile};
use crate::mesh::{FaceId, SimplicialSurface, VertexId};
use crate::numeric::vec3::{cross, dot, norm, sub};
use crate::numeric::Scalar;

/// Order of the 10 control points of a cubic Bézier triangle: exponents (i, j, k), i + j + k
/// = 3, of the Bernstein polynomial 3!/(i!j!k!) λ^i ν^j η^k for corners (c₀, c₁, c₂).
pub const CUBIC_ORDER: [[u8; 3]; 10] = [
    [3, 0, 0],
    [0, 3, 0],
    [0, 0, 3],
    [2, 1, 0],
    [1, 2, 0],
    [0, 2, 1],
    [0, 1, 2],
    [1, 0, 2],
    [2, 0, 1],
    [1, 1, 1],
];

/// The 10 cubic Bernstein polynomials at barycentric coordinates (λ, ν, η), in [`CUBIC_ORDER`].
/// Generic over the scalar so that jets give the derivatives of b_σ (normals and curvature of
/// S′ for `ppm render`).
pub fn cubic_bernstein<S: Scalar>(b: [S; 3]) -> [S; 10] {
    let [l, n, e] = b;
    let prec = l.precision_bits();
    let (three, six) = (S::from_i64(3, prec), S::from_i64(6, prec));
    let (ll, nn, ee) = (l.mul(&l), n.mul(&n), e.mul(&e));
    [
        ll.mul(&l),
        nn.mul(&n),
        ee.mul(&e),
        three.mul(&ll).mul(&n),
        three.mul(&l).mul(&nn),
        three.mul(&nn).mul(&e),
        three.mul(&n).mul(&ee),
        three.mul(&l).mul(&ee),
        three.mul(&ll).mul(&e),
        six.mul(&l).mul(&n).mul(&e),
    ]
}

/// PN triangles (Vlachos et al. 2001) from vertex normals.
///
/// **Normal rule** ([`NormalRule`]; the paper profile's default): the normal of vertex v is the angle-weighted average of the unit normals
/// of the faces around v (Thürmer & Wüthrich 1998), face normals taken in the consistent
/// orientation of K, normalised. (Angle weighting makes the normal independent of how a flat
/// region is triangulated.) A vertex whose weighted sum vanishes gets the unweighted sum, and
/// failing that (0, 0, 1); `degenerate_normals` counts them.
///
/// Control points for corners P₁, P₂, P₃ with normals N₁, N₂, N₃ (w_ij = (P_j − P_i)·N_i):
/// b₃₀₀ = P₁, b₂₁₀ = (2P₁ + P₂ − w₁₂N₁)/3, …, E = mean of the six edge points,
/// V = (P₁ + P₂ + P₃)/3, b₁₁₁ = E + (E − V)/2. Each boundary curve depends only on its
/// edge's endpoints and normals, so S′ is C⁰ (Sec. 5.1 requires at least that).
#[derive(Debug, Clone)]
pub struct PnTriangles {
    positions: Vec<[f64; 3]>,
    normals: Vec<[f64; 3]>,
    /// Vertices of K with no usable normal (every incident face degenerate); they get (0, 0, 1).
    pub degenerate_normals: usize,
}

impl PnTriangles {
    /// The PN-triangle surface of K: vertex normals are angle-weighted face normals (plain
    /// face-normal sums as a fallback).
    pub fn new(k: &SimplicialSurface) -> Self {
        Self::with_rule(k, NormalRule::AngleWeighted)
    }

    /// The PN-triangle surface of K under a profile (its [`Profile::normal_rule`]).
    pub fn for_profile(k: &SimplicialSurface, profile: Profile) -> Self {
        Self::with_rule(k, profile.normal_rule())
    }

    /// The PN-triangle surface of K with the given vertex-normal rule. With
    /// [`NormalRule::PlainMean`] (the authors' code) the normal is the mean of the unit face
    /// normals, normalised; the weighted sum is then never used.
    pub fn with_rule(k: &SimplicialSurface, rule: NormalRule) -> Self {
        let n = k.vertex_slots();
        let positions: Vec<[f64; 3]> = (0..n).map(|i| k.position(VertexId(i as u32))).collect();
        let mut acc = vec![[0.0; 3]; n];
        let mut plain = vec![[0.0; 3]; n];
        for f in k.faces() {
            let c = k.face(f);
            let p = c.map(|v| positions[v.idx()]);
            let nf = cross(sub(p[1], p[0]), sub(p[2], p[0]));
            let len = norm(nf);
            if len == 0.0 || !len.is_finite() {
                continue;
            }
            let nf = nf.map(|x| x / len);
            for t in 0..3 {
                let e1 = sub(p[(t + 1) % 3], p[t]);
                let e2 = sub(p[(t + 2) % 3], p[t]);
                let cosang = dot(e1, e2) / (norm(e1) * norm(e2));
                let ang = cosang.clamp(-1.0, 1.0).acos();
                let v = c[t].idx();
                for d in 0..3 {
                    acc[v][d] += ang * nf[d];
                    plain[v][d] += nf[d];
                }
            }
        }
        let mut degenerate = 0;
        let normals = (0..n)
            .map(|v| {
                let cands = match rule {
                    NormalRule::AngleWeighted => [acc[v], plain[v]],
                    NormalRule::PlainMean => [plain[v], plain[v]],
                };
                for cand in cands {
                    let l = norm(cand);
                    if l > 0.0 && l.is_finite() {
                        return cand.map(|x| x / l);
                    }
                }
                if k.contains(VertexId(v as u32)) {
                    degenerate += 1;
                }
                [0.0, 0.0, 1.0]
            })
            .collect();
        PnTriangles {
            positions,
            normals,
            degenerate_normals: degenerate,
        }
    }

    /// The vertex normal of v (the rule above).
    pub fn normal(&self, v: VertexId) -> [f64; 3] {
        self.normals[v.idx()]
    }

    /// The PN control net for corners (c₀, c₁, c₂) in [`CUBIC_ORDER`].
    pub fn net(&self, corners: [VertexId; 3]) -> [[f64; 3]; 10] {
        let p = corners.map(|v| self.positions[v.idx()]);
        let n = corners.map(|v| self.normals[v.idx()]);
        let edge = |i: usize, j: usize| -> [f64; 3] {
            let w = dot(sub(p[j], p[i]), n[i]);
            std::array::from_fn(|d| (2.0 * p[i][d] + p[j][d] - w * n[i][d]) / 3.0)
        };
        let b210 = edge(0, 1);
        let b120 = edge(1, 0);
        let b021 = edge(1, 2);
        let b012 = edge(2, 1);
        let b102 = edge(2, 0);
        let b201 = edge(0, 2);
        let e: [f64; 3] = std::array::from_fn(|d| {
            (b210[d] + b120[d] + b021[d] + b012[d] + b102[d] + b201[d]) / 6.0
        });
        let v: [f64; 3] = std::array::from_fn(|d| (p[0][d] + p[1][d] + p[2][d]) / 3.0);
        let b111: [f64; 3] = std::array::from_fn(|d| e[d] + (e[d] - v[d]) / 2.0);
        [p[0], p[1], p[2], b210, b120, b021, b012, b102, b201, b111]
    }
}

/// Σ_j B_j(bary) c_j for a cubic net in [`CUBIC_ORDER`] (generic: jets give derivatives).
pub fn eval_cubic<S: Scalar>(net: &[[f64; 3]; 10], bary: [S; 3]) -> [S; 3] {
    let prec = bary[0].precision_bits();
    let b = cubic_bernstein(bary);
    let mut r: [S; 3] = std::array::from_fn(|_| S::from_i64(0, prec));
    for (bj, cj) in b.iter().zip(net) {
        for d in 0..3 {
            r[d] = r[d].add(&bj.mul(&S::from_f64(cj[d], prec)));
        }
    }
    r
}

/// [`eval_cubic`] in any scalar (the oracle's S′ in MPFR): the net's f64 control points are
/// exact in `S`, so the difference from the f64 value is the rounding of the evaluation.
pub fn eval_cubic_in<S: crate::numeric::Scalar>(
    net: &[[f64; 3]; 10],
    bary: &[S; 3],
    prec: u32,
) -> [S; 3] {
    let mut r = [0, 1, 2].map(|_| S::from_i64(0, prec));
    for (e, cj) in CUBIC_ORDER.iter().zip(net) {
        // 3!/(i!j!k!) λ^i ν^j η^k
        let coef = match e.iter().filter(|&&x| x > 0).count() {
            1 => 1,
            2 => 3,
            _ => 6,
        };
        let mut b = S::from_i64(coef, prec);
        for (x, &n) in bary.iter().zip(e) {
            for _ in 0..n {
                b = b.mul(x);
            }
        }
        for d in 0..3 {
            r[d] = r[d].add(&b.mul(&S::from_f64(cj[d], prec)));
        }
    }
    r
}

impl TargetSurface for PnTriangles {
    fn name(&self) -> &str {
        "pn-triangles"
    }
    fn eval(&self, _f: FaceId, corners: [VertexId; 3], bary: [f64; 3]) -> [f64; 3] {
        eval_cubic(&self.net(corners), bary)
    }
    fn cubic_net(&self, _f: FaceId, corners: [VertexId; 3]) -> Option<[[f64; 3]; 10]> {
        Some(self.net(corners))
    }
}

/// Which S′ the construction approximates (Sec. 6.2 builds every experiment with both).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum SurfaceKind {
    /// PN triangles (Vlachos et al. 2001), the default.
    #[default]
    Pn,
    /// The Loop subdivision limit surface, evaluated exactly (Stam 1998).
    Loop,
}

impl SurfaceKind {
    /// The name used on the command line and in reports: `pn`, `loop`.
    pub fn name(self) -> &'static str {
        match self {
            SurfaceKind::Pn => "pn",
            SurfaceKind::Loop => "loop",
        }
    }
    /// Inverse of [`SurfaceKind::name`].
    pub fn parse(s: &str) -> Option<SurfaceKind> {
        match s {
            "pn" => Some(SurfaceKind::Pn),
            "loop" => Some(SurfaceKind::Loop),
            _ => None,
        }
    }
}

/// S′ of the chosen kind, built for K.
#[derive(Debug)]
pub enum SPrime {
    /// PN triangles.
    Pn(PnTriangles),
    /// The Loop limit surface.
    Loop(Box<crate::surface::loop_subdiv::LoopSurface>),
}

impl SPrime {
    /// S′ of kind `kind` for K; the Loop surface fails only for a valence above
    /// [`crate::surface::loop_subdiv::MAX_VALENCE`] (or a K that is not closed).
    pub fn new(
        kind: SurfaceKind,
        k: &SimplicialSurface,
    ) -> Result<SPrime, crate::surface::loop_subdiv::LoopError> {
        Ok(match kind {
            SurfaceKind::Pn => SPrime::Pn(PnTriangles::new(k)),
            SurfaceKind::Loop => {
                SPrime::Loop(Box::new(crate::surface::loop_subdiv::LoopSurface::new(k)?))
            }
        })
    }
    /// As [`SPrime::new`], with what `profile` evaluates: for PN its vertex-normal rule (the
    /// authors' code averages unit face normals; see [`PnTriangles::for_profile`]); for Loop,
    /// with `authors-code`, their evaluator's corner clamp
    /// ([`crate::surface::loop_subdiv::LoopSurface::with_authors_corner_clamp`]).
    pub fn for_profile(
        kind: SurfaceKind,
        k: &SimplicialSurface,
        profile: Profile,
    ) -> Result<SPrime, crate::surface::loop_subdiv::LoopError> {
        Ok(match kind {
            SurfaceKind::Pn => SPrime::Pn(PnTriangles::for_profile(k, profile)),
            SurfaceKind::Loop => {
                let l = crate::surface::loop_subdiv::LoopSurface::new(k)?;
                SPrime::Loop(Box::new(match profile {
                    Profile::Paper => l,
                    Profile::AuthorsCode => l.with_authors_corner_clamp(k),
                }))
            }
        })
    }
    /// Its kind.
    pub fn kind(&self) -> SurfaceKind {
        match self {
            SPrime::Pn(_) => SurfaceKind::Pn,
            SPrime::Loop(_) => SurfaceKind::Loop,
        }
    }
    /// As the trait the construction uses.
    pub fn as_target(&self) -> &dyn TargetSurface {
        match self {
            SPrime::Pn(p) => p,
            SPrime::Loop(l) => l.as_ref(),
        }
    }
}
