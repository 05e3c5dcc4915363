// Writes the scenes qlight ships (assets/*.gltf): the Cornell box, the "door ajar" room pair
// (Veach's hard case, used by Dahm & Keller and van Mastrigt), the Cornell box with a light
// moving along a looping animation, and a room with over a hundred small lights.
// Units are meters, +Y is up; emitters are quads whose front (counter-clockwise) side faces
// into the room. Every file is reloaded with loadGltf after writing as a check.
//
//   gen_scenes [--out DIR]      (DIR defaults to ./assets)
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <string>

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

// Two 4 m x 4 m rooms, 2.5 m high, side by side along x, joined by an 80 cm doorway in a
// 10 cm wall. The door slab, hinged on the doorway's +z side, is swung 7.2 degrees into room
// A: its free edge stands 10 cm from the jamb. The only light, a ceiling panel in room B,
// cannot be seen from the camera in room A; every light path to the camera passes the gap.
SceneAsset doorAjar() {
  SceneAsset scene;
  const uint32_t wall = addMaterial(scene, "wall", vec3(0.75f));
  const uint32_t floor = addMaterial(scene, "floor", vec3(0.5f, 0.45f, 0.4f));
  const uint32_t wood = addMaterial(scene, "door", vec3(0.55f, 0.38f, 0.22f));
  const uint32_t furniture = addMaterial(scene, "furniture", vec3(0.3f, 0.4f, 0.6f));
  // Bright: only a sliver of it reaches the first room through the gap, and that room
  // should render at an ordinary exposure (radiance ~0.1, where relative MSE is meaningful).
  const uint32_t light = addMaterial(scene, "light", vec3(0.78f), vec3(2000.0f, 1840.0f, 1600.0f));

  constexpr float kHeight = 2.5f, kDepth = 4.0f;
  constexpr float kWallX0 = 4.0f, kWallX1 = 4.1f, kEndX = 8.1f;
  constexpr float kDoorZ0 = 1.6f, kDoorZ1 = 2.4f, kDoorTop = 2.0f;

  MeshAsset rooms;
  rooms.name = "rooms";
  // The shell of both rooms, seen from inside.
  const vec3 half(kEndX / 2, kHeight / 2, kDepth / 2);
  addBox(rooms, glm::translate(glm::mat4(1.0f), half), half, wall, true, kBoxAllFaces & ~kBoxMinY);
  addQuad(rooms, {0, 0, kDepth}, {kEndX, 0, kDepth}, {kEndX, 0, 0}, {0, 0, 0}, floor);
  // The dividing wall: its two faces with the doorway cut out, the doorway's jambs and lintel.
  for (float x : {kWallX0, kWallX1}) {
    const bool facesA = x == kWallX0;  // the face towards room A points -x
    auto quad = [&](float z0, float z1, float y0, float y1) {
      if (facesA) {
        addQuad(rooms, {x, y0, z0}, {x, y0, z1}, {x, y1, z1}, {x, y1, z0}, wall);
      } else {
        addQuad(rooms, {x, y0, z1}, {x, y0, z0}, {x, y1, z0}, {x, y1, z1}, wall);
      }
    };
    quad(0.0f, kDoorZ0, 0.0f, kHeight);
    quad(kDoorZ1, kDepth, 0.0f, kHeight);
    quad(kDoorZ0, kDoorZ1, kDoorTop, kHeight);
  }
  // Jambs face into the doorway; the lintel's underside faces down.
  addQuad(rooms, {kWallX0, 0, kDoorZ0}, {kWallX1, 0, kDoorZ0}, {kWallX1, kDoorTop, kDoorZ0},
          {kWallX0, kDoorTop, kDoorZ0}, wall);  // +z
  addQuad(rooms, {kWallX1, 0, kDoorZ1}, {kWallX0, 0, kDoorZ1}, {kWallX0, kDoorTop, kDoorZ1},
          {kWallX1, kDoorTop, kDoorZ1}, wall);  // -z
  addQuad(rooms, {kWallX0, kDoorTop, kDoorZ0}, {kWallX1, kDoorTop, kDoorZ0},
          {kWallX1, kDoorTop, kDoorZ1}, {kWallX0, kDoorTop, kDoorZ1}, wall);  // -y
  addMeshNode(scene, "rooms", addMesh(scene, rooms));

  // Door: 80 cm x 198 cm x 4 cm; in its own frame the hinge edge is the y axis and the slab
  // extends along -z with its thickness along -x (closed, it would lie flat against room A's
  // side of the wall). The node turns it about the hinge.
  MeshAsset door;
  door.name = "door";
  const float width = kDoorZ1 - kDoorZ0;
  addBox(door, glm::translate(glm::mat4(1.0f), {-0.02f, 0.005f + 0.99f, -width / 2}),
         {0.02f, 0.99f, width / 2}, wood);
  NodeAsset doorNode;
  doorNode.name = "door";
  doorNode.mesh = int32_t(addMesh(scene, door));
  doorNode.local.translation = {kWallX0, 0.0f, kDoorZ1};
  const float gap = 0.10f;
  const float ajar = 2.0f * std::asin(gap / (2.0f * width));  // chord of the swing = gap
  doorNode.local.rotation = glm::angleAxis(ajar, vec3(0, 1, 0));
  addNode(scene, doorNode);

  // A little furniture in each room.
  MeshAsset blocks;
  blocks.name = "furniture";
  addBox(blocks, placed({1.6f, 0.4f, 1.0f}, 10.0f), {0.6f, 0.4f, 0.4f}, furniture);
  addBox(blocks, placed({0.5f, 0.6f, 0.5f}, 0.0f), {0.35f, 0.6f, 0.35f}, furniture);
  addBox(blocks, placed({6.5f, 0.5f, 1.2f}, -20.0f), {0.5f, 0.5f, 0.5f}, furniture);
  addMeshNode(scene, "furniture", addMesh(scene, blocks));

  // The light: 60 cm square on room B's ceiling, far from the door's line of sight.
  MeshAsset lamp;
  lamp.name = "ceiling_light";
  const float y = kHeight - 0.005f;
  addQuad(lamp, {6.6f, y, 2.9f}, {7.2f, y, 2.9f}, {7.2f, y, 3.5f}, {6.6f, y, 3.5f}, light);
  addMeshNode(scene, "ceiling_light", addMesh(scene, lamp));

  addCamera(scene, {0.4f, 1.5f, 3.6f}, {4.0f, 1.0f, 1.8f}, 1.0f, 16.0f / 9.0f);
  return scene;
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

int write(const std::filesystem::path& dir, const std::string& name, SceneAsset scene) {
  refreshBounds(scene);
  const std::filesystem::path path = dir / name;
  saveGltf(scene, path, "qlight tools/gen_scenes");
  const SceneAsset back = loadGltf(path);  // throws on anything the loader rejects
  size_t triangles = 0;
  for (const MeshAsset& m : back.meshes) triangles += m.triangleCount();
  const auto bytes = std::filesystem::file_size(path);
  std::printf("%-22s %7zu bytes %5zu triangles %3zu materials %zu warnings\n", name.c_str(),
              size_t(bytes), triangles, back.materials.size(), back.warnings.size());
  return bytes < 200 * 1024 && back.warnings.empty() ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Writes the glTF scenes qlight ships"};
  std::string out = "assets";
  app.add_option("--out", out, "output directory");
  CLI11_PARSE(app, argc, argv);
  try {
    std::filesystem::create_directories(out);
    int failures = 0;
    failures += write(out, "cornell_box.gltf", cornellBox());
    failures += write(out, "door_ajar.gltf", doorAjar());
    failures += write(out, "animated_light.gltf", animatedLight());
    failures += write(out, "many_lights.gltf", manyLights());
    if (failures != 0)
      std::fprintf(stderr, "gen_scenes: %d scene(s) too large or warned\n", failures);
    return failures == 0 ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "gen_scenes: %s\n", e.what());
    return 1;
  }
}
