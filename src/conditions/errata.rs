//! Statements of Chapter 4 that fail as literally written (SPEC.md, section "Errata found"),
//! each with the domain of configurations on which it fails.
//!
//! A failure is excused as a documented erratum only on that domain: the same statement
//! failing on a configuration outside it (e.g. the Sec. 6.1.3 lens test disagreeing with
//! Def. 4.1.9 at m_u = 8, where the paper's claim holds) is a conformance failure. Where a
//! corrected statement exists it is checked under the ID with the suffix `[restricted]`; where
//! none does, [`Erratum::corrected`] says why.

use serde::Serialize;

/// The configuration a Chapter 4 result was computed on (Sec. 6.1.3: the maps depend on a mesh
/// element only through it).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Element {
    /// An oriented edge (m_u, i = s_u(w), m_w, j = s_w(u)).
    Edge {
        /// Degree of u.
        m_u: u32,
        /// s_u(w).
        i: u32,
        /// Degree of w.
        m_w: u32,
        /// s_w(u).
        j: u32,
    },
    /// A triangle [u, w, x] read from u (P4.2.4 is run at u).
    Triangle {
        /// Degree of u.
        m_u: u32,
        /// Degree of w.
        m_w: u32,
        /// Degree of x.
        m_x: u32,
    },
    /// The star of a vertex of degree m (the gluing domains Ω_xn in Ω_x).
    Star {
        /// Degree of the centre.
        m: u32,
    },
    /// Not tied to one configuration (mesh-wide checks, the abstract Def. 3.4.1 run).
    Mesh,
}

/// Which configurations an erratum's statement fails on, in terms of the centre degree m
/// (m_u for edges and triangles, m_x for stars) of the family the check runs on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Domain {
    /// Edges with m_u ≠ 6.
    EdgeDegreeNot6,
    /// Edges with 6 ∤ m_u.
    EdgeDegreeNotMultipleOf6,
    /// Edges with m_u < 6.
    EdgeDegreeBelow6,
    /// Edges with m_u > 6.
    EdgeDegreeAbove6,
    /// Edges with m_u ≥ 11.
    EdgeDegreeFrom11,
    /// Every edge configuration.
    EveryEdge,
    /// Triangles read from a vertex u of degree 3.
    TriangleDegree3,
    /// Stars of degree m ≥ 11.
    StarDegreeFrom11,
}

impl Domain {
    /// Whether a failure on `e` lies in this domain.
    pub fn contains(&self, e: &Element) -> bool {
        match (*self, *e) {
            (Domain::EdgeDegreeNot6, Element::Edge { m_u, .. }) => m_u != 6,
            (Domain::EdgeDegreeNotMultipleOf6, Element::Edge { m_u, .. }) => m_u % 6 != 0,
            (Domain::EdgeDegreeBelow6, Element::Edge { m_u, .. }) => m_u < 6,
            (Domain::EdgeDegreeAbove6, Element::Edge { m_u, .. }) => m_u > 6,
            (Domain::EdgeDegreeFrom11, Element::Edge { m_u, .. }) => m_u >= 11,
            (Domain::EveryEdge, Element::Edge { .. }) => true,
            (Domain::TriangleDegree3, Element::Triangle { m_u, .. }) => m_u == 3,
            (Domain::StarDegreeFrom11, Element::Star { m }) => m >= 11,
            _ => false,
        }
    }

    /// The domain as SPEC.md states it.
    pub fn describe(&self) -> &'static str {
        match self {
            Domain::EdgeDegreeNot6 => "edges with m_u ≠ 6",
            Domain::EdgeDegreeNotMultipleOf6 => "edges with 6 ∤ m_u",
            Domain::EdgeDegreeBelow6 => "edges with m_u < 6",
            Domain::EdgeDegreeAbove6 => "edges with m_u > 6",
            Domain::EdgeDegreeFrom11 => "edges with m_u ≥ 11",
            Domain::EveryEdge => "every edge configuration",
            Domain::TriangleDegree3 => "triangles read from a vertex u with m_u = 3",
            Domain::StarDegreeFrom11 => "stars of degree m_x ≥ 11",
        }
    }
}

/// One documented erratum.
#[derive(Debug, Clone, Copy)]
pub struct Erratum {
    /// The SPEC.md ID of the statement as written.
    pub id: &'static str,
    /// Why it fails, in one line.
    pub reason: &'static str,
    /// Where it fails (and so where a failure is excused).
    pub domain: Domain,
    /// The corrected statement's ID (`…[restricted]`), or why there is none.
    pub corrected: Corrected,
}

/// The corrected form of an erratum.
#[derive(Debug, Clone, Copy)]
pub enum Corrected {
    /// Checked under this ID, beside the statement as written, on the same samples.
    Restricted(&'static str),
    /// No separate row; the reason.
    None(&'static str),
}

/// Every documented erratum of Chapter 4 / Sec. 6.1.3.
pub const ERRATA: &[Erratum] = &[
    Erratum {
        id: "C4.1.6-gv-bijective",
        reason: "g_v is not bijective on R²−{0} unless m_v = 6 (angle scaled by m_v/6 leaves (−π, π])",
        domain: Domain::EdgeDegreeNot6,
        corrected: Corrected::Restricted("C4.1.6-gv-bijective[restricted]"),
    },
    Erratum {
        id: "C4.1.6-gv-smooth",
        reason: "g_v jumps across Π's branch cut (negative x-axis) unless 6 | m_v",
        domain: Domain::EdgeDegreeNotMultipleOf6,
        corrected: Corrected::Restricted("C4.1.6-gv-smooth[restricted]"),
    },
    Erratum {
        id: "C4.1.8-onto-intC",
        reason: "g_u∘R_(u,w) maps Ω_u−{0} onto a sector, not onto int C−{0}, when m_u < 6",
        domain: Domain::EdgeDegreeBelow6,
        corrected: Corrected::Restricted("C4.1.8-onto-intC[restricted]"),
    },
    Erratum {
        id: "C4.1.8-guw-bijective",
        reason: "the stated inverse of g_(u,w) fails for m_u > 6",
        domain: Domain::EdgeDegreeAbove6,
        corrected: Corrected::Restricted("C4.1.8-guw-bijective[restricted]"),
    },
    Erratum {
        id: "P4.1.1",
        reason: "g_(u,w) is discontinuous along the ray opposite s_u(w) unless 6 | m_u",
        domain: Domain::EdgeDegreeNotMultipleOf6,
        corrected: Corrected::Restricted("P4.1.1[restricted]"),
    },
    Erratum {
        id: "P4.1.2-proof-step",
        reason: "the proof's step θ ∈ (−π/3, π/3) is false (the statement holds)",
        domain: Domain::EveryEdge,
        corrected: Corrected::None(
            "a step of a proof, not a statement: the statement it serves is P4.1.2, checked under its own ID",
        ),
    },
    Erratum {
        id: "P4.1.3-inverse",
        reason: "g_(u,w)⁻¹ = g_(w,u) fails for m_u ≥ 11",
        domain: Domain::EdgeDegreeFrom11,
        corrected: Corrected::Restricted("P4.1.3-inverse[restricted]"),
    },
    Erratum {
        id: "D4.1.9-lens",
        reason: "the Sec. 6.1.3 lens test accepts points outside Def. 4.1.9's Ω_uw for m_u ≥ 11",
        domain: Domain::EdgeDegreeFrom11,
        corrected: Corrected::None(
            "the corrected statement (lens test = Def. 4.1.9 for m_u ≤ 10) is the same check off the domain, where a failure is not excused",
        ),
    },
    Erratum {
        id: "P4.2.4(i,ii)",
        reason: "for m_u = 3, R_(u,w)(Ω_uz) crosses Π's cut, so (i)/(ii) fail as written",
        domain: Domain::TriangleDegree3,
        corrected: Corrected::None(
            "the corrected statement ((i), (ii) for m_u ≥ 4) is the same check off the domain, where a failure is not excused; (iii), (iv) are P4.2.4(iii,iv)",
        ),
    },
    Erratum {
        id: "C5.4-at-most-two[sec6.1.3]",
        reason: "with the lens test as membership, up to 4 gluing domains overlap for m ≥ 11",
        domain: Domain::StarDegreeFrom11,
        corrected: Corrected::None(
            "with the literal Def. 4.1.9 it holds for every degree: row C5.4-at-most-two",
        ),
    },
    Erratum {
        id: "C4.2-nonadjacent-disjoint[sec6.1.3]",
        reason: "with the lens test, gluing domains of non-adjacent neighbours meet for m ≥ 11",
        domain: Domain::StarDegreeFrom11,
        corrected: Corrected::None(
            "with the literal Def. 4.1.9 it holds for every degree: row C4.2-nonadjacent-disjoint",
        ),
    },
];

/// The documented erratum with this ID, if any.
pub fn erratum(id: &str) -> Option<&'static Erratum> {
    ERRATA.iter().find(|e| e.id == id)
}

/// A failure of `id` on `element` is a documented erratum: `id` is one and `element` lies in
/// its domain.
pub fn excused(id: &str, element: &Element) -> bool {
    erratum(id).is_some_and(|e| e.domain.contains(element))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn edge(m_u: u32) -> Element {
        Element::Edge {
            m_u,
            i: 0,
            m_w: 6,
            j: 0,
        }
    }

    #[test]
    fn d4_1_9_lens_erratum_is_excused_only_from_degree_11() {
        assert!(excused("D4.1.9-lens", &edge(11)));
        assert!(excused("D4.1.9-lens", &edge(12)));
        for m in 3..=10 {
            assert!(!excused("D4.1.9-lens", &edge(m)), "m_u = {m}");
        }
        // The wrong family is never in the domain.
        assert!(!excused("D4.1.9-lens", &Element::Star { m: 12 }));
        assert!(!excused("D4.1.9-lens", &Element::Mesh));
        // A statement that is no erratum is never excused.
        assert!(!excused("P4.2.3", &edge(12)));
    }

    #[test]
    fn x_errata_domain_matches_the_stated_degrees() {
        let fails_on = |id: &str, m: u32| -> bool {
            let e = erratum(id).map(|e| e.domain);
            let el = match e {
                Some(Domain::TriangleDegree3) => Element::Triangle {
                    m_u: m,
                    m_w: 6,
                    m_x: 6,
                },
                Some(Domain::StarDegreeFrom11) => Element::Star { m },
                _ => edge(m),
            };
            excused(id, &el)
        };
        for m in 3..=40u32 {
            assert_eq!(fails_on("C4.1.6-gv-bijective", m), m != 6);
            assert_eq!(fails_on("C4.1.6-gv-smooth", m), m % 6 != 0);
            assert_eq!(fails_on("P4.1.1", m), m % 6 != 0);
            assert_eq!(fails_on("C4.1.8-onto-intC", m), m < 6);
            assert_eq!(fails_on("C4.1.8-guw-bijective", m), m > 6);
            assert_eq!(fails_on("P4.1.3-inverse", m), m >= 11);
            assert_eq!(fails_on("D4.1.9-lens", m), m >= 11);
            assert_eq!(fails_on("P4.2.4(i,ii)", m), m == 3);
            assert_eq!(fails_on("C5.4-at-most-two[sec6.1.3]", m), m >= 11);
            assert_eq!(fails_on("C4.2-nonadjacent-disjoint[sec6.1.3]", m), m >= 11);
            assert!(fails_on("P4.1.2-proof-step", m));
        }
        let mut ids: Vec<&str> = ERRATA.iter().map(|e| e.id).collect();
        ids.sort_unstable();
        ids.dedup();
        assert_eq!(ids.len(), ERRATA.len(), "one entry per erratum");
    }
}
