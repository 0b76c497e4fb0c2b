#include "filter_qmorph_front.h"

QMorphFrontPlugin::QMorphFrontPlugin()
{
    typeList << FP_VSA_SEGMENT << FP_SMOOTH_BOUNDARIES << FP_SPLIT_ALONG_FRONT << FP_QMORPH;
    for (FilterIDType t : typeList) actionList << new QAction(filterName(t), this);
}

// These names are the scripting API (.mlx files refer to them): never rename them.
QString QMorphFrontPlugin::filterName(FilterIDType filter) const
{
    switch (filter) {
    case FP_VSA_SEGMENT: return "Segment by Variational Shape Approximation";
    case FP_SMOOTH_BOUNDARIES: return "Smooth Region Boundaries";
    case FP_SPLIT_ALONG_FRONT: return "Split Triangles along Front";
    case FP_QMORPH: return "Q-Morph Quad Conversion";
    }
    return "unknown filter";
}

// Two or three sentences (what the filter does, reads and writes) and the paper; the long
// explanations are in the README.
QString QMorphFrontPlugin::filterInfo(FilterIDType filter) const
{
    const QString pipeline =
        "<br>The pipeline: <b>\"Transformation of a closed 3D triangular mesh to a quadrilateral mesh based on feature "
        "edges\"</b>; details of every step and parameter in the plugin's README.";
    switch (filter) {
    case FP_VSA_SEGMENT: return vsaInfo() + pipeline;
    case FP_SMOOTH_BOUNDARIES: return smoothInfo() + pipeline;
    case FP_SPLIT_ALONG_FRONT: return splitInfo() + "<br>Details of every step and parameter in the plugin's README.";
    case FP_QMORPH: return qmorphInfo() + pipeline;
    }
    return "";
}

MeshFilterInterface::FilterClass QMorphFrontPlugin::getClass(QAction *a)
{
    return ID(a) == FP_QMORPH ? FilterClass(Remeshing | Polygonal) : FilterClass(Remeshing);
}

MeshFilterInterface::FILTER_ARITY QMorphFrontPlugin::filterArity(QAction *a) const
{
    return ID(a) == FP_SPLIT_ALONG_FRONT ? FIXED : SINGLE_MESH;  // splitting reads a second (polyline) layer
}

int QMorphFrontPlugin::getPreConditions(QAction *) const
{
    return MeshModel::MM_NONE;  // checked in applyFilter, with a message saying what is missing
}

// Precise post-conditions: the GUI turns on the rendering attributes a filter declares as changed.
// MM_GEOMETRY_AND_TOPOLOGY_CHANGE would reset the rendering of layer 0 (face colours no longer
// shown), and MM_VERTNORMAL switches its shading to per-vertex (MeshLab 2020.09's
// updatedRendAttsAccordingToPriorities drops face normals whenever vertex normals are updated).
int QMorphFrontPlugin::postCondition(QAction *a) const
{
    switch (ID(a)) {
    case FP_VSA_SEGMENT: return MeshModel::MM_FACEQUALITY | MeshModel::MM_FACECOLOR;
    case FP_SMOOTH_BOUNDARIES: return MeshModel::MM_NONE;  // adds a layer, the mesh is untouched
    case FP_SPLIT_ALONG_FRONT:
        // No normal bit, so the shading stays as the user set it: splitting moves no vertex (the
        // face and vertex normals keep their directions), and it adds vertices and faces whenever it
        // changes the mesh, so the GUI re-sizes and refills every normal buffer it draws anyway.
        return MeshModel::MM_VERTCOORD | MeshModel::MM_VERTNUMBER | MeshModel::MM_FACENUMBER | MeshModel::MM_FACEVERT |
               MeshModel::MM_FACEFLAG | MeshModel::MM_FACEQUALITY | MeshModel::MM_FACECOLOR;
    case FP_QMORPH:
        // No normal bit either: every face is replaced and the vertex and face counts change (the
        // same counts again would be a coincidence), so the GUI re-sizes and refills every buffer it
        // draws, normals included (the filter ends with UpdateBoxAndNormals).
        return MeshModel::MM_VERTCOORD | MeshModel::MM_VERTNUMBER | MeshModel::MM_FACENUMBER |
               MeshModel::MM_FACEVERT | MeshModel::MM_FACEFLAG | MeshModel::MM_FACEQUALITY | MeshModel::MM_FACECOLOR;
    }
    return MeshModel::MM_ALL;
}

void QMorphFrontPlugin::initParameterSet(QAction *a, MeshModel &m, RichParameterList &par)
{
    if (ID(a) == FP_VSA_SEGMENT) initVsaParameters(m, par);
}

void QMorphFrontPlugin::initParameterSet(QAction *a, MeshDocument &md, RichParameterList &par)
{
    switch (ID(a)) {
    case FP_VSA_SEGMENT: if (md.mm()) initVsaParameters(*md.mm(), par); break;
    case FP_SMOOTH_BOUNDARIES: initSmoothParameters(md, par); break;
    case FP_SPLIT_ALONG_FRONT: initSplitParameters(md, par); break;
    case FP_QMORPH: initQMorphParameters(md, par); break;
    }
}

bool QMorphFrontPlugin::applyFilter(QAction *a, MeshDocument &md, const RichParameterList &par, vcg::CallBackPos *cb)
{
    if (md.mm() == nullptr) return fail(a->text(), "there is no current mesh");
    switch (ID(a)) {
    case FP_VSA_SEGMENT: return applyVsa(md, par, cb);
    case FP_SMOOTH_BOUNDARIES: return applySmooth(md, par, cb);
    case FP_SPLIT_ALONG_FRONT: return applySplit(md, par, cb);
    case FP_QMORPH: return applyQMorph(md, par, cb);
    }
    return fail(a->text(), "unknown filter");
}

bool QMorphFrontPlugin::fail(const QString &filter, const QString &why)
{
    errorMessage = filter + ": " + why;
    Log("%s", qUtf8Printable(errorMessage));
    return false;
}

MESHLAB_PLUGIN_NAME_EXPORTER(QMorphFrontPlugin)
