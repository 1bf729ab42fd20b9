#include "store_search.h"

#include "store.h"

namespace deformseg::frontend {
namespace {

// Some clips of a store, in a given order (a search::MotionCollection).
struct Selected_clips {
  const store::Stored_motions* stored;
  std::vector<std::size_t> indices;

  std::size_t size() const { return indices.size(); }
  signatures::Motion_signature_view view(std::size_t i) const { return stored->view(indices[i]); }
  search::Motion_summary_view summary(std::size_t i) const { return stored->summary(indices[i]); }
};

// The first five names, and how many more.
std::string listed_names(const std::vector<std::string>& names) {
  std::string list;
  for (std::size_t k = 0; k < names.size() && k < 5; ++k) list += (k ? ", " : "") + names[k];
  return names.size() > 5 ? list + " and " + std::to_string(names.size() - 5) + " more" : list;
}

}  // namespace

Store_search::Store_search(const std::string& folder, store::Verify verify)
    : clips_(store::Motion_store::open(folder, verify)),
      policy_(store_policy(stored_policy_choice(clips_.store()), Front::command_line)) {}

std::string Store_search::name(std::size_t i) const { return stored_clip_name(store(), i); }

similarity::Motion_signature_description Store_search::describe(const mesh::Surface_mesh_animation& query,
                                                                 int threads) const {
  similarity::Default_similarity policy = policy_;
  policy.signatures.threads = threads;
  return policy.describe(query);
}

search::Nearest_motions Store_search::nearest(const mesh::Surface_mesh_animation& query,
                                                  const search::Nearest_motions_options& options) const {
  if (size() == 0) throw invalid_input("the store holds no clip", {.file = store().folder().string()});
  check_range(options.candidates, "candidates");  // before describing the query
  return nearest(similarity::view(describe(query, options.threads)), options);
}

search::Nearest_motions Store_search::nearest(signatures::Motion_signature_view query,
                                                  const search::Nearest_motions_options& options) const {
  if (size() == 0) throw invalid_input("the store holds no clip", {.file = store().folder().string()});
  check_range(options.candidates, "candidates");
  return search::nearest_motions(query, clips_, options, policy_);
}

search::Nearest_motions Store_search::nearest_to_clip(std::size_t i,
                                                          const search::Nearest_motions_options& options) const {
  if (i >= size())
    throw invalid_input("no clip " + std::to_string(i) + ": the store holds " + std::to_string(size()) + " clips",
                        {.file = store().folder().string()});
  check_range(options.candidates, "candidates");
  return search::nearest_others(clips_, i, options, policy_);
}

std::vector<search::Clip_match> Store_search::find(const mesh::Surface_mesh_animation& query,
                                                      const search::Find_in_collection_options& options) const {
  if (size() == 0) throw invalid_input("the store holds no clip", {.file = store().folder().string()});
  return search::find_motion_in_collection(describe(query, options.threads), clips_, options, policy_);
}

std::vector<search::Nearest_motions> Store_search::knn_graph(
    const search::Nearest_motions_options& options, std::optional<search::Clip_range> rows) const {
  check_range(rows, "rows");
  check_range(options.candidates, "candidates");
  return search::knn_graph(clips_, rows.value_or(search::all_clips(clips_)), options, policy_);
}

Eigen::MatrixXd Store_search::tile(search::Clip_range rows, search::Clip_range columns,
                                   const Progress& progress, int threads) const {
  check_range(rows, "rows");
  check_range(columns, "columns");
  return search::similarity_tile(clips_, rows, columns, policy_, progress, threads);
}

void Store_search::check_range(std::optional<search::Clip_range> range, const char* what) const {
  if (range && (range->begin > range->end || range->end > size()))
    throw invalid_input(std::string("the ") + what + " [" + std::to_string(range->begin) + ", " +
                            std::to_string(range->end) + ") are not clips of the store, which holds " +
                            std::to_string(size()),
                        {.file = store().folder().string()});
}

Eigen::MatrixXd Store_search::matrix(const Progress& progress, int threads) const {
  return search::similarity_matrix(clips_, policy_, progress, threads);
}

Eigen::MatrixXd Store_search::matrix(std::vector<std::size_t> indices, const Progress& progress, int threads) const {
  return search::similarity_matrix(Selected_clips{&clips_, std::move(indices)}, policy_, progress, threads);
}

void Store_search::check_policy(const Policy_choice& asked, Front front) const {
  // What was asked must be the store's; what was not is.
  const signatures::Motion_signature_options wanted = store_policy(asked, front).signatures;  // DTW too
  const signatures::Motion_signature_options& stored = policy_.signatures;
  const std::string where = front == Front::python ? "MotionStore.description"
                                                   : "deformseg store info " + store().folder().string();
  const auto refuse = [&](const std::string& asked_for, const std::string& theirs, const char* them = "it") {
    throw invalid_input(asked_for + " differs from the store's " + theirs + " (" + where + " gives " + them + ")",
                        {.file = store().folder().string()});
  };
  const auto same = [](const std::optional<Eigen::Vector3d>& a, const std::optional<Eigen::Vector3d>& b) {
    return a.has_value() == b.has_value() && (!a || *a == *b);
  };
  if (!asked.up.empty() && !same(wanted.up, stored.up)) refuse(spelled("up", asked.up, front), "up direction");
  if (!asked.sides.empty() && !same(wanted.sides, stored.sides))
    refuse(spelled("sides", asked.sides, front), "sides", "them");
  if (asked.bands && *asked.bands != stored.bands)
    refuse(spelled("bands", front) + " " + std::to_string(*asked.bands), std::to_string(stored.bands));
}

std::vector<std::size_t> Store_search::labelled(const std::string& labels, const std::optional<Input_options>& read,
                                                Front front) const {
  std::vector<std::size_t> indices;
  std::vector<std::string> missing, stale;
  for (const Clip_source& clip : labelled_clips(labels, read.value_or(Input_options{}))) {
    const std::optional<std::size_t> at = find_clip(store(), clip);
    if (!at) {
      missing.push_back(clip.name());
      continue;
    }
    const store::Store_record record = store().record(*at);
    if (!up_to_date(record, clip, read.value_or(recorded_input_options(record)))) stale.push_back(clip.name());
    else indices.push_back(*at);
  }
  if (missing.empty() && stale.empty()) return indices;
  std::string message = "the store does not hold every labelled clip as it is now:";
  if (!missing.empty()) message += " " + std::to_string(missing.size()) + " missing (" + listed_names(missing) + ")";
  if (!stale.empty())
    message += " " + std::to_string(stale.size()) + " changed since described (" + listed_names(stale) + ")";
  const std::string folder = store().folder().string();
  message += front == Front::python
                 ? "; describe them again: deformseg.describe_to_store('" + labels + "', '" + folder + "')"
                 : "; run: deformseg describe " + labels + " --store " + folder;
  throw invalid_input(message, {.file = folder});
}

}  // namespace deformseg::frontend
