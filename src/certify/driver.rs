//! The driver: prove every property of every configuration, merge shards, coverage.

use super::bnb::{omax, Settings};
use super::certificate::{Certificate, CertifyError};
use super::config::ConfigKey;
use super::f64_bound::{f64_rounding_statement, prove_f64_rounding};
use super::f64_props::{attach_f64_bounds, f64_bound_statement};
use super::g_chart::prove_g_chart;
use super::model::Model;
use super::prove_edge::{prove_hausdorff, prove_inverse, prove_nonempty};
use super::prove_triangle::prove_triangle;
use super::prove_vertex::{prove_lens_agreement, prove_star};
use super::result::{F64Bound, F64Outside, F64Rounding, GChartRounding, Outcome, PropertyResult};
use serde::Serialize;
use std::time::Instant;

// ---------------------------------------------------------------------------------------------
// Driver.
// ---------------------------------------------------------------------------------------------

/// All provers for one configuration.
pub fn prove_config(key: ConfigKey, model: &Model, s: &Settings) -> Vec<PropertyResult> {
    match key {
        ConfigKey::Vertex { m } => {
            let mut lens = prove_lens_agreement(m, model, s);
            // As for φ_wu below: the production evaluator's g_v, g_v⁻¹ (the oracle's queries).
            if model.is_paper() {
                lens.g_chart = Some(prove_g_chart(m));
            }
            vec![
                lens,
                prove_star(m, false, false, model, s),
                prove_star(m, false, true, model, s),
                prove_star(m, true, false, model, s),
                prove_star(m, true, true, model, s),
            ]
        }
        ConfigKey::Edge { m_u, m_w } => {
            let mut inverse = prove_inverse(m_u, m_w, model, s);
            // The rounding bound is about the production evaluator (the paper's maps at f64).
            if model.is_paper() {
                inverse.f64_rounding = Some(prove_f64_rounding(m_u, m_w, s));
            }
            vec![
                prove_nonempty(m_u, m_w, model),
                inverse,
                prove_hausdorff(m_u, m_w, model, s),
            ]
        }
        ConfigKey::Triangle { .. } => prove_triangle(key, model, s),
    }
}

/// Prove every configuration of `configs` on `jobs` threads (deterministic output order).
pub fn run(
    configs: &[ConfigKey],
    max_degree: u32,
    model: &Model,
    s: &Settings,
    jobs: usize,
    shard: Option<(usize, usize)>,
) -> Result<Certificate, CertifyError> {
    run_with(configs, max_degree, model, s, jobs, shard, None)
}

/// [`run`] with a progress hook called after each configuration (done, total).
pub fn run_with(
    configs: &[ConfigKey],
    max_degree: u32,
    model: &Model,
    s: &Settings,
    jobs: usize,
    shard: Option<(usize, usize)>,
    progress: crate::report::Progress,
) -> Result<Certificate, CertifyError> {
    use rayon::prelude::*;
    let done = std::sync::atomic::AtomicUsize::new(0);
    let t0 = Instant::now();
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(jobs.max(1))
        .build()
        .map_err(|e| CertifyError::BadArg(format!("thread pool: {e}")))?;
    let results: Vec<PropertyResult> = pool.install(|| {
        configs
            .par_iter()
            .map(|k| {
                let r = prove_config(*k, model, s);
                crate::report::tick(progress, &done, configs.len());
                r
            })
            .collect::<Vec<_>>()
            .into_iter()
            .flatten()
            .collect()
    });
    let mut cert = Certificate {
        format: "pseudomanifold-certificate/1".into(),
        max_degree,
        model: model.name(),
        shard,
        configs: configs.len(),
        results,
        wall_millis: t0.elapsed().as_millis() as u64,
        jobs,
        statements: Default::default(),
    };
    // CERT-f64-props needs the edges' and degrees' bounds, which a shard may not hold: shards
    // get them at the merge.
    if shard.is_none() {
        attach_f64_bounds(&mut cert);
    }
    Ok(cert)
}

/// Join shard certificates (same max degree and model; no configuration twice).
pub fn merge(parts: Vec<Certificate>) -> Result<Certificate, CertifyError> {
    let first = parts
        .first()
        .ok_or_else(|| CertifyError::Mismatch("no certificates to merge".into()))?;
    let (md, model) = (first.max_degree, first.model.clone());
    let mut results = Vec::new();
    let mut configs = 0;
    let mut wall = 0;
    for p in &parts {
        if p.max_degree != md || p.model != model {
            return Err(CertifyError::Mismatch(format!(
                "max degree {} / model {} vs {} / {}",
                p.max_degree, p.model, md, model
            )));
        }
        configs += p.configs;
        wall = wall.max(p.wall_millis);
        results.extend(p.results.iter().cloned());
    }
    results.sort_by(|a, b| (a.key, &a.property).cmp(&(b.key, &b.property)));
    for w in results.windows(2) {
        if w[0].key == w[1].key && w[0].property == w[1].property {
            return Err(CertifyError::Mismatch(format!(
                "{} / {} appears twice",
                w[0].key, w[0].property
            )));
        }
    }
    let mut cert = Certificate {
        format: first.format.clone(),
        max_degree: md,
        model,
        shard: None,
        configs,
        results,
        wall_millis: wall,
        jobs: first.jobs,
        statements: Default::default(),
    };
    // Derived from the merged results (a merge of one older certificate adds them to it).
    attach_f64_bounds(&mut cert);
    Ok(cert)
}

/// How a certificate covers one property for a mesh: which of the configurations the mesh
/// needs are certified, missing, refuted or inconclusive.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PropertyCoverage {
    /// SPEC ID of the property, e.g. `L4.2.2(cert)`.
    pub property: String,
    /// Every needed configuration has a `Certified`/`CertifiedOutsideDelta` result.
    pub certified: bool,
    /// Configurations with no result in the certificate.
    pub missing: Vec<ConfigKey>,
    /// Configurations whose result is a refutation.
    pub refuted: Vec<ConfigKey>,
    /// Configurations whose result is inconclusive.
    pub inconclusive: Vec<ConfigKey>,
    /// Largest δ among the covering results (`None`: all certified on the whole set).
    pub max_delta: Option<f64>,
    /// The largest proven f64 bound of the covering results (`P4.2.3(cert)`: CERT-f64-rounding's
    /// `phi`; the others: CERT-f64-props' `bound`, meaning per [`f64_bound_statement`]);
    /// `None` when one of them has none.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub f64_bound: Option<f64>,
}

/// Which properties a key kind carries.
pub fn properties_of(key: &ConfigKey) -> &'static [&'static str] {
    match key {
        ConfigKey::Vertex { .. } => &[
            "D4.1.9-lens(cert)",
            "C5.4-at-most-two(cert)",
            "C4.2-nonadjacent-disjoint(cert)",
            "C5.4-at-most-two[sec6.1.3](cert)",
            "C4.2-nonadjacent-disjoint[sec6.1.3](cert)",
        ],
        ConfigKey::Edge { .. } => &["P4.2.1(cert)", "P4.2.3(cert)", "L4.2.3(cert)"],
        ConfigKey::Triangle { .. } => &["L4.2.1(cert)", "L4.2.2(cert)"],
    }
}

/// For each property, whether the certificate covers all `configs_needed` (from
/// [`ConfigKey::all_for`]). Only results of the paper's model count.
pub fn coverage(cert: &Certificate, configs_needed: &[ConfigKey]) -> Vec<PropertyCoverage> {
    let mut props: Vec<&'static str> = Vec::new();
    for k in configs_needed {
        for p in properties_of(k) {
            if !props.contains(p) {
                props.push(p);
            }
        }
    }
    props
        .into_iter()
        .map(|prop| {
            let mut cov = PropertyCoverage {
                property: prop.into(),
                certified: true,
                missing: vec![],
                refuted: vec![],
                inconclusive: vec![],
                max_delta: None,
                f64_bound: None,
            };
            let mut bounds: Vec<Option<f64>> = Vec::new();
            for k in configs_needed
                .iter()
                .filter(|k| properties_of(k).contains(&prop))
            {
                match cert
                    .results
                    .iter()
                    .find(|r| r.key == *k && r.property == prop && cert.model == "paper")
                {
                    None => cov.missing.push(*k),
                    Some(r) => {
                        bounds.push(if prop == "P4.2.3(cert)" {
                            r.f64_rounding.as_ref().and_then(|f| f.phi)
                        } else {
                            r.f64_bound.as_ref().and_then(|b| b.bound)
                        });
                        match r.outcome {
                            Outcome::Certified => {}
                            Outcome::CertifiedOutsideDelta => {
                                cov.max_delta = omax(cov.max_delta, r.delta);
                            }
                            Outcome::Refuted => cov.refuted.push(*k),
                            Outcome::Inconclusive => cov.inconclusive.push(*k),
                        }
                    }
                }
            }
            // A covering result without a bound makes the whole `None` (no claim).
            cov.f64_bound = max_of_all(bounds);
            cov.certified =
                cov.missing.is_empty() && cov.refuted.is_empty() && cov.inconclusive.is_empty();
            cov
        })
        .collect()
}

/// The readable summary: per property, totals and worst numbers; then every refutation.
pub fn summary_table(cert: &Certificate) -> String {
    use std::collections::BTreeMap;
    let mut s = String::new();
    s.push_str(&format!(
        "# Certificate summary: degrees 3..={}, model {}, {} configurations, {} results, wall {:.1} s on {} jobs\n\n",
        cert.max_degree,
        cert.model,
        cert.configs,
        cert.results.len(),
        cert.wall_millis as f64 / 1000.0,
        cert.jobs
    ));
    s.push_str(&format!(
        "Reproduce: `ppm certify --max-degree {} --jobs {} --out certificate_M{}.json.gz --summary CERTIFICATE_SUMMARY_M{}.md` (release build; `.json.gz`: gzip-compressed, `.json`: plain). \"certified\" = proven on the whole stated set (no δ); \"certified outside δ\" = proven at every point farther than δ from the stated boundary; `max bound` = proven whole-domain bound (0 = exact identity); `max centre bound` = interval enclosures by the model's generic maps at box centres (see Statements); `max δ` = the largest δ of the results certified outside δ (a refuted result is decided by its witness and has no δ); `f64 rounding bound` = the proven bound on what the f64 evaluator computes for the property, worst over its configurations: for `P4.2.3(cert)` max |f64 evaluation − exact value| of φ_wu on all of Ω_uw, all labels (CERT-f64-rounding, section below); for the others (CERT-f64-props, section below) `gap` = the f64 cocycle gap (exact 0), `radius` = |f64 radius of φ_wu − exact| near the arc, `margin` = the f64 membership decisions are exact unless a tested quantity lies within it of its threshold (\"decided\": and every round trip and witness decision is certified exact); \"—\" = not bounded (a certificate written before the bound).\n\n",
        cert.max_degree, cert.jobs, cert.max_degree, cert.max_degree
    ));
    s.push_str("| property | configurations | certified | certified outside δ | refuted | inconclusive | max bound | max centre bound | max δ | boxes | max depth | time (s, sum) | f64 rounding bound |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    let mut by: BTreeMap<&str, Vec<&PropertyResult>> = BTreeMap::new();
    for r in &cert.results {
        by.entry(r.property.as_str()).or_default().push(r);
    }
    let fmt = |v: Option<f64>| v.map(|x| format!("{x:.2e}")).unwrap_or_else(|| "—".into());
    for (p, rs) in &by {
        let cnt = |o: Outcome| rs.iter().filter(|r| r.outcome == o).count();
        let mx = |f: &dyn Fn(&PropertyResult) -> Option<f64>| {
            rs.iter()
                .filter_map(|r| f(r))
                .fold(None, |a: Option<f64>, x| {
                    Some(a.map_or(x, |y| crate::report::dev_max(y, x)))
                })
        };
        s.push_str(&format!(
            "| `{p}` | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {:.1} | {} |\n",
            rs.len(),
            cnt(Outcome::Certified),
            cnt(Outcome::CertifiedOutsideDelta),
            cnt(Outcome::Refuted),
            cnt(Outcome::Inconclusive),
            fmt(mx(&|r| r.bound)),
            fmt(mx(&|r| r.centre_bound)),
            fmt(mx(&|r| r.delta_of_partial_proof())),
            rs.iter().map(|r| r.boxes).sum::<u64>(),
            rs.iter().map(|r| r.max_depth).max().unwrap_or(0),
            rs.iter().map(|r| r.millis).sum::<u64>() as f64 / 1000.0,
            if *p == "P4.2.3(cert)" {
                fmt(mx(&|r| r.f64_rounding.as_ref().and_then(|f| f.phi)))
            } else {
                f64_bound_cell(p, rs)
            },
        ));
    }
    s.push_str(&f64_rounding_section(cert));
    s.push_str(&f64_props_section(cert, &by));
    s.push_str(&g_chart_section(cert));
    s.push_str("\n## Per configuration (refutations and non-certified results)\n\n| configuration | property | result | bound | δ | boxes | time (ms) | witness |\n|---|---|---|---|---|---|---|---|\n");
    for r in cert.results.iter().filter(|r| {
        !matches!(
            r.outcome,
            Outcome::Certified | Outcome::CertifiedOutsideDelta
        )
    }) {
        s.push_str(&format!(
            "| {} | `{}` | {:?} | {} | {} | {} | {} | {} |\n",
            r.key,
            r.property,
            r.outcome,
            fmt(r.bound),
            fmt(r.delta_of_partial_proof()),
            r.boxes,
            r.millis,
            r.witness
                .as_ref()
                .map(|w| format!(
                    "{} (f64 confirms: {}, mp256 confirms: {})",
                    w.text, w.f64_confirms, w.mp_confirms
                ))
                .unwrap_or_default()
        ));
    }
    s.push_str("\n## Statements\n\n");
    // In property order, so a merge (which sorts the results) writes the same summary.
    let mut statements: BTreeMap<&str, &str> = BTreeMap::new();
    for r in &cert.results {
        statements
            .entry(r.property.as_str())
            .or_insert(r.statement.as_str());
    }
    for (p, st) in statements {
        s.push_str(&format!("* `{p}`: {st}\n"));
    }
    s
}

/// The CERT-f64-rounding section of the summary: the worst bound of each quantity over the
/// edge configurations, the libm assumption, coverage and cost.
fn f64_rounding_section(cert: &Certificate) -> String {
    let fr: Vec<&F64Rounding> = cert
        .results
        .iter()
        .filter_map(|r| r.f64_rounding.as_ref())
        .collect();
    if fr.is_empty() {
        return String::new();
    }
    let mx = |f: &dyn Fn(&F64Rounding) -> Option<f64>| {
        fr.iter()
            .filter_map(|x| f(x))
            .fold(None, |a: Option<f64>, x| {
                Some(a.map_or(x, |y| crate::report::dev_max(y, x)))
            })
            .map(|x| format!("{x:.2e}"))
            .unwrap_or_else(|| "—".into())
    };
    // Counts absent from older certificates are shown as "—".
    let sum_opt = |f: &dyn Fn(&F64Rounding) -> Option<u64>| {
        let v: Option<Vec<u64>> = fr.iter().map(|x| f(x)).collect();
        v.map(|v| v.iter().sum::<u64>().to_string())
            .unwrap_or_else(|| "—".into())
    };
    let unbounded = fr.iter().filter(|f| f.phi.is_none()).count();
    // The neighbourhood and the pass off it (absent from older certificates: no sentence).
    let outside: Vec<&F64Outside> = fr.iter().filter_map(|f| f.outside.as_ref()).collect();
    let off = if outside.len() == fr.len() {
        let inner = max_of_all(outside.iter().map(|o| o.inner))
            .map(|x| format!("{x:.2e}"))
            .unwrap_or_else(|| "—".into());
        format!(
            " Bounds on the closed ε-neighbourhood of Ω_uw, ε = {}; on the rest of Ω_u (exact answer \"out\") the literal test's f64 answer is \"out\" unless |q|² − r_w² ∈ [0, {inner}] (max over them), boxes decided by value {}, by margin {}, by round trip {}, unresolved {}.",
            mx(&|f| f.nbhd),
            outside.iter().map(|o| o.by_value).sum::<u64>(),
            outside.iter().map(|o| o.by_margin).sum::<u64>(),
            outside.iter().map(|o| o.by_roundtrip).sum::<u64>(),
            outside.iter().map(|o| o.unresolved).sum::<u64>(),
        )
    } else {
        String::new()
    };
    format!(
        "\n## f64 rounding (CERT-f64-rounding)\n\n{} edge configurations; max over them: φ_wu {} (Euclidean), |p|² − r_u² {}, |q|² − r_w² {}, round-trip point {} (the literal test's tolerance ≥ {:.2e}); round trip certified exact on every box: {} (round-trip boxes {}, unresolved {}); g_v alone {}, g_v⁻¹ alone {}; configurations without a bound: {unbounded}; unresolved boxes: {} (max δ {}); boxes: {}; time {:.1} s (sum).{off} The libm {}\n",
        fr.len(),
        mx(&|f| f.phi),
        mx(&|f| Some(f.outer)),
        mx(&|f| f.inner),
        mx(&|f| f.roundtrip),
        fr.iter()
            .map(|f| f.roundtrip_tol)
            .fold(f64::INFINITY, f64::min),
        fr.iter().all(|f| f.roundtrip_exact),
        sum_opt(&|f| f.roundtrip_boxes),
        sum_opt(&|f| f.roundtrip_unresolved),
        mx(&|f| f.g_v),
        mx(&|f| f.g_v_inv),
        fr.iter().map(|f| f.unresolved).sum::<u64>(),
        mx(&|f| f.delta),
        fr.iter().map(|f| f.boxes).sum::<u64>(),
        fr.iter().map(|f| f.millis).sum::<u64>() as f64 / 1000.0,
        crate::numeric::rounding::LIBM_ASSUMPTION,
    ) + &format!("\n* {}\n", f64_rounding_statement())
}

/// The CERT-f64-g-chart section of the summary: the worst bounds over the degrees.
fn g_chart_section(cert: &Certificate) -> String {
    let g: Vec<(u32, &GChartRounding)> = cert
        .results
        .iter()
        .filter_map(|r| match (r.key, r.g_chart.as_ref()) {
            (ConfigKey::Vertex { m }, Some(g)) => Some((m, g)),
            _ => None,
        })
        .collect();
    if g.is_empty() {
        return String::new();
    }
    let worst = |f: &dyn Fn(&GChartRounding) -> Option<f64>| {
        // A degree without a bound makes the maximum "—" (no claim), never a smaller number.
        let all: Option<Vec<(f64, u32)>> = g.iter().map(|(m, x)| f(x).map(|b| (b, *m))).collect();
        all.and_then(worst_with_key)
            .map(|(b, m)| format!("{b:.2e} (m = {m})"))
            .unwrap_or_else(|| "—".into())
    };
    format!(
        "\n## g_v and g_v⁻¹ on the whole chart (CERT-f64-g-chart)\n\n{} degrees; max over them of the proven |f64 − exact| (Euclidean) for every f64 point p ≠ 0 with |x|, |y| ≤ {}: g_v {}, g_v⁻¹ {}; pieces {}, unresolved {}; time {:.1} s (sum). Same libm assumption.\n",
        g.len(),
        g.iter().map(|(_, x)| x.radius).fold(f64::INFINITY, f64::min),
        worst(&|x| x.g_v),
        worst(&|x| x.g_v_inv),
        g.iter().map(|(_, x)| x.boxes).sum::<u64>(),
        g.iter().map(|(_, x)| x.unresolved).sum::<u64>(),
        g.iter().map(|(_, x)| x.millis).sum::<u64>() as f64 / 1000.0,
    )
}

/// The worst CERT-f64-props bound of a property's results: "—" unless every result carries one
/// (a missing bound is no claim, never a smaller number).
fn f64_bound_cell(p: &str, rs: &[&PropertyResult]) -> String {
    let all: Option<Vec<&F64Bound>> = rs.iter().map(|r| r.f64_bound.as_ref()).collect();
    let Some(all) = all else {
        return "—".into();
    };
    let Some(worst) = max_of_all(all.iter().map(|b| b.bound)) else {
        return "—".into();
    };
    let decided = all.iter().all(|b| b.decided == Some(true));
    let what = match p {
        "L4.2.2(cert)" => "gap",
        "L4.2.3(cert)" => "radius",
        _ => "margin",
    };
    let has_decided = all.iter().any(|b| b.decided.is_some());
    format!(
        "{what} {worst:.2e}{}",
        if has_decided && decided {
            ", decided"
        } else {
            ""
        }
    )
}

/// The largest of bounds that must all be present: `None` when one is missing (no claim, never
/// a smaller number) or there are none; a NaN wins (`dev_max`).
fn max_of_all(v: impl IntoIterator<Item = Option<f64>>) -> Option<f64> {
    v.into_iter()
        .collect::<Option<Vec<f64>>>()?
        .into_iter()
        .reduce(crate::report::dev_max)
}

/// The largest value with its key, NaN winning (a NaN bound is no claim, never hidden), ties
/// to the smallest key, so a summary does not depend on the results' order (a merged
/// certificate is sorted, a complete run is not).
fn worst_with_key<K: Ord>(v: impl IntoIterator<Item = (f64, K)>) -> Option<(f64, K)> {
    v.into_iter().reduce(|a, b| {
        if b.0 > a.0 || b.0.is_nan() || (b.0 == a.0 && b.1 < a.1) {
            b
        } else {
            a
        }
    })
}

/// The CERT-f64-props section of the summary: per property the worst bound, the worst
/// Lipschitz constant, results without a bound, and the statement.
fn f64_props_section(
    cert: &Certificate,
    by: &std::collections::BTreeMap<&str, Vec<&PropertyResult>>,
) -> String {
    if !cert.results.iter().any(|r| r.f64_bound.is_some()) {
        return String::new();
    }
    let mut s = String::from("\n## f64 bounds of the properties (CERT-f64-props)\n\nDerived from the per-edge bounds of CERT-f64-rounding (φ(a,b) = `phi` of the edge (a, b) on the ε-neighbourhood of Ω_ab, `outer`, `inner`, the margin off that neighbourhood, `roundtrip_exact`) and the per-degree bounds of CERT-f64-g-chart of this certificate (`certify::attach_f64_bounds`; no box evaluated again), with the Lipschitz constants ‖J(φ_ba)‖ ≤ k_a·max(1, a/6)·max(1, 6/b)/k_b on Ω_ab; u = 2⁻⁵³; same libm assumption.\n\n| property | results | without a bound | max bound (configuration) | max Lipschitz | all decided |\n|---|---|---|---|---|---|\n");
    let e2 = |x: Option<f64>| x.map(|v| format!("{v:.2e}")).unwrap_or_else(|| "—".into());
    let opt_max = |v: Vec<Option<f64>>| -> Option<f64> {
        v.into_iter().flatten().reduce(crate::report::dev_max)
    };
    for (p, rs) in by {
        if *p == "P4.2.3(cert)" || f64_bound_statement(p).is_none() {
            continue;
        }
        let bs: Vec<(&PropertyResult, Option<&F64Bound>)> =
            rs.iter().map(|r| (*r, r.f64_bound.as_ref())).collect();
        let without = bs
            .iter()
            .filter(|(_, b)| b.and_then(|b| b.bound).is_none())
            .count();
        let worst = bs
            .iter()
            .filter_map(|(r, b)| b.and_then(|b| b.bound).map(|v| (v, r.key)));
        let worst = worst_with_key(worst);
        let has_decided = bs
            .iter()
            .any(|(_, b)| b.is_some_and(|b| b.decided.is_some()));
        s.push_str(&format!(
            "| `{p}` | {} | {without} | {} | {} | {} |\n",
            rs.len(),
            worst
                .map(|(v, k)| format!("{v:.2e} ({k})"))
                .unwrap_or_else(|| "—".into()),
            e2(opt_max(
                bs.iter()
                    .map(|(_, b)| b.and_then(|b| b.lipschitz))
                    .collect()
            )),
            if has_decided {
                bs.iter()
                    .all(|(_, b)| b.is_some_and(|b| b.decided == Some(true)))
                    .to_string()
            } else {
                "—".into()
            },
        ));
    }
    s.push('\n');
    for p in by.keys() {
        if let Some(st) = f64_bound_statement(p).filter(|_| *p != "P4.2.3(cert)") {
            s.push_str(&format!("* `{p}`: {st}\n"));
        }
    }
    s
}
