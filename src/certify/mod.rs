//! Issue 6: certified (interval-arithmetic) proofs of the Chapter 4 conditions for every
//! degree configuration up to a bound.
//!
//! The gluing data of Chapter 4 depends only on degrees and labels; after the rotations
//! R_(u,w) (Def. 4.1.8, isometries) an edge depends only on (m_u, m_w), a triangle on
//! (m_u, m_w, m_x, orientation), a star on m_x. [`ConfigKey`] names these configurations;
//! [`run`] proves every property for all keys with degrees 3..=M by branch and bound over
//! polar boxes (θ, r) of the chart (Π⁻¹ is a bijection (−π, π] × (0, r) → disk − {0}, so the
//! boxes cover every point; boxes crossing Π's cut are evaluated as two pieces,
//! [`interval::principal_pieces`]). Interval arithmetic is `inari` (outward rounding).
//!
//! Each result is a certificate (boxes, depth, bound, unresolved boxes and δ) or a
//! refutation with a witness point that the f64 and multi-precision evaluators of
//! `construction::maps` confirm. Exactly what is proven is in [`PropertyResult::statement`].

pub mod cli;
pub mod interval;

use crate::construction::maps::{self, cos_pi_6, is_nonzero, EdgeConfig, Ppm, TriangleConfig, P2};
use crate::construction::scalar::{Iv, Mp, Scalar, Trit};
use crate::report::{CheckResult, Verdict, Witness};
use crate::construction::interval::Interval as I;
use interval::{c, iv, member, member_any, phi_polar, two_pi_frac, Deg, Domain};
use serde::{Deserialize, Serialize};
use std::time::Instant;

// ---------------------------------------------------------------------------------------------
// Models (the paper, and planted faults).
// ---------------------------------------------------------------------------------------------

/// The construction under test: the paper's, or one with a planted fault (issue 6, item 4).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Model {
    /// Added to the radius cos(π/6) of the circles of the Sec. 6.1.3 lens test.
    pub lens_radius_offset: f64,
    /// Added to the label in R_(u,w)⁻¹ (a wrong rotation label in g_(u,w), Def. 4.1.8).
    pub label_shift: i64,
}

impl Model {
    /// The paper's construction, no fault planted.
    pub fn paper() -> Model {
        Model {
            lens_radius_offset: 0.0,
            label_shift: 0,
        }
    }
    /// True when no fault is planted.
    pub fn is_paper(&self) -> bool {
        *self == Model::paper()
    }
    /// `paper`, or `planted(…)` with the fault parameters; recorded in certificates.
    pub fn name(&self) -> String {
        if self.is_paper() {
            "paper".into()
        } else {
            format!(
                "planted(lens_radius_offset={}, label_shift={})",
                self.lens_radius_offset, self.label_shift
            )
        }
    }
    /// Enclosure of the squared lens radius.
    fn lens_r2(&self) -> I {
        if self.lens_radius_offset == 0.0 {
            interval::ratio(3, 4)
        } else {
            (c(3.0).sqrt() / c(2.0) + c(self.lens_radius_offset)).sqr()
        }
    }
}

impl<S: Scalar> Ppm<S> for Model {
    fn in_canonical_lens(&self, q: &P2<S>) -> Trit {
        if self.lens_radius_offset == 0.0 {
            return maps::in_canonical_lens(q);
        }
        let prec = q.prec();
        let rr = cos_pi_6::<S>(prec)
            .add(&S::from_f64(self.lens_radius_offset, prec))
            .sqr();
        let d = P2::new(q.x.sub(&S::from_i64(1, prec)), q.y.clone());
        q.norm2()
            .lt(&rr)
            .and(d.norm2().lt(&rr))
            .and(is_nonzero(q))
            .and(is_nonzero(&d))
    }
    fn r_uw_inv(&self, e: &EdgeConfig, p: &P2<S>) -> P2<S> {
        maps::rotate_frac(p, e.i as i64 + self.label_shift, e.m_u as i64)
    }
}

// ---------------------------------------------------------------------------------------------
// Configurations.
// ---------------------------------------------------------------------------------------------

/// A configuration: everything a Chapter 4 property depends on (issue 6, "Why it is possible").
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum ConfigKey {
    /// A vertex (star) of degree m: lens agreement, at most two overlaps, non-adjacent
    /// disjointness.
    Vertex {
        /// m_x, the degree of the star's centre.
        m: u32,
    },
    /// An oriented edge [u, w] with degrees (m_u, m_w), any labels.
    Edge {
        /// m_u, the degree of u.
        m_u: u32,
        /// m_w, the degree of w.
        m_w: u32,
    },
    /// A triangle [u, w, x] with degrees and orientation of its labels.
    Triangle {
        /// m_u, the degree of u.
        m_u: u32,
        /// m_w, the degree of w.
        m_w: u32,
        /// m_x, the degree of x.
        m_x: u32,
        /// The labels step counterclockwise ([`maps::FanOrientation::Ccw`]).
        ccw: bool,
    },
}

impl std::fmt::Display for ConfigKey {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ConfigKey::Vertex { m } => write!(f, "vertex m={m}"),
            ConfigKey::Edge { m_u, m_w } => write!(f, "edge ({m_u},{m_w})"),
            ConfigKey::Triangle { m_u, m_w, m_x, ccw } => write!(
                f,
                "triangle ({m_u},{m_w},{m_x}) {}",
                if *ccw { "ccw" } else { "cw" }
            ),
        }
    }
}

impl ConfigKey {
    /// Key of an oriented edge (labels do not matter: R_(u,w) conjugates them away).
    pub fn of_edge(e: &EdgeConfig) -> ConfigKey {
        ConfigKey::Edge {
            m_u: e.m_u,
            m_w: e.m_w,
        }
    }
    /// Key of a triangle; errors if its labels are not a fan (Def. 4.1.4).
    pub fn of_triangle(t: &TriangleConfig) -> Result<ConfigKey, maps::ConfigError> {
        let o = t.orientation()?;
        Ok(ConfigKey::Triangle {
            m_u: t.m_u,
            m_w: t.m_w,
            m_x: t.m_x,
            ccw: o == maps::FanOrientation::Ccw,
        })
    }
    /// Key of a vertex (star) of degree m.
    pub fn of_vertex(m: u32) -> ConfigKey {
        ConfigKey::Vertex { m }
    }
    /// Every configuration a mesh needs: vertices by degree, both orientations of each edge,
    /// and each triangle read from each of its three vertices (all three rotations).
    pub fn all_for(
        degrees: &[u32],
        edges: &[EdgeConfig],
        triangles: &[TriangleConfig],
    ) -> Result<Vec<ConfigKey>, maps::ConfigError> {
        let mut v: Vec<ConfigKey> = degrees.iter().map(|&m| ConfigKey::of_vertex(m)).collect();
        for e in edges {
            v.push(ConfigKey::of_edge(e));
            v.push(ConfigKey::of_edge(&e.reversed()));
        }
        for t in triangles {
            let k = ConfigKey::of_triangle(t)?;
            if let ConfigKey::Triangle { m_u, m_w, m_x, ccw } = k {
                v.push(k);
                v.push(ConfigKey::Triangle {
                    m_u: m_w,
                    m_w: m_x,
                    m_x: m_u,
                    ccw,
                });
                v.push(ConfigKey::Triangle {
                    m_u: m_x,
                    m_w: m_u,
                    m_x: m_w,
                    ccw,
                });
            }
        }
        v.sort();
        v.dedup();
        Ok(v)
    }
    /// The canonical triangle of this key (labels 0/±1).
    fn triangle(&self) -> Option<TriangleConfig> {
        match *self {
            ConfigKey::Triangle { m_u, m_w, m_x, ccw } => {
                if ccw {
                    TriangleConfig::ccw(m_u, m_w, m_x, 0, 0, 0).ok()
                } else {
                    TriangleConfig::new(m_u, m_w, m_x, 0, m_u - 1, 0, 1, 1, 0).ok()
                }
            }
            _ => None,
        }
    }
}

/// All configurations with degrees in 3..=max_degree, in a fixed order.
pub fn all_configs(max_degree: u32) -> Vec<ConfigKey> {
    let ms: Vec<u32> = (maps::MIN_DEGREE..=max_degree).collect();
    let mut v: Vec<ConfigKey> = ms.iter().map(|&m| ConfigKey::Vertex { m }).collect();
    for &a in &ms {
        for &b in &ms {
            v.push(ConfigKey::Edge { m_u: a, m_w: b });
        }
    }
    for &a in &ms {
        for &b in &ms {
            for &x in &ms {
                for ccw in [true, false] {
                    v.push(ConfigKey::Triangle {
                        m_u: a,
                        m_w: b,
                        m_x: x,
                        ccw,
                    });
                }
            }
        }
    }
    v
}

/// Shard `k` of `n` (1-based): every n-th configuration starting at k − 1.
pub fn shard(configs: &[ConfigKey], k: usize, n: usize) -> Vec<ConfigKey> {
    configs
        .iter()
        .enumerate()
        .filter(|(i, _)| n > 0 && i % n == k.saturating_sub(1))
        .map(|(_, c)| *c)
        .collect()
}

// ---------------------------------------------------------------------------------------------
// Results and certificates.
// ---------------------------------------------------------------------------------------------

/// Outcome of one prover run.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Outcome {
    /// Proven on the whole stated set (no unresolved boxes).
    Certified,
    /// Proven outside the unresolved boxes (their number and δ reported).
    CertifiedOutsideDelta,
    /// A counterexample box was found.
    Refuted,
    /// Neither (budget exhausted away from a tight boundary).
    Inconclusive,
}

/// A counterexample: the centre of a box on which the property fails for every point.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CertWitness {
    /// The point, in the chart named by `text`.
    pub point: [f64; 2],
    /// The point, its chart and what fails there.
    pub text: String,
    /// The f64 evaluator of `construction::maps` confirms the failure at `point`.
    pub f64_confirms: bool,
    /// The MPFR (256-bit) evaluator confirms it.
    pub mp_confirms: bool,
}

/// The result of one property for one configuration.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PropertyResult {
    /// The configuration.
    pub key: ConfigKey,
    /// SPEC ID, e.g. `L4.2.2(cert)`.
    pub property: String,
    /// How the proof ended (certified, possibly outside δ; refuted; inconclusive).
    pub outcome: Outcome,
    /// What exactly was proven (or refuted).
    pub statement: String,
    /// Proven bound (meaning in `statement`), if any.
    pub bound: Option<f64>,
    /// Tight bound at box centres (point intervals), if measured.
    pub centre_bound: Option<f64>,
    /// δ: the largest diameter (in the chart) of an unresolved box.
    pub delta: Option<f64>,
    /// Boxes evaluated by branch and bound.
    pub boxes: u64,
    /// Deepest subdivision level reached.
    pub max_depth: u32,
    /// Boxes left undecided: at the maximum depth, or pending when the box budget ran out.
    pub unresolved: u64,
    /// The counterexample, when refuted.
    pub witness: Option<CertWitness>,
    /// Time spent proving this result, in ms.
    pub millis: u64,
}

impl PropertyResult {
    /// As a report row.
    pub fn to_check_result(&self) -> CheckResult {
        let verdict = match self.outcome {
            Outcome::Certified => Verdict::Holds,
            Outcome::CertifiedOutsideDelta => Verdict::HoldsRestricted {
                domain: format!(
                    "outside {} unresolved boxes of diameter ≤ {:.1e}",
                    self.unresolved,
                    self.delta.unwrap_or(0.0)
                ),
            },
            Outcome::Refuted => Verdict::Fails,
            Outcome::Inconclusive => Verdict::Skipped {
                reason: "prover budget exhausted".into(),
            },
        };
        let witnesses = self
            .witness
            .iter()
            .map(|w| {
                Witness::new(
                    w.text.clone(),
                    serde_json::json!({"point": w.point, "f64": w.f64_confirms, "mp": w.mp_confirms}),
                )
            })
            .collect::<Vec<_>>();
        CheckResult {
            id: self.property.clone(),
            name: format!("{} [{}]", self.statement, self.key),
            verdict,
            offenders: witnesses.len() as u64,
            witnesses,
            examined: self.boxes,
            seed: None,
            worst_deviation: self.bound,
            tolerance: self.delta,
            note: self.statement.clone(),
        }
    }
}

/// A certificate file: all results of one run (or a merge of shards).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Certificate {
    /// File format tag, `pseudomanifold-certificate/1`.
    pub format: String,
    /// M: every configuration with degrees 3..=M is in scope.
    pub max_degree: u32,
    /// [`Model::name`] of the construction proven.
    pub model: String,
    /// `(k, n)` for a shard, `None` for a complete run or a merge.
    pub shard: Option<(usize, usize)>,
    /// Number of configurations proven (summed over the shards of a merge).
    pub configs: usize,
    /// One result per (configuration, property).
    pub results: Vec<PropertyResult>,
    /// Wall-clock time of the run, in ms (the largest shard's for a merge).
    pub wall_millis: u64,
    /// Worker threads used (the first shard's for a merge).
    pub jobs: usize,
    /// Statements shared by many results, by property: a result whose `statement` is empty
    /// in the file has this one ([`Certificate::compact`], [`Certificate::expand`]).
    #[serde(default, skip_serializing_if = "std::collections::BTreeMap::is_empty")]
    pub statements: std::collections::BTreeMap<String, String>,
}

impl Certificate {
    /// Move each property's most common statement into `statements` and clear it in the
    /// results that share it (the file format; statements are long, results many).
    pub fn compact(&mut self) {
        use std::collections::BTreeMap;
        let mut counts: BTreeMap<(&str, &str), usize> = BTreeMap::new();
        for r in &self.results {
            *counts.entry((&r.property, &r.statement)).or_default() += 1;
        }
        let mut best: BTreeMap<String, (usize, String)> = BTreeMap::new();
        for ((p, st), n) in counts {
            let e = best.entry(p.to_string()).or_insert((0, String::new()));
            if n > e.0 {
                *e = (n, st.to_string());
            }
        }
        for r in &mut self.results {
            if best
                .get(&r.property)
                .is_some_and(|(_, st)| *st == r.statement)
            {
                r.statement.clear();
            }
        }
        self.statements
            .extend(best.into_iter().map(|(p, (_, st))| (p, st)));
    }
    /// Undo [`Certificate::compact`]: fill empty statements from `statements`.
    pub fn expand(&mut self) {
        for r in &mut self.results {
            if r.statement.is_empty() {
                if let Some(st) = self.statements.get(&r.property) {
                    r.statement = st.clone();
                }
            }
        }
    }
}

/// Errors of the certificate tools.
#[derive(Debug, thiserror::Error)]
pub enum CertifyError {
    /// A certificate or summary file could not be read or written.
    #[error("I/O error on {path}: {source}")]
    Io {
        /// The file.
        path: String,
        /// The underlying I/O error.
        source: std::io::Error,
    },
    /// A certificate file is not valid certificate JSON (or a certificate could not be serialised).
    #[error("malformed certificate {path}: {source}")]
    Json {
        /// The file.
        path: String,
        /// The JSON error.
        source: serde_json::Error,
    },
    /// Certificates to merge disagree (max degree, model), overlap, or none was given.
    #[error("certificates do not fit together: {0}")]
    Mismatch(String),
    /// An invalid command-line value (`--shard`, `--max-degree`) or thread-pool setup failure.
    #[error("bad argument: {0}")]
    BadArg(String),
}

// ---------------------------------------------------------------------------------------------
// Branch and bound over polar boxes.
// ---------------------------------------------------------------------------------------------

/// A box [θ0, θ1] × [r0, r1] of polar coordinates in a chart.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PBox {
    /// [θ0, θ1].
    pub th: (f64, f64),
    /// [r0, r1].
    pub r: (f64, f64),
}

impl PBox {
    fn ith(&self) -> I {
        iv(self.th.0, self.th.1)
    }
    fn ir(&self) -> I {
        iv(self.r.0, self.r.1)
    }
    fn mid(&self) -> (f64, f64) {
        (0.5 * (self.th.0 + self.th.1), 0.5 * (self.r.0 + self.r.1))
    }
    /// Diameter bound in the chart: r1·Δθ + Δr.
    fn diam(&self) -> f64 {
        self.r.1 * (self.th.1 - self.th.0) + (self.r.1 - self.r.0)
    }
    fn split(&self) -> [PBox; 2] {
        let (t, r) = self.mid();
        if self.r.1 * (self.th.1 - self.th.0) >= self.r.1 - self.r.0 {
            [
                PBox {
                    th: (self.th.0, t),
                    r: self.r,
                },
                PBox {
                    th: (t, self.th.1),
                    r: self.r,
                },
            ]
        } else {
            [
                PBox {
                    th: self.th,
                    r: (self.r.0, r),
                },
                PBox {
                    th: self.th,
                    r: (r, self.r.1),
                },
            ]
        }
    }
    /// Cartesian centre (f64).
    fn centre_xy(&self) -> [f64; 2] {
        let (t, r) = self.mid();
        [r * t.cos(), r * t.sin()]
    }
}

/// The exact case analysis of [`prove_triangle`] on a box.
enum Exact {
    /// No point of the box is in Ω_ux ∩ φ_xu⁻¹(Ω_xw).
    Empty,
    /// On the box, Ω_ux ∩ φ_xu⁻¹(Ω_xw) = Ω_ux ∩ Ω_uw and the cocycle identity is exact.
    Equal,
    Undecided,
}

/// What a classifier says about a box.
enum Leaf {
    /// The property holds on the box; optional bounds (whole box, centre).
    Proven(Option<f64>, Option<f64>),
    /// The property fails at every point of the box.
    Refuted(String),
    Split,
}

#[derive(Debug, Default)]
struct Stats {
    boxes: u64,
    max_depth: u32,
    unresolved: u64,
    delta: f64,
    bound: Option<f64>,
    centre: Option<f64>,
    refuted: Option<(PBox, String)>,
    budget_hit: bool,
}

fn omax(a: Option<f64>, b: Option<f64>) -> Option<f64> {
    match (a, b) {
        (Some(x), Some(y)) => Some(x.max(y)),
        (x, None) => x,
        (None, y) => y,
    }
}

/// Depth-first branch and bound; stops at the first refutation.
fn bnb(root: PBox, max_depth: u32, budget: u64, mut f: impl FnMut(&PBox) -> Leaf) -> Stats {
    let mut st = Stats::default();
    let mut stack = vec![(root, 0u32)];
    while let Some((b, d)) = stack.pop() {
        st.boxes += 1;
        st.max_depth = st.max_depth.max(d);
        if st.boxes > budget {
            st.budget_hit = true;
            st.unresolved += 1 + stack.len() as u64;
            st.delta = st.delta.max(b.diam());
            for (s, _) in &stack {
                st.delta = st.delta.max(s.diam());
            }
            break;
        }
        match f(&b) {
            Leaf::Proven(bd, cb) => {
                st.bound = omax(st.bound, bd);
                st.centre = omax(st.centre, cb);
            }
            Leaf::Refuted(s) => {
                st.refuted = Some((b, s));
                break;
            }
            Leaf::Split => {
                if d >= max_depth {
                    st.unresolved += 1;
                    st.delta = st.delta.max(b.diam());
                } else {
                    let [a, c2] = b.split();
                    stack.push((c2, d + 1));
                    stack.push((a, d + 1));
                }
            }
        }
    }
    st
}

/// Prover settings.
#[derive(Debug, Clone, Copy, Serialize, Deserialize)]
pub struct Settings {
    /// Maximum bisection depth (boxes at this depth that are still undecided are reported
    /// as unresolved; δ is their largest diameter).
    pub max_depth: u32,
    /// Maximum boxes per prover run.
    pub budget: u64,
    /// A composite deviating from the identity by more than this at a box centre refutes.
    pub fail_tol: f64,
    /// Boxes on which an identity is proven exactly are still split down to this diameter,
    /// so that the model's generic maps are cross-checked at a grid of centres of this
    /// spacing (the link between the model and the closed forms; catches planted faults).
    #[serde(default = "default_check_diam")]
    pub check_diam: f64,
}

fn default_check_diam() -> f64 {
    0.2
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            max_depth: 26,
            budget: 400_000,
            fail_tol: 1e-9,
            check_diam: default_check_diam(),
        }
    }
}

fn disk_box(m: u32) -> PBox {
    PBox {
        th: (-std::f64::consts::PI, std::f64::consts::PI),
        r: (0.0, Deg::new(m).rm.sup()),
    }
}

fn finish(
    key: ConfigKey,
    property: &str,
    statement: String,
    st: Stats,
    witness: Option<CertWitness>,
    t0: Instant,
) -> PropertyResult {
    let outcome = if st.refuted.is_some() {
        Outcome::Refuted
    } else if st.unresolved == 0 {
        Outcome::Certified
    } else if st.budget_hit {
        Outcome::Inconclusive
    } else {
        Outcome::CertifiedOutsideDelta
    };
    PropertyResult {
        key,
        property: property.into(),
        outcome,
        statement,
        bound: st.bound,
        centre_bound: st.centre,
        delta: if st.unresolved > 0 {
            Some(st.delta)
        } else {
            None
        },
        boxes: st.boxes,
        max_depth: st.max_depth,
        unresolved: st.unresolved,
        witness,
        millis: t0.elapsed().as_millis() as u64,
    }
}

const MP_PREC: u32 = 256;

/// Canonical edge (labels 0) of degrees (m_u, m_w).
fn canon_edge(m_u: u32, m_w: u32) -> EdgeConfig {
    EdgeConfig {
        m_u,
        i: 0,
        m_w,
        j: 0,
    }
}

// ---------------------------------------------------------------------------------------------
// Vertex provers.
// ---------------------------------------------------------------------------------------------

/// D4.1.9-lens(cert): for every point p of Ω_u, the Sec. 6.1.3 lens test agrees with the
/// literal Def. 4.1.9 (for every m_w: the closed form does not depend on it).
pub fn prove_lens_agreement(m: u32, model: &Model, s: &Settings) -> PropertyResult {
    let t0 = Instant::now();
    let d = Deg::new(m);
    let lens = Domain::Lens {
        r2: model.lens_r2(),
    };
    let paper_lens = model.lens_radius_offset == 0.0;
    let st = bnb(disk_box(m), s.max_depth, s.budget, |b| {
        let (th, r) = (b.ith(), b.ir());
        let lit = member_any(&d, th, r, Domain::Literal);
        if paper_lens {
            // With the paper's radius, lens ≡ (r>0 ∧ |b−(1,0)|²<3/4 ∧ r<r_u) exactly
            // (|b|² < 3/4 ⇔ r < r_u), and literal = lens ∧ winding0: agreement ⇔ lens ⇒ winding0.
            let l = member_any(&d, th, r, lens);
            let w = interval::all_pieces(
                &interval::principal_pieces(th)
                    .into_iter()
                    .map(|p| d.winding0(p))
                    .collect::<Vec<_>>(),
            );
            if l.is_false() || w.is_true() {
                return Leaf::Proven(None, None);
            }
            if l.is_true() && w.is_false() {
                return Leaf::Refuted("lens test True, literal Def. 4.1.9 False".into());
            }
            return Leaf::Split;
        }
        let l = member_any(&d, th, r, lens);
        match (lit, l) {
            (Trit::True, Trit::True) | (Trit::False, Trit::False) => Leaf::Proven(None, None),
            (Trit::True, Trit::False) => {
                Leaf::Refuted("literal Def. 4.1.9 True, lens test False".into())
            }
            (Trit::False, Trit::True) => {
                Leaf::Refuted("lens test True, literal Def. 4.1.9 False".into())
            }
            _ => Leaf::Split,
        }
    });
    let witness = st.refuted.as_ref().map(|(b, txt)| {
        let p = b.centre_xy();
        let e = canon_edge(m, m);
        let f = model.in_omega_uw_literal(&e, &P2::<f64>::new(p[0], p[1]))
            != model.in_omega_uw_lens(&e, &P2::<f64>::new(p[0], p[1]));
        let pm = P2::<Mp>::from_f64(p[0], p[1], MP_PREC);
        let g = model.in_omega_uw_literal(&e, &pm) != model.in_omega_uw_lens(&e, &pm);
        CertWitness {
            point: p,
            text: format!(
                "p = ({:.9}, {:.9}) in u's chart with s_u(w) at label 0 (m_u = {m}): {txt}",
                p[0], p[1]
            ),
            f64_confirms: f,
            mp_confirms: g,
        }
    });
    finish(
        ConfigKey::Vertex { m },
        "D4.1.9-lens(cert)",
        format!(
            "for all p ∈ Ω_u (m_u = {m}), any m_w: [h∘g_u∘R_(u,w)(p) ∈ E (Sec. 6.1.3, lens radius {})] ⇔ [p ∈ Ω_uw, Def. 4.1.9]",
            if paper_lens { "cos(π/6)".to_string() } else { format!("cos(π/6){:+e}", model.lens_radius_offset) }
        ),
        st,
        witness,
        t0,
    )
}

/// C5.4-at-most-two(cert) / C4.2-nonadjacent-disjoint(cert) and their Sec. 6.1.3 variants:
/// for every p ∈ Ω_x (degree m), with Ω_xk the gluing domain of the neighbour at label k.
pub fn prove_star(
    m: u32,
    use_lens: bool,
    nonadjacent: bool,
    model: &Model,
    s: &Settings,
) -> PropertyResult {
    let t0 = Instant::now();
    let d = Deg::new(m);
    let dom = if use_lens {
        Domain::Lens {
            r2: model.lens_r2(),
        }
    } else {
        Domain::Literal
    };
    let adjacent = |a: usize, b: usize| {
        let diff = (a as i64 - b as i64).rem_euclid(m as i64);
        diff == 1 || diff == m as i64 - 1
    };
    let shifts: Vec<I> = (0..m).map(|k| two_pi_frac(k as i64, m as i64)).collect();
    let st = bnb(disk_box(m), s.max_depth, s.budget, |b| {
        let (th, r) = (b.ith(), b.ir());
        let ts: Vec<Trit> = shifts
            .iter()
            .map(|sh| member_any(&d, th - *sh, r, dom))
            .collect();
        let maybe: Vec<usize> = (0..ts.len()).filter(|&k| !ts[k].is_false()).collect();
        let sure: Vec<usize> = (0..ts.len()).filter(|&k| ts[k].is_true()).collect();
        if nonadjacent {
            let bad_maybe = maybe
                .iter()
                .any(|&a| maybe.iter().any(|&c2| a != c2 && !adjacent(a, c2)));
            if !bad_maybe {
                return Leaf::Proven(None, None);
            }
            for &a in &sure {
                for &c2 in &sure {
                    if a != c2 && !adjacent(a, c2) {
                        return Leaf::Refuted(format!("p ∈ Ω_x{a} ∩ Ω_x{c2}, labels not adjacent"));
                    }
                }
            }
            Leaf::Split
        } else if maybe.len() <= 2 {
            Leaf::Proven(None, None)
        } else if sure.len() >= 3 {
            Leaf::Refuted(format!(
                "p lies in {} gluing domains, labels {:?}",
                sure.len(),
                sure
            ))
        } else {
            Leaf::Split
        }
    });
    let witness = st.refuted.as_ref().map(|(b, txt)| {
        let p = b.centre_xy();
        let count = |f64side: bool| -> Vec<u32> {
            (0..m)
                .filter(|&k| {
                    let e = EdgeConfig {
                        m_u: m,
                        i: k,
                        m_w: m,
                        j: 0,
                    };
                    let t = if f64side {
                        let q = P2::<f64>::new(p[0], p[1]);
                        if use_lens {
                            model.in_omega_uw_lens(&e, &q)
                        } else {
                            model.in_omega_uw_literal(&e, &q)
                        }
                    } else {
                        let q = P2::<Mp>::from_f64(p[0], p[1], MP_PREC);
                        if use_lens {
                            model.in_omega_uw_lens(&e, &q)
                        } else {
                            model.in_omega_uw_literal(&e, &q)
                        }
                    };
                    t.is_true()
                })
                .collect()
        };
        let ok = |ks: &[u32]| {
            if nonadjacent {
                ks.iter().any(|&a| {
                    ks.iter()
                        .any(|&c2| a != c2 && !adjacent(a as usize, c2 as usize))
                })
            } else {
                ks.len() >= 3
            }
        };
        let (kf, km) = (count(true), count(false));
        CertWitness {
            point: p,
            text: format!(
                "p = ({:.9}, {:.9}) in x's chart (m_x = {m}): {txt}; f64 finds labels {kf:?}",
                p[0], p[1]
            ),
            f64_confirms: ok(&kf),
            mp_confirms: ok(&km),
        }
    });
    let sfx = if use_lens { "[sec6.1.3]" } else { "" };
    let (id, stmt) = if nonadjacent {
        (
            format!("C4.2-nonadjacent-disjoint{sfx}(cert)"),
            format!(
                "Ω_xa ∩ Ω_xb = ∅ for all labels a, b not adjacent mod {m}{}",
                if use_lens {
                    " (Sec. 6.1.3 lens domains)"
                } else {
                    " (Def. 4.1.9)"
                }
            ),
        )
    } else {
        (
            format!("C5.4-at-most-two{sfx}(cert)"),
            format!(
                "every p ∈ Ω_x (m_x = {m}) lies in at most two Ω_xk{}",
                if use_lens {
                    " (Sec. 6.1.3 lens domains)"
                } else {
                    " (Def. 4.1.9)"
                }
            ),
        )
    };
    finish(ConfigKey::Vertex { m }, &id, stmt, st, witness, t0)
}

// ---------------------------------------------------------------------------------------------
// Edge provers.
// ---------------------------------------------------------------------------------------------

fn iv_point(p: [f64; 2]) -> P2<Iv> {
    P2::new(Iv::point(p[0]), Iv::point(p[1]))
}

/// Enclosure (sup) of |g_(w,u)(g_(u,w)(p)) − p| by the generic maps on point intervals.
fn roundtrip_dev<S: Scalar>(model: &Model, e: &EdgeConfig, p: &P2<S>) -> Option<S>
where
    Model: Ppm<S>,
{
    let q = model.g_uw_formula(e, p).ok()?;
    let back = model.g_uw_formula(&e.reversed(), &q).ok()?;
    Some(back.sub(p).norm2().sqrt())
}

/// L4.2.1 violated at p (u's chart): p ∈ Ω_ux, φ_xu(p) ∈ Ω_xw, but p ∉ Ω_uw. One generic
/// evaluation, used to confirm a witness in f64 and in MPFR.
fn inclusion_violated<S: Scalar>(
    model: &Model,
    uw: &EdgeConfig,
    ux: &EdgeConfig,
    xw: &EdgeConfig,
    p: &P2<S>,
) -> bool
where
    Model: Ppm<S>,
{
    model.in_omega_uw_literal(ux, p).is_true()
        && model
            .g_uw_formula(ux, p)
            .map(|q| model.in_omega_uw_literal(xw, &q).is_true())
            .unwrap_or(false)
        && model.in_omega_uw_literal(uw, p).is_false()
}

/// |φ_wu(p) − φ_wx(φ_xu(p))| (L4.2.2) by the model's maps, ∞ where either side is undefined.
fn cocycle_gap<S: Scalar>(
    model: &Model,
    uw: &EdgeConfig,
    ux: &EdgeConfig,
    xw: &EdgeConfig,
    p: &P2<S>,
) -> f64
where
    Model: Ppm<S>,
{
    let gap = || -> Option<f64> {
        let l = model.g_uw_formula(uw, p).ok()?;
        let r = model
            .g_uw_formula(xw, &model.g_uw_formula(ux, p).ok()?)
            .ok()?;
        Some(l.dist_f64(&r))
    };
    gap().unwrap_or(f64::INFINITY)
}

/// P4.2.1(cert): Ω_uw ≠ ∅ and Ω_wu ≠ ∅ (Def. 3.4.1(2)), by a certified interior point of each.
pub fn prove_nonempty(m_u: u32, m_w: u32, model: &Model) -> PropertyResult {
    let t0 = Instant::now();
    let mut st = Stats::default();
    let mut witness = None;
    for (a, b) in [(m_u, m_w), (m_w, m_u)] {
        let d = Deg::new(a);
        // The preimage of the lens centre (1/2, 0): θ = 0, ρ = 1/2.
        let r = c(0.5) / d.k;
        let rp = r.mid();
        let t = member_any(&d, c(0.0), c(rp), Domain::Literal);
        st.boxes += 1;
        let e = canon_edge(a, b);
        let f = model.in_omega_uw_literal(&e, &P2::<f64>::new(rp, 0.0));
        if !t.is_true() || !f.is_true() {
            witness = Some(CertWitness {
                point: [rp, 0.0],
                text: format!("p = ({rp:.9}, 0) for edge ({a},{b}): closed form {t:?}, model's literal test (f64) {f:?}"),
                f64_confirms: !f.is_true(),
                mp_confirms: !model.in_omega_uw_literal(&e, &P2::<Mp>::from_f64(rp, 0.0, MP_PREC)).is_true(),
            });
            st.refuted = Some((disk_box(a), String::new()));
        }
    }
    finish(
        ConfigKey::Edge { m_u, m_w },
        "P4.2.1(cert)",
        "Ω_uw ≠ ∅ and Ω_wu ≠ ∅: the point R_(u,w)⁻¹(ρ=1/2 preimage of the lens centre) is certified in Ω_uw (closed form) and accepted by the literal f64 test, both directions".into(),
        st,
        witness,
        t0,
    )
}

/// P4.2.3(cert): φ_uw∘φ_wu = id on Ω_uw (Def. 3.4.1(3b)), exactly, on all of Ω_uw.
///
/// Proof. Let p have principal angle θ (relative to s_u(w), after R_(u,w)) and radius r,
/// b = g_u(R_(u,w)p) = ρe^{iα} (α = m_uθ/6, ρ = k_u r), c = h(b) = 1 − b. On a box where
/// (i) θ lies in one principal piece, (ii) winding(θ) = 0, i.e. |α| < π, and (iii) c_x > 0,
/// every point satisfies: Π(c) = (β, s) with |β| < π/2, so q = φ_wu(p) has principal angle
/// 6β/m_w (|6β/m_w| < π) and radius s/k_w relative to s_w(u); q ∈ Ω_wu (closed form: |β| < π,
/// s < √3/2 since b ∈ D, |c − 1| = |b| < √3/2); g_w∘R_(w,u)(q) = s e^{iβ} = c exactly (the
/// scalings m_w/6·6/m_w and k_w/k_w cancel), h(c) = b, and Π(b) = (α, ρ) because |α| < π, so
/// φ_uw(q) = R_(u,w)⁻¹Π⁻¹(6α/m_u, ρ/k_u) = p. The prover certifies (i)–(iii) by intervals on
/// every box of u's chart that meets Ω_uw (closed form of Def. 4.1.9, module `interval`), so
/// the deviation is exactly 0 on all of Ω_uw: `bound` = 0, no δ. `centre_bound` is the
/// enclosure of |φ_uw∘φ_wu(p) − p| computed by the model's generic maps (`construction::maps`)
/// at every box centre in Ω_uw; it ties the model to the closed form (a planted fault in the
/// model is refuted there) and measures the evaluator's rounding, not the mathematics.
pub fn prove_inverse(m_u: u32, m_w: u32, model: &Model, s: &Settings) -> PropertyResult {
    let t0 = Instant::now();
    let (du, dw) = (Deg::new(m_u), Deg::new(m_w));
    let e = canon_edge(m_u, m_w);
    let st = bnb(disk_box(m_u), s.max_depth, s.budget, |b| {
        let (th, r) = (b.ith(), b.ir());
        if member_any(&du, th, r, Domain::Literal).is_false() {
            return Leaf::Proven(None, None);
        }
        let pieces = interval::principal_pieces(th);
        if pieces.len() != 1
            || !du.winding0(pieces[0]).is_true()
            || phi_polar(&du, &dw, pieces[0], r).is_none()
        {
            return Leaf::Split;
        }
        // (i)–(iii) hold on the box: the identity is exact there.
        if b.diam() > s.check_diam {
            return Leaf::Split;
        }
        let (tm, rm) = b.mid();
        let mut cb = None;
        if member_any(&du, c(tm), c(rm), Domain::Literal).is_true() {
            match roundtrip_dev(model, &e, &iv_point(b.centre_xy())) {
                Some(dv) if dv.inf() > s.fail_tol => {
                    return Leaf::Refuted(format!("|φ_uw(φ_wu(p)) − p| ≥ {:.3e}", dv.inf()))
                }
                Some(dv) => cb = Some(dv.sup()),
                None => return Leaf::Split,
            }
        }
        Leaf::Proven(Some(0.0), cb)
    });
    let witness = st.refuted.as_ref().map(|(b, txt)| {
        let p = b.centre_xy();
        let f = roundtrip_dev(model, &e, &P2::<f64>::new(p[0], p[1]))
            .map(|v| v > s.fail_tol)
            .unwrap_or(true);
        let g = roundtrip_dev(model, &e, &P2::<Mp>::from_f64(p[0], p[1], MP_PREC))
            .map(|v| v.to_f64() > s.fail_tol)
            .unwrap_or(true);
        CertWitness {
            point: p,
            text: format!(
                "p = ({:.9}, {:.9}) ∈ Ω_uw, edge ({m_u},{m_w}), labels 0: {txt}",
                p[0], p[1]
            ),
            f64_confirms: f,
            mp_confirms: g,
        }
    });
    finish(
        ConfigKey::Edge { m_u, m_w },
        "P4.2.3(cert)",
        "φ_uw∘φ_wu = id on all of Ω_uw, exactly: on every box of u's chart meeting Ω_uw the branch conditions (one principal piece, winding 0, c_x > 0) are certified by intervals, and under them the round trip is the identity by exact cancellation (proof at `certify::prove_inverse`); `bound` = 0 is the proven whole-domain bound; `centre_bound` = max interval enclosure of |φ_uw∘φ_wu(p) − p| by the model's generic maps at every box centre in Ω_uw (evaluator rounding; a larger value refutes)".into(),
        st,
        witness,
        t0,
    )
}

/// L4.2.3(cert), Hausdorff condition (4): the inner boundary arc of Ω_uw (the arc of ∂Ω_uw
/// inside Ω_u, i.e. b = g_u∘R_(u,w)(p) on ∂D ∩ int C, c = h(b) = (√3/2)(cos t, sin t),
/// cos t > 1/√3) is mapped by g_(u,w) onto ∂Ω_w. Proven on t-intervals covering
/// |t| ≤ acos(1/√3) − δ: the branch conditions hold (c_x > 0, |6t/m_w| < π, |b| < √3/2
/// with a certified margin), so |g_(u,w)(p)| = (√3/2)/k_w = cos(π/m_w) exactly; `bound` is the
/// interval enclosure of ||g_(u,w)(p)| − r_w| at the t-box centres via the generic maps, and the
/// separation distance is the certified margin min(√3/2 − |b|) (the arc stays that far inside
/// Ω_u's image), which gives the ball radii of the proof of L4.2.3.
pub fn prove_hausdorff(m_u: u32, m_w: u32, model: &Model, s: &Settings) -> PropertyResult {
    let t0 = Instant::now();
    let dw = Deg::new(m_w);
    let e = canon_edge(m_u, m_w);
    let s3h = c(3.0).sqrt() / c(2.0);
    let tmax = (c(1.0) / c(3.0).sqrt()).acos().inf();
    let delta = 1e-9;
    let n = 256usize;
    let mut st = Stats::default();
    let mut sep = f64::INFINITY;
    let mut worst: f64 = 0.0;
    let lo = -tmax + delta;
    let h = 2.0 * (tmax - delta) / n as f64;
    let mut refuted = None;
    for k in 0..n {
        st.boxes += 1;
        let t = iv(lo + h * k as f64, lo + h * (k + 1) as f64);
        let cx = s3h * t.cos();
        let cy = s3h * t.sin();
        let bx = c(1.0) - cx;
        let by = -cy;
        let bnorm = (bx.sqr() + by.sqr()).sqrt();
        let margin = (s3h - bnorm).inf();
        let branch = cx.inf() > 0.0 && (dw.six_m * t).abs().sup() < I::PI.inf() && margin > 0.0;
        if !branch {
            st.unresolved += 1;
            continue;
        }
        sep = sep.min(margin);
        // Centre point p = (g_u∘R)⁻¹(b) via the generic stated inverse, then g_(u,w).
        let tm = t.mid();
        let bpt = P2::<Iv>::new(Iv(c(1.0) - s3h * c(tm).cos()), Iv(-(s3h * c(tm).sin())));
        let p = match model.g_v_inv(m_u, &bpt) {
            Ok(p) => p,
            Err(_) => {
                st.unresolved += 1;
                continue;
            }
        };
        let q = match model.g_uw_formula(&e, &p) {
            Ok(q) => q,
            Err(_) => {
                st.unresolved += 1;
                continue;
            }
        };
        let dev = Iv(q.norm2().0.sqrt() - dw.rm).abs();
        if dev.inf() > s.fail_tol {
            let pf = [p.x.to_f64(), p.y.to_f64()];
            refuted = Some((
                pf,
                format!(
                    "arc point p = ({:.9}, {:.9}): ||g_(u,w)(p)| − cos(π/m_w)| ≥ {:.3e}",
                    pf[0],
                    pf[1],
                    dev.inf()
                ),
            ));
            break;
        }
        worst = worst.max(dev.sup());
    }
    st.bound = Some(worst);
    st.centre = if sep.is_finite() { Some(sep) } else { None };
    st.delta = delta;
    let witness = refuted.map(|(pf, txt)| {
        let chk = |v: f64| (v - dw.rm.mid()).abs() > s.fail_tol;
        let f = model
            .g_uw_formula(&e, &P2::<f64>::new(pf[0], pf[1]))
            .map(|q| chk(q.norm2().sqrt()))
            .unwrap_or(true);
        let g = model
            .g_uw_formula(&e, &P2::<Mp>::from_f64(pf[0], pf[1], MP_PREC))
            .map(|q| chk(q.norm2().sqrt().to_f64()))
            .unwrap_or(true);
        st.refuted = Some((disk_box(m_u), String::new()));
        CertWitness {
            point: pf,
            text: txt,
            f64_confirms: f,
            mp_confirms: g,
        }
    });
    let mut r = finish(
        ConfigKey::Edge { m_u, m_w },
        "L4.2.3(cert)",
        format!("g_(u,w) maps the inner arc of ∂Ω_uw (|t| ≤ acos(1/√3) − {delta:e}) onto ∂Ω_w; `bound` = max enclosure of ||g_(u,w)(p)| − r_w| at {n} arc points; `centre_bound` = separation: the arc lies ≥ this inside Ω_u's canonical image (|b| ≤ √3/2 − sep)"),
        st,
        witness,
        t0,
    );
    if r.outcome != Outcome::Refuted && r.unresolved == 0 {
        r.delta = Some(delta);
        r.outcome = Outcome::CertifiedOutsideDelta;
    }
    r
}

// ---------------------------------------------------------------------------------------------
// Triangle provers.
// ---------------------------------------------------------------------------------------------

/// L4.2.1(cert) and L4.2.2(cert) for a triangle configuration, exactly and on the whole set.
///
/// Notation: for p in u's chart, θ_x and θ_w are its principal angles relative to s_u(x) and
/// s_u(w), r its radius, b = k_u r e^{iα} with α = m_uθ_x/6 (so b = g_u∘R_(u,x)(p)), and
/// c = h(b) = 1 − b. C, D are the open disks of radius √3/2 about 0 and 1 (the lens E = C ∩ D,
/// Sec. 4.1). By the closed form of Def. 4.1.9 (module `interval`), p ∈ Ω_ux ⇔ 0 < r < r_u,
/// winding(θ_x) = 0, b ∈ D (r < r_u ⇔ b ∈ C).
///
/// On a box where θ_x is one principal piece with winding 0 and c_x > 0 (so Π(c) = (β, s),
/// |β| < π/2), q = φ_xu(p) has principal angle 6β/m_x relative to s_x(u) (|6β/m_x| < π
/// certified) and radius s/k_x. If its angle θ' relative to s_x(w) is one principal piece with
/// wrap integer k' (θ' = 6β/m_x + 2π(x_u − x_w)/m_x − 2πk'), then m_xθ'/6 = β + πn_x/3 with
/// the *integer* n_x = (x_u − x_w) − m_x k', so g_x∘R_(x,w)(q) = e^{iπn_x/3}c exactly and (with
/// winding(θ') = 0 certified; if it is certified false, q ∉ Ω_xw)
///   q ∈ Ω_xw ⇔ b ∈ D ∧ |e^{iπn_x/3}(1 − b) − 1| < √3/2 ⇔ b ∈ D ∧ b ∈ disk(1 − e^{−iπn_x/3}).
/// * n_x ≡ 2, 3, 4 (mod 6): |1 − e^{−iπn_x/3}| = 2|sin(πn_x/6)| ≥ √3, so this disk and C
///   are disjoint: no point of the box is in Ω_ux ∩ φ_xu⁻¹(Ω_xw) (for m_x = 3 this is the
///   wrapped branch, tangent to C at one point: why bisection alone cannot close it).
/// * n_x ≡ ±1: 1 − e^{∓iπ/3} = e^{±iπ/3}. If θ_w is one principal piece with wrap integer k_w,
///   m_uθ_w/6 = α + πn_u/3 with n_u = (u_x − u_w) + m_u(k_x − k_w), so g_u∘R_(u,w)(p) =
///   e^{iπn_u/3}b and (winding(θ_w) = 0 certified) p ∈ Ω_uw ⇔ 0 < r < r_u ∧
///   b ∈ disk(e^{−iπn_u/3}). With n_u ≡ −n_x (mod 6) the two disks coincide:
///   Ω_ux ∩ φ_xu⁻¹(Ω_xw) = Ω_ux ∩ Ω_uw = {b ∈ C ∩ D ∩ G} on the box (App. A.1: the inclusion is
///   an *equality*, which is why direct bisection of the two memberships never separates them).
///   Cocycle: with c_w = h(e^{iγ}b), γ = ±π/3 = πn_u/3, and c'' = h(e^{−iγ}c) both in the right
///   half-plane (certified), c'' = 1 − e^{−iγ} + e^{−iγ}b = e^{iγ}c_w exactly
///   ((h∘M_{−π/3})³ = id), so |c''| = |c_w|, arg c'' = arg c_w + γ (both in (−π/2, π/2)),
///   and with s_w(u) − s_w(x) ≡ ±1 matching the sign of γ (integer check) φ_wx(φ_xu(p)) =
///   φ_wu(p) exactly.
///
/// The branch and bound covers u's whole chart: a box is done when the closed form proves it
/// disjoint from Ω_ux ∩ φ_xu⁻¹(Ω_xw), or when the case analysis above applies to the whole box
/// (the branch conditions hold with a margin on the closure of the set, so no box is left
/// unresolved and there is no δ). A box where the closed form proves p ∈ Ω_ux, φ_xu(p) ∈ Ω_xw
/// but p ∉ Ω_uw refutes. Proven boxes are split down to `check_diam`, and at every centre in
/// the set the model's generic maps (`construction::maps`, on point intervals) are checked
/// against the closed form: its literal membership tests must all say "in" (if they show
/// p ∈ Ω_ux, φ_xu(p) ∈ Ω_xw, p ∉ Ω_uw the inclusion is refuted at that point; any other
/// disagreement makes the result inconclusive), and the enclosure of the cocycle deviation is
/// `centre_bound` (above `fail_tol` refutes).
pub fn prove_triangle(key: ConfigKey, model: &Model, s: &Settings) -> Vec<PropertyResult> {
    let t0 = Instant::now();
    let Some(t) = key.triangle() else {
        return vec![];
    };
    let (du, dw, dx) = (Deg::new(t.m_u), Deg::new(t.m_w), Deg::new(t.m_x));
    let (mu, mw, mx) = (t.m_u as i64, t.m_w as i64, t.m_x as i64);
    let sh_ux = two_pi_frac(t.u_x as i64, mu);
    let sh_uw = two_pi_frac(t.u_w as i64, mu);
    let sh_xuw = two_pi_frac(t.x_u as i64 - t.x_w as i64, mx);
    let (uw, ux, xw) = (t.uw(), t.ux(), t.xw());
    let mut cocycle_refuted: Option<(PBox, String)> = None;
    let mut model_refuted: Option<(PBox, String)> = None;
    let mut model_mismatch: u64 = 0;
    let mut first_mismatch: Option<String> = None;
    let mut centre_checks: u64 = 0;
    let cocycle = |p: &P2<Iv>| -> Option<Iv> {
        let lhs = model.g_uw_formula(&uw, p).ok()?;
        let mid = model.g_uw_formula(&ux, p).ok()?;
        let rhs = model.g_uw_formula(&xw, &mid).ok()?;
        Some(lhs.sub(&rhs).norm2().sqrt())
    };
    // Closed-form A = [p ∈ Ω_ux ∧ φ_xu(p) ∈ Ω_xw] on (θ, r), piecewise over principal angles.
    let a_of = |th: I, r: I| -> Trit {
        let mut v = Vec::with_capacity(2);
        for p in interval::principal_pieces(th - sh_ux) {
            let a1 = member(&du, p, r, Domain::Literal);
            if a1.is_false() {
                v.push(Trit::False);
                continue;
            }
            match phi_polar(&du, &dx, p, r) {
                Some((tx, rx)) => v.push(a1.and(member_any(&dx, tx + sh_xuw, rx, Domain::Literal))),
                None => v.push(Trit::Unknown),
            }
        }
        interval::all_pieces(&v)
    };
    // The exact case analysis of the doc comment, on the whole box.
    let exact = |th: I, r: I| -> Exact {
        let px = interval::principal_pieces_k(th - sh_ux);
        let [(tx, kx)] = px.as_slice() else {
            return Exact::Undecided;
        };
        match du.winding0(*tx) {
            Trit::False => return Exact::Empty,
            Trit::Unknown => return Exact::Undecided,
            Trit::True => {}
        }
        let Some((tq, rq)) = phi_polar(&du, &dx, *tx, r) else {
            return Exact::Undecided;
        };
        if tq.abs().sup() >= I::PI.inf() {
            return Exact::Undecided;
        }
        let pq = interval::principal_pieces_k(tq + sh_xuw);
        let [(tqw, kq)] = pq.as_slice() else {
            return Exact::Undecided;
        };
        match dx.winding0(*tqw) {
            Trit::False => return Exact::Empty,
            Trit::Unknown => return Exact::Undecided,
            Trit::True => {}
        }
        // g_x∘R_(x,w)(q) = e^{iπ n_x/3}·c exactly.
        let n_x = ((t.x_u as i64 - t.x_w as i64) - mx * kq).rem_euclid(6);
        if matches!(n_x, 2..=4) {
            // A ⊆ C ∩ disk(1 − e^{−iπn_x/3}): centres 2|sin(πn_x/6)| ≥ √3 apart, radii √3/2.
            return Exact::Empty;
        }
        if n_x == 0 {
            return Exact::Undecided;
        }
        let pw = interval::principal_pieces_k(th - sh_uw);
        let [(tw, kw)] = pw.as_slice() else {
            return Exact::Undecided;
        };
        // g_u∘R_(u,w)(p) = e^{iπ n_u/3}·b exactly.
        let n_u = ((t.u_x as i64 - t.u_w as i64) + mu * (kx - kw)).rem_euclid(6);
        if (n_x + n_u) % 6 != 0 || !du.winding0(*tw).is_true() {
            return Exact::Undecided;
        }
        // Equal sets. Cocycle branch conditions: c_w, c'' in the right half-plane, and the
        // angle offset ±π/3 (sign of n_u) matches the labels of u and x in w's star.
        let sgn = if n_u == 1 { 1 } else { -1 };
        let cocycle_ok = (sgn + t.w_x as i64 - t.w_u as i64).rem_euclid(mw) == 0
            && phi_polar(&du, &dw, *tw, r).is_some()
            && phi_polar(&dx, &dw, *tqw, rq).is_some();
        if cocycle_ok {
            Exact::Equal
        } else {
            Exact::Undecided
        }
    };
    let st = bnb(disk_box(t.m_u), s.max_depth, s.budget, |b| {
        let (th, r) = (b.ith(), b.ir());
        let a = a_of(th, r);
        if a.is_false() {
            return Leaf::Proven(None, None);
        }
        if a.is_true() && member_any(&du, th - sh_uw, r, Domain::Literal).is_false() {
            return Leaf::Refuted("p ∈ Ω_ux, φ_xu(p) ∈ Ω_xw, p ∉ Ω_uw (closed form)".into());
        }
        match exact(th, r) {
            Exact::Empty => return Leaf::Proven(None, None),
            Exact::Undecided => {
                if std::env::var("PPM_DBG").is_ok() && b.diam() < 1e-3 {
                    eprintln!("DBG box {b:?} a={a:?}");
                }
                return Leaf::Split;
            }
            Exact::Equal if b.diam() > s.check_diam => return Leaf::Split,
            Exact::Equal => {}
        }
        // Proven exactly on the box. Model cross-check at the centre, if it lies in the set.
        let (tm, rm) = b.mid();
        let mut cb = None;
        if a_of(c(tm), c(rm)).is_true() {
            centre_checks += 1;
            let p = iv_point(b.centre_xy());
            let m1 = model.in_omega_uw_literal(&ux, &p);
            let m2 = model
                .g_uw_formula(&ux, &p)
                .map(|q| model.in_omega_uw_literal(&xw, &q))
                .unwrap_or(Trit::Unknown);
            let m3 = model.in_omega_uw_literal(&uw, &p);
            if m1.is_true() && m2.is_true() && m3.is_false() {
                if model_refuted.is_none() {
                    model_refuted = Some((
                        *b,
                        "the model's literal tests: p ∈ Ω_ux, φ_xu(p) ∈ Ω_xw, p ∉ Ω_uw".into(),
                    ));
                }
            } else if m1.is_false() || m2.is_false() || m3.is_false() {
                model_mismatch += 1;
                if first_mismatch.is_none() {
                    let p = b.centre_xy();
                    first_mismatch = Some(format!(
                        "at p = ({:.9}, {:.9}) the closed form gives p ∈ Ω_ux ∩ φ_xu⁻¹(Ω_xw) ∩ Ω_uw, the model's literal tests give {m1:?}, {m2:?}, {m3:?}",
                        p[0], p[1]
                    ));
                }
            }
            match cocycle(&p) {
                Some(dv) if dv.inf() > s.fail_tol && cocycle_refuted.is_none() => {
                    cocycle_refuted =
                        Some((*b, format!("|φ_wu(p) − φ_wx(φ_xu(p))| ≥ {:.3e}", dv.inf())));
                }
                Some(dv) if dv.inf() > s.fail_tol => {}
                Some(dv) => cb = omax(cb, Some(dv.sup())),
                None => {
                    // The model's maps fail to evaluate at a point of the set.
                    model_mismatch += 1;
                    if first_mismatch.is_none() {
                        let p = b.centre_xy();
                        first_mismatch = Some(format!(
                            "at p = ({:.9}, {:.9}) the model's maps could not evaluate the cocycle",
                            p[0], p[1]
                        ));
                    }
                }
            }
        }
        Leaf::Proven(Some(0.0), cb)
    });
    let incl_box = st.refuted.clone().or(model_refuted);
    let wit_incl = incl_box.as_ref().map(|(b, txt)| {
        let p = b.centre_xy();
        CertWitness {
            point: p,
            text: format!(
                "p = ({:.9}, {:.9}) in u's chart, triangle {t:?}: {txt}",
                p[0], p[1]
            ),
            f64_confirms: inclusion_violated(model, &uw, &ux, &xw, &P2::<f64>::new(p[0], p[1])),
            mp_confirms: inclusion_violated(
                model,
                &uw,
                &ux,
                &xw,
                &P2::<Mp>::from_f64(p[0], p[1], MP_PREC),
            ),
        }
    });
    let wit_coc = cocycle_refuted.as_ref().map(|(b, txt)| {
        let p = b.centre_xy();
        CertWitness {
            point: p,
            text: format!(
                "p = ({:.9}, {:.9}) in u's chart, triangle {t:?}: {txt}",
                p[0], p[1]
            ),
            f64_confirms: cocycle_gap(model, &uw, &ux, &xw, &P2::<f64>::new(p[0], p[1]))
                > s.fail_tol,
            mp_confirms: cocycle_gap(
                model,
                &uw,
                &ux,
                &xw,
                &P2::<Mp>::from_f64(p[0], p[1], MP_PREC),
            ) > s.fail_tol,
        }
    });
    let ms = t0.elapsed().as_millis() as u64;
    let mismatch_note = first_mismatch
        .map(|m| format!(" INCONCLUSIVE: the model disagrees with the closed form at {model_mismatch} of {centre_checks} centres, e.g. {m}"))
        .unwrap_or_default();
    let incl_stmt = format!("φ_xu⁻¹(Ω_xu ∩ Ω_xw) = Ω_ux ∩ Ω_uw ⊆ Ω_uw at every point (literal Def. 4.1.9 via its closed form, u's chart; no δ): every box of the chart is proven disjoint from Ω_ux ∩ φ_xu⁻¹(Ω_xw) or the exact case analysis applies on it (principal pieces with integer wrap identities, winding 0, c_x > 0 certified; then both sets are C ∩ D ∩ G in g_u∘R_(u,x) coordinates, by 1 − e^{{∓iπ/3}} = e^{{±iπ/3}}, or the set is empty because two disks of radius √3/2 are ≥ √3 apart; proof at `certify::prove_triangle`); the model's literal tests agree with the closed form at every box centre in the set{mismatch_note}");
    let coc_stmt = "φ_wu = φ_wx∘φ_xu on all of φ_xu⁻¹(Ω_xu ∩ Ω_xw), exactly: on every box meeting the set the branch conditions are certified, under which c'' = e^{±iπ/3}c_w ((h∘M_{−π/3})³ = id) gives equal points; `bound` = 0 is the proven whole-domain bound; `centre_bound` = max interval enclosure of |φ_wu(p) − φ_wx(φ_xu(p))| by the model's generic maps at every box centre in the set (evaluator rounding; above fail_tol refutes)".to_string();
    let mk = |prop: &str,
              stmt: String,
              refuted: Option<CertWitness>,
              inconclusive: bool,
              bound: Option<f64>,
              cb: Option<f64>| {
        let outcome = if refuted.is_some() {
            Outcome::Refuted
        } else if inconclusive || st.refuted.is_some() || st.budget_hit {
            Outcome::Inconclusive
        } else if st.unresolved == 0 {
            Outcome::Certified
        } else {
            Outcome::CertifiedOutsideDelta
        };
        PropertyResult {
            key,
            property: prop.into(),
            outcome,
            statement: stmt,
            bound,
            centre_bound: cb,
            delta: if st.unresolved > 0 {
                Some(st.delta)
            } else {
                None
            },
            boxes: st.boxes,
            max_depth: st.max_depth,
            unresolved: st.unresolved,
            witness: refuted,
            millis: ms,
        }
    };
    let mismatch = model_mismatch > 0;
    let incl_out = mk("L4.2.1(cert)", incl_stmt, wit_incl, mismatch, None, None);
    let coc_out = mk(
        "L4.2.2(cert)",
        coc_stmt,
        wit_coc,
        mismatch,
        st.bound,
        st.centre,
    );
    vec![incl_out, coc_out]
}

// ---------------------------------------------------------------------------------------------
// Driver.
// ---------------------------------------------------------------------------------------------

/// All provers for one configuration.
pub fn prove_config(key: ConfigKey, model: &Model, s: &Settings) -> Vec<PropertyResult> {
    match key {
        ConfigKey::Vertex { m } => vec![
            prove_lens_agreement(m, model, s),
            prove_star(m, false, false, model, s),
            prove_star(m, false, true, model, s),
            prove_star(m, true, false, model, s),
            prove_star(m, true, true, model, s),
        ],
        ConfigKey::Edge { m_u, m_w } => vec![
            prove_nonempty(m_u, m_w, model),
            prove_inverse(m_u, m_w, model, s),
            prove_hausdorff(m_u, m_w, model, s),
        ],
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
    use rayon::prelude::*;
    let t0 = Instant::now();
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(jobs.max(1))
        .build()
        .map_err(|e| CertifyError::BadArg(format!("thread pool: {e}")))?;
    let results: Vec<PropertyResult> = pool.install(|| {
        configs
            .par_iter()
            .map(|k| prove_config(*k, model, s))
            .collect::<Vec<_>>()
            .into_iter()
            .flatten()
            .collect()
    });
    Ok(Certificate {
        format: "pseudomanifold-certificate/1".into(),
        max_degree,
        model: model.name(),
        shard,
        configs: configs.len(),
        results,
        wall_millis: t0.elapsed().as_millis() as u64,
        jobs,
        statements: Default::default(),
    })
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
    Ok(Certificate {
        format: first.format.clone(),
        max_degree: md,
        model,
        shard: None,
        configs,
        results,
        wall_millis: wall,
        jobs: first.jobs,
        statements: Default::default(),
    })
}

/// Coverage of one property for a mesh.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Coverage {
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
pub fn coverage(cert: &Certificate, configs_needed: &[ConfigKey]) -> Vec<Coverage> {
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
            let mut cov = Coverage {
                property: prop.into(),
                certified: true,
                missing: vec![],
                refuted: vec![],
                inconclusive: vec![],
                max_delta: None,
            };
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
                    Some(r) => match r.outcome {
                        Outcome::Certified => {}
                        Outcome::CertifiedOutsideDelta => {
                            cov.max_delta = omax(cov.max_delta, r.delta);
                        }
                        Outcome::Refuted => cov.refuted.push(*k),
                        Outcome::Inconclusive => cov.inconclusive.push(*k),
                    },
                }
            }
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
        "Reproduce: `ppm certify --max-degree {} --jobs {} --out certificate_M{}.json --summary CERTIFICATE_SUMMARY_M{}.md` (release build). \"certified\" = proven on the whole stated set (no δ); \"certified outside δ\" = proven at every point farther than δ from the stated boundary; `max bound` = proven whole-domain bound (0 = exact identity); `max centre bound` = interval enclosures by the model's generic maps at box centres (see Statements).\n\n",
        cert.max_degree, cert.jobs, cert.max_degree, cert.max_degree
    ));
    s.push_str("| property | configurations | certified | certified outside δ | refuted | inconclusive | max bound | max centre bound | max δ | boxes | max depth | time (s, sum) |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n");
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
                .fold(None, |a: Option<f64>, x| Some(a.map_or(x, |y| y.max(x))))
        };
        s.push_str(&format!(
            "| `{p}` | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {:.1} |\n",
            rs.len(),
            cnt(Outcome::Certified),
            cnt(Outcome::CertifiedOutsideDelta),
            cnt(Outcome::Refuted),
            cnt(Outcome::Inconclusive),
            fmt(mx(&|r| r.bound)),
            fmt(mx(&|r| r.centre_bound)),
            fmt(mx(&|r| r.delta)),
            rs.iter().map(|r| r.boxes).sum::<u64>(),
            rs.iter().map(|r| r.max_depth).max().unwrap_or(0),
            rs.iter().map(|r| r.millis).sum::<u64>() as f64 / 1000.0,
        ));
    }
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
            fmt(r.delta),
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
    let mut seen = std::collections::BTreeSet::new();
    for r in &cert.results {
        if seen.insert(r.property.clone()) {
            s.push_str(&format!("* `{}`: {}\n", r.property, r.statement));
        }
    }
    s
}
