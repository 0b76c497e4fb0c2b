// The mesh type qmf_report reads MeshLab's files into (float coordinates like MeshLab's CMeshO,
// face colour, quality and flags so the PLY face flags keep faux diagonals and the selected front),
// loading through vcglib's importers, and plain counts: Euler characteristic, genus, areas, angles.
#ifndef QMF_REPORT_MESH_H
#define QMF_REPORT_MESH_H

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/complex/algorithms/update/topology.h>
#include <wrap/io_trimesh/import_off.h>
#include <wrap/io_trimesh/import_ply.h>
#include <wrap/io_trimesh/import_stl.h>

#include <vcg_ext/common/polygon_geometry.h>
#include <vcg_ext/quad_quality.h>

namespace qmf_report {

class RVertex;
class REdge;
class RFace;
struct RUsedTypes : public vcg::UsedTypes<vcg::Use<RVertex>::AsVertexType, vcg::Use<REdge>::AsEdgeType,
                                          vcg::Use<RFace>::AsFaceType> {};
class RVertex : public vcg::Vertex<RUsedTypes, vcg::vertex::Coord3f, vcg::vertex::Normal3f, vcg::vertex::BitFlags> {};
class REdge : public vcg::Edge<RUsedTypes, vcg::edge::VertexRef, vcg::edge::BitFlags> {};
class RFace : public vcg::Face<RUsedTypes, vcg::face::VertexRef, vcg::face::BitFlags, vcg::face::Normal3f,
                               vcg::face::Qualityf, vcg::face::Color4b, vcg::face::FFAdj,
                               vcg::face::Mark> {};  // Mark: closest-point queries on the input
class RMesh : public vcg::tri::TriMesh<std::vector<RVertex>, std::vector<REdge>, std::vector<RFace>> {};

typedef vcg::Point3<double> P3d;

inline std::string Lower(std::string s)
{
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

inline std::string Extension(const std::string &path)
{
    size_t dot = path.find_last_of('.'), slash = path.find_last_of('/');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
    return Lower(path.substr(dot + 1));
}

// Reads an OBJ file as it is: v, f (polygons; "i/t/n" and negative indices accepted) and l lines
// (polylines, as consecutive pairs). Not vcglib's OBJ importer: the one of this vcglib miscounts
// polygons (a quad file read back lost 4 quads) and Debian's MeshLab 2020.09 asserts in it on any
// OBJ with faces (Debian bug #1054006).
inline std::string ReadObj(const std::string &path, vcg_ext::PolygonMesh &pm, std::vector<std::pair<int, int>> *edges = nullptr)
{
    FILE *in = std::fopen(path.c_str(), "r");
    if (!in) return "cannot read " + path;
    pm = vcg_ext::PolygonMesh();
    if (edges) edges->clear();
    std::string err;
    char line[4096];
    long lineNo = 0;
    while (err.empty() && std::fgets(line, sizeof line, in)) {
        ++lineNo;
        const char kind = line[0];
        if (kind == 'v' && (line[1] == ' ' || line[1] == '\t')) {
            double x, y, z;
            if (std::sscanf(line + 2, "%lf %lf %lf", &x, &y, &z) != 3) err = "bad vertex";
            pm.points.push_back(P3d(x, y, z));
        } else if ((kind == 'f' || kind == 'l') && (line[1] == ' ' || line[1] == '\t')) {
            std::vector<int> ids;
            char *s = line + 2;
            while (*s) {
                char *end;
                long i = std::strtol(s, &end, 10);
                if (end == s) break;
                if (i < 0) i += long(pm.points.size()) + 1;
                if (i < 1 || i > long(pm.points.size())) { err = "bad vertex index"; break; }
                ids.push_back(int(i - 1));
                s = end;
                while (*s && *s != ' ' && *s != '\t') ++s;  // skip "/t/n"
            }
            if (!err.empty()) break;
            if (kind == 'f') {
                if (ids.size() < 3) err = "face with fewer than 3 vertices";
                pm.faces.push_back(ids);
            } else if (edges) {
                for (size_t k = 0; k + 1 < ids.size(); ++k) edges->push_back({ids[k], ids[k + 1]});
            }
        }
    }
    std::fclose(in);
    return err.empty() ? "" : path + ":" + std::to_string(lineNo) + ": " + err;
}

// An OBJ file as a triangle mesh: polygons fanned from their first vertex, the inner edges of a
// fan flagged faux (MeshLab's polygonal form), polylines as edges.
inline std::string LoadObj(RMesh &m, const std::string &path)
{
    vcg_ext::PolygonMesh pm;
    std::vector<std::pair<int, int>> edges;
    std::string err = ReadObj(path, pm, &edges);
    if (!err.empty()) return err;
    size_t tris = 0;
    for (const auto &f : pm.faces) tris += f.size() - 2;
    if (!pm.points.empty()) vcg::tri::Allocator<RMesh>::AddVertices(m, pm.points.size());
    for (size_t i = 0; i < pm.points.size(); ++i) m.vert[i].P() = vcg::Point3f::Construct(pm.points[i]);
    if (tris) vcg::tri::Allocator<RMesh>::AddFaces(m, tris);
    size_t t = 0;
    for (const auto &f : pm.faces)
        for (size_t k = 1; k + 1 < f.size(); ++k, ++t) {
            RFace &F = m.face[t];
            F.V(0) = &m.vert[f[0]]; F.V(1) = &m.vert[f[k]]; F.V(2) = &m.vert[f[k + 1]];
            F.Flags() = 0;
            if (k > 1) F.SetF(0);                 // edge f[0]-f[k]: shared with the previous triangle
            if (k + 2 < f.size()) F.SetF(2);      // edge f[k+1]-f[0]: shared with the next one
        }
    if (!edges.empty()) vcg::tri::Allocator<RMesh>::AddEdges(m, edges.size());
    for (size_t i = 0; i < edges.size(); ++i) {
        m.edge[i].V(0) = &m.vert[edges[i].first];
        m.edge[i].V(1) = &m.vert[edges[i].second];
    }
    return "";
}

// Loads OFF, PLY, OBJ or STL (by extension) with vcglib's importers, keeping face flags, quality
// and colour when the file has them (PLY). STL vertices are unified, as MeshLab does when it opens
// an STL (its default "Unify Duplicated Vertices"), so the counts describe what the filters saw.
// Empty string on success, else the reason.
inline std::string Load(RMesh &m, const std::string &path)
{
    m.Clear();
    const std::string ext = Extension(path);
    int mask = 0;
    int err = 0;
    std::string msg;
    if (ext == "ply") {
        err = vcg::tri::io::ImporterPLY<RMesh>::Open(m, path.c_str(), mask);
        if (err != 0 && vcg::tri::io::ImporterPLY<RMesh>::ErrorCritical(err)) msg = vcg::tri::io::ImporterPLY<RMesh>::ErrorMsg(err);
    } else if (ext == "off") {
        err = vcg::tri::io::ImporterOFF<RMesh>::Open(m, path.c_str(), mask);
        if (err != 0) msg = vcg::tri::io::ImporterOFF<RMesh>::ErrorMsg(err);
    } else if (ext == "obj") {
        msg = LoadObj(m, path);
    } else if (ext == "stl") {
        err = vcg::tri::io::ImporterSTL<RMesh>::Open(m, path.c_str(), mask);
        if (err != 0) msg = vcg::tri::io::ImporterSTL<RMesh>::ErrorMsg(err);
        if (msg.empty()) {
            vcg::tri::Clean<RMesh>::RemoveDuplicateVertex(m);
            vcg::tri::Allocator<RMesh>::CompactEveryVector(m);
        }
    } else {
        return "unknown mesh format (OFF, PLY, OBJ or STL): " + path;
    }
    if (!msg.empty()) return "cannot read " + path + ": " + msg;
    vcg::tri::UpdateBounding<RMesh>::Box(m);
    if (m.fn > 0) vcg::tri::UpdateNormal<RMesh>::PerFaceNormalized(m);
    return "";
}

inline P3d PosOf(const RVertex *v) { return P3d::Construct(v->cP()); }

inline double FaceArea(const RFace &f)
{
    return 0.5 * ((PosOf(f.cV(1)) - PosOf(f.cV(0))) ^ (PosOf(f.cV(2)) - PosOf(f.cV(0)))).Norm();
}

inline double TotalArea(const RMesh &m)
{
    double a = 0;
    for (const RFace &f : m.face)
        if (!f.IsD()) a += FaceArea(f);
    return a;
}

// Smallest interior angle of a triangle in degrees (0 for a degenerate one).
inline double SmallestAngleDeg(const RFace &f)
{
    double best = 180;
    for (int k = 0; k < 3; ++k) {
        const P3d a = PosOf(f.cV((k + 1) % 3)) - PosOf(f.cV(k)), b = PosOf(f.cV((k + 2) % 3)) - PosOf(f.cV(k));
        if (!(a.Norm() > 0 && b.Norm() > 0)) return 0;
        best = std::min(best, vcg_ext::AngleBetween(a, b) * 180.0 / M_PI);
    }
    return best;
}

// Linear-interpolated percentile (q in [0,1]) of a sorted list.
inline double Percentile(const std::vector<double> &sorted, double q)
{
    if (sorted.empty()) return 0;
    double pos = q * double(sorted.size() - 1);
    size_t i = size_t(pos);
    if (i + 1 >= sorted.size()) return sorted.back();
    return sorted[i] + (pos - double(i)) * (sorted[i + 1] - sorted[i]);
}

}  // namespace qmf_report

#endif
