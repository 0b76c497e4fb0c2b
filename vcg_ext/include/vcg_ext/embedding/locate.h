// Locating polyline points on a triangle mesh: at a vertex, inside an edge or inside a face.
//
// Points are located together: a uniform grid over the points (not over the faces), then one
// pass over the faces, each testing only the points in the cells its box (grown by the tolerance)
// meets: O(F) with a small constant and no per-face allocation. Classification of a point p, with
// tolerance tol:
//   1. the closest face f and its closest point q must be within tol of p, else p is off the surface;
//   2. q within tol of a vertex of f           -> at that vertex (the nearest one);
//   3. else q within tol of an edge of f       -> inside that edge (the nearest one), re-projected
//      onto it; if the projection falls within tol of an end, at that end vertex;
//   4. else                                    -> inside f, at q.
// Located points are re-projected: a vertex point is the vertex, an edge point lies on the segment.
#ifndef VCG_EXT_EMBEDDING_LOCATE_H
#define VCG_EXT_EMBEDDING_LOCATE_H

#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <limits>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/space/index/grid_util.h>

#include <vcg_ext/common/polygon_geometry.h>
#include <vcg_ext/embedding/adjacency.h>

namespace vcg_ext {
namespace embedding {

typedef vcg::Point3<double> EmbedVec;

// A polyline point located on the mesh: the answer of a query (kind, a face holding it, its
// barycentric coordinates and re-projected position). Not a path point of the straightening
// (vcg_ext::SurfacePoint, a vertex or a parameter on an edge of the edge graph): edge points here
// are stored on a half-edge of `face`, as the splitting needs them.
struct LocatedPoint {
    enum Kind { AtVertex, OnEdge, InFace };
    Kind kind = InFace;
    int vertex = -1;      // AtVertex: the vertex index
    int face = -1;        // a face containing the point (OnEdge: the face of the half-edge)
    int edge = -1;        // OnEdge: edge index k of `face` (V(k) -> V(k+1))
    double t = 0;         // OnEdge: parameter along V(k) -> V(k+1), strictly inside (0, 1)
    EmbedVec bary = EmbedVec(0, 0, 0);  // InFace: barycentric coordinates in `face`
    EmbedVec pos = EmbedVec(0, 0, 0);   // the re-projected position
};

// Parameter of the projection of p on segment a-b (unclamped).
inline double SegmentParameter(const EmbedVec &p, const EmbedVec &a, const EmbedVec &b)
{
    const EmbedVec d = b - a;
    const double l2 = d.SquaredNorm();
    return l2 > 0 ? ((p - a) * d) / l2 : 0.0;
}

template <class MeshType>
class SurfaceLocator
{
public:
    SurfaceLocator(const MeshType &mesh, const EmbeddingAdjacency &adjacency, double tolerance)
        : m(mesh), adj(adjacency), tol(tolerance)
    {
    }

    EmbedVec P(int v) const { return EmbedVec::Construct(m.vert[v].cP()); }

    // Locates every point: found[i] says whether points[i] is within the tolerance of the surface.
    void LocateAll(const std::vector<EmbedVec> &points, std::vector<LocatedPoint> &out, std::vector<char> &found) const
    {
        const int n = int(points.size());
        out.assign(n, LocatedPoint());
        found.assign(n, 0);
        if (n == 0) return;
        std::vector<double> best(n, std::numeric_limits<double>::max());
        std::vector<int> bestFace(n, -1);
        std::vector<EmbedVec> closest(n);
        PointGrid grid(points, tol, std::max<int64_t>(n, int64_t(adj.fv.size()) / 16));
        for (int f = 0; f < int(adj.fv.size()); ++f) {
            if (!adj.IsLive(f)) continue;
            EmbedVec bmin, bmax;
            FaceBox(f, bmin, bmax);
            grid.ForPointsInBox(bmin, bmax, [&](int i) {
                const EmbedVec c = ClosestPointOnTriangle(points[i], P(adj.fv[f][0]), P(adj.fv[f][1]), P(adj.fv[f][2]));
                const double d = (c - points[i]).Norm();
                if (d <= tol && d < best[i]) { best[i] = d; bestFace[i] = f; closest[i] = c; }  // ties: lower face
            });
        }
        for (int i = 0; i < n; ++i)
            if (bestFace[i] >= 0) { Classify(bestFace[i], closest[i], out[i]); found[i] = 1; }
    }

    // One point (tests, tools): O(F).
    bool Locate(const EmbedVec &p, LocatedPoint &out) const
    {
        std::vector<LocatedPoint> o;
        std::vector<char> found;
        LocateAll({p}, o, found);
        out = o[0];
        return found[0] != 0;
    }

    // The same rules for a point already on face f (used for points computed on the surface).
    void Classify(int f, const EmbedVec &q, LocatedPoint &out) const
    {
        const std::array<int, 3> &t = adj.fv[f];
        out = LocatedPoint();
        out.face = f;
        int nearV = -1;
        double dv = tol;
        for (int k = 0; k < 3; ++k) {
            const double d = (P(t[k]) - q).Norm();
            if (d <= dv) { dv = d; nearV = k; }
        }
        if (nearV >= 0) { SetVertex(f, nearV, out); return; }
        int nearE = -1;
        double de = tol, te = 0;
        for (int k = 0; k < 3; ++k) {
            const EmbedVec a = P(t[k]), b = P(t[EmbeddingAdjacency::Next(k)]);
            const double s = std::min(1.0, std::max(0.0, SegmentParameter(q, a, b)));
            const double d = (a + (b - a) * s - q).Norm();
            if (d <= de) { de = d; nearE = k; te = s; }
        }
        if (nearE >= 0) {
            const EmbedVec a = P(t[nearE]), b = P(t[EmbeddingAdjacency::Next(nearE)]);
            const double len = (b - a).Norm();
            if (te * len <= tol) { SetVertex(f, nearE, out); return; }
            if ((1 - te) * len <= tol) { SetVertex(f, EmbeddingAdjacency::Next(nearE), out); return; }
            out.kind = LocatedPoint::OnEdge;
            out.edge = nearE;
            out.t = te;
            out.pos = a + (b - a) * te;
            return;
        }
        out.kind = LocatedPoint::InFace;
        out.bary = Barycentric(f, q);
        out.pos = q;
    }

    EmbedVec Barycentric(int f, const EmbedVec &q) const
    {
        const EmbedVec a = P(adj.fv[f][0]), b = P(adj.fv[f][1]), c = P(adj.fv[f][2]);
        const EmbedVec n = (b - a) ^ (c - a);
        const double n2 = n.SquaredNorm();
        const double l1 = (((c - b) ^ (q - b)) * n) / n2, l2 = (((a - c) ^ (q - c)) * n) / n2;
        return EmbedVec(l1, l2, 1 - l1 - l2);
    }

    // Distance from p to the closest face by brute force, O(F): only for error messages.
    double DistanceToSurface(const EmbedVec &p) const
    {
        double best = std::numeric_limits<double>::max();
        for (int f = 0; f < int(adj.fv.size()); ++f)
            if (adj.IsLive(f))
                best = std::min(best, (ClosestPointOnTriangle(p, P(adj.fv[f][0]), P(adj.fv[f][1]), P(adj.fv[f][2])) - p).Norm());
        return best;
    }

private:
    // Uniform grid over points (CSR), its box grown by the tolerance.
    class PointGrid
    {
    public:
        PointGrid(const std::vector<EmbedVec> &points, double tol, int64_t cells)
        {
            for (const EmbedVec &p : points) box.Add(p);
            box.Offset(tol + 1e-12 * std::max(1.0, box.Diag()));
            vcg::BestDim<double>(std::max<int64_t>(1, cells), box.Dim(), dim);
            for (int k = 0; k < 3; ++k) {
                dim[k] = std::max(1, dim[k]);
                cell[k] = (box.max[k] - box.min[k]) / dim[k];
            }
            start.assign(size_t(dim[0]) * dim[1] * dim[2] + 1, 0);
            std::vector<int> at(points.size());
            for (size_t i = 0; i < points.size(); ++i) ++start[(at[i] = Index(CellOf(points[i]))) + 1];
            for (size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
            ids.resize(points.size());
            std::vector<int> fill(start.begin(), start.end() - 1);
            for (size_t i = 0; i < points.size(); ++i) ids[fill[at[i]]++] = int(i);
            this->points = &points;
            grow = tol;
        }

        // Calls fn(i) for every point i inside the box grown by the tolerance.
        template <class Fn>
        void ForPointsInBox(EmbedVec bmin, EmbedVec bmax, Fn fn) const
        {
            for (int k = 0; k < 3; ++k) {
                bmin[k] -= grow;
                bmax[k] += grow;
                if (bmax[k] < box.min[k] || bmin[k] > box.max[k]) return;
            }
            const vcg::Point3i a = CellOf(bmin), b = CellOf(bmax);
            for (int z = a[2]; z <= b[2]; ++z)
                for (int y = a[1]; y <= b[1]; ++y)
                    for (int x = a[0]; x <= b[0]; ++x) {
                        const int c = (z * dim[1] + y) * dim[0] + x;
                        for (int j = start[c]; j < start[c + 1]; ++j) {
                            const EmbedVec &p = (*points)[ids[j]];
                            if (p[0] >= bmin[0] && p[0] <= bmax[0] && p[1] >= bmin[1] && p[1] <= bmax[1] &&
                                p[2] >= bmin[2] && p[2] <= bmax[2])
                                fn(ids[j]);
                        }
                    }
        }

    private:
        vcg::Box3<double> box;
        vcg::Point3i dim;
        EmbedVec cell;
        std::vector<int> start, ids;
        const std::vector<EmbedVec> *points = nullptr;
        double grow = 0;

        vcg::Point3i CellOf(const EmbedVec &p) const
        {
            vcg::Point3i c;
            for (int k = 0; k < 3; ++k) {
                const double x = cell[k] > 0 ? std::floor((p[k] - box.min[k]) / cell[k]) : 0.0;
                c[k] = int(std::max(0.0, std::min(double(dim[k] - 1), std::isfinite(x) ? x : 0.0)));
            }
            return c;
        }
        int Index(const vcg::Point3i &c) const { return (c[2] * dim[1] + c[1]) * dim[0] + c[0]; }
    };

    const MeshType &m;
    const EmbeddingAdjacency &adj;
    double tol;

    void SetVertex(int f, int corner, LocatedPoint &out) const
    {
        out.kind = LocatedPoint::AtVertex;
        out.vertex = adj.fv[f][corner];
        out.face = f;
        out.pos = P(out.vertex);
    }

    void FaceBox(int f, EmbedVec &bmin, EmbedVec &bmax) const
    {
        bmin = bmax = P(adj.fv[f][0]);
        for (int k = 1; k < 3; ++k) {
            const EmbedVec q = P(adj.fv[f][k]);
            for (int i = 0; i < 3; ++i) { bmin[i] = std::min(bmin[i], q[i]); bmax[i] = std::max(bmax[i], q[i]); }
        }
    }
};

}  // namespace embedding
}  // namespace vcg_ext

#endif
