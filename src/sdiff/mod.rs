//! Simplicial diffeomorphisms (Mello–Velho, seed 004): K-invariant maps of a simplicial
//! complex — monotonic (Eq. (9)), polynomial (Eq. (10)) and rational (Eq. (11)) — and the
//! exact decision of their central claims: det DX > 0 on every closed simplex by Bernstein
//! coefficients over ℚ (independently by intervals), K-invariance and agreement on shared
//! faces as polynomial identities, and the curved isocomplexes 𝒪 = X⁻¹(f̂⁻¹(c)) of Sec. 4.
//!
//! The paper works in ℝ^m; the code has one engine per dimension, because the exact
//! polynomials (bivariate on the triangle, trivariate on the tetrahedron) are different types:
//!
//! - [`planar`] (m = 2, SPEC rows `SD-…`): planar complexes with boundary, the maps on them,
//!   the checks of Secs. 2–3, isocurves (Sec. 4), the C¹ conditions (Sec. 5) and the
//!   polygonizer of Sec. 6;
//! - [`tet`] (m = 3, rows `SD-…(3-D)`): tetrahedral complexes read from `.tets`
//!   (docs/sdiff-3d.md), the maps, the checks and isosurfaces;
//! - [`common`]: what does not depend on m (polynomials on the m-simplex, the claim searches
//!   of L146 in any dimension, exact linear systems).

pub mod common;
pub mod planar;
pub mod tet;
