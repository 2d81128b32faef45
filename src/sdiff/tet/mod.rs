//! The tetrahedral case (m = 3) of Mello–Velho: tetrahedral complexes with boundary and the
//! maps on them (SPEC rows `SD-…(3-D)`).
//!
//! Entry points: [`file::read`] and [`complex::validate`] (the `.tets` format,
//! docs/sdiff-3d.md), [`params::read`] and [`params::MapSpec3::build`],
//! [`checks::check_all3`] (exact, and the interval route of [`interval`]),
//! [`iso::isosurfaces`], the monotonic family of [`poly`] and the rational search of
//! [`search`].

pub mod checks;
pub mod complex;
pub mod file;
pub mod interval;
pub mod iso;
pub mod maps;
pub mod params;
pub mod poly;
pub mod search;
