//! Software rendering of the surfaces to PNG (`ppm render`): pictures of S′ and of the PPS
//! coloured by curvature, in the layout of the paper's Figs. 6.4–6.7 (Sec. 6.2).
//!
//! No GPU or display: an orthographic [`camera`] fitted to the bounding box, a z-buffered
//! triangle [`raster`]iser that records per pixel the visible triangle and its barycentric
//! coordinates, then per-pixel [`shade`]: the interpolated normal (θ's analytic derivatives
//! for the PPS, [`crate::surface::geometry`]) lights a [`colour`] from a diverging map centred
//! at 0, with a colour bar whose numbers are drawn with the bitmap [`font`].
//!
//! * [`scene`] — the triangles to draw with per-vertex normals and values;
//! * [`source`] — scenes from K (`mesh`), S′ (`sprime`), the PPS (`pps`) or a sample file;
//! * [`orientation`] — the check that shading normals agree with the triangles' orientation;
//! * [`image`] — RGB images and deterministic PNG encoding; [`panels`] — side-by-side layout;
//! * [`error`] — typed errors.

pub mod camera;
pub(crate) mod colour;
pub(crate) mod colour_bar;
pub(crate) mod error;
pub(crate) mod font;
pub(crate) mod image;
pub mod orientation;
pub(crate) mod panels;
pub(crate) mod picture;
pub(crate) mod raster;
pub(crate) mod scene;
pub(crate) mod shade;
pub mod source;

pub use camera::{Camera, View};
pub use colour::{ColourBy, ColourRange};
pub use error::RenderError;
pub use image::Image;
pub use picture::{render_scene, RenderOptions, RenderReport};
pub use scene::Scene;
