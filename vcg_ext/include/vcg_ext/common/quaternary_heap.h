// A priority queue with std::priority_queue's interface and order (top() is the greatest by
// operator<), kept as a 4-ary heap: half the levels of a binary one, and the four children of a
// node side by side in memory, so a pop touches fewer cache lines. VSA's flooding pops every face
// of the mesh once per Lloyd iteration, and on a million faces the binary heap's cache misses were
// most of its time. With a total order on T the pops come in the same sequence from either queue.
#ifndef VCG_EXT_COMMON_QUATERNARY_HEAP_H
#define VCG_EXT_COMMON_QUATERNARY_HEAP_H

#include <cstddef>
#include <utility>
#include <vector>

namespace vcg_ext {

template <class T>
class QuaternaryHeap
{
public:
    bool empty() const { return items.empty(); }
    size_t size() const { return items.size(); }
    const T &top() const { return items.front(); }
    void clear() { items.clear(); }

    void push(const T &x)
    {
        size_t i = items.size();
        items.push_back(x);
        while (i > 0) {  // sift up
            const size_t parent = (i - 1) / kArity;
            if (!(items[parent] < x)) break;
            items[i] = std::move(items[parent]);
            i = parent;
        }
        items[i] = x;
    }

    void pop()
    {
        T last = std::move(items.back());
        items.pop_back();
        if (items.empty()) return;
        const size_t n = items.size();
        size_t i = 0;
        for (;;) {  // sift the last item down from the root
            const size_t first = kArity * i + 1;
            if (first >= n) break;
            size_t best = first;
            const size_t end = first + kArity < n ? first + kArity : n;
            for (size_t c = first + 1; c < end; ++c)
                if (items[best] < items[c]) best = c;
            if (!(last < items[best])) break;
            items[i] = std::move(items[best]);
            i = best;
        }
        items[i] = std::move(last);
    }

private:
    static constexpr size_t kArity = 4;
    std::vector<T> items;
};

}  // namespace vcg_ext

#endif
