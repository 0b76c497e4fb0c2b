// How often the thread that entered a filter reports progress at least, whatever runs meanwhile: the
// progress relay repeats its last report (common/progress_relay.h) and the thread pool's calling
// thread wakes to merge and report (common/parallel.h) at this period. Gaps stay well under the 2 s
// MeshLab users notice.
#ifndef VCG_EXT_COMMON_PROGRESS_PERIOD_H
#define VCG_EXT_COMMON_PROGRESS_PERIOD_H

namespace vcg_ext {

constexpr double kProgressPeriodSeconds = 0.25;

}  // namespace vcg_ext

#endif
