// Triangles in disguise (qmorph/flat_quad_split.h): a quad with a nearly straight corner at a node
// that never moves is split into two triangles along the diagonal from that corner, within the
// triangles' area budget; a quad whose straight corner is free is left to the smoothing.
#include <gtest/gtest.h>

#include <vector>

#include "test_mesh.h"
#include <vcg/complex/append.h>
#include <vcg/complex/algorithms/update/topology.h>
#include <vcg_ext/qmorph/flat_quad_split.h>
#include <vcg_ext/quad_quality.h>

using namespace qmf_test;

namespace {

typedef vcg_ext::qmorph::FlatQuadSplit<TMesh> FlatSplit;

// An n x n grid of unit cells in the z = 0 plane, each cell a quad (faux diagonal (i, j)-(i+1, j+1)).
// The corner `corner` (0: (i, j), 1: (i+1, j)) of cell (i, j) is moved to 0.04 short of the middle
// of the cell's other diagonal: the quad's angle there is 170.8 degrees (scaled Jacobian 0.16).
// `onFront`: the grid line y = j is a front (selected face-edges), so that corner never moves.
struct FlatCell {
    TMesh input, m;
    TVertex *flat = nullptr;

    FlatCell(int n, int i, int j, int corner, bool onFront)
    {
        MakeGrid(input, n, float(n), 0.f, 1, false);
        vcg::tri::Append<TMesh, TMesh>::MeshCopy(m, input);
        vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
        for (TFace &f : m.face)
            for (int k = 0; k < 3; ++k) {
                const P3 a = f.P0(k), b = f.P1(k);
                if (a[0] != b[0] && a[1] != b[1]) f.SetF(k);
                if (onFront && a[1] == float(j) && b[1] == float(j)) f.SetFaceEdgeS(k);
            }
        for (TVertex &v : m.vert)
            if (v.P()[0] == float(i + corner) && v.P()[1] == float(j)) flat = &v;
        const float e = 0.04f;
        flat->P() = corner == 0 ? P3(i + 0.5f - e, j + 0.5f - e, 0) : P3(i + 0.5f + e, j + 0.5f - e, 0);
    }
    int FauxSides() const
    {
        int n = 0;
        for (const TFace &f : m.face)
            for (int k = 0; k < 3; ++k) n += f.IsF(k);
        return n;
    }
    int Polygons()
    {
        int n = 0;
        vcg_ext::QuadQuality::ForEachFauxPolygon(m, [&](TFace &, const std::array<int, 4> &, int) { ++n; });
        return n;
    }
    int FacesTurnedOver() const
    {
        int n = 0;
        for (const TFace &f : m.face) n += vcg::TriangleNormal(f)[2] < 0;
        return n;
    }
};

}  // namespace

// On the faux diagonal's end (corner 0) the diagonal is unflagged; on the other (corner 1) it is
// flipped first. Either way the two triangles share the straight corner, nothing turns over, and
// the face-face adjacency and faux flags stay consistent.
TEST(FlatQuadSplit, AQuadWithAStraightCornerOnTheFrontBecomesTwoTriangles)
{
    for (int corner = 0; corner < 2; ++corner) {
        FlatCell cell(16, 7, 7, corner, true);
        const int faces = cell.m.fn, faux = cell.FauxSides(), polygons = cell.Polygons();
        vcg_ext::InputSurface<TMesh> surface(cell.input);
        EXPECT_EQ(FlatSplit::Do(cell.m, surface, 60), 1) << corner;
        EXPECT_EQ(cell.m.fn, faces);
        EXPECT_EQ(cell.FauxSides(), faux - 2);
        EXPECT_EQ(cell.Polygons(), polygons + 1);
        EXPECT_EQ(cell.FacesTurnedOver(), 0);
        int trianglesAtCorner = 0;
        for (TFace &f : cell.m.face) {
            const bool triangle = !f.IsF(0) && !f.IsF(1) && !f.IsF(2);
            if (triangle) {
                EXPECT_TRUE(f.V(0) == cell.flat || f.V(1) == cell.flat || f.V(2) == cell.flat) << "a triangle away from the corner";
                ++trianglesAtCorner;
            }
            for (int k = 0; k < 3; ++k)
                if (f.FFp(k) != &f) {
                    EXPECT_EQ(f.FFp(k)->FFp(f.FFi(k)), &f);
                    EXPECT_EQ(f.IsF(k), f.FFp(k)->IsF(f.FFi(k))) << "a faux side on one face only";
                }
        }
        EXPECT_EQ(trianglesAtCorner, 2);
    }
}

// The same quad is left as it is where its straight corner is free (the shape pass moves such a
// corner), or where its area (half a cell) is more than the 0.4% of the surface the triangles may
// fill (an 8 x 8 grid: 0.26).
TEST(FlatQuadSplit, AFreeCornerOrASmallSurfaceKeepsTheQuad)
{
    FlatCell free(16, 7, 7, 0, false);
    vcg_ext::InputSurface<TMesh> freeSurface(free.input);
    EXPECT_EQ(FlatSplit::Do(free.m, freeSurface, 60), 0);

    FlatCell small(8, 3, 3, 0, true);
    const int faux = small.FauxSides();
    vcg_ext::InputSurface<TMesh> smallSurface(small.input);
    EXPECT_EQ(FlatSplit::Do(small.m, smallSurface, 60), 0);
    EXPECT_EQ(small.FauxSides(), faux);
}
