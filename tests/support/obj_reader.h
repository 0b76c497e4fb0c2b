// A small OBJ/OFF reader independent of vcglib and MeshLab (so tests check MeshLab's files with a
// second implementation), and the few vector helpers the file-level checks use.
#ifndef QMF_TESTS_OBJ_READER_H
#define QMF_TESTS_OBJ_READER_H

#include <array>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace qmf_test {

typedef std::array<double, 3> V3;
inline V3 Sub(const V3 &a, const V3 &b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline V3 Cross(const V3 &a, const V3 &b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
inline double Dot(const V3 &a, const V3 &b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline double Norm(const V3 &a) { return std::sqrt(Dot(a, a)); }

struct ObjData {
    std::vector<V3> v;
    std::vector<std::vector<int>> f;       // polygons, 0-based
    std::vector<std::array<int, 2>> l;     // polyline segments, 0-based
    int otherLines = 0;                    // lines of unexpected kinds
};

// OBJ (v, f with optional /vt/vn parts, l; 1-based) or, by extension, OFF.
inline ObjData ReadObj(const std::string &path)
{
    ObjData o;
    std::ifstream in(path);
    std::string line;
    if (path.size() > 4 && path.substr(path.size() - 4) == ".off") {
        std::getline(in, line);
        int nv = 0, nf = 0, ne = 0;
        in >> nv >> nf >> ne;
        o.v.resize(nv);
        for (auto &p : o.v) in >> p[0] >> p[1] >> p[2];
        for (int i = 0; i < nf && in; ++i) {
            int k = 0;
            in >> k;
            std::vector<int> f(k);
            for (auto &x : f) in >> x;
            o.f.push_back(f);
        }
        return o;
    }
    while (std::getline(in, line)) {
        std::istringstream ss(line);
        std::string w;
        if (!(ss >> w) || w[0] == '#') continue;
        if (w == "v") {
            V3 p;
            ss >> p[0] >> p[1] >> p[2];
            o.v.push_back(p);
        } else if (w == "f" || w == "l") {
            std::vector<int> idx;
            std::string tok;
            while (ss >> tok) idx.push_back(std::stoi(tok.substr(0, tok.find('/'))) - 1);
            if (w == "f") o.f.push_back(idx);
            else
                for (size_t k = 0; k + 1 < idx.size(); ++k) o.l.push_back({idx[k], idx[k + 1]});
        } else if (w != "vn" && w != "vt" && w != "mtllib" && w != "usemtl" && w != "o" && w != "g" && w != "s")
            ++o.otherLines;
    }
    return o;
}

}  // namespace qmf_test

#endif
