//! SPEC `SV-compare`: the two constructions on the same mesh and the same S′ — distance
//! between the surfaces, distance of each to S′ (max and p99, relative to the bounding-box
//! diagonal), and curvature smoothness (mean |ΔH|·edge length over the edges of the sampled
//! mesh, relative to the diagonal), all at the same eval arguments (Sec. 6.2 pattern).

use super::surface::SigmaVPps;
use crate::mesh::SimplicialSurface;
use crate::surface::output::{sample_pattern_faces, SampledMesh};
use crate::surface::target::TargetSurface;
use crate::surface::{Pps, PpsOptions};
use serde::Serialize;

/// Max and 99th percentile of a list of distances.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct Spread {
    /// Largest value.
    pub max: f64,
    /// 99th percentile.
    pub p99: f64,
}

fn spread(mut v: Vec<f64>) -> Spread {
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n == 0 {
        return Spread {
            max: f64::NAN,
            p99: f64::NAN,
        };
    }
    Spread {
        max: v[n - 1],
        p99: v[((n as f64 * 0.99).ceil() as usize).clamp(1, n) - 1],
    }
}

/// The comparison (distances relative to the bounding-box diagonal of K).
#[derive(Debug, Clone, Serialize)]
pub struct CompareReport {
    /// Sampling level.
    pub level: u32,
    /// Points compared.
    pub points: usize,
    /// Bounding-box diagonal of K.
    pub diagonal: f64,
    /// |vertex − (σ,v)| / diagonal.
    pub between: Spread,
    /// |vertex − S′| / diagonal.
    pub vertex_to_target: Spread,
    /// |(σ,v) − S′| / diagonal.
    pub sigma_v_to_target: Spread,
    /// Mean over sampled edges of |H_a − H_b|·|a − b| (vertex construction).
    pub vertex_curvature_jump: f64,
    /// The same for the (σ, v) construction.
    pub sigma_v_curvature_jump: f64,
}

fn curvature_jump(m: &SampledMesh) -> f64 {
    let (mut s, mut n) = (0.0, 0usize);
    for f in &m.faces {
        for t in 0..3 {
            let (a, b) = (f[t] as usize, f[(t + 1) % 3] as usize);
            let d = crate::numeric::vec3::norm(crate::numeric::vec3::sub(
                m.positions[a],
                m.positions[b],
            ));
            let dh = (m.mean[a] - m.mean[b]).abs();
            if dh.is_finite() {
                s += dh * d;
                n += 1;
            }
        }
    }
    if n == 0 {
        f64::NAN
    } else {
        s / n as f64
    }
}

/// Compare the report's construction (paper profile) with the tutorial's on K at `level`.
pub fn compare(
    k: &SimplicialSurface,
    target: &dyn TargetSurface,
    sv: &SigmaVPps,
    level: u32,
) -> Result<CompareReport, String> {
    let pps = Pps::build(k, target, PpsOptions::default());
    let faces: Vec<_> = k.faces().map(|f| k.face(f)).collect();
    let pat = sample_pattern_faces(&faces, level).map_err(|e| e.to_string())?;
    let (mut lo, mut hi) = ([f64::MAX; 3], [f64::MIN; 3]);
    for v in k.vertices() {
        let p = k.position(v);
        for d in 0..3 {
            lo[d] = lo[d].min(p[d]);
            hi[d] = hi[d].max(p[d]);
        }
    }
    let diag = crate::numeric::vec3::norm(crate::numeric::vec3::sub(hi, lo)).max(f64::MIN_POSITIVE);
    let (mut between, mut vt, mut st) = (Vec::new(), Vec::new(), Vec::new());
    for s in &pat.points {
        let a = pps.eval_f64(s.face, s.bary).map_err(|e| e.to_string())?;
        let b = sv.eval_f64(s.face, s.bary).map_err(|e| e.to_string())?;
        let t = target.eval(s.face, k.face(s.face), s.bary);
        let d = |x: [f64; 3], y: [f64; 3]| {
            crate::numeric::vec3::norm(crate::numeric::vec3::sub(x, y)) / diag
        };
        between.push(d(a, b));
        vt.push(d(a, t));
        st.push(d(b, t));
    }
    let mv =
        crate::surface::output::sample_surface(&pps, level, None).map_err(|e| e.to_string())?;
    let ms = sv.sample_surface(level).map_err(|e| e.to_string())?;
    Ok(CompareReport {
        level,
        points: pat.points.len(),
        diagonal: diag,
        between: spread(between),
        vertex_to_target: spread(vt),
        sigma_v_to_target: spread(st),
        vertex_curvature_jump: curvature_jump(&mv) / diag,
        sigma_v_curvature_jump: curvature_jump(&ms) / diag,
    })
}
