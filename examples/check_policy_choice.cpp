// check_policy_choice and up_direction: a similarity policy chosen by name, as a program's user
// gives it, checked before any input is read, each mistake named; and the up directions' names.
#include <deformseg/exceptions.h>
#include <deformseg/similarity/policy_choice.h>

#include <cstdio>
#include <initializer_list>

int main() {
  using namespace deformseg;
  similarity::check_policy_choice({.policy = "graph", .alignment = "dtw", .threshold = 0.4});  // a valid choice
  int refused = 0;
  using Choice = similarity::Policy_choice;
  for (const Choice& choice : {Choice{.policy = "graphs"}, Choice{.policy = "histogram", .threshold = 0.4},
                               Choice{.policy = "histogram", .up = "+z"}, Choice{.up = "up"}}) {
    try {
      similarity::check_policy_choice(choice);
    } catch (const invalid_input& e) {
      std::printf("%s\n", e.what());
      ++refused;
    }
  }
  const auto down = similarity::up_direction("-z");
  std::printf("-z is (%g, %g, %g); none gives %s\n", down->x() + 0.0, down->y() + 0.0, down->z(),
              similarity::up_direction("none") ? "a direction" : "no direction (speeds alone)");
  return refused == 4 && down->z() == -1 ? 0 : 1;
}
