//! The bottom floor: small numeric and combinatorial tools every layer uses, written once.
//! (The scalar types of Chapter 4 still live in `construction`; see docs/architecture.md.)

pub mod union_find;
pub mod vec3;

pub use union_find::UnionFind;

/// An exact rational number (the exact backends: 1-D gluing data, Appendix A.1 replays, seeds
/// 003 and 004).
pub type Q = num_rational::BigRational;
