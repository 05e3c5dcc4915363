// The environment map: an equirectangular image of the radiance arriving from
// infinitely far away, and its importance sampling for next event estimation,
// shared by GLSL and C++ (the tests run this very code on CPU copies).
//
// Map space has +Y up (the scene's up axis). Pixel (col, row) covers
// u in [col, col+1) / width, v in [row, row+1) / height; row 0 is at +Y.
// A direction's angles are theta = pi v from +Y and phi = 2 pi (u - 1/2)
// from -Z toward +X, so the image's centre lies on the horizon at -Z (where
// a glTF camera looks by default) and +X is a quarter to the right of it.
// The map is turned by `rotation` about +Y (right-handed): worldFromMap.
//
// The map is cut into tiles (Dahm & Keller section 4.2): a grid of tilesX x tilesY
// rectangles in (u, v), tile (tx, ty) covering columns [tx w / tilesX, (tx+1) w / tilesX)
// and rows [ty h / tilesY, ...) in integer division. Each tile is one light of the scene
// (its selection weight the tile's power), so power-based and learned light selection
// choose among tiles, and a cache point learns which tiles reach it.
//
// Sampling within a tile is piecewise constant in (u, v) with pixel probabilities
// proportional to luminance x sin(theta at the row's centre): a row from the tile's
// marginal CDF, a column from that row's CDF within the tile, then uniform within the
// pixel. Its density per solid angle is p_uv / (2 pi^2 sin(theta)).
//
// Tables (built by engine/render/environment_tables.cpp):
//   texels: texel 0 = (width, height, cos(rotation), sin(rotation)) and texel 1 =
//           (tilesX, tilesY, 0, 0) as float values; texel 2 + row * width + col =
//           (radiance rgb, p_uv), p_uv being the density in (u, v) of its tile's
//           sampler, computed from the same float CDF steps the sampler walks, so the
//           pdf it states is the density it has;
//   cdf:    at row * width + col, the inclusive CDF of row `row` within the tile's
//           columns (ending at 1 at the tile's last column); then at width * height +
//           tx * height + row, the inclusive CDF over the rows of tile column tx within
//           each tile's rows (ending at 1 at each tile's last row).
// The includer defines QL_ENV_TEXEL_AT(i) (vec4) and QL_ENV_CDF_AT(i) (float)
// before including this header to get the lookups and the sampler.
#ifndef QLIGHT_SHARED_ENVIRONMENT_H
#define QLIGHT_SHARED_ENVIRONMENT_H

#include "common.h"

QL_BEGIN

QL_CONST uint kEnvironmentHeaderTexels = 2u;
// The tile grid, clamped to the map's size (8 x 4: 45 degrees a side).
QL_CONST uint kEnvironmentTilesX = 8u;
QL_CONST uint kEnvironmentTilesY = 4u;
// Solid angle per unit area of (u, v) at theta = pi/2: d omega = 2 pi^2 sin(theta) du dv.
QL_CONST float kEnvironmentUvToSolidAngle = 2.0f * kPi * kPi;

struct EnvironmentMap {
  uint width;
  uint height;
  float cosRotation;
  float sinRotation;
  uint tilesX;
  uint tilesY;
};

// First column (row) of tile column (row) t of `tiles` over `size` pixels.
QL_FN uint environmentTileStart(uint t, uint tiles, uint size) { return t * size / tiles; }

// The tile column (row) holding column (row) i: the largest t with start(t) <= i.
QL_FN uint environmentTileAt(uint i, uint tiles, uint size) {
  return ((i + 1u) * tiles - 1u) / size;
}

QL_FN vec3 environmentMapFromWorld(EnvironmentMap e, vec3 w) {
  return vec3(w.x * e.cosRotation - w.z * e.sinRotation, w.y,
              w.x * e.sinRotation + w.z * e.cosRotation);
}

QL_FN vec3 environmentWorldFromMap(EnvironmentMap e, vec3 m) {
  return vec3(m.x * e.cosRotation + m.z * e.sinRotation, m.y,
              -m.x * e.sinRotation + m.z * e.cosRotation);
}

// (u, v) in [0, 1]^2 of a unit direction in map space.
QL_FN vec2 environmentUvOfDirection(vec3 m) {
  // atan(0, 0) is undefined in GLSL: the poles belong to phi = 0.
  float phi = (m.x != 0.0f || m.z != 0.0f) ? atan(m.x, -m.z) : 0.0f;
  float theta = acos(clamp(m.y, -1.0f, 1.0f));
  return vec2(0.5f + phi * (0.5f * kInvPi), theta * kInvPi);
}

QL_FN vec3 environmentDirectionOfUv(vec2 uv) {
  float theta = kPi * uv.y;
  float phi = kTwoPi * (uv.x - 0.5f);
  float s = sin(theta);
  return vec3(s * sin(phi), cos(theta), -s * cos(phi));
}

QL_FN float environmentRowCentreSin(uint row, uint height) {
  return sin(kPi * (float(row) + 0.5f) / float(height));
}

// Solid-angle density from the (u, v) density at a direction sin(theta) away from the poles.
QL_FN float environmentSolidAnglePdf(float uvPdf, float sinTheta) {
  return sinTheta > 0.0f ? uvPdf / (kEnvironmentUvToSolidAngle * sinTheta) : 0.0f;
}

#ifdef QL_ENV_TEXEL_AT

QL_FN EnvironmentMap environmentMapHeader() {
  vec4 h = QL_ENV_TEXEL_AT(0u);
  EnvironmentMap e;
  e.width = uint(h.x);
  e.height = uint(h.y);
  e.cosRotation = h.z;
  e.sinRotation = h.w;
  vec4 tiles = QL_ENV_TEXEL_AT(1u);
  e.tilesX = uint(tiles.x);
  e.tilesY = uint(tiles.y);
  return e;
}

QL_FN uint environmentTexelIndex(EnvironmentMap e, uint col, uint row) {
  return kEnvironmentHeaderTexels + row * e.width + col;
}

struct EnvironmentTexel {
  vec3 radiance;  // the texel's (unscaled by the light's strength)
  float pdf;      // per solid angle, of the sampler of the tile holding the direction
  uint tile;      // ty * tilesX + tx
};

// The map's texel seen in world direction w.
QL_FN EnvironmentTexel environmentLookup(EnvironmentMap e, vec3 w) {
  vec3 m = environmentMapFromWorld(e, w);
  vec2 uv = environmentUvOfDirection(m);
  uint col = min(uint(max(uv.x, 0.0f) * float(e.width)), e.width - 1u);
  uint row = min(uint(max(uv.y, 0.0f) * float(e.height)), e.height - 1u);
  vec4 t = QL_ENV_TEXEL_AT(environmentTexelIndex(e, col, row));
  // From the horizontal part: sqrt(1 - y^2) loses the digits near the poles.
  float sinTheta = sqrt(m.x * m.x + m.z * m.z);
  EnvironmentTexel r;
  r.radiance = vec3(t.x, t.y, t.z);
  r.pdf = environmentSolidAnglePdf(t.w, sinTheta);
  r.tile = environmentTileAt(row, e.tilesY, e.height) * e.tilesX +
           environmentTileAt(col, e.tilesX, e.width);
  return r;
}

#ifdef QL_ENV_CDF_AT

// First entry of the inclusive CDF at [base, base + count) above `target`, and where the
// target falls within that entry's step, in [0, 1).
QL_FN uint environmentSearchCdf(uint base, uint count, float target, QL_OUT(float) offset) {
  uint lo = 0u;
  uint hi = count - 1u;
  while (lo < hi) {
    uint mid = (lo + hi) >> 1u;
    if (QL_ENV_CDF_AT(base + mid) <= target)
      lo = mid + 1u;
    else
      hi = mid;
  }
  float below = lo > 0u ? QL_ENV_CDF_AT(base + lo - 1u) : 0.0f;
  float step = QL_ENV_CDF_AT(base + lo) - below;
  offset = step > 0.0f ? clamp((target - below) / step, 0.0f, 0.99999994f) : 0.5f;
  return lo;
}

struct EnvironmentSample {
  vec3 direction;  // world, unit
  vec3 radiance;   // the texel's (unscaled by the light's strength)
  float pdf;       // per solid angle, given the tile; 0: no sample
};

// A direction within tile `tile` (ty * tilesX + tx) by its pixels' luminance x sin(theta).
QL_FN EnvironmentSample sampleEnvironmentTile(EnvironmentMap e, uint tile, vec2 u) {
  uint tx = tile % e.tilesX;
  uint ty = tile / e.tilesX;
  uint col0 = environmentTileStart(tx, e.tilesX, e.width);
  uint row0 = environmentTileStart(ty, e.tilesY, e.height);
  uint cols = environmentTileStart(tx + 1u, e.tilesX, e.width) - col0;
  uint rows = environmentTileStart(ty + 1u, e.tilesY, e.height) - row0;
  float dv;
  float du;
  uint row = row0 + environmentSearchCdf(e.width * e.height + tx * e.height + row0, rows, u.y, dv);
  uint col = col0 + environmentSearchCdf(row * e.width + col0, cols, u.x, du);
  vec2 uv = vec2((float(col) + du) / float(e.width), (float(row) + dv) / float(e.height));
  vec4 t = QL_ENV_TEXEL_AT(environmentTexelIndex(e, col, row));
  EnvironmentSample s;
  s.direction = environmentWorldFromMap(e, environmentDirectionOfUv(uv));
  s.radiance = vec3(t.x, t.y, t.z);
  s.pdf = environmentSolidAnglePdf(t.w, sin(kPi * uv.y));
  return s;
}

#endif
#endif

QL_END

#endif
