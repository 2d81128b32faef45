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

/// A sector of a vertex: its face, corners (v, a, b), stencil and the hash of its key.
type Sector = (FaceId, [VertexId; 3], FaceStencil, u64);

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
    let sectors: Vec<Option<Vec<Sector>>> = jobs
        .par_iter()
        .map(|(fi, (v, off, _))| {
            let m = k.degree(*v);
            let outgoing = k.outgoing(*v);
            (0..m)
                .map(|i| {
                    let h = outgoing[((i + off) % m) as usize];
                    let a = k.dest(h);
                    let b = k.dest(outgoing[((i + off + 1) % m) as usize]);
                    let f = k.face_of(h);
                    let c = [*v, a, b];
                    let st = lin.stencil(k, f, c)?;
                    let hash = key_hash(*fi, i as usize, &st.key);
                    Some((f, c, st, hash))
                })
                .collect()
        })
        .collect();
    // One representative per (fit, sector, key), in job order.
    let mut keys: HashMap<MatrixKey, usize, BuildHasherDefault<Fnv1a>> = HashMap::default();
    let mut reps: Vec<(usize, usize, &Sector)> = Vec::new();
    let mut slot: Vec<Option<Vec<usize>>> = Vec::with_capacity(jobs.len());
    for ((fi, _), secs) in jobs.iter().zip(&sectors) {
        slot.push(secs.as_ref().map(|secs| {
            secs.iter()
                .enumerate()
                .map(|(i, s)| {
                    let key = MatrixKey {
                        fit: *fi,
                        sector: i,
                        key: &s.2.key,
                        hash: s.3,
                    };
                    *keys.entry(key).or_insert_with(|| {
                        reps.push((*fi, i, s));
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
        .map(|&(fi, i, (f, c, st, _))| {
            let fit = &fits[fi];
            let idx = by_sector[fi].get(i)?;
            let at = pinv_t[fi].get(i)?;
            let barys: Vec<[f64; 3]> = idx.iter().map(|&j| fit.samples[j].bary).collect();
            let w = lin.weights(*f, *c, st, &barys)?;
            let (kk, len) = (fit.info.unknowns, st.verts.len());
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
    // X_v = Σ_i M_i P_i.
    jobs.into_par_iter()
        .zip(sectors)
        .zip(slot)
        .map_init(Scratch::default, |scratch, ((job, secs), slot)| {
            let (fi, (v, off, out)) = job;
            let (Some(secs), Some(slot)) = (secs, slot) else {
                return Some((fi, (v, off, out)));
            };
            let kk = fits[fi].info.unknowns;
            let served = apply(lin, &secs, &slot, &mats, kk, out, scratch);
            (!served).then_some((fi, (v, off, out)))
        })
        .flatten()
        .collect()
}

/// Per-thread buffers of [`apply`].
#[derive(Default)]
struct Scratch {
    union: Vec<VertexId>,
    merged: Vec<f64>,
    acc: Vec<f64>,
}

/// out = Σ_i M_i P_i, the M_i first summed into one matrix over the union of the sectors'
/// stencils (neighbouring sectors share most vertices, so this halves the products); false
/// (out untouched) when a matrix or a position is missing.
fn apply(
    lin: &dyn LinearTarget,
    secs: &[Sector],
    slot: &[usize],
    mats: &[Option<Vec<f64>>],
    kk: usize,
    out: &mut [[f64; 3]],
    scratch: &mut Scratch,
) -> bool {
    if out.len() != kk {
        return false;
    }
    let Scratch { union, merged, acc } = scratch;
    union.clear();
    merged.clear();
    for ((_, _, st, _), &r) in secs.iter().zip(slot) {
        let Some(Some(m)) = mats.get(r) else {
            return false;
        };
        for (&u, col) in st.verts.iter().zip(m.chunks_exact(kk)) {
            let at = match union.iter().position(|&x| x == u) {
                Some(p) => p,
                None => {
                    union.push(u);
                    merged.resize(union.len() * kk, 0.0);
                    union.len() - 1
                }
            };
            for (g, w) in merged[at * kk..(at + 1) * kk].iter_mut().zip(col) {
                *g += w;
            }
        }
    }
    // x, y, z of X_v side by side (one pass of each column per coordinate).
    acc.clear();
    acc.resize(3 * kk, 0.0);
    let (ax, rest) = acc.split_at_mut(kk);
    let (ay, az) = rest.split_at_mut(kk);
    for (&u, col) in union.iter().zip(merged.chunks_exact(kk)) {
        let Some(p) = lin.position(u) else {
            return false;
        };
        for (((x, y), z), w) in ax.iter_mut().zip(ay.iter_mut()).zip(az.iter_mut()).zip(col) {
            *x += w * p[0];
            *y += w * p[1];
            *z += w * p[2];
        }
    }
    for (c, o) in out.iter_mut().enumerate() {
        *o = [ax[c], ay[c], az[c]];
    }
    true
}
