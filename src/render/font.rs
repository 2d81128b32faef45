//! Text on the image (the colour bar's numbers, panel captions) from the public-domain 8×8
//! bitmap font of the `font8x8` crate, scaled by pixel replication.
//!
//! A bitmap font rather than an outline font and rasteriser: the text is a few numbers and
//! captions in ASCII, an embedded bitmap needs no font file at run time (CI, servers) and
//! gives the same bytes everywhere (no hinting or anti-aliasing differences).

use super::image::Image;
use font8x8::legacy::BASIC_LEGACY;

/// Glyph cell size in font pixels.
pub(crate) const GLYPH: u32 = 8;

/// Width in pixels of `text` at `scale`.
pub(crate) fn text_width(text: &str, scale: u32) -> u32 {
    text.chars().count() as u32 * GLYPH * scale
}

/// Draw `text` with its top-left corner at (x, y); characters outside ASCII print as '?'.
pub(crate) fn draw_text(img: &mut Image, x: i64, y: i64, text: &str, scale: u32, rgb: [u8; 3]) {
    let s = i64::from(scale);
    for (n, ch) in text.chars().enumerate() {
        let code = if ch.is_ascii() {
            ch as usize
        } else {
            '?' as usize
        };
        let glyph = BASIC_LEGACY[code];
        let gx = x + n as i64 * 8 * s;
        for (row, bits) in glyph.iter().enumerate() {
            for col in 0..8 {
                if bits >> col & 1 == 0 {
                    continue;
                }
                for dy in 0..s {
                    for dx in 0..s {
                        img.put(gx + col * s + dx, y + row as i64 * s + dy, rgb);
                    }
                }
            }
        }
    }
}

/// A number in at most 9 characters: fixed notation for 1e−3 ≤ |x| < 1e4, else scientific.
pub(crate) fn format_number(x: f64) -> String {
    let a = x.abs();
    if x == 0.0 {
        "0".into()
    } else if (1e-3..1e4).contains(&a) {
        let digits = (3 - a.log10().floor() as i32).clamp(0, 5) as usize;
        format!("{x:.digits$}")
    } else {
        format!("{x:.2e}")
    }
}
