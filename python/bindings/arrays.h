// NumPy arrays in and out of deformseg._deformseg: the checks and conversions of the arrays an
// Animation is made of, and arrays that show the library's results without a copy.
#pragma once

#include <deformseg/mesh/coordinate_buffer.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace deformseg::python {

// "(T, V, 3)": the shape of `a`, for messages.
std::string shape_of(const pybind11::array& a);

// "float32": the dtype of `a`, for messages.
std::string dtype_of(const pybind11::array& a);

// Any array-like (a list, a memory view, an array of another library) as a NumPy array, without
// copy when it is one already; a TypeError naming the argument `name` otherwise.
pybind11::array as_array(const pybind11::object& value, const char* name);

// The (T, V, 3) coordinates of `frames` as the library stores them, doubles frame after frame:
// one copy of a C-contiguous float64 or float32 array, a NumPy conversion first for any other.
mesh::Coordinate_buffer<double> positions_of(const pybind11::array& frames);

// The triangles of `faces`, an (F, 3) array of integers, each checked to be in [0, vertices).
std::vector<std::array<std::uint32_t, 3>> triangles_of(const pybind11::array& faces, std::size_t vertices);

// A read-only NumPy view of the values at `data`, kept alive by `owner`.
template <class T>
pybind11::array view(const T* data, std::vector<pybind11::ssize_t> shape, const pybind11::object& owner) {
  pybind11::array a(pybind11::dtype::of<T>(), std::move(shape), {}, data, owner);
  a.attr("setflags")(pybind11::arg("write") = false);
  return a;
}

// A NumPy array that owns `value` (moved to the heap) and shows `data` of it.
template <class Owned, class T>
pybind11::array owning(Owned&& value, const T* (*data)(const Owned&), std::vector<pybind11::ssize_t> shape,
                       std::vector<pybind11::ssize_t> strides = {}) {
  auto* held = new Owned(std::forward<Owned>(value));
  pybind11::capsule owner(held, [](void* p) { delete static_cast<Owned*>(p); });
  return pybind11::array(pybind11::dtype::of<T>(), std::move(shape), std::move(strides), data(*held), owner);
}

}  // namespace deformseg::python
