//! The report's vertex-indexed PPS (Defs. 5.4.1–5.4.2, eval of Sec. 6.1.4) as a
//! [`SmoothSurface`].

use super::{ChartAt, FitSummary, GluingView, Located, MpConsts, SmoothError, SmoothSurface};
use crate::construction::abstract_view::AbstractPpm;
use crate::construction::PpmGluing;
use crate::gluing::data::Idx;
use crate::mesh::{FaceId, SimplicialSurface, VertexId};
use crate::numeric::{Mp, Scalar};
use crate::report::Progress;
use crate::surface::eval_bound::BoundedPoint;
use crate::surface::geometry::SurfacePoint;
use crate::surface::jet::Jet;
use crate::surface::output::{sample_surface_with, Attributes, SampledMesh};
use crate::surface::{Consts, EvalPoint, Pps};

const NAME: &str = "the vertex-indexed PPS";

/// eval's answer as the trait gives it: the point, Ω_vertex's chart and q.
fn located<S>(e: EvalPoint<S>) -> Located<S> {
    Located {
        point: e.point,
        chart: Some(ChartAt::Vertex {
            chart: e.chart,
            vertex: e.vertex,
            q: [e.q.x, e.q.y],
        }),
    }
}

impl SmoothSurface for Pps {
    fn name(&self) -> String {
        format!(
            "the vertex-indexed PPS (Ch. 4–5; profile {}, S′ = {})",
            self.options.profile.name(),
            self.target_name()
        )
    }

    fn fit_summary(&self) -> Vec<FitSummary> {
        self.fit_info()
            .iter()
            .map(|f| FitSummary {
                m: f.m,
                l: Some(f.l),
                rows: f.rows,
                unknowns: f.unknowns,
                rank: f.rank,
                condition: f.condition,
            })
            .collect()
    }

    fn face_corners(&self) -> Result<Vec<[VertexId; 3]>, SmoothError> {
        Ok((0..self.num_faces())
            .map(|f| self.face(FaceId(f as u32)))
            .collect::<Result<_, _>>()?)
    }

    fn eval_f64(&self, f: FaceId, bary: [f64; 3]) -> Result<[f64; 3], SmoothError> {
        Ok(Pps::eval_f64(self, f, bary)?)
    }

    /// The bound of `surface::eval_bound` (SPEC `R-diff-f64-bound`).
    fn eval_bounded(
        &self,
        f: FaceId,
        bary: [f64; 3],
    ) -> Result<([f64; 3], Option<BoundedPoint>), SmoothError> {
        let b = self.eval_f64_bounded(f, bary)?;
        Ok((b.point, Some(b)))
    }

    fn eval_located(&self, f: FaceId, bary: [f64; 3]) -> Result<Located<f64>, SmoothError> {
        Ok(located(self.eval(f, &bary, self.consts_f64())?))
    }

    fn mp_consts(&self, bits: u32) -> Result<MpConsts, SmoothError> {
        Ok(MpConsts::new(bits, self.consts::<Mp>(bits)))
    }

    fn eval_mp(&self, c: &MpConsts, f: FaceId, bary: [f64; 3]) -> Result<Located<Mp>, SmoothError> {
        let cm: &Consts<Mp> = c
            .get()
            .ok_or(SmoothError::ForeignConsts { surface: NAME })?;
        let bm = bary.map(|x| Mp::from_f64(x, c.bits()));
        Ok(located(self.eval(f, &bm, cm)?))
    }

    fn eval_geometry(&self, f: FaceId, bary: [f64; 3]) -> Result<SurfacePoint, SmoothError> {
        let cj: Consts<Jet<f64>> = self.consts(53);
        Ok(Pps::eval_geometry(self, f, bary, &cj)?.2)
    }

    fn sample(
        &self,
        level: u32,
        attrs: Attributes,
        progress: Progress,
    ) -> Result<SampledMesh, SmoothError> {
        Ok(sample_surface_with(self, level, attrs, progress)?)
    }

    /// Ch. 4's gluing data on K (Defs. 4.1.1, 4.1.9, 4.1.10; membership as Def. 4.1.9 states
    /// it), through `construction::abstract_view`: I is the set of vertices of K.
    fn gluing_view<'a>(
        &'a self,
        k: &'a SimplicialSurface,
        ids: Vec<Idx>,
    ) -> Result<GluingView<'a>, SmoothError> {
        let same = k.num_faces() == self.num_faces()
            && k.faces()
                .all(|f| self.face(f).is_ok_and(|c| c == k.face(f)));
        if !same {
            return Err(SmoothError::Unsupported {
                surface: NAME,
                what: "the Def. 3.4.1 view",
                why: "the mesh given is not the K the surface was built from",
            });
        }
        let ids = ids.into_iter().map(VertexId).collect();
        Ok(Box::new(AbstractPpm::new(PpmGluing::new(k), ids)))
    }
}
