//! CERT-f64-props: a proven bound on what the `f64` evaluator computes for every certified
//! property (beyond `P4.2.3(cert)`'s CERT-f64-rounding and the vertices' CERT-f64-g-chart),
//! derived from those per-edge and per-degree bounds of the same certificate: no box is
//! evaluated again, so attaching the bounds to a finished certificate costs milliseconds
//! ([`attach_f64_bounds`]; `ppm certify attach FILE` adds them to an older certificate).
//!
//! Notation: φ(a, b) is CERT-f64-rounding's `phi` of the edge configuration (m_u, m_w) =
//! (a, b), a bound on |φ̂_wu(p) − φ_wu(p)| for every `f64` p of Ω_uw, all labels (hats: the
//! `f64` evaluation of the generic maps); `outer`(a), `inner`(a, b) bound the `f64` errors of
//! the literal membership test's quantities |p|² − r_u², |q|² − r_w²; G(m) is CERT-f64-g-chart's
//! bound on |ĝ_v(a) − g_v(a)| for every `f64` a ≠ 0 of the square |x|, |y| ≤ 1; u = 2⁻⁵³.
//!
//! ## The arguments
//! * Lipschitz constants. On Ω_ab the exact φ_ba = R⁻¹∘g_b⁻¹∘h∘g_a∘R is C¹: g_a∘R_(a,b)(p) = b
//!   lies in the lens E = C ∩ D, whose points have |arg| < π/3 (the tangents from 0 to D), so
//!   the angle of R_(a,b)(p) is below 2π/a ≤ 2π/3 in magnitude (off Π's cut), and h(b) ∈ E
//!   likewise; 0 ∉ D. Rotations and h are isometries and ‖J(g_v)‖ = k_v·max(1, v/6),
//!   ‖J(g_v⁻¹)‖ = max(1, 6/v)/k_v at every point off the origin (`certify::f64_roundtrip`,
//!   checked against the analytic Jacobians), so ‖J(φ_ba)‖ ≤ L(a→b) = k_a·max(1, a/6) ·
//!   max(1, 6/b)/k_b on Ω_ab, and the mean value theorem applies on every segment inside it.
//! * `L4.2.2(cert)` (triangle u, w, x): at an `f64` point p of φ_xu⁻¹(Ω_xu ∩ Ω_xw) = Ω_ux ∩ Ω_uw
//!   the check computes |φ̂_wu(p) − φ̂_wx(q̂)|, q̂ = φ̂_xu(p), whose exact value is 0 (the
//!   cocycle). |q̂ − q| ≤ φ(u, x), q = φ_xu(p) ∈ Ω_xw. CERT-f64-rounding's φ(x, w) holds on
//!   the closed ε-neighbourhood N_ε(Ω_xw) (module `f64_outside`), and ε ≥ φ(u, x) is checked
//!   (else no bound): the segment [q, q̂] lies in the ball of radius φ(u, x) about q, inside
//!   N_ε(Ω_xw), where the exact chain is C¹ (every box the φ pass bounded there had `Fe`
//!   decide Π's branch for the exact values) with ‖J(φ_wx)‖ ≤ L(x→w) (point-independent
//!   norms), so |φ̂_wx(q̂) − φ_wx(q)| ≤ φ(x, w) + L(x→w)·φ(u, x); with
//!   |φ̂_wu(p) − φ_wu(p)| ≤ φ(u, w) and φ_wu(p) = φ_wx(q) the exact gap of the two `f64`
//!   points is ≤ S = φ(u, w) + φ(x, w) + L(x→w)·φ(u, x); the `f64` distance (two subtractions,
//!   two squares, a sum, a square root) adds at most a factor 1 + 4u, and 2⁻⁵³⁰ for gradual
//!   underflow (√ of a few 2⁻¹⁰⁷⁴). A certificate written before the neighbourhood existed
//!   gets no bound (its former claim excluded a band along ∂Ω_xw).
//! * `L4.2.3(cert)`: for an `f64` point p of Ω_uw at distance d from the inner arc, the `f64`
//!   radius fl(|φ̂_wu(p)|) differs from |φ_wu(p)| by ≤ φ(u, w) + 3u(1 + φ(u, w)) (|φ_wu(p)| <
//!   r_w < 1; the radius rounds by < 2.6u relatively), and |φ_wu(p)| from r_w (its value on the
//!   arc) by ≤ L(u→w)·d (the segment to the nearest arc point lies in Ω_uw).
//! * Membership (`L4.2.1(cert)`, `P4.2.1(cert)`, the literal star rows and the literal side of
//!   `D4.1.9-lens(cert)`): the `f64` literal test at an `f64` point of Ω_u decides as the exact
//!   one unless one of its tested quantities lies within its bound of 0: on N_ε(Ω_uw) by
//!   `outer`, `inner` (its leaves have winding 0, so off Ω_uw the exact "out" is a sign), the
//!   round trip exactly on Ω_uw where CERT-f64-rounding says `roundtrip_exact` (`decided`); on
//!   the rest of Ω_u (exact answer "out") by the pass off the neighbourhood (`outside`: the
//!   `f64` |q̂|² − r_w² certified positive, or its margin, or the `f64` round trip certified
//!   far); `bound` is the largest of these margins of the tests the property's check runs.
//!   For `L4.2.1(cert)` the test of q̂ ∈ Ω_xw runs at q̂ ∈ N_ε(Ω_xw): its quantities there
//!   differ from those at q by ≤ 2.02·max(1, L(x→w))·φ(u, x) (gradients 2|z| and
//!   2|φ_wx(z)|·L(x→w) on the segment [q, q̂], |z|, |φ_wx(z)| ≤ 1 + Lε), which `bound` adds;
//!   if they clear it, q̂ ∈ Ω_xw and its round trip is certified too.
//! * Lens (Sec. 6.1.3 rows, the lens side of `D4.1.9-lens(cert)`): for p ∈ Ω_v (|p| < 1) and a
//!   label rotation, â = R̂(p) is an `f64` point of the unit square (|â| ≤ |p| + ρ < cos(π/64) + ρ < 1), so
//!   |ĝ(â) − g(â)| ≤ G(m), and ĉ = h(ĝ(â)) (one rounded subtraction, |ĉ_x| < 3) is within
//!   e = G(m) + 3u of c = h(g(â)). The tested quantities Q₁ = |c|², Q₂ = |c − (1, 0)|² = |b|²
//!   (|c| ≤ 1 + k, |b| ≤ k) then differ in `f64` by ≤ e(2(1 + k) + e) + 3u(1 + k + e)², and
//!   from their values at the exact R(p) by ≤ Lip·ρ (ρ: the rotations' `f64` error,
//!   `certify::f64_roundtrip`; Q₂ = k²|a|² has Lip ≤ 2k², Q₁ = 1 − 2 Re b + |b|² is
//!   continuous across Π's cut (Re b = kr cos(mθ/6) is even in θ) with Lip ≤ 2‖J(g)‖ + 2k²):
//!   the lens decisions are exact unless Q₁ or Q₂ lies within that bound of 3/4, and the
//!   punctures (c ≠ 0, c ≠ (1, 0)) unless Q₁ or Q₂ lies within it of 0 (a positive rounded
//!   |ĉ|² means ĉ ≠ 0). Underflow: 8·2⁻¹⁰⁷⁴.

use super::bnb::canon_edge;
use super::certificate::Certificate;
use super::config::ConfigKey;
use super::f64_roundtrip::rotation_error;
use super::interval::{c, Deg};
use super::prove_edge::iv_point;
use super::result::{F64Bound, F64Rounding, GChartRounding, PropertyResult};
use crate::construction::maps::Paper;
use crate::construction::maps::Ppm;
use crate::numeric::interval::Interval as I;
use crate::numeric::rounding::{Glibc, UNIT_ROUNDOFF};
use crate::numeric::Iv;
use std::collections::BTreeMap;

/// The statement of CERT-f64-props for one property (`None`: the property has none here).
pub fn f64_bound_statement(property: &str) -> Option<&'static str> {
    Some(match property {
        "L4.2.2(cert)" => "for every f64 point p of φ_xu⁻¹(Ω_xu ∩ Ω_xw) (no band: φ(x,w) holds on the ε-neighbourhood of Ω_xw, ε ≥ φ(u,x) checked, else no bound): the f64 cocycle gap |φ̂_wu(p) − φ̂_wx(φ̂_xu(p))| (exact value 0) is ≤ `bound` = (φ(u,w) + φ(x,w) + L·φ(u,x))(1 + 4u) + 2⁻⁵³⁰, L = `lipschitz` = ‖J(φ_wx)‖ on that neighbourhood",
        "L4.2.3(cert)" => "for every f64 point p of Ω_uw at distance d from the inner arc: |fl(|φ̂_wu(p)|) − r_w| ≤ `bound` + `lipschitz`·d, `bound` = φ(u,w) + 3u(1 + φ(u,w)) (r_w = |φ_wu| on the arc)",
        "L4.2.1(cert)" => "for every f64 point p of Ω_ux ∩ Ω_uw (no band): the three f64 literal tests of the check (p ∈ Ω_ux, φ̂_xu(p) ∈ Ω_xw, p ∈ Ω_uw) answer exactly ('in') unless a tested |·|² − r² (at p, resp. at q = φ_xu(p)) lies within `bound` of 0: `bound` = the tests' largest margin + `lipschitz`·φ(u,x), `lipschitz` = 2.02·max(1, ‖J(φ_wx)‖) bounding the gradients of |q|² − r_x² and |φ_wx(q)|² − r_w² on the ε-neighbourhood of Ω_xw (ε ≥ φ(u,x) checked, else no bound); round trips exact where `decided`",
        "P4.2.1(cert)" => "the f64 literal test that accepted the witness point of each direction decides exactly: its tested |·|² − r² clear `bound` (their f64 errors) and the round trip is certified exact (`decided`)",
        "D4.1.9-lens(cert)" => "for every f64 point p of Ω_u: the lens test's f64 decisions |c|² < 3/4, |c − (1,0)|² < 3/4 are exact unless those quantities lie within `bound` of 3/4, and its punctures c ≠ 0, c ≠ (1,0) unless they lie within `bound` of 0; the literal test's (any m_w ≤ M) answers exactly unless |p|² − r_u² or |q|² − r_w² lies within `bound` of 0 (on Ω_uw and its ε-neighbourhood by CERT-f64-rounding's `outer`, `inner`; on the rest of Ω_u, where the exact answer is 'out', by its pass off the neighbourhood: value, margin or round trip), round trips exact on Ω_uw where `decided`",
        "C5.4-at-most-two(cert)" | "C4.2-nonadjacent-disjoint(cert)" => "for every f64 point p of Ω_x and every label k: the f64 literal test p ∈ Ω_xk (m_w = m_x) decides exactly unless a tested |·|² − r² lies within `bound` of 0 (on all of Ω_x: the margins on Ω_xk's ε-neighbourhood and off it, CERT-f64-rounding); round trips exact on Ω_xk where `decided`",
        "C5.4-at-most-two[sec6.1.3](cert)" | "C4.2-nonadjacent-disjoint[sec6.1.3](cert)" => "for every f64 point p of Ω_x and every label k: the lens test's f64 decisions |c|² < 3/4, |c − (1,0)|² < 3/4 (c = h∘g_x∘R_(x,k)(p)) are exact unless those quantities lie within `bound` of 3/4, and its punctures unless they lie within `bound` of 0",
        "P4.2.3(cert)" => "CERT-f64-rounding: |φ̂_wu(p) − φ_wu(p)| ≤ `phi` on Ω_uw (section below)",
        _ => return None,
    })
}

fn up(x: I) -> f64 {
    x.sup()
}

/// `x` rounded up to three significant digits (a larger bound is still proven; the short
/// numbers keep the certificate files small: 54,000 triangle results at M = 32).
pub fn round_up_3(x: f64) -> f64 {
    if !x.is_finite() || x <= 0.0 {
        return x;
    }
    match format!("{:.2e}", x * 1.005).parse::<f64>() {
        Ok(y) if y >= x => y,
        _ => x,
    }
}

/// ‖J(g_v)‖ = k·max(1, m/6).
fn lip_g(d: &Deg) -> I {
    d.k * d.m6.max(c(1.0))
}

/// ‖J(g_v⁻¹)‖ = max(1, 6/m)/k.
fn lip_g_inv(d: &Deg) -> I {
    d.six_m.max(c(1.0)) / d.k
}

/// L(a→b): the norm bound of J(φ_ba) on Ω_ab (module docs).
pub fn phi_lipschitz(a: u32, b: u32) -> f64 {
    up(lip_g(&Deg::new(a)) * lip_g_inv(&Deg::new(b)))
}

/// The per-edge and per-degree bounds a certificate carries.
struct Sources<'a> {
    edges: BTreeMap<(u32, u32), &'a F64Rounding>,
    charts: BTreeMap<u32, &'a GChartRounding>,
    /// The largest degree whose edges the certificate holds, per m_u.
    partners: BTreeMap<u32, Vec<u32>>,
}

impl<'a> Sources<'a> {
    fn of(cert: &'a Certificate) -> Sources<'a> {
        let mut s = Sources {
            edges: BTreeMap::new(),
            charts: BTreeMap::new(),
            partners: BTreeMap::new(),
        };
        for r in &cert.results {
            match (r.key, &r.f64_rounding, &r.g_chart) {
                (ConfigKey::Edge { m_u, m_w }, Some(f), _) => {
                    s.edges.insert((m_u, m_w), f);
                    s.partners.entry(m_u).or_default().push(m_w);
                }
                (ConfigKey::Vertex { m }, _, Some(g)) => {
                    s.charts.insert(m, g);
                }
                _ => {}
            }
        }
        s
    }
    fn phi(&self, a: u32, b: u32) -> Option<f64> {
        self.edges.get(&(a, b)).and_then(|f| f.phi)
    }
    /// ε of the neighbourhood of Ω_ab on which φ(a, b) holds (`None`: an older certificate,
    /// on Ω_ab only).
    fn nbhd(&self, a: u32, b: u32) -> Option<f64> {
        self.edges.get(&(a, b)).and_then(|f| f.nbhd)
    }
    /// max(outer, inner, the margin off the neighbourhood) of the edge and its round-trip
    /// verdict: the literal test at every `f64` point of Ω_a (module docs). An older
    /// certificate without the pass off the neighbourhood has none.
    fn margin(&self, a: u32, b: u32) -> Option<(f64, bool)> {
        self.edges.get(&(a, b))?.literal_margin()
    }
}

/// The maximum of margins (a missing one makes the whole `None`).
fn margins(ms: &[Option<(f64, bool)>]) -> Option<(f64, bool)> {
    ms.iter().try_fold((0.0f64, true), |(m, d), x| {
        x.map(|(m2, d2)| (crate::report::dev_max(m, m2), d && d2))
    })
}

/// The lens test's margin for degree m (module docs), from G(m) and the rotations' error.
fn lens_margin(m: u32, g: &GChartRounding) -> Option<f64> {
    let gv = g.g_v?;
    if g.radius < 1.0 || !gv.is_finite() {
        return None;
    }
    let d = Deg::new(m);
    let u = c(UNIT_ROUNDOFF);
    let e = c(gv) + c(3.0) * u;
    let cmax = c(1.0) + d.k;
    let rho = c(crate::report::dev_max(
        rotation_error::<Glibc>(m, -1),
        rotation_error::<Glibc>(m, 1),
    ));
    let k2 = d.k.sqr();
    let lip = c(2.0) * lip_g(&d) + c(2.0) * k2;
    let own = e * (c(2.0) * cmax + e) + c(3.0) * u * (cmax + e).sqr();
    let b = up(own + lip * rho + c(4e-323));
    b.is_finite().then_some(b)
}

/// Does the neighbourhood ε of Ω_xw on which φ(x, w) holds contain every q̂ = φ̂_xu(p)
/// (|q̂ − q| ≤ φ(u, x), q ∈ Ω_xw)? No for an older certificate (no neighbourhood); no
/// refuses the bound.
pub fn covers_band(nbhd: Option<f64>, phi_ux: Option<f64>) -> bool {
    match (nbhd, phi_ux) {
        (Some(eps), Some(x)) => x.is_finite() && x <= eps,
        _ => false,
    }
}

/// P4.2.1's witness point of the direction (a, b) clears the literal test's margins.
fn nonempty_point_clears(a: u32, b: u32, m: (f64, bool)) -> bool {
    let d = Deg::new(a);
    let rp = (c(0.5) / d.k).mid();
    let p = iv_point([rp, 0.0]);
    let s1 = Iv(c(rp).sqr() - d.rm.sqr());
    let e = canon_edge(a, b);
    let Ok(q) = Paper.g_uw_inv(&e.reversed(), &p) else {
        return false;
    };
    let s2 = Iv(q.norm2().0 - Deg::new(b).rm.sqr());
    let mig = |x: Iv| {
        if x.inf() > 0.0 {
            x.inf()
        } else if x.sup() < 0.0 {
            -x.sup()
        } else {
            0.0
        }
    };
    m.1 && mig(s1) > m.0 && mig(s2) > m.0
}

/// CERT-f64-props for one result, from the certificate's per-edge and per-degree bounds.
fn bound_of(r: &PropertyResult, src: &Sources, max_degree: u32) -> Option<F64Bound> {
    let none = F64Bound {
        bound: None,
        lipschitz: None,
        band: None,
        decided: None,
    };
    let membership = |m: Option<(f64, bool)>| F64Bound {
        bound: m.map(|x| x.0),
        decided: m.map(|x| x.1),
        ..none.clone()
    };
    Some(match (r.property.as_str(), r.key) {
        ("L4.2.2(cert)", ConfigKey::Triangle { m_u, m_w, m_x, .. }) => {
            let l = phi_lipschitz(m_x, m_w);
            let covered = covers_band(src.nbhd(m_x, m_w), src.phi(m_u, m_x));
            let b = match (src.phi(m_u, m_w), src.phi(m_x, m_w), src.phi(m_u, m_x)) {
                (Some(a), Some(b), Some(x)) if covered => {
                    let s = (c(a) + c(b) + c(l) * c(x)) * (c(1.0) + c(4.0 * UNIT_ROUNDOFF))
                        + c(2f64.powi(-530));
                    Some(up(s)).filter(|v| v.is_finite())
                }
                _ => None,
            };
            F64Bound {
                bound: b,
                lipschitz: Some(l),
                band: None,
                decided: None,
            }
        }
        ("L4.2.1(cert)", ConfigKey::Triangle { m_u, m_w, m_x, .. }) => {
            let covered = covers_band(src.nbhd(m_x, m_w), src.phi(m_u, m_x));
            let m = margins(&[
                src.margin(m_u, m_x),
                src.margin(m_x, m_w),
                src.margin(m_u, m_w),
            ]);
            // The test at q̂ answers as the exact one at q = φ_xu(p) unless a quantity at q
            // lies within its margin plus the quantities' Lipschitz constant times φ(u, x).
            let m = match (covered, m, src.phi(m_u, m_x)) {
                (true, Some((b, d)), Some(x)) => {
                    let lq = c(2.02) * c(phi_lipschitz(m_x, m_w)).max(c(1.0));
                    Some((up(c(b) + lq * c(x)), d)).filter(|v| v.0.is_finite())
                }
                _ => None,
            };
            F64Bound {
                lipschitz: Some(up(c(2.02) * c(phi_lipschitz(m_x, m_w)).max(c(1.0)))),
                ..membership(m)
            }
        }
        ("L4.2.3(cert)", ConfigKey::Edge { m_u, m_w }) => F64Bound {
            bound: src
                .phi(m_u, m_w)
                .map(|p| up(c(p) + c(3.0 * UNIT_ROUNDOFF) * (c(1.0) + c(p)))),
            lipschitz: Some(phi_lipschitz(m_u, m_w)),
            ..none.clone()
        },
        ("P4.2.1(cert)", ConfigKey::Edge { m_u, m_w }) => {
            let m = margins(&[src.margin(m_u, m_w), src.margin(m_w, m_u)]);
            F64Bound {
                bound: m.map(|x| x.0),
                decided: m.map(|x| {
                    nonempty_point_clears(m_u, m_w, x) && nonempty_point_clears(m_w, m_u, x)
                }),
                ..none.clone()
            }
        }
        ("D4.1.9-lens(cert)", ConfigKey::Vertex { m }) => {
            // Any m_w: every partner degree up to M must be present.
            let ws: Vec<u32> = (3..=max_degree).collect();
            let have = src.partners.get(&m).map_or(0, |v| v.len());
            let lit = if have >= ws.len() {
                margins(&ws.iter().map(|&w| src.margin(m, w)).collect::<Vec<_>>())
            } else {
                None
            };
            let lens = src.charts.get(&m).and_then(|g| lens_margin(m, g));
            match (lit, lens) {
                (Some((a, d)), Some(b)) => F64Bound {
                    bound: Some(crate::report::dev_max(a, b)),
                    decided: Some(d),
                    ..none.clone()
                },
                _ => none.clone(),
            }
        }
        ("C5.4-at-most-two(cert)" | "C4.2-nonadjacent-disjoint(cert)", ConfigKey::Vertex { m }) => {
            membership(src.margin(m, m))
        }
        (
            "C5.4-at-most-two[sec6.1.3](cert)" | "C4.2-nonadjacent-disjoint[sec6.1.3](cert)",
            ConfigKey::Vertex { m },
        ) => F64Bound {
            bound: src.charts.get(&m).and_then(|g| lens_margin(m, g)),
            ..none.clone()
        },
        _ => return None,
    })
}

/// Attach CERT-f64-props to every result of the paper's model (a certificate of another model
/// is left as it is: the bounds are about the production evaluator). Bounds whose per-edge or
/// per-degree sources the certificate lacks (a shard) are `None`.
pub fn attach_f64_bounds(cert: &mut Certificate) {
    if cert.model != "paper" {
        return;
    }
    let bounds: Vec<Option<F64Bound>> = {
        let src = Sources::of(cert);
        cert.results
            .iter()
            .map(|r| bound_of(r, &src, cert.max_degree))
            .collect()
    };
    for (r, b) in cert.results.iter_mut().zip(bounds) {
        r.f64_bound = b.map(|b| F64Bound {
            bound: b.bound.map(round_up_3),
            lipschitz: b.lipschitz.map(round_up_3),
            band: b.band.map(round_up_3),
            ..b
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cert_f64_props_round_up_3_never_lowers_a_bound() {
        use rand::{Rng, SeedableRng};
        let mut rng = rand::rngs::StdRng::seed_from_u64(3);
        for _ in 0..100_000 {
            let x: f64 = rng.gen_range(0.5..10.0) * 10f64.powi(rng.gen_range(-20..3));
            let y = round_up_3(x);
            assert!(y >= x && y <= x * 1.011, "{x:e} → {y:e}");
            assert!(format!("{y:e}").len() <= 8, "{y:e}");
        }
        for x in [1.0, 9.995, 9.999999, 1e-13, 0.0] {
            assert!(round_up_3(x) >= x);
        }
        assert!(round_up_3(f64::NAN).is_nan());
    }
}
