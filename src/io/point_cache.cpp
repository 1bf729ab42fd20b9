// The point-cache readers of io/point_cache.h for the default types, compiled once here so that a
// program on them compiles against the declarations.
#include <deformseg/io/point_cache.h>

#include <filesystem>

namespace deformseg::io {

template mesh::Deforming_mesh<mesh::Surface_mesh, double>
read_pc2<mesh::Surface_mesh, double>(const std::filesystem::path&, mesh::Surface_mesh, double);
template mesh::Deforming_mesh<mesh::Surface_mesh, double>
read_mdd<mesh::Surface_mesh, double>(const std::filesystem::path&, mesh::Surface_mesh, double);

}  // namespace deformseg::io
