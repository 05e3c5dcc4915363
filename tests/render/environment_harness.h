// Includes shaders/shared/environment.h with its texel and CDF lookups reading C++ vectors,
// the way the shaders read their texel buffers, and fills them from an EnvironmentAsset
// with the renderer's own table builder.
#pragma once

#include <vector>

#include "engine/render/environment_tables.h"

namespace qlight::test {
inline std::vector<glm::vec4> gEnvTexels;
inline std::vector<float> gEnvCdf;
}  // namespace qlight::test

#define QL_ENV_TEXEL_AT(i) (::qlight::test::gEnvTexels.at(i))
#define QL_ENV_CDF_AT(i) (::qlight::test::gEnvCdf.at(i))
#include "shaders/shared/environment.h"

namespace qlight::test {

inline render::EnvironmentTables loadEnvironmentTables(const scene::EnvironmentAsset& env) {
  render::EnvironmentTables t = render::buildEnvironmentTables(env);
  gEnvTexels = t.texels;
  gEnvCdf = t.cdf;
  return t;
}

}  // namespace qlight::test
