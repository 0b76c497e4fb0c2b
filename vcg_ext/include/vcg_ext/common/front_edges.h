// Front edges stored as selected face-edges, the representation MeshLab's own "Select Crease
// Edges" uses: flag FACEEDGESEL<i> on both faces of edge i = V(i) -> V((i+1)%3); PLY keeps them in
// the face flags (meshlabserver -m ff). Helpers to clear, set and read them back, and to draw them
// as an edge-only mesh (MeshLab 2020.09 draws no selected face-edges, only edge layers).
// Index based: no FF/VF adjacency needed; each call is one pass over the faces.
#ifndef VCG_EXT_COMMON_FRONT_EDGES_H
#define VCG_EXT_COMMON_FRONT_EDGES_H

#include <algorithm>
#include <array>
#include <cstdint>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include <vcg/complex/complex.h>

#include <vcg_ext/common/edge_key.h>
#include <vcg_ext/common/edge_layer.h>

namespace vcg_ext {

template <class MeshType>
class FrontEdges
{
public:
    typedef typename MeshType::FaceType FaceType;
    typedef VertexPair Edge;  // vertex indices, first < second

    // Vertex indices of edge i of face f.
    static Edge EdgeOf(const MeshType &m, const FaceType &f, int i)
    {
        return UndirectedPair(int(vcg::tri::Index(m, f.cV(i))), int(vcg::tri::Index(m, f.cV((i + 1) % 3))));
    }

    // Clears the face-edge selection of every live face (and the faux bits too when asked).
    static void Clear(MeshType &m, bool alsoFaux = false)
    {
        int bits = FaceType::FACEEDGESEL0 | FaceType::FACEEDGESEL1 | FaceType::FACEEDGESEL2;
        if (alsoFaux) bits |= FaceType::FAUX0 | FaceType::FAUX1 | FaceType::FAUX2;
        for (FaceType &f : m.face)
            if (!f.IsD()) f.Flags() &= ~bits;
    }

    // Selects every face-edge whose vertex pair is in `edges`, on all faces sharing it (existing
    // selections stay). Returns how many of the distinct `edges` exist in the mesh.
    static int Select(MeshType &m, const std::vector<Edge> &edges)
    {
        std::unordered_set<uint64_t> wanted, found;
        std::vector<char> onFront(m.vert.size(), 0);
        for (const Edge &e : edges) {
            wanted.insert(EdgeKey(e));
            onFront[e.first] = onFront[e.second] = 1;
        }
        for (FaceType &f : m.face) {
            if (f.IsD()) continue;
            for (int i = 0; i < 3; ++i) {
                const Edge e = EdgeOf(m, f, i);
                if (!onFront[e.first] || !onFront[e.second] || !wanted.count(EdgeKey(e))) continue;
                f.SetFaceEdgeS(i);
                found.insert(EdgeKey(e));
            }
        }
        return int(found.size());
    }

    // The distinct selected edges (flagged on at least one side), sorted.
    static std::vector<Edge> Collect(const MeshType &m)
    {
        std::vector<Edge> out;
        for (const FaceType &f : m.face) {
            if (f.IsD()) continue;
            for (int i = 0; i < 3; ++i)
                if (f.IsFaceEdgeS(i)) out.push_back(EdgeOf(m, f, i));
        }
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
        return out;
    }

    // Selected edges flagged on some but not all of the faces sharing them (0 when consistent).
    static int CountOneSided(const MeshType &m)
    {
        std::unordered_map<uint64_t, std::pair<int, int>> sides;  // edge -> (faces, flagged faces)
        for (const FaceType &f : m.face) {
            if (f.IsD()) continue;
            for (int i = 0; i < 3; ++i) {
                auto &s = sides[EdgeKey(EdgeOf(m, f, i))];
                ++s.first;
                s.second += f.IsFaceEdgeS(i) ? 1 : 0;
            }
        }
        int bad = 0;
        for (const auto &s : sides)
            if (s.second.second > 0 && s.second.second != s.second.first) ++bad;
        return bad;
    }

    // Replaces the content of `out` by the edges: one vertex per mesh vertex they use (position
    // copied), one edge each. Suits a new edge-only layer showing the front.
    template <class EdgeMeshType>
    static void BuildEdgeMesh(const MeshType &m, const std::vector<Edge> &edges, EdgeMeshType &out)
    {
        std::unordered_map<int, int> index;
        std::vector<typename MeshType::CoordType> points;
        std::vector<std::array<int, 2>> segments;
        for (const Edge &e : edges) {
            for (int v : {e.first, e.second})
                if (index.emplace(v, int(points.size())).second) points.push_back(m.vert[v].cP());
            segments.push_back({index[e.first], index[e.second]});
        }
        WriteEdgeLayer(points, segments, out);
    }
};

}  // namespace vcg_ext

#endif
