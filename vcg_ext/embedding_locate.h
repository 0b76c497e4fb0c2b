// Locating polyline points on a triangle mesh: at a vertex, inside an edge or inside a face.
//
// A uniform grid over the live faces (cells ~ faces, built in O(F) by counting, no sort) finds
// every face within the tolerance of a point. Classification of a point p, with tolerance tol:
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
#include <cmath>
#include <limits>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/space/index/grid_util.h>

#include "embedding_adjacency.h"

namespace vcg_ext {
namespace embedding {

typedef vcg::Point3<double> EmbedVec;

// A point on the surface. Edge points are stored on a half-edge of `face`.
struct SurfacePoint {
    enum Kind { AtVertex, OnEdge, InFace };
    Kind kind = InFace;
    int vertex = -1;      // AtVertex: the vertex index
    int face = -1;        // a face containing the point (OnEdge: the face of the half-edge)
    int edge = -1;        // OnEdge: edge index k of `face` (V(k) -> V(k+1))
    double t = 0;         // OnEdge: parameter along V(k) -> V(k+1), strictly inside (0, 1)
    EmbedVec bary = EmbedVec(0, 0, 0);  // InFace: barycentric coordinates in `face`
    EmbedVec pos = EmbedVec(0, 0, 0);   // the re-projected position
};

// Closest point on triangle (a, b, c) to p (Ericson, Real-Time Collision Detection, 5.1.5).
inline EmbedVec ClosestPointOnTriangle(const EmbedVec &p, const EmbedVec &a, const EmbedVec &b, const EmbedVec &c)
{
    const EmbedVec ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab * ap, d2 = ac * ap;
    if (d1 <= 0 && d2 <= 0) return a;
    const EmbedVec bp = p - b;
    const double d3 = ab * bp, d4 = ac * bp;
    if (d3 >= 0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
    const EmbedVec cp = p - c;
    const double d5 = ab * cp, d6 = ac * cp;
    if (d6 >= 0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    const double denom = 1.0 / (va + vb + vc);
    return a + ab * (vb * denom) + ac * (vc * denom);
}

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
        BuildGrid();
    }

    EmbedVec P(int v) const { return EmbedVec::Construct(m.vert[v].cP()); }

    // Locates p; false when p is farther than the tolerance from the surface. `distance`: to the
    // closest face within the search box (-1 when none is there).
    bool Locate(const EmbedVec &p, SurfacePoint &out, double &distance) const
    {
        int best = -1;
        EmbedVec q;
        distance = std::numeric_limits<double>::max();
        ForFacesNear(p, tol, [&](int f) {
            const EmbedVec c = ClosestPointOnTriangle(p, P(adj.fv[f][0]), P(adj.fv[f][1]), P(adj.fv[f][2]));
            const double d = (c - p).Norm();
            if (d < distance || (d == distance && f < best)) { distance = d; best = f; q = c; }
        });
        if (best < 0 || distance > tol) {
            distance = best < 0 ? -1 : distance;
            return false;
        }
        Classify(best, q, out);
        return true;
    }

    // The same rules for a point already on face f (used for points computed on the surface).
    void Classify(int f, const EmbedVec &q, SurfacePoint &out) const
    {
        const std::array<int, 3> &t = adj.fv[f];
        out = SurfacePoint();
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
            out.kind = SurfacePoint::OnEdge;
            out.edge = nearE;
            out.t = te;
            out.pos = a + (b - a) * te;
            return;
        }
        out.kind = SurfacePoint::InFace;
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
    const MeshType &m;
    const EmbeddingAdjacency &adj;
    double tol;
    EmbedVec lo, cell;
    vcg::Point3i dim;
    std::vector<int> cellStart, cellFaces;

    void SetVertex(int f, int corner, SurfacePoint &out) const
    {
        out.kind = SurfacePoint::AtVertex;
        out.vertex = adj.fv[f][corner];
        out.face = f;
        out.pos = P(out.vertex);
    }

    vcg::Point3i CellOf(const EmbedVec &p) const
    {
        vcg::Point3i c;
        for (int k = 0; k < 3; ++k) {
            const double x = std::floor((p[k] - lo[k]) / cell[k]);
            c[k] = int(std::max(0.0, std::min(double(dim[k] - 1), std::isfinite(x) ? x : 0.0)));
        }
        return c;
    }
    int CellIndex(int x, int y, int z) const { return (z * dim[1] + y) * dim[0] + x; }

    template <class Fn>
    void ForCellsOfBox(const EmbedVec &bmin, const EmbedVec &bmax, Fn fn) const
    {
        const vcg::Point3i a = CellOf(bmin), b = CellOf(bmax);
        for (int z = a[2]; z <= b[2]; ++z)
            for (int y = a[1]; y <= b[1]; ++y)
                for (int x = a[0]; x <= b[0]; ++x) fn(CellIndex(x, y, z));
    }

    template <class Fn>
    void ForFacesNear(const EmbedVec &p, double r, Fn fn) const
    {
        const EmbedVec d(r, r, r);
        ForCellsOfBox(p - d, p + d, [&](int c) {
            for (int i = cellStart[c]; i < cellStart[c + 1]; ++i) fn(cellFaces[i]);
        });
    }

    void FaceBox(int f, EmbedVec &bmin, EmbedVec &bmax) const
    {
        bmin = bmax = P(adj.fv[f][0]);
        for (int k = 1; k < 3; ++k) {
            const EmbedVec q = P(adj.fv[f][k]);
            for (int i = 0; i < 3; ++i) { bmin[i] = std::min(bmin[i], q[i]); bmax[i] = std::max(bmax[i], q[i]); }
        }
    }

    // Cells ~ live faces (vcg's BestDim), each face listed in every cell its box meets; queries
    // look at every cell within the tolerance of the point.
    void BuildGrid()
    {
        vcg::Box3<double> box;
        int live = 0;
        for (int f = 0; f < int(adj.fv.size()); ++f)
            if (adj.IsLive(f)) {
                ++live;
                for (int k = 0; k < 3; ++k) box.Add(P(adj.fv[f][k]));
            }
        if (live == 0) box.Add(EmbedVec(0, 0, 0));
        const double pad = std::max(tol, 1e-9 * std::max(1.0, box.Diag()));
        box.Offset(pad);
        vcg::BestDim<double>(std::max(1, live), box.Dim(), dim);
        for (int k = 0; k < 3; ++k) dim[k] = std::max(1, dim[k]);
        lo = box.min;
        cell = EmbedVec(box.DimX() / dim[0], box.DimY() / dim[1], box.DimZ() / dim[2]);
        cellStart.assign(size_t(dim[0]) * dim[1] * dim[2] + 1, 0);
        for (int pass = 0; pass < 2; ++pass) {  // count, then fill
            std::vector<int> fill;
            if (pass == 1) {
                for (size_t c = 1; c < cellStart.size(); ++c) cellStart[c] += cellStart[c - 1];
                cellFaces.resize(cellStart.back());
                fill.assign(cellStart.begin(), cellStart.end() - 1);
            }
            for (int f = 0; f < int(adj.fv.size()); ++f) {
                if (!adj.IsLive(f)) continue;
                EmbedVec bmin, bmax;
                FaceBox(f, bmin, bmax);
                ForCellsOfBox(bmin, bmax, [&](int c) {
                    if (pass == 0) ++cellStart[c + 1];
                    else cellFaces[fill[c]++] = f;
                });
            }
        }
    }
};

}  // namespace embedding
}  // namespace vcg_ext

#endif
