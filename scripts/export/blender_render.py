# Renders a mesh from `fgc export` in Blender, headless, lit and coloured by its vertex colours:
#   blender -b -P scripts/export/blender_render.py -- MESH.ply OUT.png [SIZE] [SAMPLES]
# (Debian: apt-get install blender; Cycles on the CPU, about a minute for a million triangles.)
import math
import sys

import bpy
from mathutils import Vector

argv = sys.argv[sys.argv.index("--") + 1:]
mesh_path, out_path = argv[0], argv[1]
size = int(argv[2]) if len(argv) > 2 else 800
samples = int(argv[3]) if len(argv) > 3 else 32

bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_mesh.ply(filepath=mesh_path)
obj = bpy.context.selected_objects[0]
obj.rotation_euler = (math.radians(90), 0.0, 0.0)   # the graph's y up is Blender's z up
bpy.context.view_layer.update()
mesh = obj.data
mesh.polygons.foreach_set("use_smooth", [True] * len(mesh.polygons))
print(f"imported {mesh_path}: {len(mesh.vertices)} vertices, {len(mesh.polygons)} faces")

# The vertex colours as the base colour (PLY colours are sRGB bytes).
material = bpy.data.materials.new("albedo")
material.use_nodes = True
nodes = material.node_tree.nodes
bsdf = nodes["Principled BSDF"]
bsdf.inputs["Roughness"].default_value = 0.6
if mesh.color_attributes:
    colour = nodes.new("ShaderNodeVertexColor")
    colour.layer_name = mesh.color_attributes[0].name
    material.node_tree.links.new(colour.outputs["Color"], bsdf.inputs["Base Color"])
mesh.materials.append(material)

# Camera three-quarters above, framing the bounding box; a sun and a soft sky.
corners = [obj.matrix_world @ Vector(c) for c in obj.bound_box]
centre = sum(corners, Vector()) / 8.0
radius = max((c - centre).length for c in corners)
scene = bpy.context.scene
camera = bpy.data.objects.new("camera", bpy.data.cameras.new("camera"))
scene.collection.objects.link(camera)
camera.data.lens = 50
camera.location = centre + Vector((1.6, -2.2, 1.3)).normalized() * radius * 2.6
camera.rotation_euler = (centre - camera.location).to_track_quat("-Z", "Y").to_euler()
scene.camera = camera
sun = bpy.data.objects.new("sun", bpy.data.lights.new("sun", "SUN"))
sun.data.energy = 4.0
sun.rotation_euler = (math.radians(40), math.radians(15), math.radians(30))
scene.collection.objects.link(sun)
world = bpy.data.worlds.new("sky")
world.use_nodes = True
world.node_tree.nodes["Background"].inputs["Color"].default_value = (0.42, 0.46, 0.55, 1.0)
world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.6
scene.world = world

scene.render.engine = "CYCLES"
scene.cycles.device = "CPU"
scene.cycles.samples = samples
scene.cycles.use_denoising = False
scene.render.resolution_x = scene.render.resolution_y = size
scene.render.film_transparent = False
scene.view_settings.view_transform = "Filmic"
scene.render.filepath = out_path
bpy.ops.render.render(write_still=True)
print(f"wrote {out_path}")
