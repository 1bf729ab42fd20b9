// Retrieval figures that no choice was tuned on: each group of bodies left out in turn (a pack of the motion
// library, a rig of the shared characters), a choice is made among candidate policies on the other groups
// alone, and the left-out group's clips are queried under it. Not a Google Benchmark:
//
//   build-bench/test/bench/retrieval_groups [--threads 2]
//                                           [--grid default|signatures|all|expansion|fusion|descriptions]
//                                           [--learned P]... [--whitened S]... [--discriminant S]...
//
// (default: --threads 2 --grid signatures, nothing learned).
//
// Sets and groups: the shared characters (characters/motions.csv, a group per rig: kaykit, robotexpressive,
// fox), the library without its cute fish (library/labels.csv, a group per pack, the first folder of a row's
// file) and the cute fish pack alone (one animation set on 35 shapes, which would otherwise be most of the
// library's queries). Each clip is read as `deformseg evaluate` reads it (30 fps, welded and repaired) and
// described once; a clip that cannot be read is left out, as --skip-unreadable does.
//
// Candidates (--grid): `default` is today's default policy alone (`Default_similarity`), whose figures are
// then those of `deformseg evaluate` on each set; `signatures` adds motion signatures with other weights of
// their channels (the vertical rates, each lag's speeds and vertical rates), applied to the descriptions as
// the store would, speeds relative to their clip's or their body's, other scales and other alignments; `all`
// adds the self-similarity policy and blends of both values; `expansion` is the default with each query's row
// plus the mean row of its 1, 3 or 10 nearest candidates (query expansion, `expanded`); `fusion` blends the
// two policies' ranks instead of their values (`rank_scores`): each query's candidates scored by the fraction
// of them ranked after, or by reciprocal rank fusion; `descriptions` describes every clip again with the
// surface cut into 2, 3 or 4 height bands (`Motion_signature_options::bands`) and compares each at scales
// 0.75, 1.2 and 1.77.
//
// For each group g: the candidate whose mean figure (the mean of NN accuracy, mAP and ROC-AUC) over the other
// groups is best, each other group's clips queried within its set without g's; then g's queries against every
// clip of its set under that candidate. Printed: each candidate's figures per group (every group's queries
// against its whole set), the choice of each fold and its figures beside today's default, and the figures of
// each set pooled over its folds' queries. Each --learned P adds weights of the signature's 64 columns learned
// on the other groups (Fisher's criterion of each column to the power P, `learned_weights`), each group
// measured under the weights its fold learned; each --whitened S a linear map of the signature's rows learned
// so (the spread of a motion's clips whitened, with shrinkage S: `whitening`), each --discriminant S another
// (the motions' discriminant directions: `discriminant`).
#include <deformseg/alignment/smith_waterman.h>
#include <deformseg/alignment/subsequence_dtw.h>
#include <deformseg/evaluation/motion_labels.h>
#include <deformseg/evaluation/retrieval_evaluation.h>
#include <deformseg/internal/parallel_for.h>
#include <deformseg/io/gltf.h>
#include <deformseg/similarity/motion_similarity.h>
#include <deformseg/similarity/self_similarity_matching.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
namespace ds = deformseg;
using ds::evaluation::Retrieval_scores;

constexpr double fps = 30;
constexpr std::size_t lag_count = 4;  // the default signatures' lags
constexpr double default_vertical_weight = 0.2;

fs::path data_dir() {
  const char* dir = std::getenv("DEFORMSEG_DATA_DIR");
  return fs::path(dir && *dir ? dir : DEFORMSEG_DATA_DIR);
}

// One labelled clip, described by the signatures (today's, then each of the grid's other descriptions) and
// (with --grid all) the self-similarity.
struct Clip {
  ds::evaluation::Labelled_clip row;
  std::string group;
  std::vector<ds::similarity::Motion_signature_description> signatures;
  std::optional<ds::similarity::Self_similarity_matching<>::Description> self;
};

// A set of clips evaluated together: queries and candidates are its clips alone.
struct Evaluation_set {
  std::string name;
  std::vector<Clip> clips;
  std::vector<ds::evaluation::Labelled_item> items() const {
    std::vector<ds::evaluation::Labelled_item> items;
    for (const Clip& c : clips) items.push_back(c.row.item);
    return items;
  }
};

// Speeds made relative to the clip's: each column less its mean over the rows, or each lag's speeds less
// their mean (a clip's pace taken out, the shape of its distribution kept); or relative to the body's, the
// same means over every row of every clip of the body in the set (the body's pace taken out, the clip's
// kept).
enum class Centre { none, columns, lags, body_columns, body_lags };

// How a candidate blends the self-similarity with the signatures: their values; each query's candidates'
// ranks under each, as fractions of the candidates ranked after them; or reciprocal rank fusion, the sum of
// 1 / (k + rank) over both.
enum class Fusion { values, ranks, reciprocal_ranks };

// A candidate policy: signature channel weights (per lag, the speeds' and the vertical rates'), speeds
// centred or not, the signatures' scale and alignment, and the share of the self-similarity's value in a
// fusion of both.
struct Candidate {
  std::string name;
  std::array<double, lag_count> speed_weights{1, 1, 1, 1};
  std::array<double, lag_count> vertical_weights{0.2, 0.2, 0.2, 0.2};
  double scale = ds::similarity::Default_similarity{}.scale;
  double self_share = 0;
  std::string alignment = "dtw";  // or "subsequence-dtw", "smith-waterman"
  Centre centre = Centre::none;
  std::size_t description = 0;       // which of the clips' descriptions (`description_options`): 0 today's
  Eigen::VectorXf column_factors{};  // when not empty, every column multiplied by its factor
  Eigen::MatrixXf projection{};      // when not empty, every row r made r * projection
  std::size_t expansion = 0;         // query expansion: the query's nearest candidates whose rows are added
  double expansion_weight = 1;       // the share of their mean row
  Fusion fusion = Fusion::values;    // how the self-similarity is blended in (at self_share)
  double reciprocal_offset = 60;     // k of Fusion::reciprocal_ranks
};

// The rows of `csv` whose group `group_of` names, read and described; `keep` chooses the groups.
template <class GroupOf, class Keep>
Evaluation_set read_set(const std::string& name, const fs::path& csv, const GroupOf& group_of, const Keep& keep,
                        std::span<const ds::signatures::Motion_signature_options> descriptions, bool with_self,
                        int threads) {
  Evaluation_set set{name, {}};
  for (ds::evaluation::Labelled_clip& row : ds::evaluation::read_motion_labels(csv)) {
    const std::string group = group_of(row);
    if (keep(group)) set.clips.push_back({std::move(row), group, {}, std::nullopt});
  }
  std::map<fs::path, std::vector<std::size_t>> by_file;
  for (std::size_t k = 0; k < set.clips.size(); ++k) by_file[set.clips[k].row.file].push_back(k);
  std::vector<std::vector<std::size_t>> files;
  for (auto& [file, rows] : by_file) files.push_back(rows);
  std::vector<char> readable(set.clips.size(), 0);
  const ds::similarity::Self_similarity_matching<> self{};
  ds::internal::parallel_for(files.size(), threads, [&](std::size_t f) {
    try {
      const ds::io::Gltf_file file(set.clips[files[f][0]].row.file);
      const ds::io::Repaired_triangles repaired = file.repair({.weld = true});
      for (const std::size_t k : files[f]) {
        Clip& clip = set.clips[k];
        try {
          const auto animation = file.read(repaired, {.clip = clip.row.item.clip, .fps = fps, .threads = 1});
          for (const ds::signatures::Motion_signature_options& options : descriptions) {
            ds::similarity::Default_similarity signatures{};
            signatures.signatures = options;
            clip.signatures.push_back(signatures.describe(animation));
          }
          if (with_self) clip.self = self.describe(animation);
          readable[k] = 1;
        } catch (const ds::invalid_input&) {
        }
      }
    } catch (const ds::invalid_input&) {
    }
  });
  std::vector<Clip> kept;
  for (std::size_t k = 0; k < set.clips.size(); ++k)
    if (readable[k]) kept.push_back(std::move(set.clips[k]));
  std::printf("%s: %zu of %zu clips read\n", name.c_str(), kept.size(), set.clips.size());
  set.clips = std::move(kept);
  return set;
}

// The signatures of `d` as `c` has them: its channel weights in place of the defaults, its speeds centred on
// the clip's (not the body's: `less_body_means`), its column factors.
ds::similarity::Motion_signature_description weighted(const ds::similarity::Motion_signature_description& d,
                                                      const Candidate& c) {
  ds::similarity::Motion_signature_description out = d;
  const Eigen::Index k = d.signatures.cols() / Eigen::Index(2 * lag_count);
  for (std::size_t l = 0; l < lag_count; ++l) {
    const float speed = float(std::sqrt(c.speed_weights[l]));
    const float vertical = float(std::sqrt(c.vertical_weights[l] / default_vertical_weight));
    if (speed != 1) out.signatures.middleCols(Eigen::Index(l) * k, k) *= speed;
    if (vertical != 1) out.signatures.middleCols(Eigen::Index(lag_count + l) * k, k) *= vertical;
    auto speeds = out.signatures.middleCols(Eigen::Index(l) * k, k);
    if (c.centre == Centre::columns) speeds.rowwise() -= speeds.colwise().mean();
    if (c.centre == Centre::lags) speeds.array() -= speeds.mean();
  }
  if (c.column_factors.size() > 0) out.signatures.array().rowwise() *= c.column_factors.transpose().array();
  if (c.projection.size() > 0) out.signatures = out.signatures * c.projection;
  return out;
}

// Each description's speeds less the mean of its body's (`Centre::body_columns`, `Centre::body_lags`).
void less_body_means(const Evaluation_set& set, Centre centre,
                     std::vector<ds::similarity::Motion_signature_description>& descriptions) {
  const Eigen::Index speeds = descriptions.front().signatures.cols() / 2, k = speeds / Eigen::Index(lag_count);
  std::map<std::string, std::pair<Eigen::RowVectorXd, double>> bodies;  // sum of rows, rows
  for (std::size_t i = 0; i < descriptions.size(); ++i) {
    auto& [sum, rows] = bodies[set.clips[i].row.item.body];
    const Eigen::RowVectorXd clip = descriptions[i].signatures.leftCols(speeds).cast<double>().colwise().sum();
    sum = sum.size() == 0 ? clip : Eigen::RowVectorXd(sum + clip);
    rows += double(descriptions[i].signatures.rows());
  }
  for (std::size_t i = 0; i < descriptions.size(); ++i) {
    const auto& [sum, rows] = bodies[set.clips[i].row.item.body];
    Eigen::RowVectorXd mean = sum / rows;
    if (centre == Centre::body_lags)
      for (std::size_t l = 0; l < lag_count; ++l)
        mean.segment(Eigen::Index(l) * k, k).setConstant(mean.segment(Eigen::Index(l) * k, k).mean());
    descriptions[i].signatures.leftCols(speeds).rowwise() -= mean.cast<float>();
  }
}

// The candidates of query `q` by decreasing similarity in `m`, ties to the lower index: the evaluation's rule
// for which clips are candidates and its ranking.
std::vector<std::size_t> ranked_candidates(std::span<const ds::evaluation::Labelled_item> items,
                                           const Eigen::MatrixXd& m, std::size_t q) {
  std::vector<std::size_t> candidates;
  for (std::size_t c = 0; c < items.size(); ++c)
    if (c != q && ds::evaluation::internal::retrieval::is_candidate(items[q], items[c])) candidates.push_back(c);
  return ds::evaluation::internal::retrieval::ranked(m, q, std::move(candidates));
}

// Query expansion: each row of `m` plus `weight` times the mean row of the query's `k` nearest candidates
// (`ranked_candidates`: no label read), so that what is near a query's nearest clips counts too.
Eigen::MatrixXd expanded(const Evaluation_set& set, const Eigen::MatrixXd& m, std::size_t k, double weight) {
  const auto items = set.items();
  Eigen::MatrixXd out = m;
  for (std::size_t q = 0; q < items.size(); ++q) {
    const std::vector<std::size_t> nearest = ranked_candidates(items, m, q);
    const std::size_t n = std::min(k, nearest.size());
    if (n == 0) continue;
    Eigen::RowVectorXd mean = Eigen::RowVectorXd::Zero(m.cols());
    for (std::size_t i = 0; i < n; ++i) mean += m.row(Eigen::Index(nearest[i]));
    out.row(Eigen::Index(q)) += weight * mean / double(n);
  }
  return out;
}

// Each query's candidates (`ranked_candidates`) scored by their rank r among its n under `m`: the fraction
// (n - 1 - r) / (n - 1) of the candidates ranked after them, or 1 / (offset + r + 1) when `offset` is set.
// Entries of no candidate are 0.
Eigen::MatrixXd rank_scores(const Evaluation_set& set, const Eigen::MatrixXd& m, std::optional<double> offset) {
  const auto items = set.items();
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(m.rows(), m.cols());
  for (std::size_t q = 0; q < items.size(); ++q) {
    const std::vector<std::size_t> ranked = ranked_candidates(items, m, q);
    const double after = double(std::max<std::size_t>(ranked.size(), 2) - 1);
    for (std::size_t r = 0; r < ranked.size(); ++r)
      out(Eigen::Index(q), Eigen::Index(ranked[r])) =
          offset ? 1 / (*offset + double(r) + 1) : double(ranked.size() - 1 - r) / after;
  }
  return out;
}

// The offset of `c`'s rank scores (`rank_scores`): set for reciprocal rank fusion alone.
std::optional<double> rank_offset(const Candidate& c) {
  return c.fusion == Fusion::reciprocal_ranks ? std::optional(c.reciprocal_offset) : std::nullopt;
}

// The signatures' matrix `m` and the self-similarity's blended as `c` says.
Eigen::MatrixXd fused(const Evaluation_set& set, const Candidate& c, const Eigen::MatrixXd& m,
                      const Eigen::MatrixXd& self) {
  if (c.fusion == Fusion::values) return (1 - c.self_share) * m + c.self_share * self;
  return (1 - c.self_share) * rank_scores(set, m, rank_offset(c)) +
         c.self_share * rank_scores(set, self, rank_offset(c));
}

// The similarity matrix of `set` under `c`; `self_matrix` is the set's self-similarity matrix (computed once,
// when a candidate first needs it).
Eigen::MatrixXd candidate_matrix(const Evaluation_set& set, const Candidate& c,
                                 std::optional<Eigen::MatrixXd>& self_matrix, int threads) {
  std::vector<ds::similarity::Motion_signature_description> descriptions;
  for (const Clip& clip : set.clips) descriptions.push_back(weighted(clip.signatures[c.description], c));
  if (c.centre == Centre::body_columns || c.centre == Centre::body_lags) less_body_means(set, c.centre, descriptions);
  const auto matrix = [&]<class Alignment>(Alignment) {
    ds::similarity::Motion_signature_similarity<Alignment> policy{};
    policy.scale = c.scale;
    return ds::similarity::described_similarity_matrix<decltype(policy)>(descriptions, policy, {}, threads);
  };
  Eigen::MatrixXd m = c.alignment == "dtw"               ? matrix(ds::alignment::Dtw{})
                      : c.alignment == "subsequence-dtw" ? matrix(ds::alignment::Subsequence_dtw{})
                                                         : matrix(ds::alignment::Smith_waterman{});
  if (c.expansion > 0) m = expanded(set, m, c.expansion, c.expansion_weight);
  if (c.self_share == 0) return c.fusion == Fusion::values ? m : rank_scores(set, m, rank_offset(c));
  if (!self_matrix) {
    std::vector<ds::similarity::Self_similarity_matching<>::Description> selves;
    for (const Clip& clip : set.clips) selves.push_back(*clip.self);
    self_matrix = ds::similarity::described_similarity_matrix<ds::similarity::Self_similarity_matching<>>(
        selves, ds::similarity::Self_similarity_matching<>{}, {}, threads);
  }
  return fused(set, c, m, *self_matrix);
}

std::string number(double x) {
  char text[16];
  std::snprintf(text, sizeof text, "%g", x);
  return text;
}

// The descriptions of every clip for `grid`: today's first; with the `descriptions` grid, then the surface cut
// into 2, 3 and 4 height bands (each band's 8 quantiles), and into 4 bands of 4 quantiles each.
std::vector<ds::signatures::Motion_signature_options> description_options(const std::string& grid) {
  std::vector<ds::signatures::Motion_signature_options> out(1);
  if (grid != "descriptions") return out;
  for (const std::size_t bands : {2, 3, 4}) out.push_back({.bands = bands});
  out.push_back({.quantiles = 4, .bands = 4});
  return out;
}

// The candidates of `grid`: today's default first.
std::vector<Candidate> candidates(const std::string& grid) {
  std::vector<Candidate> out{{.name = "default"}};
  if (grid == "default") return out;
  if (grid == "descriptions") {
    const std::vector<ds::signatures::Motion_signature_options> options = description_options(grid);
    for (std::size_t d = 0; d < options.size(); ++d) {
      const std::string name = d == 0 ? "today's signatures"
                                      : std::to_string(options[d].bands) + " height bands of " +
                                            std::to_string(options[d].quantiles) + " quantiles";
      for (const double s : {0.75, 1.2, 1.77})
        if (d > 0 || s != out[0].scale) out.push_back({.name = name + ", scale " + number(s), .scale = s, .description = d});
    }
    return out;
  }
  if (grid == "expansion") {
    for (const std::size_t k : {1, 3, 10})
      for (const double w : {0.5, 1.0})
        out.push_back({.name = "query expanded by its " + std::to_string(k) + " nearest, share " + number(w),
                       .expansion = k,
                       .expansion_weight = w});
    return out;
  }
  if (grid == "fusion") {
    out.push_back({.name = "the signatures' ranks alone", .fusion = Fusion::ranks});
    for (const double share : {0.1, 0.2, 0.3, 0.5})
      out.push_back({.name = "ranks fused, self-similarity share " + number(share),
                     .self_share = share,
                     .fusion = Fusion::ranks});
    for (const double k : {10.0, 60.0})
      out.push_back({.name = "reciprocal rank fusion, k " + number(k),
                     .self_share = 0.5,
                     .fusion = Fusion::reciprocal_ranks,
                     .reciprocal_offset = k});
    return out;
  }
  for (const double v : {0.0, 0.1, 0.4, 0.8})
    out.push_back({.name = "vertical weight " + number(v), .vertical_weights = {v, v, v, v}});
  for (std::size_t l = 0; l < lag_count; ++l)
    for (const double w : {0.0, 0.5, 2.0}) {
      Candidate c{.name = "lag " + std::to_string(l + 1) + " weighed x" + number(w)};
      c.speed_weights[l] *= w;
      c.vertical_weights[l] *= w;
      out.push_back(c);
    }
  for (const double s : {1.0, 1.3, 2.5, 3.5}) out.push_back({.name = "scale " + number(s), .scale = s});
  out.push_back({.name = "speeds less their clip's mean", .centre = Centre::columns});
  out.push_back({.name = "each lag less its clip's mean", .centre = Centre::lags});
  out.push_back({.name = "speeds less their body's mean", .centre = Centre::body_columns});
  out.push_back({.name = "each lag less its body's mean", .centre = Centre::body_lags});
  out.push_back({.name = "subsequence DTW", .alignment = "subsequence-dtw"});
  out.push_back({.name = "Smith-Waterman", .alignment = "smith-waterman"});
  if (grid == "signatures") return out;
  for (const double share : {0.1, 0.2, 0.3, 1.0})
    out.push_back({.name = "self-similarity share " + number(share), .self_share = share});
  return out;
}

// Indices of every clip of `set`.
std::vector<std::size_t> all_clips(const Evaluation_set& set) {
  std::vector<std::size_t> out(set.clips.size());
  for (std::size_t k = 0; k < out.size(); ++k) out[k] = k;
  return out;
}

// Indices of the clips of `set` in group `g` (or not in it).
std::vector<std::size_t> clips_of_group(const Evaluation_set& set, const std::string& g, bool in) {
  std::vector<std::size_t> out;
  for (std::size_t k = 0; k < set.clips.size(); ++k)
    if ((set.clips[k].group == g) == in) out.push_back(k);
  return out;
}

// The figures of group g's queries among the clips `kept` of the set (matrix m over the whole set).
Retrieval_scores group_scores(const Evaluation_set& set, const Eigen::MatrixXd& m, const std::string& g,
                              const std::vector<std::size_t>& kept) {
  Eigen::MatrixXd sub(Eigen::Index(kept.size()), Eigen::Index(kept.size()));
  std::vector<ds::evaluation::Labelled_item> items;
  std::vector<std::size_t> queries;
  for (std::size_t i = 0; i < kept.size(); ++i) {
    items.push_back(set.clips[kept[i]].row.item);
    if (set.clips[kept[i]].group == g) queries.push_back(i);
    for (std::size_t j = 0; j < kept.size(); ++j)
      sub(Eigen::Index(i), Eigen::Index(j)) = m(Eigen::Index(kept[i]), Eigen::Index(kept[j]));
  }
  return ds::evaluation::evaluate_retrieval(sub, items, queries);
}

// The mean of a group's NN accuracy, mAP and ROC-AUC (those it has); none without a query.
std::optional<double> mean_figure(const Retrieval_scores& s) {
  double sum = 0;
  int n = 0;
  for (const auto& f : {s.nn_accuracy, s.mean_average_precision, s.roc_auc})
    if (f) sum += *f, ++n;
  if (n == 0) return std::nullopt;
  return sum / n;
}

std::string figure(const std::optional<double>& f) {
  char text[16];
  if (!f) return "   -  ";
  std::snprintf(text, sizeof text, " %.3f", *f);
  return text;
}

void print_row(const std::string& label, const Retrieval_scores& s) {
  std::printf("  %-46s %4zu %s %s %s\n", label.c_str(), s.queries, figure(s.nn_accuracy).c_str(),
              figure(s.mean_average_precision).c_str(), figure(s.roc_auc).c_str());
}

// Where `m` ranks each query's relevant candidates: per relevant candidate, the fraction of the query's
// other-motion candidates ranked before it (0 at the top); the median of those of the query's group, and of
// other groups.
void print_relevant_ranks(const Evaluation_set& set, const Eigen::MatrixXd& m) {
  const auto items = set.items();
  std::array<std::vector<double>, 2> fractions;  // the query's group, the others
  for (const auto& q : ds::evaluation::evaluate_retrieval(m, items).per_query) {
    const std::vector<std::size_t> ranked = ranked_candidates(items, m, q.query);
    const auto relevant = [&](std::size_t c) { return items[c].motion == items[q.query].motion; };
    const double others =
        double(std::count_if(ranked.begin(), ranked.end(), [&](std::size_t c) { return !relevant(c); }));
    double before = 0;
    for (const std::size_t c : ranked) {
      if (!relevant(c))
        ++before;
      else if (others > 0)
        fractions[set.clips[c].group == set.clips[q.query].group ? 0 : 1].push_back(before / others);
    }
  }
  for (auto& f : fractions) std::sort(f.begin(), f.end());
  const auto median = [](const std::vector<double>& f) { return f.empty() ? std::nan("") : f[f.size() / 2]; };
  std::printf(
      "  %s: the relevant candidates of the query's group come after %.3f of the other motions (median "
      "of %zu), those of other groups after %.3f (of %zu)\n",
      set.name.c_str(), median(fractions[0]), fractions[0].size(), median(fractions[1]), fractions[1].size());
}

struct Group_ref {
  std::size_t set;
  std::string group;
};

// Each group left out in turn: the candidate of the best mean figure over the other groups (each queried
// within its set less the group left out), then the group's figures under it. `whole[c][h]` are group h's
// figures against its whole set under candidate c, which a fold leaving out a group of another set reads
// as they are. Gives each group's choice.
std::vector<std::size_t> leave_each_group_out(const std::vector<Evaluation_set>& sets,
                                              const std::vector<Group_ref>& groups,
                                              const std::vector<Candidate>& grid_candidates,
                                              const std::vector<std::vector<Eigen::MatrixXd>>& matrices,
                                              const std::vector<std::vector<Retrieval_scores>>& whole) {
  std::printf("\nleft out: the choice of the other groups, then this group's figures (queries NN mAP ROC-AUC)\n");
  std::vector<std::size_t> choices(groups.size());
  for (std::size_t left = 0; left < groups.size(); ++left) {
    const Group_ref& out = groups[left];
    const std::vector<std::size_t> without = clips_of_group(sets[out.set], out.group, false);
    double best = -1;
    for (std::size_t c = 0; c < grid_candidates.size(); ++c) {
      double sum = 0;
      int n = 0;
      for (std::size_t h = 0; h < groups.size(); ++h) {
        if (h == left) continue;
        const Retrieval_scores scores =
            groups[h].set == out.set ? group_scores(sets[out.set], matrices[c][out.set], groups[h].group, without)
                                     : whole[c][h];
        if (const auto f = mean_figure(scores)) sum += *f, ++n;
      }
      if (n > 0 && sum / n > best) best = sum / n, choices[left] = c;
    }
    print_row(out.group + " <- " + grid_candidates[choices[left]].name, whole[choices[left]][left]);
    print_row(out.group + "    today", whole[0][left]);
  }
  return choices;
}

// `pooled` with the rows of group g's clips taken from `m` (their queries ranked as g's fold ranks them).
void take_group_rows(const Evaluation_set& set, const std::string& g, const Eigen::MatrixXd& m,
                     Eigen::MatrixXd& pooled) {
  for (const std::size_t k : clips_of_group(set, g, true)) pooled.row(Eigen::Index(k)) = m.row(Eigen::Index(k));
}

// Each set's figures, each query ranked under its own group's choice, beside today's default.
void print_pooled(const std::vector<Evaluation_set>& sets, const std::vector<Group_ref>& groups,
                  const std::vector<std::size_t>& choices, const std::vector<std::vector<Eigen::MatrixXd>>& matrices) {
  std::printf("\nper set, every group left out in turn (queries NN mAP ROC-AUC)\n");
  for (std::size_t s = 0; s < sets.size(); ++s) {
    Eigen::MatrixXd pooled = matrices[0][s];
    for (std::size_t g = 0; g < groups.size(); ++g)
      if (groups[g].set == s) take_group_rows(sets[s], groups[g].group, matrices[choices[g]][s], pooled);
    const auto items = sets[s].items();
    print_row(sets[s].name, ds::evaluation::evaluate_retrieval(pooled, items));
    print_row(sets[s].name + ", today", ds::evaluation::evaluate_retrieval(matrices[0][s], items));
  }
}

// Each labelled clip outside group `left`, as its mean row of the signatures, by motion.
std::map<std::string, std::vector<Eigen::VectorXd>> clip_means_by_motion(const std::vector<Evaluation_set>& sets,
                                                                         const Group_ref& left) {
  std::map<std::string, std::vector<Eigen::VectorXd>> motions;
  for (std::size_t s = 0; s < sets.size(); ++s)
    for (const Clip& c : sets[s].clips)
      if (c.row.item.motion != ds::evaluation::distractor_label && !(s == left.set && c.group == left.group))
        motions[c.row.item.motion].push_back(c.signatures[0].signatures.cast<double>().colwise().mean().transpose());
  return motions;
}

// The scatter of the clips' means about their motion's mean (within), and about the mean of every clip
// (total), each over the number of clips.
std::pair<Eigen::MatrixXd, Eigen::MatrixXd> within_and_total_scatter(
    const std::map<std::string, std::vector<Eigen::VectorXd>>& motions) {
  const Eigen::Index width = motions.begin()->second.front().size();
  Eigen::VectorXd all = Eigen::VectorXd::Zero(width);
  double n = 0;
  for (const auto& [motion, clips] : motions)
    for (const Eigen::VectorXd& clip : clips) all += clip, ++n;
  all /= n;
  Eigen::MatrixXd within = Eigen::MatrixXd::Zero(width, width), total = within;
  for (const auto& [motion, clips] : motions) {
    Eigen::VectorXd mean = Eigen::VectorXd::Zero(width);
    for (const Eigen::VectorXd& clip : clips) mean += clip;
    mean /= double(clips.size());
    for (const Eigen::VectorXd& clip : clips) {
      within += (clip - mean) * (clip - mean).transpose();
      total += (clip - all) * (clip - all).transpose();
    }
  }
  return {within / n, total / n};
}

// Per column of the signatures, Fisher's criterion over the labelled clips outside group `left`: the spread
// of the motions' means over the spread within each motion (the diagonals of the scatters); raised to
// `power` and scaled to a mean of 1, as weights of the squared distance.
Eigen::VectorXd learned_weights(const std::vector<Evaluation_set>& sets, const Group_ref& left, double power) {
  const auto [within, total] = within_and_total_scatter(clip_means_by_motion(sets, left));
  const Eigen::ArrayXd between = (total - within).diagonal().array().max(0.0);
  Eigen::VectorXd weights = (between / within.diagonal().array().max(1e-12)).pow(power).matrix();
  return weights / weights.mean();
}

// (W + shrink mean(diag W) I)^(-1/2) for the within scatter W: its directions of large spread shrunk.
Eigen::MatrixXd shrunk_inverse_square_root(const Eigen::MatrixXd& within, double shrink) {
  const Eigen::Index width = within.rows();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(within + shrink * within.diagonal().mean() *
                                                                          Eigen::MatrixXd::Identity(width, width));
  return eigen.eigenvectors() * eigen.eigenvalues().cwiseInverse().cwiseSqrt().asDiagonal() *
         eigen.eigenvectors().transpose();
}

// `map` scaled so that the clips' total spread keeps its size: the similarity's scale then means what it did.
Eigen::MatrixXd keeping_total_spread(const Eigen::MatrixXd& map, const Eigen::MatrixXd& total) {
  return map * std::sqrt(total.trace() / (map.transpose() * total * map).trace());
}

// The rows' map that whitens the spread of clips within a motion, learned outside group `left` (shrinkage
// `shrink`). Directions in which one motion varies from clip to clip (a studio's pace, a rig's proportions)
// shrink; those that tell motions apart are kept.
Eigen::MatrixXd whitening(const std::vector<Evaluation_set>& sets, const Group_ref& left, double shrink) {
  const auto [within, total] = within_and_total_scatter(clip_means_by_motion(sets, left));
  return keeping_total_spread(shrunk_inverse_square_root(within, shrink), total);
}

// The rows' map onto the motions' discriminant directions, learned outside group `left`: the within scatter
// whitened as by `whitening`, then each direction of the motions' means weighed by the square root of its
// spread there (its Fisher criterion, as `learned_weights` weighs columns, along the directions that separate
// motions best rather than along the columns).
Eigen::MatrixXd discriminant(const std::vector<Evaluation_set>& sets, const Group_ref& left, double shrink) {
  const auto [within, total] = within_and_total_scatter(clip_means_by_motion(sets, left));
  const Eigen::MatrixXd whiten = shrunk_inverse_square_root(within, shrink);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> directions(whiten.transpose() * (total - within) * whiten);
  return keeping_total_spread(
      whiten * directions.eigenvectors() * directions.eigenvalues().cwiseMax(0.0).cwiseSqrt().asDiagonal(), total);
}

// A candidate learned on the other groups, each group left out in turn (`learn` makes it for a fold): the
// group's figures under its fold's candidate, beside today's, and each set pooled over its folds.
template <class Learn>
void leave_each_group_out_learned(const std::vector<Evaluation_set>& sets, const std::vector<Group_ref>& groups,
                                  const std::vector<Eigen::MatrixXd>& today, const std::string& name,
                                  const Learn& learn, int threads) {
  std::printf("\nleft out, %s learned on the other groups\n", name.c_str());
  std::vector<Eigen::MatrixXd> pooled = today;
  for (const Group_ref& out : groups) {
    std::optional<Eigen::MatrixXd> unused;
    const Eigen::MatrixXd m = candidate_matrix(sets[out.set], learn(out), unused, threads);
    const std::vector<std::size_t> all = all_clips(sets[out.set]);
    print_row(out.group + " <- learned", group_scores(sets[out.set], m, out.group, all));
    print_row(out.group + "    today", group_scores(sets[out.set], today[out.set], out.group, all));
    take_group_rows(sets[out.set], out.group, m, pooled[out.set]);
  }
  for (std::size_t s = 0; s < sets.size(); ++s)
    print_row(sets[s].name + ", learned", ds::evaluation::evaluate_retrieval(pooled[s], sets[s].items()));
}

}  // namespace

int main(int argc, char** argv) {
  int threads = 2;
  std::string grid = "signatures";
  std::vector<double> learned_powers, whitening_shrinks, discriminant_shrinks;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    if (flag == "--threads")
      threads = std::atoi(argv[i + 1]);
    else if (flag == "--grid")
      grid = argv[i + 1];
    else if (flag == "--learned")
      learned_powers.push_back(std::atof(argv[i + 1]));
    else if (flag == "--whitened")
      whitening_shrinks.push_back(std::atof(argv[i + 1]));
    else if (flag == "--discriminant")
      discriminant_shrinks.push_back(std::atof(argv[i + 1]));
  }
  const auto start = std::chrono::steady_clock::now();
  const bool with_self = grid == "all" || grid == "fusion";
  const std::vector<ds::signatures::Motion_signature_options> descriptions = description_options(grid);
  const fs::path data = data_dir();
  const auto rig_of = [](const ds::evaluation::Labelled_clip& row) { return row.item.rig; };
  const auto pack_of = [](const ds::evaluation::Labelled_clip& row) {
    return row.item.body.substr(0, row.item.body.find('/'));
  };
  const auto any = [](const std::string&) { return true; };
  std::vector<Evaluation_set> sets;
  sets.push_back(read_set("characters", data / "characters/motions.csv", rig_of, any, descriptions, with_self,
                         threads));
  sets.push_back(read_set(
      "library without the cute fish", data / "library/labels.csv", pack_of,
      [](const std::string& g) { return g != "cute_fish_pack"; }, descriptions,
      with_self, threads));
  sets.push_back(read_set(
      "the cute fish", data / "library/labels.csv", pack_of, [](const std::string& g) { return g == "cute_fish_pack"; },
      descriptions, with_self, threads));

  std::vector<Group_ref> groups;
  for (std::size_t s = 0; s < sets.size(); ++s) {
    std::set<std::string> names;
    for (const Clip& c : sets[s].clips) names.insert(c.group);
    for (const std::string& g : names) groups.push_back({s, g});
  }

  // Every candidate's matrices, and each group's figures against its whole set.
  const std::vector<Candidate> grid_candidates = candidates(grid);
  std::vector<std::vector<Eigen::MatrixXd>> matrices(grid_candidates.size());
  std::vector<std::vector<Retrieval_scores>> whole(grid_candidates.size());
  std::vector<std::optional<Eigen::MatrixXd>> self_matrices(sets.size());
  for (std::size_t c = 0; c < grid_candidates.size(); ++c) {
    std::printf("%s\n", grid_candidates[c].name.c_str());
    for (std::size_t s = 0; s < sets.size(); ++s)
      matrices[c].push_back(candidate_matrix(sets[s], grid_candidates[c], self_matrices[s], threads));
    for (const Group_ref& g : groups) {
      whole[c].push_back(group_scores(sets[g.set], matrices[c][g.set], g.group, all_clips(sets[g.set])));
      print_row(g.group, whole[c].back());
    }
  }

  const std::vector<std::size_t> choices = leave_each_group_out(sets, groups, grid_candidates, matrices, whole);
  print_pooled(sets, groups, choices, matrices);
  for (const double power : learned_powers)
    leave_each_group_out_learned(
        sets, groups, matrices[0], "the columns weighed by Fisher's criterion to the power " + number(power),
        [&](const Group_ref& out) {
          return Candidate{.name = "learned",
                           .column_factors = learned_weights(sets, out, power).cwiseSqrt().cast<float>()};
        },
        threads);
  for (const double shrink : whitening_shrinks)
    leave_each_group_out_learned(
        sets, groups, matrices[0], "the spread within motions whitened, shrinkage " + number(shrink),
        [&](const Group_ref& out) {
          return Candidate{.name = "whitened", .projection = whitening(sets, out, shrink).cast<float>()};
        },
        threads);
  for (const double shrink : discriminant_shrinks)
    leave_each_group_out_learned(
        sets, groups, matrices[0], "the motions' discriminant directions, shrinkage " + number(shrink),
        [&](const Group_ref& out) {
          return Candidate{.name = "discriminant", .projection = discriminant(sets, out, shrink).cast<float>()};
        },
        threads);
  std::printf("\nwhere today's default ranks the relevant clips\n");
  for (std::size_t s = 0; s < sets.size(); ++s) print_relevant_ranks(sets[s], matrices[0][s]);
  std::printf("\n%.1f s\n", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
}
