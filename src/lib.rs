//! # pseudomanifold
//!
//! A formal-verification-oriented reference implementation of the *parametric pseudo-manifold*
//! (PPM) construction of Siqueira, Xu and Gallier ("A New Construction of Smooth Surfaces from
//! Triangle Meshes Using Parametric Pseudo-Manifolds", tech report).
//!
//! The module layout mirrors the paper, and data flows one way:
//! mesh (Sec. 3.1) → gluing data (Secs. 3.4–3.5 abstract, Ch. 4 concrete) → parametrizations
//! (Ch. 5, Sec. 6.1.4) → reports.
//!
//! * [`mesh`] — Sec. 3.1: reading triangle meshes, validating them as simplicial surfaces
//!   (Defs. 3.1.1–3.1.7), and the half-edge structure of Sec. 6.1.1 with the labelling s_v of
//!   Sec. 6.1.2 / Def. 4.1.4.
//! * [`gluing`] — Secs. 3.2–3.5: abstract sets of gluing data and their checkers.
//! * [`construction`] — Ch. 4: the PPM gluing data built from a simplicial surface.
//! * [`surface`] — Ch. 5 and Sec. 6.1.4: shape functions, weights, parametrizations.
//! * [`conditions`] — the conformance checkers and their reports.
//! * [`cli`] — the `ppm` command line.

#![warn(missing_docs)]

pub mod certify;
pub mod cli;
pub mod conditions;
pub mod construction;
pub mod exact;
pub mod gluing;
pub mod mesh;
pub mod msplines;
pub mod oracle;
pub mod report;
pub mod sdiff;
pub mod surface;
