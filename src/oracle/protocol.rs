//! The `ppm oracle` protocol: one JSON request per line on stdin, one JSON response per line
//! on stdout. Every numerical answer carries the MPFR value (decimal strings, all digits), the
//! f64 value, the MPFR precision and |f64 − MPFR|. Bad requests get a typed error, never a
//! crash. See `docs/oracle.md` for the full list of operations with a worked example.

use super::{mp_decimal, mp_distance};
use crate::construction::maps::{g_v, g_v_inv, h};
use crate::construction::{GluingError, MapError, Mp, Paper, Ppm, PpmGluing, Trit, P2};
use crate::mesh::io::{read_mesh, ReadOptions};
use crate::mesh::validate::validate;
use crate::mesh::{SimplicialSurface, VertexId};
use serde::{Deserialize, Serialize};
use serde_json::{json, Value};
use std::path::PathBuf;
use thiserror::Error;

/// Largest accepted MPFR precision (bounded time and memory per request).
pub const MAX_BITS: u32 = 65_536;

/// Membership test for Ω_uw.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum MemberTest {
    /// Def. 4.1.9 literally (the reference).
    #[default]
    Literal,
    /// The canonical-lens test of Sec. 6.1.3 (differs for degree ≥ 11, SPEC.md `D4.1.9-lens`).
    Lens,
}

/// One request of the protocol (`{"op": "...", ...}`); `id` (any JSON) is echoed back.
#[derive(Debug, Clone, Deserialize, Serialize, PartialEq)]
#[serde(tag = "op", rename_all = "snake_case", deny_unknown_fields)]
pub enum Request {
    /// Load and validate a mesh; later queries refer to its vertex ids (file indices).
    Load { path: PathBuf },
    /// Set the MPFR precision of later answers (default 256).
    SetPrecision { bits: u32 },
    /// m_v (Def. 4.1.1).
    Degree { v: u32 },
    /// The labels s_v (Def. 4.1.4 / Sec. 6.1.2): `[[neighbour, i], …]` in label order.
    Labels { v: u32 },
    /// p ∈ Ω_uw? (Def. 4.1.9 or the Sec. 6.1.3 lens test).
    Member {
        u: u32,
        w: u32,
        p: [f64; 2],
        #[serde(default)]
        test: MemberTest,
    },
    /// φ_wu(p), p ∈ Ω_uw (Def. 4.1.10: from Ω_uw to Ω_wu).
    Phi { u: u32, w: u32, p: [f64; 2] },
    /// g_v(p) (Def. 4.1.6).
    G { v: u32, p: [f64; 2] },
    /// g_v⁻¹(p) (Def. 4.1.6).
    GInv { v: u32, p: [f64; 2] },
    /// h(p) = (1 − x, −y) (Def. 4.1.7).
    H { p: [f64; 2] },
    /// R_(u,w)(p): rotation by −2π·s_u(w)/m_u (Def. 4.1.8).
    Rotate { u: u32, w: u32, p: [f64; 2] },
}

/// Error kinds of the protocol.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum OracleError {
    #[error("malformed request: {0}")]
    Malformed(String),
    #[error("no mesh loaded (send {{\"op\":\"load\",\"path\":...}} first)")]
    NoMesh,
    #[error("cannot load mesh: {0}")]
    Load(String),
    #[error("{0}")]
    Mesh(String),
    #[error("point not in the domain: {0}")]
    NotInDomain(String),
    #[error("precision {0} bits out of range 2..={MAX_BITS}")]
    Precision(u32),
    #[error("non-finite coordinate in the query point")]
    NonFinite,
}

impl OracleError {
    /// Stable machine-readable kind.
    pub fn kind(&self) -> &'static str {
        match self {
            OracleError::Malformed(_) => "malformed_request",
            OracleError::NoMesh => "no_mesh",
            OracleError::Load(_) => "load_failed",
            OracleError::Mesh(_) => "no_such_element",
            OracleError::NotInDomain(_) => "not_in_domain",
            OracleError::Precision(_) => "bad_precision",
            OracleError::NonFinite => "non_finite",
        }
    }
}

impl From<GluingError> for OracleError {
    fn from(e: GluingError) -> Self {
        match e {
            GluingError::Map { .. } => OracleError::NotInDomain(e.to_string()),
            other => OracleError::Mesh(other.to_string()),
        }
    }
}

impl From<MapError> for OracleError {
    fn from(e: MapError) -> Self {
        OracleError::NotInDomain(e.to_string())
    }
}

/// One response line.
#[derive(Debug, Clone, Serialize, Deserialize, PartialEq)]
pub struct Response {
    pub ok: bool,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub id: Option<Value>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub op: Option<String>,
    /// The reference value (MPFR, decimal strings) or a non-numerical answer.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub value: Option<Value>,
    /// The same quantity computed in f64.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub f64: Option<Value>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mp_bits: Option<u32>,
    /// |f64 − MPFR| (Euclidean, computed in MPFR): the error estimate of the f64 value.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub difference: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error: Option<Value>,
}

impl Response {
    fn err(id: Option<Value>, op: Option<String>, e: &OracleError) -> Self {
        Response {
            ok: false,
            id,
            op,
            value: None,
            f64: None,
            mp_bits: None,
            difference: None,
            error: Some(json!({"kind": e.kind(), "message": e.to_string()})),
        }
    }
    fn plain(value: Value) -> Self {
        Response {
            ok: true,
            id: None,
            op: None,
            value: Some(value),
            f64: None,
            mp_bits: None,
            difference: None,
            error: None,
        }
    }
}

/// A session: the loaded mesh and the precision.
pub struct Session {
    surface: Option<SimplicialSurface>,
    bits: u32,
}

impl Default for Session {
    fn default() -> Self {
        Session {
            surface: None,
            bits: crate::construction::DEFAULT_MP_PREC,
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

    pub fn bits(&self) -> u32 {
        self.bits
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
        let bits = self.bits;
        match req {
            Request::Load { path } => {
                let raw = read_mesh(path, &ReadOptions::default())
                    .map_err(|e| OracleError::Load(e.to_string()))?;
                let v = validate(&raw);
                let classes: Vec<&str> = v.report.error_classes.iter().map(|c| c.name()).collect();
                let k = v.surface.ok_or_else(|| {
                    OracleError::Load(format!(
                        "{}: not a simplicial surface ({})",
                        path.display(),
                        classes.join(", ")
                    ))
                })?;
                let out = json!({"vertices": k.num_vertices(), "faces": k.num_faces(), "edges": k.num_edges()});
                self.surface = Some(k);
                Ok(Response::plain(out))
            }
            Request::SetPrecision { bits } => {
                if !(2..=MAX_BITS).contains(bits) {
                    return Err(OracleError::Precision(*bits));
                }
                self.bits = *bits;
                Ok(Response::plain(json!({"bits": bits})))
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
                let (a, b) = match test {
                    MemberTest::Literal => (
                        g.in_omega_uw(u, w, &P2::<f64>::new(p[0], p[1]))?,
                        g.in_omega_uw(u, w, &P2::<Mp>::from_f64(p[0], p[1], bits))?,
                    ),
                    MemberTest::Lens => (
                        g.in_omega_uw_lens(u, w, &P2::<f64>::new(p[0], p[1]))?,
                        g.in_omega_uw_lens(u, w, &P2::<Mp>::from_f64(p[0], p[1], bits))?,
                    ),
                };
                let mut r = Response::plain(f(b));
                r.f64 = Some(f(a));
                r.mp_bits = Some(bits);
                r.difference = Some(if a == b { 0.0 } else { 1.0 });
                Ok(r)
            }
            Request::Phi { u, w, p } => {
                finite(p)?;
                let g = PpmGluing::new(self.k()?);
                let (u, w) = (VertexId(*u), VertexId(*w));
                let a = g.phi::<f64>(w, u, &P2::new(p[0], p[1]))?;
                let b = g.phi::<Mp>(w, u, &P2::from_f64(p[0], p[1], bits))?;
                Ok(both(&[a.x, a.y], &[b.x, b.y], bits))
            }
            Request::G { v, p } | Request::GInv { v, p } => {
                finite(p)?;
                let m = PpmGluing::new(self.k()?).degree(VertexId(*v))?;
                let inv = matches!(req, Request::GInv { .. });
                let a = if inv {
                    g_v_inv::<f64>(m, &P2::new(p[0], p[1]))?
                } else {
                    g_v::<f64>(m, &P2::new(p[0], p[1]))?
                };
                let pm = P2::<Mp>::from_f64(p[0], p[1], bits);
                let b = if inv {
                    g_v_inv::<Mp>(m, &pm)?
                } else {
                    g_v::<Mp>(m, &pm)?
                };
                Ok(both(&[a.x, a.y], &[b.x, b.y], bits))
            }
            Request::H { p } => {
                finite(p)?;
                let a = h(&P2::<f64>::new(p[0], p[1]));
                let b = h(&P2::<Mp>::from_f64(p[0], p[1], bits));
                Ok(both(&[a.x, a.y], &[b.x, b.y], bits))
            }
            Request::Rotate { u, w, p } => {
                finite(p)?;
                let g = PpmGluing::new(self.k()?);
                let e = g.edge_config(VertexId(*u), VertexId(*w))?;
                let a = Paper.r_uw(&e, &P2::<f64>::new(p[0], p[1]));
                let b = Paper.r_uw(&e, &P2::<Mp>::from_f64(p[0], p[1], bits));
                Ok(both(&[a.x, a.y], &[b.x, b.y], bits))
            }
        }
    }
}

/// A numerical answer: MPFR value, f64 value, difference.
fn both(a: &[f64], b: &[Mp], bits: u32) -> Response {
    let value: Vec<String> = b.iter().map(mp_decimal).collect();
    Response {
        ok: true,
        id: None,
        op: None,
        value: Some(json!(value)),
        f64: Some(json!(a)),
        mp_bits: Some(bits),
        difference: Some(mp_distance(a, b)),
        error: None,
    }
}
