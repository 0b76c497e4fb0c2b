// vcglib's uniform grid of a frozen triangle mesh, laid out for closest-triangle searches
// (InputSurface's): the same cells, the same triangles in each cell in the same order, and the same
// searches (GridClosest's walk, GetInSphere's cells), so the same answers to the last bit; but each
// cell keeps its triangles' corners in one contiguous block. GridStaticPtr keeps a pointer per
// triangle, so a search read a face, its vertex pointers and their coordinates, scattered in
// memory, for each of the ~30 triangles it tests: on an 832k-face scan most of those reads missed
// the cache, and a search took twice as long as on a 52k one.
//
// Why the answers must stay vcglib's: of equally near triangles (a point above a vertex is as near
// to every triangle around it) GridClosest keeps the first its walk meets, and every output face is
// judged by the normal of the one it keeps, so another walk would give another (no worse, but
// different) output everywhere.
#ifndef VCG_EXT_COMMON_TRIANGLE_GRID_H
#define VCG_EXT_COMMON_TRIANGLE_GRID_H

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/space/index/grid_static_ptr.h>

#include <vcg_ext/common/point_face_distance.h>

namespace vcg_ext {

template <class MeshType>
class TriangleGrid
{
public:
    typedef typename MeshType::FaceType FaceType;
    typedef typename MeshType::ScalarType ScalarType;
    typedef typename MeshType::CoordType CoordType;
    typedef vcg::Point3d P3;

    // The triangles of m (none deleted) in GridStaticPtr's grid of `cells` cells (0: one per
    // triangle, vcglib's default).
    void Build(MeshType &m, int cells)
    {
        start.clear();
        entries.clear();
        if (m.face.empty()) return;
        vcg::GridStaticPtr<FaceType, ScalarType> grid;
        grid.Set(m.face.begin(), m.face.end(), cells);
        box = grid;  // its geometry: box, cell counts, cell size
        roundingSlack = kRoundingDiagonal * double(box.bbox.Diag());
        const size_t count = size_t(box.siz[0]) * box.siz[1] * box.siz[2];
        start.resize(count + 1);
        entries.reserve(grid.links.size());
        for (size_t c = 0; c < count; ++c) {
            start[c] = int(entries.size());
            for (auto l = grid.grid[c]; l != grid.grid[c + 1]; ++l) {
                const FaceType &f = *l->Elem();
                entries.push_back(MakeEntry(f.cP(0), f.cP(1), f.cP(2), int(vcg::tri::Index(m, f))));
            }
        }
        start[count] = int(entries.size());
    }

    // GridClosest's answer with PointFaceDistance's exact distance (in double, the running least
    // distance kept in the scalar type as GridClosest keeps it): the triangle nearest p, nearer
    // than maxDistance, among those accept(index) takes (its closest point in `closest`), or -1.
    template <class Accept>
    int Closest(const CoordType &p, ScalarType maxDistance, const Accept &accept, CoordType &closest) const
    {
        if (entries.empty()) return -1;
        ScalarType minDist = maxDistance;
        int winner = -1;
        auto visit = [&](int x, int y, int z) {
            const size_t c = CellIndex(x, y, z);
            for (int i = start[c]; i < start[c + 1]; ++i)
                if (accept(entries[i].face) && Nearer(entries[i], p, minDist, closest)) winner = entries[i].face;
        };
        ScalarType newRadius = box.voxel.Norm(), radius;
        vcg::Box3i done;  // null: no cell done
        if (box.bbox.IsInEx(p)) {
            vcg::Point3i home;
            box.PToIP(p, home);
            visit(home[0], home[1], home[2]);
            if (winner >= 0) newRadius = minDist;
            done = vcg::Box3i(home, home);
        }
        const vcg::Box3i all = AllCells();
        do {
            radius = newRadius;
            vcg::Box3i todo;
            box.BoxToIBox(vcg::Box3<ScalarType>(p, radius), todo);
            todo.Intersect(all);
            for (int x = todo.min[0]; x <= todo.max[0]; ++x)
                for (int y = todo.min[1]; y <= todo.max[1]; ++y)
                    for (int z = todo.min[2]; z <= todo.max[2]; ++z)
                        if (x < done.min[0] || x > done.max[0] || y < done.min[1] || y > done.max[1] || z < done.min[2] ||
                            z > done.max[2])
                            visit(x, y, z);
            newRadius = winner < 0 ? radius + box.voxel.Norm() : minDist;
            done = todo;
        } while (minDist > radius);
        return winner;
    }

    // Calls visit(index) for every triangle nearer q than radius (PointFaceDistance's test) among
    // those filed in the cells the box of that sphere touches (vcglib's GetInSphere's set), once
    // per cell it is filed in.
    template <class Visit>
    void ForEachWithin(const CoordType &q, ScalarType radius, const Visit &visit) const
    {
        if (entries.empty()) return;
        vcg::Box3i span;
        box.BoxToIBox(vcg::Box3<ScalarType>(q, radius), span);
        span.Intersect(AllCells());
        if (span.IsNull()) return;
        CoordType point;
        for (int z = span.min[2]; z <= span.max[2]; ++z)
            for (int y = span.min[1]; y <= span.max[1]; ++y)
                for (int x = span.min[0]; x <= span.max[0]; ++x) {
                    const size_t c = CellIndex(x, y, z);
                    for (int i = start[c]; i < start[c + 1]; ++i) {
                        ScalarType d = radius;
                        if (Nearer(entries[i], q, d, point)) visit(entries[i].face);
                    }
                }
    }

private:
    // A triangle as filed in a cell: its corners, its index in the mesh, and a ball holding it.
    // The ball passes over most triangles of a cell without the exact test: near a surface every
    // neighbouring triangle's plane passes near the query point, so the plane bound of
    // PointFaceDistance lets them through, but their balls are far.
    struct Entry {
        CoordType corner[3];
        CoordType centre;
        ScalarType reach;  // every point of the triangle is within `reach` of `centre` (rounded up)
        int face;
    };
    // Relative and absolute (times the box's diagonal) slack on the ball test: it may only pass over
    // a triangle the exact test would refuse, whatever the rounding of the two (distances computed
    // from coordinates are off by about 1e-16 of the coordinates, not of the distance: a point on
    // the surface is at distance 0 up to that).
    static constexpr double kBallSlack = 1e-9;
    static constexpr double kRoundingDiagonal = 1e-12;
    double roundingSlack = 0;

    static Entry MakeEntry(const CoordType &a, const CoordType &b, const CoordType &c, int face)
    {
        Entry e;
        e.corner[0] = a;
        e.corner[1] = b;
        e.corner[2] = c;
        e.centre = (a + b + c) / ScalarType(3);
        double reach = 0;
        for (const CoordType &corner : e.corner) reach = std::max(reach, (P3::Construct(corner) - P3::Construct(e.centre)).Norm());
        e.reach = std::nextafter(ScalarType(reach * (1 + kBallSlack)), std::numeric_limits<ScalarType>::max());
        e.face = face;
        return e;
    }

    vcg::BasicGrid<ScalarType> box;  // GridStaticPtr's geometry: box, cell counts, cell size
    std::vector<int> start;          // per cell (and a sentinel): its first entry
    std::vector<Entry> entries;      // cell by cell, each cell's in GridStaticPtr's order

    vcg::Box3i AllCells() const { return vcg::Box3i(vcg::Point3i(0, 0, 0), box.siz - vcg::Point3i(1, 1, 1)); }
    size_t CellIndex(int x, int y, int z) const { return size_t(x) + size_t(box.siz[0]) * (size_t(y) + size_t(box.siz[1]) * size_t(z)); }

    bool Nearer(const Entry &e, const CoordType &p, ScalarType &minDist, CoordType &closest) const
    {
        const double beyond = (double(minDist) + double(e.reach)) * (1 + kBallSlack) + roundingSlack;
        if ((P3::Construct(p) - P3::Construct(e.centre)).SquaredNorm() > beyond * beyond) return false;
        return PointFaceDistance<FaceType>::Nearer(e.corner, p, minDist, closest);
    }
};

}  // namespace vcg_ext

#endif
