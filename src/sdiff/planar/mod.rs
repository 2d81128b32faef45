//! The planar case (m = 2) of Mello–Velho: triangle complexes with boundary and the maps on
//! them (SPEC rows `SD-…`).
//!
//! Entry points: [`complex::validate`] (a planar complex with boundary), [`params::read`] and
//! [`params::MapSpec::build`] (the map), [`checks::check_all`], [`iso::isocurves`], and the
//! seeded claim searches of [`claims`].

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
pub mod maps;
pub mod normals;
pub mod objectives;
pub mod optimise;
pub mod params;
pub mod polygonize;
pub mod refine;
pub mod refine_optimise;
pub mod subdivide;
