// The animation reader of io/read_animation.h for the default types, compiled once here so that a
// program on them compiles against the declaration.
#include <deformseg/io/read_animation.h>

#include <string>

namespace deformseg::io {

template mesh::Deforming_mesh<mesh::Surface_mesh, double>
read_animation<mesh::Surface_mesh, double>(const std::string&, const Animation_read_options&, Repair_report*);

}  // namespace deformseg::io
