//! Chapter 4 on a whole mesh: every stated property checked on every edge, triangle and vertex
//! star of a validated simplicial surface.
//!
//! The maps of Sec. 4.1 depend on a mesh element only through its *configuration* (degrees and
//! half-edge labels, Sec. 6.1.3), so identical configurations give identical computations: each
//! distinct configuration is checked once and the report says how many mesh elements it
//! stands for. Every edge, triangle and vertex of the mesh is covered that way unless a limit
//! is set (`max_*`), in which case a seeded subset of configurations is checked and the
//! coverage line says so.

use super::aggregate;
use super::errata::{self, Element};
use crate::construction::abstract_view::AbstractPpm;
use crate::construction::checks::{
    check_star_overlaps, run_edge_checks_with, run_triangle_checks_with, StarConfig,
};
use crate::construction::{EdgeConfig, Paper, Ppm, PpmGluing, TriangleConfig};
use crate::mesh::{SimplicialSurface, VertexId};
#[cfg(feature = "mpfr")]
use crate::numeric::MpMpfr;
use crate::numeric::{Mp, MpBackend};
use crate::report::{CheckResult, Witness};
use rand::seq::SliceRandom;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use rayon::prelude::*;
use serde::Serialize;
use std::collections::{BTreeMap, BTreeSet};

/// Which arithmetic the checks run in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Precision {
    /// IEEE double.
    F64,
    /// Multi-precision at the given number of bits, on [`Ch4Options::mp_backend`].
    Mp(u32),
}

/// Options of the mesh-wide Chapter 4 run.
#[derive(Debug, Clone, Serialize)]
pub struct Ch4Options {
    /// Seed of the samplers and of the configuration subsets.
    pub seed: u64,
    /// Samples per category (uniform, near boundary, near origin, near cut, …) per
    /// configuration.
    pub samples: usize,
    /// Arithmetic of the checks.
    pub precision: Precision,
    /// Implementation of [`Precision::Mp`].
    pub mp_backend: MpBackend,
    /// At most this many distinct edge / triangle / star configurations (seeded subset).
    pub max_edge_configs: Option<usize>,
    /// At most this many distinct triangle configurations (seeded subset).
    pub max_triangle_configs: Option<usize>,
    /// At most this many distinct star configurations (seeded subset).
    pub max_star_configs: Option<usize>,
}

impl Default for Ch4Options {
    fn default() -> Self {
        Ch4Options {
            seed: 20240601,
            samples: 24,
            precision: Precision::F64,
            mp_backend: MpBackend::default(),
            max_edge_configs: None,
            max_triangle_configs: None,
            max_star_configs: None,
        }
    }
}

/// What the run covered.
#[derive(Debug, Clone, Default, Serialize)]
pub struct Coverage {
    /// Oriented edges of K (two per edge).
    pub oriented_edges: u64,
    /// Distinct edge configurations (m_u, i, m_w, j) among them.
    pub edge_configs: u64,
    /// Edge configurations actually checked (after `max_edge_configs`).
    pub edge_configs_checked: u64,
    /// Oriented edges whose configuration was checked.
    pub edges_covered: u64,
    /// Triangles of K.
    pub triangles: u64,
    /// Distinct triangle configurations among them.
    pub triangle_configs: u64,
    /// Triangle configurations actually checked (after `max_triangle_configs`).
    pub triangle_configs_checked: u64,
    /// Triangles whose configuration was checked.
    pub triangles_covered: u64,
    /// Vertices of K.
    pub vertices: u64,
    /// Distinct star configurations among them.
    pub star_configs: u64,
    /// Star configurations actually checked (after `max_star_configs`).
    pub star_configs_checked: u64,
    /// Vertices whose star configuration was checked.
    pub vertices_covered: u64,
}

/// The report of a mesh-wide run.
#[derive(Debug, Clone, Serialize)]
pub struct Ch4Report {
    /// The options of the run.
    pub options: Ch4Options,
    /// What the run covered.
    pub coverage: Coverage,
    /// One result per statement ID, aggregated over configurations.
    pub checks: Vec<CheckResult>,
    /// IDs that fail, are documented errata, and fail only on their erratum's domain
    /// (expected).
    pub errata_confirmed: Vec<String>,
    /// IDs that fail and are not documented errata, or fail on a configuration outside their
    /// erratum's domain: conformance failures.
    pub unexpected_failures: Vec<String>,
    /// Set when the run examined nothing (`--max-configs 0`, or every check skipped): the
    /// run is inconclusive, not a pass.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub inconclusive: Option<String>,
    /// Coverage of the mesh by an interval-proof certificate (`--certificates FILE`), if given.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub certificates: Option<CertCoverage>,
}

impl Ch4Report {
    /// The run passes: something was checked, and every failure is a documented erratum on
    /// its domain.
    pub fn passes(&self) -> bool {
        self.unexpected_failures.is_empty() && self.inconclusive.is_none()
    }
}

/// Which Chapter 4 properties of a mesh a certificate (`ppm certify`, SPEC section "certified proofs") covers.
#[derive(Debug, Clone, Serialize)]
pub struct CertCoverage {
    /// The certificate file, as given.
    pub file: String,
    /// The certificate's max degree.
    pub max_degree: u32,
    /// The certificate's model name (`paper` or a planted fault).
    pub model: String,
    /// Distinct configurations the mesh needs (vertex degrees, oriented edges, triangles
    /// read from each of their vertices).
    pub configs_needed: usize,
    /// Configurations of the mesh that could not be keyed (invalid labels); none for a
    /// validated mesh.
    pub config_errors: Vec<String>,
    /// Per certificate property: certified for this mesh, or what is missing.
    pub properties: Vec<crate::certify::PropertyCoverage>,
}

/// The configurations of `k` (degrees, edge and triangle configurations) and their coverage
/// by `cert`.
pub fn certificate_coverage(
    k: &SimplicialSurface,
    cert: &crate::certify::Certificate,
    file: &str,
) -> CertCoverage {
    let g = PpmGluing::new(k);
    let mut errors = Vec::new();
    let mut degrees: Vec<u32> = k.vertices().map(|v| k.degree(v)).collect();
    degrees.sort_unstable();
    degrees.dedup();
    let mut edges = Vec::new();
    for (a, b) in k.edges() {
        match g.edge_config(a, b) {
            Ok(e) => edges.push(e),
            Err(e) => errors.push(format!("edge [{a}, {b}]: {e}")),
        }
    }
    let mut tris = Vec::new();
    for f in k.faces() {
        match g.triangle_config(f) {
            Ok((t, _)) => tris.push(t),
            Err(e) => errors.push(format!("face {f}: {e}")),
        }
    }
    let (needed, properties) = match crate::certify::ConfigKey::all_for(&degrees, &edges, &tris) {
        Ok(keys) => (keys.len(), crate::certify::coverage(cert, &keys)),
        Err(e) => {
            errors.push(e.to_string());
            (0, Vec::new())
        }
    };
    CertCoverage {
        file: file.to_string(),
        max_degree: cert.max_degree,
        model: cert.model.clone(),
        configs_needed: needed,
        config_errors: errors,
        properties,
    }
}

/// The Chapter 4 check ID a certificate property stands for (`L4.2.1(cert)` → `L4.2.1`).
pub fn cert_property_check_id(prop: &str) -> &str {
    prop.strip_suffix("(cert)").unwrap_or(prop)
}

fn subset<T: Clone>(all: Vec<T>, limit: Option<usize>, seed: u64) -> Vec<T> {
    match limit {
        Some(n) if n < all.len() => {
            let mut v = all;
            v.shuffle(&mut ChaCha8Rng::seed_from_u64(seed));
            v.truncate(n);
            v
        }
        _ => all,
    }
}

/// The star of x as a configuration: degree and, per label k, the neighbour's degree and
/// the label of x in the neighbour's star.
pub fn star_config(g: &PpmGluing, x: VertexId) -> Option<StarConfig> {
    let k = g.surface();
    let m = k.degree(x);
    let nbrs = (0..m)
        .map(|i| {
            let n = k.link_vertex(x, i)?;
            Some((k.degree(n), k.s(n, x)?))
        })
        .collect::<Option<Vec<_>>>()?;
    Some(StarConfig { m, nbrs })
}

/// An edge configuration as a map key (the four integers of Def. 4.1.8).
type EdgeConfigKey = (u32, u32, u32, u32);
/// A configuration with one example oriented edge (u, w) and how many oriented edges have it.
type EdgeConfigExample = (EdgeConfig, VertexId, VertexId, u64);

/// One checked configuration's result: the witness context, the configuration, the result.
type Part = (String, Element, CheckResult);

/// A Chapter 4 model ([`Paper`], or a planted fault in tests) in every arithmetic the run may
/// use.
#[cfg(not(feature = "mpfr"))]
pub trait Chapter4Model: Ppm<f64> + Ppm<Mp> {}
#[cfg(not(feature = "mpfr"))]
impl<T: Ppm<f64> + Ppm<Mp>> Chapter4Model for T {}
/// A Chapter 4 model ([`Paper`], or a planted fault in tests) in every arithmetic the run may
/// use.
#[cfg(feature = "mpfr")]
pub trait Chapter4Model: Ppm<f64> + Ppm<Mp> + Ppm<MpMpfr> {}
#[cfg(feature = "mpfr")]
impl<T: Ppm<f64> + Ppm<Mp> + Ppm<MpMpfr>> Chapter4Model for T {}

/// Run every Chapter 4 check on the mesh.
pub fn run_chapter4(k: &SimplicialSurface, opts: &Ch4Options) -> Ch4Report {
    run_chapter4_with(k, opts, None)
}

/// [`run_chapter4`] with a progress hook, called after each checked configuration with (done,
/// total) of the current family (edges, then triangles, then stars, then the abstract stars).
pub fn run_chapter4_with(
    k: &SimplicialSurface,
    opts: &Ch4Options,
    progress: crate::report::Progress,
) -> Ch4Report {
    run_chapter4_model(k, opts, &Paper, progress)
}

/// [`run_chapter4_with`] for any model of the maps (the paper's is [`Paper`]; tests plant
/// faults, e.g. a lens test that disagrees with Def. 4.1.9 at a degree where the paper's claim
/// holds, to check that it is not excused as an erratum). The abstract Def. 3.4.1 run always
/// uses the paper's maps.
pub fn run_chapter4_model<M: Chapter4Model>(
    k: &SimplicialSurface,
    opts: &Ch4Options,
    model: &M,
    progress: crate::report::Progress,
) -> Ch4Report {
    use std::sync::atomic::AtomicUsize;
    let g = PpmGluing::new(k);
    let mut cov = Coverage::default();
    let mut parts: Vec<Part> = Vec::new();

    // Oriented edges → configurations (with one example edge each, for witnesses).
    let mut edge_cfgs: BTreeMap<EdgeConfigKey, EdgeConfigExample> = BTreeMap::new();
    let mut config_errors = CheckResult::new("D4.1.8", "every edge has a valid configuration");
    for (a, b) in k.edges() {
        for (u, w) in [(a, b), (b, a)] {
            cov.oriented_edges += 1;
            config_errors.examined += 1;
            match g.edge_config(u, w) {
                Ok(e) => {
                    edge_cfgs
                        .entry((e.m_u, e.i, e.m_w, e.j))
                        .or_insert((e, u, w, 0))
                        .3 += 1
                }
                Err(err) => config_errors.offend(|| {
                    Witness::new(
                        format!("[{u}, {w}]: {err}"),
                        serde_json::json!({"u": u, "w": w}),
                    )
                }),
            }
        }
    }
    parts.push((String::new(), Element::Mesh, config_errors));
    cov.edge_configs = edge_cfgs.len() as u64;
    let edges = subset(
        edge_cfgs.into_values().collect::<Vec<_>>(),
        opts.max_edge_configs,
        opts.seed,
    );
    cov.edge_configs_checked = edges.len() as u64;
    cov.edges_covered = edges.iter().map(|e| e.3).sum();
    let seed = opts.seed;
    let n = opts.samples;
    let done = AtomicUsize::new(0);
    let edge_results: Vec<Part> = edges
        .par_iter()
        .flat_map_iter(|(e, u, w, count)| {
            let ctx = format!(
                "edge [{u}, {w}] (config m_u={}, i={}, m_w={}, j={}; {count} oriented edge(s))",
                e.m_u, e.i, e.m_w, e.j
            );
            let el = Element::Edge {
                m_u: e.m_u,
                i: e.i,
                m_w: e.m_w,
                j: e.j,
            };
            let rs = match opts.precision {
                Precision::F64 => run_edge_checks_with::<f64, M>(model, e, seed, n, 53),
                Precision::Mp(bits) => match opts.mp_backend {
                    MpBackend::PureRust => run_edge_checks_with::<Mp, M>(model, e, seed, n, bits),
                    #[cfg(feature = "mpfr")]
                    MpBackend::Mpfr => run_edge_checks_with::<MpMpfr, M>(model, e, seed, n, bits),
                },
            };
            crate::report::tick(progress, &done, edges.len());
            rs.into_iter().map(move |r| (ctx.clone(), el, r))
        })
        .collect();
    parts.extend(edge_results);

    // Triangles.
    let mut tri_cfgs: BTreeMap<String, (TriangleConfig, [VertexId; 3], u64)> = BTreeMap::new();
    let mut tri_errors = CheckResult::new(
        "D4.1.4(fan)",
        "every triangle's labels form a consistently oriented fan",
    );
    for f in k.faces() {
        cov.triangles += 1;
        tri_errors.examined += 1;
        match g.triangle_config(f) {
            Ok((t, vs)) => tri_cfgs.entry(format!("{t:?}")).or_insert((t, vs, 0)).2 += 1,
            Err(err) => tri_errors.offend(|| {
                Witness::new(format!("face {f}: {err}"), serde_json::json!({"face": f}))
            }),
        }
    }
    parts.push((String::new(), Element::Mesh, tri_errors));
    cov.triangle_configs = tri_cfgs.len() as u64;
    let tris = subset(
        tri_cfgs.into_values().collect::<Vec<_>>(),
        opts.max_triangle_configs,
        opts.seed,
    );
    cov.triangle_configs_checked = tris.len() as u64;
    cov.triangles_covered = tris.iter().map(|t| t.2).sum();
    let done = AtomicUsize::new(0);
    let tri_results: Vec<Part> = tris
        .par_iter()
        .flat_map_iter(|(t, vs, count)| {
            let ctx = format!(
                "triangle [{}, {}, {}] (degrees {}, {}, {}; {count} triangle(s))",
                vs[0], vs[1], vs[2], t.m_u, t.m_w, t.m_x
            );
            let el = Element::Triangle {
                m_u: t.m_u,
                m_w: t.m_w,
                m_x: t.m_x,
            };
            let rs = match opts.precision {
                Precision::F64 => run_triangle_checks_with::<f64, M>(model, t, seed, n, 53),
                Precision::Mp(bits) => match opts.mp_backend {
                    MpBackend::PureRust => {
                        run_triangle_checks_with::<Mp, M>(model, t, seed, n, bits)
                    }
                    #[cfg(feature = "mpfr")]
                    MpBackend::Mpfr => {
                        run_triangle_checks_with::<MpMpfr, M>(model, t, seed, n, bits)
                    }
                },
            };
            crate::report::tick(progress, &done, tris.len());
            rs.into_iter().map(move |r| (ctx.clone(), el, r))
        })
        .collect();
    parts.extend(tri_results);

    // Vertex stars: at most two gluing domains overlap; non-adjacent neighbours' gluing
    // domains are disjoint (triples x, u, w with u, w neighbours of x but [u, w] no edge).
    let mut star_cfgs: BTreeMap<String, (StarConfig, VertexId, u64)> = BTreeMap::new();
    for x in k.vertices() {
        cov.vertices += 1;
        if let Some(s) = star_config(&g, x) {
            star_cfgs.entry(format!("{s:?}")).or_insert((s, x, 0)).2 += 1;
        }
    }
    cov.star_configs = star_cfgs.len() as u64;
    let stars = subset(
        star_cfgs.into_values().collect::<Vec<_>>(),
        opts.max_star_configs,
        opts.seed,
    );
    cov.star_configs_checked = stars.len() as u64;
    cov.vertices_covered = stars.iter().map(|s| s.2).sum();
    let done = AtomicUsize::new(0);
    let star_results: Vec<Part> = stars
        .par_iter()
        .flat_map_iter(|(s, x, count)| {
            let ctx = format!("star of vertex {x} (m = {}; {count} vertex(es))", s.m);
            let mut rs = Vec::new();
            for lens in [false, true] {
                rs.extend(match opts.precision {
                    Precision::F64 => check_star_overlaps::<f64, M>(model, s, lens, seed, n, 53),
                    Precision::Mp(bits) => match opts.mp_backend {
                        MpBackend::PureRust => {
                            check_star_overlaps::<Mp, M>(model, s, lens, seed, n, bits)
                        }
                        #[cfg(feature = "mpfr")]
                        MpBackend::Mpfr => {
                            check_star_overlaps::<MpMpfr, M>(model, s, lens, seed, n, bits)
                        }
                    },
                });
            }
            crate::report::tick(progress, &done, stars.len());
            let el = Element::Star { m: s.m };
            rs.into_iter().map(move |r| (ctx.clone(), el, r))
        })
        .collect();
    parts.extend(star_results);

    // Def. 3.4.1 through the abstract interface (the general checkers, unchanged), on the
    // closed star of one vertex of every degree present (Thm. 4.2.1).
    let mut by_degree: BTreeMap<u32, VertexId> = BTreeMap::new();
    for x in k.vertices() {
        by_degree.entry(k.degree(x)).or_insert(x);
    }
    let cfg = crate::gluing::sampled::SampleConfig {
        seed: opts.seed,
        n: opts.samples.max(4),
    };
    let done = AtomicUsize::new(0);
    let abstract_results: Vec<Part> = by_degree
        .par_iter()
        .flat_map_iter(|(m, x)| {
            let view = AbstractPpm::star_of(g, *x);
            let ctx =
                format!("closed star of vertex {x} (degree {m}), abstract Def. 3.4.1 checkers");
            let rs = crate::gluing::sampled::check_all(&view, &cfg);
            crate::report::tick(progress, &done, by_degree.len());
            rs.into_iter().map(move |r| (ctx.clone(), Element::Mesh, r))
        })
        .collect();
    parts.extend(abstract_results);

    // A failure is a documented erratum only on the erratum's domain (errata.rs); decided
    // per configuration, before the results are merged per ID.
    let mut in_domain = BTreeSet::new();
    let mut outside = BTreeSet::new();
    for (_, el, r) in &parts {
        if r.failed() {
            if errata::excused(&r.id, el) {
                in_domain.insert(r.id.clone());
            } else {
                outside.insert(r.id.clone());
            }
        }
    }
    let errata_confirmed: Vec<String> = in_domain.difference(&outside).cloned().collect();
    let unexpected_failures: Vec<String> = outside.into_iter().collect();
    let checks = aggregate(parts.into_iter().map(|(ctx, _, r)| (ctx, r)));
    let examined: u64 = checks.iter().map(|c| c.examined).sum();
    let inconclusive = if cov.edge_configs_checked
        + cov.triangle_configs_checked
        + cov.star_configs_checked
        == 0
    {
        Some(format!(
            "no configuration was checked (0 of {} edge, {} triangle, {} star configurations; --max-configs)",
            cov.edge_configs, cov.triangle_configs, cov.star_configs
        ))
    } else if examined == 0 {
        Some("every check examined nothing".to_string())
    } else {
        None
    };
    Ch4Report {
        options: opts.clone(),
        coverage: cov,
        checks,
        errata_confirmed,
        unexpected_failures,
        inconclusive,
        certificates: None,
    }
}

/// Text rendering: coverage, then one line per statement with errata marked.
pub fn render(r: &Ch4Report) -> String {
    use std::fmt::Write;
    let mut s = String::new();
    let c = &r.coverage;
    let prec = match r.options.precision {
        Precision::F64 => "f64 (53-bit significand, ε = 1.1e-16)".to_string(),
        Precision::Mp(b) => {
            let used = match r.options.mp_backend {
                MpBackend::PureRust => Mp::effective_precision(b),
                #[cfg(feature = "mpfr")]
                MpBackend::Mpfr => b,
            };
            format!(
                "{} {used} bits (ε = 2^-{used})",
                r.options.mp_backend.describe()
            )
        }
    };
    let _ = writeln!(
        s,
        "Chapter 4 checks — precision {prec}, seed {}, {} samples per category per configuration",
        r.options.seed, r.options.samples
    );
    let _ = writeln!(
        s,
        "coverage: {}/{} oriented edges via {}/{} edge configurations; {}/{} triangles via {}/{} configurations; {}/{} vertices via {}/{} star configurations",
        c.edges_covered, c.oriented_edges, c.edge_configs_checked, c.edge_configs,
        c.triangles_covered, c.triangles, c.triangle_configs_checked, c.triangle_configs,
        c.vertices_covered, c.vertices, c.star_configs_checked, c.star_configs
    );
    let mut checks = r.checks.clone();
    for ch in &mut checks {
        if !ch.failed() {
            continue;
        }
        if let Some(e) = errata::erratum(&ch.id) {
            ch.note = if r.errata_confirmed.contains(&ch.id) {
                format!(
                    "documented erratum (expected on {}): {}",
                    e.domain.describe(),
                    e.reason
                )
            } else {
                format!(
                    "FAILS OUTSIDE the documented erratum's domain ({}): not excused",
                    e.domain.describe()
                )
            };
        }
    }
    s.push_str(&crate::report::render_text(&checks));
    if let Some(cc) = &r.certificates {
        let _ = writeln!(
            s,
            "certificates: {} (degrees 3..={}, model {}; {} configurations needed by this mesh)",
            cc.file, cc.max_degree, cc.model, cc.configs_needed
        );
        for e in &cc.config_errors {
            let _ = writeln!(s, "  configuration error: {e}");
        }
        let list = |v: &[crate::certify::ConfigKey]| -> String {
            let mut t: Vec<String> = v.iter().take(8).map(|k| k.to_string()).collect();
            if v.len() > 8 {
                t.push(format!("… ({} in all)", v.len()));
            }
            t.join("; ")
        };
        for p in &cc.properties {
            let id = cert_property_check_id(&p.property);
            if p.certified {
                let scope = match p.max_delta {
                    None => "on the whole stated sets".to_string(),
                    Some(d) => format!("outside δ-boxes, δ ≤ {d:.1e}"),
                };
                let f64b = p
                    .f64_bound
                    .map(|b| {
                        let spec = if p.property == "P4.2.3(cert)" {
                            "CERT-f64-rounding"
                        } else {
                            "CERT-f64-props"
                        };
                        format!("; f64 bound {b:.2e} (SPEC {spec})")
                    })
                    .unwrap_or_default();
                let _ = writeln!(
                    s,
                    "  {id}: CERTIFIED for this mesh, {scope} ({} covers every configuration){f64b}",
                    p.property
                );
            } else {
                let mut why = Vec::new();
                if !p.missing.is_empty() {
                    why.push(format!("missing {}", list(&p.missing)));
                }
                if !p.refuted.is_empty() {
                    why.push(format!("refuted {}", list(&p.refuted)));
                }
                if !p.inconclusive.is_empty() {
                    why.push(format!("inconclusive {}", list(&p.inconclusive)));
                }
                let _ = writeln!(
                    s,
                    "  {id}: not certified ({}): {}",
                    p.property,
                    why.join("; ")
                );
            }
        }
    }
    if let Some(why) = &r.inconclusive {
        let _ = writeln!(s, "Chapter 4: INCONCLUSIVE, not a pass: {why}");
    }
    if r.unexpected_failures.is_empty() {
        let _ = writeln!(
            s,
            "Chapter 4: no failure beyond the {} documented errata",
            r.errata_confirmed.len()
        );
    } else {
        let _ = writeln!(
            s,
            "Chapter 4: UNEXPECTED failures: {}",
            r.unexpected_failures.join(", ")
        );
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::certify::{ConfigKey, PropertyCoverage};
    use crate::mesh::generate;
    use crate::mesh::validate::validate;

    #[test]
    fn subset_keeps_everything_in_order_when_the_limit_is_not_below_the_count() {
        let all: Vec<u32> = (0..20).collect();
        assert_eq!(subset(all.clone(), None, 7), all);
        assert_eq!(subset(all.clone(), Some(20), 7), all);
        assert_eq!(subset(all.clone(), Some(50), 7), all);
        let some = subset(all.clone(), Some(5), 7);
        assert_eq!(some.len(), 5);
        assert_eq!(some, subset(all.clone(), Some(5), 7), "seeded");
        assert_ne!(
            some,
            all[..5].to_vec(),
            "a seeded shuffle, not the first five"
        );
    }

    fn octahedron_run(opts: &Ch4Options) -> Ch4Report {
        let k = validate(&generate::octahedron())
            .surface
            .expect("the octahedron is a simplicial surface");
        run_chapter4(&k, opts)
    }

    #[test]
    fn a_run_that_checks_only_edge_configurations_is_not_inconclusive() {
        // The "nothing was checked" test sums the three kinds: edge configurations alone are a
        // run that examined something.
        let r = octahedron_run(&Ch4Options {
            samples: 2,
            max_triangle_configs: Some(0),
            max_star_configs: Some(0),
            ..Ch4Options::default()
        });
        assert!(r.coverage.edge_configs_checked > 0);
        assert_eq!(r.coverage.triangle_configs_checked, 0);
        assert_eq!(r.coverage.star_configs_checked, 0);
        assert_eq!(r.inconclusive, None);
        let none = octahedron_run(&Ch4Options {
            samples: 2,
            max_edge_configs: Some(0),
            max_triangle_configs: Some(0),
            max_star_configs: Some(0),
            ..Ch4Options::default()
        });
        assert!(none.inconclusive.is_some());
        assert!(!none.passes());
    }

    #[test]
    fn render_lists_eight_configurations_and_counts_the_rest() {
        let mut r = octahedron_run(&Ch4Options {
            samples: 2,
            max_edge_configs: Some(1),
            max_triangle_configs: Some(0),
            max_star_configs: Some(0),
            ..Ch4Options::default()
        });
        let keys =
            |n: u32| -> Vec<ConfigKey> { (3..3 + n).map(|m| ConfigKey::Vertex { m }).collect() };
        let property = |missing: Vec<ConfigKey>| PropertyCoverage {
            property: "C5.4-at-most-two(cert)".to_string(),
            certified: false,
            missing,
            refuted: Vec::new(),
            inconclusive: Vec::new(),
            max_delta: None,
            f64_bound: None,
        };
        r.certificates = Some(CertCoverage {
            file: "c.json".to_string(),
            max_degree: 20,
            model: "paper".to_string(),
            configs_needed: 9,
            config_errors: Vec::new(),
            properties: vec![property(keys(9)), property(keys(8))],
        });
        let text = render(&r);
        assert_eq!(text.matches("… (9 in all)").count(), 1, "{text}");
        assert!(!text.contains("(8 in all)"), "{text}");
    }
}
