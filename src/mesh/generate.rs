//! Small closed surfaces built in code (tests, property tests, fuzzing seeds). Coordinates are
//! chosen so the meshes are genuine simplicial surfaces in R³ (no self-intersection).

use crate::mesh::RawMesh;

/// The boundary of a tetrahedron: 4 vertices of degree 3.
pub fn tetrahedron() -> RawMesh {
    RawMesh::from_arrays(
        vec![
            [1.0, 1.0, 1.0],
            [1.0, -1.0, -1.0],
            [-1.0, 1.0, -1.0],
            [-1.0, -1.0, 1.0],
        ],
        vec![[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]],
    )
}

/// The octahedron: 6 vertices of degree 4.
pub fn octahedron() -> RawMesh {
    RawMesh::from_arrays(
        vec![
            [1.0, 0.0, 0.0],
            [-1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, -1.0, 0.0],
            [0.0, 0.0, 1.0],
            [0.0, 0.0, -1.0],
        ],
        vec![
            [0, 2, 4],
            [2, 1, 4],
            [1, 3, 4],
            [3, 0, 4],
            [2, 0, 5],
            [1, 2, 5],
            [3, 1, 5],
            [0, 3, 5],
        ],
    )
}

/// The icosahedron: 12 vertices of degree 5.
pub fn icosahedron() -> RawMesh {
    let t = (1.0 + 5f64.sqrt()) / 2.0;
    let positions = vec![
        [-1.0, t, 0.0],
        [1.0, t, 0.0],
        [-1.0, -t, 0.0],
        [1.0, -t, 0.0],
        [0.0, -1.0, t],
        [0.0, 1.0, t],
        [0.0, -1.0, -t],
        [0.0, 1.0, -t],
        [t, 0.0, -1.0],
        [t, 0.0, 1.0],
        [-t, 0.0, -1.0],
        [-t, 0.0, 1.0],
    ];
    let faces = vec![
        [0, 11, 5],
        [0, 5, 1],
        [0, 1, 7],
        [0, 7, 10],
        [0, 10, 11],
        [1, 5, 9],
        [5, 11, 4],
        [11, 10, 2],
        [10, 7, 6],
        [7, 1, 8],
        [3, 9, 4],
        [3, 4, 2],
        [3, 2, 6],
        [3, 6, 8],
        [3, 8, 9],
        [4, 9, 5],
        [2, 4, 11],
        [6, 2, 10],
        [8, 6, 7],
        [9, 8, 1],
    ];
    RawMesh::from_arrays(positions, faces)
}

/// The bipyramid over the regular n-gon on the unit circle in z = 0, apexes (0, 0, ±1): two
/// vertices of degree n, n equator vertices of degree 4 (a simplicial surface for n ≥ 3).
pub fn bipyramid(n: u32) -> RawMesh {
    bipyramid_with_apexes(n, [0.0, 0.0, 1.0], [0.0, 0.0, -1.0])
}

/// [`bipyramid`] with its apexes (vertices 0 and 1) at `top` and `bottom`; moving them lets
/// tests fold or cross the two stars.
pub fn bipyramid_with_apexes(n: u32, top: [f64; 3], bottom: [f64; 3]) -> RawMesh {
    let mut positions = vec![top, bottom];
    let mut faces = Vec::new();
    for i in 0..n {
        let a = 2.0 * std::f64::consts::PI * f64::from(i) / f64::from(n);
        positions.push([a.cos(), a.sin(), 0.0]);
        let (p, q) = (2 + i, 2 + (i + 1) % n);
        faces.push([0, p, q]);
        faces.push([1, q, p]);
    }
    RawMesh::from_arrays(positions, faces)
}

/// A torus of revolution sampled on an n × m grid (n, m ≥ 3), every vertex of degree 6.
pub fn torus(n: u32, m: u32) -> RawMesh {
    let (n, m) = (n.max(3), m.max(3));
    let (big, small) = (2.0, 0.75);
    let mut positions = Vec::new();
    for i in 0..n {
        let a = 2.0 * std::f64::consts::PI * i as f64 / n as f64;
        for j in 0..m {
            let b = 2.0 * std::f64::consts::PI * j as f64 / m as f64;
            let r = big + small * b.cos();
            positions.push([r * a.cos(), r * a.sin(), small * b.sin()]);
        }
    }
    let id = |i: u32, j: u32| (i % n) * m + (j % m);
    let mut faces = Vec::new();
    for i in 0..n {
        for j in 0..m {
            faces.push([id(i, j), id(i + 1, j), id(i + 1, j + 1)]);
            faces.push([id(i, j), id(i + 1, j + 1), id(i, j + 1)]);
        }
    }
    RawMesh::from_arrays(positions, faces)
}

// ---------------------------------------------------------------------------------------------
// Random closed surfaces by local surgery (SPEC `D3.1.6-random`): edge flips, edge splits and 1→3 face
// splits on a closed, consistently oriented triangle list. Each operation keeps the triangle
// list a closed combinatorial surface (every edge in two triangles, every link one cycle, same
// Euler characteristic for flips, +0 for splits since ΔV − ΔE + ΔF = 0); the geometry (Def.
// 3.1.3(ii): no self-intersection) is not guaranteed, so callers re-validate and discard a
// step that breaks it ([`grow`] does).
// ---------------------------------------------------------------------------------------------

/// One surgery step. Indices are reduced modulo the number of edges / faces / vertices of the
/// current mesh, so any `usize` is meaningful (fuzzers and property tests pick them freely).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SurfaceOp {
    /// Flip the k-th edge (sorted order): [a, b] with triangles (a, b, c), (b, a, d) becomes
    /// [c, d]. Skipped when [c, d] is already an edge (this also keeps every degree ≥ 3).
    Flip(usize),
    /// Split the k-th edge at its midpoint: +1 vertex of degree 4, the two opposite vertices
    /// gain one.
    SplitEdge(usize),
    /// 1→3 split of the k-th face at its centroid: +1 vertex of degree 3, the corners gain one.
    SplitFace(usize),
    /// Raise the degree of vertex v (mod #vertices) by one: flip the k-th edge opposite v in
    /// its star (mod its degree), falling back to a 1→3 split of the k-th face around v when
    /// that flip is not allowed.
    Raise {
        /// Vertex index, taken modulo the number of vertices.
        v: usize,
        /// Which edge opposite v (or face around v) to use, modulo the degree of v.
        k: usize,
    },
}

/// A closed triangle list under surgery: positions and consistently oriented faces.
#[derive(Debug, Clone, PartialEq)]
pub struct Surgery {
    /// Vertex positions; surgery only appends.
    pub positions: Vec<[f64; 3]>,
    /// Faces as 0-based vertex indices, consistently oriented.
    pub faces: Vec<[u32; 3]>,
}

impl Surgery {
    /// Start from a closed mesh (e.g. [`tetrahedron`], [`torus`]).
    pub fn new(base: &RawMesh) -> Self {
        Surgery {
            positions: base.positions.clone(),
            faces: base.faces.clone(),
        }
    }

    /// The mesh as a [`RawMesh`] (origins are element indices).
    pub fn to_raw(&self) -> RawMesh {
        RawMesh::from_arrays(self.positions.clone(), self.faces.clone())
    }

    /// Undirected edges (a, b), a < b, sorted.
    pub fn edges(&self) -> Vec<(u32, u32)> {
        let mut e: Vec<(u32, u32)> = self
            .faces
            .iter()
            .flat_map(|t| (0..3).map(move |k| (t[k].min(t[(k + 1) % 3]), t[k].max(t[(k + 1) % 3]))))
            .collect();
        e.sort_unstable();
        e.dedup();
        e
    }

    /// Number of triangles at each vertex (m_v of Def. 4.1.1 for a closed surface).
    pub fn degrees(&self) -> Vec<u32> {
        let mut d = vec![0u32; self.positions.len()];
        for t in &self.faces {
            for &c in t {
                if let Some(x) = d.get_mut(c as usize) {
                    *x += 1;
                }
            }
        }
        d
    }

    /// Euler characteristic V − E + F of the referenced complex.
    pub fn euler_characteristic(&self) -> i64 {
        let v = self.degrees().iter().filter(|&&d| d > 0).count() as i64;
        v - self.edges().len() as i64 + self.faces.len() as i64
    }

    /// The face containing the directed edge a → b and the corner opposite it.
    fn directed(&self, a: u32, b: u32) -> Option<(usize, u32)> {
        self.faces.iter().enumerate().find_map(|(f, t)| {
            (0..3)
                .find(|&k| t[k] == a && t[(k + 1) % 3] == b)
                .map(|k| (f, t[(k + 2) % 3]))
        })
    }

    fn has_edge(&self, a: u32, b: u32) -> bool {
        self.faces.iter().any(|t| {
            (0..3).any(|k| (t[k] == a && t[(k + 1) % 3] == b) || (t[k] == b && t[(k + 1) % 3] == a))
        })
    }

    /// Flip [a, b]; `false` (mesh unchanged) when not a two-triangle edge or [c, d] exists.
    pub fn flip(&mut self, a: u32, b: u32) -> bool {
        let (Some((f1, c)), Some((f2, d))) = (self.directed(a, b), self.directed(b, a)) else {
            return false;
        };
        if c == d || self.has_edge(c, d) {
            return false;
        }
        self.faces[f1] = [c, a, d];
        self.faces[f2] = [d, b, c];
        true
    }

    /// Split [a, b] at its midpoint; `false` when [a, b] is not a two-triangle edge.
    pub fn split_edge(&mut self, a: u32, b: u32) -> bool {
        let (Some((f1, c)), Some((f2, d))) = (self.directed(a, b), self.directed(b, a)) else {
            return false;
        };
        let (Some(pa), Some(pb)) = (
            self.positions.get(a as usize),
            self.positions.get(b as usize),
        ) else {
            return false;
        };
        let mid = [0, 1, 2].map(|i| 0.5 * (pa[i] + pb[i]));
        let p = self.positions.len() as u32;
        self.positions.push(mid);
        self.faces[f1] = [a, p, c];
        self.faces.push([p, b, c]);
        self.faces[f2] = [b, p, d];
        self.faces.push([p, a, d]);
        true
    }

    /// 1→3 split of face f at its centroid; `false` when f does not exist.
    pub fn split_face(&mut self, f: usize) -> bool {
        let Some(&[a, b, c]) = self.faces.get(f) else {
            return false;
        };
        let mut cen = [0.0; 3];
        for v in [a, b, c] {
            let Some(q) = self.positions.get(v as usize) else {
                return false;
            };
            for i in 0..3 {
                cen[i] += q[i] / 3.0;
            }
        }
        let p = self.positions.len() as u32;
        self.positions.push(cen);
        self.faces[f] = [a, b, p];
        self.faces.push([b, c, p]);
        self.faces.push([c, a, p]);
        true
    }

    /// Apply one step combinatorially (no geometric check). `false` when it was not applicable.
    pub fn apply(&mut self, op: SurfaceOp) -> bool {
        match op {
            SurfaceOp::Flip(k) => {
                let e = self.edges();
                match e.get(k % e.len().max(1)) {
                    Some(&(a, b)) => self.flip(a, b),
                    None => false,
                }
            }
            SurfaceOp::SplitEdge(k) => {
                let e = self.edges();
                match e.get(k % e.len().max(1)) {
                    Some(&(a, b)) => self.split_edge(a, b),
                    None => false,
                }
            }
            SurfaceOp::SplitFace(k) => self.split_face(k % self.faces.len().max(1)),
            SurfaceOp::Raise { v, k } => {
                let nv = self.positions.len().max(1);
                let v = (v % nv) as u32;
                let around: Vec<usize> = (0..self.faces.len())
                    .filter(|&f| self.faces[f].contains(&v))
                    .collect();
                let Some(&f) = around.get(k % around.len().max(1)) else {
                    return false;
                };
                let t = self.faces[f];
                let Some(pos) = t.iter().position(|&x| x == v) else {
                    return false;
                };
                // The edge of f opposite v.
                let (a, b) = (t[(pos + 1) % 3], t[(pos + 2) % 3]);
                self.flip(a, b) || self.split_face(f)
            }
        }
    }

    /// Corrupt the mesh in one of the ways the validator must reject (or, for
    /// [`Corruption::FlipOrientation`], re-orient). Returns the expected outcome.
    pub fn corrupt(&mut self, c: Corruption) -> Option<Expected> {
        use crate::mesh::validate::ErrorClass;
        let nf = self.faces.len();
        match c {
            Corruption::DeleteFace(k) => {
                if nf == 0 {
                    return None;
                }
                self.faces.remove(k % nf);
                Some(Expected::Rejected(ErrorClass::Boundary))
            }
            Corruption::DuplicateFace(k) => {
                let t = *self.faces.get(k % nf.max(1))?;
                self.faces.push(t);
                Some(Expected::Rejected(ErrorClass::DuplicateFace))
            }
            Corruption::FlipOrientation(k) => {
                let t = self.faces.get_mut(k % nf.max(1))?;
                t.swap(1, 2);
                Some(Expected::Reoriented)
            }
            Corruption::GlueVertices(k) => {
                // Two vertices at combinatorial distance ≥ 3 (disjoint closed stars): gluing
                // them makes the link of the result two disjoint cycles.
                let nv = self.positions.len();
                let mut adj = vec![Vec::new(); nv];
                for (a, b) in self.edges() {
                    adj[a as usize].push(b as usize);
                    adj[b as usize].push(a as usize);
                }
                let a = k % nv.max(1);
                let mut dist = vec![usize::MAX; nv];
                let mut q = std::collections::VecDeque::from([a]);
                *dist.get_mut(a)? = 0;
                while let Some(x) = q.pop_front() {
                    for &y in &adj[x] {
                        if dist[y] == usize::MAX {
                            dist[y] = dist[x] + 1;
                            q.push_back(y);
                        }
                    }
                }
                let far: Vec<usize> = (0..nv)
                    .filter(|&y| dist[y] >= 3 && dist[y] != usize::MAX)
                    .collect();
                let b = *far.get((k / nv.max(1)) % far.len().max(1))?;
                for t in &mut self.faces {
                    for c in t.iter_mut() {
                        if *c as usize == b {
                            *c = a as u32;
                        }
                    }
                }
                Some(Expected::Rejected(ErrorClass::NonmanifoldVertex))
            }
        }
    }
}

/// Corruptions of a closed surface for the validator property tests.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Corruption {
    /// Remove the k-th face: its three edges become boundary edges (Def. 3.1.6).
    DeleteFace(usize),
    /// List the k-th face twice.
    DuplicateFace(usize),
    /// Identify two vertices at distance ≥ 3 (index derived from k): a non-manifold vertex.
    GlueVertices(usize),
    /// Reverse the k-th face's orientation. Not a defect of Def. 3.1.6 (K is unoriented): the
    /// validator re-orients and counts the face (SPEC row `X-input`).
    FlipOrientation(usize),
}

/// What the validator must say about a corrupted surface.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Expected {
    /// Not a simplicial surface, with this error class among those reported.
    Rejected(crate::mesh::validate::ErrorClass),
    /// Still a simplicial surface; the face is reversed by the validator.
    Reoriented,
}

/// Apply `ops` in order, re-validating after each step and undoing any step after which the
/// mesh is no longer a simplicial surface in R³ (Def. 3.1.6, decided exactly). Returns the
/// result and the number of steps kept. `base` must itself be a simplicial surface.
pub fn grow(base: &RawMesh, ops: &[SurfaceOp]) -> (Surgery, usize) {
    let mut s = Surgery::new(base);
    let mut kept = 0;
    for &op in ops {
        let mut t = s.clone();
        if t.apply(op)
            && crate::mesh::validate::validate(&t.to_raw())
                .report
                .is_simplicial_surface
        {
            s = t;
            kept += 1;
        }
    }
    (s, kept)
}
