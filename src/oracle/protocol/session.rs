//! A protocol session: the loaded mesh, precision, profile and the lazily built surfaces;
//! it answers each request (docs/oracle.md).

use super::request::{MemberTest, Request};
use super::response::{OracleError, Response};
use crate::construction::{PpmGluing, P2};
use crate::mesh::{load_surface, FaceId, LoadError, SimplicialSurface, VertexId};
use crate::numeric::{Mp, Scalar, Trit};
use crate::oracle::choice::{read_fitted, vertex_pps, Choice};
use crate::oracle::query::{add_info, both, both_or_note, vertex, Env, Needs, Numeric, OnF64};
use crate::oracle::reference::Other;
use crate::surface::jet::Jet;
use crate::surface::smooth::{MpConsts, SmoothSurface};
use crate::surface::{Construction, Consts, Pps, Profile, SurfaceError};
use serde_json::{json, Value};

/// The Chapter 5 state of a session: the pseudo-surface and its constants per scalar (the
/// MPFR ones as `eval` takes them through `SmoothSurface`, shared with the other queries).
struct Ch5 {
    pps: Pps,
    target: crate::surface::SPrime,
    jet: Consts<Jet<f64>>,
    mp: Option<MpConsts>,
    jet_mp: Option<Consts<Jet<Mp>>>,
}

// The Python layer holds a session behind a mutex shared by Python threads: it must stay
// `Send`, which this fails to compile without.
const _: fn() = || {
    fn send<T: Send>() {}
    send::<Session>();
};

/// A session: the loaded mesh, the MPFR precision, the Chapter 5 profile and (built lazily)
/// the pseudo-surface of Chapter 5.
pub struct Session {
    surface: Option<SimplicialSurface>,
    bits: u32,
    profile: Profile,
    sprime: crate::surface::SurfaceKind,
    ch5: Option<Ch5>,
    /// The reference of `eval` when it is not the vertex PPS of `ch5`.
    other: Option<Other>,
    /// The proven f64 error bounds of φ_wu (per edge configuration) and of g_v, g_v⁻¹ (per
    /// degree), from `set_certificate`.
    f64_bounds: super::super::query::CertBounds,
}

impl Default for Session {
    fn default() -> Self {
        Session {
            surface: None,
            bits: crate::numeric::DEFAULT_MP_PREC,
            profile: Profile::default(),
            sprime: crate::surface::SurfaceKind::default(),
            ch5: None,
            other: None,
            f64_bounds: Default::default(),
        }
    }
}

fn finite(p: &[f64; 2]) -> Result<(), OracleError> {
    if p.iter().all(|c| c.is_finite()) {
        Ok(())
    } else {
        Err(OracleError::NonFinite)
    }
}

impl Session {
    /// An empty session (no mesh; 256 bits; paper profile).
    pub fn new() -> Self {
        Self::default()
    }

    /// A session on an already validated surface.
    pub fn with_surface(k: SimplicialSurface) -> Self {
        Session {
            surface: Some(k),
            ..Self::default()
        }
    }

    /// The MPFR precision of the answers, in bits.
    pub fn bits(&self) -> u32 {
        self.bits
    }

    /// The Chapter 5 profile.
    pub fn profile(&self) -> Profile {
        self.profile
    }

    /// The session's reference construction as a [`SmoothSurface`], built on first use: the
    /// vertex PPS (Chapter 5) with the session's profile and S′ (Sec. 5.1) by default, the
    /// (σ, v) PPS after `set_construction` `"sigma-v"`. What `ppm diff --surface` compares
    /// against.
    pub fn reference(&mut self) -> Result<&dyn SmoothSurface, OracleError> {
        if self.other.is_some() {
            let k = self.surface.as_ref().ok_or(OracleError::NoMesh)?;
            let o = self.other.as_mut().ok_or(OracleError::NoMesh)?;
            o.surface(k)
        } else {
            Ok(&self.ch5()?.pps)
        }
    }

    /// `eval`'s reference with its MPFR constants at the session's precision and the `info`
    /// naming it (none for the vertex PPS).
    #[allow(clippy::type_complexity)]
    fn eval_reference(
        &mut self,
    ) -> Result<(&dyn SmoothSurface, &MpConsts, Option<&Value>), OracleError> {
        let bits = self.bits;
        if self.other.is_some() {
            let k = self.surface.as_ref().ok_or(OracleError::NoMesh)?;
            let o = self.other.as_mut().ok_or(OracleError::NoMesh)?;
            o.with_mp(k, bits)
        } else {
            let (pps, cm) = self.ch5()?.with_mp(bits);
            Ok((pps, cm, None))
        }
    }

    fn ch5(&mut self) -> Result<&mut Ch5, OracleError> {
        if self.ch5.is_none() {
            let k = self.k()?;
            let (target, pps) = vertex_pps(k, self.profile, self.sprime)?;
            let jet = pps.consts(53);
            self.ch5 = Some(Ch5 {
                pps,
                target,
                jet,
                mp: None,
                jet_mp: None,
            });
        }
        let bits = self.bits;
        let c = self.ch5.as_mut().ok_or(OracleError::NoMesh)?;
        if c.mp.as_ref().is_some_and(|m| m.bits() != bits) {
            c.mp = None;
            c.jet_mp = None;
        }
        Ok(c)
    }

    /// Answer one line of the protocol (never panics on any input).
    pub fn handle_line(&mut self, line: &str) -> Response {
        let v: Value = match serde_json::from_str(line) {
            Ok(v) => v,
            Err(e) => return Response::err(None, None, &OracleError::Malformed(e.to_string())),
        };
        let id = v.get("id").cloned();
        let op = v.get("op").and_then(Value::as_str).map(String::from);
        let mut body = v.clone();
        if let Some(o) = body.as_object_mut() {
            o.remove("id");
        }
        let req: Request = match serde_json::from_value(body) {
            Ok(r) => r,
            Err(e) => return Response::err(id, op, &OracleError::Malformed(e.to_string())),
        };
        let mut r = match self.handle(&req) {
            Ok(r) => r,
            Err(e) => Response::err(None, None, &e),
        };
        r.id = id;
        r.op = op;
        r
    }

    fn k(&self) -> Result<&SimplicialSurface, OracleError> {
        self.surface.as_ref().ok_or(OracleError::NoMesh)
    }

    /// Answer a parsed request.
    pub fn handle(&mut self, req: &Request) -> Result<Response, OracleError> {
        if let Some(q) = req.numeric() {
            return self.answer(req, q);
        }
        let bits = self.bits;
        match req {
            Request::Load { path } => {
                // A failed load leaves no mesh: later queries must not silently answer for
                // the previous one.
                self.surface = None;
                self.ch5 = None;
                if self.other.as_ref().is_some_and(|o| o.choice.is_none()) {
                    self.other = None;
                }
                if let Some(o) = &mut self.other {
                    o.reset();
                }
                if crate::fitting::format::is_fit_file(path) {
                    let fit = read_fitted(path)?;
                    let k = fit.k;
                    let out = json!({"vertices": k.num_vertices(), "faces": k.num_faces(), "edges": k.num_edges(), "construction": "fit"});
                    self.surface = Some(k);
                    self.other = Some(Other::read(fit.surface, fit.info));
                    return Ok(Response::plain(out));
                }
                let k = load_surface(path).map_err(|e| match e {
                    LoadError::Read(e) => OracleError::Load(e.to_string()),
                    LoadError::NotASurface { classes, .. } => {
                        let classes: Vec<&str> = classes.iter().map(|c| c.name()).collect();
                        OracleError::Load(format!(
                            "{}: not a simplicial surface ({})",
                            path.display(),
                            classes.join(", ")
                        ))
                    }
                })?;
                let out = json!({"vertices": k.num_vertices(), "faces": k.num_faces(), "edges": k.num_edges()});
                self.surface = Some(k);
                Ok(Response::plain(out))
            }
            Request::SetCertificate { path } => {
                let cert = crate::certify::read_certificate(path)
                    .map_err(|e| OracleError::Load(e.to_string()))?;
                self.f64_bounds = super::super::query::f64_bounds(&cert);
                Ok(Response::plain(json!({
                    "edge_configurations": self.f64_bounds.phi.len(),
                    "degrees": self.f64_bounds.g.len(),
                    "libm_ulps": crate::numeric::rounding::LIBM_ULPS,
                })))
            }
            Request::SetPrecision { bits } => {
                if !crate::numeric::PREC_BITS.contains(bits) {
                    return Err(OracleError::Precision(*bits));
                }
                self.bits = *bits;
                Ok(Response::plain(json!({"bits": bits})))
            }
            Request::SetSurface { surface } => {
                let s = crate::surface::SurfaceKind::parse(surface).ok_or_else(|| {
                    OracleError::Malformed(format!(
                        "unknown surface {surface:?} (expected \"pn\" or \"loop\")"
                    ))
                })?;
                if s != self.sprime {
                    self.sprime = s;
                    self.ch5 = None;
                }
                Ok(Response::plain(json!({"surface": s.name()})))
            }
            Request::SetConstruction {
                construction,
                kappa,
            } => match Construction::parse(construction) {
                Some(Construction::Vertex) => {
                    self.other = None;
                    Ok(Response::plain(json!({"construction": "vertex"})))
                }
                Some(Construction::SigmaV) => {
                    let kappa = kappa.unwrap_or(crate::surface::sigma_v::DEFAULT_KAPPA);
                    if !(kappa > 0.0 && kappa < 1.0) {
                        return Err(OracleError::Malformed(format!(
                            "kappa {kappa} is not in (0, 1) (SPEC SV-D3)"
                        )));
                    }
                    self.other = Some(Other::chosen(Choice::SigmaV {
                        kappa,
                        patch_degree: crate::surface::sigma_v::DEFAULT_PATCH_DEGREE,
                    }));
                    Ok(Response::plain(
                        json!({"construction": "sigma-v", "kappa": kappa}),
                    ))
                }
                Some(c @ Construction::ManifoldSpline) => {
                    if kappa.is_some() {
                        return Err(OracleError::Malformed(
                            "kappa applies to the sigma-v construction only (SPEC SV-D3)".into(),
                        ));
                    }
                    self.other = Some(Other::chosen(Choice::default_of(c)));
                    Ok(Response::plain(json!({"construction": c.name()})))
                }
                None => Err(OracleError::Malformed(format!(
                    "unknown construction {construction:?} (expected \"vertex\", \"sigma-v\" or \"manifold-spline\")"
                ))),
            },
            Request::SetProfile { profile } => {
                let p = Profile::parse(profile).ok_or_else(|| {
                    OracleError::Malformed(format!(
                        "unknown profile {profile:?} (expected \"paper\" or \"authors-code\")"
                    ))
                })?;
                if p != self.profile {
                    self.profile = p;
                    self.ch5 = None;
                }
                Ok(Response::plain(json!({"profile": p.name()})))
            }
            Request::PsiControl { v } => {
                let c = self.ch5()?;
                let v = vertex(&c.pps, *v)?;
                let (cp, l) = c.pps.patch(v);
                let mut r = Response::plain(json!(cp));
                r.f64 = Some(json!(cp));
                r.info = Some(json!({
                    "l": l,
                    "half_side": c.pps.half_side(v),
                    "index": "control point b_{j,k} at j·(l+1)+k",
                    "f64_only": "the control points are fitted in f64 (Sec. 5.2); the MPFR answers of psi/theta/eval use exactly these"
                }));
                Ok(r)
            }
            Request::Eval { face, bary } => {
                if !bary.iter().all(|c| c.is_finite()) {
                    return Err(OracleError::NonFinite);
                }
                let (s, c, named) = self.eval_reference()?;
                super::super::reference::answer(s, c, named, FaceId(*face), *bary)
            }
            Request::Degree { v } => {
                let g = PpmGluing::new(self.k()?);
                Ok(Response::plain(json!(g.degree(VertexId(*v))?)))
            }
            Request::Labels { v } => {
                let k = self.k()?;
                let g = PpmGluing::new(k);
                let m = g.degree(VertexId(*v))?;
                let list: Vec<[u32; 2]> = (0..m)
                    .filter_map(|i| k.link_vertex(VertexId(*v), i).map(|n| [n.0, i]))
                    .collect();
                Ok(Response::plain(json!(list)))
            }
            Request::Member { u, w, p, test } => {
                finite(p)?;
                let g = PpmGluing::new(self.k()?);
                let (u, w) = (VertexId(*u), VertexId(*w));
                let f = |t: Trit| match t {
                    Trit::True => json!(true),
                    Trit::False => json!(false),
                    Trit::Unknown => json!("undecided"),
                };
                let pm = P2::<Mp>::from_f64(p[0], p[1], bits);
                let (a, b) = (
                    member(&g, u, w, &P2::new(p[0], p[1]), *test)?,
                    member(&g, u, w, &pm, *test)?,
                );
                let mut r = Response::plain(f(b));
                r.f64 = Some(f(a));
                r.mp_bits = Some(bits);
                r.difference = Some(if a == b { 0.0 } else { 1.0 });
                add_info(&mut r, req.f64_bound(self.k().ok(), &self.f64_bounds));
                Ok(r)
            }
            _ => Err(OracleError::Malformed(
                "not a numerical query (no f64/MPFR answer)".into(),
            )),
        }
    }
}

/// p ∈ Ω_uw by `test`, in any scalar.
fn member<S: Scalar>(
    g: &PpmGluing,
    u: VertexId,
    w: VertexId,
    p: &P2<S>,
    test: MemberTest,
) -> Result<Trit, OracleError> {
    Ok(match test {
        MemberTest::Literal => g.in_omega_uw(u, w, p)?,
        MemberTest::Lens => g.in_omega_uw_lens(u, w, p)?,
    })
}

impl Session {
    /// The one dispatcher of the numerical queries: the query point must be finite; the
    /// session state the query needs is built; the query is evaluated in f64 and in MPFR
    /// ([`Request::at`], written once over the scalar) and answered with both values and
    /// their difference.
    fn answer(&mut self, req: &Request, q: Numeric) -> Result<Response, OracleError> {
        if !q.point.iter().all(|c| c.is_finite()) {
            return Err(OracleError::NonFinite);
        }
        self.check_arguments(req)?;
        let bits = self.bits;
        match q.needs {
            Needs::Nothing => {}
            Needs::Mesh => {
                self.k()?;
            }
            Needs::Surface => {
                self.ch5()?;
            }
            Needs::Consts => {
                let c = self.ch5()?;
                c.mp.get_or_insert_with(|| MpConsts::new(bits, c.pps.consts::<Mp>(bits)));
            }
            Needs::Jets => {
                let c = self.ch5()?;
                c.jet_mp
                    .get_or_insert_with(|| c.pps.consts::<Jet<Mp>>(bits));
            }
        }
        let k = self.surface.as_ref();
        let c = self.ch5.as_ref().filter(|_| q.needs >= Needs::Surface);
        let f = Env {
            bits: 53,
            k,
            pps: c.map(|c| &c.pps),
            target: c.map(|c| &c.target),
            consts: c.map(|c| c.pps.consts_f64()),
            jets: c.map(|c| &c.jet),
        };
        let m = Env {
            bits,
            k,
            pps: f.pps,
            target: f.target,
            consts: c.and_then(|c| c.mp.as_ref()).and_then(MpConsts::get),
            jets: c.and_then(|c| c.jet_mp.as_ref()),
        };
        let mut r = match q.on_f64 {
            OnF64::Error => {
                let a = req.at(&f)?;
                both(&a, &req.at(&m)?, bits)
            }
            OnF64::Note => {
                let b = req.at(&m)?;
                both_or_note(req.at(&f), &b, bits)
            }
        };
        add_info(&mut r, req.info(&f));
        if r.f64.is_some() {
            add_info(&mut r, req.f64_bound(k, &self.f64_bounds));
        }
        Ok(r)
    }

    /// The arguments of a numerical query that are checked before the session state is
    /// built (the order of the errors is part of the protocol).
    fn check_arguments(&self, req: &Request) -> Result<(), OracleError> {
        match req {
            Request::ThetaDerivatives { order, .. } => match order.unwrap_or(3) {
                o if o > 3 => Err(OracleError::Malformed(format!(
                    "order {o} > 3 (the jets are of order 3)"
                ))),
                _ => Ok(()),
            },
            Request::Sprime { face, bary } => {
                let sum: f64 = bary.iter().sum();
                if bary.iter().any(|&x| !(-1e-12..=1.0 + 1e-12).contains(&x))
                    || (sum - 1.0).abs() > 1e-9
                {
                    return Err(SurfaceError::BadBarycentric(*bary).into());
                }
                let f = FaceId(*face);
                if f.idx() >= self.k()?.num_faces() {
                    return Err(SurfaceError::NoSuchFace(f).into());
                }
                Ok(())
            }
            _ => Ok(()),
        }
    }
}

impl Ch5 {
    /// The pseudo-surface with its MPFR constants at `bits` (built once, cached).
    fn with_mp(&mut self, bits: u32) -> (&Pps, &MpConsts) {
        let Ch5 { pps, mp, .. } = self;
        let m = mp.get_or_insert_with(|| MpConsts::new(bits, pps.consts::<Mp>(bits)));
        (&*pps, &*m)
    }
}
