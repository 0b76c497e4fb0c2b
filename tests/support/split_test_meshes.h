// Test helpers for "Split Triangles along Front": polylines on test meshes (hand-made, plane
// sections with points inside edges, jaggy region boundaries through vertices) and an independent
// checker of the splitting invariants (vcg's own closest-point grid, brute-force graph walks).
#ifndef QMF_TESTS_SPLIT_TEST_MESHES_H
#define QMF_TESTS_SPLIT_TEST_MESHES_H

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <queue>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "test_mesh.h"
#include <vcg/complex/algorithms/closest.h>
#include <vcg/complex/append.h>
#include <vcg/space/index/grid_static_ptr.h>
#include <vcg_ext/common/front_edges.h>
#include <vcg_ext/common/point_face_distance.h>
#include <vcg_ext/mesh_checks.h>
#include <vcg_ext/polyline_embedding.h>

namespace qmf_test {
namespace split {

typedef vcg::Point3d D3;


typedef vcg_ext::PolylineEmbedding<TMesh> Embedding;

inline void Copy(TMesh &dst, const TMesh &src) { vcg::tri::Append<TMesh, TMesh>::MeshCopy(dst, const_cast<TMesh &>(src)); }

inline Embedding::Result Embed(TMesh &m, const TMesh &poly, double tolPercent = 1e-4)
{
    Embedding::Params p;
    p.locateTolerancePercent = tolPercent;
    return Embedding::Embed(m, poly, p);
}

// Regular tetrahedron-like closed mesh, outward oriented.
inline void MakeTetra(TMesh &m)
{
    Build(m, {P3(0, 0, 0), P3(1, 0, 0), P3(0, 1, 0), P3(0, 0, 1)}, {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}});
}

inline P3 Lerp(const P3 &a, const P3 &b, float t) { return a + (b - a) * t; }

inline int CountSelectedEdges(const TMesh &m) { return int(vcg_ext::FrontEdges<TMesh>::Collect(m).size()); }

// An edge-only mesh through `pts` (closed: last joined to first).
inline void MakePolyline(TMesh &poly, const std::vector<P3> &pts, bool closed = false)
{
    poly.Clear();
    if (pts.empty()) return;
    vcg::tri::Allocator<TMesh>::AddVertices(poly, pts.size());
    for (size_t i = 0; i < pts.size(); ++i) poly.vert[i].P() = pts[i];
    for (size_t i = 0; i + 1 < pts.size() + (closed ? 1 : 0); ++i)
        vcg::tri::Allocator<TMesh>::AddEdge(poly, &poly.vert[i], &poly.vert[(i + 1) % pts.size()]);
}

// Appends the edges (and vertices) of `src` to `dst`.
inline void AppendPolyline(TMesh &dst, const TMesh &src)
{
    vcg::tri::Append<TMesh, TMesh>::Mesh(dst, const_cast<TMesh &>(src));
}

// The section of `m` by the plane n.p = d as a polyline: one point inside every edge whose ends
// are on opposite sides, one segment per crossed face (consecutive points share a face, like the
// output of "Smooth Region Boundaries"). Returns false when the plane passes through a vertex.
inline bool PlaneSectionPolyline(const TMesh &m, const D3 &n, double d, TMesh &poly)
{
    poly.Clear();
    std::map<std::pair<int, int>, int> pointOf;
    std::vector<P3> pts;
    std::vector<std::pair<int, int>> segs;
    auto side = [&](const TVertex *v) { return n * D3::Construct(v->cP()) - d; };
    for (const TFace &f : m.face) {
        if (f.IsD()) continue;
        std::vector<int> cut;
        for (int k = 0; k < 3; ++k) {
            const TVertex *a = f.cV(k), *b = f.cV((k + 1) % 3);
            const double sa = side(a), sb = side(b);
            if (sa == 0 || sb == 0) return false;
            if ((sa < 0) == (sb < 0)) continue;
            int ia = int(vcg::tri::Index(m, a)), ib = int(vcg::tri::Index(m, b));
            auto key = vcg_ext::UndirectedPair(ia, ib);
            auto it = pointOf.find(key);
            if (it == pointOf.end()) {
                const double t = sa / (sa - sb);
                const D3 p = D3::Construct(a->cP()) + (D3::Construct(b->cP()) - D3::Construct(a->cP())) * t;
                it = pointOf.emplace(key, int(pts.size())).first;
                pts.push_back(P3::Construct(p));
            }
            cut.push_back(it->second);
        }
        if (cut.size() == 2) segs.push_back({cut[0], cut[1]});
    }
    if (pts.empty()) return true;
    vcg::tri::Allocator<TMesh>::AddVertices(poly, pts.size());
    for (size_t i = 0; i < pts.size(); ++i) poly.vert[i].P() = pts[i];
    for (auto &s : segs) vcg::tri::Allocator<TMesh>::AddEdge(poly, &poly.vert[s.first], &poly.vert[s.second]);
    return true;
}

// The (jaggy) boundaries between faces of different integral quality, as a polyline through mesh
// vertices: each segment is a mesh edge.
inline void RegionBoundaryPolyline(const TMesh &m, TMesh &poly)
{
    poly.Clear();
    std::map<std::pair<int, int>, std::vector<int>> faceIds;
    for (const TFace &f : m.face)
        for (int k = 0; k < 3; ++k) {
            auto key = vcg_ext::UndirectedPair(int(vcg::tri::Index(m, f.cV(k))), int(vcg::tri::Index(m, f.cV((k + 1) % 3))));
            faceIds[key].push_back(int(f.cQ()));
        }
    std::map<int, int> pointOf;
    auto point = [&](int v) {
        auto it = pointOf.find(v);
        if (it != pointOf.end()) return it->second;
        int i = int(poly.vert.size());
        vcg::tri::Allocator<TMesh>::AddVertices(poly, 1);
        poly.vert[i].P() = m.vert[v].cP();
        pointOf[v] = i;
        return i;
    };
    std::vector<std::pair<int, int>> segs;
    for (auto &e : faceIds)
        if (e.second.size() == 2 && e.second[0] != e.second[1]) segs.push_back({point(e.first.first), point(e.first.second)});
    for (auto &s : segs) vcg::tri::Allocator<TMesh>::AddEdge(poly, &poly.vert[s.first], &poly.vert[s.second]);
}

// Writes the polyline as OBJ with "%f" (6 decimals, like MeshLab) and reads it back.
inline void RoundTripObj6(const TMesh &poly, TMesh &out)
{
    std::vector<P3> pts;
    for (auto &v : poly.vert) {
        char buf[128];
        snprintf(buf, sizeof buf, "%f %f %f", double(v.cP()[0]), double(v.cP()[1]), double(v.cP()[2]));
        std::istringstream in(buf);
        float x, y, z;
        in >> x >> y >> z;
        pts.push_back(P3(x, y, z));
    }
    out.Clear();
    vcg::tri::Allocator<TMesh>::AddVertices(out, pts.size());
    for (size_t i = 0; i < pts.size(); ++i) out.vert[i].P() = pts[i];
    for (auto &e : poly.edge)
        vcg::tri::Allocator<TMesh>::AddEdge(out, &out.vert[vcg::tri::Index(poly, e.cV(0))], &out.vert[vcg::tri::Index(poly, e.cV(1))]);
}

inline double BoxDiag(const TMesh &m)
{
    vcg::Box3d b;
    for (auto &v : m.vert)
        if (!v.IsD()) b.Add(D3::Construct(v.cP()));
    return b.Diag();
}

// Closest-face queries on a copy of the input (vcg's grid, independent of the code under test).
class ClosestOnInput
{
public:
    explicit ClosestOnInput(const TMesh &input)
    {
        vcg::tri::Append<TMesh, TMesh>::MeshCopy(mesh, const_cast<TMesh &>(input));
        vcg::tri::UpdateBounding<TMesh>::Box(mesh);
        vcg::tri::UpdateNormal<TMesh>::PerFaceNormalized(mesh);
        grid.Set(mesh.face.begin(), mesh.face.end());
        maxDist = float(mesh.bbox.Diag());
    }
    const TFace *Closest(const P3 &p, float &dist, P3 &q)
    {
        vcg_ext::PointFaceDistance<TFace> exactDistance;
        vcg::tri::EmptyTMark<TMesh> noMarks;
        return grid.GetClosest(exactDistance, noMarks, p, maxDist, dist, q);
    }
    TMesh mesh;

private:
    vcg::GridStaticPtr<TFace, float> grid;
    float maxDist;
};

inline double Area(const TFace &f)
{
    const D3 a = D3::Construct(f.cP(0)), b = D3::Construct(f.cP(1)), c = D3::Construct(f.cP(2));
    return 0.5 * ((b - a) ^ (c - a)).Norm();
}

inline double Area(const TMesh &m)
{
    double a = 0;
    for (auto &f : m.face)
        if (!f.IsD()) a += Area(f);
    return a;
}

struct SplitExpectations {
    bool closedFront = true;        // the selected edges are exactly the region-id boundaries
    bool pointsInFaces = false;     // new vertices may lie inside input faces (user polylines)
    bool straightSegments = true;   // each polyline segment is embedded as a straight chain
    bool segmentsAreEdges = false;  // each polyline segment is one selected mesh edge (no point inside it)
};

// Everything "Split Triangles along Front" promises, checked against the input mesh and polyline.
inline void ExpectSplitInvariants(const TMesh &before, const TMesh &after, const TMesh &poly,
                                  const SplitExpectations &x = SplitExpectations())
{
    typedef vcg_ext::MeshChecks<TMesh> Checks;
    const double diag = BoxDiag(before);
    const vcg_ext::MeshCheckReport in = Checks::Inspect(before), out = Checks::Inspect(after);
    EXPECT_EQ(out.degenerateFaces, 0) << "zero-area faces";
    EXPECT_EQ(out.duplicateFaces, 0);
    EXPECT_EQ(out.nonManifoldEdges, 0);
    EXPECT_EQ(out.nonManifoldVertices, 0);
    EXPECT_EQ(out.inconsistentEdges, 0) << "orientation";
    EXPECT_EQ(out.boundaryEdges > 0, in.boundaryEdges > 0) << "closed in -> closed out";
    EXPECT_EQ(out.components, in.components);
    EXPECT_NEAR(Area(after), Area(before), 1e-6 * Area(before)) << "total area";

    // Faces keep the orientation of the input face they lie in; new vertices lie on input edges.
    ClosestOnInput input(before);
    int flipped = 0, offEdge = 0, offSurface = 0;
    for (const TFace &f : after.face) {
        if (f.IsD()) continue;
        const P3 c = (f.cP(0) + f.cP(1) + f.cP(2)) / 3.f;
        float d;
        P3 q;
        const TFace *g = input.Closest(c, d, q);
        D3 n = (D3::Construct(f.cP(1)) - D3::Construct(f.cP(0))) ^ (D3::Construct(f.cP(2)) - D3::Construct(f.cP(0)));
        if (g == nullptr || n * D3::Construct(g->cN()) <= 0) ++flipped;
    }
    for (size_t v = before.vert.size(); v < after.vert.size(); ++v) {
        float d;
        P3 q;
        const TFace *g = input.Closest(after.vert[v].cP(), d, q);
        if (g == nullptr || d > 1e-6 * diag) { ++offSurface; continue; }
        double best = 1e30;
        for (int k = 0; k < 3; ++k) {
            const D3 a = D3::Construct(g->cP(k)), b = D3::Construct(g->cP((k + 1) % 3)), p = D3::Construct(after.vert[v].cP());
            const double t = std::max(0.0, std::min(1.0, ((p - a) * (b - a)) / (b - a).SquaredNorm()));
            best = std::min(best, (a + (b - a) * t - p).Norm());
        }
        if (best > 1e-6 * diag) ++offEdge;
    }
    EXPECT_EQ(flipped, 0) << "faces flipped against the input surface";
    EXPECT_EQ(offSurface, 0) << "new vertices off the input surface";
    if (!x.pointsInFaces) {
        EXPECT_EQ(offEdge, 0) << "new vertices not on an input edge";
    }
    for (size_t v = 0; v < before.vert.size(); ++v)
        EXPECT_EQ(after.vert[v].cP(), before.vert[v].cP()) << "input vertex " << v << " moved";

    // Selection: both sides flagged, no faux bits, and (closed front) exactly the id boundaries.
    EXPECT_EQ(vcg_ext::FrontEdges<TMesh>::CountOneSided(after), 0);
    int faux = 0, idBoundaryNotSelected = 0, selectedNotIdBoundary = 0;
    std::map<std::pair<int, int>, std::vector<const TFace *>> edgeFaces;
    for (const TFace &f : after.face) {
        if (f.IsD()) continue;
        if (f.cFlags() & (TFace::FAUX0 | TFace::FAUX1 | TFace::FAUX2)) ++faux;
        for (int k = 0; k < 3; ++k)
            edgeFaces[vcg_ext::UndirectedPair(int(vcg::tri::Index(after, f.cV(k))), int(vcg::tri::Index(after, f.cV((k + 1) % 3))))].push_back(&f);
    }
    std::map<int, std::set<int>> selectedGraph;
    for (auto &e : edgeFaces) {
        const TFace *f = e.second[0];
        int k = 0;
        while (k < 3 && vcg_ext::UndirectedPair(int(vcg::tri::Index(after, f->cV(k))), int(vcg::tri::Index(after, f->cV((k + 1) % 3)))) != e.first) ++k;
        const bool selected = f->IsFaceEdgeS(k);
        if (selected) { selectedGraph[e.first.first].insert(e.first.second); selectedGraph[e.first.second].insert(e.first.first); }
        if (e.second.size() != 2) continue;
        const bool idBoundary = e.second[0]->cQ() != e.second[1]->cQ();
        if (idBoundary && !selected) ++idBoundaryNotSelected;
        if (selected && !idBoundary) ++selectedNotIdBoundary;
    }
    EXPECT_EQ(faux, 0) << "faux flags must stay clear";
    EXPECT_EQ(idBoundaryNotSelected, 0) << "region-id boundaries that are not front edges";
    if (x.closedFront) {
        EXPECT_EQ(selectedNotIdBoundary, 0) << "front edges that are not region-id boundaries";
    }

    // Every polyline segment is a chain of selected edges (straight: through vertices on it).
    auto nearestVertex = [&](const P3 &p) {
        int best = -1;
        double bd = 1e30;
        for (size_t v = 0; v < after.vert.size(); ++v) {
            const double d = (D3::Construct(after.vert[v].cP()) - D3::Construct(p)).Norm();
            if (d < bd) { bd = d; best = int(v); }
        }
        return bd <= 3e-6 * diag ? best : -1;
    };
    int missingChains = 0, notEdges = 0;
    for (const TEdge &e : poly.edge) {
        const int a = nearestVertex(e.cV(0)->cP()), b = nearestVertex(e.cV(1)->cP());
        if (a < 0 || b < 0) { ++missingChains; continue; }
        if (a == b) continue;
        if (!selectedGraph[a].count(b)) ++notEdges;
        const D3 pa = D3::Construct(after.vert[a].cP()), pb = D3::Construct(after.vert[b].cP());
        auto onSegment = [&](int v) {
            const D3 p = D3::Construct(after.vert[v].cP());
            const double t = ((p - pa) * (pb - pa)) / (pb - pa).SquaredNorm();
            return t >= -1e-9 && t <= 1 + 1e-9 && (pa + (pb - pa) * t - p).Norm() <= 1e-5 * diag;
        };
        std::set<int> seen{a};
        std::queue<int> q;
        q.push(a);
        while (!q.empty() && !seen.count(b)) {
            const int v = q.front();
            q.pop();
            for (int w : selectedGraph[v])
                if (!seen.count(w) && (!x.straightSegments || onSegment(w))) { seen.insert(w); q.push(w); }
        }
        if (!seen.count(b)) ++missingChains;
    }
    EXPECT_EQ(missingChains, 0) << "polyline segments that are not chains of selected mesh edges";
    if (x.segmentsAreEdges) {
        EXPECT_EQ(notEdges, 0) << "polyline segments that are not single selected mesh edges";
    }
}

}  // namespace split
}  // namespace qmf_test

#endif
