//! CERT-f64-g-chart: proven bounds on the rounding of g_v and g_v⁻¹ (Def. 4.1.6) in `f64`
//! on the whole chart square |x|, |y| ≤ [`G_CHART_RADIUS`], per vertex degree m — every point
//! the oracle's `g` and `g_inv` queries accept there, not only those φ_wu feeds them (which
//! `F64Rounding::g_v`, `g_v_inv` bound: the label-0 sector of Ω_uw and the canonical lens).
//!
//! ## The argument
//! The query point is an exact `f64` input, so [`Fe`] run over a Cartesian box of inputs
//! encloses |ĝ(p) − g(p)| for every `f64` point p of the box (no input error to propagate, no
//! Jacobian needed). Π (Def. 4.1.5) branches on the signs of x and y, and [`Fe`] decides a
//! branch only when every point of the box takes it, so every box is cut into the pieces
//! where the `f64` inputs take one branch (η = 2⁻¹⁰⁷⁴, the smallest positive `f64`):
//! x ≥ η (atan2); x ≤ 0, y ≥ η and x ≤ 0, y ≤ −η (atan2); x ≤ −η, y = 0 (θ = π); the origin
//! is refused by both evaluators (`MapError::AtOrigin`), so it has no answer to bound.
//! Signed zeros: −0 lies in the pieces as +0 does (the code compares with 0).
//!
//! The boxes are an 8 × 8 grid aligned with the axes; the pieces not next to the origin give
//! the target (their largest bound); a piece above it (the ones touching the origin, where
//! the enclosure of √(x² + y²) loses its relative accuracy, and any refused piece) is bisected
//! until it is below, within a budget and a minimum diameter, down to the core square
//! |x|, |y| ≤ 2⁻⁶⁴, bounded in closed form ([`CORE_BOUND`] = 2⁻⁶⁰); what is left is counted
//! as unresolved and the bound is then not claimed for the whole square.

use super::interval::{c, iv};
use super::result::GChartRounding;
use crate::construction::maps::P2;
use crate::construction::maps::{g_v, g_v_inv, MapError};
use crate::numeric::rounding::{Glibc, LibmModel, LIBM_ULPS};
use crate::numeric::Fe;
use crate::report::dev_max;
use std::time::Instant;

/// The chart square |x|, |y| ≤ this is covered. It contains the disk of radius 1, so Ω_v
/// (radius cos(π/m) < 1, Def. 4.1.1) for `g` and g_v(Ω_v) (radius cos(π/6)) for `g_inv`.
pub const G_CHART_RADIUS: f64 = 1.0;

/// The smallest positive `f64` (2⁻¹⁰⁷⁴): the first `f64` off an axis.
const ETA: f64 = 5e-324;

/// The core square |x|, |y| ≤ 2⁻⁶⁴ around the origin, where `Fe` cannot bound √(x² + y²)
/// (the exact x² + y² is not bounded away from 0, so the `f64` sum's enclosure reaches below 0).
const CORE: f64 = 1.0 / 18_446_744_073_709_551_616.0;

/// |ĝ(p) − g(p)| ≤ |ĝ(p)| + |g(p)| < 2⁻⁶⁰ on the core, by monotone rounding alone: fl(x²),
/// fl(y²) ≤ 2⁻¹²⁸ (representable), their sum ≤ 2⁻¹²⁷, its √ ≤ 2⁻⁶³; the radial factor
/// (cos(π/6)/cos(π/m) ∈ [0.86, 1.74], or its reciprocal for g_v⁻¹) keeps it ≤ 2⁻⁶²; `f64`
/// sin and cos are at most 1 + 4u ≤ 2 in magnitude (2 ulp), so each coordinate of ĝ(p) is
/// ≤ 2⁻⁶¹ and |ĝ(p)| ≤ √2·2⁻⁶¹; |g(p)| ≤ 1.74·|p| ≤ 1.74·√2·2⁻⁶⁴.
const CORE_BOUND: f64 = 1.0 / 1_152_921_504_606_846_976.0;

/// Pieces evaluated at most per map and degree.
const G_CHART_BUDGET: u64 = 20_000;

/// Pieces are not bisected below this diameter (below the core's, which the pieces next to
/// the origin must reach).
const G_CHART_MIN_DIAM: f64 = CORE / 4.0;

/// A box of `f64` inputs [x0, x1] × [y0, y1] on which Π takes one branch.
#[derive(Debug, Clone, Copy)]
struct Piece {
    x: (f64, f64),
    y: (f64, f64),
}

impl Piece {
    /// Inside the core square |x|, |y| ≤ [`CORE`] (bounded by [`CORE_BOUND`]).
    fn in_core(&self) -> bool {
        [self.x.0, self.x.1, self.y.0, self.y.1]
            .iter()
            .all(|t| t.abs() <= CORE)
    }
    fn diam(&self) -> f64 {
        (self.x.1 - self.x.0).hypot(self.y.1 - self.y.0)
    }
    /// The distance of the piece from the origin.
    fn min_dist(&self) -> f64 {
        let mig = |(a, b): (f64, f64)| {
            if a <= 0.0 && b >= 0.0 {
                0.0
            } else {
                a.abs().min(b.abs())
            }
        };
        mig(self.x).hypot(mig(self.y))
    }
    /// Halves along the longer side (a piece with y = 0 only along x).
    fn split(&self) -> [Piece; 2] {
        if self.x.1 - self.x.0 >= self.y.1 - self.y.0 {
            let m = 0.5 * (self.x.0 + self.x.1);
            [
                Piece {
                    x: (self.x.0, m),
                    ..*self
                },
                Piece {
                    x: (m, self.x.1),
                    ..*self
                },
            ]
        } else {
            let m = 0.5 * (self.y.0 + self.y.1);
            [
                Piece {
                    y: (self.y.0, m),
                    ..*self
                },
                Piece {
                    y: (m, self.y.1),
                    ..*self
                },
            ]
        }
    }
}

/// The pieces of the box [x0, x1] × [y0, y1] (not crossing an axis) on which Π takes one
/// branch for every `f64` input (module docs).
fn pieces(x: (f64, f64), y: (f64, f64)) -> Vec<Piece> {
    let mut v = Vec::new();
    if x.1 > 0.0 {
        v.push(Piece {
            x: (x.0.max(ETA), x.1),
            y,
        });
    }
    if x.0 <= 0.0 {
        let xl = (x.0, x.1.min(0.0));
        if y.1 > 0.0 {
            v.push(Piece {
                x: xl,
                y: (y.0.max(ETA), y.1),
            });
        }
        if y.0 < 0.0 {
            v.push(Piece {
                x: xl,
                y: (y.0, y.1.min(-ETA)),
            });
        }
        if x.0 < 0.0 && y.0 <= 0.0 && y.1 >= 0.0 {
            v.push(Piece {
                x: (x.0, x.1.min(-ETA)),
                y: (0.0, 0.0),
            });
        }
    }
    v
}

/// The Euclidean `f64` error of the map on the piece (`None`: refused or not finite).
fn piece_bound<L: LibmModel>(
    map: &impl Fn(&P2<Fe<L>>) -> Result<P2<Fe<L>>, MapError>,
    p: &Piece,
) -> Option<f64> {
    let q = map(&P2::new(
        Fe::exact(iv(p.x.0, p.x.1)),
        Fe::exact(iv(p.y.0, p.y.1)),
    ))
    .ok()?;
    let (ex, ey) = (c(q.x.err()), c(q.y.err()));
    let e = (ex.sqr() + ey.sqr()).sqrt().sup();
    e.is_finite().then_some(e)
}

/// The bound of one map on the square of half-side `radius` (module docs): (bound, pieces
/// evaluated, pieces left unbounded).
fn chart_bound<L: LibmModel>(
    map: impl Fn(&P2<Fe<L>>) -> Result<P2<Fe<L>>, MapError>,
    radius: f64,
) -> (Option<f64>, u64, u64) {
    const N: usize = 8;
    let h = 2.0 * radius / N as f64;
    let at = |i: usize| -radius + h * i as f64;
    let mut grid = Vec::new();
    for i in 0..N {
        for j in 0..N {
            grid.extend(pieces((at(i), at(i + 1)), (at(j), at(j + 1))));
        }
    }
    let mut evaluated = grid.len() as u64;
    let mut bound: Option<f64> = None;
    let mut target = 0.0f64;
    let mut stack = Vec::new();
    for p in grid {
        match piece_bound(&map, &p) {
            Some(e) if p.min_dist() >= 0.5 * h => {
                target = dev_max(target, e);
                bound = Some(bound.map_or(e, |b| dev_max(b, e)));
            }
            _ => stack.push(p),
        }
    }
    let mut unresolved = 0u64;
    while let Some(p) = stack.pop() {
        let e = piece_bound(&map, &p);
        evaluated += 1;
        match e {
            Some(e) if e <= target => bound = Some(bound.map_or(e, |b| dev_max(b, e))),
            _ if p.in_core() => bound = Some(bound.map_or(CORE_BOUND, |b| dev_max(b, CORE_BOUND))),
            _ if p.diam() <= G_CHART_MIN_DIAM || evaluated >= G_CHART_BUDGET => unresolved += 1,
            _ => stack.extend(p.split()),
        }
    }
    (
        if unresolved == 0 { bound } else { None },
        evaluated,
        unresolved,
    )
}

/// CERT-f64-g-chart for degree m with the libm model `L` on the square of half-side `radius`.
pub fn prove_g_chart_with<L: LibmModel>(m: u32, radius: f64) -> GChartRounding {
    let t0 = Instant::now();
    let (g, bg, ug) = chart_bound::<L>(|p| g_v(m, p), radius);
    let (gi, bi, ui) = chart_bound::<L>(|p| g_v_inv(m, p), radius);
    GChartRounding {
        radius,
        g_v: g,
        g_v_inv: gi,
        boxes: bg + bi,
        unresolved: ug + ui,
        libm_ulps: L::LIBM_ULPS,
        millis: t0.elapsed().as_millis() as u64,
    }
}

/// CERT-f64-g-chart for degree m with the certificates' libm model, on |x|, |y| ≤ 1.
pub fn prove_g_chart(m: u32) -> GChartRounding {
    debug_assert_eq!(Glibc::LIBM_ULPS, LIBM_ULPS);
    prove_g_chart_with::<Glibc>(m, G_CHART_RADIUS)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cert_f64_g_chart_pieces_cover_every_f64_point_but_the_origin() {
        // Each f64 point of a box lies in exactly one piece.
        let samples = [-0.5, -ETA, -0.0, 0.0, ETA, 0.25, 0.5];
        for (x, y) in [((-0.5, 0.0), (0.0, 0.5)), ((0.0, 0.5), (-0.5, 0.0))] {
            let ps = pieces(x, y);
            for &a in samples.iter().filter(|&&a| a >= x.0 && a <= x.1) {
                for &b in samples.iter().filter(|&&b| b >= y.0 && b <= y.1) {
                    let n = ps
                        .iter()
                        .filter(|p| a >= p.x.0 && a <= p.x.1 && b >= p.y.0 && b <= p.y.1)
                        .count();
                    assert_eq!(n, usize::from(a != 0.0 || b != 0.0), "({a}, {b}) in {ps:?}");
                }
            }
        }
    }

    #[test]
    fn cert_f64_g_chart_bounded_with_no_unresolved_piece() {
        for m in [3u32, 6, 7, 32] {
            let g = prove_g_chart(m);
            assert_eq!(g.unresolved, 0, "{g:?}");
            let (a, b) = (g.g_v.expect("bounded"), g.g_v_inv.expect("bounded"));
            assert!(a > 1e-17 && a < 1e-13 && b > 1e-17 && b < 1e-13, "{g:?}");
        }
    }
}
