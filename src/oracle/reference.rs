//! The protocol's error kinds ([`OracleError`]) for the errors of a reference construction
//! seen as a `SmoothSurface` (`Session::reference`): the report's vertex-indexed PPS
//! (Ch. 4–5) or the tutorial's (σ, v)-indexed PPS (SPEC `SV-D13`).

use super::protocol::OracleError;
use crate::surface::sigma_v::SigmaVError;
use crate::surface::smooth::SmoothError;

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
            e @ SmoothError::Unsupported { .. } => OracleError::Refused(e.to_string()),
        }
    }
}
