//! Options of the pseudo-surface of Chapter 5: the membership test of Ω_vu and the planted
//! faults of the tests that show each check can fail.

use super::profile::Profile;
use crate::mesh::VertexId;
use serde::Serialize;

/// How p ∈ Ω_vu is decided (see the module doc).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
pub enum Membership {
    /// Def. 4.1.9 (equivalent branch + lens test).
    #[default]
    Literal,
    /// Sec. 6.1.3: the canonical-lens test alone, all neighbours tested.
    Lens,
}

/// Planted faults, for the tests that show each check can fail.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub enum Fault {
    /// Γ_uv of `vertex` multiplied by `factor` whenever it enters θ_v of *another* vertex v
    /// (one control point's blending perturbed).
    NeighbourWeight {
        /// The vertex u whose weight is perturbed.
        vertex: VertexId,
        /// The factor applied to Γ_uv.
        factor: f64,
    },
    /// φ_uv (from `from`'s chart to `to`'s) followed by a rotation by `angle` about 0.
    Transition {
        /// Source chart: the perturbed map is φ_{to,from}, out of Ω_from.
        from: VertexId,
        /// Target chart.
        to: VertexId,
        /// Rotation angle (radians) applied after the map.
        angle: f64,
    },
    /// ω_uv computed with Σ Γ multiplied by `factor` (normalisation broken).
    Denominator {
        /// The factor applied to the denominator.
        factor: f64,
    },
    /// ξ replaced by the C⁰ ramp (H₂ − t)/(H₂ − H₁) on (H₁, H₂).
    RampWeight,
    /// The support radius H₂ of γ_v multiplied by `factor`.
    WeightRadius {
        /// The factor applied to H₂.
        factor: f64,
    },
}

/// Options of the construction.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize)]
pub struct PpsOptions {
    /// The parameter profile (fixed when the surface is built).
    pub profile: Profile,
    /// How p ∈ Ω_vu is decided.
    pub membership: Membership,
    /// A planted fault, `None` in production.
    pub fault: Option<Fault>,
}
