// Placeholder: this filter is being implemented (see the issue tracker). Refuses to run.
#include "filter_qmorph_front.h"

QString QMorphFrontPlugin::splitInfo() { return "Not implemented yet."; }

void QMorphFrontPlugin::initSplitParameters(MeshDocument &, RichParameterList &) {}

bool QMorphFrontPlugin::applySplit(MeshDocument &, const RichParameterList &, vcg::CallBackPos *)
{
    return fail(filterName(FP_SPLIT_ALONG_FRONT), "not implemented yet");
}
