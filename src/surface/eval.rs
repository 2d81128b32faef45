//! Sec. 6.1.4: `tPPS::eval(σ, λ, μ, ν)` — a point of M from a triangle of K and (real,
//! not integer as the text says) barycentric coordinates.
//!
//! σ = [u, w, x] in the stored (consistently oriented) corner order (u, w, x = the origins of
//! the first, second, third half-edge). q′ = λa + μb + νc in the canonical triangle t with
//! a = (0,0), b = (1/2, −√3/2), c = (1,0). Charts (Fig. 6.2):
//! * int(C) (centre a, radius cos π/6) is g_u∘R_(u,x)(Ω_u): q = R_(u,x)⁻¹∘g_u⁻¹(q′) ∈ Ω_u;
//! * int(D) (centre c) is h∘g_x∘R_(x,u)(Ω_x): q = R_(x,u)⁻¹∘g_x⁻¹∘h⁻¹(q′) ∈ Ω_x;
//! * int(E) (centre b) is M_{−π/3}∘h∘g_w∘R_(w,u)(Ω_w): q = R_(w,u)⁻¹∘g_w⁻¹∘h⁻¹∘M_{π/3}(q′).
//!
//! Paper profile: Ω_u if q′ ∈ int(C), else Ω_x if q′ ∈ int(D), else Ω_w. Authors-code profile:
//! the chart of the corner of t nearest to q′ (ties: a, then c, then b).
//! g⁻¹(0) = 0 (the centre of the chart) by continuity; Π is undefined there.

use super::consts::Consts;
use super::pps::{Pps, SurfaceError, Term};
use super::profile::Profile;
use super::scalar_ext::SurfaceScalar;
use crate::construction::P2;
use crate::mesh::{FaceId, VertexId};
use serde::Serialize;
use std::cmp::Ordering;

/// Which p-domain eval chose (named after the corner of t it is centred at).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Chart {
    /// Ω_u, circle C centred at a = (0, 0).
    U,
    /// Ω_x, circle D centred at c = (1, 0).
    X,
    /// Ω_w, circle E centred at b = (1/2, −√3/2).
    W,
}

/// The result of eval: the chart, the vertex i, q ∈ Ω_i, and θ_i(q).
#[derive(Debug, Clone)]
pub struct EvalPoint<S> {
    /// Which of the three charts was chosen.
    pub chart: Chart,
    /// The vertex i of that chart.
    pub vertex: VertexId,
    /// q ∈ Ω_i, the point where θ_i is evaluated.
    pub q: P2<S>,
    /// θ_i(q).
    pub point: [S; 3],
}

/// q′ = λa + μb + νc = (μ/2 + ν, −μ√3/2).
pub fn canonical_point<S: SurfaceScalar>(bary: &[S; 3], c: &Consts<S>) -> P2<S> {
    let half = S::from_ratio(1, 2, c.prec);
    P2::new(bary[1].mul(&half).add(&bary[2]), bary[1].mul(&c.s3h).neg())
}

/// The barycentric coordinates eval accepts: finite, ≥ 0 (−1e−12 tolerated) and summing to 1
/// (±1e−9); NaN and ±∞ are refused.
pub fn check_barycentric(b: [f64; 3]) -> Result<(), SurfaceError> {
    let s = b[0] + b[1] + b[2];
    if b.iter().any(|&x| !(x >= -1e-12) || !x.is_finite()) || !((s - 1.0).abs() <= 1e-9) {
        return Err(SurfaceError::BadBarycentric(b));
    }
    Ok(())
}

impl Pps {
    /// g_v⁻¹ (Def. 4.1.6, stated inverse) followed by the rotation by +2πj/m_v; 0 ↦ 0.
    fn chart_inverse<S: SurfaceScalar>(
        &self,
        v: VertexId,
        j: u32,
        z: &P2<S>,
        c: &Consts<S>,
    ) -> Result<P2<S>, SurfaceError> {
        let d = self.dc(c, v)?;
        if z.x.sign() == Some(Ordering::Equal) && z.y.sign() == Some(Ordering::Equal) {
            return Ok(z.clone());
        }
        let pol = crate::construction::maps::polar(z)?;
        let th = pol.theta.mul(&d.ang_inv);
        let r = pol.r.div(&d.radial);
        let q = P2::new(r.mul(&th.cos()), r.mul(&th.sin()));
        let (co, si) = &d.rot[j as usize];
        Ok(P2::new(
            q.x.mul(co).sub(&q.y.mul(si)),
            q.x.mul(si).add(&q.y.mul(co)),
        ))
    }

    fn lab(&self, a: VertexId, b: VertexId) -> Result<u32, SurfaceError> {
        self.label(a, b).ok_or(SurfaceError::NoSuchEdge(a, b))
    }

    /// The chart point of q′ in the given chart of σ = [u, w, x] (no choice made).
    pub fn chart_point<S: SurfaceScalar>(
        &self,
        f: FaceId,
        chart: Chart,
        qp: &P2<S>,
        c: &Consts<S>,
    ) -> Result<(VertexId, P2<S>), SurfaceError> {
        let [u, w, x] = self.face(f)?;
        let one = S::from_i64(1, c.prec);
        let h = |p: &P2<S>| P2::new(one.sub(&p.x), p.y.neg());
        match chart {
            Chart::U => Ok((u, self.chart_inverse(u, self.lab(u, x)?, qp, c)?)),
            Chart::X => Ok((x, self.chart_inverse(x, self.lab(x, u)?, &h(qp), c)?)),
            Chart::W => {
                // M_{π/3}(q′): rotation by +60°.
                let half = S::from_ratio(1, 2, c.prec);
                let r = P2::new(
                    qp.x.mul(&half).sub(&qp.y.mul(&c.s3h)),
                    qp.x.mul(&c.s3h).add(&qp.y.mul(&half)),
                );
                Ok((w, self.chart_inverse(w, self.lab(w, u)?, &h(&r), c)?))
            }
        }
    }

    /// The chart of [`Self::choose_chart`] and its point, unless Ω_v of that chart refuses
    /// the point: the paper's circle about a corner (radius √3/2) is tangent to the opposite
    /// edge at its midpoint, whose image is on ∂Ω_v, so for a point of the edge an ulp or two
    /// from the midpoint the rounded distance can pick a corner the point is outside of. Then
    /// the next chart, in the rule's order, whose Ω_v holds the point is taken (SPEC
    /// `D6.1.4-eval`); if none does, the rule's chart is returned and θ refuses the point.
    pub fn chart_holding<S: SurfaceScalar>(
        &self,
        f: FaceId,
        qp: &P2<S>,
        c: &Consts<S>,
    ) -> Result<(Chart, VertexId, P2<S>), SurfaceError> {
        let first = self.choose_chart(qp, c);
        let (v, q) = self.chart_point(f, first, qp, c)?;
        if self.in_omega(v, &q, c)? {
            return Ok((first, v, q));
        }
        for next in [Chart::U, Chart::X, Chart::W] {
            if next == first {
                continue;
            }
            if let Ok((w, p)) = self.chart_point(f, next, qp, c) {
                if self.in_omega(w, &p, c)? {
                    return Ok((next, w, p));
                }
            }
        }
        Ok((first, v, q))
    }

    /// The chart eval chooses for q′ (depends on the profile).
    pub fn choose_chart<S: SurfaceScalar>(&self, qp: &P2<S>, c: &Consts<S>) -> Chart {
        let one = S::from_i64(1, c.prec);
        let da = qp.norm2();
        let dc = P2::new(qp.x.sub(&one), qp.y.clone()).norm2();
        let half = S::from_ratio(1, 2, c.prec);
        let db = P2::new(qp.x.sub(&half), qp.y.add(&c.s3h)).norm2();
        if self.stages.nearest_chart {
            if da.le(&dc).is_true() && da.le(&db).is_true() {
                Chart::U
            } else if dc.le(&db).is_true() {
                Chart::X
            } else {
                Chart::W
            }
        } else if da.lt(&c.c_sq).is_true() {
            Chart::U
        } else if dc.lt(&c.c_sq).is_true() {
            Chart::X
        } else {
            Chart::W
        }
    }

    /// Sec. 6.1.4: eval(σ, λ, μ, ν).
    pub fn eval<S: SurfaceScalar>(
        &self,
        f: FaceId,
        bary: &[S; 3],
        c: &Consts<S>,
    ) -> Result<EvalPoint<S>, SurfaceError> {
        self.eval_visiting(f, bary, c, |_| {})
    }

    /// [`Self::eval`], handing every blended term u ∈ J_v(q) to `visit`.
    pub(crate) fn eval_visiting<S: SurfaceScalar>(
        &self,
        f: FaceId,
        bary: &[S; 3],
        c: &Consts<S>,
        visit: impl FnMut(&Term<S>),
    ) -> Result<EvalPoint<S>, SurfaceError> {
        check_barycentric(bary.clone().map(|x| x.to_f64()))?;
        self.face(f)?;
        let qp = canonical_point(bary, c);
        let (chart, vertex, q) = self.chart_holding(f, &qp, c)?;
        let only = self.blend_only(f, chart)?;
        let point = self.theta_visiting(vertex, &q, c, only, visit)?;
        Ok(EvalPoint {
            chart,
            vertex,
            q,
            point,
        })
    }

    /// The two neighbours eval blends from `chart` of face `f` when the profile blends
    /// within the triangle only (authors-code); `None`: every u ∈ J_v(p).
    pub(crate) fn blend_only(
        &self,
        f: FaceId,
        chart: Chart,
    ) -> Result<Option<[VertexId; 2]>, SurfaceError> {
        let [u, w, x] = self.face(f)?;
        Ok(self.stages.triangle_blend.then_some(match chart {
            Chart::U => [w, x],
            Chart::X => [u, w],
            Chart::W => [u, x],
        }))
    }

    /// eval in f64 for many points at once, in parallel (rayon); `out[i]` is the result for
    /// `points[i]`. The points are evaluated in the storage order of the patches (by the
    /// breadth-first rank of the face's first corner), so that the ψ_u of neighbouring
    /// evaluations are shared in cache: on meshes whose face or vertex numbering is not
    /// spatially coherent, per-point evaluation in input order is bound by memory traffic.
    pub fn eval_batch_f64(
        &self,
        points: &[(FaceId, [f64; 3])],
    ) -> Vec<Result<[f64; 3], SurfaceError>> {
        let keys: Vec<u32> = points.iter().map(|(f, _)| self.locality_key(*f)).collect();
        super::pps::map_in_key_order(&keys, |i| {
            let (f, b) = points[i];
            self.eval_f64(f, b)
        })
    }

    /// eval in f64 with the built-in constants.
    pub fn eval_f64(&self, f: FaceId, bary: [f64; 3]) -> Result<[f64; 3], SurfaceError> {
        Ok(self.eval(f, &bary, self.consts_f64())?.point)
    }
}

/// The chart eval chooses for q′ under `profile` (Sec. 6.1.4; shared by the (σ, v)-indexed
/// construction of `surface::sigma_v`).
pub fn choose_chart<S: SurfaceScalar>(profile: Profile, qp: &P2<S>, c: &Consts<S>) -> Chart {
    let one = S::from_i64(1, c.prec);
    let da = qp.norm2();
    let dc = P2::new(qp.x.sub(&one), qp.y.clone()).norm2();
    let half = S::from_ratio(1, 2, c.prec);
    let db = P2::new(qp.x.sub(&half), qp.y.add(&c.s3h)).norm2();
    match profile {
        Profile::Paper => {
            if da.lt(&c.c_sq).is_true() {
                Chart::U
            } else if dc.lt(&c.c_sq).is_true() {
                Chart::X
            } else {
                Chart::W
            }
        }
        Profile::AuthorsCode => {
            if da.le(&dc).is_true() && da.le(&db).is_true() {
                Chart::U
            } else if dc.le(&db).is_true() {
                Chart::X
            } else {
                Chart::W
            }
        }
    }
}
