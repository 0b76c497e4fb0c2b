// What splitting along polylines reports (EmbeddingResult) and what its planning hands to its
// writing (EmbeddingPlan), plus small shared helpers. Index based: no mesh pointers.
#ifndef VCG_EXT_EMBEDDING_RESULT_H
#define VCG_EXT_EMBEDDING_RESULT_H

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <vcg/complex/complex.h>

#include <vcg_ext/embedding/adjacency.h>
#include <vcg_ext/embedding/locate.h>
#include <vcg_ext/common/edge_key.h>

namespace vcg_ext {
namespace embedding {

struct EmbeddingResult {
    std::string error;           // empty on success
    bool inputProblem = false;   // the error is about the mesh or the parameters (else the polylines)
    double tolerance = 0;        // locate tolerance, absolute
    int polylinePoints = 0;      // polyline vertices used by its edges
    int polylineSegments = 0;    // polyline edges embedded (zero-length ones skipped)
    int pointsAtVertices = 0;    // distinct located polyline points, by kind
    int pointsOnEdges = 0;
    int pointsInFaces = 0;
    int mergedPoints = 0;        // polyline points merged with an earlier one within the tolerance
    int tracedSegments = 0;      // segments whose ends shared no face
    int tracedCrossings = 0;     // edge crossings / vertices added by tracing
    int edgePathSegments = 0;    // traced segments no plane section joins, laid along mesh edges instead
    int facesCrossed = 0;        // faces a polyline segment runs through (inside)
    int facesSplit = 0;          // faces re-triangulated (crossed, or with a new vertex on an edge)
    int verticesAdded = 0;
    int facesAdded = 0;
    int frontEdges = 0;          // selected mesh edges
    int missingFrontEdges = 0;   // front edges not found in the mesh afterwards (always 0)
    int patches = 0;
    int danglingFrontEdges = 0;  // selected edges with one patch on both sides (open polyline ends)
    double minAngleDeg = 0;      // smallest angle of the new triangles (0 when none)
    std::vector<int> faceRegion; // region id per face after relabelling (-1: deleted)
    double secondsPrepare = 0, secondsApply = 0, seconds = 0;
    // Phases: checks + adjacency, locating, tracing + planning the faces, writing faces and
    // adjacency and selection, relabelling patches (+ vcg's FF/VF when the mesh has them).
    double secondsSetup = 0, secondsLocate = 0, secondsTraceSplit = 0, secondsWrite = 0, secondsRelabel = 0;
};

// Everything Apply() needs, computed without touching the mesh.
struct EmbeddingPlan {
    EmbeddingAdjacency adj;
    double tolerance = 0;
    int vertexCount = 0, faceCount = 0;
    std::vector<LocatedPoint> newPoints;                   // point id = vertexCount + index
    std::vector<int> splitFaces;                           // faces to re-triangulate
    std::vector<std::vector<std::array<int, 3>>> pieces;   // per split face: triangles over point ids
    std::vector<std::pair<int, int>> frontEdges;                        // point id pairs (a < b)
    EmbeddingResult stats;
    bool ready = false;
};

inline double Seconds(std::chrono::steady_clock::time_point t0)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
// Seconds since the last lap (or the start).
struct Lap {
    std::chrono::steady_clock::time_point t = std::chrono::steady_clock::now();
    double operator()()
    {
        const auto now = std::chrono::steady_clock::now();
        const double s = std::chrono::duration<double>(now - t).count();
        t = now;
        return s;
    }
};
inline void Progress(vcg::CallBackPos *cb, int percent, const char *what)
{
    if (cb) cb(std::min(99, std::max(0, percent)), what);
}

}  // namespace embedding
}  // namespace vcg_ext

#endif
