// Orientation independence: a consistently flipped copy of a mesh (whichever corner each flipped
// face starts at) gives the same result mirrored. Q-Morph on the same front: the same vertices
// bit for bit, the same faces reversed, the same counts and quality; VSA: the same region ids;
// the whole pipeline (Q-Morph re-meshing first or not) on CAD parts and a scan: the same quad mesh
// mirrored, every figure of the report bit for bit, with All quads on too.
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <set>

#include "quad_checks.h"
#include "test_mesh.h"
#include <vcg/complex/append.h>
#include <vcg_ext/common/region_ids.h>
#include <vcg_ext/geodesic_straightening.h>
#include <vcg_ext/polyline_embedding.h>
#include <vcg_ext/qmorph.h>
#include <vcg_ext/vsa_segmentation.h>

using namespace qmf_test;

namespace {

typedef vcg_ext::QMorph<TMesh> QM;
typedef vcg_ext::VSASegmentation<TMesh> Vsa;

// The two ways a face is flipped in practice: MeshLab's 'Invert Faces Orientation' swaps corners 0
// and 1 (vcg's FlipMesh), other tools swap corners 1 and 2. The selected face-edges follow.
enum FlipKind { SwapCorners01, SwapCorners12 };

void FlipAll(TMesh &m, FlipKind kind)
{
    for (auto &f : m.face) {
        if (f.IsD()) continue;
        bool sel[3];
        for (int k = 0; k < 3; ++k) { sel[k] = f.IsFaceEdgeS(k); f.ClearFaceEdgeS(k); }
        // edge k runs from corner k to corner k+1; after the swap each edge sits at another index
        const int to[2][3] = {{0, 2, 1}, {2, 1, 0}};
        if (kind == SwapCorners01) std::swap(f.V(0), f.V(1));
        else std::swap(f.V(1), f.V(2));
        for (int k = 0; k < 3; ++k)
            if (sel[k]) f.SetFaceEdgeS(to[kind][k]);
    }
    vcg::tri::UpdateNormal<TMesh>::PerFaceNormalized(m);
}

// Faces as vertex triples from their lowest vertex on; `reversed` reads them the other way round.
std::multiset<std::array<int, 3>> FaceSet(const TMesh &m, bool reversed)
{
    std::multiset<std::array<int, 3>> s;
    for (auto &f : m.face) {
        if (f.IsD()) continue;
        std::array<int, 3> t{{int(vcg::tri::Index(m, f.cV(0))), int(vcg::tri::Index(m, f.cV(1))), int(vcg::tri::Index(m, f.cV(2)))}};
        if (reversed) std::swap(t[1], t[2]);
        const int r = int(std::min_element(t.begin(), t.end()) - t.begin());
        s.insert({t[r], t[(r + 1) % 3], t[(r + 2) % 3]});
    }
    return s;
}

// The run's log line without its time (the last field).
std::string SummaryWithoutTime(const QM::Result &r)
{
    const std::string s = r.Summary();
    return s.substr(0, s.rfind(';'));
}

// Q-Morph (after `before`, e.g. filters 1-3) on the input and on its flipped copies: the same mesh mirrored.
void ExpectSameQMorphMirrored(const TMesh &input, const std::function<void(TMesh &)> &before = [](TMesh &) {},
                              const QM::Params &p = QM::Params())
{
    TMesh a;
    vcg::tri::Append<TMesh, TMesh>::MeshCopy(a, const_cast<TMesh &>(input));
    before(a);
    const QM::Result ra = QM::Apply(a, p);
    ASSERT_EQ(ra.error, "");
    for (FlipKind kind : {SwapCorners01, SwapCorners12}) {
        SCOPED_TRACE(kind == SwapCorners01 ? "corners 0 and 1 swapped" : "corners 1 and 2 swapped");
        TMesh b;
        vcg::tri::Append<TMesh, TMesh>::MeshCopy(b, const_cast<TMesh &>(input));
        FlipAll(b, kind);
        before(b);
        const QM::Result rb = QM::Apply(b, p);
        ASSERT_EQ(rb.error, "");
        EXPECT_EQ(rb.quads, ra.quads);
        EXPECT_EQ(rb.triangles, ra.triangles);
        // the log lines, figures printed to 3 decimals; the figures themselves bit for bit
        EXPECT_EQ(SummaryWithoutTime(rb), SummaryWithoutTime(ra));
        EXPECT_EQ(rb.RemeshSummary(), ra.RemeshSummary());
        EXPECT_EQ(rb.QualitySummary(), ra.QualitySummary());
        EXPECT_EQ(rb.quality.meanJacobian, ra.quality.meanJacobian);
        EXPECT_EQ(rb.quality.minJacobian, ra.quality.minJacobian);
        EXPECT_EQ(rb.quality.p5Jacobian, ra.quality.p5Jacobian);
        EXPECT_EQ(rb.quality.quadAreaFraction, ra.quality.quadAreaFraction);
        EXPECT_EQ(rb.quality.quadsBelow03, ra.quality.quadsBelow03);
        EXPECT_EQ(rb.quality.irregularVertices, ra.quality.irregularVertices);
        EXPECT_EQ(rb.quality.flippedFaces, ra.quality.flippedFaces);
        EXPECT_EQ(rb.quality.foldedQuads, ra.quality.foldedQuads);
        ASSERT_EQ(b.vert.size(), a.vert.size());
        int moved = 0;
        for (size_t i = 0; i < a.vert.size(); ++i) moved += !(a.vert[i].cP() == b.vert[i].cP());
        EXPECT_EQ(moved, 0) << "vertices placed differently";
        EXPECT_TRUE(FaceSet(b, true) == FaceSet(a, false)) << "the faces are not the same ones reversed";
        EXPECT_TRUE(SelectedEdges(b) == SelectedEdges(a)) << "the front differs";
    }
}

// Filters 1-3 on m (defaults): the split mesh with its front selected, as Q-Morph gets it.
void SplitAlongRegionFronts(TMesh &m)
{
    Vsa::Segment(m, Vsa::Params());
    std::vector<int> labels;
    ASSERT_EQ(vcg_ext::RegionIds<TMesh>::Read(m, labels), "");
    typedef vcg_ext::RegionBoundarySmoothing<TMesh> Smoothing;
    const Smoothing::Result s = Smoothing::Smooth(m, labels, Smoothing::Params());
    ASSERT_EQ(s.error, "");
    TMesh poly;
    Smoothing::BuildEdgeMesh(Smoothing::ToPolylines(s.topology, s.curves), poly);
    typedef vcg_ext::PolylineEmbedding<TMesh> Embedding;
    ASSERT_EQ(Embedding::Embed(m, poly, Embedding::Params()).error, "");
}

}  // namespace

TEST(Orientation, QMorphOnAFlippedFandiskIsTheSameMeshMirrored)
{
    TMesh m;
    ASSERT_TRUE(LoadOff(m, MeshDir() + "/fandisk.off"));
    SplitAlongRegionFronts(m);
    ExpectSameQMorphMirrored(m);
}

// The four filters as the plugin runs them (Q-Morph re-meshing first at the automatic length) and
// as the paper does (the input's triangles), on a CAD part with sharp creases and on a smooth scan.
void ExpectWholePipelineMirrored(const char *name)
{
    TMesh m;
    ASSERT_TRUE(LoadOff(m, MeshDir() + "/" + name + ".off"));
    for (bool remesh : {true, false}) {
        SCOPED_TRACE(remesh ? "re-meshed first" : "the input's triangles");
        QM::Params p;
        p.remeshFirst = remesh;
        ExpectSameQMorphMirrored(m, SplitAlongRegionFronts, p);
    }
}

TEST(Orientation, WholePipelineOnAFlippedFandiskIsTheSameMeshMirrored) { ExpectWholePipelineMirrored("fandisk"); }

TEST(Orientation, WholePipelineOnAFlippedElephantIsTheSameMeshMirrored) { ExpectWholePipelineMirrored("elephant"); }

// All quads on: the final split into quads (qmorph/all_quads.h) numbers its new points and rounds
// its face centres the same way on the flipped copy. At the filter's defaults (re-meshing first).
TEST(Orientation, WholePipelineWithAllQuadsOnAFlippedFandiskAndElephantIsTheSameMeshMirrored)
{
    for (const char *name : {"fandisk", "elephant"}) {
        SCOPED_TRACE(name);
        TMesh m;
        ASSERT_TRUE(LoadOff(m, MeshDir() + "/" + name + ".off"));
        QM::Params p;
        p.allQuads = true;
        ExpectSameQMorphMirrored(m, SplitAlongRegionFronts, p);
    }
}

// The four filters on coarse CAD tessellations with slivers.
TEST(Orientation, WholePipelineOnAFlippedJointAndAnchorIsTheSameMeshMirrored)
{
    for (const char *name : {"joint", "anchor"}) {
        SCOPED_TRACE(name);
        TMesh m;
        ASSERT_TRUE(LoadOff(m, MeshDir() + "/" + name + ".off"));
        ExpectSameQMorphMirrored(m, SplitAlongRegionFronts);
    }
}

TEST(Orientation, QMorphOnAFlippedCubeWithCreasesSelectedIsTheSameMeshMirrored)
{
    TMesh m;
    MakeCube(m, 5, 0.3f, 7);
    ASSERT_GT(SelectCreases(m, 45), 0);
    ExpectSameQMorphMirrored(m);
    QM::Params remeshed;  // at a tenth of the side (the automatic length, 1% of the diagonal, is slow here)
    const double kTenthOfTheSide = 0.1;
    remeshed.targetEdgeLength = kTenthOfTheSide;
    ExpectSameQMorphMirrored(m, [](TMesh &) {}, remeshed);
}

TEST(Orientation, VsaGivesTheSameRegionsOnAFlippedCopy)
{
    for (const char *name : {"fandisk", "joint", "anchor"}) {
        SCOPED_TRACE(name);
        TMesh a;
        ASSERT_TRUE(LoadOff(a, MeshDir() + "/" + name + ".off"));
        for (FlipKind kind : {SwapCorners01, SwapCorners12}) {
            TMesh b;
            vcg::tri::Append<TMesh, TMesh>::MeshCopy(b, a);
            FlipAll(b, kind);
            const Vsa::Result rb = Vsa::Segment(b, Vsa::Params());
            TMesh c;
            vcg::tri::Append<TMesh, TMesh>::MeshCopy(c, a);
            const Vsa::Result ra = Vsa::Segment(c, Vsa::Params());
            ASSERT_EQ(ra.error, "");
            EXPECT_EQ(rb.faceRegion, ra.faceRegion);
            EXPECT_EQ(rb.l21Error, ra.l21Error);
        }
    }
}
