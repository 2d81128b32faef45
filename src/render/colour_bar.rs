//! The colour bar: the diverging map from lo (bottom) to hi (top) with its numbers (lo, 0,
//! hi and the halves) and the quantity's name, drawn into a strip at the right of the image.

use super::colour::{diverging, ColourRange};
use super::font::{draw_text, format_number, text_width, GLYPH};
use super::image::{to_rgb8, Image};

/// Width of the strip the bar needs at font scale `scale`.
pub(crate) fn strip_width(scale: u32) -> u32 {
    // bar + gap + the longest number (9 characters) + margin
    (12 + 6 + 9 * GLYPH + 8) * scale
}

/// Draw the bar for `range` into `img` in the strip starting at column `x0`; `label` is
/// printed above it.
pub(crate) fn draw_colour_bar(
    img: &mut Image,
    x0: u32,
    range: &ColourRange,
    label: &str,
    scale: u32,
) {
    let s = i64::from(scale);
    let h = i64::from(img.height);
    let top = h / 6;
    let bottom = h - h / 6;
    let bar_x = i64::from(x0) + 4 * s;
    let bar_w = 12 * s;
    let lw = i64::from(text_width(label, scale));
    draw_text(
        img,
        (bar_x + bar_w / 2 - lw / 2).max(i64::from(x0)),
        top - 12 * s,
        label,
        scale,
        [0, 0, 0],
    );
    // Row y shows the value whose position in [−1, 1] is linear in y: lo at the bottom, 0 at
    // the row proportional to −lo / (hi − lo), hi at the top.
    let span = range.hi - range.lo;
    let value_at = |y: i64| range.lo + span * (bottom - y) as f64 / (bottom - top) as f64;
    for y in top..=bottom {
        let t = range.position(value_at(y)).map_or(0.0, |p| p.0);
        let rgb = to_rgb8(diverging(t));
        for x in bar_x..bar_x + bar_w {
            img.put(x, y, rgb);
        }
    }
    let row_of = |v: f64| {
        if span > 0.0 {
            bottom - ((v - range.lo) / span * (bottom - top) as f64).round() as i64
        } else {
            bottom
        }
    };
    let mut ticks = vec![range.lo, range.lo / 2.0, 0.0, range.hi / 2.0, range.hi];
    ticks.dedup();
    let mut last_row = i64::MAX;
    for v in ticks {
        let y = row_of(v);
        // Skip a label that would overlap the previous one (e.g. lo = 0).
        if (last_row - y).abs() < 10 * s && last_row != i64::MAX {
            continue;
        }
        last_row = y;
        for x in bar_x + bar_w..bar_x + bar_w + 2 * s {
            for d in 0..s {
                img.put(x, y + d - s / 2, [0, 0, 0]);
            }
        }
        draw_text(
            img,
            bar_x + bar_w + 6 * s,
            y - 4 * s,
            &format_number(v),
            scale,
            [0, 0, 0],
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::colour::RangeSource;

    /// A tick is a black mark `scale` rows thick centred on its value's row, just right of the
    /// bar: at scale 2 the tick of 0 in [−1, 1] covers rows 59 and 60 of a 120-row image
    /// (bottom 100, top 20: row 100 − 40), and nothing above or below.
    #[test]
    fn render_colour_bar_tick_is_centred_on_its_row() {
        let scale = 2;
        let mut img = Image::filled(strip_width(scale), 120, [255, 255, 255]);
        let range = ColourRange {
            lo: -1.0,
            hi: 1.0,
            source: RangeSource::User,
        };
        draw_colour_bar(&mut img, 0, &range, "H", scale);
        let tick_x = 4 * scale + 12 * scale;
        let black = [0, 0, 0];
        assert_eq!(img.get(tick_x, 59), black);
        assert_eq!(img.get(tick_x, 60), black);
        assert_ne!(img.get(tick_x, 58), black);
        assert_ne!(img.get(tick_x, 61), black);
    }
}
