// Structured cavities: irregular nodes removed by re-meshing a disk of quads around them as a
// regular grid, after the cavity remeshing of Gmsh's quasi-structured pipeline (Reberol, Georgiadis,
// Remacle 2021, "Quasi-structured quadrilateral meshing in Gmsh"). A disk of quads whose boundary
// can be cut into four sides, opposite sides with as many edges, is filled by a grid whose inner
// nodes all have valence 4; the boundary keeps its nodes and edges, and a boundary node's valence
// changes only where the grid's corners do not match the quads it replaces. So a pair of opposite
// 3-5 dipoles, which local turns only move around, vanishes once a cavity holds both.
//
// A cavity is kept only when the valence deviation of its nodes drops, every new quad is fair on
// the input surface and the surface is not flattened: element quality holds by construction.
#ifndef VCG_EXT_QMORPH_CAVITY_PATTERNS_H
#define VCG_EXT_QMORPH_CAVITY_PATTERNS_H

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <utility>
#include <vector>

#include <vcg_ext/qmorph/patch_stage.h>

namespace vcg_ext {
namespace qmorph {

class CavityPatterns : public PatchStage
{
public:
    explicit CavityPatterns(PatchContext &context) : PatchStage(context) {}

    // Passes over the irregular inner nodes, each grown into cavities ring by ring until one is
    // re-meshed or none fits.
    void Run()
    {
        for (int pass = 0; pass < kPasses; ++pass) {
            int remeshed = 0;
            ideal = IdealValences();
            const int count = m.VertexCount();
            for (int v = 0; v < count && m.VertexCount() < vertexCap; ++v)
                if (IrregularInnerNode(v) && RemeshAround(v)) ++remeshed;
            stats.cavities += remeshed;
            if (!remeshed) break;
        }
    }

private:
    static constexpr int kPasses = 3;
    // A cavity grows at most this many rings of faces around its node, and this many quads.
    static constexpr int kMaxRings = 5;
    static constexpr size_t kMaxQuads = 250;
    // Concave boundary nodes (three quads of the cavity or more) are filled in at most this often
    // per ring: a grid's boundary turns only at its corners.
    static constexpr int kFillPasses = 2;
    // Corner choices tried on the surface, fewest irregular nodes first.
    static constexpr int kCandidates = 6;
    // The valence deviation must drop by more than this.
    static constexpr double kMinGain = 0.5;
    // Laplacian sweeps over the grid's inner nodes, in their tangent planes, before they are
    // projected onto the input surface and the grid is rated.
    static constexpr int kGridSmoothing = 10;
    // The grid's mean quality may be at most this much below the cavity's.
    static constexpr double kMeanQualityLoss = 0.02;

    struct Cavity {
        std::vector<int> faces, loop, inner;  // quads, boundary half-edges (counter-clockwise), inner nodes
        std::vector<int> quadsAt;             // per loop position: the cavity's quads at that node
        std::vector<double> angleAt;          // ... and the cavity's angle there (radians)
    };

    std::vector<int> ideal;
    std::set<std::vector<int>> tried;  // cavities (sorted faces) that did not fit: faces are never reused
    std::vector<int> faceMark, vertMark;  // stamps
    int stamp = 0;

    double Dev(int v, int val) const { return ValenceDeviation(ideal, v, val); }

    bool IrregularInnerNode(int v) const
    {
        if (!m.vertAlive[v] || m.vertFixed[v] || m.OnBoundary(v)) return false;
        bool quads = true;
        m.ForEachOutgoing(v, [&](int g) { quads = quads && m.IsQuad(m.heFace[g]); });
        return quads && m.Valence(v) != 4;
    }

    void NewStamp()
    {
        faceMark.resize(m.FaceCount(), 0);
        vertMark.resize(m.VertexCount(), 0);
        ++stamp;
    }

    // Adds every quad around node x to the cavity; false when a triangle is there (the cavity
    // stays all quads: it cannot grow past it).
    bool AddFacesAround(int x, std::vector<int> &faces)
    {
        bool quads = true;
        m.ForEachOutgoing(x, [&](int g) {
            const int f = m.heFace[g];
            if (!m.IsQuad(f)) { quads = false; return; }
            if (faceMark[f] != stamp) { faceMark[f] = stamp; faces.push_back(f); }
        });
        return quads;
    }

    // The cavity's boundary as one counter-clockwise loop, its inner nodes, and the quads at each
    // boundary node; false when the faces are not a disk (two loops, a pinched node, a hole, an
    // initial-front node inside, or two copies of an input vertex on the boundary).
    bool Describe(Cavity &c)
    {
        NewStamp();
        for (int f : c.faces) faceMark[f] = stamp;
        std::vector<int> boundary;
        for (int f : c.faces) {
            int h = m.faceHe[f];
            for (int k = 0; k < 4; ++k, h = m.heNext[h]) {
                const int t = m.heTwin[h];
                if (t < 0 || faceMark[m.heFace[t]] != stamp) boundary.push_back(h);
            }
        }
        // boundary half-edge leaving each node (a second one: the boundary is pinched there)
        std::vector<std::pair<int, int>> leaving;
        for (int h : boundary) leaving.push_back({m.Org(h), h});
        std::sort(leaving.begin(), leaving.end());
        for (size_t k = 1; k < leaving.size(); ++k)
            if (leaving[k].first == leaving[k - 1].first) return false;
        auto next = [&](int h) {
            const auto it = std::lower_bound(leaving.begin(), leaving.end(), std::make_pair(m.Dst(h), -1));
            return it != leaving.end() && it->first == m.Dst(h) ? it->second : -1;
        };
        c.loop.clear();
        for (int h = boundary.empty() ? -1 : boundary[0]; h >= 0 && c.loop.size() <= boundary.size(); h = next(h)) {
            if (!c.loop.empty() && h == c.loop[0]) break;
            c.loop.push_back(h);
        }
        if (c.loop.size() != boundary.size()) return false;
        std::vector<int> keys;
        for (int h : c.loop) {
            vertMark[m.Org(h)] = stamp;
            keys.push_back(m.vertKey[m.Org(h)]);
        }
        std::sort(keys.begin(), keys.end());
        if (std::adjacent_find(keys.begin(), keys.end()) != keys.end()) return false;
        c.inner.clear();
        for (int f : c.faces) {
            int h = m.faceHe[f];
            for (int k = 0; k < 4; ++k, h = m.heNext[h]) {
                const int x = m.Org(h);
                if (vertMark[x] == stamp) continue;
                if (m.vertFixed[x]) return false;
                vertMark[x] = stamp;
                c.inner.push_back(x);
            }
        }
        // Euler characteristic of a disk of quads: inner nodes - quads + boundary edges / 2 = 1
        if (int(c.inner.size()) - int(c.faces.size()) + int(c.loop.size()) / 2 != 1) return false;
        c.quadsAt.assign(c.loop.size(), 0);
        c.angleAt.assign(c.loop.size(), 0);
        for (size_t i = 0; i < c.loop.size(); ++i)
            m.ForEachOutgoing(m.Org(c.loop[i]), [&](int g) {
                if (faceMark[m.heFace[g]] != stamp) return;
                ++c.quadsAt[i];
                c.angleAt[i] += m.CornerAngle(g);
            });
        return true;
    }

    // Grows cavities around v and re-meshes the first that fits.
    bool RemeshAround(int v)
    {
        NewStamp();
        Cavity c;
        if (!AddFacesAround(v, c.faces)) return false;
        for (int ring = 1; ring <= kMaxRings; ++ring) {
            if (ring > 1) {  // the next ring: every quad at a node of the cavity
                std::vector<int> nodes;
                for (int f : c.faces) {
                    int h = m.faceHe[f];
                    for (int k = 0; k < 4; ++k, h = m.heNext[h]) nodes.push_back(m.Org(h));
                }
                NewStamp();
                for (int f : c.faces) faceMark[f] = stamp;
                for (int x : nodes) AddFacesAround(x, c.faces);
            }
            if (c.faces.size() > kMaxQuads) return false;
            for (int fill = 0; fill <= kFillPasses; ++fill) {
                if (!Describe(c)) break;
                std::vector<int> key = c.faces;
                std::sort(key.begin(), key.end());
                if (tried.insert(key).second && TryGrid(c)) return true;
                // fill the concave boundary nodes (three quads or more of the cavity at them)
                std::vector<int> concave;
                for (size_t i = 0; i < c.loop.size(); ++i)
                    if (c.quadsAt[i] >= 3 && !m.OnBoundary(m.Org(c.loop[i]))) concave.push_back(m.Org(c.loop[i]));
                if (concave.empty()) break;
                NewStamp();
                for (int f : c.faces) faceMark[f] = stamp;
                for (int x : concave) AddFacesAround(x, c.faces);
                if (c.faces.size() > kMaxQuads) return false;
            }
            NewStamp();  // the ring is grown from the faces as they are
            for (int f : c.faces) faceMark[f] = stamp;
        }
        return false;
    }

    // A grid of n x k quads with corners at loop positions c0, c0+n, c0+n+k, c0+2n+k.
    struct Corners {
        double cost, misfit;  // valence deviation afterwards; corners' distance from right angles
        int c0, n, k;
        bool operator<(const Corners &o) const { return cost < o.cost || (cost == o.cost && misfit < o.misfit); }
    };

    bool TryGrid(const Cavity &c)
    {
        const int P = int(c.loop.size());
        if (P % 2 || P < 8) return false;
        // valence deviation now: the inner nodes and the boundary
        double before = 0, sides = 0;
        std::vector<double> asCorner(P);
        std::vector<int> val(P);
        for (int v : c.inner) before += Dev(v, m.Valence(v));
        for (int i = 0; i < P; ++i) {
            const int x = m.Org(c.loop[i]);
            val[i] = m.Valence(x);
            before += Dev(x, val[i]);
            // as a side node the grid has two quads at x, as a corner one
            sides += Dev(x, val[i] - c.quadsAt[i] + 2);
            asCorner[i] = Dev(x, val[i] - c.quadsAt[i] + 1) - Dev(x, val[i] - c.quadsAt[i] + 2);
        }
        // A grid's corner makes a quad corner of the cavity's angle there, a side node two: both
        // must be able to hold a fair quad (sine above kFairQuad); among grids with as few
        // irregular nodes, the one whose corners are nearest right angles is tried first.
        const double minAngle = std::asin(kFairQuad);
        std::vector<int> notSide;
        for (int i = 0; i < P; ++i)
            if (c.angleAt[i] < 2 * minAngle || c.angleAt[i] > 2 * (M_PI - minAngle)) notSide.push_back(i);
        if (notSide.size() > 4) return false;
        std::vector<Corners> choices;
        for (int c0 = 0; c0 < P; ++c0)
            for (int n = 2; n <= P / 2 - 2; ++n) {
                const int k = P / 2 - n;
                if (c0 + 2 * n + k >= P) continue;  // each grid once: c0 is its first corner
                const int at[4] = {c0, c0 + n, c0 + n + k, c0 + 2 * n + k};
                double cost = sides, misfit = 0;
                bool fits = true;
                for (int x : at) {
                    cost += asCorner[x];
                    misfit += std::abs(c.angleAt[x] - M_PI / 2);
                    fits = fits && c.angleAt[x] > minAngle && c.angleAt[x] < M_PI - minAngle;
                }
                for (int x : notSide) fits = fits && std::find(at, at + 4, x) != at + 4;
                if (fits && cost < before - kMinGain) choices.push_back({cost, misfit, c0, n, k});
            }
        if (choices.empty()) return false;
        std::stable_sort(choices.begin(), choices.end());
        if (choices.size() > size_t(kCandidates)) choices.resize(kCandidates);
        double worstBefore = 1e9, meanBefore = 0;
        for (int f : c.faces) {
            const double q = FaceQualityAt(f, m.InputFaceNormal(f, true));
            worstBefore = std::min(worstBefore, q);
            meanBefore += q / c.faces.size();
        }
        for (const Corners &corners : choices)
            if (PlaceGrid(c, corners, worstBefore, meanBefore)) return true;
        return false;
    }

    // Lays the grid on the surface, rates it and, when it is fair, puts it in place of the cavity.
    bool PlaceGrid(const Cavity &c, const Corners &g, double worstBefore, double meanBefore)
    {
        const int P = int(c.loop.size()), n = g.n, k = g.k;
        // grid node (i, j), 0 <= i <= n, 0 <= j <= k: its loop position on the boundary, else -1
        auto loopPos = [&](int i, int j) {
            if (j == 0) return (g.c0 + i) % P;
            if (i == n) return (g.c0 + n + j) % P;
            if (j == k) return (g.c0 + n + k + (n - i)) % P;
            if (i == 0) return (g.c0 + 2 * n + k + (k - j)) % P;
            return -1;
        };
        auto at = [&](int i, int j) { return m.pos[m.Org(c.loop[loopPos(i, j)])]; };
        const int W = n + 1;
        std::vector<P3> pos(W * (k + 1));
        std::vector<int> homes(pos.size(), -1);
        for (int j = 0; j <= k; ++j)
            for (int i = 0; i <= n; ++i) {
                const int l = loopPos(i, j);
                if (l >= 0) {
                    pos[j * W + i] = at(i, j);
                    homes[j * W + i] = m.HomeOf(m.Org(c.loop[l]));
                    continue;
                }
                // transfinite (Coons) interpolation of the four sides
                const double u = double(i) / n, w = double(j) / k;
                pos[j * W + i] = at(i, 0) * (1 - w) + at(i, k) * w + at(0, j) * (1 - u) + at(n, j) * u -
                                 (at(0, 0) * ((1 - u) * (1 - w)) + at(n, 0) * (u * (1 - w)) + at(0, k) * ((1 - u) * w) + at(n, k) * (u * w));
                homes[j * W + i] = m.HomeOf(m.Org(c.loop[loopPos(i, 0)]));
                pos[j * W + i] = proj.Project(pos[j * W + i], homes[j * W + i]);
            }
        // Laplacian sweeps in each node's tangent plane, then back onto the surface (one projection
        // per node: the sweeps only even out the spacing)
        std::vector<P3> normals(pos.size());
        for (size_t x = 0; x < pos.size(); ++x) normals[x] = proj.Normal(homes[x]);
        for (int sweep = 0; sweep < kGridSmoothing; ++sweep)
            for (int j = 1; j < k; ++j)
                for (int i = 1; i < n; ++i) {
                    P3 &p = pos[j * W + i];
                    const P3 target = (pos[j * W + i - 1] + pos[j * W + i + 1] + pos[(j - 1) * W + i] + pos[(j + 1) * W + i]) * 0.25;
                    P3 move = target - p;
                    move -= normals[j * W + i] * (move * normals[j * W + i]);
                    p += move;
                }
        for (int j = 1; j < k; ++j)
            for (int i = 1; i < n; ++i) pos[j * W + i] = proj.Project(pos[j * W + i], homes[j * W + i]);
        // the grid must be fair: no quad worse than the worst it replaces or than kFairQuad, and
        // about as good on average
        double meanAfter = 0;
        const double floor = std::min(kFairQuad, worstBefore);
        std::vector<std::array<P3, 4>> quads;
        std::vector<std::array<int, 4>> quadHomes;
        for (int j = 0; j < k; ++j)
            for (int i = 0; i < n; ++i) {
                const int ids[4] = {j * W + i, j * W + i + 1, (j + 1) * W + i + 1, (j + 1) * W + i};
                std::array<P3, 4> q;
                P3 centre(0, 0, 0);
                int hs[4];
                for (int t = 0; t < 4; ++t) {
                    q[t] = pos[ids[t]];
                    centre += q[t] * 0.25;
                    hs[t] = homes[ids[t]];
                }
                P3 normal = m.InputSurfaceNormalAt(centre, hs, 4);
                if (!(normal.SquaredNorm() > 0)) normal = proj.Normal(hs[0]);
                const double shape = QuadShape(q, normal);
                if (!(shape > 0) || shape < floor) return false;
                meanAfter += shape;
                quads.push_back(q);
                quadHomes.push_back({hs[0], hs[1], hs[2], hs[3]});
            }
        if (meanAfter / quads.size() < meanBefore - kMeanQualityLoss) return false;
        // rated on the patch's surface above (cheap); the grid that passes is rated again under
        // the judge's normal (the true input under a re-meshed patch), as every face is
        for (size_t q = 0; q < quads.size(); ++q) {
            const P3 centre = (quads[q][0] + quads[q][1] + quads[q][2] + quads[q][3]) * 0.25;
            P3 normal = m.InputSurfaceNormalAt(centre, quadHomes[q].data(), 4, true);
            if (!(normal.SquaredNorm() > 0)) normal = proj.Normal(quadHomes[q][0]);
            const double shape = QuadShape(quads[q], normal);
            if (!(shape > 0) || shape < floor) return false;
        }
        // the surface must not flatten: every new quad stays near the input surface
        for (size_t q = 0; q < quads.size(); ++q) {
            const P3 centre = (quads[q][0] + quads[q][1] + quads[q][2] + quads[q][3]) * 0.25;
            int from = homes[(q / n) * W + q % n];
            if ((proj.Project(centre, from) - centre).Norm() > kFlattening * meanLength) return false;
        }
        // in place: new inner nodes, then the grid's quads over loop positions and new nodes
        std::vector<int> added, position(pos.size());
        for (int j = 0; j <= k; ++j)
            for (int i = 0; i <= n; ++i) {
                const int l = loopPos(i, j);
                if (l >= 0) { position[j * W + i] = l; continue; }
                position[j * W + i] = P + int(added.size());
                added.push_back(m.AddVertex(pos[j * W + i]));
                home.resize(m.VertexCount(), 0);
                home[added.back()] = homes[j * W + i];
            }
        std::vector<std::vector<int>> polygons;
        for (int j = 0; j < k; ++j)
            for (int i = 0; i < n; ++i)
                polygons.push_back({position[j * W + i], position[j * W + i + 1], position[(j + 1) * W + i + 1], position[(j + 1) * W + i]});
        int level = 0;
        for (int f : c.faces) level = std::max(level, m.faceLevel[f]);
        m.ReplaceRegion(c.loop, c.faces, c.inner, polygons, level, added);
        for (int x : added) SmoothNode(x);
        return true;
    }
};

}  // namespace qmorph
}  // namespace vcg_ext

#endif
