//! Interval building blocks for the provers: principal-angle reduction across Π's cut, the
//! closed form of the literal Ω_uw (Def. 4.1.9) and the transition φ_wu in polar form.
//!
//! ## The closed form of Def. 4.1.9 (what the provers decide)
//! Let a = R_(u,w)(p) = Π⁻¹(θ, r), θ ∈ (−π, π] (Def. 4.1.5), α = m_u θ/6, ρ = k_u r with
//! k_u = cos(π/6)/cos(π/m_u), and b = g_u(a) = ρ(cos α, sin α) (Def. 4.1.6). The literal
//! Def. 4.1.9 asks that q = g_(u,w)(p) ∈ Ω_w − {0} and g_(w,u)(q) = p. Exactly:
//! * q ∈ Ω_w − {0} ⇔ |h(b)| < cos(π/6) ⇔ |b − (1,0)|² < 3/4 (g_w⁻¹ scales radii by 1/k_w);
//! * then c = h(b) lies in the lens E, so c_x > 0 and Π(d), d = g_w⁻¹(c), has angle 6β/m_w
//!   (|6β/m_w| < π), hence g_w(d) = c, h(c) = b exactly;
//! * g_u⁻¹(b) = a iff Π(b) = (α, ρ), i.e. iff the winding of α is 0: |θ| < 6π/m_u for
//!   m_u > 6 (always for m_u ≤ 6); otherwise g_u⁻¹(b) is a rotated by 12πn/m_u with
//!   0 < 6|n| < m_u, at distance 2r|sin(6πn/m_u)| ≥ 2·0.077·sin(π/m_u) from a, far above the
//!   round-trip tolerance.
//!
//! So p ∈ Ω_uw ⇔ 0 < r < cos(π/m_u) ∧ |b − (1,0)|² < 3/4 ∧ winding(θ) = 0, which is
//! independent of m_w. The Sec. 6.1.3 lens test is the same without the winding condition
//! (|b|² < 3/4 ⇔ r < cos(π/m_u)).

use crate::numeric::interval::Interval as I;
use crate::numeric::Trit;

/// The point interval `[x, x]`.
pub fn c(x: f64) -> I {
    I::try_from((x, x)).unwrap_or(I::ENTIRE)
}
/// `[lo, hi]` (the entire line for an invalid pair: always a sound enclosure).
pub fn iv(lo: f64, hi: f64) -> I {
    I::try_from((lo, hi)).unwrap_or(I::ENTIRE)
}
/// `[−x, x]`: an error of magnitude at most `x`.
pub fn sym(x: f64) -> I {
    iv(-x, x)
}
/// Enclosure of p/q.
pub fn ratio(p: i64, q: i64) -> I {
    c(p as f64) / c(q as f64)
}
/// Enclosure of 2π·p/q.
pub fn two_pi_frac(p: i64, q: i64) -> I {
    I::PI * ratio(2 * p, q)
}
/// `a < b` decided for all points of the enclosures.
pub fn lt(a: I, b: I) -> Trit {
    let d = a - b;
    if d.sup() < 0.0 {
        Trit::True
    } else if d.inf() >= 0.0 {
        Trit::False
    } else {
        Trit::Unknown
    }
}
/// Combine the values of one predicate on several pieces covering the same set of points.
pub fn all_pieces(ts: &[Trit]) -> Trit {
    if ts.iter().all(|t| t.is_true()) && !ts.is_empty() {
        Trit::True
    } else if ts.iter().all(|t| t.is_false()) {
        Trit::False
    } else {
        Trit::Unknown
    }
}

/// Enclosures whose union contains the principal angle (Π's θ ∈ (−π, π], Def. 4.1.5) of
/// every angle in `th` (width < 2π). One piece, or two when `th` crosses the cut ±π: the
/// interval version of "a box straddling the negative x-axis is handled as two boxes".
pub fn principal_pieces(th: I) -> Vec<I> {
    principal_pieces_k(th).into_iter().map(|(p, _)| p).collect()
}

/// [`principal_pieces`] with the wrap integer of each piece: every point of the piece is
/// t − 2πk for a point t of `th` (exactly, as real numbers), with `k` the returned integer.
/// The provers use `k` for exact identities between reduced angles (e.g. "θ_w − θ_x =
/// 2π/m_u exactly on this box"), which intervals alone cannot certify.
pub fn principal_pieces_k(th: I) -> Vec<(I, i64)> {
    let two_pi = I::PI * c(2.0);
    let kf = (th.mid() / (2.0 * std::f64::consts::PI)).round();
    let k = if kf.is_finite() && kf.abs() < 1e15 {
        kf as i64
    } else {
        0
    };
    let t = th - two_pi * c(k as f64);
    let (pl, ph) = (I::PI.inf(), I::PI.sup());
    let range = iv(-ph, ph);
    let mut v = Vec::with_capacity(2);
    let main = t.intersection(range);
    if !main.is_empty() {
        v.push((main, k));
    }
    if t.sup() > pl {
        let p = (t.intersection(iv(pl, f64::INFINITY)) - two_pi).intersection(range);
        if !p.is_empty() {
            v.push((p, k + 1));
        }
    }
    if t.inf() < -pl {
        let p = (t.intersection(iv(f64::NEG_INFINITY, -pl)) + two_pi).intersection(range);
        if !p.is_empty() {
            v.push((p, k - 1));
        }
    }
    v
}

/// Per-degree constants (enclosures).
#[derive(Debug, Clone, Copy)]
pub struct Deg {
    /// The degree m.
    pub m: u32,
    /// r_v = cos(π/m) (Def. 4.1.1).
    pub rm: I,
    /// k = cos(π/6)/cos(π/m), the radial factor of f_v (Def. 4.1.6).
    pub k: I,
    /// m/6.
    pub m6: I,
    /// 6/m.
    pub six_m: I,
    /// 6π/m: the half-width of the winding-0 sector.
    pub wind: I,
}

impl Deg {
    /// Enclosures of the constants of degree m.
    pub fn new(m: u32) -> Deg {
        let rm = (I::PI / c(m as f64)).cos();
        let s3h = c(3.0).sqrt() / c(2.0);
        Deg {
            m,
            rm,
            k: s3h / rm,
            m6: ratio(m as i64, 6),
            six_m: ratio(6, m as i64),
            wind: I::PI * ratio(6, m as i64),
        }
    }
    /// winding(θ) = 0 for a principal angle θ (see the module docs).
    pub fn winding0(&self, th: I) -> Trit {
        if self.m <= 6 {
            return Trit::True;
        }
        let w = self.wind;
        if th.inf() > -w.inf() && th.sup() < w.inf() {
            Trit::True
        } else if th.inf() >= w.sup() || th.sup() <= -w.sup() {
            Trit::False
        } else {
            Trit::Unknown
        }
    }
}

/// Which description of Ω_uw to decide.
#[derive(Debug, Clone, Copy)]
pub enum Domain {
    /// The literal Def. 4.1.9 (closed form of the module docs).
    Literal,
    /// The Sec. 6.1.3 lens test with lens radius² `r2` (3/4 for the paper).
    Lens {
        /// Enclosure of the squared lens radius (3/4 for the paper).
        r2: I,
    },
}

/// Membership of the point with principal angle `th` (relative to the neighbour's label
/// direction, i.e. after R_(u,w)) and radius `r` in Ω_uw.
pub fn member(d: &Deg, th: I, r: I, dom: Domain) -> Trit {
    let rho = d.k * r;
    let a = d.m6 * th;
    let dq = rho.sqr() - c(2.0) * rho * a.cos() + c(1.0); // |b − (1,0)|²
    let rpos = if r.inf() > 0.0 {
        Trit::True
    } else if r.sup() <= 0.0 {
        Trit::False
    } else {
        Trit::Unknown
    };
    match dom {
        Domain::Literal => rpos
            .and(lt(dq, ratio(3, 4)))
            .and(lt(r, d.rm))
            .and(d.winding0(th)),
        Domain::Lens { r2 } => rpos.and(lt(dq, r2)).and(lt(rho.sqr(), r2)),
    }
}

/// Membership for an unreduced angle `th` (handles the cut by pieces).
pub fn member_any(d: &Deg, th: I, r: I, dom: Domain) -> Trit {
    let ts: Vec<Trit> = principal_pieces(th)
        .into_iter()
        .map(|p| member(d, p, r, dom))
        .collect();
    all_pieces(&ts)
}

/// φ_wu in polar form, canonical frames: from u's polar (θ principal, relative to s_u(w)) to
/// w's polar (angle relative to s_w(u), radius). `None` when the branch condition c_x > 0
/// (c = h(g_u(a)) in the right half-plane, so Π(c) is off the cut) is not certified.
pub fn phi_polar(du: &Deg, dw: &Deg, th: I, r: I) -> Option<(I, I)> {
    let rho = du.k * r;
    let a = du.m6 * th;
    let cx = c(1.0) - rho * a.cos();
    let cy = -(rho * a.sin());
    if cx.inf() <= 0.0 {
        return None;
    }
    let beta = cy.atan2(cx);
    let s = (cx.sqr() + cy.sqr()).sqrt();
    Some((dw.six_m * beta, s / dw.k))
}
