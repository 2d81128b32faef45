//! What the planar and the tetrahedral engines share and what holds for any m: exact
//! polynomials on the m-simplex and the claim search of L146 in any dimension, and exact
//! homogeneous linear systems over ℚ.

pub(crate) mod complex;
pub(crate) mod decide;
pub mod linsys;
pub mod simplex_poly;
pub mod simplex_search;
