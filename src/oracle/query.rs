//! The numerical queries of the `ppm oracle` protocol, each written once over the scalar
//! ([`Request::at`]), and the answer every one of them gets from the one dispatcher
//! (`Session::answer`): the query point checked finite, the query evaluated in f64 and in MPFR,
//! and both values reported with their difference ([`both`], [`both_or_note`]).

use super::mp_values::{mp_decimal, mp_distance};
use super::protocol::{OracleError, Request};
use crate::construction::maps::{g_v, g_v_inv, h};
use crate::construction::{Paper, Ppm, PpmGluing, P2};
use crate::mesh::{FaceId, SimplicialSurface, VertexId};
use crate::numeric::{Mp, Scalar};
use crate::surface::jet::{Jet, MONOMIALS};
use crate::surface::loop_subdiv::{LoopError, LoopSurface};
use crate::surface::target::{eval_cubic, eval_cubic_in};
use crate::surface::{Consts, Pps, SPrime, SurfaceError, SurfaceScalar};
use serde_json::{json, Value};

/// The two precisions of an answer. Where the library has one implementation per precision
/// (S′), this trait picks it; every other query is generic over the scalar.
pub(crate) trait Precision: SurfaceScalar {
    /// S′ = PN triangles with control net `net` at `bary` (Sec. 5.1).
    fn pn(net: &[[f64; 3]; 10], bary: [f64; 3], bits: u32) -> [Self; 3];
    /// S′ = the Loop limit surface at `bary` of face `f` (Sec. 6.2).
    fn loop_point(
        l: &LoopSurface,
        f: FaceId,
        corners: [VertexId; 3],
        bary: [f64; 3],
        bits: u32,
    ) -> Result<[Self; 3], LoopError>;
}

impl Precision for f64 {
    fn pn(net: &[[f64; 3]; 10], bary: [f64; 3], _: u32) -> [f64; 3] {
        eval_cubic(net, bary)
    }
    fn loop_point(
        l: &LoopSurface,
        f: FaceId,
        corners: [VertexId; 3],
        bary: [f64; 3],
        _: u32,
    ) -> Result<[f64; 3], LoopError> {
        l.eval_f64(f, corners, bary)
    }
}

impl Precision for Mp {
    fn pn(net: &[[f64; 3]; 10], bary: [f64; 3], bits: u32) -> [Mp; 3] {
        let bm = bary.map(|x| Mp::from_f64(x, bits));
        eval_cubic_in(net, &bm, bits)
    }
    /// Exactly, by Stam's method.
    fn loop_point(
        l: &LoopSurface,
        f: FaceId,
        corners: [VertexId; 3],
        bary: [f64; 3],
        bits: u32,
    ) -> Result<[Mp; 3], LoopError> {
        let bm = bary.map(|x| Mp::from_f64(x, bits));
        Ok(l.jet::<Mp>(f, corners, &bm, false)?.p)
    }
}

/// How much session state a query needs; the dispatcher builds it before evaluating, so a
/// missing mesh or a refused pseudo-surface is the answer's error.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) enum Needs {
    /// Nothing (h).
    Nothing,
    /// The validated mesh (Chapter 4).
    Mesh,
    /// The pseudo-surface of Chapter 5 and its S′.
    Surface,
    /// The pseudo-surface with its constants in MPFR.
    Consts,
    /// The pseudo-surface with its order-3 jet constants in both precisions.
    Jets,
}

/// How an f64 failure where the MPFR evaluation succeeds is answered.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum OnF64 {
    /// The f64 error is the answer's error (evaluated first).
    Error,
    /// A point on the boundary of a domain may be decided differently by the two roundings:
    /// the answer carries the MPFR value and `info.f64_failed`.
    Note,
}

/// A numerical query: its point (checked finite), its needs and its f64 rule.
pub(crate) struct Numeric<'a> {
    /// The coordinates that must be finite.
    pub point: &'a [f64],
    /// The session state it evaluates with.
    pub needs: Needs,
    /// How an f64 failure is answered.
    pub on_f64: OnF64,
}

/// What a query evaluates with at precision `S` (built by the dispatcher).
pub(crate) struct Env<'a, S> {
    /// The precision of `S` in bits (ignored by f64).
    pub bits: u32,
    /// The loaded mesh.
    pub k: Option<&'a SimplicialSurface>,
    /// The pseudo-surface of Chapter 5.
    pub pps: Option<&'a Pps>,
    /// Its S′.
    pub target: Option<&'a SPrime>,
    /// Its constants in `S`.
    pub consts: Option<&'a Consts<S>>,
    /// Its order-3 jet constants in `S`.
    pub jets: Option<&'a Consts<Jet<S>>>,
}

impl<'a, S> Env<'a, S> {
    fn k(&self) -> Result<&'a SimplicialSurface, OracleError> {
        self.k.ok_or(OracleError::NoMesh)
    }
    fn pps(&self) -> Result<&'a Pps, OracleError> {
        self.pps.ok_or(OracleError::NoMesh)
    }
    fn consts(&self) -> Result<(&'a Pps, &'a Consts<S>), OracleError> {
        Ok((self.pps()?, self.consts.ok_or(OracleError::NoMesh)?))
    }
    fn jets(&self) -> Result<(&'a Pps, &'a Consts<Jet<S>>), OracleError> {
        Ok((self.pps()?, self.jets.ok_or(OracleError::NoMesh)?))
    }
}

pub(crate) fn vertex(pps: &Pps, v: u32) -> Result<VertexId, OracleError> {
    let v = VertexId(v);
    if pps.contains(v) {
        Ok(v)
    } else {
        Err(SurfaceError::NoSuchVertex(v).into())
    }
}

fn xy<S: Scalar>(p: &P2<S>) -> Vec<S> {
    vec![p.x.clone(), p.y.clone()]
}

/// The partials ∂^{i+j}/∂x^i∂y^j with i + j ≤ `order`, in the answer's order.
fn partials(order: u32) -> Vec<(usize, usize)> {
    MONOMIALS
        .iter()
        .copied()
        .filter(|&(i, j)| i + j <= order as usize)
        .collect()
}

impl Request {
    /// The numerical queries (answered by the dispatcher); `None` for the others.
    pub(crate) fn numeric(&self) -> Option<Numeric<'_>> {
        use Needs::*;
        use OnF64::*;
        fn q(point: &[f64], needs: Needs, on_f64: OnF64) -> Option<Numeric<'_>> {
            Some(Numeric {
                point,
                needs,
                on_f64,
            })
        }
        match self {
            Request::Phi { p, .. }
            | Request::G { p, .. }
            | Request::GInv { p, .. }
            | Request::Rotate { p, .. } => q(p, Mesh, Error),
            Request::H { p } => q(p, Nothing, Error),
            Request::Gamma { p, .. } | Request::Theta { p, .. } => q(p, Consts, Note),
            Request::Psi { p, .. } => q(p, Surface, Error),
            Request::ThetaDerivatives { p, .. } => q(p, Jets, Note),
            Request::Sprime { bary, .. } => q(bary, Surface, Error),
            _ => None,
        }
    }

    /// The query at precision `S`, written once for f64 and MPFR (Chapter 4: Defs. 4.1.6–4.1.10;
    /// Chapter 5: Defs. 5.2.1, 5.3.1, 5.4.2; S′ of Sec. 5.1).
    pub(crate) fn at<S: Precision>(&self, e: &Env<S>) -> Result<Vec<S>, OracleError> {
        let pt = |p: &[f64; 2]| P2::<S>::from_f64(p[0], p[1], e.bits);
        match self {
            Request::Phi { u, w, p } => {
                let g = PpmGluing::new(e.k()?);
                Ok(xy(&g.phi::<S>(VertexId(*w), VertexId(*u), &pt(p))?))
            }
            Request::G { v, p } => {
                let m = PpmGluing::new(e.k()?).degree(VertexId(*v))?;
                Ok(xy(&g_v::<S>(m, &pt(p))?))
            }
            Request::GInv { v, p } => {
                let m = PpmGluing::new(e.k()?).degree(VertexId(*v))?;
                Ok(xy(&g_v_inv::<S>(m, &pt(p))?))
            }
            Request::H { p } => Ok(xy(&h(&pt(p)))),
            Request::Rotate { u, w, p } => {
                let g = PpmGluing::new(e.k()?);
                let c = g.edge_config(VertexId(*u), VertexId(*w))?;
                Ok(xy(&Paper.r_uw(&c, &pt(p))))
            }
            Request::Gamma { v, p } => {
                let (pps, c) = e.consts()?;
                let v = vertex(pps, *v)?;
                Ok(vec![pps.gamma(v, &pt(p), c)?])
            }
            Request::Psi { v, p } => {
                let pps = e.pps()?;
                let v = vertex(pps, *v)?;
                let l = pps.half_side(v);
                if p[0].abs() > l || p[1].abs() > l {
                    return Err(OracleError::NotInDomain(format!(
                        "ψ_{v} is defined on □_{v} = [−{l}, {l}]² (Def. 5.2.1)"
                    )));
                }
                Ok(pps.psi(v, &pt(p)).to_vec())
            }
            Request::Theta { v, p } => {
                let (pps, c) = e.consts()?;
                let v = vertex(pps, *v)?;
                Ok(pps.theta(v, &pt(p), c)?.to_vec())
            }
            Request::ThetaDerivatives { v, p, order } => {
                let (pps, c) = e.jets()?;
                let v = vertex(pps, *v)?;
                let q = pt(p);
                let (x, y) = Jet::variables(q.x, q.y);
                let jet = pps.theta(v, &P2::new(x, y), c)?;
                Ok(partials(order.unwrap_or(3))
                    .iter()
                    .flat_map(|&(i, j)| jet.iter().map(move |d| d.derivative(i, j)))
                    .collect())
            }
            Request::Sprime { face, bary } => {
                let f = FaceId(*face);
                // The stored corners: the file's order unless the validator reversed σ.
                let corners = e.k()?.face(f);
                match e.target.ok_or(OracleError::NoMesh)? {
                    SPrime::Pn(pn) => Ok(S::pn(&pn.net(corners), *bary, e.bits).to_vec()),
                    SPrime::Loop(l) => {
                        // The point the profile evaluates (the authors' corner clamp under
                        // `authors-code`).
                        let at = l.profile_bary(f, corners, *bary);
                        S::loop_point(l, f, corners, at, e.bits)
                            .map(|x| x.to_vec())
                            .map_err(|e| OracleError::Undefined(e.to_string()))
                    }
                }
            }
            _ => Err(OracleError::Malformed(
                "not a numerical query (no f64/MPFR answer)".into(),
            )),
        }
    }

    /// The certificate's proven bound on the f64 error of a `phi` answer (SPEC
    /// `CERT-f64-rounding`): 0 for φ_uu = id, the edge configuration's bound otherwise; of a
    /// `g` or `g_inv` answer at a point of the chart square the certificate covers (SPEC
    /// `CERT-f64-g-chart`), the degree's bound; nothing when no certificate was set or it does
    /// not cover the query.
    pub(crate) fn f64_bound(
        &self,
        k: Option<&crate::mesh::SimplicialSurface>,
        bounds: &CertBounds,
    ) -> Option<Value> {
        let k = k?;
        let g = PpmGluing::new(k);
        let (bound, note) = match self {
            Request::Phi { u, w, .. } => {
                if bounds.phi.is_empty() {
                    return None;
                }
                let bound = if u == w {
                    0.0
                } else {
                    let c = g.edge_config(VertexId(*u), VertexId(*w)).ok()?;
                    *bounds.phi.get(&(c.m_u, c.m_w))?
                };
                (bound, "proven |f64 − exact| of φ_wu for p in the boxes covering the closed 1e−9-neighbourhood of Ω_uw, any labels (certificate, SPEC CERT-f64-rounding)".to_string())
            }
            Request::G { v, p } | Request::GInv { v, p } => {
                let gc = bounds.g.get(&g.degree(VertexId(*v)).ok()?)?;
                if !gc.covers(*p) {
                    return None;
                }
                let (name, b) = match self {
                    Request::G { .. } => ("g_v", gc.g_v),
                    _ => ("g_v⁻¹", gc.g_v_inv),
                };
                (b?, format!("proven |f64 − exact| (Euclidean) of {name} at every f64 point p ≠ 0 with |x|, |y| ≤ {} (certificate, SPEC CERT-f64-g-chart)", gc.radius))
            }
            Request::Member { u, w, test, .. } => {
                let c = g.edge_config(VertexId(*u), VertexId(*w)).ok()?;
                let (margin, note) = match test {
                    super::protocol::MemberTest::Literal => (
                        *bounds.literal.get(&(c.m_u, c.m_w))?,
                        "the literal test's f64 decisions |p|² − r_u² < 0, |q|² − r_w² < 0 are exact unless the exact value lies within this of 0, its round trip is certified exact on Ω_uw; at every point of Ω_u (off Ω_uw the exact answer is 'out' and the f64 one too unless |q|² − r_w² lies within this of 0), any labels (certificate, SPEC CERT-f64-rounding, CERT-f64-props)",
                    ),
                    super::protocol::MemberTest::Lens => (
                        *bounds.lens.get(&c.m_u)?,
                        "the lens test's f64 decisions |c|² < 3/4, |c − (1,0)|² < 3/4 (c = h∘g_u∘R_(u,w)(p)) are exact unless the exact value lies within this of 3/4 (of 0 for the punctures); for p ∈ Ω_u, any labels (certificate, SPEC CERT-f64-props)",
                    ),
                };
                return Some(json!({
                    "f64_decision_margin": margin,
                    "f64_decision_margin_note": format!("{note}; {}", crate::numeric::rounding::LIBM_ASSUMPTION),
                }));
            }
            _ => return None,
        };
        Some(json!({
            "f64_error_bound": bound,
            "f64_error_bound_note": format!("{note}; {}", crate::numeric::rounding::LIBM_ASSUMPTION),
        }))
    }

    /// Non-numerical facts of a numerical answer (`info`), from the f64 environment.
    pub(crate) fn info(&self, e: &Env<f64>) -> Option<Value> {
        match self {
            Request::ThetaDerivatives { order, .. } => Some(json!({
                "partials": partials(order.unwrap_or(3)),
                "layout": "value[3k + d] = ∂^(i+j) θ_v,d / ∂x^i ∂y^j at p, for partials[k] = [i, j], d = 0, 1, 2",
            })),
            Request::Sprime { face, bary } => {
                let (Some(SPrime::Loop(l)), Some(k)) = (e.target, e.k) else {
                    return None;
                };
                let f = FaceId(*face);
                let at = l.profile_bary(f, k.face(f), *bary);
                (at != *bary).then(|| {
                    json!({ "evaluated_at": at, "why": "authors-code: their Loop evaluator's corner clamp (docs/authors-code.md, D2)" })
                })
            }
            _ => None,
        }
    }
}

/// Merge the object `extra` into the answer's `info`.
pub(crate) fn add_info(r: &mut super::Response, extra: Option<Value>) {
    let Some(Value::Object(extra)) = extra else {
        return;
    };
    let mut info = r.info.take().unwrap_or_else(|| json!({}));
    for (k, v) in extra {
        info[k] = v;
    }
    r.info = Some(info);
}

/// A numerical answer: MPFR value, f64 value, difference. A non-finite f64 component (which
/// JSON would print as `null`) is an f64 failure, reported as `info.f64_failed` with no `f64`
/// and no `difference` (the documented shape).
pub(crate) fn both(a: &[f64], b: &[Mp], bits: u32) -> super::Response {
    if let Some(i) = a.iter().position(|x| !x.is_finite()) {
        return mp_only(b, bits, format!("the f64 evaluation gave a non-finite component {} (index {i}) where MPFR is finite", a[i]));
    }
    let value: Vec<String> = b.iter().map(mp_decimal).collect();
    super::Response {
        ok: true,
        id: None,
        op: None,
        value: Some(json!(value)),
        f64: Some(json!(a)),
        mp_bits: Some(bits),
        difference: Some(mp_distance(a, b)),
        info: None,
        error: None,
    }
}

/// The MPFR answer alone, where the f64 evaluation failed (`info.f64_failed` says why).
pub(crate) fn mp_only(b: &[Mp], bits: u32, why: String) -> super::Response {
    let mut r = both(&[], b, bits);
    r.f64 = None;
    r.difference = None;
    r.info = Some(json!({ "f64_failed": why }));
    r
}

/// A numerical answer whose f64 evaluation may have failed where MPFR succeeded (a point on
/// the boundary of a domain, decided differently by the two roundings).
pub(crate) fn both_or_note(
    a: Result<Vec<f64>, OracleError>,
    b: &[Mp],
    bits: u32,
) -> super::Response {
    match a {
        Ok(a) => both(&a, b, bits),
        Err(e) => mp_only(b, bits, e.to_string()),
    }
}

/// The proven f64 error bounds a certificate of the paper's model gives the oracle.
#[derive(Debug, Clone, Default)]
pub(crate) struct CertBounds {
    /// φ_wu's, by edge configuration (m_u, m_w) (SPEC `CERT-f64-rounding`).
    pub phi: std::collections::BTreeMap<(u32, u32), f64>,
    /// g_v's and g_v⁻¹'s on the chart square, by degree (SPEC `CERT-f64-g-chart`).
    pub g: std::collections::BTreeMap<u32, crate::certify::GChartRounding>,
    /// The literal membership test's decision margin max(`outer`, `inner`, `outside.inner`), by
    /// edge configuration, where its round trip is certified exact (SPEC `CERT-f64-rounding`).
    pub literal: std::collections::BTreeMap<(u32, u32), f64>,
    /// The lens test's decision margin, by degree (SPEC `CERT-f64-props`).
    pub lens: std::collections::BTreeMap<u32, f64>,
}

/// The f64 error bounds of a certificate of the paper's model (none for another model).
pub(crate) fn f64_bounds(cert: &crate::certify::Certificate) -> CertBounds {
    use crate::certify::ConfigKey;
    let mut out = CertBounds::default();
    if cert.model != "paper" {
        return out;
    }
    for r in &cert.results {
        if let (ConfigKey::Edge { m_u, m_w }, Some(f)) = (r.key, &r.f64_rounding) {
            // On all of Ω_u, where the round trip is decided exactly (a certificate without the
            // pass off the neighbourhood gives no margin).
            if let Some((m, true)) = f.literal_margin() {
                out.literal.insert((m_u, m_w), m);
            }
        }
        if let (ConfigKey::Vertex { m }, Some(b)) =
            (r.key, r.f64_bound.as_ref().and_then(|b| b.bound))
        {
            if r.property == "C5.4-at-most-two[sec6.1.3](cert)" {
                out.lens.insert(m, b);
            }
        }
        match (r.key, r.f64_rounding.as_ref().and_then(|f| f.phi)) {
            (ConfigKey::Edge { m_u, m_w }, Some(b)) => {
                out.phi.insert((m_u, m_w), b);
            }
            (ConfigKey::Vertex { m }, _) => {
                if let Some(g) = &r.g_chart {
                    out.g.insert(m, g.clone());
                }
            }
            _ => {}
        }
    }
    out
}
