/// @file spatiotemporal.h
/// @brief Every public header of module `spatiotemporal`, spatio-temporal segmentation: per-frame segments of
/// triangles over a body's layout (shared edges and links between its parts), segment graphs and
/// the evolving graph, the segments' colours and the graphs' DOT files.
#pragma once

#include <deformseg/spatiotemporal/body_layout.h>
#include <deformseg/spatiotemporal/compact_segment_graph.h>
#include <deformseg/spatiotemporal/evolving_graph.h>
#include <deformseg/spatiotemporal/frame_segments.h>
#include <deformseg/spatiotemporal/part_links.h>
#include <deformseg/spatiotemporal/segment_colors.h>
#include <deformseg/spatiotemporal/segment_graph_dot.h>
#include <deformseg/spatiotemporal/spatiotemporal_segments.h>
