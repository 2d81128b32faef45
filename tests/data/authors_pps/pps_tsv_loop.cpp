// Our own driver for the authors' implementation (siqueirafm/PPS, MIT), not built by cargo:
// as pps_tsv.cpp with their PPSfromLOOP (S′ = Loop, evaluated with the eigen-structure file
// they ship, lpdata50NT.dat, given as the second argument). Contains none of their code.
#include <face_attribute.hpp>
#include <halfedge_attribute.hpp>
#include <pps.hpp>
#include <ppsfromloop.hpp>
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
  using Surface = dcel::Surface<ppsfromloop::VertexAttribute, ppsfromloop::FaceAttribute, int,
                                ppsfromloop::HalfedgeAttribute>;
  if (argc < 3) { fprintf(stderr, "usage: pps_tsv_loop mesh.off data.dat [maxfaces]\n"); return 2; }
  unsigned maxf = argc > 3 ? atoi(argv[3]) : 600;
  unsigned nv, nf; double *vset; unsigned *fset;
  off::Reader reader(argv[1]);
  reader.read(nv, vset, nf, fset);
  Surface *mesh = new Surface(nv, vset, nf, fset);
  auto *pps = new ppsfromloop::PPSfromLOOP(mesh, argv[2]);
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
