//! Def. 5.2.1: Bernstein polynomials over [−L, L] and tensor-product Bézier patches of
//! bi-degree (l, l), in f64 (the generic evaluation, over any [`super::SurfaceScalar`], is
//! the trait's own, in `scalar_ext`). Control point b_{j,k} is stored at index j·(l+1) + k (the paper's
//! "j·l + k + 1" would make different (j, k) collide: a bi-degree (l, l) patch has (l+1)²
//! control points, not l²).

/// Binomial coefficient C(n, k) as f64 (exact for n ≤ 56).
pub fn binomial(n: usize, k: usize) -> f64 {
    if k > n {
        return 0.0;
    }
    let k = k.min(n - k);
    let mut r = 1.0f64;
    for i in 0..k {
        r = r * (n - i) as f64 / (i + 1) as f64;
    }
    r.round()
}

/// Row l of Pascal's triangle as [`binomial`] computes it, for l ≤ [`MAX_FAST_L`] (computed
/// once: the evaluators of Def. 5.2.1 need it at every point).
pub(super) fn binomial_row(l: usize) -> Option<&'static [f64]> {
    static TABLE: std::sync::OnceLock<Vec<Vec<f64>>> = std::sync::OnceLock::new();
    TABLE
        .get_or_init(|| {
            (0..=MAX_FAST_L)
                .map(|n| (0..=n).map(|k| binomial(n, k)).collect())
                .collect()
        })
        .get(l)
        .map(|r| r.as_slice())
}

/// Def. 5.2.1: B_i^l(t) = C(l,i) ((L−t)/2L)^{l−i} ((t+L)/2L)^i for i = 0..=l, in f64.
pub fn bernstein_f64(l: usize, half: f64, t: f64, out: &mut [f64]) {
    if let Some(row) = binomial_row(l) {
        let u = (t + half) / (2.0 * half);
        let w = (half - t) / (2.0 * half);
        let mut pu = 1.0;
        for o in out.iter_mut().take(l + 1) {
            *o = pu;
            pu *= u;
        }
        let mut pw = 1.0;
        for i in (0..=l).rev() {
            out[i] *= pw * row[i];
            pw *= w;
        }
        return;
    }
    let u = (t + half) / (2.0 * half);
    let w = (half - t) / (2.0 * half);
    // out[i] = u^i, then multiply by w^{l-i} from the right end.
    let mut pu = 1.0;
    for o in out.iter_mut().take(l + 1) {
        *o = pu;
        pu *= u;
    }
    let mut pw = 1.0;
    for i in (0..=l).rev() {
        out[i] *= pw * binomial(l, i);
        pw *= w;
    }
}

/// [`bernstein_f64`] into a new vector (any l).
pub fn bernstein_vec_f64(l: usize, half: f64, t: f64) -> Vec<f64> {
    let mut out = vec![0.0; l + 1];
    bernstein_f64(l, half, t, &mut out);
    out
}

/// Largest l for the stack-allocated f64 evaluator.
pub const MAX_FAST_L: usize = 63;

/// ψ(x, y) in f64 without allocation (l ≤ [`MAX_FAST_L`]). Contracts x first:
/// t_k = Σ_j B_j^l(x) b_{j,k} is one vectorisable axpy per j over the contiguous row
/// (b_{j,0}, …, b_{j,l}) of 3(l+1) coordinates; then ψ = Σ_k B_k^l(y) t_k.
pub fn eval_patch_f64(cp: &[[f64; 3]], l: usize, half: f64, x: f64, y: f64) -> [f64; 3] {
    let mut bx = [0.0f64; MAX_FAST_L + 1];
    let mut by = [0.0f64; MAX_FAST_L + 1];
    bernstein_f64(l, half, x, &mut bx);
    bernstein_f64(l, half, y, &mut by);
    let l1 = l + 1;
    let mut t = [0.0f64; 3 * (MAX_FAST_L + 1)];
    let t = &mut t[..3 * l1];
    for (j, &b) in bx.iter().enumerate().take(l1) {
        let row = cp[j * l1..(j + 1) * l1].as_flattened();
        for (a, &c) in t.iter_mut().zip(row) {
            *a += b * c;
        }
    }
    let mut out = [0.0; 3];
    for (k, tk) in t.chunks_exact(3).enumerate() {
        out[0] += by[k] * tk[0];
        out[1] += by[k] * tk[1];
        out[2] += by[k] * tk[2];
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Def. 5.2.1 in f64, both branches (the tabulated binomials up to l = MAX_FAST_L and the
    /// computed ones beyond, degrees m ≥ 63): the generic evaluation gives the same values, and
    /// the l + 1 values sum to 1 (partition of unity).
    #[test]
    fn d5_2_1_bernstein_f64_matches_the_generic_values_beyond_the_table() {
        for l in [3, 7, MAX_FAST_L, MAX_FAST_L + 1, 80] {
            for t in [-0.9, -0.3, 0.0, 0.45, 0.99] {
                let half = 1.0;
                let f = bernstein_vec_f64(l, half, t);
                let g = crate::surface::scalar_ext::bernstein::<f64>(l, &half, &t);
                let sum: f64 = f.iter().sum();
                assert!((sum - 1.0).abs() < 1e-12, "l {l}, t {t}: Σ = {sum}");
                for (i, (a, b)) in f.iter().zip(&g).enumerate() {
                    assert!(
                        (a - b).abs() <= 1e-12 * b.abs().max(1e-300),
                        "l {l}, t {t}, i {i}: {a} vs {b}"
                    );
                }
            }
        }
    }
}
