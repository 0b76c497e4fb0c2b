// A small PLY reader independent of vcglib and MeshLab, so integration tests check MeshLab's
// files with a second implementation: ASCII and binary little-endian; vertex x/y/z, face vertex
// lists (any polygon size) and every scalar face / vertex property by name; edge elements.
#ifndef QMF_TESTS_PLY_READER_H
#define QMF_TESTS_PLY_READER_H

#include <array>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace qmf_test {

struct PlyData {
    std::vector<std::array<double, 3>> vertices;
    std::vector<std::vector<int>> faces;
    std::vector<std::array<int, 2>> edges;
    std::map<std::string, std::vector<double>> vertexProps;  // scalar vertex properties
    std::map<std::string, std::vector<double>> faceProps;    // scalar face properties (quality, flags, red...)
    std::string error;
};

namespace ply_detail {
inline int TypeSize(const std::string &t)
{
    if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
    if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
    if (t == "int" || t == "uint" || t == "float" || t == "int32" || t == "uint32" || t == "float32") return 4;
    if (t == "double" || t == "float64") return 8;
    return 0;
}
inline double ReadBinary(std::istream &in, const std::string &t)
{
    unsigned char b[8];
    in.read(reinterpret_cast<char *>(b), TypeSize(t));
    if (t == "char" || t == "int8") return double(int8_t(b[0]));
    if (t == "uchar" || t == "uint8") return double(b[0]);
    if (t == "short" || t == "int16") { int16_t v; std::memcpy(&v, b, 2); return v; }
    if (t == "ushort" || t == "uint16") { uint16_t v; std::memcpy(&v, b, 2); return v; }
    if (t == "int" || t == "int32") { int32_t v; std::memcpy(&v, b, 4); return v; }
    if (t == "uint" || t == "uint32") { uint32_t v; std::memcpy(&v, b, 4); return v; }
    if (t == "float" || t == "float32") { float v; std::memcpy(&v, b, 4); return v; }
    double v; std::memcpy(&v, b, 8); return v;
}
struct Property { std::string name, type, countType; bool list = false; };
struct Element { std::string name; size_t count = 0; std::vector<Property> props; };
}  // namespace ply_detail

inline PlyData ReadPly(const std::string &path)
{
    using namespace ply_detail;
    PlyData d;
    std::ifstream in(path, std::ios::binary);
    if (!in) { d.error = "cannot open " + path; return d; }
    std::string line, format;
    std::vector<Element> elements;
    std::getline(in, line);
    if (line.rfind("ply", 0) != 0) { d.error = "not a PLY file"; return d; }
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        std::istringstream ss(line);
        std::string w;
        ss >> w;
        if (w == "format") ss >> format;
        else if (w == "element") { Element e; ss >> e.name >> e.count; elements.push_back(e); }
        else if (w == "property" && !elements.empty()) {
            Property p;
            std::string t;
            ss >> t;
            if (t == "list") { p.list = true; ss >> p.countType >> p.type >> p.name; }
            else { p.type = t; ss >> p.name; }
            elements.back().props.push_back(p);
        } else if (w == "end_header") break;
    }
    const bool ascii = format == "ascii";
    if (!ascii && format != "binary_little_endian") { d.error = "unsupported PLY format " + format; return d; }
    for (const Element &e : elements) {
        for (size_t i = 0; i < e.count; ++i) {
            std::vector<double> scalars;
            std::vector<int> list;
            std::istringstream row;
            if (ascii) { std::getline(in, line); row.str(line); }
            for (const Property &p : e.props) {
                if (p.list) {
                    double n;
                    if (ascii) row >> n; else n = ReadBinary(in, p.countType);
                    std::vector<int> items(static_cast<size_t>(n));
                    for (auto &x : items) { double v; if (ascii) row >> v; else v = ReadBinary(in, p.type); x = int(v); }
                    if (p.name == "vertex_indices" || p.name == "vertex_index") list = items;
                    scalars.push_back(0);
                } else {
                    double v;
                    if (ascii) row >> v; else v = ReadBinary(in, p.type);
                    scalars.push_back(v);
                }
            }
            if (!in) { d.error = "truncated PLY file"; return d; }
            if (e.name == "vertex") {
                std::array<double, 3> xyz{0, 0, 0};
                for (size_t k = 0; k < e.props.size(); ++k) {
                    const std::string &n = e.props[k].name;
                    if (n == "x") xyz[0] = scalars[k];
                    else if (n == "y") xyz[1] = scalars[k];
                    else if (n == "z") xyz[2] = scalars[k];
                    else d.vertexProps[n].push_back(scalars[k]);
                }
                d.vertices.push_back(xyz);
            } else if (e.name == "face") {
                d.faces.push_back(list);
                for (size_t k = 0; k < e.props.size(); ++k)
                    if (!e.props[k].list) d.faceProps[e.props[k].name].push_back(scalars[k]);
            } else if (e.name == "edge") {
                std::array<int, 2> ed{-1, -1};
                for (size_t k = 0; k < e.props.size(); ++k) {
                    if (e.props[k].name == "vertex1") ed[0] = int(scalars[k]);
                    if (e.props[k].name == "vertex2") ed[1] = int(scalars[k]);
                }
                d.edges.push_back(ed);
            }
        }
    }
    return d;
}

}  // namespace qmf_test

#endif
