// The last answers of a pure query on a point (and one more number), kept in a small direct-mapped
// table: Q-Morph asks the input surface's normal under the same face centroid again and again (a
// quad's rating asks it for the face and for its corners, a refused move rates the faces as they
// were), and each answer is a closest-point search over the whole input. Exact: a hit is a query
// with the same bits, so the answer is the one the query gives; memory is fixed.
#ifndef VCG_EXT_COMMON_POINT_QUERY_MEMO_H
#define VCG_EXT_COMMON_POINT_QUERY_MEMO_H

#include <cstdint>
#include <cstring>
#include <vector>

#include <vcg/space/point3.h>

namespace vcg_ext {

template <class Value>
class PointQueryMemo
{
public:
    typedef vcg::Point3d P3;

    // The answer of query(p, extra), computed only when this table does not hold it.
    template <class Query>
    Value Get(const P3 &p, double extra, Query &&query)
    {
        if (table.empty()) table.resize(kSlots);
        Slot &s = table[Hash(p, extra) & (kSlots - 1)];
        if (s.used && Same(s.p, p) && Same(s.extra, extra)) return s.value;
        s.value = query(p, extra);
        s.p = p;
        s.extra = extra;
        s.used = true;
        return s.value;
    }

private:
    // A power of two: the recent answers of one patch's local work (a few hundred faces).
    static constexpr size_t kSlots = 1024;

    struct Slot {
        P3 p;
        double extra = 0;
        Value value{};
        bool used = false;
    };
    std::vector<Slot> table;

    static uint64_t Bits(double x)
    {
        uint64_t b;
        std::memcpy(&b, &x, sizeof b);
        return b;
    }
    // Same bits: -0 and 0 are two keys, and a NaN is a key like any other (its answer is kept too).
    static bool Same(double a, double b) { return Bits(a) == Bits(b); }
    static bool Same(const P3 &a, const P3 &b) { return Same(a[0], b[0]) && Same(a[1], b[1]) && Same(a[2], b[2]); }
    static uint64_t Mix(uint64_t x)  // splitmix64's finaliser
    {
        x ^= x >> 30;
        x *= 0xbf58476d1ce4e5b9ULL;
        x ^= x >> 27;
        x *= 0x94d049bb133111ebULL;
        return x ^ (x >> 31);
    }
    static size_t Hash(const P3 &p, double extra)
    {
        return size_t(Mix(Bits(p[0]) ^ Mix(Bits(p[1]) ^ Mix(Bits(p[2]) ^ Mix(Bits(extra))))));
    }
};

}  // namespace vcg_ext

#endif
