//! Sec. 6.1.1: the half-edge structure (DCEL) of a validated simplicial surface, and
//! Sec. 6.1.2: the labelling of each vertex's outgoing half-edges 0..m_v−1 in one cyclic
//! order, which *is* the simplicial isomorphism s_v : st(v, K) → T_v of Def. 4.1.4
//! (s_v(v) = v′, s_v(dest h) = v′_{label h}).
//!
//! Half-edge `3f + k` runs from corner k to corner k+1 of face f (faces consistently
//! oriented). The labels go counterclockwise with respect to that orientation:
//! label(rot h) = label(h) + 1 (mod m_v) with rot h = twin(prev h), so the link vertices
//! v_0, …, v_{m−1} of Def. 4.1.4 are consecutive: [v, v_i, v_{i+1}] is a triangle.

use crate::mesh::{FaceId, HalfedgeId, RawMesh, VertexId};
use std::path::PathBuf;

/// A simplicial surface (Def. 3.1.6) in R³ that passed every check of Sec. 3.1, with its
/// consistently oriented DCEL. Only [`crate::mesh::validate::validate`] constructs it.
#[derive(Debug, Clone)]
pub struct SimplicialSurface {
    positions: Vec<[f64; 3]>,
    /// Faces, re-oriented consistently where the file was not.
    faces: Vec<[VertexId; 3]>,
    /// twin[h]: the mate of half-edge h (Sec. 6.1.1).
    twin: Vec<HalfedgeId>,
    /// label[h] = s_{origin h}(dest h) as an index i of v′_i.
    label: Vec<u32>,
    /// CSR: out[out_start[v] + i] is the outgoing half-edge of v with label i.
    out_start: Vec<u32>,
    out: Vec<HalfedgeId>,
    /// out_dest[j] = dest(out[j]): the rings, contiguous (what `halfedge` scans).
    out_dest: Vec<VertexId>,
    /// CSR vertex → incident faces, built from the face list alone (independent of the
    /// half-edges, so checks can compare the two).
    vf_start: Vec<u32>,
    vf: Vec<FaceId>,
    referenced: Vec<bool>,
    flipped_faces: u64,
    source: Option<PathBuf>,
}

impl SimplicialSurface {
    /// Build the DCEL. Called by the validator only after every check of Sec. 3.1 passed
    /// (so every edge has two faces and every link is one cycle); returns `None` if the
    /// structure nevertheless cannot be built, rather than panicking.
    pub(crate) fn from_validated(
        raw: &RawMesh,
        flip: &[bool],
        referenced: &[bool],
    ) -> Option<SimplicialSurface> {
        let nv = raw.positions.len();
        let nf = raw.faces.len();
        let faces: Vec<[VertexId; 3]> = raw
            .faces
            .iter()
            .enumerate()
            .map(|(f, t)| {
                let t = if flip.get(f).copied().unwrap_or(false) {
                    [t[0], t[2], t[1]]
                } else {
                    *t
                };
                [VertexId(t[0]), VertexId(t[1]), VertexId(t[2])]
            })
            .collect();
        let nh = 3 * nf;
        // Twins through the half-edges grouped by origin (a counting sort, no comparisons): the
        // twin of a → b is the half-edge b → a, found among the few leaving b.
        let mut from_start = vec![0u32; nv + 1];
        for t in &faces {
            for v in t {
                from_start[v.idx() + 1] += 1;
            }
        }
        for v in 0..nv {
            from_start[v + 1] += from_start[v];
        }
        let mut fill = from_start.clone();
        let mut from = vec![0u32; nh];
        for (f, t) in faces.iter().enumerate() {
            for (k, v) in t.iter().enumerate() {
                from[fill[v.idx()] as usize] = (3 * f + k) as u32;
                fill[v.idx()] += 1;
            }
        }
        let dest = |h: u32| faces[h as usize / 3][(h as usize + 1) % 3].0;
        let mut twin = vec![HalfedgeId(0); nh];
        for (f, t) in faces.iter().enumerate() {
            for k in 0..3 {
                let (a, b) = (t[k].0, t[(k + 1) % 3].0);
                let leaving_b =
                    &from[from_start[b as usize] as usize..from_start[b as usize + 1] as usize];
                let mut found = leaving_b.iter().filter(|&&g| dest(g) == a);
                // Exactly one b → a on a validated surface (each edge in two consistently
                // oriented faces).
                let (Some(&g), None) = (found.next(), found.next()) else {
                    return None;
                };
                twin[3 * f + k] = HalfedgeId(g);
            }
        }
        // Outgoing half-edges per vertex, ordered by rotation rot h = twin(prev h).
        let mut degree = vec![0u32; nv];
        let mut first: Vec<Option<u32>> = vec![None; nv];
        for (f, t) in faces.iter().enumerate() {
            for (k, vk) in t.iter().enumerate() {
                let v = vk.idx();
                degree[v] += 1;
                if first[v].is_none() {
                    first[v] = Some((3 * f + k) as u32);
                }
            }
        }
        let mut out_start = vec![0u32; nv + 1];
        for v in 0..nv {
            out_start[v + 1] = out_start[v] + degree[v];
        }
        let mut out = vec![HalfedgeId(0); out_start[nv] as usize];
        let mut label = vec![0u32; nh];
        let prev = |h: u32| (h / 3) * 3 + (h % 3 + 2) % 3;
        for v in 0..nv {
            let Some(h0) = first[v] else { continue };
            let mut h = h0;
            for i in 0..degree[v] {
                out[(out_start[v] + i) as usize] = HalfedgeId(h);
                label[h as usize] = i;
                h = twin[prev(h) as usize].0;
                if h == h0 && i + 1 < degree[v] {
                    return None; // link not one cycle: validator would have said so
                }
            }
            if h != h0 {
                return None;
            }
        }
        let out_dest = out
            .iter()
            .map(|h| faces[h.idx() / 3][(h.idx() + 1) % 3])
            .collect();
        let mut vf_start = vec![0u32; nv + 1];
        for t in &faces {
            for c in t {
                vf_start[c.idx() + 1] += 1;
            }
        }
        for v in 0..nv {
            vf_start[v + 1] += vf_start[v];
        }
        let mut fill = vf_start.clone();
        let mut vf = vec![FaceId(0); 3 * nf];
        for (f, t) in faces.iter().enumerate() {
            for c in t {
                vf[fill[c.idx()] as usize] = FaceId(f as u32);
                fill[c.idx()] += 1;
            }
        }
        Some(SimplicialSurface {
            positions: raw.positions.clone(),
            vf_start,
            vf,
            faces,
            twin,
            label,
            out_start,
            out,
            out_dest,
            referenced: referenced.to_vec(),
            flipped_faces: flip.iter().filter(|&&b| b).count() as u64,
            source: raw.source.clone(),
        })
    }

    /// Number of vertex slots (file vertices, including unreferenced ones).
    pub fn vertex_slots(&self) -> usize {
        self.positions.len()
    }
    /// The vertices of K (the index set I of Ch. 4): file indices used by some face.
    pub fn vertices(&self) -> impl Iterator<Item = VertexId> + '_ {
        (0..self.positions.len() as u32)
            .map(VertexId)
            .filter(|v| self.referenced[v.idx()])
    }
    /// Number of vertices of K (referenced vertex slots), i.e. |I|.
    pub fn num_vertices(&self) -> usize {
        self.referenced.iter().filter(|&&b| b).count()
    }
    /// Is `v` a vertex of K?
    pub fn contains(&self, v: VertexId) -> bool {
        self.referenced.get(v.idx()).copied().unwrap_or(false)
    }
    /// Number of triangles of K.
    pub fn num_faces(&self) -> usize {
        self.faces.len()
    }
    /// Number of half-edges: three per face.
    pub fn num_halfedges(&self) -> usize {
        self.twin.len()
    }
    /// Number of edges of K: every edge has two half-edges, as K is closed.
    pub fn num_edges(&self) -> usize {
        self.twin.len() / 2
    }
    /// All faces, in file order.
    pub fn faces(&self) -> impl Iterator<Item = FaceId> {
        (0..self.faces.len() as u32).map(FaceId)
    }
    /// Corners of face f, in the consistent orientation.
    pub fn face(&self, f: FaceId) -> [VertexId; 3] {
        self.faces[f.idx()]
    }
    /// Position of vertex v in R³, as read from the file.
    pub fn position(&self, v: VertexId) -> [f64; 3] {
        self.positions[v.idx()]
    }
    /// The faces having v as a vertex, from the face list (not from the half-edges).
    pub fn faces_around(&self, v: VertexId) -> &[FaceId] {
        match (self.vf_start.get(v.idx()), self.vf_start.get(v.idx() + 1)) {
            (Some(&a), Some(&b)) => &self.vf[a as usize..b as usize],
            _ => &[],
        }
    }
    /// Faces the validator reversed to obtain a consistent orientation.
    pub fn flipped_faces(&self) -> u64 {
        self.flipped_faces
    }
    /// The file the surface was read from, if any.
    pub fn source(&self) -> Option<&std::path::Path> {
        self.source.as_deref()
    }

    /// m_v, the degree of v (Def. 4.1.1); 0 for a vertex slot not in K.
    pub fn degree(&self, v: VertexId) -> u32 {
        match (self.out_start.get(v.idx()), self.out_start.get(v.idx() + 1)) {
            (Some(a), Some(b)) => b - a,
            _ => 0,
        }
    }
    /// Outgoing half-edges of v in label order: `outgoing(v)[i]` points to s_v⁻¹(v′_i).
    pub fn outgoing(&self, v: VertexId) -> &[HalfedgeId] {
        match (self.out_start.get(v.idx()), self.out_start.get(v.idx() + 1)) {
            (Some(&a), Some(&b)) => &self.out[a as usize..b as usize],
            _ => &[],
        }
    }
    /// The link vertices of v in label order: `link(v)[i]` = dest(`outgoing(v)[i]`), and
    /// each is the third corner of the face of the previous one's half-edge (the ring of v
    /// in the orientation of K).
    pub fn link(&self, v: VertexId) -> &[VertexId] {
        match (self.out_start.get(v.idx()), self.out_start.get(v.idx() + 1)) {
            (Some(&a), Some(&b)) => &self.out_dest[a as usize..b as usize],
            _ => &[],
        }
    }
    /// The vertex half-edge h starts at.
    pub fn origin(&self, h: HalfedgeId) -> VertexId {
        self.faces[h.idx() / 3][h.idx() % 3]
    }
    /// The vertex half-edge h points to.
    pub fn dest(&self, h: HalfedgeId) -> VertexId {
        self.faces[h.idx() / 3][(h.idx() + 1) % 3]
    }
    /// The opposite half-edge of h (same edge, other face).
    pub fn twin(&self, h: HalfedgeId) -> HalfedgeId {
        self.twin[h.idx()]
    }
    /// The next half-edge of h's face (counterclockwise in the consistent orientation).
    pub fn next(&self, h: HalfedgeId) -> HalfedgeId {
        HalfedgeId((h.0 / 3) * 3 + (h.0 % 3 + 1) % 3)
    }
    /// The previous half-edge of h's face.
    pub fn prev(&self, h: HalfedgeId) -> HalfedgeId {
        HalfedgeId((h.0 / 3) * 3 + (h.0 % 3 + 2) % 3)
    }
    /// The face h belongs to.
    pub fn face_of(&self, h: HalfedgeId) -> FaceId {
        FaceId(h.0 / 3)
    }
    /// The Sec. 6.1.2 label of h: s_{origin h}(dest h) = v′_{label h}.
    pub fn label(&self, h: HalfedgeId) -> u32 {
        self.label[h.idx()]
    }
    /// The half-edge u → w, if [u, w] is an edge of K.
    pub fn halfedge(&self, u: VertexId, w: VertexId) -> Option<HalfedgeId> {
        let (&a, &b) = (
            self.out_start.get(u.idx())?,
            self.out_start.get(u.idx() + 1)?,
        );
        let (a, b) = (a as usize, b as usize);
        let j = self.out_dest.get(a..b)?.iter().position(|&x| x == w)?;
        self.out.get(a + j).copied()
    }
    /// Def. 4.1.4: s_v(x) for x ∈ lk(v, K), as the index i of v′_i.
    pub fn s(&self, v: VertexId, x: VertexId) -> Option<u32> {
        self.halfedge(v, x).map(|h| self.label(h))
    }
    /// s_v⁻¹(v′_i): the link vertex v_i of Def. 4.1.4.
    pub fn link_vertex(&self, v: VertexId, i: u32) -> Option<VertexId> {
        self.outgoing(v).get(i as usize).map(|&h| self.dest(h))
    }
    /// Undirected edges [u, w] with u < w.
    pub fn edges(&self) -> impl Iterator<Item = (VertexId, VertexId)> + '_ {
        (0..self.twin.len() as u32)
            .map(HalfedgeId)
            .filter(|&h| self.origin(h) < self.dest(h))
            .map(|h| (self.origin(h), self.dest(h)))
    }
}
