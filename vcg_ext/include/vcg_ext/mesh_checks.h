// Topology and sanity checks shared by all filters: empty meshes, NaN coordinates, degenerate and
// duplicate faces, boundary / non-manifold edges, non-manifold vertices, orientation, components.
// Index based (sorting of edge keys), O(F log F), needs no adjacency and never modifies the mesh.
#ifndef VCG_EXT_MESH_CHECKS_H
#define VCG_EXT_MESH_CHECKS_H

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include <vcg/complex/complex.h>

namespace vcg_ext {

struct MeshCheckReport {
    int vertices = 0;             // live vertices
    int faces = 0;                // live faces
    int nonFiniteVertices = 0;    // NaN or inf coordinates (referenced or not)
    int degenerateFaces = 0;      // repeated vertex or zero area
    int duplicateFaces = 0;       // faces with the same vertex set as an earlier face
    int boundaryEdges = 0;        // edges with one face
    int nonManifoldEdges = 0;     // edges with three or more faces
    int inconsistentEdges = 0;    // manifold edges whose two faces traverse it the same way
    int nonManifoldVertices = 0;  // vertices whose faces form more than one fan
    int components = 0;           // edge-connected face components

    bool IsClosed() const { return boundaryEdges == 0; }
    bool IsTwoManifold() const { return nonManifoldEdges == 0 && nonManifoldVertices == 0; }
    bool IsOriented() const { return inconsistentEdges == 0; }

    // The first problem, phrased for a user, or an empty string. `needClosedManifold` adds the
    // closed / 2-manifold / oriented requirements.
    std::string FirstProblem(bool needClosedManifold) const
    {
        if (faces == 0) return vertices == 0 ? "the mesh is empty" : "the mesh has no faces (a point cloud)";
        if (nonFiniteVertices) return std::to_string(nonFiniteVertices) + " vertices have NaN or infinite coordinates";
        if (degenerateFaces) return std::to_string(degenerateFaces) + " faces are degenerate (zero area or a repeated vertex); "
                                    "run 'Remove Zero Area Faces' / 'Remove Duplicate Vertices' first";
        if (duplicateFaces) return std::to_string(duplicateFaces) + " faces are duplicates; run 'Remove Duplicate Faces' first";
        if (!needClosedManifold) return "";
        if (nonManifoldEdges) return "the mesh is not 2-manifold: " + std::to_string(nonManifoldEdges) + " edges have more than two faces";
        if (nonManifoldVertices) return "the mesh is not 2-manifold: " + std::to_string(nonManifoldVertices) + " vertices are non-manifold";
        if (boundaryEdges) return "the mesh is not closed: it has " + std::to_string(boundaryEdges) + " boundary edges";
        if (inconsistentEdges) return "the mesh is not consistently oriented (" + std::to_string(inconsistentEdges) + " edges)";
        return "";
    }
};

template <class MeshType>
class MeshChecks
{
public:
    typedef typename MeshType::FaceType FaceType;
    typedef typename MeshType::VertexType VertexType;

    // Inspects everything; `withTopology` = false stops after the cheap per-element checks.
    static MeshCheckReport Inspect(const MeshType &m, bool withTopology = true)
    {
        MeshCheckReport r;
        for (const VertexType &v : m.vert) {
            if (v.IsD()) continue;
            ++r.vertices;
            for (int k = 0; k < 3; ++k)
                if (!std::isfinite(double(v.cP()[k]))) { ++r.nonFiniteVertices; break; }
        }
        std::vector<std::array<int, 3>> tris;
        tris.reserve(m.face.size());
        for (const FaceType &f : m.face) {
            if (f.IsD()) continue;
            ++r.faces;
            std::array<int, 3> t;
            for (int k = 0; k < 3; ++k) t[k] = int(vcg::tri::Index(m, f.cV(k)));
            tris.push_back(t);
            if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0] || IsZeroArea(f)) ++r.degenerateFaces;
        }
        if (!withTopology || tris.empty()) return r;

        // Duplicate faces: same sorted vertex triple.
        std::vector<std::array<int, 3>> sorted(tris);
        for (auto &t : sorted) std::sort(t.begin(), t.end());
        std::sort(sorted.begin(), sorted.end());
        for (size_t i = 1; i < sorted.size(); ++i)
            if (sorted[i] == sorted[i - 1]) ++r.duplicateFaces;

        // Edges: (min, max, face, forward?) sorted by vertex pair.
        struct HalfEdge { int a, b, face; bool forward; };
        std::vector<HalfEdge> he;
        he.reserve(tris.size() * 3);
        for (int f = 0; f < int(tris.size()); ++f)
            for (int k = 0; k < 3; ++k) {
                int u = tris[f][k], w = tris[f][(k + 1) % 3];
                if (u == w) continue;
                he.push_back({std::min(u, w), std::max(u, w), f, u < w});
            }
        std::sort(he.begin(), he.end(), [](const HalfEdge &x, const HalfEdge &y) {
            return x.a != y.a ? x.a < y.a : (x.b != y.b ? x.b < y.b : x.face < y.face);
        });
        // Union-find over faces (components) and over corners 3*f+k (fans around each vertex:
        // two faces sharing a manifold edge join their corners at both end points).
        std::vector<int> faceSet(tris.size()), cornerSet(tris.size() * 3);
        std::iota(faceSet.begin(), faceSet.end(), 0);
        std::iota(cornerSet.begin(), cornerSet.end(), 0);
        auto corner = [&](int f, int v) {
            for (int k = 0; k < 3; ++k) if (tris[f][k] == v) return 3 * f + k;
            return 3 * f;
        };
        for (size_t i = 0; i < he.size();) {
            size_t j = i;
            while (j < he.size() && he[j].a == he[i].a && he[j].b == he[i].b) ++j;
            size_t n = j - i;
            if (n == 1) ++r.boundaryEdges;
            else if (n > 2) ++r.nonManifoldEdges;
            else {
                if (he[i].forward == he[i + 1].forward) ++r.inconsistentEdges;
                int f = he[i].face, g = he[i + 1].face;
                Unite(cornerSet, corner(f, he[i].a), corner(g, he[i].a));
                Unite(cornerSet, corner(f, he[i].b), corner(g, he[i].b));
            }
            for (size_t k = i + 1; k < j; ++k) Unite(faceSet, he[i].face, he[k].face);
            i = j;
        }
        for (size_t f = 0; f < tris.size(); ++f)
            if (Find(faceSet, int(f)) == int(f)) ++r.components;
        // A vertex is manifold when all its corners are in one fan.
        std::vector<int> fanOf(m.vert.size(), -1);
        std::vector<char> bad(m.vert.size(), 0);
        for (size_t f = 0; f < tris.size(); ++f)
            for (int k = 0; k < 3; ++k) {
                int v = tris[f][k];
                if (k > 0 && (v == tris[f][0] || (k == 2 && v == tris[f][1]))) continue;
                int root = Find(cornerSet, int(3 * f + k));
                if (fanOf[v] < 0) fanOf[v] = root;
                else if (fanOf[v] != root && !bad[v]) { bad[v] = 1; ++r.nonManifoldVertices; }
            }
        return r;
    }

    static bool IsZeroArea(const FaceType &f)
    {
        typedef vcg::Point3<double> P;
        P a = P::Construct(f.cV(0)->cP()), b = P::Construct(f.cV(1)->cP()), c = P::Construct(f.cV(2)->cP());
        double l = std::max({(b - a).SquaredNorm(), (c - b).SquaredNorm(), (a - c).SquaredNorm()});
        double cr = ((b - a) ^ (c - a)).SquaredNorm();
        return !(cr > 1e-24 * l * l);  // also true for NaN
    }

private:
    static int Find(std::vector<int> &p, int x)
    {
        while (p[x] != x) { p[x] = p[p[x]]; x = p[x]; }
        return x;
    }
    static void Unite(std::vector<int> &p, int a, int b)
    {
        a = Find(p, a); b = Find(p, b);
        if (a != b) p[std::max(a, b)] = std::min(a, b);
    }
};

}  // namespace vcg_ext

#endif
