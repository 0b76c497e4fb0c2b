// PointQueryMemo (common/point_query_memo.h), Q-Morph's memo of the input surface's normal under a
// point: it answers what the query answers, asks the query again only for a point (and extra
// number) it does not hold, and stays right when two keys share a slot.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <vcg_ext/common/point_query_memo.h>

namespace {

typedef vcg::Point3d P3;

P3 Query(const P3 &p, double extra) { return P3(std::sin(p[0]) + extra, p[1] * p[2], p[0] - p[2]); }

TEST(PointQueryMemo, AnswersAsTheQueryAndAsksOncePerPoint)
{
    vcg_ext::PointQueryMemo<P3> memo;
    int asked = 0;
    auto counted = [&](const P3 &p, double extra) {
        ++asked;
        return Query(p, extra);
    };
    const P3 a(0.1, 0.2, 0.3), b(0.1, 0.2, 0.30000000000000004);  // b: a's neighbour in double
    EXPECT_EQ(memo.Get(a, -1, counted), Query(a, -1));
    EXPECT_EQ(memo.Get(a, -1, counted), Query(a, -1));
    EXPECT_EQ(asked, 1);
    EXPECT_EQ(memo.Get(b, -1, counted), Query(b, -1));  // one bit apart: another key
    EXPECT_EQ(memo.Get(a, 0.5, counted), Query(a, 0.5));  // the extra number is part of the key
    EXPECT_EQ(asked, 3);
}

TEST(PointQueryMemo, ManyPointsShareSlotsAndEveryAnswerIsRight)
{
    vcg_ext::PointQueryMemo<P3> memo;
    std::vector<P3> points;
    for (int i = 0; i < 5000; ++i) points.push_back(P3(i * 0.37, std::cos(i), i % 17));  // more than the slots
    int asked = 0;
    auto counted = [&](const P3 &p, double extra) {
        ++asked;
        return Query(p, extra);
    };
    for (int round = 0; round < 2; ++round)
        for (const P3 &p : points) ASSERT_EQ(memo.Get(p, 2.0, counted), Query(p, 2.0));
    EXPECT_GT(asked, int(points.size()));  // evicted keys asked again
    EXPECT_LE(asked, 2 * int(points.size()));
}

}  // namespace
