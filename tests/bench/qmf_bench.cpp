// qmf_bench: the project's benchmark program (not a test, never run by CTest).
//
// Per mesh, the whole pipeline with the filters' default parameters, each stage timed on the core
// (vcg_ext/, the same calls the plugin makes, on a float mesh like MeshLab's CMeshO):
//   1 VSASegmentation::Segment            -> region ids (face quality)
//   2 RegionBoundarySmoothing::Smooth     -> curves; ToPolylines + BuildEdgeMesh -> the front layer
//   3 PolylineEmbedding::Embed            -> mesh split along the front, front = selected face-edges
//   4 QMorph::Apply                       -> quad-dominant mesh (quads = triangle pairs, faux diagonal)
// then, independently of the core: quad quality of the polygon mesh read back from the faux edges,
// two-sided sampled Hausdorff distance to the input, closed 2-manifold, Euler characteristic,
// initial front kept; MeshLab's own quad conversions (vcg BitQuadCreation) on the same split input;
// CGAL's Variational_shape_approximation on the same mesh (when built with CGAL); and a ~1M-face
// case (midpoint subdivision) with per-stage times and peak memory (VmHWM, reset per stage), and
// optionally (--big-degenerate N) the same with N needle faces and with N exactly degenerate ones.
//
// Each mesh runs in a child process (fork): a crash is reported as such, and memory figures are
// per mesh. Rows travel to the parent as tab-separated lines; the parent prints markdown tables.
#include <malloc.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "bench_cgal.h"
#include "bench_checks.h"  // vcg's complex.h first: bitquad_creation.h does not include it

#include <vcg/complex/algorithms/bitquad_creation.h>
#include <wrap/io_trimesh/export_ply.h>
#include <vcg/complex/append.h>
#include <vcg_ext/geodesic_straightening.h>
#include <vcg_ext/mesh_checks.h>
#include <vcg_ext/polyline_embedding.h>
#include <vcg_ext/qmorph.h>
#include <vcg_ext/quad_quality.h>
#include <vcg_ext/vsa_segmentation.h>

namespace {

using namespace qmf_bench;
typedef vcg_ext::VSASegmentation<TMesh> VSA;
typedef vcg_ext::RegionBoundarySmoothing<TMesh> Smoothing;
typedef vcg_ext::PolylineEmbedding<TMesh> Embedding;
typedef vcg_ext::QMorph<TMesh> QM;
typedef vcg::tri::BitQuadCreation<TMesh> BitQuad;
typedef std::chrono::steady_clock Clock;

double Since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

std::string Fmt(const char *fmt, ...)
{
    char buf[512];
    va_list ap;
    va_start(ap, fmt);
    std::vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    return buf;
}
std::string Ms(double s) { return s < 0.1 ? Fmt("%.2f", 1000 * s) : s < 10 ? Fmt("%.1f", 1000 * s) : Fmt("%.0f", 1000 * s); }
std::string Sec(double s) { return s < 1 ? Fmt("%.3f", s) : Fmt("%.2f", s); }
std::string Pct(double f) { return Fmt("%.1f", 100 * f); }
std::string YesNo(bool b) { return b ? "yes" : "NO"; }
std::string Count(long n) { return std::to_string(n); }

// ------------------------------------------------------------------ report tables
enum TableId {
    T_VSA, T_SMOOTH, T_SPLIT, T_QMORPH, T_CHECKS, T_BARS, T_BITQUAD, T_CGAL_SPEED, T_CGAL_QUALITY, T_BIG, T_DEGENERATE, T_SCALING,
    T_NOTES, T_COUNT
};

struct TableDef {
    std::string title;
    std::vector<std::string> header;
    const char *note;
};

const TableDef &Def(int t)
{
    static const std::vector<TableDef> defs = {
        {Fmt("Filter 1 - VSA segmentation (defaults: %s mode, %g deg, %d initial seeds, %s, <= %d Lloyd "
             "iterations per round)", VSA::Params().mode == VSA::ThresholdSeeding ? "threshold" : "fixed-count",
             VSA::Params().thresholdAngleDeg, VSA::Params().initialSeeds,
             VSA::Params().maxRegions > 0 ? Fmt("<= %d regions", VSA::Params().maxRegions).c_str()
                                          : "automatic region cap (one per 4 faces, at least 200)",
             VSA::Params().maxIterations),
         {"mesh", "faces", "regions", "Lloyd it. (rounds)", "L2,1 error", "max dev. (deg)", "time (ms)", "ms / Lloyd it."},
         "time: wall clock of VSASegmentation::Segment (face-face topology included), best of the repeats; ms / Lloyd "
         "it. = time / Lloyd iterations (seeding and statistics included)."},
        {Fmt("Filter 2 - boundary smoothing (defaults: %d iterations, snap %g %%)", Smoothing::Params().iterations,
             Smoothing::Params().snapPercent),
         {"mesh", "curves", "corners", "points before -> after", "points / curve", "length reduction %",
          "jaggedness before -> after", "time (ms)", "of which straightening (ms)"},
         "time: RegionBoundarySmoothing::Smooth + ToPolylines + BuildEdgeMesh (what the filter computes); length "
         "reduction = 1 - length after / length before (total over the curves); jaggedness = total |geodesic turning| / length."},
        {Fmt("Filter 3 - splitting triangles along the front (defaults: locate tolerance %g %% of the diagonal)",
             Embedding::Params().locateTolerancePercent),
         {"mesh", "polyline points", "faces crossed", "faces split", "vertices added", "faces added", "front edges",
          "patches", "min angle (deg)", "time (ms)", "prepare / apply (ms)"},
         "time: PolylineEmbedding::Embed on the front layer as the plugin builds it (float coordinates, re-located)."},
        {"Filter 4 - Q-Morph (defaults) on the split mesh",
         {"mesh", "input faces", "time (ms)", "patches", "quads", "triangles", "quad % (area)", "quad % (count)",
          "mean SJ", "min SJ", "quads < 0.3 %", "inverted", "irregular %", "failed front steps",
          "flipped (core / independent, beside >90 deg creases)", "folded quads"},
         "quality measured on the polygon mesh read back from the output's faux edges (QuadQuality::FromFauxMesh + "
         "Measure); SJ = scaled Jacobian; irregular = interior all-quad vertices of valence != 4, over all such vertices; "
         "failed front steps: Q-Morph front edges whose quad formation failed and was retried later (QMorph Result::ops.failures). "
         "flipped: faces whose vector area points away from the input surface (core: Q-Morph's own report; independent: "
         "the closest input triangle to the face's centroid by a vcg grid, tests/support FlippedFaces, with the faces whose "
         "closest triangle borders a crease sharper than 90 degrees counted apart); folded: quads bent over 60 degrees "
         "along both diagonals."},
        {"Whole pipeline - invariants",
         {"mesh", "pipeline time (ms)", "Hausdorff / diag %", "volume change %", "closed 2-manifold",
          "genus kept (chi in -> out)", "front kept", "peak memory (MiB)"},
         "Hausdorff: two-sided, sampled at vertices, edge midpoints and face centroids of each surface, closest point "
         "on the other (vcg grid), over the input's bounding-box diagonal. closed 2-manifold: output triangle form "
         "closed, 2-manifold, consistently oriented. chi: V - E + F of the input and of the output polygon mesh. front "
         "kept: every selected edge of the split mesh is an output edge and the selection is unchanged. peak memory: "
         "VmHWM of the mesh's process during the 4 stages (VmHWM reset before stage 1)."},
        {"Quality bars - pass / fail",
         {"mesh", "quad area >= 95 %", "quads >= 90 %", "no inversion", "mean SJ >= 0.75", "< 2 % below 0.3",
          "irregular <= 20 %", "Hausdorff <= 0.5 %", "closed 2-manifold", "genus kept", "front kept", "all"},
         ""},
        {"Q-Morph vs MeshLab's own quad conversions (vcg BitQuadCreation) on the same split mesh",
         {"mesh", "method", "time (ms)", "quads", "triangles", "quad % (area)", "quad % (count)", "mean SJ",
          "quads < 0.3 %", "inverted", "irregular %"},
         "MeshLab 2020.09 'Turn into Quad-Dominant mesh' = BitQuadCreation::MakeDominant(m, level), default level 0 "
         "('Fewest triangles'); level 2 = 'Better quad shape'. 'Tri to Quad by smart triangle pairing' = "
         "MakeTriEvenBySplit + MakePureByFlip(m, 100). Same metrics code for all rows."},
        {"VSA vs CGAL - Lloyd iteration speed (K random seeds, same K, N iterations, same process)",
         {"mesh", "faces", "K", "ours it.", "ours ms / it.", "CGAL it.", "CGAL ms / it.", "ours / CGAL", "ours L2,1 (random seeds)",
          "CGAL L2,1 (random seeds)"},
         "ours: VSASegmentation in threshold mode with initialSeeds = maxRegions = K (K random seeds, no split round), "
         "relativeTolerance 0; ms / it. = (t(N) - t(1)) / (it(N) - it(1)) from two runs with the same seeds, so set-up "
         "(topology, normals, areas) is excluded, each iteration = re-seed + flood + fit + error. CGAL: "
         "Variational_shape_approximation (L21_metric_plane_proxy, Sequential_tag), RANDOM seeding with 0 relaxations, "
         "ms / it. = time of run(N) / N. Both L2,1 errors computed by VSASegmentation::L21Error from the labels and "
         "proxy normals. Best of the repeats."},
        {"VSA vs CGAL - L2,1 error at equal region count K",
         {"mesh", "K", "ours", "ours time (s)", "ours Lloyd it.", "ours L2,1", "CGAL", "CGAL time (s)", "CGAL L2,1",
          "ours / CGAL", "within 5 %"},
         "K = the pipeline's region count. 'threshold (pipeline)': the filter's default run (its time and error as in "
         "the filter 1 table) against CGAL's default HIERARCHICAL seeding to K proxies (5 relaxations per round) + "
         "run(N). 'fixed K': FixedRegionCount, maxRegions = K, relaxationsPerSeed 5, maxIterations N, "
         "teleportAttempts 10 (defaults) against CGAL INCREMENTAL seeding to K (5 relaxations per seed) + run(N). "
         "Times include seeding (CGAL's without its set-up of normals and areas). L2,1 by the same function "
         "(VSASegmentation::L21Error) for both."},
        {"~1M faces (midpoint subdivision) - per-stage time and memory",
         {"mesh", "faces", "VSA mode", "regions", "VSA (s)", "VSA ms / Lloyd it.", "smoothing (s)", "split (s)",
          "Q-Morph (s)", "peak MiB VSA / smooth / split / Q-Morph", "peak bytes / input face"},
         "peak MiB: VmHWM during the stage minus VmRSS before it (malloc_trim first: the stage's extra memory; the input "
         "mesh and the earlier stages' results are in the baseline). peak bytes / input face: the process's peak VmHWM over the "
         "4 stages / input faces (compare the two sizes for linearity). Targets: VSA per-iteration no worse than CGAL "
         "(see the CGAL table), smoothing < 1 s, split < 1 s, Q-Morph < 30 s, memory linear."},
        {"~1M faces with degenerate faces (--big-degenerate N) - outcome, per-stage time and memory",
         {"mesh", "faces", "injected", "degenerate (MeshChecks)", "needle area / face area", "outcome", "VSA (s)",
          "smoothing (s)", "split (s)", "Q-Morph (s)", "pipeline (s)", "peak MiB (process)", "peak bytes / input face"},
         "The big case with N faces made degenerate after the subdivision, spread evenly over the face order, the mesh "
         "kept closed and 2-manifold. needles: a vertex moved to 1e-4 of its height above the opposite edge (area ratio as "
         "written in float; a candidate whose neighbours would turn or thin is skipped); they must run. zero area: a vertex "
         "moved onto its neighbour's position (the face and the one across that edge: zero area exactly); the pipeline "
         "must refuse them at once with its message. Times: wall clock of the core calls (- : not reached); peak MiB: the "
         "process's VmHWM over the stages run (input and copies included)."},
        {"Scaling - the whole pipeline on a mesh refined 1x, 4x, 16x (midpoint subdivision), 1 and 2 threads",
         {"mesh", "faces", "threads", "regions", "max dev. (deg)", "VSA (s)", "smoothing (s)", "split (s)", "Q-Morph (s)",
          "of which re-meshing (s)", "total (s)", "us / face", "peak bytes / face", "quad % (area)", "closed, Euler kept", "flipped",
          "longest progress gap (s)", "longest step without news (s)"},
         "Each row its own process. threads: Q-Morph's pool (QMorph::Params::threads: its patches, and the re-meshing's "
         "collapses and relaxation, cell by cell in colours; the other stages run on one thread). Times: wall "
         "clock of the core calls (no file IO), default parameters. peak bytes / face: the process's "
         "VmHWM over the four stages / input faces (the process also holds a copy of the input). longest progress gap: "
         "the longest time between two progress callbacks inside one of the four core calls (what the "
         "GUI sees: the core relays its last report at least every 0.25 s, common/progress_relay.h). longest step "
         "without news: the longest time the percent and message stayed the same (one indivisible step). flipped: "
         "Q-Morph's own count against the input surface."},
        {"Notes", {"mesh", "note"}, ""},
    };
    return defs[t];
}

// Rows go to this stream: stdout-like in a child (a pipe to the parent), collected by the parent.
FILE *g_rowOut = nullptr;

std::string Clean(std::string s)
{
    for (char &c : s)
        if (c == '\t' || c == '\n' || c == '\r') c = ' ';
    return s;
}

void Emit(TableId t, const std::vector<std::string> &cells)
{
    std::fprintf(g_rowOut, "%d", int(t));
    for (const auto &c : cells) std::fprintf(g_rowOut, "\t%s", Clean(c).c_str());
    std::fputc('\n', g_rowOut);
    std::fflush(g_rowOut);
}
void Note(const std::string &mesh, const std::string &text) { Emit(T_NOTES, {mesh, text}); }

void Progress(const std::string &mesh, const std::string &what)
{
    std::fprintf(stderr, "[qmf_bench] %s: %s\n", mesh.c_str(), what.c_str());
    std::fflush(stderr);
}

// ------------------------------------------------------------------ options
struct Options {
    std::string meshDir;
    std::vector<std::string> names;
    bool all = false;
    std::string big = "auto";      // base mesh of the ~1M case ("none": skip)
    long bigFaces = 1000000;
    bool ladder = true;            // also the ~1/4 size, for memory linearity
    int bigDegenerate = 0;         // > 0: also the big case with that many needles, and with that many zero-area faces
    std::string bigVsa = "threshold";
    int bigRegions = 0;            // 0: the default (threshold mode: the automatic cap; fixed mode: 200 regions)
    bool cgal = true;
    bool cgalBigQuality = false;   // incremental CGAL/fixed-K ours on the big mesh (slow)
    bool bitquad = true;
    int repeats = 3;
    int cgalIterations = 20;
    bool fork = true;
    bool onlyBig = false;
    std::string out;
    std::string saveDir;                 // each run's input and quad mesh as PLY ("": none)
    std::string scaling;                 // base mesh of the scaling run ("": none)
    std::vector<int> scalingSteps = {0, 1, 2};
    std::vector<int> scalingThreads = {1, 2};
    std::string plot;                    // PNG of time per face against faces (gnuplot)
};

std::vector<int> IntList(const std::string &text)
{
    std::vector<int> v;
    std::stringstream ss(text);
    std::string x;
    while (std::getline(ss, x, ','))
        if (!x.empty()) v.push_back(std::atoi(x.c_str()));
    return v;
}

void Usage()
{
    std::printf(
        "qmf_bench [options] [mesh names or paths...]\n"
        "  Runs the whole pipeline (filters 1-4, default parameters) on each mesh and prints markdown tables.\n"
        "  A name is looked up as DIR/name.ply then DIR/name.off; a path to a .ply/.off file is used as is.\n"
        "  Default names: fandisk rocker_arm_3356 rocker_arm_20k bunny_3k elephant casting (those present).\n"
        "  --meshes DIR        mesh folder (default: ../shared/meshes when it exists, else .deps/meshes)\n"
        "  --all               every .ply/.off in the folder\n"
        "  --big NAMES|none    base mesh(es) of the ~1M-face case, comma-separated (default: armadillo_52k\n"
        "                      (or armadillo) and fandisk, those found)\n"
        "  --big-faces N       target face count of the big case (default 1000000; midpoint steps x4)\n"
        "  --no-ladder         skip the ~1/4-size run of the big case (memory linearity)\n"
        "  --big-vsa MODE      threshold (default) or fixed; --big-regions K (default: the automatic cap; fixed: 200)\n"
        "  --big-only          only the big case\n"
        "  --big-degenerate N  also run the full-size big case twice more: with N needle faces (a vertex at 1e-4 of\n"
        "                      its height above the opposite edge: must run) and with N exactly zero-area faces (a vertex\n"
        "                      onto its neighbour: must be refused with a clear message); outcome, per-stage times and\n"
        "                      peak memory in their own table (default: off)\n"
        "  --no-cgal, --no-bitquad, --cgal-big-quality (CGAL incremental + our fixed-K mode on the big mesh: slow)\n"
        "  --repeats R         timing repeats on the small meshes (best time; default 3)\n"
        "  --cgal-iterations N Lloyd iterations in the CGAL comparison (default 20)\n"
        "  --no-fork           run everything in this process (a crash stops the benchmark)\n"
        "  --out FILE          also write the markdown report to FILE\n"
        "  --save-dir DIR      write each run's input (NAME.input.ply: the big case exists only in memory) and\n"
        "                      quad mesh (NAME.ply, faux and front bits in the face flags) for evalquad\n"
        "  --remesh F          Q-Morph re-meshes first to F x the mean edge length of its input\n"
        "  --remesh-diag P     Q-Morph re-meshes first to P %% of the bounding-box diagonal\n"
        "  --vsa-max-regions K VSA's Max regions on every mesh (threshold mode; 0: automatic, the default)\n"
        "  --no-cleanup, --no-smoothing  Q-Morph without its topological clean-up / tangent-plane smoothing\n"
        "  --no-preserve       Q-Morph with 'Preserve initial front' off\n"
        "  --no-remesh         Q-Morph on the split mesh's own triangles ('Re-mesh first' off)\n"
        "  --scaling NAME      only the scaling run: NAME refined by midpoint steps (--scaling-steps, default 0,1,2:\n"
        "                      1x, 4x, 16x), each with Q-Morph on 1 and 2 threads (--scaling-threads, default 1,2)\n"
        "  --plot FILE.png     with --scaling: gnuplot PNG of time per face against faces (data in FILE.png.dat)\n"
        "  --timeline          with --scaling: each new progress report (percent, message) with its time since the\n"
        "                      row's start, on stderr (where a stage's time goes; the stage calls' own\n"
        "                      'called' / 'returned' lines bound them)\n");
}

bool FileExists(const std::string &p)
{
    std::ifstream f(p);
    return f.good();
}
bool DirExists(const std::string &p) { return FileExists(p + "/."); }

std::string ResolveMesh(const Options &o, const std::string &name)
{
    if ((EndsWith(Lower(name), ".ply") || EndsWith(Lower(name), ".off")) && FileExists(name)) return name;
    for (const char *ext : {".ply", ".off"})
        if (FileExists(o.meshDir + "/" + name + ext)) return o.meshDir + "/" + name + ext;
    return "";
}

std::string BaseName(const std::string &path)
{
    std::string b = path.substr(path.find_last_of('/') + 1);
    size_t dot = b.find_last_of('.');
    return dot == std::string::npos ? b : b.substr(0, dot);
}

// ------------------------------------------------------------------ the pipeline
struct PipelineRun {
    std::string error, failedStage;
    // filter 1
    VSA::Result vsa;
    double tVsa = 0;
    // filter 2
    int curves = 0, corners = 0, loops = 0, pointsBefore = 0, pointsAfter = 0, unsnapped = 0;
    double lengthBefore = 0, lengthAfter = 0, jagBefore = 0, jagAfter = 0, tSmooth = 0, tStraighten = 0;
    int polylinePoints = 0;
    // filter 3
    Embedding::Result split;
    double tSplit = 0;
    int splitFaces = 0;
    // filter 4
    QM::Result qm;
    double tQm = 0;
    // memory per stage (MiB): RSS before, VmHWM after (reset before each stage when `memory`)
    double rssBefore[4] = {0, 0, 0, 0}, peakAfter[4] = {0, 0, 0, 0};
    double Total() const { return tVsa + tSmooth + tSplit + tQm; }
};

// Runs the 4 stages on a copy of `input`; `work` ends as the Q-Morph output, `splitOut` (if given)
// receives the split mesh (Q-Morph's input).
// Q-Morph options of the whole run (--remesh, --no-remesh, --no-preserve); the filter's defaults
// otherwise (it re-meshes first at the automatic length, unlike the core's Params).
QM::Params PluginDefaults()
{
    QM::Params p;
    p.remeshFirst = true;
    return p;
}
QM::Params gQMorphParams = PluginDefaults();
double gRemeshFactor = 0;  // > 0: Q-Morph re-meshes to this times the mean edge length of its input
double gRemeshDiagPercent = 0;  // > 0: Q-Morph re-meshes to this % of the bounding-box diagonal
int gVsaMaxRegions = -1;        // >= 0: VSA's Max regions on every mesh (-1: its default)
// Front curves after re-meshing: output front points within this fraction of the diagonal of the
// input front, chords within this fraction of the edge length (the collapse pass's tolerance).
constexpr double kFrontOnCurve = 1e-5, kFrontChord = 0.1 + 1e-6;

double MeanEdgeLength(const TMesh &m)
{
    double sum = 0;
    long n = 0;
    for (const auto &f : m.face)
        if (!f.IsD())
            for (int k = 0; k < 3; ++k, ++n) sum += vcg::Distance(f.cP(k), f.cP((k + 1) % 3));
    return n ? sum / n : 0;
}

// Progress callbacks of the scaling run: the longest time between two of them (MeshLab users see a
// frozen bar when it is long).
// Also the longest time the report (percent and message) stayed the same: the core's longest
// indivisible step, which its progress relay covers with repeated reports.
struct ProgressGaps {
    bool on = false;
    bool timeline = false;  // print each new report with its time since Start (--timeline)
    Clock::time_point start, last, lastNews;
    double longest = 0, longestSame = 0;
    int lastPercent = -1;
    std::string lastMessage = "start", where, whereSame;  // the callbacks around the longest gaps
    void Start()
    {
        on = true;
        start = last = lastNews = Clock::now();
        longest = longestSame = 0;
        lastPercent = -1;
        lastMessage = "start";
        where.clear();
        whereSame.clear();
    }
    void Tick(int percent, const char *message)
    {
        if (!on) return;
        const auto now = Clock::now();
        const double gap = std::chrono::duration<double>(now - last).count();
        if (gap > longest) { longest = gap; where = lastMessage + " -> " + message; }
        last = now;
        if (percent == lastPercent && message == lastMessage) return;
        const double same = std::chrono::duration<double>(now - lastNews).count();
        if (same > longestSame) { longestSame = same; whereSame = lastMessage + " -> " + message; }
        if (timeline) std::fprintf(stderr, "%9.3f s %3d%% %s\n", std::chrono::duration<double>(now - start).count(), percent, message);
        lastNews = now;
        lastPercent = percent;
        lastMessage = message;
    }
    // Around each core call: the time between the stages is the benchmark's own (copies, layers)
    // and MeshLab's between two filters, not a filter's.
    void Enter(const char *stage)
    {
        if (!on) return;
        last = lastNews = Clock::now();
        lastPercent = -1;
        lastMessage = std::string(stage) + " called";
        if (timeline) std::fprintf(stderr, "%9.3f s      %s\n", std::chrono::duration<double>(last - start).count(), lastMessage.c_str());
    }
    void Leave(const char *stage) { Tick(-1, (std::string(stage) + " returned").c_str()); }
    void Stop() { on = false; }
} g_gaps;
bool GapCallback(const int percent, const char *message) { g_gaps.Tick(percent, message ? message : ""); return true; }
vcg::CallBackPos *g_stageCallback = nullptr;  // passed to every stage (the scaling run sets it)

void RunPipeline(const TMesh &input, const VSA::Params &vp, PipelineRun &r, TMesh &work, TMesh *splitOut,
                 const std::string &label, bool verbose)
{
    work.Clear();
    vcg::tri::Append<TMesh, TMesh>::MeshCopy(work, const_cast<TMesh &>(input));  // MeshCopy only reads it
    vcg::tri::UpdateBounding<TMesh>::Box(work);

    auto begin = [&](int stage, const char *what) {
        if (verbose) Progress(label, what);
        malloc_trim(0);  // freed heap back to the system: RSS before the stage = what is live
        ResetPeak();
        r.rssBefore[stage] = RssMiB();
        return Clock::now();
    };
    auto end = [&](int stage) { r.peakAfter[stage] = PeakMiB(); };

    // 1. segmentation
    auto t0 = begin(0, "VSA");
    g_gaps.Enter("VSA");
    r.vsa = VSA::Segment(work, vp, g_stageCallback);
    g_gaps.Leave("VSA");
    r.tVsa = Since(t0);
    end(0);
    if (!r.vsa.error.empty()) { r.error = r.vsa.error; r.failedStage = "VSA"; return; }

    // 2. boundary smoothing -> the front layer (an edge mesh, float coordinates like the plugin's)
    TMesh poly;
    {
        t0 = begin(1, "boundary smoothing");
        g_gaps.Enter("smoothing");
        Smoothing::Result s = Smoothing::Smooth(work, r.vsa.faceRegion, Smoothing::Params(), g_stageCallback);
        g_gaps.Leave("smoothing");
        if (s.error.empty()) {
            Smoothing::Polylines lines = Smoothing::ToPolylines(s.topology, s.curves);
            Smoothing::BuildEdgeMesh(lines, poly);
        }
        r.tSmooth = Since(t0);
        end(1);
        if (!s.error.empty()) { r.error = s.error; r.failedStage = "smoothing"; return; }
        r.curves = int(s.curves.size());
        r.corners = int(s.corners.size());
        r.loops = s.closedLoops;
        r.pointsBefore = s.pointsBefore;
        r.pointsAfter = s.pointsAfter;
        r.lengthBefore = s.lengthBefore;
        r.lengthAfter = s.lengthAfter;
        r.jagBefore = s.jaggednessBefore;
        r.jagAfter = s.jaggednessAfter;
        r.tStraighten = s.straightenSeconds;
        r.unsnapped = s.unsnapped;
        r.polylinePoints = poly.vn;
    }

    // 3. split along the front
    t0 = begin(2, "split along the front");
    g_gaps.Enter("split");
    r.split = Embedding::Embed(work, poly, Embedding::Params(), g_stageCallback);
    g_gaps.Leave("split");
    r.tSplit = Since(t0);
    end(2);
    r.split.faceRegion.clear();
    r.split.faceRegion.shrink_to_fit();
    if (!r.split.error.empty()) { r.error = r.split.error; r.failedStage = "split"; return; }
    poly.Clear();
    r.splitFaces = work.fn;
    if (splitOut) {
        splitOut->Clear();
        vcg::tri::Append<TMesh, TMesh>::MeshCopy(*splitOut, work);
        vcg::tri::UpdateTopology<TMesh>::FaceFace(*splitOut);
    }

    // 4. Q-Morph
    t0 = begin(3, "Q-Morph");
    QM::Params qp = gQMorphParams;
    if (gRemeshFactor > 0) qp.targetEdgeLength = gRemeshFactor * MeanEdgeLength(work);
    if (gRemeshDiagPercent > 0) {
        vcg::tri::UpdateBounding<TMesh>::Box(work);
        qp.targetEdgeLength = gRemeshDiagPercent / 100 * work.bbox.Diag();
    }
    g_gaps.Enter("Q-Morph");
    r.qm = QM::Apply(work, qp, g_stageCallback);
    g_gaps.Leave("Q-Morph");
    r.tQm = Since(t0);
    end(3);
    if (!r.qm.error.empty()) { r.error = r.qm.error; r.failedStage = "Q-Morph"; return; }
}

struct QuadMeasure {
    vcg_ext::QuadQualityReport q;
    long euler = 0;
};

QuadMeasure MeasureQuads(TMesh &m)
{
    vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
    vcg_ext::PolygonMesh pm = vcg_ext::QuadQuality::FromFauxMesh(m);
    QuadMeasure r;
    r.q = vcg_ext::QuadQuality::Measure(pm);
    r.euler = EulerCharacteristic(pm);
    return r;
}

std::vector<std::string> QuadCells(const vcg_ext::QuadQualityReport &q)
{
    return {Count(q.quads), Count(q.triangles + q.others), Pct(q.quadAreaFraction), Pct(q.quadCountFraction),
            Fmt("%.3f", q.meanJacobian), Fmt("%.3f", q.minJacobian),
            Fmt("%.2f", q.quads ? 100.0 * q.quadsBelow03 / q.quads : 0.0), Count(q.invertedQuads),
            Fmt("%.1f (%d/%d)", 100 * q.IrregularFraction(), q.irregularVertices, q.interiorAllQuadVertices)};
}

// ------------------------------------------------------------------ VSA vs CGAL
void TriangleArrays(const TMesh &m, std::vector<std::array<double, 3>> &pts, std::vector<std::array<int, 3>> &tris)
{
    pts.clear();
    tris.clear();
    for (const auto &v : m.vert) pts.push_back({double(v.cP()[0]), double(v.cP()[1]), double(v.cP()[2])});
    for (const auto &f : m.face)
        tris.push_back({int(vcg::tri::Index(m, f.cV(0))), int(vcg::tri::Index(m, f.cV(1))), int(vcg::tri::Index(m, f.cV(2)))});
}

double L21Of(TMesh &m, const std::vector<int> &label, const std::vector<std::array<double, 3>> &normals)
{
    std::vector<VSA::Vec> px;
    for (const auto &n : normals) px.push_back(VSA::Vec(n[0], n[1], n[2]));
    return VSA::L21Error(m, label, px);
}

void CompareWithCgal(TMesh &input, const std::string &label, const PipelineRun &pipeline, const Options &o, int repeats,
                     bool fixedK)
{
    const int K = pipeline.vsa.regions, pipelineK = pipeline.vsa.regions, pipelineIterations = pipeline.vsa.lloydIterations;
    const double pipelineL21 = pipeline.vsa.l21Error, pipelineSeconds = pipeline.tVsa;
    if (!CgalAvailable()) return;
    const int N = o.cgalIterations;
    std::vector<std::array<double, 3>> pts;
    std::vector<std::array<int, 3>> tris;
    TriangleArrays(input, pts, tris);
    TMesh m;
    vcg::tri::Append<TMesh, TMesh>::MeshCopy(m, input);

    // Lloyd iteration speed, K random seeds.
    Progress(label, Fmt("VSA vs CGAL: iteration speed, K = %d, N = %d", K, N));
    VSA::Params p;
    p.mode = VSA::ThresholdSeeding;
    p.initialSeeds = K;
    p.maxRegions = K;
    p.relativeTolerance = 0;
    double t1 = 1e30, tN = 1e30;
    VSA::Result r1, rN;
    for (int rep = 0; rep < repeats; ++rep) {
        p.maxIterations = 1;
        auto t0 = Clock::now();
        r1 = VSA::Segment(m, p);
        t1 = std::min(t1, Since(t0));
        p.maxIterations = N;
        t0 = Clock::now();
        rN = VSA::Segment(m, p);
        tN = std::min(tN, Since(t0));
    }
    const int dIt = rN.lloydIterations - r1.lloydIterations;
    const double oursPerIt = dIt > 0 ? (tN - t1) / dIt : tN / std::max(1, rN.lloydIterations + 1);
    CgalVsaRun best;
    double cgalIt = 1e30;
    for (int rep = 0; rep < repeats; ++rep) {
        CgalVsaRun c = RunCgalVsa(pts, tris, K, CgalSeeding::Random, 0, N, 1);
        if (!c.error.empty()) { Note(label, "CGAL: " + c.error); return; }
        if (c.iterateSeconds < cgalIt) { cgalIt = c.iterateSeconds; best = std::move(c); }
    }
    const double cgalPerIt = cgalIt / N;
    const double cgalL21 = L21Of(m, best.faceProxy, best.proxyNormal);
    if (std::fabs(cgalL21 - best.cgalError) > 1e-6 * std::max(1.0, std::fabs(cgalL21)))
        Note(label, Fmt("CGAL's own total error %.9g differs from the L2,1 recomputed from its labels and proxies %.9g",
                        best.cgalError, cgalL21));
    Emit(T_CGAL_SPEED, {label, Count(input.fn), Fmt("%d / %d", rN.regions, best.proxies),
                        Fmt("%d", rN.lloydIterations) + (dIt > 0 ? "" : " (converged: t / (it+1))"),
                        Fmt("%.3f", 1000 * oursPerIt), Count(best.iterations), Fmt("%.3f", 1000 * cgalPerIt),
                        Fmt("%.2f", oursPerIt / cgalPerIt), Fmt("%.5g", rN.l21Error), Fmt("%.5g", cgalL21)});

    // Quality at equal K: the pipeline's threshold-mode result against CGAL's default (hierarchical)
    // seeding; optionally our fixed-K mode against CGAL's incremental seeding (slow on big meshes).
    auto emitPair = [&](const std::string &oursName, int oursK, double tOurs, int oursIt, double oursL21,
                        CgalSeeding seeding, const char *cgalName) {
        Progress(label, Fmt("VSA vs CGAL: %s, K = %d", cgalName, K));
        CgalVsaRun c = RunCgalVsa(pts, tris, K, seeding, 5, N, 1);
        if (!c.error.empty()) { Note(label, std::string("CGAL: ") + c.error); return; }
        const double cl21 = L21Of(m, c.faceProxy, c.proxyNormal);
        const double ratio = cl21 > 0 ? oursL21 / cl21 : (oursL21 > 0 ? 1e9 : 1.0);
        Emit(T_CGAL_QUALITY, {label, Fmt("%d / %d", oursK, c.proxies), oursName, Sec(tOurs), Count(oursIt),
                              Fmt("%.5g", oursL21), std::string(cgalName) + Fmt(" + run(%d)", N),
                              Sec(c.seedSeconds + c.iterateSeconds), Fmt("%.5g", cl21), Fmt("%.3f", ratio),
                              ratio <= 1.05 ? "yes" : "NO"});
    };
    emitPair("threshold (pipeline)", pipelineK, pipelineSeconds, pipelineIterations, pipelineL21, CgalSeeding::Hierarchical,
             "HIERARCHICAL");
    if (!fixedK) return;
    Progress(label, Fmt("VSA fixed K = %d", K));
    VSA::Params q;
    q.mode = VSA::FixedRegionCount;
    q.maxRegions = K;
    q.maxIterations = N;
    auto t0 = Clock::now();
    VSA::Result ours = VSA::Segment(m, q);
    const double tOurs = Since(t0);
    emitPair("fixed K", ours.regions, tOurs, ours.lloydIterations, ours.l21Error, CgalSeeding::Incremental, "INCREMENTAL");
}

// ------------------------------------------------------------------ MeshLab's conversions
void CompareWithBitQuad(const TMesh &split, const std::string &label, bool pureByFlip)
{
    struct Method {
        std::string name;
        std::function<void(TMesh &)> run;
    };
    std::vector<Method> methods = {
        {"MeshLab Turn into Quad-Dominant, level 0 (default)", [](TMesh &m) { BitQuad::MakeDominant(m, 0); }},
        {"MeshLab Turn into Quad-Dominant, level 2 (better quad shape)", [](TMesh &m) { BitQuad::MakeDominant(m, 2); }},
    };
    if (pureByFlip)
        methods.push_back({"MeshLab Tri to Quad by smart triangle pairing", [label](TMesh &m) {
                               BitQuad::MakeTriEvenBySplit(m);
                               if (!BitQuad::MakePureByFlip(m, 100)) Note(label, "BitQuad MakePureByFlip(m, 100) returned false (not all paired)");
                           }});
    for (const Method &meth : methods) {
        Progress(label, meth.name);
        TMesh m;
        vcg::tri::Append<TMesh, TMesh>::MeshCopy(m, const_cast<TMesh &>(split));
        vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
        auto t0 = Clock::now();
        meth.run(m);
        const double t = Since(t0);
        QuadMeasure qm = MeasureQuads(m);
        const auto &q = qm.q;
        Emit(T_BITQUAD, {label, meth.name, Ms(t), Count(q.quads), Count(q.triangles + q.others), Pct(q.quadAreaFraction),
                         Pct(q.quadCountFraction), Fmt("%.3f", q.meanJacobian),
                         Fmt("%.2f", q.quads ? 100.0 * q.quadsBelow03 / q.quads : 0.0), Count(q.invertedQuads),
                         Fmt("%.1f", 100 * q.IrregularFraction())});
    }
}

// ------------------------------------------------------------------ one mesh
struct Job {
    std::string label, path;
    int refineSteps = 0;   // big case: midpoint subdivision steps applied to the loaded mesh
    bool big = false;
    bool scaling = false;  // scaling run: the pipeline, per-stage times, memory, progress gaps
    int threads = 0;       // scaling run: Q-Morph's threads
    enum Damage { Intact, Needles, ZeroArea } damage = Intact;  // big case: --big-degenerate
    int damaged = 0;                                            // how many faces to damage
};

void RunScaling(const Job &job)
{
    TMesh input;
    std::string err = LoadMesh(input, job.path);
    if (!err.empty()) { Note(job.label, err); return; }
    MidpointRefine(input, job.refineSteps);
    const std::string label = Fmt("%s x%d", job.label.c_str(), 1 << (2 * job.refineSteps));
    for (auto &f : input.face) f.Q() = 0;
    const long eulerIn = EulerCharacteristic(input);
    const int faces = input.fn;
    gQMorphParams.threads = job.threads;
    g_stageCallback = GapCallback;
    PipelineRun r;
    TMesh work;
    Progress(label, Fmt("%d faces, %d Q-Morph threads", faces, job.threads));
    g_gaps.Start();
    VSA::Params vp;
    if (gVsaMaxRegions >= 0) vp.maxRegions = gVsaMaxRegions;
    RunPipeline(input, vp, r, work, nullptr, label, true);
    g_gaps.Stop();
    g_stageCallback = nullptr;
    if (!r.error.empty()) { Note(label, r.failedStage + ": " + r.error); return; }
    double peak = 0;
    for (double p : r.peakAfter) peak = std::max(peak, p);
    input.Clear();
    const QuadMeasure qm = MeasureQuads(work);
    const auto out = vcg_ext::MeshChecks<TMesh>::Inspect(work);
    const bool closed = out.IsClosed() && out.IsTwoManifold() && out.IsOriented();
    Emit(T_SCALING, {label, Count(faces), Count(job.threads), Count(r.vsa.regions), Fmt("%.1f", r.vsa.maxDeviationDeg),
                     Sec(r.tVsa), Sec(r.tSmooth), Sec(r.tSplit), Sec(r.tQm), Sec(r.qm.remeshSeconds), Sec(r.Total()),
                     Fmt("%.2f", 1e6 * r.Total() / faces), Fmt("%.0f", peak * 1048576.0 / faces),
                     Pct(qm.q.quadAreaFraction), YesNo(closed) + ", " + YesNo(qm.euler == eulerIn),
                     Count(r.qm.quality.flippedFaces), Fmt("%.2f (%s)", g_gaps.longest, g_gaps.where.c_str()),
                     Fmt("%.2f (%s)", g_gaps.longestSame, g_gaps.whereSame.c_str())});
}

// --save-dir: the run's input and output as binary PLY, named after the label's first word
// (evalquad DIR/NAME.input.ply DIR/NAME.ply judges them).
void SaveRun(const std::string &dir, const std::string &label, TMesh &input, TMesh &output)
{
    std::string name = label.substr(0, label.find(' '));
    if (label.find("(") != std::string::npos)  // the big case: "armadillo_52k x16 (832k)"
        name += "_" + label.substr(label.find('(') + 1, label.find(')') - label.find('(') - 1);
    const int mask = vcg::tri::io::Mask::IOM_FACEFLAGS | vcg::tri::io::Mask::IOM_FACEQUALITY;
    const std::string in = dir + "/" + name + ".input.ply", out = dir + "/" + name + ".ply";
    if (vcg::tri::io::ExporterPLY<TMesh>::Save(input, in.c_str(), 0, true) != 0 ||
        vcg::tri::io::ExporterPLY<TMesh>::Save(output, out.c_str(), mask, true) != 0)
        Note(label, "--save-dir: cannot write " + in + " or " + out);
    else
        Progress(label, "saved " + in + " and " + out);
}

void RunJob(const Job &job, const Options &o)
{
    if (job.scaling) { RunScaling(job); return; }
    TMesh input;
    std::string err = LoadMesh(input, job.path);
    if (!err.empty()) { Note(job.label, err); return; }
    std::string label = job.label;
    if (job.big) {
        const int before = input.fn;
        auto t0 = Clock::now();
        const int steps = job.refineSteps;
        MidpointRefine(input, steps);
        label = Fmt("%s x%d (%dk)", job.label.c_str(), 1 << (2 * steps), int(std::lround(input.fn / 1000.0)));
        Progress(label, Fmt("%d -> %d faces by %d midpoint steps in %.1f s", before, input.fn, steps, Since(t0)));
    }
    Injected injected;
    if (job.damage != Job::Intact) {
        injected = InjectDegenerateFaces(input, job.damaged, job.damage == Job::ZeroArea);
        label += Fmt(" + %d %s", injected.made, job.damage == Job::Needles ? "needles" : "zero-area");
        Progress(label, Fmt("%d of %d faces made %s (%d candidates skipped)", injected.made, job.damaged,
                            job.damage == Job::Needles ? "needles" : "exactly degenerate", injected.rejected));
    }
    for (auto &f : input.face) f.Q() = 0;
    const auto inCheck = vcg_ext::MeshChecks<TMesh>::Inspect(input);
    const long eulerIn = EulerCharacteristic(input);
    const double diag = input.bbox.Diag();
    const double volumeIn = Volume(input);
    if (!inCheck.IsClosed() || !inCheck.IsTwoManifold())
        Note(label, Fmt("input: %d boundary edges, %d non-manifold edges, %d non-manifold vertices", inCheck.boundaryEdges,
                        inCheck.nonManifoldEdges, inCheck.nonManifoldVertices));
    if (inCheck.degenerateFaces) Note(label, Fmt("input: %d degenerate faces", inCheck.degenerateFaces));

    VSA::Params vp;
    std::string vsaMode = "threshold (defaults)";
    if (gVsaMaxRegions >= 0) {
        vp.maxRegions = gVsaMaxRegions;
        vsaMode = Fmt("threshold, Max regions %d", vp.maxRegions);
    }
    if (job.big && o.bigVsa == "fixed") {
        vp.mode = VSA::FixedRegionCount;
        vp.maxRegions = o.bigRegions > 0 ? o.bigRegions : 200;
        vsaMode = Fmt("fixed K = %d", vp.maxRegions);
    } else if (job.big && o.bigRegions > 0) {
        vp.maxRegions = o.bigRegions;
        vsaMode = Fmt("threshold, <= %d regions", vp.maxRegions);
    }

    // The pipeline, best time of the repeats (the results are deterministic: checked).
    const int repeats = job.big ? 1 : std::max(1, o.repeats);
    PipelineRun best;
    TMesh work, split;
    double peakAll = 0;
    // --big-degenerate: what happened, stage by stage ("-": not reached)
    auto emitDamaged = [&](const PipelineRun &r, const std::string &outcome) {
        if (job.damage == Job::Intact) return;
        const int reached = r.failedStage == "VSA" ? 1 : r.failedStage == "smoothing" ? 2 : r.failedStage == "split" ? 3 : 4;
        auto stage = [&](int s, double t) { return s < reached ? Sec(t) : std::string("-"); };
        Emit(T_DEGENERATE, {label, Count(input.fn), Fmt("%d (%d skipped)", injected.made, injected.rejected),
                            Count(inCheck.degenerateFaces),
                            job.damage == Job::Needles ? Fmt("%.1e - %.1e", injected.minAreaRatio, injected.maxAreaRatio) : "0",
                            outcome, stage(0, r.tVsa), stage(1, r.tSmooth), stage(2, r.tSplit), stage(3, r.tQm), Sec(r.Total()),
                            Fmt("%.0f", peakAll), Fmt("%.0f", peakAll * 1048576.0 / input.fn)});
    };
    for (int rep = 0; rep < repeats; ++rep) {
        PipelineRun r;
        RunPipeline(input, vp, r, work, rep + 1 == repeats ? &split : nullptr, label, rep == 0 || job.big);
        if (!r.error.empty()) {
            Note(label, "pipeline failed at " + r.failedStage + ": " + r.error);
            Emit(T_CHECKS, {label, "failed at " + r.failedStage, "", "", "", "", "", ""});
            for (int s = 0; s < 4; ++s) peakAll = std::max(peakAll, r.peakAfter[s]);
            emitDamaged(r, "refused at " + r.failedStage + ": \"" + r.error + "\"");
            return;
        }
        for (int s = 0; s < 4; ++s) peakAll = std::max(peakAll, r.peakAfter[s]);
        if (rep == 0) best = r;
        else {
            if (r.qm.quads != best.qm.quads || r.qm.triangles != best.qm.triangles || r.vsa.regions != best.vsa.regions)
                Note(label, "results differ between repeats (non-deterministic)");
            best.tVsa = std::min(best.tVsa, r.tVsa);
            best.tSmooth = std::min(best.tSmooth, r.tSmooth);
            best.tStraighten = std::min(best.tStraighten, r.tStraighten);
            if (r.tSplit < best.tSplit) { best.tSplit = r.tSplit; best.split = r.split; }
            best.tQm = std::min(best.tQm, r.tQm);
        }
    }
    const PipelineRun &r = best;

    Emit(T_VSA, {label, Count(input.fn), Count(r.vsa.regions), Fmt("%d (%d)", r.vsa.lloydIterations, r.vsa.seedingRounds),
                 Fmt("%.5g", r.vsa.l21Error), Fmt("%.1f", r.vsa.maxDeviationDeg), Ms(r.tVsa),
                 Fmt("%.3f", 1000 * r.tVsa / std::max(1, r.vsa.lloydIterations))});
    Emit(T_SMOOTH, {label, Count(r.curves), Count(r.corners), Fmt("%d -> %d", r.pointsBefore, r.pointsAfter),
                    Fmt("%.1f", double(r.pointsAfter) / std::max(1, r.curves)),
                    Pct(r.lengthBefore > 0 ? 1 - r.lengthAfter / r.lengthBefore : 0),
                    Fmt("%.3g -> %.3g", r.jagBefore, r.jagAfter), Ms(r.tSmooth), Ms(r.tStraighten)});
    if (r.unsnapped) Note(label, Fmt("smoothing: %d points left unsnapped", r.unsnapped));
    const auto &e = r.split;
    Emit(T_SPLIT, {label, Count(e.polylinePoints), Count(e.facesCrossed), Count(e.facesSplit), Count(e.verticesAdded),
                   Count(e.facesAdded), Count(e.frontEdges), Count(e.patches), Fmt("%.2f", e.minAngleDeg), Ms(r.tSplit),
                   Ms(e.secondsPrepare) + " / " + Ms(e.secondsApply)});
    if (e.tracedSegments) Note(label, Fmt("split: %d segments needed tracing", e.tracedSegments));
    if (e.missingFrontEdges || e.danglingFrontEdges)
        Note(label, Fmt("split: %d missing, %d dangling front edges", e.missingFrontEdges, e.danglingFrontEdges));

    // Independent measurements of the Q-Morph output.
    Progress(label, "measuring the output");
    QuadMeasure qm = MeasureQuads(work);
    const auto &q = qm.q;
    if (q.quads != r.qm.quality.quads || q.triangles != r.qm.quality.triangles)
        Note(label, Fmt("Q-Morph's own report (%d quads, %d triangles) differs from the mesh read back (%d, %d)",
                        r.qm.quality.quads, r.qm.quality.triangles, q.quads, q.triangles));
    std::vector<std::string> row = {label, Count(r.splitFaces), Ms(r.tQm), Count(r.qm.patches)};
    FlipCount flipsIndependent;
    for (auto &c : QuadCells(q)) row.push_back(c);
    row.push_back(Count(r.qm.ops.failures));
    {
        vcg::tri::UpdateTopology<TMesh>::FaceFace(work);
        flipsIndependent = FlippedFaces(vcg_ext::QuadQuality::FromFauxMesh(work), input);
        const FlipCount &flips = flipsIndependent;
        row.push_back(Fmt("%d / %d (+%d)", r.qm.quality.flippedFaces, flips.flipped, flips.ambiguous));
        row.push_back(Count(flips.folded));
    }
    Emit(T_QMORPH, row);

    const auto outCheck = vcg_ext::MeshChecks<TMesh>::Inspect(work);
    const bool closedManifold = outCheck.IsClosed() && outCheck.IsTwoManifold() && outCheck.IsOriented();
    const bool genusKept = qm.euler == eulerIn && outCheck.components == inCheck.components;
    const std::vector<PosEdge> frontBefore = EdgesByPosition(split, true);
    const std::vector<PosEdge> edgesAfter = EdgesByPosition(work, false), selAfter = EdgesByPosition(work, true);
    long lost = 0;
    for (const PosEdge &x : frontBefore) lost += !std::binary_search(edgesAfter.begin(), edgesAfter.end(), x);
    // re-meshing cuts front edges into pieces, and may coarsen a front over smooth surface into
    // chords within a tenth of its length (ShortEdgeCollapse): the fronts are compared as curves
    const double L = r.qm.targetEdgeLength;
    const long mismatches = L > 0 ? FrontCurveMismatches(frontBefore, selAfter, kFrontOnCurve * diag, kFrontChord * L) : 0;
    if (L > 0) lost = mismatches;
    const bool frontKept = L > 0 ? mismatches == 0 : lost == 0 && selAfter == frontBefore;
    Progress(label, "Hausdorff distance");
    auto th = Clock::now();
    const double hd = Hausdorff(work, input) / diag;
    if (job.big) Progress(label, Fmt("Hausdorff in %.1f s", Since(th)));
    const double volumeOut = Volume(work);
    std::string closedText = YesNo(closedManifold);
    if (!closedManifold)
        closedText += Fmt(" (%d boundary, %d non-manifold edges, %d non-manifold vertices, %d inconsistent)",
                          outCheck.boundaryEdges, outCheck.nonManifoldEdges, outCheck.nonManifoldVertices,
                          outCheck.inconsistentEdges);
    if (outCheck.degenerateFaces) Note(label, Fmt("output: %d degenerate triangles", outCheck.degenerateFaces));
    if (outCheck.nonManifoldEdges) {
        std::string where;
        for (const std::string &w : NonManifoldEdges(work, 3)) where += (where.empty() ? "" : "; ") + w;
        Note(label, "output non-manifold edges at " + where);
    }
    Emit(T_CHECKS, {label, Ms(r.Total()), Fmt("%.3f", 100 * hd),
                    Fmt("%+.3f", volumeIn != 0 ? 100 * (volumeOut - volumeIn) / std::fabs(volumeIn) : 0.0), closedText,
                    YesNo(genusKept) + Fmt(" (%ld -> %ld)", eulerIn, qm.euler),
                    frontKept ? (L > 0 ? "yes (as curves)" : "yes")
                              : L > 0 ? Fmt("NO (%ld front edges off the curves)", lost)
                                                  : Fmt("NO (%ld lost, selection %s)", lost, selAfter == frontBefore ? "same" : "changed"),
                    Fmt("%.0f", peakAll)});
    const double below = q.quads ? double(q.quadsBelow03) / q.quads : 0;
    emitDamaged(r, Fmt("ran: %d quads, %d triangles; closed 2-manifold %s, genus kept %s, front kept %s; flipped %d / %d (+%d)",
                       q.quads, q.triangles + q.others, YesNo(closedManifold).c_str(), YesNo(genusKept).c_str(),
                       YesNo(frontKept).c_str(), r.qm.quality.flippedFaces, flipsIndependent.flipped, flipsIndependent.ambiguous));
    const bool bars[] = {q.quadAreaFraction >= 0.95, q.quadCountFraction >= 0.90, q.invertedQuads == 0 && q.minJacobian > 0,
                         q.meanJacobian >= 0.75, below < 0.02, q.IrregularFraction() <= 0.20, hd <= 0.005,
                         closedManifold, genusKept, frontKept};
    std::vector<std::string> barRow = {label};
    bool all = true;
    for (bool b : bars) { barRow.push_back(b ? "pass" : "FAIL"); all = all && b; }
    barRow.push_back(all ? "pass" : "FAIL");
    Emit(T_BARS, barRow);

    if (!o.saveDir.empty()) SaveRun(o.saveDir, label, input, work);
    if (o.bitquad) CompareWithBitQuad(split, label, !job.big);
    split.Clear();
    work.Clear();

    if (job.big) {
        auto stagePeak = [&](int s) { return Fmt("%.0f", std::max(0.0, r.peakAfter[s] - r.rssBefore[s])); };
        Emit(T_BIG, {label, Count(input.fn), vsaMode, Count(r.vsa.regions), Sec(r.tVsa),
                     Fmt("%.1f", 1000 * r.tVsa / std::max(1, r.vsa.lloydIterations)), Sec(r.tSmooth), Sec(r.tSplit),
                     Sec(r.tQm), stagePeak(0) + " / " + stagePeak(1) + " / " + stagePeak(2) + " / " + stagePeak(3),
                     Fmt("%.0f", peakAll * 1048576.0 / input.fn)});
    }
    if (o.cgal) CompareWithCgal(input, label, r, o, job.big ? 1 : repeats, !job.big || o.cgalBigQuality);
}

// ------------------------------------------------------------------ parent: jobs in children, tables
struct Report {
    std::vector<std::vector<std::vector<std::string>>> rows = std::vector<std::vector<std::vector<std::string>>>(T_COUNT);
    void Add(const std::string &line)
    {
        std::vector<std::string> cells;
        std::stringstream ss(line);
        std::string c;
        while (std::getline(ss, c, '\t')) cells.push_back(c);
        if (cells.size() < 2) return;
        int t = std::atoi(cells[0].c_str());
        if (t < 0 || t >= T_COUNT) return;
        cells.erase(cells.begin());
        rows[t].push_back(cells);
    }
};

void RunJobInChild(const Job &job, const Options &o, Report &report)
{
    if (!o.fork) {
        char *buf = nullptr;
        size_t len = 0;
        FILE *mem = open_memstream(&buf, &len);
        g_rowOut = mem;
        RunJob(job, o);
        std::fclose(mem);
        std::stringstream ss(std::string(buf, len));
        std::free(buf);
        std::string line;
        while (std::getline(ss, line)) report.Add(line);
        return;
    }
    int fd[2];
    if (pipe(fd) != 0) { std::perror("pipe"); std::exit(1); }
    std::fflush(stdout);
    std::fflush(stderr);
    pid_t pid = fork();
    if (pid < 0) { std::perror("fork"); std::exit(1); }
    if (pid == 0) {
        close(fd[0]);
        g_rowOut = fdopen(fd[1], "w");
        RunJob(job, o);
        std::fflush(g_rowOut);
        std::_Exit(0);
    }
    close(fd[1]);
    FILE *in = fdopen(fd[0], "r");
    char *line = nullptr;
    size_t cap = 0;
    ssize_t n;
    while ((n = getline(&line, &cap, in)) > 0) {
        std::string s(line, size_t(n));
        while (!s.empty() && (s.back() == '\n' || s.back() == '\r')) s.pop_back();
        report.Add(s);
    }
    std::free(line);
    std::fclose(in);
    int status = 0;
    waitpid(pid, &status, 0);
    if (WIFSIGNALED(status)) {
        const int sig = WTERMSIG(status);
        std::string what = Fmt("CRASHED (signal %d, %s)", sig, strsignal(sig));
        Progress(job.label, what);
        report.rows[T_NOTES].push_back({job.label, what + "; rows above for this mesh are the stages it finished"});
    } else if (WIFEXITED(status) && WEXITSTATUS(status) != 0) {
        report.rows[T_NOTES].push_back({job.label, Fmt("exited with status %d", WEXITSTATUS(status))});
    }
}

std::string Markdown(const Report &rep, const std::string &preamble)
{
    std::ostringstream out;
    out << preamble;
    for (int t = 0; t < T_COUNT; ++t) {
        const auto &rows = rep.rows[t];
        if (rows.empty()) continue;
        const TableDef &d = Def(t);
        out << "\n### " << d.title << "\n\n";
        std::vector<size_t> w(d.header.size(), 3);
        for (size_t i = 0; i < d.header.size(); ++i) w[i] = std::max(w[i], d.header[i].size());
        for (const auto &r : rows)
            for (size_t i = 0; i < r.size() && i < w.size(); ++i) w[i] = std::max(w[i], r[i].size());
        auto line = [&](const std::vector<std::string> &cells) {
            out << "|";
            for (size_t i = 0; i < w.size(); ++i) {
                std::string c = i < cells.size() ? cells[i] : "";
                out << " " << c << std::string(w[i] - std::min(w[i], c.size()), ' ') << " |";
            }
            out << "\n";
        };
        line(d.header);
        out << "|";
        for (size_t i = 0; i < w.size(); ++i) {  // figures right-aligned, text left-aligned
            bool numeric = true;
            for (const auto &r : rows)
                if (i < r.size() && !r[i].empty() && !(std::isdigit((unsigned char)r[i][0]) || r[i][0] == '+' || r[i][0] == '-'))
                    numeric = false;
            out << (numeric ? std::string(w[i] + 1, '-') + ":" : ":" + std::string(w[i] + 1, '-')) << "|";
        }
        out << "\n";
        for (const auto &r : rows) line(r);
        if (d.note && *d.note) out << "\n" << d.note << "\n";
    }
    return out.str();
}

// Time per face against faces, per stage and thread count (gnuplot, log-x): writes FILE.dat and
// FILE; returns a line for the report.
std::string PlotScaling(const Report &rep, const std::string &png)
{
    const std::string dat = png + ".dat";
    std::ofstream d(dat);
    d << "# faces threads vsa_us smoothing_us split_us qmorph_us total_us (per input face)\n";
    std::map<int, std::vector<std::vector<std::string>>> byThreads;
    for (const auto &row : rep.rows[T_SCALING]) byThreads[std::atoi(row[2].c_str())].push_back(row);
    int block = 0;
    std::string plots;
    for (const auto &bt : byThreads) {
        for (const auto &row : bt.second) {
            const double f = std::atof(row[1].c_str());
            d << row[1] << " " << row[2];
            for (int c : {5, 6, 7, 8, 10}) d << " " << 1e6 * std::atof(row[c].c_str()) / f;  // 9: the re-meshing, within 8
            d << "\n";
        }
        d << "\n\n";
        const std::string t = Fmt("%d thread%s", bt.first, bt.first == 1 ? "" : "s");
        plots += Fmt("%s'%s' index %d using 1:7 with linespoints lw 2 title 'whole pipeline, %s', "
                     "'%s' index %d using 1:6 with linespoints title 'Q-Morph, %s', "
                     "'%s' index %d using 1:3 with linespoints dt 2 title 'VSA, %s'",
                     plots.empty() ? "" : ", ", dat.c_str(), block, t.c_str(), dat.c_str(), block, t.c_str(), dat.c_str(),
                     block, t.c_str());
        ++block;
    }
    d.close();
    const std::string script = png + ".gp";
    std::ofstream g(script);
    g << "set terminal pngcairo size 900,560\nset output '" << png << "'\nset logscale x\nset grid\n"
      << "set xlabel 'input faces'\nset ylabel 'wall time per input face (microseconds)'\n"
      << "set key outside right\nset yrange [0:*]\nplot " << plots << "\n";
    g.close();
    const int rc = std::system(("gnuplot '" + script + "'").c_str());
    return rc == 0 ? "- scaling plot: `" + png + "` (data `" + dat + "`)\n" : "- scaling plot: gnuplot failed on `" + script + "`\n";
}

std::string Machine()
{
    std::string cpu = "unknown CPU";
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line))
        if (line.compare(0, 10, "model name") == 0) {
            cpu = line.substr(line.find(':') + 2);
            break;
        }
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
    return Fmt("%ld cores (nproc), %s, %.0f GiB RAM", n, cpu.c_str(), double(pages) * double(page) / (1 << 30));
}

}  // namespace

int main(int argc, char **argv)
{
    Options o;
    std::string command = "qmf_bench";
    for (int i = 1; i < argc; ++i) command += std::string(" ") + argv[i];
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        auto next = [&]() -> std::string {
            if (i + 1 >= argc) { std::fprintf(stderr, "%s needs a value\n", a.c_str()); std::exit(2); }
            return argv[++i];
        };
        if (a == "-h" || a == "--help") { Usage(); return 0; }
        else if (a == "--meshes") o.meshDir = next();
        else if (a == "--all") o.all = true;
        else if (a == "--big") o.big = next();
        else if (a == "--big-faces") o.bigFaces = std::atol(next().c_str());
        else if (a == "--no-ladder") o.ladder = false;
        else if (a == "--big-vsa") o.bigVsa = next();
        else if (a == "--big-regions") o.bigRegions = std::atoi(next().c_str());
        else if (a == "--big-only") o.onlyBig = true;
        else if (a == "--big-degenerate") o.bigDegenerate = std::max(0, std::atoi(next().c_str()));
        else if (a == "--no-cgal") o.cgal = false;
        else if (a == "--cgal-big-quality") o.cgalBigQuality = true;
        else if (a == "--no-bitquad") o.bitquad = false;
        else if (a == "--repeats") o.repeats = std::atoi(next().c_str());
        else if (a == "--cgal-iterations") o.cgalIterations = std::max(2, std::atoi(next().c_str()));
        else if (a == "--no-fork") o.fork = false;
        else if (a == "--out") o.out = next();
        else if (a == "--save-dir") o.saveDir = next();
        else if (a == "--remesh") gRemeshFactor = std::atof(next().c_str());
        else if (a == "--remesh-diag") gRemeshDiagPercent = std::atof(next().c_str());
        else if (a == "--vsa-max-regions") gVsaMaxRegions = std::max(0, std::atoi(next().c_str()));
        else if (a == "--no-preserve") gQMorphParams.preserveInitialFront = false;
        else if (a == "--no-remesh") gQMorphParams.remeshFirst = false;
        else if (a == "--no-cleanup") gQMorphParams.cleanup = false;
        else if (a == "--no-smoothing") gQMorphParams.smoothing = false;
        else if (a == "--scaling") o.scaling = next();
        else if (a == "--scaling-steps") o.scalingSteps = IntList(next());
        else if (a == "--scaling-threads") o.scalingThreads = IntList(next());
        else if (a == "--plot") o.plot = next();
        else if (a == "--timeline") g_gaps.timeline = true;
        else if (!a.empty() && a[0] == '-') { std::fprintf(stderr, "unknown option %s\n", a.c_str()); Usage(); return 2; }
        else o.names.push_back(a);
    }
    if (o.bigVsa != "threshold" && o.bigVsa != "fixed") { std::fprintf(stderr, "--big-vsa: threshold or fixed\n"); return 2; }
    if (o.meshDir.empty()) {
        const std::string root = QMF_SOURCE_DIR;
        o.meshDir = DirExists(root + "/../shared/meshes") ? root + "/../shared/meshes" : root + "/.deps/meshes";
    }
    if (!DirExists(o.meshDir)) { std::fprintf(stderr, "no mesh folder %s\n", o.meshDir.c_str()); return 2; }

    Report report;
    std::vector<Job> jobs;
    if (o.all) {
        std::vector<std::string> found;
        FILE *ls = popen(("ls -1 '" + o.meshDir + "'").c_str(), "r");
        char buf[4096];
        while (ls && std::fgets(buf, sizeof buf, ls)) {
            std::string f = buf;
            while (!f.empty() && (f.back() == '\n')) f.pop_back();
            if (EndsWith(Lower(f), ".ply") || EndsWith(Lower(f), ".off")) found.push_back(BaseName(f));
        }
        if (ls) pclose(ls);
        std::sort(found.begin(), found.end());
        found.erase(std::unique(found.begin(), found.end()), found.end());
        o.names.insert(o.names.end(), found.begin(), found.end());
    }
    const bool defaults = o.names.empty();
    if (defaults) o.names = {"fandisk", "rocker_arm_3356", "rocker_arm_20k", "bunny_3k", "elephant", "casting"};
    if (!o.scaling.empty()) {  // the scaling run alone
        const std::string path = ResolveMesh(o, o.scaling);
        if (path.empty()) { std::fprintf(stderr, "--scaling: %s not found\n", o.scaling.c_str()); return 2; }
        for (int steps : o.scalingSteps)
            for (int threads : o.scalingThreads) {
                Job j{BaseName(path), path, steps, false};
                j.scaling = true;
                j.threads = threads;
                jobs.push_back(j);
            }
        o.onlyBig = true;
        o.big = "none";
    }
    if (!o.onlyBig)
        for (const std::string &n : o.names) {
            std::string path = ResolveMesh(o, n);
            if (path.empty()) {
                if (!defaults) report.rows[T_NOTES].push_back({n, "not found (as " + o.meshDir + "/" + n + ".ply/.off or a path)"});
                else report.rows[T_NOTES].push_back({n, "not in " + o.meshDir + ": skipped"});
                continue;
            }
            jobs.push_back({BaseName(n), path, 0, false});
        }
    if (o.big != "none") {
        // "auto": armadillo (armadillo_52k or armadillo, organic, a few hundred regions) and fandisk (CAD),
        // those found; else a comma-separated list. The ~1/4-size ladder run only for the first.
        std::vector<std::string> bases;
        if (o.big == "auto") {
            for (const char *c : {"armadillo_52k", "armadillo"})
                if (bases.empty() && !ResolveMesh(o, c).empty()) bases.push_back(c);
            if (!ResolveMesh(o, "fandisk").empty()) bases.push_back("fandisk");
            if (bases.empty()) report.rows[T_NOTES].push_back({"big case", "no armadillo or fandisk in " + o.meshDir});
        } else {
            std::stringstream ss(o.big);
            std::string b;
            while (std::getline(ss, b, ','))
                if (!b.empty()) bases.push_back(b);
        }
        for (size_t i = 0; i < bases.size(); ++i) {
            const std::string path = ResolveMesh(o, bases[i]);
            if (path.empty()) { report.rows[T_NOTES].push_back({bases[i], "big case: base mesh not found"}); continue; }
            TMesh probe;
            std::string err = LoadMesh(probe, path);
            if (!err.empty()) { report.rows[T_NOTES].push_back({path, err}); continue; }
            int steps = 0;
            for (long f = probe.fn; f > 0 && f * 4 <= o.bigFaces + o.bigFaces / 4; f *= 4) ++steps;
            probe.Clear();
            if (i == 0 && o.ladder && steps >= 2) jobs.push_back({BaseName(path), path, steps - 1, true});
            jobs.push_back({BaseName(path), path, steps, true});
            for (Job::Damage d : {Job::Needles, Job::ZeroArea}) {
                if (o.bigDegenerate <= 0) break;
                Job j{BaseName(path), path, steps, true};
                j.damage = d;
                j.damaged = o.bigDegenerate;
                jobs.push_back(j);
            }
        }
    }

    std::string loadBefore = "?";
    {
        std::ifstream la("/proc/loadavg");
        std::string a, b, c;
        if (la >> a >> b >> c) loadBefore = a + " " + b + " " + c;
    }
    const auto started = Clock::now();
    for (const Job &j : jobs) RunJobInChild(j, o, report);
    const double total = Since(started);

    std::time_t now = std::time(nullptr);
    char date[64];
    std::strftime(date, sizeof date, "%Y-%m-%d %H:%M %Z", std::localtime(&now));
    std::string pre = "## qmf_bench report\n\n";
    pre += Fmt("- date: %s; machine: %s\n", date, Machine().c_str());
    pre += "- command: `" + command + "`; meshes from `" + o.meshDir + "`\n";
#ifdef NDEBUG
    pre += "- build: NDEBUG (Release)";
#else
    pre += "- build: asserts ON (not a Release build: timings are not representative)";
#endif
    pre += Fmt("; CGAL: %s; total benchmark time %.0f s\n", CgalAvailable() ? ("yes, " + CgalVersion()).c_str() : "absent", total);
    pre += Fmt("- timings: wall clock (steady_clock), best of %d runs on the small meshes, 1 run on the big ones; "
               "each mesh in its own process; load average at the start: %s\n", o.repeats, loadBefore.c_str());
    if (!o.plot.empty() && !report.rows[T_SCALING].empty()) pre += PlotScaling(report, o.plot);
    const std::string md = Markdown(report, pre);
    std::fputs(md.c_str(), stdout);
    if (!o.out.empty()) {
        std::ofstream f(o.out);
        f << md;
        if (!f) { std::fprintf(stderr, "cannot write %s\n", o.out.c_str()); return 1; }
    }
    return 0;
}
