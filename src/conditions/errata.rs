//! Statements of the paper that fail as literally written (SPEC.md, section "Errata found").
//! A checker reporting *fails* for one of these IDs is reporting the documented erratum; the
//! corrected statement is checked under the ID with the `[restricted]` suffix, and a failure
//! there (or of any other ID) is a conformance failure.

/// (ID, one-line reason) for every documented erratum of Chapter 4 / Sec. 6.1.3.
pub const ERRATA: &[(&str, &str)] = &[
    (
        "C4.1.6-gv-bijective",
        "g_v is not bijective on R²−{0} unless m_v = 6 (angle scaled by m_v/6 leaves (−π, π])",
    ),
    (
        "C4.1.6-gv-smooth",
        "g_v jumps across Π's branch cut (negative x-axis) unless 6 | m_v",
    ),
    (
        "C4.1.8-onto-intC",
        "g_u∘R_(u,w) maps Ω_u−{0} onto a sector, not onto int C−{0}, when m_u < 6",
    ),
    (
        "C4.1.8-guw-bijective",
        "the stated inverse of g_(u,w) fails for m_u > 6",
    ),
    (
        "P4.1.1",
        "g_(u,w) is discontinuous along the ray opposite s_u(w) unless 6 | m_u",
    ),
    (
        "P4.1.2-proof-step",
        "the proof's step θ ∈ (−π/3, π/3) is false (the statement holds)",
    ),
    ("P4.1.3-inverse", "g_(u,w)⁻¹ = g_(w,u) fails for m_u ≥ 11"),
    (
        "D4.1.9-lens",
        "the Sec. 6.1.3 lens test accepts points outside Def. 4.1.9's Ω_uw for m_u ≥ 11",
    ),
    (
        "P4.2.4(i,ii)",
        "for m_u = 3, R_(u,w)(Ω_uz) crosses Π's cut, so (i)/(ii) fail as written",
    ),
    (
        "C5.4-at-most-two[sec6.1.3]",
        "with the lens test as membership, up to 4 gluing domains overlap for m ≥ 11",
    ),
    (
        "C4.2-nonadjacent-disjoint[sec6.1.3]",
        "with the lens test, gluing domains of non-adjacent neighbours meet for m ≥ 11",
    ),
];

/// The documented reason, when `id` is a documented erratum.
pub fn erratum(id: &str) -> Option<&'static str> {
    ERRATA.iter().find(|(e, _)| *e == id).map(|(_, why)| *why)
}
