// Tangent frames for normal maps where a file gives none: per-vertex tangents from the UV
// parameterisation (each triangle's dP/du, accumulated over the triangles of a vertex).
#pragma once
#include <cstdint>

#include "engine/scene/scene_asset.h"

namespace qlight::scene {

// Fills every tangent of `mesh` whose w is 0 (or all of them, when it has none) from UV
// set uvSet (0 or 1). w = +1 when cross(normal, tangent) points toward decreasing v (image
// up, the glTF normal texture's +Y), -1 for mirrored UVs. Degenerate UVs give any tangent
// perpendicular to the normal.
void generateTangents(MeshAsset& mesh, uint32_t uvSet);

// generateTangents for each mesh some of whose triangles use a normal-mapped material, on
// the UV set that material's normal texture reads.
void generateMissingTangents(SceneAsset& scene);

}  // namespace qlight::scene
