//! Per-degree constants of Chapters 4–5 in a scalar `S`, computed once at the precision in
//! use (so an [`crate::numeric::Mp`] evaluation uses 256-bit constants, not rounded f64).

use super::scalar_ext::SurfaceScalar;
use super::weights::XiConsts;
use crate::construction::maps::{cos_pi_6, omega_radius};

/// Constants for one degree m.
#[derive(Clone, Debug)]
pub struct DegreeConsts<S> {
    /// The degree m.
    pub m: u32,
    /// cos(π/m): the radius of Ω_v (Def. 4.1.1).
    pub radius: S,
    /// cos(π/6)/cos(π/m): the radial factor of f_v (Def. 4.1.6).
    pub radial: S,
    /// m/6 and 6/m: the angular factors of f_v and f_v⁻¹.
    pub ang: S,
    /// 6/m: the angular factor of f_v⁻¹.
    pub ang_inv: S,
    /// 6π/m: g_v is injective on {|θ| < min(π, 6π/m)} (SPEC `C4.1.6-gv-bijective`).
    pub branch: S,
    /// (cos 2πi/m, sin 2πi/m), i = 0..m: R_(v,u) and its inverse (Def. 4.1.8).
    pub rot: Vec<(S, S)>,
    /// ξ's H₁, H₂ (Def. 5.3.2).
    pub xi: XiConsts<S>,
}

/// Constants for every degree up to a maximum, plus the global ones.
#[derive(Clone, Debug)]
pub struct Consts<S> {
    /// Precision (bits) the constants were computed at.
    pub prec: u32,
    /// Indexed by degree; `None` for degrees not requested.
    pub by_degree: Vec<Option<DegreeConsts<S>>>,
    /// 3/4 = cos²(π/6): the squared radius of C, D, E (Sec. 6.1.4).
    pub c_sq: S,
    /// √3/2.
    pub s3h: S,
    /// π.
    pub pi: S,
}

impl<S: SurfaceScalar> Consts<S> {
    /// Build for the given degrees (others left empty).
    pub fn new(degrees: impl IntoIterator<Item = u32>, prec: u32) -> Self {
        let mut by_degree: Vec<Option<DegreeConsts<S>>> = Vec::new();
        let pi = S::pi(prec);
        for m in degrees {
            if m < 3 {
                continue;
            }
            let mi = m as usize;
            if by_degree.len() <= mi {
                by_degree.resize(mi + 1, None);
            }
            if by_degree[mi].is_some() {
                continue;
            }
            let radius = omega_radius::<S>(m, prec);
            let radial = cos_pi_6::<S>(prec).div(&radius);
            let rot = (0..m)
                .map(|i| {
                    let a = pi.mul(&S::from_ratio(2 * i as i64, m as i64, prec));
                    (a.cos(), a.sin())
                })
                .collect();
            by_degree[mi] = Some(DegreeConsts {
                m,
                radius,
                radial,
                ang: S::from_ratio(m as i64, 6, prec),
                ang_inv: S::from_ratio(6, m as i64, prec),
                branch: pi.mul(&S::from_ratio(6, m as i64, prec)),
                rot,
                xi: XiConsts::for_degree(m, prec),
            });
        }
        Consts {
            prec,
            by_degree,
            c_sq: S::from_ratio(3, 4, prec),
            s3h: cos_pi_6::<S>(prec),
            pi,
        }
    }

    /// The constants of degree m, if built.
    pub fn degree(&self, m: u32) -> Option<&DegreeConsts<S>> {
        self.by_degree.get(m as usize).and_then(|d| d.as_ref())
    }
}
