//! The configurations a certificate covers: an edge depends only on (m_u, m_w), a triangle on
//! (m_u, m_w, m_x, orientation), a star on m_x (after the rotations R_(u,w) of Def. 4.1.8).

use crate::construction::maps::{self, Corner, EdgeConfig, TriangleConfig};
use serde::{Deserialize, Serialize};

// ---------------------------------------------------------------------------------------------
// Configurations.
// ---------------------------------------------------------------------------------------------

/// A configuration: everything a Chapter 4 property depends on: after the rotations R_(u,w) of Def. 4.1.8 only degrees and orientation matter.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum ConfigKey {
    /// A vertex (star) of degree m: lens agreement, at most two overlaps, non-adjacent
    /// disjointness.
    Vertex {
        /// m_x, the degree of the star's centre.
        m: u32,
    },
    /// An oriented edge [u, w] with degrees (m_u, m_w), any labels.
    Edge {
        /// m_u, the degree of u.
        m_u: u32,
        /// m_w, the degree of w.
        m_w: u32,
    },
    /// A triangle [u, w, x] with degrees and orientation of its labels.
    Triangle {
        /// m_u, the degree of u.
        m_u: u32,
        /// m_w, the degree of w.
        m_w: u32,
        /// m_x, the degree of x.
        m_x: u32,
        /// The labels step counterclockwise ([`maps::FanOrientation::Ccw`]).
        ccw: bool,
    },
}

impl std::fmt::Display for ConfigKey {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ConfigKey::Vertex { m } => write!(f, "vertex m={m}"),
            ConfigKey::Edge { m_u, m_w } => write!(f, "edge ({m_u},{m_w})"),
            ConfigKey::Triangle { m_u, m_w, m_x, ccw } => write!(
                f,
                "triangle ({m_u},{m_w},{m_x}) {}",
                if *ccw { "ccw" } else { "cw" }
            ),
        }
    }
}

impl ConfigKey {
    /// Key of an oriented edge (labels do not matter: R_(u,w) conjugates them away).
    pub fn of_edge(e: &EdgeConfig) -> ConfigKey {
        ConfigKey::Edge {
            m_u: e.m_u,
            m_w: e.m_w,
        }
    }
    /// Key of a triangle; errors if its labels are not a fan (Def. 4.1.4).
    pub fn of_triangle(t: &TriangleConfig) -> Result<ConfigKey, maps::ConfigError> {
        let o = t.orientation()?;
        Ok(ConfigKey::Triangle {
            m_u: t.m_u,
            m_w: t.m_w,
            m_x: t.m_x,
            ccw: o == maps::FanOrientation::Ccw,
        })
    }
    /// Key of a vertex (star) of degree m.
    pub fn of_vertex(m: u32) -> ConfigKey {
        ConfigKey::Vertex { m }
    }
    /// Every configuration a mesh needs: vertices by degree, both orientations of each edge,
    /// and each triangle read from each of its three vertices (all three rotations).
    pub fn all_for(
        degrees: &[u32],
        edges: &[EdgeConfig],
        triangles: &[TriangleConfig],
    ) -> Result<Vec<ConfigKey>, maps::ConfigError> {
        let mut v: Vec<ConfigKey> = degrees.iter().map(|&m| ConfigKey::of_vertex(m)).collect();
        for e in edges {
            v.push(ConfigKey::of_edge(e));
            v.push(ConfigKey::of_edge(&e.reversed()));
        }
        for t in triangles {
            let k = ConfigKey::of_triangle(t)?;
            if let ConfigKey::Triangle { m_u, m_w, m_x, ccw } = k {
                v.push(k);
                v.push(ConfigKey::Triangle {
                    m_u: m_w,
                    m_w: m_x,
                    m_x: m_u,
                    ccw,
                });
                v.push(ConfigKey::Triangle {
                    m_u: m_x,
                    m_w: m_u,
                    m_x: m_w,
                    ccw,
                });
            }
        }
        v.sort();
        v.dedup();
        Ok(v)
    }
    /// The canonical triangle of this key (labels 0/±1).
    pub(super) fn triangle(&self) -> Option<TriangleConfig> {
        match *self {
            ConfigKey::Triangle { m_u, m_w, m_x, ccw } => {
                if ccw {
                    TriangleConfig::ccw(m_u, m_w, m_x, 0, 0, 0).ok()
                } else {
                    TriangleConfig::new(
                        Corner {
                            m: m_u,
                            next: 0,
                            prev: m_u - 1,
                        },
                        Corner {
                            m: m_w,
                            next: 1,
                            prev: 0,
                        },
                        Corner {
                            m: m_x,
                            next: 1,
                            prev: 0,
                        },
                    )
                    .ok()
                }
            }
            _ => None,
        }
    }
}

/// All configurations with degrees in 3..=max_degree, in a fixed order.
pub fn all_configs(max_degree: u32) -> Vec<ConfigKey> {
    let ms: Vec<u32> = (maps::MIN_DEGREE..=max_degree).collect();
    let mut v: Vec<ConfigKey> = ms.iter().map(|&m| ConfigKey::Vertex { m }).collect();
    for &a in &ms {
        for &b in &ms {
            v.push(ConfigKey::Edge { m_u: a, m_w: b });
        }
    }
    for &a in &ms {
        for &b in &ms {
            for &x in &ms {
                for ccw in [true, false] {
                    v.push(ConfigKey::Triangle {
                        m_u: a,
                        m_w: b,
                        m_x: x,
                        ccw,
                    });
                }
            }
        }
    }
    v
}

/// Shard `k` of `n` (1-based): every n-th configuration starting at k − 1.
pub fn shard(configs: &[ConfigKey], k: usize, n: usize) -> Vec<ConfigKey> {
    configs
        .iter()
        .enumerate()
        .filter(|(i, _)| n > 0 && i % n == k.saturating_sub(1))
        .map(|(_, c)| *c)
        .collect()
}
