//! astro-float plumbing shared by [`super::Mp`], [`super::Interval`] and the double-word
//! functions: the per-thread constants cache and the correctly rounded conversion to `f64`.

use astro_float::{BigFloat, Consts, Sign};
use std::cell::RefCell;

thread_local! {
    /// astro-float caches π (and e, ln 2, ln 10) per precision in a mutable cache; one per
    /// thread keeps `Mp` `Send + Sync` without a lock.
    static CONSTS: RefCell<Option<Consts>> = const { RefCell::new(None) };
}

/// Run `f` with this thread's constants cache.
pub(crate) fn with_consts<R>(f: impl FnOnce(&mut Consts) -> R) -> R {
    CONSTS.with(|c| {
        let mut c = c.borrow_mut();
        // Consts::new only allocates empty caches; it fails only when allocation fails, which
        // aborts the process elsewhere in Rust anyway.
        let cc = c.get_or_insert_with(|| Consts::new().expect("allocating astro-float constants"));
        f(cc)
    })
}

/// `x · 2^k` in f64 with a single rounding at the end (steps of at most 2^±1000 are exact
/// until the last one).
fn ldexp(mut x: f64, mut k: i64) -> f64 {
    let step_up = f64::from_bits(((1023 + 1000) as u64) << 52);
    let step_down = f64::from_bits(((1023 - 1000) as u64) << 52);
    while k > 1000 && x.is_finite() && x != 0.0 {
        x *= step_up;
        k -= 1000;
    }
    while k < -1000 && x != 0.0 {
        x *= step_down;
        k += 1000;
    }
    if k.abs() <= 1000 {
        x * f64::from_bits(((1023 + k) as u64) << 52)
    } else {
        x
    }
}

/// Round an astro-float value to the nearest `f64` (ties to even): the top word with a sticky
/// bit (round-to-odd to 64 ≥ 53 + 2 bits) then one IEEE rounding, which is exact double
/// rounding-free for normal results.
pub(crate) fn big_to_f64(v: &BigFloat) -> f64 {
    if v.is_nan() {
        return f64::NAN;
    }
    if v.is_inf() {
        return if v.is_negative() {
            f64::NEG_INFINITY
        } else {
            f64::INFINITY
        };
    }
    let neg = v.is_negative();
    let Some((words, _bits, sign, e, _)) = v.as_raw_parts() else {
        return f64::NAN;
    };
    let Some((&top, rest)) = words.split_last() else {
        return if neg { -0.0 } else { 0.0 };
    };
    if top == 0 && rest.iter().all(|w| *w == 0) {
        return if neg { -0.0 } else { 0.0 };
    }
    let sticky = rest.iter().any(|w| *w != 0) as u64;
    // value = 0.top… × 2^e = top × 2^(e − 64).
    let m = (top | sticky) as f64;
    let r = ldexp(m, e as i64 - 64);
    if sign == Sign::Neg {
        -r
    } else {
        r
    }
}
