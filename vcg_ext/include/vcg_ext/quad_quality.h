// Quality of a quad-dominant mesh, on a plain polygon list (positions + faces of 3 or 4 nodes):
// quad fraction by count and area, scaled Jacobians, inverted quads, irregular vertices. Also the
// conversion from MeshLab's polygonal form (triangle pairs sharing a faux edge) to that list.
#ifndef VCG_EXT_QUAD_QUALITY_H
#define VCG_EXT_QUAD_QUALITY_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include <vcg/complex/complex.h>

#include <vcg_ext/common/edge_key.h>
#include <vcg_ext/common/polygon_geometry.h>

namespace vcg_ext {

struct PolygonMesh {
    std::vector<vcg::Point3<double>> points;
    std::vector<std::vector<int>> faces;  // counter-clockwise, 3 or 4 nodes
    std::vector<uint64_t> frontEdges;     // EdgeKey of the point pairs on the front, sorted (empty: unknown)
};

// Scaled Jacobians are measured against the input surface's normal under each face when it is
// known (a quad upside down on the surface is then negative), else against the quad's own.
struct QuadQualityReport {
    int quads = 0, triangles = 0, others = 0;
    double quadAreaFraction = 0, quadCountFraction = 0;
    double minJacobian = 1, meanJacobian = 0, p5Jacobian = 0;  // p5: 5th percentile (nearest rank)
    int quadsBelow03 = 0;       // scaled Jacobian < 0.3
    int invertedQuads = 0;      // scaled Jacobian <= 0
    int flippedFaces = 0;       // faces whose vector area points away from the input surface
    int foldedQuads = 0;        // quads folded across both diagonals (kFoldAngleDeg)
    int interiorAllQuadVertices = 0, irregularVertices = 0;  // see IrregularFraction
    // Where the irregular vertices are, when the front is known (PolygonMesh::frontEdges): at front
    // nodes (two front edges), at front junctions (one, or three and more); the rest inside patches.
    bool frontKnown = false;
    int irregularAtFrontNodes = 0, irregularAtFrontJunctions = 0;
    int IrregularInsidePatches() const { return irregularVertices - irregularAtFrontNodes - irregularAtFrontJunctions; }
    double IrregularFraction() const { return interiorAllQuadVertices ? double(irregularVertices) / interiorAllQuadVertices : 0; }
};

class QuadQuality
{
public:
    typedef vcg::Point3<double> P3;

    // Scaled Jacobian against the quad's own normal (see polygon_geometry.h).
    static double ScaledJacobian(const P3 &a, const P3 &b, const P3 &c, const P3 &d)
    {
        const P3 q[4] = {a, b, c, d};
        return vcg_ext::ScaledJacobian(q);
    }

    static double Area(const PolygonMesh &pm, const std::vector<int> &f)
    {
        std::vector<P3> p(f.size());
        for (size_t k = 0; k < f.size(); ++k) p[k] = pm.points[f[k]];
        return VectorArea(p.data(), int(p.size())).Norm();
    }

    // Irregular vertex: not on the mesh boundary, all its faces quads, valence != 4.
    // referenceNormal: per face, the input surface's unit normal under it (empty: unknown).
    static QuadQualityReport Measure(const PolygonMesh &pm, const std::vector<P3> &referenceNormal = std::vector<P3>())
    {
        QuadQualityReport r;
        const bool referenced = referenceNormal.size() == pm.faces.size();
        double quadArea = 0, total = 0, jsum = 0;
        std::vector<double> jacobians;
        std::vector<int> faceCount(pm.points.size(), 0);
        std::vector<char> touchesTriangle(pm.points.size(), 0), onBoundary(pm.points.size(), 0);
        std::vector<uint64_t> edges;
        std::vector<P3> p;
        for (size_t i = 0; i < pm.faces.size(); ++i) {
            const std::vector<int> &f = pm.faces[i];
            // from its lowest vertex on: the same roundings whichever way the polygon runs
            const size_t low = size_t(std::min_element(f.begin(), f.end()) - f.begin());
            p.resize(f.size());
            for (size_t k = 0; k < f.size(); ++k) p[k] = pm.points[f[(low + k) % f.size()]];
            const P3 vectorArea = VectorArea(p.data(), int(p.size()));
            const double a = vectorArea.Norm();
            total += a;
            if (referenced && vectorArea * referenceNormal[i] < 0) ++r.flippedFaces;
            if (f.size() == 4) {
                ++r.quads;
                quadArea += a;
                const double j = referenced ? vcg_ext::ScaledJacobian(p.data(), referenceNormal[i]) : vcg_ext::ScaledJacobian(p.data());
                r.minJacobian = std::min(r.minJacobian, j);
                jsum += j;
                jacobians.push_back(j);
                r.quadsBelow03 += j < 0.3;
                r.invertedQuads += j <= 0;
                r.foldedQuads += IsFolded(p.data());
            } else if (f.size() == 3) ++r.triangles;
            else ++r.others;
            for (size_t k = 0; k < f.size(); ++k) {
                edges.push_back(EdgeKey(f[k], f[(k + 1) % f.size()]));
                faceCount[f[k]]++;
                if (f.size() != 4) touchesTriangle[f[k]] = 1;
            }
        }
        std::sort(edges.begin(), edges.end());
        std::vector<int> valence(pm.points.size(), 0);
        for (size_t i = 0; i < edges.size();) {
            size_t j = i;
            while (j < edges.size() && edges[j] == edges[i]) ++j;
            const int u = int(edges[i] >> 32), w = int(edges[i] & 0xffffffffu);
            valence[u]++;
            valence[w]++;
            if (j - i == 1) onBoundary[u] = onBoundary[w] = 1;
            i = j;
        }
        std::vector<int> frontEdgesAt(pm.points.size(), 0);
        for (uint64_t e : pm.frontEdges) {
            frontEdgesAt[e >> 32]++;
            frontEdgesAt[e & 0xffffffffu]++;
        }
        r.frontKnown = !pm.frontEdges.empty();
        for (size_t v = 0; v < pm.points.size(); ++v) {
            if (faceCount[v] == 0 || onBoundary[v] || touchesTriangle[v]) continue;
            ++r.interiorAllQuadVertices;
            if (valence[v] == 4) continue;
            ++r.irregularVertices;
            r.irregularAtFrontNodes += frontEdgesAt[v] == 2;
            r.irregularAtFrontJunctions += frontEdgesAt[v] != 0 && frontEdgesAt[v] != 2;
        }
        int n = int(pm.faces.size());
        r.quadCountFraction = n ? double(r.quads) / n : 0;
        r.quadAreaFraction = total > 0 ? quadArea / total : 0;
        r.meanJacobian = r.quads ? jsum / r.quads : 0;
        if (!jacobians.empty()) {
            const size_t rank = std::max<size_t>(1, size_t(std::ceil(0.05 * jacobians.size()))) - 1;
            std::nth_element(jacobians.begin(), jacobians.begin() + rank, jacobians.end());
            r.p5Jacobian = jacobians[rank];
        }
        if (!r.quads) r.minJacobian = 0;
        return r;
    }

    // Walks the polygons of a vcg triangle mesh in MeshLab's polygonal form: two triangles sharing a
    // faux edge are one quad (needs face-face adjacency); other faux configurations stay triangles.
    // visit(first, corners, n): the polygon's first triangle, its n (3 or 4) corners as indices
    // into m.vert, counter-clockwise.
    template <class MeshType, class Visit>
    static void ForEachFauxPolygon(MeshType &m, Visit visit)
    {
        std::vector<char> done(m.face.size(), 0);
        for (size_t i = 0; i < m.face.size(); ++i) {
            auto &f = m.face[i];
            if (f.IsD() || done[i]) continue;
            done[i] = 1;
            int faux = -1, count = 0;
            for (int k = 0; k < 3; ++k)
                if (f.IsF(k)) { faux = k; ++count; }
            auto V = [&](typename MeshType::FaceType &g, int k) { return int(vcg::tri::Index(m, g.V(k))); };
            if (count == 1) {
                auto *g = f.FFp(faux);
                int j = f.FFi(faux);
                size_t gi = vcg::tri::Index(m, g);
                int gFaux = 0;
                for (int k = 0; k < 3; ++k) gFaux += g->IsF(k);
                if (g != &f && !done[gi] && gFaux == 1 && g->IsF(j)) {
                    done[gi] = 1;
                    // quad: f's vertices from the far side of the faux edge, then g's opposite vertex
                    visit(f, std::array<int, 4>{{V(f, (faux + 1) % 3), V(f, (faux + 2) % 3), V(f, faux), V(*g, (j + 2) % 3)}}, 4);
                    continue;
                }
            }
            visit(f, std::array<int, 4>{{V(f, 0), V(f, 1), V(f, 2), -1}}, 3);
        }
    }

    // The polygons of a vcg triangle mesh in MeshLab's polygonal form (ForEachFauxPolygon).
    template <class MeshType>
    static PolygonMesh FromFauxMesh(MeshType &m)
    {
        PolygonMesh pm;
        std::vector<int> vid(m.vert.size(), -1);
        for (size_t i = 0; i < m.vert.size(); ++i)
            if (!m.vert[i].IsD()) {
                vid[i] = int(pm.points.size());
                pm.points.push_back(P3::Construct(m.vert[i].cP()));
            }
        ForEachFauxPolygon(m, [&](typename MeshType::FaceType &, const std::array<int, 4> &corners, int n) {
            std::vector<int> face;
            for (int k = 0; k < n; ++k) face.push_back(vid[corners[k]]);
            pm.faces.push_back(face);
        });
        for (const auto &f : m.face)  // the front: selected face-edges (a faux diagonal is none)
            if (!f.IsD())
                for (int k = 0; k < 3; ++k)
                    if (f.IsFaceEdgeS(k) && !f.IsF(k))
                        pm.frontEdges.push_back(EdgeKey(vid[vcg::tri::Index(m, f.cV(k))], vid[vcg::tri::Index(m, f.cV1(k))]));
        std::sort(pm.frontEdges.begin(), pm.frontEdges.end());
        pm.frontEdges.erase(std::unique(pm.frontEdges.begin(), pm.frontEdges.end()), pm.frontEdges.end());
        return pm;
    }
};

}  // namespace vcg_ext

#endif
