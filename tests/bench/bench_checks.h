// What the benchmark needs besides the core's own reports and the tests' independent checks
// (quad_checks.h): memory (VmRSS / VmHWM), mesh loading (PLY / OFF) and midpoint refinement.
#ifndef QMF_BENCH_CHECKS_H
#define QMF_BENCH_CHECKS_H

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <vcg/complex/algorithms/closest.h>
#include <vcg/complex/algorithms/refine.h>
#include <vcg/space/index/grid_static_ptr.h>
#include <wrap/io_trimesh/import_off.h>
#include <wrap/io_trimesh/import_ply.h>

#include "quad_checks.h"
#include "test_mesh.h"
#include <vcg_ext/quad_quality.h>

namespace qmf_bench {

using qmf_test::TMesh;
using qmf_test::TFace;
using namespace qmf_test;
typedef vcg::Point3f P3;

// ---------------------------------------------------------------- memory (Linux /proc)
// A "VmXXX:   1234 kB" field of /proc/self/status, in MiB (-1 when unreadable).
inline double StatusMiB(const char *key)
{
    std::ifstream in("/proc/self/status");
    std::string line;
    const size_t n = std::strlen(key);
    while (std::getline(in, line))
        if (line.compare(0, n, key) == 0 && line.size() > n && line[n] == ':') return std::atof(line.c_str() + n + 1) / 1024.0;
    return -1;
}
inline double RssMiB() { return StatusMiB("VmRSS"); }
inline double PeakMiB() { return StatusMiB("VmHWM"); }
// Resets VmHWM to the current RSS (Linux >= 4.0: "5" into clear_refs). False when not allowed.
inline bool ResetPeak()
{
    FILE *f = std::fopen("/proc/self/clear_refs", "w");
    if (!f) return false;
    bool ok = std::fputs("5", f) >= 0;
    ok = std::fclose(f) == 0 && ok;
    return ok;
}

// ---------------------------------------------------------------- loading
inline std::string Lower(std::string s)
{
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

inline bool EndsWith(const std::string &s, const std::string &suffix)
{
    return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// PLY (vcg's importer, plylib) or OFF, by extension. Empty string on success.
inline std::string LoadMesh(TMesh &m, const std::string &path)
{
    m.Clear();
    const std::string ext = Lower(path);
    int mask = 0;
    if (EndsWith(ext, ".ply")) {
        int e = vcg::tri::io::ImporterPLY<TMesh>::Open(m, path.c_str(), mask);
        if (e != 0 && vcg::tri::io::ImporterPLY<TMesh>::ErrorCritical(e))
            return std::string("PLY import failed: ") + vcg::tri::io::ImporterPLY<TMesh>::ErrorMsg(e);
    } else if (EndsWith(ext, ".off")) {
        int e = vcg::tri::io::ImporterOFF<TMesh>::Open(m, path.c_str(), mask);
        if (e != 0)
            return std::string("OFF import failed: ") + vcg::tri::io::ImporterOFF<TMesh>::ErrorMsg(e);
    } else {
        return "unknown mesh format (PLY or OFF): " + path;
    }
    if (m.fn == 0) return "no faces in " + path;
    for (auto &f : m.face) f.Q() = 0;
    vcg::tri::UpdateBounding<TMesh>::Box(m);
    vcg::tri::UpdateNormal<TMesh>::PerFaceNormalized(m);
    return "";
}

// Midpoint subdivision, `steps` times (vcg's tri::Refine with MidPoint, every edge split: 4 faces
// per face, the surface unchanged).
inline void MidpointRefine(TMesh &m, int steps)
{
    for (int s = 0; s < steps; ++s) {
        vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
        vcg::tri::Refine<TMesh, vcg::tri::MidPoint<TMesh>>(m, vcg::tri::MidPoint<TMesh>(&m), 0);
    }
    vcg::tri::Allocator<TMesh>::CompactEveryVector(m);
    vcg::tri::UpdateBounding<TMesh>::Box(m);
    vcg::tri::UpdateNormal<TMesh>::PerFaceNormalized(m);
}

}  // namespace qmf_bench

#endif
