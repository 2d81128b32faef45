//! An orthographic camera looking at the bounding box from the direction (azimuth, elevation).
//!
//! Orthographic, so the silhouette of a convex body is exactly the projection of its convex
//! hull (the area check) and depth is affine in screen space (exact z-buffer interpolation).
//! World "up" is +y (the convention of OBJ files); azimuth 0, elevation 0 looks along −z.

use super::error::RenderError;
use crate::numeric::vec3::{cross, dot, sub};

/// Viewing direction in degrees.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct View {
    /// Rotation of the viewer about the up (+y) axis, degrees.
    pub azimuth: f64,
    /// Angle of the viewer above the horizontal plane, degrees (|elevation| < 90).
    pub elevation: f64,
}

impl Default for View {
    fn default() -> Self {
        View {
            azimuth: 30.0,
            elevation: 20.0,
        }
    }
}

impl View {
    /// Parse `azimuth,elevation` (degrees, |elevation| < 90).
    pub fn parse(s: &str) -> Result<View, RenderError> {
        let v: Vec<f64> = s
            .split(',')
            .map(|x| x.trim().parse::<f64>())
            .collect::<Result<_, _>>()
            .map_err(|_| RenderError::BadView(s.into()))?;
        match v.as_slice() {
            [a, e] if a.is_finite() && e.is_finite() && e.abs() < 90.0 => Ok(View {
                azimuth: *a,
                elevation: *e,
            }),
            _ => Err(RenderError::BadView(s.into())),
        }
    }

    /// Unit vector from the scene towards the viewer.
    pub(crate) fn towards_viewer(&self) -> [f64; 3] {
        let (a, e) = (self.azimuth.to_radians(), self.elevation.to_radians());
        [e.cos() * a.sin(), e.sin(), e.cos() * a.cos()]
    }
}

/// Orthographic projection onto a `width` × `height` pixel grid (y down).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Camera {
    /// Screen x axis in world coordinates.
    pub right: [f64; 3],
    /// Screen up axis in world coordinates.
    pub up: [f64; 3],
    /// Towards the viewer (depth grows towards the viewer).
    pub towards: [f64; 3],
    /// World point at the image centre.
    pub centre: [f64; 3],
    /// Pixels per world unit.
    pub scale: f64,
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
}

impl Camera {
    /// The camera for `view` that fits the box [lo, hi] (all 8 corners) into the image with a
    /// margin of `margin` (fraction of each side).
    pub fn fit(
        lo: [f64; 3],
        hi: [f64; 3],
        view: View,
        width: u32,
        height: u32,
        margin: f64,
    ) -> Camera {
        let towards = view.towards_viewer();
        let a = view.azimuth.to_radians();
        let right = [a.cos(), 0.0, -a.sin()];
        let up = cross(towards, right);
        let centre: [f64; 3] = std::array::from_fn(|d| 0.5 * (lo[d] + hi[d]));
        let (mut ex, mut ey) = (0.0f64, 0.0f64);
        for k in 0..8 {
            let c: [f64; 3] = std::array::from_fn(|d| if k >> d & 1 == 1 { hi[d] } else { lo[d] });
            let r = sub(c, centre);
            ex = ex.max(dot(r, right).abs());
            ey = ey.max(dot(r, up).abs());
        }
        let usable = 1.0 - 2.0 * margin;
        let sx = if ex > 0.0 {
            usable * f64::from(width) / (2.0 * ex)
        } else {
            f64::INFINITY
        };
        let sy = if ey > 0.0 {
            usable * f64::from(height) / (2.0 * ey)
        } else {
            f64::INFINITY
        };
        let scale = if sx.min(sy).is_finite() {
            sx.min(sy)
        } else {
            1.0
        };
        Camera {
            right,
            up,
            towards,
            centre,
            scale,
            width,
            height,
        }
    }

    /// Screen position (pixels, y down) and depth (larger is nearer) of a world point.
    pub fn project(&self, p: [f64; 3]) -> [f64; 3] {
        let r = sub(p, self.centre);
        [
            0.5 * f64::from(self.width) + self.scale * dot(r, self.right),
            0.5 * f64::from(self.height) - self.scale * dot(r, self.up),
            dot(r, self.towards),
        ]
    }
}
