// Placeholder: this filter is being implemented (see the issue tracker). Refuses to run.
#include "filter_qmorph_front.h"

QString QMorphFrontPlugin::smoothInfo() { return "Not implemented yet."; }

void QMorphFrontPlugin::initSmoothParameters(MeshDocument &, RichParameterList &) {}

bool QMorphFrontPlugin::applySmooth(MeshDocument &, const RichParameterList &, vcg::CallBackPos *)
{
    return fail(filterName(FP_SMOOTH_BOUNDARIES), "not implemented yet");
}
