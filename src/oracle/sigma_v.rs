//! The oracle's answers for the tutorial's (σ, v)-indexed construction (`set_construction`
//! with `"sigma-v"`): eval(σ, λ, μ, ν) in f64 and MPFR (SPEC `SV-D13`), so that `ppm diff` on a
//! table can take either construction as the reference.

use crate::mesh::{FaceId, SimplicialSurface};
use crate::numeric::{Mp, Scalar};
use crate::surface::sigma_v::{SigmaVPps, SvConsts};
use crate::surface::PnTriangles;
use serde_json::{json, Value};

/// The (σ, v) state of a session: κ and, built on first use, the surface and MPFR constants.
#[derive(Debug, Clone)]
pub(crate) struct SigmaVOracle {
    /// κ of r_{v,σ}.
    pub kappa: f64,
    pps: Option<SigmaVPps>,
    mp: Option<SvConsts<Mp>>,
}

impl SigmaVOracle {
    /// A state with κ (validated when the surface is built).
    pub(crate) fn new(kappa: f64) -> Self {
        SigmaVOracle {
            kappa,
            pps: None,
            mp: None,
        }
    }

    /// Forget the surface (a new mesh was loaded).
    pub(crate) fn reset(&mut self) {
        self.pps = None;
        self.mp = None;
    }

    /// The surface of `k` (S′ = PN triangles, the default patch degree), built on first use.
    pub(crate) fn pps(&mut self, k: &SimplicialSurface) -> Result<&SigmaVPps, String> {
        if self.pps.is_none() {
            let pn = PnTriangles::new(k);
            let p = SigmaVPps::build(
                k,
                &pn,
                self.kappa,
                crate::surface::sigma_v::DEFAULT_PATCH_DEGREE,
            )
            .map_err(|e| e.to_string())?;
            self.pps = Some(p);
        }
        self.pps.as_ref().ok_or_else(|| "no surface".to_string())
    }

    /// eval in f64 and at `bits`: (f64 point or its error, MPFR point, info).
    #[allow(clippy::type_complexity)]
    pub(crate) fn eval(
        &mut self,
        k: &SimplicialSurface,
        face: u32,
        bary: [f64; 3],
        bits: u32,
    ) -> Result<(Result<Vec<f64>, String>, Vec<Mp>, Value), String> {
        self.pps(k)?;
        let pps = self.pps.as_ref().ok_or("no surface")?;
        if self.mp.as_ref().map_or(true, |c| c.wedges.prec != bits) {
            self.mp = Some(pps.consts::<Mp>(bits));
        }
        let cm = self.mp.as_ref().ok_or("no constants")?;
        let f = FaceId(face);
        let bm = bary.map(|x| Mp::from_f64(x, bits));
        let (corner, q, b) = pps.eval(f, &bm, cm).map_err(|e| e.to_string())?;
        let a = pps
            .eval_f64(f, bary)
            .map(|x| x.to_vec())
            .map_err(|e| e.to_string());
        let info = json!({
            "construction": "sigma-v",
            "kappa": self.kappa,
            "corner": {"v": corner.v.0, "k": corner.k},
            "q": [q.x.to_f64(), q.y.to_f64()],
        });
        Ok((a, b.to_vec(), info))
    }
}
