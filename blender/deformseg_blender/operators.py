"""The panel's operators. Each long one is a Job: frames are sampled on Blender's main thread, a
frame per timer tick (bpy is not thread-safe), then deformseg computes in a worker thread (its
calls release Python's GIL, so the interface keeps drawing), and the results are put into the
scene on the main thread. Invoked from the interface the job is modal, with a progress bar and
Esc to cancel; executed (scripts, tests, background mode) it runs to the end at once."""
import os
import threading

import bpy
import mathutils
from bpy.props import EnumProperty, IntProperty

from . import analysis, animated, display, frames, module


class Job:
    """A unit of work: what to sample (a list of (mesh objects sampled as one, frame numbers,
    action played while they are, or None)), what to
    compute from the sampled frames (a function of (deformseg, [Frames]), run off the main
    thread), and how to show the result (a function of (context, frames, result))."""

    def __init__(self, samples, compute, apply):
        self.samples = samples
        self.compute = compute
        self.apply = apply


class JobRunner:
    """Runs a Job a step at a time, for a modal operator's timer: each step() samples one frame
    (on the main thread), then starts deformseg in a worker thread and polls it. Knows its
    progress and can be cancelled between steps; the scene's frame and actions are put back."""

    def __init__(self, context, ds, job):
        self.context, self.ds, self.job = context, ds, job
        self.sampled, self.sampler, self.thread, self.outcome = [], None, None, {}
        self.total = sum(len(numbers) for _, numbers, _ in job.samples) or 1
        self.previous_action = None

    @property
    def progress(self):
        """How far the work is, in [0, 1]: sampling is 90 %, deformseg's computation the rest."""
        done = sum(len(f.frame_numbers) for f in self.sampled) + (len(self.sampler.positions) if self.sampler else 0)
        return 1.0 if "result" in self.outcome else 0.9 * done / self.total

    @property
    def message(self):
        if len(self.sampled) < len(self.job.samples):
            objects = self.job.samples[len(self.sampled)][0]
            return f"deformseg: sampling {objects[0].name}, {int(100 * self.progress)} % (Esc cancels)"
        return "deformseg: computing... (Esc cancels)"

    def step(self):
        """One step of the work; True when it is over (the result or the error is in outcome)."""
        if len(self.sampled) < len(self.job.samples):
            self._sample_step()
            return False
        if self.thread is None:
            self.thread = threading.Thread(target=self._compute, daemon=True)
            self.thread.start()
            return False
        return not self.thread.is_alive()

    def _sample_step(self):
        """Samples one frame of the current object; moves to the next object when it is done."""
        objects, numbers, action = self.job.samples[len(self.sampled)]
        if self.sampler is None:
            if action is not None:  # comparing two actions: this one plays while it is sampled
                owner = animated.animation_owner(objects[0])
                self.previous_action = animated.active_action(objects[0])
                (owner.animation_data or owner.animation_data_create()).action = action
            self.sampler = frames.FrameSampler(self.context, objects, numbers)
        try:
            self.sampler.step()
        except Exception:
            self.cancel()
            raise
        if self.sampler.done:
            result = self.sampler.result()
            self.cancel()  # puts the frame and the action back
            self.sampled.append(result)

    def _compute(self):
        try:
            self.outcome["result"] = self.job.compute(self.ds, self.sampled)
        except Exception as error:  # handed to the main thread, which reports it
            self.outcome["error"] = error

    def cancel(self):
        """Stops between steps, the scene's frame and the sampled object's action as they were.
        A deformseg call under way finishes in its thread, unused."""
        if self.sampler is None:
            return
        self.sampler.restore()
        objects, _, action = self.job.samples[len(self.sampled)]
        if action is not None:
            animated.animation_owner(objects[0]).animation_data.action = self.previous_action
        self.sampler = None


class JobOperator:
    """Runs the Job that make_job gives: modal with progress and Esc when invoked from the
    interface, to the end at once when executed (scripts, tests, background mode)."""
    bl_options = {'REGISTER', 'UNDO'}

    def make_job(self, context, ds):
        raise NotImplementedError

    def execute(self, context):
        try:
            ds = module.load_from_preferences(context)
            job = self.make_job(context, ds)
            sampled = []
            for objects, frame_numbers, action in job.samples:
                with animated.playing(objects[0], action):
                    sampled.append(frames.sample(context, objects, frame_numbers))
            return self._finish(context, job, sampled, job.compute(ds, sampled))
        except (module.ModuleMissing, ValueError, RuntimeError, OSError) as error:
            return self._fail(context, error)

    def invoke(self, context, event):
        try:
            ds = module.load_from_preferences(context)
            self._runner = JobRunner(context, ds, self.make_job(context, ds))
        except (module.ModuleMissing, ValueError, OSError) as error:
            return self._fail(context, error)
        context.window_manager.progress_begin(0, 100)
        self._timer = context.window_manager.event_timer_add(0.01, window=context.window)
        context.window_manager.modal_handler_add(self)
        return {'RUNNING_MODAL'}

    def modal(self, context, event):
        runner = self._runner
        if event.type == 'ESC':
            runner.cancel()
            self._end(context)
            self.report({'WARNING'}, "deformseg: cancelled")
            return {'CANCELLED'}
        if event.type != 'TIMER':
            return {'PASS_THROUGH'}
        try:
            over = runner.step()
        except (ValueError, RuntimeError) as error:
            self._end(context)
            return self._fail(context, error)
        context.window_manager.progress_update(int(100 * runner.progress))
        context.workspace.status_text_set(runner.message)
        if not over:
            return {'RUNNING_MODAL'}
        self._end(context)
        if "error" in runner.outcome:
            return self._fail(context, runner.outcome["error"])
        return self._finish(context, runner.job, runner.sampled, runner.outcome["result"])

    def _end(self, context):
        wm = context.window_manager
        wm.event_timer_remove(self._timer)
        wm.progress_end()
        context.workspace.status_text_set(None)

    # -- both ------------------------------------------------------------------------------------
    def _finish(self, context, job, sampled, result):
        message = job.apply(context, sampled, result)
        context.scene.deformseg.status = message
        self.report({'INFO'}, f"deformseg: {message}")
        return {'FINISHED'}

    def _fail(self, context, error):
        message = str(error)
        if type(error).__name__ == "InvalidInput":  # deformseg.InvalidInput: the mesh as sampled
            message = f"deformseg refused the mesh: {message}"
        context.scene.deformseg.status = message
        self.report({'ERROR'}, f"deformseg: {message}")
        return {'CANCELLED'}


def describe(names):
    """Objects in a status line: 'Fox', or 'Knight_Body and 14 more objects'."""
    return names[0] if len(names) == 1 else f"{names[0]} and {len(names) - 1} more objects"


# ---- Look -------------------------------------------------------------------------------------------

class DEFORMSEG_OT_look(JobOperator, bpy.types.Operator):
    """Colour the active object by strain, segments or deviation over its frames; temporal
    segments and key frames as timeline markers"""
    bl_idname = "deformseg.look"
    bl_label = "Colour"

    mode: EnumProperty(name="Colour by", items=[('SETTINGS', "As the panel says", ""), ('STRAIN', "Strain", ""),
                                                ('SEGMENTS', "Segments", ""), ('DEVIATION', "Deviation", "")],
                       default='SETTINGS')

    @classmethod
    def poll(cls, context):
        return animated.mesh_of(context.object) is not None

    def make_job(self, context, ds):
        settings = context.scene.deformseg
        mode = settings.look_mode if self.mode == 'SETTINGS' else self.mode
        objects = animated.character_meshes(context.object, settings.whole_character)
        obj = objects[0]
        numbers = animated.frames_to_sample(context.scene, settings, obj)
        threshold = settings.threshold
        if mode == 'DEVIATION' and settings.deviation_frame not in numbers:
            raise ValueError(f"frame {settings.deviation_frame} is outside the frames sampled "
                             f"({numbers[0]}-{numbers[-1]})")
        rest = numbers.index(settings.deviation_frame) if mode == 'DEVIATION' else 0

        def compute(ds, sampled):
            anim = analysis.animation(ds, sampled[0])
            result = {"temporal": analysis.temporal_segments(ds, anim),
                      "graph": analysis.evolving_graph(ds, anim, threshold, face_segments=mode == 'SEGMENTS')}
            if mode == 'SEGMENTS':
                result["field"] = result["graph"].face_segments.astype("float32")
            else:
                result["field"] = analysis.strain(ds, anim, rest_frame=rest)
            return result

        def apply(context, sampled, result):
            f = sampled[0]
            kind = "labels" if mode == 'SEGMENTS' else "strain"
            # Labels: each spatio-temporal segment its own colour, rigid (-1) grey.
            display.set_fields(f, result["field"], kind)
            display.show_colours(context)
            scene = context.scene
            display.set_markers(scene, display.temporal_markers(result["temporal"], f.frame_numbers), "temporal")
            display.set_markers(scene, display.key_frame_markers(result["graph"], f.frame_numbers), "keys")
            settings.temporal_count = len(result["temporal"])
            settings.key_frame_count = len(result["graph"].key_frames)
            return (f"{describe(f.objects)} coloured by {mode.lower()} over frames "
                    f"{f.frame_numbers[0]}-{f.frame_numbers[-1]}: {len(result['temporal'])} temporal segments, "
                    f"{len(result['graph'].key_frames)} key frames")

        return Job([(objects, numbers, None)], compute, apply)


class DEFORMSEG_OT_clear(bpy.types.Operator):
    """Take the add-on's colours and markers off the active object and the scene"""
    bl_idname = "deformseg.clear"
    bl_label = "Clear"
    bl_options = {'REGISTER', 'UNDO'}

    def execute(self, context):
        for obj in animated.character_meshes(context.object):
            display.clear_field(obj)
        for group in ("temporal", "keys", "alignment"):
            display.set_markers(context.scene, [], group)
        return {'FINISHED'}


# ---- Compare ----------------------------------------------------------------------------------------

def compared_pair(context):
    """The two (mesh objects, action) to compare, as the panel's mode says."""
    settings = context.scene.deformseg
    whole = settings.whole_character
    objects = animated.character_meshes(context.object, whole)
    if not objects:
        raise ValueError("make a character active (its mesh, or the armature that deforms it)")
    if settings.compare_mode == 'ACTIONS':
        if settings.action_a is None or settings.action_b is None:
            raise ValueError("choose actions A and B")
        return (objects, settings.action_a), (objects, settings.action_b)
    others = {}
    for selected in context.selected_objects:
        meshes = animated.character_meshes(selected, whole)
        if meshes and meshes[0] not in objects:
            others[meshes[0].name] = meshes
    if len(others) != 1:
        raise ValueError("select two characters (the active one is A)")
    return (objects, None), (others.popitem()[1], None)


class DEFORMSEG_OT_compare(JobOperator, bpy.types.Operator):
    """How alike two objects move (or one object's two actions): similarity, alignment, z-score"""
    bl_idname = "deformseg.compare"
    bl_label = "Compare"

    def make_job(self, context, ds):
        settings = context.scene.deformseg
        (objects_a, action_a), (objects_b, action_b) = compared_pair(context)
        obj_a, obj_b = objects_a[0], objects_b[0]
        samples = [(objects, animated.frames_to_sample(context.scene, settings, objects[0], action), action)
                   for objects, action in ((objects_a, action_a), (objects_b, action_b))]

        def compute(ds, sampled):
            return analysis.compare(ds, analysis.animation(ds, sampled[0]), analysis.animation(ds, sampled[1]))

        def apply(context, sampled, similarity):
            fa, fb = sampled[0].frame_numbers, sampled[1].frame_numbers
            pairs = [tuple(p) for p in similarity.alignment]
            settings.similarity = similarity.value
            settings.z_score = similarity.z_score if similarity.z_score is not None else 0.0
            settings.alignment_length = len(pairs)
            settings.has_result = True
            settings.object_a, settings.object_b = obj_a, obj_b
            if pairs:
                display.alignment_curve(context, pairs, fa, fb)
                display.set_markers(context.scene, display.alignment_markers(pairs, fa, fb), "alignment")
                context.scene["deformseg_alignment"] = [list(p) for p in pairs]
                context.scene["deformseg_alignment_frames"] = [list(fa), list(fb)]
            return (f"similarity {similarity.value:.4f}, z-score {settings.z_score:.2f}, "
                    f"{len(pairs)} aligned frames")

        return Job(samples, compute, apply)


class DEFORMSEG_OT_play_in_step(bpy.types.Operator):
    """Play B in step with A along the last comparison's alignment (B's action time keyed to A's
    frames); for one object's two actions, a copy of the character plays B beside it"""
    bl_idname = "deformseg.play_in_step"
    bl_label = "Play in step"
    bl_options = {'REGISTER', 'UNDO'}

    def execute(self, context):
        settings, scene = context.scene.deformseg, context.scene
        if "deformseg_alignment" not in scene or settings.object_b is None:
            self.report({'ERROR'}, "deformseg: compare first")
            return {'CANCELLED'}
        obj_b = settings.object_b
        if settings.object_a == obj_b:  # two actions of one character: a copy plays B
            if settings.action_b is None:
                self.report({'ERROR'}, "deformseg: choose action B")
                return {'CANCELLED'}
            width = max(obj_b.dimensions) * 1.2
            obj_b = animated.duplicate_character(context, obj_b, mathutils.Vector((width, 0.0, 0.0)))
            settings.object_b = obj_b
            animated.animation_owner(settings.object_a).animation_data.action = settings.action_a
            action = settings.action_b
        else:
            owner = animated.animation_owner(obj_b)
            action = animated.active_action(obj_b) or bpy.data.actions.get(owner.get("deformseg_action", ""))
        if action is None:
            self.report({'ERROR'}, f"deformseg: {obj_b.name} plays no action")
            return {'CANCELLED'}
        fa, fb = (list(x) for x in scene["deformseg_alignment_frames"])
        pairs = [tuple(p) for p in scene["deformseg_alignment"]]
        display.play_in_step(animated.animation_owner(obj_b), action, pairs, fa, fb)
        scene.frame_start, scene.frame_end = fa[0], fa[-1]
        return {'FINISHED'}


class DEFORMSEG_OT_stop_in_step(bpy.types.Operator):
    """Play B on its own again"""
    bl_idname = "deformseg.stop_in_step"
    bl_label = "Stop"
    bl_options = {'REGISTER', 'UNDO'}

    def execute(self, context):
        obj = context.scene.deformseg.object_b
        if obj is not None:
            display.stop_in_step(animated.animation_owner(obj))
        return {'FINISHED'}


# ---- Find -------------------------------------------------------------------------------------------

class DEFORMSEG_OT_describe(JobOperator, bpy.types.Operator):
    """Describe clips into the motion store (new ones added, changed ones described again)"""
    bl_idname = "deformseg.describe"
    bl_label = "Describe"

    def make_job(self, context, ds):
        settings = context.scene.deformseg
        store = module.bpy_path(settings.store_folder).rstrip(os.sep)
        source = module.bpy_path(settings.describe_input)
        if not store or not source:
            raise ValueError("give the motion store's folder and the clips to describe")
        fps = settings.describe_fps

        def compute(ds, sampled):
            return ds.describe_to_store(source, store, fps=fps)

        def apply(context, sampled, report):
            return (f"{len(report['described'])} clips described, {len(report['skipped'])} unchanged, into "
                    f"{report['store']}")

        return Job([], compute, apply)


class DEFORMSEG_OT_find(JobOperator, bpy.types.Operator):
    """Search the motion store for the clips that move most like the active object's action"""
    bl_idname = "deformseg.find"
    bl_label = "Find"

    @classmethod
    def poll(cls, context):
        return animated.mesh_of(context.object) is not None

    def make_job(self, context, ds):
        settings = context.scene.deformseg
        store = module.bpy_path(settings.store_folder).rstrip(os.sep)
        if not store:
            raise ValueError("give the motion store's folder (describe clips into it first)")
        objects, k = animated.character_meshes(context.object, settings.whole_character), settings.k
        numbers = animated.frames_to_sample(context.scene, settings, objects[0])

        def compute(ds, sampled):
            return analysis.search(ds, store, analysis.animation(ds, sampled[0]), k)

        def apply(context, sampled, neighbours):
            settings.neighbours.clear()
            for n in neighbours:
                item = settings.neighbours.add()
                item.name, item.path, item.clip, item.value = n["name"], n["path"], n["clip"], n["value"]
            best = f": best {neighbours[0]['clip'] or neighbours[0]['name']} ({neighbours[0]['value']:.3f})" \
                if neighbours else ""
            return f"{len(neighbours)} clips found{best}"

        return Job([(objects, numbers, None)], compute, apply)


class DEFORMSEG_OT_load_clip(bpy.types.Operator):
    """Load this clip: import its file (glTF, FBX) and play the clip, on the active armature when
    its bones have the clip's joints"""
    bl_idname = "deformseg.load_clip"
    bl_label = "Load clip"
    bl_options = {'REGISTER', 'UNDO'}

    index: IntProperty()

    def execute(self, context):
        from . import clips
        settings = context.scene.deformseg
        if not 0 <= self.index < len(settings.neighbours):
            return {'CANCELLED'}
        item = settings.neighbours[self.index]
        try:
            message = clips.load(context, item.path, item.clip, settings.onto_active)
        except (ValueError, RuntimeError, OSError) as error:
            self.report({'ERROR'}, f"deformseg: {error}")
            return {'CANCELLED'}
        settings.status = message
        self.report({'INFO'}, f"deformseg: {message}")
        return {'FINISHED'}


classes = (DEFORMSEG_OT_look, DEFORMSEG_OT_clear, DEFORMSEG_OT_compare, DEFORMSEG_OT_play_in_step,
           DEFORMSEG_OT_stop_in_step, DEFORMSEG_OT_describe, DEFORMSEG_OT_find, DEFORMSEG_OT_load_clip)

register, unregister = bpy.utils.register_classes_factory(classes)
