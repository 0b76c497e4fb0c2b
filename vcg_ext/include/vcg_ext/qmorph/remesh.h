// Optional isotropic re-meshing of one patch before Q-Morph, after Botsch & Kobbelt (2004): split
// edges longer than 4/3 L, collapse edges shorter than 4/5 L, flip edges toward valence 6 (4 on
// the boundary), relax nodes tangentially and project them back onto the patch's input surface.
// Q-Morph then starts from well-shaped triangles of one size (the seed paper's own suggestion).
//
// The patch boundary is the initial front: it is never flipped, collapsed or moved. The caller
// subdivides it first (SubdivideBoundaryEdge) with points that depend only on the edge's two input
// vertices, so the two patches on either side of a front edge get the very same points and the
// front curve stays a chain of output edges.
#ifndef VCG_EXT_QMORPH_REMESH_H
#define VCG_EXT_QMORPH_REMESH_H

#include <algorithm>
#include <cmath>
#include <vector>

#include <vcg_ext/qmorph/mixed_mesh.h>
#include <vcg_ext/qmorph/surface_projector.h>

namespace vcg_ext {
namespace qmorph {

class PatchRemesher
{
public:
    // How many pieces a front edge of this length is cut into for target length L.
    static int PiecesFor(double length, double L) { return L > 0 ? std::max(1, int(std::lround(length / L))) : 1; }

    // Splits boundary half-edge h (from a to b) at the given points, in order from a to b. The new
    // nodes are initial-front nodes (fixed). Returns them in order.
    static std::vector<int> SubdivideBoundaryEdge(MixedMesh &m, std::vector<int> &home, int h, const std::vector<P3> &points)
    {
        std::vector<int> made;
        for (const P3 &p : points) {
            const int from = m.Org(h);
            const int v = m.SplitEdge(h, p);  // h now ends at v
            m.vertFixed[v] = 1;
            home.resize(m.VertexCount(), 0);
            home[v] = home[from];
            made.push_back(v);
            h = m.vertHe[v];  // the boundary half-edge v -> b (a boundary node keeps that one)
        }
        return made;
    }

    PatchRemesher(MixedMesh &mesh, const SurfaceProjector &surface, std::vector<int> &homeTriangle, double targetLength)
        : m(mesh), proj(surface), home(homeTriangle), L(targetLength)
    {
        home.resize(m.VertexCount(), 0);
    }

    struct Stats {
        int splits = 0, collapses = 0, flips = 0;
        Stats &operator+=(const Stats &o)
        {
            splits += o.splits; collapses += o.collapses; flips += o.flips;
            return *this;
        }
    };

    Stats Run(int iterations)
    {
        for (int it = 0; it < iterations; ++it) {
            SplitLongEdges();
            CollapseShortEdges();
            FlipTowardValence();
            for (int k = 0; k < 2; ++k) Relax();
        }
        return stats;
    }

private:
    // Botsch-Kobbelt's bounds: split above 4/3 L, collapse below 4/5 L; a collapse leaves the
    // triangles around at least this good.
    static constexpr double kSplitAbove = 4.0 / 3.0, kCollapseBelow = 0.8, kMinCollapseQuality = 0.1;

    MixedMesh &m;
    const SurfaceProjector &proj;
    std::vector<int> &home;
    const double L;
    Stats stats;

    bool Interior(int h) const
    {
        const int t = m.heTwin[h];
        return t >= 0 && m.HeAlive(h) && !m.heInitial[h] && m.IsTri(m.heFace[h]) && m.IsTri(m.heFace[t]);
    }

    void SplitLongEdges()
    {
        const double hi2 = (kSplitAbove * L) * (kSplitAbove * L);
        const int count = m.HalfEdgeCount();  // edges made by this pass are already short enough
        for (int h = 0; h < count; ++h) {
            if (!Interior(h) || m.heTwin[h] < h || m.Vec(h).SquaredNorm() <= hi2) continue;
            const int from = m.Org(h);
            const P3 mid = (m.pos[m.Org(h)] + m.pos[m.Dst(h)]) * 0.5;
            const int v = m.SplitEdge(h, mid);
            home.resize(m.VertexCount(), 0);
            home[v] = home[from];
            TryMove(v, proj.Project(mid, home[v]));
            ++stats.splits;
        }
    }

    void CollapseShortEdges()
    {
        const double lo2 = (kCollapseBelow * L) * (kCollapseBelow * L), hi = kSplitAbove * L;
        for (int h = 0; h < m.HalfEdgeCount(); ++h) {
            if (!Interior(h) || m.Vec(h).SquaredNorm() >= lo2) continue;
            const int x = m.Org(h), y = m.Dst(h);
            if (m.vertFixed[y]) continue;  // y joins x: only a free node goes (the twin has the other order)
            P3 at = m.pos[x];
            if (!m.vertFixed[x]) {
                int hm = home[x];
                at = proj.Project((m.pos[x] + m.pos[y]) * 0.5, hm);
            }
            // no edge of the joined node may become long, no face may fold
            bool ok = true;
            for (int v : {x, y})
                m.ForEachOutgoing(v, [&](int g) { if ((m.pos[m.Dst(g)] - at).Norm() > hi && m.Dst(g) != x && m.Dst(g) != y) ok = false; });
            // no new chord between front nodes that another patch could also make
            if (m.vertFixed[x])
                m.ForEachOutgoing(y, [&](int g) { if (m.Dst(g) != x && m.NewChordBetweenFrontNodes(x, m.Dst(g))) ok = false; });
            if (!ok) continue;
            const std::vector<int> around = m.FacesAround({x, y}, {m.heFace[h], m.heFace[m.heTwin[h]]});
            if (m.WorstQualityIfMoved({x, y}, at, around, [&](int f, const P3 &n) { return m.TriangleQuality(f, n); }).second <= kMinCollapseQuality)
                continue;
            if (m.CollapseEdge(h, at)) ++stats.collapses;
        }
    }

    int TargetValence(int v) const { return m.OnBoundary(v) ? 4 : 6; }

    void FlipTowardValence()
    {
        for (int h = 0; h < m.HalfEdgeCount(); ++h) {
            if (!Interior(h) || m.heTwin[h] < h || !m.CanFlip(h)) continue;
            const int t = m.heTwin[h];
            const int a = m.Org(h), b = m.Dst(h), c = m.Org(m.hePrev[h]), d = m.Org(m.hePrev[t]);
            auto dev = [&](int v, int delta) { return std::abs(m.Valence(v) + delta - TargetValence(v)); };
            const int before = dev(a, 0) + dev(b, 0) + dev(c, 0) + dev(d, 0);
            const int after = dev(a, -1) + dev(b, -1) + dev(c, 1) + dev(d, 1);
            if (after < before) {
                m.Flip(h);
                ++stats.flips;
            }
        }
    }

    // Tangential relaxation toward the area-weighted centroid of the neighbouring triangles.
    void Relax()
    {
        for (int v = 0; v < m.VertexCount(); ++v) {
            if (!m.vertAlive[v] || m.vertFixed[v] || m.vertHe[v] < 0) continue;
            P3 sum(0, 0, 0);
            double area = 0;
            m.ForEachOutgoing(v, [&](int g) {
                const int f = m.heFace[g];
                const double a = m.FaceNormal(f).Norm();
                P3 c = (m.pos[m.Org(g)] + m.pos[m.Dst(g)] + m.pos[m.Org(m.hePrev[g])]) / 3.0;
                sum += c * a;
                area += a;
            });
            if (!(area > 0)) continue;
            const P3 n = m.VertexNormal(v);
            P3 move = sum / area - m.pos[v];
            move -= n * (move * n);
            TryMove(v, proj.Project(m.pos[v] + move, home[v]));
        }
    }

    bool TryMove(int v, const P3 &to)
    {
        return m.TryMoveNode(v, to, [&](int f, const P3 &n) { return m.TriangleQuality(f, n); });
    }
};

}  // namespace qmorph
}  // namespace vcg_ext

#endif
