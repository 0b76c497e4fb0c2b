// ColouredCells (common/coloured_cells.h): the zones of one colour never meet, so work confined to
// them can run on a pool; every point lies in the zone of its own cell for that cell's colour.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <vcg_ext/common/coloured_cells.h>

namespace {

typedef vcg::Point3d P3;

double ChebyshevDistance(const P3 &a, const P3 &b)
{
    return std::max(std::abs(a[0] - b[0]), std::max(std::abs(a[1] - b[1]), std::abs(a[2] - b[2])));
}

}  // namespace

TEST(ColouredCells, ZonesOfOneColourNeverMeet)
{
    const vcg::Box3d box(P3(-1, 0, 2), P3(3, 1.5, 2.5));
    vcg_ext::ColouredCells cells;
    cells.Build(box, 0.3);
    ASSERT_DOUBLE_EQ(cells.Side(), 0.3);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<P3> points;
    for (int i = 0; i < 3000; ++i)
        points.push_back(P3(box.min[0] + u(rng) * box.DimX(), box.min[1] + u(rng) * box.DimY(), box.min[2] + u(rng) * box.DimZ()));
    for (int colour = 0; colour < vcg_ext::ColouredCells::kColours; ++colour) {
        std::vector<int> zone(points.size());
        for (size_t i = 0; i < points.size(); ++i) {
            zone[i] = cells.ZoneOf(points[i], colour);
            if (zone[i] >= 0) {
                EXPECT_EQ(cells.Colour(zone[i]), colour);
            }
        }
        // two points of different zones of one colour are at least the gap apart (a side less two
        // margins of a quarter side each)
        double closest = 1e30;
        for (size_t i = 0; i < points.size(); ++i)
            for (size_t j = i + 1; j < points.size(); ++j)
                if (zone[i] >= 0 && zone[j] >= 0 && zone[i] != zone[j])
                    closest = std::min(closest, ChebyshevDistance(points[i], points[j]));
        EXPECT_GE(closest, 0.5 * cells.Side() - 1e-12) << "colour " << colour;
    }
    for (const P3 &p : points) {
        const int cell = cells.CellOf(p);
        ASSERT_GE(cell, 0);
        EXPECT_EQ(cells.ZoneOf(p, cells.Colour(cell)), cell) << "a point is in its own cell's zone";
    }
    // a point a tenth of a side outside a cell is in that cell's zone, half a side outside it is not
    const P3 inside(1.1, 0.8, 2.3);
    const int cell = cells.CellOf(inside);
    P3 nearOut = inside, farOut = inside;
    // walk to the cell's upper x face, then beyond it
    double x = inside[0];
    while (cells.CellOf(P3(x + 1e-3, inside[1], inside[2])) == cell) x += 1e-3;
    nearOut[0] = x + 0.1 * cells.Side();
    farOut[0] = x + 0.5 * cells.Side();
    EXPECT_EQ(cells.ZoneOf(nearOut, cells.Colour(cell)), cell);
    EXPECT_NE(cells.ZoneOf(farOut, cells.Colour(cell)), cell);
}

TEST(ColouredCells, TinySidesAreCappedAndPointsOutsideHaveNoCell)
{
    const vcg::Box3d box(P3(0, 0, 0), P3(10, 10, 10));
    vcg_ext::ColouredCells cells;
    cells.Build(box, 1e-9);
    EXPECT_DOUBLE_EQ(cells.Side(), 10.0 / 64) << "at most 64 cells per axis";
    EXPECT_LE(cells.Count(), 67 * 67 * 67);
    EXPECT_EQ(cells.CellOf(P3(1e6, 0, 0)), -1);
    EXPECT_EQ(cells.ZoneOf(P3(0, -1e6, 0), 0), -1);
    EXPECT_EQ(cells.CellOf(P3(std::nan(""), 0, 0)), -1);
}
