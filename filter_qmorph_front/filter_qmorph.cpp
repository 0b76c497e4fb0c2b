// Filter 4: Q-Morph Quad Conversion.
#include "filter_qmorph_front.h"

#include <QFileInfo>

#include "front_edges_layer.h"
#include <vcg_ext/common/polygon_export.h>
#include <vcg_ext/qmorph.h>
#include <vcg_ext/common/region_ids.h>

typedef vcg_ext::QMorph<CMeshO> QMorphCMeshO;

QString QMorphFrontPlugin::qmorphInfo()
{
    return "Step 4 of the closed-mesh-to-quads pipeline. Turns the triangle mesh into a quad-dominant mesh by "
           "Q-Morph, an advancing-front triangle-to-quad transformation, done directly on the 3D surface. The "
           "initial front is the <b>selected face-edges</b> (from <i>Split Triangles along Front</i>, <i>Select "
           "Crease Edges</i> or your own selection) plus the mesh boundary; they cut the surface into patches, each "
           "meshed from its own boundary loops in rows of quads parallel to the front, with Owen's seams, "
           "transition seams and transition splits. Initial front edges are never changed (the paper leaves a triangle "
           "rather than applying a seam on them, see <i>Preserve initial front</i>); new nodes are smoothed in their "
           "tangent plane and projected back onto the input surface, so nothing shrinks. Optionally each patch is "
           "re-meshed isotropically first. "
           "The result uses MeshLab's polygonal representation (a quad is two triangles sharing a faux edge): "
           "view it with <i>Polygonal Modality</i> on, save it with <i>-m ff</i> in PLY, or write real quads with the "
           "export path. Face quality (region id) is kept per patch."
           "<br><br>See: <i>S. Owen, M. Staten, S. Canann, S. Saigal</i>, <b>\"Q-Morph: an indirect approach to "
           "advancing front quad meshing\"</b>, IJNME 44:1317-1340, 1999.";
}

void QMorphFrontPlugin::initQMorphParameters(MeshDocument &md, RichParameterList &par)
{
    QMorphCMeshO::Params d;
    const float diag = md.mm() ? md.mm()->cm.bbox.Diag() : 1.f;
    par.addParam(RichBool("PreserveInitialFront", d.preserveInitialFront, "Preserve initial front",
                          "On (the paper): where two front edges meet at a very small angle and one of them is an "
                          "initial front edge, a triangle is left rather than a seam, so the quads along the front keep "
                          "their alignment. Off: the seam joins the other node onto the front node. Initial front "
                          "edges are never moved, split or removed either way."));
    par.addParam(RichBool("TangentSmoothing", d.smoothing, "Tangent-plane smoothing",
                          "Smooth new nodes after each quad and the whole quad mesh at the end, moving nodes only in "
                          "their tangent plane and projecting them back onto the input surface of their patch "
                          "(no shrinkage). Initial-front nodes never move."));
    par.addParam(RichInt("SmoothingIterations", d.smoothingIterations, "Final smoothing iterations",
                         "Number of tangent-plane smoothing sweeps over the quad mesh at the end (0..100)."));
    par.addParam(RichFloat("CreaseAngle", float(d.creaseAngleDeg), "Crease angle (deg)",
                           "Edges whose two faces' normals differ by more than this angle are cut like front edges "
                           "(they are not selected), so no quad folds over a sharp crease inside a patch (a VSA region "
                           "may hold creases up to twice its threshold angle). 180 turns it off. In (0, 180]."));
    par.addParam(RichAbsPerc("TargetEdgeLength", float(d.targetEdgeLength), 0.f, diag, "Re-mesh first: target edge length",
                             "Optional, beyond the paper: isotropic re-meshing of the mesh before Q-Morph (vcglib's "
                             "split, collapse, flip and tangential relaxation on the input surface), so the quads start "
                             "from well-shaped triangles of this size (absolute units, or % of the bounding-box "
                             "diagonal). Front edges and sharp creases stay where they are, as chains of edges (long "
                             "ones are cut at their midpoints). 0: off (the input triangles are used as they are)."));
    par.addParam(RichInt("RemeshIterations", d.remeshIterations, "Re-meshing iterations",
                         "Rounds of split, collapse, flip and relaxation when re-meshing is on (1..50)."));
    par.addParam(RichBool("FrontEdgesLayer", true, "Front edges layer",
                          "Refresh (or create) the edge-only layer '<mesh>_front_edges' showing the selected front "
                          "edges: MeshLab 2020.09 does not draw selected face-edges."));
    par.addParam(RichSaveFile("ExportPath", "", ".obj", "Export quads to",
                              "Optional: also write the result with real 4-vertex faces to this OBJ, OFF or PLY file "
                              "(by extension). Empty: no export. meshlabserver cannot write polygons itself."));
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
    p.targetEdgeLength = par.getAbsPerc("TargetEdgeLength");
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
    // needs face-face adjacency, enabled here and dropped again on error.
    // (re-meshing: vertex-face adjacency and marks too).
    const int remeshing = MeshModel::MM_VERTFACETOPO | MeshModel::MM_VERTMARK | MeshModel::MM_FACEMARK;
    const int needed = MeshModel::MM_FACEFACETOPO | (p.targetEdgeLength > 0 ? remeshing : 0);
    const int missing = needed & ~mm.dataMask();
    mm.updateDataMask(needed);
    QMorphCMeshO::Result r = QMorphCMeshO::Apply(mm.cm, p, cb);
    if (!r.error.empty()) {
        mm.clearDataMask(missing);
        return fail(name, QString::fromStdString(r.error));
    }
    mm.clearDataMask(missing & remeshing);  // the adjacency is stale after the rewrite
    mm.updateDataMask(MeshModel::MM_POLYGONAL);
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
    if (!r.RemeshSummary().empty()) Log("%s", r.RemeshSummary().c_str());
    Log("%s", r.QualitySummary().c_str());

    if (!exportPath.isEmpty()) {
        std::string err = vcg_ext::PolygonExport::Save(vcg_ext::QuadQuality::FromFauxMesh(mm.cm), exportPath.toStdString());
        if (!err.empty()) return fail(name, QString::fromStdString(err));
        Log("Q-Morph: quads written to %s", qUtf8Printable(exportPath));
    }
    return true;
}
