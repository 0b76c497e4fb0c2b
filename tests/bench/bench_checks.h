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

// ---------------------------------------------------------------- degenerate faces (--big-degenerate)
// Needles: a face's vertex c moved to this fraction of its height above the opposite edge (a "cap":
// area 1e-4 of the face's, an angle near 180 degrees), far above the core's exact degeneracy (sine
// of an angle below 1e-12, MeshChecks::IsZeroArea), so the pipeline must run on it.
constexpr double kNeedleHeight = 1e-4;
// The foot of c on the opposite edge stays this far inside it (no needle with a second tiny angle).
constexpr double kNeedleFootMargin = 0.1;
// A needle is made only when every other face around c keeps its orientation and at least this
// fraction of its area: one needle per place, not a cluster of flipped faces around it.
constexpr double kNeighbourAreaKept = 0.1;
// Candidates tried after a rejected one before the next slot (the faces are spread over the mesh).
constexpr int kInjectTries = 64;

struct Injected {
    int made = 0;       // faces made needles (or exactly degenerate)
    int rejected = 0;   // candidates skipped (a neighbour would turn or thin, a neighbourhood in use, or
                        // the needle turned over once written in float)
    double minAreaRatio = 1, maxAreaRatio = 0;  // needles: area after / before, as written in float
};

// Makes `count` faces of m degenerate, spread evenly over the face order, the mesh kept closed and
// 2-manifold (vertices move, none merge, the connectivity is untouched). exact = false: needles as
// above. exact = true: c moved onto its neighbour a's position, so the face and the one across
// edge c-a have zero area exactly (a repeated position), what the pipeline refuses.
inline Injected InjectDegenerateFaces(TMesh &m, int count, bool exact)
{
    typedef vcg::Point3d D3;
    Injected r;
    const int F = int(m.face.size());
    if (count <= 0 || F == 0) return r;
    std::vector<std::vector<int>> facesOf(m.vert.size());  // vertex -> its faces
    for (int f = 0; f < F; ++f)
        if (!m.face[f].IsD())
            for (int k = 0; k < 3; ++k) facesOf[vcg::tri::Index(m, m.face[f].V(k))].push_back(f);
    std::vector<char> used(m.vert.size(), 0);  // vertices of a changed neighbourhood
    auto cross = [&](int f, int moved, const D3 &at) {
        D3 p[3];
        for (int k = 0; k < 3; ++k) {
            const int v = int(vcg::tri::Index(m, m.face[f].V(k)));
            p[k] = v == moved ? at : D3::Construct(m.face[f].cP(k));
        }
        return (p[1] - p[0]) ^ (p[2] - p[0]);
    };
    for (int slot = 0; slot < count; ++slot) {
        const int first = int(long(slot) * F / count);
        for (int t = 0; t < kInjectTries; ++t) {
            const int f = (first + t) % F;
            if (m.face[f].IsD()) continue;
            const int a = int(vcg::tri::Index(m, m.face[f].V(0))), b = int(vcg::tri::Index(m, m.face[f].V(1))),
                      c = int(vcg::tri::Index(m, m.face[f].V(2)));
            bool free = true;
            for (int g : facesOf[c])
                for (int k = 0; k < 3; ++k) free = free && !used[vcg::tri::Index(m, m.face[g].V(k))];
            if (!free) { ++r.rejected; continue; }
            const D3 pa = D3::Construct(m.vert[a].cP()), pb = D3::Construct(m.vert[b].cP()), pc = D3::Construct(m.vert[c].cP());
            D3 target = pa;
            if (!exact) {
                const D3 ab = pb - pa;
                const double s = std::max(kNeedleFootMargin, std::min(1 - kNeedleFootMargin, ((pc - pa) * ab) / ab.SquaredNorm()));
                const D3 foot = pa + ab * s;
                target = foot + (pc - foot) * kNeedleHeight;
                bool ok = true;
                for (int g : facesOf[c]) {
                    if (g == f) continue;
                    const D3 before = cross(g, -1, target), after = cross(g, c, target);
                    ok = ok && before * after > 0 && after.Norm() >= kNeighbourAreaKept * before.Norm();
                }
                if (!ok) { ++r.rejected; continue; }
            }
            const D3 before = cross(f, -1, target);
            const P3 old = m.vert[c].cP();
            m.vert[c].P() = exact ? m.vert[a].cP() : P3::Construct(target);
            if (!exact) {  // the float position, not the double target, is the needle
                const double ratio = (cross(f, -1, target) * before) / before.SquaredNorm();
                if (!(ratio > 0)) { m.vert[c].P() = old; ++r.rejected; continue; }
                r.minAreaRatio = std::min(r.minAreaRatio, ratio);
                r.maxAreaRatio = std::max(r.maxAreaRatio, ratio);
            }
            for (int g : facesOf[c])
                for (int k = 0; k < 3; ++k) used[vcg::tri::Index(m, m.face[g].V(k))] = 1;
            ++r.made;
            break;
        }
    }
    vcg::tri::UpdateNormal<TMesh>::PerFaceNormalized(m);
    vcg::tri::UpdateBounding<TMesh>::Box(m);
    return r;
}

}  // namespace qmf_bench

#endif
