// The bad-input matrix: broken variants of a closed cube (4 x 4 cells per side, outward), each
// with what the four filters need (region ids per face, a front polyline, selected crease edges),
// and per filter the outcome: refused with a message naming the problem, or run. The plugin tests
// run every row in-process (mesh and document exactly unchanged on refusal), the integration tests
// through meshlabserver (exit status, logged message, no output file).
#ifndef QMF_TESTS_BAD_INPUT_CASES_H
#define QMF_TESTS_BAD_INPUT_CASES_H

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include "test_mesh.h"

namespace qmf_test {
namespace bad_input {

// A mesh and what the later filters read from it.
struct Input {
    std::vector<std::array<float, 3>> v;
    std::vector<std::array<int, 3>> f;
    std::vector<int> label;          // per face: region id (face quality)
    std::vector<char> creaseSel;     // per face-edge 3f+k: selected (an initial front for Q-Morph)
    std::vector<std::vector<std::array<float, 3>>> fronts;  // closed polylines on the surface (the '_front' layer)
    bool hasLabels = true, hasFrontLayer = true, hasSelection = true;
};

// What a filter must do with a row: refuse, with this text in its message (and `fix`, the MeshLab
// filter named, when not empty), or run (empty `refusal`).
struct Outcome {
    std::string refusal;
    std::string fix;
    bool Runs() const { return refusal.empty(); }
};
inline Outcome Runs() { return Outcome(); }
inline Outcome Refused(const std::string &text, const std::string &fix = "") { return Outcome{text, fix}; }

enum Filter { FilterVsa, FilterSmooth, FilterSplit, FilterQMorph, FilterCount };
inline const char *FilterName(int f)
{
    static const char *names[] = {"Segment by Variational Shape Approximation", "Smooth Region Boundaries",
                                  "Split Triangles along Front", "Q-Morph Quad Conversion"};
    return names[f];
}

// A parameter of a filter set to a value out of its range (name, type as in an .mlx, value).
struct BadParam {
    std::string name, type, value;
};

struct Case {
    std::string name;
    std::function<Input()> make;
    std::array<Outcome, FilterCount> outcome;
    std::array<BadParam, FilterCount> param;  // optional: empty name = defaults
};

// gtest prints a row by its name.
inline void PrintTo(const Case &c, std::ostream *os) { *os << c.name; }

// ---------------------------------------------------------------- the base and its damage
inline int LabelOfNormal(const vcg::Point3f &n)  // the cube side a face lies on: 0..5
{
    int axis = 0;
    for (int k = 1; k < 3; ++k)
        if (std::fabs(n[k]) > std::fabs(n[axis])) axis = k;
    return 2 * axis + (n[axis] > 0 ? 1 : 0);
}

inline Input Cube(float shift = 0)
{
    TMesh m;
    MakeCube(m, 4);
    Input in;
    for (auto &x : m.vert) in.v.push_back({x.P()[0] + shift, x.P()[1], x.P()[2]});
    for (auto &x : m.face) {
        in.f.push_back({int(vcg::tri::Index(m, x.V(0))), int(vcg::tri::Index(m, x.V(1))), int(vcg::tri::Index(m, x.V(2)))});
        in.label.push_back(LabelOfNormal(x.N()));
    }
    // the 12 edges of the cube: face-edges between faces of different sides
    std::map<std::pair<int, int>, int> faceOf;
    for (size_t i = 0; i < in.f.size(); ++i)
        for (int k = 0; k < 3; ++k) faceOf[{in.f[i][k], in.f[i][(k + 1) % 3]}] = int(i);
    in.creaseSel.assign(3 * in.f.size(), 0);
    for (size_t i = 0; i < in.f.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            auto it = faceOf.find({in.f[i][(k + 1) % 3], in.f[i][k]});
            in.creaseSel[3 * i + k] = it != faceOf.end() && in.label[it->second] != in.label[i];
        }
    // the loop z = 0 around the four sides, through the grid vertices (every segment a mesh edge)
    const float g[] = {-1, -0.5f, 0, 0.5f};
    in.fronts.emplace_back();
    for (float t : g) in.fronts.back().push_back({1 + shift, t, 0});
    for (float t : g) in.fronts.back().push_back({-t + shift, 1, 0});
    for (float t : g) in.fronts.back().push_back({-1 + shift, -t, 0});
    for (float t : g) in.fronts.back().push_back({t + shift, -1, 0});
    return in;
}

inline void AddFace(Input &in, std::array<int, 3> f, int label = 0)
{
    in.f.push_back(f);
    in.label.push_back(label);
    for (int k = 0; k < 3; ++k) in.creaseSel.push_back(0);
}

inline void Append(Input &in, const Input &other, bool withFront, bool withSelection)
{
    const int base = int(in.v.size());
    in.v.insert(in.v.end(), other.v.begin(), other.v.end());
    for (size_t i = 0; i < other.f.size(); ++i) {
        AddFace(in, {other.f[i][0] + base, other.f[i][1] + base, other.f[i][2] + base}, other.label[i] + 10);
        if (withSelection)
            for (int k = 0; k < 3; ++k) in.creaseSel[in.creaseSel.size() - 3 + k] = other.creaseSel[3 * i + k];
    }
    if (withFront) in.fronts.insert(in.fronts.end(), other.fronts.begin(), other.fronts.end());
}

// A top-side (z = 1) face, away from the front loop.
inline int TopFace(const Input &in)
{
    for (size_t i = 0; i < in.f.size(); ++i)
        if (in.label[i] == 5) return int(i);
    return 0;
}
// An interior vertex of the top side and a grid neighbour of it (an edge apart).
inline std::pair<int, int> TopInteriorEdge(const Input &in)
{
    for (size_t i = 0; i < in.f.size(); ++i) {
        if (in.label[i] != 5) continue;
        for (int k = 0; k < 3; ++k) {
            const auto &p = in.v[in.f[i][k]];
            if (std::fabs(p[0]) < 1 && std::fabs(p[1]) < 1) return {in.f[i][k], in.f[i][(k + 1) % 3]};
        }
    }
    return {0, 1};
}

// Edge a-b of face t split at m, (a, b, c) -> (a, m, c), (m, b, c) and the sliver (m, a, b):
// m on the edge (towards = 0) makes a zero-area face, moved a fraction towards c a needle.
inline Input WithSliver(double towards)
{
    Input in = Cube();
    const int t = TopFace(in);
    const int a = in.f[t][0], b = in.f[t][1], c = in.f[t][2];
    std::array<float, 3> m;
    for (int k = 0; k < 3; ++k) {
        const double mid = (double(in.v[a][k]) + in.v[b][k]) / 2;
        m[k] = float(mid + towards * (in.v[c][k] - mid));
    }
    const int mi = int(in.v.size());
    in.v.push_back(m);
    in.f[t] = {a, mi, c};
    for (int k = 0; k < 3; ++k) in.creaseSel[3 * t + k] = 0;
    AddFace(in, {mi, b, c}, in.label[t]);
    AddFace(in, {mi, a, b}, in.label[t]);
    return in;
}

// ---------------------------------------------------------------- the rows
inline std::vector<Case> Cases()
{
    const std::string zeroArea = "Remove Zero Area Faces", dupFaces = "Remove Duplicate Faces",
                      merge = "Merge Close Vertices", reorient = "Re-Orient all faces coherentely",
                      fin = "Repair non Manifold Edges by removing faces", bowtie = "Repair non Manifold Vertices by splitting";
    std::vector<Case> c;
    auto row = [&](const std::string &name, std::function<Input()> make, Outcome vsa, Outcome smooth, Outcome split,
                   Outcome qmorph) {
        Case k;
        k.name = name;
        k.make = make;
        k.outcome = {vsa, smooth, split, qmorph};
        c.push_back(k);
    };
    row("cube", [] { return Cube(); }, Runs(), Runs(), Runs(), Runs());
    row("empty", [] { Input in; in.fronts = Cube().fronts; return in; },
        Refused("the mesh is empty"), Refused("the mesh is empty"), Refused("the mesh is empty"), Refused("the mesh is empty"));
    row("point_cloud", [] { Input in = Cube(); in.f.clear(); in.label.clear(); in.creaseSel.clear(); return in; },
        Refused("no faces (a point cloud)"), Refused("no faces (a point cloud)"), Refused("no faces (a point cloud)"),
        Refused("no faces (a point cloud)"));
    row("single_triangle", [] {
            Input in;
            in.v = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
            in.f = {{0, 1, 2}};
            in.label = {0};
            in.creaseSel = {0, 0, 0};
            in.fronts = {{{0.2f, 0.2f, 0}, {0.5f, 0.2f, 0}, {0.3f, 0.4f, 0}}};
            return in;
        },
        Runs(), Refused("single region id"), Runs(), Runs());
    row("open", [] {
            Input in = Cube();
            const int t = TopFace(in);
            in.f.erase(in.f.begin() + t);
            in.label.erase(in.label.begin() + t);
            in.creaseSel.erase(in.creaseSel.begin() + 3 * t, in.creaseSel.begin() + 3 * t + 3);
            return in;
        },
        Runs(), Runs(), Runs(), Runs());
    row("nan", [] {
            Input in = Cube();
            in.v[TopInteriorEdge(in).first][1] = std::numeric_limits<float>::quiet_NaN();
            return in;
        },
        Refused("NaN"), Refused("NaN"), Refused("NaN"), Refused("NaN"));
    row("triangle_soup", [] {
            Input cube = Cube(), in = cube;
            in.v.clear();
            for (auto &t : in.f)
                for (int &i : t) { in.v.push_back(cube.v[i]); i = int(in.v.size()) - 1; }
            return in;
        },
        Refused("triangle soup", merge), Refused("triangle soup", merge), Refused("triangle soup", merge),
        Refused("triangle soup", merge));
    row("non_manifold_fin", [] {
            Input in = Cube();
            const int t = TopFace(in);
            in.v.push_back({3, 3, 3});
            AddFace(in, {in.f[t][0], in.f[t][1], int(in.v.size()) - 1}, in.label[t]);
            return in;
        },
        Runs(), Refused("lie on a region boundary", fin), Refused("edges have more than two faces", fin),
        Refused("edges have more than two faces", fin));
    row("inconsistent_orientation", [] {
            Input in = Cube();
            std::swap(in.f[7][1], in.f[7][2]);
            return in;
        },
        Refused("not consistently oriented", reorient), Runs(), Refused("not consistently oriented", reorient),
        Refused("not consistently oriented", reorient));
    row("all_faces_flipped", [] {
            Input in = Cube();
            for (size_t i = 0; i < in.f.size(); ++i) {
                std::swap(in.f[i][0], in.f[i][1]);  // edge 0 stays, edges 1 and 2 swap places
                std::swap(in.creaseSel[3 * i + 1], in.creaseSel[3 * i + 2]);
            }
            return in;
        },
        Runs(), Runs(), Runs(), Runs());
    row("two_components", [] {
            Input in = Cube();
            Append(in, Cube(4), true, true);
            return in;
        },
        Runs(), Runs(), Runs(), Runs());
    row("two_components_one_without_front", [] {
            Input in = Cube();
            Append(in, Cube(4), false, false);
            return in;
        },
        Runs(), Runs(), Runs(), Runs());
    row("collapsed_vertex", [] {
            Input in = Cube();
            const auto e = TopInteriorEdge(in);
            in.v[e.first] = in.v[e.second];
            return in;
        },
        Runs(), Runs(), Refused("degenerate", zeroArea), Refused("degenerate", zeroArea));
    row("zero_area_face", [] { return WithSliver(0); },
        Runs(), Runs(), Refused("degenerate", zeroArea), Refused("degenerate", zeroArea));
    row("needle_face", [] { return WithSliver(1e-5); }, Runs(), Runs(), Runs(), Runs());
    row("duplicate_face", [] {
            Input in = Cube();
            const int t = TopFace(in);
            AddFace(in, in.f[t], in.label[t]);
            return in;
        },
        // (the smoothing sees the duplicate's edges as non-manifold ones on a region boundary)
        Runs(), Refused("lie on a region boundary", fin), Refused("duplicates", dupFaces), Refused("duplicates", dupFaces));
    row("non_manifold_vertex", [] {
            Input in = Cube();
            const int corner = in.f[0][0];
            const auto p = in.v[corner];
            in.v.push_back({2 * p[0], 2 * p[1], 2 * p[2]});
            in.v.push_back({2 * p[0] + 0.5f, 2 * p[1], 2 * p[2]});
            AddFace(in, {corner, int(in.v.size()) - 2, int(in.v.size()) - 1}, 0);
            return in;
        },
        Runs(), Runs(), Refused("vertices are non-manifold", bowtie), Refused("vertices are non-manifold", bowtie));
    row("no_labels", [] { Input in = Cube(); in.hasLabels = false; return in; },
        Runs(), Refused("no face quality", "Segment by Variational Shape Approximation"), Runs(), Runs());
    row("no_front_layer", [] { Input in = Cube(); in.hasFrontLayer = false; return in; },
        Runs(), Runs(), Refused("the polyline layer is the mesh itself"), Runs());
    row("no_selection", [] { Input in = Cube(); in.hasSelection = false; return in; },
        Runs(), Runs(), Runs(), Refused("no selected edges", "Split Triangles along Front"));
    Case bad;
    bad.name = "parameters_out_of_range";
    bad.make = [] { return Cube(); };
    bad.outcome = {Refused("threshold angle"), Refused("snap"), Refused("locate tolerance"), Refused("smoothing iterations")};
    bad.param = {BadParam{"ThresholdAngle", "RichFloat", "190"}, BadParam{"SnapDistance", "RichFloat", "-5"},
                 BadParam{"LocateTolerance", "RichFloat", "11"}, BadParam{"SmoothingIterations", "RichInt", "101"}};
    c.push_back(bad);
    return c;
}

}  // namespace bad_input
}  // namespace qmf_test

#endif
