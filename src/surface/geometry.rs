//! Differential geometry of M from the analytic derivatives of θ_v (via [`Jet`]): unit normal,
//! Gaussian curvature K = (LN − M²)/(EG − F²) and mean curvature
//! H = (EN − 2FM + GL)/(2(EG − F²)), with the normal n = θ_x × θ_y/‖θ_x × θ_y‖ (the chart
//! orientation is the counterclockwise labelling s_v, i.e. the orientation of K).

use super::consts::Consts;
use super::eval::Chart;
use super::jet::Jet;
use super::pps::{Pps, SurfaceError};
use crate::construction::P2;
use crate::mesh::{FaceId, VertexId};
use crate::numeric::vec3::{cross, dot};

/// Point, derivatives and curvature of θ_v at a point of its chart.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SurfacePoint {
    /// θ_v(p).
    pub point: [f64; 3],
    /// θ_x, θ_y.
    pub du: [f64; 3],
    /// θ_y.
    pub dv: [f64; 3],
    /// Unit normal (zero if θ_x × θ_y vanishes: a singular point).
    pub normal: [f64; 3],
    /// ‖θ_x × θ_y‖ (regularity: rank-2 Jacobian iff > 0).
    pub area_element: f64,
    /// Gaussian curvature K = (LN − M²)/(EG − F²); NaN unless EG − F² > 0.
    pub gaussian: f64,
    /// Mean curvature H = (EN − 2FM + GL)/(2(EG − F²)), signed by `normal`; NaN unless EG − F² > 0.
    pub mean: f64,
}

/// Normal and curvatures from a jet of a parametrization (order ≥ 2 for the curvatures: an
/// order-1 jet gives NaN curvatures).
pub fn from_jet<const L: usize>(j: &[Jet<f64, L>; 3]) -> SurfacePoint {
    let g = |a: usize, b: usize| -> [f64; 3] { std::array::from_fn(|d| j[d].derivative(a, b)) };
    from_derivatives(
        [*j[0].value(), *j[1].value(), *j[2].value()],
        [g(1, 0), g(0, 1), g(2, 0), g(1, 1), g(0, 2)],
    )
}

/// Normal and curvatures of a parametrization x(u, v) from its point and its derivatives
/// `d` = [x_u, x_v, x_uu, x_uv, x_vv] (first and second fundamental forms).
pub fn from_derivatives(point: [f64; 3], d: [[f64; 3]; 5]) -> SurfacePoint {
    let [xu, xv, xuu, xuv, xvv] = d;
    let n = cross(xu, xv);
    let len = dot(n, n).sqrt();
    let normal = if len > 0.0 {
        n.map(|x| x / len)
    } else {
        [0.0; 3]
    };
    let (e, f, gg) = (dot(xu, xu), dot(xu, xv), dot(xv, xv));
    let (l, m, nn) = (dot(xuu, normal), dot(xuv, normal), dot(xvv, normal));
    let det = e * gg - f * f;
    let (gaussian, mean) = if det > 0.0 {
        (
            (l * nn - m * m) / det,
            (e * nn - 2.0 * f * m + gg * l) / (2.0 * det),
        )
    } else {
        (f64::NAN, f64::NAN)
    };
    SurfacePoint {
        point,
        du: xu,
        dv: xv,
        normal,
        area_element: len,
        gaussian,
        mean,
    }
}

impl Pps {
    /// The jet of θ_v at p (derivatives to the order of the jet type, 3 by default).
    pub fn theta_jet(
        &self,
        v: VertexId,
        p: [f64; 2],
        c: &Consts<Jet<f64>>,
        only: Option<[VertexId; 2]>,
    ) -> Result<[Jet<f64>; 3], SurfaceError> {
        self.theta_jet_of_order(v, p, c, only)
    }

    /// [`Self::theta_jet`] with jets of any order (the order of `c`'s jet type).
    pub fn theta_jet_of_order<const L: usize>(
        &self,
        v: VertexId,
        p: [f64; 2],
        c: &Consts<Jet<f64, L>>,
        only: Option<[VertexId; 2]>,
    ) -> Result<[Jet<f64, L>; 3], SurfaceError> {
        let (x, y) = Jet::variables(p[0], p[1]);
        self.theta_only(v, &P2::new(x, y), c, only)
    }

    /// θ_v at p with normal and curvatures.
    pub fn theta_geometry(
        &self,
        v: VertexId,
        p: [f64; 2],
        c: &Consts<Jet<f64>>,
    ) -> Result<SurfacePoint, SurfaceError> {
        Ok(from_jet(&self.theta_jet(v, p, c, None)?))
    }

    /// eval (Sec. 6.1.4) with normal and curvatures, from the chart eval chose.
    pub fn eval_geometry(
        &self,
        f: FaceId,
        bary: [f64; 3],
        c: &Consts<Jet<f64>>,
    ) -> Result<(Chart, VertexId, SurfacePoint), SurfaceError> {
        self.eval_geometry_of_order(f, bary, c)
    }

    /// [`Self::eval_geometry`] with jets of any order ≥ 2 (the order of `c`'s jet type;
    /// [`super::jet::Jet2`] is the cheapest that gives the curvatures).
    pub fn eval_geometry_of_order<const L: usize>(
        &self,
        f: FaceId,
        bary: [f64; 3],
        c: &Consts<Jet<f64, L>>,
    ) -> Result<(Chart, VertexId, SurfacePoint), SurfaceError> {
        super::eval::check_barycentric(bary)?;
        let cf = self.consts_f64();
        let qp = super::eval::canonical_point(&bary, cf);
        let (chart, v, q) = self.chart_holding(f, &qp, cf)?;
        let only = match self.options.profile {
            super::Profile::Paper => None,
            super::Profile::AuthorsCode => {
                let [u, w, x] = self.face(f)?;
                Some(match chart {
                    Chart::U => [w, x],
                    Chart::X => [u, w],
                    Chart::W => [u, x],
                })
            }
        };
        let j = self.theta_jet_of_order(v, [q.x, q.y], c, only)?;
        Ok((chart, v, from_jet(&j)))
    }
}
