//! The results a certificate holds: per property and configuration, how the proof ended
//! ([`Outcome`]), its witness, and the proven `f64` bounds attached to it (CERT-f64-rounding,
//! CERT-f64-g-chart, CERT-f64-props). Data only: the provers above fill them in, the
//! certificate file (module `certificate`) stores them.

use super::config::ConfigKey;
use crate::report::{CheckResult, Verdict, Witness};
use serde::{Deserialize, Serialize};

/// Outcome of one prover run.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Outcome {
    /// Proven on the whole stated set (no unresolved boxes).
    Certified,
    /// Proven outside the unresolved boxes (their number and δ reported).
    CertifiedOutsideDelta,
    /// A counterexample box was found.
    Refuted,
    /// Neither (budget exhausted away from a tight boundary).
    Inconclusive,
}

/// A counterexample: the centre of a box on which the property fails for every point.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CertWitness {
    /// The point, in the chart named by `text`.
    pub point: [f64; 2],
    /// The point, its chart and what fails there.
    pub text: String,
    /// The f64 evaluator of `construction::maps` confirms the failure at `point`.
    pub f64_confirms: bool,
    /// The MPFR (256-bit) evaluator confirms it.
    pub mp_confirms: bool,
}

/// The result of one property for one configuration.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PropertyResult {
    /// The configuration.
    pub key: ConfigKey,
    /// SPEC ID, e.g. `L4.2.2(cert)`.
    pub property: String,
    /// How the proof ended (certified, possibly outside δ; refuted; inconclusive).
    pub outcome: Outcome,
    /// What exactly was proven (or refuted).
    pub statement: String,
    /// Proven bound (meaning in `statement`), if any.
    pub bound: Option<f64>,
    /// Tight bound at box centres (point intervals), if measured.
    pub centre_bound: Option<f64>,
    /// δ: the largest diameter (in the chart) of an unresolved box.
    pub delta: Option<f64>,
    /// Boxes evaluated by branch and bound.
    pub boxes: u64,
    /// Deepest subdivision level reached.
    pub max_depth: u32,
    /// Boxes left undecided: at the maximum depth, or pending when the box budget ran out.
    pub unresolved: u64,
    /// The counterexample, when refuted.
    pub witness: Option<CertWitness>,
    /// Time spent proving this result, in ms.
    pub millis: u64,
    /// CERT-f64-rounding: proven bounds on the f64 evaluator's rounding (on `P4.2.3(cert)`,
    /// one per edge configuration; absent in certificates written before it existed).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub f64_rounding: Option<F64Rounding>,
    /// CERT-f64-g-chart: proven bounds on g_v's and g_v⁻¹'s `f64` rounding on the whole chart
    /// square (on `D4.1.9-lens(cert)`, one per degree; absent in certificates written before
    /// it existed).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub g_chart: Option<GChartRounding>,
    /// CERT-f64-props: the proven bound on what the `f64` evaluator computes for this
    /// property ([`f64_bound_statement`](super::f64_bound_statement)), derived from the
    /// per-edge and per-degree bounds ([`attach_f64_bounds`](super::attach_f64_bounds); absent
    /// in certificates written before it existed and in shards).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub f64_bound: Option<F64Bound>,
}

impl PropertyResult {
    /// δ where it qualifies what was proven: a result certified outside δ, or an inconclusive
    /// one; `None` for a whole-set certificate and for a refutation (decided by its witness).
    pub fn delta_of_partial_proof(&self) -> Option<f64> {
        match self.outcome {
            Outcome::CertifiedOutsideDelta | Outcome::Inconclusive => self.delta,
            Outcome::Certified | Outcome::Refuted => None,
        }
    }

    /// As a report row.
    pub fn to_check_result(&self) -> CheckResult {
        let verdict = match self.outcome {
            Outcome::Certified => Verdict::Holds,
            Outcome::CertifiedOutsideDelta => Verdict::HoldsRestricted {
                domain: format!(
                    "outside {} unresolved boxes of diameter ≤ {:.1e}",
                    self.unresolved,
                    self.delta.unwrap_or(0.0)
                ),
            },
            Outcome::Refuted => Verdict::Fails,
            Outcome::Inconclusive => Verdict::Skipped {
                reason: "prover budget exhausted".into(),
            },
        };
        let witnesses = self
            .witness
            .iter()
            .map(|w| {
                Witness::new(
                    w.text.clone(),
                    serde_json::json!({"point": w.point, "f64": w.f64_confirms, "mp": w.mp_confirms}),
                )
            })
            .collect::<Vec<_>>();
        // Through the harness: a certificate that examined no box is skipped, never "holds".
        let mut r = CheckResult::new(
            self.property.clone(),
            format!("{} [{}]", self.statement, self.key),
        );
        r.adopt_verdict(verdict);
        r.offenders = witnesses.len() as u64;
        r.witnesses = witnesses;
        r.examined = self.boxes;
        r.worst_deviation = self.bound;
        r.tolerance = self.delta;
        r.note = self.statement.clone();
        crate::report::Check::from_result(r).finish("")
    }
}

/// The proven `f64` rounding bounds of one edge configuration (m_u, m_w), all labels.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct F64Rounding {
    /// max |φ_wu(p) in f64 − φ_wu(p)| (Euclidean) over every box meeting Ω_uw, all labels
    /// (`None`: no box bounded).
    pub phi: Option<f64>,
    /// max |f64 − exact| of |p|² − r_u² over |p| ≤ 1: p ∈ Ω_u (Def. 4.1.1) is decided
    /// exactly unless ||p|² − r_u²| ≤ this.
    pub outer: f64,
    /// max |f64 − exact| of |q|² − r_w², q = g_(w,u)⁻¹(p), on the boxes meeting Ω_uw: q ∈ Ω_w
    /// is decided exactly unless ||q|² − r_w²| ≤ this.
    pub inner: Option<f64>,
    /// max |f64 − exact| of the round-trip point g_(w,u)(q) on the boxes meeting Ω_uw
    /// (stage-wise bound, module `f64_roundtrip`; in certificates written before it, the
    /// enclosure bound on the winding-0 boxes).
    pub roundtrip: Option<f64>,
    /// The literal test's round-trip tolerance at this configuration.
    pub roundtrip_tol: f64,
    /// The round-trip decision "close" is certified identical in f64 and exactly on every
    /// box meeting Ω_uw (f64 |g_(w,u)(q) − p|² ≤ tol² with the exact value 0).
    pub roundtrip_exact: bool,
    /// The round-trip verdict with its typed failure (absent in older certificates).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub roundtrip_verdict: Option<RoundTripVerdict>,
    /// Boxes the round-trip bisection evaluated (absent in older certificates).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub roundtrip_boxes: Option<u64>,
    /// Boxes meeting Ω_uw the round-trip bisection left unbounded (absent in older
    /// certificates).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub roundtrip_unresolved: Option<u64>,
    /// max |g_v(a) in f64 − g_v(a)|, v = u, over the f64 points a = R_(u,w)(p) of the boxes
    /// (the oracle's `g` query on the label-0 sector of Ω_uw; absent in older certificates).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub g_v: Option<f64>,
    /// max |g_v⁻¹(c) in f64 − g_v⁻¹(c)|, v = w, over the f64 points c = h(g_u(a)) of the
    /// boxes (the oracle's `g_inv` query on the canonical lens; absent in older certificates).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub g_v_inv: Option<f64>,
    /// Boxes evaluated.
    pub boxes: u64,
    /// Boxes meeting Ω_uw left unbounded at the depth limit or the budget, or where the
    /// round trip could not be bounded.
    pub unresolved: u64,
    /// Largest diameter of an unresolved box.
    pub delta: Option<f64>,
    /// The libm assumption used, in ulps (`numeric::rounding::LIBM_ULPS`).
    pub libm_ulps: f64,
    /// Time spent, in ms.
    pub millis: u64,
    /// ε: `phi` and `inner` hold on every box meeting the closed ε-neighbourhood of Ω_uw
    /// (module `f64_outside`; absent in older certificates: on the boxes meeting Ω_uw).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub nbhd: Option<f64>,
    /// The literal test's `f64` answer on the rest of Ω_u (absent in older certificates).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub outside: Option<F64Outside>,
}

impl F64Rounding {
    /// The literal membership test's decision margin at every `f64` point of Ω_u:
    /// max(`outer`, `inner`, the margin off the neighbourhood), with `roundtrip_exact` (its
    /// round trip decided exactly on Ω_uw); `None` for a certificate without the pass off the
    /// neighbourhood or a margin that is not finite.
    pub fn literal_margin(&self) -> Option<(f64, bool)> {
        let off = self.outside.as_ref()?.inner?;
        let m = crate::report::dev_max(crate::report::dev_max(self.outer, self.inner?), off);
        m.is_finite().then_some((m, self.roundtrip_exact))
    }
}

/// CERT-f64-rounding off the ε-neighbourhood of Ω_uw, on the rest of Ω_u (exact answer of the
/// literal test: "out"): the `f64` literal test answers "out" at every `f64` point there unless
/// ||p|² − r_u²| ≤ `outer` or |q|² − r_w² ∈ [0, `inner`] (module `f64_outside`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct F64Outside {
    /// The margin of |q|² − r_w² there (`None`: some box was left unresolved, no claim).
    pub inner: Option<f64>,
    /// ε of the neighbourhood left to the φ pass.
    pub eps: f64,
    /// Boxes where the `f64` value of |q̂|² − r_w² is certified > 0 (no margin needed).
    pub by_value: u64,
    /// Boxes where the exact |q|² ≥ r_w² and the margin `inner` bounds the `f64` error.
    pub by_margin: u64,
    /// Boxes with winding ≠ 0 where the `f64` round trip is certified far from p.
    pub by_roundtrip: u64,
    /// Boxes left undecided at the minimum diameter.
    pub unresolved: u64,
    /// Boxes of the whole branch and bound (both regions).
    pub boxes: u64,
}

/// What the round-trip decision of the literal test (Def. 4.1.9) is certified to be.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum RoundTripVerdict {
    /// On every box meeting Ω_uw, f64 decides "close" exactly as the exact comparison.
    Exact,
    /// Every box was bounded, but on some the bound is above what the decision allows.
    AboveTolerance,
    /// Some box was left unbounded (budget, minimum diameter, or a failed check).
    Unresolved,
}

/// The proven `f64` rounding bounds of g_v and g_v⁻¹ for one degree m (on the
/// `D4.1.9-lens(cert)` result of the vertex configuration).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct GChartRounding {
    /// The square |x|, |y| ≤ `radius` is covered.
    pub radius: f64,
    /// max |g_v(p) in f64 − g_v(p)| (Euclidean) over every `f64` point p ≠ 0 of the square
    /// (`None`: some piece was left unbounded).
    pub g_v: Option<f64>,
    /// The same for g_v⁻¹.
    pub g_v_inv: Option<f64>,
    /// Pieces evaluated (both maps).
    pub boxes: u64,
    /// Pieces left unbounded (both maps).
    pub unresolved: u64,
    /// The libm assumption used, in ulps (`numeric::rounding::LIBM_ULPS`).
    pub libm_ulps: f64,
    /// Time spent, in ms.
    pub millis: u64,
}

impl GChartRounding {
    /// Does the bound cover the query point `p` (in the square, not the origin)?
    pub fn covers(&self, p: [f64; 2]) -> bool {
        p[0].abs() <= self.radius && p[1].abs() <= self.radius && (p[0] != 0.0 || p[1] != 0.0)
    }
}

/// CERT-f64-props: the proven `f64` bound of one result (meaning per property:
/// [`f64_bound_statement`](super::f64_bound_statement)).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct F64Bound {
    /// The proven bound (`None`: not bounded, e.g. a bound it rests on is missing).
    pub bound: Option<f64>,
    /// The Lipschitz constant the statement uses (`L4.2.2(cert)`, `L4.2.3(cert)`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub lipschitz: Option<f64>,
    /// Read from older certificates only: their `L4.2.1(cert)`, `L4.2.2(cert)` claims excluded
    /// the points p whose φ_xu(p) lies within this of ∂Ω_xw. Certificates with CERT-f64-rounding
    /// on the ε-neighbourhood (`F64Rounding::nbhd`) have no band.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub band: Option<f64>,
    /// Membership rows: every round-trip decision the check runs is certified exact
    /// (CERT-f64-rounding's `roundtrip_exact`); `P4.2.1(cert)`: and its witness points clear
    /// the margins, so the `f64` test that accepted them is certified to decide exactly.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub decided: Option<bool>,
}
