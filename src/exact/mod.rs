//! Exact replay machinery for the Appendix A.1 proofs and the Sec. 6.1.4 eval consistency
//! argument.
//!
//! * [`q3`] — the field Q(√3), exact;
//! * [`plane`] — points, affine maps (M_{kπ/3}, h of Def. 4.1.7), disks C, D, F, G over Q(√3);
//! * [`polar`] — polar-affine maps (rotations by rational multiples of π, g_v, g_v⁻¹ of
//!   Def. 4.1.6) with the exact wrap analysis of Π (Def. 4.1.5) over rational regions of θ/π;
//! * [`replay`] — proofs as lists of steps, each with an exact check and a recorded verdict.

pub mod plane;
pub mod polar;
pub mod q3;
pub mod replay;
