// Region ids stored in per-face quality: reading them back (they must be integral) and colouring
// faces by region. Shared by the segmentation, the boundary smoothing, the splitting and Q-Morph.
#ifndef VCG_EXT_COMMON_REGION_IDS_H
#define VCG_EXT_COMMON_REGION_IDS_H

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <vcg/complex/complex.h>

namespace vcg_ext {

template <class MeshType>
class RegionIds
{
public:
    typedef typename MeshType::FaceType FaceType;

    // Reads face quality as integral region ids, per face index (-1 for deleted faces).
    // Returns an empty string, or why the quality cannot be region ids.
    static std::string Read(const MeshType &m, std::vector<int> &faceRegion)
    {
        if (!vcg::tri::HasPerFaceQuality(m)) return "the mesh has no face quality (region ids)";
        faceRegion.assign(m.face.size(), -1);
        int bad = 0;
        for (size_t i = 0; i < m.face.size(); ++i) {
            const FaceType &f = m.face[i];
            if (f.IsD()) continue;
            double q = double(f.cQ());
            double r = std::round(q);
            if (!std::isfinite(q) || std::fabs(q - r) > 1e-3 || r < -1e9 || r > 1e9) { ++bad; continue; }
            faceRegion[i] = int(r);
        }
        if (bad) return std::to_string(bad) + " faces have a face quality that is not an integral region id";
        return "";
    }

    static int CountDistinct(const std::vector<int> &faceRegion, const MeshType &m)
    {
        std::vector<int> ids;
        for (size_t i = 0; i < m.face.size(); ++i)
            if (!m.face[i].IsD()) ids.push_back(faceRegion[i]);
        std::sort(ids.begin(), ids.end());
        return int(std::unique(ids.begin(), ids.end()) - ids.begin());
    }

    // One distinct colour per id (hue scattered over the id range), written to face colour.
    static void ColorFaces(MeshType &m, const std::vector<int> &faceRegion)
    {
        int lo = 0, hi = 0;
        bool first = true;
        for (size_t i = 0; i < m.face.size(); ++i) {
            if (m.face[i].IsD()) continue;
            if (first || faceRegion[i] < lo) lo = faceRegion[i];
            if (first || faceRegion[i] > hi) hi = faceRegion[i];
            first = false;
        }
        const int range = std::max(1, hi - lo + 1);
        for (size_t i = 0; i < m.face.size(); ++i)
            if (!m.face[i].IsD())
                m.face[i].C() = vcg::Color4b::Scatter(range, faceRegion[i] - lo, .75f, .95f);
    }
};

}  // namespace vcg_ext

#endif
