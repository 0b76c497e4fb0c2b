#include <gtest/gtest.h>

#include <set>

#include "test_mesh.h"
#include <vcg_ext/mesh_checks.h>
#include <vcg_ext/qmorph.h>

using namespace qmf_test;
typedef vcg_ext::QMorph<TMesh> QM;

namespace {

// Selects (both sides) the mesh edges whose two faces differ in normal by more than `deg`.
void SelectCreases(TMesh &m, double deg)
{
    vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
    vcg::tri::UpdateNormal<TMesh>::PerFaceNormalized(m);
    for (auto &f : m.face)
        for (int k = 0; k < 3; ++k) {
            TFace *g = f.FFp(k);
            if (g != &f && vcg::Angle(f.N(), g->N()) > deg * M_PI / 180) f.SetFaceEdgeS(k);
        }
}

std::string Describe(const QM::Result &r)
{
    std::ostringstream s;
    s << "quads " << r.quads << " tris " << r.triangles << " patches " << r.patches << " formed " << r.ops.quadsFormed
      << " templates " << r.ops.templates << " paired " << r.ops.pairedTriangles << " failures " << r.ops.failures
      << " splits " << r.ops.splits << " swaps " << r.ops.swaps << " minJ " << r.quality.minJacobian << " meanJ "
      << r.quality.meanJacobian << " irregular " << r.quality.irregularVertices << "/" << r.quality.interiorAllQuadVertices;
    return s.str();
}

}  // namespace

TEST(QMorph, PlanarSquareGridBecomesAllQuads)
{
    TMesh m;
    MakeGrid(m, 10, 1.f, 0.f);
    QM::Params p;
    QM::Result r = QM::Apply(m, p);
    ASSERT_EQ(r.error, "");
    std::cout << Describe(r) << std::endl;
    EXPECT_EQ(r.triangles, 0);
    EXPECT_EQ(r.quality.invertedQuads, 0);
}
