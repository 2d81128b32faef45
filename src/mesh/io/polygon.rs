//! Collects faces in file order; with `triangulate`, fan-splits convex polygons once all
//! positions are known.

use super::context::Ctx;
use crate::mesh::error::{Location, MeshError};
use crate::numeric::vec3::{cross, dot, norm, sub};

/// Corners must lie within this fraction of the polygon's bounding-box diagonal from the
/// plane through their centroid with the Newell normal.
const PLANARITY_TOL: f64 = 1e-4;
/// A turn counts as strictly convex when sin(turn angle) exceeds this.
const TURN_TOL: f64 = 1e-9;

/// A polygon with more than 3 sides waiting for fan-splitting.
struct Pending {
    /// Its triangles go before `faces[slot]`.
    slot: usize,
    start: usize,
    len: usize,
    origin: u64,
}

/// Faces in file order as 0-based vertex indices, with their origins.
pub(crate) struct FaceSink {
    triangulate: bool,
    faces: Vec<[u32; 3]>,
    origins: Vec<u64>,
    pending: Vec<Pending>,
    corners: Vec<u32>,
}

/// The faces of a finished sink.
pub(crate) struct Faces {
    pub faces: Vec<[u32; 3]>,
    pub origins: Vec<u64>,
    pub triangulated_polygons: u64,
}

impl FaceSink {
    pub(crate) fn new(triangulate: bool, capacity: usize) -> Self {
        FaceSink {
            triangulate,
            faces: Vec::with_capacity(capacity),
            origins: Vec::with_capacity(capacity),
            pending: Vec::new(),
            corners: Vec::new(),
        }
    }

    /// Adds one polygon read at `at` (recorded origin `origin`).
    pub(crate) fn push(
        &mut self,
        ctx: &Ctx<'_>,
        idx: &[u32],
        origin: u64,
        at: Location,
    ) -> Result<(), MeshError> {
        match *idx {
            [a, b, c] => {
                self.faces.push([a, b, c]);
                self.origins.push(origin);
                Ok(())
            }
            _ if idx.len() < 3 => Err(MeshError::TooFewSides {
                path: ctx.path.to_path_buf(),
                at,
                sides: idx.len(),
            }),
            _ if !self.triangulate => Err(MeshError::NotTriangle {
                path: ctx.path.to_path_buf(),
                at,
                sides: idx.len(),
            }),
            _ => {
                self.pending.push(Pending {
                    slot: self.faces.len(),
                    start: self.corners.len(),
                    len: idx.len(),
                    origin,
                });
                self.corners.extend_from_slice(idx);
                Ok(())
            }
        }
    }

    /// Fan-splits the pending polygons against `positions` and returns all faces in order.
    pub(crate) fn finish(
        self,
        ctx: &Ctx<'_>,
        positions: &[[f64; 3]],
        origin_is_line: bool,
    ) -> Result<Faces, MeshError> {
        if self.pending.is_empty() {
            return Ok(Faces {
                faces: self.faces,
                origins: self.origins,
                triangulated_polygons: 0,
            });
        }
        let extra: usize = self.pending.iter().map(|p| p.len - 2).sum();
        let total = self.faces.len().saturating_add(extra);
        let mut faces = Vec::with_capacity(total);
        let mut origins = Vec::with_capacity(total);
        let mut copied = 0;
        let mut pts = Vec::new();
        for p in &self.pending {
            faces.extend_from_slice(&self.faces[copied..p.slot]);
            origins.extend_from_slice(&self.origins[copied..p.slot]);
            copied = p.slot;
            let idx = &self.corners[p.start..p.start + p.len];
            let at = if origin_is_line {
                Location::Line(p.origin)
            } else {
                Location::Element {
                    kind: "face",
                    index: p.origin,
                }
            };
            check_fan(idx, positions, &mut pts).map_err(|why| MeshError::CannotTriangulate {
                path: ctx.path.to_path_buf(),
                at,
                sides: idx.len(),
                why,
            })?;
            for w in idx[1..].windows(2) {
                faces.push([idx[0], w[0], w[1]]);
                origins.push(p.origin);
            }
        }
        faces.extend_from_slice(&self.faces[copied..]);
        origins.extend_from_slice(&self.origins[copied..]);
        Ok(Faces {
            faces,
            origins,
            triangulated_polygons: self.pending.len() as u64,
        })
    }
}

/// Whether the polygon `idx` can be fan-split from its first corner: distinct in-range
/// corners with finite coordinates, (nearly) planar, strictly convex (every turn has the same
/// sign as the Newell normal) and winding once.
fn check_fan(idx: &[u32], positions: &[[f64; 3]], pts: &mut Vec<[f64; 3]>) -> Result<(), String> {
    let mut sorted = idx.to_vec();
    sorted.sort_unstable();
    if sorted.windows(2).any(|w| w[0] == w[1]) {
        return Err("a vertex index is repeated".into());
    }
    pts.clear();
    for &i in idx {
        let p = positions
            .get(i as usize)
            .ok_or_else(|| format!("vertex index {i} is out of range"))?;
        if !p.iter().all(|c| c.is_finite()) {
            return Err(format!("vertex {i} has a non-finite coordinate"));
        }
        pts.push(*p);
    }
    let n = pts.len();
    let inv = 1.0 / n as f64;
    let mut c = [0.0; 3];
    let (mut lo, mut hi) = (pts[0], pts[0]);
    for p in pts.iter() {
        for k in 0..3 {
            c[k] += p[k] * inv;
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    let diam = norm(sub(hi, lo));
    if diam <= 0.0 || !diam.is_finite() {
        return Err("all corners coincide".into());
    }
    // Newell normal of the centred polygon (twice the vector area).
    let mut nn = [0.0; 3];
    for i in 0..n {
        let a = sub(pts[i], c);
        let b = sub(pts[(i + 1) % n], c);
        nn[0] += (a[1] - b[1]) * (a[2] + b[2]);
        nn[1] += (a[2] - b[2]) * (a[0] + b[0]);
        nn[2] += (a[0] - b[0]) * (a[1] + b[1]);
    }
    let len = norm(nn);
    if len.is_nan() || len <= 1e-12 * diam * diam {
        return Err("the polygon has (nearly) zero area".into());
    }
    let nh = [nn[0] / len, nn[1] / len, nn[2] / len];
    for (i, p) in pts.iter().enumerate() {
        let d = dot(sub(*p, c), nh).abs();
        if d > PLANARITY_TOL * diam {
            return Err(format!(
                "not planar: corner {i} is {d:e} off the mean plane (tolerance {:e})",
                PLANARITY_TOL * diam
            ));
        }
    }
    let mut winding = 0.0;
    for i in 0..n {
        let e1 = sub(pts[i], pts[(i + n - 1) % n]);
        let e2 = sub(pts[(i + 1) % n], pts[i]);
        let (l1, l2) = (norm(e1), norm(e2));
        if l1 == 0.0 || l2 == 0.0 {
            return Err(format!("corner {i} coincides with a neighbour"));
        }
        let s = dot(cross(e1, e2), nh);
        if s.is_nan() || s <= TURN_TOL * l1 * l2 {
            return Err(format!(
                "not convex: the turn at corner {i} is reflex or straight"
            ));
        }
        winding += s.atan2(dot(e1, e2));
    }
    if winding > 3.0 * std::f64::consts::PI {
        return Err("the boundary winds more than once (star-shaped polygon)".into());
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::check_fan;

    fn fan_ok(pos: &[[f64; 3]]) -> Result<(), String> {
        check_fan(&[0, 1, 2, 3], pos, &mut Vec::new())
    }

    /// The square [0, s]² with corner 2 lifted by `lift · s`.
    fn lifted(s: f64, lift: f64) -> Vec<[f64; 3]> {
        vec![
            [0.0, 0.0, 0.0],
            [s, 0.0, 0.0],
            [s, s, lift * s],
            [0.0, s, 0.0],
        ]
    }

    /// (0, 0), (1/2 + t, 1/2 − t), (1, 1), (0, 1), scaled by s: corner 1 turns by about 4t
    /// radians, at every scale.
    fn bent(s: f64, t: f64) -> Vec<[f64; 3]> {
        vec![
            [0.0, 0.0, 0.0],
            [s * (0.5 + t), s * (0.5 - t), 0.0],
            [s, s, 0.0],
            [0.0, s, 0.0],
        ]
    }

    #[test]
    fn planarity_is_relative_to_the_polygon_s_size() {
        for s in [1e-3, 1.0, 1e3] {
            assert!(
                fan_ok(&lifted(s, 0.5e-4)).is_ok(),
                "scale {s}: within the tolerance"
            );
            let e = fan_ok(&lifted(s, 1e-3)).expect_err("off the plane");
            assert!(e.contains("not planar"), "scale {s}: {e}");
        }
    }

    #[test]
    fn nearly_straight_corners_are_judged_by_their_angle_at_every_scale() {
        for s in [1e-3, 1.0, 1e3] {
            let e = fan_ok(&bent(s, 2.5e-11)).expect_err("a turn of 1e-10 rad");
            assert!(e.contains("not convex"), "scale {s}: {e}");
            assert!(
                fan_ok(&bent(s, 1e-6)).is_ok(),
                "scale {s}: a turn of 4e-6 rad"
            );
        }
    }
}
