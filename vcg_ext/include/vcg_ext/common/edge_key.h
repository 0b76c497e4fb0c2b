// Two vertex indices as one sortable, hashable value: the one way every module names an edge.
#ifndef VCG_EXT_COMMON_EDGE_KEY_H
#define VCG_EXT_COMMON_EDGE_KEY_H

#include <cstdint>
#include <utility>

namespace vcg_ext {

typedef std::pair<int, int> VertexPair;  // an undirected edge: first < second

// A directed pair (a, b) as a key: (a, b) and (b, a) differ.
inline uint64_t DirectedKey(int a, int b) { return (uint64_t(uint32_t(a)) << 32) | uint32_t(b); }

// An undirected edge, the smaller index first.
inline VertexPair UndirectedPair(int a, int b) { return a < b ? VertexPair(a, b) : VertexPair(b, a); }
inline uint64_t EdgeKey(int a, int b) { return a < b ? DirectedKey(a, b) : DirectedKey(b, a); }
inline uint64_t EdgeKey(const VertexPair &e) { return EdgeKey(e.first, e.second); }

}  // namespace vcg_ext

#endif
