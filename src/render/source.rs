//! Scenes from what `ppm render` draws: K itself (flat triangles), S′ (Sec. 5.1, PN triangles),
//! the PPS (Ch. 5, sampled as in Sec. 6.2) or a sampled surface read from a file.
//!
//! Normals and curvatures of S′ and of the PPS come from the analytic derivatives of b_σ and
//! θ_v (jets, [`crate::surface::jet`]), never from finite differences.

use super::error::RenderError;
use super::scene::Scene;
use crate::mesh::raw::RawMesh;
use crate::mesh::{FaceId, SimplicialSurface, VertexId};
use crate::numeric::vec3::{cross, sub};
use crate::surface::geometry::{from_derivatives, from_jet, SurfacePoint};
use crate::surface::jet::Jet2;
use crate::surface::loop_subdiv::stam::PatchJet;
use crate::surface::loop_subdiv::LoopSurface;
use crate::surface::output::{sample_surface_with, Attributes};
use crate::surface::target::eval_cubic;
use crate::surface::{Pps, SPrime};

/// K drawn flat: every triangle with its own three vertices and its geometric normal.
pub fn mesh_scene(k: &SimplicialSurface) -> Scene {
    let mut s = Scene::default();
    for f in k.faces() {
        let p = k.face(f).map(|v| k.position(v));
        let n = cross(sub(p[1], p[0]), sub(p[2], p[0]));
        let base = s.positions.len() as u32;
        for q in p {
            s.positions.push(q);
            s.normals.push(n);
        }
        s.faces.push([base, base + 1, base + 2]);
    }
    s
}

/// The barycentric grid (k, i, j)/2^level of a triangle and its small triangles, as in
/// Sec. 6.2's midpoint subdivision (level ≤ 10).
fn grid(level: u32) -> (Vec<[f64; 3]>, Vec<[u32; 3]>) {
    let n = 1u32 << level.min(10);
    let row = |i: u32| -> u32 { (0..i).map(|r| n + 1 - r).sum() };
    let at = |i: u32, j: u32| row(i) + j;
    let mut pts = Vec::new();
    for i in 0..=n {
        for j in 0..=(n - i) {
            let nn = f64::from(n);
            pts.push([
                f64::from(n - i - j) / nn,
                f64::from(i) / nn,
                f64::from(j) / nn,
            ]);
        }
    }
    let mut tris = Vec::new();
    for i in 0..n {
        for j in 0..(n - i) {
            tris.push([at(i, j), at(i + 1, j), at(i, j + 1)]);
            if i + j + 1 < n {
                tris.push([at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)]);
            }
        }
    }
    (pts, tris)
}

/// S′ (PN triangles or the Loop limit surface), each face's patch sampled on the level-`level`
/// grid with its own vertices (PN triangles are only C⁰ across edges: their normals and
/// curvatures jump there, and the picture shows it). The patch of σ is parametrised by
/// (s, t) ↦ S′(σ; 1 − s − t, s, t) over σ's corners in K's order, so the normal ∂_s × ∂_t
/// follows K's orientation.
pub fn sprime_scene(k: &SimplicialSurface, sprime: &SPrime, level: u32) -> Scene {
    let (pts, tris) = grid(level);
    let mut s = Scene {
        gaussian: Some(Vec::new()),
        mean: Some(Vec::new()),
        ..Scene::default()
    };
    for f in k.faces() {
        let corners = k.face(f);
        let base = s.positions.len() as u32;
        for b in &pts {
            let g = match sprime {
                SPrime::Pn(pn) => pn_point(&pn.net(corners), b[1], b[2]),
                SPrime::Loop(l) => loop_point(l, f, corners, b[1], b[2]),
            };
            s.positions.push(g.point);
            s.normals.push(g.normal);
            if let (Some(kk), Some(h)) = (s.gaussian.as_mut(), s.mean.as_mut()) {
                kk.push(g.gaussian);
                h.push(g.mean);
            }
        }
        s.faces.extend(tris.iter().map(|t| t.map(|i| i + base)));
    }
    s
}

fn pn_point(net: &[[f64; 3]; 10], s: f64, t: f64) -> SurfacePoint {
    let (x, y) = Jet2::<f64>::variables(s, t);
    let one = Jet2::<f64>::constant(1.0);
    let bary = [
        crate::numeric::Scalar::sub(&crate::numeric::Scalar::sub(&one, &x), &y),
        x,
        y,
    ];
    from_jet(&eval_cubic(net, bary))
}

/// The Loop limit point with Stam's exact derivatives. At an extraordinary vertex the
/// parametrization has derivative 0 or ∞ (Stam 1998, Sec. 5) although the surface has a
/// tangent plane (`LOOP-normal-mask`): normal and curvature are then taken 1e-9 (in
/// barycentric coordinates) towards the face's centroid, where the jet exists.
fn loop_point(l: &LoopSurface, f: FaceId, corners: [VertexId; 3], s: f64, t: f64) -> SurfacePoint {
    let jet = |b: [f64; 3]| l.jet::<f64>(f, corners, &b, true);
    let b = [1.0 - s - t, s, t];
    let nan = [f64::NAN; 3];
    match jet(b) {
        Ok(PatchJet { p, d: Some(d), .. }) => from_derivatives(p, d),
        Ok(PatchJet { p, d: None, .. }) => {
            let e = 1e-9;
            let moved = b.map(|x| x * (1.0 - 3.0 * e) + e);
            match jet(moved) {
                Ok(PatchJet { d: Some(d), .. }) => SurfacePoint {
                    point: p,
                    ..from_derivatives(p, d)
                },
                _ => from_derivatives(p, [nan; 5]),
            }
        }
        Err(_) => from_derivatives(nan, [nan; 5]),
    }
}

/// The PPS sampled at `level` (Sec. 6.2) with θ's normals, and its curvatures when
/// `curvature` (order-2 jets; order-1 jets otherwise).
pub fn pps_scene(pps: &Pps, level: u32, curvature: bool) -> Result<Scene, RenderError> {
    let attrs = if curvature {
        Attributes::Curvature
    } else {
        Attributes::Normals
    };
    let m = sample_surface_with(pps, level, attrs, None)?;
    Ok(Scene {
        positions: m.positions,
        normals: m.normals,
        gaussian: curvature.then_some(m.gaussian),
        mean: curvature.then_some(m.mean),
        faces: m.faces,
    })
}

/// A sampled surface read from a file (e.g. written by `ppm sample`): the per-vertex normals
/// (`nx ny nz`) and curvatures (`gaussian_curvature`, `mean_curvature`) it carries (PLY), and
/// otherwise area-weighted vertex normals of its triangles (the file has nothing better).
pub(crate) fn samples_scene(raw: &RawMesh) -> Result<Scene, RenderError> {
    let get = |name: &str| {
        raw.vertex_scalars
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, v)| v.clone())
    };
    let mut s = Scene {
        positions: raw.positions.clone(),
        faces: raw.faces.clone(),
        gaussian: get("gaussian_curvature"),
        mean: get("mean_curvature"),
        normals: Vec::new(),
    };
    // Indices are checked before the normals are accumulated over them.
    s.normals = vec![[0.0; 3]; s.positions.len()];
    s.validate()?;
    s.normals = match (get("nx"), get("ny"), get("nz")) {
        (Some(x), Some(y), Some(z)) => (0..x.len()).map(|i| [x[i], y[i], z[i]]).collect(),
        _ => {
            let mut n = vec![[0.0; 3]; s.positions.len()];
            for f in &s.faces {
                let p = f.map(|i| s.positions[i as usize]);
                let a = cross(sub(p[1], p[0]), sub(p[2], p[0]));
                for &i in f {
                    for d in 0..3 {
                        n[i as usize][d] += a[d];
                    }
                }
            }
            n
        }
    };
    Ok(s)
}
