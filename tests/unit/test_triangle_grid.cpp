// The closest-triangle grid (common/triangle_grid.h): vcglib's grid re-laid out, so its answers must
// be vcglib's own (GridClosest over GridStaticPtr with the same distance) to the last bit, ties
// included, and the triangles within a radius every triangle nearer than it. On a scan with thin
// fins and sharp creases (CGAL's man, extracted by set-up).
#include <gtest/gtest.h>

#include <set>

#include "test_mesh.h"
#include <vcg/complex/algorithms/closest.h>
#include <vcg_ext/common/point_face_distance.h>
#include <vcg_ext/common/triangle_grid.h>

using namespace qmf_test;

namespace {

typedef vcg::Point3d D3;

// Points near face centres, on the surface (corners, edge midpoints, centres: distances 0 up to
// rounding), just above vertices (several triangles exactly as near: which one is kept is the
// walk's choice), a few edge lengths off the surface (several rings of cells) and outside the
// grid's box.
std::vector<P3> QueryPoints(const TMesh &m)
{
    std::vector<P3> points;
    for (size_t f = 0; f < m.face.size(); f += 53) {
        const D3 a = D3::Construct(m.face[f].cP(0)), b = D3::Construct(m.face[f].cP(1)), c = D3::Construct(m.face[f].cP(2));
        const D3 n = ((b - a) ^ (c - a)).Normalize();
        const double edge = (b - a).Norm();
        points.push_back(P3::Construct((a + b + c) / 3.0 + n * (0.3 * edge)));
        points.push_back(P3::Construct(a + n * (1e-3 * edge)));
        points.push_back(P3::Construct(a - n * (4 * edge) + (c - a) * 0.5));
        // on the surface: a corner, an edge's midpoint, the centre (as projected nodes are)
        points.push_back(m.face[f].cP(0));
        points.push_back(P3::Construct((a + b) / 2.0));
        points.push_back(P3::Construct((a + b + c) / 3.0));
    }
    const D3 centre = D3::Construct(m.bbox.Center());
    points.push_back(P3::Construct(centre + D3(1, 0.5, 0.25) * m.bbox.Diag()));
    return points;
}

}  // namespace

// The same triangle and the same closest point as GridClosest (bounded and not, with a filter), and
// ForEachWithin's triangles are those nearer than the radius, on grids of 1 and 8 cells per face.
TEST(TriangleGrid, AnswersAreVcglibsGridClosestsToTheLastBit)
{
    TMesh m;
    ASSERT_TRUE(LoadOff(m, MeshDir() + "/man.off"));
    vcg::tri::UpdateBounding<TMesh>::Box(m);
    const double diagonal = m.bbox.Diag();
    const std::vector<P3> points = QueryPoints(m);
    for (const int cellsPerFace : {1, 8}) {
        SCOPED_TRACE(cellsPerFace);
        const int cells = cellsPerFace * int(m.face.size());
        vcg::GridStaticPtr<TFace, float> reference;
        reference.Set(m.face.begin(), m.face.end(), cells);
        vcg_ext::TriangleGrid<TMesh> grid;
        grid.Build(m, cells);
        vcg_ext::PointFaceDistance<TFace> distance;
        vcg::tri::EmptyTMark<TMesh> noMarks;
        int ties = 0, tested = 0;
        for (const P3 &q : points) {
            for (const float bound : {float(diagonal), float(2 * diagonal), float(1e-3 * diagonal)}) {
                float d = bound;
                P3 expectedAt, at;
                const TFace *expected = reference.GetClosest(distance, noMarks, q, bound, d, expectedAt);
                const int got = grid.Closest(q, bound, [](int) { return true; }, at);
                ASSERT_EQ(got, expected ? int(vcg::tri::Index(m, expected)) : -1);
                if (expected) {
                    EXPECT_EQ(at, expectedAt);
                }
                ++tested;
            }
            // every triangle nearer than a radius a little over the least distance
            float d = float(2 * diagonal);
            P3 at;
            const TFace *closest = reference.GetClosest(distance, noMarks, q, d, d, at);
            ASSERT_NE(closest, nullptr);
            const float radius = d + float(1e-4 * diagonal);
            std::set<int> near, within;
            for (size_t f = 0; f < m.face.size(); ++f) {
                float r = radius;
                P3 point;
                if (distance(m.face[f], q, r, point)) near.insert(int(f));
            }
            grid.ForEachWithin(q, radius, [&](int f) { within.insert(f); });
            EXPECT_EQ(within, near);
            ties += near.size() > 1;
        }
        EXPECT_GT(tested, 1000);
        EXPECT_GT(ties, int(points.size()) / 4);  // corners shared by several triangles
    }
}

// A filter leaves out the triangles it refuses: the answer is the nearest of the others, as
// GridClosest finds it with a functor that refuses them.
TEST(TriangleGrid, AFilterLeavesTrianglesOut)
{
    TMesh m;
    ASSERT_TRUE(LoadOff(m, MeshDir() + "/man.off"));
    vcg::tri::UpdateBounding<TMesh>::Box(m);
    vcg::tri::UpdateNormal<TMesh>::PerFaceNormalized(m);
    const int cells = 8 * int(m.face.size());
    vcg::GridStaticPtr<TFace, float> reference;
    reference.Set(m.face.begin(), m.face.end(), cells);
    vcg_ext::TriangleGrid<TMesh> grid;
    grid.Build(m, cells);
    struct Upward {  // the triangles facing +z only
        typedef P3 QueryType;
        static const P3 &Pos(const P3 &q) { return q; }
        bool operator()(const TFace &f, const P3 &p, float &minDist, P3 &closest) const
        {
            return f.cN()[2] > 0 && vcg_ext::PointFaceDistance<TFace>()(f, p, minDist, closest);
        }
    };
    vcg::tri::EmptyTMark<TMesh> noMarks;
    int differs = 0;
    for (const P3 &q : QueryPoints(m)) {
        float d = float(m.bbox.Diag());
        P3 expectedAt, at, anyAt;
        Upward upward;
        const TFace *expected = reference.GetClosest(upward, noMarks, q, d, d, expectedAt);
        const int got = grid.Closest(q, float(m.bbox.Diag()), [&](int f) { return m.face[f].cN()[2] > 0; }, at);
        ASSERT_EQ(got, expected ? int(vcg::tri::Index(m, expected)) : -1);
        const int any = grid.Closest(q, float(m.bbox.Diag()), [](int) { return true; }, anyAt);
        differs += any != got;
    }
    EXPECT_GT(differs, 0);  // the filter mattered
}
