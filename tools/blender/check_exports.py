# Loads aerial's exports into Blender and renders them with Cycles, headless:
#   blender -b --python tools/blender/check_exports.py -- ENVMAP.exr ENVMAP_WITH_SUN.exr AIR.vdb OUT_DIR
# ENVMAP.exr: `aerial envmap` with the disc left out; ENVMAP_WITH_SUN.exr: `--sun-disc on
# --sun-zenith-deg 60 --sun-azimuth-deg 90`; AIR.vdb: `aerial export-vdb --world-grid ...`.
# It prints what it checked:
#  - the world texture's orientation: a narrow camera looking north 10 degrees up sees the map's
#    texel of that direction by aerial's convention (centre column east, azimuth growing to the
#    right), and one looking east 30 degrees up sees the sun of the second map at its centre;
#  - the VDB recipe of docs/vdb.md: the grids Blender lists, and the air rendered with a Volume
#    Scatter (colour: the `scattering` grid) and a Volume Absorption (colour: 1 - `absorption`),
#    density 1, lit by a white sun lamp from the south, in front of a black world (its mean R, G,
#    B; Debian's Blender 3.4 renders imported VDB volumes black in Cycles, even with a constant
#    density, where a mesh with the same material renders: see docs/vdb.md).
import math
import sys

import bpy

envmap, envmap_sun, vdb, out_dir = sys.argv[sys.argv.index("--") + 1:]


def reset():
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.use_denoising = False
    scene.view_settings.view_transform = "Standard"
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_depth = "32"
    scene.world = bpy.data.worlds.new("world")
    scene.world.use_nodes = True
    return scene


def add_camera(scene, azimuth_deg, elevation_deg, fov_deg, location=(0.0, 0.0, 0.0)):
    data = bpy.data.cameras.new("camera")
    data.angle = math.radians(fov_deg)
    data.clip_end = 1e6
    camera = bpy.data.objects.new("camera", data)
    # Blender's camera looks down -Z: tilt it up to the elevation, then turn it to the compass
    # azimuth (0 north, +Y; 90 east, +X).
    camera.rotation_euler = (math.radians(90.0 + elevation_deg), 0.0, math.radians(-azimuth_deg))
    camera.location = location
    scene.collection.objects.link(camera)
    scene.camera = camera


def render(scene, name, size):
    scene.render.resolution_x, scene.render.resolution_y = size
    scene.render.filepath = f"{out_dir}/{name}.exr"
    bpy.ops.render.render(write_still=True)
    image = bpy.data.images.load(scene.render.filepath)
    width, height = image.size
    pixels = list(image.pixels)
    return width, height, [pixels[i:i + 4] for i in range(0, len(pixels), 4)]


def world_texture(scene, path):
    nodes = scene.world.node_tree.nodes
    texture = nodes.new("ShaderNodeTexEnvironment")
    texture.image = bpy.data.images.load(path)
    texture.interpolation = "Closest"
    nodes["Background"].inputs["Strength"].default_value = 1.0
    scene.world.node_tree.links.new(texture.outputs["Color"], nodes["Background"].inputs["Color"])
    return texture.image


# The world texture, north 10 degrees up: the centre pixel against the map's texel there.
scene = reset()
scene.cycles.samples = 1
image = world_texture(scene, envmap)
add_camera(scene, azimuth_deg=0.0, elevation_deg=10.0, fov_deg=0.5)
width, height, pixels = render(scene, "north", (9, 9))
seen = pixels[4 * 9 + 4]
map_width, map_height = image.size
x = int((0.0 + 90.0) / 360.0 * map_width)  # compass azimuth a at column (a + 90) / 360 of the width
y = int(80.0 / 180.0 * map_height)         # zenith 80 degrees; Blender's rows run bottom to top
texel = list(image.pixels[((map_height - 1 - y) * map_width + x) * 4:][:3])
print("blender: north 10 degrees up renders", [round(v, 5) for v in seen[:3]], "; the map's texel",
      [round(v, 5) for v in texel], "; ratio", [round(a / b, 4) for a, b in zip(seen[:3], texel)])

# The sun of the second map (zenith 60, azimuth 90): at the centre of a camera looking east 30 up.
scene = reset()
scene.cycles.samples = 4
world_texture(scene, envmap_sun)
add_camera(scene, azimuth_deg=90.0, elevation_deg=30.0, fov_deg=4.0)
width, height, pixels = render(scene, "east", (21, 21))
brightest = max(range(len(pixels)), key=lambda i: pixels[i][1])
print("blender: looking east 30 degrees up, the brightest pixel is", (brightest % width, brightest // width),
      "of", (width, height), "at", [round(v, 3) for v in pixels[brightest][:3]], "; the image's mean",
      [round(sum(p[c] for p in pixels) / len(pixels), 4) for c in range(3)])

# The VDB recipe.
scene = reset()
scene.cycles.samples = 16
scene.world.node_tree.nodes["Background"].inputs["Color"].default_value = (0, 0, 0, 1)
bpy.ops.object.volume_import(filepath=vdb, align="WORLD", location=(0, 0, 0))
volume = bpy.context.selected_objects[0]
volume.data.grids.load()
print("blender: the VDB's grids", sorted(g.name for g in volume.data.grids), "; bounds",
      [tuple(round(c) for c in corner) for corner in (volume.bound_box[0], volume.bound_box[6])])
material = bpy.data.materials.new("air")
material.use_nodes = True
nodes, links = material.node_tree.nodes, material.node_tree.links
for node in [n for n in nodes if n.type != "OUTPUT_MATERIAL"]:
    nodes.remove(node)
output = next(n for n in nodes if n.type == "OUTPUT_MATERIAL")
scattering = nodes.new("ShaderNodeAttribute")
scattering.attribute_name = "scattering"
absorption = nodes.new("ShaderNodeAttribute")
absorption.attribute_name = "absorption"
one_minus = nodes.new("ShaderNodeVectorMath")
one_minus.operation = "SUBTRACT"
one_minus.inputs[0].default_value = (1.0, 1.0, 1.0)
links.new(absorption.outputs["Vector"], one_minus.inputs[1])
scatter = nodes.new("ShaderNodeVolumeScatter")
scatter.inputs["Density"].default_value = 1.0
links.new(scattering.outputs["Color"], scatter.inputs["Color"])
absorb = nodes.new("ShaderNodeVolumeAbsorption")
absorb.inputs["Density"].default_value = 1.0
links.new(one_minus.outputs["Vector"], absorb.inputs["Color"])
both = nodes.new("ShaderNodeAddShader")
links.new(scatter.outputs["Volume"], both.inputs[0])
links.new(absorb.outputs["Volume"], both.inputs[1])
links.new(both.outputs["Shader"], output.inputs["Volume"])
volume.data.materials.append(material)
sun = bpy.data.objects.new("sun", bpy.data.lights.new("sun", "SUN"))
sun.data.energy = 1.0
sun.rotation_euler = (math.radians(30.0), 0.0, 0.0)  # shining north and down
bpy.context.collection.objects.link(sun)
add_camera(scene, azimuth_deg=0.0, elevation_deg=4.0, fov_deg=50.0, location=(0.0, -3000.0, 30.0))
scene.camera.data.clip_end = 1e5
width, height, pixels = render(scene, "air", (48, 27))
mean = [sum(p[c] for p in pixels) / len(pixels) for c in range(3)]
print("blender: the air rendered with the recipe, mean R G B", [f"{v:.4g}" for v in mean],
      "; blue / red", round(mean[2] / mean[0], 2) if mean[0] > 0 else "(red is 0)")
