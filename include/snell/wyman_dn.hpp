// Wyman's d_N per vertex: the distance from a vertex through the object along
// its inverted normal -N to the next surface of the mesh (C. Wyman, "An
// Approximate Image-Space Approach for Interactive Refraction", SIGGRAPH 2005;
// Oliveira & Brauwers 2007 sec. 2.1: "pre-computed on a per-vertex basis").
// The host computes it once per mesh; the vertex shader passes it on as a
// varying, and the fragment shader hands the interpolated value to
// snellTwoInterfaceTrace / snellTwoInterfaceRefraction (preset ISR).
//
//   std::vector<float> dN = snell::computeWymanDn(positions, normals, indices);
//
// Rays start at the vertex and run along -normalize(N); the first triangle hit
// with t > epsilon * (mesh bounding-box diagonal) that is not incident to the
// vertex counts (Moller-Trumbore, double precision). A bounding volume
// hierarchy (median split on the longest axis, 4 triangles a leaf) keeps it
// O(V log T). Vertices whose ray hits nothing (open meshes, zero normals)
// get `missValue` (default 0: the technique then uses d_V alone for them).
// GLM only, header-only.
#pragma once

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <exception>
#include <limits>
#include <stdexcept>
#include <thread>
#include <vector>

namespace snell {

namespace wyman_detail {

struct Box {
  glm::dvec3 lo{std::numeric_limits<double>::infinity()};
  glm::dvec3 hi{-std::numeric_limits<double>::infinity()};
  void grow(const glm::dvec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  void grow(const Box& b) {
    lo = glm::min(lo, b.lo);
    hi = glm::max(hi, b.hi);
  }
  // Slab test: does the ray enter the box before tMax?
  bool hit(const glm::dvec3& o, const glm::dvec3& invD, double tMax) const {
    double t0 = 0.0, t1 = tMax;
    for (int k = 0; k < 3; ++k) {
      if (!std::isfinite(invD[k])) {  // ray parallel to the slab (0 * inf would be NaN)
        if (o[k] < lo[k] || o[k] > hi[k]) return false;
        continue;
      }
      double a = (lo[k] - o[k]) * invD[k], b = (hi[k] - o[k]) * invD[k];
      if (a > b) std::swap(a, b);
      t0 = std::max(t0, a);
      t1 = std::min(t1, b);
      if (t0 > t1) return false;
    }
    return true;
  }
};

struct Node {
  Box box;
  int left = -1, right = -1;  // children (inner node)
  int first = 0, count = 0;   // triangle range in the order array (leaf)
};

struct Bvh {
  std::vector<Node> nodes;
  std::vector<int> order;  // triangle indices
};

// The node over order[first, first + count): a leaf's box, or, for an inner
// node, the median split on the longest centroid axis, which reorders that
// range (its box is its children's, set by build(): the same min/max of the
// same triangle boxes, in O(n) instead of O(n log n) over the tree). Returns the
// split (the right child's first index), or -1 for a leaf.
inline int makeNode(Node& n, std::vector<int>& order, const std::vector<Box>& triBoxes,
                    const std::vector<glm::dvec3>& centroids, int first, int count) {
  if (count <= 4) {
    for (int i = first; i < first + count; ++i) n.box.grow(triBoxes[static_cast<std::size_t>(order[static_cast<std::size_t>(i)])]);
    n.first = first;
    n.count = count;
    return -1;
  }
  Box cb;
  for (int i = first; i < first + count; ++i) cb.grow(centroids[static_cast<std::size_t>(order[static_cast<std::size_t>(i)])]);
  const glm::dvec3 ext = cb.hi - cb.lo;
  const int axis = ext.x >= ext.y && ext.x >= ext.z ? 0 : (ext.y >= ext.z ? 1 : 2);
  const int mid = first + count / 2;
  std::nth_element(order.begin() + first, order.begin() + mid, order.begin() + first + count, [&](int a, int b) {
    return centroids[static_cast<std::size_t>(a)][axis] < centroids[static_cast<std::size_t>(b)][axis];
  });
  return mid;
}

// Builds the subtree over order[first, first + count) into `nodes`; returns its
// root's index. The top `parallelDepth` levels build their right half on a
// second thread (its own node array, appended with the child indices moved):
// the ranges are disjoint, so the tree is the one a single thread builds.
inline int build(std::vector<Node>& nodes, std::vector<int>& order, const std::vector<Box>& triBoxes,
                 const std::vector<glm::dvec3>& centroids, int first, int count, int parallelDepth = 0) {
  Node n;
  const int mid = makeNode(n, order, triBoxes, centroids, first, count);
  const int index = static_cast<int>(nodes.size());
  nodes.push_back(n);
  if (mid < 0) return index;
  int l = -1, r = -1;
  if (parallelDepth > 0) {
    std::vector<Node> right;
    std::exception_ptr failure;
    std::thread worker([&] {
      try {
        r = build(right, order, triBoxes, centroids, mid, first + count - mid, parallelDepth - 1);
      } catch (...) {
        failure = std::current_exception();
      }
    });
    try {
      l = build(nodes, order, triBoxes, centroids, first, mid - first, parallelDepth - 1);
    } catch (...) {
      worker.join();
      throw;
    }
    worker.join();
    if (failure) std::rethrow_exception(failure);
    const int offset = static_cast<int>(nodes.size());
    for (Node m : right) {
      if (m.left >= 0) {
        m.left += offset;
        m.right += offset;
      }
      nodes.push_back(m);
    }
    r += offset;
  } else {
    l = build(nodes, order, triBoxes, centroids, first, mid - first);
    r = build(nodes, order, triBoxes, centroids, mid, first + count - mid);
  }
  Node& inner = nodes[static_cast<std::size_t>(index)];
  inner.left = l;
  inner.right = r;
  inner.box = nodes[static_cast<std::size_t>(l)].box;
  inner.box.grow(nodes[static_cast<std::size_t>(r)].box);
  return index;
}

// Moller-Trumbore; t of the hit or -1.
inline double rayTriangle(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& a, const glm::dvec3& b,
                          const glm::dvec3& c) {
  const glm::dvec3 e1 = b - a, e2 = c - a, p = glm::cross(d, e2);
  const double det = glm::dot(e1, p);
  if (std::fabs(det) < 1e-300) return -1.0;
  const double inv = 1.0 / det;
  const glm::dvec3 s = o - a;
  const double u = glm::dot(s, p) * inv;
  if (u < -1e-9 || u > 1.0 + 1e-9) return -1.0;
  const glm::dvec3 q = glm::cross(s, e1);
  const double v = glm::dot(d, q) * inv;
  if (v < -1e-9 || u + v > 1.0 + 1e-9) return -1.0;  // tolerance: rays through a vertex or an edge
  return glm::dot(e2, q) * inv;
}

// The validated mesh and its BVH, built once; bake() casts the d_N rays of a
// vertex range. Split from computeWymanDn so a tool can run disjoint ranges on
// several threads over one BVH (bake() only reads the baker and writes
// out[first..last); benchmarks/threads_bench.cpp does so). buildThreads > 1
// builds the BVH's top levels on that many threads (the same tree, so the same
// d_N bit for bit). Keeps references to the three vectors: they must outlive
// the baker.
class Baker {
 public:
  Baker(const std::vector<glm::vec3>& positions, const std::vector<glm::vec3>& normals,
        const std::vector<std::uint32_t>& indices, double epsilon, int buildThreads = 1)
      : positions_(positions), normals_(normals), indices_(indices) {
    if (positions.size() != normals.size()) throw std::invalid_argument("computeWymanDn: one normal per vertex");
    if (indices.size() % 3 != 0) throw std::invalid_argument("computeWymanDn: indices must form triangles");
    for (std::uint32_t i : indices)
      if (i >= positions.size()) throw std::invalid_argument("computeWymanDn: index out of range");
    const std::size_t triCount = indices.size() / 3;
    if (triCount == 0) return;
    std::vector<Box> boxes(triCount);
    std::vector<glm::dvec3> centroids(triCount);
    Box all;
    for (std::size_t t = 0; t < triCount; ++t) {
      for (int k = 0; k < 3; ++k) boxes[t].grow(glm::dvec3(positions[indices[3 * t + static_cast<std::size_t>(k)]]));
      centroids[t] = 0.5 * (boxes[t].lo + boxes[t].hi);
      all.grow(boxes[t]);
    }
    tMin_ = epsilon * glm::length(all.hi - all.lo);
    bvh_.order.resize(triCount);
    for (std::size_t t = 0; t < triCount; ++t) bvh_.order[t] = static_cast<int>(t);
    int depth = 0;  // levels split over threads: 2^depth >= buildThreads
    while (depth < 16 && (1 << depth) < buildThreads) ++depth;
    build(bvh_.nodes, bvh_.order, boxes, centroids, 0, static_cast<int>(triCount), depth);
  }

  std::size_t vertexCount() const { return positions_.size(); }

  // out[v] for v in [first, last): the d_N of vertex v, or missValue.
  void bake(std::size_t first, std::size_t last, float missValue, float* out) const {
    std::vector<int> stack;
    for (std::size_t v = first; v < last; ++v) {
      out[v] = missValue;
      if (bvh_.nodes.empty()) continue;
      const glm::dvec3 n(normals_[v]);
      const double len = glm::length(n);
      if (!(len > 0.0) || !std::isfinite(len)) continue;
      const glm::dvec3 o(positions_[v]), d = -n / len;
      const glm::dvec3 invD(1.0 / d.x, 1.0 / d.y, 1.0 / d.z);
      double best = std::numeric_limits<double>::infinity();
      stack.assign(1, 0);
      while (!stack.empty()) {
        const Node& node = bvh_.nodes[static_cast<std::size_t>(stack.back())];
        stack.pop_back();
        if (!node.box.hit(o, invD, best)) continue;
        if (node.left < 0) {
          for (int i = node.first; i < node.first + node.count; ++i) {
            const std::size_t t = static_cast<std::size_t>(bvh_.order[static_cast<std::size_t>(i)]);
            const std::uint32_t a = indices_[3 * t], b = indices_[3 * t + 1], c = indices_[3 * t + 2];
            if (a == v || b == v || c == v) continue;  // the vertex's own triangles
            const double th = rayTriangle(o, d, glm::dvec3(positions_[a]), glm::dvec3(positions_[b]),
                                          glm::dvec3(positions_[c]));
            if (th > tMin_ && th < best) best = th;
          }
        } else {
          stack.push_back(node.left);
          stack.push_back(node.right);
        }
      }
      if (std::isfinite(best)) out[v] = static_cast<float>(best);
    }
  }

 private:
  const std::vector<glm::vec3>& positions_;
  const std::vector<glm::vec3>& normals_;
  const std::vector<std::uint32_t>& indices_;
  Bvh bvh_;
  double tMin_ = 0.0;
};

}  // namespace wyman_detail

// positions, normals: one per vertex; indices: triangles (3 per triangle).
inline std::vector<float> computeWymanDn(const std::vector<glm::vec3>& positions, const std::vector<glm::vec3>& normals,
                                         const std::vector<std::uint32_t>& indices, float missValue = 0.0f,
                                         double epsilon = 1e-7) {
  const wyman_detail::Baker baker(positions, normals, indices, epsilon);
  std::vector<float> out(positions.size(), missValue);
  baker.bake(0, out.size(), missValue, out.data());
  return out;
}

}  // namespace snell
