//! Proofs as data: a proof is a list of [`Step`]s, each the paper's statement, an exact
//! [`StepCheck`] and the [`Expect`]ed verdict recorded by the replay. [`replay`] runs the checks
//! in order and reports, per step, the computed [`StepVerdict`] and whether it matches.

use super::plane::{Affine, Disk, Pt};
use super::polar::{compare, Chain, Region};
use super::q3::Q;
use std::collections::BTreeMap;
use std::fmt;

/// The exact check behind a step.
#[derive(Clone, Debug)]
pub enum StepCheck {
    /// A definition or notation; nothing to check.
    Definition,
    /// A set-theoretic consequence of earlier steps (by id): holds iff they all hold.
    Derived(Vec<String>),
    /// Two composites of affine maps over Q(√3) are equal (lists in the paper's order).
    AffineEq {
        /// Left side, f₁∘…∘fₙ.
        lhs: Vec<Affine>,
        /// Right side.
        rhs: Vec<Affine>,
    },
    /// The image of an open disk under a composite of isometries is the claimed disk.
    DiskImage {
        /// The composite (paper's order).
        map: Vec<Affine>,
        /// The disk.
        disk: Disk,
        /// The claimed image.
        claimed: Disk,
    },
    /// A point is not in an open disk.
    PointOutside {
        /// The point.
        point: Pt,
        /// The disk.
        disk: Disk,
    },
    /// An open disk lies in the open sector {θ/π ∈ (lo/6, hi/6)}.
    DiskInSector {
        /// The disk.
        disk: Disk,
        /// Lower bounding ray, in sixths of π.
        lo: i64,
        /// Upper bounding ray, in sixths of π.
        hi: i64,
    },
    /// Sum of rotation angles (in units of π) equal mod 2.
    RotEq {
        /// Angles on the left, composed.
        lhs: Vec<Q>,
        /// Angles on the right, composed.
        rhs: Vec<Q>,
    },
    /// Pointwise identity of two polar-affine chains on a t-region (the region the proof uses);
    /// the check includes every Π wrap along both chains.
    PolarEq {
        /// Left chain.
        lhs: Chain,
        /// Right chain.
        rhs: Chain,
        /// Region of t = θ/π where the proof uses the identity.
        region: Region,
    },
    /// Pointwise identity as in `PolarEq`, read as a set identity lhs(X) = rhs(X) for a set X
    /// with angular extent `region` whose right-hand image has angular extent within
    /// `rhs_extent`: fails when part of lhs(X) lands outside `rhs_extent`.
    PolarSetEq {
        /// Left chain.
        lhs: Chain,
        /// Right chain.
        rhs: Chain,
        /// Angular extent of X.
        region: Region,
        /// Angular extent of rhs(X) (upper bound).
        rhs_extent: Region,
    },
    /// chain(domain) covers `target` (angles mod 2); fails on the uncovered part of `target`.
    PolarCovers {
        /// The chain.
        chain: Chain,
        /// Region of t.
        domain: Region,
        /// Region of output angles.
        target: Region,
    },
    /// chain maps `domain` into `target`; fails on the part of `domain` mapped outside.
    PolarInto {
        /// The chain.
        chain: Chain,
        /// Region of t.
        domain: Region,
        /// Region of output angles.
        target: Region,
    },
    /// chain is injective on `domain`; fails on the points sharing their image.
    PolarInjective {
        /// The chain.
        chain: Chain,
        /// Region of t.
        domain: Region,
    },
    /// An exact fact computed by the caller (e.g. a combination of the above).
    Fact(bool, String),
}

/// The computed outcome of a step.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum StepVerdict {
    /// A definition, not checked.
    Definition,
    /// Holds exactly on everything the proof claims.
    Holds,
    /// Holds exactly on `holds`, fails on the non-empty `fails` (t = θ/π, or output angle for
    /// `PolarCovers`), both inside the claimed region.
    HoldsOn {
        /// Where it holds.
        holds: Region,
        /// Where it fails.
        fails: Region,
    },
    /// Fails (exact counter-fact).
    Fails(String),
    /// Derived from premises of which these do not hold.
    Inherits(Vec<String>),
}

impl fmt::Display for StepVerdict {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            StepVerdict::Definition => write!(f, "definition"),
            StepVerdict::Holds => write!(f, "holds"),
            StepVerdict::HoldsOn { holds, fails } => {
                write!(f, "FAILS on θ/π ∈ {fails} (holds on {holds})")
            }
            StepVerdict::Fails(s) => write!(f, "FAILS: {s}"),
            StepVerdict::Inherits(v) => write!(f, "unsupported: premise(s) {} fail", v.join(", ")),
        }
    }
}

/// The verdict recorded for a step.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Expect {
    /// Definition.
    Definition,
    /// Holds.
    Holds,
    /// Fails exactly on this region.
    FailsOn(Region),
    /// Fails (non-region counter-fact).
    Fails,
    /// Unsupported because a premise fails.
    Inherits,
}

/// One step of a proof.
#[derive(Clone, Debug)]
pub struct Step {
    /// Step id (e.g. `P4.2.4-s10`).
    pub id: String,
    /// The paper's statement at this step.
    pub claim: String,
    /// The exact check.
    pub check: StepCheck,
    /// The recorded verdict.
    pub expect: Expect,
}

impl Step {
    /// A step.
    pub fn new(id: &str, claim: &str, check: StepCheck, expect: Expect) -> Self {
        Step {
            id: id.to_string(),
            claim: claim.to_string(),
            check,
            expect,
        }
    }
}

/// The replay of one step.
#[derive(Clone, Debug)]
pub struct StepOutcome {
    /// Step id.
    pub id: String,
    /// Computed verdict.
    pub verdict: StepVerdict,
    /// Whether it matches the recorded verdict.
    pub matches: bool,
    /// Extra exact detail (failing pieces, wraps).
    pub detail: Vec<String>,
}

fn from_regions(holds: Region, fails: Region) -> StepVerdict {
    if fails.is_empty() {
        StepVerdict::Holds
    } else {
        StepVerdict::HoldsOn { holds, fails }
    }
}

/// Run one check; `done` holds the verdicts of the earlier steps.
pub fn run_check(
    check: &StepCheck,
    done: &BTreeMap<String, StepVerdict>,
) -> (StepVerdict, Vec<String>) {
    match check {
        StepCheck::Definition => (StepVerdict::Definition, vec![]),
        StepCheck::Derived(ids) => {
            let bad: Vec<String> = ids
                .iter()
                .filter(|i| {
                    !matches!(
                        done.get(*i),
                        Some(StepVerdict::Holds | StepVerdict::Definition)
                    )
                })
                .cloned()
                .collect();
            if bad.is_empty() {
                (StepVerdict::Holds, vec![])
            } else {
                (StepVerdict::Inherits(bad), vec![])
            }
        }
        StepCheck::AffineEq { lhs, rhs } => {
            let (l, r) = (Affine::compose(lhs), Affine::compose(rhs));
            if l == r {
                (StepVerdict::Holds, vec![])
            } else {
                let p = Pt::origin();
                (
                    StepVerdict::Fails(format!(
                        "lhs(0,0) = {}, rhs(0,0) = {}; lhs ≠ rhs",
                        l.apply(&p),
                        r.apply(&p)
                    )),
                    vec![format!("{l:?} vs {r:?}")],
                )
            }
        }
        StepCheck::DiskImage { map, disk, claimed } => match disk.image(&Affine::compose(map)) {
            Some(img) if &img == claimed => (StepVerdict::Holds, vec![]),
            Some(img) => (
                StepVerdict::Fails(format!("image is {img}, not {claimed}")),
                vec![],
            ),
            None => (StepVerdict::Fails("map is not an isometry".into()), vec![]),
        },
        StepCheck::PointOutside { point, disk } => {
            if disk.contains(point) {
                (StepVerdict::Fails(format!("{point} ∈ {disk}")), vec![])
            } else {
                (StepVerdict::Holds, vec![])
            }
        }
        StepCheck::DiskInSector { disk, lo, hi } => {
            if disk.in_open_sector_sixths(*lo, *hi) {
                (StepVerdict::Holds, vec![])
            } else {
                (
                    StepVerdict::Fails(format!("{disk} ⊄ sector ({lo}/6, {hi}/6)")),
                    vec![],
                )
            }
        }
        StepCheck::RotEq { lhs, rhs } => {
            let s = |v: &Vec<Q>| v.iter().fold(Q::from_integer(0.into()), |a, b| a + b);
            let d = (s(lhs) - s(rhs)) / Q::from_integer(2.into());
            if d.denom() == &1.into() {
                (StepVerdict::Holds, vec![])
            } else {
                let diff = s(lhs) - s(rhs);
                let two = Q::from_integer(2.into());
                let red = &diff - &two * (&diff / &two).floor();
                (
                    StepVerdict::Fails(format!("angles differ by {red}·π (mod 2π)")),
                    vec![],
                )
            }
        }
        StepCheck::PolarEq { lhs, rhs, region } => {
            let c = compare(lhs, rhs, region);
            (from_regions(c.holds, c.fails), c.detail)
        }
        StepCheck::PolarSetEq {
            lhs,
            rhs,
            region,
            rhs_extent,
        } => {
            let c = compare(lhs, rhs, region);
            if c.fails.is_empty() {
                return (StepVerdict::Holds, c.detail);
            }
            let escapes = c.fails_lhs_image.minus(rhs_extent);
            let mut d = c.detail;
            d.push(format!("lhs image of the failing part: θ/π ∈ {}; outside rhs extent {rhs_extent}: {escapes}", c.fails_lhs_image));
            if escapes.is_empty() {
                d.push(
                    "the failing part stays inside the claimed set: pointwise failure only".into(),
                );
            } else {
                d.push("so the set identity fails: lhs(X) has points outside rhs(X)".into());
            }
            (
                StepVerdict::HoldsOn {
                    holds: c.holds,
                    fails: c.fails,
                },
                d,
            )
        }
        StepCheck::PolarCovers {
            chain,
            domain,
            target,
        } => {
            let img = chain.image(domain);
            let uncovered = target.minus(&img);
            (
                from_regions(target.intersect(&img), uncovered),
                vec![format!("image θ/π ∈ {img}")],
            )
        }
        StepCheck::PolarInto {
            chain,
            domain,
            target,
        } => {
            let mut bad = Vec::new();
            for p in chain.eval(domain) {
                {
                    let part = &p.dom;
                    let img = Region::of(part.affine_image(&p.a, &p.b)).mod2();
                    for o in img.minus(target).0 {
                        // pull back each escaping angle interval (all shifts)
                        for k in -4i64..=4 {
                            bad.push(part.preimage(
                                &p.a,
                                &p.b,
                                &o.shift(&Q::from_integer((2 * k).into())),
                            ));
                        }
                    }
                }
            }
            let bad = Region::from_intervals(bad);
            (
                from_regions(domain.minus(&bad), bad),
                vec![format!("image θ/π ∈ {}", chain.image(domain))],
            )
        }
        StepCheck::PolarInjective { chain, domain } => {
            let bad = chain.non_injective(domain);
            (from_regions(domain.minus(&bad), bad), vec![])
        }
        StepCheck::Fact(ok, why) => {
            if *ok {
                (StepVerdict::Holds, vec![why.clone()])
            } else {
                (StepVerdict::Fails(why.clone()), vec![])
            }
        }
    }
}

fn matches(v: &StepVerdict, e: &Expect) -> bool {
    match (v, e) {
        (StepVerdict::Definition, Expect::Definition) | (StepVerdict::Holds, Expect::Holds) => true,
        (StepVerdict::HoldsOn { fails, .. }, Expect::FailsOn(r)) => fails == r,
        (StepVerdict::Fails(_), Expect::Fails) | (StepVerdict::Inherits(_), Expect::Inherits) => {
            true
        }
        _ => false,
    }
}

/// Replay the steps in order.
pub fn replay(steps: &[Step]) -> Vec<StepOutcome> {
    let mut done = BTreeMap::new();
    let mut out = Vec::new();
    for s in steps {
        let (verdict, detail) = run_check(&s.check, &done);
        let ok = matches(&verdict, &s.expect);
        done.insert(s.id.clone(), verdict.clone());
        out.push(StepOutcome {
            id: s.id.clone(),
            verdict,
            matches: ok,
            detail,
        });
    }
    out
}

/// The id of the first step whose computed verdict differs from the recorded one.
pub fn first_mismatch(outcomes: &[StepOutcome]) -> Option<&StepOutcome> {
    outcomes.iter().find(|o| !o.matches)
}

/// A printable table of a replay.
pub fn render(steps: &[Step], outcomes: &[StepOutcome]) -> String {
    let mut s = String::new();
    for (st, o) in steps.iter().zip(outcomes) {
        s.push_str(&format!(
            "{} {:<22} {}\n    ⇒ {}\n",
            if o.matches { "ok " } else { "XX " },
            o.id,
            st.claim,
            o.verdict
        ));
        for d in &o.detail {
            s.push_str(&format!("      · {d}\n"));
        }
    }
    s
}

/// Plant a sign error in the first rotation of a step's check (for the planted-fault tests):
/// the first rotation of a polar chain or of an affine composite is replaced by its inverse,
/// or the first angle of a `RotEq` is negated. Returns whether anything was changed.
pub fn plant_sign_error(step: &mut Step) -> bool {
    fn flip_chain(c: &mut Chain) -> bool {
        for m in c.0.iter_mut() {
            if matches!(m, super::polar::PMap::Rot { .. }) {
                *m = m.sign_flipped();
                return true;
            }
        }
        false
    }
    fn flip_affine(v: &mut [Affine]) -> bool {
        for a in v.iter_mut() {
            if a.t == Pt::origin() && *a != Affine::identity() && a.is_isometry() {
                let l = a.l.clone();
                a.l = [
                    [l[0][0].clone(), l[1][0].clone()],
                    [l[0][1].clone(), l[1][1].clone()],
                ];
                return true;
            }
        }
        false
    }
    match &mut step.check {
        StepCheck::PolarEq { lhs, .. } | StepCheck::PolarSetEq { lhs, .. } => flip_chain(lhs),
        StepCheck::PolarCovers { chain, .. } | StepCheck::PolarInto { chain, .. } => {
            flip_chain(chain)
        }
        StepCheck::RotEq { lhs, .. } => match lhs.first_mut() {
            Some(a) => {
                *a = -a.clone();
                true
            }
            None => false,
        },
        StepCheck::AffineEq { lhs, .. } => flip_affine(lhs),
        StepCheck::DiskImage { map, .. } => flip_affine(map),
        _ => false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exact::q3::q;

    fn rot_eq(lhs: Vec<(i64, i64)>, rhs: Vec<(i64, i64)>) -> StepVerdict {
        let v = |x: Vec<(i64, i64)>| -> Vec<Q> { x.into_iter().map(|(n, d)| q(n, d)).collect() };
        run_check(
            &StepCheck::RotEq {
                lhs: v(lhs),
                rhs: v(rhs),
            },
            &BTreeMap::new(),
        )
        .0
    }

    /// Every kind of step both ways, with the exact region where it fails: a check that
    /// could only hold (or only fail) on the paper's configurations fails here.
    #[test]
    fn every_step_kind_holds_and_fails_where_it_should() {
        use crate::exact::polar::{Chain, Interval, PMap};
        use crate::exact::q3::Q3;
        let none = BTreeMap::new();
        let run = |c: StepCheck| run_check(&c, &none).0;
        let fails_on = |holds: Region, fails: Region| StepVerdict::HoldsOn { holds, fails };
        let pi = || Region::of(Interval::pi_range());
        let g = |m| Chain(vec![PMap::g("g", m)]);
        // Derived: holds when every premise holds or is a definition, else names the others.
        let mut done = BTreeMap::new();
        done.insert("a".to_string(), StepVerdict::Holds);
        done.insert("b".to_string(), StepVerdict::Definition);
        done.insert("c".to_string(), StepVerdict::Fails("x".into()));
        let derived = |ids: &[&str]| {
            run_check(
                &StepCheck::Derived(ids.iter().map(|s| s.to_string()).collect()),
                &done,
            )
            .0
        };
        assert_eq!(derived(&["a", "b"]), StepVerdict::Holds);
        assert_eq!(
            derived(&["a", "c", "z"]),
            StepVerdict::Inherits(vec!["c".into(), "z".into()])
        );
        // Affine identities: h ∘ h = id, M_{π/6} ≠ id.
        let affine = |lhs, rhs| run(StepCheck::AffineEq { lhs, rhs });
        assert_eq!(
            affine(vec![Affine::h(), Affine::h()], vec![Affine::identity()]),
            StepVerdict::Holds
        );
        assert!(matches!(
            affine(vec![Affine::rot_sixths(1)], vec![]),
            StepVerdict::Fails(_)
        ));
        // Disk images: a disk rotated by π, the right claim, a wrong one, a map that is no
        // isometry.
        let disk = Disk::new(Pt::new(Q3::one(), Q3::one()), Q3::frac(1, 4));
        let image = |map, claimed| {
            run(StepCheck::DiskImage {
                map,
                disk: disk.clone(),
                claimed,
            })
        };
        let turned = Disk::new(Pt::new(-Q3::one(), -Q3::one()), Q3::frac(1, 4));
        assert_eq!(
            image(vec![Affine::rot_sixths(6)], turned.clone()),
            StepVerdict::Holds
        );
        assert!(matches!(
            image(vec![Affine::rot_sixths(3)], turned.clone()),
            StepVerdict::Fails(s) if s.starts_with("image is")
        ));
        let mut stretch = Affine::identity();
        stretch.l[0][0] = Q3::frac(2, 1);
        assert_eq!(
            image(vec![stretch], turned),
            StepVerdict::Fails("map is not an isometry".into())
        );
        // A sector check both ways.
        let sector = |lo, hi| {
            run(StepCheck::DiskInSector {
                disk: disk.clone(),
                lo,
                hi,
            })
        };
        assert_eq!(sector(0, 3), StepVerdict::Holds);
        assert!(matches!(sector(0, 1), StepVerdict::Fails(_)));
        // Pointwise identities of chains: g_6 is Π (the identity on (−1, 1]); g_3 halves t and
        // takes the square root of the radius, so it agrees with the identity nowhere.
        let eq = |lhs, region| {
            run(StepCheck::PolarEq {
                lhs,
                rhs: Chain(vec![]),
                region,
            })
        };
        assert_eq!(eq(g(6), pi()), StepVerdict::Holds);
        let half = Region::of(Interval::open(q(-1, 2), q(1, 2)));
        assert_eq!(
            eq(g(3), half.clone()),
            fails_on(Region::empty(), half.clone())
        );
        // Covers: g_7 covers all angles from (−1, 1]; g_3 of (−1/2, 1/2) is (−1/4, 1/4).
        let covers = |chain, domain| {
            run(StepCheck::PolarCovers {
                chain,
                domain,
                target: Region::of(Interval::open(q(-1, 2), q(1, 2))),
            })
        };
        assert_eq!(covers(g(7), pi()), StepVerdict::Holds);
        assert_eq!(
            covers(g(3), half.clone()),
            fails_on(
                Region::of(Interval::open(q(-1, 4), q(1, 4))),
                Region::from_intervals(vec![
                    Interval::open_closed(q(-1, 2), q(-1, 4)),
                    Interval::closed_open(q(1, 4), q(1, 2)),
                ])
            )
        );
        // Into: g_3 maps (−1, 1] into (−1/2, 1/2], and into (−1/4, 1/4) only for |t| < 1/2.
        let into = |target| {
            run(StepCheck::PolarInto {
                chain: g(3),
                domain: pi(),
                target,
            })
        };
        assert_eq!(
            into(Region::of(Interval::open_closed(q(-1, 2), q(1, 2)))),
            StepVerdict::Holds
        );
        assert_eq!(
            into(Region::of(Interval::open(q(-1, 4), q(1, 4)))),
            fails_on(
                Region::of(Interval::open(q(-1, 2), q(1, 2))),
                Region::from_intervals(vec![
                    Interval::open_closed(q(-1, 1), q(-1, 2)),
                    Interval::closed(q(1, 2), q(1, 1)),
                ])
            )
        );
        // Injective: g_6 is, g_7 is not on (−1, −5/7] ∪ (5/7, 1].
        let injective = |chain| {
            run(StepCheck::PolarInjective {
                chain,
                domain: pi(),
            })
        };
        assert_eq!(injective(g(6)), StepVerdict::Holds);
        assert_eq!(
            injective(g(7)),
            fails_on(
                Region::of(Interval::open_closed(q(-5, 7), q(5, 7))),
                Region::from_intervals(vec![
                    Interval::open_closed(q(-1, 1), q(-5, 7)),
                    Interval::open_closed(q(5, 7), q(1, 1)),
                ])
            )
        );
        // Facts.
        assert_eq!(run(StepCheck::Fact(true, "y".into())), StepVerdict::Holds);
        assert_eq!(
            run(StepCheck::Fact(false, "n".into())),
            StepVerdict::Fails("n".into())
        );
    }

    /// A set identity fails only where the left image leaves the right side's extent; a
    /// pointwise failure inside it is said to be one.
    #[test]
    fn set_identity_fails_only_outside_the_right_extent() {
        use crate::exact::polar::{Chain, Interval, PMap};
        let set_eq = |extent| {
            run_check(
                &StepCheck::PolarSetEq {
                    lhs: Chain(vec![PMap::g("g", 3)]),
                    rhs: Chain(vec![]),
                    region: Region::of(Interval::open(q(0, 1), q(1, 2))),
                    rhs_extent: extent,
                },
                &BTreeMap::new(),
            )
        };
        let (v, d) = set_eq(Region::of(Interval::open(q(0, 1), q(1, 2))));
        assert!(matches!(v, StepVerdict::HoldsOn { .. }), "{v}");
        assert!(
            d.iter().any(|s| s.contains("pointwise failure only")),
            "{d:?}"
        );
        let (_, d) = set_eq(Region::of(Interval::open(q(1, 8), q(1, 2))));
        assert!(
            d.iter().any(|s| s.contains("the set identity fails")),
            "{d:?}"
        );
        let (v, _) = run_check(
            &StepCheck::PolarSetEq {
                lhs: Chain(vec![PMap::g("g", 6)]),
                rhs: Chain(vec![]),
                region: Region::of(Interval::pi_range()),
                rhs_extent: Region::of(Interval::pi_range()),
            },
            &BTreeMap::new(),
        );
        assert_eq!(v, StepVerdict::Holds);
    }

    /// Replay's match of a computed verdict against the recorded one: a failure matches
    /// `FailsOn` only on exactly that region, and a definition only a definition.
    #[test]
    fn replay_matches_recorded_verdicts_exactly() {
        use crate::exact::polar::{Chain, Interval, PMap};
        let bad = Region::from_intervals(vec![
            Interval::open_closed(q(-1, 1), q(-5, 7)),
            Interval::open_closed(q(5, 7), q(1, 1)),
        ]);
        let inj = || StepCheck::PolarInjective {
            chain: Chain(vec![PMap::g("g", 7)]),
            domain: Region::of(Interval::pi_range()),
        };
        let steps = vec![
            Step::new("1", "", inj(), Expect::FailsOn(bad)),
            Step::new(
                "2",
                "",
                inj(),
                Expect::FailsOn(Region::of(Interval::pi_range())),
            ),
            Step::new("3", "", StepCheck::Definition, Expect::Definition),
            Step::new("4", "", StepCheck::Definition, Expect::Holds),
            Step::new(
                "5",
                "",
                StepCheck::Derived(vec!["2".into()]),
                Expect::Inherits,
            ),
            Step::new("6", "", StepCheck::Fact(false, "n".into()), Expect::Fails),
        ];
        let out = replay(&steps);
        let m: Vec<bool> = out.iter().map(|o| o.matches).collect();
        assert_eq!(m, [true, false, true, false, true, true]);
        assert_eq!(first_mismatch(&out).map(|o| o.id.as_str()), Some("2"));
    }

    /// The printed table: per step a mark (ok / XX against the recorded verdict), its id, the
    /// paper's claim and the computed verdict, then the details.
    #[test]
    fn render_lists_each_step_with_its_mark_claim_and_verdict() {
        let steps = vec![
            Step::new(
                "S-1",
                "a full turn is the identity",
                StepCheck::RotEq {
                    lhs: vec![q(2, 1)],
                    rhs: vec![],
                },
                Expect::Holds,
            ),
            Step::new(
                "S-2",
                "π/2 is π/4",
                StepCheck::RotEq {
                    lhs: vec![q(1, 2)],
                    rhs: vec![q(1, 4)],
                },
                Expect::Holds,
            ),
        ];
        let mut out = replay(&steps);
        out[1].detail.push("a detail".into());
        let text = render(&steps, &out);
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines.len(), 5, "{text}");
        assert!(
            lines[0].starts_with("ok ") && lines[0].contains("S-1"),
            "{text}"
        );
        assert!(lines[0].contains("a full turn is the identity"), "{text}");
        assert!(lines[1].contains("⇒ holds"), "{text}");
        assert!(
            lines[2].starts_with("XX ") && lines[2].contains("S-2"),
            "{text}"
        );
        assert!(lines[3].contains("FAILS: angles differ by 1/4·π"), "{text}");
        assert!(lines[4].contains("· a detail"), "{text}");
    }

    /// `PointOutside` is strict membership in an open disk: the centre fails the step with
    /// the point named, a point on the circle and one beyond it hold.
    #[test]
    fn point_outside_fails_inside_the_open_disk_only() {
        use crate::exact::q3::Q3;
        let disk = Disk::new(Pt::origin(), Q3::one());
        let step = |point: Pt| {
            run_check(
                &StepCheck::PointOutside {
                    point,
                    disk: disk.clone(),
                },
                &BTreeMap::new(),
            )
            .0
        };
        match step(Pt::new(Q3::frac(1, 2), Q3::zero())) {
            StepVerdict::Fails(s) => assert!(s.contains('∈'), "{s}"),
            v => panic!("a point inside the unit disk taken for outside: {v}"),
        }
        assert_eq!(step(Pt::new(Q3::one(), Q3::zero())), StepVerdict::Holds);
        assert_eq!(step(Pt::new(Q3::frac(3, 2), Q3::one())), StepVerdict::Holds);
    }

    #[test]
    fn rotation_equality_is_mod_two_pi_and_reports_the_reduced_difference() {
        // Angles in units of π: 1/3 + 2/3 = 1 ≡ 1 − 2 = −1, but 1 ≢ 0.
        assert_eq!(
            rot_eq(vec![(1, 3), (2, 3)], vec![(-1, 1)]),
            StepVerdict::Holds
        );
        assert_eq!(rot_eq(vec![(3, 1)], vec![(1, 1)]), StepVerdict::Holds);
        match rot_eq(vec![(1, 1)], vec![]) {
            StepVerdict::Fails(s) => assert!(s.contains("by 1·π"), "{s}"),
            v => panic!("a rotation by π taken for the identity: {v}"),
        }
        // The witness is the difference reduced into [0, 2): 5/2 ≡ 1/2.
        match rot_eq(vec![(5, 2)], vec![]) {
            StepVerdict::Fails(s) => assert!(s.contains("by 1/2·π"), "{s}"),
            v => panic!("5π/2 taken for a multiple of 2π: {v}"),
        }
        // The witness is lhs − rhs: 1/2 − 1/4 = 1/4 (the sum would say 3/4).
        match rot_eq(vec![(1, 2)], vec![(1, 4)]) {
            StepVerdict::Fails(s) => assert!(s.contains("by 1/4·π"), "{s}"),
            v => panic!("π/2 taken for π/4: {v}"),
        }
    }
}
