//! Branch and bound over polar boxes (θ, r) of a chart, and the prover settings.

use super::config::ConfigKey;
use super::interval::{iv, Deg};
use super::result::{CertWitness, Outcome, PropertyResult};
use crate::construction::maps::EdgeConfig;
use crate::numeric::interval::Interval as I;
use serde::{Deserialize, Serialize};
use std::time::Instant;

// ---------------------------------------------------------------------------------------------
// Branch and bound over polar boxes.
// ---------------------------------------------------------------------------------------------

/// A box [θ0, θ1] × [r0, r1] of polar coordinates in a chart.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PBox {
    /// [θ0, θ1].
    pub th: (f64, f64),
    /// [r0, r1].
    pub r: (f64, f64),
}

impl PBox {
    pub(super) fn ith(&self) -> I {
        iv(self.th.0, self.th.1)
    }
    pub(super) fn ir(&self) -> I {
        iv(self.r.0, self.r.1)
    }
    pub(super) fn mid(&self) -> (f64, f64) {
        (0.5 * (self.th.0 + self.th.1), 0.5 * (self.r.0 + self.r.1))
    }
    /// Diameter bound in the chart: r1·Δθ + Δr.
    pub(super) fn diam(&self) -> f64 {
        self.r.1 * (self.th.1 - self.th.0) + (self.r.1 - self.r.0)
    }
    pub(super) fn split(&self) -> [PBox; 2] {
        let (t, r) = self.mid();
        if self.r.1 * (self.th.1 - self.th.0) >= self.r.1 - self.r.0 {
            [
                PBox {
                    th: (self.th.0, t),
                    r: self.r,
                },
                PBox {
                    th: (t, self.th.1),
                    r: self.r,
                },
            ]
        } else {
            [
                PBox {
                    th: self.th,
                    r: (self.r.0, r),
                },
                PBox {
                    th: self.th,
                    r: (r, self.r.1),
                },
            ]
        }
    }
    /// Cartesian centre (f64).
    pub(super) fn centre_xy(&self) -> [f64; 2] {
        let (t, r) = self.mid();
        [r * t.cos(), r * t.sin()]
    }
}

/// The exact case analysis of [`prove_triangle`] on a box.
pub(super) enum Exact {
    /// No point of the box is in Ω_ux ∩ φ_xu⁻¹(Ω_xw).
    Empty,
    /// On the box, Ω_ux ∩ φ_xu⁻¹(Ω_xw) = Ω_ux ∩ Ω_uw and the cocycle identity is exact.
    Equal,
    Undecided,
}

/// What a classifier says about a box.
pub(super) enum Leaf {
    /// The property holds on the box; optional bounds (whole box, centre).
    Proven(Option<f64>, Option<f64>),
    /// The property fails at every point of the box.
    Refuted(String),
    Split,
}

#[derive(Debug, Default)]
pub(super) struct Stats {
    pub(super) boxes: u64,
    pub(super) max_depth: u32,
    pub(super) unresolved: u64,
    pub(super) delta: f64,
    pub(super) bound: Option<f64>,
    pub(super) centre: Option<f64>,
    pub(super) refuted: Option<(PBox, String)>,
    pub(super) budget_hit: bool,
}

pub(super) fn omax(a: Option<f64>, b: Option<f64>) -> Option<f64> {
    match (a, b) {
        (Some(x), Some(y)) => Some(x.max(y)),
        (x, None) => x,
        (None, y) => y,
    }
}

/// Depth-first branch and bound; stops at the first refutation.
pub(super) fn bnb(
    root: PBox,
    max_depth: u32,
    budget: u64,
    mut f: impl FnMut(&PBox) -> Leaf,
) -> Stats {
    let mut st = Stats::default();
    let mut stack = vec![(root, 0u32)];
    while let Some((b, d)) = stack.pop() {
        // `boxes` counts the boxes evaluated (the certificate's `examined`): with budget 0
        // nothing is examined and the result is inconclusive, never certified.
        if st.boxes >= budget {
            st.budget_hit = true;
            st.unresolved += 1 + stack.len() as u64;
            st.delta = st.delta.max(b.diam());
            for (s, _) in &stack {
                st.delta = st.delta.max(s.diam());
            }
            break;
        }
        st.boxes += 1;
        st.max_depth = st.max_depth.max(d);
        match f(&b) {
            Leaf::Proven(bd, cb) => {
                st.bound = omax(st.bound, bd);
                st.centre = omax(st.centre, cb);
            }
            Leaf::Refuted(s) => {
                st.refuted = Some((b, s));
                break;
            }
            Leaf::Split => {
                if d >= max_depth {
                    st.unresolved += 1;
                    st.delta = st.delta.max(b.diam());
                } else {
                    let [a, c2] = b.split();
                    stack.push((c2, d + 1));
                    stack.push((a, d + 1));
                }
            }
        }
    }
    st
}

/// Prover settings.
#[derive(Debug, Clone, Copy, Serialize, Deserialize)]
pub struct Settings {
    /// Maximum bisection depth (boxes at this depth that are still undecided are reported
    /// as unresolved; δ is their largest diameter).
    pub max_depth: u32,
    /// Maximum boxes per prover run.
    pub budget: u64,
    /// A composite deviating from the identity by more than this at a box centre refutes.
    pub fail_tol: f64,
    /// Boxes on which an identity is proven exactly are still split down to this diameter,
    /// so that the model's generic maps are cross-checked at a grid of centres of this
    /// spacing (the link between the model and the closed forms; catches planted faults).
    #[serde(default = "default_check_diam")]
    pub check_diam: f64,
}

pub(super) fn default_check_diam() -> f64 {
    0.2
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            max_depth: 26,
            budget: 400_000,
            fail_tol: 1e-9,
            check_diam: default_check_diam(),
        }
    }
}

/// The whole chart: θ ∈ [−π⁺, π⁺] with π⁺ = the f64 above π (`f64::consts::PI` is below π,
/// so a box up to it would miss the ray θ = π, the negative x-axis, where the cut of Π lies),
/// r ∈ [0, r_m].
pub(super) fn disk_box(m: u32) -> PBox {
    let pi_up = I::PI.sup();
    PBox {
        th: (-pi_up, pi_up),
        r: (0.0, Deg::new(m).rm.sup()),
    }
}

pub(super) fn finish(
    key: ConfigKey,
    property: &str,
    statement: String,
    st: Stats,
    witness: Option<CertWitness>,
    t0: Instant,
) -> PropertyResult {
    let outcome = if st.refuted.is_some() {
        Outcome::Refuted
    } else if st.unresolved == 0 {
        Outcome::Certified
    } else if st.budget_hit {
        Outcome::Inconclusive
    } else {
        Outcome::CertifiedOutsideDelta
    };
    PropertyResult {
        key,
        property: property.into(),
        outcome,
        statement,
        bound: st.bound,
        centre_bound: st.centre,
        delta: if st.unresolved > 0 {
            Some(st.delta)
        } else {
            None
        },
        boxes: st.boxes,
        max_depth: st.max_depth,
        unresolved: st.unresolved,
        witness,
        millis: t0.elapsed().as_millis() as u64,
        f64_rounding: None,
        g_chart: None,
        f64_bound: None,
    }
}

pub(super) const MP_PREC: u32 = 256;

/// Canonical edge (labels 0) of degrees (m_u, m_w).
pub(super) fn canon_edge(m_u: u32, m_w: u32) -> EdgeConfig {
    EdgeConfig {
        m_u,
        i: 0,
        m_w,
        j: 0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The provers report the size of what they left unresolved, and decide when a box is small
    /// enough to stop splitting, by `PBox::diam`: it must bound the distance between any two
    /// points of the polar box in the chart (|Δr| + r_max·|Δθ|), here against its corners and
    /// its angular midpoints.
    #[test]
    fn l4_2_2_cert_box_diameter_bounds_chart_distances() {
        for (th, r) in [
            ((0.0, 0.1), (0.5, 1.0)),
            ((-2.0, 1.0), (0.1, 0.2)),
            ((1.0, 1.5), (0.3, 0.3)),
        ] {
            let b = PBox { th, r };
            let pts: Vec<(f64, f64)> = [th.0, 0.5 * (th.0 + th.1), th.1]
                .iter()
                .flat_map(|&t| [r.0, r.1].map(|rr| (rr * t.cos(), rr * t.sin())))
                .collect();
            for p in &pts {
                for q in &pts {
                    let d = ((p.0 - q.0).powi(2) + (p.1 - q.1).powi(2)).sqrt();
                    assert!(d <= b.diam() * (1.0 + 1e-12), "{b:?}: {d} > {}", b.diam());
                }
            }
        }
    }
}
