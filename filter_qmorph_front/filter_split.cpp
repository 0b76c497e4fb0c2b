// Filter 3: Split Triangles along Front.
#include "filter_qmorph_front.h"

#include "front_edges_layer.h"
#include <vcg_ext/polyline_embedding.h>

typedef vcg_ext::PolylineEmbedding<CMeshO> Embedding;

QString QMorphFrontPlugin::splitInfo()
{
    return "Step 3 of the closed-mesh-to-quads pipeline: re-triangulates the mesh so that every polyline of the "
           "<b>polyline layer</b> (by default <i>&lt;mesh&gt;_front</i>, from <i>Smooth Region Boundaries</i>) "
           "becomes a chain of mesh edges, splitting each crossed face along it (one new vertex per crossing; area "
           "and orientation kept). Reads a 2-manifold, consistently oriented triangle mesh and the polyline layer; "
           "writes the re-triangulated mesh with those edges as <b>selected face-edges</b> (saved with <i>-m ff</i>), "
           "the face quality relabelled per patch bounded by them, and the layer <i>&lt;mesh&gt;_front_edges</i> "
           "showing them. "
           "<br><br>See: <b>\"Transformation of a closed 3D triangular mesh to a quadrilateral mesh based on feature "
           "edges\"</b> (its triangle splitting step).";
}

// Default polyline layer: '<current>_front' if there is one, else the next layer (else the first other one).
void QMorphFrontPlugin::initSplitParameters(MeshDocument &md, RichParameterList &par)
{
    MeshModel *current = md.mm();
    MeshModel *def = nullptr;
    for (MeshModel *m : md.meshList)  // by label (MeshDocument::getMesh(QString) compares file names)
        if (current != nullptr && m != current && m->label() == current->label() + "_front") def = m;
    if (def == nullptr && current != nullptr) def = md.nextMesh(current);
    for (int i = 0; def == nullptr && i < md.meshList.size(); ++i)
        if (md.meshList[i] != current) def = md.meshList[i];
    if (def == nullptr) def = current;  // a single layer: applying refuses it with a message
    Embedding::Params d;
    par.addParam(RichMesh("PolylineLayer", def, def ? &md : nullptr, "Polyline layer",
                          "A layer (no unit): the edge-only layer whose polylines become mesh edges, by default "
                          "'<mesh>_front' from Smooth Region Boundaries. Any polyline whose points lie on the surface "
                          "works (loaded or drawn); segments whose ends share no face are traced across the faces "
                          "between them. In an .mlx script: the layer position (1 for the front layer after loading "
                          "one mesh)."));
    par.addParam(RichFloat("LocateTolerance", float(d.locateTolerancePercent), "Locate tolerance (% of diagonal)",
                           "In % of the mesh bounding-box diagonal, in (0, 10]: a polyline point farther than this "
                           "from the surface is an error; a point within it of a vertex is that vertex, within it of an "
                           "edge lies on that edge. Larger: coarser polylines (e.g. points written with 6 decimals to an "
                           "OBJ from a small mesh) are still found, but nearby points merge."));
    par.addParam(RichBool("FrontEdgesLayer", true, "Front edges layer",
                          "On/off. On: refresh (or create) the edge-only layer '<mesh>_front_edges' that shows the "
                          "selected front edges (MeshLab 2020.09 does not draw selected face-edges). Off: no layer is "
                          "touched; the selection is made either way."));
}

bool QMorphFrontPlugin::applySplit(MeshDocument &md, const RichParameterList &par, vcg::CallBackPos *cb)
{
    const QString name = filterName(FP_SPLIT_ALONG_FRONT);
    MeshModel &mm = *md.mm();
    MeshModel *poly = par.getMesh("PolylineLayer");
    if (poly == nullptr || !md.meshList.contains(poly))
        return fail(name, "the polyline layer is missing: run 'Smooth Region Boundaries' first, or choose the layer "
                          "holding the polylines");
    if (poly == &mm)
        return fail(name, "the polyline layer is the mesh itself: choose the layer holding the polylines (e.g. '" +
                              mm.label() + "_front')");
    if (poly->cm.en == 0)
        return fail(name, "the polyline layer '" + poly->label() + "' is empty: it has no edges" +
                              (poly->cm.fn > 0 ? " (it is a triangle mesh, not a polyline)" : ""));

    Embedding::Params p;
    p.locateTolerancePercent = par.getFloat("LocateTolerance");
    // The core checks the parameters and the mesh, then locates, traces and plans the split without
    // touching the mesh: bad input leaves it as it was.
    Embedding::Plan plan;
    Embedding::Result r = Embedding::Prepare(mm.cm, poly->cm, p, plan, cb);
    if (!r.error.empty()) {
        const QString why = QString::fromStdString(r.error);
        return fail(name, r.inputProblem ? why : "layer '" + poly->label() + "': " + why);
    }

    // Checks passed: from here on the mesh changes.
    mm.updateDataMask(MeshModel::MM_FACEQUALITY | MeshModel::MM_FACECOLOR);
    r = Embedding::Apply(mm.cm, plan, cb);
    if (!r.error.empty()) return fail(name, QString::fromStdString(r.error));
    mm.UpdateBoxAndNormals();

    QString layerNote;
    if (par.getBool("FrontEdgesLayer")) {
        bool existed = false;
        MeshModel *layer = RefreshFrontEdgesLayer(md, mm, plan.frontEdges, existed);
        const QString label = layer->label();
        layerNote = QString("; %1 layer '%2' (%3 edges)").arg(existed ? "refreshed" : "new", label).arg(layer->cm.en);
    }
    if (cb) cb(100, "Split Triangles along Front: done");

    Log("Split Triangles along Front: %d polyline points (%d at vertices, %d on edges, %d inside faces, %d merged), "
        "%d segments (%d traced%s, %d crossings added); locate tolerance %.3g",
        r.polylinePoints, r.pointsAtVertices, r.pointsOnEdges, r.pointsInFaces, r.mergedPoints, r.polylineSegments,
        r.tracedSegments,
        r.edgePathSegments ? qUtf8Printable(QString(", %1 of them along mesh edges (no plane section joins their ends)")
                                                .arg(r.edgePathSegments))
                           : "",
        r.tracedCrossings, r.tolerance);
    Log("Split Triangles along Front: %d faces crossed, %d faces re-triangulated; %d vertices and %d faces added; "
        "%d front edges selected; %d patches%s; %s; %.3f s%s",
        r.facesCrossed, r.facesSplit, r.verticesAdded, r.facesAdded, r.frontEdges, r.patches,
        r.danglingFrontEdges ? qUtf8Printable(QString(" (%1 front edges inside a patch: open polyline ends)")
                                                  .arg(r.danglingFrontEdges))
                             : "",
        r.facesSplit ? qUtf8Printable(QString("min angle of the new triangles %1 deg").arg(r.minAngleDeg, 0, 'f', 2))
                     : "no new triangles",
        r.seconds, qUtf8Printable(layerNote));
    return true;
}
