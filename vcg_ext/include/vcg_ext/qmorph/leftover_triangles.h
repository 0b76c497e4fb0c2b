// Q-Morph after the front advance, on one patch: the triangles left are paired into quads where
// the quad is good, triangles far apart are brought together through the quads between them, and
// doublets (valence-2 nodes between two quads) are dissolved.
#ifndef VCG_EXT_QMORPH_LEFTOVER_TRIANGLES_H
#define VCG_EXT_QMORPH_LEFTOVER_TRIANGLES_H

#include <algorithm>
#include <array>
#include <unordered_map>
#include <vector>

#include <vcg_ext/qmorph/patch_stage.h>

namespace vcg_ext {
namespace qmorph {

class LeftoverTriangles : public PatchStage
{
public:
    explicit LeftoverTriangles(PatchContext &context) : PatchStage(context) {}

    // Merges good adjacent pairs first, then poorer ones, then brings distant triangles together.
    void Run()
    {
        PairLeftoverTriangles(p.pairMinJacobian);
        PairLeftoverTriangles(p.migrationMinJacobian);
        MigrateTrianglesIntoPairs();
        DissolveDoublets();
    }

    void DissolveDoublets()
    {
        for (bool changed = true; changed;) {
            changed = false;
            for (int v = 0; v < m.VertexCount(); ++v)
                if (m.vertAlive[v] && !m.vertFixed[v] && m.Valence(v) == 2 && DoubletMergeIsValid(v) && m.DissolveDoublet(v)) {
                    ++stats.doublets;
                    changed = true;
                }
        }
    }

private:
    // The search for a partner triangle: moves explored at most, path length (a triangle on a
    // straight front travels along the first row to a corner), searched triangles entering one face.
    static constexpr size_t kMaxSearchMoves = 100000;
    static constexpr int kMaxSearchDepth = 96, kMaxCrossings = 4;

    void PairLeftoverTriangles(double minQuality)
    {
        struct Pair { double q; int h; };
        std::vector<Pair> pairs;
        for (int h = 0; h < m.HalfEdgeCount(); ++h) {
            int t = m.heTwin[h];
            if (t < h || !m.HeAlive(h) || !m.IsTri(m.heFace[h]) || !m.IsTri(m.heFace[t])) continue;
            double q = PairQuality(h);
            if (q > minQuality) pairs.push_back({q, h});
        }
        std::sort(pairs.begin(), pairs.end(), [](const Pair &x, const Pair &y) { return x.q > y.q; });
        for (const Pair &pr : pairs) {
            int h = pr.h, t = m.heTwin[h];
            if (!m.HeAlive(h) || t < 0 || !m.IsTri(m.heFace[h]) || !m.IsTri(m.heFace[t])) continue;
            m.MergeTriangles(h, 0);
            ++stats.pairedTriangles;
        }
    }

    // Triangles left in different places (e.g. two loops of odd length) are brought together
    // through the quads between them: a triangle and the quad it touches form a pentagon, re-split
    // into a quad and a triangle that touches another face; when the triangle reaches another
    // triangle the two merge into a quad. A breadth-first search over these moves (simulated on
    // vertex positions, every intermediate quad checked) finds a sequence, which is then applied.
    // Connectivity only: no node moves, no new node.
    struct Move {
        std::array<int, 3> v;  // triangle, counter-clockwise
        std::array<int, 3> e;  // half-edge of side v[k]->v[k+1] in the mesh, -1 for a new diagonal
        int face;              // face entered (the triangle's own face for the start)
        int option;            // pentagon split used to get here
        int parent;
        int depth;
    };

    // The pentagon formed by triangle `t` (its side k shared with quad across) and that quad:
    // vertices and side half-edges, counter-clockwise, as MigrateStep builds it.
    void Pentagon(const Move &t, int k, std::array<int, 5> &v, std::array<int, 5> &e) const
    {
        int tw = m.heTwin[t.e[k]];
        e = {t.e[(k + 1) % 3], t.e[(k + 2) % 3], m.heNext[tw], m.heNext[m.heNext[tw]], m.hePrev[tw]};
        v = {t.v[(k + 1) % 3], t.v[(k + 2) % 3], t.v[k], m.Org(e[3]), m.Org(e[4])};
    }

    bool SplitIsValid(const std::array<int, 5> &v, int i) const
    {
        for (int a = 0; a < 5; ++a)
            for (int b = a + 1; b < 5; ++b)
                if (m.vertKey[v[a]] == m.vertKey[v[b]]) return false;
        int a = v[i], b = v[(i + 1) % 5], c = v[(i + 2) % 5], d = v[(i + 3) % 5], e = v[(i + 4) % 5];
        // the quad's diagonals must not be edges already (except the edge being removed, v[0]-v[2])
        auto taken = [&](int x, int y) {
            bool removed = (x == v[0] && y == v[2]) || (x == v[2] && y == v[0]);
            return !removed && m.EdgeExists(x, y);
        };
        return !m.EdgeExists(a, c) && !m.NewChordBetweenFrontNodes(a, c) && TriPositive(a, b, c) && QuadShape(c, d, e, a) > p.migrationMinJacobian &&
               !(taken(c, e) && taken(d, a));
    }

    void MigrateTrianglesIntoPairs()
    {
        std::vector<char> gaveUp;
        int triangles = 0;  // a search needs a partner: none when a single triangle is left
        for (int f = 0; f < m.FaceCount(); ++f) triangles += m.FaceAlive(f) && m.IsTri(f);
        for (int round = 0; round < int(kMaxSearchMoves) && triangles >= 2; ++round) {
            int tri = -1;
            for (int f = 0; f < m.FaceCount() && tri < 0; ++f)
                if (m.FaceAlive(f) && m.IsTri(f) && (f >= int(gaveUp.size()) || !gaveUp[f])) tri = f;
            if (tri < 0) return;
            std::vector<Move> moves;
            int goal = -1, goalSide = -1;
            if (!SearchMigration(tri, moves, goal, goalSide)) {
                if (int(gaveUp.size()) < m.FaceCount()) gaveUp.resize(m.FaceCount(), 0);
                gaveUp[tri] = 1;
                continue;
            }
            std::vector<int> chain;
            for (int s = goal; s >= 0; s = moves[s].parent) chain.push_back(s);
            std::reverse(chain.begin(), chain.end());
            int current = tri;
            for (size_t i = 1; i < chain.size() && current >= 0; ++i)
                current = MigrateStep(current, moves[chain[i]].face, moves[chain[i]].option);
            int target = current >= 0 ? m.heFace[m.heTwin[moves[goal].e[goalSide]]] : -1;
            int shared = current >= 0 ? SharedHalfEdge(current, target) : -1;
            if (shared < 0) return;  // cannot happen: the search simulated exactly these steps
            m.MergeTriangles(shared, 0);
            ++stats.pairedTriangles;
            triangles -= 2;
        }
    }

    bool SearchMigration(int tri, std::vector<Move> &moves, int &goal, int &goalSide) const
    {
        Move start;
        int g = m.faceHe[tri];
        for (int k = 0; k < 3; ++k, g = m.heNext[g]) { start.v[k] = m.Org(g); start.e[k] = g; }
        start.face = tri;
        start.option = -1;
        start.parent = -1;
        start.depth = 0;
        moves.assign(1, start);
        std::unordered_map<int, int> crossings;  // face -> how many searched triangles entered it
        for (size_t head = 0; head < moves.size() && moves.size() < kMaxSearchMoves; ++head) {
            const Move t = moves[head];
            if (t.depth > kMaxSearchDepth) continue;  // a triangle on a straight front travels along the first row to a corner
            for (int k = 0; k < 3; ++k) {
                if (t.e[k] < 0 || m.heTwin[t.e[k]] < 0) continue;
                int face = m.heFace[m.heTwin[t.e[k]]];
                bool onPath = false;
                for (int s = int(head); s >= 0 && !onPath; s = moves[s].parent) onPath = moves[s].face == face;
                if (onPath) continue;
                if (m.IsTri(face)) {
                    int w = m.Org(m.hePrev[m.heTwin[t.e[k]]]);  // the other triangle's apex
                    if (face != tri && QuadShape(t.v[(k + 1) % 3], t.v[(k + 2) % 3], t.v[k], w) > p.migrationMinJacobian) {
                        goal = int(head);
                        goalSide = k;
                        return true;
                    }
                    continue;
                }
                // a face may be crossed by a few different triangles (other pentagon splits)
                if (++crossings[face] > kMaxCrossings) continue;
                std::array<int, 5> v, e;
                Pentagon(t, k, v, e);
                for (int i = 0; i < 5; ++i) {
                    if (!SplitIsValid(v, i)) continue;
                    Move next;
                    next.v = {v[i], v[(i + 1) % 5], v[(i + 2) % 5]};
                    next.e = {e[i], e[(i + 1) % 5], -1};
                    next.face = face;
                    next.option = i;
                    next.parent = int(head);
                    next.depth = t.depth + 1;
                    moves.push_back(next);
                }
            }
        }
        return false;
    }

    int SharedHalfEdge(int f, int g) const
    {
        int h = m.faceHe[f];
        for (int k = 0; k < m.faceSize[f]; ++k, h = m.heNext[h])
            if (m.heTwin[h] >= 0 && m.heFace[m.heTwin[h]] == g) return h;
        return -1;
    }

    // Triangle `tri` + adjacent quad `quad` -> triangle (pentagon positions option..option+2) + quad.
    int MigrateStep(int tri, int quad, int option)
    {
        int shared = SharedHalfEdge(tri, quad);
        if (shared < 0) return -1;
        int t = m.heTwin[shared];
        std::vector<int> loop{m.heNext[shared], m.hePrev[shared], m.heNext[t], m.heNext[m.heNext[t]], m.hePrev[t]};
        const int i = option;
        return m.ReplaceRegion(loop, {tri, quad}, {},
                               {{i, (i + 1) % 5, (i + 2) % 5}, {(i + 2) % 5, (i + 3) % 5, (i + 4) % 5, i}}, m.faceLevel[quad]);
    }

    double PairQuality(int h) const
    {
        int t = m.heTwin[h];
        int a = m.Org(h), b = m.Dst(h), c = m.Org(m.hePrev[h]), d = m.Org(m.hePrev[t]);
        if (!m.QuadHasFreeDiagonal(b, c, a, d, {m.heFace[h], m.heFace[t]})) return -1;
        return QuadShape(b, c, a, d, true);  // two triangles across a thin strip make a thin rectangle
    }

    // The quad left after removing a doublet node must not be inverted.
    bool DoubletMergeIsValid(int v) const
    {
        std::vector<int> out;
        m.ForEachOutgoing(v, [&](int g) { out.push_back(g); });
        if (out.size() != 2 || !m.IsQuad(m.heFace[out[0]]) || !m.IsQuad(m.heFace[out[1]])) return false;
        int h1 = out[0], h2 = out[1];
        int a = m.Dst(h1), b = m.Dst(m.heNext[h1]), c = m.Dst(h2), d = m.Dst(m.heNext[h2]);
        return QuadShape(a, b, c, d) > p.minQuadJacobian && m.QuadHasFreeDiagonal(a, b, c, d, {m.heFace[h1], m.heFace[h2]}) &&
               InnerNodesNearQuad({v}, {a, b, c, d});
    }
};

}  // namespace qmorph
}  // namespace vcg_ext

#endif
