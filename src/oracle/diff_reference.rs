//! The reference constructions `ppm diff --surface` compares against ([`DiffReference`]):
//! the report's vertex-indexed PPS (Ch. 4–5), whose f64 eval carries an error bound (SPEC
//! `R-diff-f64-bound`), and the tutorial's (σ, v)-indexed PPS (SPEC `SV-D13`), which has none.

use super::protocol::OracleError;
use crate::mesh::{FaceId, VertexId};
use crate::numeric::{Mp, Scalar};
use crate::surface::eval_bound::BoundedPoint;
use crate::surface::sigma_v::{SigmaVError, SigmaVPps, SvConsts};
use crate::surface::{Consts, Pps};

/// What [`super::surface_diff::diff_surface`] needs of a reference construction.
pub trait DiffReference: Sync {
    /// MPFR constants of the construction at one precision.
    type MpConsts: Sync;
    /// The construction, as the report names it.
    fn name(&self) -> String;
    /// The corners of every face of K in stored order (the sampling pattern's input).
    fn face_corners(&self) -> Result<Vec<[VertexId; 3]>, OracleError>;
    /// eval(σ, λ, μ, ν) in f64, with its error bound when the construction has an analysis.
    fn eval_bounded(
        &self,
        f: FaceId,
        bary: [f64; 3],
    ) -> Result<([f64; 3], Option<BoundedPoint>), OracleError>;
    /// The MPFR constants at `bits`.
    fn mp_consts(&self, bits: u32) -> Self::MpConsts;
    /// eval at the precision of `c`.
    fn eval_mp(
        &self,
        c: &Self::MpConsts,
        f: FaceId,
        bary: [f64; 3],
        bits: u32,
    ) -> Result<[Mp; 3], OracleError>;
}

impl DiffReference for Pps {
    type MpConsts = Consts<Mp>;
    fn name(&self) -> String {
        format!(
            "the vertex-indexed PPS (Ch. 4–5; profile {}, S′ = {})",
            self.options.profile.name(),
            self.target_name()
        )
    }
    fn face_corners(&self) -> Result<Vec<[VertexId; 3]>, OracleError> {
        Ok((0..self.num_faces())
            .map(|f| self.face(FaceId(f as u32)))
            .collect::<Result<_, _>>()?)
    }
    fn eval_bounded(
        &self,
        f: FaceId,
        bary: [f64; 3],
    ) -> Result<([f64; 3], Option<BoundedPoint>), OracleError> {
        let b = self.eval_f64_bounded(f, bary)?;
        Ok((b.point, Some(b)))
    }
    fn mp_consts(&self, bits: u32) -> Consts<Mp> {
        self.consts(bits)
    }
    fn eval_mp(
        &self,
        c: &Consts<Mp>,
        f: FaceId,
        bary: [f64; 3],
        bits: u32,
    ) -> Result<[Mp; 3], OracleError> {
        let bm = bary.map(|x| Mp::from_f64(x, bits));
        Ok(self.eval(f, &bm, c)?.point)
    }
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

impl DiffReference for SigmaVPps {
    type MpConsts = SvConsts<Mp>;
    fn name(&self) -> String {
        format!(
            "the (σ, v)-indexed PPS of the tutorial (SPEC SV-D13; κ = {}, S′ = {})",
            self.gluing.kappa,
            self.target_name()
        )
    }
    fn face_corners(&self) -> Result<Vec<[VertexId; 3]>, OracleError> {
        (0..self.gluing.num_faces())
            .map(|f| self.gluing.face_corners(FaceId(f as u32)).map_err(sv_error))
            .collect()
    }
    fn eval_bounded(
        &self,
        f: FaceId,
        bary: [f64; 3],
    ) -> Result<([f64; 3], Option<BoundedPoint>), OracleError> {
        Ok((self.eval_f64(f, bary).map_err(sv_error)?, None))
    }
    fn mp_consts(&self, bits: u32) -> SvConsts<Mp> {
        self.consts(bits)
    }
    fn eval_mp(
        &self,
        c: &SvConsts<Mp>,
        f: FaceId,
        bary: [f64; 3],
        bits: u32,
    ) -> Result<[Mp; 3], OracleError> {
        let bm = bary.map(|x| Mp::from_f64(x, bits));
        Ok(self.eval(f, &bm, c).map_err(sv_error)?.2)
    }
}
