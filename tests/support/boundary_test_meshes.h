// Region labellings and independent checks for the boundary smoothing tests (filter 2): the
// labelled meshes, and geometric checks of the curves that do not reuse the core's own tests.
#ifndef QMF_TESTS_BOUNDARY_TEST_MESHES_H
#define QMF_TESTS_BOUNDARY_TEST_MESHES_H

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "test_mesh.h"
#include <vcg_ext/geodesic_straightening.h>

namespace qmf_test {
namespace boundary {  // (nested: other test headers share qmf_test)

typedef vcg::Point3d D3;
typedef vcg_ext::MeshEdgeTopology<TMesh> Topo;
typedef vcg_ext::GeodesicStraightening<TMesh> Straight;
typedef vcg_ext::RegionBoundarySmoothing<TMesh> Smoothing;

// Writes labels to the face quality and returns them.
inline std::vector<int> SetRegions(TMesh &m, const std::function<int(int face)> &label)
{
    std::vector<int> r(m.face.size());
    for (size_t f = 0; f < m.face.size(); ++f) {
        r[f] = label(int(f));
        m.face[f].Q() = float(r[f]);
    }
    return r;
}

inline D3 Centroid(const TMesh &m, int f)
{
    const auto &face = m.face[f];
    return (D3::Construct(face.cP(0)) + D3::Construct(face.cP(1)) + D3::Construct(face.cP(2))) / 3.0;
}

// MakeGrid's cell of a face: faces come two per cell, row by row.
inline void GridCell(int n, int face, int &i, int &j)
{
    int cell = face / 2;
    i = cell % n;
    j = cell / n;
}

inline double BBoxDiagonal(const TMesh &m)
{
    vcg::Box3d b;
    for (auto &v : m.vert) b.Add(D3::Construct(v.cP()));
    return b.Diag();
}

// Distance from p to the segment ab.
inline double SegmentDistance(const D3 &p, const D3 &a, const D3 &b)
{
    D3 d = b - a;
    double l2 = d.SquaredNorm();
    double s = l2 > 0 ? std::max(0.0, std::min(1.0, ((p - a) * d) / l2)) : 0.0;
    return (a + d * s - p).Norm();
}

// Float position of an output point, as the layer stores it.
inline D3 AsFloat(const D3 &p) { return D3(float(p[0]), float(p[1]), float(p[2])); }

// Two segments of one face (3D points in its plane) cross or touch other than at a shared end?
inline bool SegmentsMeet(const D3 &a, const D3 &b, const D3 &c, const D3 &d, const D3 &normal, double eps)
{
    // 2D frame in the face plane.
    D3 u = (b - a);
    if (u.Norm() == 0) return false;
    u.Normalize();
    D3 w = normal ^ u;
    w.Normalize();
    auto to2 = [&](const D3 &p) { return vcg::Point2d((p - a) * u, (p - a) * w); };
    vcg::Point2d A = to2(a), B = to2(b), C = to2(c), D = to2(d);
    auto cross = [](const vcg::Point2d &o, const vcg::Point2d &p, const vcg::Point2d &q) {
        return (p[0] - o[0]) * (q[1] - o[1]) - (p[1] - o[1]) * (q[0] - o[0]);
    };
    auto same = [&](const vcg::Point2d &p, const vcg::Point2d &q) { return (p - q).Norm() <= eps; };
    const bool sharedEnd = same(A, C) || same(A, D) || same(B, C) || same(B, D);
    auto onSegment = [&](const vcg::Point2d &p, const vcg::Point2d &s0, const vcg::Point2d &s1) {
        vcg::Point2d d = s1 - s0;
        double l = d.Norm();
        if (l == 0) return false;
        double along = ((p - s0) * d) / l;
        double off = std::fabs(cross(s0, s1, p)) / l;
        return off <= eps && along > eps && along < l - eps;  // strictly inside
    };
    // An end point lying inside the other segment: touching or overlapping.
    if (onSegment(C, A, B) || onSegment(D, A, B) || onSegment(A, C, D) || onSegment(B, C, D)) return true;
    if (sharedEnd) return false;
    double d1 = cross(A, B, C), d2 = cross(A, B, D), d3 = cross(C, D, A), d4 = cross(C, D, B);
    return ((d1 > eps && d2 < -eps) || (d1 < -eps && d2 > eps)) && ((d3 > eps && d4 < -eps) || (d3 < -eps && d4 > eps));
}

struct CurveCheck {
    int pointsOffEdges = 0;      // float position farther than tol from its claimed vertex / edge
    int segmentsWithoutFace = 0; // consecutive points on no common face
    int crossings = 0;           // segment pairs of one face that meet other than at a shared end
    int pointsNearVertex = 0;    // edge points closer to an edge end than the snap fraction
    int sharedPoints = 0;        // a vertex holding points of two curves that is not a corner of both
    std::string firstProblem;
};

// Checks the invariants of a set of curves with plain geometry: positions against the source
// edges, a common face for each segment, and every pair of segments inside each face.
inline CurveCheck CheckCurves(const TMesh &m, const Topo &t, const std::vector<Smoothing::Curve> &curves, double snapFraction,
                              const std::set<int> &corners)
{
    CurveCheck c;
    const double diag = BBoxDiagonal(m), tol = 1e-6 * diag;
    struct Seg { D3 a, b; int curve; vcg_ext::SurfacePoint pa, pb; };
    std::map<int, std::vector<Seg>> perFace;
    std::map<int, std::set<int>> curvesAtVertex;
    for (size_t ci = 0; ci < curves.size(); ++ci) {
        const auto &path = curves[ci].path;
        const size_t n = path.points.size();
        for (size_t i = 0; i < n; ++i) {
            const auto &q = path.points[i];
            D3 pos = AsFloat(Straight::Position(t, q));
            double dist;
            if (q.IsVertex()) {
                dist = (pos - D3::Construct(m.vert[q.vertex].cP())).Norm();
                curvesAtVertex[q.vertex].insert(int(ci));
            } else {
                D3 a = D3::Construct(m.vert[t.edgeVerts[q.edge][0]].cP()), b = D3::Construct(m.vert[t.edgeVerts[q.edge][1]].cP());
                dist = SegmentDistance(pos, a, b);
                if (q.t < snapFraction - 1e-9 || q.t > 1 - snapFraction + 1e-9) ++c.pointsNearVertex;
            }
            if (dist > tol) {
                ++c.pointsOffEdges;
                if (c.firstProblem.empty()) c.firstProblem = "point off its edge by " + std::to_string(dist);
            }
        }
        const size_t segs = path.closed ? n : n - 1;
        for (size_t i = 0; i < segs; ++i) {
            const auto &a = path.points[i], &b = path.points[(i + 1) % n];
            int found[3];
            int nf = Straight::SharedFaces(t, a, b, found, 3);
            std::vector<int> faces(found, found + nf);
            if (faces.empty()) {
                ++c.segmentsWithoutFace;
                if (c.firstProblem.empty()) c.firstProblem = "segment without a common face in curve " + std::to_string(ci);
            }
            for (int f : faces)
                perFace[f].push_back({Straight::Position(t, a), Straight::Position(t, b), int(ci), a, b});
        }
    }
    for (auto &pf : perFace) {
        const auto &face = m.face[pf.first];
        D3 p0 = D3::Construct(face.cP(0)), p1 = D3::Construct(face.cP(1)), p2 = D3::Construct(face.cP(2));
        D3 normal = (p1 - p0) ^ (p2 - p0);
        normal.Normalize();
        double scale = std::max((p1 - p0).Norm(), (p2 - p0).Norm());
        const auto &s = pf.second;
        for (size_t i = 0; i < s.size(); ++i)
            for (size_t j = i + 1; j < s.size(); ++j) {
                bool identical = (s[i].pa == s[j].pa && s[i].pb == s[j].pb) || (s[i].pa == s[j].pb && s[i].pb == s[j].pa);
                if (identical || SegmentsMeet(s[i].a, s[i].b, s[j].a, s[j].b, normal, 1e-9 * scale)) {
                    ++c.crossings;
                    if (c.firstProblem.empty())
                        c.firstProblem = "curves " + std::to_string(s[i].curve) + " and " + std::to_string(s[j].curve) +
                                         " meet in face " + std::to_string(pf.first);
                }
            }
    }
    for (auto &cv : curvesAtVertex)
        if (cv.second.size() > 1 && !corners.count(cv.first)) ++c.sharedPoints;
    return c;
}

// Patches of mesh vertices not separated by the curves: the two ends of a mesh edge are joined
// when neither is a curve point and no curve point lies inside the edge. Each patch takes the
// region id most of its faces (faces with all corners in the patch) carry.
struct VertexPatches {
    std::vector<int> patchOf;        // per vertex, -1 for curve points
    std::vector<int> label;          // per patch
    std::vector<int> votes;          // per patch: faces that voted
};

inline VertexPatches ComputePatches(const TMesh &m, const Topo &t, const std::vector<Smoothing::Curve> &curves,
                                    const std::vector<int> &faceRegion)
{
    VertexPatches vp;
    std::vector<char> onCurve(m.vert.size(), 0), edgeCut(t.EdgeCount(), 0);
    for (auto &c : curves)
        for (auto &q : c.path.points) {
            if (q.IsVertex()) onCurve[q.vertex] = 1;
            else edgeCut[q.edge] = 1;
        }
    std::vector<int> parent(m.vert.size());
    for (size_t i = 0; i < parent.size(); ++i) parent[i] = int(i);
    std::function<int(int)> find = [&](int x) { while (parent[x] != x) x = parent[x] = parent[parent[x]]; return x; };
    for (int e = 0; e < t.EdgeCount(); ++e) {
        int a = t.edgeVerts[e][0], b = t.edgeVerts[e][1];
        if (edgeCut[e] || onCurve[a] || onCurve[b]) continue;
        parent[find(a)] = find(b);
    }
    vp.patchOf.assign(m.vert.size(), -1);
    std::map<int, int> ids;
    for (size_t v = 0; v < m.vert.size(); ++v) {
        if (onCurve[v] || t.FacesAround(int(v)) == 0) continue;
        int r = find(int(v));
        auto it = ids.find(r);
        if (it == ids.end()) it = ids.insert({r, int(ids.size())}).first;
        vp.patchOf[v] = it->second;
    }
    std::vector<std::map<int, int>> count(ids.size());
    for (int f = 0; f < t.faceCount; ++f) {
        if (t.faceVerts[f][0] < 0) continue;
        int p = vp.patchOf[t.faceVerts[f][0]];
        if (p < 0 || vp.patchOf[t.faceVerts[f][1]] != p || vp.patchOf[t.faceVerts[f][2]] != p) continue;
        count[p][faceRegion[f]]++;
    }
    vp.label.assign(ids.size(), -1);
    vp.votes.assign(ids.size(), 0);
    for (size_t p = 0; p < count.size(); ++p) {
        int best = 0;
        for (auto &c : count[p]) {
            vp.votes[p] += c.second;
            if (c.second > best) { best = c.second; vp.label[p] = c.first; }
        }
    }
    return vp;
}

// Labels of the patches beside a curve: for each segment, the vertices of its face(s) that are not
// curve points lie left or right of it (seen from the side the face normal points to); their
// patches' labels are counted per side (patches with fewer than `minVotes` faces are ignored).
inline void SideLabels(const TMesh &m, const Topo &t, const vcg_ext::SurfacePath &path, const VertexPatches &vp,
                       int minVotes, std::map<int, int> &left, std::map<int, int> &right)
{
    const size_t n = path.points.size();
    const size_t segs = path.closed ? n : n - 1;
    for (size_t i = 0; i < segs; ++i) {
        const auto &a = path.points[i], &b = path.points[(i + 1) % n];
        int faces[3];
        int nf = Straight::SharedFaces(t, a, b, faces, 3);
        D3 pa = Straight::Position(t, a), pb = Straight::Position(t, b);
        for (int k = 0; k < nf; ++k) {
            const auto &face = m.face[faces[k]];
            D3 p0 = D3::Construct(face.cP(0)), p1 = D3::Construct(face.cP(1)), p2 = D3::Construct(face.cP(2));
            D3 normal = (p1 - p0) ^ (p2 - p0);
            for (int j = 0; j < 3; ++j) {
                int v = t.faceVerts[faces[k]][j];
                int patch = vp.patchOf[v];
                if (patch < 0 || vp.votes[patch] < minVotes) continue;
                double side = ((pb - pa) ^ (D3::Construct(m.vert[v].cP()) - pa)) * normal;
                if (side > 0) ++left[vp.label[patch]];
                else if (side < 0) ++right[vp.label[patch]];
            }
        }
    }
}

inline int Majority(const std::map<int, int> &count)
{
    int best = -1, n = 0;
    for (auto &c : count)
        if (c.second > n) { n = c.second; best = c.first; }
    return best;
}

}  // namespace boundary
}  // namespace qmf_test

#endif
