"""Renders the shared Cornell box (scenes/cornell-box/test.pbrt) with Blender's Cycles on the CPU.

Run by scripts/compare_peers.sh as a third peer, or by hand:

    blender -b --factory-startup -noaudio --python scripts/cycles_cornell.py -- \
        [--scene PATH/test.pbrt] [--spp N] [--threads T] [--resolution W H] --out OUT.exr

The scene is read from the pbrt-v4 file rather than written out here, so the Blender scene follows the
shared file if it changes. The reader knows only the subset that file uses: transforms (Transform,
ConcatTransform, Translate, Scale, Rotate, LookAt, Identity), a perspective camera, the Film resolution,
the Sampler's pixelsamples, the Integrator's maxdepth, the PixelFilter, diffuse materials with an rgb
reflectance (named or not), "trianglemesh" shapes and "diffuse" area lights with an rgb L. Anything else is
an error, not a silent approximation, so a changed scene cannot quietly render as something else.

What is matched, so that Cycles and the pbrt-v4 renderers see the same scene:
- geometry, albedos and the light's radiance (Diffuse BSDF, an emission shader on the light's front side
  only: pbrt-v4's diffuse area light is one-sided, Cycles' mesh emission is two-sided);
- the camera: pbrt's fov spans the shorter image axis, so Blender's sensor fit is set to that axis;
- the path length (every Cycles bounce limit set to the Integrator's maxdepth);
- the estimator: no denoising, no adaptive sampling, no clamping, no glossy blur, no path guiding, no
  light threshold;
- the pixel filter, as far as Cycles allows (box, Gaussian or Blackman-Harris; see cycles_filter);
- the output: the "Standard" view transform, linear 32-bit EXR, black background.
Prints "cycles_cornell: render seconds S" (the time of the render call alone) after the render, in case
Blender's own "Time:" line is missing from its log.
"""
import argparse
import math
import os
import sys
import time

import bpy
import mathutils


# ---------------------------------------------------------------------------------------------------------
# A tokenizer and reader for the subset of the pbrt-v4 format the Cornell box uses.

# The tokenizer is shared with compare_peers.sh (scripts/pbrt_tokens.py, beside this file).
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pbrt_tokens import tokenize  # noqa: E402


def is_directive(token):
    # Directives are bare words starting with a capital letter; bare values are numbers or true/false.
    return token[0].isalpha() and token[0].isupper()


def number(token):
    return float(token)


def split_statements(tokens):
    """Groups the tokens into (directive, arguments) pairs: a directive's arguments run up to the next
    directive."""
    statements = []
    for token in tokens:
        if is_directive(token):
            statements.append((token, []))
        elif not statements:
            raise SystemExit(f"cycles_cornell: value {token!r} before any directive")
        else:
            statements[-1][1].append(token)
    return statements


def parse_parameters(args):
    """Turns '"type name" value' or '"type name" [ values ]' pairs into {name: (type, [values])}."""
    params = {}
    i = 0
    while i < len(args):
        decl = args[i]
        if not decl.startswith('"'):
            raise SystemExit(f"cycles_cornell: expected a parameter declaration, found {decl!r}")
        parts = decl.strip('"').split()
        if len(parts) != 2:
            raise SystemExit(f"cycles_cornell: bad parameter declaration {decl}")
        ptype, name = parts
        i += 1
        values = []
        if i < len(args) and args[i] == '[':
            i += 1
            while args[i] != ']':
                values.append(args[i])
                i += 1
            i += 1
        else:
            values.append(args[i])
            i += 1
        if ptype in ('float', 'integer', 'rgb', 'blackbody', 'point2', 'vector2', 'point3', 'vector3',
                     'point', 'vector', 'normal', 'normal3'):
            values = [number(v) for v in values]
        elif ptype == 'string':
            values = [v.strip('"') for v in values]
        elif ptype == 'bool':
            values = [v.strip('"') == 'true' for v in values]
        params[name] = (ptype, values)
    return params


def name_and_parameters(directive, args):
    if not args or not args[0].startswith('"'):
        raise SystemExit(f"cycles_cornell: {directive} needs a quoted name")
    return args[0].strip('"'), parse_parameters(args[1:])


def flat_numbers(args):
    return [number(a) for a in args if a not in ('[', ']')]


def param(params, name, default):
    """The first value of a parameter, or the default pbrt-v4 gives it."""
    return params[name][1][0] if name in params else default


# Matrices are mathutils.Matrix (4x4, row-major as written, acting on column vectors).

def pbrt_transform_matrix(values):
    # pbrt lists a matrix column after column (the translation is the last four numbers).
    rows = [[values[col * 4 + row] for col in range(4)] for row in range(4)]
    return mathutils.Matrix(rows)


def look_at(eye, target, up):
    """pbrt's LookAt: the world-to-camera matrix of a left-handed camera looking down +z with +y up."""
    eye, target, up = (mathutils.Vector(v) for v in (eye, target, up))
    forward = (target - eye).normalized()
    right = up.normalized().cross(forward)
    if right.length == 0:
        raise SystemExit("cycles_cornell: LookAt's up vector is parallel to its view direction")
    right.normalize()
    new_up = forward.cross(right)
    camera_to_world = mathutils.Matrix((
        (right.x, new_up.x, forward.x, eye.x),
        (right.y, new_up.y, forward.y, eye.y),
        (right.z, new_up.z, forward.z, eye.z),
        (0, 0, 0, 1)))
    return camera_to_world.inverted()


class Scene:
    """What the reader keeps of the pbrt file."""

    def __init__(self):
        self.world_to_camera = None
        self.fov = 90.0             # pbrt-v4's default
        self.resolution = (1280, 720)
        self.spp = 16
        self.max_depth = 5
        self.filter = ('gaussian', {})
        self.meshes = []            # (world points, triangles, world normals or None, reflectance, emission)


def read_pbrt(path):
    with open(path) as f:
        statements = split_statements(tokenize(f.read()))
    scene = Scene()
    named_materials = {}
    # The graphics state that AttributeBegin/End save: transform, material, area light, orientation.
    state = {'ctm': mathutils.Matrix.Identity(4), 'reflectance': (0.5, 0.5, 0.5), 'emission': None,
             'reverse': False}
    stack = []
    film_params = {}
    in_world = False
    for directive, args in statements:
        if directive == 'WorldBegin':
            in_world = True
            state['ctm'] = mathutils.Matrix.Identity(4)
        elif directive in ('AttributeBegin', 'TransformBegin'):
            stack.append(dict(state))
        elif directive in ('AttributeEnd', 'TransformEnd'):
            state = stack.pop()
        elif directive == 'Identity':
            state['ctm'] = mathutils.Matrix.Identity(4)
        elif directive == 'Transform':
            state['ctm'] = pbrt_transform_matrix(flat_numbers(args))
        elif directive == 'ConcatTransform':
            state['ctm'] = state['ctm'] @ pbrt_transform_matrix(flat_numbers(args))
        elif directive == 'Translate':
            state['ctm'] = state['ctm'] @ mathutils.Matrix.Translation(flat_numbers(args))
        elif directive == 'Scale':
            sx, sy, sz = flat_numbers(args)
            state['ctm'] = state['ctm'] @ mathutils.Matrix.Diagonal((sx, sy, sz, 1))
        elif directive == 'Rotate':
            angle, *axis = flat_numbers(args)
            state['ctm'] = state['ctm'] @ mathutils.Matrix.Rotation(math.radians(angle), 4,
                                                                    mathutils.Vector(axis))
        elif directive == 'LookAt':
            v = flat_numbers(args)
            state['ctm'] = state['ctm'] @ look_at(v[0:3], v[3:6], v[6:9])
        elif directive == 'ReverseOrientation':
            state['reverse'] = not state['reverse']
        elif directive == 'Camera':
            kind, params = name_and_parameters(directive, args)
            if kind != 'perspective':
                raise SystemExit(f"cycles_cornell: only a perspective camera is supported, not {kind}")
            if param(params, 'lensradius', 0.0) != 0.0 or 'screenwindow' in params:
                raise SystemExit("cycles_cornell: lens radius and screen window are not supported")
            scene.fov = param(params, 'fov', 90.0)
            scene.world_to_camera = state['ctm'].copy()
        elif directive == 'Film':
            _, film_params = name_and_parameters(directive, args)
            scene.resolution = (int(param(film_params, 'xresolution', 1280)),
                                int(param(film_params, 'yresolution', 720)))
        elif directive == 'Sampler':
            _, params = name_and_parameters(directive, args)
            scene.spp = int(param(params, 'pixelsamples', 16))
        elif directive == 'Integrator':
            _, params = name_and_parameters(directive, args)
            scene.max_depth = int(param(params, 'maxdepth', 5))
        elif directive == 'PixelFilter':
            scene.filter = name_and_parameters(directive, args)
        elif directive in ('MakeNamedMaterial', 'Material'):
            name, params = name_and_parameters(directive, args)
            kind = param(params, 'type', None) if directive == 'MakeNamedMaterial' else name
            if kind != 'diffuse':
                raise SystemExit(f"cycles_cornell: only diffuse materials are supported, not {kind}")
            if 'reflectance' in params and params['reflectance'][0] != 'rgb':
                raise SystemExit("cycles_cornell: only an rgb reflectance is supported")
            reflectance = tuple(params['reflectance'][1]) if 'reflectance' in params else (0.5, 0.5, 0.5)
            if directive == 'MakeNamedMaterial':
                named_materials[name] = reflectance
            else:
                state['reflectance'] = reflectance
        elif directive == 'NamedMaterial':
            name = args[0].strip('"')
            state['reflectance'] = named_materials[name]
        elif directive == 'AreaLightSource':
            kind, params = name_and_parameters(directive, args)
            if kind != 'diffuse' or 'L' not in params or params['L'][0] != 'rgb':
                raise SystemExit("cycles_cornell: only a diffuse area light with an rgb L is supported")
            if param(params, 'twosided', False):
                raise SystemExit("cycles_cornell: two-sided area lights are not supported")
            if 'power' in params:
                raise SystemExit("cycles_cornell: an area light given by its power is not supported")
            scale = param(params, 'scale', 1.0)
            state['emission'] = tuple(scale * c for c in params['L'][1])
        elif directive == 'Shape':
            kind, params = name_and_parameters(directive, args)
            if kind != 'trianglemesh':
                raise SystemExit(f"cycles_cornell: only trianglemesh shapes are supported, not {kind}")
            scene.meshes.append(world_mesh(params, state))
        else:
            raise SystemExit(f"cycles_cornell: the directive {directive} is not supported")
    for unsupported in ('iso', 'exposuretime', 'whitebalance', 'sensor'):
        if unsupported in film_params:
            raise SystemExit(f"cycles_cornell: the Film's {unsupported} is not supported")
    if scene.world_to_camera is None:
        raise SystemExit("cycles_cornell: the scene has no Camera")
    return scene


def world_mesh(params, state):
    """The mesh in world space, with the facing pbrt-v4 gives its triangles: the winding normal
    cross(p0 - p2, p1 - p2), flipped when the transform swaps handedness or ReverseOrientation is on, and
    then turned to the side of the shading normal N when the mesh has one (pbrt's area lights emit on that
    side only)."""
    ctm = state['ctm']
    p = params['P'][1]
    indices = [int(i) for i in params['indices'][1]]
    points = [ctm @ mathutils.Vector(p[i:i + 3]) for i in range(0, len(p), 3)]
    normal_matrix = ctm.to_3x3().inverted().transposed()
    normals = None
    if 'N' in params:
        n = params['N'][1]
        normals = [(normal_matrix @ mathutils.Vector(n[i:i + 3])) for i in range(0, len(n), 3)]
    flip = (ctm.to_3x3().determinant() < 0) != state['reverse']
    triangles = []
    for t in range(0, len(indices), 3):
        i0, i1, i2 = indices[t:t + 3]
        facing = (points[i0] - points[i2]).cross(points[i1] - points[i2])
        if flip:
            facing = -facing
        if normals is not None:
            shading = normals[i0] + normals[i1] + normals[i2]
            if facing.dot(shading) < 0:
                facing = -facing
        triangles.append(((i0, i1, i2), facing))
    return points, triangles, state['reflectance'], state['emission']


# ---------------------------------------------------------------------------------------------------------
# The Blender scene.

def pbrt_to_blender_world(world_to_camera):
    """A fixed orthogonal map from pbrt's world to Blender's, chosen so that the camera comes out as a
    proper rigid motion. pbrt's camera space is left-handed (x right, y up, z forward) and Blender's
    camera is right-handed (x right, y up, looking down -z): Blender's camera space is pbrt's with z
    negated. Blender's camera-to-world matrix is then W * inverse(world_to_camera) * diag(1, 1, -1); when
    pbrt's world-to-camera has a positive determinant that product would be a reflection, which a Blender
    camera cannot be, so the world is mirrored instead (a mirror image of a scene of diffuse surfaces, seen
    through the mirrored camera, is the same image). Either way pbrt's +y (up in these scenes) becomes
    Blender's +z."""
    y_up_to_z_up = mathutils.Matrix(((1, 0, 0, 0), (0, 0, -1, 0), (0, 1, 0, 0), (0, 0, 0, 1)))
    mirror_y = mathutils.Matrix.Diagonal((1, -1, 1, 1))
    flip_z = mathutils.Matrix.Diagonal((1, 1, -1, 1))
    camera_linear = (world_to_camera.inverted() @ flip_z).to_3x3()
    if camera_linear.determinant() > 0:
        return y_up_to_z_up
    return mirror_y @ y_up_to_z_up


def cycles_filter(kind, params):
    """Cycles offers box, Gaussian and Blackman-Harris pixel filters with one "filter_width"; both Cycles
    and pbrt-v4 importance-sample the filter, so only its shape matters. What the width means differs by
    filter (Cycles' film.cpp scales it before tabulating the filter over [-width/2, width/2]): a box
    spans the width itself; a Gaussian is tabulated over three times the width, exp(-2 (2 v / width)^2),
    a standard deviation of width / 4; Blackman-Harris is tabulated over twice the width, so the width is
    its radius. Hence: pbrt's box of radius r is a Cycles box of width 2 r; pbrt's Gaussian of sigma s a
    Cycles Gaussian of width 4 s. pbrt's triangle of radius r has no Cycles equivalent: Blackman-Harris
    (compact support and a bell shape, like the triangle) is used with the radius that gives it the
    triangle's variance r^2 / 6, about 1.47 r. The variance of a Blackman-Harris window, in units of its
    full width squared, is (a0 / 12 - a1 / (2 pi^2) + a2 / (8 pi^2) - a3 / (18 pi^2)) / a0."""
    if kind == 'box':
        return 'BOX', 2 * param(params, 'xradius', 0.5)
    if kind == 'gaussian':
        return 'GAUSSIAN', 4 * param(params, 'sigma', 0.5)
    if kind == 'triangle':
        radius = param(params, 'xradius', 2.0)
        a0, a1, a2, a3 = 0.35875, 0.48829, 0.14128, 0.01168
        pi2 = math.pi ** 2
        unit_variance = (a0 / 12 - a1 / (2 * pi2) + a2 / (8 * pi2) - a3 / (18 * pi2)) / a0
        full_width = math.sqrt(radius * radius / 6 / unit_variance)
        return 'BLACKMAN_HARRIS', full_width / 2
    raise SystemExit(f"cycles_cornell: no Cycles counterpart for the {kind} pixel filter")


def diffuse_material(name, reflectance, emission):
    material = bpy.data.materials.new(name)
    material.use_nodes = True
    nodes, links = material.node_tree.nodes, material.node_tree.links
    nodes.clear()
    output = nodes.new('ShaderNodeOutputMaterial')
    diffuse = nodes.new('ShaderNodeBsdfDiffuse')
    diffuse.inputs['Color'].default_value = (*reflectance, 1.0)
    diffuse.inputs['Roughness'].default_value = 0.0     # Lambertian, as pbrt's diffuse
    if emission is None:
        links.new(diffuse.outputs['BSDF'], output.inputs['Surface'])
        return material
    # Front faces emit and reflect; back faces only reflect (pbrt's area light is one-sided).
    emit = nodes.new('ShaderNodeEmission')
    emit.inputs['Color'].default_value = (*emission, 1.0)
    emit.inputs['Strength'].default_value = 1.0         # strength 1: the colour is the radiance
    add = nodes.new('ShaderNodeAddShader')
    links.new(diffuse.outputs['BSDF'], add.inputs[0])
    links.new(emit.outputs['Emission'], add.inputs[1])
    geometry = nodes.new('ShaderNodeNewGeometry')
    front_or_back = nodes.new('ShaderNodeMixShader')
    links.new(geometry.outputs['Backfacing'], front_or_back.inputs['Fac'])
    links.new(add.outputs['Shader'], front_or_back.inputs[1])
    links.new(diffuse.outputs['BSDF'], front_or_back.inputs[2])
    links.new(front_or_back.outputs['Shader'], output.inputs['Surface'])
    return material


def build_blender_scene(pbrt, spp, threads, resolution):
    # Start from an empty scene: --factory-startup still brings the default cube, light and camera.
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj, do_unlink=True)
    scene = bpy.context.scene
    world_map = pbrt_to_blender_world(pbrt.world_to_camera)
    normal_map = world_map.to_3x3()   # orthogonal, so it maps normals as it maps points

    for index, (points, triangles, reflectance, emission) in enumerate(pbrt.meshes):
        vertices = [tuple(world_map @ p) for p in points]
        faces = []
        for (i0, i1, i2), facing in triangles:
            # Blender's front face is the counter-clockwise one; order the corners so that it is the
            # side pbrt's triangle faces (the map may be a mirror, which reverses windings).
            wanted = normal_map @ facing
            a, b, c = (mathutils.Vector(vertices[i]) for i in (i0, i1, i2))
            if (b - a).cross(c - a).dot(wanted) < 0:
                i1, i2 = i2, i1
            faces.append((i0, i1, i2))
        mesh = bpy.data.meshes.new(f"mesh{index}")
        mesh.from_pydata(vertices, [], faces)
        mesh.update()
        obj = bpy.data.objects.new(f"mesh{index}", mesh)
        obj.data.materials.append(diffuse_material(f"material{index}", reflectance, emission))
        scene.collection.objects.link(obj)

    width, height = resolution
    camera_data = bpy.data.cameras.new("camera")
    camera_data.type = 'PERSP'
    camera_data.lens_unit = 'FOV'
    camera_data.clip_start = 1e-3
    camera_data.clip_end = 1e6
    # pbrt's fov is the angle across the shorter image side.
    if height <= width:
        camera_data.sensor_fit = 'VERTICAL'
        camera_data.angle_y = math.radians(pbrt.fov)
    else:
        camera_data.sensor_fit = 'HORIZONTAL'
        camera_data.angle_x = math.radians(pbrt.fov)
    camera = bpy.data.objects.new("camera", camera_data)
    flip_z = mathutils.Matrix.Diagonal((1, 1, -1, 1))
    camera.matrix_world = world_map @ pbrt.world_to_camera.inverted() @ flip_z
    scene.collection.objects.link(camera)
    scene.camera = camera

    world = bpy.data.worlds.new("black")
    world.use_nodes = True
    world.node_tree.nodes['Background'].inputs['Strength'].default_value = 0.0
    scene.world = world

    render = scene.render
    render.engine = 'CYCLES'
    render.resolution_x, render.resolution_y = width, height
    render.resolution_percentage = 100
    render.pixel_aspect_x = render.pixel_aspect_y = 1.0
    render.film_transparent = False
    render.use_persistent_data = False
    render.threads_mode = 'FIXED' if threads > 0 else 'AUTO'
    if threads > 0:
        render.threads = threads

    cycles = scene.cycles
    cycles.device = 'CPU'
    cycles.samples = spp
    cycles.use_adaptive_sampling = False
    cycles.use_denoising = False
    cycles.seed = 0
    cycles.use_animated_seed = False
    cycles.sample_clamp_direct = 0.0      # 0 turns the clamp off (the indirect default is 10)
    cycles.sample_clamp_indirect = 0.0
    cycles.blur_glossy = 0.0
    cycles.light_sampling_threshold = 0.0
    cycles.caustics_reflective = True
    cycles.caustics_refractive = True
    for bounces in ('max_bounces', 'diffuse_bounces', 'glossy_bounces', 'transmission_bounces',
                    'volume_bounces', 'transparent_max_bounces'):
        setattr(cycles, bounces, pbrt.max_depth)
    if hasattr(cycles, 'use_guiding'):
        cycles.use_guiding = False
    filter_type, filter_width = cycles_filter(*pbrt.filter)
    cycles.pixel_filter_type = filter_type
    cycles.filter_width = filter_width

    # Linear radiance out: no view transform, no look, no exposure.
    scene.display_settings.display_device = 'sRGB'
    scene.view_settings.view_transform = 'Standard'
    scene.view_settings.look = 'None'
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    image = render.image_settings
    image.file_format = 'OPEN_EXR'
    image.color_mode = 'RGB'
    image.color_depth = '32'
    image.exr_codec = 'ZIP'
    return scene, filter_type, filter_width


def main():
    argv = sys.argv[sys.argv.index('--') + 1:] if '--' in sys.argv else []
    parser = argparse.ArgumentParser(prog='cycles_cornell.py',
                                     description="Render the shared Cornell box with Cycles (CPU).")
    shared = os.environ.get('ILLUM_SHARED_DIR',
                            os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'shared'))
    parser.add_argument('--scene', default=os.path.join(shared, 'scenes', 'cornell-box', 'test.pbrt'),
                        help="the pbrt-v4 file (default: $ILLUM_SHARED_DIR or ../shared, "
                             "scenes/cornell-box/test.pbrt)")
    parser.add_argument('--spp', type=int, default=0, help="samples per pixel (default: the scene's)")
    parser.add_argument('--threads', type=int, default=0, help="render threads (default: all cores)")
    parser.add_argument('--resolution', type=int, nargs=2, metavar=('W', 'H'),
                        help="image size (default: the scene's)")
    parser.add_argument('--out', required=True, help="the linear EXR to write")
    options = parser.parse_args(argv)

    pbrt = read_pbrt(options.scene)
    spp = options.spp or pbrt.spp
    resolution = tuple(options.resolution) if options.resolution else pbrt.resolution
    scene, filter_type, filter_width = build_blender_scene(pbrt, spp, options.threads, resolution)
    print(f"cycles_cornell: {len(pbrt.meshes)} meshes, {resolution[0]}x{resolution[1]}, {spp} spp, "
          f"max bounces {pbrt.max_depth}, fov {pbrt.fov}, filter {filter_type} width {filter_width:.3f}",
          flush=True)
    scene.render.filepath = os.path.abspath(options.out)
    start = time.perf_counter()
    bpy.ops.render.render(write_still=True)
    print(f"cycles_cornell: render seconds {time.perf_counter() - start:.3f}", flush=True)


main()
