// Variational Shape Approximation with the L2,1 metric (Cohen-Steiner, Alliez, Desbrun 2004):
// partitions a triangle mesh into near-planar, edge-connected regions.
//
//   E(t, P) = |t| * |n_t - N_P|^2          (area times squared normal deviation)
//
// Lloyd iterations alternate (1) flooding from one seed per region with one global priority
// queue keyed by E(face, proxy of the region that reaches it) and (2) fitting each proxy normal
// as the normalised area-weighted normal sum of its region. Seeding, as the seed paper does it:
// a few random seeds, then an extra seed (the face of largest error) in every region whose
// largest face-normal deviation from its proxy exceeds a threshold angle; or a fixed region count
// reached by incremental seeding in the region of largest error (as CGAL's VSA does).
//
// Needs face-face adjacency (computed here) and per-face quality for the output labels.
#ifndef VCG_EXT_VSA_SEGMENTATION_H
#define VCG_EXT_VSA_SEGMENTATION_H

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <queue>
#include <random>
#include <string>
#include <vector>

#include <vcg/complex/complex.h>

#include <vcg_ext/common/face_clusters.h>
#include <vcg_ext/common/face_face_adjacency.h>
#include <vcg_ext/common/live_box.h>
#include <vcg_ext/common/progress_relay.h>
#include <vcg_ext/mesh_checks.h>

namespace vcg_ext {

template <class MeshType>
class VSASegmentation
{
public:
    typedef typename MeshType::FaceType FaceType;
    typedef vcg::Point3<double> Vec;

    enum SeedingMode {
        ThresholdSeeding = 0,  // random seeds, then split regions deviating more than the threshold
        FixedRegionCount = 1   // exactly maxRegions regions, incremental seeding at the worst region
    };

    struct Params {
        SeedingMode mode = ThresholdSeeding;
        int initialSeeds = 2;             // random seeds to start from (>= 1)
        double thresholdAngleDeg = 60.0;  // max normal deviation inside a region (0 < a < 180)
        int maxRegions = 0;               // cap (threshold mode, 0: AutomaticRegionCap) or exact count (fixed mode, >= 1)
        int maxIterations = 30;           // cap on Lloyd iterations after each (re)seeding, >= 1
        double relativeTolerance = 1e-4;  // Lloyd stops when the error drops by less than this fraction
        uint32_t randomSeed = 0;          // same seed, same result
        int relaxationsPerSeed = 5;       // fixed mode: Lloyd iterations after each added seed
        int teleportAttempts = 10;        // fixed mode: merge the cheapest adjacent pair, re-seed the worst region
        int facesPerCluster = 0;          // threshold mode: seed on face clusters of this size first (0: AutomaticClusterSize, 1: never)

        // Empty when valid, else what is wrong.
        std::string Validate() const
        {
            if (initialSeeds < 1) return "initial seeds must be at least 1";
            if (!(thresholdAngleDeg > 0.0 && thresholdAngleDeg < 180.0)) return "the threshold angle must be in (0, 180) degrees";
            if (maxRegions < 0) return "max regions must be at least 0 (0: automatic)";
            if (mode == FixedRegionCount && maxRegions < 1) return "max regions must be at least 1 with a fixed region count";
            if (maxIterations < 1) return "max iterations must be at least 1";
            if (!(relativeTolerance >= 0.0)) return "the relative tolerance must be >= 0";
            if (facesPerCluster < 0) return "faces per cluster must be at least 0 (0: automatic)";
            return "";
        }
    };

    struct Result {
        std::string error;             // empty on success
        std::string warning;           // a problem segmented anyway that the later filters refuse (Check)
        std::vector<int> faceRegion;   // per face index (tri::Index), -1 for deleted faces
        std::vector<int> seedFace;     // per region: the face its last flooding started from
        std::vector<Vec> proxyNormal;  // per region
        int regions = 0;
        int components = 0;
        int lloydIterations = 0;       // in total, over all seeding rounds, on faces
        int clusters = 0;              // face clusters seeded on first (0: none)
        int clusterIterations = 0;     // Lloyd iterations on them
        int seedingRounds = 0;
        double l21Error = 0;           // total L2,1 error of the final partition
        double maxDeviationDeg = 0;    // largest face-normal / proxy angle over all regions
        int regionCap = 0;             // threshold mode: the cap seeding stopped at or under
        double seconds = 0;
    };

    // The automatic cap on the region count in threshold mode (the default): one region per
    // kFacesPerAutoRegion faces, at least kMinAutoRegions. A fixed cap of 200 stopped the seeding
    // of big scans far above the threshold (armadillo, 52k faces: 105 degrees; feline, 100k faces:
    // 152 degrees; armadillo refined to 832k faces: 108 degrees), and so did one region per 100
    // faces on rough scans of CGAL's data, whose ridges and tips turn by more than the threshold
    // within a few faces (femur, 7.8k faces: 170 degrees at 200 regions; it meets the angle with
    // 868, one per 9 faces; bull one per 13, cheese one per 18). The cap only bounds the seeding
    // rounds where the angle needs regions of a few faces.
    static int AutomaticRegionCap(int faces) { return std::max(kMinAutoRegions, faces / kFacesPerAutoRegion); }
    static constexpr int kMinAutoRegions = 200;
    static constexpr int kFacesPerAutoRegion = 4;
    // Faces with less area than this fraction of the squared bounding-box diagonal have no normal
    // worth the name (needles of scans): left out of the regions' deviation, the split test and
    // the logged figure.
    static constexpr double kNegligibleAreaFraction = 1e-12;

    // Threshold seeding on a big mesh starts on near-planar clusters of faces (common/face_clusters.h)
    // and goes on to faces once the clusters' regions meet the threshold angle: its early rounds,
    // Lloyd iterations over the whole mesh with few regions (46 of the 83 iterations on armadillo
    // refined to 832k faces, each a priority-queue flooding of every face), then flood about
    // kClusterCount clusters instead, and the rounds on faces only move the boundaries and split
    // where the clusters' boundaries left a face beyond the angle (VSA on that mesh: 15.9 s ->
    // 4.2 s, 464 -> 489 regions, L2,1 error 3% lower; refined to 3.3M faces: 108 s -> 18 s). A
    // cluster's error against a proxy is exact (2A - 2 S.N, see Teleport), so the clusters change
    // where the regions start, not what is minimised. Under kMinClusterFaces
    // faces per cluster (meshes under 131,072 faces) the faces alone are about as fast (armadillo,
    // 52k faces: 0.80 s on faces, 0.72 s from clusters of 3) and seeding stays on them.
    static int AutomaticClusterSize(int faces) { return faces / kClusterCount >= kMinClusterFaces ? faces / kClusterCount : 1; }
    static constexpr int kClusterCount = 16384;
    static constexpr int kMinClusterFaces = 8;
    // A cluster's cone is this fraction of the threshold angle: a region of one cluster deviates at
    // most twice that, so it never needs a split the clusters cannot make.
    static constexpr double kClusterConeFraction = 0.25;

    // Why `m` cannot be segmented with `p`, or "": the parameters, no faces, NaN coordinates, and
    // what would make the regions meaningless: unmerged vertices (a triangle soup would make every
    // face a component of its own) and an inconsistent orientation (the metric compares normals).
    // Open, non-manifold and multi-component meshes are segmented, and so are degenerate and
    // duplicate faces (zero-area faces get a region without NaNs); `warning` (when given) receives
    // the first of these problems that the later filters of the pipeline refuse (non-manifold
    // edges or vertices, degenerate or duplicate faces, in MeshCheckReport's order), or "".
    static std::string Check(const MeshType &m, const Params &p, std::string *warning = nullptr)
    {
        const std::string invalid = p.Validate();
        if (!invalid.empty()) return invalid;
        const MeshCheckReport report = MeshChecks<MeshType>::Inspect(m);
        const std::string why = report.FacesAndCoordinatesProblem();
        if (!why.empty()) return why;
        const MeshCheckReport::Problem problem = report.First(MeshCheckReport::ManifoldOriented);
        if (problem == MeshCheckReport::DuplicateVertices || problem == MeshCheckReport::Inconsistent)
            return report.Describe(problem);
        if (warning) *warning = report.Describe(problem);
        return "";
    }

    // Segments `m` (after Check: on error it is left as it is); on success writes region ids to
    // face quality (when the mesh has it).
    static Result Segment(MeshType &m, const Params &p, vcg::CallBackPos *cb = nullptr)
    {
        return ProgressRelay::Run(cb, [&](vcg::CallBackPos *report) { return SegmentHere(m, p, report); });
    }

    // L2,1 error of a labelling against the given proxy normals (for tests and reports).
    static double L21Error(MeshType &m, const std::vector<int> &faceRegion, const std::vector<Vec> &proxy)
    {
        double e = 0;
        for (FaceType &f : m.face) {
            if (f.IsD()) continue;
            Vec n; double a;
            AreaNormal(f, a, n);
            e += a * (n - proxy[faceRegion[vcg::tri::Index(m, f)]]).SquaredNorm();
        }
        return e;
    }

    // From the corner of lowest address on, so a flipped face gives exactly the opposite normal
    // (whichever corner the flip starts it at): the errors, hence the regions, do not depend on
    // the orientation.
    static void AreaNormal(const FaceType &f, double &area, Vec &normal)
    {
        const int r = f.cV(1) < f.cV(0) ? (f.cV(2) < f.cV(1) ? 2 : 1) : (f.cV(2) < f.cV(0) ? 2 : 0);
        Vec a = Vec::Construct(f.cV(r)->cP()), b = Vec::Construct(f.cV((r + 1) % 3)->cP()), c = Vec::Construct(f.cV((r + 2) % 3)->cP());
        Vec cr = (b - a) ^ (c - a);
        double len = cr.Norm();
        area = 0.5 * len;
        normal = (len > 0 && std::isfinite(len)) ? cr / len : Vec(0, 0, 0);  // zero-area: no normal, no error
        if (!std::isfinite(area)) area = 0;
    }

private:
    struct QueueItem {
        double error;
        int face;
        int region;
        bool operator<(const QueueItem &o) const  // min-heap on error, ties by face index, then region
        {                                         // (a total order: the push order never matters)
            return error != o.error ? error > o.error : face != o.face ? face > o.face : region > o.region;
        }
        // For the same element: whether this entry would pop before `queued`, the element's best so
        // far (only such an entry is worth queueing; the larger one would pop later and be skipped).
        bool PopsBefore(const QueueItem &queued) const
        {
            return error < queued.error || (error == queued.error && region < queued.region);
        }
    };

    MeshType &m;
    const Params &p;
    vcg::CallBackPos *cb;
    int roundPercent = 0;  // the current seeding round's progress, repeated by its Lloyd iterations
    static constexpr int kSeedingFromPercent = 3;  // where the seeding's progress starts (after the set-up)
    int n;                          // face vector size (deleted faces included, never labelled)
    std::vector<double> area;
    double negligibleArea = 0;      // kNegligibleAreaFraction of the squared diagonal
    std::vector<Vec> normal;
    std::vector<int> label;         // region per face
    std::vector<int> seeds;         // seed face per region
    std::vector<Vec> proxy;         // proxy normal per region
    std::vector<std::array<int, 3>> adj;  // edge-adjacent faces (-1: none)
    std::vector<QueueItem> queued;  // Partition's scratch: each face's best entry in the queue

    // The coarse level of threshold seeding on big meshes (see kClusterCount; empty otherwise).
    enum Level { OnFaces, OnClusters };
    FaceClusters clusters;
    std::vector<double> clusterArea;
    std::vector<Vec> clusterNormalSum;  // area-weighted
    std::vector<int> clusterLabel;      // region per cluster

    // Threshold seeding relaxes only the split regions and their neighbours when fewer than one
    // region in this many splits.
    static constexpr size_t kLocalTailRatio = 8;

    VSASegmentation(MeshType &mesh, const Params &params, vcg::CallBackPos *callback)
        : m(mesh), p(params), cb(callback), n(int(mesh.face.size()))
    {
        area.assign(n, 0.0);
        normal.assign(n, Vec(0, 0, 0));
        adj.assign(n, {-1, -1, -1});
        const double diagonal = LiveVertexBox(m).Diag();
        negligibleArea = kNegligibleAreaFraction * diagonal * diagonal;
        for (FaceType &f : m.face) {
            if (f.IsD()) continue;
            int i = int(vcg::tri::Index(m, f));
            AreaNormal(f, area[i], normal[i]);
            for (int k = 0; k < 3; ++k) {
                FaceType *g = f.FFp(k);
                if (g != nullptr && g != &f && !g->IsD()) adj[i][k] = int(vcg::tri::Index(m, g));
            }
        }
    }

    double Error(int face, int region) const { return area[face] * (normal[face] - proxy[region]).SquaredNorm(); }

    // Segment, on the thread the progress relay runs it on.
    static Result SegmentHere(MeshType &m, const Params &p, vcg::CallBackPos *cb)
    {
        auto t0 = std::chrono::steady_clock::now();
        Result res;
        if (cb) cb(0, "VSA: checking the mesh");
        res.error = Check(m, p, &res.warning);
        if (!res.error.empty()) return res;
        vcg::tri::RequireFFAdjacency(m);
        if (cb) cb(1, "VSA: face adjacency");
        FaceFaceAdjacency<MeshType>::Update(m);

        if (cb) cb(3, "VSA: face areas and normals");
        VSASegmentation s(m, p, cb);
        s.Run(res);

        if (vcg::tri::HasPerFaceQuality(m))
            for (FaceType &f : m.face)
                if (!f.IsD()) f.Q() = typename MeshType::ScalarType(res.faceRegion[vcg::tri::Index(m, f)]);
        res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        return res;
    }

    void Progress(int percent, const char *what) const
    {
        if (cb) cb(std::min(99, std::max(0, percent)), what);
    }

    // Progress inside a Lloyd run, once per iteration (at the percent of its seeding round): a
    // round takes seconds on a big mesh, and the threshold mode's rounds are not known ahead.
    void ReportIteration(const Result &res, int iteration) const
    {
        if (!cb) return;
        char what[96];
        std::snprintf(what, sizeof what, "VSA: seeding round %d, %d regions, Lloyd iteration %d", res.seedingRounds,
                      int(seeds.size()), iteration + 1);
        Progress(roundPercent, what);
    }

    // The faces a Lloyd iteration works on, in index order (so sums and ties come out the same
    // whichever scope holds them): every live face, or only the faces of a few regions, whose
    // neighbours then keep their faces and proxies (the tail of threshold seeding, see Run).
    struct Scope {
        std::vector<int> faces;    // ascending
        std::vector<char> region;  // per region: in scope (empty: every region)
        bool Has(int r) const { return region.empty() || region[r]; }
    };

    Scope Everything() const
    {
        Scope s;
        for (int f = 0; f < n; ++f)
            if (!m.face[f].IsD()) s.faces.push_back(f);
        return s;
    }

    // The faces of the regions flagged in `regions`.
    Scope Only(const std::vector<char> &regions) const
    {
        Scope s;
        s.region = regions;
        for (int f = 0; f < n; ++f)
            if (label[f] >= 0 && regions[label[f]]) s.faces.push_back(f);
        return s;
    }

    // One flooding of the scope's faces from its regions' seeds with the current proxies. A face
    // is queued again only with a smaller (error, region) than it already has in the queue: the
    // larger entry would pop after it and be skipped, so the partition is the same with fewer heap
    // operations (most faces are reached by two or three neighbours of one region, all with the
    // same error).
    void Partition(const Scope &scope)
    {
        if (label.size() != size_t(n)) label.assign(n, -1);
        if (queued.size() != size_t(n)) queued.resize(n);
        for (int f : scope.faces) {
            label[f] = -1;
            queued[f].error = std::numeric_limits<double>::infinity();
        }
        std::priority_queue<QueueItem> q;
        auto push = [&](int g, int r) {
            const QueueItem it{Error(g, r), g, r};
            if (it.PopsBefore(queued[g])) {
                queued[g] = it;
                q.push(it);
            }
        };
        for (int r = 0; r < int(seeds.size()); ++r)
            if (scope.Has(r)) label[seeds[r]] = r;
        for (int r = 0; r < int(seeds.size()); ++r)
            if (scope.Has(r))
                for (int g : adj[seeds[r]])
                    if (g >= 0 && label[g] < 0) push(g, r);
        while (!q.empty()) {
            QueueItem it = q.top();
            q.pop();
            if (label[it.face] >= 0) continue;
            label[it.face] = it.region;
            for (int g : adj[it.face])
                if (g >= 0 && label[g] < 0) push(g, it.region);
        }
    }

    // Proxy normals of the scope's regions from their faces (SetProxy).
    void FitProxies(const Scope &scope)
    {
        std::vector<Vec> sum(seeds.size(), Vec(0, 0, 0));
        for (int f : scope.faces)
            if (label[f] >= 0) sum[label[f]] += normal[f] * area[f];
        for (size_t r = 0; r < seeds.size(); ++r)
            if (scope.Has(int(r))) SetProxy(int(r), sum[r]);
    }

    // Proxy normal of region r from its area-weighted normal sum; a zero sum keeps the seed's normal.
    void SetProxy(int r, const Vec &sum)
    {
        const double len = sum.Norm();
        if (len > 0) proxy[r] = sum / len;
        else if (normal[seeds[r]].SquaredNorm() > 0) proxy[r] = normal[seeds[r]];
    }

    double TotalError(const Scope &scope) const
    {
        double e = 0;
        for (int f : scope.faces)
            if (label[f] >= 0) e += Error(f, label[f]);
        return e;
    }

    // Each region of the scope restarts from its face of smallest error.
    void ReseedAtBestFaces(const Scope &scope)
    {
        std::vector<double> best(seeds.size(), -1);
        for (int f : scope.faces) {
            int r = label[f];
            if (r < 0) continue;
            double e = Error(f, r);
            if (best[r] < 0 || e < best[r] || (e == best[r] && f < seeds[r])) { best[r] = e; seeds[r] = f; }
        }
    }

    // Lloyd iterations on the scope from the current seeds and proxies; returns the scope's final
    // error. On clusters the scope is every face.
    double Lloyd(int maxIterations, Result &res, const Scope &scope, Level level = OnFaces)
    {
        const bool coarse = level == OnClusters;
        auto step = [&]() {
            if (coarse) { PartitionClusters(); FitProxiesOnClusters(); return TotalErrorOnClusters(); }
            Partition(scope);
            FitProxies(scope);
            return TotalError(scope);
        };
        auto reseed = [&]() { if (coarse) ReseedAtBestClusters(); else ReseedAtBestFaces(scope); };
        double e = step();
        for (int it = 0; it < maxIterations; ++it) {
            ReportIteration(res, it);
            reseed();
            double e2 = step();
            ++(coarse ? res.clusterIterations : res.lloydIterations);
            bool converged = !(e - e2 > p.relativeTolerance * e);
            e = e2;
            if (converged) break;
        }
        reseed();
        if (coarse) LabelFacesFromClusters();
        return e;
    }

    void BuildClusters(int facesPerCluster)
    {
        std::vector<char> live(n);
        for (int f = 0; f < n; ++f) live[f] = !m.face[f].IsD();
        clusters = FaceClusters::Grow(adj, normal, live, facesPerCluster, kClusterConeFraction * p.thresholdAngleDeg);
        clusterArea.assign(clusters.Count(), 0.0);
        clusterNormalSum.assign(clusters.Count(), Vec(0, 0, 0));
        for (int c = 0; c < clusters.Count(); ++c)
            for (int i = clusters.faceStart[c]; i < clusters.faceStart[c + 1]; ++i) {
                const int f = clusters.faces[i];
                clusterArea[c] += area[f];
                clusterNormalSum[c] += normal[f] * area[f];
            }
    }

    void ReleaseClusters()
    {
        clusters = FaceClusters();
        std::vector<double>().swap(clusterArea);
        std::vector<Vec>().swap(clusterNormalSum);
        std::vector<int>().swap(clusterLabel);
    }

    // A cluster's error against a region's proxy: sum a_f |n_f - N|^2 = 2A - 2 S.N (unit normals).
    double ClusterError(int c, int region) const
    {
        return std::max(0.0, 2 * clusterArea[c] - 2 * (clusterNormalSum[c] * proxy[region]));
    }

    // Partition's flooding over the clusters' graph from the seeds' clusters (the faces take their
    // cluster's region at the end of the Lloyd run: LabelFacesFromClusters). A seed whose cluster
    // a region of lower index holds floods nothing.
    void PartitionClusters()
    {
        const int k = clusters.Count();
        clusterLabel.assign(k, -1);
        std::vector<QueueItem> best(k, QueueItem{std::numeric_limits<double>::infinity(), 0, 0});
        std::priority_queue<QueueItem> q;
        auto push = [&](int c, int r) {
            // error per area: by the error alone, clusters of many faces would join last
            // whatever their fit (three times the regions on the 832k mesh)
            const QueueItem it{clusterArea[c] > 0 ? ClusterError(c, r) / clusterArea[c] : 0.0, c, r};
            if (it.PopsBefore(best[c])) {
                best[c] = it;
                q.push(it);
            }
        };
        auto flood = [&](int c, int r) {
            for (int i = clusters.neighbourStart[c]; i < clusters.neighbourStart[c + 1]; ++i)
                if (clusterLabel[clusters.neighbours[i]] < 0) push(clusters.neighbours[i], r);
        };
        for (int r = 0; r < int(seeds.size()); ++r)
            if (clusterLabel[clusters.clusterOf[seeds[r]]] < 0) clusterLabel[clusters.clusterOf[seeds[r]]] = r;
        for (int r = 0; r < int(seeds.size()); ++r)
            if (clusterLabel[clusters.clusterOf[seeds[r]]] == r) flood(clusters.clusterOf[seeds[r]], r);
        while (!q.empty()) {
            QueueItem it = q.top();
            q.pop();
            if (clusterLabel[it.face] >= 0) continue;
            clusterLabel[it.face] = it.region;
            flood(it.face, it.region);
        }
    }

    void LabelFacesFromClusters()
    {
        label.assign(n, -1);
        for (int f = 0; f < n; ++f)
            if (clusters.clusterOf[f] >= 0) label[f] = clusterLabel[clusters.clusterOf[f]];
    }

    void FitProxiesOnClusters()
    {
        std::vector<Vec> sum(seeds.size(), Vec(0, 0, 0));
        for (int c = 0; c < clusters.Count(); ++c)
            if (clusterLabel[c] >= 0) sum[clusterLabel[c]] += clusterNormalSum[c];
        for (size_t r = 0; r < seeds.size(); ++r) SetProxy(int(r), sum[r]);
    }

    double TotalErrorOnClusters() const
    {
        double e = 0;
        for (int c = 0; c < clusters.Count(); ++c)
            if (clusterLabel[c] >= 0) e += ClusterError(c, clusterLabel[c]);
        return e;
    }

    // Each region restarts from its cluster of smallest error, at that cluster's face of smallest
    // error (ties to the lower index, as ReseedAtBestFaces).
    void ReseedAtBestClusters()
    {
        std::vector<double> best(seeds.size(), -1);
        std::vector<int> bestCluster(seeds.size(), -1);
        for (int c = 0; c < clusters.Count(); ++c) {
            const int r = clusterLabel[c];
            if (r < 0) continue;
            const double e = ClusterError(c, r);
            if (best[r] < 0 || e < best[r]) { best[r] = e; bestCluster[r] = c; }
        }
        for (size_t r = 0; r < seeds.size(); ++r) {
            const int c = bestCluster[r];
            if (c < 0) continue;
            double bestFace = -1;
            for (int i = clusters.faceStart[c]; i < clusters.faceStart[c + 1]; ++i) {
                const int f = clusters.faces[i];
                const double e = Error(f, int(r));
                if (bestFace < 0 || e < bestFace || (e == bestFace && f < seeds[r])) { bestFace = e; seeds[r] = f; }
            }
        }
    }

    // Regions left with no face (two seeds fell in one cluster) removed, the others renumbered in
    // order.
    void DropEmptyRegions()
    {
        std::vector<int> newIndex(seeds.size(), -1);
        for (int f = 0; f < n; ++f)
            if (label[f] >= 0) newIndex[label[f]] = 0;
        int kept = 0;
        for (size_t r = 0; r < seeds.size(); ++r)
            if (newIndex[r] == 0) {
                newIndex[r] = kept;
                seeds[kept] = seeds[r];
                proxy[kept] = proxy[r];
                ++kept;
            }
        seeds.resize(kept);
        proxy.resize(kept);
        for (int f = 0; f < n; ++f)
            if (label[f] >= 0) label[f] = newIndex[label[f]];
    }

    // A new region's proxy: its seed's normal (any unit vector for a zero-area seed).
    Vec SeedNormal(int face) const { return normal[face].SquaredNorm() > 0 ? normal[face] : Vec(0, 0, 1); }

    void AddSeed(int face)
    {
        seeds.push_back(face);
        proxy.push_back(SeedNormal(face));
    }

    // Splits regions: each (region, face) pair adds a seed at `face` (a face of `region`) and
    // restarts `region` itself from its face farthest from the new seed in the L2,1 sense, so the
    // two floodings start on opposite sides (a region spanning two flat parts separates cleanly).
    // One pass over the faces for all splits. `reuse[i]` >= 0 recycles that region index. On
    // clusters the restart face is sought outside the new seed's cluster (two seeds in one cluster
    // would flood as one) and a region with no such face is not split. Returns the seeds added.
    int SplitRegions(const std::vector<std::pair<int, int>> &splits, const std::vector<int> &reuse = {},
                     Level level = OnFaces)
    {
        std::vector<int> splitOf(seeds.size(), -1);
        for (size_t i = 0; i < splits.size(); ++i) splitOf[splits[i].first] = int(i);
        std::vector<double> best(splits.size(), 0.0);
        std::vector<int> far(splits.size(), -1);
        for (int f = 0; f < n; ++f) {
            int r = label[f];
            if (r < 0 || splitOf[r] < 0) continue;
            int i = splitOf[r];
            if (level == OnClusters && clusters.clusterOf[f] == clusters.clusterOf[splits[i].second]) continue;
            double e = area[f] * (normal[f] - normal[splits[i].second]).SquaredNorm();
            if (e > best[i]) { best[i] = e; far[i] = f; }
        }
        int added = 0;
        for (size_t i = 0; i < splits.size(); ++i) {
            int r = splits[i].first, face = splits[i].second;
            if (level == OnClusters && far[i] < 0) continue;
            if (far[i] >= 0 && far[i] != face) { seeds[r] = far[i]; proxy[r] = normal[far[i]]; }
            if (i < reuse.size() && reuse[i] >= 0) {
                seeds[reuse[i]] = face;
                proxy[reuse[i]] = SeedNormal(face);
            } else {
                AddSeed(face);
                ++added;
            }
        }
        return added;
    }

    // Random distinct seed faces, then one more in every component that got none.
    void InitialSeeds(int count, Result &res)
    {
        std::vector<int> comp(n, -1);
        std::vector<int> compFace;  // a face of each component
        std::vector<int> stack;
        for (int f = 0; f < n; ++f) {
            if (m.face[f].IsD() || comp[f] >= 0) continue;
            int c = int(compFace.size());
            compFace.push_back(f);
            comp[f] = c;
            stack.push_back(f);
            while (!stack.empty()) {
                int g = stack.back();
                stack.pop_back();
                for (int h : adj[g])
                    if (h >= 0 && comp[h] < 0) { comp[h] = c; stack.push_back(h); }
            }
        }
        res.components = int(compFace.size());
        std::vector<int> live;
        for (int f = 0; f < n; ++f)
            if (!m.face[f].IsD()) live.push_back(f);
        std::mt19937 rng(p.randomSeed);
        std::vector<char> taken(n, 0), compSeeded(compFace.size(), 0);
        count = std::min<int>(count, int(live.size()));
        for (int k = 0; k < count; ++k) {  // partial Fisher-Yates: distinct, reproducible
            int j = k + int(rng() % uint32_t(live.size() - k));
            std::swap(live[k], live[j]);
            AddSeed(live[k]);
            taken[live[k]] = 1;
            compSeeded[comp[live[k]]] = 1;
        }
        for (size_t c = 0; c < compFace.size(); ++c)
            if (!compSeeded[c]) AddSeed(compFace[c]);
    }

    // The share of the surface's area in regions whose largest normal deviation is within the
    // threshold angle (maxAngle: per region, from RegionStats).
    double AreaWithin(const std::vector<double> &maxAngle) const
    {
        double within = 0, total = 0;
        for (int f = 0; f < n; ++f) {
            if (label[f] < 0) continue;
            total += area[f];
            if (maxAngle[label[f]] <= p.thresholdAngleDeg) within += area[f];
        }
        return total > 0 ? within / total : 1;
    }

    // Per region: largest angle between a face normal and the proxy, and the face of largest error.
    void RegionStats(std::vector<double> &maxAngle, std::vector<int> &worstFace, std::vector<double> &regionError) const
    {
        size_t k = seeds.size();
        maxAngle.assign(k, 0.0);
        worstFace.assign(k, -1);
        regionError.assign(k, 0.0);
        std::vector<double> worst(k, -1.0);
        for (int f = 0; f < n; ++f) {
            int r = label[f];
            if (r < 0) continue;
            double e = Error(f, r);
            regionError[r] += e;
            if (f != seeds[r] && e > worst[r]) { worst[r] = e; worstFace[r] = f; }
            if (area[f] > negligibleArea) {
                double c = std::max(-1.0, std::min(1.0, normal[f] * proxy[r]));
                maxAngle[r] = std::max(maxAngle[r], std::acos(c) * 180.0 / M_PI);
            }
        }
    }

    // Fitted-proxy error of a region from its area sum A and area-weighted normal sum S:
    // sum a_f |n_f - S/|S||^2 = 2A - 2|S| (unit normals; zero-area faces contribute nothing).
    // Merging two regions therefore costs 2 (|S_a| + |S_b| - |S_a + S_b|).
    //
    // Incremental seeding can leave two seeds on one flat part while another region spans two
    // parts (a local minimum Lloyd cannot leave). Teleportation (as in CGAL's VSA) merges the
    // adjacent pair that is cheapest to merge, spends the freed seed in the region of largest error,
    // and keeps the change only when the Lloyd iterations that follow lower the total error.
    // `all`: Everything().
    void Teleport(Result &res, const Scope &all)
    {
        for (int attempt = 0; attempt < p.teleportAttempts && seeds.size() >= 3; ++attempt) {
            const size_t k = seeds.size();
            std::vector<Vec> sum(k, Vec(0, 0, 0));
            for (int f = 0; f < n; ++f)
                if (label[f] >= 0) sum[label[f]] += normal[f] * area[f];
            double bestCost = -1;
            int ra = -1, rb = -1;
            for (int f = 0; f < n; ++f)
                for (int g : adj[f]) {
                    if (g < 0 || label[f] < 0 || label[g] < 0 || label[f] >= label[g]) continue;
                    int a = label[f], b = label[g];
                    double cost = 2 * (sum[a].Norm() + sum[b].Norm() - (sum[a] + sum[b]).Norm());
                    if (bestCost < 0 || cost < bestCost) { bestCost = cost; ra = a; rb = b; }
                }
            if (ra < 0) return;
            std::vector<double> maxAngle, regionError;
            std::vector<int> worstFace;
            RegionStats(maxAngle, worstFace, regionError);
            int worst = -1;
            for (size_t r = 0; r < k; ++r)
                if (int(r) != ra && int(r) != rb && worstFace[r] >= 0 && (worst < 0 || regionError[r] > regionError[worst]))
                    worst = int(r);
            if (worst < 0 || !(bestCost < regionError[worst])) return;

            const double before = TotalError(all);
            std::vector<int> oldLabel = label, oldSeeds = seeds;
            std::vector<Vec> oldProxy = proxy;
            const int newSeed = worstFace[worst];
            for (int f = 0; f < n; ++f)  // merge rb into ra
                if (label[f] == rb) label[f] = ra;
            FitProxies(all);
            ReseedAtBestFaces(all);
            SplitRegions({{worst, newSeed}}, {rb});  // the freed index rb restarts in the worst region
            const double after = Lloyd(p.maxIterations, res, all);
            if (!(after < before * (1 - 1e-9))) {
                label = oldLabel; seeds = oldSeeds; proxy = oldProxy;
                return;
            }
        }
    }

    // The split regions and the regions next to them (the new regions included, which have no
    // face yet), as flags over the region count after the split.
    std::vector<char> SplitNeighbourhood(const std::vector<std::pair<int, int>> &splits) const
    {
        std::vector<char> regions(seeds.size() + splits.size(), 0);
        std::vector<char> split(seeds.size(), 0);
        for (const auto &s : splits) split[s.first] = regions[s.first] = 1;
        for (size_t i = seeds.size(); i < regions.size(); ++i) regions[i] = 1;
        for (int f = 0; f < n; ++f)
            if (label[f] >= 0 && split[label[f]])
                for (int g : adj[f])
                    if (g >= 0 && label[g] >= 0) regions[label[g]] = 1;
        return regions;
    }

    // Threshold seeding's rounds: Lloyd iterations, then a split of every region deviating more than
    // the threshold angle, until none does or the cap is reached.
    void ThresholdRounds(Result &res, int cap, const Scope &all, Level level)
    {
        // The tail of the seeding splits a few regions per round (a noisy bump here and there:
        // 25 rounds on armadillo, 37 on it refined to 832k faces, the last dozen splitting one
        // to five regions each). Lloyd iterations over the whole mesh for those dominated the
        // time, so a round on faces that splits few regions relaxes only them and their neighbours
        // (the regions farther away were relaxed already and keep their faces and proxies). A Lloyd
        // over the whole mesh after the tail was tried: it moved boundaries enough to start more
        // rounds of splits (55 rounds on the 832k mesh instead of 26) for 10% less error.
        Scope tail;
        bool local = false;
        for (;;) {
            ++res.seedingRounds;
            roundPercent = std::max(roundPercent, int(100.0 * seeds.size() / cap));
            Progress(roundPercent, level == OnClusters ? "VSA: Lloyd iterations on face clusters" : "VSA: Lloyd iterations");
            Lloyd(p.maxIterations, res, local ? tail : all, level);
            std::vector<double> maxAngle, regionError;
            std::vector<int> worstFace;
            RegionStats(maxAngle, worstFace, regionError);
            // the rounds are not known ahead: the share of the area whose region already meets
            // the threshold tells how far the seeding is (the cap's share stays small when the
            // automatic cap is far from binding)
            roundPercent = std::max(roundPercent, kSeedingFromPercent + int((99 - kSeedingFromPercent) * AreaWithin(maxAngle)));
            std::vector<int> split;
            for (size_t r = 0; r < seeds.size(); ++r)
                if (maxAngle[r] > p.thresholdAngleDeg && worstFace[r] >= 0) split.push_back(int(r));
            if (split.empty() || int(seeds.size()) >= cap) break;
            // Worst regions first, so the cap on the region count keeps the most useful seeds.
            std::sort(split.begin(), split.end(), [&](int a, int b) { return regionError[a] > regionError[b]; });
            std::vector<std::pair<int, int>> splits;
            for (int r : split)
                if (int(seeds.size() + splits.size()) < cap) splits.push_back({r, worstFace[r]});
            local = level == OnFaces && splits.size() * kLocalTailRatio < seeds.size();
            const std::vector<char> neighbourhood = local ? SplitNeighbourhood(splits) : std::vector<char>();
            if (SplitRegions(splits, {}, level) == 0) break;
            if (local) tail = Only(neighbourhood);
        }
    }

    void Run(Result &res)
    {
        const int liveFaces = m.fn;
        const Scope all = Everything();
        if (p.mode == ThresholdSeeding) {
            const int cap = res.regionCap = p.maxRegions > 0 ? p.maxRegions : AutomaticRegionCap(liveFaces);
            InitialSeeds(std::min(p.initialSeeds, cap), res);
            const int clusterSize = p.facesPerCluster > 0 ? p.facesPerCluster : AutomaticClusterSize(liveFaces);
            if (clusterSize >= 2) {
                Progress(kSeedingFromPercent, "VSA: face clusters");
                BuildClusters(clusterSize);
                res.clusters = clusters.Count();
                ThresholdRounds(res, cap, all, OnClusters);
                DropEmptyRegions();
                ReleaseClusters();
            }
            ThresholdRounds(res, cap, all, OnFaces);
        } else {
            const int target = std::min(p.maxRegions, liveFaces);
            InitialSeeds(std::min(p.initialSeeds, target), res);
            while (int(seeds.size()) < target) {
                ++res.seedingRounds;
                roundPercent = int(100.0 * seeds.size() / target);
                Progress(roundPercent, "VSA: incremental seeding");
                Lloyd(std::min(p.relaxationsPerSeed, p.maxIterations), res, all);
                std::vector<double> maxAngle, regionError;
                std::vector<int> worstFace;
                RegionStats(maxAngle, worstFace, regionError);
                int best = -1;
                for (size_t r = 0; r < seeds.size(); ++r)
                    if (worstFace[r] >= 0 && (best < 0 || regionError[r] > regionError[best])) best = int(r);
                if (best < 0) break;  // every region is a single face
                SplitRegions({{best, worstFace[best]}});
            }
            ++res.seedingRounds;
            Lloyd(p.maxIterations, res, all);
            Teleport(res, all);
        }
        // Labels and proxies are those of the last Lloyd step (consistent with each other).
        std::vector<double> maxAngle, regionError;
        std::vector<int> worstFace;
        RegionStats(maxAngle, worstFace, regionError);
        res.faceRegion = label;
        res.seedFace = seeds;
        res.proxyNormal = proxy;
        res.regions = int(seeds.size());
        res.l21Error = TotalError(all);
        res.maxDeviationDeg = maxAngle.empty() ? 0.0 : *std::max_element(maxAngle.begin(), maxAngle.end());
    }
};

}  // namespace vcg_ext

#endif
