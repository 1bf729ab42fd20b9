// deformseg: the command-line tool. Each sub-command is a thin layer over the library; errors
// end the run with one line on standard error and the exit status 1.
#include "command.h"

#include <deformseg/exceptions.h>

#include <exception>
#include <iostream>
#include <new>
#include <string>

int main(int argc, char** argv) {
  CLI::App app{"deformseg: segmentation and motion similarity of deforming meshes"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("deformseg ") + DEFORMSEG_VERSION_TEXT);
  deformseg::tool::add_info_command(app);
  deformseg::tool::add_convert_command(app);
  deformseg::tool::add_synth_command(app);
  deformseg::tool::add_strain_command(app);
  deformseg::tool::add_temporal_command(app);
  deformseg::tool::add_spatiotemporal_command(app);
  deformseg::tool::add_ged_command(app);
  deformseg::tool::add_ged_matrix_command(app);
  deformseg::tool::add_similarity_command(app);
  deformseg::tool::add_matrix_command(app);
  deformseg::tool::add_evaluate_command(app);
  deformseg::tool::add_find_command(app);
  deformseg::tool::add_view_command(app);
  deformseg::tool::add_describe_command(app);
  deformseg::tool::add_search_command(app);
  deformseg::tool::add_knn_graph_command(app);
  deformseg::tool::add_store_command(app);
  const std::vector<std::string> arguments(argv + 1, argv + argc);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // A likely typo is named alone, before CLI11's generic words ("A subcommand is required").
    const std::string hint = deformseg::tool::typo_hint(app, arguments);
    if (!hint.empty()) {
      std::cerr << "deformseg: " << hint << '\n';
      return 1;
    }
    // Help and version exit with 0; every refusal with 1, as every other error (CLI11's own
    // codes, 105 for a failed check, say nothing more than its message).
    const int status = app.exit(e) == 0 ? 0 : 1;
    if (dynamic_cast<const CLI::ExtrasError*>(&e))  // often a glob the shell expanded, a file an argument
      std::cerr << "deformseg: a glob must be quoted to name one animation, e.g. 'frames/*.obj'\n";
    return status;
  } catch (const std::bad_alloc&) {  // says nothing of its own: the sizes asked are the user's to change
    std::cerr << "deformseg: error: out of memory: the animation, or what the command makes of it, does not fit "
                 "in this machine's memory (fewer frames, vertices or clips at a time?)\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "deformseg: error: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
