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
