// Splitting a triangle mesh along polylines (seed paper, section 3.3): afterwards every polyline
// is a chain of mesh edges, those edges are selected face-edges, and the region ids in face quality
// are constant on each patch the polylines cut out.
//
//   1. Locate   every polyline point: at a vertex, inside an edge or inside a face (embedding_locate.h).
//   2. Trace    segments whose ends share no face across the faces between them (embedding_trace.h).
//   3. Split    each face holding polyline points: one new vertex per point on an edge, shared by
//               both faces of that edge; chords cut the face's looped vertex list, the pieces are
//               triangulated maximising the smallest angle (embedding_face_split.h). No snapping:
//               points are embedded where they are located.
//   4. Relabel  patches (faces connected without crossing a selected edge): each takes the region id
//               covering most of its area before the split (a patch whose majority id a larger patch
//               already took gets a new id), so id boundaries are exactly the selected edges of a
//               closed front.
//
// Prepare() does steps 1-3 without touching the mesh (bad input: an error, nothing changed);
// Apply() writes the result. Work is O(F) set-up (adjacency, grid, relabelling flood) plus time
// proportional to the polyline points and the faces they cross.
#ifndef VCG_EXT_POLYLINE_EMBEDDING_H
#define VCG_EXT_POLYLINE_EMBEDDING_H

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/update/topology.h>

#include "embedding_adjacency.h"
#include "embedding_face_split.h"
#include "embedding_locate.h"
#include "embedding_trace.h"
#include "front_edges.h"
#include "region_ids.h"

namespace vcg_ext {

template <class MeshType, class PolylineType = MeshType>
class PolylineEmbedding
{
public:
    typedef embedding::EmbeddingAdjacency EmbeddingAdjacency;
    typedef embedding::SurfacePoint SurfacePoint;
    typedef embedding::EmbedVec EmbedVec;
    typedef embedding::FaceSplitter FaceSplitter;
    typedef typename MeshType::FaceType FaceType;
    typedef typename MeshType::VertexType VertexType;
    typedef typename MeshType::CoordType CoordType;
    typedef typename MeshType::ScalarType ScalarType;
    typedef std::pair<int, int> IdPair;

    struct Params {
        double locateTolerancePercent = 1e-4;  // % of the mesh bounding-box diagonal

        std::string Validate() const
        {
            if (!(locateTolerancePercent > 0 && locateTolerancePercent <= 10))
                return "the locate tolerance must be in (0, 10] % of the bounding box diagonal";
            return "";
        }
    };

    struct Result {
        std::string error;           // empty on success
        double tolerance = 0;        // locate tolerance, absolute
        int polylinePoints = 0;      // polyline vertices used by its edges
        int polylineSegments = 0;    // polyline edges embedded (zero-length ones skipped)
        int pointsAtVertices = 0;    // distinct located polyline points, by kind
        int pointsOnEdges = 0;
        int pointsInFaces = 0;
        int mergedPoints = 0;        // polyline points merged with an earlier one within the tolerance
        int tracedSegments = 0;      // segments whose ends shared no face
        int tracedCrossings = 0;     // edge crossings / vertices added by tracing
        int facesCrossed = 0;        // faces a polyline segment runs through (inside)
        int facesSplit = 0;          // faces re-triangulated (crossed, or with a new vertex on an edge)
        int verticesAdded = 0;
        int facesAdded = 0;
        int frontEdges = 0;          // selected mesh edges
        int missingFrontEdges = 0;   // front edges not found in the mesh afterwards (always 0)
        int patches = 0;
        int danglingFrontEdges = 0;  // selected edges with one patch on both sides (open polyline ends)
        double minAngleDeg = 0;      // smallest angle of the new triangles (0 when none)
        std::vector<int> faceRegion; // region id per face after relabelling (-1: deleted)
        double secondsPrepare = 0, secondsApply = 0, seconds = 0;
        // Phases: checks + adjacency + grid, locating, tracing + planning the faces, writing faces and
        // adjacency and selection, relabelling patches (+ vcg's FF/VF when the mesh has them).
        double secondsSetup = 0, secondsLocate = 0, secondsTraceSplit = 0, secondsWrite = 0, secondsRelabel = 0;
    };

    // Everything Apply() needs, computed without touching the mesh.
    struct Plan {
        EmbeddingAdjacency adj;
        double tolerance = 0;
        int vertexCount = 0, faceCount = 0;
        std::vector<SurfacePoint> newPoints;                   // point id = vertexCount + index
        std::vector<int> splitFaces;                           // faces to re-triangulate
        std::vector<std::vector<std::array<int, 3>>> pieces;   // per split face: triangles over point ids
        std::vector<IdPair> frontEdges;                        // point id pairs (a < b)
        Result stats;
        bool ready = false;
    };

    // Steps 1-3 (read-only): on error, Result::error says why and the plan is not ready.
    static Result Prepare(const MeshType &m, const PolylineType &poly, const Params &p, Plan &plan,
                          vcg::CallBackPos *cb = nullptr)
    {
        auto t0 = std::chrono::steady_clock::now();
        plan = Plan();
        Planner planner(m, plan, cb);
        Result r = planner.Run(poly, p, static_cast<const void *>(&m) == static_cast<const void *>(&poly));
        r.secondsPrepare = Seconds(t0);
        r.seconds = r.secondsPrepare;
        plan.ready = r.error.empty();
        plan.stats = r;
        return r;
    }

    // Writes a ready plan into the mesh it was prepared on (step 4 included).
    static Result Apply(MeshType &m, Plan &plan, vcg::CallBackPos *cb = nullptr)
    {
        auto t0 = std::chrono::steady_clock::now();
        Result r = plan.stats;
        if (!plan.ready) { r.error = "the plan is not ready"; return r; }
        if (int(m.vert.size()) != plan.vertexCount || int(m.face.size()) != plan.faceCount) {
            r.error = "the mesh changed since the plan was prepared";
            return r;
        }
        Writer w(m, plan, r, cb);
        w.Run();
        plan.ready = false;
        r.secondsApply = Seconds(t0);
        r.seconds = r.secondsPrepare + r.secondsApply;
        return r;
    }

    // Prepare + Apply.
    static Result Embed(MeshType &m, const PolylineType &poly, const Params &p, vcg::CallBackPos *cb = nullptr)
    {
        Plan plan;
        Result r = Prepare(m, poly, p, plan, cb);
        if (!r.error.empty()) return r;
        return Apply(m, plan, cb);
    }

private:
    static double Seconds(std::chrono::steady_clock::time_point t0)
    {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
    // Seconds since the last lap (or the start).
    struct Lap {
        std::chrono::steady_clock::time_point t = std::chrono::steady_clock::now();
        double operator()()
        {
            const auto now = std::chrono::steady_clock::now();
            const double s = std::chrono::duration<double>(now - t).count();
            t = now;
            return s;
        }
    };
    static IdPair Ordered(int a, int b) { return a < b ? IdPair(a, b) : IdPair(b, a); }
    static uint64_t EdgeKey(int u, int w)
    {
        if (u > w) std::swap(u, w);
        return (uint64_t(uint32_t(u)) << 32) | uint32_t(w);
    }
    static void Progress(vcg::CallBackPos *cb, int percent, const char *what)
    {
        if (cb) cb(std::min(99, std::max(0, percent)), what);
    }

    // ---------------------------------------------------------------- planning (read-only)
    class Planner
    {
    public:
        Planner(const MeshType &mesh, Plan &pl, vcg::CallBackPos *callback) : m(mesh), plan(pl), cb(callback) {}

        Result Run(const PolylineType &poly, const Params &p, bool polyIsMesh)
        {
            r.error = p.Validate();
            if (!r.error.empty()) return r;
            if (polyIsMesh) return Fail("the polyline layer is the mesh itself");
            if (poly.en == 0) return Fail(poly.fn > 0 ? "the polyline layer has no edges (it is a triangle mesh, not a polyline)"
                                                      : "the polyline layer has no edges");
            if (m.fn == 0) return Fail("the mesh has no faces");
            Lap lap;
            for (const VertexType &v : m.vert)
                if (!v.IsD() && !(std::isfinite(double(v.cP()[0])) && std::isfinite(double(v.cP()[1])) && std::isfinite(double(v.cP()[2]))))
                    return Fail("the mesh has vertices with NaN or infinite coordinates");
            Progress(cb, 2, "Split along front: adjacency");
            std::string bad = plan.adj.Build(m);
            if (!bad.empty()) return Fail(bad);
            plan.vertexCount = int(m.vert.size());
            plan.faceCount = int(m.face.size());
            vcg::Box3<double> box;
            for (const VertexType &v : m.vert)
                if (!v.IsD()) box.Add(EmbedVec::Construct(v.cP()));
            tol = plan.tolerance = r.tolerance = p.locateTolerancePercent / 100.0 * box.Diag();
            if (!(tol > 0)) return Fail("the mesh has a zero bounding box");

            Progress(cb, 8, "Split along front: locating points");
            embedding::SurfaceLocator<MeshType> locator(m, plan.adj, tol);
            loc = &locator;
            embedding::SurfaceTracer<MeshType> tracer(m, plan.adj, tol);
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
        const embedding::SurfaceLocator<MeshType> *loc = nullptr;
        embedding::SurfaceTracer<MeshType> *tr = nullptr;
        std::vector<int> polyPoint;                                   // polyline vertex -> point id
        std::unordered_map<uint64_t, std::vector<std::pair<double, int>>> edgePoints;  // t from the lower vertex
        std::unordered_map<int, std::vector<int>> facePoints;          // face -> point ids inside it
        std::unordered_map<int, std::vector<IdPair>> faceChords;       // face -> segments inside it
        std::vector<AlongEdge> along;                                  // segments along mesh edges
        std::vector<IdPair> front;

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

        SurfacePoint PointOf(int id) const
        {
            if (id >= plan.vertexCount) return plan.newPoints[id - plan.vertexCount];
            SurfacePoint s;
            s.kind = SurfacePoint::AtVertex;
            s.vertex = id;
            s.face = plan.adj.vertexFace[id];
            s.pos = EmbedVec::Construct(m.vert[id].cP());
            return s;
        }

        // The id of a located point; points within the tolerance of an earlier one on the same
        // edge / in the same face are that point.
        int Register(const SurfacePoint &s)
        {
            const EmbeddingAdjacency &adj = plan.adj;
            if (s.kind == SurfacePoint::AtVertex) return s.vertex;
            if (s.kind == SurfacePoint::OnEdge) {
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
                    if (!(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])))
                        return Error("polyline point " + std::to_string(i) + " has NaN or infinite coordinates");
                    polyPoint[i] = -2;
                    used.push_back(i);
                    points.push_back(p);
                }
            }
            std::vector<SurfacePoint> located;
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
                const SurfacePoint &s = located[j];
                const int id = Register(s);
                polyPoint[used[j]] = id;
                ++r.polylinePoints;
                if (!seen.insert(id).second) { ++r.mergedPoints; continue; }
                if (s.kind == SurfacePoint::AtVertex) ++r.pointsAtVertices;
                else if (s.kind == SurfacePoint::OnEdge) ++r.pointsOnEdges;
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
            const SurfacePoint &s = plan.newPoints[id - plan.vertexCount];
            if (s.kind != SurfacePoint::OnEdge) return 0;
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
            std::vector<SurfacePoint> path;
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
                const SurfacePoint A = PointOf(s.first), B = PointOf(s.second);
                if (tr->CommonFace(A, B) >= 0) {
                    if (!AddSubSegment(s.first, s.second)) return false;
                    continue;
                }
                if (!tr->Trace(A, B, maxSteps, path))
                    return Error("the polyline segment from " + Pos(A.pos) + " to " + Pos(B.pos) +
                                 " cannot be traced on the surface (the plane section through its ends does not join them)");
                ++r.tracedSegments;
                int prev = s.first;
                for (const SurfacePoint &q : path) {
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
                const SurfacePoint &s = plan.newPoints[ep.second.front().second - plan.vertexCount];
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
                for (const auto &s : out.segmentEdges) front.push_back(Ordered(ids[s.first], ids[s.second]));
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
                for (int k = i; k >= 0 && k < j; ++k) front.push_back(Ordered(chain[k].second, chain[k + 1].second));
            }
        }
    };

    // ---------------------------------------------------------------- writing
    class Writer
    {
    public:
        Writer(MeshType &mesh, Plan &pl, Result &res, vcg::CallBackPos *callback) : m(mesh), plan(pl), r(res), cb(callback) {}

        void Run()
        {
            Progress(cb, 70, "Split along front: writing faces");
            Lap lap;
            AddVertices();
            std::vector<int> changed, parent;
            AddFaces(changed, parent);
            UpdateAdjacency(changed, parent);
            Progress(cb, 80, "Split along front: selecting front edges");
            SelectFrontEdges();
            for (int f : changed) UpdateFace(f);
            MeasureNewTriangles(changed);
            r.secondsWrite = lap();
            Progress(cb, 85, "Split along front: relabelling patches");
            Relabel();
            WriteVcgTopology();
            r.secondsRelabel = lap();
        }

    private:
        MeshType &m;
        Plan &plan;
        Result &r;
        vcg::CallBackPos *cb;

        EmbedVec P(int v) const { return EmbedVec::Construct(m.vert[v].cP()); }

        void AddVertices()
        {
            const int n = int(plan.newPoints.size());
            if (n == 0) return;
            vcg::tri::Allocator<MeshType>::AddVertices(m, n);
            for (int k = 0; k < n; ++k) {
                const SurfacePoint &s = plan.newPoints[k];
                VertexType &v = m.vert[plan.vertexCount + k];
                int src[3];
                double w[3];
                int count;
                if (s.kind == SurfacePoint::OnEdge) {
                    src[0] = plan.adj.fv[s.face][s.edge];
                    src[1] = plan.adj.fv[s.face][EmbeddingAdjacency::Next(s.edge)];
                    w[0] = 1 - s.t;
                    w[1] = s.t;
                    count = 2;
                } else {
                    for (int i = 0; i < 3; ++i) { src[i] = plan.adj.fv[s.face][i]; w[i] = s.bary[i]; }
                    count = 3;
                }
                const int nearest = int(std::max_element(w, w + count) - w);
                v.ImportData(m.vert[src[nearest]]);  // attributes without an interpolation rule
                v.Flags() = 0;
                v.P() = CoordType::Construct(s.pos);
                if (vcg::tri::HasPerVertexNormal(m)) {
                    EmbedVec nrm(0, 0, 0);
                    for (int i = 0; i < count; ++i) nrm += EmbedVec::Construct(m.vert[src[i]].cN()) * w[i];
                    if (nrm.Norm() > 0) v.N() = CoordType::Construct(nrm.Normalize());
                }
                if (vcg::tri::HasPerVertexQuality(m)) {
                    double q = 0;
                    for (int i = 0; i < count; ++i) q += double(m.vert[src[i]].cQ()) * w[i];
                    v.Q() = typename VertexType::QualityType(q);
                }
                if (vcg::tri::HasPerVertexColor(m)) {
                    double c[4] = {0, 0, 0, 0};
                    for (int i = 0; i < count; ++i)
                        for (int j = 0; j < 4; ++j) c[j] += double(m.vert[src[i]].cC()[j]) * w[i];
                    for (int j = 0; j < 4; ++j) v.C()[j] = (unsigned char)std::max(0.0, std::min(255.0, std::round(c[j])));
                }
            }
        }

        // `parent[i]`: the position in plan.splitFaces of the face changed[i] comes from.
        void AddFaces(std::vector<int> &changed, std::vector<int> &parent)
        {
            int added = 0;
            for (const auto &pc : plan.pieces) added += int(pc.size()) - 1;
            if (added > 0) vcg::tri::Allocator<MeshType>::AddFaces(m, added);
            int next = plan.faceCount;
            changed.reserve(plan.splitFaces.size() + added);
            parent.reserve(plan.splitFaces.size() + added);
            for (size_t i = 0; i < plan.splitFaces.size(); ++i) {
                const int f = plan.splitFaces[i];
                for (size_t j = 0; j < plan.pieces[i].size(); ++j) {
                    const int slot = j == 0 ? f : next++;
                    FaceType &nf = m.face[slot];
                    if (slot != f) nf.ImportData(m.face[f]);
                    for (int k = 0; k < 3; ++k) nf.V(k) = &m.vert[plan.pieces[i][j][k]];
                    changed.push_back(slot);
                    parent.push_back(int(i));
                }
            }
        }

        // Local update of the half-edge adjacency: the new faces among themselves (matched by
        // sorting their half-edges), and across the unsplit edges of their parents to the
        // untouched neighbours (the parents' old twins).
        void UpdateAdjacency(const std::vector<int> &changed, const std::vector<int> &parent)
        {
            EmbeddingAdjacency &adj = plan.adj;
            const size_t nSplit = plan.splitFaces.size();
            std::vector<std::array<int, 3>> oldFv(nSplit), oldTwin(nSplit);
            for (size_t i = 0; i < nSplit; ++i) {
                const int f = plan.splitFaces[i];
                oldFv[i] = adj.fv[f];
                oldTwin[i] = {adj.twin[3 * f], adj.twin[3 * f + 1], adj.twin[3 * f + 2]};
            }
            adj.fv.resize(m.face.size(), {-1, -1, -1});
            adj.twin.resize(3 * m.face.size(), -1);
            adj.vertexFace.resize(m.vert.size(), -1);
            auto key = [](int a, int b) { return (uint64_t(uint32_t(a)) << 32) | uint32_t(b); };
            std::vector<std::pair<uint64_t, int>> halfEdges;  // (from, to) -> half-edge
            halfEdges.reserve(3 * changed.size());
            for (int f : changed) {
                for (int k = 0; k < 3; ++k) adj.fv[f][k] = int(vcg::tri::Index(m, m.face[f].V(k)));
                for (int k = 0; k < 3; ++k) {
                    halfEdges.push_back({key(adj.fv[f][k], adj.fv[f][EmbeddingAdjacency::Next(k)]), 3 * f + k});
                    adj.vertexFace[adj.fv[f][k]] = f;
                }
            }
            std::sort(halfEdges.begin(), halfEdges.end());
            for (size_t i = 0; i < changed.size(); ++i) {
                const int f = changed[i];
                for (int k = 0; k < 3; ++k) {
                    const int a = adj.fv[f][k], b = adj.fv[f][EmbeddingAdjacency::Next(k)];
                    auto it = std::lower_bound(halfEdges.begin(), halfEdges.end(), std::make_pair(key(b, a), -1));
                    if (it != halfEdges.end() && it->first == key(b, a)) { adj.twin[3 * f + k] = it->second; continue; }
                    const std::array<int, 3> &pv = oldFv[parent[i]];
                    adj.twin[3 * f + k] = -1;
                    for (int j = 0; j < 3; ++j)
                        if (pv[j] == a && pv[EmbeddingAdjacency::Next(j)] == b) {
                            const int h = oldTwin[parent[i]][j];
                            adj.twin[3 * f + k] = h;
                            if (h >= 0) adj.twin[h] = 3 * f + k;
                        }
                }
            }
        }

        void SelectFrontEdges()
        {
            FrontEdges<MeshType>::Clear(m, true);  // the front replaces any earlier selection; faux stays clear
            for (const IdPair &e : plan.frontEdges) {
                const int h = plan.adj.FindEdge(e.first, e.second);
                if (h < 0) { ++r.missingFrontEdges; continue; }
                m.face[h / 3].SetFaceEdgeS(h % 3);
                const int t = plan.adj.twin[h];
                if (t >= 0) m.face[t / 3].SetFaceEdgeS(t % 3);
            }
        }

        void UpdateFace(int f)
        {
            FaceType &face = m.face[f];
            for (int k = 0; k < 3; ++k) {
                if (plan.adj.twin[3 * f + k] < 0) face.SetB(k);
                else face.ClearB(k);
            }
            if (vcg::tri::HasPerFaceNormal(m)) {
                EmbedVec n = (P(plan.adj.fv[f][1]) - P(plan.adj.fv[f][0])) ^ (P(plan.adj.fv[f][2]) - P(plan.adj.fv[f][0]));
                if (n.Norm() > 0) face.N() = CoordType::Construct(n.Normalize());
            }
        }

        static double Area(const FaceType &f)
        {
            const EmbedVec a = EmbedVec::Construct(f.cP(0)), b = EmbedVec::Construct(f.cP(1)), c = EmbedVec::Construct(f.cP(2));
            return 0.5 * ((b - a) ^ (c - a)).Norm();
        }

        // Patches: faces connected without crossing a selected edge. Each takes the id covering most
        // of its area (the new faces carry their parent's id); ids already taken by a larger patch
        // are replaced by new ones, so different patches always have different ids. Areas are only
        // computed for the few patches that hold several ids or share one.
        void Relabel()
        {
            const int n = int(m.face.size());
            std::vector<int> oldId(n, -1);
            if (!(vcg::tri::HasPerFaceQuality(m) && RegionIds<MeshType>::Read(m, oldId).empty())) oldId.assign(n, -1);
            // Union-find over the faces in index order (cache friendly), joined across unselected edges.
            std::vector<int> parent(n), patch(n, -1);
            for (int f = 0; f < n; ++f) parent[f] = f;
            auto find = [&](int x) {
                while (parent[x] != x) x = parent[x] = parent[parent[x]];
                return x;
            };
            for (int f = 0; f < n; ++f) {
                if (m.face[f].IsD()) continue;
                for (int k = 0; k < 3; ++k) {
                    const int h = plan.adj.twin[3 * f + k];
                    if (h < 0 || h / 3 < f || m.face[f].IsFaceEdgeS(k)) continue;
                    const int a = find(f), b = find(h / 3);
                    if (a != b) parent[std::max(a, b)] = std::min(a, b);
                }
            }
            std::vector<int> claim;  // per patch: its majority id
            std::vector<char> mixed;
            for (int f = 0; f < n; ++f) {  // a root is its set's lowest face: patches numbered in face order
                if (m.face[f].IsD()) continue;
                const int root = find(f);
                if (root == f) {
                    patch[f] = int(claim.size());
                    claim.push_back(oldId[f]);
                    mixed.push_back(0);
                } else {
                    patch[f] = patch[root];
                    if (oldId[f] != claim[patch[f]]) mixed[patch[f]] = 1;
                }
            }
            const int k = int(claim.size());
            if (std::find(mixed.begin(), mixed.end(), 1) != mixed.end()) {
                std::vector<std::vector<std::pair<int, double>>> idArea(k);  // (old id, area) per mixed patch
                for (int f = 0; f < n; ++f) {
                    if (patch[f] < 0 || !mixed[patch[f]]) continue;
                    auto &ia = idArea[patch[f]];
                    auto it = std::find_if(ia.begin(), ia.end(), [&](const std::pair<int, double> &x) { return x.first == oldId[f]; });
                    if (it == ia.end()) ia.push_back({oldId[f], Area(m.face[f])});
                    else it->second += Area(m.face[f]);
                }
                for (int pid = 0; pid < k; ++pid) {
                    if (!mixed[pid]) continue;
                    double bestArea = -1;
                    for (const auto &x : idArea[pid])
                        if (x.second > bestArea || (x.second == bestArea && x.first < claim[pid])) { claim[pid] = x.first; bestArea = x.second; }
                }
            }
            // Patches without an id or sharing one: by decreasing area, the first keeps it, the others get new ids.
            std::unordered_map<int, int> claims;
            for (int pid = 0; pid < k; ++pid) ++claims[claim[pid]];
            std::vector<char> contested(k, 0);
            std::vector<double> area(k, 0.0);
            bool anyContested = false;
            for (int pid = 0; pid < k; ++pid)
                if (claim[pid] < 0 || claims[claim[pid]] > 1) contested[pid] = 1, anyContested = true;
            if (anyContested)
                for (int f = 0; f < n; ++f)
                    if (patch[f] >= 0 && contested[patch[f]]) area[patch[f]] += Area(m.face[f]);
            std::vector<int> order;
            for (int pid = 0; pid < k; ++pid)
                if (contested[pid]) order.push_back(pid);
            std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return area[a] > area[b]; });
            int nextFree = 0;
            for (int i = 0; i < n; ++i) nextFree = std::max(nextFree, oldId[i] + 1);
            std::vector<int> newId(claim);
            std::unordered_set<int> taken;
            for (int pid : order) {
                if (claim[pid] >= 0 && !taken.count(claim[pid])) taken.insert(claim[pid]);
                else newId[pid] = nextFree++;
            }
            r.patches = k;
            r.faceRegion.assign(n, -1);
            for (int f = 0; f < n; ++f)
                if (patch[f] >= 0) r.faceRegion[f] = newId[patch[f]];
            r.danglingFrontEdges = 0;
            for (int f = 0; f < n; ++f)
                for (int e = 0; e < 3; ++e) {
                    const int h = plan.adj.twin[3 * f + e];
                    if (patch[f] >= 0 && h > 3 * f + e && m.face[f].IsFaceEdgeS(e) && patch[h / 3] == patch[f]) ++r.danglingFrontEdges;
                }
            if (vcg::tri::HasPerFaceQuality(m))
                for (int f = 0; f < n; ++f)
                    if (!m.face[f].IsD()) m.face[f].Q() = typename FaceType::QualityType(r.faceRegion[f]);
            if (vcg::tri::HasPerFaceColor(m)) ColorPatches(patch, newId);
        }

        // The colours RegionIds::ColorFaces gives (hue scattered over the id range), once per patch.
        void ColorPatches(const std::vector<int> &patch, const std::vector<int> &patchId)
        {
            if (patchId.empty()) return;
            const int lo = *std::min_element(patchId.begin(), patchId.end());
            const int hi = *std::max_element(patchId.begin(), patchId.end());
            const int range = std::max(1, hi - lo + 1);
            std::vector<vcg::Color4b> colour;
            for (int id : patchId) colour.push_back(vcg::Color4b::Scatter(range, id - lo, .75f, .95f));
            for (int f = 0; f < int(m.face.size()); ++f)
                if (patch[f] >= 0) m.face[f].C() = colour[patch[f]];
        }

        // vcg's own FF / VF adjacency, when the mesh has them, are kept valid.
        void WriteVcgTopology()
        {
            if (vcg::tri::HasFFAdjacency(m))
                for (int f = 0; f < int(m.face.size()); ++f) {
                    if (m.face[f].IsD()) continue;
                    for (int k = 0; k < 3; ++k) {
                        const int h = plan.adj.twin[3 * f + k];
                        m.face[f].FFp(k) = h >= 0 ? &m.face[h / 3] : &m.face[f];
                        m.face[f].FFi(k) = h >= 0 ? h % 3 : k;
                    }
                }
            if (vcg::tri::HasVFAdjacency(m)) vcg::tri::UpdateTopology<MeshType>::VertexFace(m);
        }

        void MeasureNewTriangles(const std::vector<int> &changed)
        {
            double minAngle = M_PI;
            for (int f : changed) {
                const FaceType &face = m.face[f];
                for (int k = 0; k < 3; ++k) {
                    const EmbedVec a = EmbedVec::Construct(face.cP(k));
                    const EmbedVec u = EmbedVec::Construct(face.cP((k + 1) % 3)) - a, v = EmbedVec::Construct(face.cP((k + 2) % 3)) - a;
                    minAngle = std::min(minAngle, std::atan2((u ^ v).Norm(), u * v));
                }
            }
            r.minAngleDeg = changed.empty() ? 0.0 : minAngle * 180.0 / M_PI;
        }
    };
};

}  // namespace vcg_ext

#endif
