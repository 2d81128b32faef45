//! The two parameter profiles of the construction.
//!
//! * [`Profile::Paper`] (default): the text literally — Sec. 5.2: l = max(m_v + 1, 7), a
//!   uniform sampling of □_v with 4·l² points (a 2l × 2l grid, both ends included), points
//!   outside P_v dropped; Sec. 6.1.4: eval picks Ω_u if q′ ∈ int(C), else Ω_x if q′ ∈ int(D),
//!   else Ω_w.
//! * [`Profile::AuthorsCode`]: the parameters of the authors' published C++ implementation (as
//!   described in the project's design notes; their code was not consulted): l = min(m_v + 1, 7), a
//!   (2l + 1) × (2l + 1) grid on □_v clipped to P_v, and eval picks the p-domain of the corner
//!   of the canonical triangle (0,0), (1,0), (1/2, −√3/2) nearest to q′, blending in θ only v
//!   and the two other vertices of the evaluated triangle.

use serde::Serialize;

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
}
