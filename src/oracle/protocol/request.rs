//! The requests of the `ppm oracle` protocol (one JSON object per line; docs/oracle.md).

use serde::{Deserialize, Serialize};
use std::path::PathBuf;

/// Largest accepted MPFR precision (bounded time and memory per request): the end of the one
/// precision limit [`crate::numeric::PREC_BITS`].
pub const MAX_BITS: u32 = *crate::numeric::PREC_BITS.end();

/// Membership test for Ω_uw.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum MemberTest {
    /// Def. 4.1.9 literally (the reference).
    #[default]
    Literal,
    /// The canonical-lens test of Sec. 6.1.3 (differs for degree ≥ 11, SPEC.md `D4.1.9-lens`).
    Lens,
}

/// One request of the protocol (`{"op": "...", ...}`); `id` (any JSON) is echoed back.
#[derive(Debug, Clone, Deserialize, Serialize, PartialEq)]
#[serde(tag = "op", rename_all = "snake_case", deny_unknown_fields)]
pub enum Request {
    /// Load and validate a mesh; later queries refer to its vertex ids (file indices). A
    /// fitted-surface file (`ppm fit -o`, docs/fit-format.md) loads its base mesh, and later
    /// `eval` requests answer for the fitted surface (until `set_construction` or another
    /// `load`).
    Load {
        /// Mesh file (OFF, OBJ or PLY) or fitted-surface file.
        path: PathBuf,
    },
    /// Read a certificate (`ppm certify`): later `phi` answers of the edge configurations it
    /// bounds carry `info.f64_error_bound`, its proven bound on |f64 − exact| (SPEC
    /// `CERT-f64-rounding`), and `member` answers `info.f64_decision_margin` (SPEC
    /// `CERT-f64-props`).
    SetCertificate {
        /// Certificate JSON file.
        path: PathBuf,
    },
    /// Set the MPFR precision of later answers (default 256).
    SetPrecision {
        /// Precision in bits, 2..=[`MAX_BITS`].
        bits: u32,
    },
    /// m_v (Def. 4.1.1).
    Degree {
        /// Vertex id (0-based file index).
        v: u32,
    },
    /// The labels s_v (Def. 4.1.4 / Sec. 6.1.2): `[[neighbour, i], …]` in label order.
    Labels {
        /// Vertex id (0-based file index).
        v: u32,
    },
    /// p ∈ Ω_uw? (Def. 4.1.9 or the Sec. 6.1.3 lens test).
    Member {
        /// First vertex of the edge [u, w]: the point lives in Ω_u.
        u: u32,
        /// Second vertex of the edge [u, w].
        w: u32,
        /// The point `[x, y]` in the local coordinates of the first-named p-domain.
        p: [f64; 2],
        /// The membership test (default: literal).
        #[serde(default)]
        test: MemberTest,
    },
    /// φ_wu(p), p ∈ Ω_uw (Def. 4.1.10: from Ω_uw to Ω_wu).
    Phi {
        /// First vertex of the edge [u, w]: the point lives in Ω_u.
        u: u32,
        /// Second vertex of the edge [u, w].
        w: u32,
        /// The point `[x, y]` in the local coordinates of the first-named p-domain.
        p: [f64; 2],
    },
    /// g_v(p) (Def. 4.1.6).
    G {
        /// Vertex id (0-based file index).
        v: u32,
        /// The point `[x, y]` in the local coordinates of the first-named p-domain.
        p: [f64; 2],
    },
    /// g_v⁻¹(p) (Def. 4.1.6).
    GInv {
        /// Vertex id (0-based file index).
        v: u32,
        /// The point `[x, y]` in the local coordinates of the first-named p-domain.
        p: [f64; 2],
    },
    /// h(p) = (1 − x, −y) (Def. 4.1.7).
    H {
        /// The point `[x, y]` in the local coordinates of the first-named p-domain.
        p: [f64; 2],
    },
    /// R_(u,w)(p): rotation by −2π·s_u(w)/m_u (Def. 4.1.8).
    Rotate {
        /// First vertex of the edge [u, w]: the point lives in Ω_u.
        u: u32,
        /// Second vertex of the edge [u, w].
        w: u32,
        /// The point `[x, y]` in the local coordinates of the first-named p-domain.
        p: [f64; 2],
    },
    /// Select S′ (Sec. 6.2): `"pn"` (PN triangles, default) or `"loop"` (the Loop limit
    /// surface, exact); the pseudo-surface is rebuilt on the next Chapter 5 request.
    SetSurface {
        /// `"pn"` or `"loop"`.
        surface: String,
    },
    /// Select the construction later `eval` requests answer for: `"vertex"` (the report's,
    /// default), `"sigma-v"` (the tutorial's (σ, v)-indexed PPS, SPEC `SV-…`; optional
    /// `kappa`, default 1/4) or `"manifold-spline"` (seed 003 Secs. 5.5–5.6; no MPFR
    /// evaluation, so its `eval` is refused). Other Chapter 5 ops stay with the vertex
    /// construction.
    SetConstruction {
        /// `"vertex"`, `"sigma-v"` or `"manifold-spline"`.
        construction: String,
        /// κ of r_{v,σ} (sigma-v only).
        #[serde(default)]
        kappa: Option<f64>,
    },
    /// Select the parameter profile of Chapter 5 (`"paper"` or `"authors-code"`, see
    /// [`Profile`](crate::surface::Profile)); the pseudo-surface is rebuilt on the next Chapter 5 request.
    SetProfile {
        /// `"paper"` or `"authors-code"`.
        profile: String,
    },
    /// γ_v(p) = ξ(‖p‖) (Defs. 5.3.1–5.3.2), as a one-element array; 0 outside Ω_v.
    Gamma {
        /// Vertex id (0-based file index).
        v: u32,
        /// The point `[x, y]` in the local coordinates of the first-named p-domain.
        p: [f64; 2],
    },
    /// ψ_v(p), the shape function (Def. 5.2.1), for p in the square □_v = [−L, L]²,
    /// L = cos(π/m_v).
    Psi {
        /// Vertex id (0-based file index).
        v: u32,
        /// The point `[x, y]` in the local coordinates of the first-named p-domain.
        p: [f64; 2],
    },
    /// The control points of ψ_v (Sec. 5.2 least-squares fit; f64 only).
    PsiControl {
        /// Vertex id (0-based file index).
        v: u32,
    },
    /// θ_v(p), p ∈ Ω_v (Def. 5.4.2, Eq. 5.1).
    Theta {
        /// Vertex id (0-based file index).
        v: u32,
        /// The point `[x, y]` in the local coordinates of the first-named p-domain.
        p: [f64; 2],
    },
    /// Every partial derivative ∂^{i+j}θ_v/∂x^i∂y^j at p ∈ Ω_v with i + j ≤ `order` (≤ 3,
    /// default 3), from order-3 jets (forward-mode differentiation, no finite differences).
    ThetaDerivatives {
        /// Vertex id (0-based file index).
        v: u32,
        /// The point `[x, y]` in the local coordinates of the first-named p-domain.
        p: [f64; 2],
        /// Highest total order i + j, 0..=3 (default 3).
        #[serde(default)]
        order: Option<u32>,
    },
    /// S′ at (σ, λ, μ, ν) (Sec. 5.1): the session's PN-triangle surface b_σ (normal rule of
    /// the profile), f64 and MPFR with the same f64 control net.
    Sprime {
        /// σ: face id (0-based file index).
        face: u32,
        /// (λ, μ, ν) at the corners of σ in file order (≥ 0, sum 1).
        bary: [f64; 3],
    },
    /// eval(σ, λ, μ, ν) (Sec. 6.1.4): the point of M, with the chart and q ∈ Ω_vertex.
    Eval {
        /// σ: face id (0-based file index).
        face: u32,
        /// (λ, μ, ν) at the corners of σ in file order (≥ 0, sum 1).
        bary: [f64; 3],
    },
}
