//! One picture: fit the camera, rasterise, shade, colour, draw the colour bar.

use super::camera::{Camera, View};
use super::colour::{diverging, ColourBy, ColourRange, PLAIN, UNDEFINED};
use super::colour_bar::{draw_colour_bar, strip_width};
use super::error::RenderError;
use super::image::{to_rgb8, Image};
use super::orientation::{check_orientation, OrientationReport};
use super::raster::{Visibility, NONE};
use super::scene::Scene;
use super::shade::{brightness, light_direction, lit};
use serde::Serialize;

/// Background colour.
pub(crate) const BACKGROUND: [u8; 3] = [255, 255, 255];

/// How to draw a scene.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RenderOptions {
    /// Image width (including the colour bar strip).
    pub width: u32,
    /// Image height.
    pub height: u32,
    /// Viewing direction.
    pub view: View,
    /// What to colour by.
    pub colour: ColourBy,
    /// The colour range (robust range of the scene's values when None).
    pub range: Option<ColourRange>,
    /// The box the camera is fitted to (the scene's bounding box when None); panels share one.
    pub frame: Option<([f64; 3], [f64; 3])>,
    /// Draw the colour bar (when colouring).
    pub colour_bar: bool,
}

impl Default for RenderOptions {
    fn default() -> Self {
        RenderOptions {
            width: 800,
            height: 600,
            view: View::default(),
            colour: ColourBy::Gaussian,
            range: None,
            frame: None,
            colour_bar: true,
        }
    }
}

/// What a render did (printed by the CLI).
#[derive(Debug, Clone, Serialize)]
pub struct RenderReport {
    /// Image size.
    pub width: u32,
    /// Image size.
    pub height: u32,
    /// Vertices and triangles drawn.
    pub vertices: usize,
    /// Triangles drawn.
    pub triangles: usize,
    /// What the surface is coloured by.
    pub colour: ColourBy,
    /// The colour range used (None for `--colour none`).
    pub range: Option<ColourRange>,
    /// Vertex values outside the range (drawn in the end colours).
    pub outside_range: usize,
    /// Vertex values that are NaN (drawn grey).
    pub undefined: usize,
    /// Pixels covered by the surface.
    pub covered_pixels: usize,
    /// Triangles skipped because a corner is not finite.
    pub skipped_triangles: usize,
    /// Pixels per world unit.
    pub scale: f64,
    /// Agreement of the normals with the triangles' orientation.
    pub orientation: OrientationReport,
}

/// The scene's per-vertex values for `colour`, or an error when it carries none.
pub(crate) fn values(scene: &Scene, colour: ColourBy) -> Result<Option<&[f64]>, RenderError> {
    match colour {
        ColourBy::None => Ok(None),
        ColourBy::Gaussian => scene
            .gaussian
            .as_deref()
            .map(Some)
            .ok_or(RenderError::NoCurvature("gaussian")),
        ColourBy::Mean => scene
            .mean
            .as_deref()
            .map(Some)
            .ok_or(RenderError::NoCurvature("mean")),
    }
}

/// Render `scene` (validated first) and report.
pub fn render_scene(
    scene: &Scene,
    o: &RenderOptions,
) -> Result<(Image, RenderReport), RenderError> {
    scene.validate()?;
    let vals = values(scene, o.colour)?;
    let range = match (vals, o.range) {
        (None, _) => None,
        (Some(_), Some(r)) => Some(r),
        (Some(v), None) => Some(ColourRange::robust(v).ok_or_else(|| {
            RenderError::Empty(format!("no finite {} curvature value", o.colour.name()))
        })?),
    };
    let scale = (o.height / 400).max(1);
    let strip = if range.is_some() && o.colour_bar {
        strip_width(scale)
    } else {
        0
    };
    if o.width <= strip + 16 {
        return Err(RenderError::BadSize(format!(
            "{}x{} (the colour bar needs {strip} columns)",
            o.width, o.height
        )));
    }
    let vw = o.width - strip;
    let (lo, hi) = match o.frame {
        Some(f) => f,
        None => scene
            .bbox()
            .ok_or_else(|| RenderError::Empty("no finite vertex position".into()))?,
    };
    let cam = Camera::fit(lo, hi, o.view, vw, o.height, 0.05);
    let screen: Vec<[f64; 3]> = scene.positions.iter().map(|&p| cam.project(p)).collect();
    let mut vis = Visibility::new(vw, o.height);
    for (i, f) in scene.faces.iter().enumerate() {
        vis.draw(i as u32, f.map(|v| screen[v as usize]));
    }
    let light = light_direction(cam.right, cam.up, cam.towards);
    let mut img = Image::filled(o.width, o.height, BACKGROUND);
    for y in 0..o.height {
        for x in 0..vw {
            let k = y as usize * vw as usize + x as usize;
            let face = vis.face[k];
            if face == NONE {
                continue;
            }
            let f = scene.faces[face as usize];
            let b = vis.bary[k];
            let n: [f64; 3] = std::array::from_fn(|d| {
                (0..3).map(|c| b[c] * scene.normals[f[c] as usize][d]).sum()
            });
            let base = match (vals, &range) {
                (Some(v), Some(r)) => {
                    let x: f64 = (0..3).map(|c| b[c] * v[f[c] as usize]).sum();
                    r.position(x).map_or(UNDEFINED, |(t, _)| diverging(t))
                }
                _ => PLAIN,
            };
            img.put(
                i64::from(x),
                i64::from(y),
                to_rgb8(lit(base, brightness(n, light))),
            );
        }
    }
    let (mut outside_range, mut undefined) = (0, 0);
    if let (Some(v), Some(r)) = (vals, &range) {
        for &x in v {
            match r.position(x) {
                None => undefined += 1,
                Some((_, true)) => outside_range += 1,
                Some(_) => {}
            }
        }
        if strip > 0 {
            let label = match o.colour {
                ColourBy::Gaussian => "K",
                ColourBy::Mean => "H",
                ColourBy::None => "",
            };
            draw_colour_bar(&mut img, vw, r, label, scale);
        }
    }
    let report = RenderReport {
        width: o.width,
        height: o.height,
        vertices: scene.positions.len(),
        triangles: scene.faces.len(),
        colour: o.colour,
        range,
        outside_range,
        undefined,
        covered_pixels: vis.covered(),
        skipped_triangles: vis.skipped_non_finite,
        scale: cam.scale,
        orientation: check_orientation(scene),
    };
    Ok((img, report))
}
