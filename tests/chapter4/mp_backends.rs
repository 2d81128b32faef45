//! Differential test of the two multi-precision backends (feature `mpfr`): every oracle
//! quantity — φ_wu (Def. 4.1.10), g_v and g_v⁻¹ (Def. 4.1.6), eval (Sec. 6.1.4), θ_v
//! (Def. 5.3.2) and its partial derivatives to order 3, and the fit residual ψ_v(q) − b_σ(r) at
//! the Sec. 5.2 samples — computed with the pure-Rust `Mp` and with MPFR `MpMpfr` at 256 bits,
//! on the bundled meshes and a deterministic sample of the corpus (skipped when absent).
//!
//! Bound (printed): with u = 2^−p, the backends may differ by at most
//! 2^AMP · max(e, u · max(|x|, 1)), where e = |x_MPFR,p − x_MPFR,2p| is MPFR's own rounding
//! error at p bits for that quantity (measured against MPFR at 2p bits) and 2^AMP = 2^8 allows
//! astro-float's faithful (not always correctly rounded) atan2 to round differently from MPFR
//! in every operation. Both backends round +, −, ×, ÷, √, sin, cos, exp correctly, so
//! for most quantities the two answers are bit-identical.
//!
//! A planted wrong constant (π off by 2^−180 relative in one backend) must be reported.

#![cfg(feature = "mpfr")]

use crate::common;

use pseudomanifold::construction::maps::{g_v, g_v_inv};
use pseudomanifold::construction::{PpmGluing, P2};
use pseudomanifold::mesh::io::{read_mesh, ReadOptions};
use pseudomanifold::mesh::validate::validate;
use pseudomanifold::mesh::{FaceId, SimplicialSurface, VertexId};
use pseudomanifold::numeric::{Mp, MpMpfr, Scalar, Trit};
use pseudomanifold::surface::fit::sample_set;
use pseudomanifold::surface::jet::MONOMIALS;
use pseudomanifold::surface::{
    Jet, PnTriangles, Pps, PpsOptions, Profile, SurfaceScalar, TargetSurface,
};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::cmp::Ordering;
use std::path::Path;

const P: u32 = 256;
const AMP: i32 = 8;
const SEED: u64 = 20240601;

/// A backend value converted exactly to an MPFR float (for differences beyond f64).
trait Exact: SurfaceScalar {
    fn exact(&self) -> rug::Float;
}

impl Exact for MpMpfr {
    fn exact(&self) -> rug::Float {
        self.0.clone()
    }
}

impl Exact for Mp {
    fn exact(&self) -> rug::Float {
        let b = self.big();
        if b.is_nan() {
            return rug::Float::with_val(64, rug::float::Special::Nan);
        }
        if b.is_inf() {
            let s = if b.is_negative() {
                rug::float::Special::NegInfinity
            } else {
                rug::float::Special::Infinity
            };
            return rug::Float::with_val(64, s);
        }
        let Some((words, _, sign, e, _)) = b.as_raw_parts() else {
            return rug::Float::with_val(64, 0);
        };
        let m = rug::Integer::from_digits(words, rug::integer::Order::Lsf);
        let bits = 64 * words.len() as u32;
        let mut f = rug::Float::with_val(bits.max(64), m);
        f <<= e - bits as i32;
        if sign == astro_float::Sign::Neg {
            -f
        } else {
            f
        }
    }
}

/// MPFR with π off by 2^−180 (relative): the planted wrong constant.
#[derive(Clone, Debug)]
struct Planted(MpMpfr);

impl Scalar for Planted {
    fn type_name(&self) -> String {
        "planted".into()
    }
    fn from_f64(x: f64, prec: u32) -> Self {
        Planted(MpMpfr::from_f64(x, prec))
    }
    fn from_i64(x: i64, prec: u32) -> Self {
        Planted(MpMpfr::from_i64(x, prec))
    }
    fn from_ratio(p: i64, q: i64, prec: u32) -> Self {
        Planted(MpMpfr::from_ratio(p, q, prec))
    }
    fn pi(prec: u32) -> Self {
        let pi = MpMpfr::pi(prec);
        let eps = MpMpfr(rug::Float::with_val(prec, rug::Float::u_exp(1, -180)));
        Planted(pi.add(&pi.mul(&eps)))
    }
    fn to_f64(&self) -> f64 {
        self.0.to_f64()
    }
    fn precision_bits(&self) -> u32 {
        self.0.precision_bits()
    }
    fn add(&self, o: &Self) -> Self {
        Planted(self.0.add(&o.0))
    }
    fn sub(&self, o: &Self) -> Self {
        Planted(self.0.sub(&o.0))
    }
    fn mul(&self, o: &Self) -> Self {
        Planted(self.0.mul(&o.0))
    }
    fn div(&self, o: &Self) -> Self {
        Planted(self.0.div(&o.0))
    }
    fn neg(&self) -> Self {
        Planted(self.0.neg())
    }
    fn sqrt(&self) -> Self {
        Planted(self.0.sqrt())
    }
    fn sin(&self) -> Self {
        Planted(self.0.sin())
    }
    fn cos(&self) -> Self {
        Planted(self.0.cos())
    }
    fn abs(&self) -> Self {
        Planted(self.0.abs())
    }
    fn atan2(&self, x: &Self) -> Self {
        Planted(self.0.atan2(&x.0))
    }
    fn sign(&self) -> Option<Ordering> {
        self.0.sign()
    }
}

impl SurfaceScalar for Planted {
    fn exp(&self) -> Self {
        Planted(self.0.exp())
    }
}

impl Exact for Planted {
    fn exact(&self) -> rug::Float {
        self.0 .0.clone()
    }
}

/// A Sec. 5.2 fit sample: v, the face σ, its corners, q in the p-domain of v and b_σ(r) on S′.
type FitPoint = (VertexId, FaceId, [VertexId; 3], [f64; 2], [f64; 3]);

/// The sample points of one mesh, chosen once in f64 (seeded) and shared by every backend.
struct Points {
    phi: Vec<(VertexId, VertexId, [f64; 2])>,
    g: Vec<(u32, [f64; 2])>,
    eval: Vec<(FaceId, [f64; 3])>,
    theta: Vec<(VertexId, [f64; 2])>,
    fit: Vec<FitPoint>,
}

fn points(k: &SimplicialSurface, pps: &Pps, rng: &mut ChaCha8Rng) -> Points {
    let g = PpmGluing::new(k);
    let verts: Vec<VertexId> = k.vertices().collect();
    let faces: Vec<FaceId> = k.faces().collect();
    let disk = |rng: &mut ChaCha8Rng| loop {
        let p = [rng.gen_range(-1.0..1.0), rng.gen_range(-1.0..1.0)];
        if p[0] * p[0] + p[1] * p[1] < 0.95 {
            return p;
        }
    };
    let mut phi = Vec::new();
    for _ in 0..200 {
        if phi.len() >= 4 {
            break;
        }
        let u = verts[rng.gen_range(0..verts.len())];
        let h = k.outgoing(u)[0];
        let w = k.dest(h);
        let p = disk(rng);
        if g.in_omega_uw(u, w, &P2::<f64>::new(p[0], p[1])).ok() == Some(Trit::True) {
            phi.push((u, w, p));
        }
    }
    let gs = (0..3)
        .map(|_| {
            let v = verts[rng.gen_range(0..verts.len())];
            (k.degree(v), disk(rng))
        })
        .collect();
    let eval = (0..4)
        .map(|_| {
            let a: f64 = rng.gen_range(0.05..1.0);
            let b: f64 = rng.gen_range(0.05..1.0);
            let c: f64 = rng.gen_range(0.05..1.0);
            let s = a + b + c;
            (
                faces[rng.gen_range(0..faces.len())],
                [a / s, b / s, 1.0 - a / s - b / s],
            )
        })
        .collect();
    let mut theta = Vec::new();
    for _ in 0..200 {
        if theta.len() >= 3 {
            break;
        }
        let v = verts[rng.gen_range(0..verts.len())];
        let p = disk(rng);
        if pps
            .in_omega(v, &P2::new(p[0], p[1]), pps.consts_f64())
            .unwrap_or(false)
        {
            theta.push((v, p));
        }
    }
    // Fit residual at Sec. 5.2 samples of one vertex: ψ_v(q) − b_σ(r).
    let v = verts[rng.gen_range(0..verts.len())];
    let m = k.degree(v);
    let out = k.outgoing(v);
    let target = PnTriangles::new(k);
    let samples = sample_set(m, Profile::Paper);
    let fit = (0..3)
        .filter_map(|_| {
            let s = samples.get(rng.gen_range(0..samples.len()))?;
            let h = out[s.sector as usize];
            let corners = [v, k.dest(h), k.dest(out[((s.sector + 1) % m) as usize])];
            let f = k.face_of(h);
            Some((v, f, corners, s.q, target.eval(f, corners, s.bary)))
        })
        .collect();
    Points {
        phi,
        g: gs,
        eval,
        theta,
        fit,
    }
}

/// Every quantity at the points, in backend `S` at `bits`: (name, components).
fn quantities<S: SurfaceScalar>(
    k: &SimplicialSurface,
    pps: &Pps,
    pts: &Points,
    bits: u32,
) -> Vec<(String, Vec<S>)> {
    let g = PpmGluing::new(k);
    let p2 = |p: &[f64; 2]| P2::<S>::from_f64(p[0], p[1], bits);
    let mut out = Vec::new();
    for (u, w, p) in &pts.phi {
        if let Ok(q) = g.phi::<S>(*w, *u, &p2(p)) {
            out.push((format!("φ_{}{}({:?})", w.0, u.0, p), vec![q.x, q.y]));
        }
    }
    for (m, p) in &pts.g {
        if let Ok(q) = g_v::<S>(*m, &p2(p)) {
            out.push((format!("g(m={m}, {p:?})"), vec![q.x, q.y]));
        }
        if let Ok(q) = g_v_inv::<S>(*m, &p2(p)) {
            out.push((format!("g⁻¹(m={m}, {p:?})"), vec![q.x, q.y]));
        }
    }
    let c = pps.consts::<S>(bits);
    for (f, b) in &pts.eval {
        if let Ok(e) = pps.eval(*f, &b.map(|x| S::from_f64(x, bits)), &c) {
            out.push((format!("eval({}, {b:?})", f.0), e.point.to_vec()));
        }
    }
    for (v, p) in &pts.theta {
        if let Ok(t) = pps.theta(*v, &p2(p), &c) {
            out.push((format!("θ_{}({p:?})", v.0), t.to_vec()));
        }
    }
    let cj = pps.consts::<Jet<S>>(bits);
    for (v, p) in pts.theta.iter().take(2) {
        let (x, y) = Jet::variables(S::from_f64(p[0], bits), S::from_f64(p[1], bits));
        if let Ok(t) = pps.theta(*v, &P2::new(x, y), &cj) {
            let d: Vec<S> = MONOMIALS
                .iter()
                .flat_map(|&(i, j)| t.iter().map(move |d| d.derivative(i, j)))
                .collect();
            out.push((format!("∂θ_{}({p:?})", v.0), d));
        }
    }
    for (v, _f, _c, q, b) in &pts.fit {
        let psi = pps.psi(*v, &p2(q));
        let r: Vec<S> = psi
            .iter()
            .zip(b)
            .map(|(x, y)| x.sub(&S::from_f64(*y, bits)))
            .collect();
        out.push((format!("fit residual ψ_{}({q:?})", v.0), r));
    }
    out
}

struct Outcome {
    compared: usize,
    worst_ratio: f64,
    worst: String,
    offences: Vec<String>,
}

/// Compare backend `A` with MPFR at P bits on one mesh, the bound from MPFR at 2P.
fn compare<A: Exact>(name: &str, k: &SimplicialSurface) -> Outcome {
    let pps = Pps::build(k, &PnTriangles::new(k), PpsOptions::default());
    let mut rng = ChaCha8Rng::seed_from_u64(SEED);
    let pts = points(k, &pps, &mut rng);
    let a = quantities::<A>(k, &pps, &pts, P);
    let m = quantities::<MpMpfr>(k, &pps, &pts, P);
    let t = quantities::<MpMpfr>(k, &pps, &pts, 2 * P);
    let mut o = Outcome {
        compared: 0,
        worst_ratio: 0.0,
        worst: String::new(),
        offences: vec![],
    };
    let names_a: Vec<&String> = a.iter().map(|q| &q.0).collect();
    let names_m: Vec<&String> = m.iter().map(|q| &q.0).collect();
    if names_a != names_m {
        o.offences.push(format!(
            "{name}: the backends answered different sets of queries"
        ));
        return o;
    }
    let u = rug::Float::with_val(64, rug::Float::u_exp(1, -(P as i32)));
    for ((qa, qm), qt) in a.iter().zip(&m).zip(&t) {
        for ((xa, xm), xt) in qa.1.iter().zip(&qm.1).zip(&qt.1) {
            let (ea, em, et) = (xa.exact(), xm.exact(), xt.exact());
            let diff = rug::Float::with_val(4 * P, &ea - &em).abs();
            let own = rug::Float::with_val(4 * P, &em - &et).abs();
            let scale = rug::Float::with_val(64, em.abs_ref()).max(&rug::Float::with_val(64, 1));
            let floor = rug::Float::with_val(4 * P, &u * &scale);
            let bound = rug::Float::with_val(4 * P, own.max(&floor)) << AMP;
            o.compared += 1;
            if diff.is_nan() || diff > bound {
                o.offences.push(format!(
                    "{name}: {} differs by {:.3e} > bound {:.3e}",
                    qa.0,
                    diff.to_f64(),
                    bound.to_f64()
                ));
            }
            let d = diff.to_f64();
            let ratio = (diff / &bound).to_f64();
            if ratio >= o.worst_ratio {
                o.worst_ratio = ratio;
                o.worst = format!(
                    "{name}: {} (|Δ| = {d:.3e}, bound {:.3e})",
                    qa.0,
                    bound.to_f64()
                );
            }
        }
    }
    o
}

fn meshes(test: &str) -> Vec<(String, SimplicialSurface)> {
    let load = |p: &Path| validate(&read_mesh(p, &ReadOptions::default()).ok()?).surface;
    let mut v: Vec<(String, SimplicialSurface)> = common::bundled_good()
        .iter()
        .filter_map(|p| Some((p.file_name()?.to_string_lossy().into_owned(), load(p)?)))
        .collect();
    // The three smallest good corpus meshes (deterministic).
    let mut corpus: Vec<_> = common::corpus(test)
        .into_iter()
        .filter(|m| m.good)
        .collect();
    corpus.sort_by_key(|m| (m.faces, m.file.clone()));
    for m in corpus.into_iter().take(3) {
        if let Some(k) = load(&m.path) {
            v.push((m.file.clone(), k));
        }
    }
    v
}

#[test]
fn bk_mp_agree_every_oracle_quantity_at_256_bits() {
    eprintln!(
        "bound: |x_astro − x_MPFR| ≤ 2^{AMP} · max(|x_MPFR,{P} − x_MPFR,{}|, 2^-{P} · max(|x|, 1)); seed {SEED}",
        2 * P
    );
    let mut total = 0;
    let mut worst = (0.0, String::new());
    for (name, k) in meshes("bk_mp_agree_every_oracle_quantity_at_256_bits") {
        let o = compare::<Mp>(&name, &k);
        assert!(o.offences.is_empty(), "{}", o.offences.join("\n"));
        total += o.compared;
        if o.worst_ratio >= worst.0 {
            worst = (o.worst_ratio, o.worst);
        }
    }
    eprintln!(
        "{total} components compared; worst |Δ|/bound = {:.3e} at {}",
        worst.0, worst.1
    );
    assert!(total > 100, "only {total} components compared");
    crate::common::verdicts::record(
        "BK-mp-agree",
        crate::common::verdicts::Seen::Holds,
        total as u64,
    );
}

#[test]
fn bk_mp_agree_planted_wrong_pi_is_caught() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/icosahedron_binary_le.ply");
    let k = validate(&read_mesh(&path, &ReadOptions::default()).expect("fixture"))
        .surface
        .expect("valid");
    let o = compare::<Planted>("icosahedron (π + 2^-180 π)", &k);
    eprintln!(
        "{} components, {} offences; first: {:?}",
        o.compared,
        o.offences.len(),
        o.offences.first()
    );
    assert!(o.compared > 0);
    assert!(
        !o.offences.is_empty(),
        "a wrong π in one backend went unnoticed"
    );
}
