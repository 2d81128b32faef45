//! Sec. 6.1.1 (DCEL) and Sec. 6.1.2 (labelling s_v). Being written in issue 2.

/// A validated simplicial surface (Def. 3.1.6). Only the validator constructs it.
#[derive(Debug, Clone)]
pub struct SimplicialSurface {
    _private: (),
}
