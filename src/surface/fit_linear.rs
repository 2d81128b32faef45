//! The fit of Sec. 5.2 for targets that are linear in the vertex positions
//! ([`LinearTarget`], the Loop limit surface): X_v = A⁺ D_v with D_v the samples of S′, and
//! on sector i the samples are W_i P (W_i the weights of the sector's samples over the face's
//! stencil, P its positions), so X_v = Σ_i (A⁺_i W_i) P_i. The matrix A⁺_i W_i depends only on
//! (degree, sector, stencil key): it is computed once per key, from the first vertex (in the
//! storage order) that has it, so the result does not depend on the thread schedule.

use super::fit::DegreeFit;
use super::target::{FaceStencil, LinearTarget};
use crate::mesh::{FaceId, SimplicialSurface, VertexId};
use rayon::prelude::*;
use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hasher};

/// FNV-1a: the keys are ~30 small integers hashed ~300k times per construction, where std's
/// SipHash (DoS-resistant, not needed for keys derived from K) showed in profiles; no
/// non-cryptographic hasher crate is among the dependencies, and this is ten lines.
#[derive(Default)]
struct Fnv1a(u64);

impl Hasher for Fnv1a {
    fn finish(&self) -> u64 {
        self.0
    }
    fn write(&mut self, bytes: &[u8]) {
        let mut h = if self.0 == 0 {
            0xcbf2_9ce4_8422_2325
        } else {
            self.0
        };
        for &b in bytes {
            h = (h ^ b as u64).wrapping_mul(0x0100_0000_01b3);
        }
        self.0 = h;
    }
}

/// One vertex to fit: its id, its label offset and its control points (written in place).
pub(super) type Job<'a> = (VertexId, u32, &'a mut [[f64; 3]]);

/// A sector of a vertex: its face, corners (v, a, b), where its key and stencil vertices
/// lie in the vertex's [`Sectors`] and the hash of its key.
struct Sector {
    face: FaceId,
    corners: [VertexId; 3],
    key: std::ops::Range<usize>,
    verts: std::ops::Range<usize>,
    hash: u64,
}

/// The sectors of one vertex, their keys and stencil vertices in two shared buffers (one
/// allocation each per vertex instead of two per sector).
struct Sectors {
    list: Vec<Sector>,
    keys: Vec<u32>,
    verts: Vec<VertexId>,
}

impl Sectors {
    fn key(&self, s: &Sector) -> &[u32] {
        &self.keys[s.key.clone()]
    }
    fn verts(&self, s: &Sector) -> &[VertexId] {
        &self.verts[s.verts.clone()]
    }
}

/// What a matrix A⁺_i W_i depends on: the degree's fit, the sector and the stencil key (its
/// hash computed once, in parallel).
#[derive(PartialEq, Eq)]
struct MatrixKey<'a> {
    fit: usize,
    sector: usize,
    key: &'a [u32],
    hash: u64,
}

impl std::hash::Hash for MatrixKey<'_> {
    fn hash<H: Hasher>(&self, state: &mut H) {
        state.write_u64(self.hash);
    }
}

fn key_hash(fit: usize, sector: usize, key: &[u32]) -> u64 {
    let mut h = Fnv1a::default();
    h.write_u64(fit as u64);
    h.write_u64(sector as u64);
    for &x in key {
        h.write_u32(x);
    }
    h.finish()
}

/// Fits the vertices of `jobs` (all of degree `fit.info.m`, one entry of `fits` each);
/// returns the jobs the linear form could not serve (the caller samples S′ for them).
pub(super) fn fit_linear<'a>(
    k: &SimplicialSurface,
    lin: &dyn LinearTarget,
    fits: &[DegreeFit],
    jobs: Vec<(usize, Job<'a>)>,
) -> Vec<(usize, Job<'a>)> {
    // The sectors of every vertex, with their stencils.
    let sectors: Vec<Option<Sectors>> = jobs
        .par_iter()
        .map_init(
            || FaceStencil {
                key: Vec::new(),
                verts: Vec::new(),
            },
            |st, (fi, (v, off, _))| {
                let m = k.degree(*v);
                let outgoing = k.outgoing(*v);
                let mut out = Sectors {
                    list: Vec::with_capacity(m as usize),
                    keys: Vec::with_capacity(24 * m as usize),
                    verts: Vec::with_capacity(14 * m as usize),
                };
                for i in 0..m {
                    let h = outgoing[((i + off) % m) as usize];
                    let a = k.dest(h);
                    let b = k.dest(outgoing[((i + off + 1) % m) as usize]);
                    let face = k.face_of(h);
                    let corners = [*v, a, b];
                    lin.stencil_into(k, face, corners, st)?;
                    let key = out.keys.len()..out.keys.len() + st.key.len();
                    let verts = out.verts.len()..out.verts.len() + st.verts.len();
                    out.keys.extend_from_slice(&st.key);
                    out.verts.extend_from_slice(&st.verts);
                    let hash = key_hash(*fi, i as usize, &st.key);
                    out.list.push(Sector {
                        face,
                        corners,
                        key,
                        verts,
                        hash,
                    });
                }
                Some(out)
            },
        )
        .collect();
    // One representative per (fit, sector, key), in job order.
    let mut keys: HashMap<MatrixKey, usize, BuildHasherDefault<Fnv1a>> = HashMap::default();
    let mut reps: Vec<(usize, usize, &Sectors, &Sector)> = Vec::new();
    let mut slot: Vec<Option<Vec<usize>>> = Vec::with_capacity(jobs.len());
    for ((fi, _), secs) in jobs.iter().zip(&sectors) {
        slot.push(secs.as_ref().map(|secs| {
            secs.list
                .iter()
                .enumerate()
                .map(|(i, s)| {
                    let key = MatrixKey {
                        fit: *fi,
                        sector: i,
                        key: secs.key(s),
                        hash: s.hash,
                    };
                    *keys.entry(key).or_insert_with(|| {
                        reps.push((*fi, i, secs, s));
                        reps.len() - 1
                    })
                })
                .collect()
        }));
    }
    let by_sector: Vec<Vec<Vec<usize>>> = fits
        .iter()
        .map(|fit| {
            let mut s = vec![Vec::new(); fit.info.m as usize];
            for (j, sample) in fit.samples.iter().enumerate() {
                if let Some(list) = s.get_mut(sample.sector as usize) {
                    list.push(j);
                }
            }
            s
        })
        .collect();
    // A⁺ restricted to each sector's samples, transposed (n_i × kk).
    let pinv_t: Vec<Vec<Vec<f64>>> = fits
        .iter()
        .zip(&by_sector)
        .map(|(fit, secs)| {
            let (n, kk) = (fit.samples.len(), fit.info.unknowns);
            secs.iter()
                .map(|idx| {
                    let mut t = vec![0.0; idx.len() * kk];
                    for (s, &j) in idx.iter().enumerate() {
                        for row in 0..kk {
                            t[s * kk + row] = fit.pinv[row * n + j];
                        }
                    }
                    t
                })
                .collect()
        })
        .collect();
    // M_i stored transposed (|stencil| × kk), so the products run along kk.
    let mats: Vec<Option<Vec<f64>>> = reps
        .par_iter()
        .map(|&(fi, i, secs, s)| {
            let fit = &fits[fi];
            let idx = by_sector[fi].get(i)?;
            let at = pinv_t[fi].get(i)?;
            let barys: Vec<[f64; 3]> = idx.iter().map(|&j| fit.samples[j].bary).collect();
            let w = lin.weights(s.face, s.corners, secs.verts(s), &barys)?;
            let (kk, len) = (fit.info.unknowns, s.verts.len());
            let mut m = vec![0.0; kk * len];
            for s in 0..idx.len() {
                let a = &at[s * kk..(s + 1) * kk];
                for (col, &wv) in w[s * len..(s + 1) * len].iter().enumerate() {
                    if wv == 0.0 {
                        continue;
                    }
                    for (o, x) in m[col * kk..(col + 1) * kk].iter_mut().zip(a) {
                        *o += x * wv;
                    }
                }
            }
            Some(m)
        })
        .collect();
    // Vertices whose sectors have the same matrices (e.g. every vertex of one degree whose
    // neighbours are regular) share the merged matrix Σ_i M_i over the union of their stencils
    // when their stencils also meet the same way (the same layout): it is summed once.
    let mut groups: HashMap<(usize, &[usize]), usize, BuildHasherDefault<Fnv1a>> =
        HashMap::default();
    let mut members: Vec<usize> = Vec::new();
    let group_of: Vec<Option<usize>> = jobs
        .iter()
        .zip(&slot)
        .map(|((fi, _), sl)| {
            let sl = sl.as_deref()?;
            let g = *groups.entry((*fi, sl)).or_insert_with(|| {
                members.push(0);
                members.len() - 1
            });
            members[g] += 1;
            Some(g)
        })
        .collect();
    let mut first: Vec<Option<usize>> = vec![None; members.len()];
    for (j, g) in group_of.iter().enumerate() {
        if let Some(g) = *g {
            first[g].get_or_insert(j);
        }
    }
    let shared: Vec<Option<Shared>> = first
        .par_iter()
        .zip(&members)
        .map_init(Scratch::default, |scratch, (rep, &count)| {
            let rep = (*rep)?;
            if count < SHARE_MIN {
                return None;
            }
            let (secs, sl) = (sectors[rep].as_ref()?, slot[rep].as_ref()?);
            let kk = fits[jobs[rep].0].info.unknowns;
            union_layout(secs, &mut scratch.union, &mut scratch.places);
            merge(secs, sl, &mats, kk, scratch)?;
            Some(Shared {
                places: scratch.places.clone(),
                merged: scratch.merged.clone(),
            })
        })
        .collect();
    // X_v = Σ_i M_i P_i.
    jobs.into_par_iter()
        .zip(sectors)
        .zip(slot)
        .zip(group_of)
        .map_init(Scratch::default, |scratch, (((job, secs), slot), g)| {
            let (fi, (v, off, out)) = job;
            let (Some(secs), Some(slot)) = (secs, slot) else {
                return Some((fi, (v, off, out)));
            };
            let kk = fits[fi].info.unknowns;
            let shared = g.and_then(|g| shared[g].as_ref());
            let served = apply(lin, &secs, &slot, &mats, shared, kk, out, scratch);
            (!served).then_some((fi, (v, off, out)))
        })
        .flatten()
        .collect()
}

/// Vertices with the same matrices share their merged matrix from this many on: from two
/// on, one sum and a copy read less memory than two sums (koala: merge time −25 %).
const SHARE_MIN: usize = 2;

/// The merged matrix of a group of vertices and the layout it was summed for.
struct Shared {
    places: Vec<u32>,
    merged: Vec<f64>,
}

/// Per-thread buffers of [`apply`].
#[derive(Default)]
struct Scratch {
    union: Vec<VertexId>,
    places: Vec<u32>,
    merged: Vec<f64>,
    acc: Vec<f64>,
}

/// The union of the sectors' stencils (in order of first appearance) and, for every column of
/// every sector's stencil, its place in the union.
fn union_layout(secs: &Sectors, union: &mut Vec<VertexId>, places: &mut Vec<u32>) {
    union.clear();
    places.clear();
    for s in &secs.list {
        for &u in secs.verts(s) {
            let at = match union.iter().position(|&x| x == u) {
                Some(p) => p,
                None => {
                    union.push(u);
                    union.len() - 1
                }
            };
            places.push(at as u32);
        }
    }
}

/// Σ_i M_i summed into `scratch.merged` over the union laid out in `scratch.places`; `None`
/// when a matrix is missing.
fn merge(
    secs: &Sectors,
    slot: &[usize],
    mats: &[Option<Vec<f64>>],
    kk: usize,
    scratch: &mut Scratch,
) -> Option<()> {
    let Scratch {
        union,
        places,
        merged,
        ..
    } = scratch;
    merged.clear();
    merged.resize(union.len() * kk, 0.0);
    let mut at = places.iter();
    for (s, &r) in secs.list.iter().zip(slot) {
        let m = mats.get(r)?.as_ref()?;
        for col in m.chunks_exact(kk).take(s.verts.len()) {
            let p = *at.next()? as usize;
            for (g, w) in merged[p * kk..(p + 1) * kk].iter_mut().zip(col) {
                *g += w;
            }
        }
    }
    Some(())
}

/// out = Σ_i M_i P_i, the M_i first summed into one matrix over the union of the sectors'
/// stencils (neighbouring sectors share most vertices, so this halves the products), or taken
/// from `shared` when its layout is this vertex's; false (out untouched) when a matrix or a
/// position is missing.
#[allow(clippy::too_many_arguments)]
fn apply(
    lin: &dyn LinearTarget,
    secs: &Sectors,
    slot: &[usize],
    mats: &[Option<Vec<f64>>],
    shared: Option<&Shared>,
    kk: usize,
    out: &mut [[f64; 3]],
    scratch: &mut Scratch,
) -> bool {
    if out.len() != kk {
        return false;
    }
    union_layout(secs, &mut scratch.union, &mut scratch.places);
    let merged: &[f64] = match shared {
        Some(sh) if sh.places == scratch.places && sh.merged.len() == scratch.union.len() * kk => {
            &sh.merged
        }
        _ => {
            if merge(secs, slot, mats, kk, scratch).is_none() {
                return false;
            }
            &scratch.merged
        }
    };
    let Scratch { union, acc, .. } = scratch;
    // x, y, z of X_v side by side (one pass of each column per coordinate).
    acc.clear();
    acc.resize(3 * kk, 0.0);
    let (ax, rest) = acc.split_at_mut(kk);
    let (ay, az) = rest.split_at_mut(kk);
    let (ax, ay, az) = (&mut ax[..kk], &mut ay[..kk], &mut az[..kk]);
    for (&u, col) in union.iter().zip(merged.chunks_exact(kk)) {
        let Some(p) = lin.position(u) else {
            return false;
        };
        // Indexed over slices of one known length, so the loop is vectorised.
        let col = &col[..kk];
        for c in 0..kk {
            ax[c] += col[c] * p[0];
            ay[c] += col[c] * p[1];
            az[c] += col[c] * p[2];
        }
    }
    for (c, o) in out.iter_mut().enumerate() {
        *o = [ax[c], ay[c], az[c]];
    }
    true
}
