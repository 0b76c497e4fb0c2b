// Topology and sanity checks shared by all filters: empty meshes, NaN coordinates, degenerate and
// duplicate faces, boundary / non-manifold edges, non-manifold vertices, orientation, components.
// Index based (sorting of edge keys), O(F log F), needs no adjacency and never modifies the mesh.
#ifndef VCG_EXT_MESH_CHECKS_H
#define VCG_EXT_MESH_CHECKS_H

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <vcg/complex/complex.h>

#include <vcg_ext/common/edge_pairing.h>
#include <vcg_ext/common/union_find.h>

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
    int edges = 0;                // distinct edges (vertex pairs) of the live faces
    int referencedVertices = 0;   // live vertices used by a live face
    // V - E + F over the referenced vertices (2 - 2 genus for a closed connected surface).
    int EulerCharacteristic() const { return referencedVertices - edges + faces; }

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
        r.nonFiniteVertices = CountNonFiniteVertices(m);
        for (const VertexType &v : m.vert) r.vertices += v.IsD() ? 0 : 1;
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

        // Union-find over faces (components) and over corners 3*f+k (fans around each vertex:
        // two faces sharing a manifold edge join their corners at both end points).
        IndexUnionFind faceSet(int(tris.size())), cornerSet(int(3 * tris.size()));
        auto corner = [&](int f, int v) {
            for (int k = 0; k < 3; ++k) if (tris[f][k] == v) return 3 * f + k;
            return 3 * f;
        };
        const EdgePairing::Groups edges = EdgePairing::Group(tris);
        r.edges = edges.Count();
        for (int e = 0; e < edges.Count(); ++e) {
            const int n = edges.Size(e), *h = edges.Begin(e);
            if (n == 1) ++r.boundaryEdges;
            else if (n > 2) ++r.nonManifoldEdges;
            else {
                const int a = EdgePairing::From(tris, h[0]), b = EdgePairing::To(tris, h[0]);
                if (a == EdgePairing::From(tris, h[1])) ++r.inconsistentEdges;  // both run a -> b
                const int f = h[0] / 3, g = h[1] / 3;
                cornerSet.Unite(corner(f, a), corner(g, a));
                cornerSet.Unite(corner(f, b), corner(g, b));
            }
            for (int k = 1; k < n; ++k) faceSet.Unite(h[0] / 3, h[k] / 3);
        }
        for (size_t f = 0; f < tris.size(); ++f)
            if (faceSet.Find(int(f)) == int(f)) ++r.components;
        // A vertex is manifold when all its corners are in one fan.
        std::vector<int> fanOf(m.vert.size(), -1);
        std::vector<char> bad(m.vert.size(), 0);
        for (size_t f = 0; f < tris.size(); ++f)
            for (int k = 0; k < 3; ++k) {
                int v = tris[f][k];
                if (k > 0 && (v == tris[f][0] || (k == 2 && v == tris[f][1]))) continue;
                int root = cornerSet.Find(int(3 * f + k));
                if (fanOf[v] < 0) { fanOf[v] = root; ++r.referencedVertices; }
                else if (fanOf[v] != root && !bad[v]) { bad[v] = 1; ++r.nonManifoldVertices; }
            }
        return r;
    }

    // The mesh has faces and no NaN or infinite coordinate, or the first of these problems: what
    // every filter needs (cheap, no topology).
    static std::string CheckFacesAndCoordinates(const MeshType &m)
    {
        const MeshCheckReport report = Inspect(m, false);
        return report.faces == 0 || report.nonFiniteVertices ? report.FirstProblem(false) : "";
    }

    // Live vertices with a NaN or infinite coordinate.
    static int CountNonFiniteVertices(const MeshType &m)
    {
        int n = 0;
        for (const VertexType &v : m.vert)
            if (!v.IsD() && !IsFinite(v.cP())) ++n;
        return n;
    }

    template <class PointType>
    static bool IsFinite(const PointType &p)
    {
        return std::isfinite(double(p[0])) && std::isfinite(double(p[1])) && std::isfinite(double(p[2]));
    }

    static bool IsZeroArea(const FaceType &f)
    {
        typedef vcg::Point3<double> P;
        P a = P::Construct(f.cV(0)->cP()), b = P::Construct(f.cV(1)->cP()), c = P::Construct(f.cV(2)->cP());
        double l = std::max({(b - a).SquaredNorm(), (c - b).SquaredNorm(), (a - c).SquaredNorm()});
        double cr = ((b - a) ^ (c - a)).SquaredNorm();
        return !(cr > 1e-24 * l * l);  // also true for NaN
    }
};

}  // namespace vcg_ext

#endif
