// MeshLab 2020.09 filter plugin: closed triangle mesh -> feature-aligned quad-dominant mesh.
// A thin adapter over the vcg_ext core: parameters, preconditions, progress, log and errors.
// Each filter lives in its own file (filter_<step>.cpp) with its info text, its parameters and
// its apply function; this class only dispatches.
#ifndef FILTER_QMORPH_FRONT_H
#define FILTER_QMORPH_FRONT_H

#include <common/interfaces.h>

class QMorphFrontPlugin : public QObject, public MeshFilterInterface
{
    Q_OBJECT
    MESHLAB_PLUGIN_IID_EXPORTER(MESH_FILTER_INTERFACE_IID)
    Q_INTERFACES(MeshFilterInterface)

public:
    enum {
        FP_VSA_SEGMENT,         // 1. Segment by Variational Shape Approximation   (filter_vsa.cpp)
        FP_SMOOTH_BOUNDARIES,   // 2. Smooth Region Boundaries                     (filter_smooth.cpp)
        FP_SPLIT_ALONG_FRONT,   // 3. Split Triangles along Front                  (filter_split.cpp)
        FP_QMORPH,              // 4. Q-Morph Quad Conversion                      (filter_qmorph.cpp)
    };

    QMorphFrontPlugin();

    QString pluginName() const override { return "FilterQMorphFront"; }
    QString filterName(FilterIDType filter) const override;
    QString filterInfo(FilterIDType filter) const override;
    FilterClass getClass(QAction *a) override;
    FILTER_ARITY filterArity(QAction *a) const override;
    int getPreConditions(QAction *a) const override;
    int postCondition(QAction *a) const override;
    void initParameterSet(QAction *a, MeshModel &m, RichParameterList &par) override;
    void initParameterSet(QAction *a, MeshDocument &md, RichParameterList &par) override;
    bool applyFilter(QAction *a, MeshDocument &md, const RichParameterList &par, vcg::CallBackPos *cb) override;

private:
    // Sets errorMessage and writes the same text to the log (meshlabserver prints only the log).
    bool fail(const QString &filter, const QString &why);

    static QString vsaInfo();
    void initVsaParameters(MeshModel &m, RichParameterList &par);
    bool applyVsa(MeshDocument &md, const RichParameterList &par, vcg::CallBackPos *cb);

    static QString smoothInfo();
    void initSmoothParameters(MeshDocument &md, RichParameterList &par);
    bool applySmooth(MeshDocument &md, const RichParameterList &par, vcg::CallBackPos *cb);

    static QString splitInfo();
    void initSplitParameters(MeshDocument &md, RichParameterList &par);
    bool applySplit(MeshDocument &md, const RichParameterList &par, vcg::CallBackPos *cb);

    static QString qmorphInfo();
    void initQMorphParameters(MeshDocument &md, RichParameterList &par);
    bool applyQMorph(MeshDocument &md, const RichParameterList &par, vcg::CallBackPos *cb);
};

#endif
