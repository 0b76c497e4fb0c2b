// The bounding box of a mesh's live vertices in double, read without touching the mesh (vcglib's
// UpdateBounding writes m.bbox, in the mesh's scalar type): the scale the filters' tolerances and
// lengths are fractions of.
#ifndef VCG_EXT_COMMON_LIVE_BOX_H
#define VCG_EXT_COMMON_LIVE_BOX_H

#include <vcg/space/box3.h>

namespace vcg_ext {

template <class MeshType>
vcg::Box3d LiveVertexBox(const MeshType &m)
{
    vcg::Box3d box;
    for (const auto &v : m.vert)
        if (!v.IsD()) box.Add(vcg::Point3d::Construct(v.cP()));
    return box;
}

}  // namespace vcg_ext

#endif
