// Writes the scenes qlight ships (assets/*.gltf): the Cornell box, the "door ajar" room pair
// (Veach's hard case, used by Dahm & Keller and van Mastrigt), the Cornell box with a light
// moving along a looping animation, a room with over a hundred small lights, and three scenes
// for benchmarking guiding in hard indirect light: an L-shaped corridor lit around its corner,
// a room lit through a doorway with a glossy floor, and a finely tessellated (~200k
// triangles) furnished version of the door-ajar pair.
// Units are meters, +Y is up; emitters are quads whose front (counter-clockwise) side faces
// into the room. Every file is reloaded with loadGltf after writing as a check; files must
// stay under 200 KB. The furnished room (7 MB) is not kept in the repository: `--large`
// writes it, and the build runs that into build/assets.
//
//   gen_scenes [--out DIR] [--large | --tessellated N]      (DIR defaults to ./assets)
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "engine/gltf/gltf_loader.h"
#include "engine/gltf/gltf_writer.h"
#include "engine/scene/procedural.h"

namespace {

using namespace qlight::scene;
using glm::vec3;
using qlight::gltf::loadGltf;
using qlight::gltf::saveGltf;

constexpr float kPi = 3.14159265358979f;

uint32_t addMaterial(SceneAsset& scene, const std::string& name, vec3 albedo,
                     vec3 emissive = vec3(0.0f)) {
  MaterialAsset m;
  m.name = name;
  m.baseColorFactor = glm::vec4(albedo, 1.0f);
  // Exactly Lambertian: metallic 0 (glTF's default of 1 would make black mirrors) and
  // KHR_materials_specular specularFactor 0 (no dielectric specular layer).
  m.metallicFactor = 0.0f;
  m.specularFactor = 0.0f;
  m.roughnessFactor = 1.0f;
  m.emissive = emissive;
  scene.materials.push_back(m);
  return uint32_t(scene.materials.size() - 1);
}

uint32_t addMesh(SceneAsset& scene, MeshAsset mesh) {
  scene.meshes.push_back(std::move(mesh));
  return uint32_t(scene.meshes.size() - 1);
}

uint32_t addMeshNode(SceneAsset& scene, const std::string& name, uint32_t mesh,
                     vec3 translation = vec3(0.0f), int32_t parent = -1) {
  NodeAsset node;
  node.name = name;
  node.mesh = int32_t(mesh);
  node.local.translation = translation;
  return addNode(scene, node, parent);
}

void addCamera(SceneAsset& scene, vec3 eye, vec3 target, float yfov, float aspect) {
  CameraAsset camera;
  camera.name = "camera";
  camera.yfov = yfov;
  camera.aspectRatio = aspect;
  camera.znear = 0.01f;
  camera.zfar = 100.0f;
  scene.cameras.push_back(camera);
  NodeAsset node;
  node.name = "camera";
  node.camera = int32_t(scene.cameras.size() - 1);
  node.local.translation = eye;
  node.local.rotation = glm::quatLookAt(glm::normalize(target - eye), vec3(0, 1, 0));
  addNode(scene, node);
}

glm::mat4 placed(vec3 center, float yawDegrees) {
  return glm::rotate(glm::translate(glm::mat4(1.0f), center), glm::radians(yawDegrees),
                     vec3(0, 1, 0));
}

// The Cornell box, 2 m: x in [-1, 1], y in [0, 2], z in [-1, 1], open towards +z where the
// camera stands. Albedos and the light's radiance (17, 12, 4) follow the classic setup.
// Returns the scene without its ceiling light so the animated variant can add a moving one.
SceneAsset cornellRoom() {
  SceneAsset scene;
  const uint32_t white = addMaterial(scene, "white", vec3(0.73f));
  const uint32_t red = addMaterial(scene, "red", vec3(0.65f, 0.05f, 0.05f));
  const uint32_t green = addMaterial(scene, "green", vec3(0.12f, 0.45f, 0.15f));

  MeshAsset room;
  room.name = "room";
  addQuad(room, {-1, 0, 1}, {1, 0, 1}, {1, 0, -1}, {-1, 0, -1}, white);    // floor, +y
  addQuad(room, {-1, 2, -1}, {1, 2, -1}, {1, 2, 1}, {-1, 2, 1}, white);    // ceiling, -y
  addQuad(room, {-1, 0, -1}, {1, 0, -1}, {1, 2, -1}, {-1, 2, -1}, white);  // back, +z
  addQuad(room, {-1, 0, 1}, {-1, 0, -1}, {-1, 2, -1}, {-1, 2, 1}, red);    // left, +x
  addQuad(room, {1, 0, -1}, {1, 0, 1}, {1, 2, 1}, {1, 2, -1}, green);      // right, -x
  addMeshNode(scene, "room", addMesh(scene, room));

  MeshAsset blocks;
  blocks.name = "blocks";
  addBox(blocks, placed({-0.38f, 0.6f, -0.35f}, 17.0f), {0.3f, 0.6f, 0.3f}, white);  // tall
  addBox(blocks, placed({0.38f, 0.3f, 0.35f}, -17.0f), {0.3f, 0.3f, 0.3f}, white);   // short
  addMeshNode(scene, "blocks", addMesh(scene, blocks));

  addCamera(scene, {0.0f, 1.0f, 3.9f}, {0.0f, 1.0f, 0.0f}, 0.69f, 1.0f);
  return scene;
}

SceneAsset cornellBox() {
  SceneAsset scene = cornellRoom();
  const uint32_t light = addMaterial(scene, "light", vec3(0.78f), vec3(17.0f, 12.0f, 4.0f));
  MeshAsset lamp;
  lamp.name = "ceiling_light";
  // 0.5 m x 0.4 m, 5 mm below the ceiling, facing down (-y).
  addQuad(lamp, {-0.25f, 1.995f, -0.2f}, {0.25f, 1.995f, -0.2f}, {0.25f, 1.995f, 0.2f},
          {-0.25f, 1.995f, 0.2f}, light);
  addMeshNode(scene, "ceiling_light", addMesh(scene, lamp));
  return scene;
}

// A 0.3 m square light facing down, circling 0.5 m around the room's axis at 1.7 m height
// once every 4 s (9 LINEAR keys, the last equal to the first, so the loop is seamless).
SceneAsset animatedLight() {
  SceneAsset scene = cornellRoom();
  const uint32_t light = addMaterial(scene, "moving_light", vec3(0.78f), vec3(34.0f, 24.0f, 8.0f));
  MeshAsset lamp;
  lamp.name = "moving_light";
  addQuad(lamp, {-0.15f, 0, -0.15f}, {0.15f, 0, -0.15f}, {0.15f, 0, 0.15f}, {-0.15f, 0, 0.15f},
          light);
  const uint32_t node = addMeshNode(scene, "moving_light", addMesh(scene, lamp), {0.5f, 1.7f, 0});

  AnimationChannel path;
  path.node = node;
  path.path = AnimationPath::Translation;
  path.interpolation = Interpolation::Linear;
  constexpr int kKeys = 9;
  constexpr float kPeriod = 4.0f;
  for (int k = 0; k < kKeys; ++k) {
    const float angle = 2.0f * kPi * float(k % (kKeys - 1)) / float(kKeys - 1);
    path.times.push_back(kPeriod * float(k) / float(kKeys - 1));
    path.values.push_back({0.5f * std::cos(angle), 1.7f, 0.5f * std::sin(angle), 0.0f});
  }
  AnimationAsset animation;
  animation.name = "light_loop";
  animation.duration = kPeriod;
  animation.channels.push_back(path);
  scene.animations.push_back(animation);
  return scene;
}

// Two rooms side by side along x joined by a doorway in the dividing wall: room A, x in
// [0, wallX0], where the cameras stand, and room B, x in [wallX1, endX]; both span z in
// [0, depth]. Shared by the door-ajar, glossy-floor and furnished scenes.
struct RoomPair {
  float height, depth;
  float wallX0, wallX1, endX;
  float doorZ0, doorZ1, doorTop;
};

// A rectangular emitter just under a ceiling at `height`, facing down, over the (x, z)
// rectangle from lo to hi.
void addCeilingLight(SceneAsset& scene, float height, glm::vec2 lo, glm::vec2 hi,
                     uint32_t material) {
  MeshAsset lamp;
  lamp.name = "ceiling_light";
  const float y = height - 0.005f, x0 = lo.x, z0 = lo.y, x1 = hi.x, z1 = hi.y;
  addQuad(lamp, {x0, y, z0}, {x1, y, z0}, {x1, y, z1}, {x0, y, z1}, material);
  addMeshNode(scene, "ceiling_light", addMesh(scene, lamp));
}

// The shell of both rooms seen from inside, the floor (one quad when both rooms share the
// material), and the dividing wall: its two faces with the doorway cut out, the doorway's
// jambs and lintel; one mesh "rooms" with its node.
void addRoomPairShell(SceneAsset& scene, const RoomPair& r, uint32_t wall, uint32_t floorA,
                      uint32_t floorB) {
  MeshAsset rooms;
  rooms.name = "rooms";
  const vec3 half(r.endX / 2, r.height / 2, r.depth / 2);
  addBox(rooms, glm::translate(glm::mat4(1.0f), half), half, wall, true, kBoxAllFaces & ~kBoxMinY);
  if (floorA == floorB) {
    addQuad(rooms, {0, 0, r.depth}, {r.endX, 0, r.depth}, {r.endX, 0, 0}, {0, 0, 0}, floorA);
  } else {  // room A's floor ends under the doorway, where the wall's room A face is
    addQuad(rooms, {0, 0, r.depth}, {r.wallX0, 0, r.depth}, {r.wallX0, 0, 0}, {0, 0, 0}, floorA);
    addQuad(rooms, {r.wallX0, 0, r.depth}, {r.endX, 0, r.depth}, {r.endX, 0, 0}, {r.wallX0, 0, 0},
            floorB);
  }
  for (float x : {r.wallX0, r.wallX1}) {
    const bool facesA = x == r.wallX0;  // the face towards room A points -x
    auto quad = [&](float z0, float z1, float y0, float y1) {
      if (facesA) {
        addQuad(rooms, {x, y0, z0}, {x, y0, z1}, {x, y1, z1}, {x, y1, z0}, wall);
      } else {
        addQuad(rooms, {x, y0, z1}, {x, y0, z0}, {x, y1, z0}, {x, y1, z1}, wall);
      }
    };
    quad(0.0f, r.doorZ0, 0.0f, r.height);
    quad(r.doorZ1, r.depth, 0.0f, r.height);
    quad(r.doorZ0, r.doorZ1, r.doorTop, r.height);
  }
  // Jambs face into the doorway; the lintel's underside faces down.
  addQuad(rooms, {r.wallX0, 0, r.doorZ0}, {r.wallX1, 0, r.doorZ0}, {r.wallX1, r.doorTop, r.doorZ0},
          {r.wallX0, r.doorTop, r.doorZ0}, wall);  // +z
  addQuad(rooms, {r.wallX1, 0, r.doorZ1}, {r.wallX0, 0, r.doorZ1}, {r.wallX0, r.doorTop, r.doorZ1},
          {r.wallX1, r.doorTop, r.doorZ1}, wall);  // -z
  addQuad(rooms, {r.wallX0, r.doorTop, r.doorZ0}, {r.wallX1, r.doorTop, r.doorZ0},
          {r.wallX1, r.doorTop, r.doorZ1}, {r.wallX0, r.doorTop, r.doorZ1}, wall);  // -y
  addMeshNode(scene, "rooms", addMesh(scene, std::move(rooms)));
}

// The door, 4 cm thick and 2 * halfHeight tall, 5 mm above the floor: in its own
// frame the hinge edge is the y axis and the slab extends along -z with its thickness along
// -x (closed, it would lie flat against room A's side of the wall). The node turns it about
// the hinge, on the doorway's +z side, until the free edge stands `gap` from the other jamb.
void addDoor(SceneAsset& scene, const RoomPair& r, float halfHeight, float gap, uint32_t material) {
  MeshAsset door;
  door.name = "door";
  const float width = r.doorZ1 - r.doorZ0;
  addBox(door, glm::translate(glm::mat4(1.0f), {-0.02f, 0.005f + halfHeight, -width / 2}),
         {0.02f, halfHeight, width / 2}, material);
  NodeAsset doorNode;
  doorNode.name = "door";
  doorNode.mesh = int32_t(addMesh(scene, door));
  doorNode.local.translation = {r.wallX0, 0.0f, r.doorZ1};
  const float ajar = 2.0f * std::asin(gap / (2.0f * width));  // chord of the swing = gap
  doorNode.local.rotation = glm::angleAxis(ajar, vec3(0, 1, 0));
  addNode(scene, doorNode);
}

// Two 4 m x 4 m rooms, 2.5 m high, side by side along x, joined by an 80 cm doorway in a
// 10 cm wall. The door slab, hinged on the doorway's +z side, is swung 7.2 degrees into room
// A: its free edge stands 10 cm from the jamb. Without its light and camera (the door-ajar
// scenes add them, in this order).
SceneAsset doorAjarRooms() {
  SceneAsset scene;
  const uint32_t wall = addMaterial(scene, "wall", vec3(0.75f));
  const uint32_t floor = addMaterial(scene, "floor", vec3(0.5f, 0.45f, 0.4f));
  const uint32_t wood = addMaterial(scene, "door", vec3(0.55f, 0.38f, 0.22f));
  const uint32_t furniture = addMaterial(scene, "furniture", vec3(0.3f, 0.4f, 0.6f));

  const RoomPair pair{2.5f, 4.0f, 4.0f, 4.1f, 8.1f, 1.6f, 2.4f, 2.0f};
  addRoomPairShell(scene, pair, wall, floor, floor);

  addDoor(scene, pair, 0.99f, 0.10f, wood);  // 80 cm x 198 cm

  // A little furniture in each room.
  MeshAsset blocks;
  blocks.name = "furniture";
  addBox(blocks, placed({1.6f, 0.4f, 1.0f}, 10.0f), {0.6f, 0.4f, 0.4f}, furniture);
  addBox(blocks, placed({0.5f, 0.6f, 0.5f}, 0.0f), {0.35f, 0.6f, 0.35f}, furniture);
  addBox(blocks, placed({6.5f, 0.5f, 1.2f}, -20.0f), {0.5f, 0.5f, 0.5f}, furniture);
  addMeshNode(scene, "furniture", addMesh(scene, blocks));
  return scene;
}

void addDoorAjarCamera(SceneAsset& scene) {
  addCamera(scene, {0.4f, 1.5f, 3.6f}, {4.0f, 1.0f, 1.8f}, 1.0f, 16.0f / 9.0f);
}

// Bright: only a sliver of it reaches the first room through the gap, and that room
// should render at an ordinary exposure (radiance ~0.1, where relative MSE is meaningful).
uint32_t doorAjarLightMaterial(SceneAsset& scene) {
  return addMaterial(scene, "light", vec3(0.78f), vec3(2000.0f, 1840.0f, 1600.0f));
}

// The only light, a ceiling panel in room B, cannot be seen from the camera in room A; every
// light path to the camera passes the gap.
SceneAsset doorAjar() {
  SceneAsset scene = doorAjarRooms();
  // 60 cm square on room B's ceiling, far from the door's line of sight.
  addCeilingLight(scene, 2.5f, {6.6f, 2.9f}, {7.2f, 3.5f}, doorAjarLightMaterial(scene));
  addDoorAjarCamera(scene);
  return scene;
}

// A key of the door-ajar light's animation: where on the ceiling (x, z) and how large.
struct LightKey {
  float time;
  glm::vec2 at;
  float scale = 1.0f;
};

// The door-ajar rooms with their ceiling panel on a node that `keys` move over the ceiling
// (and scale): the scenes that show guiding following a light (the demo's default scene
// and the tracking study).
SceneAsset doorAjarAnimated(const std::string& name, Interpolation interpolation,
                            const std::vector<LightKey>& keys) {
  SceneAsset scene = doorAjarRooms();
  const uint32_t light = doorAjarLightMaterial(scene);
  MeshAsset lamp;
  lamp.name = name;
  const float y = -0.005f;  // under the ceiling, in the node's frame at ceiling height
  addQuad(lamp, {-0.3f, y, -0.3f}, {0.3f, y, -0.3f}, {0.3f, y, 0.3f}, {-0.3f, y, 0.3f}, light);
  const glm::vec2 start = keys.front().at;
  const uint32_t node = addMeshNode(scene, name, addMesh(scene, lamp), {start.x, 2.5f, start.y});
  AnimationChannel move, size;
  move.node = size.node = node;
  move.path = AnimationPath::Translation;
  size.path = AnimationPath::Scale;
  move.interpolation = size.interpolation = interpolation;
  bool scaled = false;
  for (const LightKey& k : keys) {
    move.times.push_back(k.time);
    move.values.push_back({k.at.x, 2.5f, k.at.y, 0.0f});
    size.times.push_back(k.time);
    size.values.push_back({k.scale, 1.0f, k.scale, 0.0f});
    scaled |= k.scale != 1.0f;
  }
  AnimationAsset animation;
  animation.name = name;
  animation.duration = keys.back().time;
  animation.channels.push_back(move);
  if (scaled) animation.channels.push_back(size);
  scene.animations.push_back(animation);
  addDoorAjarCamera(scene);
  return scene;
}

// The demo's default: the panel glides between room B's far corner and the dividing wall
// beside the door and back, every 8 s (LINEAR keys, the last equal to the first).
SceneAsset doorAjarMovingLight() {
  return doorAjarAnimated("moving_light", Interpolation::Linear,
                          {{0.0f, {6.9f, 3.2f}}, {4.0f, {4.6f, 0.8f}}, {8.0f, {6.9f, 3.2f}}});
}

// The tracking study's jump: the panel stands 6 s in room B's far corner, then 6 s on room
// A's ceiling, shrunk to 3 cm so room A is not flooded (STEP keys): where room A's light came
// through the gap it now comes from above, and back, so what each point learned is wrong at
// once.
SceneAsset doorAjarJumpingLight() {
  return doorAjarAnimated(
      "jumping_light", Interpolation::Step,
      {{0.0f, {6.9f, 3.2f}}, {6.0f, {2.0f, 1.2f}, 0.05f}, {12.0f, {2.0f, 1.2f}, 0.05f}});
}

// Light i of n: a repeatable strength spread over two decades, and a slight tint.
vec3 lightEmission(int i) {
  const float u = std::fmod(std::abs(std::sin(float(i) * 12.9898f) * 43758.5453f), 1.0f);
  const float strength = 2.0f * std::pow(50.0f, u);  // 2 .. 100
  const vec3 tints[4] = {
      {1.0f, 0.9f, 0.75f}, {0.8f, 0.9f, 1.0f}, {1.0f, 1.0f, 1.0f}, {1.0f, 0.8f, 0.8f}};
  return strength * tints[i % 4];
}

// An 8 m x 8 m x 3 m closed room split by partial walls and pillars, with 64 small ceiling
// panels (20 cm) and 48 wall lamps (15 cm, low on the walls), 112 emitters of strengths from 2
// to 100, most of them hidden from most of the room by the occluders.
SceneAsset manyLights() {
  SceneAsset scene;
  const uint32_t wall = addMaterial(scene, "wall", vec3(0.7f));
  const uint32_t floor = addMaterial(scene, "floor", vec3(0.45f));
  const uint32_t block = addMaterial(scene, "occluder", vec3(0.6f, 0.55f, 0.5f));

  MeshAsset room;
  room.name = "room";
  addBox(room, glm::translate(glm::mat4(1.0f), {0, 1.5f, 0}), {4, 1.5f, 4}, wall, true,
         kBoxAllFaces & ~kBoxMinY);
  addQuad(room, {-4, 0, 4}, {4, 0, 4}, {4, 0, -4}, {-4, 0, -4}, floor);
  addMeshNode(scene, "room", addMesh(scene, room));

  MeshAsset occluders;
  occluders.name = "occluders";
  addBox(occluders, placed({0, 1.5f, -2.5f}, 0), {0.1f, 1.5f, 1.5f}, block);    // full height
  addBox(occluders, placed({2.5f, 1.0f, 1.2f}, 0), {1.5f, 1.0f, 0.1f}, block);  // partial
  addBox(occluders, placed({-2.5f, 1.2f, 1.0f}, 30), {1.0f, 1.2f, 0.1f}, block);
  for (vec3 c : {vec3(-1.5f, 1.5f, -1.0f), vec3(1.5f, 1.5f, -1.0f), vec3(0.0f, 1.5f, 2.0f)})
    addBox(occluders, placed(c, 45), {0.2f, 1.5f, 0.2f}, block);                 // pillars
  addBox(occluders, placed({-1.0f, 0.4f, 2.8f}, 0), {0.6f, 0.4f, 0.4f}, block);  // low box
  addMeshNode(scene, "occluders", addMesh(scene, occluders));

  MeshAsset lamps;
  lamps.name = "lights";
  int count = 0;
  auto lightMaterial = [&] {
    const uint32_t m =
        addMaterial(scene, "light_" + std::to_string(count), vec3(0.78f), lightEmission(count));
    ++count;
    return m;
  };
  constexpr float kCeiling = 2.995f, kPanel = 0.1f;
  for (int gx = 0; gx < 8; ++gx) {
    for (int gz = 0; gz < 8; ++gz) {
      const float x = -3.5f + float(gx), z = -3.5f + float(gz);
      addQuad(lamps, {x - kPanel, kCeiling, z - kPanel}, {x + kPanel, kCeiling, z - kPanel},
              {x + kPanel, kCeiling, z + kPanel}, {x - kPanel, kCeiling, z + kPanel},
              lightMaterial());  // facing down
    }
  }
  constexpr float kLamp = 0.075f, kInset = 3.995f;
  for (int i = 0; i < 12; ++i) {
    const float s = -3.3f + 0.6f * float(i);
    const float y = 0.4f + 0.3f * float(i % 3);
    // One lamp per wall at s, each facing into the room.
    addQuad(lamps, {s - kLamp, y - kLamp, -kInset}, {s + kLamp, y - kLamp, -kInset},
            {s + kLamp, y + kLamp, -kInset}, {s - kLamp, y + kLamp, -kInset}, lightMaterial());
    addQuad(lamps, {s + kLamp, y - kLamp, kInset}, {s - kLamp, y - kLamp, kInset},
            {s - kLamp, y + kLamp, kInset}, {s + kLamp, y + kLamp, kInset}, lightMaterial());
    addQuad(lamps, {-kInset, y - kLamp, s + kLamp}, {-kInset, y - kLamp, s - kLamp},
            {-kInset, y + kLamp, s - kLamp}, {-kInset, y + kLamp, s + kLamp}, lightMaterial());
    addQuad(lamps, {kInset, y - kLamp, s - kLamp}, {kInset, y - kLamp, s + kLamp},
            {kInset, y + kLamp, s + kLamp}, {kInset, y + kLamp, s - kLamp}, lightMaterial());
  }
  addMeshNode(scene, "lights", addMesh(scene, lamps));

  addCamera(scene, {-3.5f, 1.7f, 3.5f}, {1.0f, 1.0f, -1.0f}, 1.1f, 16.0f / 9.0f);
  return scene;
}

// An L-shaped corridor, 1.5 m wide and 2.5 m high: leg A runs from z = 0 to the corner at
// z in [-7.5, -6] (x in [0, 1.5]), leg B from the corner 6 m along +x. The only light, a
// 50 cm panel at the far end of leg B, sits 40 cm up a ceiling recess: the recess stops its
// grazing rays, so it lights leg B only beyond x ~ 3 m, while the camera in leg A, looking at
// the corner, sees no further than x ~ 1.7 m into leg B. Every path to the camera turns the
// corner after at least one bounce.
SceneAsset corridor() {
  SceneAsset scene;
  const uint32_t wall = addMaterial(scene, "wall", vec3(0.75f));
  const uint32_t ceiling = addMaterial(scene, "ceiling", vec3(0.8f));
  const uint32_t floor = addMaterial(scene, "floor", vec3(0.5f, 0.45f, 0.4f));
  // The recess is lined black, as downlight baffles are: lit at close range, a pale lining
  // would be a small, very bright secondary source that only BSDF sampling finds (fireflies).
  const uint32_t baffle = addMaterial(scene, "baffle", vec3(0.05f));
  const uint32_t light = addMaterial(scene, "light", vec3(0.78f), vec3(3000.0f, 2760.0f, 2400.0f));

  constexpr float kW = 1.5f, kH = 2.5f, kLeg = 6.0f;
  constexpr float kEnd = -(kLeg + kW), kTurn = -kLeg, kFarX = kW + kLeg;
  // The recess: 60 cm square, 40 cm deep, centered 60 cm from leg B's end wall.
  constexpr float kRx0 = kFarX - 0.9f, kRx1 = kFarX - 0.3f, kRz0 = kEnd + 0.45f,
                  kRz1 = kTurn - 0.45f;
  constexpr float kRecess = 0.4f;

  MeshAsset hall;
  hall.name = "corridor";
  addQuad(hall, {0, 0, 0}, {kW, 0, 0}, {kW, 0, kEnd}, {0, 0, kEnd}, floor);  // leg A + corner
  addQuad(hall, {kW, 0, kTurn}, {kFarX, 0, kTurn}, {kFarX, 0, kEnd}, {kW, 0, kEnd}, floor);
  auto ceilingQuad = [&](float x0, float x1, float z0, float z1) {  // facing down
    addQuad(hall, {x0, kH, z0}, {x1, kH, z0}, {x1, kH, z1}, {x0, kH, z1}, ceiling);
  };
  ceilingQuad(0, kW, kEnd, 0);
  ceilingQuad(kW, kRx0, kEnd, kTurn);  // leg B's ceiling around the recess
  ceilingQuad(kRx1, kFarX, kEnd, kTurn);
  ceilingQuad(kRx0, kRx1, kEnd, kRz0);
  ceilingQuad(kRx0, kRx1, kRz1, kTurn);
  // Walls along the outline, walked so that each faces into the corridor.
  const glm::vec2 outline[] = {{0, 0},         {0, kEnd},   {kFarX, kEnd},
                               {kFarX, kTurn}, {kW, kTurn}, {kW, 0}};
  auto wallQuad = [&](glm::vec2 a, glm::vec2 b, float y0, float y1, uint32_t m) {
    addQuad(hall, {a.x, y0, a.y}, {b.x, y0, b.y}, {b.x, y1, b.y}, {a.x, y1, a.y}, m);
  };
  for (size_t i = 0; i < 6; ++i) wallQuad(outline[i], outline[(i + 1) % 6], 0, kH, wall);
  // The recess's sides face inward, its top down.
  const glm::vec2 recess[] = {{kRx0, kRz1}, {kRx0, kRz0}, {kRx1, kRz0}, {kRx1, kRz1}};
  for (size_t i = 0; i < 4; ++i) wallQuad(recess[i], recess[(i + 1) % 4], kH, kH + kRecess, baffle);
  addQuad(hall, {kRx0, kH + kRecess, kRz0}, {kRx1, kH + kRecess, kRz0}, {kRx1, kH + kRecess, kRz1},
          {kRx0, kH + kRecess, kRz1}, baffle);
  addMeshNode(scene, "corridor", addMesh(scene, hall));

  MeshAsset lamp;
  lamp.name = "recessed_light";
  const float y = kH + kRecess - 0.005f, cx = (kRx0 + kRx1) / 2, cz = (kRz0 + kRz1) / 2;
  addQuad(lamp, {cx - 0.25f, y, cz - 0.25f}, {cx + 0.25f, y, cz - 0.25f},
          {cx + 0.25f, y, cz + 0.25f}, {cx - 0.25f, y, cz + 0.25f}, light);  // facing down
  addMeshNode(scene, "recessed_light", addMesh(scene, lamp));

  // Near leg A's inner (x = 1.5) wall, so the opening into leg B is seen at a steep angle.
  addCamera(scene, {1.05f, 1.6f, -2.5f}, {0.75f, 1.1f, kEnd}, 1.0f, 16.0f / 9.0f);
  return scene;
}

// Room A (5 m x 5 m, 2.6 m high) and room B (4 m x 5 m) joined by an open 1 m doorway. The
// only light, a panel on the dividing wall's room B face, shines into room B: no straight
// line from it passes the doorway, so room A receives only light that bounced in room B.
// Room A's floor is a glossy dielectric (GGX, roughness 0.25) that mirrors the bright
// doorway: behind its diffuse bounces guiding meets a narrow specular lobe.
SceneAsset glossyFloor() {
  SceneAsset scene;
  const uint32_t wall = addMaterial(scene, "wall", vec3(0.75f));
  const uint32_t floorB = addMaterial(scene, "floor", vec3(0.5f, 0.45f, 0.4f));
  const uint32_t wood = addMaterial(scene, "wood", vec3(0.55f, 0.38f, 0.22f));
  const uint32_t blue = addMaterial(scene, "cabinet", vec3(0.3f, 0.4f, 0.6f));
  const uint32_t pale = addMaterial(scene, "pale", vec3(0.7f, 0.68f, 0.6f));
  const uint32_t light = addMaterial(scene, "light", vec3(0.78f), vec3(200.0f, 184.0f, 160.0f));
  // Dark polished floor: the plain glTF dielectric layer (specularFactor 1, F0 0.04) over a
  // dark base, so reflections stand out against the diffuse part.
  MaterialAsset glossy;
  glossy.name = "glossy_floor";
  glossy.baseColorFactor = glm::vec4(0.25f, 0.22f, 0.2f, 1.0f);
  glossy.metallicFactor = 0.0f;
  glossy.specularFactor = 1.0f;
  glossy.roughnessFactor = 0.25f;
  scene.materials.push_back(glossy);
  const auto floorA = uint32_t(scene.materials.size() - 1);

  const RoomPair pair{2.6f, 5.0f, 5.0f, 5.1f, 9.1f, 1.6f, 2.6f, 2.1f};
  addRoomPairShell(scene, pair, wall, floorA, floorB);

  // Furniture in room A, kept clear of the walls (no coincident faces); one block in room B.
  MeshAsset blocks;
  blocks.name = "furniture";
  const glm::mat4 table = placed({2.6f, 0.0f, 2.4f}, 15.0f);
  addBox(blocks, table * glm::translate(glm::mat4(1.0f), {0, 0.74f, 0}), {0.8f, 0.03f, 0.45f},
         wood);  // top
  for (float sx : {-1.0f, 1.0f})
    for (float sz : {-1.0f, 1.0f})
      addBox(blocks, table * glm::translate(glm::mat4(1.0f), {0.72f * sx, 0.355f, 0.37f * sz}),
             {0.035f, 0.355f, 0.035f}, wood);                                      // legs
  addBox(blocks, placed({1.2f, 0.45f, 0.3f}, 0.0f), {0.9f, 0.45f, 0.25f}, blue);   // sideboard
  addBox(blocks, placed({4.55f, 1.0f, 4.4f}, 0.0f), {0.4f, 1.0f, 0.5f}, pale);     // wardrobe
  addBox(blocks, placed({3.2f, 0.22f, 4.2f}, -25.0f), {0.6f, 0.22f, 0.2f}, blue);  // bench
  addBox(blocks, placed({4.3f, 0.3f, 0.6f}, 30.0f), {0.3f, 0.3f, 0.3f}, pale);     // crate
  addBox(blocks, placed({7.6f, 0.5f, 1.0f}, -20.0f), {0.5f, 0.5f, 0.5f}, blue);    // room B
  addMeshNode(scene, "furniture", addMesh(scene, blocks));

  // 1 m x 60 cm, 5 mm off the wall's room B face (x = 5.1), facing +x, 1 m from the doorway.
  MeshAsset lamp;
  lamp.name = "wall_light";
  const float x = pair.wallX1 + 0.005f;
  addQuad(lamp, {x, 1.6f, 4.6f}, {x, 1.6f, 3.6f}, {x, 2.2f, 3.6f}, {x, 2.2f, 4.6f}, light);
  addMeshNode(scene, "wall_light", addMesh(scene, lamp));

  addCamera(scene, {0.4f, 1.5f, 4.6f}, {5.0f, 0.5f, 1.9f}, 1.0f, 16.0f / 9.0f);
  return scene;
}

// ---- Finely tessellated shapes (furnished room) ------------------------------------------

// Positions through worldFrom, normals through its inverse transpose (non-uniform scales make
// ellipsoids and flattened leaves).
struct Placement {
  glm::mat4 world;
  glm::mat3 normal;
  explicit Placement(const glm::mat4& m)
      : world(m), normal(glm::transpose(glm::inverse(glm::mat3(m)))) {}
  uint32_t vertex(MeshAsset& mesh, vec3 p, vec3 n, glm::vec2 uv) const {
    mesh.positions.push_back(vec3(world * glm::vec4(p, 1.0f)));
    mesh.normals.push_back(glm::normalize(normal * n));
    mesh.uv0.push_back(uv);
    return uint32_t(mesh.positions.size() - 1);
  }
};

void addTriangle(MeshAsset& mesh, uint32_t a, uint32_t b, uint32_t c, uint32_t material) {
  mesh.indices.insert(mesh.indices.end(), {a, b, c});
  mesh.triangleMaterials.push_back(material);
}

// A surface of revolution: the profile's (radius, height) points swept about the y axis in
// `segments` steps. The profile runs from the bottom up the outside, so the surface faces
// outward; a point with radius 0 closes the surface there. smooth: normals are averaged
// across profile points (vases, spheres); otherwise every profile segment keeps its own
// normal, for sharp rims (cylinder caps, lamp shades).
void addLathe(MeshAsset& mesh, const glm::mat4& worldFrom, const std::vector<glm::vec2>& profile,
              int segments, uint32_t material, bool smooth = true) {
  const Placement place(worldFrom);
  auto segmentNormal = [&](size_t i) {
    const glm::vec2 d = profile[i + 1] - profile[i];
    return glm::normalize(glm::vec2(d.y, -d.x));  // (radial, y)
  };
  struct Ring {
    glm::vec2 p, n;
  };
  std::vector<Ring> rings;
  std::vector<std::pair<size_t, size_t>> bands;
  if (smooth) {
    for (size_t i = 0; i < profile.size(); ++i) {
      glm::vec2 n(0.0f);
      if (i > 0) n += segmentNormal(i - 1);
      if (i + 1 < profile.size()) n += segmentNormal(i);
      if (profile[i].x == 0.0f) n = {0.0f, n.y >= 0.0f ? 1.0f : -1.0f};  // a pole
      rings.push_back({profile[i], glm::normalize(n)});
      if (i > 0) bands.emplace_back(i - 1, i);
    }
  } else {
    for (size_t i = 0; i + 1 < profile.size(); ++i) {
      rings.push_back({profile[i], segmentNormal(i)});
      rings.push_back({profile[i + 1], segmentNormal(i)});
      bands.emplace_back(2 * i, 2 * i + 1);
    }
  }
  std::vector<uint32_t> first;  // each ring's first vertex; segments + 1 of them (uv seam)
  for (size_t r = 0; r < rings.size(); ++r) {
    first.push_back(uint32_t(mesh.positions.size()));
    for (int j = 0; j <= segments; ++j) {
      const float phi = 2.0f * kPi * float(j) / float(segments);
      const float s = std::sin(phi), c = std::cos(phi);
      const Ring& ring = rings[r];
      place.vertex(mesh, {ring.p.x * s, ring.p.y, ring.p.x * c},
                   {ring.n.x * s, ring.n.y, ring.n.x * c},
                   {float(j) / float(segments), float(r) / float(rings.size() - 1)});
    }
  }
  for (auto [a, b] : bands) {
    for (int j = 0; j < segments; ++j) {
      const uint32_t a0 = first[a] + uint32_t(j), b0 = first[b] + uint32_t(j);
      // Counter-clockwise from outside: around (+phi), then along the profile.
      if (rings[a].p.x > 0.0f) addTriangle(mesh, a0, a0 + 1, b0 + 1, material);
      if (rings[b].p.x > 0.0f) addTriangle(mesh, a0, b0 + 1, b0, material);
    }
  }
}

// A closed frustum along y: radius r0 at y = -halfHeight, r1 at +halfHeight, flat caps.
void addCylinder(MeshAsset& mesh, const glm::mat4& worldFrom, float r0, float r1, float halfHeight,
                 int segments, uint32_t material) {
  addLathe(mesh, worldFrom,
           {{0, -halfHeight}, {r0, -halfHeight}, {r1, halfHeight}, {0, halfHeight}}, segments,
           material, false);
}

// A UV sphere (an ellipsoid when worldFrom scales).
void addSphere(MeshAsset& mesh, const glm::mat4& worldFrom, float radius, int segments, int stacks,
               uint32_t material) {
  std::vector<glm::vec2> profile;
  for (int i = 0; i <= stacks; ++i) {
    const float theta = kPi * float(i) / float(stacks);
    profile.push_back(
        {i == 0 || i == stacks ? 0.0f : radius * std::sin(theta), -radius * std::cos(theta)});
  }
  addLathe(mesh, worldFrom, profile, segments, material);
}

// The box [-h, h] with edges and corners rounded to radius r (< every h), each quarter arc in
// 2 * arcSteps segments: six face grids whose points are pushed out onto the rounded surface.
// A face covers the first 45 degrees of each arc it borders, sampled uniformly in angle, and
// its neighbor the rest, so faces meet on the same points (no cracks).
void addRoundedBox(MeshAsset& mesh, const glm::mat4& worldFrom, vec3 h, float r, int arcSteps,
                   uint32_t material) {
  const Placement place(worldFrom);
  auto samples = [&](float half) {
    std::vector<float> t;
    for (int i = arcSteps; i >= 0; --i)
      t.push_back(-(half - r) - r * std::tan(0.25f * kPi * float(i) / float(arcSteps)));
    for (int i = 0; i <= arcSteps; ++i)
      t.push_back(half - r + r * std::tan(0.25f * kPi * float(i) / float(arcSteps)));
    return t;
  };
  const vec3 inner = h - vec3(r);
  // Normal axis, sign, and the two in-face axes with u x v = sign * normal axis.
  const int faces[6][4] = {{0, 1, 1, 2},  {0, -1, 2, 1}, {1, 1, 2, 0},
                           {1, -1, 0, 2}, {2, 1, 0, 1},  {2, -1, 1, 0}};
  for (const auto& f : faces) {
    const int a = f[0], u = f[2], v = f[3];
    const std::vector<float> tu = samples(h[u]), tv = samples(h[v]);
    const auto base = uint32_t(mesh.positions.size());
    for (size_t j = 0; j < tv.size(); ++j) {
      for (size_t i = 0; i < tu.size(); ++i) {
        vec3 q;
        q[a] = float(f[1]) * h[a];
        q[u] = tu[i];
        q[v] = tv[j];
        const vec3 core = glm::clamp(q, -inner, inner);
        const vec3 n = glm::normalize(q - core);
        place.vertex(mesh, core + r * n, n,
                     {float(i) / float(tu.size() - 1), float(j) / float(tv.size() - 1)});
      }
    }
    const auto row = uint32_t(tu.size());
    for (uint32_t j = 0; j + 1 < tv.size(); ++j) {
      for (uint32_t i = 0; i + 1 < row; ++i) {
        const uint32_t p = base + j * row + i;
        addTriangle(mesh, p, p + 1, p + row + 1, material);
        addTriangle(mesh, p, p + row + 1, p + row, material);
      }
    }
  }
}

glm::mat4 offset(const glm::mat4& frame, vec3 t) { return glm::translate(frame, t); }
glm::mat4 scaled(const glm::mat4& frame, vec3 s) { return glm::scale(frame, s); }

// Repeatable variety (book sizes, colors, leaves) without <random>'s platform differences.
struct Hash {
  uint32_t state;
  float next() {
    state = state * 1664525u + 1013904223u;
    return float(state >> 8) / float(1u << 24);
  }
  float in(float lo, float hi) { return lo + (hi - lo) * next(); }
};

// A turned leg, foot at y = 0, `height` tall: a slim baluster profile.
void addTurnedLeg(MeshAsset& mesh, const glm::mat4& at, float height, float radius,
                  uint32_t material) {
  std::vector<glm::vec2> profile{{0, 0}};
  constexpr int kSteps = 14;
  for (int i = 0; i <= kSteps; ++i) {
    const float t = float(i) / kSteps;
    const float bulge =
        1.0f + 0.35f * std::exp(-std::pow((t - 0.7f) / 0.08f, 2.0f)) - 0.25f * std::sin(kPi * t);
    profile.push_back({radius * bulge * (0.75f + 0.25f * t), height * t});
  }
  profile.push_back({0, height});
  addLathe(mesh, at, profile, 32, material);
}

struct Palette {
  uint32_t fabric, cushion, pillow, woodLight, woodDark, metal, shade, rug, leaf, pot;
  uint32_t ceramics[3], fruit[3], books[6];
};

// A three-seat sofa, 2.1 m wide, its back to -z, seat front towards +z; frame origin on the
// floor under the seat's center.
void addSofa(MeshAsset& m, const glm::mat4& at, const Palette& p) {
  addRoundedBox(m, offset(at, {0, 0.2f, 0}), {1.05f, 0.12f, 0.43f}, 0.05f, 8, p.fabric);  // base
  for (float s : {-1.0f, 1.0f}) {
    addRoundedBox(m, offset(at, {s * 0.94f, 0.35f, 0}), {0.11f, 0.27f, 0.43f}, 0.08f, 8, p.fabric);
    for (float t : {-1.0f, 1.0f})  // feet
      addCylinder(m, offset(at, {s * 0.95f, 0.04f, t * 0.35f}), 0.025f, 0.03f, 0.04f, 32,
                  p.woodDark);
  }
  addRoundedBox(m, offset(at, {0, 0.55f, -0.33f}), {0.83f, 0.3f, 0.1f}, 0.08f, 8,
                p.fabric);  // back
  for (int i = 0; i < 3; ++i) {
    const float x = -0.55f + 0.55f * float(i);
    addRoundedBox(m, offset(at, {x, 0.39f, 0.06f}), {0.27f, 0.07f, 0.34f}, 0.06f, 6, p.cushion);
    addRoundedBox(m,
                  glm::rotate(offset(at, {x, 0.66f, -0.18f}), glm::radians(-10.0f), vec3(1, 0, 0)),
                  {0.26f, 0.2f, 0.07f}, 0.065f, 6, p.cushion);
  }
  for (float s : {-1.0f, 1.0f})  // throw pillows, tilted against the arms
    addSphere(m,
              scaled(glm::rotate(offset(at, {s * 0.62f, 0.6f, -0.02f}), glm::radians(s * 20.0f),
                                 vec3(0, 0, 1)),
                     {0.18f, 0.17f, 0.07f}),
              1.0f, 64, 32, p.pillow);
}

// A bowl with a rounded rim: out and up along the outside, back down the inside.
void addBowl(MeshAsset& m, const glm::mat4& at, float radius, float height, uint32_t material) {
  std::vector<glm::vec2> profile{{0, 0}};
  constexpr int kSteps = 12;
  for (int i = 0; i <= kSteps; ++i) {  // outside
    const float a = 0.5f * kPi * float(i) / kSteps;
    profile.push_back(
        {0.35f * radius + 0.65f * radius * std::sin(a), height * (1.0f - std::cos(a))});
  }
  const float wall = 0.08f * radius;
  for (int i = kSteps; i >= 0; --i) {  // inside
    const float a = 0.5f * kPi * float(i) / kSteps;
    profile.push_back({0.35f * radius + (0.65f * radius - wall) * std::sin(a),
                       wall + (height - wall) * (1.0f - std::cos(a))});
  }
  profile.push_back({0, wall});
  addLathe(m, at, profile, 96, material);
}

// A closed vase: foot, belly, neck and a flared lip, `height` tall.
void addVase(MeshAsset& m, const glm::mat4& at, float height, float belly, float neck,
             uint32_t material, int segments = 96) {
  std::vector<glm::vec2> profile{{0, 0}};
  constexpr int kSteps = 40;
  for (int i = 0; i <= kSteps; ++i) {
    const float t = float(i) / kSteps;
    const float bulge = std::sin(kPi * std::min(t / 0.75f, 1.0f));
    const float lip = std::max(0.0f, (t - 0.85f) / 0.15f);
    profile.push_back({0.6f * neck + (belly - 0.6f * neck) * bulge * (1.0f - lip) +
                           lip * lip * 0.7f * neck + 0.4f * neck * (t > 0.75f ? 1.0f : t / 0.75f),
                       height * t});
  }
  profile.push_back({0.8f * neck, 0.97f * height});  // the opening, shallow
  profile.push_back({0, 0.94f * height});
  addLathe(m, at, profile, segments, material);
}

// A lamp shade: a thin open frustum with a slight curve, faces out and in.
void addShade(MeshAsset& m, const glm::mat4& at, float r0, float r1, float height,
              uint32_t material) {
  std::vector<glm::vec2> profile;
  constexpr int kSteps = 10;
  auto radius = [&](float t) { return r0 + (r1 - r0) * t + 0.01f * std::sin(kPi * t); };
  for (int i = 0; i <= kSteps; ++i)
    profile.push_back({radius(float(i) / kSteps), height * float(i) / kSteps});
  for (int i = kSteps; i >= 0; --i)
    profile.push_back({radius(float(i) / kSteps) - 0.004f, height * float(i) / kSteps});
  profile.push_back(profile.front());  // close the bottom rim
  addLathe(m, at, profile, 96, material, false);
}

// A floor lamp: a weighted disk base, a pole and a shade (not lit: the scene's only light is
// in the other room).
void addFloorLamp(MeshAsset& m, const glm::mat4& at, const Palette& p) {
  addLathe(m, at,
           {{0, 0},
            {0.16f, 0},
            {0.165f, 0.01f},
            {0.16f, 0.025f},
            {0.1f, 0.04f},
            {0.03f, 0.05f},
            {0.02f, 0.06f},
            {0, 0.06f}},
           96, p.metal);
  addCylinder(m, offset(at, {0, 0.8f, 0}), 0.012f, 0.012f, 0.75f, 32, p.metal);
  addShade(m, offset(at, {0, 1.38f, 0}), 0.23f, 0.15f, 0.32f, p.shade);
}

void addTableLamp(MeshAsset& m, const glm::mat4& at, const Palette& p) {
  addVase(m, at, 0.3f, 0.09f, 0.025f, p.ceramics[0]);
  addCylinder(m, offset(at, {0, 0.36f, 0}), 0.008f, 0.008f, 0.08f, 24, p.metal);
  addShade(m, offset(at, {0, 0.35f, 0}), 0.17f, 0.11f, 0.22f, p.shade);
}

// A chair facing +z: turned legs, a cushioned seat, a back with spindles.
void addChair(MeshAsset& m, const glm::mat4& at, const Palette& p) {
  for (float sx : {-1.0f, 1.0f})
    for (float sz : {-1.0f, 1.0f})
      addTurnedLeg(m, offset(at, {sx * 0.19f, 0, sz * 0.18f}), 0.43f, 0.02f, p.woodLight);
  addRoundedBox(m, offset(at, {0, 0.45f, 0}), {0.23f, 0.025f, 0.22f}, 0.015f, 4, p.woodLight);
  addRoundedBox(m, offset(at, {0, 0.49f, 0.01f}), {0.2f, 0.025f, 0.19f}, 0.02f, 5, p.cushion);
  for (float sx : {-1.0f, 1.0f})  // back posts
    addCylinder(m, offset(at, {sx * 0.19f, 0.72f, -0.19f}), 0.018f, 0.014f, 0.25f, 32, p.woodLight);
  addRoundedBox(m, offset(at, {0, 0.92f, -0.19f}), {0.21f, 0.05f, 0.018f}, 0.012f, 4, p.woodLight);
  for (int i = -1; i <= 1; ++i)
    addCylinder(m, offset(at, {0.09f * float(i), 0.69f, -0.19f}), 0.009f, 0.009f, 0.19f, 24,
                p.woodLight);
}

// A bookcase against a wall, its back to -z, 1.4 m wide and 2 m tall, five shelves of books
// of varied sizes and colors, a vase on three of them.
void addBookcase(MeshAsset& m, const glm::mat4& at, const Palette& p, Hash& hash) {
  constexpr float kHalfW = 0.7f, kDepth = 0.34f, kTop = 2.0f, kBoard = 0.018f;
  for (float s : {-1.0f, 1.0f})
    addRoundedBox(m, offset(at, {s * (kHalfW - kBoard), kTop / 2, kDepth / 2}),
                  {kBoard, kTop / 2, kDepth / 2}, 0.006f, 2, p.woodDark);
  addRoundedBox(m, offset(at, {0, kTop / 2, 0.006f}),
                {kHalfW - 2 * kBoard, kTop / 2 - kBoard, 0.005f}, 0.004f, 1,
                p.woodDark);  // back panel
  constexpr int kShelves = 6;
  for (int s = 0; s < kShelves; ++s) {
    const float y = 0.06f + (kTop - 0.08f) * float(s) / float(kShelves - 1);
    addRoundedBox(m, offset(at, {0, y, kDepth / 2}),
                  {kHalfW - 2 * kBoard, kBoard * 0.8f, kDepth / 2 - 0.005f}, 0.006f, 2, p.woodDark);
    if (s == kShelves - 1) break;  // the top board
    float x = -kHalfW + 2 * kBoard + 0.01f;
    const float right = kHalfW - 2 * kBoard - 0.01f, floorY = y + kBoard * 0.8f;
    int n = 0;
    while (x < right - 0.05f) {
      if (++n == 7 + 4 * s && s % 2 == 0 && right - x > 0.2f) {  // a vase in a gap
        const float r = hash.in(0.05f, 0.07f);
        addVase(m, offset(at, {x + r + 0.01f, floorY, kDepth / 2}), hash.in(0.18f, 0.3f), r,
                0.35f * r, p.ceramics[s % 3], 64);
        x += 2 * r + 0.03f;
        continue;
      }
      const float w = hash.in(0.018f, 0.045f), hgt = hash.in(0.2f, 0.3f), d = hash.in(0.15f, 0.24f);
      addRoundedBox(m, offset(at, {x + w / 2, floorY + hgt / 2 + 0.001f, 0.02f + d / 2}),
                    {w / 2, hgt / 2, d / 2}, 0.003f, 1, p.books[uint32_t(hash.next() * 6) % 6]);
      x += w + 0.002f;
    }
  }
}

// A potted plant: a tapered pot, stems, and flattened-ellipsoid leaves fanning out.
void addPlant(MeshAsset& m, const glm::mat4& at, const Palette& p, Hash& hash) {
  addLathe(m, at,
           {{0, 0},
            {0.13f, 0},
            {0.19f, 0.38f},
            {0.205f, 0.4f},
            {0.2f, 0.42f},
            {0.18f, 0.42f},
            {0.18f, 0.38f},
            {0, 0.38f}},
           96, p.pot, false);
  constexpr int kLeaves = 44;
  for (int i = 0; i < kLeaves; ++i) {
    const float yaw = 2.0f * kPi * (float(i) * 0.618034f - std::floor(float(i) * 0.618034f));
    const float reach = hash.in(0.15f, 0.4f), height = 0.45f + hash.in(0.15f, 0.7f);
    glm::mat4 stem = glm::rotate(offset(at, {0, 0.38f, 0}), yaw, vec3(0, 1, 0));
    const float tilt = std::atan2(reach, height - 0.38f);
    addCylinder(m,
                offset(glm::rotate(stem, tilt, vec3(1, 0, 0)),
                       {0, 0.5f * std::hypot(reach, height - 0.38f), 0}),
                0.004f, 0.003f, 0.5f * std::hypot(reach, height - 0.38f), 8, p.leaf);
    const glm::mat4 leaf = glm::rotate(offset(stem, {0, height - 0.38f, reach + 0.08f}),
                                       hash.in(0.2f, 0.7f), vec3(1, 0, 0));
    addSphere(m, scaled(leaf, {0.045f, 0.004f, 0.11f}), 1.0f, 24, 12, p.leaf);
  }
}

// Veach's door-ajar pair furnished: room A, 6 m x 5.5 m x 2.6 m, is a living room (sofa,
// coffee table on a rug, a dining table with chairs, a bookcase, lamps, vases, a plant) of
// finely tessellated shapes, ~200k triangles; room B holds the only light, a ceiling panel out
// of the camera's sight. The door, hinged on the doorway's +z jamb, is open 12 cm.
SceneAsset furnishedRoom() {
  SceneAsset scene;
  const uint32_t wall = addMaterial(scene, "wall", vec3(0.75f, 0.73f, 0.7f));
  const uint32_t floor = addMaterial(scene, "floor", vec3(0.45f, 0.33f, 0.23f));
  const uint32_t door = addMaterial(scene, "door", vec3(0.55f, 0.38f, 0.22f));
  Palette p{};
  p.fabric = addMaterial(scene, "sofa_fabric", vec3(0.25f, 0.32f, 0.45f));
  p.cushion = addMaterial(scene, "cushion", vec3(0.6f, 0.55f, 0.45f));
  p.pillow = addMaterial(scene, "pillow", vec3(0.7f, 0.3f, 0.25f));
  p.woodLight = addMaterial(scene, "wood_light", vec3(0.62f, 0.46f, 0.3f));
  p.woodDark = addMaterial(scene, "wood_dark", vec3(0.3f, 0.22f, 0.2f));
  p.metal = addMaterial(scene, "metal_grey", vec3(0.35f));
  p.shade = addMaterial(scene, "lamp_shade", vec3(0.8f, 0.78f, 0.7f));
  p.rug = addMaterial(scene, "rug", vec3(0.55f, 0.25f, 0.2f));
  p.leaf = addMaterial(scene, "leaf", vec3(0.2f, 0.4f, 0.2f));
  p.pot = addMaterial(scene, "terracotta", vec3(0.6f, 0.35f, 0.25f));
  p.ceramics[0] = addMaterial(scene, "ceramic_blue", vec3(0.2f, 0.35f, 0.55f));
  p.ceramics[1] = addMaterial(scene, "ceramic_white", vec3(0.78f, 0.75f, 0.68f));
  p.ceramics[2] = addMaterial(scene, "ceramic_red", vec3(0.5f, 0.22f, 0.2f));
  p.fruit[0] = addMaterial(scene, "orange", vec3(0.75f, 0.45f, 0.2f));
  p.fruit[1] = addMaterial(scene, "apple", vec3(0.55f, 0.2f, 0.2f));
  p.fruit[2] = addMaterial(scene, "lime", vec3(0.4f, 0.6f, 0.2f));
  const vec3 bookColors[6] = {{0.6f, 0.25f, 0.2f}, {0.2f, 0.3f, 0.5f},   {0.3f, 0.45f, 0.3f},
                              {0.7f, 0.65f, 0.5f}, {0.45f, 0.3f, 0.45f}, {0.25f, 0.25f, 0.25f}};
  for (int i = 0; i < 6; ++i)
    p.books[i] = addMaterial(scene, "book_" + std::to_string(i), bookColors[i]);
  const uint32_t light = addMaterial(scene, "light", vec3(0.78f), vec3(6000.0f, 5520.0f, 4800.0f));

  const RoomPair pair{2.6f, 5.5f, 6.0f, 6.1f, 10.6f, 2.3f, 3.2f, 2.05f};
  addRoomPairShell(scene, pair, wall, floor, floor);
  addDoor(scene, pair, 1.0f, 0.12f, door);  // 90 cm x 200 cm

  Hash hash{12345u};
  // One mesh per piece: each stays under 65536 vertices, so its indices are 16-bit.
  auto piece = [&](const char* name, auto&& build) {
    MeshAsset m;
    m.name = name;
    build(m);
    addMeshNode(scene, name, addMesh(scene, std::move(m)));
  };
  piece("sofa", [&](MeshAsset& m) { addSofa(m, placed({2.0f, 0, 0.5f}, 0), p); });
  piece("rug", [&](MeshAsset& m) {
    addRoundedBox(m, offset(glm::mat4(1.0f), {2.0f, 0.007f, 1.75f}), {1.3f, 0.006f, 0.9f}, 0.005f,
                  2, p.rug);
  });
  piece("coffee_table", [&](MeshAsset& m) {
    const glm::mat4 at = placed({2.0f, 0.013f, 1.65f}, 0);
    addRoundedBox(m, offset(at, {0, 0.4f, 0}), {0.55f, 0.025f, 0.3f}, 0.02f, 6, p.woodLight);
    for (float sx : {-1.0f, 1.0f})
      for (float sz : {-1.0f, 1.0f})
        addTurnedLeg(m, offset(at, {sx * 0.48f, 0, sz * 0.23f}), 0.375f, 0.022f, p.woodLight);
    addBowl(m, offset(at, {-0.15f, 0.425f, 0}), 0.16f, 0.07f, p.ceramics[1]);
    const vec3 fruit[7] = {{-0.2f, 0.49f, 0.03f},  {-0.1f, 0.49f, -0.04f}, {-0.14f, 0.49f, 0.08f},
                           {-0.2f, 0.49f, -0.08f}, {-0.08f, 0.49f, 0.06f}, {-0.15f, 0.55f, 0.0f},
                           {-0.25f, 0.5f, -0.0f}};
    for (int i = 0; i < 7; ++i) addSphere(m, offset(at, fruit[i]), 0.038f, 32, 20, p.fruit[i % 3]);
    addVase(m, offset(at, {0.3f, 0.425f, -0.05f}), 0.28f, 0.07f, 0.025f, p.ceramics[0]);
  });
  piece("side_table", [&](MeshAsset& m) {
    const glm::mat4 at = placed({3.45f, 0, 0.45f}, 0);
    addLathe(m, at,
             {{0, 0},
              {0.18f, 0},
              {0.18f, 0.02f},
              {0.05f, 0.04f},
              {0.03f, 0.3f},
              {0.04f, 0.5f},
              {0.22f, 0.52f},
              {0.225f, 0.55f},
              {0, 0.55f}},
             96, p.woodDark, false);
    addTableLamp(m, offset(at, {0, 0.55f, 0}), p);
  });
  piece("floor_lamp", [&](MeshAsset& m) { addFloorLamp(m, placed({0.45f, 0, 0.45f}, 0), p); });
  piece("floor_lamp_2", [&](MeshAsset& m) { addFloorLamp(m, placed({5.55f, 0, 4.1f}, 0), p); });
  piece("bookcase", [&](MeshAsset& m) { addBookcase(m, placed({4.7f, 0, 0.03f}, 0), p, hash); });
  piece("dining_table", [&](MeshAsset& m) {
    const glm::mat4 at = placed({2.7f, 0, 3.8f}, 0);
    std::vector<glm::vec2> top{{0, 0.72f}};  // a disk with a rounded edge, 55 cm radius
    for (int i = 0; i <= 16; ++i) {
      const float a = -0.5f * kPi + kPi * float(i) / 16.0f;
      top.push_back({0.535f + 0.015f * std::cos(a), 0.735f + 0.015f * std::sin(a)});
    }
    top.push_back({0, 0.75f});
    addLathe(m, at, top, 128, p.woodLight);
    std::vector<glm::vec2> column{{0, 0}, {0.3f, 0}, {0.3f, 0.02f}};
    for (int i = 0; i <= 24; ++i) {
      const float t = float(i) / 24.0f;
      column.push_back(
          {0.05f + 0.2f * std::pow(1.0f - t, 6.0f) + 0.02f * std::sin(3.0f * kPi * t) * t,
           0.02f + 0.7f * t});
    }
    column.push_back({0, 0.72f});
    addLathe(m, at, column, 64, p.woodDark);
    addVase(m, offset(at, {0.1f, 0.75f, 0.05f}), 0.35f, 0.08f, 0.03f, p.ceramics[2]);
  });
  for (int i = 0; i < 4; ++i) {
    const float yaw = 45.0f + 90.0f * float(i);
    const glm::mat4 around =
        glm::rotate(placed({2.7f, 0, 3.8f}, 0), glm::radians(yaw), vec3(0, 1, 0));
    // Each chair 65 cm from the table's center, facing it (+z of the chair towards the axis).
    const std::string name = "chair_" + std::to_string(i);
    piece(name.c_str(), [&](MeshAsset& m) {
      addChair(m, glm::rotate(offset(around, {0, 0, 0.68f}), kPi, vec3(0, 1, 0)), p);
    });
  }
  piece("plant", [&](MeshAsset& m) { addPlant(m, placed({5.5f, 0, 0.5f}, 0), p, hash); });
  piece("floor_vase", [&](MeshAsset& m) {
    addVase(m, placed({0.4f, 0, 2.6f}, 0), 0.6f, 0.14f, 0.05f, p.ceramics[1]);
  });

  // Room B: a cabinet; the light, 60 cm square on the ceiling in the corner farthest from the
  // door, out of the gap's line of sight from room A.
  piece("cabinet", [&](MeshAsset& m) {
    addRoundedBox(m, placed({8.8f, 0.45f, 0.6f}, -15.0f), {0.6f, 0.45f, 0.3f}, 0.02f, 4,
                  p.woodDark);
  });
  addCeilingLight(scene, pair.height, {9.3f, 4.1f}, {9.9f, 4.7f}, light);

  addCamera(scene, {0.45f, 1.6f, 5.1f}, {5.0f, 0.8f, 1.6f}, 1.0f, 16.0f / 9.0f);
  return scene;
}

int write(const std::filesystem::path& dir, const std::string& name, SceneAsset scene,
          size_t maxBytes = 200 * 1024) {
  refreshBounds(scene);
  const std::filesystem::path path = dir / name;
  saveGltf(scene, path, "qlight tools/gen_scenes");
  const SceneAsset back = loadGltf(path);  // throws on anything the loader rejects
  size_t triangles = 0;
  for (const MeshAsset& m : back.meshes) triangles += m.triangleCount();
  const auto bytes = std::filesystem::file_size(path);
  std::printf("%-22s %7zu bytes %5zu triangles %3zu materials %zu warnings\n", name.c_str(),
              size_t(bytes), triangles, back.materials.size(), back.warnings.size());
  return bytes < maxBytes && back.warnings.empty() ? 0 : 1;
}

// The scale test: the Cornell room around one finely tessellated sphere of about
// `triangles` triangles, every one its own (no instancing), for measuring load and BVH build.
SceneAsset tessellatedSphere(uint32_t triangles) {
  SceneAsset scene = cornellBox();
  const uint32_t white = addMaterial(scene, "sphere", vec3(0.7f));
  const int stacks = std::max(4, int(std::sqrt(double(triangles) / 4.0)));
  MeshAsset sphere;
  addSphere(sphere, glm::translate(glm::mat4(1.0f), vec3(0.0f, 0.6f, 0.0f)), 0.5f, 2 * stacks,
            stacks, white);
  addMeshNode(scene, "sphere", addMesh(scene, std::move(sphere)));
  return scene;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Writes the glTF scenes qlight ships"};
  std::string out = "assets";
  bool large = false;
  uint32_t tessellated = 0;
  app.add_option("--out", out, "output directory");
  app.add_option("--tessellated", tessellated,
                 "write only tessellated_sphere.gltf: the Cornell room around a sphere of about "
                 "this many triangles (the scale test; not kept in the repository)");
  app.add_flag("--large", large,
               "write the scenes too large for the repository instead (the build does, into "
               "build/assets)");
  CLI11_PARSE(app, argc, argv);
  try {
    std::filesystem::create_directories(out);
    int failures = 0;
    if (tessellated > 0)
      return write(out, "tessellated_sphere.gltf", tessellatedSphere(tessellated),
                   std::numeric_limits<size_t>::max());
    if (large) {
      failures += write(out, "furnished_room.gltf", furnishedRoom(), 12 * 1024 * 1024);
      return failures == 0 ? 0 : 1;
    }
    failures += write(out, "cornell_box.gltf", cornellBox());
    failures += write(out, "door_ajar.gltf", doorAjar());
    failures += write(out, "animated_light.gltf", animatedLight());
    failures += write(out, "door_ajar_moving_light.gltf", doorAjarMovingLight());
    failures += write(out, "door_ajar_jumping_light.gltf", doorAjarJumpingLight());
    failures += write(out, "many_lights.gltf", manyLights());
    failures += write(out, "corridor.gltf", corridor());
    failures += write(out, "glossy_floor.gltf", glossyFloor());
    if (failures != 0)
      std::fprintf(stderr, "gen_scenes: %d scene(s) too large or warned\n", failures);
    return failures == 0 ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "gen_scenes: %s\n", e.what());
    return 1;
  }
}
