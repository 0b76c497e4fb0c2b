// Filter 3: Split Triangles along Front.
#include "filter_qmorph_front.h"

#include "front_edges_layer.h"
#include <vcg_ext/polyline_embedding.h>

typedef vcg_ext::PolylineEmbedding<CMeshO> Embedding;

QString QMorphFrontPlugin::splitInfo()
{
    return "Step 3 of the closed-mesh-to-quads pipeline. Re-triangulates the mesh so that every polyline of the "
           "<b>polyline layer</b> (by default <i>&lt;mesh&gt;_front</i>, made by <i>Smooth Region Boundaries</i>) "
           "becomes a chain of mesh edges, and <b>selects</b> those edges (face-edge selection on both faces of each "
           "edge, as <i>Select Crease Edges</i> does; saved in the PLY face flags with <i>-m ff</i>)."
           "<br><b>Locating</b>: each polyline point is located on the mesh by closest point; farther than the "
           "locate tolerance from the surface is an error. Then, with tol the tolerance: a point whose closest "
           "surface point is within tol of a vertex is that vertex; else within tol of an edge, it lies on that "
           "edge (projected onto it; at the end vertex if the projection is within tol of it); else it lies inside "
           "the face. Points are embedded where they are: no snapping."
           "<br><b>Tracing</b>: a segment whose end points share no face (a user-drawn or loaded polyline) is "
           "traced across the faces between them along the section of the surface by the plane through both "
           "points that contains the average of their normals."
           "<br><b>Splitting</b> (the paper's procedure): one new vertex per crossing point, shared by the two faces "
           "of its edge; each crossed face becomes a looped vertex list (corners and points on its edges) split "
           "along every segment; the remaining polygons are triangulated maximising the smallest angle."
           "<br><b>Relabelling</b>: the front cuts the surface into patches (faces connected without crossing a "
           "selected edge). Each patch gets the region id (face quality) covering most of its area before the "
           "split, or a new id when a larger patch already has it, and its colour; so the region-id boundaries are "
           "exactly the selected edges of a closed front. Earlier selected and faux face-edges are cleared."
           "<br>The mesh must be 2-manifold and consistently oriented (it may have a border); it stays so, with "
           "the same area. An edge-only layer <i>&lt;mesh&gt;_front_edges</i> shows the selected edges, which "
           "MeshLab does not draw otherwise.";
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
                          "The edge-only layer whose polylines become mesh edges: by default the layer "
                          "'<mesh>_front' made by Smooth Region Boundaries. Any polyline whose points lie on the "
                          "surface works (loaded or drawn); segments whose ends share no face are traced across the "
                          "faces between them. In an .mlx script the value is the layer position (the front layer "
                          "made by Smooth Region Boundaries after loading one mesh is 1)."));
    par.addParam(RichFloat("LocateTolerance", float(d.locateTolerancePercent), "Locate tolerance (% of diagonal)",
                           "A polyline point farther than this from the surface (in % of the mesh bounding-box "
                           "diagonal) is an error. Points within this distance of a vertex are that vertex; within it "
                           "of an edge, they lie on the edge. Large enough for points written with 6 decimals (OBJ) on "
                           "meshes about 1 unit in size; raise it for smaller meshes. In (0, 10]."));
    par.addParam(RichBool("FrontEdgesLayer", true, "Front edges layer",
                          "Refresh (or create) the edge-only layer '<mesh>_front_edges' showing the selected front "
                          "edges: MeshLab 2020.09 does not draw selected face-edges. Save it with -o x.obj -l <layer>."));
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
        "%d segments (%d traced, %d crossings added); locate tolerance %.3g",
        r.polylinePoints, r.pointsAtVertices, r.pointsOnEdges, r.pointsInFaces, r.mergedPoints, r.polylineSegments,
        r.tracedSegments, r.tracedCrossings, r.tolerance);
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
