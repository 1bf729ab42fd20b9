// The motion store as Python holds it (store.cpp binds it as MotionStore): a store opened for
// queries by the front end (frontend/store_search.h), which similarity.cpp and evaluation.cpp take
// where they take animations.
#pragma once

#include "common.h"

#include "frontend/store_search.h"

#include <deformseg/evaluation/retrieval_evaluation.h>
#include <deformseg/store/motion_store.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <functional>
#include <optional>
#include <string>

namespace deformseg::python {

// open_store's choices of `verify`, also in _deformseg._choices for the stub's test.
extern const std::array<frontend::Choice, 2> store_verifications;

// An open store: its clips memory-mapped for as long as the object lives (the arrays it gives
// out are views of the mapping that keep the object alive), and how it was checked when opened,
// which a pickled store is opened with again.
struct Opened_store {
  frontend::Store_search search;
  store::Verify verify = store::Verify::structure;
};

// The similarity of every pair of the store's clips, as described (the tool's `matrix --store`):
// the policy options must be the store's (motion-signature, dtw; `up`, when given, its own); on
// `threads` threads (checked).
pybind11::array stored_similarity_matrix(const Opened_store& store, const frontend::Policy_choice& choice,
                                         const Progress& progress, int threads);

// The retrieval scores of the clips of the labels CSV `labels` as the store holds them (the tool's
// `evaluate LABELS --store S`), the items in the rows' order.
evaluation::Retrieval_scores evaluate_stored(const Opened_store& store, const std::string& labels);

}  // namespace deformseg::python
