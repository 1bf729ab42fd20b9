// How well a similarity matrix retrieves the same motion on another body: five clips of three
// bodies (the last a distractor, compared but never queried), a hand-made matrix, the scores and
// what each query found; then one group's clips alone as queries.
#include <deformseg/evaluation/retrieval_evaluation.h>

#include <iostream>
#include <string>
#include <vector>

int main() {
  using namespace deformseg;
  const std::vector<evaluation::Labelled_item> items{
      {.motion = "walk", .body = "fox", .rig = "", .clip = "Walk"},
      {.motion = "walk", .body = "knight", .rig = "kaykit", .clip = "Walking_A"},
      {.motion = "run", .body = "knight", .rig = "kaykit", .clip = "Running_A"},
      {.motion = "run", .body = "mage", .rig = "kaykit", .clip = "Running_B"},
      {.motion = evaluation::distractor_label, .body = "mage", .rig = "kaykit", .clip = "Cheer"}};
  Eigen::MatrixXd similarity(5, 5);
  similarity << 1.0, 0.6, 0.8, 0.4, 0.5,  //
      0.7, 1.0, 0.9, 0.7, 0.2,            //
      0.3, 0.95, 1.0, 0.3, 0.6,           //
      0.5, 0.4, 0.9, 1.0, 0.99,           //
      0.9, 0.9, 0.9, 0.9, 1.0;
  const evaluation::Retrieval_scores scores = evaluation::evaluate_retrieval(similarity, items);
  std::cout << "queries " << scores.queries << "\nNN accuracy " << *scores.nn_accuracy << "\nmAP "
            << *scores.mean_average_precision << "\nROC-AUC " << *scores.roc_auc << "\nmedian same "
            << *scores.median_same << ", different " << *scores.median_different << '\n';
  for (const auto& m : scores.per_motion)
    std::cout << m.motion << ": " << m.correct << " of " << m.queries << " nearest neighbours right\n";
  // What each query found: the clips a policy takes for which.
  for (const evaluation::Query_retrieval& q : scores.per_query) {
    const evaluation::Labelled_item &query = items[q.query], &nearest = items[q.nearest];
    std::cout << query.body << " " << query.clip << ": nearest " << nearest.body << " " << nearest.clip << " ("
              << q.nearest_similarity << "), first " << query.motion << " at rank "
              << (q.first_relevant_rank ? std::to_string(*q.first_relevant_rank) : "none") << '\n';
  }

  // A group's clips alone as queries (the KayKit rig's, items 1 to 4), every other body's clips
  // as candidates: the figures of a group left out.
  const std::vector<std::size_t> kaykit{1, 2, 3, 4};
  const evaluation::Retrieval_scores group = evaluation::evaluate_retrieval(similarity, items, kaykit);
  std::cout << "the KayKit rig's clips as queries: " << group.queries << " queries, NN accuracy "
            << *group.nn_accuracy << '\n';
  return group.queries == 3 ? 0 : 1;
}
