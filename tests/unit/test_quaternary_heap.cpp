// QuaternaryHeap (common/quaternary_heap.h), VSA's flooding queue: under a total order it pops in
// exactly the sequence std::priority_queue does, through interleaved pushes and pops with many
// ties on the first key (the flooding's equal errors).
#include <gtest/gtest.h>

#include <queue>
#include <random>
#include <tuple>

#include <vcg_ext/common/quaternary_heap.h>

namespace {

struct Item {
    int key, tieBreak;
    bool operator<(const Item &o) const { return std::tie(key, tieBreak) < std::tie(o.key, o.tieBreak); }
};

TEST(QuaternaryHeap, PopsInTheOrderOfStdPriorityQueue)
{
    std::mt19937 rng(7);
    std::uniform_int_distribution<int> key(0, 50), action(0, 2);
    vcg_ext::QuaternaryHeap<Item> heap;
    std::priority_queue<Item> reference;
    int pops = 0;
    for (int step = 0; step < 20000; ++step) {
        if (action(rng) > 0 || reference.empty()) {
            const Item x{key(rng), step};
            heap.push(x);
            reference.push(x);
        } else {
            ASSERT_FALSE(heap.empty());
            EXPECT_EQ(heap.top().key, reference.top().key);
            EXPECT_EQ(heap.top().tieBreak, reference.top().tieBreak);
            heap.pop();
            reference.pop();
            ++pops;
        }
        ASSERT_EQ(heap.size(), reference.size());
    }
    while (!reference.empty()) {  // then drained
        EXPECT_EQ(heap.top().tieBreak, reference.top().tieBreak);
        heap.pop();
        reference.pop();
        ++pops;
    }
    EXPECT_TRUE(heap.empty());
    EXPECT_GT(pops, 13000);  // two pushes per pop on average: the heap was deep most of the time
}

TEST(QuaternaryHeap, SingleItemAndClear)
{
    vcg_ext::QuaternaryHeap<Item> heap;
    heap.push({3, 0});
    EXPECT_EQ(heap.top().key, 3);
    heap.pop();
    EXPECT_TRUE(heap.empty());
    heap.push({1, 0});
    heap.push({2, 0});
    heap.clear();
    EXPECT_TRUE(heap.empty());
}

}  // namespace
