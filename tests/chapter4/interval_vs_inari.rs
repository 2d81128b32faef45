//! The crate's own interval arithmetic (`numeric::interval::Interval`, used by the
//! certified provers) against MPFR-backed `inari` (IEEE 1788), feature `inari`: for seeded
//! random intervals, every result must contain inari's tightest-possible enclosure's points
//! that we sample (soundness, checked against MPFR point values at 256 bits) and be at most a
//! few ulps wider than inari's (tightness).

#![cfg(feature = "inari")]

use pseudomanifold::numeric::interval::Interval;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

const SEED: u64 = 20240601;
const N: usize = 4000;

fn ours(lo: f64, hi: f64) -> Interval {
    Interval::try_from((lo, hi)).expect("valid interval")
}

fn theirs(lo: f64, hi: f64) -> inari::Interval {
    inari::Interval::try_from((lo, hi)).expect("valid interval")
}

/// Distance in ulps from `a` outward to `b` (0 when `a` is at or inside `b`).
fn ulps_outside(a: f64, b: f64, lower: bool) -> u64 {
    let (x, y) = if lower { (a, b) } else { (-a, -b) };
    if x >= y {
        return 0;
    }
    let key = |v: f64| {
        let i = v.to_bits() as i64;
        if i < 0 {
            i64::MIN - i
        } else {
            i
        }
    };
    (key(y) - key(x)) as u64
}

fn random_interval(rng: &mut ChaCha8Rng, scale: f64) -> (f64, f64) {
    let a: f64 = rng.gen_range(-scale..scale);
    let w: f64 = if rng.gen_bool(0.2) {
        0.0
    } else {
        rng.gen_range(0.0..scale / 4.0)
    };
    (a, a + w)
}

/// Every point sampled in the argument(s) maps (in MPFR, rounded to f64 toward the outside by
/// one ulp) into our result; our result is at most `slack` ulps wider than inari's on each
/// side. Returns the worst excess width in ulps.
fn check_unary(
    name: &str,
    f: impl Fn(Interval) -> Interval,
    g: impl Fn(inari::Interval) -> inari::Interval,
    pt: impl Fn(&rug::Float) -> rug::Float,
    scale: f64,
    slack: u64,
) {
    let mut rng = ChaCha8Rng::seed_from_u64(SEED);
    let mut worst = 0;
    for _ in 0..N {
        let (a, b) = random_interval(&mut rng, scale);
        let (r, t) = (f(ours(a, b)), g(theirs(a, b)));
        if t.is_empty() {
            assert!(r.is_empty() || r.inf() <= r.sup(), "{name}[{a}, {b}]");
            continue;
        }
        // Soundness: inari's enclosure is tight, so ours must contain it.
        assert!(
            r.inf() <= t.inf() && t.sup() <= r.sup(),
            "{name}[{a}, {b}]: ours [{}, {}] ⊉ inari [{}, {}]",
            r.inf(),
            r.sup(),
            t.inf(),
            t.sup()
        );
        for x in [a, b, 0.5 * (a + b)] {
            let v = pt(&rug::Float::with_val(256, x));
            if v.is_nan() {
                continue; // x outside the function's domain (sqrt, acos): no point value to enclose
            }
            assert!(
                v >= r.inf() && v <= r.sup(),
                "{name}({x}) = {v} ∉ [{}, {}]",
                r.inf(),
                r.sup()
            );
        }
        worst = worst
            .max(ulps_outside(r.inf(), t.inf(), true))
            .max(ulps_outside(r.sup(), t.sup(), false));
    }
    eprintln!("{name}: {N} intervals (seed {SEED}), ours ⊇ inari, worst excess {worst} ulp (allowed {slack})");
    assert!(worst <= slack, "{name}: {worst} ulp wider than inari");
}

#[test]
fn bk_iv_enclose_sqrt_sin_cos_acos_and_tight() {
    check_unary(
        "sqrt",
        Interval::sqrt,
        inari::Interval::sqrt,
        |x| x.clone().sqrt(),
        100.0,
        1,
    );
    check_unary(
        "sin",
        Interval::sin,
        inari::Interval::sin,
        |x| x.clone().sin(),
        20.0,
        2,
    );
    check_unary(
        "cos",
        Interval::cos,
        inari::Interval::cos,
        |x| x.clone().cos(),
        20.0,
        2,
    );
    check_unary(
        "acos",
        Interval::acos,
        inari::Interval::acos,
        |x| x.clone().acos(),
        1.2,
        2,
    );
    check_unary(
        "sqr",
        Interval::sqr,
        inari::Interval::sqr,
        |x| x.clone().square(),
        10.0,
        1,
    );
}

#[test]
fn bk_iv_enclose_arithmetic_atan2_and_tight() {
    let mut rng = ChaCha8Rng::seed_from_u64(SEED);
    let mut worst = [0u64; 5];
    for _ in 0..N {
        let (a, b) = random_interval(&mut rng, 10.0);
        let (c, d) = random_interval(&mut rng, 10.0);
        let (x, y) = (ours(a, b), ours(c, d));
        let (xi, yi) = (theirs(a, b), theirs(c, d));
        let pairs = [
            (x + y, xi + yi),
            (x - y, xi - yi),
            (x * y, xi * yi),
            (x / y, xi / yi),
            (x.atan2(y), xi.atan2(yi)),
        ];
        for (k, (r, t)) in pairs.iter().enumerate() {
            if t.is_empty() {
                continue;
            }
            assert!(
                r.inf() <= t.inf() && t.sup() <= r.sup(),
                "op {k} on [{a},{b}], [{c},{d}]: ours [{}, {}] ⊉ inari [{}, {}]",
                r.inf(),
                r.sup(),
                t.inf(),
                t.sup()
            );
            // Division by an interval containing 0 and atan2 over the cut are coarser by
            // design (whole line; [−π, π]); tightness is measured elsewhere.
            if r.inf().is_finite() && r.sup().is_finite() && !(k == 4 && r.sup() - r.inf() > 6.0) {
                worst[k] = worst[k]
                    .max(ulps_outside(r.inf(), t.inf(), true))
                    .max(ulps_outside(r.sup(), t.sup(), false));
            }
        }
    }
    eprintln!("+ − × ÷ atan2: {N} pairs (seed {SEED}), ours ⊇ inari, worst excess {worst:?} ulp");
    assert!(worst[..4].iter().all(|&w| w <= 1), "{worst:?}");
    assert!(worst[4] <= 2, "{worst:?}");
}
