// Placeholder: this filter is being implemented (see the issue tracker). Refuses to run.
#include "filter_qmorph_front.h"

QString QMorphFrontPlugin::qmorphInfo() { return "Not implemented yet."; }

void QMorphFrontPlugin::initQMorphParameters(MeshDocument &, RichParameterList &) {}

bool QMorphFrontPlugin::applyQMorph(MeshDocument &, const RichParameterList &, vcg::CallBackPos *)
{
    return fail(filterName(FP_QMORPH), "not implemented yet");
}
