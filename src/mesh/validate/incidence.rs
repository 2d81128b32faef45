//! Edge and vertex incidences of a triangle list, built once by sorting (O(F log F)), shared
//! by the combinatorial checks.

use crate::mesh::RawMesh;

/// Compressed incidence tables over the *well-formed* faces (indices in range, three distinct
/// corners); the other faces are reported by their own checks and take no part here.
#[derive(Debug, Clone, Default)]
pub struct Incidence {
    /// Faces that take part (well-formed).
    pub active: Vec<bool>,
    /// Undirected edges (a < b), sorted.
    pub edges: Vec<(u32, u32)>,
    /// CSR: faces of edge e are `edge_faces[edge_start[e]..edge_start[e+1]]`.
    pub edge_start: Vec<u32>,
    /// Face indices, grouped by edge (see `edge_start`).
    pub edge_faces: Vec<u32>,
    /// CSR: faces of vertex v are `vertex_faces[vertex_start[v]..vertex_start[v+1]]`.
    pub vertex_start: Vec<u32>,
    /// Face indices, grouped by vertex (see `vertex_start`).
    pub vertex_faces: Vec<u32>,
    /// Faces sorted by their sorted vertex triple (for duplicate detection).
    sorted_keys: Vec<([u32; 3], u32)>,
    /// `face_edges[f][k]`: index into `edges` of the edge from corner k to corner k + 1 of an
    /// active face f (u32::MAX for the others), so walks across edges need no search.
    face_edges: Vec<[u32; 3]>,
}

impl Incidence {
    /// Builds the tables from the faces with `active[f]` set.
    pub fn build(raw: &RawMesh, active: Vec<bool>) -> Incidence {
        let nv = raw.positions.len();
        let mut half: Vec<(u32, u32, u32, u8)> = Vec::with_capacity(raw.faces.len() * 3);
        let mut deg = vec![0u32; nv + 1];
        let mut sorted_keys = Vec::with_capacity(raw.faces.len());
        for (f, t) in raw.faces.iter().enumerate() {
            if !active[f] {
                continue;
            }
            for k in 0..3 {
                let a = t[k];
                let b = t[(k + 1) % 3];
                half.push((a.min(b), a.max(b), f as u32, k as u8));
                deg[a as usize] += 1;
            }
            let mut key = *t;
            key.sort_unstable();
            sorted_keys.push((key, f as u32));
        }
        half.sort_unstable();
        sorted_keys.sort_unstable();
        let mut edges = Vec::new();
        let mut edge_start = Vec::new();
        let mut edge_faces = Vec::with_capacity(half.len());
        let mut face_edges = vec![[u32::MAX; 3]; raw.faces.len()];
        let mut i = 0;
        while i < half.len() {
            let (a, b, _, _) = half[i];
            let e = edges.len() as u32;
            edges.push((a, b));
            edge_start.push(edge_faces.len() as u32);
            while i < half.len() && half[i].0 == a && half[i].1 == b {
                edge_faces.push(half[i].2);
                face_edges[half[i].2 as usize][half[i].3 as usize] = e;
                i += 1;
            }
        }
        edge_start.push(edge_faces.len() as u32);
        // Vertex → faces CSR.
        let mut vertex_start = vec![0u32; nv + 1];
        for v in 0..nv {
            vertex_start[v + 1] = vertex_start[v] + deg[v];
        }
        let mut fill = vertex_start.clone();
        let mut vertex_faces = vec![0u32; vertex_start[nv] as usize];
        for (f, t) in raw.faces.iter().enumerate() {
            if !active[f] {
                continue;
            }
            for &a in t {
                let slot = &mut fill[a as usize];
                vertex_faces[*slot as usize] = f as u32;
                *slot += 1;
            }
        }
        Incidence {
            active,
            edges,
            edge_start,
            edge_faces,
            vertex_start,
            vertex_faces,
            sorted_keys,
            face_edges,
        }
    }

    /// The faces containing edge `e` (an index into `edges`); panics if `e` is out of range.
    pub(crate) fn faces_of_edge(&self, e: usize) -> &[u32] {
        &self.edge_faces[self.edge_start[e] as usize..self.edge_start[e + 1] as usize]
    }

    /// The active faces having `v` as a corner; empty for an out-of-range `v`.
    pub(crate) fn faces_of_vertex(&self, v: usize) -> &[u32] {
        match (self.vertex_start.get(v), self.vertex_start.get(v + 1)) {
            (Some(&a), Some(&b)) => &self.vertex_faces[a as usize..b as usize],
            _ => &[],
        }
    }

    /// Index of the edge from corner `k` to corner `k + 1` (mod 3) of face `f`, if `f` is
    /// active.
    pub(crate) fn face_edge(&self, f: usize, k: usize) -> Option<usize> {
        let e = *self.face_edges.get(f)?.get(k)?;
        (e != u32::MAX).then_some(e as usize)
    }

    /// Groups (of size ≥ 2) of faces with the same vertex set.
    pub(crate) fn duplicate_groups(&self) -> Vec<Vec<u32>> {
        let mut out = Vec::new();
        let mut i = 0;
        while i < self.sorted_keys.len() {
            let mut j = i + 1;
            while j < self.sorted_keys.len() && self.sorted_keys[j].0 == self.sorted_keys[i].0 {
                j += 1;
            }
            if j - i > 1 {
                out.push(self.sorted_keys[i..j].iter().map(|x| x.1).collect());
            }
            i = j;
        }
        out
    }
}
