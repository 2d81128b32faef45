//! Several renders side by side, each with a caption above it (the layout of Figs. 6.4–6.7:
//! S′ | the PPS built from it, for each S′).

use super::font::{draw_text, text_width, GLYPH};
use super::image::Image;
use super::picture::BACKGROUND;

/// Height of the caption band at font scale `scale`.
pub(crate) fn caption_height(scale: u32) -> u32 {
    (GLYPH + 8) * scale
}

/// Lay out `panels` (caption, image) left to right, captions centred above their images.
pub(crate) fn side_by_side(panels: &[(String, Image)], scale: u32) -> Image {
    let ch = caption_height(scale);
    let w: u32 = panels.iter().map(|(_, i)| i.width).sum();
    let h = panels.iter().map(|(_, i)| i.height).max().unwrap_or(0) + ch;
    let mut out = Image::filled(w.max(1), h.max(1), BACKGROUND);
    let mut x = 0i64;
    for (caption, img) in panels {
        let tw = i64::from(text_width(caption, scale));
        let cx = x + (i64::from(img.width) - tw) / 2;
        draw_text(
            &mut out,
            cx.max(x),
            i64::from(4 * scale),
            caption,
            scale,
            [0, 0, 0],
        );
        out.blit(img, x, i64::from(ch));
        x += i64::from(img.width);
    }
    out
}
