# Imports a run's point cache (`rice point-cache --run RUN --out CACHE`) into Blender as an
# animated scene: grains.obj as one mesh, animated by a Mesh Cache modifier reading grains.pc2,
# the scene's frame range and rate set from the cache's run_info.txt. Run by Blender:
#
#   blender --background --python scripts/blender_import.py -- CACHE [--save FILE.blend]
#       [--dump FRAME ... --dump-to FILE.csv]
#
# --save writes the scene to a .blend file to open; --dump writes the evaluated (animated)
# vertex positions at the given scene frames as CSV rows frame,vertex,x,y,z (the round-trip
# test, tests/experiments/render/run_blender_import.sh). Coordinates are the run's: metres,
# z up, as Blender's.
import os
import sys

import bpy


def arguments():
    args = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    if not args:
        sys.exit("blender_import.py: give the point cache's folder after --")
    parsed = {"cache": os.path.abspath(args[0]), "save": None, "dump": [], "dump_to": None}
    key = None
    for a in args[1:]:
        if a in ("--save", "--dump", "--dump-to"):
            key = a[2:].replace("-", "_")
        elif key == "dump":
            parsed["dump"].append(int(a))
        elif key:
            parsed[key] = a
            key = None
    return parsed


def run_info(cache):
    info = {}
    with open(os.path.join(cache, "run_info.txt")) as f:
        for line in f:
            key, _, value = line.partition(": ")
            info[key] = value.strip()
    return info


def read_obj(path):
    """Vertices and triangles of an OBJ of v and f lines, in the file's order."""
    vertices, faces = [], []
    with open(path) as f:
        for line in f:
            if line.startswith("v "):
                vertices.append(tuple(float(x) for x in line.split()[1:4]))
            elif line.startswith("f "):
                faces.append(tuple(int(x.split("/")[0]) - 1 for x in line.split()[1:]))
    return vertices, faces


def import_cache(cache):
    info = run_info(cache)
    vertices, faces = read_obj(os.path.join(cache, "grains.obj"))
    mesh = bpy.data.meshes.new("grains")
    mesh.from_pydata(vertices, [], faces)
    mesh.update()
    grains = bpy.data.objects.new("grains", mesh)
    scene = bpy.context.scene
    scene.collection.objects.link(grains)
    cache_modifier = grains.modifiers.new("point cache", "MESH_CACHE")
    cache_modifier.cache_format = "PC2"
    cache_modifier.filepath = os.path.join(cache, "grains.pc2")
    first, frames = int(info["first_frame"]), int(info["frames"])
    cache_modifier.frame_start = first  # the cache's first sample shows at the run's first frame
    scene.frame_start, scene.frame_end = first, first + frames - 1
    scene.render.fps = round(float(info["fps"]))
    return grains


def dump(grains, frames, path):
    scene = bpy.context.scene
    with open(path, "w") as out:
        out.write("frame,vertex,x,y,z\n")
        for frame in frames:
            scene.frame_set(frame)
            evaluated = grains.evaluated_get(bpy.context.evaluated_depsgraph_get())
            mesh = evaluated.to_mesh()
            for v in mesh.vertices:
                out.write(f"{frame},{v.index},{v.co.x!r},{v.co.y!r},{v.co.z!r}\n")
            evaluated.to_mesh_clear()


def main():
    args = arguments()
    bpy.ops.wm.read_factory_settings(use_empty=True)
    grains = import_cache(args["cache"])
    if args["dump"]:
        dump(grains, args["dump"], args["dump_to"])
    if args["save"]:
        bpy.ops.wm.save_as_mainfile(filepath=os.path.abspath(args["save"]))


main()
