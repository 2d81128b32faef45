//! Defs. 5.4.1–5.4.2 and Eq. (5.1): the parametric pseudo-surface M = (G, (θ_v)_{v∈I}).
//!
//! θ_v(p) = Σ_u Γ_uv(p)·Ψ_uv(p) / Σ_u Γ_uv(p), with Γ_uv = γ_u∘φ_uv and Ψ_uv = ψ_u∘φ_uv on
//! Ω_vu (0 elsewhere). Everything is generic over [`SurfaceScalar`]: `f64` (production),
//! [`crate::numeric::Mp`] (oracle), and [`super::jet::Jet`] (derivatives to order 3).
//!
//! Transition maps. θ_v needs φ_uv(p) for p ∈ Ω_vu. This module evaluates
//! φ_uv = R_(u,v)⁻¹∘g_u⁻¹∘h∘g_v∘R_(v,u) (Def. 4.1.8) with per-degree constants, deciding
//! p ∈ Ω_vu by: q = R_(v,u)(p) ≠ 0, |θ(q)| < min(π, 6π/m_v) (the branch on which g_v is
//! injective) and g_v(q) in the canonical lens E. This is equivalent to the literal Def. 4.1.9
//! (`PpmGluing::in_omega_uw`, which needs a round trip) — tested point by point in
//! `tests/surface_theta.rs` — and ~10× cheaper. [`Membership::Lens`] drops the branch test: that
//! is the Sec. 6.1.3 test, which differs for m_v ≥ 11 (SPEC `D4.1.9-lens`).
//!
//! Only the two spokes bounding p's sector of P_v can have p ∈ Ω_vu: g_v∘R_(v,u)(Ω_vu) ⊂ E and
//! E lies in the open sector |β| < π/3 (the tangents from 0 to the circle D touch it at angle
//! ±π/3), i.e. |θ(R_(v,u)p)| < 2π/m_v. With the literal membership only those two are tested.

use super::authors_fit::{fit_vertex_authors, AuthorsDegreeFit};
use super::consts::{Consts, DegreeConsts};
use super::fit::{factor_degree, sample_set, DegreeFit, DegreeFitInfo, Sample};
use super::fit_linear::{LinearPlan, SectorMajor};
use super::profile::{label_offset, AuthorsStages};
use super::scalar_ext::SurfaceScalar;
use super::target::TargetSurface;
use super::weights::{xi_of_sq, XiConsts};
use crate::construction::P2;
use crate::mesh::{FaceId, SimplicialSurface, VertexId};
use rayon::prelude::*;
use std::cmp::Ordering;
use std::sync::Arc;

pub use super::error::SurfaceError;
pub use super::options::{Fault, Membership, PpsOptions};
pub(crate) use super::storage::map_in_key_order;
use super::storage::{bfs_order, prefetch};

/// One term of Eq. (5.1): u ∈ J_v(p), q = φ_uv(p), Γ_uv(p) = γ_u(q).
#[derive(Debug, Clone)]
pub struct Term<S> {
    /// u ∈ J_v(p).
    pub u: VertexId,
    /// q = φ_uv(p) ∈ Ω_u (q = p for u = v).
    pub q: P2<S>,
    /// Γ_uv(p) = γ_u(q).
    pub gamma: S,
}

/// The parametric pseudo-surface built from K and S′ (Chapter 5).
#[derive(Debug, Clone)]
pub struct Pps {
    /// The options the surface evaluates with.
    pub options: PpsOptions,
    /// The authors'-code stages it was built and evaluates with.
    pub stages: AuthorsStages,
    target_name: String,
    faces: Vec<[VertexId; 3]>,
    positions: Vec<[f64; 3]>,
    degree: Vec<u32>,
    nbr_start: Vec<usize>,
    /// nbr[nbr_start[v] + i] = s_v⁻¹(v′_i).
    nbr: Vec<VertexId>,
    /// back[nbr_start[v] + i] = s_u(v) for u = nbr[..].
    back: Vec<u32>,
    /// ψ_v's control points are cps[patch_off[v]..patch_end[v]] (stored in `rank` order).
    patch_off: Vec<usize>,
    patch_end: Vec<usize>,
    patch_l: Vec<usize>,
    /// Position of each vertex in the breadth-first storage order.
    rank: Vec<u32>,
    cps: Vec<[f64; 3]>,
    half_by_degree: Vec<f64>,
    fits: Vec<DegreeFitInfo>,
    consts: Arc<Consts<f64>>,
}

impl Pps {
    /// Build all ψ_v (Sec. 5.2) for K approximating S′ = `target`.
    pub fn build(k: &SimplicialSurface, target: &dyn TargetSurface, options: PpsOptions) -> Pps {
        Self::build_staged(k, target, options, options.profile.stages())
    }

    /// [`Self::build`] with the authors'-code stages chosen one by one (to measure the effect
    /// of each difference between the paper and their code).
    pub fn build_staged(
        k: &SimplicialSurface,
        target: &dyn TargetSurface,
        options: PpsOptions,
        stages: AuthorsStages,
    ) -> Pps {
        let slots = k.vertex_slots();
        let degree: Vec<u32> = (0..slots).map(|v| k.degree(VertexId(v as u32))).collect();
        let mut nbr_start = vec![0usize; slots + 1];
        for v in 0..slots {
            nbr_start[v + 1] = nbr_start[v] + degree[v] as usize;
        }
        let mut nbr = vec![VertexId(0); nbr_start[slots]];
        let mut back = vec![0u32; nbr_start[slots]];
        // v′_0 depends on the profile (`Profile::label_offset`): label i of the profile is
        // label (i + offset_v) mod m_v of K.
        let offset: Vec<u32> = (0..slots)
            .map(|v| label_offset(k, VertexId(v as u32), stages))
            .collect();
        for v in k.vertices() {
            let out = k.outgoing(v);
            let m = out.len();
            for i in 0..m {
                let h = out[(i + offset[v.idx()] as usize) % m];
                let u = k.dest(h);
                let mu = degree[u.idx()].max(1);
                nbr[nbr_start[v.idx()] + i] = u;
                back[nbr_start[v.idx()] + i] =
                    (k.label(k.twin(h)) + mu - offset[u.idx()] % mu) % mu;
            }
        }
        let mut degs: Vec<u32> = k.vertices().map(|v| k.degree(v)).collect();
        degs.sort_unstable();
        degs.dedup();
        // Storage order of the patches: breadth-first over the edges of K, so that the patches
        // of neighbouring vertices (the ψ_u one θ_v needs) are close in memory whatever the
        // vertex numbering of the input (`rank` also orders batch evaluation).
        let order = bfs_order(&degree, &nbr_start, &nbr);
        let mut rank = vec![u32::MAX; slots];
        for (r, v) in order.iter().enumerate() {
            rank[v.idx()] = r as u32;
        }
        let mut patch_off = vec![0usize; slots];
        let mut patch_end = vec![0usize; slots];
        let mut patch_l = vec![0usize; slots];
        let mut total = 0usize;
        for &v in &order {
            let v = v.idx();
            let l = if degree[v] >= 3 {
                options.profile.bezier_degree(degree[v])
            } else {
                0
            };
            patch_l[v] = l;
            let size = if degree[v] >= 3 { (l + 1) * (l + 1) } else { 0 };
            patch_off[v] = total;
            total += size;
            patch_end[v] = total;
        }
        let mut cps = vec![[0.0; 3]; total];
        // Cubic-net targets (PN triangles): the control points of every vertex of degree m are
        // A⁺W·N (Sec. 5.2; A⁺W is the same for the whole degree), so the vertices of one
        // degree are fitted together, in batches, by one matrix product each (3 columns per
        // vertex: x, y, z of its m cubic nets). Vertices whose target gives no cubic net take
        // the general path (sampling S′).
        const BATCH: usize = 512;
        // Split the control-point array per vertex; each batch owns the slices of its vertices
        // and writes them in place.
        let mut slot: Vec<Option<&mut [[f64; 3]]>> = (0..slots).map(|_| None).collect();
        {
            let mut rest: &mut [[f64; 3]] = &mut cps;
            for &v in &order {
                let (a, b) = rest.split_at_mut(patch_end[v.idx()] - patch_off[v.idx()]);
                slot[v.idx()] = Some(a);
                rest = b;
            }
        }
        // The vertices of each degree (index into `degs`, and so into the fits), in storage
        // order, in batches.
        type Batch<'a> = Vec<(VertexId, &'a mut [[f64; 3]])>;
        let mut tasks: Vec<(usize, Batch)> = Vec::new();
        for (fi, &m) in degs.iter().enumerate() {
            let mut cur: Batch = Vec::with_capacity(BATCH);
            for &v in &order {
                if degree[v.idx()] != m {
                    continue;
                }
                if let Some(out) = slot[v.idx()].take() {
                    if !out.is_empty() {
                        cur.push((v, out));
                    }
                }
                if cur.len() == BATCH {
                    tasks.push((fi, std::mem::take(&mut cur)));
                }
            }
            if !cur.is_empty() {
                tasks.push((fi, cur));
            }
        }
        // Targets linear in the positions (the Loop S′; not with the authors' fit): the part of
        // their fit that needs no A⁺ (stencils and weights, `fit_linear`) runs beside the
        // factorisations, whose largest degree otherwise keeps one thread busy alone.
        let lin = target.linear().filter(|_| !stages.normal_equations);
        let planned: Vec<(usize, VertexId, u32)> = match lin {
            Some(_) => tasks
                .iter()
                .flat_map(|(fi, vs)| vs.iter().map(|(v, _)| (*fi, *v, offset[v.idx()])))
                .collect(),
            None => Vec::new(),
        };
        // Cubic-net targets with the paper's fit: each degree's batches are fitted as soon as
        // that degree is factored, so the small degrees' fits run beside the largest degree's
        // factorisation (the longest single task) instead of after it.
        let pipelined = lin.is_none() && !stages.normal_equations;
        let mut per_degree: Vec<Vec<Batch>> = (0..degs.len()).map(|_| Vec::new()).collect();
        if pipelined {
            for (fi, vs) in tasks.drain(..) {
                per_degree[fi].push(vs);
            }
        }
        let offset_ref = &offset;
        let ((factored, major), plan): ((Vec<DegreeFit>, Vec<Option<SectorMajor>>), _) =
            rayon::join(
                || {
                    degs.par_iter()
                        .zip(per_degree.into_par_iter())
                        .map(|(&m, batches)| {
                            let f = factor_degree(m, options.profile);
                            let major = lin.is_some().then(|| SectorMajor::new(&f));
                            batches
                                .into_par_iter()
                                .for_each(|mut vs| fit_batch(k, target, &f, offset_ref, &mut vs));
                            (f, major)
                        })
                        .unzip()
                },
                || {
                    lin.map(|lin| {
                        let samples: Vec<(u32, Vec<Sample>)> = degs
                            .iter()
                            .map(|&m| (m, sample_set(m, options.profile)))
                            .collect();
                        LinearPlan::new(k, lin, &samples, &planned)
                    })
                },
            );
        let maxd = degs.last().copied().unwrap_or(3) as usize;
        let mut half_by_degree = vec![0.0; maxd + 1];
        for f in &factored {
            half_by_degree[f.info.m as usize] = f.info.half_side;
        }
        if stages.normal_equations {
            // Their fit (normal equations, their samples), vertex by vertex.
            let afits: Vec<(u32, AuthorsDegreeFit)> = degs
                .par_iter()
                .map(|&m| {
                    (
                        m,
                        AuthorsDegreeFit::new(m, options.profile.bezier_degree(m)),
                    )
                })
                .collect();
            tasks.into_par_iter().for_each(|(fi, mut vs)| {
                let Some((_, af)) = afits.iter().find(|(m, _)| Some(m) == degs.get(fi)) else {
                    return;
                };
                for (v, out) in vs.iter_mut() {
                    if !fit_vertex_authors(k, target, *v, offset[v.idx()], af, out) {
                        // Their code stops here (AᵀA singular: never met, as every sample
                        // is interior to □_v); NaN makes every use of ψ_v report it.
                        out.fill([f64::NAN; 3]);
                    }
                }
            });
        } else if let (Some(lin), Some(plan)) = (lin, &plan) {
            // Targets linear in the positions (the Loop S′): one weight matrix per local
            // combinatorics (`fit_linear`, planned above); what it cannot serve samples S′.
            let offset = &offset;
            let jobs: Vec<(usize, super::fit_linear::Job)> = tasks
                .into_iter()
                .flat_map(|(fi, vs)| {
                    vs.into_iter()
                        .map(move |(v, out)| (fi, (v, offset[v.idx()], out)))
                })
                .collect();
            let rest = plan.apply(lin, &factored, &major, jobs);
            rest.into_par_iter().for_each(|(fi, (v, off, out))| {
                fit_vertex(k, target, v, off, &factored[fi], out);
            });
        } else {
            tasks
                .into_par_iter()
                .for_each(|(fi, mut vs)| fit_batch(k, target, &factored[fi], &offset, &mut vs));
        }
        Pps {
            options,
            stages,
            target_name: target.name().to_string(),
            faces: k.faces().map(|f| k.face(f)).collect(),
            positions: (0..slots).map(|v| k.position(VertexId(v as u32))).collect(),
            degree,
            nbr_start,
            nbr,
            back,
            patch_off,
            patch_end,
            patch_l,
            rank,
            cps,
            half_by_degree,
            fits: factored.into_iter().map(|f| f.info).collect(),
            consts: Arc::new(Consts::new(degs.iter().copied(), 53)),
        }
    }

    /// Replace the options (profile changes need a rebuild; this is for membership/fault).
    pub fn with_options(mut self, membership: Membership, fault: Option<Fault>) -> Pps {
        self.options.membership = membership;
        self.options.fault = fault;
        self
    }

    /// The name of the target surface S′ the shape functions were fitted to.
    pub fn target_name(&self) -> &str {
        &self.target_name
    }
    /// Per-degree least-squares summaries (rank, κ).
    pub fn fit_info(&self) -> &[DegreeFitInfo] {
        &self.fits
    }
    /// Number of triangles of K.
    pub fn num_faces(&self) -> usize {
        self.faces.len()
    }
    /// The corners of face f, or [`SurfaceError::NoSuchFace`].
    pub fn face(&self, f: FaceId) -> Result<[VertexId; 3], SurfaceError> {
        self.faces
            .get(f.idx())
            .copied()
            .ok_or(SurfaceError::NoSuchFace(f))
    }
    /// Position of v in R³ (the mesh vertex); panics for an out-of-range slot.
    pub fn position(&self, v: VertexId) -> [f64; 3] {
        self.positions[v.idx()]
    }
    /// Whether v is a vertex of K (degree ≥ 3).
    pub fn contains(&self, v: VertexId) -> bool {
        self.degree.get(v.idx()).is_some_and(|&m| m >= 3)
    }
    /// m_v, or 0 if v is not a vertex of K.
    pub fn degree(&self, v: VertexId) -> u32 {
        self.degree.get(v.idx()).copied().unwrap_or(0)
    }
    /// The vertices of K.
    pub fn vertices(&self) -> impl Iterator<Item = VertexId> + '_ {
        (0..self.degree.len())
            .filter(|&v| self.degree[v] >= 3)
            .map(|v| VertexId(v as u32))
    }
    /// s_v⁻¹(v′_i).
    pub fn link(&self, v: VertexId, i: u32) -> VertexId {
        self.nbr[self.nbr_start[v.idx()] + i as usize]
    }
    /// s_v(u), if u is in the link of v.
    pub fn label(&self, v: VertexId, u: VertexId) -> Option<u32> {
        let s = self.nbr_start.get(v.idx())?;
        let e = self.nbr_start.get(v.idx() + 1)?;
        self.nbr[*s..*e]
            .iter()
            .position(|&x| x == u)
            .map(|i| i as u32)
    }
    /// The control points of ψ_v (index j·(l+1)+k) and l.
    pub fn patch(&self, v: VertexId) -> (&[[f64; 3]], usize) {
        let i = v.idx();
        (
            &self.cps[self.patch_off[i]..self.patch_end[i]],
            self.patch_l[i],
        )
    }
    /// Position of v in the storage order of the patches (breadth-first over K): vertices
    /// close in this order have their ψ close in memory.
    pub(crate) fn storage_rank(&self, v: VertexId) -> u32 {
        self.rank.get(v.idx()).copied().unwrap_or(u32::MAX)
    }
    /// A cache hint: prefetch the control points of ψ_v (no effect on any result).
    #[inline]
    fn prefetch_patch(&self, v: VertexId) {
        if self.options.membership != Membership::Literal {
            return; // Lens: all m_v neighbours are candidates
        }
        if let (Some(&a), Some(&b)) = (self.patch_off.get(v.idx()), self.patch_end.get(v.idx())) {
            if let Some(cp) = self.cps.get(a..b) {
                for line in cp.as_flattened().chunks(8) {
                    prefetch(&line[0]);
                }
            }
        }
    }

    /// Breadth-first storage rank of the first-stored corner of face f: sorting evaluation
    /// points by it makes consecutive evaluations share their ψ_u in cache.
    pub(crate) fn locality_key(&self, f: FaceId) -> u32 {
        match self.faces.get(f.idx()) {
            Some(c) => c
                .iter()
                .map(|&v| self.storage_rank(v))
                .min()
                .unwrap_or(u32::MAX),
            None => u32::MAX,
        }
    }
    /// Mutable control points (for planted-fault tests).
    pub fn patch_mut(&mut self, v: VertexId) -> &mut [[f64; 3]] {
        let i = v.idx();
        &mut self.cps[self.patch_off[i]..self.patch_end[i]]
    }
    /// L = cos(π/m_v), the half side of □_v.
    pub fn half_side(&self, v: VertexId) -> f64 {
        self.half_by_degree[self.degree(v) as usize]
    }
    /// The f64 constants.
    pub fn consts_f64(&self) -> &Consts<f64> {
        &self.consts
    }
    /// Constants for another scalar at `prec` bits (all degrees of K).
    pub fn consts<S: SurfaceScalar>(&self, prec: u32) -> Consts<S> {
        let mut d: Vec<u32> = self.degree.iter().copied().filter(|&m| m >= 3).collect();
        d.sort_unstable();
        d.dedup();
        Consts::new(d, prec)
    }
    /// Largest |control point coordinate| over all patches (scale for tolerances).
    pub fn scale(&self) -> f64 {
        self.cps
            .iter()
            .flat_map(|c| c.iter())
            .fold(0.0f64, |a, &b| a.max(b.abs()))
            .max(f64::MIN_POSITIVE)
    }

    /// The constants of m_v; a foreign v is [`SurfaceError::NoSuchVertex`] (crate doc, *Ids*).
    pub(super) fn dc<'c, S>(
        &self,
        c: &'c Consts<S>,
        v: VertexId,
    ) -> Result<&'c DegreeConsts<S>, SurfaceError>
    where
        S: SurfaceScalar,
    {
        let m = self.degree(v);
        if m < 3 {
            return Err(SurfaceError::NoSuchVertex(v));
        }
        c.degree(m).ok_or(SurfaceError::MissingDegree(m))
    }

    /// Def. 5.3.2 (with the planted faults): γ_v(p).
    pub fn gamma<S: SurfaceScalar>(
        &self,
        v: VertexId,
        p: &P2<S>,
        c: &Consts<S>,
    ) -> Result<S, SurfaceError> {
        let d = self.dc(c, v)?;
        Ok(match self.options.fault {
            Some(Fault::RampWeight) => ramp(&d.xi, &p.norm2()),
            Some(Fault::WeightRadius { factor }) => {
                let f = S::from_f64(factor, c.prec);
                let k = XiConsts {
                    h1: d.xi.h1.clone(),
                    h2: d.xi.h2.mul(&f),
                };
                xi_of_sq(&k, &p.norm2())
            }
            _ => xi_of_sq(&d.xi, &p.norm2()),
        })
    }

    /// Def. 5.2.1: ψ_v(p).
    pub fn psi<S: SurfaceScalar>(&self, v: VertexId, p: &P2<S>) -> [S; 3] {
        let (cp, l) = self.patch(v);
        S::patch(cp, l, self.half_side(v), &p.x, &p.y)
    }

    /// p ∈ Ω_v (Def. 4.1.1).
    pub fn in_omega<S: SurfaceScalar>(
        &self,
        v: VertexId,
        p: &P2<S>,
        c: &Consts<S>,
    ) -> Result<bool, SurfaceError> {
        let d = self.dc(c, v)?;
        Ok(p.norm2().lt(&d.radius.sqr()).is_true())
    }

    /// φ_uv(p) for u = s_v⁻¹(v′_i), if p ∈ Ω_vu (Defs. 4.1.8–4.1.10; see the module doc).
    pub fn phi_label<S: SurfaceScalar>(
        &self,
        v: VertexId,
        i: u32,
        p: &P2<S>,
        c: &Consts<S>,
    ) -> Result<Option<P2<S>>, SurfaceError> {
        let dv = self.dc(c, v)?;
        let slot = self.nbr_start[v.idx()] + i as usize;
        let u = self.nbr[slot];
        let j = self.back[slot];
        let du = self.dc(c, u)?;
        // q = R_(v,u)(p): rotation by −2πi/m_v.
        let (co, si) = &dv.rot[i as usize];
        let q = P2::new(p.x.mul(co).add(&p.y.mul(si)), p.y.mul(co).sub(&p.x.mul(si)));
        if q.x.sign() == Some(Ordering::Equal) && q.y.sign() == Some(Ordering::Equal) {
            return Ok(None);
        }
        let pol = crate::construction::maps::polar(&q)?;
        if self.options.membership == Membership::Literal
            && !pol.theta.abs().lt(&dv.branch).is_true()
        {
            return Ok(None);
        }
        // a = g_v(q). The authors' code takes the polar angle in (−π/2, 3π/2]: +2π in the
        // third quadrant, where (for m_v = 3, the only degree whose two candidate spokes
        // reach it) g_v(q) then leaves the lens and u's term is dropped.
        let zero = S::from_i64(0, c.prec);
        let theta = if self.stages.polar_angle && q.x.lt(&zero).is_true() && q.y.lt(&zero).is_true()
        {
            pol.theta.add(&S::pi(c.prec).mul(&S::from_i64(2, c.prec)))
        } else {
            pol.theta
        };
        let beta = theta.mul(&dv.ang);
        let rho = pol.r.mul(&dv.radial);
        let a = P2::new(rho.mul(&beta.cos()), rho.mul(&beta.sin()));
        // Canonical lens E: |a|² < 3/4, |a − (1,0)|² < 3/4, a ∉ {0, (1,0)}.
        let one = S::from_i64(1, c.prec);
        let b = P2::new(one.sub(&a.x), a.y.neg()); // h(a)
        let in_lens = a.norm2().lt(&c.c_sq).is_true()
            && b.norm2().lt(&c.c_sq).is_true()
            && !(b.x.sign() == Some(Ordering::Equal) && b.y.sign() == Some(Ordering::Equal));
        if !in_lens {
            return Ok(None);
        }
        // g_u⁻¹(b), then R_(u,v)⁻¹: rotation by +2πj/m_u.
        let pb = crate::construction::maps::polar(&b)?;
        let th = pb.theta.mul(&du.ang_inv);
        let r = pb.r.div(&du.radial);
        let cq = P2::new(r.mul(&th.cos()), r.mul(&th.sin()));
        let (co, si) = &du.rot[j as usize];
        let mut d = P2::new(
            cq.x.mul(co).sub(&cq.y.mul(si)),
            cq.x.mul(si).add(&cq.y.mul(co)),
        );
        if let Some(Fault::Transition { from, to, angle }) = self.options.fault {
            if from == v && to == u {
                d = crate::construction::maps::rotate(&d, &S::from_f64(angle, c.prec));
            }
        }
        Ok(Some(d))
    }

    /// φ_uv(p) if [v, u] is an edge and p ∈ Ω_vu; `Ok(None)` if p ∉ Ω_vu.
    pub fn phi<S: SurfaceScalar>(
        &self,
        u: VertexId,
        v: VertexId,
        p: &P2<S>,
        c: &Consts<S>,
    ) -> Result<Option<P2<S>>, SurfaceError> {
        if u == v {
            return Ok(if self.in_omega(v, p, c)? {
                Some(p.clone())
            } else {
                None
            });
        }
        let i = self.label(v, u).ok_or(SurfaceError::NoSuchEdge(v, u))?;
        self.phi_label(v, i, p, c)
    }

    /// The labels i whose gluing domain Ω_v{s_v⁻¹(v′_i)} may contain p (no allocation: this is
    /// on the path of every eval).
    fn candidates(&self, v: VertexId, p: [f64; 2]) -> impl Iterator<Item = u32> + Clone {
        let m = self.degree(v);
        let (all, pair, len) = if self.options.membership == Membership::Lens {
            (m, [0, 0], 0)
        } else if p == [0.0, 0.0] {
            (0, [0, 0], 0)
        } else {
            let mut a = p[1].atan2(p[0]);
            if a < 0.0 {
                a += 2.0 * std::f64::consts::PI;
            }
            let i0 = ((a * m as f64 / (2.0 * std::f64::consts::PI)).floor() as u32).min(m - 1);
            (0, [i0, (i0 + 1) % m], 2)
        };
        (0..all).chain(pair.into_iter().take(len))
    }

    /// J_v(p) with Γ_uv(p) and φ_uv(p) (Eq. 5.1, Def. 5.4.1). `only`: restrict the neighbours
    /// (authors-code profile: the other two vertices of the evaluated triangle).
    pub fn terms<S: SurfaceScalar>(
        &self,
        v: VertexId,
        p: &P2<S>,
        c: &Consts<S>,
        only: Option<[VertexId; 2]>,
    ) -> Result<Vec<Term<S>>, SurfaceError> {
        let mut out = Vec::with_capacity(3);
        self.for_each_term(v, p, c, only, |t| out.push(t))?;
        Ok(out)
    }

    /// [`Self::terms`] without collecting: `f` gets the terms of J_v(p) in order (v first).
    fn for_each_term<S: SurfaceScalar>(
        &self,
        v: VertexId,
        p: &P2<S>,
        c: &Consts<S>,
        only: Option<[VertexId; 2]>,
        mut f: impl FnMut(Term<S>),
    ) -> Result<(), SurfaceError> {
        if !self.in_omega(v, p, c)? {
            let [x, y] = p.to_f64();
            return Err(SurfaceError::NotInOmega { v, x, y });
        }
        // ψ_v and the ψ_u of the candidate neighbours are needed below, after the transcendental
        // work of γ and φ: start loading them now (memory latency dominates on large meshes).
        let candidates = self.candidates(v, p.to_f64());
        self.prefetch_patch(v);
        for i in candidates.clone() {
            self.prefetch_patch(self.link(v, i));
        }
        f(Term {
            u: v,
            q: p.clone(),
            gamma: self.gamma(v, p, c)?,
        });
        for i in candidates {
            let u = self.link(v, i);
            if let Some(o) = only {
                if !o.contains(&u) {
                    continue;
                }
            }
            if let Some(q) = self.phi_label(v, i, p, c)? {
                let mut g = self.gamma(u, &q, c)?;
                if let Some(Fault::NeighbourWeight { vertex, factor }) = self.options.fault {
                    if vertex == u {
                        g = g.mul(&S::from_f64(factor, c.prec));
                    }
                }
                f(Term { u, q, gamma: g });
            }
        }
        Ok(())
    }

    /// Eq. (5.1): the weights ω_uv(p), u ∈ J_v(p).
    pub fn weights<S: SurfaceScalar>(
        &self,
        v: VertexId,
        p: &P2<S>,
        c: &Consts<S>,
    ) -> Result<Vec<(VertexId, S)>, SurfaceError> {
        let t = self.terms(v, p, c, None)?;
        let den = self.denominator(&t, c);
        Ok(t.into_iter().map(|t| (t.u, t.gamma.div(&den))).collect())
    }

    fn denominator<S: SurfaceScalar>(&self, t: &[Term<S>], c: &Consts<S>) -> S {
        let mut den = S::from_i64(0, c.prec);
        for x in t {
            den = den.add(&x.gamma);
        }
        if let Some(Fault::Denominator { factor }) = self.options.fault {
            den = den.mul(&S::from_f64(factor, c.prec));
        }
        den
    }

    /// Def. 5.4.2: θ_v(p) = Σ_u Γ_uv(p)Ψ_uv(p) / Σ_u Γ_uv(p), p ∈ Ω_v.
    pub fn theta<S: SurfaceScalar>(
        &self,
        v: VertexId,
        p: &P2<S>,
        c: &Consts<S>,
    ) -> Result<[S; 3], SurfaceError> {
        self.theta_only(v, p, c, None)
    }

    /// θ_v with the neighbours restricted to `only` (authors-code eval).
    pub fn theta_only<S: SurfaceScalar>(
        &self,
        v: VertexId,
        p: &P2<S>,
        c: &Consts<S>,
        only: Option<[VertexId; 2]>,
    ) -> Result<[S; 3], SurfaceError> {
        self.theta_visiting(v, p, c, only, |_| {})
    }

    /// [`Self::theta_only`], handing every term of J_v(p) to `visit` as it is blended (the
    /// error bound of `eval_bound` reads the terms of the same pass).
    pub(crate) fn theta_visiting<S: SurfaceScalar>(
        &self,
        v: VertexId,
        p: &P2<S>,
        c: &Consts<S>,
        only: Option<[VertexId; 2]>,
        mut visit: impl FnMut(&Term<S>),
    ) -> Result<[S; 3], SurfaceError> {
        // One pass: Σ Γ_uv and Σ Γ_uv·Ψ_uv accumulated in the order of J_v(p) (the same
        // operations as summing the collected terms).
        let z = S::from_i64(0, c.prec);
        let mut den = z.clone();
        let mut num = [z.clone(), z.clone(), z];
        self.for_each_term(v, p, c, only, |x| {
            visit(&x);
            den = den.add(&x.gamma);
            if x.gamma.sign() == Some(Ordering::Equal) {
                return;
            }
            let psi = self.psi(x.u, &x.q);
            for d in 0..3 {
                num[d] = num[d].add(&x.gamma.mul(&psi[d]));
            }
        })?;
        if let Some(Fault::Denominator { factor }) = self.options.fault {
            den = den.mul(&S::from_f64(factor, c.prec));
        }
        if den.sign() != Some(Ordering::Greater) {
            return Err(SurfaceError::ZeroWeight(v));
        }
        Ok(num.map(|n| n.div(&den)))
    }

    /// θ_v(p) in f64 with the built-in constants.
    pub fn theta_f64(&self, v: VertexId, p: [f64; 2]) -> Result<[f64; 3], SurfaceError> {
        self.theta(v, &P2::new(p[0], p[1]), &self.consts)
    }
}

/// The planted C⁰ ramp replacing ξ (Fault::RampWeight).
fn ramp<S: SurfaceScalar>(k: &XiConsts<S>, t2: &S) -> S {
    let prec = t2.precision_bits();
    if t2.le(&k.h1.sqr()).is_true() {
        return S::from_i64(1, prec);
    }
    if k.h2.sqr().le(t2).is_true() {
        return S::from_i64(0, prec);
    }
    k.h2.sub(&t2.sqrt()).div(&k.h2.sub(&k.h1))
}

/// Fit ψ_v for the vertices `vs` (all of degree `fit.info.m`), writing each one's (l+1)²
/// control points in place. Where the target gives cubic nets: X_v = (A⁺W)·N_v with N_v the
/// m_v stacked nets (10·m_v × 3), all such vertices in one product (A⁺W)·[N_v1 N_v2 …]; the
/// others by [`fit_vertex`] (sampling S′).
fn fit_batch(
    k: &SimplicialSurface,
    target: &dyn TargetSurface,
    fit: &DegreeFit,
    offset: &[u32],
    vs: &mut [(VertexId, &mut [[f64; 3]])],
) {
    let m = fit.info.m;
    let rows = m as usize * 10;
    let kk = fit.info.unknowns;
    let mut done = Vec::with_capacity(vs.len());
    // Column 3j + d of N: coordinate d of the nets of vertex vs[done[j]], sector-major.
    let mut n = Vec::with_capacity(rows * 3 * vs.len());
    let mut nets = Vec::with_capacity(m as usize);
    for (idx, (v, out)) in vs.iter_mut().enumerate() {
        let v = *v;
        let outgoing = k.outgoing(v);
        let off = offset[v.idx()] as usize;
        nets.clear();
        for i in 0..m as usize {
            let h = outgoing[(i + off) % m as usize];
            let a = k.dest(h);
            let b = k.dest(outgoing[(i + off + 1) % m as usize]);
            match target.cubic_net(k.face_of(h), [v, a, b]) {
                Some(net) => nets.push(net),
                None => break,
            }
        }
        if nets.len() != m as usize || out.len() != kk {
            fit_vertex(k, target, v, off as u32, fit, out);
            continue;
        }
        for d in 0..3 {
            n.extend(nets.iter().flat_map(|net| net.iter().map(|p| p[d])));
        }
        done.push(idx);
    }
    if done.is_empty() {
        return;
    }
    let nmat = nalgebra::DMatrix::from_vec(rows, 3 * done.len(), n);
    let map = nalgebra::DMatrix::from_row_slice(kk, rows, &fit.net_map);
    let x = map * nmat; // kk × 3·|done|, column-major
    for (j, &idx) in done.iter().enumerate() {
        let out = &mut *vs[idx].1;
        for d in 0..3 {
            for (c, slot) in out.iter_mut().enumerate() {
                slot[d] = x[(c, 3 * j + d)];
            }
        }
    }
}

/// Fit ψ_v: the control points minimising Σ‖ψ_v(q) − b_σ(r)‖² over the Sec. 5.2 samples, by
/// sampling S′ (the path of targets without cubic nets, e.g. the Loop S′).
fn fit_vertex(
    k: &SimplicialSurface,
    target: &dyn TargetSurface,
    v: VertexId,
    off: u32,
    fit: &DegreeFit,
    out: &mut [[f64; 3]],
) {
    let m = k.degree(v);
    let outgoing = k.outgoing(v);
    let sector = |i: u32| -> (FaceId, [VertexId; 3]) {
        let h = outgoing[((i + off) % m) as usize];
        let a = k.dest(h);
        let b = k.dest(outgoing[((i + off + 1) % m) as usize]);
        (k.face_of(h), [v, a, b])
    };
    let kk = out.len();
    for o in out.iter_mut() {
        *o = [0.0; 3];
    }
    // D = b_σ at the samples, X = A⁺ D (targets with cubic nets go through `fit_batch`).
    let n = fit.samples.len();
    let d: Vec<[f64; 3]> = fit
        .samples
        .iter()
        .map(|s| {
            let (f, c) = sector(s.sector);
            target.eval(f, c, s.bary)
        })
        .collect();
    for (c, out_c) in out.iter_mut().enumerate().take(kk) {
        let row = &fit.pinv[c * n..(c + 1) * n];
        let mut acc = [0.0; 3];
        for (w, p) in row.iter().zip(&d) {
            acc[0] += w * p[0];
            acc[1] += w * p[1];
            acc[2] += w * p[2];
        }
        *out_c = acc;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::generate::icosahedron;
    use crate::mesh::validate::validate;
    use crate::surface::PnTriangles;

    /// The locality key of `eval_batch_f64` (Sec. 6.1.4 evaluated in storage order): a face's
    /// key is the smallest breadth-first storage rank of its corners, so the faces around the
    /// first-stored vertex come first and the keys spread over the mesh; an unknown face sorts
    /// last.
    #[test]
    fn c6_1_4_locality_key_is_the_first_corner_in_storage_order() {
        let k = validate(&icosahedron()).surface.expect("valid");
        let pps = Pps::build(&k, &PnTriangles::new(&k), PpsOptions::default());
        let mut keys = Vec::new();
        for f in k.faces() {
            let want = k.face(f).iter().map(|&v| pps.storage_rank(v)).min();
            assert_eq!(Some(pps.locality_key(f)), want, "face {f}");
            keys.push(pps.locality_key(f));
        }
        // Five faces meet at the first-stored vertex (the icosahedron's valence).
        assert_eq!(keys.iter().filter(|&&x| x == 0).count(), 5);
        assert!(keys.iter().any(|&x| x > 0));
        assert_eq!(pps.locality_key(FaceId(k.num_faces() as u32)), u32::MAX);
    }

    /// Def. 4.1.1: one p-domain Ω_v per vertex v of K; `contains` is true exactly on them
    /// (every vertex of the icosahedron, no slot past the last).
    #[test]
    fn d4_1_1_pps_contains_exactly_the_vertices_of_k() {
        let k = validate(&icosahedron()).surface.expect("valid");
        let pps = Pps::build(&k, &PnTriangles::new(&k), PpsOptions::default());
        for v in k.vertices() {
            assert!(pps.contains(v), "vertex {v:?}");
        }
        assert!(!pps.contains(VertexId(k.vertex_slots() as u32)));
    }
}
