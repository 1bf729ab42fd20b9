// The parts of deformseg._deformseg, one per topic, each in its own file (python/bindings/), each
// adding its classes and functions to the module. module.cpp calls them in the order of this list:
// a class is registered before the functions that take or return it, so that their signatures
// name it (deformseg._deformseg.Animation) rather than its C++ type.
#pragma once

#include <pybind11/pybind11.h>

namespace deformseg::python {

void bind_errors(pybind11::module_& m);          // errors.cpp: InvalidInput, SimilarityStopped
void bind_animation(pybind11::module_& m);       // animation.cpp: Animation, read_animation, clips
void bind_store(pybind11::module_& m);           // store.cpp: MotionStore, open_store
void bind_store_describe(pybind11::module_& m);  // store_describe.cpp: describe_to_store
void bind_strain(pybind11::module_& m);          // strain.cpp: strain
void bind_temporal(pybind11::module_& m);        // temporal.cpp: frame_distances, temporal_segmentation
void bind_spatiotemporal(pybind11::module_& m);  // spatiotemporal.cpp: _evolving_graph
void bind_similarity(pybind11::module_& m);      // similarity.cpp: Similarity, similarity, similarity_matrix
void bind_find_motion(pybind11::module_& m);     // find_motion.cpp: MotionMatch, find_motion
void bind_evaluation(pybind11::module_& m);      // evaluation.cpp: RetrievalScores, evaluate, read_motion_labels
void bind_ged(pybind11::module_& m);             // ged.cpp: GedResult, _ged, EXACT_GED_MAX_EXPANDED

}  // namespace deformseg::python
