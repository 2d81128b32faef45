//! The fit of Sec. 5.2 for targets that are linear in the vertex positions
//! ([`LinearTarget`], the Loop limit surface): X_v = A⁺ D_v with D_v the samples of S′, and
//! on sector i the samples are W_i P_i (W_i the weights of the sector's samples over the
//! face's stencil, P_i its positions). W_i depends only on (degree, sector, stencil key): it
//! is computed once per key, from the first vertex (in the storage order) that has it, so the
//! result does not depend on the thread schedule. Per vertex, D_v = (W_i P_i)_i costs a few
//! thousand multiplications, and A⁺ D_v is one GEMM per chunk of vertices of one degree, as
//! on the cubic-net path (`pps::fit_batch`).
//!
//! Everything but the last step needs only the samples of Sec. 5.2, not A⁺: [`LinearPlan`]
//! (stencils, keys, weights) is built beside the factorisations (`pps::Pps::build_staged`),
//! whose largest degree otherwise keeps one thread busy alone, and [`LinearPlan::apply`] does
//! the rest once A⁺ is known.

use super::fit::{DegreeFit, Sample};
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
pub(crate) struct WordHash(u64);

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

/// The part of the fit that does not need A⁺ (so it can run beside the factorisation of
/// Sec. 5.2): every vertex's sectors and stencils, one weight matrix W_i per (degree, sector,
/// key), and which matrix each sector uses.
pub(super) struct LinearPlan {
    /// The vertices planned, with their fit (index into the degrees), in job order.
    verts: Vec<(usize, VertexId)>,
    sectors: Vec<Option<Sectors>>,
    slot: Vec<Option<Vec<usize>>>,
    /// W_i per key, stored transposed (|stencil| × n_i).
    weights: Vec<Option<Vec<f64>>>,
    /// Per fit, the number of samples the weights were computed for.
    samples: Vec<usize>,
}

impl LinearPlan {
    /// Plans the vertices `verts` (fit index, vertex, label offset; in the storage order of
    /// the patches, which fixes each key's representative); `samples[fi]` are the degree and
    /// the Sec. 5.2 samples of fit fi (`fit::sample_set`, the rows of its A).
    pub(super) fn new(
        k: &SimplicialSurface,
        lin: &dyn LinearTarget,
        samples: &[(u32, Vec<Sample>)],
        verts: &[(usize, VertexId, u32)],
    ) -> LinearPlan {
        // The sectors of every vertex, with their stencils; beside them, the tables the
        // weights need (built once, on one thread) and the samples of each sector.
        let (sectors, by_sector): (Vec<Option<Sectors>>, _) = rayon::join(
            || {
                verts
                    .par_iter()
                    .map_init(
                        || FaceStencil {
                            key: Vec::new(),
                            verts: Vec::new(),
                        },
                        |st, &(fi, v, off)| sectors_of(k, lin, fi, v, off, st),
                    )
                    .collect()
            },
            || {
                lin.prepare();
                samples
                    .iter()
                    .map(|(m, s)| by_sector(*m, s))
                    .collect::<Vec<_>>()
            },
        );
        // One representative per (fit, sector, key), in job order.
        let mut keys: HashMap<MatrixKey, usize, BuildHasherDefault<WordHash>> = HashMap::default();
        let mut reps: Vec<(usize, usize, &Sectors, &Sector)> = Vec::new();
        let mut slot: Vec<Option<Vec<usize>>> = Vec::with_capacity(verts.len());
        for (&(fi, _, _), secs) in verts.iter().zip(&sectors) {
            slot.push(secs.as_ref().map(|secs| {
                secs.list
                    .iter()
                    .enumerate()
                    .map(|(i, s)| {
                        let key = MatrixKey {
                            fit: fi,
                            sector: i,
                            key: secs.key(s),
                            hash: s.hash,
                        };
                        *keys.entry(key).or_insert_with(|| {
                            reps.push((fi, i, secs, s));
                            reps.len() - 1
                        })
                    })
                    .collect()
            }));
        }
        // W_i per key: the weights of the sector's samples over its stencil.
        let weights: Vec<Option<Vec<f64>>> = reps
            .par_iter()
            .map(|&(fi, i, secs, s)| {
                let barys: Vec<[f64; 3]> = by_sector
                    .get(fi)?
                    .get(i)?
                    .iter()
                    .map(|&j| samples[fi].1[j].bary)
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
        LinearPlan {
            verts: verts.iter().map(|&(fi, v, _)| (fi, v)).collect(),
            sectors,
            slot,
            weights,
            samples: samples.iter().map(|(_, s)| s.len()).collect(),
        }
    }

    /// Fits the vertices of `jobs` (the planned ones, in the same order; `fits[fi]` factored
    /// from the samples the plan was made for, `major[fi]` its [`SectorMajor`] form): X = A⁺ D
    /// per chunk of vertices of one degree, D's columns the samples of S′ (W_i P_i on sector
    /// i), the product one GEMM, as the cubic-net path does with its nets. Returns the jobs it
    /// could not serve (the caller samples S′ for them).
    pub(super) fn apply<'a>(
        &self,
        lin: &dyn LinearTarget,
        fits: &[DegreeFit],
        major: &[Option<SectorMajor>],
        jobs: Vec<(usize, Job<'a>)>,
    ) -> Vec<(usize, Job<'a>)> {
        let mut chunks: Vec<Vec<Item>> = Vec::new();
        let mut rest = Vec::new();
        let planned = self.verts.iter().zip(&self.sectors).zip(&self.slot);
        let mut planned = planned.peekable();
        for job in jobs {
            // The plan's entry for this job (same vertex and fit, the same samples).
            let mut entry = None;
            if let Some(((&(fi, v), secs), slot)) = planned.peek() {
                if fi == job.0 && v == job.1 .0 {
                    entry = Some((*secs, *slot));
                    planned.next();
                }
            }
            let same_samples = fits.get(job.0).map(|f| f.samples.len())
                == self.samples.get(job.0).copied()
                && matches!(major.get(job.0), Some(Some(_)));
            let Some((secs, slot)) = entry.filter(|_| same_samples) else {
                rest.push(job);
                continue;
            };
            let item = ((job, secs), slot);
            match chunks.last_mut() {
                Some(c) if c.len() < CHUNK && c[0].0 .0 .0 == item.0 .0 .0 => c.push(item),
                _ => chunks.push(vec![item]),
            }
        }
        let served: Vec<_> = chunks
            .into_par_iter()
            .map_init(ChunkScratch::default, |sc, chunk| {
                apply_chunk(lin, chunk, &self.weights, major, sc)
            })
            .flatten_iter()
            .collect();
        rest.extend(served);
        rest
    }
}

/// The m sectors of v (label i of the profile is K's label i + off), with their stencils.
fn sectors_of(
    k: &SimplicialSurface,
    lin: &dyn LinearTarget,
    fi: usize,
    v: VertexId,
    off: u32,
    st: &mut FaceStencil,
) -> Option<Sectors> {
    let m = k.degree(v);
    let outgoing = k.outgoing(v);
    // link[i] = dest(outgoing[i]), contiguous (no lookup in the faces).
    let link = k.link(v);
    let mut out = Sectors {
        list: Vec::with_capacity(m as usize),
        keys: Vec::with_capacity(24 * m as usize),
        verts: Vec::with_capacity(14 * m as usize),
    };
    for i in 0..m {
        let (ia, ib) = (((i + off) % m) as usize, ((i + off + 1) % m) as usize);
        let (Some(&h), Some(&a), Some(&b)) = (outgoing.get(ia), link.get(ia), link.get(ib)) else {
            return None;
        };
        let face = k.face_of(h);
        let corners = [v, a, b];
        lin.stencil_into(k, face, corners, st)?;
        let key = out.keys.len()..out.keys.len() + st.key.len();
        let verts = out.verts.len()..out.verts.len() + st.verts.len();
        out.keys.extend_from_slice(&st.key);
        out.verts.extend_from_slice(&st.verts);
        let hash = key_hash(fi, i as usize, &st.key);
        out.list.push(Sector {
            face,
            corners,
            key,
            verts,
            hash,
        });
    }
    Some(out)
}

/// The samples of each sector (indices into the samples, ascending).
fn by_sector(m: u32, samples: &[Sample]) -> Vec<Vec<usize>> {
    let mut s = vec![Vec::new(); m as usize];
    for (j, sample) in samples.iter().enumerate() {
        if let Some(list) = s.get_mut(sample.sector as usize) {
            list.push(j);
        }
    }
    s
}

/// A⁺ with its columns in sector-major sample order (kk × n, column-major), so the samples of
/// one sector fill consecutive rows of D, and where each sector's rows start.
pub(super) struct SectorMajor {
    a: Vec<f64>,
    starts: Vec<usize>,
}

impl SectorMajor {
    /// The sector-major form of a fit's A⁺ (computed beside the other degrees' factorisations).
    pub(super) fn new(fit: &DegreeFit) -> SectorMajor {
        let (n, kk) = (fit.samples.len(), fit.info.unknowns);
        let mut a = Vec::with_capacity(n * kk);
        let mut starts = vec![0];
        for idx in by_sector(fit.info.m, &fit.samples) {
            for j in idx {
                a.extend((0..kk).map(|row| fit.pinv[row * n + j]));
            }
            starts.push(a.len() / kk.max(1));
        }
        SectorMajor { a, starts }
    }
}

/// Vertices per GEMM of [`apply_chunk`] (D is samples × 3·CHUNK: ~0.5 MB for degree 6).
const CHUNK: usize = 128;

/// Per-thread buffers of [`apply_chunk`] (D and X are ~0.5 MB: fresh ones per chunk were
/// mapped and faulted in by the allocator each time).
#[derive(Default)]
struct ChunkScratch {
    d: Vec<f64>,
    x: Vec<f64>,
    positions: [Vec<f64>; 3],
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
    major: &[Option<SectorMajor>],
    scratch: &mut ChunkScratch,
) -> Vec<(usize, Job<'a>)> {
    let mut rest = Vec::new();
    let Some(fi) = chunk.first().map(|it| it.0 .0 .0) else {
        return rest;
    };
    let Some(Some(SectorMajor { a, starts })) = major.get(fi) else {
        rest.extend(chunk.into_iter().map(|((job, _), _)| job));
        return rest;
    };
    let n = starts.last().copied().unwrap_or(0);
    let kk = a.len().checked_div(n).unwrap_or(0);
    let ChunkScratch { d, x, positions } = scratch;
    // Every row of a served vertex's columns is written (`samples_into`), and the product
    // overwrites X: neither needs zeroing.
    if d.len() < n * 3 * chunk.len() {
        d.resize(n * 3 * chunk.len(), 0.0);
    }
    let mut done: Vec<(usize, Job<'a>)> = Vec::with_capacity(chunk.len());
    pulp::Arch::new().dispatch(FillD {
        lin,
        chunk,
        weights,
        starts,
        kk,
        scratch: (d, positions),
        done: &mut done,
        rest: &mut rest,
    });
    if done.is_empty() {
        return rest;
    }
    let cols = 3 * done.len();
    if x.len() < kk * cols {
        x.resize(kk * cols, 0.0);
    }
    faer::linalg::matmul::matmul(
        faer::mat::from_column_major_slice_mut::<f64>(&mut x[..kk * cols], kk, cols),
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

/// D for one chunk: the samples of each vertex ([`samples_into`]) in its three columns; the
/// vertices served go to `done`, the others to `rest`. A [`pulp::WithSimd`] operation, so
/// its loops (inlined into `with_simd`) are compiled for the CPU's vector extensions.
struct FillD<'a, 's, 'x> {
    lin: &'x dyn LinearTarget,
    chunk: Vec<Item<'a, 's>>,
    weights: &'x [Option<Vec<f64>>],
    starts: &'x [usize],
    kk: usize,
    scratch: (&'x mut Vec<f64>, &'x mut [Vec<f64>; 3]),
    done: &'x mut Vec<(usize, Job<'a>)>,
    rest: &'x mut Vec<(usize, Job<'a>)>,
}

impl pulp::WithSimd for FillD<'_, '_, '_> {
    type Output = ();
    #[inline(always)]
    fn with_simd<S: pulp::Simd>(self, _: S) {
        let (d, positions) = self.scratch;
        let n = self.starts.last().copied().unwrap_or(0);
        for ((job, secs), slot) in self.chunk {
            let col = self.done.len();
            let ok = self.kk > 0
                && match (secs, slot) {
                    (Some(secs), Some(slot)) if job.1 .2.len() == self.kk => samples_into(
                        self.lin,
                        secs,
                        slot,
                        self.weights,
                        self.starts,
                        positions,
                        &mut d[n * 3 * col..n * 3 * (col + 1)],
                    ),
                    _ => false,
                };
            if ok {
                self.done.push(job);
            } else {
                self.rest.push(job);
            }
        }
    }
}

/// The samples of S′ at one vertex, W_i P_i for every sector i, written into `d` (three
/// columns of length n, one per coordinate, sector i in rows starts[i]..starts[i + 1], every
/// row written); false when a weight matrix or a position is missing.
#[inline(always)]
fn samples_into(
    lin: &dyn LinearTarget,
    secs: &Sectors,
    slot: &[usize],
    weights: &[Option<Vec<f64>>],
    starts: &[usize],
    p: &mut [Vec<f64>; 3],
    d: &mut [f64],
) -> bool {
    let n = d.len() / 3;
    if slot.len() != secs.list.len() || starts.len() != slot.len() + 1 {
        return false;
    }
    let all = lin.positions();
    let (dx, rest) = d.split_at_mut(n);
    let (dy, dz) = rest.split_at_mut(n);
    for (i, (s, &r)) in secs.list.iter().zip(slot).enumerate() {
        let Some(Some(w)) = weights.get(r) else {
            return false;
        };
        // The stencil's positions, one vector per coordinate.
        for c in p.iter_mut() {
            c.clear();
        }
        for &u in secs.verts(s) {
            let Some(q) = all.get(u.idx()) else {
                return false;
            };
            for (c, x) in p.iter_mut().zip(q) {
                c.push(*x);
            }
        }
        let (lo, hi) = (starts[i], starts[i + 1]);
        let (len, n_i) = (p[0].len(), hi - lo);
        if len == 0 || w.len() != n_i * len || hi > n {
            return false;
        }
        let y = [&mut dx[lo..hi], &mut dy[lo..hi], &mut dz[lo..hi]];
        let (r0, y) = rows_into::<8>(w, n_i, 0, p, y);
        let (r0, y) = rows_into::<4>(w, n_i, r0, p, y);
        rows_into::<1>(w, n_i, r0, p, y);
    }
    true
}

/// One sector's rows of D, one slice per coordinate.
type Rows<'y> = [&'y mut [f64]; 3];

/// Rows r0, r0 + B, … (while B fit) of W_i P_i into `y`, each block of B rows summed over the
/// stencil in registers (W_iᵀ's column c holds the samples' weights of stencil vertex c; the
/// sum runs over c in order, as a plain loop would). Returns the first row not written, with
/// `y`, for a smaller block.
#[inline(always)]
fn rows_into<'y, const B: usize>(
    w: &[f64],
    n_i: usize,
    mut r0: usize,
    p: &[Vec<f64>; 3],
    y: Rows<'y>,
) -> (usize, Rows<'y>) {
    let [yx, yy, yz] = y;
    let (px, py, pz) = (&p[0], &p[1], &p[2]);
    while r0 + B <= n_i {
        let (mut ax, mut ay, mut az) = ([0.0; B], [0.0; B], [0.0; B]);
        for (c, wc) in w.chunks_exact(n_i).enumerate() {
            let wb = &wc[r0..r0 + B];
            let (x, yv, z) = (px[c], py[c], pz[c]);
            for t in 0..B {
                ax[t] += wb[t] * x;
                ay[t] += wb[t] * yv;
                az[t] += wb[t] * z;
            }
        }
        yx[r0..r0 + B].copy_from_slice(&ax);
        yy[r0..r0 + B].copy_from_slice(&ay);
        yz[r0..r0 + B].copy_from_slice(&az);
        r0 += B;
    }
    (r0, [yx, yy, yz])
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sector(key: std::ops::Range<usize>, hash: u64) -> Sector {
        Sector {
            face: FaceId(0),
            corners: [VertexId(0); 3],
            key,
            verts: 0..0,
            hash,
        }
    }

    /// `LOOP-linear-fit`: a weight matrix is shared by equal keys only. The table looks a key
    /// up by its hash, computed once per sector, and then compares the keys themselves, so a
    /// 64-bit hash collision between different keys cannot merge them: planted, three sectors
    /// with one hash and two distinct keys get two matrices.
    #[test]
    fn loop_linear_fit_keys_colliding_in_the_hash_keep_their_own_matrices() {
        let secs = Sectors {
            list: vec![sector(0..3, 7), sector(3..6, 7), sector(6..9, 7)],
            keys: vec![1, 6, 0, 1, 5, 0, 1, 6, 0],
            verts: Vec::new(),
        };
        assert_eq!(secs.key(&secs.list[1]), &[1, 5, 0]);
        let mut table: HashMap<MatrixKey, usize, BuildHasherDefault<WordHash>> = HashMap::default();
        let ids: Vec<usize> = secs
            .list
            .iter()
            .map(|s| {
                let next = table.len();
                let key = MatrixKey {
                    fit: 0,
                    sector: 0,
                    key: secs.key(s),
                    hash: s.hash,
                };
                *table.entry(key).or_insert(next)
            })
            .collect();
        assert_eq!(ids, [0, 1, 0], "keys merged or split wrongly");
    }
}
