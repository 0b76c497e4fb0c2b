#include "filter_qmorph_front.h"

namespace {
const char *kPaperReference =
    "<br><br>See: <i>Transformation of a closed 3D triangular mesh to a quadrilateral mesh based on "
    "feature edges</i> (the seed paper of this plugin), and<br>"
    "<i>S. Owen, M. Staten, S. Canann, S. Saigal</i>, <b>\"Q-Morph: an indirect approach to advancing front "
    "quad meshing\"</b>, IJNME 44:1317-1340, 1999.";
}

QMorphFrontPlugin::QMorphFrontPlugin()
{
    typeList << FP_VSA_SEGMENT;
    for (FilterIDType t : typeList) actionList << new QAction(filterName(t), this);
}

QString QMorphFrontPlugin::filterName(FilterIDType filter) const
{
    switch (filter) {
    case FP_VSA_SEGMENT: return "Segment by Variational Shape Approximation";
    }
    return "unknown filter";
}

QString QMorphFrontPlugin::filterInfo(FilterIDType filter) const
{
    switch (filter) {
    case FP_VSA_SEGMENT:
        return QString(
                   "Step 1 of the closed-mesh-to-quads pipeline. Partitions the mesh into near-planar, "
                   "edge-connected regions by Variational Shape Approximation with the L<sup>2,1</sup> metric "
                   "(Lloyd iterations of flooding and proxy fitting). Starts from a few random seeds and adds a "
                   "seed in every region whose faces deviate from its proxy normal by more than the threshold "
                   "angle, or reaches a fixed region count by incremental seeding. The region id of each face "
                   "is written to the <b>face quality</b> (0..K-1) and faces are coloured by region."
                   "<br><br>See: <i>D. Cohen-Steiner, P. Alliez, M. Desbrun</i>, <b>\"Variational Shape "
                   "Approximation\"</b>, ACM SIGGRAPH 2004, pp. 905-914.") + kPaperReference;
    }
    return "";
}

MeshFilterInterface::FilterClass QMorphFrontPlugin::getClass(QAction *)
{
    return FilterClass(Remeshing);
}

MeshFilterInterface::FILTER_ARITY QMorphFrontPlugin::filterArity(QAction *) const
{
    return SINGLE_MESH;
}

int QMorphFrontPlugin::getPreConditions(QAction *) const
{
    return MeshModel::MM_NONE;  // checked in applyFilter, with a message saying what is missing
}

int QMorphFrontPlugin::postCondition(QAction *a) const
{
    switch (ID(a)) {
    case FP_VSA_SEGMENT: return MeshModel::MM_FACEQUALITY | MeshModel::MM_FACECOLOR;
    }
    return MeshModel::MM_ALL;
}

void QMorphFrontPlugin::initParameterSet(QAction *a, MeshModel &m, RichParameterList &par)
{
    switch (ID(a)) {
    case FP_VSA_SEGMENT: initVsaParameters(m, par); break;
    }
}

bool QMorphFrontPlugin::applyFilter(QAction *a, MeshDocument &md, const RichParameterList &par, vcg::CallBackPos *cb)
{
    if (md.mm() == nullptr) return fail(a->text(), "there is no current mesh");
    switch (ID(a)) {
    case FP_VSA_SEGMENT: return applyVsa(md, par, cb);
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
