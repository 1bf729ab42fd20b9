"""The sidebar panel of the 3D view (N, tab deformseg): Look, Compare, Find."""
import bpy

from . import module


class DEFORMSEG_UL_neighbours(bpy.types.UIList):
    """The clips the store search found: name, similarity, and a button that loads the clip."""

    def draw_item(self, context, layout, data, item, icon, active_data, active_propname, index):
        row = layout.row(align=True)
        row.label(text=item.clip or item.name.split("/")[-1])
        row.label(text=f"{item.value:.3f}")
        row.operator("deformseg.load_clip", text="", icon='IMPORT').index = index


class DeformsegPanel:
    bl_space_type = 'VIEW_3D'
    bl_region_type = 'UI'
    bl_category = "deformseg"


class DEFORMSEG_PT_main(DeformsegPanel, bpy.types.Panel):
    bl_label = "deformseg"

    def draw(self, context):
        settings = context.scene.deformseg
        layout = self.layout
        try:
            module.load_from_preferences(context)
        except module.ModuleMissing:
            layout.label(text="deformseg module not found:", icon='ERROR')
            layout.label(text="set its folder in the add-on's preferences")
            return
        layout.prop(settings, "whole_character")
        row = layout.row()
        row.prop(settings, "use_range")
        if settings.use_range:
            row = layout.row(align=True)
            row.prop(settings, "frame_first")
            row.prop(settings, "frame_last")
        if settings.status:
            layout.label(text=settings.status, icon='INFO')


class DEFORMSEG_PT_look(DeformsegPanel, bpy.types.Panel):
    bl_label = "Look"
    bl_parent_id = "DEFORMSEG_PT_main"

    def draw(self, context):
        settings = context.scene.deformseg
        layout = self.layout
        layout.prop(settings, "look_mode", expand=True)
        if settings.look_mode == 'DEVIATION':
            layout.prop(settings, "deviation_frame")
        if settings.look_mode == 'SEGMENTS':
            layout.prop(settings, "threshold")
        row = layout.row(align=True)
        row.operator("deformseg.look", icon='BRUSH_DATA')
        row.operator("deformseg.clear", text="", icon='X')
        if settings.temporal_count:
            layout.label(text=f"{settings.temporal_count} temporal segments, {settings.key_frame_count} key frames")


class DEFORMSEG_PT_compare(DeformsegPanel, bpy.types.Panel):
    bl_label = "Compare"
    bl_parent_id = "DEFORMSEG_PT_main"

    def draw(self, context):
        settings = context.scene.deformseg
        layout = self.layout
        layout.prop(settings, "compare_mode", expand=True)
        if settings.compare_mode == 'ACTIONS':
            layout.prop(settings, "action_a")
            layout.prop(settings, "action_b")
        layout.operator("deformseg.compare", icon='ARROW_LEFTRIGHT')
        if settings.has_result:
            col = layout.column(align=True)
            col.label(text=f"Similarity {settings.similarity:.4f}")
            col.label(text=f"z-score {settings.z_score:.2f}, {settings.alignment_length} aligned frames")
            row = layout.row(align=True)
            row.operator("deformseg.play_in_step", icon='PLAY')
            row.operator("deformseg.stop_in_step", icon='PAUSE')


class DEFORMSEG_PT_find(DeformsegPanel, bpy.types.Panel):
    bl_label = "Find"
    bl_parent_id = "DEFORMSEG_PT_main"

    def draw(self, context):
        settings = context.scene.deformseg
        layout = self.layout
        layout.prop(settings, "store_folder")
        box = layout.box()
        box.prop(settings, "describe_input")
        row = box.row(align=True)
        row.prop(settings, "describe_fps")
        row.operator("deformseg.describe", icon='FILE_NEW')
        row = layout.row(align=True)
        row.prop(settings, "k")
        row.operator("deformseg.find", icon='VIEWZOOM')
        layout.template_list("DEFORMSEG_UL_neighbours", "", settings, "neighbours", settings, "neighbour_index", rows=3)
        layout.prop(settings, "onto_active")


classes = (DEFORMSEG_UL_neighbours, DEFORMSEG_PT_main, DEFORMSEG_PT_look, DEFORMSEG_PT_compare, DEFORMSEG_PT_find)

register, unregister = bpy.utils.register_classes_factory(classes)
