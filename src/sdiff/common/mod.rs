//! What the planar and the tetrahedral engines share and what holds for any m: exact
//! rationals ([`rational`]), the bivariate polynomials and their exact positivity decision
//! ([`poly2`], [`positivity`]; the tetrahedral checks decide g′ > 0 on [0, 1] with them), the
//! g's of Eq. (9) ([`poly1`]), the parameter-file format of either dimension ([`params`]), the
//! interval routes' verdict ([`interval`]), polynomials on the m-simplex and the claim search
//! of L146 in any dimension, and exact homogeneous linear systems over ℚ.

pub(crate) mod complex;
pub(crate) mod decide;
pub mod interval;
pub mod linsys;
pub mod params;
pub mod poly1;
pub mod poly2;
pub mod positivity;
pub mod rational;
pub mod simplex_poly;
pub mod simplex_search;
