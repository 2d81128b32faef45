//! Structure-aware: closed surfaces built from the tetrahedron, octahedron, icosahedron or a
//! small torus by random edge flips, edge splits and 1→3 splits (`mesh::generate::grow`, which
//! re-validates each step exactly), so every input reaches the DCEL, the labelling and the
//! Chapter 4 checks. Oracles: Euler characteristic preserved, validator accepts, DCEL and
//! Def. 4.1.4 invariants, Chapter 4 statements that hold do hold, and a corruption is rejected
//! with the expected error class.
#![no_main]
use arbitrary::Arbitrary;
use libfuzzer_sys::fuzz_target;
use pseudomanifold::mesh::generate::{self, Corruption, Expected, SurfaceOp};
use pseudomanifold::mesh::validate::validate;

#[derive(Arbitrary, Debug)]
enum Op {
    Flip(u16),
    SplitEdge(u16),
    SplitFace(u16),
    Raise(u8, u8),
}

#[derive(Arbitrary, Debug)]
enum Corrupt {
    None,
    Delete(u16),
    Duplicate(u16),
    Glue(u16),
    Flip(u16),
}

#[derive(Arbitrary, Debug)]
struct Input {
    base: u8,
    ops: Vec<Op>,
    corrupt: Corrupt,
    pick: u64,
}

fuzz_target!(|inp: Input| {
    let base = match inp.base % 5 {
        0 => generate::tetrahedron(),
        1 => generate::octahedron(),
        2 => generate::icosahedron(),
        3 => generate::torus(
            3 + (inp.base as u32 / 5) % 3,
            3 + (inp.base as u32 / 15) % 3,
        ),
        _ => generate::torus(4, 4),
    };
    let ops: Vec<SurfaceOp> = inp
        .ops
        .iter()
        .take(24)
        .map(|o| match *o {
            Op::Flip(k) => SurfaceOp::Flip(k as usize),
            Op::SplitEdge(k) => SurfaceOp::SplitEdge(k as usize),
            Op::SplitFace(k) => SurfaceOp::SplitFace(k as usize),
            Op::Raise(v, k) => SurfaceOp::Raise {
                v: v as usize,
                k: k as usize,
            },
        })
        .collect();
    let chi0 = generate::Surgery::new(&base).euler_characteristic();
    let (mut s, _) = generate::grow(&base, &ops);
    assert_eq!(s.euler_characteristic(), chi0, "surgery changed χ");
    let raw = s.to_raw();
    let surf = pseudomanifold_fuzz::validate_checked(&raw).expect("grow keeps a surface");
    let degrees = s.degrees();
    for v in surf.vertices() {
        assert_eq!(surf.degree(v), degrees[v.0 as usize]);
    }
    pseudomanifold_fuzz::chapter4_low_density(&surf, inp.pick, 2, 3);

    let c = match inp.corrupt {
        Corrupt::None => return,
        Corrupt::Delete(k) => Corruption::DeleteFace(k as usize),
        Corrupt::Duplicate(k) => Corruption::DuplicateFace(k as usize),
        Corrupt::Glue(k) => Corruption::GlueVertices(k as usize),
        Corrupt::Flip(k) => Corruption::FlipOrientation(k as usize),
    };
    let Some(expected) = s.corrupt(c) else {
        return; // e.g. no two vertices at distance ≥ 3 on a tetrahedron
    };
    let v = validate(&s.to_raw());
    match expected {
        Expected::Rejected(class) => {
            assert!(!v.report.is_simplicial_surface, "{c:?} accepted");
            assert!(
                v.report.error_classes.contains(&class),
                "{c:?}: expected {class:?}, got {:?}",
                v.report.error_classes
            );
        }
        Expected::Reoriented => {
            let surf = v
                .surface
                .expect("a reversed face is re-oriented, not rejected");
            let nf = surf.num_faces() as u64;
            assert!(surf.flipped_faces() == 1 || surf.flipped_faces() == nf - 1);
        }
    }
});
