// MeshEdgeTopology: index-based edge adjacency of a const triangle mesh (no vcg adjacency
// component needed, the mesh is never touched): vertex -> face lists, the edges of the shared twin
// pairing (EdgePairing) numbered in face order, and the ordered fan of faces around a vertex with
// its corner angles. The straightening's paths live on it.
#ifndef VCG_EXT_BOUNDARY_MESH_EDGE_TOPOLOGY_H
#define VCG_EXT_BOUNDARY_MESH_EDGE_TOPOLOGY_H

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <vcg/complex/complex.h>

#include <vcg_ext/common/canonical_faces.h>
#include <vcg_ext/common/edge_pairing.h>
#include <vcg_ext/common/polygon_geometry.h>

namespace vcg_ext {

// Half-edge h = 3 * face + k runs from vertex k to vertex (k + 1) % 3 of the face read canonically
// (common/canonical_faces.h: lowest vertex first, components of negative orientation reversed).
template <class MeshType>
class MeshEdgeTopology
{
public:
    typedef typename MeshType::FaceType FaceType;
    typedef vcg::Point3<double> Vec;

    enum EdgeKind : char { Border = 1, Manifold = 2, NonManifold = 3 };

    // Faces around a vertex v in order: face j has the corners v, ring[j], ring[j + 1] and the
    // corner angle angle[j] at v; start[j] is the sum of the angles before face j (so spoke j,
    // the edge v-ring[j], sits at the unfolded polar angle start[j]). A closed fan (interior
    // vertex) has ring.size() == faces.size() and wraps around; an open fan (mesh border) has one
    // more ring vertex than faces.
    struct Fan {
        std::vector<int> faces;
        std::vector<int> ring;
        std::vector<int> spokeEdge;  // edge id of each spoke v-ring[j]
        std::vector<double> angle;
        std::vector<double> start;
        double total = 0;    // sum of the corner angles
        bool closed = false;
        int Spokes() const { return int(ring.size()); }
        double SpokeAngle(int j) const { return j < int(start.size()) ? start[j] : total; }
    };

    const MeshType *mesh = nullptr;
    int vertexCount = 0;                       // size of m.vert (deleted vertices included)
    int faceCount = 0;                         // size of m.face (deleted faces included)
    std::vector<std::array<int, 3>> faceVerts; // vertex indices per face read canonically, {-1,-1,-1} when deleted or ignored
    int ignoredFaces = 0;                      // live faces with a repeated vertex: left out (no edges, no area)
    std::vector<int> vertFaceStart, vertFaces; // live faces around each vertex (CSR)
    std::vector<int> edgeOf;                   // edge id per half-edge, -1 for deleted faces
    std::vector<int> twin;                     // the other half-edge of a manifold edge, else -1
    std::vector<std::array<int, 2>> edgeVerts; // end points per edge: edge parameters run from [0] to [1]
    std::vector<int> edgeHalf;                 // a half-edge of each edge
    std::vector<char> edgeKind;                // EdgeKind per edge
    std::vector<char> vertOnBorder;            // vertex touches a border or non-manifold edge

    void Build(const MeshType &m)
    {
        mesh = &m;
        vertexCount = int(m.vert.size());
        faceCount = int(m.face.size());
        faceVerts.assign(faceCount, {-1, -1, -1});
        std::vector<int> count(vertexCount + 1, 0);
        ignoredFaces = 0;
        CanonicalFaces canon;  // so that a flipped copy of the mesh rounds every step the same way
        canon.Read(m);
        for (int f = 0; f < faceCount; ++f) {
            if (m.face[f].IsD()) continue;
            const std::array<int, 3> &v = canon.tri[f];
            if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0]) { ++ignoredFaces; continue; }  // no edges, no area
            faceVerts[f] = v;
            for (int k = 0; k < 3; ++k) ++count[v[k]];
        }
        vertFaceStart.assign(vertexCount + 1, 0);
        for (int v = 0; v < vertexCount; ++v) vertFaceStart[v + 1] = vertFaceStart[v] + count[v];
        vertFaces.assign(vertFaceStart[vertexCount], -1);
        std::vector<int> fill(vertFaceStart.begin(), vertFaceStart.end() - 1);
        for (int f = 0; f < faceCount; ++f)
            if (faceVerts[f][0] >= 0)
                for (int k = 0; k < 3; ++k) vertFaces[fill[faceVerts[f][k]]++] = f;

        // Edges numbered in the order of their first half-edge (face order): each group is filed at
        // its first half-edge (distinct keys), read back in half-edge order (a sort of millions of
        // edges took most of this build).
        const EdgePairing::Groups groups = EdgePairing::Group(faceVerts);
        std::vector<int> groupFrom(3 * size_t(faceCount), -1);
        for (int g = 0; g < groups.Count(); ++g) groupFrom[size_t(groups.Begin(g)[0])] = g;
        edgeOf.assign(3 * size_t(faceCount), -1);
        twin.assign(3 * size_t(faceCount), -1);
        edgeVerts.clear();
        edgeHalf.clear();
        edgeKind.clear();
        vertOnBorder.assign(vertexCount, 0);
        for (const int g : groupFrom) {
            if (g < 0) continue;
            const int id = int(edgeVerts.size()), n = groups.Size(g), *h = groups.Begin(g);
            const int a = EdgePairing::From(faceVerts, h[0]), b = EdgePairing::To(faceVerts, h[0]);
            edgeVerts.push_back({a, b});
            edgeHalf.push_back(h[0]);
            for (int i = 0; i < n; ++i) edgeOf[h[i]] = id;
            if (n == 2) {
                edgeKind.push_back(Manifold);
                twin[h[0]] = h[1];
                twin[h[1]] = h[0];
            } else {
                edgeKind.push_back(n == 1 ? Border : NonManifold);
                vertOnBorder[a] = vertOnBorder[b] = 1;
            }
        }
    }

    int EdgeCount() const { return int(edgeVerts.size()); }
    int FacesAround(int v) const { return vertFaceStart[v + 1] - vertFaceStart[v]; }
    const int *FacesBegin(int v) const { return vertFaces.data() + vertFaceStart[v]; }
    const int *FacesEnd(int v) const { return vertFaces.data() + vertFaceStart[v + 1]; }
    bool IsManifoldEdge(int e) const { return edgeKind[e] == Manifold; }

    // The one or two faces of a border or manifold edge (count returned).
    int EdgeFaces(int e, int faces[2]) const
    {
        int h = edgeHalf[e];
        faces[0] = h / 3;
        if (twin[h] < 0) return 1;
        faces[1] = twin[h] / 3;
        return 2;
    }

    bool FaceHasVertex(int f, int v) const
    {
        return faceVerts[f][0] == v || faceVerts[f][1] == v || faceVerts[f][2] == v;
    }
    int CornerOf(int f, int v) const
    {
        for (int k = 0; k < 3; ++k)
            if (faceVerts[f][k] == v) return k;
        return -1;
    }
    int EdgeInFace(int f, int a, int b) const  // the edge a-b of face f, or -1
    {
        for (int k = 0; k < 3; ++k) {
            int u = faceVerts[f][k], w = faceVerts[f][(k + 1) % 3];
            if ((u == a && w == b) || (u == b && w == a)) return edgeOf[3 * f + k];
        }
        return -1;
    }
    int SideOf(int f, int e) const  // k with edgeOf[3f+k] == e, or -1
    {
        for (int k = 0; k < 3; ++k)
            if (edgeOf[3 * f + k] == e) return k;
        return -1;
    }
    // The edge between two vertices, or -1 (searches the faces of a).
    int EdgeBetween(int a, int b) const
    {
        for (const int *it = FacesBegin(a); it != FacesEnd(a); ++it) {
            int f = *it, c = CornerOf(f, a);
            if (faceVerts[f][(c + 1) % 3] == b) return edgeOf[3 * f + c];
            if (faceVerts[f][(c + 2) % 3] == b) return edgeOf[3 * f + (c + 2) % 3];
        }
        return -1;
    }

    Vec Position(int v) const { return Vec::Construct(mesh->vert[v].cP()); }
    double EdgeLength(int e) const { return (Position(edgeVerts[e][1]) - Position(edgeVerts[e][0])).Norm(); }
    // Face f's cross product (p1 - p0) x (p2 - p0): twice its area times its normal (zero for a
    // deleted or ignored face).
    Vec Cross(int f) const
    {
        const std::array<int, 3> &v = faceVerts[f];
        if (v[0] < 0) return Vec(0, 0, 0);
        return (Position(v[1]) - Position(v[0])) ^ (Position(v[2]) - Position(v[0]));
    }
    double DoubleArea(int f) const { return Cross(f).Norm(); }
    // The angle between the normals of a manifold edge's two faces, in degrees (0 elsewhere, and
    // where a face has no normal).
    double DihedralDeg(int e) const
    {
        if (edgeKind[e] != Manifold) return 0;
        const int h = edgeHalf[e];
        return AngleBetween(Cross(h / 3), Cross(twin[h] / 3)) * 180 / M_PI;
    }

    // The ordered fan around v; false when v is not a manifold vertex with a single fan of
    // non-degenerate faces (non-manifold edges, several fans, repeated vertices).
    bool VertexFan(int v, Fan &fan) const
    {
        fan.faces.clear();
        fan.ring.clear();
        fan.closed = false;
        const int n = FacesAround(v);
        if (n == 0) return false;
        const int f0 = *FacesBegin(v);
        int c = CornerOf(f0, v);
        // Forward: leave each face through the spoke to its last ring vertex (into fan's own
        // vectors: fans are rebuilt for every vertex move, so no allocation once they have grown).
        fan.faces.push_back(f0);
        fan.ring.push_back(faceVerts[f0][(c + 1) % 3]);
        fan.ring.push_back(faceVerts[f0][(c + 2) % 3]);
        int f = f0;
        for (;;) {
            int out = fan.ring.back();
            int g = Across(f, v, out);
            if (g == -2) return false;
            if (g < 0) break;
            if (g == f0) { fan.closed = true; break; }
            if (int(fan.faces.size()) >= n) return false;
            fan.faces.push_back(g);
            fan.ring.push_back(ThirdVertex(g, v, out));
            f = g;
        }
        if (fan.closed) {
            fan.ring.pop_back();  // back at the first ring vertex
        } else {
            // Backward from f0 through the spoke to its first ring vertex, prepended (border vertices only).
            std::vector<int> backFaces, backRing;
            f = f0;
            int in = fan.ring.front();
            for (;;) {
                int g = Across(f, v, in);
                if (g == -2) return false;
                if (g < 0) break;
                if (int(fan.faces.size() + backFaces.size()) >= n) return false;
                backFaces.push_back(g);
                in = ThirdVertex(g, v, in);
                backRing.push_back(in);
                f = g;
            }
            fan.faces.insert(fan.faces.begin(), backFaces.rbegin(), backFaces.rend());
            fan.ring.insert(fan.ring.begin(), backRing.rbegin(), backRing.rend());
        }
        if (int(fan.faces.size()) != n) return false;  // more than one fan
        fan.spokeEdge.resize(fan.ring.size());
        for (size_t j = 0; j < fan.ring.size(); ++j)
            fan.spokeEdge[j] = EdgeInFace(fan.faces[std::min(j, fan.faces.size() - 1)], v, fan.ring[j]);
        const Vec p = Position(v);
        fan.angle.resize(n);
        fan.start.resize(n);
        fan.total = 0;
        for (int j = 0; j < n; ++j) {
            fan.start[j] = fan.total;
            fan.angle[j] = Angle(Position(fan.ring[j]) - p, Position(fan.ring[(j + 1) % fan.ring.size()]) - p);
            fan.total += fan.angle[j];
        }
        return true;
    }

    // Angle between two vectors in [0, pi] (atan2: accurate near 0 and pi).
    static double Angle(const Vec &a, const Vec &b)
    {
        return std::atan2((a ^ b).Norm(), a * b);
    }

private:
    // The face across the edge v-w of face f: -1 across a border, -2 when not manifold.
    int Across(int f, int v, int w) const
    {
        for (int k = 0; k < 3; ++k) {
            int a = faceVerts[f][k], b = faceVerts[f][(k + 1) % 3];
            if ((a == v && b == w) || (a == w && b == v)) {
                int e = edgeOf[3 * f + k];
                if (edgeKind[e] == Border) return -1;
                if (edgeKind[e] != Manifold) return -2;
                int g = twin[3 * f + k] / 3;
                if (CornerOf(g, v) < 0 || ThirdVertex(g, v, w) < 0) return -2;
                return g;
            }
        }
        return -2;
    }
    int ThirdVertex(int g, int v, int w) const
    {
        for (int k = 0; k < 3; ++k)
            if (faceVerts[g][k] != v && faceVerts[g][k] != w) return faceVerts[g][k];
        return -1;
    }
};

}  // namespace vcg_ext

#endif
