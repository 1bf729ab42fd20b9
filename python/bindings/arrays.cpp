#include "arrays.h"

#include "common.h"

#include <deformseg/exceptions.h>

#include <cstdint>
#include <string>

namespace py = pybind11;

namespace deformseg::python {

std::string shape_of(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t k = 0; k < a.ndim(); ++k) s += (k ? ", " : "") + std::to_string(a.shape(k));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

std::string dtype_of(const py::array& a) { return py::str(a.dtype()).cast<std::string>(); }

py::array as_array(const py::object& value, const char* name) {
  py::array a = py::array::ensure(value);
  if (!a) throw py::type_error(std::string(name) + ": expected an array, got " + type_name(value));
  return a;
}

mesh::Coordinate_buffer<double> positions_of(const py::array& frames) {
  if (frames.dtype().kind() != 'f' || (frames.itemsize() != 4 && frames.itemsize() != 8))
    throw py::type_error("frames: expected a float32 or float64 array of shape (T, V, 3), got dtype " +
                         dtype_of(frames));
  if (frames.ndim() != 3 || frames.shape(2) != 3 || frames.shape(0) < 1 || frames.shape(1) < 3)
    throw py::value_error("frames: expected shape (T, V, 3) with T >= 1 and V >= 3, got " + shape_of(frames));
  const auto count = std::size_t(frames.size());
  const bool contiguous = (frames.flags() & py::array::c_style) != 0;
  if (contiguous && frames.itemsize() == 8) {
    const auto* data = static_cast<const double*>(frames.data());
    Interruptible_call call;
    return mesh::Coordinate_buffer<double>(data, data + count);
  }
  if (contiguous) {
    const auto* data = static_cast<const float*>(frames.data());
    Interruptible_call call;
    return mesh::Coordinate_buffer<double>(data, data + count);
  }
  const auto converted = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(frames);
  return mesh::Coordinate_buffer<double>(converted.data(), converted.data() + count);
}

namespace {

// A vertex index as the message shows it: a negative index stored in an unsigned array (NumPy
// wraps -1 to 4294967295 in uint32) is named as the negative number it was too.
std::string index_text(std::int64_t v, const py::array& faces) {
  const auto bits = 8 * faces.dtype().itemsize();
  if (faces.dtype().kind() != 'u' || bits >= 64 || v < (std::int64_t{1} << (bits - 1))) return std::to_string(v);
  return std::to_string(v) + " (" + std::to_string(v - (std::int64_t{1} << bits)) + " stored as an unsigned " +
         std::to_string(bits) + "-bit integer?)";
}

}  // namespace

std::vector<std::array<std::uint32_t, 3>> triangles_of(const py::array& faces, std::size_t vertices) {
  if (faces.dtype().kind() != 'i' && faces.dtype().kind() != 'u')
    throw py::type_error("faces: expected an integer array of shape (F, 3), got dtype " + dtype_of(faces));
  if (faces.ndim() != 2 || faces.shape(1) != 3 || faces.shape(0) < 1)
    throw py::value_error("faces: expected shape (F, 3) with F >= 1, got " + shape_of(faces));
  const auto indices = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(faces);
  const auto read = indices.unchecked<2>();
  std::vector<std::array<std::uint32_t, 3>> triangles(std::size_t(read.shape(0)));
  for (py::ssize_t j = 0; j < read.shape(0); ++j)
    for (py::ssize_t k = 0; k < 3; ++k) {
      const std::int64_t v = read(j, k);
      if (v < 0 || std::uint64_t(v) >= vertices)
        throw invalid_input("faces: triangle " + std::to_string(j) + " has vertex index " + index_text(v, faces) +
                            " out of range [0, " + std::to_string(vertices) + ")");
      triangles[std::size_t(j)][std::size_t(k)] = std::uint32_t(v);
    }
  return triangles;
}

}  // namespace deformseg::python
