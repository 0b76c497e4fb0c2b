// Planning the split of a mesh along polylines, without touching the mesh: locate every polyline
// point, trace the segments whose ends share no face, and triangulate every face that gets new
// points (EmbeddingPlan). Any bad input stops here with a message, before a single change.
#ifndef VCG_EXT_EMBEDDING_PLAN_H
#define VCG_EXT_EMBEDDING_PLAN_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include <vcg/complex/complex.h>

#include <vcg_ext/common/live_box.h>
#include <vcg_ext/embedding/adjacency.h>
#include <vcg_ext/embedding/face_split.h>
#include <vcg_ext/embedding/locate.h>
#include <vcg_ext/embedding/result.h>
#include <vcg_ext/embedding/trace.h>
#include <vcg_ext/mesh_checks.h>

namespace vcg_ext {
namespace embedding {

template <class MeshType, class PolylineType>
class PlanBuilder
{
public:
    typedef typename MeshType::VertexType VertexType;
    typedef std::pair<int, int> IdPair;
    typedef EmbeddingResult Result;
    typedef EmbeddingPlan Plan;

    PlanBuilder(const MeshType &mesh, Plan &pl, vcg::CallBackPos *callback) : m(mesh), plan(pl), cb(callback) {}

    // Steps 1-3 for a validated tolerance (% of the bounding-box diagonal).
    Result Run(const PolylineType &poly, double tolerancePercent, bool polyIsMesh)
    {
        if (polyIsMesh) return Fail("the polyline layer is the mesh itself");
        if (poly.en == 0) return Fail(poly.fn > 0 ? "the polyline layer has no edges (it is a triangle mesh, not a polyline)"
                                                  : "the polyline layer has no edges");
        Lap lap;
        Progress(cb, 0, "Split along front: checking the mesh");
        const std::string meshProblem = CheckMesh(m);
        if (!meshProblem.empty()) {
            r.inputProblem = true;
            return Fail(meshProblem);
        }
        Progress(cb, 2, "Split along front: adjacency");
        std::string bad = plan.adj.Build(m);
        if (!bad.empty()) return Fail(bad);
        plan.vertexCount = int(m.vert.size());
        plan.faceCount = int(m.face.size());
        tol = plan.tolerance = r.tolerance = tolerancePercent / 100.0 * LiveVertexBox(m).Diag();
        if (!(tol > 0)) return Fail("the mesh has a zero bounding box");

        Progress(cb, 8, "Split along front: locating points");
        SurfaceLocator<MeshType> locator(m, plan.adj, tol);
        loc = &locator;
        SurfaceTracer<MeshType> tracer(m, plan.adj, tol);
        tr = &tracer;
        r.secondsSetup = lap();
        if (!LocatePolyline(poly)) return r;
        r.secondsLocate = lap();
        Progress(cb, 25, "Split along front: tracing segments");
        if (!EmbedSegments(poly)) return r;
        Progress(cb, 40, "Split along front: splitting faces");
        if (!SplitFaces()) return r;
        ExpandAlongEdgeSegments();
        r.secondsTraceSplit = lap();
        std::sort(front.begin(), front.end());
        front.erase(std::unique(front.begin(), front.end()), front.end());
        plan.frontEdges = front;
        r.frontEdges = int(front.size());
        r.verticesAdded = int(plan.newPoints.size());
        r.facesSplit = int(plan.splitFaces.size());
        for (const auto &pc : plan.pieces) r.facesAdded += int(pc.size()) - 1;
        return r;
    }

private:
    struct AlongEdge { int a, b, u, w; };

    const MeshType &m;
    Plan &plan;
    vcg::CallBackPos *cb;
    Result r;
    double tol = 0;
    const SurfaceLocator<MeshType> *loc = nullptr;
    SurfaceTracer<MeshType> *tr = nullptr;
    std::vector<int> polyPoint;                                   // polyline vertex -> point id
    std::unordered_map<uint64_t, std::vector<std::pair<double, int>>> edgePoints;  // t from the lower vertex
    std::unordered_map<int, std::vector<int>> facePoints;          // face -> point ids inside it
    std::unordered_map<int, std::vector<IdPair>> faceChords;       // face -> segments inside it
    std::vector<AlongEdge> along;                                  // segments along mesh edges
    std::vector<IdPair> front;

    // The mesh must be a consistently oriented 2-manifold with merged vertices and without degenerate
    // or duplicate faces (open and multi-component meshes are fine).
    static std::string CheckMesh(const MeshType &m)
    {
        return MeshChecks<MeshType>::Inspect(m, true).PipelineProblem();
    }

    Result Fail(const std::string &why)
    {
        r.error = why;
        return r;
    }
    bool Error(const std::string &why)
    {
        r.error = why;
        return false;
    }
    static std::string Pos(const EmbedVec &p)
    {
        char buf[96];
        snprintf(buf, sizeof buf, "(%g, %g, %g)", p[0], p[1], p[2]);
        return buf;
    }

    LocatedPoint PointOf(int id) const
    {
        if (id >= plan.vertexCount) return plan.newPoints[id - plan.vertexCount];
        LocatedPoint s;
        s.kind = LocatedPoint::AtVertex;
        s.vertex = id;
        s.face = plan.adj.vertexFace[id];
        s.pos = EmbedVec::Construct(m.vert[id].cP());
        return s;
    }

    // The id of a located point; points within the tolerance of an earlier one on the same
    // edge / in the same face are that point.
    int Register(const LocatedPoint &s)
    {
        const EmbeddingAdjacency &adj = plan.adj;
        if (s.kind == LocatedPoint::AtVertex) return s.vertex;
        if (s.kind == LocatedPoint::OnEdge) {
            const int u = adj.fv[s.face][s.edge], w = adj.fv[s.face][EmbeddingAdjacency::Next(s.edge)];
            const double t = u < w ? s.t : 1 - s.t;
            const double len = (loc->P(w) - loc->P(u)).Norm();
            auto &list = edgePoints[EdgeKey(u, w)];
            for (const auto &e : list)
                if (std::fabs(e.first - t) * len <= tol) return e.second;
            const int id = plan.vertexCount + int(plan.newPoints.size());
            plan.newPoints.push_back(s);
            list.push_back({t, id});
            return id;
        }
        auto &list = facePoints[s.face];
        for (int id : list)
            if ((PointOf(id).pos - s.pos).Norm() <= tol) return id;
        const int id = plan.vertexCount + int(plan.newPoints.size());
        plan.newPoints.push_back(s);
        list.push_back(id);
        return id;
    }

    bool LocatePolyline(const PolylineType &poly)
    {
        polyPoint.assign(poly.vert.size(), -1);
        std::vector<int> used;  // polyline vertices used by live edges, in order of first use
        std::vector<EmbedVec> points;
        for (int e = 0; e < int(poly.edge.size()); ++e) {
            if (poly.edge[e].IsD()) continue;
            for (int k = 0; k < 2; ++k) {
                const auto *pv = poly.edge[e].cV(k);
                const int i = int(vcg::tri::Index(poly, pv));
                if (polyPoint[i] != -1) continue;
                if (pv->IsD()) return Error("polyline edge " + std::to_string(e) + " uses a deleted vertex");
                const EmbedVec p = EmbedVec::Construct(pv->cP());
                if (!MeshChecks<MeshType>::IsFinite(p))
                    return Error("polyline point " + std::to_string(i) + " has NaN or infinite coordinates");
                polyPoint[i] = -2;
                used.push_back(i);
                points.push_back(p);
            }
        }
        std::vector<LocatedPoint> located;
        std::vector<char> found;
        loc->LocateAll(points, located, found);
        std::unordered_set<int> seen;
        for (size_t j = 0; j < used.size(); ++j) {
            if (!found[j]) {
                char buf[160];
                snprintf(buf, sizeof buf, " is %.3g from the surface, farther than the locate tolerance %.3g",
                         loc->DistanceToSurface(points[j]), tol);
                return Error("polyline point " + std::to_string(used[j]) + " " + Pos(points[j]) + buf);
            }
            const LocatedPoint &s = located[j];
            const int id = Register(s);
            polyPoint[used[j]] = id;
            ++r.polylinePoints;
            if (!seen.insert(id).second) { ++r.mergedPoints; continue; }
            if (s.kind == LocatedPoint::AtVertex) ++r.pointsAtVertices;
            else if (s.kind == LocatedPoint::OnEdge) ++r.pointsOnEdges;
            else ++r.pointsInFaces;
        }
        return true;
    }

    // Bit k set when point `id` lies on edge k of face f (corners lie on two edges); 0 inside.
    unsigned char MaskIn(int f, int id) const
    {
        const std::array<int, 3> &t = plan.adj.fv[f];
        if (id < plan.vertexCount) {
            const int k = plan.adj.CornerOf(f, id);
            return k < 0 ? 0 : (unsigned char)((1 << k) | (1 << EmbeddingAdjacency::Prev(k)));
        }
        const LocatedPoint &s = plan.newPoints[id - plan.vertexCount];
        if (s.kind != LocatedPoint::OnEdge) return 0;
        const uint64_t key = EdgeKey(plan.adj.fv[s.face][s.edge], plan.adj.fv[s.face][EmbeddingAdjacency::Next(s.edge)]);
        for (int k = 0; k < 3; ++k)
            if (EdgeKey(t[k], t[EmbeddingAdjacency::Next(k)]) == key) return (unsigned char)(1 << k);
        return 0;
    }

    // A sub-segment whose ends share a face: a chord of that face or a piece of one of its edges.
    bool AddSubSegment(int a, int b)
    {
        if (a == b) return true;
        const int f = tr->CommonFace(PointOf(a), PointOf(b));
        if (f < 0) return Error("internal error: consecutive traced points share no face");
        const unsigned char common = MaskIn(f, a) & MaskIn(f, b);
        if (common) {
            const int k = (common & 1) ? 0 : (common & 2) ? 1 : 2;
            along.push_back({a, b, plan.adj.fv[f][k], plan.adj.fv[f][EmbeddingAdjacency::Next(k)]});
        } else {
            faceChords[f].push_back({a, b});
        }
        return true;
    }

    bool EmbedSegments(const PolylineType &poly)
    {
        std::vector<LocatedPoint> path;
        std::vector<IdPair> done;
        const int total = int(poly.edge.size());
        int maxSteps = 0;
        for (int f = 0; f < int(plan.adj.fv.size()); ++f) maxSteps += plan.adj.IsLive(f);
        for (int e = 0; e < total; ++e) {
            if (poly.edge[e].IsD()) continue;
            if ((e & 1023) == 0) Progress(cb, 25 + 15 * e / std::max(1, total), "Split along front: tracing segments");
            int a = polyPoint[vcg::tri::Index(poly, poly.edge[e].cV(0))];
            int b = polyPoint[vcg::tri::Index(poly, poly.edge[e].cV(1))];
            if (a == b) continue;
            if (a > b) std::swap(a, b);
            done.push_back({a, b});
        }
        std::sort(done.begin(), done.end());
        done.erase(std::unique(done.begin(), done.end()), done.end());
        for (const IdPair &s : done) {
            ++r.polylineSegments;
            const LocatedPoint A = PointOf(s.first), B = PointOf(s.second);
            if (tr->CommonFace(A, B) >= 0) {
                if (!AddSubSegment(s.first, s.second)) return false;
                continue;
            }
            if (!tr->Trace(A, B, maxSteps, path)) {
                if (!tr->EdgePath(A, B, path))
                    return Error("the polyline segment from " + Pos(A.pos) + " to " + Pos(B.pos) +
                                 " cannot be traced on the surface (no path over the surface joins its ends)");
                ++r.edgePathSegments;
            }
            ++r.tracedSegments;
            int prev = s.first;
            for (const LocatedPoint &q : path) {
                const int before = int(plan.newPoints.size());
                const int id = Register(q);
                r.tracedCrossings += int(plan.newPoints.size()) - before;
                if (!AddSubSegment(prev, id)) return false;
                prev = id;
            }
            if (!AddSubSegment(prev, s.second)) return false;
        }
        return true;
    }

    // Faces with chords, points inside, or new points on their edges.
    std::vector<int> FacesToSplit() const
    {
        std::vector<int> faces;
        for (const auto &fc : faceChords) faces.push_back(fc.first);
        for (const auto &fp : facePoints) faces.push_back(fp.first);
        for (const auto &ep : edgePoints) {
            const LocatedPoint &s = plan.newPoints[ep.second.front().second - plan.vertexCount];
            faces.push_back(s.face);
            const int h = plan.adj.twin[3 * s.face + s.edge];
            if (h >= 0) faces.push_back(h / 3);
        }
        std::sort(faces.begin(), faces.end());
        faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
        return faces;
    }

    bool SplitFaces()
    {
        const std::vector<int> faces = FacesToSplit();
        std::vector<char> crossed(m.face.size(), 0);
        for (const auto &fc : faceChords) crossed[fc.first] = 1;
        for (const auto &fp : facePoints) crossed[fp.first] = 1;
        for (size_t i = 0; i < faces.size(); ++i) {
            if ((i & 1023) == 0) Progress(cb, 40 + int(25 * i / faces.size()), "Split along front: splitting faces");
            const int f = faces[i];
            r.facesCrossed += crossed[f];
            std::vector<int> ids;
            FaceSplitter::Input in;
            if (!BuildFaceInput(f, ids, in)) return false;
            FaceSplitter::Output out = FaceSplitter::Split(in);
            if (!out.error.empty()) {
                const EmbedVec c = (loc->P(plan.adj.fv[f][0]) + loc->P(plan.adj.fv[f][1]) + loc->P(plan.adj.fv[f][2])) / 3.0;
                return Error(out.error + " (face " + std::to_string(f) + " near " + Pos(c) +
                             "): the polylines cross each other or themselves there");
            }
            std::vector<std::array<int, 3>> tris;
            for (const auto &t : out.triangles) tris.push_back({ids[t[0]], ids[t[1]], ids[t[2]]});
            for (const auto &s : out.segmentEdges) front.push_back(UndirectedPair(ids[s.first], ids[s.second]));
            plan.splitFaces.push_back(f);
            plan.pieces.push_back(tris);
        }
        return true;
    }

    // The face in its own 2D frame: corners and edge points in loop order, then interior points.
    bool BuildFaceInput(int f, std::vector<int> &ids, FaceSplitter::Input &in)
    {
        const std::array<int, 3> &t = plan.adj.fv[f];
        const EmbedVec p0 = loc->P(t[0]), e1 = loc->P(t[1]) - p0, e2 = loc->P(t[2]) - p0;
        const EmbedVec n = e1 ^ e2;
        if (!(n.Norm() > 0) || !(e1.Norm() > 0)) {
            r.error = "the polylines cross a degenerate face (" + std::to_string(f) + ")";
            return false;
        }
        const EmbedVec u = e1 / e1.Norm(), v = (n ^ u).Normalize();
        auto add = [&](int id, unsigned char mask) {
            const EmbedVec q = PointOf(id).pos - p0;
            ids.push_back(id);
            in.xy.push_back(FaceSplitter::P2(q * u, q * v));
            in.edgeMask.push_back(mask);
        };
        for (int k = 0; k < 3; ++k) {
            const int a = t[k], b = t[EmbeddingAdjacency::Next(k)];
            in.loop.push_back(int(ids.size()));
            add(a, (unsigned char)((1 << k) | (1 << EmbeddingAdjacency::Prev(k))));
            auto it = edgePoints.find(EdgeKey(a, b));
            if (it == edgePoints.end()) continue;
            std::vector<std::pair<double, int>> onEdge = it->second;
            if (a > b)
                for (auto &e : onEdge) e.first = 1 - e.first;
            std::sort(onEdge.begin(), onEdge.end());
            for (const auto &e : onEdge) {
                in.loop.push_back(int(ids.size()));
                add(e.second, (unsigned char)(1 << k));
            }
        }
        auto fp = facePoints.find(f);
        if (fp != facePoints.end())
            for (int id : fp->second) add(id, 0);
        auto fc = faceChords.find(f);
        if (fc != faceChords.end())
            for (const IdPair &s : fc->second) {
                const int a = int(std::find(ids.begin(), ids.end(), s.first) - ids.begin());
                const int b = int(std::find(ids.begin(), ids.end(), s.second) - ids.begin());
                in.segments.push_back({a, b});
            }
        in.tolerance = tol;
        return true;
    }

    // Segments along a mesh edge select every piece of it between their ends.
    void ExpandAlongEdgeSegments()
    {
        for (const AlongEdge &s : along) {
            const int lo = std::min(s.u, s.w), hi = std::max(s.u, s.w);
            std::vector<std::pair<double, int>> chain{{0.0, lo}, {1.0, hi}};
            auto it = edgePoints.find(EdgeKey(lo, hi));
            if (it != edgePoints.end()) chain.insert(chain.end(), it->second.begin(), it->second.end());
            std::sort(chain.begin(), chain.end());
            int i = -1, j = -1;
            for (int k = 0; k < int(chain.size()); ++k) {
                if (chain[k].second == s.a) i = k;
                if (chain[k].second == s.b) j = k;
            }
            if (i > j) std::swap(i, j);
            for (int k = i; k >= 0 && k < j; ++k) front.push_back(UndirectedPair(chain[k].second, chain[k + 1].second));
        }
    }
};

}  // namespace embedding
}  // namespace vcg_ext

#endif
