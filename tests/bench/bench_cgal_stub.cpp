// Built when CGAL is absent: the benchmark prints that the comparison was skipped.
#include "bench_cgal.h"

namespace qmf_bench {

bool CgalAvailable() { return false; }
std::string CgalVersion() { return ""; }
CgalVsaRun RunCgalVsa(const std::vector<std::array<double, 3>> &, const std::vector<std::array<int, 3>> &, int, CgalSeeding,
                      int, int, unsigned)
{
    CgalVsaRun r;
    r.error = "CGAL not available (apt-get install libcgal-dev, then reconfigure)";
    return r;
}

}  // namespace qmf_bench
