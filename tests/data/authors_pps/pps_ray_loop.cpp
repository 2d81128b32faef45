// Our own driver for the authors' implementation (siqueirafm/PPS, MIT), not built by cargo:
// their PPSfromLOOP S′ (eval_surface) and PPS (eval_pps) at points approaching a corner of a
// face, bary = corner·(1 − 2t) + t·others with t = 2^-k (k = 1..K), or, with DELTA > 0, at
// t·(1 ∓ DELTA) on both sides of each tile boundary v + w = 2^(1−k) of Stam's evaluation.
// Contains none of their code.
#include <face_attribute.hpp>
#include <halfedge_attribute.hpp>
#include <pps.hpp>
#include <ppsfromloop.hpp>
#include <reader.hpp>
#include <surface.hpp>
#include <vertex_attribute.hpp>
#include <cstdio>
#include <cstdlib>
#include <cmath>
#include <vector>
int main(int argc, char **argv) {
  using Surface = dcel::Surface<ppsfromloop::VertexAttribute, ppsfromloop::FaceAttribute, int,
                                ppsfromloop::HalfedgeAttribute>;
  if (argc < 5) { fprintf(stderr, "usage: pps_ray_loop mesh.off data.dat face corner [kmax [delta]]\n"); return 2; }
  unsigned face_id = atoi(argv[3]), corner = atoi(argv[4]);
  int kmax = argc > 5 ? atoi(argv[5]) : 40;
  double delta = argc > 6 ? atof(argv[6]) : 0.0;
  unsigned nv, nf; double *vset; unsigned *fset;
  off::Reader reader(argv[1]);
  reader.read(nv, vset, nf, fset);
  Surface *mesh = new Surface(nv, vset, nf, fset);
  auto *pps = new ppsfromloop::PPSfromLOOP(mesh, argv[2]);
  pps->build();
  std::vector<Surface::Face *> faces;
  for (auto it = mesh->faces_begin(); it != mesh->faces_end(); ++it) faces.push_back(*it);
  printf("face\tlambda\tmu\tnu\tpps_x\tpps_y\tpps_z\tsprime_x\tsprime_y\tsprime_z\n");
  for (int k = (delta > 0 ? 2 : 1); k <= kmax; ++k) {
    for (int side = -1; side <= 1; side += 2) {
    if (delta == 0.0 && side == 1) continue;
    double t = std::ldexp(1.0, -k) * (1 + side * delta);
    double c[3] = {t, t, t};
    c[corner] = 1 - 2 * t;
    double x, y, z, sx, sy, sz;
    pps->eval_pps(faces[face_id], c[0], c[1], c[2], x, y, z);
    pps->eval_surface(faces[face_id], c[0], c[1], c[2], sx, sy, sz);
    printf("%u\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\n", face_id, c[0], c[1], c[2], x, y, z, sx, sy, sz);
    }
  }
  return 0;
}
