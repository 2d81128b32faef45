//! The reference of the protocol's `eval`, through `SmoothSurface` only: the session's vertex
//! PPS (Ch. 4–5) by default, or the construction chosen by `set_construction` (built by
//! `oracle::choice`) or read from a fitted-surface file by `load`, each with its MPFR
//! constants kept across requests ([`Other`]); the answer with the chart eval chose
//! ([`answer`]); and the protocol's error kinds ([`OracleError`]) for the errors of a
//! construction seen as a `SmoothSurface`.

use super::choice::{BuildError, Choice};
use super::protocol::{OracleError, Response};
use super::query::{both, both_or_note};
use crate::mesh::{FaceId, SimplicialSurface};
use crate::numeric::Scalar;
use crate::surface::sigma_v::SigmaVError;
use crate::surface::smooth::{ChartAt, MpConsts, SmoothError, SmoothSurface};
use serde_json::{json, Value};

/// The reference of `eval` when it is not the session's vertex PPS.
pub(crate) struct Other {
    /// How it is rebuilt for a new mesh; `None` for a surface read from a fitted-surface file
    /// (it brings its own K, so loading another mesh drops it).
    pub choice: Option<Choice>,
    /// The surface, built on first use.
    surface: Option<Box<dyn SmoothSurface>>,
    /// Its MPFR constants at the session's precision.
    mp: Option<MpConsts>,
    /// What the answers add to `info` to name the construction.
    info: Option<Value>,
}

impl Other {
    /// `choice`, built on first use.
    pub(crate) fn chosen(choice: Choice) -> Self {
        Other {
            choice: Some(choice),
            surface: None,
            mp: None,
            info: choice.info(),
        }
    }

    /// A surface read with its own K (a fitted-surface file).
    pub(crate) fn read(surface: Box<dyn SmoothSurface>, info: Value) -> Self {
        Other {
            choice: None,
            surface: Some(surface),
            mp: None,
            info: Some(info),
        }
    }

    /// Forget the surface (a new mesh was loaded).
    pub(crate) fn reset(&mut self) {
        self.surface = None;
        self.mp = None;
    }

    /// The surface of `k`, built on first use (a build failure is `refused`: the session
    /// continues).
    pub(crate) fn surface(
        &mut self,
        k: &SimplicialSurface,
    ) -> Result<&dyn SmoothSurface, OracleError> {
        if self.surface.is_none() {
            let choice = self.choice.ok_or(OracleError::NoMesh)?;
            let s = choice
                .build(k)
                .map_err(|e| OracleError::Refused(e.to_string()))?;
            self.surface = Some(s);
        }
        self.surface.as_deref().ok_or(OracleError::NoMesh)
    }

    /// The surface with its MPFR constants at `bits` (built once per precision) and the
    /// `info` naming it.
    pub(crate) fn with_mp(
        &mut self,
        k: &SimplicialSurface,
        bits: u32,
    ) -> Result<(&dyn SmoothSurface, &MpConsts, Option<&Value>), OracleError> {
        self.surface(k)?;
        let s = self.surface.as_deref().ok_or(OracleError::NoMesh)?;
        if self.mp.as_ref().map_or(true, |c| c.bits() != bits) {
            self.mp = Some(s.mp_consts(bits)?);
        }
        let mp = self.mp.as_ref().ok_or(OracleError::NoMesh)?;
        Ok((s, mp, self.info.as_ref()))
    }
}

/// eval(σ, λ, μ, ν) in MPFR (with `c`) and in f64, answered with both points and the chart:
/// for the vertex PPS `chart`, `vertex`, `q` (MPFR decimals), `q_f64` and `chart_f64` where
/// the f64 evaluation chose another chart (Sec. 6.1.4); for a (σ, v) PPS `corner` and `q`
/// (SPEC `SV-D13`); `named` (the construction, when it is not the vertex PPS) is added.
pub(crate) fn answer(
    s: &dyn SmoothSurface,
    c: &MpConsts,
    named: Option<&Value>,
    f: FaceId,
    bary: [f64; 3],
) -> Result<Response, OracleError> {
    let bits = c.bits();
    let b = s.eval_mp(c, f, bary)?;
    let a = s.eval_located(f, bary);
    let mut info = json!({});
    match &b.chart {
        Some(ChartAt::Vertex { chart, vertex, q }) => {
            let q: Vec<String> = q.iter().map(super::mp_values::mp_decimal).collect();
            info = json!({"chart": chart, "vertex": vertex.0, "q": q});
            if let Ok(a) = &a {
                if let Some(ChartAt::Vertex { chart: ca, q, .. }) = &a.chart {
                    info["q_f64"] = json!(q);
                    if ca != chart {
                        info["chart_f64"] = json!(ca);
                    }
                }
            }
        }
        Some(ChartAt::Corner { v, k, q }) => {
            let q: Vec<f64> = q.iter().map(Scalar::to_f64).collect();
            info = json!({"corner": {"v": v.0, "k": k}, "q": q});
        }
        None => {}
    }
    let mut r = match a {
        Ok(a) => both(&a.point, &b.point, bits),
        Err(e) => both_or_note(Err(e.into()), &b.point, bits),
    };
    for extra in [r.info.take(), named.cloned()] {
        if let Some(Value::Object(extra)) = extra {
            for (k, v) in extra {
                info[k] = v;
            }
        }
    }
    r.info = Some(info);
    Ok(r)
}

fn sv_error(e: SigmaVError) -> OracleError {
    match e {
        SigmaVError::NoSuchCorner(_)
        | SigmaVError::NoSuchFace(_)
        | SigmaVError::LevelTooLarge(_) => OracleError::Mesh(e.to_string()),
        SigmaVError::NotInOmega { .. } | SigmaVError::BadBarycentric(_) => {
            OracleError::NotInDomain(e.to_string())
        }
        SigmaVError::ZeroWeight(_) => OracleError::Undefined(e.to_string()),
        SigmaVError::BadKappa(_) => OracleError::Malformed(e.to_string()),
    }
}

impl From<SmoothError> for OracleError {
    fn from(e: SmoothError) -> Self {
        match e {
            SmoothError::Vertex(e) => e.into(),
            SmoothError::SigmaV(e) => sv_error(e),
            SmoothError::Spline(e) => OracleError::Undefined(e.to_string()),
            e @ (SmoothError::Unsupported { .. } | SmoothError::ForeignConsts { .. }) => {
                OracleError::Refused(e.to_string())
            }
        }
    }
}

impl From<BuildError> for OracleError {
    fn from(e: BuildError) -> Self {
        match e {
            BuildError::Target { msg, .. } => OracleError::Load(msg),
            BuildError::Surface(e) => e.into(),
            BuildError::Spline(e) => OracleError::Refused(e.to_string()),
            BuildError::Fit(e) => OracleError::Load(e.to_string()),
        }
    }
}
