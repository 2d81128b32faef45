//! Floater's parametrization of each curved triangle onto its base triangle (seed 002,
//! Part II: "we use Floater's parametrization to build the map for each 'curved' triangle";
//! "points where geodesics intersect edges of S_T are also mapped to T_v"). SPEC
//! `AF-param-bijective`, `AF-param-weights`.
//!
//! The tutorial does not say which of Floater's maps; the choice here is the mean value
//! coordinates (Floater 2003, "Mean value coordinates", CAGD 20): the weight of the overlay
//! edge i–j at an interior vertex i is (tan(α/2) + tan(β/2)) / ‖x_j − x_i‖, α and β the angles
//! at i of the two pieces beside the edge, computed in R³. They are positive for every piece
//! of positive area, so with the boundary mapped homeomorphically onto the (convex) base
//! triangle the map is one-to-one unless an edge joins two boundary points of one side
//! (Floater 2003, "One-to-one piecewise linear mappings over triangulations", Math. Comp. 72;
//! such a piece has area 0 and fails `AF-param-bijective`). The boundary: each curve is laid
//! on its side of the triangle by arc length, the corners on the corners.
//!
//! The base triangle of face (c0, c1, c2) is the reference triangle c0 = (0, 0), c1 = (1, 0),
//! c2 = (0, 1): a point (x, y) has barycentric coordinates (1 − x − y, x, y). Its map into
//! each T_v holding the face is affine and orientation-preserving (a positively oriented
//! sector), so a piece positive here is positive in every T_v.

use super::base::{BaseMesh, Param};
use super::geodesic::{dist, Embedding};
use super::overlay::Overlay;
use faer::sparse::linalg::solvers::SpSolver;
use faer::sparse::SparseColMat;
use faer::Mat;
use std::collections::{BTreeMap, HashMap};

/// One curved triangle mapped onto its base triangle.
#[derive(Debug, Clone)]
pub struct RegionMap {
    /// Base face slot.
    pub face: u32,
    /// Its pieces (indices into the overlay's pieces).
    pub pieces: Vec<usize>,
    /// Image (x, y) of every overlay vertex of the region in the reference triangle.
    pub uv: HashMap<u32, [f64; 2]>,
    /// Interior vertices solved for.
    pub interior: usize,
}

/// Why a curved triangle could not be mapped.
#[derive(Debug, Clone, thiserror::Error)]
pub enum FloaterError {
    /// The sparse solver refused the system of a face.
    #[error("base face {face}: the mean value system could not be solved: {reason}")]
    Solve {
        /// Base face slot.
        face: u32,
        /// The solver's message.
        reason: String,
    },
}

const CORNER: [[f64; 2]; 3] = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];

/// tan(α/2) of the angle at o between o→p and o→q (stable: |u×v| / (|u||v| + u·v)).
fn half_tan(o: [f64; 3], p: [f64; 3], q: [f64; 3]) -> f64 {
    let u = [p[0] - o[0], p[1] - o[1], p[2] - o[2]];
    let v = [q[0] - o[0], q[1] - o[1], q[2] - o[2]];
    let c = [
        u[1] * v[2] - u[2] * v[1],
        u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0],
    ];
    let nc = (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]).sqrt();
    let d = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
    let nu = (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]).sqrt();
    let nv = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    nc / (nu * nv + d)
}

/// Map every base face's region (the faces named by exactly one region) by mean value
/// coordinates (module doc).
pub fn map_regions(
    ov: &Overlay,
    base: &BaseMesh,
    emb: &Embedding,
) -> Result<Vec<RegionMap>, FloaterError> {
    map_regions_with(ov, base, emb, |_, _| None)
}

/// [`map_regions`], where `reuse(face, pieces)` may give a face's map instead (a curved
/// triangle that a refinement round did not change keeps its map, `super::local`); the other
/// faces are solved.
pub fn map_regions_with(
    ov: &Overlay,
    base: &BaseMesh,
    emb: &Embedding,
    mut reuse: impl FnMut(u32, &[usize]) -> Option<RegionMap>,
) -> Result<Vec<RegionMap>, FloaterError> {
    let mut pieces_of: Vec<Vec<usize>> = vec![Vec::new(); ov.regions];
    for (i, &r) in ov.region.iter().enumerate() {
        pieces_of[r as usize].push(i);
    }
    let mut out = Vec::new();
    for (r, f) in ov.face_of_region.iter().enumerate() {
        let Some(f) = *f else { continue };
        let Some(c) = base.face(f) else { continue };
        if let Some(m) = reuse(f, &pieces_of[r]) {
            out.push(m);
            continue;
        }
        let mut uv: HashMap<u32, [f64; 2]> = HashMap::new();
        for i in 0..3 {
            let (u, w) = (c[i], c[(i + 1) % 3]);
            uv.insert(u, CORNER[i]);
            let Some((curve, forward)) = emb.curve(u, w) else {
                continue;
            };
            let mut ids = ov.curve_ids[emb.index[&(curve.a, curve.b)]].clone();
            if !forward {
                ids.reverse();
            }
            let p = |id: u32| ov.points[id as usize];
            let mut acc = vec![0.0];
            for w in ids.windows(2) {
                let l = acc[acc.len() - 1] + dist(p(w[0]), p(w[1]));
                acc.push(l);
            }
            let total = acc[acc.len() - 1];
            let (a, b) = (CORNER[i], CORNER[(i + 1) % 3]);
            for (j, &id) in ids
                .iter()
                .enumerate()
                .skip(1)
                .take(ids.len().saturating_sub(2))
            {
                let s = acc[j] / total;
                uv.insert(id, [a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1])]);
            }
        }
        let pieces = pieces_of[r].clone();
        // Interior vertices and their weights.
        let mut row: HashMap<u32, usize> = HashMap::new();
        // Ordered: the sums into the diagonal and the right-hand side, and the triplets' order,
        // must not follow a hash map's per-process random order (the fit would differ in its
        // last bits from run to run).
        let mut w: BTreeMap<(usize, u32), f64> = BTreeMap::new();
        for &pi in &pieces {
            let v = ov.pieces[pi].v;
            for j in 0..3 {
                let (o, p, q) = (v[j], v[(j + 1) % 3], v[(j + 2) % 3]);
                if uv.contains_key(&o) {
                    continue;
                }
                let n = row.len();
                let i = *row.entry(o).or_insert(n);
                let (xo, xp, xq) = (
                    ov.points[o as usize],
                    ov.points[p as usize],
                    ov.points[q as usize],
                );
                let t = half_tan(xo, xp, xq);
                *w.entry((i, p)).or_default() += t / dist(xo, xp);
                *w.entry((i, q)).or_default() += t / dist(xo, xq);
            }
        }
        let n = row.len();
        if n > 0 {
            let mut trip = Vec::new();
            let mut rhs = Mat::<f64>::zeros(n, 2);
            let mut diag = vec![0.0; n];
            for (&(i, j), &wij) in &w {
                diag[i] += wij;
                match row.get(&j) {
                    Some(&jj) => trip.push((i, jj, -wij)),
                    None => {
                        let b = uv.get(&j).copied().unwrap_or([f64::NAN; 2]);
                        rhs.write(i, 0, rhs.read(i, 0) + wij * b[0]);
                        rhs.write(i, 1, rhs.read(i, 1) + wij * b[1]);
                    }
                }
            }
            trip.extend(diag.iter().enumerate().map(|(i, &d)| (i, i, d)));
            let err = |reason: String| FloaterError::Solve { face: f, reason };
            let mat = SparseColMat::<usize, f64>::try_new_from_triplets(n, n, &trip)
                .map_err(|e| err(format!("{e:?}")))?;
            let lu = mat.sp_lu().map_err(|e| err(format!("{e:?}")))?;
            lu.solve_in_place(rhs.as_mut());
            for (&id, &i) in &row {
                uv.insert(id, [rhs.read(i, 0), rhs.read(i, 1)]);
            }
        }
        out.push(RegionMap {
            face: f,
            pieces,
            uv,
            interior: n,
        });
    }
    Ok(out)
}

/// The parameter of every vertex of S_T from the maps: a base vertex is `Vertex`; a vertex
/// of S_T inside a curved triangle, or on a curve (then in the face left of the curve's
/// direction a → b), gets its face and (1 − x − y, x, y). A vertex no map reaches keeps
/// NaN coordinates (so the fit and `AF-epsilon` fail on it, never silently).
pub fn params(maps: &[RegionMap], base: &BaseMesh, emb: &Embedding, n: usize) -> Vec<Param> {
    let mut out: Vec<Param> = (0..n as u32)
        .map(|x| {
            if base.is_base(x) {
                Param::Vertex
            } else {
                Param::Face {
                    f: 0,
                    b: [f64::NAN; 3],
                }
            }
        })
        .collect();
    // A vertex node of a curve is mapped by both faces beside it: the face left of a → b.
    let mut left: HashMap<u32, u32> = HashMap::new();
    for c in &emb.curves {
        if let Some(f) = base.face_of_edge(c.a, c.b) {
            for node in &c.nodes {
                if let super::geodesic::Node::Vertex(x) = *node {
                    left.insert(x, f);
                }
            }
        }
    }
    for m in maps {
        for (&id, &[x, y]) in &m.uv {
            let i = id as usize;
            if i >= n || base.is_base(id) {
                continue;
            }
            if left.get(&id).map_or(true, |&f| f == m.face) {
                out[i] = Param::Face {
                    f: m.face,
                    b: [1.0 - x - y, x, y],
                };
            }
        }
    }
    out
}
