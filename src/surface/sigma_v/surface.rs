//! Tutorial Part V (T 2751–2982, 2649–2747): the parametrizations θ_(σ,v), built on the
//! (σ, v)-indexed gluing data, and eval from a mesh triangle.
//!
//! θ_i(p) = Σ_{j∈J(p)} γ_j(φ_ji(p))·ψ_j(φ_ji(p)) / Σ_{j∈J(p)} γ_j(φ_ji(p)), J(p) = {j : p ∈ Ω_ij}
//! (T 2877–2895, SPEC `SV-D12`). Points of Ω_i are handled in plane coordinates q = f_i(p)
//! ([`super::gluing`]); γ_j and ψ_j in the local frame of j. Generic over
//! [`SurfaceScalar`]: f64, `Mp` (oracle) and jets (derivatives, curvature, smoothness).
//!
//! J(p) candidates: every corner at v (q ∈ W_j is tested), and the corners at the two
//! neighbours w whose spokes bound q's sector of P_v (the report's Ω_vw lies within angle
//! 2π/m_v of the spoke of w; `surface::pps` uses the same bound).

use super::gluing::{g_uw_on_domain, Corner, CornerId, SigmaV, SigmaVError};
use super::patch::{
    eval_tri, eval_tri_f64, factor, multinomials, num_control_points, TriFit, TriFitInfo,
};
use super::wedge::{WedgeConsts, WedgeTable};
use super::weight::{gamma_local, WeightConsts};
use crate::construction::maps::{g_v_inv, rotate_frac, P2};
use crate::mesh::{FaceId, SimplicialSurface, VertexId};
use crate::surface::eval::{canonical_point, choose_chart, Chart};
use crate::surface::geometry::{from_jet, SurfacePoint};
use crate::surface::jet::Jet;
use crate::surface::output::{sample_pattern_faces, Attributes, SamplePoint, SampledMesh};
use crate::surface::target::TargetSurface;
use crate::surface::{Consts, Profile, SurfaceScalar};
use rayon::prelude::*;
use std::cmp::Ordering;

/// Constants of the construction in one scalar type.
#[derive(Clone, Debug)]
pub struct SvConsts<S> {
    /// Wedges per degree.
    pub wedges: WedgeTable<S>,
    weights: Vec<Option<WeightConsts<S>>>,
    /// The constants of the report's eval (Sec. 6.1.4).
    pub eval: Consts<S>,
}

impl<S: SurfaceScalar> SvConsts<S> {
    /// For the degrees of `g` at `prec` bits.
    pub fn new(g: &SigmaV, prec: u32) -> Self {
        let wedges = WedgeTable::new(g.degrees().iter().copied(), g.kappa, prec);
        let max = g.degrees().last().copied().unwrap_or(0) as usize;
        let weights = (0..=max)
            .map(|m| wedges.get(m as u32).map(|w| WeightConsts::new(w, prec)))
            .collect();
        SvConsts {
            wedges,
            weights,
            eval: Consts::new(g.degrees().iter().copied(), prec),
        }
    }
    /// The wedge constants of degree m.
    pub fn wedge(&self, m: u32) -> &WedgeConsts<S> {
        // Built for every degree of K; a missing one is a programming error upstream.
        self.wedges
            .get(m)
            .expect("wedge constants for every degree of K")
    }
    fn weight(&self, m: u32) -> &WeightConsts<S> {
        self.weights[m as usize]
            .as_ref()
            .expect("weight constants for every degree of K")
    }
}

/// A planted fault (tests: each check must be able to fail).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SvFault {
    /// γ of one corner multiplied by a factor when it enters θ of *another* corner.
    NeighbourWeight {
        /// The corner id.
        corner: u32,
        /// The factor.
        factor: f64,
    },
    /// The cross-edge transition followed by a rotation by `angle`.
    Transition {
        /// Rotation angle (radians).
        angle: f64,
    },
}

/// The parametric pseudo-surface of the tutorial.
#[derive(Debug, Clone)]
pub struct SigmaVPps {
    /// The gluing data.
    pub gluing: SigmaV,
    /// Patch degree d.
    pub degree: usize,
    /// A planted fault (None in production).
    pub fault: Option<SvFault>,
    target_name: String,
    coef: Vec<f64>,
    ncp: usize,
    /// Control points: corner c's are cps[c·ncp..(c+1)·ncp].
    cps: Vec<[f64; 3]>,
    fits: Vec<TriFitInfo>,
    consts: SvConsts<f64>,
}

/// What the sampling keeps of each point: the point, the normal, K and H.
type Kept = ([f64; 3], [f64; 3], f64, f64);

/// Corners fitted per matrix product (bounds memory: 10·m_v·3·BATCH doubles).
const BATCH: usize = 2048;

impl SigmaVPps {
    /// Build all ψ_(σ,v) for K approximating S′ = `target`.
    pub fn build(
        k: &SimplicialSurface,
        target: &dyn TargetSurface,
        kappa: f64,
        degree: usize,
    ) -> Result<Self, SigmaVError> {
        let mut pps = Self::unfitted(k, kappa, degree, target.name())?;
        let (g, ncp) = (&pps.gluing, pps.ncp);
        let fits: Vec<TriFit> = g
            .degrees()
            .par_iter()
            .map(|&m| factor(pps.consts.wedge(m), pps.degree))
            .collect();
        // The control points of the corners at v are one block (corner ids are offset_v + k):
        // each vertex's block is handed to the task that fits it and written in place.
        let mut slot: Vec<Option<&mut [[f64; 3]]>> = (0..k.vertex_slots()).map(|_| None).collect();
        {
            let mut order: Vec<VertexId> = k.vertices().collect();
            order.sort_by_key(|&v| g.id(Corner { v, k: 0 }).0);
            let mut rest: &mut [[f64; 3]] = &mut pps.cps;
            let mut at = 0usize;
            for v in order {
                let start = g.id(Corner { v, k: 0 }).0 as usize * ncp;
                let len = g.degree(v) as usize * ncp;
                let (_, r) = std::mem::take(&mut rest).split_at_mut(start - at);
                let (a, b) = r.split_at_mut(len);
                slot[v.idx()] = Some(a);
                rest = b;
                at = start + len;
            }
        }
        // Work items: (fit, vertices of its degree with their blocks), chunked.
        type Block<'a> = (VertexId, &'a mut [[f64; 3]]);
        let mut tasks: Vec<(&TriFit, Vec<Block>)> = Vec::new();
        for f in &fits {
            let per = (BATCH / f.info.m as usize).max(1);
            let mut cur: Vec<Block> = Vec::with_capacity(per);
            for v in k.vertices().filter(|&v| k.degree(v) == f.info.m) {
                if let Some(out) = slot[v.idx()].take() {
                    cur.push((v, out));
                }
                if cur.len() == per {
                    tasks.push((f, std::mem::take(&mut cur)));
                }
            }
            if !cur.is_empty() {
                tasks.push((f, cur));
            }
        }
        tasks
            .into_par_iter()
            .for_each(|(fit, mut vs)| fit_vertices(g, target, fit, &mut vs, ncp));
        pps.fits = fits.into_iter().map(|f| f.info).collect();
        Ok(pps)
    }

    /// The construction over K with every control point 0 and no sampled fit, for shape
    /// functions fitted or read elsewhere (the adaptive fit, `fitting`), set through
    /// [`Self::patch_mut`]; `target_name` names what they approximate.
    pub fn unfitted(
        k: &SimplicialSurface,
        kappa: f64,
        degree: usize,
        target_name: &str,
    ) -> Result<Self, SigmaVError> {
        let g = SigmaV::new(k, kappa)?;
        let degree = degree.clamp(1, super::patch::MAX_PATCH_DEGREE);
        let ncp = num_control_points(degree);
        let consts = SvConsts::<f64>::new(&g, 53);
        Ok(SigmaVPps {
            cps: vec![[0.0; 3]; g.len() * ncp],
            gluing: g,
            degree,
            fault: None,
            target_name: target_name.to_string(),
            coef: multinomials(degree),
            ncp,
            fits: Vec::new(),
            consts,
        })
    }

    /// Name of S′.
    pub fn target_name(&self) -> &str {
        &self.target_name
    }
    /// Per-degree least-squares summaries.
    pub fn fit_info(&self) -> &[TriFitInfo] {
        &self.fits
    }
    /// The f64 constants.
    pub fn consts_f64(&self) -> &SvConsts<f64> {
        &self.consts
    }
    /// Constants in another scalar.
    pub fn consts<S: SurfaceScalar>(&self, prec: u32) -> SvConsts<S> {
        SvConsts::new(&self.gluing, prec)
    }
    /// Control points of ψ of a corner.
    pub fn patch(&self, c: CornerId) -> &[[f64; 3]] {
        let s = c.0 as usize * self.ncp;
        &self.cps[s..s + self.ncp]
    }
    /// Mutable control points (planted faults).
    pub fn patch_mut(&mut self, c: CornerId) -> &mut [[f64; 3]] {
        let s = c.0 as usize * self.ncp;
        &mut self.cps[s..s + self.ncp]
    }
    /// Largest |control point coordinate| (scale of tolerances).
    pub fn scale(&self) -> f64 {
        self.cps
            .iter()
            .flat_map(|c| c.iter())
            .fold(0.0f64, |a, &b| a.max(b.abs()))
            .max(f64::MIN_POSITIVE)
    }

    /// ψ_j at a local point.
    pub(crate) fn psi_local<S: SurfaceScalar>(
        &self,
        j: CornerId,
        w: &WedgeConsts<S>,
        p: &P2<S>,
    ) -> [S; 3] {
        let l = w.envelope_bary(p);
        let cp = self.patch(j);
        if let Some(l64) = (&l as &dyn std::any::Any).downcast_ref::<[f64; 3]>() {
            let r = eval_tri_f64(self.degree, cp, &self.coef, *l64);
            if let Some(out) = (&r as &dyn std::any::Any).downcast_ref::<[S; 3]>() {
                return out.clone();
            }
        }
        eval_tri(self.degree, cp, &self.coef, &l)
    }

    /// γ_j at a plane point q of its vertex (0 outside W_j).
    pub fn gamma_plane<S: SurfaceScalar>(&self, j: Corner, q: &P2<S>, c: &SvConsts<S>) -> S {
        let m = self.gluing.degree(j.v);
        let w = c.wedge(m);
        gamma_local(w, c.weight(m), &w.to_local(j.k, q))
    }

    /// J(p) with γ_j(φ_ji(p)) and the local point of φ_ji(p), i = `i`, q = f_i(p). Calls
    /// `f(j, γ, local point, wedge)` for each j ∈ J(p) (i first among the corners at v).
    fn for_each_term<S: SurfaceScalar>(
        &self,
        i: Corner,
        q: &P2<S>,
        c: &SvConsts<S>,
        mut f: impl FnMut(CornerId, S, P2<S>, &WedgeConsts<S>),
    ) -> Result<(), SigmaVError> {
        let g = &self.gluing;
        let m = g.degree(i.v);
        let w = c.wedge(m);
        if !w.in_wedge(i.k, q) {
            let [x, y] = q.to_f64();
            return Err(SigmaVError::NotInOmega {
                corner: g.id(i).0,
                x,
                y,
            });
        }
        let iid = g.id(i);
        for kk in 0..m {
            let p = w.to_local(kk, q);
            if w.in_wedge_local(&p) {
                let j = Corner { v: i.v, k: kk };
                let jid = g.id(j);
                let mut gam = gamma_local(w, c.weight(m), &p);
                if let Some(SvFault::NeighbourWeight { corner, factor }) = self.fault {
                    if corner == jid.0 && jid != iid {
                        gam = gam.mul(&S::from_f64(factor, c.wedges.prec));
                    }
                }
                f(jid, gam, p, w);
            }
        }
        let [x, y] = q.to_f64();
        if x == 0.0 && y == 0.0 {
            return Ok(());
        }
        let mut a = y.atan2(x);
        if a < 0.0 {
            a += std::f64::consts::TAU;
        }
        let s0 = ((a * m as f64 / std::f64::consts::TAU).floor() as u32).min(m - 1);
        for l in [s0, (s0 + 1) % m] {
            let e = g.edge_config(i.v, l);
            let Some(mut y) = g_uw_on_domain(&e, q) else {
                continue;
            };
            if let Some(SvFault::Transition { angle }) = self.fault {
                y = crate::construction::maps::rotate(&y, &S::from_f64(angle, c.wedges.prec));
            }
            let u = g.link(i.v, l);
            let ww = c.wedge(e.m_w);
            let w_in_tau = l == i.k || l == (i.k + 1) % m;
            for kk in 0..e.m_w {
                let u_in_eta = e.j == kk || e.j == (kk + 1) % e.m_w;
                if !(w_in_tau || u_in_eta) {
                    continue; // case (3): declared empty (T 2430)
                }
                let p = ww.to_local(kk, &y);
                if ww.in_wedge_local(&p) {
                    let j = Corner { v: u, k: kk };
                    let mut gam = gamma_local(ww, c.weight(e.m_w), &p);
                    if let Some(SvFault::NeighbourWeight { corner, factor }) = self.fault {
                        if corner == g.id(j).0 {
                            gam = gam.mul(&S::from_f64(factor, c.wedges.prec));
                        }
                    }
                    f(g.id(j), gam, p, ww);
                }
            }
        }
        Ok(())
    }

    /// J(p) with the local point of φ_ji(p) for each j: where θ_i(p) evaluates each ψ_j
    /// (the adaptive fit's rows, `fitting::fitted`).
    pub fn local_points(
        &self,
        i: Corner,
        q: [f64; 2],
    ) -> Result<Vec<(CornerId, [f64; 2])>, SigmaVError> {
        let mut out = Vec::new();
        self.for_each_term(i, &P2::new(q[0], q[1]), &self.consts, |j, _, p, _| {
            out.push((j, [p.x, p.y]))
        })?;
        Ok(out)
    }

    /// J(p) as a list (corner id, γ_j(φ_ji(p))), for the checks.
    pub fn terms(&self, i: Corner, q: [f64; 2]) -> Result<Vec<(CornerId, f64)>, SigmaVError> {
        let mut out = Vec::new();
        self.for_each_term(i, &P2::new(q[0], q[1]), &self.consts, |j, g, _, _| {
            out.push((j, g))
        })?;
        Ok(out)
    }

    /// θ_i at q = f_i(p) (plane coordinates of P_v).
    pub fn theta_plane<S: SurfaceScalar>(
        &self,
        i: Corner,
        q: &P2<S>,
        c: &SvConsts<S>,
    ) -> Result<[S; 3], SigmaVError> {
        let z = S::from_i64(0, c.wedges.prec);
        let mut den = z.clone();
        let mut num = [z.clone(), z.clone(), z];
        self.for_each_term(i, q, c, |j, gam, p, w| {
            if gam.sign() == Some(Ordering::Equal) {
                return;
            }
            let psi = self.psi_local(j, w, &p);
            for d in 0..3 {
                num[d] = num[d].add(&gam.mul(&psi[d]));
            }
            den = den.add(&gam);
        })?;
        if den.sign() != Some(Ordering::Greater) {
            return Err(SigmaVError::ZeroWeight(self.gluing.id(i).0));
        }
        Ok(num.map(|n| n.div(&den)))
    }

    /// θ_i in f64.
    pub fn theta_f64(&self, i: Corner, q: [f64; 2]) -> Result<[f64; 3], SigmaVError> {
        self.theta_plane(i, &P2::new(q[0], q[1]), &self.consts)
    }

    /// SPEC `SV-D13`: eval(σ, λ, μ, ν): the report's chart choice (Sec. 6.1.4, paper
    /// profile) gives a corner c* of σ and q ∈ D_{c*} in the sector of σ; returns the corner
    /// (σ, c*), q = f_(σ,c*)(p) and θ_(σ,c*)(p).
    pub fn eval<S: SurfaceScalar>(
        &self,
        f: FaceId,
        bary: &[S; 3],
        c: &SvConsts<S>,
    ) -> Result<(Corner, P2<S>, [S; 3]), SigmaVError> {
        let (corner, q) = self.eval_chart(f, bary, c)?;
        let x = self.theta_plane(corner, &q, c)?;
        Ok((corner, q, x))
    }

    /// The corner and plane point eval uses (no θ).
    pub fn eval_chart<S: SurfaceScalar>(
        &self,
        f: FaceId,
        bary: &[S; 3],
        c: &SvConsts<S>,
    ) -> Result<(Corner, P2<S>), SigmaVError> {
        let b = bary.clone().map(|x| x.to_f64());
        let s = b[0] + b[1] + b[2];
        if b.iter().any(|&x| !(x >= -1e-12)) || !((s - 1.0).abs() <= 1e-9) {
            return Err(SigmaVError::BadBarycentric(b));
        }
        let g = &self.gluing;
        let [u, w, x] = g.face_corners(f)?;
        let lab = |a: VertexId, b: VertexId| g.label(a, b).ok_or(SigmaVError::NoSuchFace(f));
        let qp = canonical_point(bary, &c.eval);
        let one = S::from_i64(1, c.wedges.prec);
        let h = |p: &P2<S>| P2::new(one.sub(&p.x), p.y.neg());
        let place = |chart: Chart| -> Result<(Corner, P2<S>), SigmaVError> {
            // (corner vertex, label of the face's half-edge, rotation label, chart point z)
            let (v, k, rot, z) = match chart {
                Chart::U => (u, lab(u, w)?, lab(u, x)?, qp.clone()),
                Chart::X => (x, lab(x, u)?, lab(x, u)?, h(&qp)),
                Chart::W => (w, lab(w, x)?, lab(w, u)?, h(&rotate_frac(&qp, 1, 6))),
            };
            let m = g.degree(v);
            let is_zero =
                z.x.sign() == Some(Ordering::Equal) && z.y.sign() == Some(Ordering::Equal);
            let q = if is_zero {
                z
            } else {
                let a = g_v_inv(m, &z).map_err(|_| SigmaVError::BadBarycentric(b))?;
                rotate_frac(&a, rot as i64, m as i64)
            };
            Ok((Corner { v, k }, q))
        };
        let first = choose_chart(Profile::Paper, &qp, &c.eval);
        let chosen = place(first)?;
        if g.in_wedge(&c.wedges, chosen.0, &chosen.1) {
            return Ok(chosen);
        }
        // The rule's circle about a corner (radius √3/2) is tangent to the opposite edge at
        // its midpoint, whose image is on ∂W of that corner: a point of the edge an ulp from
        // the midpoint is outside the circle, but its rounded distance can say inside. Then
        // the next chart of the rule that holds the point is taken (SPEC `SV-D13`); if none
        // does, the rule's corner is returned and θ refuses the point.
        for next in [Chart::U, Chart::X, Chart::W] {
            if next != first {
                if let Ok(other) = place(next) {
                    if g.in_wedge(&c.wedges, other.0, &other.1) {
                        return Ok(other);
                    }
                }
            }
        }
        Ok(chosen)
    }

    /// eval in f64.
    pub fn eval_f64(&self, f: FaceId, bary: [f64; 3]) -> Result<[f64; 3], SigmaVError> {
        Ok(self.eval(f, &bary, &self.consts)?.2)
    }

    /// Sample M by midpoint subdivision through eval (the Sec. 6.2 pattern of
    /// `surface::output`, shared), with normals and curvatures from the jets of θ.
    pub fn sample_surface(&self, level: u32) -> Result<SampledMesh, SigmaVError> {
        self.sample_surface_with(level, Attributes::Curvature)
    }

    /// [`Self::sample_surface`] computing only `attrs` (the other arrays stay empty):
    /// positions by θ in f64, normals from order-1 jets, curvatures from order-2 jets (the
    /// truncated jets' coefficients are those of the higher orders: the products sum the same
    /// terms in the same order).
    pub fn sample_surface_with(
        &self,
        level: u32,
        attrs: Attributes,
    ) -> Result<SampledMesh, SigmaVError> {
        let faces: Vec<_> = (0..self.gluing.num_faces())
            .map(|f| self.gluing.face_corners(FaceId(f as u32)))
            .collect::<Result<_, _>>()?;
        let pat = sample_pattern_faces(&faces, level).map_err(|e| match e {
            crate::surface::SurfaceError::LevelTooLarge { level, .. } => {
                SigmaVError::LevelTooLarge(level)
            }
            _ => SigmaVError::LevelTooLarge(level),
        })?;
        let mut out = SampledMesh {
            faces: pat.faces,
            title: "ppm sample: C-infinity PPS surface, (sigma, v)-indexed construction (tutorial, Part IV)",
            ..SampledMesh::default()
        };
        let points = &pat.points;
        match attrs {
            Attributes::Positions => {
                let res =
                    self.map_points(points, |s| Ok(self.eval(s.face, &s.bary, &self.consts)?.2));
                // The first error in point order, on every run.
                out.positions = res.into_iter().collect::<Result<_, _>>()?;
            }
            Attributes::Normals => {
                let g = self.geometry::<3>(points)?;
                out.positions = g.iter().map(|g| g.0).collect();
                out.normals = g.iter().map(|g| g.1).collect();
            }
            Attributes::Curvature => {
                let g = self.geometry::<6>(points)?;
                out.positions = g.iter().map(|g| g.0).collect();
                out.normals = g.iter().map(|g| g.1).collect();
                out.gaussian = g.iter().map(|g| g.2).collect();
                out.mean = g.iter().map(|g| g.3).collect();
            }
        }
        Ok(out)
    }

    /// `f` at every sample point, evaluated in parallel in the storage order of the control
    /// points (by the smallest vertex id of the point's face: the corners of v are stored
    /// together, in vertex order), so that neighbouring evaluations share their ψ_j in cache;
    /// the results in point order (as `surface::output` does for the vertex construction).
    fn map_points<T: Send>(
        &self,
        points: &[SamplePoint],
        f: impl Fn(&SamplePoint) -> T + Sync + Send,
    ) -> Vec<T> {
        let keys: Vec<u32> = points
            .iter()
            .map(|s| {
                self.gluing.face_corners(s.face).map_or(u32::MAX, |c| {
                    c.iter().map(|v| v.0).min().unwrap_or(u32::MAX)
                })
            })
            .collect();
        crate::surface::pps::map_in_key_order(&keys, |i| f(&points[i]))
    }

    /// Point, normal and curvatures at each sample from jets of θ of `L` coefficients (what
    /// the output keeps of each point: half a [`SurfacePoint`]).
    fn geometry<const L: usize>(&self, points: &[SamplePoint]) -> Result<Vec<Kept>, SigmaVError>
    where
        Jet<f64, L>: SurfaceScalar,
    {
        let cj = self.consts::<Jet<f64, L>>(53);
        let res = self.map_points(points, |s| {
            let (corner, q) = self.eval_chart(s.face, &s.bary, &self.consts)?;
            let (x, y) = Jet::<f64, L>::variables(q.x, q.y);
            let t = self.theta_plane(corner, &P2::new(x, y), &cj)?;
            let g: SurfacePoint = from_jet(&t);
            Ok((g.point, g.normal, g.gaussian, g.mean))
        });
        // The first error in point order, on every run.
        res.into_iter().collect()
    }

    /// eval of many points in parallel; `out[i]` for `points[i]`.
    pub fn eval_batch_f64(
        &self,
        points: &[(FaceId, [f64; 3])],
    ) -> Vec<Result<[f64; 3], SigmaVError>> {
        points
            .par_iter()
            .map(|&(f, b)| self.eval_f64(f, b))
            .collect()
    }
}

/// Fit the corners of the vertices `vs` (all of degree fit.info.m). Cubic-net targets: one
/// product with A⁺W per batch; others: A⁺ times S′ sampled at the fit's samples. Each vertex's
/// block holds its corners' control points, `ncp` per corner, corner k at k·ncp.
fn fit_vertices(
    g: &SigmaV,
    target: &dyn TargetSurface,
    fit: &TriFit,
    vs: &mut [(VertexId, &mut [[f64; 3]])],
    ncp: usize,
) {
    pulp::Arch::new().dispatch(FitVertices {
        g,
        target,
        fit,
        vs,
        ncp,
    });
}

/// [`fit_vertices`] as a [`pulp::WithSimd`] operation: its loops (inlined into `with_simd`)
/// are compiled for the CPU's vector extensions. Products and sums stay separate operations
/// (Rust does not contract them into fused multiply-adds), so the bits do not depend on the
/// CPU.
struct FitVertices<'a, 'b> {
    g: &'a SigmaV,
    target: &'a dyn TargetSurface,
    fit: &'a TriFit,
    vs: &'a mut [(VertexId, &'b mut [[f64; 3]])],
    ncp: usize,
}

impl pulp::WithSimd for FitVertices<'_, '_> {
    type Output = ();
    #[inline(always)]
    fn with_simd<S: pulp::Simd>(self, _: S) {
        let FitVertices {
            g,
            target,
            fit,
            vs,
            ncp,
        } = self;
        fit_vertices_body(g, target, fit, vs, ncp);
    }
}

#[inline(always)]
fn fit_vertices_body(
    g: &SigmaV,
    target: &dyn TargetSurface,
    fit: &TriFit,
    vs: &mut [(VertexId, &mut [[f64; 3]])],
    ncp: usize,
) {
    let m = fit.info.m;
    let cols = 10 * fit.sectors.len();
    let sector = |v: VertexId, s: u32| -> (FaceId, [VertexId; 3]) {
        let c = Corner { v, k: s % m };
        (g.face_of(c), [v, g.link(v, s % m), g.link(v, (s + 1) % m)])
    };
    // A⁺W transposed (column j of A⁺W contiguous): the products below run over all control
    // points at once, each control point's sum still taken term by term in the column order
    // (the same additions in the same order as row by row, so the same bits).
    let mut net_t = vec![0.0; cols * ncp];
    for c in 0..ncp {
        for j in 0..cols {
            net_t[j * ncp + c] = fit.net_map[c * cols + j];
        }
    }
    let mut acc = vec![[0.0f64; 3]; ncp];
    let (mut ax, mut ay, mut az) = (vec![0.0; ncp], vec![0.0; ncp], vec![0.0; ncp]);
    for (v, block) in vs.iter_mut() {
        let v = *v;
        let nets: Option<Vec<[[f64; 3]; 10]>> = (0..m)
            .map(|s| {
                let (f, c) = sector(v, s);
                target.cubic_net(f, c)
            })
            .collect();
        for (kk, out) in (0..m).zip(block.chunks_exact_mut(ncp)) {
            match &nets {
                Some(nets) => {
                    ax.fill(0.0);
                    ay.fill(0.0);
                    az.fill(0.0);
                    for (t, &srel) in fit.sectors.iter().enumerate() {
                        let net = &nets[((kk + srel) % m) as usize];
                        for (q, p) in net.iter().enumerate() {
                            let w = &net_t[(10 * t + q) * ncp..(10 * t + q + 1) * ncp];
                            let lanes = ax.iter_mut().zip(ay.iter_mut()).zip(az.iter_mut());
                            for (((x, y), z), &wc) in lanes.zip(w) {
                                *x += wc * p[0];
                                *y += wc * p[1];
                                *z += wc * p[2];
                            }
                        }
                    }
                    for (((o, x), y), z) in acc.iter_mut().zip(&ax).zip(&ay).zip(&az) {
                        *o = [*x, *y, *z];
                    }
                }
                None => {
                    let rows = fit.samples.len();
                    let d: Vec<[f64; 3]> = fit
                        .samples
                        .iter()
                        .map(|s| {
                            let (f, c) = sector(v, kk + s.sector);
                            target.eval(f, c, s.bary)
                        })
                        .collect();
                    for (c, o) in acc.iter_mut().enumerate() {
                        let row = &fit.pinv[c * rows..(c + 1) * rows];
                        let mut a = [0.0; 3];
                        for (wgt, p) in row.iter().zip(&d) {
                            a[0] += wgt * p[0];
                            a[1] += wgt * p[1];
                            a[2] += wgt * p[2];
                        }
                        *o = a;
                    }
                }
            }
            out.copy_from_slice(&acc);
        }
    }
}
