// The mesh type the unit tests instantiate the core with (float coordinates like MeshLab's CMeshO,
// non-optional components), mesh generators and file loading.
#ifndef QMF_TESTS_TEST_MESH_H
#define QMF_TESTS_TEST_MESH_H

#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/update/topology.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/create/platonic.h>
#include <wrap/io_trimesh/import_off.h>

namespace qmf_test {

class TVertex;
class TEdge;
class TFace;
struct TUsedTypes : public vcg::UsedTypes<vcg::Use<TVertex>::AsVertexType, vcg::Use<TEdge>::AsEdgeType,
                                          vcg::Use<TFace>::AsFaceType> {};
class TVertex : public vcg::Vertex<TUsedTypes, vcg::vertex::Coord3f, vcg::vertex::Normal3f, vcg::vertex::BitFlags,
                                   vcg::vertex::Qualityf, vcg::vertex::Color4b, vcg::vertex::VFAdj,
                                   vcg::vertex::Mark> {};
class TEdge : public vcg::Edge<TUsedTypes, vcg::edge::BitFlags, vcg::edge::EVAdj, vcg::edge::EEAdj> {};
class TFace : public vcg::Face<TUsedTypes, vcg::face::VertexRef, vcg::face::BitFlags, vcg::face::Normal3f,
                               vcg::face::Qualityf, vcg::face::Mark, vcg::face::Color4b, vcg::face::FFAdj,
                               vcg::face::VFAdj> {};
class TMesh : public vcg::tri::TriMesh<std::vector<TVertex>, std::vector<TEdge>, std::vector<TFace>> {};

typedef vcg::Point3f P3;

inline void Build(TMesh &m, const std::vector<P3> &v, const std::vector<std::array<int, 3>> &f)
{
    m.Clear();
    std::vector<vcg::Point3i> fi;
    for (auto &t : f) fi.push_back(vcg::Point3i(t[0], t[1], t[2]));
    vcg::tri::BuildMeshFromCoordVectorIndexVector(m, v, fi);
    vcg::tri::UpdateBounding<TMesh>::Box(m);
    vcg::tri::UpdateNormal<TMesh>::PerFaceNormalized(m);
}

// Square [0,size]^2 in the z=0 plane, n x n cells, each split by a diagonal (alternating when
// `alternate`); interior vertices jittered by up to `jitter` of a cell (irregular triangulation).
inline void MakeGrid(TMesh &m, int n, float size = 1.f, float jitter = 0.f, unsigned seed = 1, bool alternate = true)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1.f, 1.f);
    std::vector<P3> v;
    std::vector<std::array<int, 3>> f;
    float h = size / n;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            P3 p(i * h, j * h, 0);
            if (i > 0 && j > 0 && i < n && j < n) p += P3(u(rng), u(rng), 0) * (jitter * h);
            v.push_back(p);
        }
    auto id = [n](int i, int j) { return j * (n + 1) + i; };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
            if (!alternate || (i + j) % 2 == 0) { f.push_back({a, b, c}); f.push_back({a, c, d}); }
            else { f.push_back({a, b, d}); f.push_back({b, c, d}); }
        }
    Build(m, v, f);
}

// Closed cube [-1,1]^3, n x n cells per side, outward oriented; interior vertices of each side
// jittered within the side's plane (the cube stays exact).
inline void MakeCube(TMesh &m, int n, float jitter = 0.f, unsigned seed = 1)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1.f, 1.f);
    std::vector<P3> v;
    std::vector<std::array<int, 3>> f;
    // side: origin corner (in {0,1}^3), U, V with U x V = outward normal; integer lattice
    // coordinates make the shared edge vertices of two sides bit-identical.
    typedef vcg::Point3i I3;
    const I3 sides[6][3] = {{I3(0, 0, 1), I3(1, 0, 0), I3(0, 1, 0)},  {I3(0, 1, 0), I3(1, 0, 0), I3(0, -1, 0)},
                            {I3(1, 0, 0), I3(0, 1, 0), I3(0, 0, 1)},  {I3(0, 1, 0), I3(0, -1, 0), I3(0, 0, 1)},
                            {I3(0, 1, 0), I3(0, 0, 1), I3(1, 0, 0)},  {I3(0, 0, 0), I3(1, 0, 0), I3(0, 0, 1)}};
    for (int s = 0; s < 6; ++s) {
        int base = int(v.size());
        P3 U = P3(sides[s][1][0], sides[s][1][1], sides[s][1][2]), V = P3(sides[s][2][0], sides[s][2][1], sides[s][2][2]);
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) {
                I3 k = sides[s][0] * n + sides[s][1] * i + sides[s][2] * j;
                P3 p(-1.f + 2.f * k[0] / n, -1.f + 2.f * k[1] / n, -1.f + 2.f * k[2] / n);
                if (i > 0 && j > 0 && i < n && j < n) p += (U * u(rng) + V * u(rng)) * (jitter / n);
                v.push_back(p);
            }
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                int a = base + j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
                if ((i + j) % 2 == 0) { f.push_back({a, b, c}); f.push_back({a, c, d}); }
                else { f.push_back({a, b, d}); f.push_back({b, c, d}); }
            }
    }
    Build(m, v, f);
    vcg::tri::Clean<TMesh>::RemoveDuplicateVertex(m);
    vcg::tri::Allocator<TMesh>::CompactEveryVector(m);
    vcg::tri::UpdateBounding<TMesh>::Box(m);
    vcg::tri::UpdateNormal<TMesh>::PerFaceNormalized(m);
}

// Closed capped cylinder (axis z, radius r, height h): `slices` around, `stacks` along, caps as
// fans around a centre vertex with `rings` concentric rings.
inline void MakeCylinder(TMesh &m, int slices, int stacks, float r = 1.f, float h = 2.f, int rings = 3)
{
    std::vector<P3> v;
    std::vector<std::array<int, 3>> f;
    auto ring = [&](float z, float rad) {
        int base = int(v.size());
        for (int i = 0; i < slices; ++i) {
            float t = 2.f * float(M_PI) * i / slices;
            v.push_back(P3(rad * std::cos(t), rad * std::sin(t), z));
        }
        return base;
    };
    std::vector<int> side;
    for (int k = 0; k <= stacks; ++k) side.push_back(ring(-h / 2 + h * k / stacks, r));
    for (int k = 0; k < stacks; ++k)
        for (int i = 0; i < slices; ++i) {
            int a = side[k] + i, b = side[k] + (i + 1) % slices, c = side[k + 1] + (i + 1) % slices, d = side[k + 1] + i;
            f.push_back({a, b, c});
            f.push_back({a, c, d});
        }
    for (int cap = 0; cap < 2; ++cap) {
        float z = cap ? h / 2 : -h / 2;
        std::vector<int> rs{cap ? side[stacks] : side[0]};
        for (int k = rings - 1; k >= 1; --k) rs.push_back(ring(z, r * k / rings));
        int centre = int(v.size());
        v.push_back(P3(0, 0, z));
        for (size_t k = 0; k + 1 < rs.size(); ++k)
            for (int i = 0; i < slices; ++i) {
                int a = rs[k] + i, b = rs[k] + (i + 1) % slices, c = rs[k + 1] + (i + 1) % slices, d = rs[k + 1] + i;
                if (cap) { f.push_back({a, b, c}); f.push_back({a, c, d}); }
                else { f.push_back({a, c, b}); f.push_back({a, d, c}); }
            }
        int last = rs.back();
        for (int i = 0; i < slices; ++i) {
            int a = last + i, b = last + (i + 1) % slices;
            if (cap) f.push_back({a, b, centre});
            else f.push_back({b, a, centre});
        }
    }
    Build(m, v, f);
}

// Icosphere of the given radius (vcg's subdivided icosahedron).
inline void MakeSphere(TMesh &m, int subdiv, float radius = 1.f)
{
    m.Clear();
    vcg::tri::Sphere(m, subdiv);
    for (auto &v : m.vert) v.P() *= radius;
    vcg::tri::UpdateBounding<TMesh>::Box(m);
    vcg::tri::UpdateNormal<TMesh>::PerFaceNormalized(m);
}

inline bool LoadOff(TMesh &m, const std::string &path)
{
    m.Clear();
    int mask = 0;
    if (vcg::tri::io::ImporterOFF<TMesh>::Open(m, path.c_str(), mask) != 0) return false;
    vcg::tri::UpdateBounding<TMesh>::Box(m);
    vcg::tri::UpdateNormal<TMesh>::PerFaceNormalized(m);
    return m.fn > 0;
}

// Folders set by CMake: meshes extracted from Debian packages at set-up, and tests/data.
inline std::string MeshDir() { return QMF_TEST_MESH_DIR; }

// In double: a float cross product of a long thin triangle is off by about an ulp of its edges
// (1e-8 on a unit mesh), more than a needle's whole area may change by.
inline double TotalArea(const TMesh &m)
{
    typedef vcg::Point3d D3;
    double a = 0;
    for (auto &f : m.face)
        if (!f.IsD()) {
            const D3 p0 = D3::Construct(f.cP(0)), p1 = D3::Construct(f.cP(1)), p2 = D3::Construct(f.cP(2));
            a += 0.5 * vcg::Norm((p1 - p0) ^ (p2 - p0));
        }
    return a;
}

// Everything a filter writes, as bytes (live elements in order): coordinates, face vertex
// indices, flags, quality.
inline std::vector<unsigned char> MeshBytes(const TMesh &m)
{
    std::vector<unsigned char> b;
    auto put = [&b](const void *p, size_t n) {
        const unsigned char *c = static_cast<const unsigned char *>(p);
        b.insert(b.end(), c, c + n);
    };
    for (const auto &v : m.vert) {
        if (v.IsD()) continue;
        put(&v.cP()[0], 3 * sizeof(float));
    }
    for (const auto &f : m.face) {
        if (f.IsD()) continue;
        for (int k = 0; k < 3; ++k) {
            const int i = int(vcg::tri::Index(m, f.cV(k)));
            put(&i, sizeof i);
        }
        const int flags = f.cFlags();
        put(&flags, sizeof flags);
        const float q = f.cQ();
        put(&q, sizeof q);
    }
    return b;
}

}  // namespace qmf_test

#endif
