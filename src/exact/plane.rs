//! Exact plane geometry over Q(√3): points, affine maps (rotations M_{kπ/3}, the double
//! reflection h of Def. 4.1.7, translations), open disks and open angular sectors.

use super::q3::{cos_sin_sixth_pi, Q3};
use std::cmp::Ordering;
use std::fmt;

/// A point (x, y) with coordinates in Q(√3).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Pt {
    /// x coordinate.
    pub x: Q3,
    /// y coordinate.
    pub y: Q3,
}

impl Pt {
    /// (x, y).
    pub fn new(x: Q3, y: Q3) -> Self {
        Pt { x, y }
    }
    /// The origin.
    pub fn origin() -> Self {
        Pt::new(Q3::zero(), Q3::zero())
    }
    /// Squared distance to `o`.
    pub fn dist2(&self, o: &Pt) -> Q3 {
        let dx = &self.x - &o.x;
        let dy = &self.y - &o.y;
        &(&dx * &dx) + &(&dy * &dy)
    }
    /// Cross product self × o.
    pub fn cross(&self, o: &Pt) -> Q3 {
        &(&self.x * &o.y) - &(&self.y * &o.x)
    }
}

impl fmt::Display for Pt {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "({}, {})", self.x, self.y)
    }
}

/// An affine map p ↦ L·p + t with L a 2×2 matrix over Q(√3).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Affine {
    /// Linear part, row-major.
    pub l: [[Q3; 2]; 2],
    /// Translation.
    pub t: Pt,
}

impl Affine {
    /// The identity.
    pub fn identity() -> Self {
        Affine::rot_sixths(0)
    }
    /// M_{kπ/6}: rotation about (0,0) by k·π/6 (so M_{−π/3} is `rot_sixths(-2)`).
    pub fn rot_sixths(k: i64) -> Self {
        let (c, s) = cos_sin_sixth_pi(k);
        Affine {
            l: [[c.clone(), -&s], [s, c]],
            t: Pt::origin(),
        }
    }
    /// Def. 4.1.7: h(x, y) = (1 − x, −y).
    pub fn h() -> Self {
        let m1 = -Q3::one();
        Affine {
            l: [[m1.clone(), Q3::zero()], [Q3::zero(), m1]],
            t: Pt::new(Q3::one(), Q3::zero()),
        }
    }
    /// The image of p.
    pub fn apply(&self, p: &Pt) -> Pt {
        let x = &(&(&self.l[0][0] * &p.x) + &(&self.l[0][1] * &p.y)) + &self.t.x;
        let y = &(&(&self.l[1][0] * &p.x) + &(&self.l[1][1] * &p.y)) + &self.t.y;
        Pt::new(x, y)
    }
    /// self ∘ o (apply `o` first).
    pub fn after(&self, o: &Affine) -> Affine {
        let mut l: [[Q3; 2]; 2] = [[Q3::zero(), Q3::zero()], [Q3::zero(), Q3::zero()]];
        for (i, row) in l.iter_mut().enumerate() {
            for (j, cell) in row.iter_mut().enumerate() {
                *cell = &(&self.l[i][0] * &o.l[0][j]) + &(&self.l[i][1] * &o.l[1][j]);
            }
        }
        // L(o.t) + t
        let lin = Affine {
            l: self.l.clone(),
            t: Pt::origin(),
        };
        let t0 = lin.apply(&o.t);
        Affine {
            l,
            t: Pt::new(&t0.x + &self.t.x, &t0.y + &self.t.y),
        }
    }
    /// The composite f₁ ∘ f₂ ∘ … ∘ fₙ of a list written in the paper's order.
    pub fn compose(maps: &[Affine]) -> Affine {
        maps.iter()
            .rev()
            .fold(Affine::identity(), |acc, f| f.after(&acc))
    }
    /// Whether L is orthogonal (LᵀL = I), i.e. the map is an isometry.
    pub fn is_isometry(&self) -> bool {
        let c0 = Pt::new(self.l[0][0].clone(), self.l[1][0].clone());
        let c1 = Pt::new(self.l[0][1].clone(), self.l[1][1].clone());
        let dot = &(&c0.x * &c1.x) + &(&c0.y * &c1.y);
        c0.dist2(&Pt::origin()) == Q3::one()
            && c1.dist2(&Pt::origin()) == Q3::one()
            && dot.is_zero()
    }
}

/// An open disk {p : |p − c|² < r2}.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Disk {
    /// Centre.
    pub c: Pt,
    /// Squared radius.
    pub r2: Q3,
}

impl Disk {
    /// The open disk of centre c and squared radius r2.
    pub fn new(c: Pt, r2: Q3) -> Self {
        Disk { c, r2 }
    }
    /// Strict membership.
    pub fn contains(&self, p: &Pt) -> bool {
        self.c.dist2(p).cmp_exact(&self.r2) == Ordering::Less
    }
    /// The image under an isometry (`None` if `f` is not an isometry).
    pub fn image(&self, f: &Affine) -> Option<Disk> {
        f.is_isometry()
            .then(|| Disk::new(f.apply(&self.c), self.r2.clone()))
    }
    /// Whether the open disk lies in the open half-plane to the left of the line through the
    /// origin with unit direction `u` (cross(u, p) > 0): cross(u, c) ≥ 0 and cross(u, c)² ≥ r².
    pub fn left_of(&self, u: &Pt) -> bool {
        let d = u.cross(&self.c);
        d.signum() != Ordering::Less && (&d * &d).cmp_exact(&self.r2) != Ordering::Less
    }
    /// Whether the open disk lies in the open sector {θ/π ∈ (lo/6, hi/6)} with
    /// 0 < hi − lo ≤ 6 (an angle of at most π): left of the ray at lo·π/6, right of the ray at
    /// hi·π/6.
    pub fn in_open_sector_sixths(&self, lo: i64, hi: i64) -> bool {
        if hi <= lo || hi - lo > 6 {
            return false;
        }
        let (c0, s0) = cos_sin_sixth_pi(lo);
        let (c1, s1) = cos_sin_sixth_pi(hi);
        let u1 = Pt::new(-c1, -s1);
        self.left_of(&Pt::new(c0, s0)) && self.left_of(&u1)
    }
}

impl fmt::Display for Disk {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "disk(centre {}, r² {})", self.c, self.r2)
    }
}

/// The disks of Sec. 4.1 (Fig. 4.4), Appendix A.1 (Figs. A.1, A.2) and Sec. 6.1.4 (Fig. 6.2):
/// all of radius cos(π/6) = √3/2.
pub mod disks {
    use super::*;
    fn r2() -> Q3 {
        Q3::frac(3, 4)
    }
    /// C: centre (0, 0) (Sec. 4.1; centre a of Sec. 6.1.4).
    pub fn c() -> Disk {
        Disk::new(Pt::origin(), r2())
    }
    /// D: centre (1, 0) (Sec. 4.1; centre c of Sec. 6.1.4).
    pub fn d() -> Disk {
        Disk::new(Pt::new(Q3::one(), Q3::zero()), r2())
    }
    /// F as the proof of Prop. 4.2.4 states it: centre (1/2, √3/2).
    pub fn f() -> Disk {
        Disk::new(Pt::new(Q3::frac(1, 2), Q3::sqrt3_times(1, 2)), r2())
    }
    /// G: centre (1/2, −√3/2) (proof of Lemma 4.2.1; the disk "E" centred at b in Sec. 6.1.4).
    pub fn g() -> Disk {
        Disk::new(Pt::new(Q3::frac(1, 2), Q3::sqrt3_times(-1, 2)), r2())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn h_is_an_involutive_isometry_and_rotations_compose() {
        let h = Affine::h();
        assert!(h.is_isometry());
        assert_eq!(h.after(&h), Affine::identity());
        assert_eq!(
            Affine::rot_sixths(2).after(&Affine::rot_sixths(-2)),
            Affine::identity()
        );
        assert_eq!(
            Affine::compose(&vec![Affine::rot_sixths(1); 12]),
            Affine::identity()
        );
        assert!(disks::d().in_open_sector_sixths(-2, 2));
        assert!(!disks::d().in_open_sector_sixths(-1, 1));
    }

    /// A small disk at angle π/4: inside the sector (0, π/2), and in neither (0, π/6) (left of
    /// its lower ray only) nor (π/3, π/2) (right of its upper ray only): both rays bound.
    /// `contains` is strict: the centre in, a point of the circle out.
    #[test]
    fn sectors_need_both_rays_and_disks_are_open() {
        let r2 = Q3::frac(1, 100);
        let disk = Disk::new(Pt::new(Q3::one(), Q3::one()), r2);
        assert!(disk.in_open_sector_sixths(0, 3));
        assert!(!disk.in_open_sector_sixths(0, 1));
        assert!(!disk.in_open_sector_sixths(2, 3));
        assert!(!disk.in_open_sector_sixths(3, 0));
        assert!(disk.contains(&Pt::new(Q3::one(), Q3::one())));
        assert!(!disk.contains(&Pt::new(Q3::frac(11, 10), Q3::one())));
    }
}
