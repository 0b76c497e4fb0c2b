// Reading a triangle mesh the same way whatever its orientation: every face from its lowest vertex
// index on, and the faces of an edge-connected component with a negative orientation sign read
// reversed. A mesh and its consistently flipped copy (whatever corner each flipped face starts at)
// then give the same triangles, so every decision and every rounding made on them is the same; the
// caller writes its results back through `corner` / `reversed` in the input's own orientation.
//
// The sign of a component is that of its volume seen from a point inside, else (zero: flat) of the
// largest coordinate of its vector area; both are sums over the faces read lowest vertex first, so
// a flipped copy gives exactly the opposite sums (and outward closed meshes are read as they are).
#ifndef VCG_EXT_COMMON_CANONICAL_FACES_H
#define VCG_EXT_COMMON_CANONICAL_FACES_H

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <vcg/complex/complex.h>

#include <vcg_ext/common/edge_pairing.h>
#include <vcg_ext/common/union_find.h>

namespace vcg_ext {

class CanonicalFaces
{
public:
    typedef std::array<int, 3> Triangle;

    std::vector<Triangle> tri;                  // per face slot: vertex indices, lowest first, read reversed
                                                // where `reversed`; {-1, -1, -1} for a deleted face
    std::vector<std::array<char, 3>> corner;    // per face slot: the face's own corner holding tri[f][k]
    std::vector<char> reversed;                 // per face slot: its component is read the other way round

    // The face's own edge index of edge k of tri[f] (tri[f][k] -> tri[f][k + 1]).
    int InputEdge(int f, int k) const { return reversed[f] ? corner[f][(k + 1) % 3] : corner[f][k]; }

    template <class MeshType>
    void Read(const MeshType &m)
    {
        const size_t F = m.face.size();
        tri.assign(F, {{-1, -1, -1}});
        corner.assign(F, {{0, 1, 2}});
        for (size_t f = 0; f < F; ++f) {
            const auto &face = m.face[f];
            if (face.IsD()) continue;
            const Triangle t{{int(vcg::tri::Index(m, face.cV(0))), int(vcg::tri::Index(m, face.cV(1))), int(vcg::tri::Index(m, face.cV(2)))}};
            const int r = int(std::min_element(t.begin(), t.end()) - t.begin());
            for (int k = 0; k < 3; ++k) {
                tri[f][k] = t[(r + k) % 3];
                corner[f][k] = char((r + k) % 3);
            }
        }
        std::vector<vcg::Point3d> pos(m.vert.size());
        for (size_t v = 0; v < m.vert.size(); ++v) pos[v] = vcg::Point3d::Construct(m.vert[v].cP());
        reversed = NegativeComponents(tri, pos);
        for (size_t f = 0; f < F; ++f)
            if (reversed[f]) {  // (a, b, c) -> (a, c, b)
                std::swap(tri[f][1], tri[f][2]);
                std::swap(corner[f][1], corner[f][2]);
            }
    }

private:
    // Per face slot: whether its component's orientation sign is negative (see the top of the file).
    static std::vector<char> NegativeComponents(const std::vector<Triangle> &tri, const std::vector<vcg::Point3d> &pos)
    {
        const int F = int(tri.size());
        IndexUnionFind comp(F);
        const EdgePairing::Groups edges = EdgePairing::Group(tri);
        for (int e = 0; e < edges.Count(); ++e)
            for (int k = 1; k < edges.Size(e); ++k) comp.Unite(edges.Begin(e)[0] / 3, edges.Begin(e)[k] / 3);
        typedef vcg::Point3d P3;
        std::vector<P3> centroid(F, P3(0, 0, 0)), area(F, P3(0, 0, 0));
        std::vector<double> count(F, 0), volume(F, 0);
        for (int f = 0; f < F; ++f) {  // the mean of the faces' lowest vertices (summed the same way both ways round)
            if (tri[f][0] < 0) continue;
            const int c = comp.Find(f);
            centroid[c] += pos[tri[f][0]];
            count[c] += 1;
        }
        for (int f = 0; f < F; ++f) {
            if (tri[f][0] < 0) continue;
            const int c = comp.Find(f);
            const P3 o = centroid[c] / count[c];
            const P3 &p0 = pos[tri[f][0]], &p1 = pos[tri[f][1]], &p2 = pos[tri[f][2]];
            volume[c] += (p0 - o) * ((p1 - o) ^ (p2 - o));
            area[c] += (p1 - p0) ^ (p2 - p0);
        }
        std::vector<char> out(F, 0);
        for (int f = 0; f < F; ++f) {
            if (tri[f][0] < 0) continue;
            const int c = comp.Find(f);
            double sign = volume[c];
            if (sign == 0) {
                const P3 &a = area[c];
                sign = a[0];
                if (std::fabs(a[1]) > std::fabs(sign)) sign = a[1];
                if (std::fabs(a[2]) > std::fabs(sign)) sign = a[2];
            }
            out[f] = sign < 0;
        }
        return out;
    }
};

}  // namespace vcg_ext

#endif
