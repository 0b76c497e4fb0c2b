// Fills an edge-only vcg mesh (a MeshLab polyline layer) with points and segments: the one writer
// of the `_front` and `_front_edges` layers (MeshLab 2020.09 draws mesh edges only in such layers).
#ifndef VCG_EXT_COMMON_EDGE_LAYER_H
#define VCG_EXT_COMMON_EDGE_LAYER_H

#include <array>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/update/bounding.h>

namespace vcg_ext {

// Replaces the content of `out`: one vertex per point, one edge per segment (point indices).
template <class EdgeMeshType, class PointType>
void WriteEdgeLayer(const std::vector<PointType> &points, const std::vector<std::array<int, 2>> &segments, EdgeMeshType &out)
{
    typedef typename EdgeMeshType::CoordType Coord;
    out.Clear();
    if (!points.empty()) {
        auto vi = vcg::tri::Allocator<EdgeMeshType>::AddVertices(out, points.size());
        for (size_t i = 0; i < points.size(); ++i, ++vi) vi->P() = Coord::Construct(points[i]);
    }
    if (!segments.empty()) {
        auto ei = vcg::tri::Allocator<EdgeMeshType>::AddEdges(out, segments.size());
        for (size_t i = 0; i < segments.size(); ++i, ++ei) {
            ei->V(0) = &out.vert[segments[i][0]];
            ei->V(1) = &out.vert[segments[i][1]];
        }
    }
    vcg::tri::UpdateBounding<EdgeMeshType>::Box(out);
}

}  // namespace vcg_ext

#endif
