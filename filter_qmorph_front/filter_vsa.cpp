// Filter 1: Segment by Variational Shape Approximation.
#include "filter_qmorph_front.h"

#include "face_face_adjacency_scope.h"

#include <vcg_ext/mesh_checks.h>
#include <vcg_ext/common/region_ids.h>
#include <vcg_ext/vsa_segmentation.h>

typedef vcg_ext::VSASegmentation<CMeshO> VSA;

QString QMorphFrontPlugin::vsaInfo()
{
    return "Step 1 of the closed-mesh-to-quads pipeline: partitions the mesh into near-planar, edge-connected regions "
           "by Variational Shape Approximation (L<sup>2,1</sup> metric, Lloyd iterations). Reads the triangle mesh "
           "(vertices merged, faces consistently oriented); writes the region id of each face to the <b>face "
           "quality</b> (0..K-1) and a colour per region. "
           "<br><br>See: <i>D. Cohen-Steiner, P. Alliez, M. Desbrun</i>, <b>\"Variational Shape Approximation\"</b>, "
           "ACM SIGGRAPH 2004, pp. 905-914.";
}

void QMorphFrontPlugin::initVsaParameters(MeshModel &, RichParameterList &par)
{
    VSA::Params d;
    par.addParam(RichEnum("SeedingMode", d.mode,
                          QStringList() << "Split regions above the threshold angle" << "Fixed region count",
                          "Seeding mode",
                          "A choice (no unit) of how the regions are seeded. <i>Split regions above the threshold angle</i> "
                          "(the paper): regions are added until no face deviates from its region's proxy normal by more "
                          "than the threshold angle (or <i>Max regions</i> is reached): flat parts give few regions, "
                          "curved parts many. <i>Fixed region count</i>: exactly <i>Max regions</i> regions, one seed at a "
                          "time in the region of largest L2,1 error."));
    par.addParam(RichInt("InitialSeeds", d.initialSeeds, "Initial seeds",
                         "Number of random seed faces (count, at least 1) the first flooding starts from; every "
                         "connected component also gets one. The paper uses 2; more seeds start with more, smaller "
                         "regions (in threshold mode the angle decides the final count)."));
    par.addParam(RichFloat("ThresholdAngle", float(d.thresholdAngleDeg), "Threshold angle (deg)",
                           "In degrees, in (0, 180): a region with a face whose normal deviates from the region's proxy "
                           "normal by more than this angle gets an extra seed (threshold mode). Smaller: more, flatter "
                           "regions, hence more front curves and smaller patches. The paper: 60 degrees (pi/3). Faces "
                           "with less area than 1e-12 of the squared bounding-box diagonal have no reliable normal and "
                           "are left out."));
    par.addParam(RichInt("MaxRegions", d.maxRegions, "Max regions",
                         "Number of regions (count). Threshold mode: the most seeding may make (it stops there even "
                         "if faces still exceed the angle); 0 is automatic: one region per 4 faces, at least 200, "
                         "so big and rough scans still meet the angle. Fixed mode: exactly this many (at least 1; fewer only on "
                         "a mesh with fewer faces)."));
    par.addParam(RichInt("MaxIterations", d.maxIterations, "Max iterations",
                         "Number of Lloyd iterations (flooding + proxy fitting; at least 1) at most after each "
                         "(re)seeding; they stop earlier when the L2,1 error drops by less than 0.01%. More: lower "
                         "error and smoother region boundaries, longer run."));
    par.addParam(RichInt("RandomSeed", int(d.randomSeed), "Random seed",
                         "An integer (no unit) seeding the random choice of the initial seed faces: the same value "
                         "gives the same regions, another value regions started elsewhere."));
    par.addParam(RichBool("ColorByRegion", true, "Colour faces by region",
                          "On/off. On: each region gets a distinct face colour (shown when the mesh is drawn with face "
                          "colours). The region id always goes to the face quality."));
}

bool QMorphFrontPlugin::applyVsa(MeshDocument &md, const RichParameterList &par, vcg::CallBackPos *cb)
{
    const QString name = filterName(FP_VSA_SEGMENT);
    MeshModel &mm = *md.mm();

    // The enum index is checked before it becomes a SeedingMode (an enum holding a value outside its
    // enumerators is undefined behaviour: UBSan reported it for an index out of range).
    const int mode = par.getEnum("SeedingMode");
    if (mode != VSA::ThresholdSeeding && mode != VSA::FixedRegionCount) return fail(name, "unknown seeding mode");
    VSA::Params p;
    p.mode = VSA::SeedingMode(mode);
    p.initialSeeds = par.getInt("InitialSeeds");
    p.thresholdAngleDeg = par.getFloat("ThresholdAngle");
    p.maxRegions = par.getInt("MaxRegions");
    p.maxIterations = par.getInt("MaxIterations");
    p.randomSeed = uint32_t(par.getInt("RandomSeed"));
    // The core checks the mesh and the parameters first and leaves the mesh as it is on error; it
    // writes the face quality, enabled here and dropped on error, and builds the face-face
    // adjacency it needs itself (only the component is turned on, for the call).
    const int added = MeshModel::MM_FACEQUALITY & ~mm.dataMask();
    mm.updateDataMask(MeshModel::MM_FACEQUALITY);
    VSA::Result r;
    {
        FaceFaceAdjacencyScope adjacency(mm.cm);
        r = VSA::Segment(mm.cm, p, cb);
    }
    if (!r.error.empty()) {
        mm.clearDataMask(added);
        return fail(name, QString::fromStdString(r.error));
    }
    if (par.getBool("ColorByRegion")) {
        mm.updateDataMask(MeshModel::MM_FACECOLOR);
        vcg_ext::RegionIds<CMeshO>::ColorFaces(mm.cm, r.faceRegion);
    }
    // Segmented anyway, but the pipeline's later filters refuse it: say so at the first filter, with the fix.
    if (!r.warning.empty())
        Log(GLLogStream::WARNING, "%s: warning: %s (segmented anyway, but '%s' and '%s' refuse such a mesh)",
            qUtf8Printable(name), r.warning.c_str(), qUtf8Printable(filterName(FP_SPLIT_ALONG_FRONT)),
            qUtf8Printable(filterName(FP_QMORPH)));
    if (p.mode == VSA::FixedRegionCount && r.regions != p.maxRegions)
        Log("VSA: %d regions instead of %d (the mesh has %d faces and %d connected components)", r.regions,
            p.maxRegions, mm.cm.fn, r.components);
    const QString onClusters =
        r.clusters > 0 ? QString(" (seeded first on %1 face clusters, %2 Lloyd iterations on them)").arg(r.clusters).arg(r.clusterIterations)
                       : QString();
    Log("VSA: %d regions on %d faces (%d components), L2,1 error %.6g, max normal deviation %.1f deg, "
        "%d Lloyd iterations in %d seeding rounds%s, %.3f s",
        r.regions, mm.cm.fn, r.components, r.l21Error, r.maxDeviationDeg, r.lloydIterations, r.seedingRounds,
        qUtf8Printable(onClusters), r.seconds);
    if (p.mode == VSA::ThresholdSeeding)
        Log("VSA: region cap %d (%s)%s", r.regionCap, p.maxRegions > 0 ? "Max regions" : "automatic",
            r.regions >= r.regionCap && r.maxDeviationDeg > p.thresholdAngleDeg
                ? ": reached before every face was within the threshold angle; raise Max regions (0: automatic)"
                : "");
    return true;
}
