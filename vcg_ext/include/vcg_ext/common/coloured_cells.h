// Cells of a coarse grid in eight colours (the parities of their three coordinates), each with a
// zone: the cell grown by a quarter of its side on every side. Zones of one colour never meet (a
// cell of another colour lies between any two of them), so local mesh work confined to the zones
// of one colour can run on a pool, one colour after the other, and give the same result whatever
// the number of threads.
#ifndef VCG_EXT_COMMON_COLOURED_CELLS_H
#define VCG_EXT_COMMON_COLOURED_CELLS_H

#include <algorithm>
#include <cmath>
#include <vector>

#include <vcg/space/box3.h>
#include <vcg/space/point3.h>

namespace vcg_ext {

class ColouredCells
{
public:
    typedef vcg::Point3d P3;
    static constexpr int kColours = 8;

    // Cells over `box` grown by a cell, their side `side` (at least maxExtent / kMaxCellsPerAxis).
    // The side is used as given: a caller that wants the same cells for a flipped copy of a mesh
    // passes the same bits (QMorph's automatic length is computed orientation-free for that).
    void Build(const vcg::Box3d &box, double side)
    {
        const double extent = std::max(box.DimX(), std::max(box.DimY(), box.DimZ()));
        const double wanted = std::max(side, extent / kMaxCellsPerAxis);
        h = wanted > 0 && std::isfinite(wanted) ? wanted : 1;
        origin = box.min - P3(h, h, h);
        for (int k = 0; k < 3; ++k) n[k] = int(std::floor((box.max[k] - box.min[k]) / h)) + 3;
    }

    int Count() const { return n[0] * n[1] * n[2]; }
    double Side() const { return h; }
    int Colour(int cell) const
    {
        const int x = cell % n[0], y = (cell / n[0]) % n[1], z = cell / (n[0] * n[1]);
        return (x & 1) | ((y & 1) << 1) | ((z & 1) << 2);
    }

    // The cell p lies in, or -1 outside the grid.
    int CellOf(const P3 &p) const
    {
        int c[3];
        for (int k = 0; k < 3; ++k) {
            const double t = std::floor((p[k] - origin[k]) / h);
            if (!(t >= 0 && t < n[k])) return -1;
            c[k] = int(t);
        }
        return c[0] + n[0] * (c[1] + n[1] * c[2]);
    }

    // The cell of colour `colour` whose zone holds p, or -1 (at most one does).
    int ZoneOf(const P3 &p, int colour) const
    {
        const double margin = kMarginOfSide * h;
        int c[3];
        for (int k = 0; k < 3; ++k) {
            const double u = (p[k] - origin[k]) / h;
            if (!(u >= 0 && u < n[k])) return -1;
            int i = int(std::floor(u));
            const int parity = (colour >> k) & 1;
            if ((i & 1) != parity) {
                // the cells of that parity beside i: p must be within the margin of one of them
                if ((u - i) * h < margin) --i;
                else if ((i + 1 - u) * h < margin) ++i;
                else return -1;
                if (i < 0 || i >= n[k]) return -1;
            }
            c[k] = i;
        }
        return c[0] + n[0] * (c[1] + n[1] * c[2]);
    }

private:
    // Cells per axis at most (the work of a colour is spread over its cells; millions of empty
    // cells would only cost memory).
    static constexpr double kMaxCellsPerAxis = 64;
    // A zone's margin, as a fraction of the side: under a half, so zones of one colour stay apart.
    static constexpr double kMarginOfSide = 0.25;

    double h = 1;
    P3 origin = P3(0, 0, 0);
    int n[3] = {1, 1, 1};
};

}  // namespace vcg_ext

#endif
