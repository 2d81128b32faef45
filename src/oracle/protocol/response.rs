//! The responses of the `ppm oracle` protocol and its typed errors.

use super::request::MAX_BITS;
use crate::construction::{GluingError, MapError};
use crate::surface::SurfaceError;
use serde::{Deserialize, Serialize};
use serde_json::{json, Value};
use thiserror::Error;

/// Error kinds of the protocol (see [`OracleError::kind`] for the stable names).
#[derive(Debug, Error, Clone, PartialEq)]
pub enum OracleError {
    /// The line is not JSON, or not a known request with the right fields.
    #[error("malformed request: {0}")]
    Malformed(String),
    /// A query arrived before any mesh was loaded.
    #[error("no mesh loaded (send {{\"op\":\"load\",\"path\":...}} first)")]
    NoMesh,
    /// The mesh could not be read, or is not a simplicial surface (Def. 3.1.6).
    #[error("cannot load mesh: {0}")]
    Load(String),
    /// No such vertex, edge or face in the loaded mesh.
    #[error("{0}")]
    Mesh(String),
    /// The point is outside the domain of the queried map (Ω_v, Ω_uw, □_v, or the
    /// barycentric simplex).
    #[error("point not in the domain: {0}")]
    NotInDomain(String),
    /// `set_precision` outside 2..=[`MAX_BITS`].
    #[error("precision {0} bits out of range {min}..={MAX_BITS}", min = crate::numeric::PREC_BITS.start())]
    Precision(u32),
    /// NaN or ±∞ in the query.
    #[error("non-finite coordinate in the query point")]
    NonFinite,
    /// The quantity is undefined at this point (Σ_u Γ_uv(p) = 0 in Eq. 5.1).
    #[error("undefined: {0}")]
    Undefined(String),
    /// The loaded mesh is beyond what the construction can be built for (fit memory of
    /// Sec. 5.2, or coordinates outside the f64 range of normals and curvatures); the session
    /// continues (Chapter 4 queries still answer).
    #[error("refused: {0}")]
    Refused(String),
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
            OracleError::Undefined(_) => "undefined",
            OracleError::Refused(_) => "refused",
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

impl From<SurfaceError> for OracleError {
    fn from(e: SurfaceError) -> Self {
        match e {
            SurfaceError::NoSuchVertex(_)
            | SurfaceError::NoSuchFace(_)
            | SurfaceError::NoSuchEdge(..)
            | SurfaceError::MissingDegree(_)
            | SurfaceError::LevelTooLarge { .. } => OracleError::Mesh(e.to_string()),
            SurfaceError::NotInOmega { .. }
            | SurfaceError::BadBarycentric(_)
            | SurfaceError::Map(_) => OracleError::NotInDomain(e.to_string()),
            SurfaceError::ZeroWeight(_) => OracleError::Undefined(e.to_string()),
            SurfaceError::FitTooLarge { .. }
            | SurfaceError::CoordinateOutOfRange { .. }
            | SurfaceError::ExtentTooSmall { .. } => OracleError::Refused(e.to_string()),
        }
    }
}

/// One response line.
#[derive(Debug, Clone, Serialize, Deserialize, PartialEq)]
pub struct Response {
    /// `true` for an answer, `false` for an error (then `error` is set).
    pub ok: bool,
    /// The request's `id`, echoed.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub id: Option<Value>,
    /// The request's `op`, echoed.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub op: Option<String>,
    /// The reference value (MPFR, decimal strings) or a non-numerical answer.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub value: Option<Value>,
    /// The same quantity computed in f64.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub f64: Option<Value>,
    /// The MPFR precision of `value`, in bits.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mp_bits: Option<u32>,
    /// |f64 − MPFR| (Euclidean, computed in MPFR): the error estimate of the f64 value.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub difference: Option<f64>,
    /// Auxiliary, non-numerical facts of the answer (eval's chart and q, the layout of
    /// `theta_derivatives`, notes such as "f64 only").
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub info: Option<Value>,
    /// `{"kind", "message"}` when `ok` is false (kinds: [`OracleError::kind`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error: Option<Value>,
}

impl Response {
    /// The error response to a line that is not a request (no `id` or `op` to echo).
    pub fn error(e: &OracleError) -> Self {
        Self::err(None, None, e)
    }
    pub(super) fn err(id: Option<Value>, op: Option<String>, e: &OracleError) -> Self {
        Response {
            ok: false,
            id,
            op,
            value: None,
            f64: None,
            mp_bits: None,
            difference: None,
            info: None,
            error: Some(json!({"kind": e.kind(), "message": e.to_string()})),
        }
    }
    pub(super) fn plain(value: Value) -> Self {
        Response {
            ok: true,
            id: None,
            op: None,
            value: Some(value),
            f64: None,
            mp_bits: None,
            difference: None,
            info: None,
            error: None,
        }
    }
}
