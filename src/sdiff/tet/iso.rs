//! Curved isosurfaces on a tetrahedral complex (Mello–Velho Sec. 4, m = 3): the linear
//! isocomplex O = f̂⁻¹(c) and the curved one 𝒪 = (f̂∘X)⁻¹(c) = X⁻¹(O), as triangle meshes,
//! and the comparison of their topology (L168: "𝒪 has the same topology of O"; SPEC
//! `SD-L168(3-D)`).
//!
//! Like the planar `iso` (𝒪 as X⁻¹ of O, not X(O)), 𝒪 is read implicitly: F = f̂∘X − c is
//! evaluated on the level-N lattice of each tetrahedron's parameter domain (Kuhn subdivision of
//! σ into N³ tetrahedra), and marching tetrahedra joins the sign changes. Signs are exact
//! (F = (Σ_c f_c N_c − c D)/D evaluated over ℚ at lattice points, 0 counted as +, i.e. the level
//! c − ε); crossing points are linear interpolations in f64. A lattice point and a lattice edge
//! are keyed by their global vertex multiset, so two tetrahedra sharing a triangle share its
//! points (the face lattices are the same regular triangular grid from both sides) and the
//! surface is watertight wherever X agrees on shared faces (`SD-L99(3-D)`). O is the same
//! construction with X = id, where it is exact up to the crossing points' rounding (f̂ is linear
//! on every small tetrahedron).

use super::complex::TetComplex;
use super::maps::fixed_control4;
use super::params::TetMap;
use super::poly::Poly3;
use crate::mesh::io::write_mesh_to;
use crate::mesh::MeshFormat;
use crate::report::{CheckResult, Witness};
use crate::sdiff::common::rational::{q, to_f64, Q};
use num_traits::{Signed, Zero};
use serde_json::json;
use std::collections::HashMap;

/// Largest lattice level accepted (N³ small tetrahedra per tetrahedron).
pub(crate) const MAX_LEVEL: usize = 64;

/// A triangle mesh in ℝ³.
#[derive(Debug, Clone, Default)]
pub struct TriMesh {
    /// Points.
    pub points: Vec<[f64; 3]>,
    /// Triangles as point indices.
    pub triangles: Vec<[usize; 3]>,
}

/// Topological invariants of a [`TriMesh`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
pub struct Topology {
    /// Vertices used by a triangle.
    pub vertices: usize,
    /// Distinct edges.
    pub edges: usize,
    /// Triangles.
    pub faces: usize,
    /// V − E + F.
    pub euler: i64,
    /// Connected components.
    pub components: usize,
    /// Closed loops of boundary edges (edges of one triangle).
    pub boundary_loops: usize,
    /// Edges of more than two triangles.
    pub nonmanifold_edges: usize,
}

impl TriMesh {
    /// The mesh in `format`, written by the crate's one mesh writer (`mesh::io`); a point
    /// index beyond u32 is refused (`InvalidData`), never truncated.
    pub fn encode(&self, format: MeshFormat) -> std::io::Result<Vec<u8>> {
        let ix = |i: usize| {
            u32::try_from(i).map_err(|_| {
                std::io::Error::new(
                    std::io::ErrorKind::InvalidData,
                    format!("point index {i} does not fit the mesh writer's u32 indices"),
                )
            })
        };
        let faces = self
            .triangles
            .iter()
            .map(|t| Ok([ix(t[0])?, ix(t[1])?, ix(t[2])?]))
            .collect::<std::io::Result<Vec<_>>>()?;
        let mut out = Vec::new();
        write_mesh_to(&mut out, &self.points, &faces, format)?;
        Ok(out)
    }
    /// Euler characteristic, components, boundary loops.
    pub fn topology(&self) -> Topology {
        let n = self.points.len();
        let mut sets = crate::numeric::UnionFind::new(n);
        let mut used = vec![false; n];
        let mut edges: HashMap<(usize, usize), usize> = HashMap::new();
        for t in &self.triangles {
            for k in 0..3 {
                let (a, b) = (t[k], t[(k + 1) % 3]);
                used[a] = true;
                *edges.entry((a.min(b), a.max(b))).or_default() += 1;
                sets.union(a, b);
            }
        }
        let vertices = used.iter().filter(|u| **u).count();
        let mut roots: Vec<usize> = (0..n).filter(|&v| used[v]).map(|v| sets.find(v)).collect();
        roots.sort_unstable();
        roots.dedup();
        // Boundary loops: components of the graph of boundary edges.
        let mut bsets = crate::numeric::UnionFind::new(n);
        let mut on_boundary = vec![false; n];
        for (&(a, b), &m) in &edges {
            if m == 1 {
                on_boundary[a] = true;
                on_boundary[b] = true;
                bsets.union(a, b);
            }
        }
        let mut broots: Vec<usize> = (0..n)
            .filter(|&v| on_boundary[v])
            .map(|v| bsets.find(v))
            .collect();
        broots.sort_unstable();
        broots.dedup();
        Topology {
            vertices,
            edges: edges.len(),
            faces: self.triangles.len(),
            euler: vertices as i64 - edges.len() as i64 + self.triangles.len() as i64,
            components: roots.len(),
            boundary_loops: broots.len(),
            nonmanifold_edges: edges.values().filter(|&&m| m > 2).count(),
        }
    }
}

/// Why the isosurface cannot be built.
#[derive(Debug, thiserror::Error)]
pub enum IsoError3 {
    /// Sec. 1 takes f : V → ℝ − {c}.
    #[error("vertex {vertex}: f = c = {value}; Sec. 1 takes f : V → ℝ − {{c}}")]
    LevelAtVertex {
        /// The vertex.
        vertex: usize,
        /// The value.
        value: String,
    },
    /// f has the wrong length.
    #[error("{given} iso values for {vertices} vertices")]
    Length {
        /// Values given.
        given: usize,
        /// Vertices of K.
        vertices: usize,
    },
    /// The lattice level is 0 or above [`MAX_LEVEL`].
    #[error("lattice level {0} is outside 1..={MAX_LEVEL}")]
    Level(usize),
}

/// O, 𝒪 and the checks on them.
#[derive(Debug, Clone)]
pub struct Isosurfaces {
    /// O = f̂⁻¹(c) (X = id).
    pub linear: TriMesh,
    /// 𝒪 = (f̂∘X)⁻¹(c).
    pub curved: TriMesh,
    /// Topology of O.
    pub linear_topology: Topology,
    /// Topology of 𝒪.
    pub curved_topology: Topology,
    /// Checks (`SD-L168(3-D)`).
    pub report: Vec<CheckResult>,
}

/// The Kuhn subdivision of the level-N lattice of a tetrahedron: N³ tetrahedra, each as four
/// integer barycentric points (a_0..a_3), Σ a = N.
pub fn kuhn_lattice(n: usize) -> Vec<[[usize; 4]; 4]> {
    const PERMS: [[usize; 3]; 6] = [
        [0, 1, 2],
        [0, 2, 1],
        [1, 0, 2],
        [1, 2, 0],
        [2, 0, 1],
        [2, 1, 0],
    ];
    let mut out = Vec::new();
    for x in 0..n {
        for y in 0..n {
            for z in 0..n {
                'perm: for p in PERMS {
                    let mut v = [x, y, z];
                    let mut pts = [[0usize; 4]; 4];
                    for step in 0..4 {
                        if step > 0 {
                            v[p[step - 1]] += 1;
                        }
                        // The staircase simplex N ≥ x ≥ y ≥ z ≥ 0 is σ.
                        if !(v[0] <= n && v[0] >= v[1] && v[1] >= v[2]) {
                            continue 'perm;
                        }
                        pts[step] = [n - v[0], v[0] - v[1], v[1] - v[2], v[2]];
                    }
                    out.push(pts);
                }
            }
        }
    }
    out
}

type PointKey = Vec<(u32, usize)>;

fn point_key(t: &[u32; 4], a: &[usize; 4]) -> PointKey {
    let mut k: PointKey = (0..4).filter(|&c| a[c] > 0).map(|c| (t[c], a[c])).collect();
    k.sort_unstable();
    k
}

/// The level-c surface of F = (Σ_c f_c N_c − c D)/D over K, by marching tetrahedra on the
/// level-`n` lattices; also the worst |F| at its vertices (f64, measured).
fn march(k: &TetComplex, maps: &[TetMap], f: &[Q], c: &Q, n: usize) -> (TriMesh, f64) {
    let cells = kuhn_lattice(n);
    let mut mesh = TriMesh::default();
    let mut edge_ids: HashMap<(PointKey, PointKey), usize> = HashMap::new();
    let mut worst = 0.0f64;
    for (ti, t) in k.tets.iter().enumerate() {
        let m = &maps[ti];
        // g = Σ_j f_j N_j − c D, so F = g / D.
        let g = (0..4).fold(Poly3::default().axpy(&-c, &m.den), |acc, j| {
            acc.axpy(&f[t[j] as usize], &m.num[j])
        });
        let gf = to_f64_poly(&g);
        let df = to_f64_poly(&m.den);
        let corners = t.map(|v| k.points_f64[v as usize]);
        let mut values: HashMap<[usize; 4], (bool, f64)> = HashMap::new();
        let mut value = |a: &[usize; 4]| -> (bool, f64) {
            *values.entry(*a).or_insert_with(|| {
                let p = [
                    q(a[1] as i64) / q(n as i64),
                    q(a[2] as i64) / q(n as i64),
                    q(a[3] as i64) / q(n as i64),
                ];
                let (gv, dv) = (g.eval(&p), m.den.eval(&p));
                let positive = !(&gv * &dv).is_negative();
                let value = if dv.is_zero() {
                    f64::NAN
                } else {
                    to_f64(&(gv / dv))
                };
                (positive, value)
            })
        };
        let position = |a: &[usize; 4], b: &[usize; 4], lam: f64| -> [f64; 3] {
            std::array::from_fn(|x| {
                (0..4)
                    .map(|j| {
                        ((1.0 - lam) * a[j] as f64 + lam * b[j] as f64) / n as f64 * corners[j][x]
                    })
                    .sum()
            })
        };
        for cell in &cells {
            let vals: Vec<(bool, f64)> = cell.iter().map(&mut value).collect();
            let pos: Vec<usize> = (0..4).filter(|&j| vals[j].0).collect();
            let neg: Vec<usize> = (0..4).filter(|&j| !vals[j].0).collect();
            if pos.is_empty() || neg.is_empty() {
                continue;
            }
            let mut crossing = |i: usize, j: usize| -> usize {
                let (ka, kb) = (point_key(t, &cell[i]), point_key(t, &cell[j]));
                let key = if ka < kb { (ka, kb) } else { (kb, ka) };
                if let Some(&id) = edge_ids.get(&key) {
                    return id;
                }
                let (fi, fj) = (vals[i].1, vals[j].1);
                let lam = if fi == fj {
                    0.5
                } else {
                    (fi / (fi - fj)).clamp(0.0, 1.0)
                };
                mesh.points.push(position(&cell[i], &cell[j], lam));
                let w: [f64; 3] = std::array::from_fn(|x| {
                    ((1.0 - lam) * cell[i][x + 1] as f64 + lam * cell[j][x + 1] as f64) / n as f64
                });
                worst =
                    crate::report::dev_max(worst, (eval_f64(&gf, &w) / eval_f64(&df, &w)).abs());
                edge_ids.insert(key, mesh.points.len() - 1);
                mesh.points.len() - 1
            };
            let mut tris: Vec<[usize; 3]> = Vec::new();
            match (neg.len(), pos.len()) {
                (1, 3) | (3, 1) => {
                    let (lone, others) = if neg.len() == 1 {
                        (neg[0], &pos)
                    } else {
                        (pos[0], &neg)
                    };
                    tris.push([
                        crossing(lone, others[0]),
                        crossing(lone, others[1]),
                        crossing(lone, others[2]),
                    ]);
                }
                _ => {
                    let (a, b, cc, d) = (neg[0], neg[1], pos[0], pos[1]);
                    let (ac, ad, bd, bc) = (
                        crossing(a, cc),
                        crossing(a, d),
                        crossing(b, d),
                        crossing(b, cc),
                    );
                    tris.push([ac, ad, bd]);
                    tris.push([ac, bd, bc]);
                }
            }
            // Orient each triangle towards the + side (for viewers; topology ignores it).
            let centre = |ids: &[usize]| -> [f64; 3] {
                let ps: Vec<[f64; 3]> = ids
                    .iter()
                    .map(|&j| position(&cell[j], &cell[j], 0.0))
                    .collect();
                std::array::from_fn(|x| ps.iter().map(|p| p[x]).sum::<f64>() / ps.len() as f64)
            };
            let (cp, cn) = (centre(&pos[..]), centre(&neg[..]));
            for tri in tris {
                let [p0, p1, p2] = tri.map(|j| mesh.points[j]);
                let u: [f64; 3] = std::array::from_fn(|x| p1[x] - p0[x]);
                let v: [f64; 3] = std::array::from_fn(|x| p2[x] - p0[x]);
                let nrm = [
                    u[1] * v[2] - u[2] * v[1],
                    u[2] * v[0] - u[0] * v[2],
                    u[0] * v[1] - u[1] * v[0],
                ];
                let dir: f64 = (0..3).map(|x| nrm[x] * (cp[x] - cn[x])).sum();
                mesh.triangles.push(if dir >= 0.0 {
                    tri
                } else {
                    [tri[0], tri[2], tri[1]]
                });
            }
        }
    }
    (mesh, worst)
}

type PolyF = Vec<([usize; 3], f64)>;

fn to_f64_poly(p: &Poly3) -> PolyF {
    p.0.iter().map(|(e, v)| (*e, to_f64(v))).collect()
}

fn eval_f64(p: &PolyF, x: &[f64; 3]) -> f64 {
    p.iter()
        .map(|(e, v)| v * x[0].powi(e[0] as i32) * x[1].powi(e[1] as i32) * x[2].powi(e[2] as i32))
        .sum()
}

/// Builds O (X = id) and 𝒪 on the level-`n` lattices and compares their topology (L168).
pub fn isosurfaces(
    k: &TetComplex,
    maps: &[TetMap],
    f: &[Q],
    c: &Q,
    n: usize,
) -> Result<Isosurfaces, IsoError3> {
    if f.len() != k.points.len() {
        return Err(IsoError3::Length {
            given: f.len(),
            vertices: k.points.len(),
        });
    }
    if n == 0 || n > MAX_LEVEL {
        return Err(IsoError3::Level(n));
    }
    if let Some(v) = f.iter().position(|x| x == c) {
        return Err(IsoError3::LevelAtVertex {
            vertex: v,
            value: c.to_string(),
        });
    }
    let id: Vec<TetMap> = (0..k.tets.len())
        .map(|_| TetMap::bezier(1, fixed_control4(1), None))
        .collect();
    let (linear, lin_dev) = march(k, &id, f, c, n);
    let (curved, cur_dev) = march(k, maps, f, c, n);
    let (lt, ct) = (linear.topology(), curved.topology());
    let mut r = CheckResult::new(
        "SD-L168(3-D)",
        "Sec. 4: 𝒪 = (f̂∘X)⁻¹(c) has the topology of O (Euler characteristic, components, boundary loops)",
    );
    r.examined = curved.triangles.len() as u64;
    let key = |t: &Topology| (t.euler, t.components, t.boundary_loops, t.nonmanifold_edges);
    if key(&lt) != key(&ct) {
        r.offend(|| {
            Witness::new(
                format!(
                    "O: χ = {}, {} components, {} boundary loops; 𝒪: χ = {}, {} components, {} boundary loops (lattice level {n})",
                    lt.euler, lt.components, lt.boundary_loops, ct.euler, ct.components, ct.boundary_loops
                ),
                json!({"linear": lt, "curved": ct, "level": n}),
            )
        });
    }
    let bad_points = curved
        .points
        .iter()
        .filter(|p| p.iter().any(|x| !x.is_finite()))
        .count();
    if bad_points > 0 {
        r.offend(|| {
            Witness::new(
                format!("{bad_points} points of 𝒪 are not finite (D = 0 at a lattice point)"),
                json!({"non_finite_points": bad_points}),
            )
        });
    }
    if ct.nonmanifold_edges > 0 {
        let e = ct.nonmanifold_edges;
        r.offend(|| {
            Witness::new(
                format!("𝒪 has {e} edges in more than two triangles"),
                json!({"nonmanifold_edges": e}),
            )
        });
    }
    r.worst_deviation = Some(cur_dev);
    r.note = format!(
        "lattice level {n}; O: χ = {}, {} components, {} boundary loops, {} triangles; 𝒪: χ = {}, {} components, {} boundary loops, {} triangles; max |f̂∘X − c| at 𝒪's vertices {cur_dev:.3e} (O: {lin_dev:.3e}), measured: the marching-tetrahedra interpolation error, not a tolerance",
        lt.euler, lt.components, lt.boundary_loops, lt.faces, ct.euler, ct.components, ct.boundary_loops, ct.faces
    );
    if curved.triangles.is_empty() && linear.triangles.is_empty() {
        r.skip("the level set misses every tetrahedron");
    }
    Ok(Isosurfaces {
        linear,
        curved,
        linear_topology: lt,
        curved_topology: ct,
        report: vec![r],
    })
}
