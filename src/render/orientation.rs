//! Do the shading normals point out of the visible side? Each corner's normal is compared with
//! the geometric normal (p₁ − p₀) × (p₂ − p₀) of its triangle (K's orientation, which the
//! chart orientation follows, Sec. 4.1): on a sampled smooth surface they agree (positive
//! cosine). A sign error in the normal makes them disagree everywhere, which also turns the
//! lit side dark; this check reports it with a witness.

use super::scene::Scene;
use crate::numeric::vec3::{cross, dot, norm, sub};
use serde::Serialize;

/// The corner where the normal and the triangle disagree most.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct OrientationWitness {
    /// The triangle.
    pub face: usize,
    /// The vertex (index into the scene).
    pub vertex: u32,
    /// cos of the angle between the vertex normal and the triangle's normal.
    pub cosine: f64,
}

/// Agreement of the normals with the triangles' orientation.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Default)]
pub struct OrientationReport {
    /// Corners compared (non-degenerate triangle, non-zero finite normal).
    pub checked: usize,
    /// Corners with a negative cosine.
    pub disagreeing: usize,
    /// The smallest cosine seen.
    pub worst: Option<OrientationWitness>,
}

impl OrientationReport {
    /// More than half the corners disagree: the normals are flipped (a sign error).
    pub fn flipped(&self) -> bool {
        self.checked > 0 && 2 * self.disagreeing > self.checked
    }
}

/// Compare every corner's normal with its triangle's normal.
pub fn check_orientation(scene: &Scene) -> OrientationReport {
    let mut r = OrientationReport::default();
    for (face, f) in scene.faces.iter().enumerate() {
        let p = f.map(|i| scene.positions[i as usize]);
        let nf = cross(sub(p[1], p[0]), sub(p[2], p[0]));
        let lf = norm(nf);
        if !(lf > 0.0 && lf.is_finite()) {
            continue;
        }
        for &v in f {
            let n = scene.normals[v as usize];
            let ln = norm(n);
            if !(ln > 0.0 && ln.is_finite()) {
                continue;
            }
            let cosine = dot(n, nf) / (ln * lf);
            r.checked += 1;
            if cosine < 0.0 {
                r.disagreeing += 1;
            }
            if r.worst.map_or(true, |w| cosine < w.cosine) {
                r.worst = Some(OrientationWitness {
                    face,
                    vertex: v,
                    cosine,
                });
            }
        }
    }
    r
}
