// Index-based half-edge adjacency for splitting a mesh along polylines.
//
// Half-edge 3f+k is edge k of face f read canonically (common/canonical_faces.h: lowest vertex first,
// components of negative orientation reversed, so a flipped copy of the mesh is split with the same
// roundings), running fv[f][k] -> fv[f][(k+1)%3]; InputEdge gives the face's own edge index. twin[h]
// is the half-edge running the other way along the same edge (-1 on a mesh boundary). Built by the
// shared edge pairing (EdgePairing), without vcg's optional FF/VF components, so validating input
// never touches the mesh.
// The build refuses meshes it cannot walk on: edges with more than two faces, inconsistently
// oriented neighbours, repeated vertices in a face, vertices whose faces form several fans.
#ifndef VCG_EXT_EMBEDDING_ADJACENCY_H
#define VCG_EXT_EMBEDDING_ADJACENCY_H

#include <array>
#include <string>
#include <vector>

#include <vcg/complex/complex.h>

#include <vcg_ext/common/canonical_faces.h>
#include <vcg_ext/common/edge_pairing.h>

namespace vcg_ext {
namespace embedding {

class EmbeddingAdjacency
{
public:
    std::vector<std::array<int, 3>> fv;  // vertex indices per face slot ({-1,-1,-1} for deleted faces)
    std::vector<int> twin;               // per half-edge, -1 on a boundary
    std::vector<int> vertexFace;         // per vertex: one incident live face, -1 if unreferenced
    std::vector<std::array<char, 3>> corner;  // per face slot: the face's own corner holding fv[f][k]
    std::vector<char> reversed;               // per face slot: fv runs the other way round than the face

    // The face's own edge index of half-edge 3f+k (what its flags and vcg adjacency are indexed by).
    int InputEdge(int f, int k) const { return reversed[f] ? corner[f][Next(k)] : corner[f][k]; }

    static int Next(int k) { return k == 2 ? 0 : k + 1; }
    static int Prev(int k) { return k == 0 ? 2 : k - 1; }
    int From(int h) const { return fv[h / 3][h % 3]; }
    int To(int h) const { return fv[h / 3][Next(h % 3)]; }
    bool IsLive(int f) const { return fv[f][0] >= 0; }
    int CornerOf(int f, int v) const
    {
        for (int k = 0; k < 3; ++k)
            if (fv[f][k] == v) return k;
        return -1;
    }

    // Builds everything; returns an empty string or why the mesh cannot be walked on.
    template <class MeshType>
    std::string Build(const MeshType &m)
    {
        const int nf = int(m.face.size()), nv = int(m.vert.size());
        CanonicalFaces canon;
        canon.Read(m);
        fv = canon.tri;
        corner = canon.corner;
        reversed = canon.reversed;
        for (int f = 0; f < nf; ++f) {
            if (m.face[f].IsD()) continue;
            if (fv[f][0] == fv[f][1] || fv[f][1] == fv[f][2] || fv[f][2] == fv[f][0])
                return "face " + std::to_string(f) + " has a repeated vertex";
        }
        // Twins: an edge must have one face (boundary) or two that run it in opposite directions.
        // The first bad half-edge in face order names the edge in the message.
        const EdgePairing::Groups edges = EdgePairing::Group(fv);
        int firstBad = -1;
        for (int e = 0; e < edges.Count(); ++e) {
            const int *h = edges.Begin(e);
            const bool bad = edges.Size(e) > 2 || (edges.Size(e) == 2 && From(h[0]) == From(h[1]));
            if (bad && (firstBad < 0 || h[0] < firstBad)) firstBad = h[0];
        }
        if (firstBad >= 0)
            return "the mesh is not a consistently oriented 2-manifold (edge " + std::to_string(From(firstBad)) + "-" +
                   std::to_string(To(firstBad)) + " has more than two faces or faces of opposite orientation)";
        twin = EdgePairing::Twins(edges, 3 * size_t(nf));
        vertexFace.assign(nv, -1);
        std::vector<int> faceCount(nv, 0);
        for (int f = 0; f < nf; ++f)
            if (IsLive(f))
                for (int k = 0; k < 3; ++k) {
                    vertexFace[fv[f][k]] = f;
                    ++faceCount[fv[f][k]];
                }
        // Manifold vertices: walking the fan reaches every incident face.
        for (int v = 0; v < nv; ++v) {
            if (vertexFace[v] < 0) continue;
            int reached = 0;
            ForEachFaceAround(vertexFace[v], v, [&](int, int) { ++reached; });
            if (reached != faceCount[v])
                return "the mesh is not 2-manifold: vertex " + std::to_string(v) + " has several fans of faces";
        }
        return "";
    }

    // Calls fn(face, corner) once for every face around vertex v (a corner of face f), walking the
    // fan through the twins: first one way, then, if a boundary stops it, the other way.
    template <class Fn>
    void ForEachFaceAround(int f, int v, Fn fn) const
    {
        int g = f;
        for (;;) {  // clockwise: across the edge leaving v
            const int i = CornerOf(g, v);
            fn(g, i);
            const int h = twin[3 * g + i];
            if (h < 0) break;
            g = h / 3;
            if (g == f) return;  // closed fan
        }
        g = f;
        for (;;) {  // counter-clockwise from f: across the edge entering v
            const int i = CornerOf(g, v);
            const int h = twin[3 * g + Prev(i)];
            if (h < 0) return;
            g = h / 3;
            if (g == f) return;
            fn(g, CornerOf(g, v));
        }
    }

    // The half-edge u -> v, or v -> u when that one does not exist; -1 when u, v are not adjacent.
    int FindEdge(int u, int v) const
    {
        if (u < 0 || vertexFace[u] < 0) return -1;
        int found = -1;
        ForEachFaceAround(vertexFace[u], u, [&](int g, int i) {
            if (found >= 0) return;
            if (fv[g][Next(i)] == v) found = 3 * g + i;
            else if (fv[g][Prev(i)] == v) found = 3 * g + Prev(i);
        });
        return found;
    }
};

}  // namespace embedding
}  // namespace vcg_ext

#endif
