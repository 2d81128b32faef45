//! Triangulations of a box for Mello–Velho Sec. 6.2: the canonical (Kuhn) triangulation K_0 of
//! a grid of squares, each split by its diagonal, and conforming refinement by newest-vertex
//! bisection (our stand-in for the paper's SUBDIVIDE "with adaptive propagation" \[15\], L308:
//! bisecting a triangle first bisects the neighbour across its refinement edge when that
//! neighbour's refinement edge differs, so the mesh stays conforming).

use crate::mesh::raw::RawMesh;
use std::collections::HashMap;

/// Why a refinement stopped.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum RefineError {
    /// More triangles than the budget.
    #[error("refinement would exceed {0} triangles")]
    Budget(usize),
    /// The triangle id is not alive.
    #[error("triangle {0} is not in the mesh")]
    NoSuchTriangle(usize),
}

/// A triangulation being refined. Triangle `[apex, b, c]` has refinement edge (b, c).
#[derive(Debug, Clone)]
pub struct Mesh2 {
    /// Vertex positions.
    pub points: Vec<[f64; 2]>,
    /// Triangles (dead ones stay, flagged in `alive`).
    pub tris: Vec<[u32; 3]>,
    /// Alive flags.
    pub alive: Vec<bool>,
    /// Bisection level of each triangle.
    pub level: Vec<u32>,
    edges: HashMap<(u32, u32), Vec<usize>>,
    mids: HashMap<(u32, u32), u32>,
    /// Largest number of alive triangles allowed.
    pub max_triangles: usize,
    alive_count: usize,
}

fn key(a: u32, b: u32) -> (u32, u32) {
    (a.min(b), a.max(b))
}

impl Mesh2 {
    /// K_0: an nx × ny grid of squares over \[lo, hi\], each split by its diagonal.
    pub fn kuhn(nx: usize, ny: usize, lo: [f64; 2], hi: [f64; 2], max_triangles: usize) -> Mesh2 {
        let mut m = Mesh2 {
            points: Vec::new(),
            tris: Vec::new(),
            alive: Vec::new(),
            level: Vec::new(),
            edges: HashMap::new(),
            mids: HashMap::new(),
            max_triangles,
            alive_count: 0,
        };
        for j in 0..=ny {
            for i in 0..=nx {
                let x = lo[0] + (hi[0] - lo[0]) * i as f64 / nx as f64;
                let y = lo[1] + (hi[1] - lo[1]) * j as f64 / ny as f64;
                m.points.push([x, y]);
            }
        }
        let id = |i: usize, j: usize| (j * (nx + 1) + i) as u32;
        for j in 0..ny {
            for i in 0..nx {
                let (p00, p10, p11, p01) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
                m.add([p10, p11, p00], 0);
                m.add([p01, p00, p11], 0);
            }
        }
        m
    }

    fn add(&mut self, t: [u32; 3], level: u32) -> usize {
        let id = self.tris.len();
        self.tris.push(t);
        self.alive.push(true);
        self.level.push(level);
        self.alive_count += 1;
        for k in 0..3 {
            self.edges
                .entry(key(t[k], t[(k + 1) % 3]))
                .or_default()
                .push(id);
        }
        id
    }

    fn remove(&mut self, id: usize) {
        self.alive[id] = false;
        self.alive_count -= 1;
        let t = self.tris[id];
        for k in 0..3 {
            if let Some(v) = self.edges.get_mut(&key(t[k], t[(k + 1) % 3])) {
                v.retain(|&x| x != id);
            }
        }
    }

    /// Alive triangles.
    pub fn alive_ids(&self) -> Vec<usize> {
        (0..self.tris.len()).filter(|&i| self.alive[i]).collect()
    }

    fn neighbour(&self, id: usize) -> Option<usize> {
        let t = self.tris[id];
        self.edges
            .get(&key(t[1], t[2]))?
            .iter()
            .copied()
            .find(|&x| x != id)
    }

    /// Bisects triangle `id` (and, first, whatever keeps the mesh conforming). Returns the new
    /// triangles.
    pub(crate) fn bisect(&mut self, id: usize) -> Result<Vec<usize>, RefineError> {
        let mut out = Vec::new();
        self.bisect_into(id, &mut out, 0)?;
        Ok(out.into_iter().filter(|&t| self.alive[t]).collect())
    }

    fn bisect_into(
        &mut self,
        id: usize,
        out: &mut Vec<usize>,
        depth: u32,
    ) -> Result<(), RefineError> {
        if id >= self.tris.len() || !self.alive[id] {
            return Err(RefineError::NoSuchTriangle(id));
        }
        if self.alive_count + 2 > self.max_triangles || depth > 64 {
            return Err(RefineError::Budget(self.max_triangles));
        }
        let e = key(self.tris[id][1], self.tris[id][2]);
        if let Some(n) = self.neighbour(id) {
            let nt = self.tris[n];
            if key(nt[1], nt[2]) != e {
                self.bisect_into(n, out, depth + 1)?;
            }
        }
        let n = self.neighbour(id);
        out.extend(self.split(id));
        if let Some(n) = n {
            out.extend(self.split(n));
        }
        Ok(())
    }

    fn split(&mut self, id: usize) -> [usize; 2] {
        let [apex, b, c] = self.tris[id];
        let k = key(b, c);
        let m = match self.mids.get(&k) {
            Some(&m) => m,
            None => {
                let (pb, pc) = (self.points[b as usize], self.points[c as usize]);
                self.points
                    .push([0.5 * (pb[0] + pc[0]), 0.5 * (pb[1] + pc[1])]);
                let m = (self.points.len() - 1) as u32;
                self.mids.insert(k, m);
                m
            }
        };
        let lv = self.level[id] + 1;
        self.remove(id);
        [self.add([m, b, apex], lv), self.add([m, apex, c], lv)]
    }

    /// Triangle `id`'s vertices listed counterclockwise.
    pub fn oriented(&self, id: usize) -> [u32; 3] {
        let [a, b, c] = self.tris[id];
        let (pa, pb, pc) = (
            self.points[a as usize],
            self.points[b as usize],
            self.points[c as usize],
        );
        let o = (pb[0] - pa[0]) * (pc[1] - pa[1]) - (pb[1] - pa[1]) * (pc[0] - pa[0]);
        if o > 0.0 {
            [a, b, c]
        } else {
            [a, c, b]
        }
    }

    /// The alive triangles as a mesh (z = 0), each listed counterclockwise; with the map from
    /// its face index to the triangle id.
    pub fn to_raw(&self) -> (RawMesh, Vec<usize>) {
        let ids = self.alive_ids();
        let faces = ids.iter().map(|&i| self.oriented(i)).collect::<Vec<_>>();
        let raw = RawMesh {
            positions: self.points.iter().map(|p| [p[0], p[1], 0.0]).collect(),
            face_origin: (0..faces.len() as u64).collect(),
            vertex_origin: (0..self.points.len() as u64).collect(),
            faces,
            ..Default::default()
        };
        (raw, ids)
    }
}
