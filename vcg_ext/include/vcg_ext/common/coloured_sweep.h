// One pass over a mesh's vertices on a pool of threads, with the same result whatever their number:
// the vertices are visited cell by cell of ColouredCells, one colour of cells after the other, the
// cells of one colour on the pool, each visiting its vertices in index order. Before each colour
// every vertex gets its zone for that colour (the zones of one colour never meet); a visit must
// read and change only vertices of its own zone and faces whose every vertex is in it, so no two
// threads touch the same element. A visit that would reach further says Later: those vertices are
// visited once more at the end, in index order, on the calling thread, with no zone (-1).
#ifndef VCG_EXT_COMMON_COLOURED_SWEEP_H
#define VCG_EXT_COMMON_COLOURED_SWEEP_H

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <vector>

#include <vcg/complex/complex.h>

#include <vcg_ext/common/coloured_cells.h>
#include <vcg_ext/common/parallel.h>

namespace vcg_ext {

template <class MeshType>
class ColouredSweep
{
public:
    typedef vcg::Point3d P3;
    static constexpr int kLater = -1;          // a visit's answer: visit me again at the end
    static constexpr int kDeletedVertex = -2;  // the zone of a vertex deleted before the colour

    // Visits every live vertex of m: visit(vi, z, scratch) returns kLater or a count (summed and
    // returned); `zone` is filled per colour. Scratch: a default-constructed object per work item,
    // for the visits' buffers. report(fraction of the vertices visited) runs on this thread.
    template <class Scratch, class Visit, class Report>
    static long Run(MeshType &m, double side, int threads, std::vector<int> &zone, const Visit &visit, const Report &report)
    {
        vcg::Box3d box;
        for (const auto &v : m.vert)
            if (!v.IsD()) box.Add(P3::Construct(v.cP()));
        ColouredCells cells;
        cells.Build(box, side);
        std::vector<std::vector<size_t>> inCell(cells.Count());
        std::vector<size_t> later;
        for (size_t vi = 0; vi < m.vert.size(); ++vi) {
            if (m.vert[vi].IsD()) continue;
            const int c = cells.CellOf(P3::Construct(m.vert[vi].cP()));
            if (c < 0) later.push_back(vi);
            else inCell[c].push_back(vi);
        }
        long total = 0;
        size_t visited = 0;
        const double all = double(std::max<size_t>(1, m.vert.size()));
        struct Outcome {
            long count = 0;
            size_t visited = 0;
            std::vector<size_t> later;
        };
        zone.assign(m.vert.size(), kDeletedVertex);
        for (int colour = 0; colour < ColouredCells::kColours; ++colour) {
            for (size_t vi = 0; vi < m.vert.size(); ++vi)
                zone[vi] = m.vert[vi].IsD() ? kDeletedVertex : cells.ZoneOf(P3::Construct(m.vert[vi].cP()), colour);
            std::vector<int> work;
            for (int c = 0; c < cells.Count(); ++c)
                if (cells.Colour(c) == colour && !inCell[c].empty()) work.push_back(c);
            std::vector<size_t> biggestFirst(work.size());
            std::iota(biggestFirst.begin(), biggestFirst.end(), size_t(0));
            std::stable_sort(biggestFirst.begin(), biggestFirst.end(),
                             [&](size_t a, size_t b) { return inCell[work[a]].size() > inCell[work[b]].size(); });
            OrderedParallelFor<Outcome>(
                work.size(), threads, biggestFirst,
                [&](size_t i) {
                    Outcome o;
                    Scratch scratch;
                    for (size_t vi : inCell[work[i]]) {
                        const int r = visit(vi, work[i], scratch);
                        if (r == kLater) o.later.push_back(vi);
                        else o.count += r;
                    }
                    o.visited = inCell[work[i]].size();
                    return o;
                },
                [&](size_t, Outcome &&o) {
                    total += o.count;
                    visited += o.visited;
                    later.insert(later.end(), o.later.begin(), o.later.end());
                },
                [&]() { report(double(visited) / all); });
        }
        std::sort(later.begin(), later.end());
        Scratch scratch;
        for (size_t k = 0; k < later.size(); ++k) {
            if (k % kReportEvery == 0) report(double(visited) / all);
            const int r = visit(later[k], -1, scratch);
            if (r > 0) total += r;
        }
        return total;
    }

private:
    static constexpr size_t kReportEvery = 1 << 15;  // vertices of the last visits between reports
};

}  // namespace vcg_ext

#endif
