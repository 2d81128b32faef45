//! Sec. 5.2: the least-squares fit of the shape functions ψ_v (Def. 5.2.1).
//!
//! The design matrix A (A_{i, j(l+1)+k} = B_j^l(x_i)·B_k^l(y_i)) depends only on m_v and the
//! profile, so it is factored once per degree by a thin SVD (no normal equations: the
//! Bernstein tensor basis clipped to P_v is ill-conditioned, κ(A) ≈ 10⁴–10¹², and AᵀA would
//! square that). Singular values below σ_max · max(RCOND, max(n, (l+1)²)·ε) are dropped (minimum-norm
//! least-squares solution); the numerical rank and κ are reported per degree.
//!
//! Speed: the SVD is block-diagonalised by the reflection symmetries of P_v and of
//! the grid (y ↦ −y always, x ↦ −x for even m_v; see [`factor_degree`]): an orthogonal change
//! of basis, so the singular values, rank, κ and A⁺ are those of A up to rounding, at 1/4
//! (odd m_v) to 1/16 (even m_v) of the cost — degree 26 (2220 × 784) went from ~0.9 s to
//! ~0.1 s. The per-vertex fit is then one matrix product per batch of vertices
//! (`Pps::build`).
//!
//! The sample set of Sec. 5.2: a uniform grid on □_v = [−L, L]², L = cos(π/m_v), both ends
//! included; points outside the closed P-polygon P_v are dropped; each kept point q lies in a
//! triangle s_v(σ) = [v′, v′_i, v′_{i+1}] of T_v, whose barycentric coordinates (λ, ν, η) give
//! the point of S′ paired with q: b_σ(λa + νb + ηc).

use super::bezier::bernstein_f64;
use super::profile::Profile;
use super::target::cubic_bernstein;
use serde::Serialize;

/// Relative truncation of the SVD: singular values ≤ RCOND·σ_max are dropped. With the
/// rank-revealing floor max(n, k)·ε alone, high-degree fits (m ≥ 19) return minimum-norm
/// solutions with control points ~10⁹ times the geometry (cancellation then costs ~10⁻⁷ in
/// every evaluation of ψ_v); 10⁻⁹ bounds the amplification of the truncated problem.
pub const RCOND: f64 = 1e-9;

/// One sample of Sec. 5.2 (depends on the degree only).
#[derive(Debug, Clone, Copy, Serialize)]
pub struct Sample {
    /// q ∈ P_v ∩ □_v.
    pub q: [f64; 2],
    /// i: q ∈ [v′, v′_i, v′_{i+1}].
    pub sector: u32,
    /// Barycentric coordinates of q w.r.t. (v′, v′_i, v′_{i+1}).
    pub bary: [f64; 3],
}

/// Summary of the per-degree factorization (reported by `ppm sample`/checks).
#[derive(Debug, Clone, Serialize)]
pub struct DegreeFitInfo {
    /// m, the vertex degree.
    pub m: u32,
    /// l, the Bézier bi-degree (Sec. 5.2).
    pub l: usize,
    /// L = cos(π/m): □_v = [−L, L]².
    pub half_side: f64,
    /// Grid points kept (in P_v): the rows of A.
    pub rows: usize,
    /// Unknowns per coordinate: (l+1)².
    pub unknowns: usize,
    /// Numerical rank of A (singular values > σ_max · max(RCOND, max(n, k) · ε)).
    pub rank: usize,
    /// κ(A) = σ_max/σ_min over all singular values (∞ if σ_min = 0).
    pub condition: f64,
    /// σ_max/σ_rank: the condition number of the truncated problem actually solved.
    pub effective_condition: f64,
}

/// The factored least-squares problem for one degree.
#[derive(Debug, Clone)]
pub struct DegreeFit {
    /// Summary of the factorization.
    pub info: DegreeFitInfo,
    /// The grid points kept in P_v, in row order of A.
    pub samples: Vec<Sample>,
    /// A⁺, (l+1)² × rows, row-major.
    pub pinv: Vec<f64>,
    /// A⁺·W for cubic-triangle targets: (l+1)² × (m·10), row-major; column i·10 + t is the
    /// weight of control point t (in `CUBIC_ORDER`) of the cubic net of sector i.
    pub net_map: Vec<f64>,
}

/// The Sec. 5.2 sample set for degree m.
pub fn sample_set(m: u32, profile: Profile) -> Vec<Sample> {
    sample_grid(m, profile)
        .into_iter()
        .map(|(s, _)| s)
        .collect()
}

/// The Sec. 5.2 samples with their grid indices (a, b): x = −L + 2La/(n−1), y likewise.
fn sample_grid(m: u32, profile: Profile) -> Vec<(Sample, [usize; 2])> {
    let l = profile.bezier_degree(m);
    let n = profile.grid_side(l);
    let mf = m as f64;
    let half = (std::f64::consts::PI / mf).cos();
    let corner = |i: u32| {
        let a = 2.0 * std::f64::consts::PI * (i % m) as f64 / mf;
        [a.cos(), a.sin()]
    };
    let mut out = Vec::with_capacity(n * n);
    for a in 0..n {
        for b in 0..n {
            let x = -half + 2.0 * half * a as f64 / (n - 1) as f64;
            let y = -half + 2.0 * half * b as f64 / (n - 1) as f64;
            let mut ang = y.atan2(x);
            if ang < 0.0 {
                ang += 2.0 * std::f64::consts::PI;
            }
            let i = ((ang * mf / (2.0 * std::f64::consts::PI)).floor() as u32).min(m - 1);
            let (p, r) = (corner(i), corner(i + 1));
            // q = ν p + η r.
            let det = p[0] * r[1] - p[1] * r[0];
            let nu = (x * r[1] - y * r[0]) / det;
            let eta = (p[0] * y - p[1] * x) / det;
            let lam = 1.0 - nu - eta;
            if lam < -1e-12 {
                continue; // outside P_v
            }
            out.push((
                Sample {
                    q: [x, y],
                    sector: i,
                    bary: [lam.max(0.0), nu, eta],
                },
                [a, b],
            ));
        }
    }
    out
}

/// The reflection g (bit 0: y ↦ −y, bit 1: x ↦ −x) on the Bézier index c = j·(l+1) + k of
/// the bi-degree-l tensor basis: y ↦ −y maps B_k to B_{l−k}, x ↦ −x maps B_j to B_{l−j}.
fn column_action(l: usize, c: usize, g: u8) -> usize {
    let l1 = l + 1;
    let (mut j, mut kk) = (c / l1, c % l1);
    if g & 1 != 0 {
        kk = l - kk;
    }
    if g & 2 != 0 {
        j = l - j;
    }
    j * l1 + kk
}

/// Orbits of a set (grid samples, or Bézier indices (j, k)) under a group of reflections of
/// □_v. Group elements are bit masks: bit 0 = y ↦ −y, bit 1 = x ↦ −x.
struct Orbits {
    /// Per orbit: the members and the group element mapping the representative (first
    /// member) to each.
    members: Vec<Vec<(usize, u8)>>,
    /// Per orbit: the stabilizer of the representative (bit g set if g fixes it).
    stab: Vec<u8>,
}

impl Orbits {
    /// `act(i, g)`: the image of item i under g, `None` if it is not in the set (then the set
    /// is not invariant and `None` is returned).
    fn new(count: usize, group: &[u8], act: impl Fn(usize, u8) -> Option<usize>) -> Option<Self> {
        let mut seen = vec![false; count];
        let mut members = Vec::new();
        let mut stab = Vec::new();
        for i in 0..count {
            if seen[i] {
                continue;
            }
            let mut orbit: Vec<(usize, u8)> = Vec::with_capacity(group.len());
            let mut st = 0u8;
            for &g in group {
                let x = act(i, g)?;
                if x == i {
                    st |= 1 << g;
                }
                if !orbit.iter().any(|&(y, _)| y == x) {
                    if seen[x] {
                        return None; // not a group action on this set
                    }
                    seen[x] = true;
                    orbit.push((x, g));
                }
            }
            members.push(orbit);
            stab.push(st);
        }
        Some(Orbits { members, stab })
    }

    /// The orbits on which the character `chi` is trivial on the stabilizer: they index the
    /// rows (columns) of the χ-block.
    fn for_character(&self, group: &[u8], chi: u8) -> Vec<usize> {
        (0..self.members.len())
            .filter(|&o| {
                group
                    .iter()
                    .all(|&g| self.stab[o] & (1 << g) == 0 || character(chi, g) > 0.0)
            })
            .collect()
    }
}

/// χ(g) = (−1)^{|g ∧ χ|} for the characters of (Z/2)² (bit masks as in [`Orbits`]).
fn character(chi: u8, g: u8) -> f64 {
    if (chi & g).count_ones() % 2 == 0 {
        1.0
    } else {
        -1.0
    }
}

/// Factor the least-squares problem of degree m (thin SVD) and precompute A⁺ and A⁺·W.
///
/// Symmetry reduction (exact in exact arithmetic, an orthogonal change of basis of rows and
/// columns — no normal equations): P_v is symmetric under y ↦ −y, and under x ↦ −x when m_v
/// is even; the grid on □_v is too, and B_j^l(−t) = B_{l−j}^l(t) on [−L, L]. With
/// A[g·x, g·y] = A[x, y] for every reflection g of the group G, the orthonormal bases
/// u_{O,χ} = |O|^{−1/2} Σ_{x∈O} χ(g_x) e_x of the isotypic components (O an orbit, χ a
/// character of G) block-diagonalise A: UᵀAW = ⊕_χ B_χ with B_χ[O, O′] =
/// (|O|/|O′|)^{1/2} Σ_{y∈O′} χ(g_y) A[rep O, y]. The singular values of A are those of the
/// blocks, A⁺ = ⊕ W_χ B_χ⁺ U_χᵀ with the same global truncation, and the SVD costs
/// |G|² ≈ 4–16 times less (|G| blocks of 1/|G| the rows and columns). If the clipped grid is
/// not exactly invariant (a boundary sample dropped on one side only) the group is reduced,
/// down to the trivial group (plain thin SVD of A).
pub fn factor_degree(m: u32, profile: Profile) -> DegreeFit {
    factor_degree_with(m, profile, true)
}

/// [`factor_degree`] without the symmetry blocks (one thin SVD of A): the unstructured
/// baseline of the scaling experiment (`examples/fit_scaling.rs`, SPEC `R-fit-scaling`).
pub fn factor_degree_plain(m: u32, profile: Profile) -> DegreeFit {
    factor_degree_with(m, profile, false)
}

/// [`factor_degree`]; `symmetric = false` forces the trivial group (one thin SVD of A).
fn factor_degree_with(m: u32, profile: Profile, symmetric: bool) -> DegreeFit {
    let l = profile.bezier_degree(m);
    let l1 = l + 1;
    let k = l1 * l1;
    let grid = sample_grid(m, profile);
    let side = profile.grid_side(l);
    let n = grid.len();
    let half = (std::f64::consts::PI / m as f64).cos();
    // Grid index → sample index.
    let mut at = vec![usize::MAX; side * side];
    for (i, (_, [a, b])) in grid.iter().enumerate() {
        at[a * side + b] = i;
    }
    let row_act = |i: usize, g: u8| -> Option<usize> {
        let [mut a, mut b] = grid[i].1;
        if g & 1 != 0 {
            b = side - 1 - b;
        }
        if g & 2 != 0 {
            a = side - 1 - a;
        }
        let s = at[a * side + b];
        (s != usize::MAX).then_some(s)
    };
    let col_act = |c: usize, g: u8| Some(column_action(l, c, g));
    let candidates: &[&[u8]] = match (symmetric, m % 2 == 0) {
        (false, _) => &[],
        (true, true) => &[&[0, 1, 2, 3], &[0, 1]],
        (true, false) => &[&[0, 1]],
    };
    let mut chosen = None;
    for &group in candidates {
        if let (Some(ro), Some(co)) = (
            Orbits::new(n, group, row_act),
            Orbits::new(k, group, col_act),
        ) {
            chosen = Some((group, ro, co));
            break;
        }
    }
    let (group, rows, cols) = match chosen {
        Some(c) => c,
        None => trivial_group(n, k),
    };
    let samples: Vec<Sample> = grid.into_iter().map(|(s, _)| s).collect();
    // Rows of A at the row-orbit representatives.
    let mut bx = vec![0.0; l1];
    let mut by = vec![0.0; l1];
    let rep_rows: Vec<Vec<f64>> = rows
        .members
        .iter()
        .map(|o| {
            let s = &samples[o[0].0];
            bernstein_f64(l, half, s.q[0], &mut bx);
            bernstein_f64(l, half, s.q[1], &mut by);
            let mut r = vec![0.0; k];
            for j in 0..l1 {
                for kk in 0..l1 {
                    r[j * l1 + kk] = bx[j] * by[kk];
                }
            }
            r
        })
        .collect();
    struct Block {
        chi: u8,
        rows: Vec<usize>,
        cols: Vec<usize>,
        svd: nalgebra::SVD<f64, nalgebra::Dyn, nalgebra::Dyn>,
    }
    let mut blocks: Vec<Block> = Vec::with_capacity(group.len());
    for &chi in group {
        let br = rows.for_character(group, chi);
        let bc = cols.for_character(group, chi);
        if br.is_empty() || bc.is_empty() {
            continue;
        }
        let b = nalgebra::DMatrix::<f64>::from_fn(br.len(), bc.len(), |i, j| {
            let (r, c) = (br[i], bc[j]);
            let a = &rep_rows[r];
            let scale = (rows.members[r].len() as f64 / cols.members[c].len() as f64).sqrt();
            let mut acc = 0.0;
            for &(y, g) in &cols.members[c] {
                acc += character(chi, g) * a[y];
            }
            scale * acc
        });
        blocks.push(Block {
            chi,
            rows: br,
            cols: bc,
            svd: b.svd(true, true),
        });
    }
    let smax = blocks
        .iter()
        .flat_map(|b| b.svd.singular_values.iter().cloned())
        .fold(0.0, crate::report::dev_max);
    // κ(A) is finite only if every block has at least as many rows as columns.
    let smin_all = if blocks.iter().all(|b| b.rows.len() >= b.cols.len())
        && blocks.iter().map(|b| b.cols.len()).sum::<usize>() == k
    {
        blocks
            .iter()
            .flat_map(|b| b.svd.singular_values.iter().cloned())
            .fold(f64::INFINITY, f64::min)
    } else {
        0.0
    };
    let tol = smax * RCOND.max(n.max(k) as f64 * f64::EPSILON);
    let kept = || {
        blocks
            .iter()
            .flat_map(|b| b.svd.singular_values.iter().cloned())
            .filter(|&s| s > tol)
    };
    let rank = kept().count();
    let smin_kept = kept().fold(f64::INFINITY, f64::min);
    let mut pinv = vec![0.0; k * n];
    for b in &blocks {
        let (Some(u), Some(vt)) = (&b.svd.u, &b.svd.v_t) else {
            continue;
        };
        // B⁺ = V Σ⁺ Uᵀ over the kept singular values.
        let keep: Vec<usize> = (0..b.svd.singular_values.len())
            .filter(|&s| b.svd.singular_values[s] > tol)
            .collect();
        if keep.is_empty() {
            continue;
        }
        let vk = nalgebra::DMatrix::<f64>::from_fn(b.cols.len(), keep.len(), |c, s| {
            vt[(keep[s], c)] / b.svd.singular_values[keep[s]]
        });
        let uk =
            nalgebra::DMatrix::<f64>::from_fn(b.rows.len(), keep.len(), |r, s| u[(r, keep[s])]);
        let bplus = vk * uk.transpose();
        // A⁺[y, x] += χ(g_y) χ(g_x) (|O_c| |O_r|)^{−1/2} B⁺[c, r].
        for (bj, &c) in b.cols.iter().enumerate() {
            let oc = &cols.members[c];
            for (bi, &r) in b.rows.iter().enumerate() {
                let or = &rows.members[r];
                let w = bplus[(bj, bi)] / ((oc.len() * or.len()) as f64).sqrt();
                for &(y, gy) in oc {
                    let wy = w * character(b.chi, gy);
                    let row = &mut pinv[y * n..(y + 1) * n];
                    for &(x, gx) in or {
                        row[x] += wy * character(b.chi, gx);
                    }
                }
            }
        }
    }
    let cols = m as usize * 10;
    let mut net_map = vec![0.0; k * cols];
    for (i, s) in samples.iter().enumerate() {
        let w = cubic_bernstein(s.bary);
        let base = s.sector as usize * 10;
        for c in 0..k {
            let a = pinv[c * n + i];
            if a == 0.0 {
                continue;
            }
            let row = &mut net_map[c * cols + base..c * cols + base + 10];
            for t in 0..10 {
                row[t] += a * w[t];
            }
        }
    }
    DegreeFit {
        info: DegreeFitInfo {
            m,
            l,
            half_side: half,
            rows: n,
            unknowns: k,
            rank,
            condition: if smin_all > 0.0 {
                smax / smin_all
            } else {
                f64::INFINITY
            },
            effective_condition: smax / smin_kept,
        },
        samples,
        pinv,
        net_map,
    }
}

/// The trivial group and its singleton orbits (acts on any set).
fn trivial_group(n: usize, k: usize) -> (&'static [u8], Orbits, Orbits) {
    let single = |c: usize| Orbits {
        members: (0..c).map(|i| vec![(i, 0u8)]).collect(),
        stab: vec![1; c],
    };
    (&[0], single(n), single(k))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Sec. 5.2 (the fit's symmetry reduction): the reflections act on the Bézier indices as
    /// the group Z₂ × Z₂ (identity fixes every index, g∘h = g xor h) and the orbits accept it,
    /// so the factorisation uses the blocks instead of falling back to one plain SVD (which
    /// gives the same A⁺, so only this test sees a wrong action).
    #[test]
    fn d5_2_1_reflections_act_on_the_bezier_indices_as_a_group() {
        for l in 1..=13usize {
            let count = (l + 1) * (l + 1);
            for c in 0..count {
                assert_eq!(column_action(l, c, 0), c, "identity, l={l}, c={c}");
                for g in 0..4u8 {
                    for h in 0..4u8 {
                        let gh = column_action(l, column_action(l, c, h), g);
                        assert_eq!(gh, column_action(l, c, g ^ h), "l={l}, c={c}, g={g}, h={h}");
                    }
                }
            }
            let act = |c: usize, g: u8| Some(column_action(l, c, g));
            assert!(Orbits::new(count, &[0, 1, 2, 3], act).is_some(), "l={l}");
        }
    }

    /// The symmetry-reduced factorization agrees with one thin SVD of A (rank, κ, A⁺).
    #[test]
    fn symmetric_blocks_agree_with_plain_svd() {
        for profile in [Profile::Paper, Profile::AuthorsCode] {
            for m in [3u32, 4, 5, 6, 7, 8, 11, 12] {
                let a = factor_degree_with(m, profile, true);
                let b = factor_degree_with(m, profile, false);
                assert_eq!(a.info.rank, b.info.rank, "m={m}");
                assert_eq!(a.samples.len(), b.samples.len());
                let rel = (a.info.condition / b.info.condition - 1.0).abs();
                assert!(
                    rel < 1e-6,
                    "m={m}: κ {} vs {}",
                    a.info.condition,
                    b.info.condition
                );
                // Perturbation bound of A⁺: κ_eff·ε relative (both are backward stable).
                let scale = b.pinv.iter().fold(0.0f64, |s, x| s.max(x.abs()))
                    * 64.0
                    * b.info.effective_condition
                    * f64::EPSILON;
                let dev = a
                    .pinv
                    .iter()
                    .zip(&b.pinv)
                    .fold(0.0f64, |s, (x, y)| s.max((x - y).abs()));
                assert!(
                    dev <= scale,
                    "m={m} {profile:?}: |ΔA⁺| = {dev:e} > {scale:e}"
                );
                eprintln!("m={m} {profile:?}: |ΔA⁺| = {dev:.2e} (bound {scale:.2e})");
                let dev = a
                    .net_map
                    .iter()
                    .zip(&b.net_map)
                    .fold(0.0f64, |s, (x, y)| s.max((x - y).abs()));
                assert!(dev <= scale, "m={m} {profile:?}: |ΔA⁺W| = {dev:e}");
            }
        }
    }
}
