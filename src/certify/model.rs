//! The construction under test: the paper's, or one with a planted fault.

use super::interval;
use super::interval::c;
use crate::construction::maps::{self, cos_pi_6, is_nonzero, EdgeConfig, Ppm, P2};
use crate::numeric::interval::Interval as I;
use crate::numeric::{Scalar, Trit};
use serde::{Deserialize, Serialize};

// ---------------------------------------------------------------------------------------------
// Models (the paper, and planted faults).
// ---------------------------------------------------------------------------------------------

/// The construction under test: the paper's, or one with a planted fault.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Model {
    /// Added to the radius cos(π/6) of the circles of the Sec. 6.1.3 lens test.
    pub lens_radius_offset: f64,
    /// Added to the label in R_(u,w)⁻¹ (a wrong rotation label in g_(u,w), Def. 4.1.8).
    pub label_shift: i64,
    /// A planted evaluation fault of g_v⁻¹ (Def. 4.1.6), hence of every transition map the
    /// provers evaluate at box centres (SPEC `X-planted-certify`); `None` in the paper's model.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub fault: Option<EvalFault>,
}

/// A planted evaluation fault of the model's g_v⁻¹.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum EvalFault {
    /// g_v⁻¹ returns NaN coordinates (with a point interval: the empty/NaN enclosure).
    Nan,
    /// g_v⁻¹ returns an error (`MapError::NotInDomain`) everywhere.
    Error,
}

impl Model {
    /// The paper's construction, no fault planted.
    pub fn paper() -> Model {
        Model {
            lens_radius_offset: 0.0,
            label_shift: 0,
            fault: None,
        }
    }
    /// True when no fault is planted.
    pub fn is_paper(&self) -> bool {
        *self == Model::paper()
    }
    /// `paper`, or `planted(…)` with the fault parameters; recorded in certificates.
    pub fn name(&self) -> String {
        if self.is_paper() {
            "paper".into()
        } else {
            let fault = match self.fault {
                None => String::new(),
                Some(f) => format!(", fault={f:?}"),
            };
            format!(
                "planted(lens_radius_offset={}, label_shift={}{fault})",
                self.lens_radius_offset, self.label_shift
            )
        }
    }
    /// Enclosure of the squared lens radius.
    pub(super) fn lens_r2(&self) -> I {
        if self.lens_radius_offset == 0.0 {
            interval::ratio(3, 4)
        } else {
            (c(3.0).sqrt() / c(2.0) + c(self.lens_radius_offset)).sqr()
        }
    }
}

impl<S: Scalar> Ppm<S> for Model {
    fn in_canonical_lens(&self, q: &P2<S>) -> Trit {
        if self.lens_radius_offset == 0.0 {
            return maps::in_canonical_lens(q);
        }
        let prec = q.prec();
        let rr = cos_pi_6::<S>(prec)
            .add(&S::from_f64(self.lens_radius_offset, prec))
            .sqr();
        let d = P2::new(q.x.sub(&S::from_i64(1, prec)), q.y.clone());
        q.norm2()
            .lt(&rr)
            .and(d.norm2().lt(&rr))
            .and(is_nonzero(q))
            .and(is_nonzero(&d))
    }
    fn g_v_inv(&self, m: u32, q: &P2<S>) -> Result<P2<S>, maps::MapError> {
        match self.fault {
            None => maps::g_v_inv(m, q),
            Some(EvalFault::Nan) => Ok(P2::new(q.x.like_f64(f64::NAN), q.y.like_f64(f64::NAN))),
            Some(EvalFault::Error) => Err(maps::MapError::NotInDomain("planted: g_v⁻¹ fails")),
        }
    }
    fn r_uw_inv(&self, e: &EdgeConfig, p: &P2<S>) -> P2<S> {
        maps::rotate_frac(p, e.i as i64 + self.label_shift, e.m_u as i64)
    }
}
