//! The fit of Sec. 5.2 for targets that are linear in the vertex positions
//! ([`LinearTarget`], the Loop limit surface): X_v = A⁺ D_v with D_v the samples of S′, and
//! on sector i the samples are W_i P_i (W_i the weights of the sector's samples over the
//! face's stencil, P_i its positions). W_i depends only on (degree, sector, stencil key): it
//! is computed once per key, from the first vertex (in the storage order) that has it, so the
//! result does not depend on the thread schedule. Per vertex, D_v = (W_i P_i)_i costs a few
//! thousand multiplications, and A⁺ D_v is one GEMM per chunk of vertices of one degree, as
//! on the cubic-net path (`pps::fit_batch`).

use super::fit::DegreeFit;
use super::target::{FaceStencil, LinearTarget};
use crate::mesh::{FaceId, SimplicialSurface, VertexId};
use rayon::prelude::*;
use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hasher};

/// A word-at-a-time multiplicative hash (FxHash's step, with murmur3's finaliser so the low
/// bits the table indexes by depend on every word): the keys are ~25 small integers hashed
/// ~300k times per construction, where std's SipHash (DoS-resistant, not needed for keys
/// derived from K) and then a byte-at-a-time FNV-1a showed in profiles; no non-cryptographic
/// hasher crate is among the dependencies, and this is a few lines.
#[derive(Default)]
struct WordHash(u64);

impl WordHash {
    fn mix(&mut self, x: u64) {
        self.0 = (self.0.rotate_left(5) ^ x).wrapping_mul(0x517c_c1b7_2722_0a95);
    }
}

impl Hasher for WordHash {
    fn finish(&self) -> u64 {
        let mut h = self.0;
        h ^= h >> 33;
        h = h.wrapping_mul(0xff51_afd7_ed55_8ccd);
        h ^= h >> 33;
        h = h.wrapping_mul(0xc4ce_b9fe_1a85_ec53);
        h ^ (h >> 33)
    }
    fn write(&mut self, bytes: &[u8]) {
        for chunk in bytes.chunks(8) {
            let mut w = [0u8; 8];
            w[..chunk.len()].copy_from_slice(chunk);
            self.mix(u64::from_le_bytes(w));
        }
    }
    fn write_u32(&mut self, x: u32) {
        self.mix(x as u64);
    }
    fn write_u64(&mut self, x: u64) {
        self.mix(x);
    }
    fn write_usize(&mut self, x: usize) {
        self.mix(x as u64);
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

/// What a weight matrix W_i depends on: the degree's fit, the sector and the stencil key (its
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
    let mut h = WordHash::default();
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
    // The sectors of every vertex, with their stencils; beside them, the tables the weights
    // need (built once, on one thread).
    let (sectors, ()): (Vec<Option<Sectors>>, ()) = rayon::join(
        || {
            jobs.par_iter()
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
                .collect()
        },
        || lin.prepare(),
    );
    // One representative per (fit, sector, key), in job order.
    let mut keys: HashMap<MatrixKey, usize, BuildHasherDefault<WordHash>> = HashMap::default();
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
    // A⁺ with its columns in sector-major sample order (kk × n, column-major), so the samples
    // of one sector fill consecutive rows of D; and where each sector's rows start.
    let pinv_sm: Vec<(Vec<f64>, Vec<usize>)> = fits
        .iter()
        .zip(&by_sector)
        .map(|(fit, secs)| {
            let (n, kk) = (fit.samples.len(), fit.info.unknowns);
            let mut t = Vec::with_capacity(n * kk);
            let mut starts = vec![0];
            for idx in secs {
                for &j in idx {
                    t.extend((0..kk).map(|row| fit.pinv[row * n + j]));
                }
                starts.push(starts.last().copied().unwrap_or(0) + idx.len());
            }
            (t, starts)
        })
        .collect();
    // W_i per key, stored transposed (|stencil| × n_i): the weights of the sector's samples
    // over its stencil.
    let weights: Vec<Option<Vec<f64>>> = reps
        .par_iter()
        .map(|&(fi, i, secs, s)| {
            let fit = &fits[fi];
            let barys: Vec<[f64; 3]> = by_sector[fi]
                .get(i)?
                .iter()
                .map(|&j| fit.samples[j].bary)
                .collect();
            let w = lin.weights(s.face, s.corners, secs.verts(s), &barys)?;
            let (n_i, len) = (barys.len(), s.verts.len());
            let mut wt = vec![0.0; w.len()];
            for (r, row) in w.chunks_exact(len).enumerate() {
                for (c, x) in row.iter().enumerate() {
                    wt[c * n_i + r] = *x;
                }
            }
            Some(wt)
        })
        .collect();
    // X = A⁺ D per chunk of vertices of one degree: D's columns are the samples of S′ (W_i P_i
    // on sector i), the product one GEMM, as the cubic-net path does with its nets.
    let mut chunks: Vec<Vec<Item>> = Vec::new();
    for item in jobs.into_iter().zip(&sectors).zip(&slot) {
        match chunks.last_mut() {
            Some(c) if c.len() < CHUNK && c[0].0 .0 .0 == item.0 .0 .0 => c.push(item),
            _ => chunks.push(vec![item]),
        }
    }
    let rest = chunks
        .into_par_iter()
        .map_init(ChunkScratch::default, |sc, chunk| {
            apply_chunk(lin, chunk, &weights, &pinv_sm, sc)
        })
        .flatten_iter()
        .collect();
    rest
}

/// Vertices per GEMM of [`apply_chunk`] (D is samples × 3·CHUNK: ~0.5 MB for degree 6).
const CHUNK: usize = 128;

/// Per-thread buffers of [`apply_chunk`] (D and X are ~0.5 MB: fresh ones per chunk were
/// mapped and faulted in by the allocator each time).
#[derive(Default)]
struct ChunkScratch {
    d: Vec<f64>,
    x: Vec<f64>,
    positions: Vec<[f64; 3]>,
}

/// A vertex to fit with its sectors and their weight matrices (indices into the per-key list).
/// Borrowed, so the per-vertex buffers are freed at the end on one thread (freed inside the
/// parallel loop, on another thread than the one that allocated them, they showed as
/// allocator lock contention).
type Item<'a, 's> = (
    ((usize, Job<'a>), &'s Option<Sectors>),
    &'s Option<Vec<usize>>,
);

/// X_v = A⁺ D_v for the vertices of `chunk` (all of one degree's fit): the samples of S′ on
/// sector i are W_i P_i (W_i per key, P_i the stencil's positions), written into the columns
/// of D, then one product with A⁺. Computed in this order, not as precomputed products
/// A⁺_i W_i (kk × |stencil| per key, 23 MB on koala), because those, read once per vertex,
/// made the fit memory-bound; the weights are a third of their size. Returns the vertices it
/// could not serve (a missing weight matrix or position).
fn apply_chunk<'a>(
    lin: &dyn LinearTarget,
    chunk: Vec<Item<'a, '_>>,
    weights: &[Option<Vec<f64>>],
    pinv_sm: &[(Vec<f64>, Vec<usize>)],
    scratch: &mut ChunkScratch,
) -> Vec<(usize, Job<'a>)> {
    let mut rest = Vec::new();
    let Some(fi) = chunk.first().map(|it| it.0 .0 .0) else {
        return rest;
    };
    let Some((a, starts)) = pinv_sm.get(fi) else {
        rest.extend(chunk.into_iter().map(|((job, _), _)| job));
        return rest;
    };
    let n = starts.last().copied().unwrap_or(0);
    let kk = a.len().checked_div(n).unwrap_or(0);
    let ChunkScratch { d, x, positions } = scratch;
    d.clear();
    d.resize(n * 3 * chunk.len(), 0.0);
    let mut done: Vec<(usize, Job<'a>)> = Vec::with_capacity(chunk.len());
    for ((job, secs), slot) in chunk {
        let col = done.len();
        let ok = kk > 0
            && match (secs, slot) {
                (Some(secs), Some(slot)) if job.1 .2.len() == kk => samples_into(
                    lin,
                    secs,
                    slot,
                    weights,
                    starts,
                    positions,
                    &mut d[n * 3 * col..n * 3 * (col + 1)],
                ),
                _ => false,
            };
        if ok {
            done.push(job);
        } else {
            rest.push(job);
        }
    }
    if done.is_empty() {
        return rest;
    }
    let cols = 3 * done.len();
    x.clear();
    x.resize(kk * cols, 0.0);
    faer::linalg::matmul::matmul(
        faer::mat::from_column_major_slice_mut::<f64>(x, kk, cols),
        faer::mat::from_column_major_slice::<f64>(a, kk, n),
        faer::mat::from_column_major_slice::<f64>(&d[..n * cols], n, cols),
        None,
        1.0,
        faer::Parallelism::None,
    );
    for (j, (_, (_, _, out))) in done.iter_mut().enumerate() {
        for (c, o) in out.iter_mut().enumerate() {
            let at = |col: usize| x[col * kk + c];
            *o = [at(3 * j), at(3 * j + 1), at(3 * j + 2)];
        }
    }
    rest
}

/// The samples of S′ at one vertex, W_i P_i for every sector i, written into `d` (three
/// columns of length n, one per coordinate, sector i in rows starts[i]..starts[i + 1]); false
/// when a weight matrix or a position is missing.
fn samples_into(
    lin: &dyn LinearTarget,
    secs: &Sectors,
    slot: &[usize],
    weights: &[Option<Vec<f64>>],
    starts: &[usize],
    positions: &mut Vec<[f64; 3]>,
    d: &mut [f64],
) -> bool {
    let n = d.len() / 3;
    if slot.len() != secs.list.len() || starts.len() != slot.len() + 1 {
        return false;
    }
    let (dx, rest) = d.split_at_mut(n);
    let (dy, dz) = rest.split_at_mut(n);
    for (i, (s, &r)) in secs.list.iter().zip(slot).enumerate() {
        let Some(Some(w)) = weights.get(r) else {
            return false;
        };
        positions.clear();
        for &u in secs.verts(s) {
            let Some(p) = lin.position(u) else {
                return false;
            };
            positions.push(p);
        }
        let (lo, hi) = (starts[i], starts[i + 1]);
        let (len, n_i) = (positions.len(), hi - lo);
        if len == 0 || w.len() != n_i * len || hi > n {
            return false;
        }
        let (yx, yy, yz) = (&mut dx[lo..hi], &mut dy[lo..hi], &mut dz[lo..hi]);
        yx.fill(0.0);
        yy.fill(0.0);
        yz.fill(0.0);
        // Column by column of W_iᵀ, so the loop runs along the samples (vectorised).
        for (wc, p) in w.chunks_exact(n_i).zip(positions.iter()) {
            let ys = yx.iter_mut().zip(yy.iter_mut()).zip(yz.iter_mut());
            for (((x, y), z), c) in ys.zip(wc) {
                *x += c * p[0];
                *y += c * p[1];
                *z += c * p[2];
            }
        }
    }
    true
}
