// Filter 4: Q-Morph Quad Conversion.
#include "filter_qmorph_front.h"

#include <QFileInfo>

#include "face_face_adjacency_scope.h"
#include "front_edges_layer.h"
#include <vcg_ext/common/polygon_export.h>
#include <vcg_ext/qmorph.h>
#include <vcg_ext/common/region_ids.h>

typedef vcg_ext::QMorph<CMeshO> QMorphCMeshO;

QString QMorphFrontPlugin::qmorphInfo()
{
    return "Step 4 of the closed-mesh-to-quads pipeline: turns the triangle mesh into a quad-dominant mesh by Q-Morph, "
           "advancing rows of quads on the 3D surface from the initial front, which is kept unchanged. Reads a "
           "2-manifold, consistently oriented triangle mesh whose initial front is its <b>selected face-edges</b> "
           "(from <i>Split Triangles along Front</i> or <i>Select Crease Edges</i>) plus its boundary; writes the quad "
           "mesh in MeshLab's polygonal form (a quad is two triangles sharing a faux edge: turn <i>Polygonal "
           "Modality</i> on), the face quality kept per patch, and optionally real quads to a file. "
           "<br><br>See: <i>S. Owen, M. Staten, S. Canann, S. Saigal</i>, <b>\"Q-Morph: an indirect approach to "
           "advancing front quad meshing\"</b>, IJNME 44:1317-1340, 1999.";
}

void QMorphFrontPlugin::initQMorphParameters(MeshDocument &md, RichParameterList &par)
{
    QMorphCMeshO::Params d;
    const float diag = md.mm() ? md.mm()->cm.bbox.Diag() : 1.f;
    par.addParam(RichBool("PreserveInitialFront", d.preserveInitialFront, "Preserve initial front",
                          "On/off. On (the paper): where two front edges meet at a very small angle and one of them is "
                          "an initial front edge, a triangle is left rather than a seam, so the quads along the front "
                          "keep their alignment. Off: the seam joins the other node onto the front node (fewer "
                          "triangles). Initial front edges are never moved, split or removed either way."));
    par.addParam(RichBool("TangentSmoothing", d.smoothing, "Tangent-plane smoothing",
                          "On/off. On: new nodes are smoothed after each quad and the whole quad mesh at the end, "
                          "moving only in their tangent plane and projected back onto the input surface (better "
                          "shaped quads, no shrinkage). Off: nodes stay where the rows put them. Initial-front nodes "
                          "never move."));
    par.addParam(RichInt("SmoothingIterations", d.smoothingIterations, "Final smoothing iterations",
                         "Number of tangent-plane smoothing sweeps (0 to 100) over the whole quad mesh at the end "
                         "(when smoothing is on). More: more evenly shaped quads, a longer run; 0: none."));
    par.addParam(RichFloat("CreaseAngle", float(d.creaseAngleDeg), "Crease angle (deg)",
                           "In degrees, in (0, 180]: edges whose two faces' normals differ by more than this angle "
                           "are cut like front edges (they are not selected), so no quad folds over a sharp crease "
                           "inside a patch (a VSA region may hold creases up to twice its threshold angle). Smaller: "
                           "more cuts, more patches; 180: off."));
    par.addParam(RichBool("AllQuads", d.allQuads, "All quads",
                          "On/off. On: no triangle is left; at the end every face is split into quads (a quad "
                          "into four, a triangle into three, new points on the input surface; front and creases "
                          "cut at their midpoints, the same way on both sides, so they stay chains of edges). With a "
                          "target edge length set, the re-meshing runs at twice it so the quads have that length; "
                          "with the automatic one, at that length, so the quads are half as long (four times as "
                          "many as without All quads, as well shaped). Off: the few triangles Q-Morph cannot pair "
                          "stay."));
    par.addParam(RichBool("RemeshFirst", true, "Re-mesh first",
                          "On/off. On (beyond the paper): the mesh is first re-meshed isotropically to triangles of "
                          "the target edge length, so the quads are well shaped whatever the input's triangles (CAD "
                          "slivers, uneven scans); sharp creases stay exact chains of edges, the front stays a chain "
                          "of selected edges on its curve. Off: the input triangles are used as they are."));
    par.addParam(RichAbsPerc("TargetEdgeLength", 0.f, 0.f, diag, "Target edge length",
                             "A length in the mesh's units (or % of the bounding-box diagonal) for the re-meshing; 0: "
                             "automatic, the side of equilateral triangles tiling the surface in as many triangles as "
                             "the input (at most 250,000), and at most 1% of the diagonal. Used when 'Re-mesh first' "
                             "is on. Smaller: more, smaller quads."));
    par.addParam(RichInt("RemeshIterations", d.remeshIterations, "Re-meshing iterations",
                         "Number of rounds (1 to 50) of split, collapse, flip and relaxation when re-meshing is on. "
                         "More: more uniform triangles before Q-Morph, a longer run."));
    par.addParam(RichBool("FrontEdgesLayer", true, "Front edges layer",
                          "On/off. On: refresh (or create) the edge-only layer '<mesh>_front_edges' that shows the "
                          "selected front edges (MeshLab 2020.09 does not draw selected face-edges). Off: no layer is "
                          "touched."));
    par.addParam(RichSaveFile("ExportPath", "", ".obj", "Export quads to",
                              "A file path ending in .obj, .off or .ply; empty: no export. When set, the result is also "
                              "written there with real 4-vertex faces (meshlabserver cannot write polygons itself); "
                              "the mesh in MeshLab is the same either way."));
}

bool QMorphFrontPlugin::applyQMorph(MeshDocument &md, const RichParameterList &par, vcg::CallBackPos *cb)
{
    const QString name = filterName(FP_QMORPH);
    MeshModel &mm = *md.mm();
    QMorphCMeshO::Params p;
    p.preserveInitialFront = par.getBool("PreserveInitialFront");
    p.smoothing = par.getBool("TangentSmoothing");
    p.smoothingIterations = par.getInt("SmoothingIterations");
    p.creaseAngleDeg = par.getFloat("CreaseAngle");
    p.remeshFirst = par.getBool("RemeshFirst");
    p.allQuads = par.getBool("AllQuads");
    p.targetEdgeLength = p.remeshFirst ? par.getAbsPerc("TargetEdgeLength") : 0;
    p.remeshIterations = par.getInt("RemeshIterations");
    const QString exportPath = par.getSaveFileName("ExportPath").trimmed();
    if (!exportPath.isEmpty()) {
        QString suffix = QFileInfo(exportPath).suffix().toLower();
        if (suffix != "obj" && suffix != "off" && suffix != "ply")
            return fail(name, "the export path must end in .obj, .off or .ply: " + exportPath);
        QFileInfo dir(QFileInfo(exportPath).absolutePath());
        if (!dir.isDir() || !dir.isWritable()) return fail(name, "cannot write into the folder of " + exportPath);
    }

    // The core checks the mesh and the parameters first and leaves the mesh as it is on error; it
    // needs the face-face adjacency component, on for the call (the core builds the links before it
    // reads them), and for re-meshing vertex-face adjacency and marks, enabled here and dropped
    // again on error.
    const int remeshing = MeshModel::MM_VERTFACETOPO | MeshModel::MM_VERTMARK | MeshModel::MM_FACEMARK;
    const int needed = QMorphCMeshO::RemeshLength(mm.cm, p) > 0 ? remeshing : 0;
    const int missing = needed & ~mm.dataMask();
    FaceFaceAdjacencyScope adjacency(mm.cm);
    mm.updateDataMask(needed);
    QMorphCMeshO::Result r = QMorphCMeshO::Apply(mm.cm, p, cb);
    if (!r.error.empty()) {
        mm.clearDataMask(missing);
        return fail(name, QString::fromStdString(r.error));
    }
    mm.clearDataMask(missing & remeshing);  // the adjacency is stale after the rewrite
    // The quad mesh keeps its face-face adjacency, flagged: MeshLab builds it again on the output,
    // on big scans a fraction of the input.
    mm.updateDataMask(MeshModel::MM_POLYGONAL | MeshModel::MM_FACEFACETOPO);
    adjacency.Keep();
    if (mm.hasDataMask(MeshModel::MM_FACEQUALITY) && mm.hasDataMask(MeshModel::MM_FACECOLOR)) {
        std::vector<int> ids;
        if (vcg_ext::RegionIds<CMeshO>::Read(mm.cm, ids).empty()) vcg_ext::RegionIds<CMeshO>::ColorFaces(mm.cm, ids);
    }
    mm.UpdateBoxAndNormals();

    QString layerNote;
    if (par.getBool("FrontEdgesLayer")) {
        bool existed = false;
        MeshModel *layer = RefreshFrontEdgesLayer(md, mm, vcg_ext::FrontEdges<CMeshO>::Collect(mm.cm), existed);
        layerNote = QString("; %1 layer '%2' (%3 edges)").arg(existed ? "refreshed" : "new", layer->label()).arg(layer->cm.en);
    }

    Log("%s%s", r.Summary().c_str(), qUtf8Printable(layerNote));
    if (!r.RemeshSummary().empty()) Log("%s; %.3f s", r.RemeshSummary().c_str(), r.remeshSeconds);
    Log("%s", r.QualitySummary().c_str());

    if (!exportPath.isEmpty()) {
        std::string err = vcg_ext::PolygonExport::Save(vcg_ext::QuadQuality::FromFauxMesh(mm.cm), exportPath.toStdString());
        if (!err.empty()) return fail(name, QString::fromStdString(err));
        Log("Q-Morph: quads written to %s", qUtf8Printable(exportPath));
    }
    return true;
}
