//! Sampled checkers for Def. 3.4.1, valid for any [`GluingData`] implementor. They cannot prove
//! a condition, only refute it: a `holds` verdict means "on every sample" (count and seed are in
//! the result); a `FAILS` verdict always carries a concrete witness.

pub(crate) mod cocycle;
pub(crate) mod domains;
pub mod hausdorff;

pub use cocycle::{check_3a, check_3b, check_3c, check_grimm_hughes, check_maps_into};
pub use domains::{check_1, check_2};
pub use hausdorff::check_4;

use crate::gluing::data::{GluingData, Idx};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

/// Sampling parameters shared by the sampled checkers.
#[derive(Clone, Copy, Debug)]
pub struct SampleConfig {
    /// Seed of the ChaCha8 generator; every checker derives its own stream from it.
    pub seed: u64,
    /// Samples per domain.
    pub n: usize,
}

impl Default for SampleConfig {
    fn default() -> Self {
        SampleConfig {
            seed: 0x5eed,
            n: 200,
        }
    }
}

impl SampleConfig {
    /// A generator for checker number `stream`, so checkers do not share random streams.
    pub fn rng(&self, stream: u64) -> ChaCha8Rng {
        let mut r = ChaCha8Rng::seed_from_u64(self.seed);
        r.set_stream(stream);
        r
    }
}

/// K of Def. 3.4.1(3), as seen by the samplers: the pairs with a non-empty gluing domain.
pub fn sampled_k<G: GluingData<N>, const N: usize>(g: &G, cfg: &SampleConfig) -> Vec<(Idx, Idx)> {
    let mut rng = cfg.rng(99);
    let ids = g.indices();
    let mut k = Vec::new();
    for &i in &ids {
        for &j in &ids {
            if !g.sample_gluing_domain(i, j, &mut rng, 1).is_empty() {
                k.push((i, j));
            }
        }
    }
    k
}

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
