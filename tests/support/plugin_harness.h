// Runs the plugin's filters in-process on a MeshDocument (as MeshLab does, without a GUI), so the
// tests can check the contract on bad input: false, a clear errorMessage, the same text in the
// log, and the mesh left exactly as it was (snapshots compared field by field).
#ifndef QMF_TESTS_PLUGIN_HARNESS_H
#define QMF_TESTS_PLUGIN_HARNESS_H

#include <array>

#include <gtest/gtest.h>
#include <string>
#include <vector>

#include <common/GLLogStream.h>
#include <common/meshmodel.h>
#include <common/ml_shared_data_context.h>
#include <filter_qmorph_front.h>
#include <vcg/complex/algorithms/create/platonic.h>
#include <wrap/gl/glu_tesselator.h>  // import_off.h tessellates with GLU when GL is included
#include <wrap/io_trimesh/import_off.h>

#include "mesh_snapshot.h"
#include "test_mesh.h"

namespace qmf_test {

// The filters' names: the scripting API (.mlx files refer to them).
const QString kVsa = "Segment by Variational Shape Approximation";
const QString kSmooth = "Smooth Region Boundaries";
const QString kSplit = "Split Triangles along Front";
const QString kQMorph = "Q-Morph Quad Conversion";

// Everything a filter could change on a layer, in comparable form: the data mask and the mesh
// (face quality and colour when the mask holds them).
struct MeshSnapshot {
    int dataMask = 0;
    Snapshot mesh;

    static MeshSnapshot Of(MeshModel &mm)
    {
        MeshSnapshot s;
        s.dataMask = mm.dataMask();
        s.mesh = Snapshot::Of(mm.cm, mm.hasDataMask(MeshModel::MM_FACEQUALITY), mm.hasDataMask(MeshModel::MM_FACECOLOR));
        return s;
    }
    bool operator==(const MeshSnapshot &o) const { return dataMask == o.dataMask && mesh == o.mesh; }
};

struct FilterRun {
    bool ok = false;
    std::string error;               // errorMessage
    std::vector<std::string> log;    // every log line the run wrote
    bool Logged(const std::string &text) const
    {
        for (auto &l : log)
            if (l.find(text) != std::string::npos) return true;
        return false;
    }
};

class PluginHarness
{
public:
    QMorphFrontPlugin plugin;
    GLLogStream log;
    MeshDocument doc;

    PluginHarness() { plugin.setLog(&log); }

    MeshModel *AddMesh(const std::vector<vcg::Point3f> &v, const std::vector<std::array<int, 3>> &f,
                       const QString &name = "mesh")
    {
        MeshModel *mm = doc.addNewMesh("", name, true);
        std::vector<vcg::Point3i> fi;
        for (auto &t : f) fi.push_back(vcg::Point3i(t[0], t[1], t[2]));
        vcg::tri::BuildMeshFromCoordVectorIndexVector(mm->cm, v, fi);
        mm->UpdateBoxAndNormals();
        return mm;
    }

    // A layer copied from any vcg triangle mesh (e.g. the unit tests' generated meshes).
    template <class SourceMesh>
    MeshModel *AddCopyOf(const SourceMesh &t, const QString &name = "mesh")
    {
        std::vector<vcg::Point3f> v;
        std::vector<std::array<int, 3>> f;
        for (auto &x : t.vert) v.push_back(vcg::Point3f::Construct(x.cP()));
        for (auto &x : t.face)
            f.push_back({int(vcg::tri::Index(t, x.cV(0))), int(vcg::tri::Index(t, x.cV(1))), int(vcg::tri::Index(t, x.cV(2)))});
        return AddMesh(v, f, name);
    }

    MeshModel *LoadOff(const std::string &path, const QString &name = "mesh")
    {
        MeshModel *mm = doc.addNewMesh(QString::fromStdString(path), name, true);
        int mask = 0;
        if (vcg::tri::io::ImporterOFF<CMeshO>::Open(mm->cm, path.c_str(), mask) != 0) return nullptr;
        mm->UpdateBoxAndNormals();
        return mm;
    }

    QAction *Action(const QString &filterName)
    {
        for (QAction *a : plugin.actions())
            if (a->text() == filterName) return a;
        return nullptr;
    }

    // Default parameters of a filter for the current mesh.
    RichParameterList Defaults(const QString &filterName)
    {
        RichParameterList par;
        plugin.initParameterSet(Action(filterName), doc, par);
        return par;
    }

    vcg::CallBackPos *callback = nullptr;  // MeshLab's progress callback, passed to applyFilter

    FilterRun Apply(const QString &filterName, const RichParameterList &par)
    {
        FilterRun r;
        int before = log.logStringList().size();
        r.ok = plugin.applyFilter(Action(filterName), doc, par, callback);
        r.error = plugin.errorMsg().toStdString();
        const auto &lines = log.logStringList();
        for (int i = before; i < lines.size(); ++i) r.log.push_back(lines[i].second.toStdString());
        return r;
    }
    FilterRun Apply(const QString &filterName) { return Apply(filterName, Defaults(filterName)); }
};

// Bad input: false, the message in errorMessage (prefixed by the filter name) and in the log,
// mesh and document unchanged.
inline void ExpectRefused(PluginHarness &h, const QString &filter, const RichParameterList &par, const std::string &expected)
{
    MeshSnapshot before = MeshSnapshot::Of(*h.doc.mm());
    const int layers = h.doc.size();
    FilterRun r = h.Apply(filter, par);
    EXPECT_FALSE(r.ok);
    EXPECT_NE(r.error.find(expected), std::string::npos) << r.error;
    EXPECT_EQ(r.error.rfind(filter.toStdString() + ": ", 0), 0u) << r.error;
    EXPECT_TRUE(r.Logged(r.error)) << "the error must also be in the log (meshlabserver prints only the log)";
    EXPECT_TRUE(MeshSnapshot::Of(*h.doc.mm()) == before) << "the mesh changed";
    EXPECT_EQ(h.doc.size(), layers) << "a layer was added or removed";
}

// A cube (4 cells per side edge, jittered) with its 12 edges selected on both faces, as MeshLab's
// 'Select Crease Edges' leaves it: an initial front for Q-Morph alone.
inline MeshModel *AddCubeWithCreasesSelected(PluginHarness &h)
{
    TMesh t;
    MakeCube(t, 4, 0.3f, 2);
    MeshModel *mm = h.AddCopyOf(t);
    mm->updateDataMask(MeshModel::MM_FACEFACETOPO);
    vcg::tri::UpdateTopology<CMeshO>::FaceFace(mm->cm);
    vcg::tri::UpdateNormal<CMeshO>::PerFaceNormalized(mm->cm);
    for (auto &f : mm->cm.face)
        for (int k = 0; k < 3; ++k)
            if (vcg::Angle(f.N(), f.FFp(k)->N()) > M_PI / 4) f.SetFaceEdgeS(k);
    return mm;
}

// What MeshLab 2020.09's GUI draws on the solid mesh after a filter (its
// MainWindow::updateSharedContextDataAfterFilterExecution, in src/meshlab): the attributes to
// refresh are the data-mask bits that changed plus the filter's postCondition, merged into what the
// layer drew by libmeshlab-common's MLPoliciesStandAloneFunctions, the functions the GUI calls.
inline MLRenderingData::RendAtts SolidAttributesAfter(PluginHarness &h, const QString &filter, const MLRenderingData::RendAtts &before)
{
    MeshModel *mm = h.doc.mm();
    const int maskBefore = mm->dataMask();
    FilterRun r = h.Apply(filter);
    EXPECT_TRUE(r.ok) << r.error;
    const int updated = (maskBefore ^ mm->dataMask()) | h.plugin.postCondition(h.Action(filter));
    MLRenderingData::RendAtts changed, after;
    MLPoliciesStandAloneFunctions::fromMeshModelMaskToMLRenderingAtts(updated, changed);
    MLPoliciesStandAloneFunctions::updatedRendAttsAccordingToPriorities(MLRenderingData::PR_SOLID, changed, before, after);
    MLPoliciesStandAloneFunctions::filterUselessUdpateAccordingToMeshMask(mm, after);
    return after;
}

// Applies `filter` to a layer drawn with flat (face normals) or smooth (vertex normals) shading and
// checks the GUI keeps that shading; returns the attributes it would draw, for further checks.
inline MLRenderingData::RendAtts ExpectShadingKept(PluginHarness &h, const QString &filter, bool flat)
{
    typedef MLRenderingData::ATT_NAMES A;
    MLRenderingData::RendAtts shading;
    shading[A::ATT_VERTPOSITION] = true;
    shading[flat ? A::ATT_FACENORMAL : A::ATT_VERTNORMAL] = true;
    const MLRenderingData::RendAtts after = SolidAttributesAfter(h, filter, shading);
    EXPECT_EQ(after[A::ATT_FACENORMAL], flat) << (flat ? "flat" : "smooth") << " shading";
    EXPECT_EQ(after[A::ATT_VERTNORMAL], !flat) << (flat ? "flat" : "smooth") << " shading";
    return after;
}

}  // namespace qmf_test

#endif
