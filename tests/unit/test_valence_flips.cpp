// qmorph/valence_flips.h: the re-meshing's flips toward valence 6, judged against the input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <utility>
#include <vector>

#include "test_mesh.h"
#include <vcg/complex/algorithms/update/topology.h>
#include <vcg_ext/common/input_surface.h>
#include <vcg_ext/qmorph/valence_flips.h>

using namespace qmf_test;

namespace {

typedef vcg_ext::qmorph::ValenceFlips<TMesh> Flips;

constexpr int kCells = 6;              // a 6 x 6 grid of unit square cells
constexpr double kNear = 0.1;          // the surface distance the flips may leave

// A 6 x 6 grid whose cells' diagonals alternate: inside, valences 4 and 8, never the ideal 6.
void MakeCheckerboard(TMesh &m)
{
    MakeGrid(m, kCells, float(kCells), 0.f, 1, true);
    vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
}

// Per vertex, its number of distinct neighbours.
std::vector<int> Valences(TMesh &m)
{
    std::vector<std::vector<int>> neighbours(m.vert.size());
    for (TFace &f : m.face)
        for (int k = 0; k < 3; ++k) {
            const int a = int(vcg::tri::Index(m, f.V0(k))), b = int(vcg::tri::Index(m, f.V1(k)));
            for (auto [v, w] : {std::pair<int, int>{a, b}, {b, a}})
                if (std::find(neighbours[v].begin(), neighbours[v].end(), w) == neighbours[v].end()) neighbours[v].push_back(w);
        }
    std::vector<int> valence;
    for (const auto &n : neighbours) valence.push_back(int(n.size()));
    return valence;
}

// Sum over the grid's inner vertices of |valence - 6|.
int InnerDeviation(TMesh &m)
{
    const std::vector<int> valence = Valences(m);
    int sum = 0;
    for (size_t v = 0; v < m.vert.size(); ++v) {
        const P3 p = m.vert[v].cP();
        if (p[0] > 0 && p[1] > 0 && p[0] < kCells && p[1] < kCells) sum += std::abs(valence[v] - 6);
    }
    return sum;
}

void ExpectEveryFaceFacing(const TMesh &m, double z)
{
    for (const TFace &f : m.face) EXPECT_GT(vcg::Normal(f.cP(0), f.cP(1), f.cP(2))[2] * z, 0) << "a face turned over";
}

}  // namespace

TEST(ValenceFlips, CheckerboardFlipsTowardValenceSixWithoutTurningAFace)
{
    TMesh m;
    MakeCheckerboard(m);
    vcg_ext::InputSurface<TMesh> input(m);
    const int before = InnerDeviation(m);
    ASSERT_EQ(before, 2 * (kCells - 1) * (kCells - 1));  // every inner vertex 2 off (4 or 8)
    const int faces = m.fn;

    const int flips = Flips::Do(m, input, kNear);

    EXPECT_GT(flips, 0);
    EXPECT_LT(InnerDeviation(m), before / 2) << flips << " flips";
    EXPECT_EQ(m.fn, faces);
    ExpectEveryFaceFacing(m, 1);
    for (TFace &f : m.face)  // the adjacency is kept valid
        for (int k = 0; k < 3; ++k) {
            if (f.FFp(k) != &f) {
                EXPECT_EQ(f.FFp(k)->FFp(f.FFi(k)), &f);
            }
        }
}

TEST(ValenceFlips, SelectedEdgesAreNeverFlipped)
{
    TMesh m;
    MakeCheckerboard(m);
    vcg_ext::InputSurface<TMesh> input(m);
    for (TFace &f : m.face)  // every diagonal is front
        for (int k = 0; k < 3; ++k)
            if (f.P0(k)[0] != f.P1(k)[0] && f.P0(k)[1] != f.P1(k)[1]) f.SetFaceEdgeS(k);

    EXPECT_EQ(Flips::Do(m, input, kNear), 0);
    EXPECT_EQ(InnerDeviation(m), 2 * (kCells - 1) * (kCells - 1));
}

TEST(ValenceFlips, FlipsWhoseFacesWouldFaceAwayFromTheInputAreRefused)
{
    // the mesh is the checkerboard turned over (faces reversed): every new face would face away
    // from the input under it, though it lies on it and improves the valences
    TMesh input, m;
    MakeCheckerboard(input);
    vcg_ext::InputSurface<TMesh> surface(input);
    MakeCheckerboard(m);
    for (TFace &f : m.face) std::swap(f.V(1), f.V(2));
    vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
    ExpectEveryFaceFacing(m, -1);

    EXPECT_EQ(Flips::Do(m, surface, kNear), 0);
}

TEST(ValenceFlips, FlipsWhoseNewEdgeLeavesTheInputAreRefused)
{
    // the mesh floats a unit above the input: the new edges' midpoints are farther than kNear
    TMesh input, m;
    MakeCheckerboard(input);
    vcg_ext::InputSurface<TMesh> surface(input);
    MakeCheckerboard(m);
    for (TVertex &v : m.vert) v.P()[2] += 1;

    EXPECT_EQ(Flips::Do(m, surface, kNear), 0);
    // within reach, the same flips are made
    EXPECT_GT(Flips::Do(m, surface, 2), 0);
}
