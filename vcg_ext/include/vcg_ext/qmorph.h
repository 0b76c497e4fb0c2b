// Q-Morph quad conversion of a vcg triangle mesh from its selected face-edges (and boundary).
//
// The front (selected face-edges + boundary edges) cuts the surface into patches; every patch is
// cut out as its own mesh (a node where the front passes is copied once per fan sector, so slits,
// patches touching themselves and annuli need no special case), meshed by PatchMesher from its
// boundary loops, and written back. Initial front edges are never changed, so patches are
// independent and the front stays a set of mesh edges; after the run those edges are again the
// only selected face-edges. Output in MeshLab's polygonal form: a quad is two triangles sharing a
// faux edge. Face quality (region id) is kept per patch (its area-majority value).
#ifndef VCG_EXT_QMORPH_H
#define VCG_EXT_QMORPH_H

#include <algorithm>
#include <chrono>
#include <climits>
#include <iterator>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>
#include <string>
#include <unordered_set>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/update/topology.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/flag.h>

#include <vcg_ext/mesh_checks.h>
#include <vcg_ext/qmorph/patch_mesher.h>
#include <vcg_ext/qmorph/remesh.h>
#include <vcg_ext/quad_quality.h>

namespace vcg_ext {

template <class MeshType>
class QMorph
{
public:
    typedef typename MeshType::FaceType FaceType;
    typedef typename MeshType::VertexType VertexType;
    typedef typename MeshType::CoordType CoordType;
    typedef qmorph::P3 P3;

    struct Params {
        bool preserveInitialFront = true;  // the paper: no seam onto initial front edges, a triangle is
                                           // left instead; off: the seam joins the other node to the
                                           // front node (initial front edges are never changed either way)
        bool transitions = true;           // Owen's transition seam and transition split
        bool cleanup = true;               // valence turns and diagonal collapses after the front
        bool rescueBadQuads = true;        // quads below 0.3 scaled Jacobian: their nodes re-placed
        bool smoothing = true;             // tangent-plane smoothing (local, and final sweeps)
        int smoothingIterations = 5;       // final smoothing sweeps, 0..100
        double closedAngleDeg = 135;       // front angle closing an edge end (Owen: 3pi/4)
        double creaseAngleDeg = 60;        // edges this sharp (angle between face normals) are front
                                           // too, so no quad folds over a crease; >= 180: off
        double targetEdgeLength = 0;       // > 0: isotropic re-meshing of each patch first (absolute units)
        int remeshIterations = 5;          // split/collapse/flip/relax rounds of that re-meshing

        std::string Validate() const
        {
            if (smoothingIterations < 0 || smoothingIterations > 100) return "smoothing iterations must be in 0..100";
            if (!(creaseAngleDeg > 0 && creaseAngleDeg <= 180)) return "the crease angle must be in (0, 180] degrees";
            if (!(closedAngleDeg > 30 && closedAngleDeg < 180)) return "the closed-end angle must be in (30, 180) degrees";
            if (!(targetEdgeLength >= 0 && std::isfinite(targetEdgeLength))) return "the target edge length must be a finite number >= 0 (0: no re-meshing)";
            if (remeshIterations < 1 || remeshIterations > 50) return "re-meshing iterations must be in 1..50";
            return "";
        }
    };

    struct Result {
        std::string error;
        int initialFrontEdges = 0, patches = 0, patchesWithoutFront = 0;
        int creaseEdges = 0;  // sharp edges that were not selected but cut the patches too
        int frontEdgesSubdivided = 0;  // front edges cut into pieces of the target length (re-meshing on)
        qmorph::PatchRemesher::Stats remesh;
        int quads = 0, triangles = 0;
        qmorph::PatchStats ops;
        QuadQualityReport quality;
        double seconds = 0;
    };

    // Unchanged mesh and a message when the input cannot be converted.
    static std::string CheckInput(const MeshType &m)
    {
        MeshCheckReport r = MeshChecks<MeshType>::Inspect(m);
        std::string why = r.FirstProblem(false);
        if (!why.empty()) return why;
        if (!r.IsTwoManifold()) return r.FirstProblem(true);
        if (!r.IsOriented()) return "the mesh is not consistently oriented (" + std::to_string(r.inconsistentEdges) + " edges)";
        if (r.IsClosed() && CountSelectedEdges(m) == 0)
            return "the mesh is closed and has no selected edges: there is no initial front. Run 'Split Triangles "
                   "along Front' (or 'Select Crease Edges') first";
        return "";
    }

    // Bounded memory: a target edge length far below the mesh's scale would make a huge mesh.
    static std::string CheckRemeshSize(const MeshType &m, const Params &params)
    {
        if (params.targetEdgeLength <= 0) return "";
        double area = 0;
        for (const FaceType &f : m.face)
            if (!f.IsD()) area += vcg::DoubleArea(f) / 2;
        const double L = params.targetEdgeLength;
        const double estimate = area / (std::sqrt(3.0) / 4 * L * L);
        const double cap = 2e7;
        if (estimate > cap)
            return "the target edge length " + std::to_string(L) + " is too small for this mesh: re-meshing would make about " +
                   std::to_string(long(estimate)) + " triangles (at most " + std::to_string(long(cap)) + ")";
        return "";
    }

    static int CountSelectedEdges(const MeshType &m)
    {
        int n = 0;
        for (const FaceType &f : m.face)
            if (!f.IsD())
                for (int k = 0; k < 3; ++k) n += f.IsFaceEdgeS(k) ? 1 : 0;
        return n;  // face-edges (an interior edge selected on both sides counts twice)
    }

    static Result Apply(MeshType &m, const Params &params, vcg::CallBackPos *cb = nullptr)
    {
        auto t0 = std::chrono::steady_clock::now();
        Result res;
        res.error = params.Validate();
        if (res.error.empty()) res.error = CheckInput(m);
        if (res.error.empty()) res.error = CheckRemeshSize(m, params);
        if (!res.error.empty()) return res;

        vcg::tri::RequireFFAdjacency(m);  // to read the quads back for the quality report
        QMorph q(m, params, cb);
        q.Run(res);
        res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        return res;
    }

private:
    MeshType &m;
    const Params &par;
    vcg::CallBackPos *cb;

    // live faces and their vertex indices
    std::vector<int> faceIdx;                 // live face -> index in m.face
    std::vector<std::array<int, 3>> tri;      // per live face
    std::vector<char> cut;                    // per face-edge 3*f+k: on the front
    std::vector<int> twinCorner;              // per face-edge: matching face-edge of the neighbour, or -1
    std::vector<int> patchOf, sectorOf;       // per live face / per corner (root)
    std::unordered_set<uint64_t> selectedPairs;  // selected input edges (vertex pairs): selected again at the end

    QMorph(MeshType &mesh, const Params &p, vcg::CallBackPos *callback) : m(mesh), par(p), cb(callback) {}

    int creaseCount = 0;

    // Sharp edges inside a patch (VSA regions may hold creases up to twice the threshold angle)
    // are cut like front edges: quads then follow them instead of folding over them.
    bool IsCrease(int f, int g)
    {
        if (par.creaseAngleDeg >= 180) return false;
        auto normal = [&](int t) {
            P3 a = P3::Construct(m.vert[tri[t][0]].cP()), b = P3::Construct(m.vert[tri[t][1]].cP()),
               c = P3::Construct(m.vert[tri[t][2]].cP());
            return ((b - a) ^ (c - a)).Normalize();
        };
        bool sharp = normal(f) * normal(g) < std::cos(par.creaseAngleDeg * M_PI / 180);
        creaseCount += sharp;
        return sharp;
    }

    static uint64_t Key(int a, int b)
    {
        return (uint64_t(uint32_t(std::min(a, b))) << 32) | uint32_t(std::max(a, b));
    }
    static int Find(std::vector<int> &s, int x)
    {
        while (s[x] != x) { s[x] = s[s[x]]; x = s[x]; }
        return x;
    }
    static void Unite(std::vector<int> &s, int a, int b)
    {
        a = Find(s, a); b = Find(s, b);
        if (a != b) s[std::max(a, b)] = std::min(a, b);
    }

    void Progress(int percent, const char *msg) const
    {
        if (cb) cb(std::max(0, std::min(99, percent)), msg);
    }

    // Front edges, patches (faces joined across non-front edges) and node sectors (corners joined
    // across non-front edges around a node).
    void Partition(Result &res)
    {
        for (size_t i = 0; i < m.face.size(); ++i)
            if (!m.face[i].IsD()) {
                faceIdx.push_back(int(i));
                const FaceType &f = m.face[i];
                tri.push_back({int(vcg::tri::Index(m, f.cV(0))), int(vcg::tri::Index(m, f.cV(1))), int(vcg::tri::Index(m, f.cV(2)))});
            }
        const int F = int(tri.size());
        struct E { uint64_t key; int he; };
        std::vector<E> edges;
        edges.reserve(3 * F);
        for (int f = 0; f < F; ++f)
            for (int k = 0; k < 3; ++k) edges.push_back({Key(tri[f][k], tri[f][(k + 1) % 3]), 3 * f + k});
        std::sort(edges.begin(), edges.end(), [](const E &a, const E &b) { return a.key < b.key || (a.key == b.key && a.he < b.he); });
        cut.assign(3 * F, 0);
        twinCorner.assign(3 * F, -1);
        for (size_t i = 0; i < edges.size();) {
            size_t j = i;
            while (j < edges.size() && edges[j].key == edges[i].key) ++j;
            bool selected = false;
            for (size_t k = i; k < j; ++k) selected = selected || m.face[faceIdx[edges[k].he / 3]].IsFaceEdgeS(edges[k].he % 3);
            if (selected) selectedPairs.insert(edges[i].key);
            if (j - i == 2) {
                twinCorner[edges[i].he] = edges[i + 1].he;
                twinCorner[edges[i + 1].he] = edges[i].he;
            }
            const bool crease = !selected && j - i == 2 && IsCrease(edges[i].he / 3, edges[i + 1].he / 3);
            if (selected || crease || j - i != 2) {
                for (size_t k = i; k < j; ++k) cut[edges[k].he] = 1;
                ++res.initialFrontEdges;
            }
            i = j;
        }
        res.creaseEdges = creaseCount;
        std::vector<int> faceSet(F), cornerSet(3 * F);
        std::iota(faceSet.begin(), faceSet.end(), 0);
        std::iota(cornerSet.begin(), cornerSet.end(), 0);
        for (int h = 0; h < 3 * F; ++h) {
            int t = twinCorner[h];
            if (t < h || cut[h]) continue;
            int f = h / 3, g = t / 3, k = h % 3, l = t % 3;
            Unite(faceSet, f, g);
            // edge k of f goes tri[f][k] -> tri[f][k+1]; edge l of g goes tri[f][k+1] -> tri[f][k]
            Unite(cornerSet, 3 * f + k, 3 * g + (l + 1) % 3);
            Unite(cornerSet, 3 * f + (k + 1) % 3, 3 * g + l);
        }
        patchOf.resize(F);
        sectorOf.resize(3 * F);
        for (int f = 0; f < F; ++f) patchOf[f] = Find(faceSet, f);
        for (int c = 0; c < 3 * F; ++c) sectorOf[c] = Find(cornerSet, c);
    }

    void Run(Result &res)
    {
        Partition(res);
        const int F = int(tri.size());
        // faces grouped by patch
        std::vector<int> order(F);
        std::iota(order.begin(), order.end(), 0);
        std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return patchOf[a] < patchOf[b]; });

        const bool hasQuality = vcg::tri::HasPerFaceQuality(m);
        std::vector<int> vertexNewPos(m.vert.size(), -2);  // -2 untouched, -1 removed, else moved
        std::vector<P3> movedTo;
        std::vector<std::array<int, 5>> outFaces;  // global vertex ids (negative: new vertex -k-1), size in [4]
        std::vector<float> outQuality;
        std::vector<signed char> outDiagonal;  // per quad: 1 split a-c, 0 split b-d, -1 either (by shape)
        std::vector<char> used(m.vert.size(), 0);
        qmorph::PatchParams pp;
        pp.smoothing = par.smoothing;
        pp.finalSmoothing = par.smoothingIterations;
        pp.closedAngle = par.closedAngleDeg * M_PI / 180;
        pp.preserveInitialFront = par.preserveInitialFront;
        pp.transitions = par.transitions;
        pp.cleanup = par.cleanup;
        pp.rescueBadQuads = par.rescueBadQuads;

        // per input vertex: the patches holding it (sorted), to tell which chords between front
        // nodes another patch could also make
        std::vector<std::vector<int>> patchesOfVertex(m.vert.size());
        for (int f = 0; f < F; ++f)
            for (int k = 0; k < 3; ++k) {
                std::vector<int> &ps = patchesOfVertex[tri[f][k]];
                if (std::find(ps.begin(), ps.end(), patchOf[f]) == ps.end()) ps.push_back(patchOf[f]);
            }
        for (auto &ps : patchesOfVertex) std::sort(ps.begin(), ps.end());

        std::vector<int> localOfSector(3 * F, -1);
        for (size_t s = 0; s < order.size();) {
            size_t e = s;
            while (e < order.size() && patchOf[order[e]] == patchOf[order[s]]) ++e;
            Progress(int(100.0 * s / std::max<size_t>(1, order.size())), "Q-Morph: meshing patches");
            ++res.patches;
            // local mesh of the patch
            std::vector<P3> pts;
            std::vector<int> globalOf;      // local vertex -> global vertex
            std::vector<std::array<int, 3>> ltri;
            std::vector<char> lcut;
            std::vector<int> home;
            std::map<float, double> qualityArea;
            for (size_t i = s; i < e; ++i) {
                int f = order[i];
                std::array<int, 3> t;
                for (int k = 0; k < 3; ++k) {
                    int sec = sectorOf[3 * f + k];
                    if (localOfSector[sec] < 0) {
                        localOfSector[sec] = int(pts.size());
                        pts.push_back(P3::Construct(m.vert[tri[f][k]].cP()));
                        globalOf.push_back(tri[f][k]);
                        home.push_back(int(ltri.size()));
                    }
                    t[k] = localOfSector[sec];
                    lcut.push_back(cut[3 * f + k]);
                }
                ltri.push_back(t);
                if (hasQuality) {
                    P3 a = pts[t[0]], b = pts[t[1]], c = pts[t[2]];
                    qualityArea[float(m.face[faceIdx[f]].cQ())] += ((b - a) ^ (c - a)).Norm();
                }
            }
            float patchQuality = 0;
            double bestArea = -1;
            for (auto &qv : qualityArea)
                if (qv.second > bestArea) { bestArea = qv.second; patchQuality = qv.first; }
            bool hasFront = false;
            for (char c : lcut) hasFront = hasFront || c;
            if (!hasFront) ++res.patchesWithoutFront;

            qmorph::MixedMesh mm;
            mm.Build(pts, ltri, lcut);
            mm.SetKeys(globalOf);
            SurfaceProjector surface;
            surface.Build(pts, ltri);
            std::unordered_map<int, int> sharedOfLocal;  // front subdivision node -> its point index
            if (hasFront && par.targetEdgeLength > 0) SubdivideFront(mm, globalOf, home, sharedOfLocal, res, patchesOfVertex);
            if (hasFront) {  // which other patches hold each front node (see NewChordBetweenFrontNodes)
                const int patch = patchOf[order[s]];
                mm.otherPatches.assign(mm.VertexCount(), {});
                for (int v = 0; v < mm.VertexCount(); ++v) {
                    if (!mm.vertFixed[v]) continue;
                    auto shared = sharedOfLocal.find(v);
                    std::vector<int> &ps = mm.otherPatches[v];
                    ps = shared != sharedOfLocal.end() ? sharedPatches[shared->second] : patchesOfVertex[globalOf[v]];
                    ps.erase(std::remove(ps.begin(), ps.end(), patch), ps.end());
                }
            }
            if (hasFront && par.targetEdgeLength > 0) {
                qmorph::PatchRemesher remesher(mm, surface, home, par.targetEdgeLength);
                qmorph::PatchRemesher::Stats rs = remesher.Run(par.remeshIterations);
                res.remesh.splits += rs.splits; res.remesh.collapses += rs.collapses; res.remesh.flips += rs.flips;
            }
            if (hasFront) {
                qmorph::PatchMesher mesher(mm, surface, home, pp);
                qmorph::PatchStats st = mesher.Run();
                res.ops.quadsFormed += st.quadsFormed; res.ops.templates += st.templates; res.ops.swaps += st.swaps;
                res.ops.splits += st.splits; res.ops.failures += st.failures; res.ops.pairedTriangles += st.pairedTriangles;
                res.ops.doublets += st.doublets; res.ops.iterations += st.iterations;
                res.ops.valenceTurns += st.valenceTurns;
                res.ops.seams += st.seams;
                res.ops.transitionSeams += st.transitionSeams;
                res.ops.transitionSplits += st.transitionSplits;
                res.ops.diagonalCollapses += st.diagonalCollapses;
                res.ops.quadsOpened += st.quadsOpened;
            }
            // write back: vertex ids (global, or new), positions of moved interior nodes
            std::vector<int> outId(mm.VertexCount(), 0);
            for (int v = 0; v < mm.VertexCount(); ++v) {
                if (!mm.vertAlive[v]) continue;
                auto shared = sharedOfLocal.find(v);
                if (shared != sharedOfLocal.end()) {
                    outId[v] = sharedOut[shared->second];
                } else if (v < int(globalOf.size())) {
                    int g = globalOf[v];
                    outId[v] = g;
                    used[g] = 1;
                    if (!mm.vertFixed[v] && !(mm.pos[v] == pts[v])) {
                        vertexNewPos[g] = int(movedTo.size());
                        movedTo.push_back(mm.pos[v]);
                    }
                } else {
                    newPoints.push_back(mm.pos[v]);
                    outId[v] = -int(newPoints.size());
                }
            }
            for (int f = 0; f < mm.FaceCount(); ++f) {
                if (!mm.FaceAlive(f)) continue;
                std::array<int, 5> of{mm.faceSize[f], 0, 0, 0, 0};
                int h = mm.faceHe[f];
                int corner[4] = {-1, -1, -1, -1};
                for (int k = 0; k < mm.faceSize[f]; ++k, h = mm.heNext[h]) {
                    corner[k] = mm.Org(h);
                    of[1 + k] = outId[corner[k]];
                }
                outFaces.push_back(of);
                outQuality.push_back(patchQuality);
                outDiagonal.push_back(mm.faceSize[f] == 4 ? PreferredDiagonal(mm, surface, home, corner) : -1);
                if (mm.faceSize[f] == 4) ++res.quads; else ++res.triangles;
            }
            for (size_t i = s; i < e; ++i)
                for (int k = 0; k < 3; ++k) localOfSector[sectorOf[3 * order[i] + k]] = -1;
            s = e;
        }
        Progress(99, "Q-Morph: writing the quad mesh");
        WriteBack(newPoints, vertexNewPos, movedTo, outFaces, outQuality, outDiagonal, used, hasQuality);
        res.quality = QuadQuality::Measure(QuadQuality::FromFauxMesh(m));
    }

    // Front edges cut into pieces of about the target length, with points that depend only on the
    // edge's input vertices: both patches on an edge make the same points, written once.
    std::vector<P3> newPoints;                       // vertices added to the mesh (output id -k-1: newPoints[k])
    std::unordered_map<uint64_t, int> sharedOfEdge;  // edge key -> first of its points in sharedOut
    std::vector<int> sharedOut;                      // output id (negative: new vertex) per point
    std::vector<std::vector<int>> sharedPatches;     // patches holding each point (sorted)
    std::vector<std::pair<int, int>> frontChains;    // selected sub-edges, as output ids

    void SubdivideFront(qmorph::MixedMesh &mm, const std::vector<int> &globalOf, std::vector<int> &home,
                        std::unordered_map<int, int> &sharedOfLocal, Result &res,
                        const std::vector<std::vector<int>> &patchesOfVertex)
    {
        const double L = par.targetEdgeLength;
        const int boundaryCount = mm.HalfEdgeCount();
        std::vector<int> keys(globalOf.begin(), globalOf.end());
        for (int h = 0; h < boundaryCount; ++h) {
            if (!mm.HeAlive(h) || mm.heTwin[h] >= 0 || mm.Org(h) >= int(globalOf.size()) || mm.Dst(h) >= int(globalOf.size())) continue;
            const int ga = globalOf[mm.Org(h)], gb = globalOf[mm.Dst(h)];
            const int lo = std::min(ga, gb), hi = std::max(ga, gb);
            const P3 plo = P3::Construct(m.vert[lo].cP()), phi = P3::Construct(m.vert[hi].cP());
            const int n = qmorph::PatchRemesher::PiecesFor((phi - plo).Norm(), L);
            if (n < 2) continue;
            const uint64_t key = Key(lo, hi);
            auto it = sharedOfEdge.find(key);
            if (it == sharedOfEdge.end()) {
                it = sharedOfEdge.emplace(key, int(sharedOut.size())).first;
                std::vector<int> both;  // the patches on the edge hold its points
                std::set_intersection(patchesOfVertex[lo].begin(), patchesOfVertex[lo].end(), patchesOfVertex[hi].begin(),
                                      patchesOfVertex[hi].end(), std::back_inserter(both));
                std::vector<int> chain{lo};
                for (int k = 1; k < n; ++k) {
                    newPoints.push_back(plo + (phi - plo) * (double(k) / n));
                    sharedOut.push_back(-int(newPoints.size()));
                    sharedPatches.push_back(both);
                    chain.push_back(sharedOut.back());
                }
                chain.push_back(hi);
                if (selectedPairs.count(key))
                    for (size_t k = 0; k + 1 < chain.size(); ++k) frontChains.push_back({chain[k], chain[k + 1]});
                ++res.frontEdgesSubdivided;
            }
            // the edge's points from the half-edge's origin to its end
            std::vector<int> order;
            std::vector<P3> points;
            for (int k = 0; k < n - 1; ++k) {
                order.push_back(it->second + (ga == lo ? k : n - 2 - k));
                points.push_back(newPoints[-sharedOut[order.back()] - 1]);
            }
            const std::vector<int> made = qmorph::PatchRemesher::SubdivideBoundaryEdge(mm, home, h, points);
            keys.resize(mm.VertexCount(), 0);
            for (int k = 0; k < n - 1; ++k) {
                sharedOfLocal[made[k]] = order[k];
                keys[made[k]] = INT_MIN / 2 + order[k];  // copies of one point (both sides of a slit) share it
            }
        }
        mm.SetKeys(keys);
    }

    // Replaces the faces of m by the new polygons (quads as faux pairs), front edges selected.
    void WriteBack(const std::vector<P3> &outPoints, const std::vector<int> &vertexNewPos, const std::vector<P3> &movedTo,
                   const std::vector<std::array<int, 5>> &outFaces, const std::vector<float> &outQuality,
                   const std::vector<signed char> &outDiagonal,
                   const std::vector<char> &used, bool hasQuality)
    {
        // The selection is kept as vertex pairs: flips do not carry per-edge flags, and the
        // initial front edges survive unchanged, so the pairs are still edges.
        const int firstNew = int(m.vert.size());
        auto resolve = [&](int id) { return id >= 0 ? id : firstNew + (-id - 1); };
        std::unordered_set<uint64_t> frontPairs = selectedPairs;
        for (const auto &e : sharedOfEdge) frontPairs.erase(e.first);  // cut into pieces: no longer an edge
        for (const auto &e : frontChains) frontPairs.insert(Key(resolve(e.first), resolve(e.second)));

        for (size_t v = 0; v < m.vert.size(); ++v) {
            if (m.vert[v].IsD()) continue;
            if (vertexNewPos[v] >= 0) m.vert[v].P() = CoordType::Construct(movedTo[vertexNewPos[v]]);
        }
        if (!outPoints.empty()) {
            auto vi = vcg::tri::Allocator<MeshType>::AddVertices(m, outPoints.size());
            for (size_t i = 0; i < outPoints.size(); ++i, ++vi) vi->P() = CoordType::Construct(outPoints[i]);
        }
        for (auto &f : m.face)
            if (!f.IsD()) vcg::tri::Allocator<MeshType>::DeleteFace(m, f);
        size_t triCount = 0;
        for (auto &of : outFaces) triCount += of[0] == 4 ? 2 : 1;
        // polygon sides and chosen diagonals, so a quad is never split along an edge that exists elsewhere
        std::unordered_set<uint64_t> sides;
        for (const auto &of : outFaces)
            for (int k = 0; k < of[0]; ++k) sides.insert(Key(resolve(of[1 + k]), resolve(of[1 + (k + 1) % of[0]])));
        auto fi = vcg::tri::Allocator<MeshType>::AddFaces(m, triCount);
        auto setFace = [&](FaceType &f, int a, int b, int c, float q) {
            f.V(0) = &m.vert[a];
            f.V(1) = &m.vert[b];
            f.V(2) = &m.vert[c];
            f.Flags() = 0;
            if (hasQuality) f.Q() = q;
            const int vv[3] = {a, b, c};
            for (int k = 0; k < 3; ++k)
                if (frontPairs.count(Key(vv[k], vv[(k + 1) % 3]))) f.SetFaceEdgeS(k);
        };
        for (size_t i = 0; i < outFaces.size(); ++i) {
            const auto &of = outFaces[i];
            int a = resolve(of[1]), b = resolve(of[2]), c = resolve(of[3]);
            if (of[0] == 3) {
                setFace(*fi, a, b, c, outQuality[i]);
                ++fi;
                continue;
            }
            int d = resolve(of[4]);
            // the diagonal that follows the input surface, else the one giving the better pair of
            // triangles (the larger smallest angle)
            P3 pa = P3::Construct(m.vert[a].cP()), pb = P3::Construct(m.vert[b].cP()), pc = P3::Construct(m.vert[c].cP()),
               pd = P3::Construct(m.vert[d].cP());
            bool acDiagonal = outDiagonal[i] >= 0 ? outDiagonal[i] == 1
                                                  : std::min(MinAngle(pa, pb, pc), MinAngle(pa, pc, pd)) >= std::min(MinAngle(pb, pc, pd), MinAngle(pb, pd, pa));
            if (sides.count(Key(a, c))) acDiagonal = false;
            else if (sides.count(Key(b, d))) acDiagonal = true;
            sides.insert(acDiagonal ? Key(a, c) : Key(b, d));  // two quads around a doublet node must not share a diagonal
            if (acDiagonal) {
                setFace(*fi, a, b, c, outQuality[i]); fi->SetF(2); ++fi;  // c->a faux
                setFace(*fi, a, c, d, outQuality[i]); fi->SetF(0); ++fi;  // a->c faux
            } else {
                setFace(*fi, b, c, d, outQuality[i]); fi->SetF(2); ++fi;  // d->b faux
                setFace(*fi, b, d, a, outQuality[i]); fi->SetF(0); ++fi;  // b->d faux
            }
        }
        std::vector<char> wasUsed(used.size(), 0);  // isolated input vertices stay as they are
        for (auto &t : tri)
            for (int k = 0; k < 3; ++k) wasUsed[t[k]] = 1;
        for (size_t v = 0; v < used.size(); ++v)
            if (wasUsed[v] && !used[v] && !m.vert[v].IsD()) vcg::tri::Allocator<MeshType>::DeleteVertex(m, m.vert[v]);
        vcg::tri::Allocator<MeshType>::CompactEveryVector(m);
        vcg::tri::UpdateBounding<MeshType>::Box(m);
        if (vcg::tri::HasFFAdjacency(m)) vcg::tri::UpdateTopology<MeshType>::FaceFace(m);
        if (vcg::tri::HasVFAdjacency(m)) vcg::tri::UpdateTopology<MeshType>::VertexFace(m);
        vcg::tri::UpdateNormal<MeshType>::PerVertexNormalizedPerFace(m);
    }

    // A non-planar quad is written as two triangles: the diagonal whose midpoint lies clearly
    // nearer the input surface (1: corners 0-2, 0: corners 1-3) keeps the shape; -1 when the
    // quad is about flat and either will do.
    static int PreferredDiagonal(const qmorph::MixedMesh &mm, const SurfaceProjector &surface, const std::vector<int> &home,
                                 const int (&corner)[4])
    {
        auto distance = [&](const P3 &q, int near) {
            int hm = near < int(home.size()) ? home[near] : 0;
            return (surface.Project(q, hm) - q).Norm();
        };
        // the farthest of the diagonal's midpoint and the two triangles' centres
        auto offSurface = [&](int i) {
            const P3 &u = mm.pos[corner[i]], &w = mm.pos[corner[(i + 2) % 4]];
            const P3 &x = mm.pos[corner[(i + 1) % 4]], &y = mm.pos[corner[(i + 3) % 4]];
            return std::max({distance((u + w) * 0.5, corner[i]), distance((u + w + x) / 3.0, corner[(i + 1) % 4]),
                             distance((u + w + y) / 3.0, corner[(i + 3) % 4])});
        };
        const double ac = offSurface(0), bd = offSurface(1);
        double side = 0;
        for (int k = 0; k < 4; ++k) side += (mm.pos[corner[(k + 1) % 4]] - mm.pos[corner[k]]).Norm();
        if (std::fabs(ac - bd) <= 0.02 * side / 4) return -1;
        return ac < bd ? 1 : 0;
    }

    static double MinAngle(const P3 &a, const P3 &b, const P3 &c)
    {
        return std::min({qmorph::AngleBetween(b - a, c - a), qmorph::AngleBetween(a - b, c - b), qmorph::AngleBetween(a - c, b - c)});
    }
};

}  // namespace vcg_ext

#endif
