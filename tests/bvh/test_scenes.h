// Meshes, scenes and rays for the BVH tests and bench/bvh.cpp (header-only so
// the benchmark can include it too). Everything is seeded: same input every run.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <map>
#include <tuple>
#include <utility>
#include <vector>

#include "engine/bvh/scene_bvh.h"

namespace qlight::bvh::testing {

// splitmix64: tiny, fast, the same on every platform (unlike std::*_distribution).
class Random {
 public:
  explicit Random(uint64_t seed) : state_(seed) {}
  uint64_t next() {
    uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  float uniform() { return static_cast<float>(next() >> 40) * 0x1.0p-24f; }  // [0, 1)
  float uniform(float lo, float hi) { return lo + (hi - lo) * uniform(); }
  glm::vec3 inBox(const glm::vec3& lo, const glm::vec3& hi) {
    return glm::vec3(uniform(lo.x, hi.x), uniform(lo.y, hi.y), uniform(lo.z, hi.z));
  }
  glm::vec3 direction() {  // uniform on the sphere
    float z = uniform(-1.0f, 1.0f);
    float phi = uniform(0.0f, 6.28318530718f);
    float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    return glm::vec3(r * std::cos(phi), r * std::sin(phi), z);
  }

 private:
  uint64_t state_;
};

struct Mesh {
  std::vector<glm::vec3> positions;
  std::vector<uint32_t> indices;
  uint32_t triangleCount() const { return static_cast<uint32_t>(indices.size() / 3); }
};

struct Ray {
  glm::vec3 origin;
  glm::vec3 dir;
};

struct Scene {
  std::vector<Mesh> meshes;
  std::vector<Instance> instances;
};

inline void addTriangle(Mesh& m, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  uint32_t base = static_cast<uint32_t>(m.positions.size());
  m.positions.insert(m.positions.end(), {a, b, c});
  m.indices.insert(m.indices.end(), {base, base + 1, base + 2});
}

// Quad a-b-c-d (in order around its boundary) as two triangles sharing a-c.
inline void addQuad(Mesh& m, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
                    const glm::vec3& d) {
  uint32_t base = static_cast<uint32_t>(m.positions.size());
  m.positions.insert(m.positions.end(), {a, b, c, d});
  m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
}

// Axis-aligned quad in the plane `axis` = at, spanning [lo, hi] in the other two axes.
inline void addAxisQuad(Mesh& m, int axis, float at, glm::vec2 lo, glm::vec2 hi) {
  auto p = [&](float u, float v) {
    glm::vec3 q;
    q[axis] = at;
    q[(axis + 1) % 3] = u;
    q[(axis + 2) % 3] = v;
    return q;
  };
  addQuad(m, p(lo.x, lo.y), p(hi.x, lo.y), p(hi.x, hi.y), p(lo.x, hi.y));
}

// count triangles with centres uniform in [0, extent]^3 and random sizes.
inline Mesh randomSoup(uint32_t count, uint64_t seed, float extent = 10.0f, float minSize = 0.05f,
                       float maxSize = 1.0f) {
  Random rng(seed);
  Mesh m;
  for (uint32_t i = 0; i < count; ++i) {
    glm::vec3 c = rng.inBox(glm::vec3(0.0f), glm::vec3(extent));
    float size = rng.uniform(minSize, maxSize);
    addTriangle(m, c + size * rng.direction(), c + size * rng.direction(),
                c + size * rng.direction());
  }
  return m;
}

// Zero-area triangles of every kind: repeated vertices, collinear vertices.
inline void addDegenerateTriangles(Mesh& m, uint32_t count, uint64_t seed, float extent = 10.0f) {
  Random rng(seed);
  for (uint32_t i = 0; i < count; ++i) {
    glm::vec3 a = rng.inBox(glm::vec3(0.0f), glm::vec3(extent));
    glm::vec3 b = rng.inBox(glm::vec3(0.0f), glm::vec3(extent));
    switch (i % 4) {
      case 0:
        addTriangle(m, a, a, a);
        break;
      case 1:
        addTriangle(m, a, b, a);
        break;
      case 2:
        addTriangle(m, a, a + glm::vec3(1, 0, 0), a + glm::vec3(3, 0, 0));
        break;
      default:
        addTriangle(m, a, a + glm::vec3(0, 0.5f, 0), a + glm::vec3(0, 2, 0));
        break;
    }
  }
}

// Icosphere of radius 1: each subdivision splits every triangle into four,
// with shared midpoints (an index buffer with no duplicate vertices).
inline Mesh icosphere(int subdivisions) {
  const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
  Mesh m;
  m.positions = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                 {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  for (glm::vec3& p : m.positions) p = glm::normalize(p);
  m.indices = {0, 11, 5,  0, 5,  1, 0, 1, 7, 0, 7,  10, 0, 10, 11, 1, 5, 9, 5, 11,
               4, 11, 10, 2, 10, 7, 6, 7, 1, 8, 3,  9,  4, 3,  4,  2, 3, 2, 6, 3,
               6, 8,  3,  8, 9,  4, 9, 5, 2, 4, 11, 6,  2, 10, 8,  6, 7, 9, 8, 1};
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoints;
    auto midpoint = [&](uint32_t a, uint32_t b) {
      auto key = std::minmax(a, b);
      auto it = midpoints.find(key);
      if (it != midpoints.end()) return it->second;
      uint32_t index = static_cast<uint32_t>(m.positions.size());
      m.positions.push_back(glm::normalize(m.positions[a] + m.positions[b]));
      midpoints.emplace(key, index);
      return index;
    };
    std::vector<uint32_t> next;
    for (size_t i = 0; i < m.indices.size(); i += 3) {
      uint32_t a = m.indices[i], b = m.indices[i + 1], c = m.indices[i + 2];
      uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      next.insert(next.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
    }
    m.indices = std::move(next);
  }
  return m;
}

// Cube [-1,1]^3, each face an n x n grid of quads; vertices on the cube's
// edges and corners are shared between faces (one index buffer, no seams).
inline Mesh gridCube(int n) {
  Mesh m;
  std::map<std::tuple<int, int, int>, uint32_t> ids;  // integer lattice coords -> index
  auto vertex = [&](glm::ivec3 q) {
    auto key = std::make_tuple(q.x, q.y, q.z);
    auto it = ids.find(key);
    if (it != ids.end()) return it->second;
    uint32_t index = static_cast<uint32_t>(m.positions.size());
    m.positions.push_back(glm::vec3(q) * (2.0f / static_cast<float>(n)) - glm::vec3(1.0f));
    ids.emplace(key, index);
    return index;
  };
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = 0; side < 2; ++side) {
      for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
          auto at = [&](int u, int v) {
            glm::ivec3 q;
            q[axis] = side * n;
            q[(axis + 1) % 3] = u;
            q[(axis + 2) % 3] = v;
            return vertex(q);
          };
          uint32_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
          m.indices.insert(m.indices.end(), {a, b, c, a, c, d});
        }
      }
    }
  }
  return m;
}

// Two rooms in a closed box [0,10]x[0,3]x[0,5]; the dividing wall at x = 5
// has a narrow door (z in [2.4, 2.6], y below 2).
inline Mesh twoRooms() {
  Mesh m;
  for (float x0 : {0.0f, 5.0f}) {
    addAxisQuad(m, 1, 0.0f, {0.0f, x0}, {5.0f, x0 + 5.0f});  // floor (axis y: u=z, v=x)
    addAxisQuad(m, 1, 3.0f, {0.0f, x0}, {5.0f, x0 + 5.0f});  // ceiling
    addAxisQuad(m, 2, 0.0f, {x0, 0.0f}, {x0 + 5.0f, 3.0f});  // z = 0 wall (u=x, v=y)
    addAxisQuad(m, 2, 5.0f, {x0, 0.0f}, {x0 + 5.0f, 3.0f});  // z = 5 wall
  }
  addAxisQuad(m, 0, 0.0f, {0.0f, 0.0f}, {3.0f, 5.0f});   // x = 0 wall (u=y, v=z)
  addAxisQuad(m, 0, 10.0f, {0.0f, 0.0f}, {3.0f, 5.0f});  // x = 10 wall
  addAxisQuad(m, 0, 5.0f, {0.0f, 0.0f}, {3.0f, 2.4f});   // dividing wall, left of the door
  addAxisQuad(m, 0, 5.0f, {0.0f, 2.6f}, {3.0f, 5.0f});   // right of the door
  addAxisQuad(m, 0, 5.0f, {2.0f, 2.4f}, {3.0f, 2.6f});   // above the door
  return m;
}

inline glm::mat4 trs(const glm::vec3& translation, float angle, const glm::vec3& axis,
                     const glm::vec3& scale) {
  glm::mat4 m = glm::translate(glm::mat4(1.0f), translation);
  m = glm::rotate(m, angle, glm::normalize(axis));
  return glm::scale(m, scale);
}

// The two rooms plus rotated, non-uniformly scaled and mirrored instances of a
// cube and a sphere. Mesh i is BLAS i.
inline Scene twoRoomScene() {
  Scene s;
  s.meshes = {twoRooms(), gridCube(2), icosphere(2)};
  s.instances = {
      {glm::mat4(1.0f), 0, 100},
      {trs({2.5f, 1.0f, 2.5f}, 0.6f, {1, 2, 3}, {0.5f, 1.2f, 0.3f}), 1, 101},
      {trs({1.2f, 0.5f, 4.0f}, -1.1f, {0, 1, 0}, {-0.4f, 0.4f, 0.8f}), 1, 102},  // mirrored
      {trs({7.5f, 1.2f, 2.5f}, 2.0f, {1, 0, 1}, {0.7f, 0.4f, 0.9f}), 2, 103},
      {trs({8.5f, 2.2f, 1.0f}, 0.3f, {0, 0, 1}, {0.3f, 0.3f, 0.3f}), 2, 104},
  };
  return s;
}

// Twelve rotated, non-uniformly scaled (some mirrored) instances of two random soups,
// instance i of mesh i % 2.
inline Scene instancedSoups() {
  Scene scene;
  scene.meshes = {randomSoup(1500, 3), randomSoup(800, 4, 4.0f, 0.01f, 0.5f)};
  Random rng(5);
  for (uint32_t i = 0; i < 12; ++i) {
    glm::vec3 scale(rng.uniform(0.2f, 1.5f), rng.uniform(0.2f, 1.5f), rng.uniform(0.2f, 1.5f));
    if (i % 3 == 0) scale.y = -scale.y;  // mirrored
    scene.instances.push_back({trs(rng.inBox(glm::vec3(-10), glm::vec3(10)),
                                   rng.uniform(0.0f, 6.28f), rng.direction(), scale),
                               i % 2, i});
  }
  return scene;
}

inline std::vector<Ray> randomRays(uint32_t count, uint64_t seed, const glm::vec3& lo,
                                   const glm::vec3& hi) {
  Random rng(seed);
  std::vector<Ray> rays(count);
  for (Ray& r : rays) r = {rng.inBox(lo, hi), rng.direction()};
  return rays;
}

inline SceneBvh buildScene(const Scene& scene, const BuildOptions& options = {}) {
  SceneBvh bvh;
  for (const Mesh& m : scene.meshes) bvh.addMesh(m.positions, m.indices, options);
  bvh.rebuildTopLevel(scene.instances);
  return bvh;
}

}  // namespace qlight::bvh::testing
