// The bad-input matrix in-process (tests/support/bad_input_cases.h): every row and filter on a
// MeshDocument. Refused: false, the message (naming the problem, and the MeshLab filter that fixes
// it) in errorMessage and the log, and the document exactly as it was (every layer, the current
// one); run: true. One test per row, so the CTest log shows the matrix.
#include <gtest/gtest.h>

#include "bad_input_cases.h"
#include "document_digest.h"
#include "plugin_harness.h"

using namespace qmf_test;
using namespace qmf_test::bad_input;

namespace {

// The row's mesh (current layer), with its region ids, selection and (for the splitting) front layer.
void Load(PluginHarness &h, const Input &in, int filter)
{
    std::vector<vcg::Point3f> v;
    for (auto &p : in.v) v.push_back(vcg::Point3f(p[0], p[1], p[2]));
    MeshModel *mm = h.AddMesh(v, in.f);
    if (in.hasLabels && !in.f.empty()) {
        mm->updateDataMask(MeshModel::MM_FACEQUALITY);
        for (size_t i = 0; i < in.f.size(); ++i) mm->cm.face[i].Q() = float(in.label[i]);
    }
    if (in.hasSelection)
        for (size_t i = 0; i < in.f.size(); ++i)
            for (int k = 0; k < 3; ++k)
                if (in.creaseSel[3 * i + k]) mm->cm.face[i].SetFaceEdgeS(k);
    if (filter == FilterSplit && in.hasFrontLayer) {
        MeshModel *front = h.doc.addNewMesh("", "mesh_front", false);
        for (const auto &loop : in.fronts) {
            const int base = front->cm.vn;
            vcg::tri::Allocator<CMeshO>::AddVertices(front->cm, loop.size());
            for (size_t i = 0; i < loop.size(); ++i) front->cm.vert[base + i].P() = vcg::Point3f(loop[i][0], loop[i][1], loop[i][2]);
            for (size_t i = 0; i < loop.size(); ++i)
                vcg::tri::Allocator<CMeshO>::AddEdge(front->cm, &front->cm.vert[base + i], &front->cm.vert[base + (i + 1) % loop.size()]);
        }
        front->UpdateBoxAndNormals();
    }
    h.doc.setCurrentMesh(mm->id());
}

std::string DocumentDigest(PluginHarness &h)
{
    Digest d;
    AddDocument(d, h.doc);
    return d.Hex();
}

void RunRow(const Case &c)
{
    for (int filter = 0; filter < FilterCount; ++filter) {
        SCOPED_TRACE(c.name + " / " + FilterName(filter));
        PluginHarness h;
        Load(h, c.make(), filter);
        const QString name = FilterName(filter);
        RichParameterList par = h.Defaults(name);
        const BadParam &bad = c.param[filter];
        if (!bad.name.empty()) {
            if (bad.type == "RichInt") par.setValue(QString::fromStdString(bad.name), IntValue(std::stoi(bad.value)));
            else par.setValue(QString::fromStdString(bad.name), FloatValue(std::stof(bad.value)));
        }
        const Outcome &o = c.outcome[filter];
        if (o.Runs()) {
            const FilterRun r = h.Apply(name, par);
            EXPECT_TRUE(r.ok) << r.error;
            continue;
        }
        const std::string before = DocumentDigest(h);
        ExpectRefused(h, name, par, o.refusal);  // message, log, current mesh unchanged, layer count
        EXPECT_EQ(DocumentDigest(h), before) << "a layer of the document changed";
        if (!o.fix.empty()) {
            EXPECT_NE(h.plugin.errorMsg().toStdString().find("'" + o.fix + "'"), std::string::npos)
                << "the message must name the MeshLab filter that fixes it: " << h.plugin.errorMsg().toStdString();
        }
    }
}

}  // namespace

class BadInputMatrix : public ::testing::TestWithParam<Case> {};

TEST_P(BadInputMatrix, EveryFilterRefusesOrRuns) { RunRow(GetParam()); }

INSTANTIATE_TEST_SUITE_P(Plugin, BadInputMatrix, ::testing::ValuesIn(Cases()),
                         [](const ::testing::TestParamInfo<Case> &i) { return i.param.name; });
