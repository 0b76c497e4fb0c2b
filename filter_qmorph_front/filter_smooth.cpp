// Filter 2: Smooth Region Boundaries.
#include "filter_qmorph_front.h"

#include <vcg_ext/geodesic_straightening.h>
#include <vcg_ext/mesh_checks.h>
#include <vcg_ext/common/region_ids.h>

typedef vcg_ext::RegionBoundarySmoothing<CMeshO> Smoothing;

QString QMorphFrontPlugin::smoothInfo()
{
    return "Step 2 of the closed-mesh-to-quads pipeline: finds the curves between regions and straightens them "
           "geodesically on the surface (corners fixed, no curve crossing another, points on a crease of 45 degrees or "
           "more held there), then moves points near a vertex onto it. Regions thinner than 5% of the mean triangle "
           "side (slivers of a CAD tessellation) join a neighbour first. Reads the region ids from the <b>face quality</b> (integral values, e.g. from <i>Segment by "
           "Variational Shape Approximation</i>) and leaves the mesh unchanged; writes the curves to a new edge-only "
           "layer <b>&lt;mesh&gt;_front</b> (replacing an earlier one), and their length and jaggedness before and "
           "after to the log. "
           "<br><br>See: <i>D. Martinez, L. Velho, P. C. Carvalho</i>, <b>\"Computing geodesics on triangular "
           "meshes\"</b>, Computers &amp; Graphics 29(5), 2005, pp. 667-675.";
}

void QMorphFrontPlugin::initSmoothParameters(MeshDocument &, RichParameterList &par)
{
    Smoothing::Params d;
    par.addParam(RichInt("Iterations", d.iterations, "Iterations",
                         "Number of straightening passes (0 to 1000), each moving every curve point once. The paper "
                         "uses a few, for smooth rather than straight curves; more passes approach locally shortest "
                         "curves (they stop early once nothing moves); 0 outputs the raw, jaggy boundary (chains of "
                         "mesh edges)."));
    par.addParam(RichFloat("SnapDistance", float(d.snapPercent), "Snap distance (% of edge length)",
                           "In % of the length of the edge the point lies on (0 to 45): a curve point closer than "
                           "this to one of the edge's vertices moves onto it, so splitting along the curves later makes "
                           "no sliver triangles. Larger: fewer slivers along the front (better quads next to it), "
                           "curves a little less straight; 0: no snapping."));
    par.addParam(RichInt("MinRegionFaces", d.minRegionFaces, "Minimum region size (faces)",
                         "In faces (count): a region with fewer faces is merged into the neighbour it shares the "
                         "longest boundary with before the curves are built, so tiny regions make no curves (the face "
                         "quality itself is not changed). 0 keeps every region."));
}

bool QMorphFrontPlugin::applySmooth(MeshDocument &md, const RichParameterList &par, vcg::CallBackPos *cb)
{
    const QString name = filterName(FP_SMOOTH_BOUNDARIES);
    MeshModel &mm = *md.mm();

    Smoothing::Params p;
    p.iterations = par.getInt("Iterations");
    p.snapPercent = par.getFloat("SnapDistance");
    p.minRegionFaces = par.getInt("MinRegionFaces");
    // A problem of the mesh or the parameters is named before one of the region ids. Smooth checks
    // them itself (the core must be safe on its own), so they are checked here only when the region
    // ids fail: a whole-mesh inspection less on the way through (0.6 s at 3.3M faces).
    auto regionIdsProblem = [&](const std::string &why) {
        const std::string bad = Smoothing::Check(mm.cm, p);
        return fail(name, QString::fromStdString(bad.empty() ? why : bad));
    };
    if (!mm.hasDataMask(MeshModel::MM_FACEQUALITY))
        return regionIdsProblem("the mesh has no face quality (region ids): run 'Segment by Variational Shape "
                                "Approximation' first, or store integral region ids in the face quality");
    std::vector<int> faceRegion;
    const std::string badIds = vcg_ext::RegionIds<CMeshO>::Read(mm.cm, faceRegion);
    if (!badIds.empty()) return regionIdsProblem(badIds);

    // The mesh is only read: nothing to enable, nothing to undo on failure.
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

    if (r.thinRegions)
        Log("Smooth Region Boundaries: %d regions thinner than %.0f%% of the mean triangle side merged into a neighbour",
            r.thinRegions, 100 * Smoothing::kThinRegionWidth);
    if (r.heldCreasePoints)
        Log("Smooth Region Boundaries: %d boundary points held on creases (both edges at least %.0f degrees sharp)",
            r.heldCreasePoints, Smoothing::kHeldCreaseDeg);
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
