// Geodesic straightening of paths on a triangle mesh (Martinez, Velho, Carvalho, "Computing
// geodesics on triangular meshes", Computers & Graphics 29(5), 2005), as the seed paper uses it to
// smooth region boundaries, with the constraints that keep the result usable for splitting.
//
// A path is a sequence of surface points, each at a mesh vertex or inside a mesh edge, where
// consecutive points share a face (so each segment is straight inside one face). One pass visits
// every movable point p_i once, with its neighbours P = p_(i-1), N = p_(i+1):
//   - P, p_i and N share a face: p_i is redundant and is removed;
//   - p_i inside edge e: the two faces of e are unfolded into one plane and p_i moves to where
//     the segment PN crosses e (clamped to e: at an end it becomes a vertex point);
//   - p_i at vertex v: the fan of v is unfolded by polar angle; the path splits the angle sum
//     into two sides. When one side is below pi the path is shortened on that side: p_i is
//     replaced by the crossings of segment PN with the spokes (edges at v) of that side.
// A move is kept only when it shortens the path (so passes converge to a locally shortest path)
// and keeps every invariant:
//   - a mesh vertex holds at most one path point, except the fixed points (corners) where paths
//     end; two points on one edge stay at least the snap fraction of its length apart;
//   - points never change order along an edge (a move sweeps no other point);
//   - no two segments cross inside a face (in a triangle, two chords with distinct ends cross
//     exactly when their ends interleave along its boundary) or overlap along an edge.
// The region a move sweeps (between the old and the new path) lies in the faces around p_i and
// holds no mesh vertex except on the new path, so with these checks no path can jump over a
// corner or another path: the arrangement of the paths on the surface (which region lies
// between which curves) is kept.
// Snapping: while straightening, new points closer than 0.1% of their edge to an end go to that
// vertex. At the end, edge points closer than the user's snap fraction move onto the vertex (or,
// when that would break an invariant, to the snap distance on their edge), so splitting the mesh
// along the paths later makes no slivers. Snapping at every move instead pins curves at vertices
// and at the snap distance: local minima of the length far from the shortest path.
//
// Files: boundary/surface_path.h (points, paths, their geometry), boundary/straightening_engine.h
// (moves and invariants), boundary/straightening.h (GeodesicStraightening), and
// boundary/boundary_smoothing.h (RegionBoundarySmoothing: the whole of filter 2).
#ifndef VCG_EXT_GEODESIC_STRAIGHTENING_H
#define VCG_EXT_GEODESIC_STRAIGHTENING_H

#include <vcg_ext/boundary/boundary_smoothing.h>
#include <vcg_ext/boundary/straightening.h>

#endif
