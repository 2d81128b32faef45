//! The tutorial's (σ, v)-indexed PPS (Part V, SPEC `SV-D12`, eval `SV-D13`) as a
//! [`SmoothSurface`].

use super::gluing::{Corner, CornerId};
use super::surface::{SigmaVPps, SvConsts};
use super::view::{SigmaVView, Version};
use crate::construction::P2;
use crate::gluing::data::Idx;
use crate::mesh::{FaceId, SimplicialSurface, VertexId};
use crate::numeric::{Mp, Scalar};
use crate::report::Progress;
use crate::surface::geometry::{from_jet, SurfacePoint};
use crate::surface::jet::Jet;
use crate::surface::output::{Attributes, SampledMesh};
use crate::surface::smooth::{
    ChartAt, FitSummary, GluingView, Located, MpConsts, SmoothError, SmoothSurface,
};

/// eval's answer as the trait gives it: the point, the corner (σ, v) and q (SPEC `SV-D13`).
fn located<S>((corner, q, point): (Corner, P2<S>, [S; 3])) -> Located<S> {
    Located {
        point,
        chart: Some(ChartAt::Corner {
            v: corner.v,
            k: corner.k,
            q: [q.x, q.y],
        }),
    }
}

impl SmoothSurface for SigmaVPps {
    fn name(&self) -> String {
        format!(
            "the (σ, v)-indexed PPS of the tutorial (SPEC SV-D13; κ = {}, S′ = {})",
            self.gluing.kappa,
            self.target_name()
        )
    }

    fn fit_summary(&self) -> Vec<FitSummary> {
        self.fit_info()
            .iter()
            .map(|f| FitSummary {
                m: f.m,
                l: None,
                rows: f.rows,
                unknowns: f.unknowns,
                rank: f.rank,
                condition: f.condition,
            })
            .collect()
    }

    fn face_corners(&self) -> Result<Vec<[VertexId; 3]>, SmoothError> {
        Ok((0..self.gluing.num_faces())
            .map(|f| self.gluing.face_corners(FaceId(f as u32)))
            .collect::<Result<_, _>>()?)
    }

    fn eval_f64(&self, f: FaceId, bary: [f64; 3]) -> Result<[f64; 3], SmoothError> {
        Ok(SigmaVPps::eval_f64(self, f, bary)?)
    }

    fn eval_located(&self, f: FaceId, bary: [f64; 3]) -> Result<Located<f64>, SmoothError> {
        Ok(located(self.eval(f, &bary, self.consts_f64())?))
    }

    fn mp_consts(&self, bits: u32) -> Result<MpConsts, SmoothError> {
        Ok(MpConsts::new(bits, self.consts::<Mp>(bits)))
    }

    fn eval_mp(&self, c: &MpConsts, f: FaceId, bary: [f64; 3]) -> Result<Located<Mp>, SmoothError> {
        let cm: &SvConsts<Mp> = c.get().ok_or(SmoothError::ForeignConsts {
            surface: "the (σ, v)-indexed PPS",
        })?;
        let bm = bary.map(|x| Mp::from_f64(x, c.bits()));
        Ok(located(self.eval(f, &bm, cm)?))
    }

    /// θ_(σ,c*) as an order-3 jet at q = f_(σ,c*)(p), in the corner eval chose (`SV-D13`).
    fn eval_geometry(&self, f: FaceId, bary: [f64; 3]) -> Result<SurfacePoint, SmoothError> {
        let cj: SvConsts<Jet<f64>> = self.consts(53);
        let (corner, q) = self.eval_chart(f, &bary, self.consts_f64())?;
        let (x, y) = Jet::<f64>::variables(q.x, q.y);
        Ok(from_jet(&self.theta_plane(corner, &P2::new(x, y), &cj)?))
    }

    /// The sampling reports no progress (`progress` is not called).
    fn sample(
        &self,
        level: u32,
        attrs: Attributes,
        _progress: Progress,
    ) -> Result<SampledMesh, SmoothError> {
        Ok(self.sample_surface_with(level, attrs)?)
    }

    /// The fixed version of the tutorial's gluing data (T 2112–2120, [`Version::Fixed`]): I is
    /// the set of corners (σ, v); `k` is not needed (the gluing data are kept).
    fn gluing_view<'a>(
        &'a self,
        _k: &'a SimplicialSurface,
        ids: Vec<Idx>,
    ) -> Result<GluingView<'a>, SmoothError> {
        let ids = ids.into_iter().map(CornerId).collect();
        Ok(Box::new(SigmaVView::new(&self.gluing, ids, Version::Fixed)))
    }
}
