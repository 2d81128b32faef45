//! Vertex provers: D4.1.9-lens(cert) and the star conditions (C5.4, C4.2).

use super::bnb::{bnb, canon_edge, disk_box, finish, Leaf, Settings, MP_PREC};
use super::config::ConfigKey;
use super::interval::{member_any, two_pi_frac, Deg, Domain};
use super::model::Model;
use super::result::{CertWitness, PropertyResult};
use super::{interval, sector};
use crate::construction::maps::Ppm;
use crate::construction::maps::{EdgeConfig, P2};
use crate::numeric::interval::Interval as I;
use crate::numeric::{Mp, Trit};
use std::time::Instant;

// ---------------------------------------------------------------------------------------------
// Vertex provers.
// ---------------------------------------------------------------------------------------------

/// D4.1.9-lens(cert): for every point p of Ω_u, the Sec. 6.1.3 lens test agrees with the
/// literal Def. 4.1.9 (for every m_w: the closed form does not depend on it). With the
/// paper's radius a box is proven by intervals, or else by the exact sheet bound of
/// `sector` (Lemma B: for m_u ≤ 10 a lens point has |α| < π/3, hence winding 0), which
/// decides the tangency of the cut ray at m_u = 10 with no δ.
pub fn prove_lens_agreement(m: u32, model: &Model, s: &Settings) -> PropertyResult {
    let t0 = Instant::now();
    let d = Deg::new(m);
    let lens = Domain::Lens {
        r2: model.lens_r2(),
    };
    let paper_lens = model.lens_radius_offset == 0.0;
    let st = bnb(disk_box(m), s.max_depth, s.budget, |b| {
        let (th, r) = (b.ith(), b.ir());
        let lit = member_any(&d, th, r, Domain::Literal);
        if paper_lens {
            // With the paper's radius, lens ≡ (r>0 ∧ |b−(1,0)|²<3/4 ∧ r<r_u) exactly
            // (|b|² < 3/4 ⇔ r < r_u), and literal = lens ∧ winding0: agreement ⇔ lens ⇒ winding0.
            let l = member_any(&d, th, r, lens);
            let w = interval::all_pieces(
                &interval::principal_pieces(th)
                    .into_iter()
                    .map(|p| d.winding0(p))
                    .collect::<Vec<_>>(),
            );
            if l.is_false() || w.is_true() {
                return Leaf::Proven(None, None);
            }
            if l.is_true() && w.is_false() {
                return Leaf::Refuted("lens test True, literal Def. 4.1.9 False".into());
            }
            // Where intervals cannot separate the lens from the winding cut (m_u = 10: the
            // ray θ = π is tangent to D), the exact sector argument decides (`sector`).
            if sector::lens_winding0_exact(&d, th, r) {
                return Leaf::Proven(None, None);
            }
            return Leaf::Split;
        }
        let l = member_any(&d, th, r, lens);
        match (lit, l) {
            (Trit::True, Trit::True) | (Trit::False, Trit::False) => Leaf::Proven(None, None),
            (Trit::True, Trit::False) => {
                Leaf::Refuted("literal Def. 4.1.9 True, lens test False".into())
            }
            (Trit::False, Trit::True) => {
                Leaf::Refuted("lens test True, literal Def. 4.1.9 False".into())
            }
            _ => Leaf::Split,
        }
    });
    let witness = st.refuted.as_ref().map(|(b, txt)| {
        let p = b.centre_xy();
        let e = canon_edge(m, m);
        let f = model.in_omega_uw_literal(&e, &P2::<f64>::new(p[0], p[1]))
            != model.in_omega_uw_lens(&e, &P2::<f64>::new(p[0], p[1]));
        let pm = P2::<Mp>::from_f64(p[0], p[1], MP_PREC);
        let g = model.in_omega_uw_literal(&e, &pm) != model.in_omega_uw_lens(&e, &pm);
        CertWitness {
            point: p,
            text: format!(
                "p = ({:.9}, {:.9}) in u's chart with s_u(w) at label 0 (m_u = {m}): {txt}",
                p[0], p[1]
            ),
            f64_confirms: f,
            mp_confirms: g,
        }
    });
    finish(
        ConfigKey::Vertex { m },
        "D4.1.9-lens(cert)",
        format!(
            "for all p ∈ Ω_u (m_u = {m}), any m_w: [h∘g_u∘R_(u,w)(p) ∈ E (Sec. 6.1.3, lens radius {})] ⇔ [p ∈ Ω_uw, Def. 4.1.9]",
            if paper_lens { "cos(π/6)".to_string() } else { format!("cos(π/6){:+e}", model.lens_radius_offset) }
        ),
        st,
        witness,
        t0,
    )
}

/// C5.4-at-most-two(cert) / C4.2-nonadjacent-disjoint(cert) and their Sec. 6.1.3 variants:
/// for every p ∈ Ω_x (degree m), with Ω_xk the gluing domain of the neighbour at label k.
/// A box is proven by interval membership, or else by the exact sector argument with the
/// sharp bound π/3 (module `sector`: it decides the tangencies of non-adjacent lenses, where
/// bisection alone left δ-boxes).
pub fn prove_star(
    m: u32,
    use_lens: bool,
    nonadjacent: bool,
    model: &Model,
    s: &Settings,
) -> PropertyResult {
    prove_star_with(
        m,
        use_lens,
        nonadjacent,
        model,
        s,
        sector::SectorBound::paper(),
    )
}

/// [`prove_star`] with the sector bound of the exact argument given (a wrong bound is a
/// planted fault: its premise must be refused, `sector::SectorBound::premise`).
pub fn prove_star_with(
    m: u32,
    use_lens: bool,
    nonadjacent: bool,
    model: &Model,
    s: &Settings,
    bound: sector::SectorBound,
) -> PropertyResult {
    let t0 = Instant::now();
    let d = Deg::new(m);
    let dom = if use_lens {
        Domain::Lens {
            r2: model.lens_r2(),
        }
    } else {
        Domain::Literal
    };
    let adjacent = |a: usize, b: usize| {
        let diff = (a as i64 - b as i64).rem_euclid(m as i64);
        diff == 1 || diff == m as i64 - 1
    };
    let shifts: Vec<I> = (0..m).map(|k| two_pi_frac(k as i64, m as i64)).collect();
    let st = bnb(disk_box(m), s.max_depth, s.budget, |b| {
        let (th, r) = (b.ith(), b.ir());
        let ts: Vec<Trit> = shifts
            .iter()
            .map(|sh| member_any(&d, th - *sh, r, dom))
            .collect();
        let maybe: Vec<usize> = (0..ts.len()).filter(|&k| !ts[k].is_false()).collect();
        let sure: Vec<usize> = (0..ts.len()).filter(|&k| ts[k].is_true()).collect();
        if nonadjacent {
            let bad_maybe = maybe
                .iter()
                .any(|&a| maybe.iter().any(|&c2| a != c2 && !adjacent(a, c2)));
            if !bad_maybe {
                return Leaf::Proven(None, None);
            }
            for &a in &sure {
                for &c2 in &sure {
                    if a != c2 && !adjacent(a, c2) {
                        return Leaf::Refuted(format!("p ∈ Ω_x{a} ∩ Ω_x{c2}, labels not adjacent"));
                    }
                }
            }
        } else if maybe.len() <= 2 {
            return Leaf::Proven(None, None);
        } else if sure.len() >= 3 {
            return Leaf::Refuted(format!(
                "p lies in {} gluing domains, labels {:?}",
                sure.len(),
                sure
            ));
        }
        if sector::star_exact(&d, th, r, dom, bound, nonadjacent) {
            Leaf::Proven(None, None)
        } else {
            Leaf::Split
        }
    });
    let witness = st.refuted.as_ref().map(|(b, txt)| {
        let p = b.centre_xy();
        let count = |f64side: bool| -> Vec<u32> {
            (0..m)
                .filter(|&k| {
                    let e = EdgeConfig {
                        m_u: m,
                        i: k,
                        m_w: m,
                        j: 0,
                    };
                    let t = if f64side {
                        let q = P2::<f64>::new(p[0], p[1]);
                        if use_lens {
                            model.in_omega_uw_lens(&e, &q)
                        } else {
                            model.in_omega_uw_literal(&e, &q)
                        }
                    } else {
                        let q = P2::<Mp>::from_f64(p[0], p[1], MP_PREC);
                        if use_lens {
                            model.in_omega_uw_lens(&e, &q)
                        } else {
                            model.in_omega_uw_literal(&e, &q)
                        }
                    };
                    t.is_true()
                })
                .collect()
        };
        let ok = |ks: &[u32]| {
            if nonadjacent {
                ks.iter().any(|&a| {
                    ks.iter()
                        .any(|&c2| a != c2 && !adjacent(a as usize, c2 as usize))
                })
            } else {
                ks.len() >= 3
            }
        };
        let (kf, km) = (count(true), count(false));
        CertWitness {
            point: p,
            text: format!(
                "p = ({:.9}, {:.9}) in x's chart (m_x = {m}): {txt}; f64 finds labels {kf:?}",
                p[0], p[1]
            ),
            f64_confirms: ok(&kf),
            mp_confirms: ok(&km),
        }
    });
    let sfx = if use_lens { "[sec6.1.3]" } else { "" };
    let (id, stmt) = if nonadjacent {
        (
            format!("C4.2-nonadjacent-disjoint{sfx}(cert)"),
            format!(
                "Ω_xa ∩ Ω_xb = ∅ for all labels a, b not adjacent mod {m}{}",
                if use_lens {
                    " (Sec. 6.1.3 lens domains)"
                } else {
                    " (Def. 4.1.9)"
                }
            ),
        )
    } else {
        (
            format!("C5.4-at-most-two{sfx}(cert)"),
            format!(
                "every p ∈ Ω_x (m_x = {m}) lies in at most two Ω_xk{}",
                if use_lens {
                    " (Sec. 6.1.3 lens domains)"
                } else {
                    " (Def. 4.1.9)"
                }
            ),
        )
    };
    finish(ConfigKey::Vertex { m }, &id, stmt, st, witness, t0)
}
