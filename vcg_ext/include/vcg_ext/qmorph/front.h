// The Q-Morph front on a MixedMesh: a front edge is a half-edge of an unmeshed triangle whose
// other side is a quad or the patch boundary (the initial front), directed so the unmeshed region
// is on its left. The front is implicit in the mesh, so loops split and merge by themselves when
// quads are added; its neighbours along a loop are found by walking the triangle fan at a node.
//
// State of a front edge (Owen et al.): bit 1 = its left end is "closed" (the angle to the previous
// front edge, on the unmeshed side, is below the threshold, so that edge becomes a quad side),
// bit 2 = its right end is closed. Level = the row: 0 on the initial front, quad level + 1 after.
// The queue serves the highest state first, then the lowest level; entries are checked when popped.
#ifndef VCG_EXT_QMORPH_FRONT_H
#define VCG_EXT_QMORPH_FRONT_H

#include <cmath>
#include <queue>
#include <vector>

#include <vcg_ext/qmorph/mixed_mesh.h>

namespace vcg_ext {
namespace qmorph {

// An edge radiating from a front node into the unmeshed region, with its angle from the front
// edge, measured on the surface (sum of the triangle corner angles swept).
struct FanEdge {
    int vertex;  // other end
    int he;      // half-edge from the node along the edge; for the closing edge: the adjacent
                 // front half-edge itself (incoming at a left fan, outgoing at a right fan)
    double angle;
};
// The triangle between two consecutive fan edges, by its side opposite the node.
struct FanGap {
    int opposite;  // half-edge (inside that triangle) of the side opposite the node
    double angleStart, angleEnd;
};
struct Fan {
    int node = -1;
    std::vector<FanEdge> edges;  // edges[0] = the front edge itself (angle 0), back() = the adjacent front edge
    std::vector<FanGap> gaps;    // gaps[i] between edges[i] and edges[i+1]
    double Total() const { return edges.empty() ? 0 : edges.back().angle; }
};

class Front
{
public:
    explicit Front(MixedMesh &mesh) : m(mesh) {}

    bool IsFront(int h) const
    {
        if (!m.HeAlive(h) || !m.IsTri(m.heFace[h])) return false;
        int t = m.heTwin[h];
        return t < 0 || m.IsQuad(m.heFace[t]);
    }

    int Level(int h) const
    {
        int t = m.heTwin[h];
        return t < 0 ? 0 : m.faceLevel[m.heFace[t]];
    }

    // Fan at the left end (origin) of front edge h, counter-clockwise from h to the previous front edge.
    bool LeftFan(int h, Fan &fan) const
    {
        fan.node = m.Org(h);
        fan.edges.assign(1, {m.Dst(h), h, 0.0});
        fan.gaps.clear();
        int g = h;
        double cum = 0;
        for (int guard = 0; guard < 256; ++guard) {
            cum += m.CornerAngle(g);
            int e = m.hePrev[g];  // X -> node
            fan.gaps.push_back({m.heNext[g], fan.edges.back().angle, cum});
            if (IsFront(e)) { fan.edges.push_back({m.Org(e), e, cum}); return true; }
            g = m.heTwin[e];
            if (g < 0) return false;
            fan.edges.push_back({m.Dst(g), g, cum});
        }
        return false;
    }

    // Fan at the right end (destination) of front edge h, clockwise from h to the next front edge.
    bool RightFan(int h, Fan &fan) const
    {
        fan.node = m.Dst(h);
        fan.edges.assign(1, {m.Org(h), -1, 0.0});
        fan.gaps.clear();
        int g = m.heNext[h];  // node -> Y, in the face of h
        double cum = 0;
        for (int guard = 0; guard < 256; ++guard) {
            cum += m.CornerAngle(g);
            fan.gaps.push_back({m.heNext[g], fan.edges.back().angle, cum});
            fan.edges.push_back({m.Dst(g), g, cum});
            if (IsFront(g)) return true;
            int t = m.heTwin[g];
            if (t < 0) return false;
            g = m.heNext[t];
        }
        return false;
    }

    // The next front edge of the loop after h, walking the unmeshed fan at h's destination
    // clockwise (-1 when the walk reaches the boundary); `angle` gets the corner angles swept.
    int NextFront(int h, double *angle = nullptr) const
    {
        double a = 0;
        int g = m.heNext[h];
        int found = -1;
        for (int guard = 0; guard < 256; ++guard) {
            if (angle) a += m.CornerAngle(g);
            if (IsFront(g)) { found = g; break; }
            if (m.heTwin[g] < 0) break;
            g = m.heNext[m.heTwin[g]];
        }
        if (angle) *angle = a;
        return found;
    }

    // The previous front edge, walking the fan at h's origin counter-clockwise.
    int PrevFront(int h, double *angle = nullptr) const
    {
        double a = 0;
        int g = h;
        int found = -1;
        for (int guard = 0; guard < 256; ++guard) {
            if (angle) a += m.CornerAngle(g);
            int e = m.hePrev[g];
            if (IsFront(e)) { found = e; break; }
            if (m.heTwin[e] < 0) break;
            g = m.heTwin[e];
        }
        if (angle) *angle = a;
        return found;
    }

    // Front angles at both ends (sum of unmeshed corner angles).
    double LeftAngle(int h) const
    {
        double a = 0;
        PrevFront(h, &a);
        return a;
    }
    double RightAngle(int h) const
    {
        double a = 0;
        NextFront(h, &a);
        return a;
    }

    int State(int h, double closedAngle) const
    {
        return (EndClosed(m.Org(h), LeftAngle(h), closedAngle) ? 1 : 0) | (EndClosed(m.Dst(h), RightAngle(h), closedAngle) ? 2 : 0);
    }

    // An end is closed below the angle. At a node with a plan (FrontNodePlan) whose unmeshed angle
    // is near the threshold, in [kPlanMinOpen, kPlanMaxClosed], the plan decides instead: closed
    // once its planned side edges are made. A wider band (100-160 degrees) made fewer irregular
    // nodes but poorer quads (mean scaled Jacobian -0.002 to -0.004 on the scans).
    bool EndClosed(int node, double angle, double closedAngle) const
    {
        if (angle < kPlanMinOpen || angle > kPlanMaxClosed) return angle < closedAngle;
        const int left = m.PlannedSidesLeft(node);
        return left < 0 ? angle < closedAngle : left == 0;
    }

    // Number of edges of the loop through h, or -1 when longer than `limit`.
    int LoopLength(int h, int limit) const
    {
        int g = h;
        for (int n = 1; n <= limit; ++n) {
            g = NextFront(g);
            if (g < 0) return -1;
            if (g == h) return n;
        }
        return -1;
    }

    void Loop(int h, std::vector<int> &loop) const
    {
        loop.clear();
        int g = h;
        do {
            loop.push_back(g);
            g = NextFront(g);
        } while (g >= 0 && g != h && loop.size() < 100000);
    }

private:
    static constexpr double kPlanMinOpen = 2 * M_PI / 3, kPlanMaxClosed = 7 * M_PI / 9;  // 120, 140 degrees
    MixedMesh &m;
};

// Priority of front edges: highest state (3, then one side closed, then 0), lowest level, then
// insertion order (deterministic).
struct FrontEntry {
    int rank;   // 2: both ends closed, 1: one end, 0: none
    int level;
    long order;
    int he;
    bool operator<(const FrontEntry &o) const
    {
        if (rank != o.rank) return rank < o.rank;
        if (level != o.level) return level > o.level;
        return order > o.order;
    }
};

class FrontQueue
{
public:
    void Push(int he, int state, int level)
    {
        int rank = state == 3 ? 2 : (state ? 1 : 0);
        q.push({rank, level, counter++, he});
    }
    bool Empty() const { return q.empty(); }
    FrontEntry Pop()
    {
        FrontEntry e = q.top();
        q.pop();
        return e;
    }
    static int Rank(int state) { return state == 3 ? 2 : (state ? 1 : 0); }

private:
    std::priority_queue<FrontEntry> q;
    long counter = 0;
};

}  // namespace qmorph
}  // namespace vcg_ext

#endif
