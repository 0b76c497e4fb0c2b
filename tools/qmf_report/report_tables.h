// The figures qmf_report prints and the rows of its tables. Every row of a table is listed in one
// function (InputRows, AngleRows, QuadRows): to report a new figure of the core, add it to the
// figures struct where it is computed and one Row line here.
#ifndef QMF_REPORT_TABLES_H
#define QMF_REPORT_TABLES_H

#include <cstdio>
#include <string>
#include <vector>

#include <vcg_ext/mesh_checks.h>
#include <vcg_ext/quad_quality.h>

namespace qmf_report {

struct Row {
    std::string label, value;
};

inline std::string Fmt(const char *format, double v)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}
inline std::string Int(long v) { return std::to_string(v); }
inline std::string Pct(double fraction) { return Fmt("%.2f %%", 100.0 * fraction); }
inline std::string Ratio(long part, long whole) { return whole ? Pct(double(part) / double(whole)) : "-"; }
inline std::string YesNo(bool b) { return b ? "yes" : "no"; }

// Topology of a triangle mesh (the core's MeshChecks) plus its Euler characteristic.
struct Topology {
    vcg_ext::MeshCheckReport checks;
    long euler = 0;
    bool Valid() const { return checks.IsClosed() && checks.IsTwoManifold() && checks.IsOriented(); }
    // Closed oriented 2-manifold: chi = sum over components of (2 - 2 g).
    long Genus() const { return (2L * checks.components - euler) / 2; }
    std::string GenusText() const
    {
        return Valid() ? Int(Genus()) + " (Euler characteristic " + Int(euler) + ")"
                       : "n/a (not a closed oriented 2-manifold; Euler characteristic " + Int(euler) + ")";
    }
};

struct InputFigures {
    std::string path;
    Topology topo;
    double area = 0;
    double bboxDiagonal = 0;
    // smallest angle per triangle, degrees
    double angleMin = 0, angleP5 = 0, angleMedian = 0, angleMean = 0;
    std::vector<double> angleBucketEdges;  // bucket k: [edges[k], edges[k+1])
    std::vector<long> angleBucketCounts;
};

struct QuadFigures {
    vcg_ext::QuadQualityReport q;  // the core's report (QuadQuality::Measure)
    long vertices = 0;
    Topology topo;                 // of the faux-edge triangle form
    long inputGenus = -1;          // -1: the input has no genus
    long frontEdges = 0, frontKept = 0, frontStillSelected = 0;
    std::string objCheck;          // quads.obj read back: agrees or how it differs
};

inline std::vector<Row> InputRows(const InputFigures &in)
{
    const auto &c = in.topo.checks;
    return {
        {"faces", Int(c.faces)},
        {"vertices", Int(c.vertices)},
        {"connected components", Int(c.components)},
        {"closed (no boundary edge)", c.IsClosed() ? "yes" : "no (" + Int(c.boundaryEdges) + " boundary edges)"},
        {"2-manifold", c.IsTwoManifold() ? "yes"
                                          : "no (" + Int(c.nonManifoldEdges) + " edges, " + Int(c.nonManifoldVertices) + " vertices)"},
        {"consistently oriented", c.IsOriented() ? "yes" : "no (" + Int(c.inconsistentEdges) + " edges)"},
        {"degenerate / duplicate faces", Int(c.degenerateFaces) + " / " + Int(c.duplicateFaces)},
        {"genus", in.topo.GenusText()},
        {"surface area", Fmt("%.6g", in.area)},
        {"bounding-box diagonal", Fmt("%.6g", in.bboxDiagonal)},
    };
}

inline std::vector<Row> AngleRows(const InputFigures &in)
{
    std::vector<Row> rows = {
        {"minimum", Fmt("%.2f deg", in.angleMin)},
        {"5th percentile", Fmt("%.2f deg", in.angleP5)},
        {"median", Fmt("%.2f deg", in.angleMedian)},
        {"mean", Fmt("%.2f deg", in.angleMean)},
    };
    long total = 0;
    for (long n : in.angleBucketCounts) total += n;
    for (size_t k = 0; k < in.angleBucketCounts.size(); ++k) {
        const bool last = k + 1 == in.angleBucketCounts.size();
        std::string label = Fmt("%.0f", in.angleBucketEdges[k]) + (last ? " - " : " - <") + Fmt("%.0f deg", in.angleBucketEdges[k + 1]);
        rows.push_back({label, Int(in.angleBucketCounts[k]) + " (" + Ratio(in.angleBucketCounts[k], total) + ")"});
    }
    return rows;
}

inline std::vector<Row> QuadRows(const QuadFigures &f)
{
    const auto &q = f.q;
    const auto &c = f.topo.checks;
    std::string genus = f.topo.GenusText();
    if (f.topo.Valid() && f.inputGenus >= 0) genus += f.topo.Genus() == f.inputGenus ? ", same as the input" : ", input " + Int(f.inputGenus);
    return {
        {"quads", Int(q.quads)},
        {"triangles", Int(q.triangles)},
        {"other polygons", Int(q.others)},
        {"vertices", Int(f.vertices)},
        {"quads by count", Pct(q.quadCountFraction)},
        {"area in quads", Pct(q.quadAreaFraction)},
        {"scaled Jacobian min (against the input surface's normal)", Fmt("%.3f", q.minJacobian)},
        {"scaled Jacobian mean", Fmt("%.3f", q.meanJacobian)},
        {"scaled Jacobian 5th percentile", Fmt("%.3f", q.p5Jacobian)},
        {"quads below 0.3", Int(q.quadsBelow03) + " (" + Ratio(q.quadsBelow03, q.quads) + ")"},
        {"inverted quads (scaled Jacobian <= 0)", Int(q.invertedQuads)},
        {"flipped faces (upside down on the input surface)", Int(q.flippedFaces)},
        {"folded quads (bent over 60 degrees along both diagonals)", Int(q.foldedQuads)},
        {"irregular vertices (valence != 4, inner all-quad vertices)",
         Int(q.irregularVertices) + " of " + Int(q.interiorAllQuadVertices) + " (" + Pct(q.IrregularFraction()) + ")"},
        {"... inside patches / at front nodes (two front edges) / at front junctions",
         q.frontKnown ? Int(q.IrregularInsidePatches()) + " / " + Int(q.irregularAtFrontNodes) + " / " + Int(q.irregularAtFrontJunctions)
                      : std::string("front unknown")},
        {"front edges kept (output edges, still selected)",
         Int(f.frontKept) + " of " + Int(f.frontEdges) + " (" + Int(f.frontStillSelected) + " selected)"},
        {"closed 2-manifold, oriented",
         YesNo(c.IsClosed() && c.IsTwoManifold()) + ", " + YesNo(c.IsOriented()) + " (" + Int(c.components) + " components)"},
        {"genus", genus},
        {"quads.obj (real quads) read back", f.objCheck},
    };
}

inline void PrintTable(FILE *out, const std::string &head1, const std::string &head2, const std::vector<Row> &rows)
{
    std::fprintf(out, "| %s | %s |\n|:--|--:|\n", head1.c_str(), head2.c_str());
    for (const Row &r : rows) std::fprintf(out, "| %s | %s |\n", r.label.c_str(), r.value.c_str());
}

}  // namespace qmf_report

#endif
