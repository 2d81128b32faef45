//! RGB images and their PNG encoding (the `png` crate, fixed settings and no time stamp, so the
//! same image always gives the same bytes).

use super::error::RenderError;

/// An 8-bit RGB image, rows top to bottom.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Image {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// RGB triples, row-major.
    pub data: Vec<u8>,
}

impl Image {
    /// An image filled with `rgb`.
    pub fn filled(width: u32, height: u32, rgb: [u8; 3]) -> Image {
        let n = width as usize * height as usize;
        Image {
            width,
            height,
            data: rgb.iter().copied().cycle().take(3 * n).collect(),
        }
    }
    /// Set pixel (x, y); points outside the image are ignored (text and bars may overhang).
    pub(crate) fn put(&mut self, x: i64, y: i64, rgb: [u8; 3]) {
        if x < 0 || y < 0 || x >= i64::from(self.width) || y >= i64::from(self.height) {
            return;
        }
        let k = 3 * (y as usize * self.width as usize + x as usize);
        self.data[k..k + 3].copy_from_slice(&rgb);
    }
    /// Pixel (x, y) (inside the image).
    pub fn get(&self, x: u32, y: u32) -> [u8; 3] {
        let k = 3 * (y as usize * self.width as usize + x as usize);
        [self.data[k], self.data[k + 1], self.data[k + 2]]
    }
    /// Copy `other` with its top-left corner at (x, y).
    pub(crate) fn blit(&mut self, other: &Image, x: i64, y: i64) {
        for j in 0..other.height {
            for i in 0..other.width {
                self.put(x + i64::from(i), y + i64::from(j), other.get(i, j));
            }
        }
    }
    /// The PNG encoding (8-bit RGB, default compression, no ancillary chunks).
    pub fn to_png(&self) -> Result<Vec<u8>, RenderError> {
        let mut out = Vec::new();
        {
            let mut enc = png::Encoder::new(&mut out, self.width, self.height);
            enc.set_color(png::ColorType::Rgb);
            enc.set_depth(png::BitDepth::Eight);
            let mut w = enc
                .write_header()
                .map_err(|e| RenderError::Png(e.to_string()))?;
            w.write_image_data(&self.data)
                .map_err(|e| RenderError::Png(e.to_string()))?;
        }
        Ok(out)
    }
}

/// A colour in [0, 1]³ as 8-bit RGB (rounded; out-of-range components saturate).
pub(crate) fn to_rgb8(c: [f64; 3]) -> [u8; 3] {
    c.map(|x| (x * 255.0).round().clamp(0.0, 255.0) as u8)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A point left of, above, right of or below the image writes nothing (text and bars
    /// overhang the edges): not even the pixel its wrapped index would name.
    #[test]
    fn render_image_put_outside_writes_nothing() {
        let white = [255, 255, 255];
        let mut img = Image::filled(4, 3, white);
        for (x, y) in [(-1, 1), (1, -1), (4, 1), (1, 3), (-1, -1)] {
            img.put(x, y, [0, 0, 0]);
        }
        for y in 0..3 {
            for x in 0..4 {
                assert_eq!(img.get(x, y), white, "pixel ({x}, {y})");
            }
        }
        img.put(3, 2, [0, 0, 0]);
        assert_eq!(img.get(3, 2), [0, 0, 0]);
    }
}
