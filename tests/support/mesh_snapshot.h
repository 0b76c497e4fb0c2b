// Everything a filter could change on a vcg mesh (any mesh type with per-face quality and colour),
// in comparable form: "the mesh is left exactly as it was" is a comparison of two snapshots.
#ifndef QMF_TESTS_MESH_SNAPSHOT_H
#define QMF_TESTS_MESH_SNAPSHOT_H

#include <array>
#include <cstring>
#include <vector>

#include <vcg/complex/complex.h>

namespace qmf_test {

struct Snapshot {
    std::vector<std::array<float, 3>> coords;
    std::vector<std::array<int, 3>> faces;
    std::vector<int> faceFlags, vertFlags;
    std::vector<float> faceQuality;
    std::vector<unsigned> faceColor;
    std::vector<std::array<int, 2>> edges;

    // withQuality / withColor: whether the face attributes hold data (MeshLab's data mask).
    template <class MeshType>
    static Snapshot Of(const MeshType &m, bool withQuality = true, bool withColor = true)
    {
        Snapshot s;
        for (auto &v : m.vert) {
            s.coords.push_back({float(v.cP()[0]), float(v.cP()[1]), float(v.cP()[2])});
            s.vertFlags.push_back(v.cFlags());
        }
        for (auto &f : m.face) {
            s.faces.push_back({int(vcg::tri::Index(m, f.cV(0))), int(vcg::tri::Index(m, f.cV(1))), int(vcg::tri::Index(m, f.cV(2)))});
            s.faceFlags.push_back(f.cFlags());
            if (withQuality) s.faceQuality.push_back(float(f.cQ()));
            if (withColor) {
                auto c = f.cC();
                s.faceColor.push_back(unsigned(c[0]) | unsigned(c[1]) << 8 | unsigned(c[2]) << 16 | unsigned(c[3]) << 24);
            }
        }
        for (auto &e : m.edge) s.edges.push_back({int(vcg::tri::Index(m, e.cV(0))), int(vcg::tri::Index(m, e.cV(1)))});
        return s;
    }

    // Coordinates and quality compared bitwise (NaN equals NaN).
    bool operator==(const Snapshot &o) const
    {
        return SameBits(coords, o.coords) && SameBits(faceQuality, o.faceQuality) && faces == o.faces &&
               faceFlags == o.faceFlags && vertFlags == o.vertFlags && faceColor == o.faceColor && edges == o.edges;
    }
    bool operator!=(const Snapshot &o) const { return !(*this == o); }

    // (memcmp of an empty vector's null data() is undefined behaviour: sizes first.)
    template <class T>
    static bool SameBits(const std::vector<T> &a, const std::vector<T> &b)
    {
        return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
    }
};

}  // namespace qmf_test

#endif
