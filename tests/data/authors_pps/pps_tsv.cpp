// Our own driver for the authors' implementation (siqueirafm/PPS, MIT), not built by cargo:
// builds their PPSfromPNT on an OFF mesh through its public API and prints eval_pps /
// eval_surface at (face, bary) points as TSV, like ../shared/reference/authors-pps/pn/*.tsv.
// Query points: corners, edge midpoints, centroid, 3 seeded random interior points; at most
// MAXF faces (seeded choice). Build: see tests/data/README.md. Contains none of their code.
#include <face_attribute.hpp>
#include <halfedge_attribute.hpp>
#include <pps.hpp>
#include <ppsfrompnt.hpp>
#include <reader.hpp>
#include <surface.hpp>
#include <vertex_attribute.hpp>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>
#include <array>
#include <algorithm>
int main(int argc, char **argv) {
  using Surface = dcel::Surface<ppsfrompnt::VertexAttribute, ppsfrompnt::FaceAttribute, int,
                                ppsfrompnt::HalfedgeAttribute>;
  if (argc < 2) { fprintf(stderr, "usage: pps_tsv mesh.off [maxfaces]\n"); return 2; }
  unsigned maxf = argc > 2 ? atoi(argv[2]) : 600;
  unsigned nv, nf; double *vset; unsigned *fset;
  off::Reader reader(argv[1]);
  reader.read(nv, vset, nf, fset);
  Surface *mesh = new Surface(nv, vset, nf, fset);
  auto *pps = new ppsfrompnt::PPSfromPNT(mesh);
  pps->build();
  std::vector<Surface::Face *> faces;
  for (auto it = mesh->faces_begin(); it != mesh->faces_end(); ++it) faces.push_back(*it);
  std::mt19937_64 rng(20261201);
  std::vector<unsigned> chosen(faces.size());
  for (unsigned i = 0; i < chosen.size(); ++i) chosen[i] = i;
  if (chosen.size() > maxf) { std::shuffle(chosen.begin(), chosen.end(), rng); chosen.resize(maxf); std::sort(chosen.begin(), chosen.end()); }
  std::uniform_real_distribution<double> U(0.0, 1.0);
  printf("face\tlambda\tmu\tnu\tpps_x\tpps_y\tpps_z\tsprime_x\tsprime_y\tsprime_z\n");
  for (unsigned fi : chosen) {
    std::vector<std::array<double, 3>> q = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.5, 0.5, 0}, {0, 0.5, 0.5}, {0.5, 0, 0.5}, {1.0 / 3, 1.0 / 3, 1.0 / 3}};
    for (int r = 0; r < 3; ++r) { double a = U(rng), b = U(rng); if (a + b > 1) { a = 1 - a; b = 1 - b; } q.push_back({a, b, 1 - a - b}); }
    for (auto &c : q) {
      double x, y, z, sx, sy, sz;
      pps->eval_pps(faces[fi], c[0], c[1], c[2], x, y, z);
      pps->eval_surface(faces[fi], c[0], c[1], c[2], sx, sy, sz);
      printf("%u\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\n", fi, c[0], c[1], c[2], x, y, z, sx, sy, sz);
    }
  }
  return 0;
}
