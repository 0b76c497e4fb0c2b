// Cavity patterns: irregular nodes removed by re-meshing a disk of quads around them from a
// pattern, after the cavity remeshing of Gmsh's quasi-structured pipeline (Reberol, Georgiadis,
// Remacle 2021, "Quasi-structured quadrilateral meshing in Gmsh"). The disk's boundary keeps its
// nodes and edges and is cut into sides at chosen corners:
//   - four sides, opposite ones with as many edges: a grid, whose inner nodes all have valence 4
//     (a pair of opposite 3-5 dipoles, which local turns only move around, vanishes);
//   - three or five sides: a star of grids around one centre of valence 3 or 5 (a cluster of
//     irregular nodes whose valences do not cancel becomes the one node they add up to).
// A boundary node's valence changes only where the pattern's corners do not match the quads it
// replaces. A pattern is kept only when the valence deviation of the cavity's nodes drops (or,
// around a quad below 0.3 scaled Jacobian, stays while every new quad gets above 0.3), every new
// quad is fair on the input surface (no worse than the worst it replaces, or than 0.3) and the
// surface is not flattened: element quality holds by construction.
#ifndef VCG_EXT_QMORPH_CAVITY_PATTERNS_H
#define VCG_EXT_QMORPH_CAVITY_PATTERNS_H

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
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
                if ((IrregularInnerNode(v) || NodeOfPoorQuad(v)) && RemeshAround(v)) ++remeshed;
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
    static constexpr int kCandidates = 3;
    // A star's corners are chosen among this many loop nodes, those where a corner fits best.
    static constexpr int kStarCornerNodes = 8;
    static constexpr int kMaxStar = 5;  // corners of the largest star
    // The valence deviation must drop by more than this (around a poor quad: not rise, by more
    // than rounding).
    static constexpr double kMinGain = 0.5, kSameDeviation = 1e-9;
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
    std::vector<double> quality;       // per face, once rated (NaN: not yet); no old node moves during a run

    double QualityOf(int f)
    {
        if (f >= int(quality.size())) quality.resize(m.FaceCount(), std::nan(""));
        if (std::isnan(quality[f])) quality[f] = FaceQualityAt(f, m.InputFaceNormal(f));
        return quality[f];
    }
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

    // An inner node with only quads around, one of them poor (below kFairQuad): a pattern that
    // keeps the valences but makes every quad fair is taken too.
    bool NodeOfPoorQuad(int v)
    {
        if (!m.vertAlive[v] || m.vertFixed[v] || m.OnBoundary(v)) return false;
        bool quads = true, poor = false;
        m.ForEachOutgoing(v, [&](int g) {
            quads = quads && m.IsQuad(m.heFace[g]);
            poor = poor || (quads && QualityOf(m.heFace[g]) < kFairQuad);
        });
        return quads && poor;
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
                if (tried.insert(key).second && TryPatterns(c)) return true;
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

    // Where a pattern's corners go on the loop (increasing positions): 4 for a grid, 3 or 5 for a
    // star; rated by the valence deviation it leaves, then by how far its corners are from the
    // angle the pattern wants there.
    struct Corners {
        double cost, misfit;
        std::vector<int> at;
        bool operator<(const Corners &o) const { return cost < o.cost || (cost == o.cost && misfit < o.misfit); }
    };

    // A pattern laid out on the surface: nodes are the loop's positions (as they are) then the new
    // inner nodes; quads counter-clockwise over them.
    struct Layout {
        std::vector<P3> pos;
        std::vector<int> homes;  // a triangle of the input surface near each node
        std::vector<std::array<int, 4>> quads;
    };

    // Picks the patterns that would lower the valence deviation of the cavity's nodes and lays
    // the best that is fair in place of the cavity.
    bool TryPatterns(const Cavity &c)
    {
        const int P = int(c.loop.size());
        // valence deviation now: the inner nodes and the boundary; afterwards the boundary's is
        // `sides` when every loop node is a side node of the pattern (two of its quads there), plus
        // asCorner[i] for each loop node that is a corner instead (one quad)
        double before = 0, sides = 0;
        std::vector<double> asCorner(P);
        for (int v : c.inner) before += Dev(v, m.Valence(v));
        for (int i = 0; i < P; ++i) {
            const int x = m.Org(c.loop[i]), outside = m.Valence(x) - c.quadsAt[i];
            before += Dev(x, m.Valence(x));
            sides += Dev(x, outside + 2);
            asCorner[i] = Dev(x, outside + 1) - Dev(x, outside + 2);
        }
        // A corner makes one quad corner of the cavity's angle there, a side node two: both must
        // be able to hold a fair quad (sine above kFairQuad).
        const double minAngle = std::asin(kFairQuad);
        std::vector<int> notSide, cornerable;
        for (int i = 0; i < P; ++i) {
            if (c.angleAt[i] < 2 * minAngle || c.angleAt[i] > 2 * (M_PI - minAngle)) notSide.push_back(i);
            if (c.angleAt[i] > minAngle && c.angleAt[i] < M_PI - minAngle) cornerable.push_back(i);
        }
        if (notSide.size() > 5) return false;  // no pattern has more corners
        double worstBefore = 1e9, meanBefore = 0;
        for (int f : c.faces) {
            const double q = QualityOf(f);
            worstBefore = std::min(worstBefore, q);
            meanBefore += q / c.faces.size();
        }
        // a pattern must lower the valence deviation; around a poor quad, keeping it is enough
        // when every new quad is fair
        const double allowed = worstBefore < kFairQuad ? before + kSameDeviation : before - kMinGain;
        std::vector<Corners> choices;
        // `at`: `count` loop positions, increasing
        auto consider = [&](const int *at, int count, double inside) {
            double cost = sides + inside;
            for (int i = 0; i < count; ++i) cost += asCorner[at[i]];
            if (!(cost < allowed)) return;
            for (int x : notSide)
                if (!std::binary_search(at, at + count, x)) return;
            const double want = M_PI * (count - 2) / count;  // a regular polygon's angle
            double misfit = 0;
            for (int i = 0; i < count; ++i) misfit += std::abs(c.angleAt[at[i]] - want);
            choices.push_back({cost, misfit, std::vector<int>(at, at + count)});
        };
        // grids: opposite sides alike (n and k edges, both at least 2: every quad has a new node,
        // so no new edge joins two loop nodes)
        if (P % 2 == 0)
            for (int c0 = 0; c0 < P; ++c0)
                for (int n = 2; n <= P / 2 - 2; ++n) {
                    const int k = P / 2 - n;
                    const int at[4] = {c0, c0 + n, c0 + n + k, c0 + 2 * n + k};
                    if (at[3] < P) consider(at, 4, 0);
                }
        // stars: corners among the loop nodes that fit one best, a centre of valence 3 or 5
        std::vector<int> best = cornerable;
        std::stable_sort(best.begin(), best.end(), [&](int x, int y) { return asCorner[x] < asCorner[y]; });
        if (best.size() > size_t(kStarCornerNodes)) best.resize(kStarCornerNodes);
        for (int x : notSide)
            if (std::find(best.begin(), best.end(), x) == best.end()) best.push_back(x);
        std::sort(best.begin(), best.end());  // picks in increasing order are increasing positions
        double lowest = 0;  // the most a corner can lower the cost: bounds the search
        for (int x : best) lowest = std::min(lowest, asCorner[x]);
        for (int N : {3, 5}) {
            const double centre = ValenceDeviation({}, 0, N);  // the centre's: ideally 4
            std::array<int, kMaxStar> pick, parts;
            std::function<void(int, int, double)> choose = [&](int from, int count, double cost) {
                if (!(cost + (N - count) * lowest < allowed)) return;
                if (count == N) {
                    if (StarSides(pick.data(), N, P, parts.data())) consider(pick.data(), N, centre);
                    return;
                }
                for (int i = from; i < int(best.size()); ++i) {
                    pick[count] = best[i];
                    choose(i + 1, count + 1, cost + asCorner[best[i]]);
                }
            };
            choose(0, 0, sides + centre);
        }
        if (choices.empty()) return false;
        std::stable_sort(choices.begin(), choices.end());
        if (choices.size() > size_t(kCandidates)) choices.resize(kCandidates);
        for (const Corners &corners : choices) {
            Layout layout = corners.at.size() == 4 ? GridLayout(c, corners.at) : StarLayout(c, corners.at);
            const double floor = corners.cost < before - kMinGain ? std::min(kFairQuad, worstBefore) : kFairQuad;
            if (Fair(c, layout, floor, meanBefore)) {
                Place(c, layout);
                return true;
            }
        }
        return false;
    }

    // A star of N grids around one centre: side s (from corner s to corner s+1, l[s] edges) is
    // split after a[s] edges, and a spoke runs from that split to the centre. Grid s sits at
    // corner s, a[s] by l[s-1] - a[s-1], so the spoke from side s has a[s+1] = l[s-1] - a[s-1]
    // edges: for odd N that fixes every a[s]. False when there is no such star (parity, or a
    // part without an edge).
    static bool StarSides(const int *at, int N, int P, int *a)
    {
        int l[kMaxStar];
        for (int s = 0; s < N; ++s) l[s] = (at[(s + 1) % N] - at[s] + P) % P;
        int sum = 0;  // walking a[t + 2] = l[t] - a[t] around the star: a[0] = sum - a[0]
        for (int t = 0, step = 0; step < N; ++step, t = (t + 2) % N) sum = l[t] - sum;
        if (sum % 2 || sum <= 0) return false;
        a[0] = sum / 2;
        for (int t = 0, step = 0; step < N - 1; ++step, t = (t + 2) % N) a[(t + 2) % N] = l[t] - a[t];
        for (int s = 0; s < N; ++s)
            if (a[s] < 1 || l[s] - a[s] < 1) return false;
        return true;
    }

    Layout StartLayout(const Cavity &c) const
    {
        Layout layout;
        for (int h : c.loop) {
            layout.pos.push_back(m.pos[m.Org(h)]);
            layout.homes.push_back(m.HomeOf(m.Org(h)));
        }
        return layout;
    }

    // A new node on the surface near p, found from input triangle `from` (a node's next to it:
    // the walk is short).
    int NewNode(Layout &layout, const P3 &p, int from) const
    {
        layout.pos.push_back(proj.Project(p, from));
        layout.homes.push_back(from);
        return int(layout.pos.size()) - 1;
    }

    // A grid of quads inside four sides given as node lists: bottom[u] and top[u] for u = 0..a,
    // left[v] and right[v] for v = 0..b (bottom[0] = left[0], bottom[a] = right[0], and so on);
    // its inner nodes by transfinite (Coons) interpolation of the sides, onto the surface.
    void AddGrid(Layout &layout, const std::vector<int> &bottom, const std::vector<int> &right, const std::vector<int> &top,
                 const std::vector<int> &left) const
    {
        const int a = int(bottom.size()) - 1, b = int(left.size()) - 1;
        std::vector<int> id((a + 1) * (b + 1));
        auto P = [&](int node) { return layout.pos[node]; };
        for (int v = 0; v <= b; ++v)
            for (int u = 0; u <= a; ++u) {
                int &node = id[v * (a + 1) + u];
                if (v == 0) node = bottom[u];
                else if (v == b) node = top[u];
                else if (u == 0) node = left[v];
                else if (u == a) node = right[v];
                else {
                    const double s = double(u) / a, t = double(v) / b;
                    const P3 p = P(bottom[u]) * (1 - t) + P(top[u]) * t + P(left[v]) * (1 - s) + P(right[v]) * s -
                                 (P(bottom[0]) * ((1 - s) * (1 - t)) + P(bottom[a]) * (s * (1 - t)) + P(top[0]) * ((1 - s) * t) + P(top[a]) * (s * t));
                    node = NewNode(layout, p, layout.homes[id[(v - 1) * (a + 1) + u]]);  // from the row below
                }
            }
        for (int v = 0; v < b; ++v)
            for (int u = 0; u < a; ++u)
                layout.quads.push_back({id[v * (a + 1) + u], id[v * (a + 1) + u + 1], id[(v + 1) * (a + 1) + u + 1], id[(v + 1) * (a + 1) + u]});
    }

    // Nodes of the loop from position `from`, `count` edges forward (count < 0: backward).
    static std::vector<int> LoopRun(int from, int count, int P)
    {
        std::vector<int> run;
        for (int k = 0; k <= std::abs(count); ++k) run.push_back(((from + (count < 0 ? -k : k)) % P + P) % P);
        return run;
    }

    // One grid with corners at[0..3]: n = at[1] - at[0] by k = at[2] - at[1] quads.
    Layout GridLayout(const Cavity &c, const std::vector<int> &at) const
    {
        const int P = int(c.loop.size()), n = at[1] - at[0], k = at[2] - at[1];
        Layout layout = StartLayout(c);
        AddGrid(layout, LoopRun(at[0], n, P), LoopRun(at[1], k, P), LoopRun(at[3], -n, P), LoopRun(at[0], -k, P));
        return layout;
    }

    // N grids around a centre of valence N (see StarSides).
    Layout StarLayout(const Cavity &c, const std::vector<int> &at) const
    {
        const int P = int(c.loop.size()), N = int(at.size());
        int a[kMaxStar];
        StarSides(at.data(), N, P, a);
        Layout layout = StartLayout(c);
        // the centre: the loop's mean, onto the surface from the loop node nearest it
        P3 mean(0, 0, 0);
        for (const P3 &p : layout.pos) mean += p / double(P);
        int nearest = 0;
        for (int i = 1; i < P; ++i)
            if ((layout.pos[i] - mean).SquaredNorm() < (layout.pos[nearest] - mean).SquaredNorm()) nearest = i;
        const int centre = NewNode(layout, mean, layout.homes[nearest]);
        // spoke s: from the split of side s to the centre, a[s + 1] edges
        std::vector<std::vector<int>> spoke(N);
        for (int s = 0; s < N; ++s) {
            const int split = (at[s] + a[s]) % P, length = a[(s + 1) % N];
            spoke[s].push_back(split);
            for (int t = 1; t < length; ++t)
                spoke[s].push_back(NewNode(layout, layout.pos[split] + (layout.pos[centre] - layout.pos[split]) * (double(t) / length),
                                           layout.homes[spoke[s].back()]));
            spoke[s].push_back(centre);
        }
        // grid s at corner s: along side s to its split, back along side s - 1 to its split
        for (int s = 0; s < N; ++s) {
            const int prev = (s + N - 1) % N;
            AddGrid(layout, LoopRun(at[s], a[s], P), spoke[s], spoke[prev], LoopRun(at[s], -int(spoke[s].size() - 1), P));
        }
        return layout;
    }

    // Evens out the new nodes (Laplacian sweeps in their tangent planes, then onto the surface)
    // and rates the pattern: no quad below `floor`, about as good on average as the quads it
    // replaces, none farther from the input surface than the flattening allowance.
    bool Fair(const Cavity &c, Layout &layout, double floor, double meanBefore) const
    {
        const int P = int(c.loop.size()), count = int(layout.pos.size());
        std::vector<P3> normals(count);
        for (int x = P; x < count; ++x) normals[x] = proj.Normal(layout.homes[x]);
        for (int sweep = 0; sweep < kGridSmoothing; ++sweep) {
            std::vector<P3> sum(count, P3(0, 0, 0));
            std::vector<int> edges(count, 0);
            for (const auto &q : layout.quads)  // every edge of a new node is in two quads: counted alike
                for (int t = 0; t < 4; ++t) {
                    const int x = q[t], y = q[(t + 1) % 4];
                    sum[x] += layout.pos[y], ++edges[x];
                    sum[y] += layout.pos[x], ++edges[y];
                }
            for (int x = P; x < count; ++x) {
                P3 move = sum[x] / double(edges[x]) - layout.pos[x];
                move -= normals[x] * (move * normals[x]);
                layout.pos[x] += move;
            }
        }
        for (int x = P; x < count; ++x) layout.pos[x] = proj.Project(layout.pos[x], layout.homes[x]);
        auto corners = [&](const std::array<int, 4> &q) {
            return std::array<P3, 4>{layout.pos[q[0]], layout.pos[q[1]], layout.pos[q[2]], layout.pos[q[3]]};
        };
        auto shape = [&](const std::array<int, 4> &q, bool exact) {
            const std::array<P3, 4> pos = corners(q);
            int homes[4] = {layout.homes[q[0]], layout.homes[q[1]], layout.homes[q[2]], layout.homes[q[3]]};
            P3 normal = m.InputSurfaceNormalAt((pos[0] + pos[1] + pos[2] + pos[3]) * 0.25, homes, 4, exact);
            if (!(normal.SquaredNorm() > 0)) normal = proj.Normal(homes[0]);
            return QuadShape(pos, normal);
        };
        // rated on the patch's surface first (cheap), then under the judge's normal (the true
        // input under a re-meshed patch), as every face is
        double meanAfter = 0;
        for (const auto &q : layout.quads) {
            const double quality = shape(q, false);
            if (!(quality > 0) || quality < floor) return false;
            meanAfter += quality / layout.quads.size();
        }
        if (meanAfter < meanBefore - kMeanQualityLoss) return false;
        for (const auto &q : layout.quads) {
            const double quality = shape(q, true);
            if (!(quality > 0) || quality < floor) return false;
        }
        for (const auto &q : layout.quads) {
            const std::array<P3, 4> pos = corners(q);
            const P3 centre = (pos[0] + pos[1] + pos[2] + pos[3]) * 0.25;
            int from = layout.homes[q[0]];
            if ((proj.Project(centre, from) - centre).Norm() > kFlattening * meanLength) return false;
        }
        return true;
    }

    // The pattern in place of the cavity: its new nodes, then its quads.
    void Place(const Cavity &c, const Layout &layout)
    {
        const int P = int(c.loop.size());
        std::vector<int> added;
        for (int x = P; x < int(layout.pos.size()); ++x) {
            added.push_back(m.AddVertex(layout.pos[x]));
            home.resize(m.VertexCount(), 0);
            home[added.back()] = layout.homes[x];
        }
        std::vector<std::vector<int>> polygons;
        for (const auto &q : layout.quads) polygons.push_back({q[0], q[1], q[2], q[3]});
        int level = 0;
        for (int f : c.faces) level = std::max(level, m.faceLevel[f]);
        m.ReplaceRegion(c.loop, c.faces, c.inner, polygons, level, added);
        for (int x : added) SmoothNode(x);
    }
};

}  // namespace qmorph
}  // namespace vcg_ext

#endif
