// Writes a polygon mesh (quads as real 4-node faces) to OBJ, OFF or PLY (ASCII, by extension).
// MeshLab 2020.09 cannot do it from meshlabserver: its OFF polygon export writes vertex flags in
// place of indices and the PLY exporter writes triangles.
#ifndef VCG_EXT_COMMON_POLYGON_EXPORT_H
#define VCG_EXT_COMMON_POLYGON_EXPORT_H

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <string>

#include <vcg_ext/quad_quality.h>

namespace vcg_ext {

class PolygonExport
{
public:
    // Empty string on success, else why the file could not be written.
    static std::string Save(const PolygonMesh &pm, const std::string &path)
    {
        std::string ext = path.size() >= 4 ? path.substr(path.size() - 4) : "";
        std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
        if (ext != ".obj" && ext != ".off" && ext != ".ply") return "the export path must end in .obj, .off or .ply";
        FILE *out = std::fopen(path.c_str(), "w");
        if (!out) return "cannot write " + path;
        if (ext == ".obj") {
            std::fprintf(out, "# quad-dominant mesh: %zu vertices, %zu faces\n", pm.points.size(), pm.faces.size());
            for (const auto &p : pm.points) std::fprintf(out, "v %.9g %.9g %.9g\n", p[0], p[1], p[2]);
            for (const auto &f : pm.faces) {
                std::fputc('f', out);
                for (int v : f) std::fprintf(out, " %d", v + 1);
                std::fputc('\n', out);
            }
        } else if (ext == ".off") {
            std::fprintf(out, "OFF\n%zu %zu 0\n", pm.points.size(), pm.faces.size());
            for (const auto &p : pm.points) std::fprintf(out, "%.9g %.9g %.9g\n", p[0], p[1], p[2]);
            WriteFaces(out, pm);
        } else {
            std::fprintf(out, "ply\nformat ascii 1.0\nelement vertex %zu\nproperty float x\nproperty float y\nproperty float z\n"
                              "element face %zu\nproperty list uchar int vertex_indices\nend_header\n",
                         pm.points.size(), pm.faces.size());
            for (const auto &p : pm.points) std::fprintf(out, "%.9g %.9g %.9g\n", p[0], p[1], p[2]);
            WriteFaces(out, pm);
        }
        bool failed = std::ferror(out) != 0;
        failed = std::fclose(out) != 0 || failed;
        return failed ? "error while writing " + path : "";
    }

private:
    static void WriteFaces(FILE *out, const PolygonMesh &pm)
    {
        for (const auto &f : pm.faces) {
            std::fprintf(out, "%zu", f.size());
            for (int v : f) std::fprintf(out, " %d", v);
            std::fputc('\n', out);
        }
    }
};

}  // namespace vcg_ext

#endif
