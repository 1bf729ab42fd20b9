// deformseg: the command-line tool. Each sub-command is a thin layer over the library; errors
// end the run with one line on standard error and a non-zero exit status.
#include "command.h"

#include <deformseg/exceptions.h>

#include <exception>
#include <iostream>

int main(int argc, char** argv) {
  CLI::App app{"deformseg: segmentation and motion similarity of deforming meshes"};
  app.require_subcommand(1);
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
  try {
    app.parse(argc, argv);
  } catch (const CLI::ExtrasError& e) {
    // The usual cause: a glob the shell expanded into one argument per file.
    const int status = app.exit(e);
    std::cerr << "deformseg: a glob must be quoted to name one animation, e.g. 'frames/*.obj'\n";
    return status;
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const std::exception& e) {
    std::cerr << "deformseg: error: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
