//! What every reader shares: the options, the file being read (for located errors), the one
//! coordinate parser and the capacity cap of every allocation sized by the input.

use super::limits::Limits;
use crate::mesh::error::{Location, MeshError};
use std::path::{Path, PathBuf};

/// How to read a mesh.
#[derive(Debug, Clone, Default)]
pub struct ReadOptions {
    /// Fan-split convex polygons with more than 3 sides (counted in
    /// [`crate::mesh::RawMesh::triangulated_polygons`]); without it such polygons are
    /// [`MeshError::NotTriangle`].
    pub triangulate: bool,
    /// Upper bounds on declared element counts.
    pub limits: Limits,
}

/// The file being read and the options: builds located errors.
pub(crate) struct Ctx<'a> {
    pub path: &'a Path,
    pub opts: &'a ReadOptions,
}

impl Ctx<'_> {
    fn path(&self) -> PathBuf {
        self.path.to_path_buf()
    }

    pub(crate) fn parse(&self, at: Location, msg: impl Into<String>) -> MeshError {
        MeshError::Parse {
            path: self.path(),
            at,
            msg: msg.into(),
        }
    }

    pub(crate) fn truncated(&self, at: Location, msg: impl Into<String>) -> MeshError {
        MeshError::Truncated {
            path: self.path(),
            at,
            msg: msg.into(),
        }
    }

    pub(crate) fn encoding(&self, at: Location) -> MeshError {
        MeshError::Encoding {
            path: self.path(),
            at,
        }
    }

    /// Fails if `count` of `what` exceeds `limit`.
    pub(crate) fn check_limit(
        &self,
        at: Location,
        what: &'static str,
        count: u64,
        limit: u64,
    ) -> Result<(), MeshError> {
        if count > limit {
            return Err(MeshError::TooLarge {
                path: self.path(),
                at,
                what,
                count,
                limit,
            });
        }
        Ok(())
    }
}

/// Parses a coordinate. Accepts Rust/C decimal syntax and `nan`/`inf`/`infinity` in any case
/// with an optional sign; every NaN is normalised to [`f64::NAN`] so results are deterministic.
pub(crate) fn parse_coord(tok: &str) -> Option<f64> {
    let v: f64 = tok.parse().ok()?;
    Some(if v.is_nan() { f64::NAN } else { v })
}

/// A capacity hint that never exceeds what `remaining` bytes could encode at
/// `min_bytes_each` bytes per element.
pub(crate) fn capped_capacity(count: u64, remaining: usize, min_bytes_each: usize) -> usize {
    let fit = remaining / min_bytes_each.max(1);
    usize::try_from(count).unwrap_or(usize::MAX).min(fit)
}

#[cfg(test)]
mod tests {
    use super::capped_capacity;

    /// The hint is the claimed count when the bytes left could hold it, and never more than
    /// they could: a header claiming 10¹⁸ elements in 100 bytes reserves room for 16, not 10¹⁸
    /// (nor none, which would only be slower, so pinned here rather than seen by a reader test).
    #[test]
    fn capped_capacity_is_the_count_capped_by_the_bytes_left() {
        assert_eq!(capped_capacity(10, 100, 6), 10);
        assert_eq!(capped_capacity(1_000_000_000_000_000_000, 100, 6), 16);
        assert_eq!(capped_capacity(u64::MAX, 100, 8), 12);
        assert_eq!(capped_capacity(5, 100, 0), 5);
        assert_eq!(capped_capacity(5, 0, 6), 0);
    }
}
