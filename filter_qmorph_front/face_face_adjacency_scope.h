// The face-face adjacency component a core needs, turned on without MeshLab's
// updateDataMask(MM_FACEFACETOPO): that also builds the adjacency with vcglib's
// UpdateTopology::FaceFace, which sorts a record per face edge (about a second at 3.3M faces, once per
// filter), although the cores build their own in linear time (vcg_ext::FaceFaceAdjacency, the same
// links). The component is on for the scope and off again at its end when it was off before
// (Keep: stays on); the data-mask bit is left to the caller, so no filter trusts links it did not
// build.
#ifndef FILTER_QMORPH_FRONT_FACE_FACE_ADJACENCY_SCOPE_H
#define FILTER_QMORPH_FRONT_FACE_FACE_ADJACENCY_SCOPE_H

#include <common/meshmodel.h>

class FaceFaceAdjacencyScope
{
public:
    explicit FaceFaceAdjacencyScope(CMeshO &m) : mesh(m), enabledHere(!m.face.IsFFAdjacencyEnabled())
    {
        if (enabledHere) mesh.face.EnableFFAdjacency();
    }
    ~FaceFaceAdjacencyScope()
    {
        if (enabledHere) mesh.face.DisableFFAdjacency();
    }
    FaceFaceAdjacencyScope(const FaceFaceAdjacencyScope &) = delete;
    FaceFaceAdjacencyScope &operator=(const FaceFaceAdjacencyScope &) = delete;

    // The component stays on after the scope (the caller has set the data-mask bit).
    void Keep() { enabledHere = false; }

private:
    CMeshO &mesh;
    bool enabledHere;
};

#endif
