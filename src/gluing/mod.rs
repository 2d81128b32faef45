//! Secs. 3.2–3.5: abstract sets of gluing data (Def. 3.4.1) and their checkers.
//!
//! * [`data`] — the [`GluingData`] trait (Def. 3.4.1), dimension- and scalar-generic.
//! * [`sampled`] — sampled checkers of every condition, for any implementor.
//! * [`exact1d`] — the exact 1-D backend (rational intervals, piecewise-affine maps) where every
//!   condition is decided.
//! * [`relation`] — the relation ∼ of the proof of Thm. 3.4.1 and the proof's Claim.
//! * [`ppm`] — Def. 3.5.1 (C), (C′), (C″) and Prop. 3.5.1.
//! * [`stereo`] — the stereographic atlas of Sⁿ of Sec. 3.3 (Def. 3.3.3) as gluing data.
//! * [`file`](mod@file), [`report`] — the TOML format of `ppm gluing FILE` and its report.
//!
//! Index convention, kept literally: Ω_ij ⊆ Ω_i, and φ_ji : Ω_ij → Ω_ji.

pub mod data;
pub(crate) mod error;
pub mod exact1d;
pub mod file;
pub mod ppm;
pub mod relation;
pub mod report;
pub mod sampled;
pub mod stereo;
pub(crate) mod tolerance;

pub use data::{GluingData, Idx, Point};
pub use error::GluingFileError;
