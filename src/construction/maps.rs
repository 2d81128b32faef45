//! The maps of Sec. 4.1, generic over [`Scalar`], independent of meshes.
//!
//! Everything for an oriented edge `[u, w]` depends only on an [`EdgeConfig`] (the degrees
//! `m_u, m_w` and the labels `i = s_u(w)`, `j = s_w(u)`), and for a triangle on a
//! [`TriangleConfig`]. Labels follow Def. 4.1.2/4.1.4: `s_v(v_k) = (cos 2πk/m_v, sin 2πk/m_v)`,
//! numbered counterclockwise.
//!
//! The paper's maps are the default methods of the trait [`Ppm`]; the production model is
//! [`Paper`], which overrides nothing. Tests plant faults by overriding single pieces (e.g.
//! [`Ppm::h`] or [`Ppm::in_canonical_lens`]); the composite maps and every check in
//! `checks.rs` are written against the trait, so a planted fault propagates.

pub use super::config::{
    ConfigError, Corner, EdgeConfig, FanOrientation, TriangleConfig, VertexPair, MIN_DEGREE,
};
use crate::numeric::{Scalar, Trit};
use std::cmp::Ordering;

/// A point of R² (one copy of R² per vertex; the copy is implicit).
#[derive(Clone, Debug, PartialEq)]
pub struct P2<S> {
    /// First coordinate.
    pub x: S,
    /// Second coordinate.
    pub y: S,
}

impl<S: Scalar> P2<S> {
    /// The point (x, y).
    pub fn new(x: S, y: S) -> Self {
        P2 { x, y }
    }
    /// (x, y) rounded to `prec` bits in `S`.
    pub fn from_f64(x: f64, y: f64, prec: u32) -> Self {
        P2 {
            x: S::from_f64(x, prec),
            y: S::from_f64(y, prec),
        }
    }
    /// The coordinates as f64 (nearest, or midpoint for intervals).
    pub fn to_f64(&self) -> [f64; 2] {
        [self.x.to_f64(), self.y.to_f64()]
    }
    /// The larger precision of the two coordinates, in bits.
    pub fn prec(&self) -> u32 {
        self.x.precision_bits().max(self.y.precision_bits())
    }
    /// ‖p‖² = x² + y² (no square root, so membership tests stay exact where possible).
    pub fn norm2(&self) -> S {
        self.x.sqr().add(&self.y.sqr())
    }
    /// p − o.
    pub fn sub(&self, o: &Self) -> Self {
        P2::new(self.x.sub(&o.x), self.y.sub(&o.y))
    }
    /// p + o.
    pub fn add(&self, o: &Self) -> Self {
        P2::new(self.x.add(&o.x), self.y.add(&o.y))
    }
    /// k·p.
    pub fn scale(&self, k: &S) -> Self {
        P2::new(self.x.mul(k), self.y.mul(k))
    }
    /// Euclidean distance to `o`, as f64 (for reporting deviations).
    pub fn dist_f64(&self, o: &Self) -> f64 {
        self.sub(o).norm2().sqrt().to_f64()
    }
    /// Convert to another scalar type at precision `prec` (via the f64 value for `f64`
    /// sources, which is exact).
    pub fn convert<T: Scalar>(&self, prec: u32) -> P2<T> {
        P2::from_f64(self.x.to_f64(), self.y.to_f64(), prec)
    }
}

/// Polar coordinates `(θ, r)` as in Def. 4.1.5.
#[derive(Clone, Debug, PartialEq)]
pub struct Polar<S> {
    /// θ, the angle: in (−π, π] when produced by Π; [`f_v`] may leave that range.
    pub theta: S,
    /// r, the length.
    pub r: S,
}

/// A 2×2 Jacobian, row-major: `j[row][col]`, row = output coordinate.
pub type Jac<S> = [[S; 2]; 2];

/// Why a map could not be evaluated.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum MapError {
    /// Π (Def. 4.1.5) and hence g_v (Def. 4.1.6) are undefined at the origin.
    #[error("the point is the origin, where Π (Def. 4.1.5) is undefined")]
    AtOrigin,
    /// The point is not in the domain of the map (e.g. p ∉ Ω_uw for φ_wu, Def. 4.1.10).
    #[error("the point is not in the domain: {0}")]
    NotInDomain(&'static str),
    /// A decision (sign, membership, branch of Π) could not be made at the precision used.
    #[error("undecided at this precision: {0}")]
    Undecided(&'static str),
}

// ---------------------------------------------------------------------------------------------
// Named constants of the construction.
// ---------------------------------------------------------------------------------------------

/// cos(π/6) = √3/2: radius of the canonical circles C and D (Def. 4.1.6, Fig. 4.4).
pub fn cos_pi_6<S: Scalar>(prec: u32) -> S {
    S::from_i64(3, prec).sqrt().div(&S::from_i64(2, prec))
}

/// (cos(π/6))² = 3/4, exactly representable: used for the strict membership tests.
pub fn cos_pi_6_sq<S: Scalar>(prec: u32) -> S {
    S::from_ratio(3, 4, prec)
}

/// r_v = cos(π/m_v): radius of Ω_v (Def. 4.1.1).
pub fn omega_radius<S: Scalar>(m: u32, prec: u32) -> S {
    S::pi(prec).div(&S::from_i64(m as i64, prec)).cos()
}

/// Centre of the circle D of Fig. 4.4 (the image of the centre of C under h).
pub const LENS_D_CENTRE: (i64, i64) = (1, 0);

// ---------------------------------------------------------------------------------------------
// Elementary maps.
// ---------------------------------------------------------------------------------------------

/// Def. 4.1.5: Π(x, y) = (θ, r), θ ∈ (−π, π], r = √(x²+y²) > 0.
///
/// Branch and signed zeros: on the negative x-axis (`y == 0` — either `+0.0` or `-0.0` — and
/// `x < 0`) θ = π exactly as the definition demands (IEEE `atan2(-0.0, -1.0)` would give −π,
/// which is outside the stated range). Elsewhere θ = atan2(y, x), correctly rounded by the
/// library; for y < 0 tiny the rounded θ may be −π_rounded, which approximates a true angle in
/// (−π, π]. Errors: the origin ([`MapError::AtOrigin`]); a sign that cannot be decided.
pub fn polar<S: Scalar>(p: &P2<S>) -> Result<Polar<S>, MapError> {
    if p.x.is_nan() {
        return Err(MapError::Undecided("sign of x in Π"));
    }
    if p.y.is_nan() {
        return Err(MapError::Undecided("sign of y in Π"));
    }
    let theta = match (p.x.sign(), p.y.sign()) {
        (Some(Ordering::Equal), Some(Ordering::Equal)) => return Err(MapError::AtOrigin),
        (Some(Ordering::Less), Some(Ordering::Equal)) => S::pi(p.prec()),
        // Off the closed ray {y = 0, x ≤ 0} atan2 is the principal angle and continuous, so
        // knowing x > 0 or y ≠ 0 suffices: a box that crosses the positive x-axis or the
        // y-axis is decided (point types always know both signs; intervals and
        // `numeric::rounding::Fe` may know only one).
        (Some(Ordering::Greater), _) | (_, Some(Ordering::Less | Ordering::Greater)) => {
            p.y.atan2(&p.x)
        }
        (None, _) => return Err(MapError::Undecided("sign of x in Π")),
        (_, None) => return Err(MapError::Undecided("sign of y in Π")),
    };
    let r = p.norm2().sqrt();
    Ok(Polar { theta, r })
}

/// Def. 4.1.5: Π⁻¹(θ, r) = (r cos θ, r sin θ). Evaluated for any θ (the formula does not need
/// θ ∈ (−π, π]; this matters for f_v, whose image leaves that range when m_v ≠ 6).
pub fn polar_inv<S: Scalar>(q: &Polar<S>) -> P2<S> {
    P2::new(q.r.mul(&q.theta.cos()), q.r.mul(&q.theta.sin()))
}

/// Radial scale factor of f_v: cos(π/6)/cos(π/m_v) (Def. 4.1.6).
pub fn f_v_radial_factor<S: Scalar>(m: u32, prec: u32) -> S {
    cos_pi_6::<S>(prec).div(&omega_radius::<S>(m, prec))
}

/// Def. 4.1.6: f_v(θ, r) = (m_v/6 · θ, cos(π/6)/cos(π/m_v) · r).
///
/// Note: the stated codomain (−π, π] × R₊ is wrong when m_v > 6 (m_v/6·θ reaches ±m_vπ/6).
pub fn f_v<S: Scalar>(m: u32, q: &Polar<S>) -> Polar<S> {
    let prec = q.theta.precision_bits().max(q.r.precision_bits());
    Polar {
        theta: S::from_ratio(m as i64, 6, prec).mul(&q.theta),
        r: f_v_radial_factor::<S>(m, prec).mul(&q.r),
    }
}

/// Def. 4.1.6: f_v⁻¹(β, s) = (6/m_v · β, cos(π/m_v)/cos(π/6) · s).
///
/// Note: the stated codomain (−π, π] × R₊ is wrong when m_v < 6.
pub fn f_v_inv<S: Scalar>(m: u32, q: &Polar<S>) -> Polar<S> {
    let prec = q.theta.precision_bits().max(q.r.precision_bits());
    Polar {
        theta: S::from_ratio(6, m as i64, prec).mul(&q.theta),
        r: q.r.div(&f_v_radial_factor::<S>(m, prec)),
    }
}

/// Def. 4.1.6: g_v = Π⁻¹ ∘ f_v ∘ Π on R² − {0}.
pub fn g_v<S: Scalar>(m: u32, p: &P2<S>) -> Result<P2<S>, MapError> {
    Ok(polar_inv(&f_v(m, &polar(p)?)))
}

/// Def. 4.1.6: g_v⁻¹ = Π⁻¹ ∘ f_v⁻¹ ∘ Π on R² − {0} (the stated inverse formula).
pub fn g_v_inv<S: Scalar>(m: u32, q: &P2<S>) -> Result<P2<S>, MapError> {
    Ok(polar_inv(&f_v_inv(m, &polar(q)?)))
}

/// Jacobian of Π⁻¹ ∘ (θ, r) ↦ (kθ, c·r) ∘ Π at p (valid off the branch cut; on each side of the
/// cut it is the one-sided derivative). Used for g_v (k = m/6, c = cos(π/6)/cos(π/m)) and g_v⁻¹.
fn polar_scaling_jacobian<S: Scalar>(k: &S, c: &S, p: &P2<S>) -> Result<Jac<S>, MapError> {
    let pol = polar(p)?;
    let r2 = p.norm2();
    let (kt_c, kt_s) = (k.mul(&pol.theta).cos(), k.mul(&pol.theta).sin());
    // ∂r/∂x = x/r, ∂r/∂y = y/r, ∂θ/∂x = −y/r², ∂θ/∂y = x/r².
    let drdx = p.x.div(&pol.r);
    let drdy = p.y.div(&pol.r);
    let dtdx = p.y.neg().div(&r2);
    let dtdy = p.x.div(&r2);
    // X = c r cos(kθ), Y = c r sin(kθ).
    let crk = c.mul(&pol.r).mul(k);
    let dxdr = c.mul(&kt_c);
    let dydr = c.mul(&kt_s);
    let dxdt = crk.mul(&kt_s).neg();
    let dydt = crk.mul(&kt_c);
    Ok([
        [
            dxdr.mul(&drdx).add(&dxdt.mul(&dtdx)),
            dxdr.mul(&drdy).add(&dxdt.mul(&dtdy)),
        ],
        [
            dydr.mul(&drdx).add(&dydt.mul(&dtdx)),
            dydr.mul(&drdy).add(&dydt.mul(&dtdy)),
        ],
    ])
}

/// Analytic Jacobian of g_v at p (chain rule through Π, f_v, Π⁻¹).
pub fn g_v_jacobian<S: Scalar>(m: u32, p: &P2<S>) -> Result<Jac<S>, MapError> {
    let prec = p.prec();
    polar_scaling_jacobian(
        &S::from_ratio(m as i64, 6, prec),
        &f_v_radial_factor::<S>(m, prec),
        p,
    )
}

/// Analytic Jacobian of g_v⁻¹ at q.
pub fn g_v_inv_jacobian<S: Scalar>(m: u32, q: &P2<S>) -> Result<Jac<S>, MapError> {
    let prec = q.prec();
    let c = S::from_i64(1, prec).div(&f_v_radial_factor::<S>(m, prec));
    polar_scaling_jacobian(&S::from_ratio(6, m as i64, prec), &c, q)
}

/// Def. 4.1.7: h(x, y) = (1 − x, −y) (reflection in x = 1/2 then in y = 0; a rotation by π
/// about (1/2, 0)).
pub fn h<S: Scalar>(p: &P2<S>) -> P2<S> {
    P2::new(S::from_i64(1, p.prec()).sub(&p.x), p.y.neg())
}

/// Jacobian of h: −I.
pub fn h_jacobian<S: Scalar>(prec: u32) -> Jac<S> {
    let z = S::from_i64(0, prec);
    let m1 = S::from_i64(-1, prec);
    [[m1.clone(), z.clone()], [z, m1]]
}

/// M_α: rotation about the origin by α = 2π·num/den (counterclockwise for α > 0).
pub fn rotate_frac<S: Scalar>(p: &P2<S>, num: i64, den: i64) -> P2<S> {
    if num.rem_euclid(den.max(1)) == 0 {
        return p.clone();
    }
    let prec = p.prec();
    let a = S::pi(prec).mul(&S::from_ratio(2 * num, den, prec));
    rotate(p, &a)
}

/// M_α: rotation about the origin by the angle α.
pub fn rotate<S: Scalar>(p: &P2<S>, alpha: &S) -> P2<S> {
    let (c, s) = (alpha.cos(), alpha.sin());
    P2::new(p.x.mul(&c).sub(&p.y.mul(&s)), p.x.mul(&s).add(&p.y.mul(&c)))
}

/// Jacobian of M_α with α = 2π·num/den.
pub fn rotation_jacobian<S: Scalar>(num: i64, den: i64, prec: u32) -> Jac<S> {
    let a = S::pi(prec).mul(&S::from_ratio(2 * num, den, prec));
    let (c, s) = (a.cos(), a.sin());
    [[c.clone(), s.neg()], [s, c]]
}

/// 2×2 matrix product `a·b`.
pub fn jac_mul<S: Scalar>(a: &Jac<S>, b: &Jac<S>) -> Jac<S> {
    let e = |r: usize, c: usize| a[r][0].mul(&b[0][c]).add(&a[r][1].mul(&b[1][c]));
    [[e(0, 0), e(0, 1)], [e(1, 0), e(1, 1)]]
}

/// Def. 4.1.1: p ∈ Ω_v ⇔ x² + y² < cos²(π/m_v).
pub fn in_omega_v<S: Scalar>(m: u32, p: &P2<S>) -> Trit {
    let r = omega_radius::<S>(m, p.prec());
    p.norm2().lt(&r.sqr())
}

/// p ∈ Ω_v − {0}.
pub fn in_omega_v_punctured<S: Scalar>(m: u32, p: &P2<S>) -> Trit {
    in_omega_v(m, p).and(is_nonzero(p))
}

/// p ≠ (0, 0), three-valued.
pub fn is_nonzero<S: Scalar>(p: &P2<S>) -> Trit {
    match (p.x.sign(), p.y.sign()) {
        (Some(Ordering::Equal), Some(Ordering::Equal)) => Trit::False,
        (Some(_), Some(_)) => Trit::True,
        (Some(Ordering::Less | Ordering::Greater), None)
        | (None, Some(Ordering::Less | Ordering::Greater)) => Trit::True,
        _ => Trit::Unknown,
    }
}

/// q ∈ int(C) − {0}: C the circle of radius cos(π/6) centred at (0, 0) (Fig. 4.4).
pub fn in_int_c_punctured<S: Scalar>(q: &P2<S>) -> Trit {
    q.norm2().lt(&cos_pi_6_sq::<S>(q.prec())).and(is_nonzero(q))
}

/// Sec. 4.1 / Sec. 6.1.3: the canonical lens E = (int(C) − {0}) ∩ (int(D) − {(1, 0)}), with C,
/// D of radius cos(π/6) centred at (0, 0) and (1, 0). Strict tests against 3/4 (exact).
pub fn in_canonical_lens<S: Scalar>(q: &P2<S>) -> Trit {
    in_lens_with_centre(q, LENS_D_CENTRE.0, LENS_D_CENTRE.1, 1)
}

/// Lens (int(C) − {0}) ∩ (int(D') − {c}) with D' centred at c = (cx/den, cy/den), radius
/// cos(π/6). With c = (1, 0) this is the canonical lens.
pub fn in_lens_with_centre<S: Scalar>(q: &P2<S>, cx: i64, cy: i64, den: i64) -> Trit {
    let prec = q.prec();
    let c = P2::new(S::from_ratio(cx, den, prec), S::from_ratio(cy, den, prec));
    let d = q.sub(&c);
    in_int_c_punctured(q)
        .and(d.norm2().lt(&cos_pi_6_sq::<S>(prec)))
        .and(is_nonzero(&d))
}

/// Quadrilateral Q of Fig. 4.4, closed: vertices (0,0), (1/2, −√3/2), (1,0), (1/2, √3/2).
/// Decided by the four half-planes (Q is convex; vertices counterclockwise).
pub fn in_quad_q<S: Scalar>(q: &P2<S>) -> Trit {
    let prec = q.prec();
    let half = S::from_ratio(1, 2, prec);
    let s3h = cos_pi_6::<S>(prec);
    let z = S::from_i64(0, prec);
    let one = S::from_i64(1, prec);
    let verts = [
        P2::new(z.clone(), z.clone()),
        P2::new(half.clone(), s3h.neg()),
        P2::new(one, z.clone()),
        P2::new(half, s3h),
    ];
    let mut t = Trit::True;
    for k in 0..4 {
        let a = &verts[k];
        let b = &verts[(k + 1) % 4];
        // cross((b − a), (q − a)) >= 0 for a point left of / on a CCW edge.
        let e = b.sub(a);
        let v = q.sub(a);
        let cross = e.x.mul(&v.y).sub(&e.y.mul(&v.x));
        t = t.and(z.le(&cross));
    }
    t
}

// ---------------------------------------------------------------------------------------------
// The model trait: the paper's maps as overridable default methods.
// ---------------------------------------------------------------------------------------------

/// The Chapter 4 construction. Every method has the paper's definition as its default; the
/// production model is [`Paper`]. Overriding one elementary piece (e.g. `h`, a rotation, the
/// lens test) changes every composite that uses it, which is how tests plant faults.
pub trait Ppm<S: Scalar>: Sync {
    /// Def. 4.1.5: Π.
    fn polar(&self, p: &P2<S>) -> Result<Polar<S>, MapError> {
        polar(p)
    }
    /// Def. 4.1.7.
    fn h(&self, p: &P2<S>) -> P2<S> {
        h(p)
    }
    /// Def. 4.1.6.
    fn g_v(&self, m: u32, p: &P2<S>) -> Result<P2<S>, MapError> {
        Ok(polar_inv(&f_v(m, &self.polar(p)?)))
    }
    /// Def. 4.1.6 (stated inverse).
    fn g_v_inv(&self, m: u32, q: &P2<S>) -> Result<P2<S>, MapError> {
        Ok(polar_inv(&f_v_inv(m, &self.polar(q)?)))
    }
    /// Def. 4.1.8: R_(u,w), the rotation about (0,0) taking u'_i = s_u(w) to u'_0, i.e. by
    /// −2π·i/m_u.
    fn r_uw(&self, e: &EdgeConfig, p: &P2<S>) -> P2<S> {
        rotate_frac(p, -(e.i as i64), e.m_u as i64)
    }
    /// R_(u,w)⁻¹: rotation by +2π·i/m_u.
    fn r_uw_inv(&self, e: &EdgeConfig, p: &P2<S>) -> P2<S> {
        rotate_frac(p, e.i as i64, e.m_u as i64)
    }
    /// Def. 4.1.8: the canonical lens test (Sec. 4.1, Sec. 6.1.3).
    fn in_canonical_lens(&self, q: &P2<S>) -> Trit {
        in_canonical_lens(q)
    }

    /// Def. 4.1.8 without the domain check: R_(w,u)⁻¹ ∘ g_w⁻¹ ∘ h ∘ g_u ∘ R_(u,w) (p).
    /// R_(w,u) is `r_uw` of the reversed edge (rotation by −2π·j/m_w).
    fn g_uw_formula(&self, e: &EdgeConfig, p: &P2<S>) -> Result<P2<S>, MapError> {
        let er = e.reversed();
        let a = self.r_uw(e, p);
        let b = self.g_v(e.m_u, &a)?;
        let c = self.h(&b);
        let d = self.g_v_inv(e.m_w, &c)?;
        Ok(self.r_uw_inv(&er, &d))
    }

    /// Def. 4.1.8: g_(u,w) : Ω_u − {0} → g_(u,w)(Ω_u − {0}),
    /// g_(u,w) = R_(w,u)⁻¹ ∘ g_w⁻¹ ∘ h ∘ g_u ∘ R_(u,w). Errors if p ∉ Ω_u − {0}.
    fn g_uw(&self, e: &EdgeConfig, p: &P2<S>) -> Result<P2<S>, MapError> {
        match in_omega_v_punctured(e.m_u, p) {
            Trit::True => self.g_uw_formula(e, p),
            Trit::False => Err(MapError::NotInDomain("g_(u,w) is defined on Ω_u − {0}")),
            Trit::Unknown => Err(MapError::Undecided("p ∈ Ω_u − {0}")),
        }
    }

    /// Def. 4.1.8, the stated inverse: g_(u,w)⁻¹ = R_(u,w)⁻¹ ∘ g_u⁻¹ ∘ h ∘ g_w ∘ R_(w,u) (q),
    /// written out literally (not as `g_uw` of the reversed edge).
    fn g_uw_inv(&self, e: &EdgeConfig, q: &P2<S>) -> Result<P2<S>, MapError> {
        let er = e.reversed();
        let a = self.r_uw(&er, q);
        let b = self.g_v(e.m_w, &a)?;
        let c = self.h(&b);
        let d = self.g_v_inv(e.m_u, &c)?;
        Ok(self.r_uw_inv(e, &d))
    }

    /// Def. 4.1.9, read literally, for an edge [u, w]:
    /// p ∈ Ω_uw = g_(w,u)(Ω_w − {0}) ∩ Ω_u ⇔ p ∈ Ω_u, and the preimage q = g_(w,u)⁻¹(p)
    /// computed by the stated inverse formula of Def. 4.1.8 exists, lies in Ω_w − {0}, and
    /// g_(w,u)(q) = p (up to `roundtrip_tolerance`).
    fn in_omega_uw_literal(&self, e: &EdgeConfig, p: &P2<S>) -> Trit {
        let in_u = in_omega_v(e.m_u, p);
        if in_u.is_false() {
            return Trit::False;
        }
        let er = e.reversed();
        let q = match self.g_uw_inv(&er, p) {
            Ok(q) => q,
            Err(MapError::AtOrigin) => return Trit::False,
            Err(_) => return Trit::Unknown,
        };
        let in_w = in_omega_v_punctured(e.m_w, &q);
        if in_w.is_false() {
            return Trit::False;
        }
        let back = match self.g_uw_formula(&er, &q) {
            Ok(b) => b,
            Err(MapError::AtOrigin) => return Trit::False,
            Err(_) => return Trit::Unknown,
        };
        let tol = S::from_f64(roundtrip_tolerance(e, 1.0), p.prec()).mul(&p.x.unit_roundoff());
        let close = back.sub(p).norm2().le(&tol.sqr());
        in_u.and(in_w).and(close)
    }

    /// Sec. 6.1.3: p ∈ Ω_uw ⇔ h ∘ g_u ∘ R_(u,w)(p) belongs to the canonical lens E.
    /// (E is invariant under h, so this equals "g_u ∘ R_(u,w)(p) ∈ E".)
    fn in_omega_uw_lens(&self, e: &EdgeConfig, p: &P2<S>) -> Trit {
        let a = self.r_uw(e, p);
        match self.g_v(e.m_u, &a) {
            Ok(b) => self.in_canonical_lens(&self.h(&b)),
            Err(MapError::AtOrigin) => Trit::False,
            Err(_) => Trit::Unknown,
        }
    }

    /// Def. 4.1.9 for any pair: Ω_uu = Ω_u; Ω_uw for an edge (literal reading); ∅ otherwise.
    fn in_omega_pair(&self, pair: &VertexPair, p: &P2<S>) -> Trit {
        match pair {
            VertexPair::Same { m } => in_omega_v(*m, p),
            VertexPair::Edge(e) => self.in_omega_uw_literal(e, p),
            VertexPair::NotAdjacent => Trit::False,
        }
    }

    /// Def. 4.1.10: φ_wu : Ω_uw → Ω_wu (FROM u's gluing domain Ω_uw TO w's gluing domain Ω_wu;
    /// the first index of φ is the target vertex). φ_wu(p) = p if u = w, g_(u,w)(p) otherwise.
    /// Membership p ∈ Ω_uw is decided by the literal Def. 4.1.9; a point outside gives
    /// [`MapError::NotInDomain`].
    fn phi_wu(&self, pair: &VertexPair, p: &P2<S>) -> Result<P2<S>, MapError> {
        match self.in_omega_pair(pair, p) {
            Trit::True => {}
            Trit::False => return Err(MapError::NotInDomain("p ∉ Ω_uw (Def. 4.1.9)")),
            Trit::Unknown => return Err(MapError::Undecided("p ∈ Ω_uw")),
        }
        match pair {
            VertexPair::Same { .. } => Ok(p.clone()),
            VertexPair::Edge(e) => self.g_uw_formula(e, p),
            VertexPair::NotAdjacent => Err(MapError::NotInDomain("Ω_uw = ∅")),
        }
    }

    /// Analytic Jacobian of g_(u,w) at p by the chain rule (one-sided on the cut of Π).
    fn g_uw_jacobian(&self, e: &EdgeConfig, p: &P2<S>) -> Result<Jac<S>, MapError> {
        let prec = p.prec();
        let er = e.reversed();
        let a = self.r_uw(e, p);
        let b = self.g_v(e.m_u, &a)?;
        let c = self.h(&b);
        let j1 = rotation_jacobian::<S>(-(e.i as i64), e.m_u as i64, prec);
        let j2 = g_v_jacobian(e.m_u, &a)?;
        let j3 = h_jacobian::<S>(prec);
        let j4 = g_v_inv_jacobian(e.m_w, &c)?;
        let j5 = rotation_jacobian::<S>(er.i as i64, er.m_u as i64, prec);
        Ok(jac_mul(
            &j5,
            &jac_mul(&j4, &jac_mul(&j3, &jac_mul(&j2, &j1))),
        ))
    }
}

/// The paper's construction, unmodified.
#[derive(Debug, Clone, Copy, Default)]
pub struct Paper;

impl<S: Scalar> Ppm<S> for Paper {}

/// Condition factor of the round trip g_(w,u)(g_(w,u)⁻¹(p)) used by the literal membership
/// test: 2^12 · max(1, m_u/6, m_w/6) (about 40 elementary operations, each with relative error
/// ≤ ε, angles amplified by at most m/6 and radii bounded by 1).
pub const ROUNDTRIP_COND: f64 = 4096.0;

/// Tolerance of the literal membership round trip: `ROUNDTRIP_COND · max(1, m/6) · ε`.
pub fn roundtrip_tolerance(e: &EdgeConfig, eps: f64) -> f64 {
    let amp = (e.m_u.max(e.m_w) as f64 / 6.0).max(1.0);
    ROUNDTRIP_COND * amp * eps
}

// ---------------------------------------------------------------------------------------------
// Convenience entry points (production model).
// ---------------------------------------------------------------------------------------------

/// Def. 4.1.10 for the paper's construction: φ_wu(p) for p ∈ Ω_uw (typed error otherwise).
pub fn phi_wu<S: Scalar>(pair: &VertexPair, p: &P2<S>) -> Result<P2<S>, MapError> {
    Paper.phi_wu(pair, p)
}

/// Def. 4.1.8 for the paper's construction.
pub fn g_uw<S: Scalar>(e: &EdgeConfig, p: &P2<S>) -> Result<P2<S>, MapError> {
    Paper.g_uw(e, p)
}

/// Def. 4.1.9 (literal) for the paper's construction.
pub fn in_omega_uw<S: Scalar>(e: &EdgeConfig, p: &P2<S>) -> Trit {
    Paper.in_omega_uw_literal(e, p)
}

/// Def. 4.1.9 via the Sec. 6.1.3 lens test for the paper's construction.
pub fn in_omega_uw_lens<S: Scalar>(e: &EdgeConfig, p: &P2<S>) -> Trit {
    Paper.in_omega_uw_lens(e, p)
}

/// The running-text identity of Appendix A.1 (proof of L4.2.2):
/// (h ∘ M_{−π/3})³ (p), which should equal p.
pub fn h_identity_lhs<S: Scalar>(p: &P2<S>) -> P2<S> {
    let mut q = p.clone();
    for _ in 0..3 {
        q = h(&rotate_frac(&q, -1, 6));
    }
    q
}

/// All preimages of q ≠ 0 under g_v on R² − {0}: the points with polar angle
/// θ_k = 6(β + 2πk)/m_v ∈ (−π, π] and radius s·cos(π/m_v)/cos(π/6), where (β, s) = Π(q).
/// (g_v is injective iff m_v ≤ 6; for m_v > 6 a point has up to ⌈m_v/6⌉ preimages.)
pub fn g_v_preimages<S: Scalar>(m: u32, q: &P2<S>) -> Result<Vec<P2<S>>, MapError> {
    let prec = q.prec();
    let pq = polar(q)?;
    let base = f_v_inv(m, &pq);
    let pi = S::pi(prec);
    let step = S::from_ratio(12, m as i64, prec).mul(&pi); // 6·2π/m
    let mut out = Vec::new();
    let kmax = (m as i64) / 6 + 2;
    for k in -kmax..=kmax {
        let th = base.theta.add(&step.mul(&S::from_i64(k, prec)));
        let in_range = pi.neg().lt(&th).and(th.le(&pi));
        if !in_range.is_false() {
            out.push(polar_inv(&Polar {
                theta: th,
                r: base.r.clone(),
            }));
        }
    }
    Ok(out)
}

/// Evaluate φ_wu(p) in f64 and in `Mp` at `prec` bits (p given in f64, exact in both).
/// Returns (f64 value, Mp value as f64 pair, Euclidean difference). Oracle use.
pub fn phi_wu_f64_vs_mp(
    pair: &VertexPair,
    p: [f64; 2],
    prec: u32,
) -> Result<([f64; 2], [f64; 2], f64), MapError> {
    use crate::numeric::Mp;
    let pf = P2::<f64>::new(p[0], p[1]);
    let pm = P2::<Mp>::from_f64(p[0], p[1], prec);
    let a = phi_wu(pair, &pf)?;
    let b = phi_wu(pair, &pm)?;
    let bf = P2::<Mp>::from_f64(a.x, a.y, prec);
    let diff = b.dist_f64(&bf);
    Ok((a.to_f64(), b.to_f64(), diff))
}
