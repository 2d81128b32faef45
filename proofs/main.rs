//! The proofs test binary (proofs/README.md): the exact replays of Appendix A.1 and Sec. 6.1.4
//! and the bounded-exhaustive harnesses of the combinatorial core. One binary, not one per
//! file: each test binary links the whole crate and instantiates its generic code again.

mod support;

mod appendix_a1;
mod combinatorial;
mod eval_c6_1_4;
