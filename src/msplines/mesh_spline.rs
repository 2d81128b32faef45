//! Secs. 5.5–5.6 on a mesh: knots assigned on M, control points per face (DMS: C(k+2,2)
//! per triangle, not shared), and the manifold spline F evaluated in any chart of the
//! Sec. 5.4 atlas by the DMS basis of [`super::dms`].
//!
//! Reading choices (SPEC `MS-5.5`, `MS-5.6`):
//! - Knot clouds (eq. (1)) are defined on M directly (Def. 13): t_{v,0} = v and t_{v,l},
//!   l = 1..k, seeded generic points of distinct faces of the open star of v. The paper's
//!   "uniform subdivision" of L473 does not give DMS control points.
//! - Sec. 5.5 (1)–(2): the knots of face I's control points are recorded in one chart
//!   covering I (the first chart, in vertex order of I, that contains every knot of I).
//! - Sec. 5.6 (1)–(4): F(p) for p in face F is evaluated in a chart γ covering F; the
//!   recorded knots of every face J of the 1-ring of F (Sec. 3.1.3(1)) are converted to γ by
//!   the translation φ_γ − φ_home on J (eq. (6) corrected, `MS-5.4(6)-corrected`), which is
//!   defined only when J's knots lie in U_γ.
//! - Control points c_β^I: the mean of the positions in ℝ³ of the knots X_β^I (eq. (2)), the
//!   blossom of the embedding where it is affine, so F approximates M.
//!
//! Charts: the k-ring charts of Sec. 5.4 with ring 3, the smallest ring whose chart at a
//! vertex of F holds every knot the 1-ring of F needs.

use super::atlas::{Atlas, P2};
use super::dms::{Dms, DmsError};
use super::polar::multi_indices;
use crate::mesh::{FaceId, SimplicialSurface, VertexId};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::collections::{BTreeSet, HashMap};

/// A point of M: a face and barycentric coordinates at its corners (file order).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct MeshPoint {
    /// The face.
    pub face: FaceId,
    /// Barycentric coordinates.
    pub bary: [f64; 3],
}

/// Why F cannot be evaluated at a point in a chart.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SplineError {
    /// The chart does not contain the face of the point.
    #[error("face {face} is not in chart {chart} (centre vertex {centre})")]
    FaceNotInChart {
        /// The face.
        face: u32,
        /// The chart.
        chart: u32,
        /// Its centre p_α.
        centre: u32,
    },
    /// A knot needed on F lies outside the chart (its transition is undefined there).
    #[error("knot of face {knot_face} (used by face {by}) lies outside chart {chart} (centre vertex {centre}): φ_γ of it is undefined")]
    KnotOutsideChart {
        /// Face carrying the knot.
        knot_face: u32,
        /// The face J whose control points use it.
        by: u32,
        /// The chart.
        chart: u32,
        /// Its centre.
        centre: u32,
    },
    /// No chart covers face J together with its knots (Sec. 5.5 (1) cannot record them):
    /// near a zero, whose faces were removed (Sec. 5.4 step 2).
    #[error("face {face}: no chart contains it and all its knots (Sec. 5.5 (1)); a removed face near a zero point is involved")]
    NoHomeChart {
        /// The face.
        face: u32,
    },
    /// No chart at the corners of the face can evaluate it.
    #[error("face {face}: no chart at its corners holds the knots of its 1-ring")]
    NoChart {
        /// The face.
        face: u32,
    },
    /// The DMS basis is undefined (degenerate knots).
    #[error(transparent)]
    Dms(#[from] DmsError),
}

/// The value of F at a point, with Σ N (partition of unity) and what the evaluation used.
#[derive(Debug, Clone)]
pub struct Evaluation {
    /// F(p) ∈ ℝ³.
    pub value: [f64; 3],
    /// Σ_J Σ_β N_β^J(u).
    pub sum_n: f64,
    /// Σ_J Σ_β |c_β^J|_∞ over the basis functions non-zero at u.
    pub control_mass: f64,
    /// Smallest height of a knot triangle of the V_β^J used (first-order sensitivity).
    pub min_height: f64,
    /// Largest |coordinate| of the chart data used.
    pub radius: f64,
}

/// Secs. 5.5–5.6: the knots, control points and recorded charts.
#[derive(Debug, Clone)]
pub struct MeshSpline {
    /// Degree k.
    pub k: usize,
    /// Knot cloud of each vertex (index = vertex id).
    pub clouds: Vec<Vec<MeshPoint>>,
    /// c_β^I per face, β in `multi_indices(k)` order.
    pub control: Vec<Vec<[f64; 3]>>,
    /// Sec. 5.5 (2): the chart id where face I's knots are recorded.
    pub home: Vec<Option<u32>>,
    /// The corner clouds of face I in its home chart.
    pub recorded: Vec<Option<[Vec<P2>; 3]>>,
    /// Chart id of each vertex's chart.
    pub chart_of_vertex: HashMap<VertexId, u32>,
    /// Planted fault: the knots of this face are not converted to the evaluation chart
    /// (Sec. 5.6 step (3) skipped).
    pub planted_unconverted: Option<FaceId>,
    /// Sec. 5.6 step (3) literally: convert face J's recorded knots by the translation
    /// φ_γ − φ_home measured on J (one knot then has slightly different f64 images for
    /// different J). Off by default: each knot of M is mapped into U_γ once, the same map
    /// up to rounding; both readings are tested.
    pub convert_by_translation: bool,
}

fn pos3(k: &SimplicialSurface, p: &MeshPoint) -> [f64; 3] {
    let vs = k.face(p.face);
    let mut x = [0.0; 3];
    for (i, v) in vs.iter().enumerate() {
        let q = k.position(*v);
        for (a, qa) in x.iter_mut().zip(q) {
            *a += p.bary[i] * qa;
        }
    }
    x
}

/// The image of a point of M in chart α (affine on the face), if the face is in U_α.
pub fn image(at: &Atlas, alpha: u32, p: &MeshPoint) -> Option<P2> {
    let t = at.charts.get(alpha as usize)?.faces.get(&p.face)?;
    Some([
        p.bary[0] * t[0][0] + p.bary[1] * t[1][0] + p.bary[2] * t[2][0],
        p.bary[0] * t[0][1] + p.bary[1] * t[1][1] + p.bary[2] * t[2][1],
    ])
}

/// Faces sharing a vertex with f (the 1-ring of Sec. 3.1.3(1)), f included.
pub fn face_ring(k: &SimplicialSurface, f: FaceId) -> Vec<FaceId> {
    let s: BTreeSet<FaceId> = k
        .face(f)
        .iter()
        .flat_map(|&v| k.faces_around(v).iter().copied())
        .collect();
    s.into_iter().collect()
}

/// Sec. 5.5: knot clouds on M (seeded, generic), control points, and the recorded charts.
pub fn assign(k: &SimplicialSurface, at: &Atlas, degree: usize, seed: u64) -> MeshSpline {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut clouds = vec![Vec::new(); k.vertex_slots()];
    for v in k.vertices() {
        let star = k.faces_around(v);
        let mut c = Vec::new();
        if let Some(&f0) = star.first() {
            let at_v = |f: FaceId| k.face(f).iter().position(|&x| x == v).unwrap_or(0);
            let mut b = [0.0; 3];
            b[at_v(f0)] = 1.0;
            c.push(MeshPoint { face: f0, bary: b });
            // Knot l in face (o + l·⌊deg/k⌋) of the star: distinct faces, so the knots are
            // distinct (eq. (1)) and no two are collinear with v by construction.
            let o = rng.gen_range(0..star.len());
            let step = (star.len() / degree.max(1)).max(1);
            for l in 1..=degree {
                let f = star[(o + l * step) % star.len()];
                let i = at_v(f);
                // Weights in (1/16, 5/16): inside the open star of v.
                let (s, r) = (rng.gen_range(0.0625..0.3125), rng.gen_range(0.0625..0.3125));
                let mut b = [0.0; 3];
                b[i] = 1.0 - s - r;
                b[(i + 1) % 3] = s;
                b[(i + 2) % 3] = r;
                c.push(MeshPoint { face: f, bary: b });
            }
        }
        clouds[v.idx()] = c;
    }
    let betas = multi_indices(degree);
    let mut control = Vec::with_capacity(k.num_faces());
    for f in k.faces() {
        let vs = k.face(f);
        control.push(
            betas
                .iter()
                .map(|b| {
                    let xs: Vec<[f64; 3]> = (0..3)
                        .flat_map(|c| clouds[vs[c].idx()].iter().take(b[c]))
                        .map(|p| pos3(k, p))
                        .collect();
                    let n = xs.len().max(1) as f64;
                    let mut m = [0.0; 3];
                    for x in &xs {
                        for a in 0..3 {
                            m[a] += x[a] / n;
                        }
                    }
                    m
                })
                .collect(),
        );
    }
    let chart_of_vertex: HashMap<VertexId, u32> = at
        .charts
        .iter()
        .enumerate()
        .map(|(a, c)| (c.centre, a as u32))
        .collect();
    let mut sp = MeshSpline {
        k: degree,
        clouds,
        control,
        home: vec![None; k.num_faces()],
        recorded: vec![None; k.num_faces()],
        chart_of_vertex,
        planted_unconverted: None,
        convert_by_translation: false,
    };
    sp.record(k, at);
    sp
}

impl MeshSpline {
    /// Sec. 5.5 (1)–(2): record each face's knots in the first chart at its corners that
    /// holds them all (again after the clouds changed).
    pub fn record(&mut self, k: &SimplicialSurface, at: &Atlas) {
        for f in k.faces() {
            self.home[f.idx()] = None;
            self.recorded[f.idx()] = None;
            for v in k.face(f) {
                let Some(&alpha) = self.chart_of_vertex.get(&v) else {
                    continue;
                };
                if let Ok(rec) = self.corner_clouds_in(k, at, f, alpha) {
                    self.home[f.idx()] = Some(alpha);
                    self.recorded[f.idx()] = Some(rec);
                    break;
                }
            }
        }
    }

    /// The corner clouds of face J mapped into chart α (every knot must lie in U_α).
    pub fn corner_clouds_in(
        &self,
        k: &SimplicialSurface,
        at: &Atlas,
        j: FaceId,
        alpha: u32,
    ) -> Result<[Vec<P2>; 3], SplineError> {
        let vs = k.face(j);
        let mut out: [Vec<P2>; 3] = Default::default();
        for c in 0..3 {
            for p in &self.clouds[vs[c].idx()] {
                let img = image(at, alpha, p).ok_or(SplineError::KnotOutsideChart {
                    knot_face: p.face.0,
                    by: j.0,
                    chart: alpha,
                    centre: at.charts[alpha as usize].centre.0,
                })?;
                out[c].push(img);
            }
        }
        Ok(out)
    }

    /// Sec. 5.6 (1)–(4): F(p) evaluated in chart γ.
    pub fn evaluate(
        &self,
        k: &SimplicialSurface,
        at: &Atlas,
        p: &MeshPoint,
        gamma: u32,
    ) -> Result<Evaluation, SplineError> {
        let ch = &at.charts[gamma as usize];
        let u = image(at, gamma, p).ok_or(SplineError::FaceNotInChart {
            face: p.face.0,
            chart: gamma,
            centre: ch.centre.0,
        })?;
        let betas = multi_indices(self.k);
        let mut ev = Evaluation {
            value: [0.0; 3],
            sum_n: 0.0,
            control_mass: 0.0,
            min_height: f64::INFINITY,
            radius: u[0].abs().max(u[1].abs()),
        };
        for j in face_ring(k, p.face) {
            let (Some(home), Some(rec)) = (self.home[j.idx()], &self.recorded[j.idx()]) else {
                return Err(SplineError::NoHomeChart { face: j.0 });
            };
            // Step (3): the transition is defined on U_γ ∩ U_home only, and the knots on M
            // map into U_γ directly (one image per knot, shared by every J using it).
            self.corner_clouds_in(k, at, j, gamma)?;
            let (Some(tg), Some(th)) = (ch.faces.get(&j), at.charts[home as usize].faces.get(&j))
            else {
                return Err(SplineError::FaceNotInChart {
                    face: j.0,
                    chart: gamma,
                    centre: ch.centre.0,
                });
            };
            let clouds: Vec<Vec<P2>> = if self.planted_unconverted == Some(j) {
                rec.to_vec()
            } else if self.convert_by_translation {
                let tau = [tg[0][0] - th[0][0], tg[0][1] - th[0][1]];
                rec.iter()
                    .map(|c| c.iter().map(|x| [x[0] + tau[0], x[1] + tau[1]]).collect())
                    .collect()
            } else {
                self.corner_clouds_in(k, at, j, gamma)?.to_vec()
            };
            for x in clouds.iter().flatten() {
                ev.radius = ev.radius.max(x[0].abs()).max(x[1].abs());
            }
            let dms = Dms {
                k: self.k,
                clouds,
                triangles: vec![[0, 1, 2]],
                overrides: Default::default(),
                planted: Default::default(),
            };
            for (bi, b) in betas.iter().enumerate() {
                let n = dms.basis(0, b, &u)?;
                if n == 0.0 {
                    continue;
                }
                let c = self.control[j.idx()][bi];
                for (x, ca) in ev.value.iter_mut().zip(c) {
                    *x += ca * n;
                }
                ev.sum_n += n;
                ev.control_mass += c.iter().fold(0.0f64, |m, x| m.max(x.abs()));
                let (v, _) = dms.v_beta(0, b)?;
                ev.min_height = ev.min_height.min(min_height(&v));
            }
        }
        Ok(ev)
    }

    /// Sec. 3.1.3(1) on M: Σ |N_β^J(u)| over the faces J of the 2-ring of p's face that are
    /// not in its 1-ring (those whose knots chart γ holds), and how many were evaluated. The
    /// evaluation above sums the 1-ring only; this is the mass it leaves out.
    pub fn outside_ring_mass(
        &self,
        k: &SimplicialSurface,
        at: &Atlas,
        p: &MeshPoint,
        gamma: u32,
    ) -> Result<(f64, usize), SplineError> {
        let u = image(at, gamma, p).ok_or(SplineError::FaceNotInChart {
            face: p.face.0,
            chart: gamma,
            centre: at.charts[gamma as usize].centre.0,
        })?;
        let ring1: BTreeSet<FaceId> = face_ring(k, p.face).into_iter().collect();
        let ring2: BTreeSet<FaceId> = ring1.iter().flat_map(|&j| face_ring(k, j)).collect();
        let (mut mass, mut n) = (0.0, 0usize);
        for j in ring2.difference(&ring1) {
            let Ok(clouds) = self.corner_clouds_in(k, at, *j, gamma) else {
                continue;
            };
            let dms = Dms {
                k: self.k,
                clouds: clouds.to_vec(),
                triangles: vec![[0, 1, 2]],
                overrides: Default::default(),
                planted: Default::default(),
            };
            for b in multi_indices(self.k) {
                mass += dms.basis(0, &b, &u)?.abs();
                n += 1;
            }
        }
        Ok((mass, n))
    }

    /// F(p) in the first chart at a corner of p's face that can evaluate it.
    pub fn evaluate_anywhere(
        &self,
        k: &SimplicialSurface,
        at: &Atlas,
        p: &MeshPoint,
    ) -> Result<Evaluation, SplineError> {
        let mut last = SplineError::NoChart { face: p.face.0 };
        for v in k.face(p.face) {
            if let Some(&g) = self.chart_of_vertex.get(&v) {
                match self.evaluate(k, at, p, g) {
                    Ok(e) => return Ok(e),
                    Err(e) => last = e,
                }
            }
        }
        Err(last)
    }
}

/// min over non-degenerate triples of V of 2·area / longest edge (a triangle's least height).
fn min_height(v: &[P2]) -> f64 {
    let mut h = f64::INFINITY;
    for a in 0..v.len() {
        for b in a + 1..v.len() {
            for c in b + 1..v.len() {
                let d = ((v[b][0] - v[a][0]) * (v[c][1] - v[a][1])
                    - (v[c][0] - v[a][0]) * (v[b][1] - v[a][1]))
                    .abs();
                let e = [(a, b), (b, c), (a, c)]
                    .iter()
                    .map(|&(x, y)| (v[x][0] - v[y][0]).hypot(v[x][1] - v[y][1]))
                    .fold(0.0f64, f64::max);
                if d > 0.0 && e > 0.0 {
                    h = h.min(d / e);
                }
            }
        }
    }
    h
}

#[cfg(test)]
mod tests {
    use super::min_height;

    /// The least height of the knot triangles: 2·area over the longest edge, least over every
    /// non-degenerate triple.
    #[test]
    fn min_height_is_twice_the_area_over_the_longest_edge() {
        // hypot need not round as sqrt does: a few ulps.
        let close = |a: f64, b: f64| (a - b).abs() <= 4.0 * f64::EPSILON * b;
        let right = [[0.0, 0.0], [2.0, 0.0], [0.0, 1.0]];
        assert!(close(min_height(&right), 2.0 / 5f64.sqrt()));
        // A fourth point: the least height is the flattest triple's, (2,0), (0,1), (1,1/4),
        // 2·area 1/2 over the edge √5.
        let four = [[0.0, 0.0], [2.0, 0.0], [0.0, 1.0], [1.0, 0.25]];
        assert!(close(min_height(&four), 0.5 / 5f64.sqrt()));
        // A collinear triple has no height and is passed over.
        assert_eq!(
            min_height(&[[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]]),
            f64::INFINITY
        );
    }
}
