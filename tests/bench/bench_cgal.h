// The CGAL side of the VSA comparison, behind a plain interface so that CGAL
// is compiled in its own translation unit (bench_cgal.cpp; bench_cgal_stub.cpp without CGAL).
#ifndef QMF_BENCH_CGAL_H
#define QMF_BENCH_CGAL_H

#include <array>
#include <string>
#include <vector>

namespace qmf_bench {

enum class CgalSeeding { Random, Incremental, Hierarchical };

struct CgalVsaRun {
    std::string error;           // empty on success
    int proxies = 0;
    int iterations = 0;          // Lloyd iterations of run(iterations), after the seeding
    double buildSeconds = 0;     // Surface_mesh from the arrays (not part of VSA)
    double setupSeconds = 0;     // VSA object + L2,1 metric (face normals and areas)
    double seedSeconds = 0;      // initialize_seeds (with its relaxations)
    double iterateSeconds = 0;   // run(iterations): partition + fit, `iterations` times
    double cgalError = 0;        // CGAL's own compute_total_error()
    std::vector<int> faceProxy;                     // per input triangle
    std::vector<std::array<double, 3>> proxyNormal; // per proxy
};

bool CgalAvailable();
std::string CgalVersion();

// L2,1 VSA (CGAL::Variational_shape_approximation with L21_metric_plane_proxy, sequential) on the
// triangle soup given as indexed arrays (one face per triangle, same order): `proxies` proxies
// seeded by `seeding` with `relaxations` Lloyd iterations interleaved, then run(iterations).
// std::srand(randomSeed) first (CGAL's random seeding uses std::rand()).
CgalVsaRun RunCgalVsa(const std::vector<std::array<double, 3>> &points, const std::vector<std::array<int, 3>> &triangles,
                      int proxies, CgalSeeding seeding, int relaxations, int iterations, unsigned randomSeed);

}  // namespace qmf_bench

#endif
