//! A diverging colour map centred at 0 (blue < 0 < red, white at 0, as in the curvature plots
//! of Figs. 6.4–6.7) over a range [lo, hi] ∋ 0 that is either the user's or robust: the
//! 2nd and 98th percentiles of the finite values, widened to contain 0.

use super::error::RenderError;
use serde::Serialize;

/// What the surface is coloured by.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum ColourBy {
    /// Gaussian curvature K.
    Gaussian,
    /// Mean curvature H.
    Mean,
    /// Plain grey.
    None,
}

impl ColourBy {
    /// Parse `gaussian | mean | none`.
    pub fn parse(s: &str) -> Option<ColourBy> {
        match s {
            "gaussian" => Some(ColourBy::Gaussian),
            "mean" => Some(ColourBy::Mean),
            "none" => Some(ColourBy::None),
            _ => None,
        }
    }
    /// The name used on the command line and in captions.
    pub fn name(self) -> &'static str {
        match self {
            ColourBy::Gaussian => "gaussian",
            ColourBy::Mean => "mean",
            ColourBy::None => "none",
        }
    }
}

/// Where a colour range came from.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum RangeSource {
    /// Given by the user (`--range a,b`).
    User,
    /// The `lo`-th and `hi`-th percentiles of the finite values, widened to contain 0.
    Percentiles {
        /// Lower percentile.
        lo: f64,
        /// Upper percentile.
        hi: f64,
        /// Number of finite values they were taken over.
        count: usize,
    },
}

/// The range [lo, hi] (lo ≤ 0 ≤ hi) mapped onto the colour map; values outside it take the end
/// colours and are counted in the render report.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ColourRange {
    /// Value drawn in full blue.
    pub lo: f64,
    /// Value drawn in full red.
    pub hi: f64,
    /// Where the range came from.
    pub source: RangeSource,
}

/// The percentiles used for the robust range.
pub(crate) const ROBUST_PERCENTILES: (f64, f64) = (2.0, 98.0);

impl ColourRange {
    /// Parse `--range a,b` (finite, a ≤ 0 ≤ b, a < b).
    pub fn parse(s: &str) -> Result<ColourRange, RenderError> {
        let v: Vec<f64> = s
            .split(',')
            .map(|x| x.trim().parse::<f64>())
            .collect::<Result<_, _>>()
            .map_err(|_| RenderError::BadRange(s.into()))?;
        match v.as_slice() {
            [a, b] if a.is_finite() && b.is_finite() && *a <= 0.0 && *b >= 0.0 && a < b => {
                Ok(ColourRange {
                    lo: *a,
                    hi: *b,
                    source: RangeSource::User,
                })
            }
            _ => Err(RenderError::BadRange(s.into())),
        }
    }

    /// The robust range of `values` ([`ROBUST_PERCENTILES`], nearest rank), or None when no
    /// value is finite.
    pub(crate) fn robust<'a>(values: impl IntoIterator<Item = &'a f64>) -> Option<ColourRange> {
        let mut v: Vec<f64> = values
            .into_iter()
            .copied()
            .filter(|x| x.is_finite())
            .collect();
        if v.is_empty() {
            return None;
        }
        v.sort_by(f64::total_cmp);
        let at = |p: f64| v[((v.len() - 1) as f64 * p / 100.0).round() as usize];
        let (pl, ph) = ROBUST_PERCENTILES;
        Some(ColourRange {
            lo: at(pl).min(0.0),
            hi: at(ph).max(0.0),
            source: RangeSource::Percentiles {
                lo: pl,
                hi: ph,
                count: v.len(),
            },
        })
    }

    /// Position in [−1, 1] of x (0 ↦ 0), and whether x was outside the range. NaN ↦ None.
    pub fn position(&self, x: f64) -> Option<(f64, bool)> {
        if x.is_nan() {
            return None;
        }
        let t = if x > 0.0 {
            if self.hi > 0.0 {
                x / self.hi
            } else {
                f64::INFINITY
            }
        } else if x < 0.0 {
            if self.lo < 0.0 {
                x / -self.lo
            } else {
                f64::NEG_INFINITY
            }
        } else {
            0.0
        };
        Some((t.clamp(-1.0, 1.0), !(-1.0..=1.0).contains(&t)))
    }
}

/// Colour of undefined values (NaN curvature at a singular point).
pub(crate) const UNDEFINED: [f64; 3] = [0.5, 0.5, 0.5];
/// Colour of a surface drawn with `--colour none`.
pub(crate) const PLAIN: [f64; 3] = [0.8, 0.8, 0.8];

const BLUE: [f64; 3] = [0.13, 0.40, 0.67];
const WHITE: [f64; 3] = [0.97, 0.97, 0.97];
const RED: [f64; 3] = [0.70, 0.09, 0.17];

/// The diverging map at t ∈ [−1, 1]: BLUE at −1, WHITE at 0, RED at 1 (linear in RGB).
pub(crate) fn diverging(t: f64) -> [f64; 3] {
    let (end, s) = if t >= 0.0 { (RED, t) } else { (BLUE, -t) };
    std::array::from_fn(|d| WHITE[d] + s * (end[d] - WHITE[d]))
}
