// Tests of the front end's tables of parameters (frontend/parameters.h): a text parameter is empty
// by default exactly when its kind says so, which is what the Python module reads to make it None
// by default; and every other default of a choice is one of its choices.
#include <frontend/ged.h>
#include <frontend/inputs.h>
#include <frontend/parameters.h>
#include <frontend/similarity.h>
#include <frontend/spatiotemporal.h>
#include <frontend/strain.h>
#include <frontend/temporal.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <type_traits>

namespace {

using namespace deformseg::frontend;

template <class Table>
void check_defaults(const Table& table) {
  for_each_parameter(table, [](const auto& parameter) {
    using Parameter = std::remove_cvref_t<decltype(parameter)>;
    if constexpr (std::is_same_v<typename Parameter::value_type, std::string>) {
      const std::string fallback = typename Parameter::request_type{}.*parameter.member;
      INFO("parameter " << parameter.name << ", default '" << fallback << "'");
      CHECK(fallback.empty() == is_empty_by_default(parameter.kind));
      if (parameter.kind == Parameter_kind::choice)
        CHECK(std::ranges::any_of(parameter.choices, [&](const Choice& c) { return c.name == fallback; }));
    }
  });
}

}  // namespace

TEST_CASE("parameter tables: a text is empty by default exactly when its kind says so, a choice's default is a choice",
          "[frontend][parameters]") {
  check_defaults(input_parameters);
  check_defaults(strain_parameters);
  check_defaults(frame_distance_table);
  check_defaults(temporal_parameters);
  check_defaults(spatiotemporal_parameters);
  check_defaults(ged_parameters);
  check_defaults(policy_parameters);
  check_defaults(comparison_parameters);
}
