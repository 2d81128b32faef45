//! Sampled checkers for Def. 3.4.1, valid for any [`GluingData`] implementor. They cannot prove
//! a condition, only refute it: a `holds` verdict means "on every sample" (count and seed are in
//! the result); a `FAILS` verdict always carries a concrete witness.

pub(crate) mod cocycle;
pub(crate) mod domains;
pub mod hausdorff;
mod sampling;

pub use cocycle::{check_3a, check_3b, check_3c, check_grimm_hughes, check_maps_into};
pub use domains::{check_1, check_2};
pub use hausdorff::check_4;
pub use sampling::{sampled_k, SampleConfig};

use crate::gluing::data::GluingData;

/// Run every sampled checker of Def. 3.4.1 and the Grimm–Hughes variants of App. A.2.
pub fn check_all<G: GluingData<N>, const N: usize>(
    g: &G,
    cfg: &SampleConfig,
) -> Vec<crate::report::CheckResult> {
    vec![
        check_1(g, cfg),
        check_2(g, cfg),
        check_maps_into(g, cfg),
        check_3a(g, cfg),
        check_3b(g, cfg),
        check_3c(g, cfg),
        check_grimm_hughes(g, cfg, false),
        check_grimm_hughes(g, cfg, true),
        check_4(g, cfg),
    ]
}
