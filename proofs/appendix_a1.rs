//! Exact replay of the Appendix A.1 proofs: Prop. 4.2.4, Lemma 4.2.1 and
//! Lemma 4.2.2, each written as the list of steps the paper takes, every step checked exactly
//! (Q(√3) for rotations by multiples of π/3, h and the disks C, D, F, G; polar-affine maps with
//! the Π wrap analysis over rational regions of θ/π for R_(u,w), g_v, g_v⁻¹).
//! Each test replays a proof over every degree in 3..=MAX_DEG and every label, and asserts the
//! recorded verdict of every step; a failing step is recorded with its exact region.
//! See proofs/README.md for the bounds and for running under Kani.

use crate::support::*;
use pseudomanifold::exact::plane::{disks, Pt};
use pseudomanifold::exact::polar::Region;
use pseudomanifold::exact::q3::{q, Q3};
use pseudomanifold::exact::replay::{
    first_mismatch, plant_sign_error, render, replay, Expect, Step, StepCheck,
};

/// Degrees enumerated (every label of every degree).
const MAX_DEG: u32 = 14;

fn deg3(m: u32, fail: Region) -> Expect {
    if m == 3 {
        Expect::FailsOn(fail)
    } else {
        Expect::Holds
    }
}

fn derived(ids: &[&str], expect: Expect) -> (StepCheck, Expect) {
    (
        StepCheck::Derived(ids.iter().map(|s| s.to_string()).collect()),
        expect,
    )
}

fn step(id: &str, claim: &str, ce: (StepCheck, Expect)) -> Step {
    Step::new(id, claim, ce.0, ce.1)
}

/// Prop. 4.2.4 for a triangle [u, w, z] with s_u(z) = s_u(w) − 1 (z precedes w), s_u(w) = i.
pub fn p4_2_4_steps(mu: u32, i: u32, mw: u32, mz: u32) -> Vec<Step> {
    let iz = (i + mu - 1) % mu;
    let ruw = || r("R_(u,w)", i, mu);
    let ruw_i = || r_inv("R_(u,w)⁻¹", i, mu);
    let ruz = || r("R_(u,z)", iz, mu);
    let ruz_i = || r_inv("R_(u,z)⁻¹", iz, mu);
    let gu = || g("g_u", mu);
    let gui = || gi("g_u⁻¹", mu);
    let m_u = i64::from(mu);
    let inherits_if = |bad: bool| if bad { Expect::Inherits } else { Expect::Holds };
    let mut s = extent_steps("P4.2.4");
    let img_w = chain(vec![g("g_w", mw)]).image(&pi_range());
    let img_z = chain(vec![g("g_z", mz)]).image(&pi_range());
    s.extend([
        step("P4.2.4-s1", "Ω_uw = g_(w,u)(Ω_w−{0}) ∩ Ω_u and Ω_uz = g_(z,u)(Ω_z−{0}) ∩ Ω_u (Def. 4.1.9)", (StepCheck::Definition, Expect::Definition)),
        step(
            "P4.2.4-s2",
            "(0,0) ∉ g_(w,u)(Ω_w−{0}) (Prop. 4.1.2): h(q) = 0 only for q = (1,0), and (1,0) ∉ int(C) ⊇ g_w∘R_(w,u)(Ω_w−{0})",
            (StepCheck::PointOutside { point: Pt::new(Q3::one(), Q3::zero()), disk: disks::c() }, Expect::Holds),
        ),
        step(
            "P4.2.4-s3",
            "g_u∘R_(u,w) is bijective on Ω_u−{0} (used to distribute it over ∩): injectivity of g_u on θ(R_(u,w)p) ∈ (−π, π]",
            (StepCheck::PolarInjective { chain: chain(vec![gu()]), domain: pi_range() }, g_non_injective(mu)),
        ),
        step(
            "P4.2.4-s4",
            "g_u∘R_(u,w)(Ω_u−{0}) = int(C)−{(0,0)} (angles: the image of (−π, π] covers (−π, π])",
            (StepCheck::PolarCovers { chain: chain(vec![gu(), ruw()]), domain: pi_range(), target: pi_range() }, g_uncovered(mu)),
        ),
        step("P4.2.4-s5", "g_u∘R_(u,w)(g_(w,u)(Ω_w−{0})) = g_u∘R_(u,w)∘R_(u,w)⁻¹∘g_u⁻¹∘h∘g_w∘R_(w,u)(Ω_w−{0}) (Def. 4.1.8)", (StepCheck::Definition, Expect::Definition)),
        step(
            "P4.2.4-s6",
            "g_u∘R_(u,w)∘R_(u,w)⁻¹∘g_u⁻¹ = id on h∘g_w∘R_(w,u)(Ω_w−{0}) ⊆ int(D) (|θ| < π/3)",
            (StepCheck::PolarEq { lhs: chain(vec![gu(), ruw(), ruw_i(), gui()]), rhs: chain(vec![]), region: ext_d() }, Expect::Holds),
        ),
        step(
            "P4.2.4-s7a",
            "g_w∘R_(w,u)(Ω_w−{0}) = int(C)−{(0,0)} (premise of s7; angles of the image)",
            (StepCheck::PolarCovers { chain: chain(vec![g("g_w", mw)]), domain: pi_range(), target: pi_range() }, g_uncovered(mw)),
        ),
        step("P4.2.4-s7b", "h(int(C)) = int(D) and h(0,0) = (1,0)", (StepCheck::DiskImage { map: vec![h()], disk: disks::c(), claimed: disks::d() }, Expect::Holds)),
        step("P4.2.4-s7", "h∘g_w∘R_(w,u)(Ω_w−{0}) = int(D)−{(1,0)}", derived(&["P4.2.4-s7a", "P4.2.4-s7b"], inherits_if(mw < 6))),
        step(
            "P4.2.4-lit",
            "(used throughout) Ω_uw = R_(u,w)⁻¹∘g_u⁻¹(E): E ⊆ h(g_w∘R_(w,u)(Ω_w−{0})) since h(E) = E and |θ| < π/3 on E lies in the image sector of g_w",
            (
                StepCheck::Fact(
                    ext_d().subset_of(&img_w) && ext_d().subset_of(&img_z) && disk_eq(&[h()], &disks::c(), &disks::d()) && disk_eq(&[h()], &disks::d(), &disks::c()),
                    format!("image sectors of g_w: {img_w}, of g_z: {img_z} ⊇ (−1/3, 1/3); h swaps C and D"),
                ),
                Expect::Holds,
            ),
        ),
        step("P4.2.4-s8", "g_u∘R_(u,w)(g_(z,u)(Ω_z−{0})) = g_u∘R_(u,w)∘R_(u,z)⁻¹∘g_u⁻¹∘h∘g_z∘R_(z,u)(Ω_z−{0}) (Def. 4.1.8; the paper writes Ω_w)", (StepCheck::Definition, Expect::Definition)),
        step(
            "P4.2.4-s9a",
            "R_(u,w)∘R_(u,z)⁻¹ = M_{−2π/m_u}",
            (StepCheck::RotEq { lhs: vec![q(-2 * i64::from(i), m_u), q(2 * i64::from(iz), m_u)], rhs: vec![q(-2, m_u)] }, Expect::Holds),
        ),
        step(
            "P4.2.4-s9b",
            "h∘g_z∘R_(z,u)(Ω_z−{0}) = h∘g_w∘R_(w,u)(Ω_w−{0}) (the proof silently replaces z by w)",
            (
                StepCheck::Fact(img_w == img_z, format!("angles of g_w∘R_(w,u)(Ω_w−{{0}}): {img_w}; of g_z∘R_(z,u)(Ω_z−{{0}}): {img_z}")),
                if mw.min(6) == mz.min(6) { Expect::Holds } else { Expect::Fails },
            ),
        ),
        step(
            "P4.2.4-s10",
            "g_u∘M_{−2π/m_u}∘g_u⁻¹ = M_{−π/3} on h∘g_w∘R_(w,u)(Ω_w−{0}) ⊆ int(D) (|θ| < π/3), every Π inside in (−π, π]",
            (
                StepCheck::PolarEq { lhs: chain(vec![gu(), ruw(), ruz_i(), gui()]), rhs: chain(vec![m_rot("M_{−π/3}", q(-1, 3))]), region: ext_d() },
                deg3(mu, oc(-1, 3, -1, 6)),
            ),
        ),
        step(
            "P4.2.4-s11",
            "M_{−π/3}(int(D)−{(1,0)}) = int(F)−{(1/2, √3/2)}, F of centre (1/2, √3/2)",
            (StepCheck::DiskImage { map: vec![rot6(-2)], disk: disks::d(), claimed: disks::f() }, Expect::Fails),
        ),
        step(
            "P4.2.4-s11c",
            "(corrected) M_{−π/3}(int(D)−{(1,0)}) = int(G)−{(1/2, −√3/2)}, G of centre (1/2, −√3/2)",
            (StepCheck::DiskImage { map: vec![rot6(-2)], disk: disks::d(), claimed: disks::g() }, Expect::Holds),
        ),
        step("P4.2.4-s12", "g_u∘R_(u,w)(Ω_uw) = (int(C)−{0}) ∩ (int(D)−{(1,0)}) = E", derived(&["P4.2.4-s2", "P4.2.4-s3", "P4.2.4-s4", "P4.2.4-s6", "P4.2.4-s7"], inherits_if(mu != 6 || mw < 6))),
        step(
            "P4.2.4-s13",
            "g_u∘R_(u,w)(Ω_uz) = (int(C)−{0}) ∩ (int(F)−{(1/2, √3/2)})",
            derived(&["P4.2.4-s3", "P4.2.4-s4", "P4.2.4-s9a", "P4.2.4-s9b", "P4.2.4-s10", "P4.2.4-s11"], Expect::Inherits),
        ),
        step(
            "P4.2.4-i",
            "(i) M_{−π/3}∘g_u∘R_(u,w)(Ω_uw) = g_u∘R_(u,w)(Ω_uz), on the literal domains Ω_uw = R_(u,w)⁻¹g_u⁻¹(E), Ω_uz = R_(u,z)⁻¹g_u⁻¹(E)",
            (
                StepCheck::PolarSetEq {
                    lhs: chain(vec![gu(), ruw(), ruz_i(), gui()]),
                    rhs: chain(vec![m_rot("M_{−π/3}", q(-1, 3)), gu(), ruw(), ruw_i(), gui()]),
                    region: ext_d(),
                    rhs_extent: ext_g(),
                },
                deg3(mu, oc(-1, 3, -1, 6)),
            ),
        ),
        step("P4.2.4-s14", "R_(u,z)∘R_(u,w)⁻¹ = M_{2π/m_u}", (StepCheck::RotEq { lhs: vec![q(-2 * i64::from(iz), m_u), q(2 * i64::from(i), m_u)], rhs: vec![q(2, m_u)] }, Expect::Holds)),
        step(
            "P4.2.4-s15",
            "g_u∘M_{2π/m_u}∘g_u⁻¹ = M_{π/3} on int(D) (|θ| < π/3)",
            (
                StepCheck::PolarEq { lhs: chain(vec![gu(), ruz(), ruw_i(), gui()]), rhs: chain(vec![m_rot("M_{π/3}", q(1, 3))]), region: ext_d() },
                deg3(mu, oo(1, 6, 1, 3)),
            ),
        ),
        step(
            "P4.2.4-ii",
            "(ii) M_{π/3}∘g_u∘R_(u,z)(Ω_uz) = g_u∘R_(u,z)(Ω_uw) (literal domains)",
            (
                StepCheck::PolarSetEq {
                    lhs: chain(vec![gu(), ruz(), ruw_i(), gui()]),
                    rhs: chain(vec![m_rot("M_{π/3}", q(1, 3)), gu(), ruz(), ruz_i(), gui()]),
                    region: ext_d(),
                    rhs_extent: ext_f(),
                },
                deg3(mu, oo(1, 6, 1, 3)),
            ),
        ),
        step("P4.2.4-s16", "M_{−2π/m_u}(Ω_uw) = M_{−2π/m_u}(g_(w,u)(Ω_w−{0})) ∩ M_{−2π/m_u}(Ω_u−{0}) (a rotation is a bijection of R²)", (StepCheck::Fact(true, "rotations are bijections".into()), Expect::Holds)),
        step("P4.2.4-s17", "M_{−2π/m_u}(Ω_u−{0}) = Ω_u−{0} (rotation about the centre of Ω_u)", (StepCheck::Fact(true, "Ω_u is a disk centred at (0,0)".into()), Expect::Holds)),
        step("P4.2.4-s18", "M_{−2π/m_u}∘R_(u,w)⁻¹ = R_(u,z)⁻¹", (StepCheck::RotEq { lhs: vec![q(-2, m_u), q(2 * i64::from(i), m_u)], rhs: vec![q(2 * i64::from(iz), m_u)] }, Expect::Holds)),
        step("P4.2.4-s19a", "(the paper writes int(D)−{(0,0)}) (0,0) ∉ int(D), so removing it is harmless", (StepCheck::PointOutside { point: Pt::origin(), disk: disks::d() }, Expect::Holds)),
        step("P4.2.4-s19", "R_(u,z)⁻¹∘g_u⁻¹∘h∘g_w∘R_(w,u)(Ω_w−{0}) = R_(u,z)⁻¹∘g_u⁻¹(int(D)−{(0,0)})", derived(&["P4.2.4-s7", "P4.2.4-s19a"], inherits_if(mw < 6))),
        step("P4.2.4-s20", "R_(u,z)⁻¹∘g_u⁻¹(int(D)) ∩ (Ω_u−{0}) = Ω_uz (∩Ω_u cuts D to E; Ω_uz = R_(u,z)⁻¹g_u⁻¹(E))", derived(&["P4.2.4-lit"], Expect::Holds)),
        step(
            "P4.2.4-iii",
            "(iii) Ω_uz = M_{−2π/m_u}(Ω_uw): M_{−2π/m_u}∘R_(u,w)⁻¹∘g_u⁻¹ = R_(u,z)⁻¹∘g_u⁻¹ on E",
            (
                StepCheck::PolarEq { lhs: chain(vec![m_rot("M_{−2π/m_u}", q(-2, m_u)), ruw_i(), gui()]), rhs: chain(vec![ruz_i(), gui()]), region: ext_d() },
                Expect::Holds,
            ),
        ),
        step(
            "P4.2.4-iv",
            "(iv) Ω_uw = M_{2π/m_u}(Ω_uz): M_{2π/m_u}∘R_(u,z)⁻¹ = R_(u,w)⁻¹ (after g_u⁻¹ on E)",
            (
                StepCheck::PolarEq { lhs: chain(vec![m_rot("M_{2π/m_u}", q(2, m_u)), ruz_i(), gui()]), rhs: chain(vec![ruw_i(), gui()]), region: ext_d() },
                Expect::Holds,
            ),
        ),
    ]);
    s
}

/// Lemma 4.2.1, case (c), for the counterclockwise triangle [u, w, x] (x follows w at u).
pub fn l4_2_1_steps(t: Tri) -> Vec<Step> {
    let (mu, mx) = (t.mu, t.mx);
    let gu = || g("g_u", mu);
    let gui = || gi("g_u⁻¹", mu);
    let gx = || g("g_x", mx);
    let gxi = || gi("g_x⁻¹", mx);
    let rux = || r("R_(u,x)", t.su_x(), mu);
    let rux_i = || r_inv("R_(u,x)⁻¹", t.su_x(), mu);
    let ruw_i = || r_inv("R_(u,w)⁻¹", t.su_w(), mu);
    let rxu = || r("R_(x,u)", t.sx_u(), mx);
    let rxu_i = || r_inv("R_(x,u)⁻¹", t.sx_u(), mx);
    let rxw_i = || r_inv("R_(x,w)⁻¹", t.sx_w(), mx);
    let mut s = extent_steps("L4.2.1");
    s.extend([
        step("L4.2.1-ab", "cases (a) u = w = x and (b) two indices equal: φ_xu⁻¹(Ω_xu ∩ Ω_xw) is Ω_x, Ω_ux or Ω_xw (Defs. 4.1.9, 4.1.10)", (StepCheck::Definition, Expect::Definition)),
        step(
            "L4.2.1-c1",
            "g_(u,x)⁻¹ is bijective, so g_(u,x)⁻¹(Ω_xu ∩ Ω_xw) = g_(u,x)⁻¹(Ω_xu) ∩ g_(u,x)⁻¹(Ω_xw): injectivity of g_(u,x) on Ω_u−{0}, i.e. of g_u on θ(R_(u,x)p) ∈ (−π, π]",
            (StepCheck::PolarInjective { chain: chain(vec![gu()]), domain: pi_range() }, g_non_injective(mu)),
        ),
        step(
            "L4.2.1-c2a",
            "g_(x,u) maps Ω_xu = R_(x,u)⁻¹g_x⁻¹(E) onto Ω_ux: g_x∘R_(x,u)∘R_(x,u)⁻¹∘g_x⁻¹ = id on E, then h(E) = E",
            (StepCheck::PolarEq { lhs: chain(vec![gx(), rxu(), rxu_i(), gxi()]), rhs: chain(vec![]), region: ext_d() }, Expect::Holds),
        ),
        step(
            "L4.2.1-c2b",
            "g_(u,x)∘g_(x,u) = id on Ω_xu: g_u∘R_(u,x)∘R_(u,x)⁻¹∘g_u⁻¹ = id on h(E) = E",
            (StepCheck::PolarEq { lhs: chain(vec![gu(), rux(), rux_i(), gui()]), rhs: chain(vec![]), region: ext_d() }, Expect::Holds),
        ),
        step(
            "L4.2.1-c2c",
            "… and g_x⁻¹∘g_x = id on R_(x,u)(Ω_xu) = g_x⁻¹(E), i.e. on |θ| < 2π/m_x",
            (StepCheck::PolarEq { lhs: chain(vec![gxi(), gx()]), rhs: chain(vec![]), region: oo(-2, i64::from(mx), 2, i64::from(mx)) }, Expect::Holds),
        ),
        step("L4.2.1-c2", "g_(u,x)⁻¹(Ω_xu) = g_(x,u)(Ω_xu) = Ω_ux (Props. 4.1.3, 4.2.1)", derived(&["L4.2.1-c2a", "L4.2.1-c2b", "L4.2.1-c2c"], Expect::Holds)),
        step("L4.2.1-c3", "g_(x,u)(Ω_xw) = R_(u,x)⁻¹∘g_u⁻¹∘h∘g_x∘R_(x,u)(Ω_xw) (Def. 4.1.8)", (StepCheck::Definition, Expect::Definition)),
        step(
            "L4.2.1-c4",
            "g_x∘R_(x,u)(Ω_xw) = M_{π/3}∘g_x∘R_(x,u)(Ω_xu) (Prop. 4.2.4(ii) at x; Ω_xw = R_(x,w)⁻¹g_x⁻¹(E))",
            (
                StepCheck::PolarSetEq {
                    lhs: chain(vec![gx(), rxu(), rxw_i(), gxi()]),
                    rhs: chain(vec![m_rot("M_{π/3}", q(1, 3)), gx(), rxu(), rxu_i(), gxi()]),
                    region: ext_d(),
                    rhs_extent: ext_f(),
                },
                deg3(mx, oo(1, 6, 1, 3)),
            ),
        ),
        step(
            "L4.2.1-c5",
            "g_x∘R_(x,u)(Ω_xu) = E",
            (StepCheck::PolarEq { lhs: chain(vec![gx(), rxu(), rxu_i(), gxi()]), rhs: chain(vec![]), region: ext_d() }, Expect::Holds),
        ),
        step("L4.2.1-c6a", "h∘M_{π/3}(int(C)) = int(D)", (StepCheck::DiskImage { map: vec![h(), rot6(2)], disk: disks::c(), claimed: disks::d() }, Expect::Holds)),
        step("L4.2.1-c6b", "h∘M_{π/3}(int(D)) = int(G)", (StepCheck::DiskImage { map: vec![h(), rot6(2)], disk: disks::d(), claimed: disks::g() }, Expect::Holds)),
        step("L4.2.1-c7", "g_(x,u)(Ω_xw) ∩ Ω_u = R_(u,x)⁻¹∘g_u⁻¹(C ∩ D ∩ G) (minus the centres)", derived(&["L4.2.1-c4", "L4.2.1-c5", "L4.2.1-c6a", "L4.2.1-c6b"], if mx == 3 { Expect::Inherits } else { Expect::Holds })),
        step("L4.2.1-c8", "g_u∘R_(u,x)(Ω_ux ∩ Ω_uw) = g_u∘R_(u,x)(Ω_ux) ∩ g_u∘R_(u,x)(Ω_uw) (g_u∘R_(u,x) bijective)", derived(&["L4.2.1-c1"], if mu > 6 { Expect::Inherits } else { Expect::Holds })),
        step(
            "L4.2.1-c9",
            "g_u∘R_(u,x)(Ω_ux) = E",
            (StepCheck::PolarEq { lhs: chain(vec![gu(), rux(), rux_i(), gui()]), rhs: chain(vec![]), region: ext_d() }, Expect::Holds),
        ),
        step(
            "L4.2.1-c10",
            "g_u∘R_(u,x)(Ω_uw) = M_{−π/3}∘g_u∘R_(u,x)(Ω_ux) (Prop. 4.2.4(i) at u; the paper writes Ω_uw on the right)",
            (
                StepCheck::PolarSetEq {
                    lhs: chain(vec![gu(), rux(), ruw_i(), gui()]),
                    rhs: chain(vec![m_rot("M_{−π/3}", q(-1, 3)), gu(), rux(), rux_i(), gui()]),
                    region: ext_d(),
                    rhs_extent: ext_g(),
                },
                deg3(mu, oc(-1, 3, -1, 6)),
            ),
        ),
        step("L4.2.1-c11a", "M_{−π/3}(int(C)) = int(C)", (StepCheck::DiskImage { map: vec![rot6(-2)], disk: disks::c(), claimed: disks::c() }, Expect::Holds)),
        step("L4.2.1-c11b", "M_{−π/3}(int(D)) = int(G)", (StepCheck::DiskImage { map: vec![rot6(-2)], disk: disks::d(), claimed: disks::g() }, Expect::Holds)),
        step(
            "L4.2.1-c12",
            "Ω_ux ∩ Ω_uw = g_(x,u)(Ω_xw) ∩ Ω_u = … = g_(u,x)⁻¹(Ω_xw ∩ Ω_xu)",
            derived(
                &["L4.2.1-c2", "L4.2.1-c7", "L4.2.1-c8", "L4.2.1-c9", "L4.2.1-c10", "L4.2.1-c11a", "L4.2.1-c11b"],
                if mu == 3 || mx == 3 || mu > 6 { Expect::Inherits } else { Expect::Holds },
            ),
        ),
        step("L4.2.1-c13", "φ_xu⁻¹(Ω_xu ∩ Ω_xw) = Ω_ux ∩ Ω_uw ⊆ Ω_uw", derived(&["L4.2.1-c12"], if mu == 3 || mx == 3 || mu > 6 { Expect::Inherits } else { Expect::Holds })),
    ]);
    s
}

/// Lemma 4.2.2 for the counterclockwise triangle [u, w, x].
pub fn l4_2_2_steps(t: Tri) -> Vec<Step> {
    let (mu, mw, mx) = (t.mu, t.mw, t.mx);
    let (m_u, m_x) = (i64::from(mu), i64::from(mx));
    let gu = || g("g_u", mu);
    let gui = || gi("g_u⁻¹", mu);
    let gw = || g("g_w", mw);
    let gwi = || gi("g_w⁻¹", mw);
    let gx = || g("g_x", mx);
    let gxi = || gi("g_x⁻¹", mx);
    let rux = || r("R_(u,x)", t.su_x(), mu);
    let ruw_i = || r_inv("R_(u,w)⁻¹", t.su_w(), mu);
    let rwx = || r("R_(w,x)", t.sw_x(), mw);
    let rwx_i = || r_inv("R_(w,x)⁻¹", t.sw_x(), mw);
    let rwu_i = || r_inv("R_(w,u)⁻¹", t.sw_u(), mw);
    let rxw = || r("R_(x,w)", t.sx_w(), mx);
    let rxu_i = || r_inv("R_(x,u)⁻¹", t.sx_u(), mx);
    let m_m3 = || m_rot("M_{−π/3}", q(-1, 3));
    let m_p3 = || m_rot("M_{π/3}", q(1, 3));
    // the region the lemma's domain occupies: g_u∘R_(u,w)(Ω_uw ∩ Ω_ux) ⊆ C∩D∩F, angles (0, π/3)
    let upper = oo(0, 1, 1, 3);
    let lower = oo(-1, 3, 0, 1);
    let hm = [h(), rot6(-2)];
    let cdf_invariant = disk_eq(&hm, &disks::c(), &disks::d())
        && disk_eq(&hm, &disks::d(), &disks::f())
        && disk_eq(&hm, &disks::f(), &disks::c());
    let mut s = extent_steps("L4.2.2");
    s.extend([
        step("L4.2.2-s0", "if two of u, w, x coincide the claim is condition (3)(b) (Prop. 4.2.3)", (StepCheck::Definition, Expect::Definition)),
        step("L4.2.2-A1-A4", "(A.1)–(A.4): g_(u,w), g_(x,w), g_(u,x) and g_(x,w)∘g_(u,x) written out (Def. 4.1.8)", (StepCheck::Definition, Expect::Definition)),
        step("L4.2.2-orient", "s_u(x) follows s_u(w) ⇒ s_w(u) follows s_w(x) and s_x(w) follows s_x(u) (orientation of K; labels of Sec. 6.1.2, see the `combinatorial` module of the proofs binary)", (StepCheck::Definition, Expect::Definition)),
        step("L4.2.2-dom", "g_(u,x)⁻¹(Ω_xu ∩ Ω_xw) ⊆ Ω_uw (Lemma 4.2.1, replayed separately)", (StepCheck::Definition, Expect::Definition)),
        step(
            "L4.2.2-A5-cited",
            "Prop. 4.2.4 as cited: g_u∘R_(u,x) = M_{−π/3}∘g_u∘R_(u,w) pointwise on all of Ω_uw (g_u∘R_(u,w)(p) ∈ E, |θ| < π/3)",
            (StepCheck::PolarEq { lhs: chain(vec![gu(), rux(), ruw_i(), gui()]), rhs: chain(vec![m_m3()]), region: ext_d() }, deg3(mu, oc(-1, 3, -1, 6))),
        ),
        step(
            "L4.2.2-A5",
            "(A.5) g_u∘R_(u,x)(p) = M_{−π/3}∘g_u∘R_(u,w)(p) for p ∈ Ω_ux ∩ Ω_uw (g_u∘R_(u,w)(p) ∈ C∩D∩F, θ ∈ (0, π/3))",
            (StepCheck::PolarEq { lhs: chain(vec![gu(), rux(), ruw_i(), gui()]), rhs: chain(vec![m_m3()]), region: upper.clone() }, Expect::Holds),
        ),
        step(
            "L4.2.2-A6-cited",
            "Prop. 4.2.4 as cited: g_w∘R_(w,x) = M_{π/3}∘g_w∘R_(w,u) pointwise on all of Ω_wu",
            (
                StepCheck::PolarEq { lhs: chain(vec![gw(), rwx(), rwu_i(), gwi()]), rhs: chain(vec![m_p3()]), region: ext_d() },
                deg3(mw, oo(1, 6, 1, 3)),
            ),
        ),
        step(
            "L4.2.2-A6-pre",
            "g_w∘R_(w,x)(q) = M_{π/3}∘g_w∘R_(w,u)(q) for q ∈ Ω_wu ∩ Ω_wx (g_w∘R_(w,u)(q) ∈ C∩D∩G, θ ∈ (−π/3, 0))",
            (StepCheck::PolarEq { lhs: chain(vec![gw(), rwx(), rwu_i(), gwi()]), rhs: chain(vec![m_p3()]), region: lower.clone() }, Expect::Holds),
        ),
        step(
            "L4.2.2-A6",
            "(A.6) R_(w,x)⁻¹∘g_w⁻¹(t) = R_(w,u)⁻¹∘g_w⁻¹∘M_{−π/3}(t) for t = g_w∘R_(w,x)(q) (θ(t) ∈ (0, π/3))",
            (StepCheck::PolarEq { lhs: chain(vec![rwx_i(), gwi()]), rhs: chain(vec![rwu_i(), gwi(), m_m3()]), region: upper.clone() }, Expect::Holds),
        ),
        step("L4.2.2-A7", "(A.7) substitute (A.5), (A.6) into (A.4)", derived(&["L4.2.2-A5", "L4.2.2-A6-pre", "L4.2.2-A6"], Expect::Holds)),
        step(
            "L4.2.2-xrot",
            "R_(x,w)∘R_(x,u)⁻¹ = M_{−2π/m_x} (s_x(w) follows s_x(u))",
            (StepCheck::RotEq { lhs: vec![q(-2 * i64::from(t.sx_w()), m_x), q(2 * i64::from(t.sx_u()), m_x)], rhs: vec![q(-2, m_x)] }, Expect::Holds),
        ),
        step(
            "L4.2.2-xconj",
            "g_x∘M_{−2π/m_x}∘g_x⁻¹(q) = M_{−π/3}(q) for q in the upper half of E: α = m_x/6·(−2π/m_x + 6β/m_x) = β − π/3 with −2π/m_x + 6β/m_x ∈ (−π, π], t = s",
            (StepCheck::PolarEq { lhs: chain(vec![gx(), rxw(), rxu_i(), gxi()]), rhs: chain(vec![m_m3()]), region: upper.clone() }, Expect::Holds),
        ),
        step(
            "L4.2.2-xregion",
            "the argument of g_x∘R_(x,w)∘R_(x,u)⁻¹∘g_x⁻¹ in (A.7), h∘M_{−π/3}∘g_u∘R_(u,w)(p), lies in the upper half of E: h∘M_{−π/3} permutes C → D → F → C",
            (StepCheck::Fact(cdf_invariant, "h∘M_{−π/3}(C) = D, (D) = F, (F) = C, so C∩D∩F ⊆ upper half of E is invariant".into()), Expect::Holds),
        ),
        step("L4.2.2-A8", "(A.8) g_(x,w)∘g_(u,x) = R_(w,u)⁻¹∘g_w⁻¹∘M_{−π/3}∘h∘M_{−π/3}∘h∘M_{−π/3}∘g_u∘R_(u,w)", derived(&["L4.2.2-A7", "L4.2.2-xrot", "L4.2.2-xconj", "L4.2.2-xregion"], Expect::Holds)),
        step(
            "L4.2.2-h3",
            "h∘M_{−π/3}∘h∘M_{−π/3}∘h∘M_{−π/3} = id",
            (StepCheck::AffineEq { lhs: vec![h(), rot6(-2), h(), rot6(-2), h(), rot6(-2)], rhs: vec![] }, Expect::Holds),
        ),
        step("L4.2.2-hh", "h∘h = id", (StepCheck::AffineEq { lhs: vec![h(), h()], rhs: vec![] }, Expect::Holds)),
        step(
            "L4.2.2-hid",
            "h = M_{−π/3}∘h∘M_{−π/3}∘h∘M_{−π/3}",
            (StepCheck::AffineEq { lhs: vec![rot6(-2), h(), rot6(-2), h(), rot6(-2)], rhs: vec![h()] }, Expect::Holds),
        ),
        step("L4.2.2-A9", "(A.9) g_(x,w)∘g_(u,x)(p) = R_(w,u)⁻¹∘g_w⁻¹∘h∘g_u∘R_(u,w)(p) = g_(u,w)(p)", derived(&["L4.2.2-A8", "L4.2.2-h3", "L4.2.2-hh", "L4.2.2-hid"], Expect::Holds)),
    ]);
    let _ = m_u;
    s
}

fn degrees() -> Vec<u32> {
    (3..=MAX_DEG).collect()
}

/// Replays the proof of Prop. 4.2.4 for every m_u, m_w, m_z ∈ 3..=MAX_DEG and every label.
#[cfg_attr(kani, kani::proof)]
#[test]
fn p4_2_4_proof_replays_exactly() {
    let mut n = 0;
    for mu in degrees() {
        for i in 0..mu {
            for mw in degrees() {
                for mz in [3, 5, 6, mw] {
                    assert_replay(
                        &format!("P4.2.4 (m_u={mu}, i={i}, m_w={mw}, m_z={mz})"),
                        &p4_2_4_steps(mu, i, mw, mz),
                    );
                    n += 1;
                }
            }
        }
    }
    assert!(n > 1000);
    // Each replay asserts the expected verdict of every step, the failures of s10, s15, s11,
    // s3, s4/s7a, s9b where the degrees make them fail (SPEC `P4.2.4(proof)`).
    record("P4.2.4(proof)", Seen::Fails, n);
    println!(
        "{}",
        render(
            &p4_2_4_steps(3, 1, 5, 7),
            &replay(&p4_2_4_steps(3, 1, 5, 7))
        )
    );
}

/// The bounded configurations of the lemma replays: every degree triple in 3..=MAX_DEG with
/// labels s_u(w) = m_u − 1, s_w(x) = m_w − 1, s_x(u) = m_x − 1 (the labels whose rotations
/// reach furthest around, so every Π wrap is exercised), plus every label of every triple
/// of degrees in {3, 5, 7}.
fn lemma_configs() -> Vec<Tri> {
    let mut v: Vec<Tri> = Vec::new();
    for mu in degrees() {
        for mw in degrees() {
            for mx in degrees() {
                v.push(Tri {
                    mu,
                    mw,
                    mx,
                    i: mu - 1,
                    j: mw - 1,
                    k: mx - 1,
                });
            }
        }
    }
    v.extend(Tri::all(&[3, 5, 7], true));
    v
}

/// Replays the proof of Lemma 4.2.1 over [`lemma_configs`].
#[cfg_attr(kani, kani::proof)]
#[test]
fn l4_2_1_proof_replays_exactly() {
    let configs = lemma_configs();
    for t in &configs {
        assert_replay(&format!("L4.2.1 {t:?}"), &l4_2_1_steps(*t));
    }
    // The replays assert c1, c4, c10 failing where the degrees make them fail.
    record("L4.2.1(proof)", Seen::Fails, configs.len() as u64);
    let t = Tri {
        mu: 3,
        mw: 5,
        mx: 7,
        i: 1,
        j: 0,
        k: 2,
    };
    println!("{}", render(&l4_2_1_steps(t), &replay(&l4_2_1_steps(t))));
}

/// Replays the proof of Lemma 4.2.2 over [`lemma_configs`].
#[cfg_attr(kani, kani::proof)]
#[test]
fn l4_2_2_proof_replays_exactly() {
    let configs = lemma_configs();
    for t in &configs {
        assert_replay(&format!("L4.2.2 {t:?}"), &l4_2_2_steps(*t));
    }
    record("L4.2.2(proof)", Seen::Holds, configs.len() as u64);
    let t = Tri {
        mu: 3,
        mw: 3,
        mx: 3,
        i: 1,
        j: 0,
        k: 2,
    };
    println!("{}", render(&l4_2_2_steps(t), &replay(&l4_2_2_steps(t))));
}

/// Planted fault: a wrong sign in one rotation makes the replay fail exactly at that step.
#[cfg_attr(kani, kani::proof)]
#[test]
fn a_1_planted_rotation_sign_error_fails_at_the_right_step() {
    let cases: Vec<(&str, Vec<Step>)> = vec![
        ("P4.2.4-s10", p4_2_4_steps(5, 1, 4, 4)),
        ("P4.2.4-s9a", p4_2_4_steps(7, 2, 6, 6)),
        ("P4.2.4-iii", p4_2_4_steps(4, 1, 6, 6)),
        ("P4.2.4-s11c", p4_2_4_steps(6, 1, 6, 6)),
        (
            "L4.2.1-c10",
            l4_2_1_steps(Tri {
                mu: 5,
                mw: 4,
                mx: 6,
                i: 1,
                j: 1,
                k: 1,
            }),
        ),
        (
            "L4.2.2-A5",
            l4_2_2_steps(Tri {
                mu: 5,
                mw: 5,
                mx: 6,
                i: 1,
                j: 1,
                k: 1,
            }),
        ),
        (
            "L4.2.2-xconj",
            l4_2_2_steps(Tri {
                mu: 4,
                mw: 5,
                mx: 6,
                i: 1,
                j: 1,
                k: 1,
            }),
        ),
        (
            "L4.2.2-h3",
            l4_2_2_steps(Tri {
                mu: 4,
                mw: 5,
                mx: 6,
                i: 1,
                j: 1,
                k: 1,
            }),
        ),
    ];
    let n_cases = cases.len() as u64;
    for (id, mut steps) in cases {
        assert!(
            first_mismatch(&replay(&steps)).is_none(),
            "unplanted replay of {id} must match"
        );
        let st = steps
            .iter_mut()
            .find(|s| s.id == id)
            .expect("step id exists");
        assert!(plant_sign_error(st), "{id} has a rotation to flip");
        let out = replay(&steps);
        let bad = first_mismatch(&out).map(|o| o.id.clone());
        assert_eq!(
            bad.as_deref(),
            Some(id),
            "planted error must be caught at {id}\n{}",
            render(&steps, &out)
        );
    }
    record("A.1-planted", Seen::Caught, n_cases);
}
