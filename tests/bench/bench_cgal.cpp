// CGAL's Variational Shape Approximation (L2,1 metric, planar proxies) on the benchmark's meshes.
// Its own translation unit: CGAL takes long to compile and needs none of vcg.
#include "bench_cgal.h"

#include <chrono>
#include <cstdlib>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Variational_shape_approximation.h>

namespace qmf_bench {

namespace {
typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef boost::property_map<Mesh, CGAL::vertex_point_t>::type VertexPointMap;
typedef CGAL::Surface_mesh_approximation::L21_metric_plane_proxy<Mesh> L21Metric;
typedef CGAL::Variational_shape_approximation<Mesh, VertexPointMap, L21Metric> VSA;

double Since(std::chrono::steady_clock::time_point t0)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

bool CgalAvailable() { return true; }
std::string CgalVersion() { return QMF_BENCH_CGAL_VERSION; }

CgalVsaRun RunCgalVsa(const std::vector<std::array<double, 3>> &points, const std::vector<std::array<int, 3>> &triangles,
                      int proxies, CgalSeeding seeding, int relaxations, int iterations, unsigned randomSeed)
{
    CgalVsaRun r;
    auto t0 = std::chrono::steady_clock::now();
    Mesh mesh;
    mesh.reserve(Mesh::size_type(points.size()), Mesh::size_type(3 * triangles.size() / 2),
                 Mesh::size_type(triangles.size()));
    std::vector<Mesh::Vertex_index> vi;
    vi.reserve(points.size());
    for (const auto &p : points) vi.push_back(mesh.add_vertex(Point(p[0], p[1], p[2])));
    for (size_t i = 0; i < triangles.size(); ++i) {
        const auto &t = triangles[i];
        Mesh::Face_index f = mesh.add_face(vi[t[0]], vi[t[1]], vi[t[2]]);
        if (f == Mesh::null_face() || size_t(f) != i) {
            r.error = "CGAL::Surface_mesh refused triangle " + std::to_string(i) + " (not an oriented 2-manifold)";
            return r;
        }
    }
    r.buildSeconds = Since(t0);

    t0 = std::chrono::steady_clock::now();
    VertexPointMap vpm = get(boost::vertex_point, const_cast<const Mesh &>(mesh));
    L21Metric metric(mesh, vpm);
    VSA vsa(mesh, vpm, metric);
    r.setupSeconds = Since(t0);

    std::srand(randomSeed);
    t0 = std::chrono::steady_clock::now();
    const auto method = seeding == CgalSeeding::Random        ? CGAL::Surface_mesh_approximation::RANDOM
                        : seeding == CgalSeeding::Incremental ? CGAL::Surface_mesh_approximation::INCREMENTAL
                                                              : CGAL::Surface_mesh_approximation::HIERARCHICAL;
    vsa.initialize_seeds(CGAL::parameters::seeding_method(method)
                             .max_number_of_proxies(std::size_t(proxies))
                             .number_of_relaxations(std::size_t(relaxations)));
    r.seedSeconds = Since(t0);

    t0 = std::chrono::steady_clock::now();
    vsa.run(std::size_t(iterations));
    r.iterateSeconds = Since(t0);
    r.iterations = iterations;
    r.cgalError = CGAL::to_double(vsa.compute_total_error());
    r.proxies = int(vsa.number_of_proxies());

    std::vector<Kernel::Vector_3> px;
    vsa.proxies(std::back_inserter(px));
    for (const auto &n : px) r.proxyNormal.push_back({n.x(), n.y(), n.z()});
    auto fpm = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:bench_proxy", 0).first;
    vsa.proxy_map(fpm);
    r.faceProxy.resize(triangles.size());
    for (Mesh::Face_index f : mesh.faces()) r.faceProxy[size_t(f)] = int(fpm[f]);
    return r;
}

}  // namespace qmf_bench
