// Topology and sanity checks shared by all filters: empty meshes, NaN coordinates, unmerged
// (duplicate) vertices, degenerate and duplicate faces, boundary / non-manifold edges, non-manifold
// vertices, orientation, components. Every problem is reported with the MeshLab filter that fixes it.
// Index based (the shared edge pairing, linear; vertex positions sorted only when the mesh has a
// boundary), needs no adjacency and never modifies the mesh.
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
    int duplicateVertices = 0;    // boundary vertices at exactly the position of another referenced vertex
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
    // No two faces share a vertex and some vertices coincide: vertices never merged (STL-like input).
    bool IsTriangleSoup() const { return faces > 1 && referencedVertices == 3 * faces && duplicateVertices > 0; }

    // The problems, in the order they are reported and should be fixed (each fix can reveal the
    // next one: merging vertices can make zero-area or duplicate faces; MeshLab re-orients only a
    // 2-manifold mesh; a non-manifold fin also makes boundary edges).
    enum Problem {
        NoProblem, Empty, NoFaces, NonFiniteVertices, DuplicateVertices, DegenerateFaces, DuplicateFaces,
        NonManifoldEdges, NonManifoldVertices, Open, Inconsistent
    };
    // What is required beyond faces, finite coordinates, merged vertices and no degenerate or
    // duplicate face (`Basic`).
    enum Requirement { Basic, ManifoldOriented, ClosedManifoldOriented };

    Problem First(Requirement need) const
    {
        if (faces == 0) return vertices == 0 ? Empty : NoFaces;
        if (nonFiniteVertices) return NonFiniteVertices;
        if (duplicateVertices) return DuplicateVertices;
        if (degenerateFaces) return DegenerateFaces;
        if (duplicateFaces) return DuplicateFaces;
        if (need == Basic) return NoProblem;
        if (nonManifoldEdges) return NonManifoldEdges;
        if (nonManifoldVertices) return NonManifoldVertices;
        if (boundaryEdges && need == ClosedManifoldOriented) return Open;
        if (inconsistentEdges) return Inconsistent;
        return NoProblem;
    }

    // The problem phrased for a user, naming the MeshLab filter that repairs it; "" for NoProblem.
    std::string Describe(Problem p) const
    {
        auto n = [](int k) { return std::to_string(k); };
        switch (p) {
        case NoProblem: return "";
        case Empty: return "the mesh is empty";
        case NoFaces: return "the mesh has no faces (a point cloud)";
        case NonFiniteVertices: return n(nonFiniteVertices) + " vertices have NaN or infinite coordinates";
        case DuplicateVertices:
            return (IsTriangleSoup() ? "the mesh is a triangle soup: none of its " + n(faces) + " faces shares a vertex with "
                                       "another (" + n(duplicateVertices) + " vertices lie exactly on another vertex)"
                                     : "the mesh has " + n(duplicateVertices) + " duplicate vertices (on its boundary, exactly "
                                       "on another vertex: the surface is cut open there)") +
                   "; run 'Merge Close Vertices' first";
        case DegenerateFaces:
            return n(degenerateFaces) + " faces are degenerate (zero area or a repeated vertex); run 'Remove Zero Area "
                   "Faces' first";
        case DuplicateFaces: return n(duplicateFaces) + " faces are duplicates; run 'Remove Duplicate Faces' first";
        case NonManifoldEdges:
            return "the mesh is not 2-manifold: " + n(nonManifoldEdges) + " edges have more than two faces; run 'Repair "
                   "non Manifold Edges by removing faces' first";
        case NonManifoldVertices:
            return "the mesh is not 2-manifold: " + n(nonManifoldVertices) + " vertices are non-manifold; run 'Repair "
                   "non Manifold Vertices by splitting' first";
        case Open: return "the mesh is not closed: it has " + n(boundaryEdges) + " boundary edges";
        case Inconsistent:
            return "the mesh is not consistently oriented (" + n(inconsistentEdges) + " edges whose two faces disagree); "
                   "run 'Re-Orient all faces coherentely' first";
        }
        return "";
    }

    // The first problem, phrased for a user, or an empty string. `needClosedManifold` adds the
    // closed / 2-manifold / oriented requirements.
    std::string FirstProblem(bool needClosedManifold) const
    {
        return Describe(First(needClosedManifold ? ClosedManifoldOriented : Basic));
    }
    // What Split Triangles along Front and Q-Morph need (open meshes are fine: the boundary is front).
    std::string PipelineProblem() const { return Describe(First(ManifoldOriented)); }
    // What every filter needs: faces, and no NaN or infinite coordinate ("" when so).
    std::string FacesAndCoordinatesProblem() const { return faces == 0 || nonFiniteVertices ? FirstProblem(false) : ""; }
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

        const EdgePairing::Groups edges = EdgePairing::Group(tris);
        r.duplicateFaces = CountDuplicateFaces(tris, edges);

        // Union-find over faces (components) and over corners 3*f+k (fans around each vertex:
        // two faces sharing a manifold edge join their corners at both end points).
        IndexUnionFind faceSet(int(tris.size())), cornerSet(int(3 * tris.size()));
        auto corner = [&](int f, int v) {
            for (int k = 0; k < 3; ++k) if (tris[f][k] == v) return 3 * f + k;
            return 3 * f;
        };
        std::vector<char> onBoundary(m.vert.size(), 0);
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
            if (n == 1) onBoundary[EdgePairing::From(tris, h[0])] = onBoundary[EdgePairing::To(tris, h[0])] = 1;
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
        r.duplicateVertices = r.boundaryEdges ? CountDuplicateBoundaryVertices(m, fanOf, onBoundary) : 0;
        return r;
    }

    // Faces with the same vertex set as an earlier face (in `tris` order). Two such faces share
    // every edge, so faces are compared only on the edge between their two lowest vertices (one of
    // EdgePairing's groups, two faces on a manifold edge), by their third vertex: linear, where
    // sorting millions of vertex triples took a quarter of the checks (each filter runs them). Faces
    // with a repeated vertex have no such edge, and only repeat each other: their sorted triples
    // are compared among themselves.
    static int CountDuplicateFaces(const std::vector<std::array<int, 3>> &tris, const EdgePairing::Groups &edges)
    {
        int count = 0;
        std::vector<std::array<int, 3>> repeating;  // sorted triples of the faces with a repeated vertex
        for (std::array<int, 3> t : tris) {
            std::sort(t.begin(), t.end());
            if (t[0] == t[1] || t[1] == t[2]) repeating.push_back(t);
        }
        std::sort(repeating.begin(), repeating.end());
        for (size_t i = 1; i < repeating.size(); ++i)
            if (repeating[i] == repeating[i - 1]) ++count;
        std::vector<int> thirds;  // third vertices of the faces whose lowest edge is this one
        for (int e = 0; e < edges.Count(); ++e) {
            const int n = edges.Size(e), *h = edges.Begin(e);
            if (n < 2) continue;
            thirds.clear();
            for (int i = 0; i < n; ++i) {
                const std::array<int, 3> &t = tris[h[i] / 3];
                const int k = h[i] % 3, third = t[(k + 2) % 3];
                if (third > t[k] && third > t[(k + 1) % 3]) thirds.push_back(third);
            }
            std::sort(thirds.begin(), thirds.end());  // a non-manifold fan stays O(n log n)
            for (size_t i = 1; i < thirds.size(); ++i)
                if (thirds[i] == thirds[i - 1]) ++count;
        }
        return count;
    }

    // Boundary vertices whose position is exactly that of another referenced vertex: vertices that
    // were never merged (a triangle soup, or a surface cut open along a seam). Coincident vertices
    // away from the boundary (closed parts touching at a point) are not counted: a mesh without
    // boundary edges has none, and Inspect does not call this (no sort of its vertices).
    static int CountDuplicateBoundaryVertices(const MeshType &m, const std::vector<int> &referenced,
                                              const std::vector<char> &onBoundary)
    {
        std::vector<int> ids;
        for (size_t v = 0; v < m.vert.size(); ++v)
            if (referenced[v] >= 0 && IsFinite(m.vert[v].cP())) ids.push_back(int(v));
        auto less = [&](int a, int b) {
            const auto &p = m.vert[a].cP(), &q = m.vert[b].cP();
            if (p[0] != q[0]) return p[0] < q[0];
            if (p[1] != q[1]) return p[1] < q[1];
            if (p[2] != q[2]) return p[2] < q[2];
            return a < b;
        };
        std::sort(ids.begin(), ids.end(), less);
        int count = 0;
        for (size_t i = 0, j = 0; i < ids.size(); i = j) {
            for (j = i + 1; j < ids.size() && m.vert[ids[j]].cP() == m.vert[ids[i]].cP();) ++j;
            if (j - i > 1)
                for (size_t k = i; k < j; ++k) count += onBoundary[ids[k]] ? 1 : 0;
        }
        return count;
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
