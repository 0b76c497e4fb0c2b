// A uniform grid of a frozen triangle mesh for exact closest-triangle searches (InputSurface's).
//
// Why not vcglib's GridStaticPtr and GridClosest:
// - each cell keeps its triangles' corners in one contiguous block, so a search reads a few blocks
//   in a row instead of a face, its vertices and their coordinates per triangle (on an 832k-face
//   scan those reads missed the cache: a search took twice as long as on a 52k one);
// - the answer is the least (exact distance in double, triangle index) over every triangle: it
//   depends neither on the grid nor on the order cells are visited in. GridClosest keeps the first
//   of equally near triangles it meets (a point above a vertex is as near to every triangle around
//   it) and its running distance in float, so its answer changed with the grid and the walk.
// Cells are sized as vcglib sizes them (BestDim over the inflated box) and a triangle is filed in
// every cell its bounding box touches, as GridStaticPtr files it.
#ifndef VCG_EXT_COMMON_TRIANGLE_GRID_H
#define VCG_EXT_COMMON_TRIANGLE_GRID_H

#include <algorithm>
#include <cmath>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/space/index/grid_util.h>

#include <vcg_ext/common/polygon_geometry.h>

namespace vcg_ext {

template <class MeshType>
class TriangleGrid
{
public:
    typedef typename MeshType::ScalarType ScalarType;
    typedef typename MeshType::CoordType CoordType;
    typedef vcg::Point3d P3;

    // The triangles of m (none deleted), about cellsPerFace cells per triangle.
    void Build(const MeshType &m, double cellsPerFace)
    {
        cells = vcg::BasicGrid<ScalarType>();
        start.clear();
        entries.clear();
        if (m.face.empty()) return;
        vcg::Box3<ScalarType> box;
        for (const auto &f : m.face)
            for (int i = 0; i < 3; ++i) box.Add(f.cP(i));
        const long long wanted = std::max(1LL, (long long)(cellsPerFace * double(m.face.size())));
        const ScalarType inflate = box.Diag() / ScalarType(wanted);  // as GridStaticPtr::Set
        box.Offset(inflate);
        cells.bbox = box;
        cells.dim = box.max - box.min;
        vcg::BestDim(wanted, cells.dim, cells.siz);
        cells.ComputeDimAndVoxel();
        const double magnitude = P3::Construct(box.min).Norm() + P3::Construct(box.max).Norm();
        slack = kCellRounding * magnitude;
        planeSlack = kDistanceRounding * magnitude;

        // counting sort by cell, triangles in index order within a cell
        const size_t cellCount = size_t(cells.siz[0]) * cells.siz[1] * cells.siz[2];
        start.assign(cellCount + 1, 0);
        std::vector<vcg::Box3i> spans(m.face.size());
        for (size_t f = 0; f < m.face.size(); ++f) {
            spans[f] = Span(m.face[f]);
            ForEachCell(spans[f], [&](size_t c) { ++start[c + 1]; });
        }
        for (size_t c = 0; c < cellCount; ++c) start[c + 1] += start[c];
        entries.resize(start[cellCount]);
        std::vector<int> fill(start.begin(), start.end() - 1);
        for (size_t f = 0; f < m.face.size(); ++f) {
            Entry e;
            for (int i = 0; i < 3; ++i) e.corner[i] = m.face[f].cP(i);
            e.face = int(f);
            ForEachCell(spans[f], [&](size_t c) { entries[fill[c]++] = e; });
        }
    }

    // The triangle nearest q, nearer than maxDistance, among those accept(index) takes (its closest
    // point in `at`), or -1. Cells are visited in shells of growing Chebyshev distance around q's
    // cell; a cell, and then a whole shell, farther than the best distance so far is skipped.
    template <class Accept>
    int Closest(const P3 &q, double maxDistance, const Accept &accept, P3 &at) const
    {
        if (entries.empty()) return -1;
        int home[3];
        for (int a = 0; a < 3; ++a) home[a] = std::max(0, std::min(cells.siz[a] - 1, int(std::floor((q[a] - Low(a)) / Step(a)))));
        double best = maxDistance;
        int bestFace = -1;
        auto visit = [&](int x, int y, int z) {
            const double gx = Gap(q, 0, x), gy = Gap(q, 1, y), gz = Gap(q, 2, z);
            const double reach = best + slack;
            if (gx * gx + gy * gy + gz * gz > reach * reach) return;
            const size_t c = CellIndex(x, y, z);
            for (int i = start[c]; i < start[c + 1]; ++i) {
                const Entry &e = entries[i];
                if (!accept(e.face)) continue;
                P3 point;
                const double d = DistanceUpTo(e, q, best, point);
                if (d < best || (d == best && e.face < bestFace)) {
                    best = d;
                    bestFace = e.face;
                    at = point;
                }
            }
        };
        for (int k = 0;; ++k) {
            if (k > 0) {
                // every cell not visited yet lies beyond the cube of shells 0..k-1 along some axis
                double beyond = HUGE_VAL;
                for (int a = 0; a < 3; ++a) {
                    if (home[a] + k < cells.siz[a]) beyond = std::min(beyond, std::max(0.0, Low(a) + (home[a] + k) * Step(a) - q[a]));
                    if (home[a] - k >= 0) beyond = std::min(beyond, std::max(0.0, q[a] - (Low(a) + (home[a] - k + 1) * Step(a))));
                }
                if (beyond - slack > best) break;  // also when no cell is left (infinity)
            }
            const int x0 = std::max(0, home[0] - k), x1 = std::min(cells.siz[0] - 1, home[0] + k);
            for (int z = std::max(0, home[2] - k); z <= std::min(cells.siz[2] - 1, home[2] + k); ++z)
                for (int y = std::max(0, home[1] - k); y <= std::min(cells.siz[1] - 1, home[1] + k); ++y) {
                    if (std::abs(z - home[2]) == k || std::abs(y - home[1]) == k) {
                        for (int x = x0; x <= x1; ++x) visit(x, y, z);
                    } else {  // inside the shell's rows only its two ends are on the shell
                        if (home[0] - k >= 0) visit(home[0] - k, y, z);
                        if (home[0] + k < cells.siz[0]) visit(home[0] + k, y, z);
                    }
                }
        }
        return bestFace;
    }

    // Calls visit(index) for every triangle nearer q than radius among those filed in the cells the
    // box of that sphere touches (vcglib's GetInSphere's set), once per cell it is filed in.
    template <class Visit>
    void ForEachWithin(const P3 &q, double radius, const Visit &visit) const
    {
        if (entries.empty()) return;
        vcg::Box3i span;
        cells.BoxToIBox(vcg::Box3<ScalarType>(CoordType::Construct(q), ScalarType(radius)), span);
        span.Intersect(vcg::Box3i(vcg::Point3i(0, 0, 0), cells.siz - vcg::Point3i(1, 1, 1)));
        if (span.IsNull()) return;
        ForEachCell(span, [&](size_t c) {
            for (int i = start[c]; i < start[c + 1]; ++i) {
                P3 point;
                if (DistanceUpTo(entries[i], q, radius, point) < radius) visit(entries[i].face);
            }
        });
    }

    size_t Entries() const { return entries.size(); }

private:
    // A triangle as filed in a cell: its corners (in the mesh's scalar type) and its index.
    struct Entry {
        CoordType corner[3];
        int face;
    };

    // A point is filed in its cell by float arithmetic on coordinates up to this much (times their
    // size) from the cell's exact box (a few float roundings, with a margin).
    static constexpr double kCellRounding = 1e-6;
    // The plane test lets through triangles up to this much (times the coordinates' size) beyond
    // the bound: the exact distance of a point a hair above a triangle is computed with that much
    // rounding, and may come out below the plane's distance. So a triangle whose distance equals
    // the bound is never rejected by the plane alone (a tie is then broken by index, whatever was
    // met first).
    static constexpr double kDistanceRounding = 1e-12;

    vcg::BasicGrid<ScalarType> cells;  // box, cell counts and sizes
    std::vector<int> start;            // per cell (and a sentinel): its first entry
    std::vector<Entry> entries;        // cell by cell
    double slack = 0;                  // how far a point may lie outside the cell it is filed in
    double planeSlack = 0;             // see kDistanceRounding

    double Low(int a) const { return double(cells.bbox.min[a]); }
    double Step(int a) const { return double(cells.voxel[a]); }
    size_t CellIndex(int x, int y, int z) const { return size_t(x) + size_t(cells.siz[0]) * (size_t(y) + size_t(cells.siz[1]) * size_t(z)); }

    // How far q is from cell i along axis a (0 when within it).
    double Gap(const P3 &q, int a, int i) const
    {
        return std::max(0.0, std::max(Low(a) + i * Step(a) - q[a], q[a] - (Low(a) + (i + 1) * Step(a))));
    }

    // The cells a triangle's bounding box touches, as GridStaticPtr computes them.
    template <class FaceType>
    vcg::Box3i Span(const FaceType &f) const
    {
        vcg::Box3<ScalarType> b;
        for (int i = 0; i < 3; ++i) b.Add(f.cP(i));
        b.Intersect(cells.bbox);
        vcg::Box3i span;
        cells.BoxToIBox(b, span);
        return span;
    }

    template <class Visit>
    void ForEachCell(const vcg::Box3i &span, const Visit &visit) const
    {
        for (int z = span.min[2]; z <= span.max[2]; ++z)
            for (int y = span.min[1]; y <= span.max[1]; ++y)
                for (int x = span.min[0]; x <= span.max[0]; ++x) visit(CellIndex(x, y, z));
    }

    // The exact distance from q to the triangle in double (its closest point in `at`), or infinity
    // when the triangle's plane alone puts it farther than `bound`.
    double DistanceUpTo(const Entry &e, const P3 &q, double bound, P3 &at) const
    {
        const P3 a = P3::Construct(e.corner[0]), b = P3::Construct(e.corner[1]), c = P3::Construct(e.corner[2]);
        const P3 n = (b - a) ^ (c - a);
        const double h = (q - a) * n, reach = bound + planeSlack;
        if (h * h > reach * reach * n.SquaredNorm()) return HUGE_VAL;
        at = ClosestPointOnTriangle(q, a, b, c);
        return (at - q).Norm();
    }
};

}  // namespace vcg_ext

#endif
