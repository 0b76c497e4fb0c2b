// The working mesh of Q-Morph: an index-based half-edge mesh whose faces are triangles or quads,
// with the local operations the advancing front needs (edge flip, edge split, merging the
// triangles enclosed by four edges into one quad) and intrinsic geometry (corner angles, fan
// walks, node normals, orientation tests in a node's tangent plane).
//
// Faces are counter-clockwise seen from outside. Elements are never reused once deleted, so an
// index kept in a queue either still names the same element or is dead (checked on use).
#ifndef VCG_EXT_QMORPH_MIXED_MESH_H
#define VCG_EXT_QMORPH_MIXED_MESH_H

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <functional>
#include <map>
#include <unordered_map>
#include <vector>

#include <vcg/space/point3.h>

#include <vcg_ext/common/edge_pairing.h>
#include <vcg_ext/common/polygon_geometry.h>
#include <vcg_ext/qmorph/surface_projector.h>

namespace vcg_ext {
namespace qmorph {

typedef vcg::Point3<double> P3;


// Node keys say which input vertex a node is, so that copies of one vertex (on both sides of a
// front) count as one node: input vertex g has key g; a point made on a front edge, which both
// patches of the edge hold, has SharedPointKey(k); a node made inside a patch has a key of its own.
inline int SharedPointKey(int k) { return INT_MIN / 2 + k; }
inline int OwnNodeKey(int node) { return -1 - node; }

class MixedMesh
{
public:
    // Flips: only between triangles this close to coplanar; new triangles keep this sine of their
    // smallest angle.
    static constexpr double kMaxFlipDihedralDeg = 25, kMinFlipSine = 1e-3;
    // A quad never encloses more triangles: bounds the work on a bad loop.
    static constexpr size_t kMaxEnclosed = 4096;

    // vertices
    std::vector<P3> pos;
    std::vector<int> vertHe;      // an outgoing half-edge (a boundary one when the vertex is on the boundary)
    std::vector<char> vertFixed;  // initial-front nodes: never moved, never removed
    std::vector<char> vertAlive;
    std::vector<int> vertKey;     // which input vertex a node is (copies of a vertex cut by the front
                                  // share it); new nodes get a key of their own
    std::unordered_map<int, std::vector<int>> copiesOfKey;  // keys held by several nodes
    std::vector<std::vector<int>> otherPatches;  // per initial-front node: the other patches holding it
                                                 // (empty when not told: every chord is then suspect)
    // half-edges
    std::vector<int> heVert, heNext, hePrev, heTwin, heFace;  // heFace < 0: dead
    std::vector<char> heInitial;  // on the initial front (patch boundary): never flipped, split or merged
    // faces
    std::vector<int> faceHe, faceSize;  // faceSize 0: dead
    std::vector<int> faceLevel;         // quads: the row they were made in
    const SurfaceProjector *input = nullptr;  // see SetInputSurface
    const std::vector<int> *home = nullptr;
    // Optional: the normal of the surface the mesh must agree with (the whole input) under a
    // point, or (0, 0, 0) where it cannot tell (then the patch's own surface decides); used by
    // every orientation judgement (see InputSurfaceNormalAt). The second argument: how far the
    // patch's surface is from the point, where the search starts (< 0: unknown; always so when
    // the patch is not the input, see patchIsInput).
    std::function<P3(const P3 &, double)> judge;
    // Optional, with the judge: whether a direction (a new triangle's normal) faces every input
    // triangle as close to a point as the judge's (a tie the judge breaks one way, an independent
    // check perhaps the other).
    std::function<bool(const P3 &, const P3 &)> facesEveryClosest;
    // The patch's own surface is the input (no re-meshing): swaps are rated by walks over it. Off
    // (a re-meshed patch), the judge rates them (see CanFlip).
    bool patchIsInput = false;

    // Per node: the interior edges planned at an initial-front node (FrontNodePlan); -1, or a node
    // beyond the vector (made later): none.
    std::vector<int> plannedSides;
    int PlannedSides(int v) const { return v < int(plannedSides.size()) ? plannedSides[v] : -1; }
    // The planned edges v still lacks (those that bound a quad already count), or -1 without a plan.
    int PlannedSidesLeft(int v) const
    {
        const int planned = PlannedSides(v);
        if (planned < 0) return -1;
        int made = 0;
        ForEachOutgoing(v, [&](int h) {
            const int t = heTwin[h];
            if (!heInitial[h] && (IsQuad(heFace[h]) || (t >= 0 && heFace[t] >= 0 && IsQuad(heFace[t])))) ++made;
        });
        return std::max(0, planned - made);
    }

    int VertexCount() const { return int(pos.size()); }
    int HalfEdgeCount() const { return int(heVert.size()); }
    int FaceCount() const { return int(faceHe.size()); }

    // Distinct input vertices (two copies of one vertex, split by the front, are the same node
    // once the patches are put back together: a face must not use both).
    // Declares which input vertex each node is (after Build); copies of one vertex share a key.
    void SetKeys(const std::vector<int> &keys)
    {
        std::unordered_map<int, std::vector<int>> all;
        for (size_t v = 0; v < keys.size(); ++v) {
            vertKey[v] = keys[v];
            all[keys[v]].push_back(int(v));
        }
        copiesOfKey.clear();
        for (auto &kv : all)
            if (kv.second.size() > 1) copiesOfKey.emplace(kv.first, kv.second);
    }

    // Calls f(h) for every half-edge between the nodes of a's key and the nodes of b's key.
    template <class F>
    void ForEachEdgeBetween(int a, int b, F f) const
    {
        auto nodes = [&](int v) {
            auto it = copiesOfKey.find(vertKey[v]);
            return it == copiesOfKey.end() ? std::vector<int>{v} : it->second;
        };
        const int ka = vertKey[a], kb = vertKey[b];
        for (int x : nodes(a))
            if (vertAlive[x]) ForEachOutgoing(x, [&](int h) { if (vertKey[Dst(h)] == kb) f(h); });
        for (int y : nodes(b))
            if (vertAlive[y]) ForEachOutgoing(y, [&](int h) { if (vertKey[Dst(h)] == ka) f(h); });
    }

    bool DistinctNodes(std::initializer_list<int> vs) const
    {
        for (auto a = vs.begin(); a != vs.end(); ++a)
            for (auto b = a + 1; b != vs.end(); ++b)
                if (vertKey[*a] == vertKey[*b]) return false;
        return true;
    }

    bool HeAlive(int h) const { return h >= 0 && heFace[h] >= 0; }
    bool FaceAlive(int f) const { return f >= 0 && faceSize[f] > 0; }
    bool IsTri(int f) const { return faceSize[f] == 3; }
    bool IsQuad(int f) const { return faceSize[f] == 4; }
    int Org(int h) const { return heVert[h]; }
    int Dst(int h) const { return heVert[heNext[h]]; }
    P3 Vec(int h) const { return pos[Dst(h)] - pos[Org(h)]; }
    double Length(int h) const { return Vec(h).Norm(); }

    // Builds from counter-clockwise triangles; every edge must have at most two faces. Half-edges
    // flagged in `cut` (index 3*t+k: edge k of triangle t) are not joined to their twin. Boundary
    // half-edges are the initial front: marked initial, their nodes fixed.
    void Build(const std::vector<P3> &points, const std::vector<std::array<int, 3>> &tris,
               const std::vector<char> &cut = std::vector<char>())
    {
        pos = points;
        vertHe.assign(pos.size(), -1);
        vertFixed.assign(pos.size(), 0);
        vertAlive.assign(pos.size(), 1);
        vertKey.resize(pos.size());
        for (size_t v = 0; v < pos.size(); ++v) vertKey[v] = int(v);
        heVert.clear(); heNext.clear(); hePrev.clear(); heTwin.clear(); heFace.clear(); heInitial.clear();
        faceHe.clear(); faceSize.clear(); faceLevel.clear();
        for (auto &t : tris) AddFace({t[0], t[1], t[2]}, 3);
        heTwin = EdgePairing::Twins(tris, cut);  // half-edge 3t+k is edge k of triangle t, as AddFace made them
        for (int h = 0; h < HalfEdgeCount(); ++h)
            if (heTwin[h] < 0) { heInitial[h] = 1; vertFixed[Org(h)] = 1; vertFixed[Dst(h)] = 1; }
        for (int h = 0; h < HalfEdgeCount(); ++h) SetVertexHe(Org(h), h);
    }

    // ---- navigation -------------------------------------------------------------------------
    // Around the origin of h: the next outgoing half-edge counter-clockwise / clockwise (-1 at the boundary).
    int RotateCCW(int h) const { return heTwin[hePrev[h]]; }
    int RotateCW(int h) const { return heTwin[h] < 0 ? -1 : heNext[heTwin[h]]; }

    template <class F>
    void ForEachOutgoing(int v, F f) const
    {
        int start = vertHe[v];
        if (start < 0) return;
        int h = start;
        do {  // vertHe is the clockwise-most half-edge on the boundary: walk counter-clockwise
            f(h);
            h = RotateCCW(h);
        } while (h >= 0 && h != start);
    }

    // The half-edge a->b, or -1 (also when only b->a exists: a boundary edge seen from the other side).
    int FindHalfEdge(int a, int b) const
    {
        int found = -1;
        ForEachOutgoing(a, [&](int h) { if (Dst(h) == b) found = h; });
        return found;
    }
    // Is a-b an edge, counting copies of the same input vertex as one node?
    bool EdgeExists(int a, int b) const
    {
        bool found = false;
        ForEachEdgeBetween(a, b, [&](int) { found = true; });
        return found;
    }

    // Would an edge a-b be a new chord between two initial-front nodes that another patch also
    // holds? That patch could make the same chord (two patches, one edge, four faces), so such
    // chords are never created; existing edges are fine.
    bool NewChordBetweenFrontNodes(int a, int b) const
    {
        if (!vertFixed[a] || !vertFixed[b] || EdgeExists(a, b)) return false;
        if (a >= int(otherPatches.size()) || b >= int(otherPatches.size())) return true;
        const std::vector<int> &pa = otherPatches[a], &pb = otherPatches[b];  // sorted
        for (size_t i = 0, j = 0; i < pa.size() && j < pb.size();) {
            if (pa[i] == pb[j]) return true;  // a patch holding both could make the same chord
            if (pa[i] < pb[j]) ++i; else ++j;
        }
        return false;
    }

    // Are a and b opposite corners of a quad? (an edge a-b would then duplicate that quad's
    // diagonal once quads are written as triangle pairs)
    bool OppositeInQuad(int a, int b) const
    {
        auto it = copiesOfKey.find(vertKey[a]);
        std::vector<int> nodes = it == copiesOfKey.end() ? std::vector<int>{a} : it->second;
        bool found = false;
        for (int x : nodes)
            if (vertAlive[x])
                ForEachOutgoing(x, [&](int h) {
                    if (IsQuad(heFace[h]) && vertKey[Dst(heNext[h])] == vertKey[b]) found = true;
                });
        return found;
    }

    // Is there an edge a-b not interior to the given faces (which are about to be replaced)?
    bool EdgeOutside(int a, int b, const std::vector<int> &faces) const
    {
        auto inside = [&](int f) { return std::find(faces.begin(), faces.end(), f) != faces.end(); };
        bool outside = false;
        ForEachEdgeBetween(a, b, [&](int h) {
            int t = heTwin[h];
            if (!(inside(heFace[h]) && t >= 0 && inside(heFace[t]))) outside = true;
        });
        return outside;
    }

    // A quad (a b c d) replacing `faces` can be written as two triangles when one of its diagonals
    // is not already an edge elsewhere.
    bool QuadHasFreeDiagonal(int a, int b, int c, int d, const std::vector<int> &faces) const
    {
        return !EdgeOutside(a, c, faces) || !EdgeOutside(b, d, faces);
    }

    int Valence(int v) const
    {
        int n = 0, last = -1;
        ForEachOutgoing(v, [&](int h) { ++n; last = h; });
        if (last >= 0 && heTwin[hePrev[last]] < 0) ++n;  // boundary: one more edge than faces
        return n;
    }

    // vertHe is the clockwise-most outgoing half-edge: on the boundary it has no twin.
    bool OnBoundary(int v) const { return vertHe[v] >= 0 && heTwin[vertHe[v]] < 0; }

    // Corner angle of the face of h at the origin of h.
    double CornerAngle(int h) const { return AngleBetween(pos[Dst(h)] - pos[Org(h)], pos[Org(hePrev[h])] - pos[Org(h)]); }

    // Vector area of a face: its normal times its area (right for non-planar quads too).
    P3 FaceNormal(int f) const
    {
        P3 p[4];
        int h = faceHe[f];
        for (int k = 0; k < faceSize[f]; ++k, h = heNext[h]) p[k] = pos[Org(h)];
        return VectorArea(p, faceSize[f]);
    }
    // The input surface the mesh lies on, and per node the triangle of it the node lies on (its
    // home): the reference of every orientation test, so that no operation can turn a face upside
    // down on the surface (a face's own normal cannot tell). Without it, the mesh's own normals.
    void SetInputSurface(const SurfaceProjector *surface, const std::vector<int> *homeTriangle)
    {
        input = surface;
        home = homeTriangle;
    }
    int HomeOf(int v) const { return input && v >= 0 && v < int(home->size()) ? (*home)[v] : -1; }
    // Unit normal of the input surface at node v.
    P3 InputNormal(int v) const
    {
        const P3 n = input ? input->Normal(HomeOf(v)) : P3(0, 0, 0);
        return n.SquaredNorm() > 0 ? n : VertexNormal(v);
    }
    // Unit normal of the input surface at `point` ((0, 0, 0) without one), the nearest of the walks
    // from `homes`; `exact`: the judge's when there is one (a walk over the patch can end on the far
    // side of a tight bend, and a re-meshed patch is not the input).
    P3 InputSurfaceNormalAt(const P3 &point, const int *homes, int count, bool exact = false) const
    {
        // off the input the judge needs no distance: the walk only where it cannot tell
        const bool judgeFirst = exact && judge && !patchIsInput;
        P3 judged(0, 0, 0);
        if (judgeFirst && (judged = judge(point, -1)).SquaredNorm() > 0) return judged;
        double distance = -1;
        const P3 n = input ? input->NormalAt(point, homes, count, &distance) : P3(0, 0, 0);
        if (!exact || !judge) return n;
        if (!judgeFirst) judged = judge(point, distance);
        return judged.SquaredNorm() > 0 ? judged : n;
    }
    // Unit normal of the input surface under face f, at its centroid (as an independent judge
    // measures it: a face is flipped when it points away from it); `exact` walks from every corner.
    P3 InputFaceNormal(int f, bool exact = false) const
    {
        P3 c(0, 0, 0);
        int homes[4];
        int h = faceHe[f];
        for (int k = 0; k < faceSize[f]; ++k, h = heNext[h]) {
            c += pos[Org(h)];
            homes[k] = HomeOf(Org(h));
        }
        c /= double(faceSize[f]);
        const P3 n = InputSurfaceNormalAt(c, homes, exact ? faceSize[f] : 1, exact);
        return n.SquaredNorm() > 0 ? n : UnitFaceNormal(f);
    }

    // Unit normal of a node from its faces (all in one patch: never averaged across a crease).
    P3 VertexNormal(int v) const
    {
        P3 n(0, 0, 0);
        ForEachOutgoing(v, [&](int h) { n += FaceNormal(heFace[h]); });
        double l = n.Norm();
        return l > 0 ? n / l : P3(0, 0, 1);
    }

    // Shape of triangle f against unit normal n: 1 equilateral, 0 degenerate, negative folded.
    double TriangleQuality(int f, const P3 &n) const
    {
        const int g = faceHe[f];
        const P3 A = pos[Org(g)], B = pos[Dst(g)], C = pos[Org(hePrev[g])];
        const double l2 = (B - A).SquaredNorm() + (C - B).SquaredNorm() + (A - C).SquaredNorm();
        return l2 > 0 ? 2 * std::sqrt(3.0) * (((B - A) ^ (C - A)) * n) / l2 : -1;
    }

    // Unit normal of face f (zero for a degenerate face).
    P3 UnitFaceNormal(int f) const
    {
        const P3 fn = FaceNormal(f);
        const double l = fn.Norm();
        return l > 0 ? fn / l : P3(0, 0, 0);
    }

    // The faces around the given nodes, each once, but the `dying` ones (about to vanish).
    std::vector<int> FacesAround(std::initializer_list<int> nodes, std::initializer_list<int> dying = {}) const
    {
        std::vector<int> faces;
        for (int v : nodes)
            ForEachOutgoing(v, [&](int g) {
                const int f = heFace[g];
                if (std::find(dying.begin(), dying.end(), f) == dying.end() && std::find(faces.begin(), faces.end(), f) == faces.end())
                    faces.push_back(f);
            });
        return faces;
    }

    // ---- construction -------------------------------------------------------------------------
    int AddVertex(const P3 &p)
    {
        pos.push_back(p);
        vertHe.push_back(-1);
        vertFixed.push_back(0);
        vertAlive.push_back(1);
        vertKey.push_back(OwnNodeKey(VertexCount() - 1));
        return VertexCount() - 1;
    }

    // Adds a face over the given vertices with fresh half-edges (twins left unset).
    int AddFace(const std::array<int, 4> &v, int n)
    {
        int f = FaceCount();
        int h0 = HalfEdgeCount();
        for (int k = 0; k < n; ++k) {
            heVert.push_back(v[k]);
            heNext.push_back(h0 + (k + 1) % n);
            hePrev.push_back(h0 + (k + n - 1) % n);
            heTwin.push_back(-1);
            heFace.push_back(f);
            heInitial.push_back(0);
        }
        faceHe.push_back(h0);
        faceSize.push_back(n);
        faceLevel.push_back(0);
        return f;
    }

    void Link(int a, int b)
    {
        if (a >= 0) heTwin[a] = b;
        if (b >= 0) heTwin[b] = a;
    }

    // Keeps vertHe[v] on the clockwise-most outgoing half-edge when v is on the boundary.
    void SetVertexHe(int v, int h)
    {
        vertHe[v] = h;
        int g = h, guard = 0;
        while (heTwin[g] >= 0 && guard++ < 100000) {
            g = heNext[heTwin[g]];
            if (g == h) return;  // interior vertex
        }
        vertHe[v] = g;
    }

    // ---- edge flip ----------------------------------------------------------------------------
    // Flip of the edge of h between two triangles (a b c) and (b a d) into (c a d) and (d b c).
    // The convexity test is against the input surface's normal. Refuses constrained edges.
    bool CanFlip(int h) const
    {
        int t = heTwin[h];
        if (t < 0 || heInitial[h] || !IsTri(heFace[h]) || !IsTri(heFace[t])) return false;
        int a = Org(h), b = Dst(h), c = Org(hePrev[h]), d = Org(hePrev[t]);
        if (c == d || EdgeExists(c, d) || OppositeInQuad(c, d) || NewChordBetweenFrontNodes(c, d)) return false;
        P3 n1 = FaceNormal(heFace[h]), n2 = FaceNormal(heFace[t]);
        P3 n = InputFaceNormal(heFace[h]) + InputFaceNormal(heFace[t]);
        if (!(n.Norm() > 0)) return false;
        // across a ridge a flip would change the surface (cut or fill the ridge): refused
        if ((n1 * n2) < std::cos(kMaxFlipDihedralDeg * M_PI / 180) * n1.Norm() * n2.Norm()) return false;
        // the new triangles (c a d) and (d b c) must be positive, and not slivers that would be
        // degenerate once written in float (sine of the smallest angle above kMinFlipSine)
        n.Normalize();
        auto positive = [&](int x, int y, int z) {
            P3 u = pos[y] - pos[x], v = pos[z] - pos[x], w = pos[z] - pos[y];
            double l2 = std::max({u.SquaredNorm(), v.SquaredNorm(), w.SquaredNorm()});
            if (!((u ^ v) * n > kMinFlipSine * l2)) return false;  // before the searches below
            // the surface under the new triangle: on the input itself, walked from a corner's home;
            // under a re-meshed patch the input as the judge has it (the patch's own surface can lean
            // far from the input: a sliver between nearly collinear front nodes passed against it and
            // came out upside down on the input), and facing every input triangle as close as the
            // closest one (not standing on edge over an input edge)
            const bool judged = !patchIsInput;
            const int from[3] = {HomeOf(x), HomeOf(y), HomeOf(z)};
            const P3 centroid = (pos[x] + pos[y] + pos[z]) / 3.0;
            P3 under = InputSurfaceNormalAt(centroid, from, judged ? 3 : 1, judged);
            if (!(under.SquaredNorm() > 0)) under = n;
            return (u ^ v) * under > kMinFlipSine * l2 && (!judged || !facesEveryClosest || facesEveryClosest(centroid, u ^ v));
        };
        return positive(c, a, d) && positive(d, b, c);
    }

    void Flip(int h)
    {
        int t = heTwin[h];
        int f = heFace[h], g = heFace[t];
        int hn = heNext[h], hp = hePrev[h], tn = heNext[t], tp = hePrev[t];
        int a = Org(h), b = Dst(h), c = Org(hp), d = Org(tp);
        // face f becomes (c a d): hp (c->a), tn (a->d), h (d->c)
        // face g becomes (d b c): tp (d->b), hn (b->c), t (c->d)
        heVert[h] = d;
        heVert[t] = c;
        SetFace(f, {hp, tn, h});
        SetFace(g, {tp, hn, t});
        if (vertHe[a] == h) vertHe[a] = tn;
        if (vertHe[b] == t) vertHe[b] = hn;
        SetVertexHe(a, vertHe[a]);
        SetVertexHe(b, vertHe[b]);
    }

    // ---- edge split ---------------------------------------------------------------------------
    // Splits the edge of h (triangles on both sides, or a boundary on one side) at p; returns the
    // new vertex. The half-edge h keeps its origin and now ends at the new vertex.
    int SplitEdge(int h, const P3 &p)
    {
        int t = heTwin[h];
        int m = AddVertex(p);
        int a = Org(h), b = Dst(h);
        // side of h: triangle (a b c) -> (a m c) + (m b c)
        int hNew = SplitSide(h, m);           // hNew: m->b
        int tNew = t >= 0 ? SplitSide(t, m) : -1;  // tNew: m->a
        if (t >= 0) {
            Link(h, tNew);  // a->m with m->a
            Link(t, hNew);  // b->m with m->b
        }
        if (t < 0) heInitial[hNew] = heInitial[h];
        vertHe[m] = hNew;
        SetVertexHe(m, hNew);
        SetVertexHe(a, vertHe[a]);
        SetVertexHe(b, vertHe[b]);
        return m;
    }

    // ---- merging into a quad ------------------------------------------------------------------
    // The four half-edges a->b, b->c, c->d, d->a bound (on their left) a disk of triangles.
    // Collects it; false when they do not (another front or a quad is reached, or the count of
    // faces does not fit a disk with four boundary nodes).
    bool EnclosedTriangles(const std::array<int, 4> &loop, std::vector<int> &faces, std::vector<int> &inner) const
    {
        faces.clear();
        inner.clear();
        std::vector<int> stack{heFace[loop[0]]};
        auto isLoop = [&](int h) { return h == loop[0] || h == loop[1] || h == loop[2] || h == loop[3]; };
        for (int h : loop)
            if (!IsTri(heFace[h])) return false;
        faces.push_back(stack[0]);
        const size_t cap = kMaxEnclosed;
        while (!stack.empty()) {
            int f = stack.back();
            stack.pop_back();
            int h = faceHe[f];
            for (int k = 0; k < 3; ++k, h = heNext[h]) {
                if (isLoop(h)) continue;
                int t = heTwin[h];
                if (t < 0 || heInitial[h] || !IsTri(heFace[t])) return false;  // leaked out of the loop
                int g = heFace[t];
                if (std::find(faces.begin(), faces.end(), g) == faces.end()) {
                    if (faces.size() >= cap) return false;
                    faces.push_back(g);
                    stack.push_back(g);
                }
            }
        }
        const int corners[4] = {Org(loop[0]), Org(loop[1]), Org(loop[2]), Org(loop[3])};
        for (int f : faces) {
            int h = faceHe[f];
            for (int k = 0; k < 3; ++k, h = heNext[h]) {
                int v = Org(h);
                if (std::find(corners, corners + 4, v) == corners + 4 && std::find(inner.begin(), inner.end(), v) == inner.end())
                    inner.push_back(v);
            }
        }
        for (int v : inner)
            if (vertFixed[v]) return false;
        return int(faces.size()) == 2 * int(inner.size()) + 2;  // Euler: disk with 4 boundary nodes
    }

    // Replaces the faces of a disk-shaped region bounded (on their left) by the half-edges
    // `loop`, in order, by new polygons given as lists of positions (counter-clockwise): position
    // i < loop.size() is the origin of loop[i], position loop.size() + k is the node added[k] (made
    // by AddVertex, inside the region). Loop half-edges are reused for the polygon sides they
    // cover; other sides get new half-edges. Inner vertices are removed. Returns the first new face.
    int ReplaceRegion(const std::vector<int> &loop, const std::vector<int> &faces, const std::vector<int> &inner,
                      const std::vector<std::vector<int>> &polygons, int level, const std::vector<int> &added = {})
    {
        for (int f : faces) {
            int h = faceHe[f];
            for (int k = 0, n = faceSize[f]; k < n; ++k) {
                int nx = heNext[h];
                if (std::find(loop.begin(), loop.end(), h) == loop.end()) heFace[h] = -1;
                h = nx;
            }
            faceSize[f] = 0;
        }
        for (int v : inner) { vertAlive[v] = 0; vertHe[v] = -1; }
        const int n = int(loop.size());
        auto node = [&](int i) { return i < n ? Org(loop[i]) : added[i - n]; };
        std::map<std::pair<int, int>, int> sides;  // new half-edges by (from position, to position)
        std::vector<int> addedHe(added.size(), -1);
        int first = FaceCount();
        for (const auto &poly : polygons) {
            int f = FaceCount();
            faceHe.push_back(-1);
            faceSize.push_back(int(poly.size()));
            faceLevel.push_back(level);
            std::vector<int> hs;
            for (size_t k = 0; k < poly.size(); ++k) {
                int i = poly[k], j = poly[(k + 1) % poly.size()];
                if (i < n && j == (i + 1) % n) { hs.push_back(loop[i]); continue; }
                int h = HalfEdgeCount();
                heVert.push_back(node(i));
                heNext.push_back(-1); hePrev.push_back(-1); heTwin.push_back(-1); heFace.push_back(-1);
                heInitial.push_back(0);
                hs.push_back(h);
                const auto twin = sides.find({j, i});
                if (twin != sides.end()) Link(twin->second, h);
                sides[{i, j}] = h;
                if (i >= n) addedHe[i - n] = h;
            }
            for (size_t k = 0; k < hs.size(); ++k) {
                heNext[hs[k]] = hs[(k + 1) % hs.size()];
                hePrev[hs[k]] = hs[(k + hs.size() - 1) % hs.size()];
                heFace[hs[k]] = f;
            }
            faceHe[f] = hs[0];
        }
        for (int h : loop) SetVertexHe(Org(h), h);
        for (size_t k = 0; k < added.size(); ++k) SetVertexHe(added[k], addedHe[k]);
        return first;
    }

    // Replaces the enclosed triangles by the quad (a b c d); inner nodes are removed.
    int MakeQuad(const std::array<int, 4> &loop, const std::vector<int> &faces, const std::vector<int> &inner, int level)
    {
        return ReplaceRegion({loop[0], loop[1], loop[2], loop[3]}, faces, inner, {{0, 1, 2, 3}}, level);
    }

    // Replaces the two triangles sharing the edge of h by one quad; returns it.
    int MergeTriangles(int h, int level)
    {
        int t = heTwin[h];
        return ReplaceRegion({heNext[h], hePrev[h], heNext[t], hePrev[t]}, {heFace[h], heFace[t]}, {}, {{0, 1, 2, 3}}, level);
    }

    // Collapses the edge of h = x->y between two triangles (x y p) and (y x q): both triangles
    // vanish, y joins x (moved to `at`), the two other sides of each triangle become one edge.
    // False (nothing changed) when y is on the boundary, a side is a boundary edge, or the link
    // condition fails (x and y share a neighbour besides p and q: not a 2-manifold afterwards).
    // With `allowBoundarySide`, one side of a triangle may be a boundary (initial front) edge at x:
    // the other side then takes its place on the boundary (the seam onto the initial front).
    bool CollapseEdge(int h, const P3 &at, bool allowBoundarySide = false)
    {
        const int t = heTwin[h];
        if (t < 0 || !IsTri(heFace[h]) || !IsTri(heFace[t])) return false;
        const int x = Org(h), y = Dst(h), p = Org(hePrev[h]), q = Org(hePrev[t]);
        const int h1 = heNext[h], h2 = hePrev[h], t1 = heNext[t], t2 = hePrev[t];
        if (p == q || OnBoundary(y)) return false;  // y interior: h1 and t2 (at y) have twins
        const int open = (heTwin[h2] < 0) + (heTwin[t1] < 0);
        if (open > (allowBoundarySide ? 1 : 0)) return false;
        std::vector<int> outX, outY, nx;
        ForEachOutgoing(x, [&](int g) {
            outX.push_back(g);
            nx.push_back(vertKey[Dst(g)]);
            if (heTwin[hePrev[g]] < 0) nx.push_back(vertKey[Org(hePrev[g])]);
        });
        ForEachOutgoing(y, [&](int g) { outY.push_back(g); });
        int common = 0;
        for (int g : outY) {
            int k = vertKey[Dst(g)];
            if (k != vertKey[x] && std::find(nx.begin(), nx.end(), k) != nx.end()) ++common;
        }
        if (common != 2) return false;
        const int f1 = heFace[h], f2 = heFace[t];
        // p->y (becomes p->x); q->x, or q's next edge when x-q was on the boundary
        const int pOut = heTwin[h1], qOut = heTwin[t1] >= 0 ? heTwin[t1] : heNext[heTwin[t2]];
        for (int g : outY) heVert[g] = x;
        Link(heTwin[h1], heTwin[h2]);
        Link(heTwin[t1], heTwin[t2]);
        if (heTwin[h2] < 0) heInitial[heTwin[h1]] = 1;  // now on the boundary in place of h2
        if (heTwin[t1] < 0) heInitial[heTwin[t2]] = 1;
        for (int g : {h, h1, h2, t, t1, t2}) heFace[g] = -1;
        faceSize[f1] = faceSize[f2] = 0;
        vertAlive[y] = 0;
        vertHe[y] = -1;
        pos[x] = at;
        vertHe[x] = -1;
        for (int g : outX)
            if (heFace[g] >= 0) { SetVertexHe(x, g); break; }
        if (vertHe[x] < 0)
            for (int g : outY)
                if (heFace[g] >= 0) { SetVertexHe(x, g); break; }
        SetVertexHe(p, pOut);
        SetVertexHe(q, qOut);
        return true;
    }

    // Quad open (the inverse of a diagonal collapse): interior node v, all of whose faces are
    // quads, is split in two along its edges to a = Dst(out[i]) and b = Dst(out[j]) (out: v's
    // outgoing half-edges counter-clockwise, i < j). v keeps the faces from out[i] to out[j-1] and
    // moves to p1; a new node at p2 takes the others; the new quad (a v b v') fills the gap.
    // Returns the new node.
    int OpenQuad(int v, int i, int j, const P3 &p1, const P3 &p2, int level)
    {
        std::vector<int> out;
        ForEachOutgoing(v, [&](int h) { out.push_back(h); });
        const int n = int(out.size());
        const int gi = out[i], gj = out[j], ti = heTwin[gi], tj = heTwin[gj];
        const int a = Dst(gi), b = Dst(gj);
        const int w = AddVertex(p2);
        pos[v] = p1;
        for (int k = j; k != i; k = (k + 1) % n) heVert[out[k]] = w;  // faces F_j .. F_{i-1} go to w
        const int q = AddFace({a, v, b, w}, 4);
        faceLevel[q] = level;
        const int q0 = faceHe[q], q1 = heNext[q0], q2 = heNext[q1], q3 = heNext[q2];  // a->v, v->b, b->w, w->a
        Link(gi, q0);
        Link(ti, q3);
        Link(tj, q1);
        Link(gj, q2);
        SetVertexHe(v, gi);
        SetVertexHe(w, gj);
        SetVertexHe(a, vertHe[a]);
        SetVertexHe(b, vertHe[b]);
        return w;
    }

    // Removes a valence-2 interior node shared by two quads (a "doublet"): the quads become one.
    bool DissolveDoublet(int v)
    {
        if (vertFixed[v] || !vertAlive[v] || OnBoundary(v)) return false;
        std::vector<int> out;
        ForEachOutgoing(v, [&](int h) { out.push_back(h); });
        if (out.size() != 2) return false;
        int f = heFace[out[0]], g = heFace[out[1]];
        if (!IsQuad(f) || !IsQuad(g) || f == g) return false;
        // quad f: v->x ... ->v ; its two edges at v are out[0] and prev(out[0])
        int h1 = out[0], h2 = out[1];
        int p1 = hePrev[h1], p2 = hePrev[h2];  // p1: y->v in f (twin of h2), p2: x->v in g (twin of h1)
        if (heTwin[p1] != h2 || heTwin[p2] != h1) return false;
        // the hexagon minus v: f contributes next(h1), next(next(h1)); g contributes next(h2), next(next(h2))
        std::vector<int> loop{heNext[h1], heNext[heNext[h1]], heNext[h2], heNext[heNext[h2]]};
        int xs[4] = {Org(loop[0]), Org(loop[1]), Org(loop[2]), Org(loop[3])};
        for (int i = 0; i < 4; ++i)
            for (int j = i + 1; j < 4; ++j)
                if (xs[i] == xs[j]) return false;
        ReplaceRegion(loop, {f, g}, {v}, {{0, 1, 2, 3}}, std::max(faceLevel[f], faceLevel[g]));
        return true;
    }

private:
    void SetFace(int f, std::initializer_list<int> hs)
    {
        std::vector<int> v(hs);
        for (size_t k = 0; k < v.size(); ++k) {
            heNext[v[k]] = v[(k + 1) % v.size()];
            hePrev[v[k]] = v[(k + v.size() - 1) % v.size()];
            heFace[v[k]] = f;
        }
        faceHe[f] = v[0];
        faceSize[f] = int(v.size());
    }

    // In the triangle of h = (a->b), (a b c) becomes (a m c) + (m b c); returns the new m->b.
    int SplitSide(int h, int m)
    {
        int f = heFace[h];
        int hn = heNext[h], hp = hePrev[h];  // b->c, c->a
        int c = Org(hp);
        int g = FaceCount();
        faceHe.push_back(-1);
        faceSize.push_back(3);
        faceLevel.push_back(0);
        int h0 = HalfEdgeCount();
        // new half-edges: m->b (h0), c->m (h0+1) in g; m->c (h0+2) in f
        for (int k = 0; k < 3; ++k) {
            heVert.push_back(k == 1 ? c : m);
            heNext.push_back(-1);
            hePrev.push_back(-1);
            heTwin.push_back(-1);
            heFace.push_back(-1);
            heInitial.push_back(0);
        }
        int mb = h0, cm = h0 + 1, mc = h0 + 2;
        // f: a->m (h, its destination becomes m through next), m->c, c->a
        SetFace(f, {h, mc, hp});
        // g: m->b, b->c, c->m
        SetFace(g, {mb, hn, cm});
        Link(mc, cm);
        vertHe[c] = vertHe[c] < 0 ? hp : vertHe[c];
        SetVertexHe(c, vertHe[c]);
        return mb;
    }
};

}  // namespace qmorph
}  // namespace vcg_ext

#endif
