//! The one-dimensional example of Sec. 4.1 (Fig. 7): a cubic B-spline curve on S¹ through an
//! affine atlas, decided exactly with the 1-D gluing-data backend.
//!
//! S¹ has circumference L (rational; the intervals are "arbitrary"), knots at arc positions
//! s_0 < … < s_{n−1}. Chart i is the arc U_i = (t_{i−2} − ε, t_{i+2} + ε) as written, or a
//! wider arc of `half_width` knots each side, with φ_i(t) = a_i + b_i·(t − t_i) (eq. (6)); the
//! p-domains are put apart by a_i so that Def. 3.4.1(1) (disjoint Ω_i) can hold, and b_i
//! varies so the transitions are affine but not translations.

use crate::gluing::exact1d::{decide, Exact1d, Interval, Q};
use crate::report::{CheckResult, Witness};
use num_traits::{One, Zero};
use serde_json::json;

fn q(a: i64, b: i64) -> Q {
    super::polar::q(a, b)
}

/// The data of Fig. 7.
#[derive(Clone, Debug)]
pub struct CircleSplines {
    /// Circumference.
    pub length: Q,
    /// Arc positions of the knots t_0..t_{n−1}, increasing in [0, L).
    pub knots: Vec<Q>,
    /// ε of the charts.
    pub eps: Q,
    /// Knots each side of t_i in U_i (2 as written in Fig. 7).
    pub half_width: usize,
    /// (a_i, b_i) of eq. (6).
    pub ab: Vec<(Q, Q)>,
    /// The control polygon c_0..c_{n−1} (a planar n-gon).
    pub control: Vec<[Q; 2]>,
}

impl CircleSplines {
    /// The paper's example with n knots at irregular rational spacing.
    pub fn example(n: usize, half_width: usize) -> Self {
        let mut knots = Vec::with_capacity(n);
        let mut s = Q::zero();
        for i in 0..n {
            knots.push(s.clone());
            s += q(3 + (i as i64 * 5) % 7, 4);
        }
        let ab = (0..n)
            .map(|i| (q(1000 * i as i64, 1), q(2 + i as i64 % 3, 3)))
            .collect();
        let control = (0..n)
            .map(|i| {
                [
                    q(((i * 7) % 11) as i64 - 5, 2),
                    q(((i * 3) % 5) as i64 - 2, 1),
                ]
            })
            .collect();
        CircleSplines {
            length: s,
            knots,
            eps: q(1, 16),
            half_width,
            ab,
            control,
        }
    }
    fn n(&self) -> usize {
        self.knots.len()
    }
    /// Unwrapped arc position of knot i + d seen from knot i (d may be negative).
    pub fn t(&self, i: usize, d: i64) -> Q {
        let n = self.n() as i64;
        let j = i as i64 + d;
        let wraps = j.div_euclid(n);
        &self.knots[j.rem_euclid(n) as usize] + &self.length * q(wraps, 1)
    }
    /// U_i as an interval of unwrapped arc positions around t_i.
    pub fn chart_arc(&self, i: usize) -> (Q, Q) {
        let h = self.half_width as i64;
        (self.t(i, -h) - &self.eps, self.t(i, h) + &self.eps)
    }
    /// φ_i(t) of eq. (6).
    pub fn phi(&self, i: usize, t: &Q) -> Q {
        let (a, b) = &self.ab[i];
        a + b * (t - &self.knots[i])
    }
    /// The atlas as exact 1-D gluing data: Ω_i = φ_i(U_i), Ω_ij = φ_i(U_i ∩ U_j), one affine
    /// piece per component of the arc intersection.
    pub fn gluing(&self) -> Exact1d {
        let mut g = Exact1d::default();
        let n = self.n();
        for i in 0..n {
            let (lo, hi) = self.chart_arc(i);
            if let Some(iv) = Interval::new(self.phi(i, &lo), self.phi(i, &hi)) {
                g.add_domain(i as u32, iv);
            }
        }
        for i in 0..n {
            let (lo, hi) = self.chart_arc(i);
            for j in 0..n {
                if i == j {
                    continue;
                }
                let (ljo, hj) = self.chart_arc(j);
                for m in -1i64..=1 {
                    let shift = &self.length * q(m, 1);
                    let (a, b) = (
                        (&ljo + &shift).max(lo.clone()),
                        (&hj + &shift).min(hi.clone()),
                    );
                    if a >= b {
                        continue;
                    }
                    // t ∈ U_i (unwrapped at i) is t − mL in j's unwrapping.
                    let (ai, bi) = &self.ab[i];
                    let (aj, bj) = &self.ab[j];
                    let slope = bj / bi;
                    // φ_j(t − mL) with t = s_i + (x − a_i)/b_i.
                    let off = aj + bj * (&self.knots[i] - ai / bi - &shift - &self.knots[j]);
                    if let Some(dom) = Interval::new(self.phi(i, &a), self.phi(i, &b)) {
                        g.add_piece(i as u32, j as u32, dom, slope, off);
                    }
                }
            }
        }
        g.with_default_diagonal()
    }
}

/// Def. 3.4.1, every condition decided exactly on the Fig. 7 atlas (and Def. 7: the pieces are
/// affine by construction, x ↦ (b_j/b_i)x + c).
pub fn check_gluing(c: &CircleSplines) -> Vec<CheckResult> {
    let g = c.gluing();
    decide::check_all(&g)
        .into_iter()
        .map(|mut r| {
            r.id = format!("MS-F7:{}", r.id);
            r
        })
        .collect()
}

/// Def. 13(1) on Fig. 7: the piece F_i on [t_i, t_{i+1}] is evaluated "on (U_i, φ_i) with
/// control polygon C_i = {c_{i−2}, …, c_{i+2}}"; every knot t_{j−2..j+2} of those c_j must lie
/// in U_i to have chart coordinates there (decided exactly).
pub fn check_knots_in_chart(c: &CircleSplines) -> CheckResult {
    let mut r = CheckResult::new(
        "MS-D13(1)",
        "Fig. 7: knots of C_i lie in U_i (Def. 13(1); exact)",
    );
    for i in 0..c.n() {
        let (lo, hi) = c.chart_arc(i);
        for j in -2i64..=2 {
            for d in -2i64..=2 {
                r.examined += 1;
                let t = c.t(i, j + d);
                if !(lo < t && t < hi) {
                    let idx = (i as i64 + j + d).rem_euclid(c.n() as i64);
                    r.offend(|| Witness::new(format!("chart U_{i} (half-width {}): knot t_{idx} of control point c_{} is not in U_{i}", c.half_width, (i as i64 + j).rem_euclid(c.n() as i64)), json!({"chart": i, "knot": idx})));
                }
            }
        }
    }
    r
}

/// A polynomial over ℚ, coefficients from degree 0.
type Poly = Vec<Q>;

fn padd(a: &Poly, b: &Poly) -> Poly {
    (0..a.len().max(b.len()))
        .map(|i| {
            a.get(i).cloned().unwrap_or_else(Q::zero) + b.get(i).cloned().unwrap_or_else(Q::zero)
        })
        .collect()
}
fn pmul(a: &Poly, b: &Poly) -> Poly {
    let mut out = vec![Q::zero(); a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        for (j, y) in b.iter().enumerate() {
            out[i + j] += x * y;
        }
    }
    out
}
fn pscale(a: &Poly, s: &Q) -> Poly {
    a.iter().map(|x| x * s).collect()
}
fn pderiv(a: &Poly) -> Poly {
    a.iter()
        .enumerate()
        .skip(1)
        .map(|(i, x)| x * q(i as i64, 1))
        .collect()
}
fn peval(a: &Poly, x: &Q) -> Q {
    a.iter().rev().fold(Q::zero(), |acc, c| acc * x + c)
}
/// p(A x + B).
fn pcompose_affine(p: &Poly, a: &Q, b: &Q) -> Poly {
    let lin: Poly = vec![b.clone(), a.clone()];
    let mut out: Poly = vec![Q::zero()];
    let mut pow: Poly = vec![Q::one()];
    for c in p {
        out = padd(&out, &pscale(&pow, c));
        pow = pmul(&pow, &lin);
    }
    out
}

/// Cox–de Boor: the degree-p B-spline with knots x[l..=l+p+1], restricted to [x_s, x_{s+1}).
fn bspline_on(x: &[Q], l: usize, p: usize, s: usize) -> Poly {
    if p == 0 {
        return vec![if l == s { Q::one() } else { Q::zero() }];
    }
    let mut out = vec![Q::zero()];
    let d1 = &x[l + p] - &x[l];
    if !d1.is_zero() {
        let f: Poly = vec![-&x[l] / &d1, Q::one() / &d1];
        out = padd(&out, &pmul(&f, &bspline_on(x, l, p - 1, s)));
    }
    let d2 = &x[l + p + 1] - &x[l + 1];
    if !d2.is_zero() {
        let f: Poly = vec![&x[l + p + 1] / &d2, -Q::one() / &d2];
        out = padd(&out, &pmul(&f, &bspline_on(x, l + 1, p - 1, s)));
    }
    out
}

impl CircleSplines {
    /// The cubic piece F_i on [t_i, t_{i+1}] in chart i's coordinate: two polynomials (x, y).
    pub fn piece(&self, i: usize) -> [Poly; 2] {
        self.piece_in(i, 0)
    }
    /// The cubic piece F_{i+o} on [t_{i+o}, t_{i+o+1}] in chart i's coordinate.
    pub fn piece_in(&self, chart: usize, o: i64) -> [Poly; 2] {
        let i = (chart as i64 + o).rem_euclid(self.n() as i64) as usize;
        // Chart coordinates of t_{i−3} … t_{i+4}; knot index 3 is t_i.
        let x: Vec<Q> = (-3i64..=4)
            .map(|d| self.phi(chart, &self.t(chart, o + d)))
            .collect();
        let mut out = [vec![Q::zero()], vec![Q::zero()]];
        for jd in -1i64..=2 {
            // c_{i+jd} has knots t_{i+jd−2..i+jd+2}: starting index 3 + jd − 2 in x.
            let basis = bspline_on(&x, (1 + jd) as usize, 3, 3);
            let cj = &self.control[(i as i64 + jd).rem_euclid(self.n() as i64) as usize];
            for (o, cc) in out.iter_mut().zip(cj) {
                *o = padd(o, &pscale(&basis, cc));
            }
        }
        out
    }
}

/// Sec. 4.1: "It is C² continuous everywhere": at each joint t_{i+1}, F_i (chart i) and F_{i+1}
/// (chart i+1, pulled back through the affine transition φ_{i+1}∘φ_i⁻¹) agree with their
/// first and second derivatives (exact); the third derivative's jump is reported.
pub fn check_c2(c: &CircleSplines) -> CheckResult {
    check_c2_with(c, &Q::zero())
}

/// [`check_c2`] with the transition shifted by `fault` (planted-fault tests: a wrong
/// transition must show up as a jump).
pub fn check_c2_with(c: &CircleSplines, fault: &Q) -> CheckResult {
    let mut r = CheckResult::new(
        "MS-F7-C2",
        "Fig. 7: the cubic spline on S¹ is C² at every knot (exact)",
    );
    let mut c3_jumps = 0;
    for i in 0..c.n() {
        let j = (i + 1) % c.n();
        let (pi, pj) = (c.piece(i), c.piece(j));
        // y = φ_j(t) with t = t_i + (x − a_i)/b_i, shifted by L when j wraps to 0.
        let (ai, bi) = &c.ab[i];
        let (aj, bj) = &c.ab[j];
        let shift = if j == 0 { c.length.clone() } else { Q::zero() };
        let slope = bj / bi;
        let off = aj + bj * (&c.knots[i] - ai / bi - &shift - &c.knots[j]) + fault;
        let x0 = c.phi(i, &c.t(i, 1));
        for comp in 0..2 {
            let pulled = pcompose_affine(&pj[comp], &slope, &off);
            let (mut a, mut b) = (pi[comp].clone(), pulled);
            for d in 0..=3 {
                r.examined += 1;
                let (va, vb) = (peval(&a, &x0), peval(&b, &x0));
                if d < 3 && va != vb {
                    r.offend(|| Witness::new(format!("joint t_{j}: derivative {d} of component {comp} jumps ({va} vs {vb})"), json!({"joint": j, "order": d})));
                }
                if d == 3 && va != vb {
                    c3_jumps += 1;
                }
                a = pderiv(&a);
                b = pderiv(&b);
            }
        }
    }
    r.with_note(format!(
        "third derivative jumps at {c3_jumps} of {} joint components (so exactly C², not C³)",
        2 * c.n()
    ))
}

/// Def. 13(2) on Fig. 7: where a piece's knots t_{j−3..j+4} lie in both U_i and U_{i+1}, the
/// piece computed in chart i+1 and pulled back through φ_{i+1}∘φ_i⁻¹ is the same polynomial
/// as the piece computed in chart i (exact). Pieces with a knot outside either chart are
/// skipped and counted (that is Def. 13(1)).
pub fn check_d13_2(c: &CircleSplines) -> CheckResult {
    let mut r = CheckResult::new(
        "MS-D13(2)",
        "Fig. 7: F_α = F_β∘φ_αβ on the overlap (Def. 13(2); exact)",
    );
    let mut skipped = 0;
    for i in 0..c.n() {
        let j = (i + 1) % c.n();
        let (lo_i, hi_i) = c.chart_arc(i);
        let (lo_j, hi_j) = c.chart_arc(j);
        for o in -2i64..=2 {
            let in_both = (-3i64..=4).all(|d| {
                let t = c.t(i, o + d);
                let tj = c.t(j, o + d - 1);
                lo_i < t && t < hi_i && lo_j < tj && tj < hi_j
            });
            if !in_both {
                skipped += 1;
                continue;
            }
            let (ai, bi) = &c.ab[i];
            let (aj, bj) = &c.ab[j];
            let shift = if j == 0 { c.length.clone() } else { Q::zero() };
            let slope = bj / bi;
            let off = aj + bj * (&c.knots[i] - ai / bi - &shift - &c.knots[j]);
            let (pi, pj) = (c.piece_in(i, o), c.piece_in(j, o - 1));
            for comp in 0..2 {
                r.examined += 1;
                let pulled = pcompose_affine(&pj[comp], &slope, &off);
                let diff = padd(&pi[comp], &pscale(&pulled, &-Q::one()));
                if diff.iter().any(|x| !x.is_zero()) {
                    r.offend(|| {
                        Witness::new(
                            format!(
                                "charts {i}, {j}: piece {} component {comp} differs",
                                (i as i64 + o).rem_euclid(c.n() as i64)
                            ),
                            json!({"chart": i, "piece_offset": o}),
                        )
                    });
                }
            }
        }
    }
    if r.examined == 0 {
        r.skip("no piece has all its knots in two neighbouring charts (Def. 13(1) fails)");
    }
    r.with_note(format!(
        "{skipped} (chart, piece) pairs skipped: a knot outside a chart"
    ))
}

/// Def. 5 as written: φ_xy∘φ_yz = φ_xz with φ_xy : φ_x(U_x∩U_y) → φ_y(U_x∩U_y). The left side
/// applies φ_yz to a point of φ_x(…) ⊆ Ω_x, but φ_yz is defined on Ω_y only, and the
/// p-domains are disjoint: the witness is a point where the literal composition is undefined
/// (the corrected order φ_yz∘φ_xy = φ_xz is Def. 3.4.1(3c), checked by `check_gluing`).
pub fn check_def5_literal(c: &CircleSplines) -> CheckResult {
    let mut r = CheckResult::new(
        "MS-D5",
        "Def. 5 cocycle φ_xy∘φ_yz = φ_xz, composition order as written",
    );
    let g = c.gluing();
    let n = c.n() as u32;
    'outer: for x in 0..n {
        for y in 0..n {
            for z in 0..n {
                if x == y || y == z || x == z {
                    continue;
                }
                // A point p ∈ φ_x(U_x ∩ U_y ∩ U_z): the midpoint of a piece of Ω_xy mapped into Ω_yz.
                for piece in g.pieces(x, y) {
                    let p = piece.dom.midpoint();
                    let Some(py) = g.phi(y, x, &p) else { continue };
                    if !g.in_omega_ij(y, z, &py) || !g.in_omega_ij(x, z, &p) {
                        continue;
                    }
                    r.examined += 1;
                    // Literal: first φ_yz (paper's φ_yz: chart y → chart z) applied to p ∈ Ω_x.
                    if g.phi(z, y, &p).is_none() {
                        r.offend(|| Witness::new(format!("x={x}, y={y}, z={z}: p = {p} ∈ φ_x(U_x∩U_y∩U_z) ⊆ Ω_x, but φ_yz is defined on Ω_y only, so φ_xy∘φ_yz(p) is undefined; φ_yz∘φ_xy(p) = {:?} = φ_xz(p) = {:?}", g.phi(z, y, &py).map(|v| v.to_string()), g.phi(z, x, &p).map(|v| v.to_string())), json!({"x": x, "y": y, "z": z, "p": p.to_string()})));
                        break 'outer;
                    }
                }
            }
        }
    }
    r
}

/// Every Fig. 7 check for the given chart half-width.
pub fn check_all(c: &CircleSplines) -> Vec<CheckResult> {
    let mut out = check_gluing(c);
    out.push(check_knots_in_chart(c));
    out.push(check_c2(c));
    out.push(check_d13_2(c));
    out.push(check_def5_literal(c));
    out
}
