//! Errata of the tutorial's slides (seed 002), each as a check that reports the statement as
//! written failing with a witness, next to the corrected statement checked (SPEC `SV-E…`).

use crate::construction::maps::{g_v, polar, P2};
use crate::report::{CheckResult, Witness};
use serde_json::json;
use std::f64::consts::PI;

/// T 2174: g_u(θ, r) = (6/m_u·θ, …). The map must take the sector of s_u(σ) (angle 2π/m_u) to
/// the sector of the canonical triangle (angle π/3), as the report's m_u/6 does (R 690, S 1015).
/// As written, the spoke at angle 2π/m_u goes to 12π/m_u² (witness: any m_u ≠ 6).
pub fn check_gu_factor_as_written(degrees: &[u32]) -> CheckResult {
    let mut r = CheckResult::new(
        "SV-E-gu-factor",
        "T 2174 as written: g_u scales angles by 6/m_u",
    );
    for &m in degrees {
        r.examined += 1;
        let spoke = 2.0 * PI / m as f64;
        let image = 6.0 / m as f64 * spoke;
        let dev = (image - PI / 3.0).abs();
        if dev > 64.0 * f64::EPSILON {
            r.offend(|| {
                Witness::new(
                    format!("m_u = {m}: the spoke at angle 2π/{m} goes to {image:.6} ≠ π/3 (deviation {dev:.3e})"),
                    json!({"m": m, "image": image}),
                )
            });
        }
    }
    r.with_note(
        "erratum: the angular factor is inverted; corrected statement SV-E-gu-factor[corrected]",
    )
}

/// The corrected g_u (the report's, `construction::maps::g_v`, factor m_u/6) takes the spoke at
/// angle 2π/m_u to angle π/3 for every degree (checked numerically through the shared map).
pub fn check_gu_factor_corrected(degrees: &[u32]) -> CheckResult {
    let mut r = CheckResult::new(
        "SV-E-gu-factor[corrected]",
        "g_u = Π⁻¹∘(m_u/6·θ, cos(π/6)/cos(π/m_u)·r)∘Π maps the spoke 2π/m_u to π/3",
    );
    let mut worst = 0.0f64;
    for &m in degrees {
        let a = 2.0 * PI / m as f64 * 0.999_999; // inside (−π, π] for m = 3 too
        let q = P2::new(0.5 * a.cos(), 0.5 * a.sin());
        r.examined += 1;
        match g_v(m, &q).and_then(|z| polar(&z)) {
            Ok(p) => {
                let want = PI / 3.0 * 0.999_999;
                let dev = (p.theta - want).abs();
                worst = crate::report::dev_max(worst, dev);
                let tol = 64.0 * f64::EPSILON * (m as f64 / 6.0).max(1.0) * PI;
                if !(dev <= tol) {
                    r.offend(|| {
                        Witness::new(format!("m = {m}: angle {} ≠ π/3", p.theta), json!({"m": m}))
                    });
                }
            }
            Err(e) => r.offend(|| Witness::new(format!("m = {m}: {e}"), json!({"m": m}))),
        }
    }
    r.worst_deviation = Some(worst);
    r
}

/// T 2172, 2211: g_u and g_(u,w) map [0, 2π) × R₊ to [0, 2π) × R₊. With the corrected factor
/// m_u/6 the image of θ ∈ [0, 2π) is [0, m_uπ/3), which leaves [0, 2π) for m_u > 6; with the
/// slides' 6/m_u it is [0, 12π/m_u), which leaves it for m_u < 6. Witnesses for both.
pub fn check_angle_range_as_written(degrees: &[u32]) -> CheckResult {
    let mut r = CheckResult::new(
        "SV-E-angle-range",
        "T 2172: g_u maps [0, 2π) × R₊ into [0, 2π) × R₊",
    );
    for &m in degrees {
        r.examined += 1;
        let theta = 2.0 * PI * 0.99;
        for (which, f) in [
            ("m_u/6 (corrected factor)", m as f64 / 6.0),
            ("6/m_u (as written)", 6.0 / m as f64),
        ] {
            let img = f * theta;
            if img >= 2.0 * PI {
                r.offend(|| {
                    Witness::new(
                        format!("m_u = {m}, factor {which}: θ = {theta:.4} ↦ {img:.4} ∉ [0, 2π)"),
                        json!({"m": m, "theta": theta, "image": img}),
                    )
                });
            }
        }
    }
    r.with_note("erratum: read as the report's (−π, π] with the rotations R_(u,w) (R 656, 731); the corrected reading only uses |θ| < 2π/m_u, mapped into |β| < π/3 (checked by SV-E-angle-range[corrected])")
}

/// Corrected reading of T 2172: on the report's branch (−π, π] after R_(u,w), the gluing
/// region |θ| < 2π/m_u is mapped into |β| < π/3 ⊂ (−π, π] by the corrected factor.
pub fn check_angle_range_corrected(degrees: &[u32]) -> CheckResult {
    let mut r = CheckResult::new(
        "SV-E-angle-range[corrected]",
        "|θ| < 2π/m_u ↦ |m_u θ/6| < π/3 (inside (−π, π])",
    );
    for &m in degrees {
        for t in 0..=64 {
            r.examined += 1;
            let theta = (2.0 * PI / m as f64) * (-1.0 + 2.0 * t as f64 / 64.0) * 0.999_999;
            let img = m as f64 / 6.0 * theta;
            if !(img.abs() < PI / 3.0 + 64.0 * f64::EPSILON) {
                r.offend(|| Witness::new(format!("m = {m}: θ = {theta} ↦ {img}"), json!({"m": m})));
            }
        }
    }
    r
}

/// T 2678: the third vertex of the equilateral triangle of eval is printed "(1/2, √2/3)"; the
/// equilateral triangle on (0,0), (1,0) has it at (1/2, ±√3/2). The report's (1/2, −√3/2)
/// (R 1360) is the corrected statement.
pub fn check_equilateral() -> (CheckResult, CheckResult) {
    let side = |p: [f64; 2]| {
        (
            (p[0] * p[0] + p[1] * p[1]).sqrt(),
            ((p[0] - 1.0).powi(2) + p[1] * p[1]).sqrt(),
        )
    };
    let mut w = CheckResult::new(
        "SV-E-equilateral",
        "T 2678 as written: (0,0), (1,0), (1/2, √2/3) is equilateral",
    );
    let (a, b) = side([0.5, 2f64.sqrt() / 3.0]);
    w.examined = 1;
    if (a - 1.0).abs() > 4.0 * f64::EPSILON || (b - 1.0).abs() > 4.0 * f64::EPSILON {
        w.offend(|| {
            Witness::new(
                format!("|b − a| = {a:.6}, |b − c| = {b:.6} ≠ 1"),
                json!({"sides": [a, b]}),
            )
        });
    }
    let mut c = CheckResult::new(
        "SV-E-equilateral[corrected]",
        "(0,0), (1,0), (1/2, −√3/2) is equilateral (R 1360)",
    );
    let (a, b) = side([0.5, -(3f64.sqrt()) / 2.0]);
    c.examined = 1;
    let tol = 4.0 * f64::EPSILON;
    c.worst_deviation = Some((a - 1.0).abs().max((b - 1.0).abs()));
    c.tolerance = Some(tol);
    if (a - 1.0).abs() > tol || (b - 1.0).abs() > tol {
        c.offend(|| Witness::new(format!("sides {a}, {b}"), json!({})));
    }
    (w, c)
}

/// All errata rows for the degrees of a mesh.
pub fn run_errata(degrees: &[u32]) -> Vec<CheckResult> {
    let (eq, eqc) = check_equilateral();
    vec![
        check_gu_factor_as_written(degrees),
        check_gu_factor_corrected(degrees),
        check_angle_range_as_written(degrees),
        check_angle_range_corrected(degrees),
        eq,
        eqc,
    ]
}
