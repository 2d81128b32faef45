//! Sec. 6.2: sampling M "in a triangle midpoint subdivision manner" through eval, and writing
//! the result with per-vertex normals and curvatures by `mesh::io`'s writers (OBJ, OFF, PLY;
//! curvature also as vertex colours in PLY).
//!
//! Level N subdivides every triangle of K N times at edge midpoints, i.e. samples the
//! barycentric grid (i, j, k)/2^N. Points on an edge of K, and the corners, are shared by the
//! triangles around them (evaluated once, through one of them), so the output is a closed
//! triangle mesh whenever K is: watertight by construction, and geometrically consistent by
//! condition (C) (the point does not depend on the triangle used, up to rounding).

use super::consts::Consts;
use super::fit_linear::WordHash;
use super::jet::{Jet1, Jet2};
use super::pps::{Pps, SurfaceError};
use crate::mesh::io::{output_format, write_mesh_file, MeshOut, PlyIndex};
use crate::mesh::{FaceId, MeshFormat};
use std::collections::HashMap;
use std::hash::BuildHasherDefault;
use std::path::Path;
use std::sync::atomic::{AtomicUsize, Ordering};

/// The sampled surface.
#[derive(Debug, Clone, Default)]
pub struct SampledMesh {
    /// Vertex positions θ_v(q) of the samples.
    pub positions: Vec<[f64; 3]>,
    /// Unit normals (zero at a singular point).
    pub normals: Vec<[f64; 3]>,
    /// Gaussian curvature K (NaN at a singular point).
    pub gaussian: Vec<f64>,
    /// Mean curvature H, with the sign given by the normal (NaN at a singular point).
    pub mean: Vec<f64>,
    /// Triangles as 0-based indices into the per-vertex arrays.
    pub faces: Vec<[u32; 3]>,
    /// The OBJ header line: the command and what the surface is ("" = `ppm sample` of the
    /// paper's PPS).
    pub title: &'static str,
}

/// A sample point shared between faces: a mesh vertex, or the point of weight w on edge (a, b).
#[derive(Hash, PartialEq, Eq, Clone, Copy)]
enum Key {
    Corner(u32),
    Edge(u32, u32, u32),
}

/// One point of the Sec. 6.2 sampling: the arguments of eval(σ, λ, μ, ν).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct SamplePoint {
    /// σ.
    pub face: FaceId,
    /// (λ, μ, ν) at the corners of σ in file order.
    pub bary: [f64; 3],
}

/// The sampling pattern at one level: the eval argument of every output vertex (in output
/// order) and the output triangles. [`sample_surface`] evaluates exactly this pattern, and the
/// oracle's `diff --surface` compares a third-party sampling against it.
#[derive(Debug, Clone, Default)]
pub struct SamplePattern {
    /// The eval argument of every output vertex, in output order.
    pub points: Vec<SamplePoint>,
    /// The output triangles (vertex indices).
    pub faces: Vec<[u32; 3]>,
}

/// Memory budget of one sampling (positions, normals, curvatures, triangles and the pattern).
pub const SAMPLE_MEMORY_LIMIT: u128 = 8 << 30;

/// Estimated (points, bytes) of the Sec. 6.2 sampling of `faces` triangles at `level`: each
/// face contributes at most (2^N + 1)(2^N + 2)/2 points and 4^N triangles; a point costs ~96
/// bytes (position, normal, two curvatures, its eval argument and index entry), a triangle 12.
pub fn sample_estimate(faces: usize, level: u32) -> (u128, u128) {
    // Saturating: the estimate only has to exceed any limit when the true count does.
    let n = 1u128 << level.min(100);
    let f = faces as u128;
    let points = f.saturating_mul(n + 1).saturating_mul(n + 2) / 2;
    let bytes = points
        .saturating_mul(96)
        .saturating_add(f.saturating_mul(n).saturating_mul(n).saturating_mul(12));
    (points, bytes)
}

/// The midpoint-subdivision pattern of Sec. 6.2 at `level`: the barycentric grid
/// (k, i, j)/2^level of every face, a point on an edge or corner of K listed once (through the
/// first face that reaches it), so the triangles close up. A level whose estimated output
/// exceeds [`SAMPLE_MEMORY_LIMIT`] is refused with [`SurfaceError::LevelTooLarge`].
pub fn sample_pattern(pps: &Pps, level: u32) -> Result<SamplePattern, SurfaceError> {
    let faces = (0..pps.num_faces())
        .map(|f| pps.face(FaceId(f as u32)))
        .collect::<Result<Vec<_>, _>>()?;
    sample_pattern_faces(&faces, level)
}

/// [`sample_pattern`] for any list of faces (corner triples in their stored order): shared
/// by the constructions that sample through eval(σ, λ, μ, ν). Refuses a level whose estimated
/// output exceeds [`SAMPLE_MEMORY_LIMIT`] with [`SurfaceError::LevelTooLarge`].
pub fn sample_pattern_faces(
    faces: &[[crate::mesh::VertexId; 3]],
    level: u32,
) -> Result<SamplePattern, SurfaceError> {
    let (points, bytes) = sample_estimate(faces.len(), level);
    if level > 30 || bytes > SAMPLE_MEMORY_LIMIT {
        return Err(SurfaceError::LevelTooLarge {
            level,
            points,
            bytes,
            limit: SAMPLE_MEMORY_LIMIT,
        });
    }
    let n = 1u32 << level;
    let nf = faces.len();
    // Lookups only (never iterated), so the hasher does not change the output; keys derived
    // from K need no DoS-resistant SipHash.
    let mut index: HashMap<Key, u32, BuildHasherDefault<WordHash>> = HashMap::default();
    let mut out = SamplePattern {
        points: Vec::new(),
        faces: Vec::with_capacity(nf * (n * n) as usize),
    };
    // local index of (i, j): Σ_{i' < i} (n + 1 − i') + j.
    let mut row_start = vec![0usize; (n + 2) as usize];
    for i in 0..=n {
        row_start[i as usize + 1] = row_start[i as usize] + (n + 1 - i) as usize;
    }
    for (fi, &c) in faces.iter().enumerate().take(nf) {
        let f = FaceId(fi as u32);
        let mut local = Vec::with_capacity(row_start[n as usize + 1]);
        for i in 0..=n {
            for j in 0..=(n - i) {
                let k = n - i - j;
                // weights: corner 0 ↦ k, corner 1 ↦ i, corner 2 ↦ j.
                let w = [k, i, j];
                let mut nz = [0usize; 3];
                let mut len = 0;
                for (t, &wt) in w.iter().enumerate() {
                    if wt != 0 {
                        nz[len] = t;
                        len += 1;
                    }
                }
                let key = match &nz[..len] {
                    [a] => Some(Key::Corner(c[*a].0)),
                    [a, b] => {
                        let (a, b) = (*a, *b);
                        Some(if c[a].0 < c[b].0 {
                            Key::Edge(c[a].0, c[b].0, w[a])
                        } else {
                            Key::Edge(c[b].0, c[a].0, w[b])
                        })
                    }
                    // An interior point belongs to this face alone: no lookup needed.
                    _ => None,
                };
                let next = out.points.len() as u32;
                let nn = f64::from(n);
                let point = SamplePoint {
                    face: f,
                    bary: [f64::from(k) / nn, f64::from(i) / nn, f64::from(j) / nn],
                };
                let id = match key {
                    Some(key) => *index.entry(key).or_insert_with(|| {
                        out.points.push(point);
                        next
                    }),
                    None => {
                        out.points.push(point);
                        next
                    }
                };
                local.push(id);
            }
        }
        let at = |i: u32, j: u32| local[row_start[i as usize] + j as usize];
        for i in 0..n {
            for j in 0..(n - i) {
                out.faces.push([at(i, j), at(i + 1, j), at(i, j + 1)]);
                if i + j + 1 < n {
                    out.faces
                        .push([at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)]);
                }
            }
        }
    }
    Ok(out)
}

/// Which per-vertex attributes a sampling computes: each costs more than the one before
/// (positions: plain f64 eval; normals: order-1 jets; curvatures: order-2 jets).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Attributes {
    /// Positions only.
    Positions,
    /// Positions and unit normals.
    Normals,
    /// Positions, normals, Gaussian and mean curvature.
    #[default]
    Curvature,
}

impl Attributes {
    /// Parse `positions | normals | curvature`.
    pub fn parse(s: &str) -> Option<Attributes> {
        match s {
            "positions" => Some(Attributes::Positions),
            "normals" => Some(Attributes::Normals),
            "curvature" => Some(Attributes::Curvature),
            _ => None,
        }
    }
}

/// A progress hook of a long evaluation, called with (points done, total) about ten times.
pub use crate::report::Progress;

/// Sample M at subdivision level `level` (Sec. 6.2) with normals and curvatures.
pub fn sample_surface(
    pps: &Pps,
    level: u32,
    progress: Progress,
) -> Result<SampledMesh, SurfaceError> {
    sample_surface_with(pps, level, Attributes::Curvature, progress)
}

/// Evaluate `f` at every point of `todo`, in the patches' storage order (cache locality),
/// results in `todo` order.
fn eval_points<T: Send>(
    pps: &Pps,
    todo: &[SamplePoint],
    progress: Progress,
    f: impl Fn(SamplePoint) -> Result<T, SurfaceError> + Sync,
) -> Result<Vec<T>, SurfaceError> {
    let done = AtomicUsize::new(0);
    let total = todo.len();
    let step = (total / 10).max(1);
    let keys: Vec<u32> = todo.iter().map(|s| pps.locality_key(s.face)).collect();
    let results = super::pps::map_in_key_order(&keys, |i| {
        let r = f(todo[i]);
        if let Some(show) = progress {
            let d = done.fetch_add(1, Ordering::Relaxed) + 1;
            if d % step == 0 || d == total {
                show(d, total);
            }
        }
        r
    });
    results.into_iter().collect()
}

/// Sample M at subdivision level `level` (Sec. 6.2) computing only `attrs` (the other arrays
/// of the result stay empty).
pub fn sample_surface_with(
    pps: &Pps,
    level: u32,
    attrs: Attributes,
    progress: Progress,
) -> Result<SampledMesh, SurfaceError> {
    let SamplePattern {
        points: todo,
        faces,
    } = sample_pattern(pps, level)?;
    let mut out = SampledMesh {
        faces,
        ..SampledMesh::default()
    };
    // What the output keeps of each point (a `SurfacePoint` also holds θ_x, θ_y and the area
    // element: half its size, and the results pass through three arrays of 800k at level 2).
    type Kept = ([f64; 3], [f64; 3], f64, f64);
    let keep =
        |g: super::geometry::SurfacePoint| -> Kept { (g.point, g.normal, g.gaussian, g.mean) };
    let geometry = |attrs| -> Result<Vec<Kept>, SurfaceError> {
        if attrs == Attributes::Normals {
            let cj: Consts<Jet1<f64>> = pps.consts(53);
            eval_points(pps, &todo, progress, |s| {
                pps.eval_geometry_of_order(s.face, s.bary, &cj)
                    .map(|x| keep(x.2))
            })
        } else {
            // Order-2 jets: the normal and curvatures need no third derivatives.
            let cj: Consts<Jet2<f64>> = pps.consts(53);
            eval_points(pps, &todo, progress, |s| {
                pps.eval_geometry_of_order(s.face, s.bary, &cj)
                    .map(|x| keep(x.2))
            })
        }
    };
    match attrs {
        Attributes::Positions => {
            out.positions = eval_points(pps, &todo, progress, |s| pps.eval_f64(s.face, s.bary))?;
        }
        Attributes::Normals | Attributes::Curvature => {
            let g = geometry(attrs)?;
            out.positions = g.iter().map(|g| g.0).collect();
            out.normals = g.iter().map(|g| g.1).collect();
            if attrs == Attributes::Curvature {
                out.gaussian = g.iter().map(|g| g.2).collect();
                out.mean = g.iter().map(|g| g.3).collect();
            }
        }
    }
    Ok(out)
}

/// Number of edges of the output used by exactly two faces / other counts (watertightness).
pub fn edge_use_counts(faces: &[[u32; 3]]) -> (usize, usize) {
    // Each edge {a, b} is listed under its smaller end by a counting sort, then every (short)
    // list is sorted and its runs counted: O(n) where sorting the 4.8M half-edges of a level-2
    // koala as one array of keys was a few per cent of `ppm sample` (and a hash map before that
    // a tenth).
    let nv = faces.iter().flatten().max().map_or(0, |&v| v as usize + 1);
    let ends = |f: &[u32; 3], t: usize| {
        let (a, b) = (f[t], f[(t + 1) % 3]);
        (a.min(b) as usize, a.max(b))
    };
    let mut start = vec![0usize; nv + 1];
    for f in faces {
        for t in 0..3 {
            start[ends(f, t).0 + 1] += 1;
        }
    }
    for v in 1..start.len() {
        start[v] += start[v - 1];
    }
    let mut at = start.clone();
    let mut other = vec![0u32; 3 * faces.len()];
    for f in faces {
        for t in 0..3 {
            let (lo, hi) = ends(f, t);
            other[at[lo]] = hi;
            at[lo] += 1;
        }
    }
    let (mut two, mut edges) = (0usize, 0usize);
    for v in 0..nv {
        let list = &mut other[start[v]..start[v + 1]];
        list.sort_unstable();
        let mut i = 0;
        while i < list.len() {
            let mut j = i + 1;
            while j < list.len() && list[j] == list[i] {
                j += 1;
            }
            edges += 1;
            if j - i == 2 {
                two += 1;
            }
            i = j;
        }
    }
    (two, edges - two)
}

/// Write the sampled mesh by `mesh::io`'s writer of the format of `path`'s extension: `.obj`
/// (# title, v, vn, f a//a), `.off` (NOFF: positions and normals), `.ply` (ascii: x y z nx ny
/// nz red green blue gaussian_curvature mean_curvature; colours from the mean curvature,
/// clipped at its 98th percentile). Attributes that were not computed ([`Attributes`]) are
/// left out. Any other extension is refused (`InvalidInput`). The file is written next to
/// `path` under a temporary name and renamed into place, so a failed write never leaves a
/// truncated `path`.
pub fn write_mesh_with_attributes(path: &Path, m: &SampledMesh) -> std::io::Result<()> {
    let format = output_format(path)?;
    let title = if m.title.is_empty() {
        "ppm sample: C-infinity PPS surface (Siqueira-Xu-Gallier)"
    } else {
        m.title
    };
    let out = MeshOut {
        positions: &m.positions,
        normals: &m.normals,
        gaussian: &m.gaussian,
        mean: &m.mean,
        faces: &m.faces,
        // The title heads an OBJ file only (the PLY header names the colours instead).
        comment: (format == MeshFormat::Obj).then_some(title),
        ply_index: PlyIndex::Int,
    };
    write_mesh_file(path, &out, format)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The edge counts are those of sorting all undirected edges as one array: a closed
    /// surface, an open one, a non-manifold edge and a repeated face.
    #[test]
    fn c6_2_edge_use_counts_match_sorting_all_edges() {
        let by_sorting = |faces: &[[u32; 3]]| {
            let mut keys: Vec<(u32, u32)> = faces
                .iter()
                .flat_map(|f| {
                    (0..3).map(move |t| (f[t].min(f[(t + 1) % 3]), f[t].max(f[(t + 1) % 3])))
                })
                .collect();
            keys.sort_unstable();
            let mut counts = std::collections::BTreeMap::new();
            for k in keys {
                *counts.entry(k).or_insert(0usize) += 1;
            }
            let two = counts.values().filter(|&&c| c == 2).count();
            (two, counts.len() - two)
        };
        let tetra = vec![[0, 1, 2], [0, 3, 1], [1, 3, 2], [2, 3, 0]];
        let mut cases = vec![tetra.clone(), tetra[..3].to_vec(), Vec::new()];
        let mut fin = tetra.clone();
        fin.push([0, 1, 4]);
        cases.push(fin);
        let mut rep = tetra;
        rep.push([0, 1, 2]);
        cases.push(rep);
        for faces in cases {
            assert_eq!(edge_use_counts(&faces), by_sorting(&faces), "{faces:?}");
        }
    }
}
