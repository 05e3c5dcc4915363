# Renders a glTF scene with Blender's Cycles on the CPU as qlight renders it, for the race in
# tools/race_cycles.sh (issue 10): Lambertian materials (each material's base colour as a
# Diffuse BSDF, its emission as an Emission shader of the same radiance from front faces only),
# no world light, a box pixel filter of one pixel, no denoising, no adaptive sampling, no
# clamping, the same bounce limit. Writes one PFM (linear radiance) per sample count and a JSON
# line per render with its seconds (bpy.ops.render.render, the scene already loaded).
#
#   blender -b -noaudio --python tools/cycles_render.py -- SCENE.gltf OUT_PREFIX WIDTH HEIGHT \
#       MAX_DEPTH THREADS SEED SPP [SPP ...]
import json
import struct
import sys
import time

import bpy
import numpy

# Debian 12's Blender 3.4 glTF importer still uses numpy.bool, which numpy 1.24 removed.
if not hasattr(numpy, "bool"):
    numpy.bool = bool


def lambertian_materials():
    for mat in bpy.data.materials:
        if not mat.use_nodes:
            continue
        nodes = mat.node_tree.nodes
        principled = next((n for n in nodes if n.type == "BSDF_PRINCIPLED"), None)
        if principled is None:
            continue
        if principled.inputs["Base Color"].is_linked:
            raise SystemExit(f"cycles_render: material {mat.name} has a texture (not supported)")
        base = list(principled.inputs["Base Color"].default_value)
        emission = list(principled.inputs["Emission"].default_value)
        strength = principled.inputs["Emission Strength"].default_value
        links = mat.node_tree.links
        for n in list(nodes):
            nodes.remove(n)
        out = nodes.new("ShaderNodeOutputMaterial")
        diffuse = nodes.new("ShaderNodeBsdfDiffuse")
        diffuse.inputs["Color"].default_value = base
        diffuse.inputs["Roughness"].default_value = 0.0  # Lambert, not Oren-Nayar
        if strength > 0.0 and max(emission[:3]) > 0.0:
            # Cycles' mesh emission is two-sided; glTF's (and qlight's) emits from the front
            # face only: the strength is multiplied by 1 - backfacing.
            emit = nodes.new("ShaderNodeEmission")
            emit.inputs["Color"].default_value = emission
            geometry = nodes.new("ShaderNodeNewGeometry")
            front = nodes.new("ShaderNodeMath")
            front.operation = "SUBTRACT"
            front.inputs[0].default_value = 1.0
            links.new(geometry.outputs["Backfacing"], front.inputs[1])
            front_strength = nodes.new("ShaderNodeMath")
            front_strength.operation = "MULTIPLY"
            front_strength.inputs[1].default_value = strength
            links.new(front.outputs[0], front_strength.inputs[0])
            links.new(front_strength.outputs[0], emit.inputs["Strength"])
            add = nodes.new("ShaderNodeAddShader")
            links.new(diffuse.outputs[0], add.inputs[0])
            links.new(emit.outputs[0], add.inputs[1])
            links.new(add.outputs[0], out.inputs["Surface"])
        else:
            links.new(diffuse.outputs[0], out.inputs["Surface"])


def write_pfm(path, width, height, rgba):
    # Blender's pixels run bottom row first, as PFM's do.
    rgb = numpy.asarray(rgba, dtype=numpy.float32).reshape(height, width, 4)[:, :, :3]
    with open(path, "wb") as f:
        f.write(f"PF\n{width} {height}\n-1.0\n".encode())
        f.write(rgb.astype("<f4").tobytes())


def main():
    args = sys.argv[sys.argv.index("--") + 1:]
    scene_path, prefix = args[0], args[1]
    width, height, max_depth, threads, seed = (int(a) for a in args[2:7])
    spps = [int(a) for a in args[7:]]

    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.import_scene.gltf(filepath=scene_path)
    scene = bpy.context.scene
    cameras = [o for o in scene.objects if o.type == "CAMERA"]
    if not cameras:
        raise SystemExit("cycles_render: the scene has no camera")
    scene.camera = cameras[0]
    lambertian_materials()
    world = bpy.data.worlds.new("black")
    world.use_nodes = False
    world.color = (0.0, 0.0, 0.0)
    scene.world = world

    r = scene.render
    r.engine = "CYCLES"
    r.resolution_x, r.resolution_y, r.resolution_percentage = width, height, 100
    r.threads_mode = "FIXED"
    r.threads = threads
    r.image_settings.file_format = "OPEN_EXR"
    r.image_settings.color_depth = "32"
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    c = scene.cycles
    c.device = "CPU"
    c.use_adaptive_sampling = False
    c.use_denoising = False
    c.max_bounces = c.diffuse_bounces = c.glossy_bounces = max_depth
    c.transmission_bounces = c.volume_bounces = c.transparent_max_bounces = max_depth
    c.sample_clamp_direct = c.sample_clamp_indirect = 0.0
    c.blur_glossy = 0.0
    c.pixel_filter_type = "BOX"
    c.filter_width = 1.0
    c.seed = seed

    for spp in spps:
        c.samples = spp
        exr = f"{prefix}_{spp}.exr"
        r.filepath = exr
        start = time.perf_counter()
        bpy.ops.render.render(write_still=True)
        seconds = time.perf_counter() - start
        image = bpy.data.images.load(exr)
        write_pfm(f"{prefix}_{spp}.pfm", width, height, image.pixels[:])
        bpy.data.images.remove(image)
        print("CYCLES_RESULT " + json.dumps({"spp": spp, "seconds": seconds, "seed": seed}),
              flush=True)


main()
