#!/usr/bin/env python3
"""Writes the tetrahedral fixtures of the seed-004 3-D rows (SD-…(3-D)); run from the crate
root: python3 tests/data/sdiff/gen_tets.py. Authored for this project; the crate's licence."""
from fractions import Fraction as F
from itertools import permutations, product
import os

HERE = os.path.dirname(os.path.abspath(__file__))


def det3(u, v, w):
    return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
            + u[2] * (v[0] * w[1] - v[1] * w[0]))


def orient(pts, t):
    a, b, c, d = (pts[i] for i in t)
    sub = lambda p, q: [p[k] - q[k] for k in range(3)]
    return det3(sub(b, a), sub(c, a), sub(d, a))


def positive(pts, t):
    t = list(t)
    o = orient(pts, t)
    assert o != 0, t
    if o < 0:
        t[2], t[3] = t[3], t[2]
    return t


def write(name, comment, pts, tets):
    with open(os.path.join(HERE, name), "w") as f:
        f.write("tets\n")
        for line in comment.strip().splitlines():
            f.write(f"# {line}\n")
        for p in pts:
            f.write("v {} {} {}\n".format(*p))
        for t in tets:
            f.write("t {} {} {} {}\n".format(*t))


def kuhn(cells):
    """Kuhn triangulation (6 tetrahedra per unit cube) of the given unit cubes."""
    index, pts, tets = {}, [], []

    def vid(p):
        if p not in index:
            index[p] = len(pts)
            pts.append(p)
        return index[p]

    for z0 in cells:
        for perm in permutations(range(3)):
            v = list(z0)
            chain = [tuple(v)]
            for axis in perm:
                v[axis] += 1
                chain.append(tuple(v))
            tets.append([vid(p) for p in chain])
    tets = [positive(pts, t) for t in tets]
    return pts, tets


# The unit cube in 5 tetrahedra: the central one on the even corners and 4 corner tetrahedra.
cube = [p for p in product((0, 1), repeat=3)]
cube = sorted(cube, key=lambda p: (p[2], p[1], p[0]))
idx = {p: i for i, p in enumerate(cube)}
even = [p for p in cube if sum(p) % 2 == 0]
odd = [p for p in cube if sum(p) % 2 == 1]
tets5 = [positive(cube, [idx[p] for p in even])]
for o in odd:
    nb = [p for p in cube if sum(abs(p[k] - o[k]) for k in range(3)) == 1]
    tets5.append(positive(cube, [idx[o]] + [idx[p] for p in nb]))
write("cube5.tets", "The unit cube in 5 tetrahedra (central one on the even corners).", cube, tets5)

pts, tets = kuhn([(0, 0, 0)])
write("cube6.tets", "The unit cube in 6 Kuhn tetrahedra around the diagonal (0,0,0)-(1,1,1).", pts, tets)

pts, tets = kuhn(list(product(range(2), repeat=3)))
write("kuhn222.tets", "The cube [0,2]^3 as 2x2x2 unit cubes, 6 Kuhn tetrahedra each (48).", pts, tets)

pts, tets = kuhn([(0, 0, 0), (1, 0, 0), (0, 1, 0)])
write("lshape.tets", "An L of three unit cubes (non-convex boundary), 18 Kuhn tetrahedra.", pts, tets)


def frac(x):
    x = F(x)
    return f'"{x.numerator}/{x.denominator}"' if x.denominator != 1 else f'"{x.numerator}"'


def toml_file(name, header, body):
    with open(os.path.join(HERE, name), "w") as f:
        for line in header.strip().splitlines():
            f.write(f"# {line}\n")
        f.write(body)


def edges(tets):
    es = set()
    for t in tets:
        for i in range(4):
            for j in range(i + 1, 4):
                es.add((min(t[i], t[j]), max(t[i], t[j])))
    return sorted(es)


def iso(values, c="0"):
    return "[iso]\nf = [{}]\nc = {}\n".format(", ".join(frac(v) for v in values), frac(c))


# Kuhn 2x2x2: an adjusted quadratic (every edge point at 2/5 from its lower id, Eq. (10)) and a
# rational map with fixed points and positive weights (Eq. (11)); f = |p - (1,1,1)|^2 - 1/2
# (O a closed surface around the centre vertex).
pts, tets = kuhn(list(product(range(2), repeat=3)))
ball = [sum((F(p[k]) - 1) ** 2 for k in range(3)) - F(1, 2) for p in pts]
lam = F(2, 5)
body = "family = \"polynomial\"\ndegree = 2\n"
for a, b in edges(tets):
    p = [(1 - lam) * pts[a][k] + lam * pts[b][k] for k in range(3)]
    body += f"[[control]]\nat = [{a}, {b}]\npoint = [{', '.join(frac(x) for x in p)}]\n"
toml_file("kuhn222_quadratic.toml",
          "Eq. (10) on kuhn222.tets: adjusted quadratic, every edge point at 2/5 (L141, 3-D).",
          body + iso(ball))
centre = pts.index((1, 1, 1))
body = "family = \"rational\"\ndegree = 2\n"
for a, b in edges(tets):
    if centre in (a, b):
        body += f"[[weight]]\nat = [{a}, {b}]\nq = \"3\"\n"
body += f"[[weight]]\nat = [{centre}, {centre}]\nq = \"1/10\"\n"
toml_file("kuhn222_rational.toml",
          "Eq. (11) on kuhn222.tets: fixed control points, weights 3 on the centre's edges, 1/10 at the centre (L161, 3-D).",
          body + iso(ball))

# The L: every triangle's solitary cubic control point at weights (1/2, 1/4, 1/4) of its sorted
# vertices (Fig. 1(b), L146 with n = 2); f = x + y + z - 3/2 (O a disk with one boundary loop).
pts, tets = kuhn([(0, 0, 0), (1, 0, 0), (0, 1, 0)])
tris = sorted({tuple(sorted(t[:i] + t[i + 1:])) for t in tets for i in range(4)})
body = "family = \"polynomial\"\ndegree = 3\n"
for a, b, c in tris:
    p = [F(1, 2) * pts[a][k] + F(1, 4) * pts[b][k] + F(1, 4) * pts[c][k] for k in range(3)]
    body += f"[[control]]\nat = [{a}, {b}, {c}]\npoint = [{', '.join(frac(x) for x in p)}]\n"
toml_file("lshape_cubic.toml",
          "Eq. (10) on lshape.tets: cubic, every solitary face point moved inside its face, the rest fixed (L146, 3-D).",
          body + iso([F(sum(p)) - F(3, 2) for p in pts]))

# The cube in 6: monotonic g (Eq. (9)) and the planted faults.
pts, tets = kuhn([(0, 0, 0)])
plane = iso([F(sum(p)) - F(3, 2) for p in pts])
toml_file("cube6_monotonic.toml", "Eq. (9) on cube6.tets: g = t + t^2 at vertex 0, t + 3t^3 at vertex 3.",
          "family = \"monotonic\"\n[[g]]\nvertex = 0\ncoeffs = [\"0\", \"1\", \"1\"]\n"
          "[[g]]\nvertex = 3\ncoeffs = [\"0\", \"1\", \"0\", \"3\"]\n" + plane)
toml_file("planted3_off_face.toml", "Planted: the control point of the diagonal (0, 3) off its edge (Def. 1).",
          "family = \"polynomial\"\ndegree = 2\n[[control]]\nat = [0, 3]\npoint = [\"1/2\", \"1/2\", \"3/5\"]\n")
toml_file("planted3_disagree.toml", "Planted: tetrahedron 0 alone moves the point of the diagonal (0, 3) (L99).",
          "family = \"polynomial\"\ndegree = 2\n[[control]]\nat = [0, 3]\npoint = [\"2/5\", \"2/5\", \"2/5\"]\ntet = 0\n")
toml_file("planted3_negative_weight.toml", "Planted: weight -3 on the diagonal (0, 3) (Eq. (11) hypothesis).",
          "family = \"rational\"\ndegree = 2\n[[weight]]\nat = [0, 3]\nq = \"-3\"\n")
toml_file("planted3_fold.toml", "Planted: the point of edge (0, 1) beyond vertex 1: X folds the edge back (non-injective).",
          "family = \"polynomial\"\ndegree = 2\n[[control]]\nat = [0, 1]\npoint = [\"6/5\", \"0\", \"0\"]\n")
