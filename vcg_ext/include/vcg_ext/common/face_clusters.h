// Near-planar, edge-connected clusters of faces over a face graph: the coarse level on which VSA
// seeds big meshes (vsa_segmentation.h). Each cluster grows breadth-first from its first face (the
// unclustered face of lowest index) through faces whose normal is within a cone around its first
// normal, up to a size; zero normals (zero-area faces) join any cluster. Deterministic, O(F).
#ifndef VCG_EXT_COMMON_FACE_CLUSTERS_H
#define VCG_EXT_COMMON_FACE_CLUSTERS_H

#include <array>
#include <cmath>
#include <vector>

namespace vcg_ext {

struct FaceClusters {
    std::vector<int> clusterOf;        // per face, -1 for faces not in the graph
    std::vector<int> faceStart;        // cluster c holds faces[faceStart[c] .. faceStart[c + 1])
    std::vector<int> faces;            // in the order they joined (first face first)
    std::vector<int> neighbourStart;   // cluster c touches neighbours[neighbourStart[c] .. neighbourStart[c + 1])
    std::vector<int> neighbours;       // edge-adjacent clusters, in the order first met

    int Count() const { return int(faceStart.size()) - 1; }

    // `adj`: per face its edge-adjacent faces (-1: none); `normal`: per face a unit normal or zero;
    // `live`: per face whether it is in the graph. No face of a cluster is more than
    // `coneAngleDeg` from the cluster's first face with a normal, so no two faces of it more than twice that.
    template <class Vec>
    static FaceClusters Grow(const std::vector<std::array<int, 3>> &adj, const std::vector<Vec> &normal,
                             const std::vector<char> &live, int maxFaces, double coneAngleDeg)
    {
        const int n = int(adj.size());
        const double minCos = std::cos(coneAngleDeg * M_PI / 180.0);
        FaceClusters c;
        c.clusterOf.assign(n, -1);
        c.faceStart.push_back(0);
        for (int first = 0; first < n; ++first) {
            if (!live[first] || c.clusterOf[first] >= 0) continue;
            const int id = c.Count();
            const size_t begin = c.faces.size();
            c.clusterOf[first] = id;
            c.faces.push_back(first);
            Vec axis = normal[first];  // the cone's axis: the first non-zero normal of the cluster
            for (size_t next = begin; next < c.faces.size() && int(c.faces.size() - begin) < maxFaces; ++next)
                for (int g : adj[c.faces[next]]) {
                    if (g < 0 || !live[g] || c.clusterOf[g] >= 0 || int(c.faces.size() - begin) >= maxFaces) continue;
                    if (normal[g].SquaredNorm() > 0) {
                        if (axis.SquaredNorm() == 0) axis = normal[g];
                        else if (normal[g] * axis < minCos) continue;
                    }
                    c.clusterOf[g] = id;
                    c.faces.push_back(g);
                }
            c.faceStart.push_back(int(c.faces.size()));
        }
        // cluster adjacency: each cluster's faces scanned once, a neighbour listed at first sight
        std::vector<int> seenBy(c.Count(), -1);
        c.neighbourStart.push_back(0);
        for (int id = 0; id < c.Count(); ++id) {
            seenBy[id] = id;
            for (int i = c.faceStart[id]; i < c.faceStart[id + 1]; ++i)
                for (int g : adj[c.faces[i]]) {
                    if (g < 0 || c.clusterOf[g] < 0 || seenBy[c.clusterOf[g]] == id) continue;
                    seenBy[c.clusterOf[g]] = id;
                    c.neighbours.push_back(c.clusterOf[g]);
                }
            c.neighbourStart.push_back(int(c.neighbours.size()));
        }
        return c;
    }
};

}  // namespace vcg_ext

#endif
