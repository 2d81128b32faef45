//! The f64 jets' products, quotients and Bézier patches (Def. 5.2.1) without the generic
//! scalar's overhead, with the **same bits** as the generic code of [`super::jet`] and
//! [`super::bezier`].
//!
//! Why the bits are the same. The generic product sums the table's terms a·b in order from +0.
//! When one factor is a constant jet (every coefficient past the value is ±0) and the other
//! factor's coefficients are all finite, every term but one is ±0, so coefficient r is
//! +0 + (the one term) + (±0)… = `0.0 + p` with p that term: adding ±0 to a non-zero value
//! leaves it, and +0 + ±0 = +0. The generic quotient by a constant jet c multiplies by the
//! constant jet compose(c, [1/c, −1/c², 2/c³, −6/c⁴]), whose coefficients past the value are
//! ±0 when those four numbers are finite: the product rule above then applies. Any other case
//! (a non-finite coefficient, a non-constant factor) takes the table loop itself. The tests
//! below compare both with the table loop and the literal quotient bit for bit, signed zeros,
//! infinities and NaN included.

use super::jet::{idx, JET_LEN, MONOMIALS};

/// The product table of jets with `L` coefficients, as [`super::jet`] builds it: the triples
/// (a, b, c) with monomial a · monomial b = monomial c of degree ≤ the order, a then b
/// ascending.
const fn table<const L: usize>() -> ([(u8, u8, u8); 35], usize) {
    let order = match L {
        1 => 0,
        3 => 1,
        6 => 2,
        _ => 3,
    };
    let mut t = [(0u8, 0u8, 0u8); 35];
    let mut n = 0;
    let mut a = 0;
    while a < JET_LEN {
        let mut b = 0;
        while b < JET_LEN {
            let (ia, ja) = MONOMIALS[a];
            let (ib, jb) = MONOMIALS[b];
            if ia + ja + ib + jb <= order {
                t[n] = (a as u8, b as u8, idx(ia + ib, ja + jb) as u8);
                n += 1;
            }
            b += 1;
        }
        a += 1;
    }
    (t, n)
}

struct Table<const L: usize>;
impl<const L: usize> Table<L> {
    const T: ([(u8, u8, u8); 35], usize) = table::<L>();
}

/// The generic product: the table's terms summed in order from +0. Orders 1 and 2 are
/// written out term by term in the table's order (no index loads, no bounds checks; the
/// `0.0 + ` keeps the table loop's +0 for a product −0).
#[inline(always)]
pub(crate) fn mul_table<const L: usize>(a: &[f64; L], b: &[f64; L]) -> [f64; L] {
    let mut c = [0.0f64; L];
    if L == 6 {
        c[0] = 0.0 + a[0] * b[0];
        c[1] = (0.0 + a[0] * b[1]) + a[1] * b[0];
        c[2] = (0.0 + a[0] * b[2]) + a[2] * b[0];
        c[3] = ((0.0 + a[0] * b[3]) + a[1] * b[1]) + a[3] * b[0];
        c[4] = (((0.0 + a[0] * b[4]) + a[1] * b[2]) + a[2] * b[1]) + a[4] * b[0];
        c[5] = ((0.0 + a[0] * b[5]) + a[2] * b[2]) + a[5] * b[0];
        return c;
    }
    if L == 3 {
        c[0] = 0.0 + a[0] * b[0];
        c[1] = (0.0 + a[0] * b[1]) + a[1] * b[0];
        c[2] = (0.0 + a[0] * b[2]) + a[2] * b[0];
        return c;
    }
    mul_by_table(a, b)
}

/// The table loop itself (orders 0 and 3, and the reference of the tests).
#[inline(always)]
fn mul_by_table<const L: usize>(a: &[f64; L], b: &[f64; L]) -> [f64; L] {
    let mut c = [0.0f64; L];
    let (t, n) = &Table::<L>::T;
    for &(x, y, r) in &t[..*n] {
        c[r as usize] += a[x as usize] * b[y as usize];
    }
    c
}

#[inline]
fn is_constant<const L: usize>(a: &[f64; L]) -> bool {
    a[1..].iter().all(|&x| x == 0.0)
}

#[inline]
fn all_finite<const L: usize>(a: &[f64; L]) -> bool {
    a.iter().all(|x| x.is_finite())
}

/// `0.0 + a[k]·k` for every k: the product with the constant jet k when `a` is finite.
#[inline]
fn scale_plus_zero<const L: usize>(a: &[f64; L], k: f64) -> [f64; L] {
    std::array::from_fn(|i| 0.0 + a[i] * k)
}

/// The jet product, bit for bit [`mul_table`].
#[cfg(test)]
fn mul<const L: usize>(a: &[f64; L], b: &[f64; L]) -> [f64; L] {
    if is_constant(b) && all_finite(a) {
        return scale_plus_zero(a, b[0]);
    }
    if is_constant(a) && all_finite(b) {
        return scale_plus_zero(b, a[0]);
    }
    mul_table(a, b)
}

/// The product with the constant jet k, bit for bit [`mul_table`]`(a, constant(k))`.
#[inline]
fn mul_constant<const L: usize>(a: &[f64; L], k: f64) -> [f64; L] {
    if all_finite(a) {
        scale_plus_zero(a, k)
    } else {
        mul_table(a, &constant(k))
    }
}

/// The jet's `compose` of [`super::jet`]: f(a + h) = d₀ + d₁h + d₂/2 h² + d₃/6 h³, h the
/// nilpotent part of `a`, bit for bit. For orders ≤ 2 the table product h²·h has no term of
/// non-zero factors (h has no value, h² no terms below degree 2), so when h and h² are finite
/// it is +0 everywhere and is not formed.
#[inline]
pub(crate) fn compose<const L: usize>(a: &[f64; L], d: [f64; 4]) -> [f64; L] {
    let mut h = *a;
    h[0] = 0.0;
    let h2 = mul_table(&h, &h);
    let h3 = if L <= 6 && all_finite(&h) && all_finite(&h2) {
        [0.0; L]
    } else {
        mul_table(&h2, &h)
    };
    let (d2h, d3s) = (d[2] * 0.5, d[3] * (1.0 / 6.0));
    let mut r: [f64; L] = std::array::from_fn(|i| (h[i] * d[1] + h2[i] * d2h) + h3[i] * d3s);
    r[0] = d[0];
    r
}

/// [`compose`] with h²·h always formed (the reference of the tests).
#[cfg(test)]
fn compose_literal<const L: usize>(a: &[f64; L], d: [f64; 4]) -> [f64; L] {
    let mut h = *a;
    h[0] = 0.0;
    let h2 = mul_table(&h, &h);
    let h3 = mul_table(&h2, &h);
    let (d2h, d3s) = (d[2] * 0.5, d[3] * (1.0 / 6.0));
    let mut r: [f64; L] = std::array::from_fn(|i| (h[i] * d[1] + h2[i] * d2h) + h3[i] * d3s);
    r[0] = d[0];
    r
}

/// The literal jet quotient of [`super::jet`]: a · compose(b, [1/b₀, −1/b₀², 2/b₀³, −6/b₀⁴]).
pub(crate) fn div_literal<const L: usize>(a: &[f64; L], b: &[f64; L]) -> [f64; L] {
    let r = 1.0 / b[0];
    let r2 = r * r;
    let r3 = r2 * r;
    let r4 = r3 * r;
    let inv = compose(b, [r, -r2, r3 * 2.0, r4 * -6.0]);
    mul_table(a, &inv)
}

/// The jet quotient, bit for bit [`div_literal`].
#[inline]
pub(crate) fn div<const L: usize>(a: &[f64; L], b: &[f64; L]) -> [f64; L] {
    if is_constant(b) && all_finite(a) {
        let r = 1.0 / b[0];
        let r2 = r * r;
        let r3 = r2 * r;
        let r4 = r3 * r;
        // compose's coefficients past the value are ±0 exactly when these are finite.
        if (-r2).is_finite()
            && (r3 * 2.0 * 0.5).is_finite()
            && (r4 * -6.0 * (1.0 / 6.0)).is_finite()
        {
            return scale_plus_zero(a, r);
        }
    }
    div_literal(a, b)
}

/// The constant jet k.
#[inline]
fn constant<const L: usize>(k: f64) -> [f64; L] {
    let mut c = [0.0; L];
    c[0] = k;
    c
}

#[inline]
fn add<const L: usize>(a: &[f64; L], b: &[f64; L]) -> [f64; L] {
    std::array::from_fn(|i| a[i] + b[i])
}

#[inline]
fn sub<const L: usize>(a: &[f64; L], b: &[f64; L]) -> [f64; L] {
    std::array::from_fn(|i| a[i] - b[i])
}

/// [`super::bezier::bernstein`] on f64 jets, into `out[..=l]`: the same
/// operations in the same order, without the vector.
fn bernstein<const L: usize>(l: usize, half: &[f64; L], t: &[f64; L], out: &mut [[f64; L]]) {
    let row = super::bezier::binomial_row(l);
    let two_l = mul_constant(half, 2.0);
    let u = div(&add(t, half), &two_l);
    let w = div(&sub(half, t), &two_l);
    let mut acc = constant::<L>(1.0);
    for o in out.iter_mut().take(l + 1) {
        *o = acc;
        acc = mul_table(&acc, &u);
    }
    let mut pw = constant::<L>(1.0);
    for i in (0..=l).rev() {
        let c = row.map_or_else(|| super::bezier::binomial(l, i), |r| r[i]);
        out[i] = mul_constant(&mul_table(&out[i], &pw), c);
        pw = mul_table(&pw, &w);
    }
}

/// Largest l of the jet evaluator (the paper's l = max(m + 1, 7): degrees up to 15; the
/// stack arrays of Bernstein jets stay small enough to clear at every call).
const FAST_L: usize = 16;

/// [`super::bezier::eval_patch`] on f64 jets (l ≤ [`FAST_L`]), bit for bit: ψ(x, y) =
/// Σ_j (Σ_k B_k(y)·b_{j,k})·B_j(x), the inner sums coefficient-wise from +0, the outer
/// products full jet products.
pub(crate) fn eval_patch<const L: usize>(
    cp: &[[f64; 3]],
    l: usize,
    half: f64,
    x: &[f64; L],
    y: &[f64; L],
) -> Option<[[f64; L]; 3]> {
    if l > FAST_L || cp.len() < (l + 1) * (l + 1) {
        return None;
    }
    let h = constant::<L>(half);
    let mut bx = [[0.0; L]; FAST_L + 1];
    let mut by = [[0.0; L]; FAST_L + 1];
    bernstein(l, &h, x, &mut bx);
    bernstein(l, &h, y, &mut by);
    let mut out = [[0.0; L]; 3];
    let by = &by[..=l];
    for (j, bxj) in bx.iter().enumerate().take(l + 1) {
        let cj = &cp[j * (l + 1)..(j + 1) * (l + 1)];
        for d in 0..3 {
            // Each coefficient's sum over k in order from +0, as the generic loop; one
            // coordinate at a time keeps the L sums in registers.
            let mut row = [0.0; L];
            for (byk, c) in by.iter().zip(cj) {
                let cd = c[d];
                for i in 0..L {
                    row[i] += byk[i] * cd;
                }
            }
            out[d] = add(&out[d], &mul_table(&row, bxj));
        }
    }
    Some(out)
}

/// Largest degree d of the triangular patches the jet evaluator takes (the (σ, v)
/// construction's [`crate::surface::sigma_v::patch::MAX_PATCH_DEGREE`]).
const TRI_D: usize = 15;

/// `eval_tri` of the (σ, v) construction (a triangular Bézier patch at barycentric jets λ) on
/// f64 jets (d ≤ 15), bit for bit the generic evaluator: the powers λ_t^e as running products
/// from 1, each Bernstein jet ((λ₀^a λ₁^b) λ₂^c) · coef, each coordinate summed from +0.
pub(crate) fn eval_tri<const L: usize>(
    d: usize,
    cps: &[[f64; 3]],
    coef: &[f64],
    l: &[[f64; L]; 3],
) -> Option<[[f64; L]; 3]> {
    let n = (d + 1) * (d + 2) / 2;
    if d > TRI_D || cps.len() < n || coef.len() < n {
        return None;
    }
    let mut pw = [[[0.0; L]; TRI_D + 1]; 3];
    for t in 0..3 {
        pw[t][0] = constant(1.0);
        for e in 1..=d {
            pw[t][e] = mul_table(&pw[t][e - 1], &l[t]);
        }
    }
    let mut acc = [[0.0; L]; 3];
    let mut i = 0;
    for a in 0..=d {
        for b in 0..=d - a {
            let p = mul_table(&mul_table(&pw[0][a], &pw[1][b]), &pw[2][d - a - b]);
            let bern: [f64; L] = std::array::from_fn(|k| p[k] * coef[i]);
            for (t, slot) in acc.iter_mut().enumerate() {
                let c = cps[i][t];
                for k in 0..L {
                    slot[k] += bern[k] * c;
                }
            }
            i += 1;
        }
    }
    Some(acc)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::surface::jet::Jet;
    use rand::{Rng, SeedableRng};

    /// The same bits, or both NaN: Rust leaves a NaN's sign and payload unspecified (the
    /// optimiser may swap the operands of a sum), and the output text of a NaN has neither.
    fn same<const L: usize>(a: &[f64; L], b: &[f64; L]) -> bool {
        a.iter()
            .zip(b)
            .all(|(x, y)| x.to_bits() == y.to_bits() || (x.is_nan() && y.is_nan()))
    }

    /// Coefficients mixing ordinary values, ±0, huge, tiny and non-finite values.
    fn coef(r: &mut impl Rng) -> f64 {
        match r.gen_range(0..12) {
            0 => 0.0,
            1 => -0.0,
            2 => f64::INFINITY,
            3 => f64::NAN,
            4 => r.gen_range(-1e300..1e300),
            5 => r.gen_range(-1e-300..1e-300),
            _ => r.gen_range(-4.0..4.0),
        }
    }

    fn jet<const L: usize>(r: &mut impl Rng) -> [f64; L] {
        let finite = r.gen_bool(0.7);
        let constant = r.gen_bool(0.5);
        std::array::from_fn(|i| {
            if i > 0 && constant {
                if r.gen_bool(0.5) {
                    0.0
                } else {
                    -0.0
                }
            } else if finite {
                r.gen_range(-4.0..4.0) * if r.gen_bool(0.1) { 0.0 } else { 1.0 }
            } else {
                coef(r)
            }
        })
    }

    fn products_agree<const L: usize>() {
        let mut r = rand_chacha::ChaCha8Rng::seed_from_u64(7 + L as u64);
        for _ in 0..200_000 {
            let (a, b) = (jet::<L>(&mut r), jet::<L>(&mut r));
            assert!(
                same(&mul_table(&a, &b), &mul_by_table(&a, &b)),
                "{a:?} · {b:?}"
            );
            assert!(same(&mul(&a, &b), &mul_table(&a, &b)), "{a:?} · {b:?}");
            let k = b[0];
            assert!(
                same(&mul_constant(&a, k), &mul_table(&a, &constant(k))),
                "{a:?} · {k}"
            );
            assert!(same(&div(&a, &b), &div_literal(&a, &b)), "{a:?} / {b:?}");
            let d = [coef(&mut r), coef(&mut r), coef(&mut r), coef(&mut r)];
            assert!(
                same(&compose(&a, d), &compose_literal(&a, d)),
                "{a:?} ∘ {d:?}"
            );
        }
    }

    /// The fast products and quotients give the table loop's and the literal quotient's bits
    /// for jets of orders 1, 2 and 3, on constant and non-constant factors with signed zeros,
    /// huge, tiny and non-finite coefficients.
    #[test]
    fn jet_f64_products_and_quotients_are_bit_identical_to_the_literal_ones() {
        products_agree::<3>();
        products_agree::<6>();
        products_agree::<10>();
    }

    /// The table loop and the literal quotient here are the generic code of `surface::jet`
    /// (its product and quotient before the f64 kernels): same bits.
    #[test]
    fn jet_f64_literal_product_and_quotient_are_the_generic_ones() {
        let mut r = rand_chacha::ChaCha8Rng::seed_from_u64(11);
        for _ in 0..50_000 {
            let (a, b) = (jet::<6>(&mut r), jet::<6>(&mut r));
            let (ja, jb) = (Jet { c: a }, Jet { c: b });
            assert!(
                same(&ja.mul_generic(&jb).c, &mul_table(&a, &b)),
                "{a:?} · {b:?}"
            );
            assert!(
                same(&ja.div_generic(&jb).c, &div_literal(&a, &b)),
                "{a:?} / {b:?}"
            );
        }
    }

    /// Def. 5.2.1 on jets: the allocation-free patch gives the generic evaluator's bits, on
    /// jets of x and y together (a neighbour's term) and of y alone (the chart's own term).
    #[test]
    fn d5_2_1_jet_patch_is_bit_identical_to_the_generic_evaluator() {
        use crate::surface::bezier::eval_patch as generic;
        let mut r = rand_chacha::ChaCha8Rng::seed_from_u64(5);
        for l in [3usize, 7, 8, 12, 16] {
            for _ in 0..300 {
                let cp: Vec<[f64; 3]> = (0..(l + 1) * (l + 1))
                    .map(|_| std::array::from_fn(|_| r.gen_range(-3.0..3.0)))
                    .collect();
                let half = r.gen_range(0.5..1.0);
                let x: [f64; 6] = std::array::from_fn(|_| r.gen_range(-0.9..0.9));
                let mut y: [f64; 6] = std::array::from_fn(|_| r.gen_range(-0.9..0.9));
                if r.gen_bool(0.5) {
                    y[1] = 0.0;
                    y[3] = 0.0;
                    y[4] = 0.0;
                }
                let g = generic(&cp, l, half, &Jet { c: x }, &Jet { c: y });
                let f = eval_patch(&cp, l, half, &x, &y).expect("l ≤ 16");
                for d in 0..3 {
                    assert!(same(&g[d].c, &f[d]), "l {l} d {d}");
                }
            }
        }
    }

    /// The (σ, v) triangular patch on jets: the allocation-free evaluator gives the generic
    /// one's bits (degrees 1, 5, 7, 15; jets of order 1 and 2).
    #[test]
    fn sv_jet_triangular_patch_is_bit_identical_to_the_generic_evaluator() {
        use crate::surface::sigma_v::patch::{eval_tri as generic, multinomials};
        let mut r = rand_chacha::ChaCha8Rng::seed_from_u64(9);
        for d in [1usize, 5, 7, 15] {
            let coef = multinomials(d);
            for _ in 0..100 {
                let cps: Vec<[f64; 3]> = (0..coef.len())
                    .map(|_| std::array::from_fn(|_| r.gen_range(-3.0..3.0)))
                    .collect();
                let l6: [[f64; 6]; 3] =
                    std::array::from_fn(|_| std::array::from_fn(|_| r.gen_range(-0.2..1.0)));
                let g = generic(d, &cps, &coef, &l6.map(|c| Jet { c }));
                let f = eval_tri(d, &cps, &coef, &l6).expect("d ≤ 15");
                for t in 0..3 {
                    assert!(same(&g[t].c, &f[t]), "d {d} t {t}");
                }
                let l3: [[f64; 3]; 3] = l6.map(|c| [c[0], c[1], c[2]]);
                let g = generic(d, &cps, &coef, &l3.map(|c| Jet { c }));
                let f = eval_tri(d, &cps, &coef, &l3).expect("d ≤ 15");
                for t in 0..3 {
                    assert!(same(&g[t].c, &f[t]), "d {d} t {t}");
                }
            }
        }
    }
}
