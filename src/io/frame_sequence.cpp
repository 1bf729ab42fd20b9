// The frame-sequence reader of io/frame_sequence.h for the default types, compiled once here so
// that a program on them compiles against the declaration.
#include <deformseg/io/frame_sequence.h>

#include <string>

namespace deformseg::io {

template mesh::Deforming_mesh<mesh::Surface_mesh, double>
read_frame_sequence<mesh::Surface_mesh, double>(const std::string&, const Frame_sequence_options&, Repair_report*);

}  // namespace deformseg::io
