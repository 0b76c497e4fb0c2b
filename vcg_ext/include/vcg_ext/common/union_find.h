// Union-find over the indices 0..n-1 (path halving). The root of a set is always its smallest
// index, whatever the order of the unions: sets come out numbered in index order, so patches and
// components are enumerated deterministically.
#ifndef VCG_EXT_COMMON_UNION_FIND_H
#define VCG_EXT_COMMON_UNION_FIND_H

#include <algorithm>
#include <numeric>
#include <vector>

namespace vcg_ext {

class IndexUnionFind
{
public:
    explicit IndexUnionFind(int n = 0) : parent(size_t(n)) { std::iota(parent.begin(), parent.end(), 0); }

    int Find(int x)
    {
        while (parent[x] != x) {
            parent[x] = parent[parent[x]];
            x = parent[x];
        }
        return x;
    }

    void Unite(int a, int b)
    {
        a = Find(a);
        b = Find(b);
        if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }

private:
    std::vector<int> parent;
};

}  // namespace vcg_ext

#endif
