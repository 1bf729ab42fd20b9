"""The Blender add-on, headless: installed from its zip, registered, and its figures on a shared
glTF character imported by Blender's own importer compared with deformseg's on the same clip read
by deformseg itself (the tool's values: the module and the tool are one front end).

Usage (test/blender_addon/run.cmake runs it; DEFORMSEG_TOOL, when set, names the deformseg tool,
whose outputs are compared too):
    blender -b --factory-startup --python-use-system-env --python-exit-code 1 \
        --python test_addon.py -- ADDON.zip Fox.glb OUT [Knight.glb]

The Fox's keys are on 24 fps, so the scene and deformseg both sample it at 24: Blender's frames
are then the file's keys, and the only gap is Blender's float32 skinning. The Knight (its keys on
30 fps) is a character of several objects, measured whole. The gaps measured (printed as "gap"),
with the bounds asserted a little above them.
"""
import json
import os
import subprocess
import sys
import time

import numpy

numpy.bool = bool  # Debian's Blender 3.4 glTF importer needs it (NumPy 1.24 removed the alias)

import addon_utils  # noqa: E402
import bpy  # noqa: E402
import numpy as np  # noqa: E402

ZIP, FOX, OUT, KNIGHT = (sys.argv[sys.argv.index("--") + 1:] + [""])[:4]
TOOL = os.environ.get("DEFORMSEG_TOOL")  # the deformseg tool, when built: compared with too
FPS = 24
STRAIN_BOUND = 1e-4       # normalised strain, in [0, 1]
SIMILARITY_BOUND = 1e-4   # similarity value and store search values
Z_SCORE_BOUND = 2e-3      # the z-score divides the value's gap by the shuffled copies' spread
KNIGHT_STRAIN_BOUND = 5e-4
CELL_SHARE_BOUND = 0.002  # triangle-frames in another segment than deformseg's

started = time.time()
failures = []


def check(condition, what):
    """Records a failure rather than stopping, so one run says everything that is wrong."""
    print(("ok    " if condition else "FAIL  ") + what, flush=True)
    if not condition:
        failures.append(what)


def gap(name, a, b):
    """The largest absolute difference of two arrays, printed."""
    difference = np.abs(np.asarray(a, dtype=np.float64) - np.asarray(b, dtype=np.float64))
    value = float(difference.max()) if difference.size else 0.0
    print(f"gap   {name}: {value:.3g}", flush=True)
    return value


def tool(*arguments):
    """Runs the deformseg tool on the Fox at the test's rate; its standard output."""
    return subprocess.run([TOOL, *arguments, "--fps", str(FPS)], check=True, capture_output=True, text=True).stdout


def install():
    """Installs the zip as a user does (Preferences > Add-ons > Install) and enables it."""
    result = bpy.ops.preferences.addon_install(filepath=ZIP, overwrite=True)
    check(result == {'FINISHED'}, "the add-on installs from its zip")
    addon_utils.enable("deformseg_blender", default_set=True, handle_error=None)
    check("deformseg_blender" in bpy.context.preferences.addons, "the add-on is enabled")
    check(hasattr(bpy.types, "DEFORMSEG_PT_main") and hasattr(bpy.ops.deformseg, "look"),
          "its panel and operators are registered")


def empty_scene(fps):
    """An empty scene at `fps`, the add-on enabled again (factory settings turn it off)."""
    bpy.ops.wm.read_factory_settings(use_empty=True)
    if "deformseg_blender" not in bpy.context.preferences.addons:
        addon_utils.enable("deformseg_blender", default_set=True)
    scene = bpy.context.scene
    scene.render.fps, scene.render.fps_base = fps, 1.0


def import_fox():
    """An empty scene at the Fox's key rate, with the Fox imported by Blender's glTF importer."""
    empty_scene(FPS)
    before = set(bpy.data.objects)
    assert bpy.ops.import_scene.gltf(filepath=FOX) == {'FINISHED'}
    added = [o for o in bpy.data.objects if o not in before]
    mesh = next(o for o in added if o.type == 'MESH')
    armature = next(o for o in added if o.type == 'ARMATURE')
    return mesh, armature


def action_of(armature, clip):
    """The action of a glTF clip: the importer keeps it on an NLA track named as the clip."""
    return next(t.strips[0].action for t in armature.animation_data.nla_tracks if t.name == clip)


def make_active(*objects):
    bpy.ops.object.select_all(action='DESELECT')
    for obj in objects:
        obj.select_set(True)
    bpy.context.view_layer.objects.active = objects[0]


def field_of(obj):
    mesh = obj.data
    return np.array(mesh["deformseg_field"]).reshape(len(mesh["deformseg_frames"]), -1)


def markers(prefix):
    return sorted(((m.frame, m.name) for m in bpy.context.scene.timeline_markers if m.name.startswith(prefix)))


def test_look(ds, fox, armature, walk):
    """Strain, temporal markers, key frame markers, segments and deviation against deformseg."""
    armature.animation_data.action = action_of(armature, "Walk")
    make_active(fox)
    check(bpy.ops.deformseg.look(mode='STRAIN') == {'FINISHED'}, "Look (strain) finishes")
    field = field_of(fox)
    check(field.shape == (walk.num_frames, walk.num_faces),
          f"a strain per frame and triangle: {field.shape} against deformseg's {(walk.num_frames, walk.num_faces)}")
    # The Fox's polygons are its glTF triangles, in the file's order: polygon i is triangle i.
    check(gap("strain", field, ds.strain(walk)) < STRAIN_BOUND, "the strain equals deformseg's")
    if TOOL:
        csv = os.path.join(OUT, "walk-strain.csv")
        tool("strain", FOX + "#Walk", "--out", csv)
        check(gap("strain against the tool", field, np.loadtxt(csv, delimiter=",", ndmin=2)) < STRAIN_BOUND,
              "the strain equals the tool's (deformseg strain --out)")
    mesh = fox.data
    check("deformseg" in mesh.color_attributes and mesh.color_attributes["deformseg"].domain == 'CORNER',
          "the colour attribute exists, on the corners")
    check(mesh.color_attributes.active_color_name == "deformseg", "and it is the active colour")
    colours = []
    for frame in (0, 10):
        bpy.context.scene.frame_set(frame)
        data = np.empty(len(mesh.loops) * 4, dtype=np.float32)
        mesh.color_attributes["deformseg"].data.foreach_get("color", data)
        colours.append(data)
    check(not np.array_equal(*colours), "the colours follow the timeline (frames 0 and 10 differ)")
    values = np.empty(len(mesh.polygons), dtype=np.float32)
    mesh.attributes["deformseg_value"].data.foreach_get("value", values)
    check(np.allclose(values, field[10]), "the face attribute holds frame 10's strain")
    make_active(armature)  # a click on a character often selects its armature: its mesh is measured
    check(bpy.ops.deformseg.clear() == {'FINISHED'} and "deformseg_field" not in mesh, "Clear takes the colours off")
    check(bpy.ops.deformseg.look(mode='STRAIN') == {'FINISHED'} and "deformseg_field" in mesh,
          "Look with the armature active colours its mesh")

    segments = ds.temporal_segmentation(walk)
    expected = sorted((first, f"S{n} {first}-{last}") for n, (first, last) in enumerate(segments))
    check(markers("S") == expected, f"temporal markers as deformseg's segments: {markers('S')} against {expected}")
    graph = ds.evolving_graph(walk)
    expected = sorted((key.first, f"K{n} " + " ".join(node.label for node in key.nodes))
                      for n, key in enumerate(graph.key_frames))
    check(markers("K") == expected,
          f"key frame markers as deformseg's evolving graph: {markers('K')} against {expected}")

    check(bpy.ops.deformseg.look(mode='SEGMENTS') == {'FINISHED'}, "Look (segments) finishes")
    labels = field_of(fox).astype(np.int32)
    reference = ds.evolving_graph(walk, face_segments=True).face_segments
    share = float(np.mean(labels != reference))
    print(f"gap   triangle-frames in another segment than deformseg's: {share:.3g} of {labels.size}", flush=True)
    check(share <= CELL_SHARE_BOUND, "each triangle's segment is deformseg's")
    check(len(np.unique(labels[labels >= 0])) > 1, "the segments are told apart: more than one colour")

    bpy.context.scene.deformseg.deviation_frame = 5
    check(bpy.ops.deformseg.look(mode='DEVIATION') == {'FINISHED'}, "Look (deviation from frame 5) finishes")
    check(gap("deviation from frame 5", field_of(fox), ds.strain(walk, rest_frame=5)) < STRAIN_BOUND,
          "the deviation equals deformseg's strain against frame 5")


def test_compare(ds, fox, armature, walk, run):
    """One object's two actions, then two objects, against deformseg's similarity."""
    reference = ds.similarity(walk, run, significance=20)
    settings = bpy.context.scene.deformseg
    settings.compare_mode = 'ACTIONS'
    settings.action_a, settings.action_b = action_of(armature, "Walk"), action_of(armature, "Run")
    make_active(fox)
    check(bpy.ops.deformseg.compare() == {'FINISHED'}, "Compare (two actions) finishes")
    check(gap("similarity", settings.similarity, reference.value) < SIMILARITY_BOUND, "the similarity is deformseg's")
    check(gap("z-score", settings.z_score, reference.z_score) < Z_SCORE_BOUND, "the z-score is deformseg's")
    if TOOL:
        printed = json.loads(tool("similarity", FOX + "#Walk", FOX + "#Run", "--significance", "20", "--json", "-"))
        check(gap("similarity against the tool", settings.similarity, printed["similarity"]) < SIMILARITY_BOUND
              and gap("z-score against the tool", settings.z_score, printed["z_score"]) < Z_SCORE_BOUND,
              "the similarity and z-score are the tool's")
        check([tuple(p) for p in printed["alignment"]] == [tuple(p) for p in reference.alignment],
              "the alignment is the tool's")
    aligned = [tuple(p) for p in bpy.context.scene["deformseg_alignment"]]
    check(aligned == [tuple(p) for p in reference.alignment], "the alignment is deformseg's")
    check(settings.alignment_length == len(reference.alignment), "the panel gives its length")
    check(bpy.data.objects.get("deformseg alignment") is not None, "the alignment is drawn as a curve")
    check(len(markers("A")) > 0, "and marked on the timeline")
    check(bpy.ops.deformseg.play_in_step() == {'FINISHED'}, "Play in step (two actions) finishes")
    copy = settings.object_b
    copy_armature = next((m.object for m in copy.modifiers if m.type == 'ARMATURE'), None) if copy else None
    check(copy is not None and copy != fox and copy_armature not in (None, armature),
          "a copy of the character plays B")
    if copy_armature is not None:
        check_in_step(copy_armature, reference, "the copy")
        check(armature.animation_data.action == settings.action_a, "while the character plays A")
        for obj in (copy, copy_armature):
            bpy.data.objects.remove(obj)

    # A second Fox playing Run: two objects.
    other, other_armature = import_second_fox()
    armature.animation_data.action = action_of(armature, "Walk")
    other_armature.animation_data.action = action_of(other_armature, "Run")
    settings.compare_mode = 'OBJECTS'
    make_active(fox, other)
    check(bpy.ops.deformseg.compare() == {'FINISHED'}, "Compare (two objects) finishes")
    check(gap("similarity of two objects", settings.similarity, reference.value) < SIMILARITY_BOUND,
          "the similarity of two objects is deformseg's")
    check(bpy.ops.deformseg.play_in_step() == {'FINISHED'}, "Play in step finishes")
    check_in_step(other_armature, reference, "B")
    bpy.ops.deformseg.stop_in_step()
    check(other_armature.animation_data.nla_tracks.get("deformseg in step") is None
          and other_armature.animation_data.action is not None, "Stop puts B's action back")
    for obj in (other, other_armature):
        bpy.data.objects.remove(obj)


def check_in_step(owner, reference, name):
    """owner plays from the in-step NLA track, its strip time at A's frames the aligned B frames."""
    track = owner.animation_data.nla_tracks.get("deformseg in step")
    check(track is not None and owner.animation_data.action is None, f"{name} plays from an in-step NLA track")
    if track is None:
        return
    strip = track.strips[0]
    times = {}
    for frame in (0, 8, 17):
        bpy.context.scene.frame_set(frame)
        times[frame] = strip.strip_time
    pairs = dict(reversed([tuple(p) for p in reference.alignment]))  # the first B frame of each A frame
    expected = {f: pairs[f] for f in times if f in pairs}
    check(all(abs(times[f] - expected[f]) < 1e-4 for f in expected),
          f"{name}'s time follows the alignment: {times} against {expected}")


def import_second_fox():
    before = set(bpy.data.objects)
    assert bpy.ops.import_scene.gltf(filepath=FOX) == {'FINISHED'}
    added = [o for o in bpy.data.objects if o not in before]
    return next(o for o in added if o.type == 'MESH'), next(o for o in added if o.type == 'ARMATURE')


def test_find(ds, fox, armature, walk):
    """Describe the Fox into a store from the panel, search it with the Walk, load the Run."""
    store = os.path.join(OUT, "fox.store")
    settings = bpy.context.scene.deformseg
    settings.store_folder, settings.describe_input, settings.describe_fps = store, FOX, FPS
    check(bpy.ops.deformseg.describe() == {'FINISHED'}, "Describe finishes")
    armature.animation_data.action = action_of(armature, "Walk")
    make_active(fox)
    settings.k = 3
    check(bpy.ops.deformseg.find() == {'FINISHED'}, "Find finishes")
    found = [(n.clip, n.value) for n in settings.neighbours]
    expected = [(n["clip"], n["value"]) for n in ds.open_store(store).search(walk, k=3)["neighbours"]]
    print(f"      found {found}, deformseg {expected}", flush=True)
    check([c for c, _ in found] == [c for c, _ in expected], "the clips found are deformseg's, in its order")
    check(gap("store search values", [v for _, v in found], [v for _, v in expected]) < SIMILARITY_BOUND,
          "with deformseg's values")
    if TOOL:
        printed = json.loads(tool("search", FOX + "#Walk", "--store", store, "-k", "3", "--json", "-"))
        neighbours = [(n["clip"], n["value"]) for n in printed["queries"][0]["neighbours"]]
        check([c for c, _ in found] == [c for c, _ in neighbours] and
              gap("store search against the tool", [v for _, v in found], [v for _, v in neighbours])
              < SIMILARITY_BOUND,
              "the clips found and their values are the tool's (deformseg search --store)")
    run = next(i for i, n in enumerate(settings.neighbours) if n.clip == "Run")
    objects = len(bpy.data.objects)
    settings.onto_active = True
    make_active(armature)
    check(bpy.ops.deformseg.load_clip(index=run) == {'FINISHED'}, "Load clip finishes")
    action = armature.animation_data.action
    check(action is not None and action.name.startswith("Run") and action not in
          [t.strips[0].action for t in armature.animation_data.nla_tracks],
          f"the Run clip is loaded onto the Fox's armature ({action and action.name})")
    check(len(bpy.data.objects) == objects, "and the imported character is removed")


def test_modal_steps(ds, fox, armature, walk):
    """The modal operators' work, step by step as their timer runs it (a window's event loop, which
    background mode lacks): progress rises, the result is the blocking path's, and a cancel puts
    the scene's frame and the object's action back."""
    from types import SimpleNamespace

    from deformseg_blender import operators
    context, scene = bpy.context, bpy.context.scene
    walk_action = action_of(armature, "Walk")
    armature.animation_data.action = walk_action
    make_active(fox)
    scene.frame_set(3)
    job = operators.DEFORMSEG_OT_look.make_job(SimpleNamespace(mode='STRAIN'), context, ds)
    runner = operators.JobRunner(context, ds, job)
    progress = [runner.progress]
    while not runner.step():
        progress.append(runner.progress)
        time.sleep(0.001)  # as the timer's ticks leave the worker thread time
    progress.append(runner.progress)
    sampling = len(set(progress)) - 1
    check(sampling >= walk.num_frames and progress == sorted(progress) and abs(progress[-1] - 1) < 1e-9,
          f"the modal work goes a frame a step, its progress rising to 1: {sorted(set(round(p, 3) for p in progress))}")
    job.apply(context, runner.sampled, runner.outcome["result"])
    check(gap("strain, modal", field_of(fox), ds.strain(walk)) < STRAIN_BOUND, "its strain is deformseg's")
    check(scene.frame_current == 3, "the scene is back on its frame")

    settings = scene.deformseg
    settings.compare_mode = 'ACTIONS'
    settings.action_a, settings.action_b = walk_action, action_of(armature, "Run")
    runner = operators.JobRunner(context, ds, operators.DEFORMSEG_OT_compare.make_job(None, context, ds))
    for _ in range(walk.num_frames + 3):  # into the second action's frames
        runner.step()
    runner.cancel()
    check(scene.frame_current == 3 and armature.animation_data.action == walk_action,
          "a cancel puts the frame and the action back")


def ref_order(frames, reference, tolerance):
    """For each triangle the add-on sampled, the reference's triangle it is: the add-on puts the
    character's objects in name order, deformseg its meshes in the file's order, each mesh's
    triangles in the file's order in both. Each object's block of triangles is found in the
    reference by its triangles' centroids at the first and the middle frame."""
    def centroids(positions, faces):
        middle = len(positions) // 2
        return np.concatenate([positions[0][faces].mean(axis=1), positions[middle][faces].mean(axis=1)], axis=1)
    ours = centroids(frames.positions, frames.faces.astype(np.int64))
    theirs = centroids(reference.frames, reference.faces.astype(np.int64))
    order = []
    for part in range(len(frames.objects)):
        block = ours[frames.triangle_object == part]
        starts = np.flatnonzero(np.abs(theirs - block[0]).max(axis=1) < tolerance)
        start = next((j for j in starts if j + len(block) <= len(theirs) and
                      np.abs(theirs[j:j + len(block)] - block).max() < tolerance), None)
        if start is None:
            raise AssertionError(f"no block of the reference's triangles is {frames.objects[part]}'s")
        order.extend(range(start, start + len(block)))
    return np.array(order)


def test_knight(ds):
    """A character of several objects (body, head, limbs, helmet, cape, weapons on bone slots),
    measured whole as the tool reads the file: the Knight walking, its keys on 30 fps."""
    from deformseg_blender import animated, frames
    empty_scene(30)
    scene = bpy.context.scene
    assert bpy.ops.import_scene.gltf(filepath=KNIGHT) == {'FINISHED'}
    rig = next(o for o in bpy.data.objects if o.type == 'ARMATURE')
    rig.animation_data.action = action_of(rig, "Walking_A")
    make_active(rig)
    check(bpy.ops.deformseg.look(mode='STRAIN') == {'FINISHED'}, "Look on the Knight's rig finishes")
    objects = animated.character_meshes(rig)
    sampled = frames.sample(bpy.context, objects, animated.action_frames(rig.animation_data.action))
    reference = ds.read_animation(KNIGHT, clip="Walking_A", fps=30)
    check(len(objects) > 1 and sampled.faces.shape == reference.faces.shape
          and sampled.positions.shape == reference.frames.shape,
          f"its {len(objects)} objects are one mesh of deformseg's vertices and triangles "
          f"({sampled.positions.shape[1]}, {len(sampled.faces)})")
    field = np.concatenate([field_of(bpy.data.objects[name]) for name in sampled.objects], axis=1)
    diagonal = float(np.linalg.norm(np.ptp(reference.frames.reshape(-1, 3), axis=0)))
    order = ref_order(sampled, reference, 1e-4 * diagonal)
    check(gap("Knight strain", field, ds.strain(reference)[:, order]) < KNIGHT_STRAIN_BOUND,
          "the Knight's strain equals deformseg's")
    segments = ds.temporal_segmentation(reference)
    expected = sorted((first, f"S{n} {first}-{last}") for n, (first, last) in enumerate(segments))
    check(markers("S") == expected, "the Knight's temporal markers are deformseg's segments")
    settings = scene.deformseg
    settings.compare_mode = 'ACTIONS'
    settings.action_a, settings.action_b = action_of(rig, "Walking_A"), action_of(rig, "Running_A")
    check(bpy.ops.deformseg.compare() == {'FINISHED'}, "Compare on the Knight finishes")
    running = ds.read_animation(KNIGHT, clip="Running_A", fps=30)
    expected = ds.similarity(reference, running, significance=20)
    check(gap("Knight similarity", settings.similarity, expected.value) < SIMILARITY_BOUND
          and gap("Knight z-score", settings.z_score, expected.z_score) < Z_SCORE_BOUND,
          "the Knight's walk and run compare as deformseg compares them")


class FakeLayout:
    """Stands for a panel's layout in background mode, where panels are not drawn: records the
    properties, operators and icons a draw() names, so the test can check that they exist."""

    def __init__(self, record):
        self.record = record

    def __getattr__(self, name):  # row, column, box, split: nested layouts
        return lambda *args, **kwargs: FakeLayout(self.record)

    def prop(self, data, name, **kwargs):
        self.record.append(("prop", data, name, kwargs.get("icon")))

    def operator(self, idname, **kwargs):
        self.record.append(("operator", None, idname, kwargs.get("icon")))
        return type("Properties", (), {})()

    def label(self, **kwargs):
        self.record.append(("label", None, kwargs.get("text"), kwargs.get("icon")))

    def template_list(self, list_type, _, data, name, active_data, active_name, **kwargs):
        self.record.append(("prop", data, name, None))
        self.record.append(("prop", active_data, active_name, None))


def test_panel():
    """Every sub-panel draws, in each mode, naming properties, operators and icons that exist."""
    from types import SimpleNamespace

    from deformseg_blender import panel
    icons = set(bpy.types.UILayout.bl_rna.functions["label"].parameters["icon"].enum_items.keys())
    settings = bpy.context.scene.deformseg
    record = []
    for look_mode, compare_mode, result in (('STRAIN', 'OBJECTS', False), ('DEVIATION', 'ACTIONS', True),
                                            ('SEGMENTS', 'OBJECTS', True)):
        settings.look_mode, settings.compare_mode, settings.has_result = look_mode, compare_mode, result
        settings.use_range = result
        for cls in panel.classes[1:]:
            cls.draw(SimpleNamespace(layout=FakeLayout(record)), bpy.context)
    settings.use_range = False
    wrong = []
    for kind, data, name, icon in record:
        if kind == "prop" and name not in data.bl_rna.properties:
            wrong.append(f"property {name}")
        if kind == "operator" and not hasattr(getattr(bpy.ops, name.split(".")[0]), name.split(".")[1]):
            wrong.append(f"operator {name}")
        if icon is not None and icon not in icons:
            wrong.append(f"icon {icon}")
    check(len(record) > 20 and not wrong, f"the panels draw {len(record)} items, none missing: {wrong}")


def test_saved(fox):
    """The colours follow the timeline again in the saved file, opened anew."""
    name = fox.name
    bpy.ops.object.select_all(action='DESELECT')
    fox.select_set(True)
    bpy.context.view_layer.objects.active = fox
    assert bpy.ops.deformseg.look(mode='STRAIN') == {'FINISHED'}
    path = os.path.join(OUT, "saved.blend")
    bpy.ops.wm.save_as_mainfile(filepath=path)
    bpy.ops.wm.open_mainfile(filepath=path)
    fox = bpy.data.objects[name]
    values = np.empty(len(fox.data.polygons), dtype=np.float32)
    rows = []
    for frame in (4, 12):
        bpy.context.scene.frame_set(frame)
        fox.data.attributes["deformseg_value"].data.foreach_get("value", values)
        rows.append(values.copy())
    field = field_of(fox)
    check(np.array_equal(rows[0], field[4]) and np.array_equal(rows[1], field[12]),
          "the saved file's colours follow the timeline when opened again")


def test_messages(fox):
    """A clear message where deformseg is missing, or the mesh changes its triangles over time."""
    from deformseg_blender import module
    saved = sys.modules.get("deformseg")
    sys.modules["deformseg"] = None  # import deformseg now fails, as where it is not installed
    try:
        module.load("")
        check(False, "a missing module raises ModuleMissing")
    except module.ModuleMissing as error:
        check("deformseg module folder" in str(error), f"a missing module says where to point: {error}")
    finally:
        sys.modules["deformseg"] = saved
    bpy.ops.mesh.primitive_plane_add()
    plane = bpy.context.object
    subdivision = plane.modifiers.new("subdivide", 'SUBSURF')
    for frame, level in ((0, 0), (1, 1)):
        subdivision.levels = level
        subdivision.keyframe_insert("levels", frame=frame)
    settings = bpy.context.scene.deformseg
    settings.use_range, settings.frame_first, settings.frame_last = True, 0, 2
    try:  # an operator that reports an error raises it in a script
        result = bpy.ops.deformseg.look(mode='STRAIN')
    except RuntimeError:
        result = {'CANCELLED'}
    check(result == {'CANCELLED'} and "triangles" in settings.status,
          f"a mesh whose triangles change is refused, saying so: {settings.status}")
    settings.use_range = False
    bpy.data.objects.remove(plane)


def main():
    import deformseg as ds
    install()
    fox, armature = import_fox()
    walk = ds.read_animation(FOX, clip="Walk", fps=FPS)
    run = ds.read_animation(FOX, clip="Run", fps=FPS)
    test_panel()
    test_look(ds, fox, armature, walk)
    test_compare(ds, fox, armature, walk, run)
    test_find(ds, fox, armature, walk)
    test_modal_steps(ds, fox, armature, walk)
    test_messages(fox)
    test_saved(fox)
    if KNIGHT and os.path.exists(KNIGHT):
        test_knight(ds)
    else:
        print(f"skip  the Knight (a character of several objects): {KNIGHT or 'not given'} not found", flush=True)
    print(f"blender_addon: {'FAILED: ' + '; '.join(failures) if failures else 'passed'} in "
          f"{time.time() - started:.1f} s", flush=True)
    if failures:
        sys.exit(1)


if __name__ == "__main__":
    try:
        main()
    except Exception:  # Blender exits with 0 after a script's exception: say it, exit 1
        import traceback
        traceback.print_exc()
        sys.stdout.flush()
        sys.exit(1)
