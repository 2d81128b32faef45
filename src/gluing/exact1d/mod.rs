//! The exact 1-D backend: gluing data in ℝ¹ with rational interval endpoints
//! and piecewise-affine transition maps, where every condition of Def. 3.4.1 is decided.

pub mod data;
pub mod decide;
pub mod interval;
pub mod random;
pub(crate) mod sampled_view;

pub use data::{Adjacency, Exact1d, Piece};
pub use interval::{Interval, OpenSet, Q};
