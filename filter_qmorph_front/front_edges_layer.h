// The edge-only layer '<mesh>_front_edges' showing the selected front edges (MeshLab 2020.09 draws
// no selected face-edges): shared by Split Triangles along Front and Q-Morph Quad Conversion.
#ifndef FILTER_QMORPH_FRONT_EDGES_LAYER_H
#define FILTER_QMORPH_FRONT_EDGES_LAYER_H

#include <common/meshmodel.h>
#include <vcg_ext/common/front_edges.h>

// Replaces the content of the layer (created, not current, when missing) by the given edges of
// mm's mesh. Returns the layer; `existed` tells whether it was refreshed rather than created.
inline MeshModel *RefreshFrontEdgesLayer(MeshDocument &md, MeshModel &mm,
                                         const std::vector<vcg_ext::FrontEdges<CMeshO>::Edge> &edges, bool &existed)
{
    const QString label = mm.label() + "_front_edges";
    MeshModel *layer = nullptr;
    for (MeshModel *other : md.meshList)
        if (other != &mm && other->label() == label) layer = other;
    existed = layer != nullptr;
    if (layer == nullptr) layer = md.addNewMesh("", label, false);
    vcg_ext::FrontEdges<CMeshO>::BuildEdgeMesh(mm.cm, edges, layer->cm);
    layer->UpdateBoxAndNormals();
    return layer;
}

#endif
