// Filter 2 as one call: region ids per face -> boundary graph (region_boundary.h) -> curves
// straightened on the surface (GeodesicStraightening) -> polylines for the `_front` layer.
#ifndef VCG_EXT_BOUNDARY_BOUNDARY_SMOOTHING_H
#define VCG_EXT_BOUNDARY_BOUNDARY_SMOOTHING_H

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include <vcg/complex/complex.h>

#include <vcg_ext/boundary/region_boundary.h>
#include <vcg_ext/boundary/straightening.h>
#include <vcg_ext/common/edge_layer.h>
#include <vcg_ext/common/polygon_geometry.h>
#include <vcg_ext/common/progress_relay.h>
#include <vcg_ext/mesh_checks.h>

namespace vcg_ext {

template <class MeshType>
class RegionBoundarySmoothing
{
public:
    typedef MeshEdgeTopology<MeshType> Topology;
    typedef RegionBoundaryGraph<MeshType> Graph;
    typedef GeodesicStraightening<MeshType> Straightening;
    typedef vcg::Point3<double> Vec;

    // Points of a boundary that runs along a crease (both of its edges there at least this sharp)
    // stay where they are: on CAD parts a region boundary on a crease is the crease, and shortening
    // would cut a curved one (block's circular rims) off into the facets beside it, leaving a strip
    // a hair wide between the front and the crease, all needles. At 30 degrees a scan's noise held
    // its boundaries jagged (armadillo_52k: 546 points; irregular vertices 9.7 -> 9.8%, Hausdorff
    // 0.27 -> 0.29%); at 60 the organic meshes lost what holding gains them (elephant: quads below
    // 0.3 0.25 -> 0.43%; armadillo_52k: 9.96% irregular vertices).
    static constexpr double kHeldCreaseDeg = 45;
    // Regions narrower than this times MeanTriangleSide join their neighbour (MergeThinRegions):
    // far below any quad size the pipeline makes (block: 35 regions, single slivers folded across a
    // crease; the organic meshes: none or a few).
    static constexpr double kThinRegionWidth = 0.05;

    struct Params {
        int iterations = 3;        // straightening passes (0: the raw boundary, chains of mesh edges)
        double snapPercent = 25;   // % of an edge's length: closer edge points snap to its vertex
        int minRegionFaces = 0;    // regions with fewer faces join their longest-boundary neighbour (0: off)

        std::string Validate() const
        {
            typename Straightening::Params s;
            s.iterations = iterations;
            s.snapFraction = snapPercent / 100;
            std::string e = s.Validate();
            if (!e.empty()) return e;
            if (minRegionFaces < 0) return "the minimum region size must be >= 0 faces";
            return "";
        }
    };

    struct Curve {
        SurfacePath path;
        int regionLeft = -1, regionRight = -1;  // as in BoundaryCurve
    };

    struct Result {
        std::string error;                 // empty on success
        Topology topology;                 // edge ids of the surface points refer to it
        std::vector<Curve> curves;
        std::vector<int> corners;          // corner vertices
        int regions = 0;                   // distinct region ids in the input
        int mergedRegions = 0;             // regions merged away (minRegionFaces)
        int thinRegions = 0;               // regions merged away for being thinner than kThinRegionWidth
        int heldCreasePoints = 0;          // boundary points held on a crease (kHeldCreaseDeg)
        int boundaryEdges = 0;
        int closedLoops = 0;
        int pointsBefore = 0, pointsAfter = 0;
        double lengthBefore = 0, lengthAfter = 0;
        double jaggednessBefore = 0, jaggednessAfter = 0;  // total |geodesic turning| / total length (rad per unit length)
        int passes = 0, moves = 0, rejectedMoves = 0;
        int snapped = 0, held = 0, unsnapped = 0;  // final snapping (see GeodesicStraightening::Result)
        bool converged = false;
        double topologySeconds = 0, graphSeconds = 0, straightenSeconds = 0, seconds = 0;
    };

    // Why the boundaries of `m` cannot be smoothed with `p`, or "" (the region ids are checked by
    // Smooth: integral labels come from RegionIds). Unmerged vertices are named with their fix:
    // else a triangle soup would only be "regions without a boundary between them".
    static std::string Check(const MeshType &m, const Params &p)
    {
        std::string why = p.Validate();
        if (!why.empty()) return why;
        const MeshCheckReport r = MeshChecks<MeshType>::Inspect(m);
        why = r.FacesAndCoordinatesProblem();
        if (why.empty() && r.duplicateVertices) why = r.Describe(MeshCheckReport::DuplicateVertices);
        return why;
    }

    // faceRegion: region id per face index (deleted faces ignored). The mesh is not modified.
    static Result Smooth(const MeshType &m, const std::vector<int> &faceRegion, const Params &p, vcg::CallBackPos *cb = nullptr)
    {
        return ProgressRelay::Run(cb, [&](vcg::CallBackPos *report) { return SmoothHere(m, faceRegion, p, report); });
    }

    // The output polylines: one vertex per distinct point (a corner shared by several curves is
    // one vertex), one segment per pair of consecutive points, loops closed back to their start.
    struct Polylines {
        std::vector<Vec> points;
        std::vector<SurfacePoint> where;          // per point: its vertex or edge on the source mesh
        std::vector<std::array<int, 2>> segments;
        std::vector<int> segmentCurve;             // per segment: its curve index
    };

    static Polylines ToPolylines(const Topology &t, const std::vector<Curve> &curves)
    {
        Polylines out;
        std::unordered_map<int, int> atVertex;
        for (size_t c = 0; c < curves.size(); ++c) {
            const SurfacePath &path = curves[c].path;
            int first = -1, last = -1;
            for (const SurfacePoint &q : path.points) {
                int id = -1;
                if (q.IsVertex()) {
                    auto it = atVertex.find(q.vertex);
                    if (it != atVertex.end()) id = it->second;
                }
                if (id < 0) {
                    id = int(out.points.size());
                    out.points.push_back(Straightening::Position(t, q));
                    out.where.push_back(q);
                    if (q.IsVertex()) atVertex[q.vertex] = id;
                }
                if (last >= 0) { out.segments.push_back({last, id}); out.segmentCurve.push_back(int(c)); }
                if (first < 0) first = id;
                last = id;
            }
            if (path.closed && path.points.size() > 2) { out.segments.push_back({last, first}); out.segmentCurve.push_back(int(c)); }
        }
        return out;
    }

    // Fills an (empty) vcg mesh with the polylines as vertices and edges (an edge-only mesh).
    template <class EdgeMeshType>
    static void BuildEdgeMesh(const Polylines &pl, EdgeMeshType &out) { WriteEdgeLayer(pl.points, pl.segments, out); }

private:
    static Result SmoothHere(const MeshType &m, const std::vector<int> &faceRegion, const Params &p, vcg::CallBackPos *cb)
    {
        typedef std::chrono::steady_clock Clock;
        auto t0 = Clock::now();
        Result r;
        if (cb) cb(0, "Region boundaries: checking the mesh");
        r.error = Check(m, p);
        if (!r.error.empty()) return r;
        if (faceRegion.size() != m.face.size()) { r.error = "one region id per face is needed"; return r; }
        if (cb) cb(0, "Region boundaries: mesh topology");
        r.topology.Build(m);
        auto t1 = Clock::now();
        r.topologySeconds = std::chrono::duration<double>(t1 - t0).count();

        r.regions = Graph::CountRegions(r.topology, faceRegion);
        if (r.regions < 2) {
            r.error = "the face quality holds a single region id: there is no region boundary to smooth";
            return r;
        }
        std::vector<int> merged = MergeThinRegions(r.topology, faceRegion, kThinRegionWidth * MeanTriangleSide(r.topology), &r.thinRegions);
        if (p.minRegionFaces > 1) merged = MergeSmallRegions(r.topology, merged, p.minRegionFaces, &r.mergedRegions);
        const std::vector<int> *labels = &merged;
        if (cb) cb(10, "Region boundaries: curves and corners");
        Graph g = Graph::Build(r.topology, *labels);
        if (!g.error.empty()) { r.error = g.error; return r; }
        if (g.boundaryEdges == 0) {
            r.error = std::to_string(r.regions) + " regions but no boundary edge between two of them (" +
                      (r.mergedRegions || r.thinRegions ? "small or thin regions were merged away" : "each region is a whole connected component") +
                      "): nothing to smooth";
            return r;
        }
        r.boundaryEdges = g.boundaryEdges;
        r.corners = g.corners;
        r.closedLoops = g.closedLoops;
        std::vector<SurfacePath> paths;
        for (const BoundaryCurve &c : g.curves) {
            paths.push_back(InitialPath(r.topology, c));
            r.heldCreasePoints += HoldCreases(r.topology, c, paths.back());
        }
        auto t2 = Clock::now();
        r.graphSeconds = std::chrono::duration<double>(t2 - t1).count();

        Measure(r.topology, paths, r.pointsBefore, r.lengthBefore, r.jaggednessBefore);
        typename Straightening::Params sp;
        sp.iterations = p.iterations;
        sp.snapFraction = p.snapPercent / 100;
        typename Straightening::Result sr = Straightening::Straighten(r.topology, paths, sp, cb, 20, 95);
        if (!sr.error.empty()) { r.error = sr.error; return r; }
        r.passes = sr.passes;
        r.moves = sr.moves;
        r.rejectedMoves = sr.rejected;
        r.snapped = sr.snapped;
        r.held = sr.held;
        r.unsnapped = sr.unsnapped;
        r.converged = sr.converged;
        Measure(r.topology, paths, r.pointsAfter, r.lengthAfter, r.jaggednessAfter);
        for (size_t i = 0; i < paths.size(); ++i) {
            Curve c;
            c.path = std::move(paths[i]);
            c.regionLeft = g.curves[i].regionLeft;
            c.regionRight = g.curves[i].regionRight;
            r.curves.push_back(std::move(c));
        }
        auto t3 = Clock::now();
        r.straightenSeconds = std::chrono::duration<double>(t3 - t2).count();
        r.seconds = std::chrono::duration<double>(t3 - t0).count();
        return r;
    }

    // The boundary chain as vertex points. Corners are fixed; a closed loop is pinned at three
    // vertices a third of its length apart and a curve that starts and ends at the same corner
    // at two more, so shortening cannot shrink either to nothing.
    static SurfacePath InitialPath(const Topology &t, const BoundaryCurve &c)
    {
        SurfacePath path;
        path.closed = c.closed;
        for (int v : c.vertices) path.points.push_back(SurfacePoint::AtVertex(v));
        const int n = int(path.points.size());
        path.fixed.assign(n, 0);
        if (!c.closed) { path.fixed[0] = path.fixed[n - 1] = 1; }
        const bool lasso = !c.closed && c.vertices.front() == c.vertices.back();
        if (c.closed || lasso) {
            std::vector<double> at(n + 1, 0.0);  // arc length at each point (and back at the start for loops)
            for (int i = 0; i < n; ++i) {
                if (i + 1 == n && !c.closed) { at[n] = at[n - 1]; break; }
                at[i + 1] = at[i] + (t.Position(c.vertices[(i + 1) % n]) - t.Position(c.vertices[i])).Norm();
            }
            const double total = c.closed ? at[n] : at[n - 1];
            for (int k = c.closed ? 0 : 1; k < 3; ++k) {
                const double target = total * k / 3;
                int best = 0;
                for (int i = 0; i < n; ++i)
                    if (std::fabs(at[i] - target) < std::fabs(at[best] - target)) best = i;
                path.fixed[best] = 1;
            }
        }
        return path;
    }

    // The side of the equilateral triangle of the mesh's mean face area (EquilateralSide).
    static double MeanTriangleSide(const Topology &t)
    {
        double area = 0;
        int faces = 0;
        for (int f = 0; f < t.faceCount; ++f)
            if (t.faceVerts[f][0] >= 0) {
                area += t.DoubleArea(f) / 2;
                ++faces;
            }
        return faces ? EquilateralSide(area, faces) : 0;
    }

    // Fixes the points of path (read from c) whose two edges are creases; returns how many.
    static int HoldCreases(const Topology &t, const BoundaryCurve &c, SurfacePath &path)
    {
        const int n = int(c.vertices.size()), edges = int(c.edges.size());
        int held = 0;
        for (int i = 0; i < n; ++i) {
            const int before = c.closed ? (i + edges - 1) % edges : i - 1;
            if (before < 0 || i >= edges || path.fixed[i]) continue;
            if (t.DihedralDeg(c.edges[before]) >= kHeldCreaseDeg && t.DihedralDeg(c.edges[i]) >= kHeldCreaseDeg) {
                path.fixed[i] = 1;
                ++held;
            }
        }
        return held;
    }

    static void Measure(const Topology &t, const std::vector<SurfacePath> &paths, int &points, double &length, double &jaggedness)
    {
        points = 0;
        length = 0;
        double turning = 0;
        for (const SurfacePath &p : paths) {
            points += int(p.points.size());
            length += Straightening::Length(t, p);
            turning += Straightening::TotalTurning(t, p);
        }
        jaggedness = length > 0 ? turning / length : 0;
    }
};

}  // namespace vcg_ext

#endif
