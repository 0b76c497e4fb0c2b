// The texts the MeshLab dialogs show: every filter's info is two or three sentences (what it does,
// reads and writes) and the paper, the long explanations being in the README; every parameter's
// tooltip starts with its unit (or kind) and goes on with its effect.
#include <gtest/gtest.h>

#include <QRegularExpression>

#include "plugin_harness.h"

using namespace qmf_test;

TEST(PluginTexts, FilterInfoIsShortAndCitesThePaper)
{
    PluginHarness h;
    for (QAction *a : h.plugin.actions()) {
        const QString info = h.plugin.filterInfo(h.plugin.ID(a));
        const int see = info.indexOf("<br><br>See: ");
        ASSERT_GT(see, 0) << a->text().toStdString() << ": no paper reference";
        QString text = info.left(see);
        text.remove(QRegularExpression("<[^>]*>"));
        const int sentences = text.count(QRegularExpression("[.;:!?](\\s|$)(?=\\s*[A-Z]|\\s*$)"));
        EXPECT_GE(sentences, 2) << a->text().toStdString() << ": " << text.toStdString();
        EXPECT_LE(sentences, 3) << a->text().toStdString() << ": " << text.toStdString();
        EXPECT_TRUE(info.contains("README")) << "the long explanations are in the README";
    }
}

TEST(PluginTexts, EveryTooltipStatesItsUnitAndEffect)
{
    PluginHarness h;
    h.AddMesh({vcg::Point3f(1, 0, 0), vcg::Point3f(-1, 0, 0), vcg::Point3f(0, 1, 0), vcg::Point3f(0, -1, 0),
               vcg::Point3f(0, 0, 1), vcg::Point3f(0, 0, -1)},
              {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}});
    h.doc.addNewMesh("", "mesh_front", false);
    const QStringList units = {"Number of ", "In degrees", "In % of", "In faces", "A length in the mesh's units",
                               "An integer (no unit)", "On/off.", "A layer (no unit)", "A file path",
                               "A choice (no unit)"};
    int parameters = 0;
    for (QAction *a : h.plugin.actions()) {
        RichParameterList par = h.Defaults(a->text());
        for (RichParameter &p : par) {
            ++parameters;
            const QString tip = p.toolTip();
            bool unit = false;
            for (const QString &u : units) unit = unit || tip.startsWith(u);
            EXPECT_TRUE(unit) << a->text().toStdString() << " / " << p.name().toStdString() << ": " << tip.toStdString();
            EXPECT_GE(tip.size(), 80) << a->text().toStdString() << " / " << p.name().toStdString() << ": the effect";
        }
    }
    EXPECT_EQ(parameters, 7 + 3 + 3 + 10);
}
