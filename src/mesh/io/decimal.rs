//! Decimal text of the mesh writers, byte for byte what `{:?}` prints for an f64 (the shortest
//! text that reads back to the same f64) and `{}` for an integer, but without the formatting
//! machinery: a level-2 sample of Sec. 6.2 with curvatures writes ~6.4M numbers, and `write!`
//! spent most of the output's time in it.
//!
//! `{:?}` prints the shortest decimal that reads back to the same f64 (the nearest such if there
//! are two), in positional notation when 1e-4 ≤ |x| < 1e16 or x = 0 ("0.001234", "12.0",
//! "-0.0"), in exponential notation otherwise. The Żmij algorithm (crate `zmij`, also used by
//! serde_json) prints the same shortest digits in the same positional layout on that range
//! (its own positional range is 1e-5 ≤ |x| < 1e16); outside it, and for NaN and ±∞, `{:?}` is
//! used as before. The two differ where x lies exactly halfway between the two nearest shortest
//! decimals (-85113420695635.125: std "…635.13", Żmij "…635.12"). That needs x's exact decimal
//! expansion, which has as many fractional digits q as x has fractional bits (the last digit a
//! 5), to be one digit longer than the printed one; such texts are printed by `{:?}` instead.
//! The unit tests compare both on the corner cases and on random bit patterns.

use std::io::Write;

/// Appends `x` as `{:?}` would print it.
#[inline]
pub(crate) fn push_f64(b: &mut Vec<u8>, x: f64) {
    let a = x.abs();
    if a == 0.0 || (1e-4..1e16).contains(&a) {
        let mut buf = zmij::Buffer::new();
        let text = buf.format_finite(x);
        let printed = text.len() - text.find('.').map_or(text.len(), |p| p + 1);
        if printed + 1 != fraction_bits(x) {
            b.extend_from_slice(text.as_bytes());
            return;
        }
    }
    // Writing into a Vec cannot fail.
    let _ = write!(b, "{x:?}");
}

/// The number of binary digits of a normal, nonzero `x` after the point (0 for integers):
/// also the number of decimal digits of its exact expansion after the point.
fn fraction_bits(x: f64) -> usize {
    let bits = x.to_bits();
    let m = (bits & ((1u64 << 52) - 1)) | (1u64 << 52);
    let e = ((bits >> 52) & 0x7ff) as i64 - 1075 + i64::from(m.trailing_zeros());
    if e < 0 {
        (-e) as usize
    } else {
        0
    }
}

/// Appends an unsigned integer as `{}` would print it.
#[inline]
pub(crate) fn push_uint(b: &mut Vec<u8>, x: u64) {
    b.extend_from_slice(itoa::Buffer::new().format(x).as_bytes());
}

/// Appends the three numbers separated by single spaces.
#[inline]
pub(crate) fn push_f64x3(b: &mut Vec<u8>, p: [f64; 3]) {
    push_f64(b, p[0]);
    b.push(b' ');
    push_f64(b, p[1]);
    b.push(b' ');
    push_f64(b, p[2]);
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};

    fn same(x: f64) {
        let mut b = Vec::new();
        push_f64(&mut b, x);
        assert_eq!(
            String::from_utf8(b).ok(),
            Some(format!("{x:?}")),
            "bits {:#x}",
            x.to_bits()
        );
    }

    /// The written text equals `{:?}` at the ends of the positional range, at zero, for
    /// subnormals, NaN, ±∞, integers, halfway cases, and for a million each of random bit
    /// patterns, values of the sizes a sampled surface has, and values with few fractional
    /// bits (seeded).
    #[test]
    fn decimal_text_is_debug_formatting() {
        let edges = [
            0.0,
            f64::from_bits(0xc2d3_5a40_cd32_14c8), // -85113420695635.125, halfway
            0.5,
            1.5,
            2.5,
            1e-4,
            1e-5,
            9.999999999999999e-5,
            1e16,
            9999999999999998.0,
            1e15,
            123456789012345680.0,
            0.1,
            0.3,
            1.0,
            12.0,
            1e-320,
            f64::MIN_POSITIVE,
            f64::MAX,
            f64::EPSILON,
            f64::NAN,
            f64::INFINITY,
        ];
        for x in edges {
            same(x);
            same(-x);
            same(f64::from_bits(x.to_bits() + 1));
            same(f64::from_bits(x.to_bits().saturating_sub(1)));
        }
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(0x5eed);
        for _ in 0..1_000_000 {
            same(f64::from_bits(rng.gen()));
            same(rng.gen_range(-1e3..1e3));
            same(rng.gen_range(-1.0..1.0) * 10f64.powi(rng.gen_range(-6..18)));
            // Few fractional bits: where halfway cases are.
            let m = rng.gen_range(1u64..1 << 53) as f64;
            same(m * 2f64.powi(-rng.gen_range(0..30)));
        }
        for x in [0u64, 7, 10, 99, 100, 255, 4_294_967_295, u64::MAX] {
            let mut b = Vec::new();
            push_uint(&mut b, x);
            assert_eq!(b, x.to_string().into_bytes());
        }
    }
}
