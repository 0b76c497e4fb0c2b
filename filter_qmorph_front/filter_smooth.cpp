// Filter 2: Smooth Region Boundaries.
#include "filter_qmorph_front.h"

#include <vcg_ext/geodesic_straightening.h>
#include <vcg_ext/mesh_checks.h>
#include <vcg_ext/common/region_ids.h>

typedef vcg_ext::RegionBoundarySmoothing<CMeshO> Smoothing;

QString QMorphFrontPlugin::smoothInfo()
{
    return "Step 2 of the closed-mesh-to-quads pipeline. Reads region ids from the <b>face quality</b> (integral "
           "values, e.g. from <i>Segment by Variational Shape Approximation</i>), finds the boundary curves between "
           "regions and straightens them geodesically. The mesh itself is not modified: the curves go to a new "
           "edge-only layer <b>&lt;mesh&gt;_front</b> (replacing an earlier one; the mesh stays the current layer)."
           "<br><br><b>Curves</b>: chains of edges between faces of different regions, from corner to corner. "
           "<i>Corners</i> (vertices where three or more regions meet, where the boundary branches or a region "
           "touches itself, or on the mesh border) never move; a closed loop is pinned at three points a third of "
           "its length apart so it cannot shrink away."
           "<br><b>Straightening</b> (Martinez, Velho, Carvalho 2005): every curve point lies on a mesh vertex or "
           "inside a mesh edge. Each pass moves an edge point to where the straight line between its neighbours "
           "crosses the edge (its two faces unfolded), replaces a vertex point by the crossings with the edges "
           "around the vertex when one side of the curve has an angle sum below 180 degrees, and removes points "
           "whose neighbours share a face. A move is made only if it shortens the curve and no curve crosses another "
           "or itself, passes over a corner or changes the order of points along an edge, so the arrangement of the "
           "regions is kept. After the passes, points closer to a vertex than the snap distance snap to it (or, "
           "when the vertex is taken, stay at the snap distance)."
           "<br><b>Output</b>: one layer vertex per distinct point (a corner shared by curves is one vertex), one "
           "edge per pair of consecutive points (they always share a face of the mesh); loops are closed. Save it "
           "with <i>meshlabserver -o front.obj -l 1</i> (OBJ line elements). OBJ keeps 6 decimals: a reader should "
           "locate each point on its mesh edge by closest point within a small tolerance and project it onto that "
           "edge, as <i>Split Triangles along Front</i> does."
           "<br><b>Log</b>: curves, closed loops, corners, total length and jaggedness before and after. "
           "Jaggedness = the sum over curve points of the absolute geodesic turning angle (in the unfolded faces; at a "
           "vertex half the difference of the angle sums on the two sides) divided by the total length, in radians "
           "per unit length: a staircase of mesh edges scores high, a straight curve 0."
           "<br><br>See: <i>D. Martinez, L. Velho, P. C. Carvalho</i>, <b>\"Computing geodesics on triangular "
           "meshes\"</b>, Computers &amp; Graphics 29(5), 2005, pp. 667-675.";
}

void QMorphFrontPlugin::initSmoothParameters(MeshDocument &, RichParameterList &par)
{
    Smoothing::Params d;
    par.addParam(RichInt("Iterations", d.iterations, "Iterations",
                         "Straightening passes; each moves every curve point once (the paper: a few, for smooth "
                         "rather than straight curves). More passes converge to locally shortest curves and stop "
                         "early once nothing moves. 0 outputs the raw boundary (chains of mesh edges). 0 to 1000."));
    par.addParam(RichFloat("SnapDistance", float(d.snapPercent), "Snap distance (% of edge length)",
                           "A curve point inside an edge that is closer to one of the edge's vertices than this "
                           "percentage of the edge length is moved onto that vertex, so splitting the mesh along the "
                           "curves later makes no sliver triangles. Points of different curves on one edge also keep "
                           "this distance. 0 to 45; the default 25% keeps every new vertex at least a quarter of an edge "
                           "from the old ones (fewer slivers along the front: better quads next to it in Q-Morph)."));
    par.addParam(RichInt("MinRegionFaces", d.minRegionFaces, "Minimum region size (faces)",
                         "Regions with fewer faces are merged into the neighbouring region they share the longest "
                         "boundary with before the curves are built, so tiny regions make no curves (the face quality "
                         "is not changed). 0 keeps every region."));
}

bool QMorphFrontPlugin::applySmooth(MeshDocument &md, const RichParameterList &par, vcg::CallBackPos *cb)
{
    const QString name = filterName(FP_SMOOTH_BOUNDARIES);
    MeshModel &mm = *md.mm();

    Smoothing::Params p;
    p.iterations = par.getInt("Iterations");
    p.snapPercent = par.getFloat("SnapDistance");
    p.minRegionFaces = par.getInt("MinRegionFaces");
    std::string bad = Smoothing::Check(mm.cm, p);
    if (!bad.empty()) return fail(name, QString::fromStdString(bad));
    if (!mm.hasDataMask(MeshModel::MM_FACEQUALITY))
        return fail(name, "the mesh has no face quality (region ids): run 'Segment by Variational Shape Approximation' "
                          "first, or store integral region ids in the face quality");
    std::vector<int> faceRegion;
    bad = vcg_ext::RegionIds<CMeshO>::Read(mm.cm, faceRegion);
    if (!bad.empty()) return fail(name, QString::fromStdString(bad));

    // The mesh is only read: nothing to enable, nothing to undo on failure. (Smooth runs the same
    // cheap check again: the core must be safe on its own.)
    Smoothing::Result r = Smoothing::Smooth(mm.cm, faceRegion, p, cb);
    if (!r.error.empty()) return fail(name, QString::fromStdString(r.error));

    const QString label = mm.label() + "_front";
    bool replaced = false;
    for (MeshModel *old : md.meshList)  // an earlier front of this mesh (getMesh() matches file names, not labels)
        if (old != &mm && old->label() == label && old->cm.fn == 0) {
            replaced = md.delMesh(old);
            break;
        }
    MeshModel *front = md.addNewMesh("", label, false);
    Smoothing::Polylines lines = Smoothing::ToPolylines(r.topology, r.curves);
    Smoothing::BuildEdgeMesh(lines, front->cm);
    front->UpdateBoxAndNormals();
    if (cb) cb(100, "Smooth Region Boundaries: done");

    if (r.mergedRegions)
        Log("Smooth Region Boundaries: %d regions smaller than %d faces merged into a neighbour", r.mergedRegions,
            p.minRegionFaces);
    const double change = r.lengthBefore > 0 ? 100.0 * (r.lengthAfter - r.lengthBefore) / r.lengthBefore : 0.0;
    Log("Smooth Region Boundaries: %d curves (%d closed loops), %d corners, %d boundary edges between %d regions; "
        "total length %.6g -> %.6g (%+.1f%%); jaggedness %.4g -> %.4g rad per unit length; points %d -> %d; "
        "%d passes%s, %d moves (%d refused by the no-crossing constraints); %.3f s",
        int(r.curves.size()), r.closedLoops, int(r.corners.size()), r.boundaryEdges, r.regions, r.lengthBefore,
        r.lengthAfter, change, r.jaggednessBefore, r.jaggednessAfter, r.pointsBefore, r.pointsAfter, r.passes,
        r.converged ? " (converged)" : "", r.moves, r.rejectedMoves, r.seconds);
    if (p.iterations > 0)
        Log("Smooth Region Boundaries: snapping: %d points moved onto a vertex, %d kept at the snap distance%s", r.snapped,
            r.held, r.unsnapped ? qUtf8Printable(QString(", %1 left nearer (no valid place)").arg(r.unsnapped)) : "");
    Log("Smooth Region Boundaries: %s layer '%s': %d vertices, %d edges", replaced ? "replaced the" : "new",
        qUtf8Printable(front->label()), front->cm.vn, front->cm.en);
    return true;
}
