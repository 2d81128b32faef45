//! The samples of the sampled checkers: the seeded generators (one stream per checker) and K
//! as the samplers see it.

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
