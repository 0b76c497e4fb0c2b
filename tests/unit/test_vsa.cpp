#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "test_mesh.h"
#include <vcg_ext/common/face_clusters.h>
#include <vcg_ext/vsa_segmentation.h>

using namespace qmf_test;
typedef vcg_ext::VSASegmentation<TMesh> VSA;
typedef vcg::Point3d D3;

namespace {

// Bumps on the unit sphere (AutomaticRegionCap test): radius 1 + h sin(k x) sin(k y) sin(k z).
constexpr float kBumpHeight = 0.1f, kBumpFrequency = 20.f;

D3 UnitNormal(const TFace &f)
{
    D3 a = D3::Construct(f.cP(0)), b = D3::Construct(f.cP(1)), c = D3::Construct(f.cP(2));
    return ((b - a) ^ (c - a)).Normalize();
}

// Every label in 0..K-1, every region non-empty and edge-connected (BFS inside the region).
void ExpectValidPartition(TMesh &m, const VSA::Result &r)
{
    ASSERT_EQ(r.faceRegion.size(), m.face.size());
    std::vector<int> size(r.regions, 0);
    for (auto &f : m.face) {
        int id = r.faceRegion[vcg::tri::Index(m, f)];
        ASSERT_GE(id, 0);
        ASSERT_LT(id, r.regions);
        ASSERT_EQ(int(f.Q()), id) << "face quality holds the region id";
        size[id]++;
    }
    vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
    std::vector<char> seen(m.face.size(), 0);
    for (int id = 0; id < r.regions; ++id) {
        ASSERT_GT(size[id], 0) << "region " << id << " is empty";
        int start = -1;
        for (size_t i = 0; i < m.face.size() && start < 0; ++i)
            if (r.faceRegion[i] == id) start = int(i);
        std::vector<int> stack{start};
        seen[start] = 1;
        int reached = 0;
        while (!stack.empty()) {
            int f = stack.back();
            stack.pop_back();
            ++reached;
            for (int k = 0; k < 3; ++k) {
                int g = int(vcg::tri::Index(m, m.face[f].FFp(k)));
                if (!seen[g] && r.faceRegion[g] == id) { seen[g] = 1; stack.push_back(g); }
            }
        }
        EXPECT_EQ(reached, size[id]) << "region " << id << " is not edge-connected";
    }
}

// Largest angle (deg) between a face normal and the area-weighted mean normal of its region,
// computed independently of the core.
double MaxRegionDeviation(TMesh &m, const std::vector<int> &label, int regions)
{
    std::vector<D3> sum(regions, D3(0, 0, 0));
    for (auto &f : m.face) {
        D3 a = D3::Construct(f.cP(0)), b = D3::Construct(f.cP(1)), c = D3::Construct(f.cP(2));
        sum[label[vcg::tri::Index(m, f)]] += (b - a) ^ (c - a);  // 2 * area * normal
    }
    double worst = 0;
    for (auto &f : m.face) {
        D3 n = UnitNormal(f), p = sum[label[vcg::tri::Index(m, f)]];
        p.Normalize();
        worst = std::max(worst, std::acos(std::max(-1.0, std::min(1.0, n * p))) * 180 / M_PI);
    }
    return worst;
}

}  // namespace

TEST(VSA, CubeFixedSixRegionsAreTheSixSidesWithZeroError)
{
    TMesh m;
    MakeCube(m, 6, 0.35f, 7);
    VSA::Params p;
    p.mode = VSA::FixedRegionCount;
    p.maxRegions = 6;
    for (uint32_t seed : {0u, 1u, 2u, 3u}) {
        p.randomSeed = seed;
        VSA::Result r = VSA::Segment(m, p);
        ASSERT_EQ(r.error, "");
        ASSERT_EQ(r.regions, 6);
        ExpectValidPartition(m, r);
        EXPECT_NEAR(r.l21Error, 0.0, 1e-9) << "seed " << seed;
        // each region is exactly one side: all its faces share one axis normal, sides distinct
        std::set<int> axes;
        for (int id = 0; id < 6; ++id) {
            std::set<int> regionAxes;
            for (auto &f : m.face) {
                if (r.faceRegion[vcg::tri::Index(m, f)] != id) continue;
                D3 n = UnitNormal(f);
                int axis = 0;
                for (int k = 1; k < 3; ++k) if (std::fabs(n[k]) > std::fabs(n[axis])) axis = k;
                regionAxes.insert(axis * 2 + (n[axis] > 0));
            }
            ASSERT_EQ(regionAxes.size(), 1u) << "region " << id << " spans several sides (seed " << seed << ")";
            axes.insert(*regionAxes.begin());
        }
        EXPECT_EQ(axes.size(), 6u);
        int perSide = 6 * 6 * 2;
        for (int id = 0; id < 6; ++id)
            EXPECT_EQ(std::count(r.faceRegion.begin(), r.faceRegion.end(), id), perSide);
    }
}

TEST(VSA, ThresholdModeKeepsEveryRegionWithinTheAngle)
{
    TMesh m;
    MakeCube(m, 5, 0.3f, 3);
    for (double thr : {60.0, 30.0, 10.0}) {
        VSA::Params p;
        p.thresholdAngleDeg = thr;
        VSA::Result r = VSA::Segment(m, p);
        ASSERT_EQ(r.error, "");
        ExpectValidPartition(m, r);
        EXPECT_LE(r.maxDeviationDeg, thr + 1e-6);
        EXPECT_LE(MaxRegionDeviation(m, r.faceRegion, r.regions), thr + 1e-6);
        if (thr < 45) { EXPECT_GE(r.regions, 6) << "two cube sides in one region deviate by 45 deg"; }
    }
    TMesh sphere;
    MakeSphere(sphere, 3);
    VSA::Params p;
    VSA::Result r = VSA::Segment(sphere, p);
    ExpectValidPartition(sphere, r);
    EXPECT_GT(r.regions, 2);
    EXPECT_LE(MaxRegionDeviation(sphere, r.faceRegion, r.regions), 60.0 + 1e-6);
}

TEST(VSA, CylinderCapsAreSeparatedFromTheSide)
{
    TMesh m;
    MakeCylinder(m, 32, 6, 1.f, 3.f, 3);
    VSA::Params p;
    p.thresholdAngleDeg = 30;  // a region mixing cap and side faces deviates >= 45 deg
    VSA::Result r = VSA::Segment(m, p);
    ASSERT_EQ(r.error, "");
    ExpectValidPartition(m, r);
    std::vector<int> kinds(r.regions, 0);  // bit 1: cap face, bit 2: side face
    for (auto &f : m.face) {
        D3 n = UnitNormal(f);
        kinds[r.faceRegion[vcg::tri::Index(m, f)]] |= std::fabs(n[2]) > 0.99 ? 1 : 2;
    }
    int capRegions = 0;
    for (int k : kinds) {
        EXPECT_NE(k, 3) << "a region holds both cap and side faces";
        capRegions += k == 1;
    }
    EXPECT_EQ(capRegions, 2);
}

TEST(VSA, ErrorMatchesHandComputation)
{
    // Two faces on the edge (0,0,0)-(1,0,0): normal +z with area 1/2, normal +y with area 1.
    // One region: N = (0, 1, 1/2) / |.| = (0, 2, 1)/sqrt5;
    // E = 1/2 * (2 - 2/sqrt5) + 1 * (2 - 4/sqrt5) = 3 - sqrt5.
    TMesh m;
    Build(m, {P3(0, 0, 0), P3(1, 0, 0), P3(0, 1, 0), P3(0, 0, 2)}, {{0, 1, 2}, {1, 0, 3}});
    VSA::Params p;
    p.mode = VSA::FixedRegionCount;
    p.maxRegions = 1;
    VSA::Result r = VSA::Segment(m, p);
    ASSERT_EQ(r.regions, 1);
    EXPECT_NEAR(r.l21Error, 3.0 - std::sqrt(5.0), 1e-7);
    EXPECT_NEAR(r.proxyNormal[0][1], 2 / std::sqrt(5.0), 1e-7);
    EXPECT_NEAR(r.proxyNormal[0][2], 1 / std::sqrt(5.0), 1e-7);
    EXPECT_NEAR(VSA::L21Error(m, r.faceRegion, r.proxyNormal), 3.0 - std::sqrt(5.0), 1e-7);
    p.maxRegions = 2;
    r = VSA::Segment(m, p);
    ASSERT_EQ(r.regions, 2);
    EXPECT_NEAR(r.l21Error, 0.0, 1e-12);
    EXPECT_NE(r.faceRegion[0], r.faceRegion[1]);
}

// The random seed decides the initial seed faces: the same seed gives the same labels, other
// seeds start elsewhere and give other labels (a sphere has no preferred place for a region).
TEST(VSA, SameSeedSameLabelsOtherSeedOtherLabels)
{
    TMesh m;
    MakeSphere(m, 3);
    VSA::Params p;
    p.randomSeed = 42;
    VSA::Result a = VSA::Segment(m, p), b = VSA::Segment(m, p);
    EXPECT_EQ(a.faceRegion, b.faceRegion);
    EXPECT_EQ(a.l21Error, b.l21Error);
    int differing = 0;
    for (uint32_t seed : {1u, 7u, 1234u}) {
        p.randomSeed = seed;
        differing += VSA::Segment(m, p).faceRegion != a.faceRegion;
    }
    EXPECT_EQ(differing, 3) << "another seed must start from other faces";
    p.randomSeed = 42;
    p.mode = VSA::FixedRegionCount;
    p.maxRegions = 9;
    a = VSA::Segment(m, p);
    b = VSA::Segment(m, p);
    EXPECT_EQ(a.faceRegion, b.faceRegion);
    EXPECT_EQ(a.regions, 9);
    p.randomSeed = 7;
    EXPECT_NE(VSA::Segment(m, p).faceRegion, a.faceRegion);
}

TEST(VSA, EveryComponentGetsARegion)
{
    TMesh m, other;
    MakeCube(m, 3);
    MakeSphere(other, 2);
    for (auto &v : other.vert) v.P() += P3(5, 0, 0);
    vcg::tri::Append<TMesh, TMesh>::Mesh(m, other);
    VSA::Params p;
    p.initialSeeds = 1;
    p.mode = VSA::FixedRegionCount;
    p.maxRegions = 1;  // fewer than the components: each still gets its own
    VSA::Result r = VSA::Segment(m, p);
    EXPECT_EQ(r.components, 2);
    EXPECT_EQ(r.regions, 2);
    ExpectValidPartition(m, r);
}

TEST(VSA, ZeroAreaFacesAreLabelledWithoutNaN)
{
    TMesh m;  // a strip with a collinear (zero-area) face in the middle
    Build(m, {P3(0, 0, 0), P3(1, 0, 0), P3(2, 0, 0), P3(0, 1, 0), P3(2, 1, 0), P3(1, 0, 1)},
          {{0, 1, 3}, {1, 2, 4}, {0, 2, 1}, {1, 4, 3}, {0, 5, 2}});
    VSA::Params p;
    VSA::Result r = VSA::Segment(m, p);
    ASSERT_EQ(r.error, "");
    EXPECT_TRUE(std::isfinite(r.l21Error));
    for (auto &n : r.proxyNormal) EXPECT_TRUE(std::isfinite(n[0]) && std::isfinite(n[1]) && std::isfinite(n[2]));
    for (auto &f : m.face) EXPECT_GE(r.faceRegion[vcg::tri::Index(m, f)], 0);
}

TEST(VSA, ParametersOutOfRangeAreRejected)
{
    TMesh m;
    MakeCube(m, 2);
    for (double a : {0.0, -5.0, 180.0, 200.0}) {
        VSA::Params p;
        p.thresholdAngleDeg = a;
        EXPECT_NE(VSA::Segment(m, p).error, "") << a;
    }
    VSA::Params p;
    p.maxRegions = -1;
    EXPECT_NE(VSA::Segment(m, p).error.find("max regions"), std::string::npos);
    p.maxRegions = 0;  // automatic in threshold mode, but a fixed count needs a number
    p.mode = VSA::FixedRegionCount;
    EXPECT_NE(VSA::Segment(m, p).error.find("max regions"), std::string::npos);
    p = VSA::Params();
    p.maxIterations = 0;
    EXPECT_NE(VSA::Segment(m, p).error, "");
    p = VSA::Params();
    p.initialSeeds = 0;
    EXPECT_NE(VSA::Segment(m, p).error, "");
    TMesh empty;
    EXPECT_NE(VSA::Segment(empty, VSA::Params()).error, "");
}

TEST(VSA, FandiskThresholdRegionsFollowTheShape)
{
    TMesh m;
    ASSERT_TRUE(LoadOff(m, MeshDir() + "/fandisk.off")) << "run scripts/setup.sh to extract the test meshes";
    VSA::Params p;
    VSA::Result r = VSA::Segment(m, p);
    ASSERT_EQ(r.error, "");
    ExpectValidPartition(m, r);
    EXPECT_LE(MaxRegionDeviation(m, r.faceRegion, r.regions), 60.0 + 1e-6);
    EXPECT_GE(r.regions, 6);
    EXPECT_LE(r.regions, 60);
}

// Unmerged vertices and inconsistent orientation are refused (the regions would be meaningless)
// and the mesh is left as it was; what VSA can segment but the later filters refuse (non-manifold,
// zero-area and duplicate faces) is segmented with a warning naming the fix; an inward-oriented
// mesh is fine.
TEST(VSA, InputProblemsAreRefusedOrWarnedWithTheirFix)
{
    TMesh cube;
    MakeCube(cube, 3);
    {
        TMesh soup;  // every face with its own vertices
        std::vector<P3> v;
        std::vector<std::array<int, 3>> f;
        for (auto &face : cube.face) {
            f.push_back({int(v.size()), int(v.size()) + 1, int(v.size()) + 2});
            for (int k = 0; k < 3; ++k) v.push_back(face.V(k)->P());
        }
        Build(soup, v, f);
        for (auto &face : soup.face) face.Q() = -7;
        VSA::Result r = VSA::Segment(soup, VSA::Params());
        EXPECT_NE(r.error.find("triangle soup"), std::string::npos) << r.error;
        EXPECT_NE(r.error.find("'Merge Close Vertices'"), std::string::npos) << r.error;
        for (auto &face : soup.face) EXPECT_EQ(face.Q(), -7) << "the mesh must be left as it was";
    }
    {
        TMesh m;
        vcg::tri::Append<TMesh, TMesh>::MeshCopy(m, cube);
        std::swap(m.face[5].V(1), m.face[5].V(2));  // one face flipped
        VSA::Result r = VSA::Segment(m, VSA::Params());
        EXPECT_NE(r.error.find("'Re-Orient all faces coherentely'"), std::string::npos) << r.error;
    }
    {
        TMesh m;  // the cube with a fin on one of its edges
        vcg::tri::Append<TMesh, TMesh>::MeshCopy(m, cube);
        const int a = int(vcg::tri::Index(m, m.face[0].V(0))), b = int(vcg::tri::Index(m, m.face[0].V(1)));
        auto vi = vcg::tri::Allocator<TMesh>::AddVertex(m, P3(3, 3, 3));
        vcg::tri::Allocator<TMesh>::AddFace(m, &m.vert[a], &m.vert[b], &*vi);
        VSA::Result r = VSA::Segment(m, VSA::Params());
        EXPECT_EQ(r.error, "");
        EXPECT_NE(r.warning.find("'Repair non Manifold Edges by removing faces'"), std::string::npos) << r.warning;
        EXPECT_GT(r.regions, 0);
    }
    {
        TMesh m;
        vcg::tri::Append<TMesh, TMesh>::MeshCopy(m, cube);
        for (auto &f : m.face) std::swap(f.V(1), f.V(2));  // every face inward
        VSA::Result r = VSA::Segment(m, VSA::Params());
        EXPECT_EQ(r.error, "");
        EXPECT_EQ(r.warning, "");
    }
}

// A sphere of 82k faces covered with bumps steep enough that 200 regions (the old default cap)
// leave faces far beyond the threshold angle: the automatic cap (Max regions 0, the default: one
// region per 4 faces) lets the seeding go on until every face is within the angle of its
// region's normal. The tail of that seeding relaxes only the split regions and their neighbours:
// every region must still be one edge-connected piece whose proxy is its faces' mean normal.
TEST(VSA, AutomaticRegionCapGrowsWithTheMeshSoTheThresholdHolds)
{
    TMesh bumpy;
    MakeSphere(bumpy, 6);
    for (auto &v : bumpy.vert) {
        const vcg::Point3f p = v.P();
        v.P() *= 1 + kBumpHeight * std::sin(kBumpFrequency * p[0]) * std::sin(kBumpFrequency * p[1]) * std::sin(kBumpFrequency * p[2]);
    }
    vcg::tri::UpdateBounding<TMesh>::Box(bumpy);
    vcg::tri::UpdateNormal<TMesh>::PerFaceNormalized(bumpy);
    TMesh capped;
    vcg::tri::Append<TMesh, TMesh>::MeshCopy(capped, bumpy);

    VSA::Params old;
    old.maxRegions = 200;
    const VSA::Result r200 = VSA::Segment(capped, old);
    ASSERT_EQ(r200.error, "");
    EXPECT_EQ(r200.regions, 200);
    EXPECT_GT(MaxRegionDeviation(capped, r200.faceRegion, r200.regions), 60.0 + 10) << "the case needs more regions";

    const VSA::Params defaults;
    ASSERT_EQ(defaults.maxRegions, 0) << "the automatic cap is the default";
    const VSA::Result r = VSA::Segment(bumpy, defaults);
    ASSERT_EQ(r.error, "");
    ExpectValidPartition(bumpy, r);
    EXPECT_EQ(r.regionCap, int(bumpy.fn) / VSA::kFacesPerAutoRegion);
    EXPECT_GT(r.regions, 200);
    EXPECT_LT(r.regions, r.regionCap) << "stopped by the angle, not the cap";
    EXPECT_LE(r.maxDeviationDeg, 60.0 + 1e-6);
    EXPECT_LE(MaxRegionDeviation(bumpy, r.faceRegion, r.regions), 60.0 + 1e-6);
    std::vector<D3> sum(r.regions, D3(0, 0, 0));
    for (auto &f : bumpy.face) {
        const D3 a = D3::Construct(f.cP(0)), b = D3::Construct(f.cP(1)), c = D3::Construct(f.cP(2));
        sum[r.faceRegion[vcg::tri::Index(bumpy, f)]] += (b - a) ^ (c - a);
    }
    for (int id = 0; id < r.regions; ++id)
        EXPECT_GT(r.proxyNormal[id] * (sum[id] / sum[id].Norm()), 1 - 1e-9) << "region " << id << "'s proxy is stale";
}

// The coarse level of big meshes: every face in exactly one cluster, each cluster edge-connected,
// at most the size asked, within its cone (so none spans two sides of a cube), and the cluster
// adjacency symmetric and exactly the clusters' shared edges.
TEST(FaceClusters, ClustersAreConnectedConesOfBoundedSizeWithSymmetricAdjacency)
{
    TMesh m;
    MakeCube(m, 12);
    vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
    const int n = int(m.face.size());
    std::vector<std::array<int, 3>> adj(n);
    std::vector<D3> normal(n);
    for (int f = 0; f < n; ++f) {
        normal[f] = UnitNormal(m.face[f]);
        for (int k = 0; k < 3; ++k) adj[f][k] = int(vcg::tri::Index(m, m.face[f].FFp(k)));
    }
    const int maxFaces = 10;
    const vcg_ext::FaceClusters c = vcg_ext::FaceClusters::Grow(adj, normal, std::vector<char>(n, 1), maxFaces, 15.0);
    ASSERT_EQ(int(c.faces.size()), n);
    EXPECT_GE(c.Count(), (n + maxFaces - 1) / maxFaces);
    std::vector<int> times(n, 0);
    for (int id = 0; id < c.Count(); ++id) {
        const int size = c.faceStart[id + 1] - c.faceStart[id];
        ASSERT_GE(size, 1);
        EXPECT_LE(size, maxFaces);
        const int first = c.faces[c.faceStart[id]];
        std::set<int> members, reached{first};
        for (int i = c.faceStart[id]; i < c.faceStart[id + 1]; ++i) {
            const int f = c.faces[i];
            ++times[f];
            members.insert(f);
            EXPECT_EQ(c.clusterOf[f], id);
            EXPECT_GT(normal[f] * normal[first], 0.999) << "a cluster spans two sides of the cube";
        }
        std::vector<int> stack{first};
        while (!stack.empty()) {
            const int f = stack.back();
            stack.pop_back();
            for (int g : adj[f])
                if (members.count(g) && reached.insert(g).second) stack.push_back(g);
        }
        EXPECT_EQ(reached.size(), members.size()) << "cluster " << id << " is not edge-connected";
    }
    for (int f = 0; f < n; ++f) ASSERT_EQ(times[f], 1);
    std::set<std::pair<int, int>> listed, shared;
    for (int id = 0; id < c.Count(); ++id)
        for (int i = c.neighbourStart[id]; i < c.neighbourStart[id + 1]; ++i)
            EXPECT_TRUE(listed.insert({id, c.neighbours[i]}).second) << "a neighbour listed twice";
    for (int f = 0; f < n; ++f)
        for (int g : adj[f])
            if (c.clusterOf[g] != c.clusterOf[f]) shared.insert({c.clusterOf[f], c.clusterOf[g]});
    EXPECT_EQ(listed, shared);
}

// Threshold seeding that starts on face clusters (the default from 131,072 faces; forced here on
// armadillo's 52k faces) meets the threshold angle on the faces, gives a valid partition, does
// most of its Lloyd iterations on the clusters and ends with about the regions and the L2,1 error
// of seeding on faces alone. Below the automatic size the seeding stays on faces.
TEST(VSA, BigMeshesAreSeededOnFaceClustersWithinTheAngle)
{
    TMesh onFaces, onClusters;
    ASSERT_TRUE(LoadOff(onFaces, MeshDir() + "/armadillo.off")) << "run scripts/setup.sh to extract the test meshes";
    vcg::tri::Append<TMesh, TMesh>::MeshCopy(onClusters, onFaces);
    ASSERT_LT(onFaces.fn, VSA::kClusterCount * VSA::kMinClusterFaces);
    EXPECT_EQ(VSA::AutomaticClusterSize(VSA::kClusterCount * VSA::kMinClusterFaces - 1), 1);
    EXPECT_EQ(VSA::AutomaticClusterSize(VSA::kClusterCount * VSA::kMinClusterFaces), VSA::kMinClusterFaces);

    const VSA::Params defaults;
    const VSA::Result r0 = VSA::Segment(onFaces, defaults);
    ASSERT_EQ(r0.error, "");
    EXPECT_EQ(r0.clusters, 0) << "a mesh under the automatic size is seeded on faces";
    EXPECT_EQ(r0.clusterIterations, 0);

    VSA::Params p;
    p.facesPerCluster = 8;
    const VSA::Result r = VSA::Segment(onClusters, p);
    ASSERT_EQ(r.error, "");
    ExpectValidPartition(onClusters, r);
    EXPECT_GE(r.clusters, onClusters.fn / p.facesPerCluster);
    EXPECT_LT(r.clusters, onClusters.fn / 2);
    EXPECT_LE(r.maxDeviationDeg, defaults.thresholdAngleDeg + 1e-6);
    EXPECT_LE(MaxRegionDeviation(onClusters, r.faceRegion, r.regions), defaults.thresholdAngleDeg + 1e-6);
    EXPECT_GT(r.clusterIterations, r.lloydIterations) << "most iterations on the clusters";
    EXPECT_LT(r.lloydIterations, r0.lloydIterations / 2) << "r0: " << r0.lloydIterations;
    EXPECT_NEAR(r.regions, r0.regions, 0.15 * r0.regions);
    EXPECT_NEAR(r.l21Error, r0.l21Error, 0.05 * r0.l21Error);
    EXPECT_NEAR(r.l21Error, VSA::L21Error(onClusters, r.faceRegion, r.proxyNormal), 1e-9 * r.l21Error);
}
