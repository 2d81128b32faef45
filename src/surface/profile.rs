//! The two parameter profiles of the construction.
//!
//! * [`Profile::Paper`] (default): the text literally — Sec. 5.2: l = max(m_v + 1, 7), a
//!   uniform sampling of □_v with 4·l² points (a 2l × 2l grid, both ends included), points
//!   outside P_v dropped; Sec. 6.1.4: eval picks Ω_u if q′ ∈ int(C), else Ω_x if q′ ∈ int(D),
//!   else Ω_w.
//! * [`Profile::AuthorsCode`]: what the authors' published C++ implementation
//!   (`siqueirafm/PPS`, MIT, commit b405979) computes, stage by stage — see
//!   `docs/authors-code.md` for the table of differences with the place in their code and the
//!   measured effect of each:
//!   - S′: PN-triangle vertex normals are the plain mean of the unit face normals
//!     ([`NormalRule::PlainMean`]);
//!   - labels s_v: v′_0 is the far end of v's out-going half-edge in the **last** face (file
//!     order) containing v ([`Profile::label_offset`]);
//!   - l = min(m_v + 1, 7); a (2l + 1) × (2l + 1) grid on □_v whose coordinates are
//!     accumulated sums, a point kept when it lies in a triangle of T_v after snapping its
//!     barycentric coordinates within 10⁻¹⁴ of 0 or 1 ([`super::authors_fit`]);
//!   - the fit by the normal equations AᵀA x = Aᵀb and Crout LU with implicit partial
//!     pivoting;
//!   - eval picks the p-domain of the corner of the canonical triangle nearest to q′ and
//!     blends only the three vertices of the evaluated triangle; the polar angle of their
//!     canonical-domain map lies in (−π/2, 3π/2], which drops a neighbour's term in part of
//!     the gluing domains of degree-3 vertices (a defect, documented with a witness).

use crate::mesh::{HalfedgeId, SimplicialSurface, VertexId};
use serde::Serialize;

/// The stages in which the authors' code departs from the paper's text, each switchable on
/// its own (all on for [`Profile::AuthorsCode`], all off for [`Profile::Paper`]): switching
/// one back to the paper's rule measures that difference's effect (`docs/authors-code.md`).
/// The Bézier degree, grid and normal rule follow the profile itself.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Default)]
pub struct AuthorsStages {
    /// v′_0 from the last face containing v ([`Profile::label_offset`]).
    pub labels: bool,
    /// Their grid and kept points and the normal-equations fit (else the SVD of Sec. 5.2 on
    /// the profile's grid).
    pub normal_equations: bool,
    /// Their canonical-domain polar angle in (−π/2, 3π/2].
    pub polar_angle: bool,
    /// eval's chart: the nearest corner of the canonical triangle (else Sec. 6.1.4's rule).
    pub nearest_chart: bool,
    /// eval blends only the evaluated triangle's three vertices (else all of J_v(p)).
    pub triangle_blend: bool,
}

impl AuthorsStages {
    /// Every stage as in the authors' code.
    pub const ALL: AuthorsStages = AuthorsStages {
        labels: true,
        normal_equations: true,
        polar_angle: true,
        nearest_chart: true,
        triangle_blend: true,
    };
}

/// How the PN-triangle vertex normals of S′ are formed (Sec. 5.1 leaves it open).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum NormalRule {
    /// Angle-weighted mean of the unit face normals (Thürmer & Wüthrich 1998).
    AngleWeighted,
    /// Plain mean of the unit face normals (the authors' code).
    PlainMean,
}

/// Parameter profile of the construction (see the module doc).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Profile {
    /// The paper's text literally (default).
    #[default]
    Paper,
    /// The parameters of the authors' published implementation.
    AuthorsCode,
}

impl Profile {
    /// The name used on the command line and in reports: `paper`, `authors-code`.
    pub fn name(self) -> &'static str {
        match self {
            Profile::Paper => "paper",
            Profile::AuthorsCode => "authors-code",
        }
    }
    /// Inverse of [`Profile::name`].
    pub fn parse(s: &str) -> Option<Profile> {
        match s {
            "paper" => Some(Profile::Paper),
            "authors-code" => Some(Profile::AuthorsCode),
            _ => None,
        }
    }
    /// The Bézier degree l for a vertex of degree m (Sec. 5.2).
    pub fn bezier_degree(self, m: u32) -> usize {
        let m1 = m as usize + 1;
        match self {
            Profile::Paper => m1.max(7),
            Profile::AuthorsCode => m1.min(7),
        }
    }
    /// Points per side of the uniform grid on □_v (Sec. 5.2).
    pub fn grid_side(self, l: usize) -> usize {
        match self {
            Profile::Paper => 2 * l,
            Profile::AuthorsCode => 2 * l + 1,
        }
    }
    /// The PN-triangle normal rule of S′ under this profile.
    pub fn normal_rule(self) -> NormalRule {
        match self {
            Profile::Paper => NormalRule::AngleWeighted,
            Profile::AuthorsCode => NormalRule::PlainMean,
        }
    }
    /// Which of v's labels (Sec. 6.1.2, `SimplicialSurface::outgoing`) is v′_0 under this
    /// profile. Paper: label 0 (the out-going half-edge of v in the first face containing
    /// v). Authors' code: their DCEL keeps, per vertex, the half-edge of the last face read,
    /// and numbers the others counterclockwise from it (same direction as ours), so their
    /// v′_i is our label (i + offset) mod m_v.
    pub fn label_offset(self, k: &SimplicialSurface, v: VertexId) -> u32 {
        label_offset(k, v, self.stages())
    }
    /// The stages of [`AuthorsStages`] this profile follows.
    pub fn stages(self) -> AuthorsStages {
        match self {
            Profile::Paper => AuthorsStages::default(),
            Profile::AuthorsCode => AuthorsStages::ALL,
        }
    }
}

/// [`Profile::label_offset`] for a set of stages.
pub fn label_offset(k: &SimplicialSurface, v: VertexId, stages: AuthorsStages) -> u32 {
    if !stages.labels {
        return 0;
    }
    let Some(&f) = k.faces_around(v).last() else {
        return 0;
    };
    match k.face(f).iter().position(|&c| c == v) {
        Some(c) => k.label(HalfedgeId(3 * f.0 + c as u32)),
        None => 0,
    }
}
