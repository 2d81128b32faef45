//! The fitted surface: the (σ, v)-indexed PPS over the base mesh (seed 002, Part IV), its
//! shape functions ψ_(σ,v) fitted by least squares to the vertices of S_T (Part II, "Fit").
//!
//! **The rows of one corner's least-squares problem.** A vertex x of S_T whose parameter
//! (base face, barycentric coordinates) lies in the star of the base vertex v has a point
//! q ∈ P_v (the face's sector of T_v, the same barycentric coordinates), and for each corner
//! (σ, v) a local point p = f_(σ,v)⁻¹(q). Every x whose p lies in the corner's sample region
//! (the envelope triangle ∩ the disk of radius ρ, where the sampled fit of the construction
//! takes its samples) gives the row ψ(p) = x. To these, the construction's own samples of that
//! region are added with weight [`PRIOR_WEIGHT`], their data the flat base triangle: without
//! them a corner with fewer vertices of S_T than control points would be rank-deficient (a
//! choice, SPEC `AF-fit-rows`). The system is solved through its normal equations; rank and
//! condition number of the weighted design matrix are reported per corner
//! (SPEC `AF-fit-rank`).

use super::base::{permute, BaseMesh, Param};
use crate::construction::maps::P2;
use crate::mesh::raw::RawMesh;
use crate::mesh::validate::{validate, ErrorClass};
use crate::mesh::{FaceId, SimplicialSurface, VertexId};
use crate::surface::sigma_v::patch::{
    bernstein_tri, multinomials, num_control_points, tri_samples,
};
use crate::surface::sigma_v::{Corner, CornerId, SigmaVError, SigmaVPps};
use rayon::prelude::*;
use serde::Serialize;

/// Weight of the prior rows (the flat base triangle at the construction's samples).
pub const PRIOR_WEIGHT: f64 = 1e-2;

/// Why the base mesh gave no surface.
#[derive(Debug, Clone)]
pub enum BaseSurfaceError {
    /// The validator refused the base mesh: its classes, and the base faces (slots) named by
    /// the self-intersection witnesses.
    NotASurface {
        /// Defect classes.
        classes: Vec<ErrorClass>,
        /// Base face slots in the first witnesses of crossing triangles.
        crossing: Vec<u32>,
    },
    /// The (σ, v) construction refused it.
    SigmaV(SigmaVError),
}

/// The base mesh as a validated simplicial surface, with the maps between ids.
#[derive(Debug, Clone)]
pub struct BaseSurface {
    /// S̃_T (validated, Sec. 3.1).
    pub k: SimplicialSurface,
    /// Fine id of each base vertex (base vertex ids are 0..n).
    pub fine_of: Vec<u32>,
    /// Base face slot of each FaceId.
    pub slot_of: Vec<u32>,
    /// FaceId of each base face slot (u32::MAX for free slots).
    pub face_of_slot: Vec<u32>,
}

/// A parameter in the base surface's ids: face and barycentric coordinates in `k.face` order.
pub type SurfaceParam = (FaceId, [f64; 3]);

impl BaseSurface {
    /// Validate the base mesh (exactly, as every mesh: Sec. 3.1).
    pub fn new(base: &BaseMesh) -> Result<Self, BaseSurfaceError> {
        let fine_of = base.base_vertices();
        let mut id = vec![u32::MAX; base.positions().len()];
        for (i, &v) in fine_of.iter().enumerate() {
            id[v as usize] = i as u32;
        }
        let pos: Vec<[f64; 3]> = fine_of
            .iter()
            .map(|&v| base.positions()[v as usize])
            .collect();
        let (slots, faces): (Vec<u32>, Vec<[u32; 3]>) = base
            .faces()
            .map(|(s, c)| (s, c.map(|v| id[v as usize])))
            .unzip();
        let raw = RawMesh::from_arrays(pos, faces);
        let val = validate(&raw);
        let Some(k) = val.surface else {
            let mut crossing = Vec::new();
            for c in &val.report.checks {
                for w in &c.witnesses {
                    if let Some(fs) = w.data.get("faces").and_then(|f| f.as_array()) {
                        crossing.extend(
                            fs.iter()
                                .filter_map(|x| x.as_u64())
                                .filter_map(|i| slots.get(i as usize).copied()),
                        );
                    }
                }
            }
            return Err(BaseSurfaceError::NotASurface {
                classes: val.report.error_classes,
                crossing,
            });
        };
        let mut face_of_slot = vec![u32::MAX; slots.iter().max().map_or(0, |&m| m as usize + 1)];
        for (i, &s) in slots.iter().enumerate() {
            face_of_slot[s as usize] = i as u32;
        }
        Ok(BaseSurface {
            k,
            fine_of,
            slot_of: slots,
            face_of_slot,
        })
    }

    /// The parameter of every vertex of S_T in this surface's ids (the simplification's).
    pub fn params(&self, base: &BaseMesh) -> Vec<SurfaceParam> {
        self.params_of(base, base.params())
    }

    /// Parameters `ps` (base face slots) in this surface's ids.
    pub fn params_of(&self, base: &BaseMesh, ps: &[Param]) -> Vec<SurfaceParam> {
        let mut base_id = vec![u32::MAX; base.positions().len()];
        for (i, &v) in self.fine_of.iter().enumerate() {
            base_id[v as usize] = i as u32;
        }
        ps.iter()
            .enumerate()
            .map(|(x, p)| match *p {
                Param::Face { f, b } => {
                    // A slot that is no live face (a vertex no map reached): NaN, so the
                    // fit and AF-epsilon fail on it.
                    let Some(&id) = self
                        .face_of_slot
                        .get(f as usize)
                        .filter(|&&i| i != u32::MAX)
                    else {
                        return (FaceId(0), [f64::NAN; 3]);
                    };
                    let fid = FaceId(id);
                    let order = self.k.face(fid).map(|v| self.fine_of[v.idx()]);
                    (fid, permute(base.face(f).unwrap_or(order), b, order))
                }
                Param::Vertex => {
                    let v = VertexId(base_id[x]);
                    let f = self.k.faces_around(v)[0];
                    let c = self.k.face(f);
                    (f, c.map(|u| if u == v { 1.0 } else { 0.0 }))
                }
            })
            .collect()
    }
}

/// What the fitted ψ approximate (the PPS's target name).
pub const FIT_TARGET: &str = "fitted to S_T";

/// The point of the flat triangle `corners` of K at barycentric coordinates `b`: the data of
/// the prior rows.
fn flat(k: &SimplicialSurface, corners: [VertexId; 3], b: [f64; 3]) -> [f64; 3] {
    let p = corners.map(|v| k.position(v));
    std::array::from_fn(|i| b[0] * p[0][i] + b[1] * p[1][i] + b[2] * p[2][i])
}

/// A data row: corner id, local point, vertex of S_T.
type Row = (u32, [f64; 2], u32);

/// One corner's least-squares summary (SPEC `AF-fit-rank`).
#[derive(Debug, Clone, Copy, Serialize)]
pub struct CornerFit {
    /// Rows from vertices of S_T.
    pub data_rows: u32,
    /// Numerical rank of the weighted design matrix.
    pub rank: u32,
    /// Its condition number σ_max/σ_min.
    pub condition: f64,
}

/// The fitted PPS with the per-corner summaries.
pub struct Fitted {
    /// The PPS over the base surface.
    pub pps: SigmaVPps,
    /// Per corner (CornerId order).
    pub corners: Vec<CornerFit>,
    /// Vertices of S_T whose parameter eval refused (they give no row; counted, reported).
    pub eval_errors: u64,
}

/// Fit every ψ_(σ,v) of the (σ, v) PPS over `bs` to the vertices of S_T with parameters
/// `params` (module doc).
pub fn fit(
    bs: &BaseSurface,
    pos: &[[f64; 3]],
    params: &[SurfaceParam],
    kappa: f64,
    degree: usize,
) -> Result<Fitted, SigmaVError> {
    let k = &bs.k;
    let mut pps = SigmaVPps::unfitted(k, kappa, degree, FIT_TARGET)?;
    let d = pps.degree;
    let ncp = num_control_points(d);
    let coef = multinomials(d);
    let consts = pps.consts_f64();
    let g = &pps.gluing;
    // Rows: every vertex x of S_T at its parameter gives, for each corner j that θ blends
    // there, the row ψ_j(p_j) = x at the local point p_j where eval evaluates ψ_j.
    let rows: Vec<Result<Vec<Row>, SigmaVError>> = params
        .par_iter()
        .enumerate()
        .map(|(x, (f, b))| {
            let (i, q) = pps.eval_chart(*f, b, consts)?;
            Ok(pps
                .local_points(i, q.to_f64())?
                .into_iter()
                .map(|(j, p)| (j.0, p, x as u32))
                .collect())
        })
        .collect();
    let mut all: Vec<Row> = Vec::new();
    let mut eval_errors = 0u64;
    for r in rows {
        match r {
            Ok(v) => all.extend(v),
            Err(_) => eval_errors += 1,
        }
    }
    all.sort_by_key(|r| r.0);
    let mut start = vec![0usize; g.len() + 1];
    for r in &all {
        start[r.0 as usize + 1] += 1;
    }
    for i in 0..g.len() {
        start[i + 1] += start[i];
    }
    let ids: Vec<CornerId> = g.ids().collect();
    let results: Vec<(u32, Vec<[f64; 3]>, CornerFit)> = ids
        .par_iter()
        .map(|&id| {
            let c = g.corner(id).unwrap_or(Corner {
                v: VertexId(0),
                k: 0,
            });
            let (v, kk) = (c.v, c.k);
            let m = g.degree(v);
            let w = consts.wedge(m);
            let samples = tri_samples(w, d);
            let mut buf = vec![0.0; ncp];
            let mut ata = nalgebra::DMatrix::<f64>::zeros(ncp, ncp);
            let mut atb = nalgebra::DMatrix::<f64>::zeros(ncp, 3);
            let mut add = |l: [f64; 3], x: [f64; 3], wt: f64, buf: &mut Vec<f64>| {
                bernstein_tri(d, l, &coef, buf);
                for i in 0..ncp {
                    let bi = wt * wt * buf[i];
                    for j in 0..ncp {
                        ata[(i, j)] += bi * buf[j];
                    }
                    for c in 0..3 {
                        atb[(i, c)] += bi * x[c];
                    }
                }
            };
            for s in &samples {
                let sec = (kk + s.sector) % m;
                let corners = [v, g.link(v, sec), g.link(v, (sec + 1) % m)];
                let x = flat(k, corners, s.bary);
                let l = w.envelope_bary(&P2::new(s.p[0], s.p[1]));
                add(l, x, PRIOR_WEIGHT, &mut buf);
            }
            let mine = &all[start[id.0 as usize]..start[id.0 as usize + 1]];
            for (_, p, x) in mine {
                let l = w.envelope_bary(&P2::new(p[0], p[1]));
                add(l, pos[*x as usize], 1.0, &mut buf);
            }
            let eig = nalgebra::SymmetricEigen::new(ata.clone());
            let ev = &eig.eigenvalues;
            // NaN-propagating: a NaN eigenvalue makes the condition NaN, which AF-fit-rank fails.
            let emax = ev
                .iter()
                .cloned()
                .fold(0.0f64, crate::report::harness::dev_max);
            let emin = ev.iter().cloned().fold(f64::INFINITY, f64::min);
            let cut = emax * (ncp as f64) * f64::EPSILON;
            let rank = ev.iter().filter(|&&e| e > cut).count() as u32;
            let sol = ata
                .cholesky()
                .map(|ch| ch.solve(&atb))
                .unwrap_or_else(|| nalgebra::DMatrix::from_element(ncp, 3, f64::NAN));
            let cps: Vec<[f64; 3]> = (0..ncp)
                .map(|i| [sol[(i, 0)], sol[(i, 1)], sol[(i, 2)]])
                .collect();
            let info = CornerFit {
                data_rows: mine.len() as u32,
                rank,
                condition: if emin > 0.0 {
                    (emax / emin).sqrt()
                } else {
                    f64::INFINITY
                },
            };
            (id.0, cps, info)
        })
        .collect();
    let mut corners = vec![
        CornerFit {
            data_rows: 0,
            rank: 0,
            condition: f64::NAN
        };
        g.len()
    ];
    for (id, cps, info) in results {
        pps.patch_mut(CornerId(id)).copy_from_slice(&cps);
        corners[id as usize] = info;
    }
    Ok(Fitted {
        pps,
        corners,
        eval_errors,
    })
}
