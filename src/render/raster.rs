//! A z-buffered triangle rasteriser that records, per pixel, the nearest triangle and the
//! barycentric coordinates of the pixel centre in it (a "visibility buffer"); shading is a
//! separate pass ([`super::shade`]).
//!
//! Written here rather than taken from a crate: the 2-D crates (tiny-skia, raqote) have no depth
//! buffer, and the 3-D software renderers pull in their own pipelines; what is needed is ~60
//! lines: edge functions at pixel centres, depth interpolated affinely (exact for the
//! orthographic camera).

/// No triangle covers the pixel.
pub(crate) const NONE: u32 = u32::MAX;

/// Per-pixel visibility: nearest triangle, its depth and the barycentric coordinates.
#[derive(Debug, Clone)]
pub(crate) struct Visibility {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Depth of the nearest surface (larger is nearer); −∞ where empty.
    pub depth: Vec<f64>,
    /// Index of the nearest triangle, or [`NONE`].
    pub face: Vec<u32>,
    /// Barycentric coordinates of the pixel centre in that triangle.
    pub bary: Vec<[f64; 3]>,
    /// Triangles skipped because a corner projected to a non-finite point.
    pub skipped_non_finite: usize,
}

impl Visibility {
    /// An empty buffer.
    pub(crate) fn new(width: u32, height: u32) -> Self {
        let n = width as usize * height as usize;
        Visibility {
            width,
            height,
            depth: vec![f64::NEG_INFINITY; n],
            face: vec![NONE; n],
            bary: vec![[0.0; 3]; n],
            skipped_non_finite: 0,
        }
    }

    /// Number of covered pixels (the silhouette area).
    pub(crate) fn covered(&self) -> usize {
        self.face.iter().filter(|&&f| f != NONE).count()
    }

    /// Draw triangle `id` with screen corners `s` (x, y in pixels; depth). A pixel is covered
    /// when its centre lies in the closed triangle; the nearer depth wins, ties keep the first.
    pub(crate) fn draw(&mut self, id: u32, s: [[f64; 3]; 3]) {
        if s.iter().flatten().any(|x| !x.is_finite()) {
            self.skipped_non_finite += 1;
            return;
        }
        let edge = |a: [f64; 3], b: [f64; 3], px: f64, py: f64| {
            (b[0] - a[0]) * (py - a[1]) - (b[1] - a[1]) * (px - a[0])
        };
        let area = edge(s[0], s[1], s[2][0], s[2][1]);
        if area == 0.0 {
            return;
        }
        let (w, h) = (f64::from(self.width), f64::from(self.height));
        let lo_x = s.iter().map(|p| p[0]).fold(f64::INFINITY, f64::min);
        let hi_x = s.iter().map(|p| p[0]).fold(f64::NEG_INFINITY, f64::max);
        let lo_y = s.iter().map(|p| p[1]).fold(f64::INFINITY, f64::min);
        let hi_y = s.iter().map(|p| p[1]).fold(f64::NEG_INFINITY, f64::max);
        // Pixel i has its centre at i + 0.5; the ranges are empty for a triangle off the image
        // (the float-to-int casts saturate).
        let x0 = (lo_x - 0.5).ceil().max(0.0) as u32;
        let x1 = ((hi_x - 0.5).floor().min(w - 1.0)) as i64;
        let y0 = (lo_y - 0.5).ceil().max(0.0) as u32;
        let y1 = ((hi_y - 0.5).floor().min(h - 1.0)) as i64;
        for y in i64::from(y0)..=y1 {
            let py = y as f64 + 0.5;
            for x in i64::from(x0)..=x1 {
                let px = x as f64 + 0.5;
                let b0 = edge(s[1], s[2], px, py) / area;
                let b1 = edge(s[2], s[0], px, py) / area;
                let b2 = edge(s[0], s[1], px, py) / area;
                if b0 < 0.0 || b1 < 0.0 || b2 < 0.0 {
                    continue;
                }
                let z = b0 * s[0][2] + b1 * s[1][2] + b2 * s[2][2];
                let k = y as usize * self.width as usize + x as usize;
                if z > self.depth[k] {
                    self.depth[k] = z;
                    self.face[k] = id;
                    self.bary[k] = [b0, b1, b2];
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Triangles wholly off the image cover nothing (the pixel ranges are empty, also for
    /// corners far beyond u32); one straddling the left edge covers only pixels inside.
    #[test]
    fn render_raster_off_image_triangles_cover_nothing() {
        let mut v = Visibility::new(8, 6);
        let far = 1e300;
        for s in [
            [[-9.0, 1.0, 0.0], [-1.0, 1.0, 0.0], [-1.0, 5.0, 0.0]],
            [[9.0, 1.0, 0.0], [far, 1.0, 0.0], [far, 5.0, 0.0]],
            [[1.0, -far, 0.0], [7.0, -far, 0.0], [7.0, -0.6, 0.0]],
            [[1.0, 6.6, 0.0], [7.0, 6.6, 0.0], [7.0, far, 0.0]],
        ] {
            v.draw(0, s);
        }
        assert_eq!(v.covered(), 0);
        v.draw(1, [[-4.0, 0.0, 0.0], [2.0, 0.0, 0.0], [-4.0, 6.0, 0.0]]);
        assert!(v.covered() > 0);
        assert!(v.face.iter().all(|&f| f == NONE || f == 1));
    }
}
