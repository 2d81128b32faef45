//! Exact replay of the consistency argument of Sec. 6.1.4 (`tPPS::eval()`): the four cases
//! (1) q' ∈ C∩D, (2) q' ∈ C∩E_b, (3) q' ∈ D∩E_b, (4) q' ∈ C∩D∩E_b, where t = (a, b, c) =
//! ((0,0), (1/2, −√3/2), (1,0)), C, D, E_b are the disks of radius cos(π/6) centred at a, c, b
//! (E_b is the disk G of Appendix A.1). σ = [u, w, x] is mapped to t with u → a, w → b,
//! x → c, so σ is counterclockwise: s_u(x) = s_u(w) + 1, s_w(u) = s_w(x) + 1,
//! s_x(w) = s_x(u) + 1.

use crate::support::*;
use pseudomanifold::exact::plane::{disks, Pt};
use pseudomanifold::exact::q3::{q, Q3};
use pseudomanifold::exact::replay::{
    first_mismatch, plant_sign_error, render, replay, Expect, Step, StepCheck,
};

/// Degrees enumerated.
const MAX_DEG: u32 = 48;

fn step(id: &str, claim: &str, check: StepCheck, expect: Expect) -> Step {
    Step::new(id, claim, check, expect)
}
fn derived(ids: &[&str]) -> StepCheck {
    StepCheck::Derived(ids.iter().map(|s| s.to_string()).collect())
}

/// The steps of Sec. 6.1.4 for the counterclockwise triangle σ = [u, w, x].
pub fn eval_steps(t: Tri) -> Vec<Step> {
    let (mu, mw, mx) = (t.mu, t.mw, t.mx);
    let m_u = i64::from(mu);
    let gu = || g("g_u", mu);
    let gui = || gi("g_u⁻¹", mu);
    let gwi = || gi("g_w⁻¹", mw);
    let gx = || g("g_x", mx);
    let gxi = || gi("g_x⁻¹", mx);
    let rux = || r("R_(u,x)", t.su_x(), mu);
    let rux_i = || r_inv("R_(u,x)⁻¹", t.su_x(), mu);
    let ruw = || r("R_(u,w)", t.su_w(), mu);
    let rwx_i = || r_inv("R_(w,x)⁻¹", t.sw_x(), mw);
    let rwu_i = || r_inv("R_(w,u)⁻¹", t.sw_u(), mw);
    let rxw = || r("R_(x,w)", t.sx_w(), mx);
    let rxw_i = || r_inv("R_(x,w)⁻¹", t.sx_w(), mx);
    let rxu_i = || r_inv("R_(x,u)⁻¹", t.sx_u(), mx);
    let m_m3 = || m_rot("M_{−π/3}", q(-1, 3));
    let m_p3 = || m_rot("M_{π/3}", q(1, 3));
    let (c, d, gb) = (disks::c(), disks::d(), disks::g());
    // circumcentre of t and its squared distance to the vertices
    let cc_pt = Pt::new(Q3::frac(1, 2), Q3::sqrt3_times(-1, 6));
    let r2 = cc_pt.dist2(&Pt::origin());
    let covered = r2 == cc_pt.dist2(&d.c)
        && r2 == cc_pt.dist2(&gb.c)
        && r2.cmp_exact(&Q3::frac(3, 4)) == std::cmp::Ordering::Less;
    // t seen from a has angles [−π/3, 0]; h(t) seen from a has angles [0, π/3]
    let t_at_a = cc(-1, 3, 0, 1);
    let t_h = cc(0, 1, 1, 3);
    let as_written_conj = if (mu + 30) % 36 == 0 {
        Expect::Holds
    } else {
        Expect::FailsOn(ext_g())
    };
    let mut s = extent_steps("C6.1.4");
    s.extend([
        step(
            "C6.1.4-cover",
            "t ⊂ int(C) ∪ int(D) ∪ int(E_b): every point of t is within the circumradius of a vertex, and circumradius² = 1/3 < 3/4",
            StepCheck::Fact(covered, format!("circumcentre {cc_pt}, squared distance {r2} to a, b, c")),
            Expect::Holds,
        ),
        step(
            "C6.1.4-C-as-stated",
            "int(C) is the image of Ω_u by g_u∘R_(u,x) (angles of the image cover (−π, π])",
            StepCheck::PolarCovers { chain: chain(vec![gu(), rux()]), domain: pi_range(), target: pi_range() },
            g_uncovered(mu),
        ),
        step(
            "C6.1.4-C-on-t",
            "… on t: the angles [−π/3, 0] of t at a are covered by g_u∘R_(u,x)(Ω_u)",
            StepCheck::PolarCovers { chain: chain(vec![gu(), rux()]), domain: pi_range(), target: t_at_a.clone() },
            Expect::Holds,
        ),
        step(
            "C6.1.4-D-as-stated",
            "int(D) is the image of Ω_x by h∘g_x∘R_(x,u) (needs g_x∘R_(x,u)(Ω_x) = int(C))",
            StepCheck::PolarCovers { chain: chain(vec![gx()]), domain: pi_range(), target: pi_range() },
            g_uncovered(mx),
        ),
        step(
            "C6.1.4-D-on-t",
            "… on t: h(t) has angles [0, π/3] at a, covered by g_x∘R_(x,u)(Ω_x)",
            StepCheck::PolarCovers { chain: chain(vec![gx()]), domain: pi_range(), target: t_h.clone() },
            Expect::Holds,
        ),
        step(
            "C6.1.4-E-disk",
            "int(E_b) = M_{−π/3}∘h(int(C)) (so E_b is the image of Ω_w by M_{−π/3}∘h∘g_w∘R_(w,u))",
            StepCheck::DiskImage { map: vec![rot6(-2), h()], disk: c.clone(), claimed: gb.clone() },
            Expect::Holds,
        ),
        step(
            "C6.1.4-E-on-t",
            "… on t: h⁻¹∘M_{π/3}(t) = t has angles [−π/3, 0] at a, covered by g_w∘R_(w,u)(Ω_w)",
            StepCheck::PolarCovers { chain: chain(vec![g("g_w", mw)]), domain: pi_range(), target: t_at_a },
            Expect::Holds,
        ),
        // case (1)
        step("C6.1.4-case1-def", "φ_xu(q) = R_(x,u)⁻¹∘g_x⁻¹∘h∘g_u∘R_(u,x)(q) (Def. 4.1.10; the paper cites Def. 3.3.2)", StepCheck::Definition, Expect::Definition),
        step(
            "C6.1.4-case1-cancel",
            "g_u∘R_(u,x)∘R_(u,x)⁻¹∘g_u⁻¹(q') = q' for q' ∈ C∩D (|θ| < π/3); in particular q ∈ Ω_ux",
            StepCheck::PolarEq { lhs: chain(vec![gu(), rux(), rux_i(), gui()]), rhs: chain(vec![]), region: ext_d() },
            Expect::Holds,
        ),
        step("C6.1.4-case1-h", "h = h⁻¹", StepCheck::AffineEq { lhs: vec![h(), h()], rhs: vec![] }, Expect::Holds),
        step("C6.1.4-case1", "case (1): φ_xu(q) = R_(x,u)⁻¹∘g_x⁻¹∘h⁻¹(q')", derived(&["C6.1.4-case1-cancel", "C6.1.4-case1-h"]), Expect::Holds),
        // case (2)
        step(
            "C6.1.4-case2-rot-as-written",
            "R_(u,w)∘R_(u,x)⁻¹ = M_{π/3} (as written)",
            StepCheck::RotEq { lhs: vec![q(-2 * i64::from(t.su_w()), m_u), q(2 * i64::from(t.su_x()), m_u)], rhs: vec![q(1, 3)] },
            if mu == 6 { Expect::Holds } else { Expect::Fails },
        ),
        step(
            "C6.1.4-case2-conj-as-written",
            "g_u∘M_{π/3}∘g_u⁻¹(q') = M_{π/3}(q') for q' ∈ C∩E_b (as written; θ ∈ (−2π/3, 0))",
            StepCheck::PolarEq { lhs: chain(vec![gu(), m_p3(), gui()]), rhs: chain(vec![m_p3()]), region: ext_g() },
            as_written_conj,
        ),
        step(
            "C6.1.4-case2-rot",
            "(corrected) R_(u,w)∘R_(u,x)⁻¹ = M_{2π/m_u}",
            StepCheck::RotEq { lhs: vec![q(-2 * i64::from(t.su_w()), m_u), q(2 * i64::from(t.su_x()), m_u)], rhs: vec![q(2, m_u)] },
            Expect::Holds,
        ),
        step(
            "C6.1.4-case2-conj",
            "(corrected) g_u∘R_(u,w)∘R_(u,x)⁻¹∘g_u⁻¹(q') = M_{π/3}(q') for q' ∈ C∩E_b; so g_u∘R_(u,w)(q) ∈ M_{π/3}(C∩E_b) = E and q ∈ Ω_uw",
            StepCheck::PolarEq { lhs: chain(vec![gu(), ruw(), rux_i(), gui()]), rhs: chain(vec![m_p3()]), region: ext_g() },
            Expect::Holds,
        ),
        step("C6.1.4-case2-disk", "M_{π/3}(int(E_b)) = int(D), M_{π/3}(int(C)) = int(C)", StepCheck::DiskImage { map: vec![rot6(2)], disk: gb.clone(), claimed: d.clone() }, Expect::Holds),
        step("C6.1.4-case2-h", "h = h⁻¹", StepCheck::AffineEq { lhs: vec![h(), h()], rhs: vec![] }, Expect::Holds),
        step("C6.1.4-case2", "case (2): φ_wu(q) = R_(w,u)⁻¹∘g_w⁻¹∘h⁻¹∘M_{π/3}(q')", derived(&["C6.1.4-case2-rot", "C6.1.4-case2-conj", "C6.1.4-case2-disk", "C6.1.4-case2-h"]), Expect::Holds),
        // case (3)
        step("C6.1.4-case3-def", "φ_wx(q) = R_(w,x)⁻¹∘g_w⁻¹∘h∘g_x∘R_(x,w)(q)", StepCheck::Definition, Expect::Definition),
        step(
            "C6.1.4-case3-region",
            "for q' ∈ D∩E_b: h⁻¹(q') ∈ C∩F, M_{−π/3}(C∩F) = C∩D and h(C∩D) = C∩D, so the arguments below have the stated angles",
            StepCheck::Fact(
                disk_eq(&[h()], &d, &c) && disk_eq(&[h()], &gb, &disks::f()) && disk_eq(&[rot6(-2)], &disks::f(), &d) && disk_eq(&[rot6(-2)], &c, &c),
                "h(D) = C, h(E_b) = F, M_{−π/3}(F) = D, M_{−π/3}(C) = C".into(),
            ),
            Expect::Holds,
        ),
        step(
            "C6.1.4-case3-sub-w",
            "R_(w,x)⁻¹∘g_w⁻¹ = R_(w,u)⁻¹∘g_w⁻¹∘M_{−π/3} (Prop. 4.2.4) on h∘g_x∘R_(x,w)(q) ∈ C∩D (|θ| < π/3)",
            StepCheck::PolarEq { lhs: chain(vec![rwx_i(), gwi()]), rhs: chain(vec![rwu_i(), gwi(), m_m3()]), region: ext_d() },
            Expect::Holds,
        ),
        step(
            "C6.1.4-case3-sub-x",
            "R_(x,u)⁻¹∘g_x⁻¹ = R_(x,w)⁻¹∘g_x⁻¹∘M_{−π/3} (Prop. 4.2.4) on h⁻¹(q') ∈ C∩F (θ ∈ (0, 2π/3))",
            StepCheck::PolarEq { lhs: chain(vec![rxu_i(), gxi()]), rhs: chain(vec![rxw_i(), gxi(), m_m3()]), region: ext_f() },
            Expect::Holds,
        ),
        step(
            "C6.1.4-case3-cancel",
            "g_x∘R_(x,w)∘R_(x,w)⁻¹∘g_x⁻¹ = id on M_{−π/3}∘h⁻¹(q') ∈ C∩D",
            StepCheck::PolarEq { lhs: chain(vec![gx(), rxw(), rxw_i(), gxi()]), rhs: chain(vec![]), region: ext_d() },
            Expect::Holds,
        ),
        step(
            "C6.1.4-case3-h3",
            "h = M_{−π/3}∘h∘M_{−π/3}∘h∘M_{−π/3} and h = h⁻¹",
            StepCheck::AffineEq { lhs: vec![rot6(-2), h(), rot6(-2), h(), rot6(-2)], rhs: vec![h()] },
            Expect::Holds,
        ),
        step(
            "C6.1.4-case3-text",
            "h∘M_{π/3} = M_{−π/3}∘h∘M_{−π/3}∘h⁻¹ (the text's conclusion)",
            StepCheck::AffineEq { lhs: vec![h(), rot6(2)], rhs: vec![rot6(-2), h(), rot6(-2), h()] },
            Expect::Holds,
        ),
        step(
            "C6.1.4-case3-last-as-written",
            "last displayed line: M_{−π/3}∘h∘M_{−π/3}∘h⁻¹ = h∘M_{−π/3}",
            StepCheck::AffineEq { lhs: vec![rot6(-2), h(), rot6(-2), h()], rhs: vec![h(), rot6(-2)] },
            Expect::Fails,
        ),
        step(
            "C6.1.4-case3",
            "case (3): φ_wx(q) = R_(w,u)⁻¹∘g_w⁻¹∘h⁻¹∘M_{π/3}(q') (with the text's h∘M_{π/3})",
            derived(&["C6.1.4-case3-region", "C6.1.4-case3-sub-w", "C6.1.4-case3-sub-x", "C6.1.4-case3-cancel", "C6.1.4-case3-h3", "C6.1.4-case3-text"]),
            Expect::Holds,
        ),
        step("C6.1.4-case4", "case (4) q' ∈ C∩D∩E_b follows from cases (1)–(3)", derived(&["C6.1.4-case1", "C6.1.4-case2", "C6.1.4-case3"]), Expect::Holds),
    ]);
    s
}

fn configs() -> Vec<Tri> {
    let mut v = Vec::new();
    for mu in 3..=MAX_DEG {
        for mw in [3, 6, 7, mu] {
            for mx in [3, 6, 7, mu] {
                for (i, j, k) in [(0, 0, 0), (mu - 1, mw - 1, mx - 1)] {
                    v.push(Tri {
                        mu,
                        mw,
                        mx,
                        i,
                        j,
                        k,
                    });
                }
            }
        }
    }
    v.extend(Tri::all(&[3, 5], true));
    v
}

fn replay_case(which: &str) -> u64 {
    let mut n = 0;
    for t in configs() {
        let steps = eval_steps(t);
        assert_replay(&format!("Sec. 6.1.4 {t:?}"), &steps);
        let out = replay(&steps);
        let o = out
            .iter()
            .find(|o| o.id == which)
            .expect("case step exists");
        assert!(o.matches);
        n += 1;
    }
    let t = Tri {
        mu: 3,
        mw: 5,
        mx: 7,
        i: 1,
        j: 0,
        k: 2,
    };
    let steps = eval_steps(t);
    println!("{}", render(&steps, &replay(&steps)));
    n
}

/// Case (1) q' ∈ C∩D, replayed exactly over `configs`: m_u ∈ 3..=48 with m_w, m_x ∈
/// {3, 6, 7, m_u} and labels all 0 or all m − 1, plus every label of every triple in {3, 5}.
#[cfg_attr(kani, kani::proof)]
#[test]
fn c6_1_4_case1_proof_replays_exactly() {
    let n = replay_case("C6.1.4-case1");
    record("C6.1.4-case1(proof)", Seen::Holds, n);
}
/// Case (2) q' ∈ C∩E_b.
#[cfg_attr(kani, kani::proof)]
#[test]
fn c6_1_4_case2_proof_replays_exactly_with_rotation_corrected() {
    // The replay asserts the as-written steps fail (Expect::Fails unless m_u = 6) and the
    // corrected ones hold.
    let n = replay_case("C6.1.4-case2");
    record("C6.1.4-case2(proof)", Seen::Fails, n);
}
/// Case (3) q' ∈ D∩E_b.
#[cfg_attr(kani, kani::proof)]
#[test]
fn c6_1_4_case3_proof_replays_exactly_last_line_typo_found() {
    let n = replay_case("C6.1.4-case3");
    record("C6.1.4-case3(proof)", Seen::Holds, n);
}
/// Case (4) q' ∈ C∩D∩E_b.
#[cfg_attr(kani, kani::proof)]
#[test]
fn c6_1_4_case4_proof_replays_exactly() {
    let n = replay_case("C6.1.4-case4");
    record("C6.1.4-case4(proof)", Seen::Holds, n);
}

/// Planted fault: a wrong sign in one rotation fails the replay at that step.
#[cfg_attr(kani, kani::proof)]
#[test]
fn c6_1_4_planted_rotation_sign_error_fails_at_the_right_step() {
    let t = Tri {
        mu: 5,
        mw: 7,
        mx: 4,
        i: 1,
        j: 1,
        k: 1,
    };
    for id in [
        "C6.1.4-case2-conj",
        "C6.1.4-case3-sub-w",
        "C6.1.4-case3-sub-x",
        "C6.1.4-case2-rot",
        "C6.1.4-E-disk",
        "C6.1.4-case3-h3",
    ] {
        let mut steps = eval_steps(t);
        assert!(first_mismatch(&replay(&steps)).is_none());
        let st = steps.iter_mut().find(|s| s.id == id).expect("step exists");
        assert!(plant_sign_error(st), "{id}");
        let out = replay(&steps);
        assert_eq!(
            first_mismatch(&out).map(|o| o.id.as_str()),
            Some(id),
            "{}",
            render(&steps, &out)
        );
    }
    record("C6.1.4-planted", Seen::Caught, 6);
}
