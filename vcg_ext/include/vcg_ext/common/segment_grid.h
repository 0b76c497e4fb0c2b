// A hash grid of 3D segments: which stored segment a point lies on (or is nearest to). Segments are
// entered cell by cell along their length, so a long CAD edge costs its length over the cell size,
// never the volume of its bounding box.
#ifndef VCG_EXT_COMMON_SEGMENT_GRID_H
#define VCG_EXT_COMMON_SEGMENT_GRID_H

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include <vcg/space/point3.h>

namespace vcg_ext {

class SegmentGrid
{
public:
    typedef vcg::Point3d P3;

    // cellSize: about the typical segment length (> 0).
    explicit SegmentGrid(double cellSize) : h(cellSize) {}

    int Add(const P3 &a, const P3 &b)
    {
        const int id = int(from.size());
        from.push_back(a);
        to.push_back(b);
        // samples closer than half a cell: every point of the segment is within one cell of one
        const int steps = std::max(1, int(std::ceil(2 * (b - a).Norm() / h)));
        uint64_t last = ~uint64_t(0);
        for (int s = 0; s <= steps; ++s) {
            const uint64_t key = Key(a + (b - a) * (double(s) / steps));
            if (key == last) continue;
            std::vector<int> &list = cells[key];
            if (list.empty() || list.back() != id) list.push_back(id);
            last = key;
        }
        return id;
    }

    // The segment nearest p among those within about a cell of it, or -1; its distance in `dist`.
    int Nearest(const P3 &p, double &dist) const
    {
        return Nearest(p, dist, [](int) { return true; });
    }

    // The same among the segments `accept(id)` takes.
    template <class Accept>
    int Nearest(const P3 &p, double &dist, const Accept &accept) const
    {
        int best = -1;
        dist = 1e300;
        ForEachAround(p, [&](int id) {
            if (!accept(id)) return;
            const double d = Distance(p, id);
            if (d < dist) { dist = d; best = id; }
        });
        return best;
    }

    // Every segment stored in the cells within one cell of segment a-b, each once.
    template <class Visit>
    void ForEachNear(const P3 &a, const P3 &b, const Visit &visit) const
    {
        std::vector<int> seen;
        const int steps = std::max(1, int(std::ceil(2 * (b - a).Norm() / h)));
        for (int s = 0; s <= steps; ++s)
            ForEachAround(a + (b - a) * (double(s) / steps), [&](int id) {
                if (std::find(seen.begin(), seen.end(), id) != seen.end()) return;
                seen.push_back(id);
                visit(id);
            });
    }

    P3 Midpoint(int id) const { return (from[id] + to[id]) * 0.5; }

    double Distance(const P3 &p, int id) const { return (p - Closest(p, id)).Norm(); }

    // The point of segment id nearest p.
    P3 Closest(const P3 &p, int id) const
    {
        const P3 ab = to[id] - from[id];
        const double l2 = ab.SquaredNorm();
        const double t = l2 > 0 ? std::max(0.0, std::min(1.0, ((p - from[id]) * ab) / l2)) : 0.0;
        return from[id] + ab * t;
    }

private:
    // Every entry of the cells within one cell of p's (a segment may come more than once).
    template <class Visit>
    void ForEachAround(const P3 &p, const Visit &visit) const
    {
        const long cx = Cell(p[0]), cy = Cell(p[1]), cz = Cell(p[2]);
        for (long x = cx - 1; x <= cx + 1; ++x)
            for (long y = cy - 1; y <= cy + 1; ++y)
                for (long z = cz - 1; z <= cz + 1; ++z) {
                    auto it = cells.find(Key(x, y, z));
                    if (it == cells.end()) continue;
                    for (int id : it->second) visit(id);
                }
    }

    long Cell(double x) const { return long(std::floor(x / h)); }
    uint64_t Key(const P3 &p) const { return Key(Cell(p[0]), Cell(p[1]), Cell(p[2])); }
    static uint64_t Key(long x, long y, long z)
    {
        const uint64_t mask = (uint64_t(1) << 21) - 1;  // 21 bits a coordinate: wraps far away, harmlessly
        return ((uint64_t(x) & mask) << 42) | ((uint64_t(y) & mask) << 21) | (uint64_t(z) & mask);
    }

    double h;
    std::vector<P3> from, to;
    std::unordered_map<uint64_t, std::vector<int>> cells;
};

}  // namespace vcg_ext

#endif
