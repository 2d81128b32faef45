//! Simplicial diffeomorphisms (Mello–Velho, seed 004): K-invariant maps of a planar triangle
//! complex — monotonic (Eq. (9)), polynomial (Eq. (10)) and rational (Eq. (11)) — and the
//! exact decision of their central claims: det DX > 0 on every closed simplex by Bernstein
//! coefficients over ℚ (independently by intervals), K-invariance and agreement on shared
//! faces as polynomial identities, and the curved isocurves 𝒪 = X⁻¹(f̂⁻¹(c)) of Sec. 4.
//!
//! Entry points: [`complex::validate`] (a planar complex with boundary), [`params::read`] and
//! [`params::MapSpec::build`] (the map), [`checks::check_all`], [`iso::isocurves`], and the
//! seeded claim searches of [`claims`]. SPEC IDs: `SD-…`.
//!
//! 3-D (m = 3, tetrahedral complexes with boundary, rows `SD-…(3-D)`): [`tet_complex::read`] and
//! [`tet_complex::validate`] (the `.tets` format, docs/sdiff-3d.md), [`tet_params::read`] and
//! [`tet_params::MapSpec3::build`], [`tet_checks::check_all3`] (exact, and the interval route of
//! [`tet_interval`]), [`tet_iso::isosurfaces`], and the rational search of [`tet_search`].

pub mod c1;
pub mod checks;
pub mod claims;
pub mod complex;
pub mod edge;
pub mod handles;
pub mod implicit;
pub mod interval;
pub mod inverse;
pub mod iso;
pub mod linsys;
pub mod maps;
pub mod normals;
pub mod objectives;
pub mod optimise;
pub mod params;
pub mod poly;
pub mod polygonize;
pub mod positivity;
pub mod refine;
pub mod refine_optimise;
pub mod simplex_poly;
pub mod simplex_search;
pub mod subdivide;
pub mod tet;
pub mod tet_checks;
pub mod tet_complex;
pub mod tet_interval;
pub mod tet_iso;
pub mod tet_maps;
pub mod tet_params;
pub mod tet_search;
