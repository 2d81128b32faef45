//! Figures like the paper's Figs. 4.1–4.6, as SVG: for an edge configuration (m_u, m_w) the
//! left panel shows u's copy of R² — Ω_u (Def. 4.1.1), P_u and T_u (Defs. 4.1.2–4.1.3), the
//! gluing domains Ω_uw of all m_u neighbours (Def. 4.1.9) and a grid in Ω_uw (neighbour with
//! label 0); the right panel shows w's copy with Ω_w, P_w, T_w, Ω_wu and the image of that
//! grid under φ_wu (Def. 4.1.10). Written by hand: a few hundred lines of SVG text need no
//! plotting crate.

use super::maps::{g_v_inv, in_omega_v, omega_radius, phi_wu, rotate_frac, EdgeConfig, VertexPair};
use super::{Paper, Ppm, P2};
use std::fmt::Write;

const PANEL: f64 = 360.0;
const SCALE: f64 = 150.0;

fn xy(p: [f64; 2], panel: usize) -> (f64, f64) {
    (
        panel as f64 * PANEL + PANEL / 2.0 + SCALE * p[0],
        PANEL / 2.0 + 20.0 - SCALE * p[1],
    )
}

fn polyline(s: &mut String, pts: &[[f64; 2]], panel: usize, style: &str, closed: bool) {
    let finite: Vec<(f64, f64)> = pts
        .iter()
        .filter(|p| p[0].is_finite() && p[1].is_finite())
        .map(|&p| xy(p, panel))
        .collect();
    if finite.len() < 2 {
        return;
    }
    let d: Vec<String> = finite
        .iter()
        .map(|(x, y)| format!("{x:.2},{y:.2}"))
        .collect();
    let tag = if closed { "polygon" } else { "polyline" };
    let _ = writeln!(s, r#"<{tag} points="{}" style="{style}"/>"#, d.join(" "));
}

/// The boundary of the canonical lens E (Fig. 4.4) as a closed polyline.
fn lens_boundary(n: usize) -> Vec<[f64; 2]> {
    let c = (std::f64::consts::PI / 6.0).cos();
    let a = 2f64.sqrt().atan(); // corners (1/2, ±√2/2)
    let mut v = Vec::new();
    for k in 0..=n {
        let t = -a + 2.0 * a * k as f64 / n as f64;
        v.push([c * t.cos(), c * t.sin()]);
    }
    for k in 0..=n {
        let t = std::f64::consts::PI - a + 2.0 * a * k as f64 / n as f64;
        v.push([1.0 + c * t.cos(), c * t.sin()]);
    }
    v
}

/// Pull a point of E back into v's copy: R⁻¹∘g_v⁻¹ (label i).
fn pull_back(m: u32, i: u32, q: [f64; 2]) -> Option<[f64; 2]> {
    let p = g_v_inv::<f64>(m, &P2::new(q[0], q[1])).ok()?;
    Some(rotate_frac(&p, i as i64, m as i64).to_f64())
}

fn frame(s: &mut String, m: u32, panel: usize, title: &str) {
    let rho = omega_radius::<f64>(m, 53);
    let corners: Vec<[f64; 2]> = (0..m)
        .map(|i| {
            let a = 2.0 * std::f64::consts::PI * i as f64 / m as f64;
            [a.cos(), a.sin()]
        })
        .collect();
    polyline(
        s,
        &corners,
        panel,
        "fill:none;stroke:#888;stroke-width:1",
        true,
    );
    for c in &corners {
        polyline(
            s,
            &[[0.0, 0.0], *c],
            panel,
            "stroke:#bbb;stroke-width:0.7",
            false,
        );
    }
    let (cx, cy) = xy([0.0, 0.0], panel);
    let _ = writeln!(
        s,
        r#"<circle cx="{cx:.2}" cy="{cy:.2}" r="{:.2}" style="fill:none;stroke:#000;stroke-width:1.2"/>"#,
        SCALE * rho
    );
    let _ = writeln!(
        s,
        r#"<text x="{:.1}" y="16" font-family="sans-serif" font-size="13">{title}</text>"#,
        panel as f64 * PANEL + 10.0
    );
}

/// Render the figure for degrees (m_u, m_w); the edge [u, w] has label 0 at both ends.
pub fn render_svg(m_u: u32, m_w: u32) -> Result<String, super::ConfigError> {
    // Each of the m gluing domains is drawn with a fixed number of points (~10 kB of SVG):
    // an unbounded degree is unbounded memory.
    const MAX_FIGURE_DEGREE: u32 = 1024;
    for m in [m_u, m_w] {
        if m > MAX_FIGURE_DEGREE {
            return Err(super::ConfigError::DegreeTooLarge {
                m,
                limit: MAX_FIGURE_DEGREE,
            });
        }
    }
    let e = EdgeConfig::new(m_u, 0, m_w, 0)?;
    let mut s = String::new();
    let _ = writeln!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{}" height="{}" viewBox="0 0 {} {}">"#,
        2.0 * PANEL,
        PANEL + 40.0,
        2.0 * PANEL,
        PANEL + 40.0
    );
    let _ = writeln!(
        s,
        "<desc>PPM gluing data for an edge [u, w] with m_u = {m_u}, m_w = {m_w} (Defs. 4.1.1–4.1.10)</desc>"
    );
    frame(
        &mut s,
        m_u,
        0,
        &format!("Ω_u, P_u, T_u, Ω_uk (m_u = {m_u}); grid in Ω_uw"),
    );
    frame(
        &mut s,
        m_w,
        1,
        &format!("Ω_w (m_w = {m_w}); Ω_wu and φ_wu(grid)"),
    );
    let lens = lens_boundary(48);
    // Gluing domains of all neighbours of u, and Ω_wu in w's copy.
    for i in 0..m_u {
        let pts: Vec<[f64; 2]> = lens.iter().filter_map(|&q| pull_back(m_u, i, q)).collect();
        let style = if i == 0 {
            "fill:#fdd;fill-opacity:0.6;stroke:#c00;stroke-width:1"
        } else {
            "fill:#eef;fill-opacity:0.5;stroke:#55a;stroke-width:0.7"
        };
        polyline(&mut s, &pts, 0, style, true);
    }
    let back: Vec<[f64; 2]> = lens.iter().filter_map(|&q| pull_back(m_w, 0, q)).collect();
    polyline(
        &mut s,
        &back,
        1,
        "fill:#dfd;fill-opacity:0.6;stroke:#080;stroke-width:1",
        true,
    );
    // A grid of E pulled back into Ω_uw, and its image under φ_wu.
    let pair = VertexPair::Edge(e);
    let lines = 9;
    for dir in 0..2 {
        for k in 1..lines {
            let mut src = Vec::new();
            let mut img = Vec::new();
            for j in 0..=60 {
                let a = 0.13 + 0.74 * k as f64 / lines as f64;
                let b = -0.72 + 1.44 * j as f64 / 60.0;
                let q = if dir == 0 {
                    [a, b * 0.6]
                } else {
                    [0.13 + 0.74 * (b + 0.72) / 1.44, (a - 0.5) * 1.2]
                };
                let Some(p) = pull_back(m_u, 0, q) else {
                    continue;
                };
                let pp = P2::new(p[0], p[1]);
                if !(in_omega_v(m_u, &pp).is_true() && Paper.in_omega_uw_literal(&e, &pp).is_true())
                {
                    continue;
                }
                if let Ok(t) = phi_wu(&pair, &pp) {
                    src.push(p);
                    img.push(t.to_f64());
                }
            }
            let colour = if dir == 0 { "#c00" } else { "#06c" };
            polyline(
                &mut s,
                &src,
                0,
                &format!("fill:none;stroke:{colour};stroke-width:0.6"),
                false,
            );
            polyline(
                &mut s,
                &img,
                1,
                &format!("fill:none;stroke:{colour};stroke-width:0.6"),
                false,
            );
        }
    }
    s.push_str("</svg>\n");
    Ok(s)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::construction::maps::in_canonical_lens;

    /// The grid of Fig. 4.x as drawn: each grid line in Ω_uw (left panel, x ∈ [0, 360]) is
    /// followed by its image under φ_wu (right panel, x ∈ [360, 720]), every point inside the
    /// picture, and each line spans a good part of the lens (not a few pixels).
    #[test]
    fn d4_1_9_figure_grid_lines_lie_in_their_panels_and_span_the_lens() {
        let svg = render_svg(5, 7).expect("valid degrees");
        let grid: Vec<Vec<(f64, f64)>> = svg
            .lines()
            .filter(|l| l.contains("stroke-width:0.6"))
            .map(|l| {
                let pts = l
                    .split("points=\"")
                    .nth(1)
                    .and_then(|r| r.split('"').next());
                pts.unwrap_or("")
                    .split(' ')
                    .filter_map(|xy| {
                        let (x, y) = xy.split_once(',')?;
                        Some((x.parse().ok()?, y.parse().ok()?))
                    })
                    .collect()
            })
            .collect();
        assert_eq!(
            grid.len(),
            2 * 2 * 8,
            "two directions × 8 lines, each drawn twice"
        );
        for (n, line) in grid.iter().enumerate() {
            let panel = (n % 2) as f64;
            assert!(line.len() > 10, "line {n}: {line:?}");
            for &(x, y) in line {
                assert!(
                    x >= panel * PANEL && x <= (panel + 1.0) * PANEL,
                    "line {n}: x = {x}"
                );
                assert!((0.0..=PANEL + 40.0).contains(&y), "line {n}: y = {y}");
            }
            let span = |f: fn(&(f64, f64)) -> f64| {
                let v: Vec<f64> = line.iter().map(f).collect();
                v.iter().cloned().fold(f64::NEG_INFINITY, f64::max)
                    - v.iter().cloned().fold(f64::INFINITY, f64::min)
            };
            let extent = span(|p| p.0).max(span(|p| p.1));
            assert!(extent > 20.0, "line {n} spans {extent} px");
        }
    }

    /// The drawn lens of Figs. 4.1–4.6 is the boundary of the canonical lens E (Sec. 4.1):
    /// every vertex of the polyline has points of E within 10⁻⁶ and points outside E within
    /// 10⁻⁶, and the two arcs meet at E's corners (1/2, ±√2/2).
    #[test]
    fn d4_1_8_figure_lens_is_the_boundary_of_e() {
        let pts = lens_boundary(24);
        let inside = |x: f64, y: f64| in_canonical_lens(&P2::new(x, y)).is_true();
        for p in &pts {
            let near: Vec<bool> = (0..16)
                .map(|k| {
                    let t = std::f64::consts::TAU * k as f64 / 16.0;
                    inside(p[0] + 1e-6 * t.cos(), p[1] + 1e-6 * t.sin())
                })
                .collect();
            assert!(near.contains(&true) && near.contains(&false), "{p:?}");
        }
        let h = 2f64.sqrt() / 2.0;
        for (p, q) in [(pts[0], [0.5, -h]), (pts[24], [0.5, h])] {
            assert!((p[0] - q[0]).abs() < 1e-12 && (p[1] - q[1]).abs() < 1e-12);
        }
    }
}
