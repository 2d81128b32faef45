//! `ppm render FILE -o out.png`: a picture of K, of S′ or of the PPS, coloured by curvature
//! (Figs. 6.4–6.7), or, with `--panels`, S′ next to the PPS built from it.

use crate::mesh::io::{read_mesh, ReadOptions};
use crate::mesh::SimplicialSurface;
use crate::render::colour::RangeSource;
use crate::render::panels::side_by_side;
use crate::render::source::{mesh_scene, pps_scene, samples_scene, sprime_scene};
use crate::render::{
    render_scene, ColourBy, ColourRange, Image, RenderError, RenderOptions, RenderReport, Scene,
    View,
};
use crate::surface::{Pps, PpsOptions, Profile, SPrime, SurfaceKind};
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

/// Arguments of `ppm render`.
#[derive(clap::Args, Debug)]
pub(crate) struct RenderArgs {
    /// The mesh K (OFF, OBJ, PLY), or a sampled surface with --input-is-samples.
    pub file: PathBuf,
    /// The PNG to write.
    #[arg(short = 'o', long)]
    pub output: PathBuf,
    /// mesh (K, flat) | sprime (S′, Sec. 5.1) | pps (the PPS, Ch. 5).
    #[arg(long, default_value = "pps")]
    pub what: String,
    /// The surface S′ the PPS approximates: pn (PN triangles) | loop.
    #[arg(long, default_value = "pn")]
    pub surface: String,
    /// Chapter 5 profile: paper | authors-code.
    #[arg(long, default_value = "paper")]
    pub profile: String,
    /// FILE is a sampled surface (e.g. from `ppm sample`): draw it as it is, with the normals
    /// and curvatures it carries (PLY) when present.
    #[arg(long)]
    pub input_is_samples: bool,
    /// Midpoint-subdivision level of the sampling (Sec. 6.2); default: the smallest giving
    /// ≥ 100,000 triangles, at most 5.
    #[arg(long)]
    pub level: Option<u32>,
    /// gaussian | mean | none (default: gaussian when the source has curvature).
    #[arg(long)]
    pub colour: Option<String>,
    /// Colour range a,b with a ≤ 0 ≤ b (default: 2nd–98th percentiles, widened to contain 0).
    #[arg(long, allow_hyphen_values = true)]
    pub range: Option<String>,
    /// azimuth,elevation in degrees (y is up; 0,0 looks along −z).
    #[arg(long, default_value = "30,20", allow_hyphen_values = true)]
    pub view: String,
    /// Image size WxH (per panel with --panels).
    #[arg(long, default_value = "800x600")]
    pub size: String,
    /// S′ next to the PPS built from it (Figs. 6.4–6.7), one shared camera and colour range.
    #[arg(long)]
    pub panels: bool,
    /// Print the report as JSON.
    #[arg(long)]
    pub json: bool,
}

fn parse_size(s: &str) -> Result<(u32, u32), RenderError> {
    let bad = || RenderError::BadSize(s.into());
    let (w, h) = s.split_once(['x', 'X']).ok_or_else(bad)?;
    let (w, h) = (
        w.trim().parse::<u32>().map_err(|_| bad())?,
        h.trim().parse::<u32>().map_err(|_| bad())?,
    );
    if !(16..=8192).contains(&w) || !(16..=8192).contains(&h) {
        return Err(bad());
    }
    Ok((w, h))
}

fn load(file: &std::path::Path) -> Result<SimplicialSurface, RenderError> {
    crate::mesh::load_surface(file).map_err(|e| RenderError::Mesh(e.to_string()))
}

/// One panel to draw: its caption and scene.
struct Panel {
    caption: String,
    scene: Scene,
}

fn default_level(faces: usize) -> u32 {
    (0..=5u32)
        .find(|&l| faces.saturating_mul(1 << (2 * l)) >= 100_000)
        .unwrap_or(5)
}

/// An axis-aligned box: (min corner, max corner).
type BoundingBox = ([f64; 3], [f64; 3]);

fn scenes(
    a: &RenderArgs,
    notes: &mut Vec<String>,
) -> Result<(Vec<Panel>, Option<BoundingBox>), RenderError> {
    if a.input_is_samples {
        let raw = read_mesh(&a.file, &ReadOptions::default())
            .map_err(|e| RenderError::Mesh(e.to_string()))?;
        let scene = samples_scene(&raw)?;
        return Ok((
            vec![Panel {
                caption: format!("{}", a.file.display()),
                scene,
            }],
            None,
        ));
    }
    let k = load(&a.file)?;
    let level = a.level.unwrap_or_else(|| default_level(k.num_faces()));
    if level > 8 {
        return Err(RenderError::Mesh(format!("--level {level}: at most 8")));
    }
    let profile = Profile::parse(&a.profile).ok_or_else(|| {
        RenderError::Mesh(format!(
            "unknown --profile {:?} (paper | authors-code)",
            a.profile
        ))
    })?;
    let kind = SurfaceKind::parse(&a.surface).ok_or_else(|| {
        RenderError::Mesh(format!("unknown --surface {:?} (pn | loop)", a.surface))
    })?;
    // Curvature costs order-2 jets: skip it when the picture is not coloured.
    let curvature = a.colour.as_deref() != Some("none");
    let frame = mesh_scene(&k).bbox();
    let sprime = SPrime::for_profile(kind, &k, profile)
        .map_err(|e| RenderError::Mesh(format!("S′ = {}: {e}", kind.name())))?;
    let pps = || {
        Pps::try_build(
            &k,
            sprime.as_target(),
            PpsOptions {
                profile,
                ..PpsOptions::default()
            },
        )
        .map_err(|e| RenderError::Mesh(e.to_string()))
    };
    let sname = match kind {
        SurfaceKind::Pn => "PN triangles",
        SurfaceKind::Loop => "the Loop limit surface",
    };
    notes.push(format!(
        "{}: {} vertices, {} faces; level {level}; S′ = {sname}; profile {}",
        a.file.display(),
        k.num_vertices(),
        k.num_faces(),
        profile.name()
    ));
    let panels = if a.panels {
        vec![
            Panel {
                caption: format!("S' = {sname}"),
                scene: sprime_scene(&k, &sprime, level),
            },
            Panel {
                caption: format!("PPS from {sname}"),
                scene: pps_scene(&pps()?, level, curvature)?,
            },
        ]
    } else {
        let (caption, scene) = match a.what.as_str() {
            "mesh" => ("K", mesh_scene(&k)),
            "sprime" => ("S'", sprime_scene(&k, &sprime, level)),
            "pps" => ("PPS", pps_scene(&pps()?, level, curvature)?),
            other => {
                return Err(RenderError::Mesh(format!(
                    "unknown --what {other:?} (mesh | sprime | pps)"
                )))
            }
        };
        vec![Panel {
            caption: caption.into(),
            scene,
        }]
    };
    Ok((panels, frame))
}

fn describe(r: &RenderReport) -> String {
    let mut s = format!(
        "  {}x{}: {} vertices, {} triangles; silhouette {} pixels",
        r.width, r.height, r.vertices, r.triangles, r.covered_pixels
    );
    if let Some(c) = &r.range {
        let how = match c.source {
            RangeSource::User => "--range".to_string(),
            RangeSource::Percentiles { lo, hi, count } => {
                format!("percentiles {lo}–{hi} of {count} finite values, widened to contain 0")
            }
        };
        s += &format!(
            "\n  colour: {} curvature in [{:e}, {:e}] ({how}); {} vertex values outside, {} undefined (NaN)",
            r.colour.name(),
            c.lo,
            c.hi,
            r.outside_range,
            r.undefined
        );
    }
    let o = &r.orientation;
    s += &format!(
        "\n  normals vs triangle orientation: {} of {} corners disagree",
        o.disagreeing, o.checked
    );
    if let Some(w) = o.worst {
        s += &format!(
            " (worst cos {:.3} at triangle {}, vertex {})",
            w.cosine, w.face, w.vertex
        );
    }
    if r.skipped_triangles > 0 {
        s += &format!(
            "\n  {} triangles with non-finite corners skipped",
            r.skipped_triangles
        );
    }
    s
}

fn run_inner(a: &RenderArgs) -> Result<(Image, Vec<RenderReport>, Vec<String>), RenderError> {
    let (width, height) = parse_size(&a.size)?;
    let view = View::parse(&a.view)?;
    let user_range = a.range.as_deref().map(ColourRange::parse).transpose()?;
    let mut notes = Vec::new();
    let (panels, frame) = scenes(a, &mut notes)?;
    let has_curv = panels.iter().all(|p| p.scene.gaussian.is_some());
    let colour = match a.colour.as_deref() {
        None if has_curv => ColourBy::Gaussian,
        None => ColourBy::None,
        Some(c) => ColourBy::parse(c).ok_or_else(|| {
            RenderError::Mesh(format!("unknown --colour {c:?} (gaussian | mean | none)"))
        })?,
    };
    // One range for all panels, so equal colours mean equal curvature.
    let range = match user_range {
        Some(r) => Some(r),
        None if colour != ColourBy::None => {
            let mut all = Vec::new();
            for p in &panels {
                if let Some(v) = crate::render::picture::values(&p.scene, colour)? {
                    all.extend_from_slice(v);
                }
            }
            ColourRange::robust(&all)
        }
        None => None,
    };
    let mut images = Vec::new();
    let mut reports = Vec::new();
    for p in &panels {
        let (img, rep) = render_scene(
            &p.scene,
            &RenderOptions {
                width,
                height,
                view,
                colour,
                range,
                frame,
                colour_bar: true,
            },
        )?;
        images.push((p.caption.clone(), img));
        reports.push(rep);
    }
    let img = if a.panels {
        side_by_side(&images, (height / 400).max(1))
    } else {
        images.remove(0).1
    };
    Ok((img, reports, notes))
}

/// Run `ppm render`; exit 0 on success, 1 when the normals are flipped (a sign error: the
/// orientation check), 2 on bad input or I/O errors.
pub(crate) fn run(a: RenderArgs) -> ExitCode {
    let t0 = Instant::now();
    let (img, reports, notes) = match run_inner(&a) {
        Ok(x) => x,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(2);
        }
    };
    let bytes = match img.to_png() {
        Ok(b) => b,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(2);
        }
    };
    if let Err(e) = std::fs::write(&a.output, bytes) {
        eprintln!("error: {}: {e}", a.output.display());
        return ExitCode::from(2);
    }
    if a.json {
        println!(
            "{}",
            serde_json::json!({ "output": a.output, "panels": reports })
        );
    } else {
        for n in &notes {
            println!("ppm render: {n}");
        }
        for r in &reports {
            println!("{}", describe(r));
        }
        println!(
            "ppm render: wrote {} ({}x{}) in {:.2} s",
            a.output.display(),
            img.width,
            img.height,
            t0.elapsed().as_secs_f64()
        );
    }
    if reports.iter().any(|r| r.orientation.flipped()) {
        eprintln!("error: most normals point against the triangles' orientation (a sign error in the normal?)");
        return ExitCode::from(1);
    }
    ExitCode::SUCCESS
}
